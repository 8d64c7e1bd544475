"""Write your own Robot: a small kinematic robot that a primitive drives.

tautwire's primitives talk to a narrow interface, :class:`tautwire.robot.Robot`:
``control_period``, ``observe() -> Observation`` and ``act(Command)``. Anything
that implements those three runs every primitive, whether a real robot's
driver or, as here, a few lines of NumPy: two grippers that move exactly as
commanded, and a cable from a fixed anchor to the left gripper that pulls
like a spring once taut (Hooke, plus the weight of half its span), read by a
noisy wrist force sensor. No MuJoCo.

Primitive D (single-arm tension) then tensions the cable to 3 N, blind,
learning the stiffness from a 100 N/m guess, and primitive I circles the
anchor half round, estimating where the cable is fixed.

Run: python examples/own_robot.py [--seed N]
"""

from __future__ import annotations

import argparse
import math

import numpy as np
from scipy.spatial.transform import Rotation

from tautwire.model import PathGraph
from tautwire.primitives import RotateAroundFeaturePoint, SingleArmTension, make_context
from tautwire.robot import Command, GripperState, Observation, Robot, Wrench
from tautwire.tasks import RobotGuard, run_step

GRAVITY = np.array([0.0, 0.0, -9.81])  # [m/s^2], world z up


class KinematicRobot:
    """Two grippers that follow their twist exactly; a taut cable from an anchor.

    Args:
        anchor: Where the cable is fixed [m], world frame.
        rest_length: The cable's rest length [m].
        stiffness: Its axial stiffness [N/m].
        mass_per_length: Its linear density [kg/m].
        left: The left gripper's start position [m].
        yaw: The left gripper's start yaw about world z [rad].
        force_noise: Std of the sensor's force noise, per axis [N].
        seed: Seed of the noise.
    """

    def __init__(
        self,
        anchor: np.ndarray,
        rest_length: float,
        stiffness: float,
        mass_per_length: float,
        left: np.ndarray,
        yaw: float,
        force_noise: float = 0.05,
        seed: int = 0,
    ) -> None:
        self.anchor = anchor
        self.rest_length = rest_length
        self.stiffness = stiffness
        self.mass_per_length = mass_per_length
        self.force_noise = force_noise
        self._rng = np.random.default_rng(seed)
        self._time = 0.0
        self._position = {"left": left.copy(), "right": np.array([0.6, -0.45, 0.35])}
        self._rotation = {
            "left": Rotation.from_euler("z", yaw),
            "right": Rotation.identity(),
        }

    # --------------------------------------------------------- the Robot protocol
    @property
    def control_period(self) -> float:
        """One act() call lasts 4 ms (a 250 Hz interface)."""
        return 0.004

    def observe(self) -> Observation:
        """The latest sample: time, both grippers, the left wrist's wrench."""
        force = self.cable_force() + self._rng.normal(0.0, self.force_noise, 3)
        torque = self._rng.normal(0.0, 0.002, 3)  # the cable leaves at the TCP
        return Observation(
            time=self._time,
            left=self._gripper("left"),
            right=self._gripper("right"),
            wrenches=(Wrench("left", force, torque),),
        )

    def act(self, command: Command) -> None:
        """Move both grippers by the commanded twist for one control period."""
        dt = self.control_period
        for i, arm in enumerate(("left", "right")):
            v = command.twist[6 * i : 6 * i + 3]  # linear [m/s], world frame
            w = command.twist[6 * i + 3 : 6 * i + 6]  # angular [rad/s], world frame
            self._position[arm] = self._position[arm] + v * dt
            self._rotation[arm] = Rotation.from_rotvec(w * dt) * self._rotation[arm]
        self._time += dt

    # ------------------------------------------------------------ the cable's physics
    def cable_force(self) -> np.ndarray:
        """Force [N] the cable exerts on the left gripper: spring when taut, plus weight."""
        chord = self.anchor - self._position["left"]
        distance = float(np.linalg.norm(chord))
        tension = self.stiffness * max(0.0, distance - self.rest_length)
        weight = 0.5 * self.mass_per_length * min(distance, self.rest_length) * GRAVITY
        return tension * chord / distance + weight

    def _gripper(self, arm: str) -> GripperState:
        x, y, z, w = self._rotation[arm].as_quat()  # scipy is [x, y, z, w]
        return GripperState(
            position=self._position[arm].copy(),
            orientation=np.array([w, x, y, z]),  # tautwire is [w, x, y, z]
            opening=0.0,
            grip_force=20.0,
        )


def main(seed: int = 0) -> dict[str, float]:
    """Tension the cable (D), circle the anchor (I); print and return what was learnt."""
    design = np.array([0.30, 0.0, 0.08])  # the board's design says the anchor is here
    anchor = design + np.array([0.004, -0.003, 0.0])  # where it truly is: 5 mm off
    start = np.array([0.30, 0.32, 0.10])  # the gripper holds the cable at 0.40 m
    rho = 0.030
    robot = KinematicRobot(anchor, 0.40, 200.0, rho, start, yaw=math.pi / 2, seed=seed)
    assert isinstance(robot, Robot)  # the protocol is runtime-checkable

    # the robot's prior picture: the anchor's design position, the gripper, 0.40 m between
    graph = PathGraph.from_positions(
        np.array([design, start]),
        rho,
        lengths=[0.40],
        kinds=["fixed", "gripper"],
        labels=["A1", "left"],
    )
    ctx = make_context(graph, "left", fixtures={"A1": design}, estimation_period=0.04)
    # one guard for the whole run: it screens every sample and command
    guard = RobotGuard(robot, force_limit=15.0, force_noise=0.05)

    for primitive in (
        SingleArmTension(arm="left", force=3.0),
        RotateAroundFeaturePoint(arm="left", angle=math.pi, speed=0.5, about="A1"),
    ):
        report = run_step(guard, primitive, ctx)
        print(
            f"{report.letter} {report.primitive}: {report.outcome} after {report.sim_time:.1f} s, "
            f"largest force {report.max_force:.2f} N"
        )
        if not report.success:
            raise SystemExit(f"{report.primitive} failed: {report.cause}: {report.detail}")

    k_hat = ctx.estimator.elasticity.k_hat
    point = ctx.graph.points[ctx.graph.index_of("fixed", "A1") or 0]
    error = float(np.linalg.norm(point.position - anchor))
    std = np.sqrt(np.diag(point.covariance)) if point.covariance is not None else np.full(3, np.nan)
    print(f"stiffness learnt: {k_hat:.1f} N/m (the cable's: {robot.stiffness:.0f} N/m)")
    print(
        f"anchor: {1e3 * float(np.linalg.norm(design - anchor)):.1f} mm off its design, "
        f"estimated {1e3 * error:.2f} mm from the truth "
        f"(reported std {np.array2string(1e3 * std, precision=2)} mm)"
    )
    return {
        "k_hat": k_hat,
        "anchor_error": error,
        "design_error": float(np.linalg.norm(design - anchor)),
    }


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=0)
    main(parser.parse_args().seed)
