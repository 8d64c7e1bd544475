"""Small worlds shared by the simulator tests (built in code, nothing downloaded)."""

from __future__ import annotations

import numpy as np

from tautwire.sim import (
    AnchorSpec,
    CableSpec,
    GripperSpec,
    HoldSpec,
    PegSpec,
    SimOptions,
    SimWorld,
    WorldSpec,
)

#: Tool x-axis pointing straight up (rotation of -90 degrees about y).
X_UP = np.array([np.sqrt(0.5), 0.0, -np.sqrt(0.5), 0.0])
RIGHT_AWAY = GripperSpec([0.0, -0.5, 0.3])


def anchor_and_gripper(
    anchor: list[float],
    gripper: list[float],
    length: float,
    stiffness: float = 100.0,
    mass_per_length: float = 0.03,
    orientation: np.ndarray | None = None,
    held_at: float | None = None,
    fixtures: tuple = (),
    via: tuple[str, ...] = (),
    sensor_arms: tuple = ("left",),
    noise_force: float = 0.0,
    noise_torque: float = 0.0,
    force_limit: float = 15.0,
    seed: int = 0,
    **options: object,
) -> SimWorld:
    """A cable from an anchor to the left gripper (held at its end by default)."""
    spec = WorldSpec(
        fixtures=(AnchorSpec("A", anchor), *fixtures),
        cables=(
            CableSpec(
                "W",
                length,
                mass_per_length,
                stiffness,
                0.0025,
                start="A",
                via=via,
                holds=(HoldSpec("left", length if held_at is None else held_at),),
            ),
        ),
        left=GripperSpec(gripper, np.array([1.0, 0, 0, 0]) if orientation is None else orientation),
        right=RIGHT_AWAY,
        sensor_arms=sensor_arms,
        noise_force=noise_force,
        noise_torque=noise_torque,
        force_limit=force_limit,
        seed=seed,
    )
    return SimWorld(spec, SimOptions.from_kwargs(**options))


def peg_scene(**options: object) -> SimWorld:
    """One anchor, one peg, a 0.42 m cable, one held gripper (the benchmark scene)."""
    return anchor_and_gripper(
        [0.0, 0.0, 0.12],
        [0.35, 0.15, 0.12],
        0.42,
        stiffness=200.0,
        fixtures=(PegSpec("P", [0.15, 0.05, 0.10], 0.006, 0.05),),
        via=("P",),
        **options,
    )


def rest(world: SimWorld, seconds: float) -> None:
    """Step ``world`` with the grippers still."""
    world.set_twist(np.zeros(12))
    for _ in range(round(seconds / world.control_period)):
        world.step()
