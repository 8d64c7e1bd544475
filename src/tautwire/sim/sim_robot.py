"""The simulated robot: :class:`tautwire.robot.Robot` on a :class:`SimWorld`.

A :class:`SimRobot` shows a primitive exactly what a real robot would: time,
gripper poses, finger openings and grip forces, and the noisy wrench of the
wrist sensor(s). The world it drives is private; no ground truth is reachable
through it.
"""

from __future__ import annotations

import numpy as np

from tautwire.robot.arm import ARMS
from tautwire.robot.command import Command
from tautwire.robot.observation import GripperState, Observation
from tautwire.sim.ft_sensor import FTSensor
from tautwire.sim.world import SimWorld


class SimRobot:
    """A dual-arm robot in the simulated world.

    Args:
        world: The world to drive (kept private).
        seed: Seed of the sensor noise (default: the world spec's seed).
    """

    __slots__ = ("__world", "_latest", "_sensors")

    def __init__(self, world: SimWorld, seed: int | None = None) -> None:
        spec = world.spec
        rng = np.random.default_rng(spec.seed if seed is None else seed)
        self.__world = world
        self._sensors = tuple(
            FTSensor(arm, spec.noise_force, spec.noise_torque, rng) for arm in spec.sensor_arms
        )
        self._latest = self._sample()

    @property
    def control_period(self) -> float:
        """Period [s] of one :meth:`act` call."""
        return self.__world.control_period

    def observe(self) -> Observation:
        """The measurement taken at the end of the last control period."""
        return self._latest

    def act(self, command: Command) -> None:
        """Apply ``command`` for one control period, then sample the sensors.

        Raises:
            SimulationDiverged: if the physics blows up.
        """
        world = self.__world
        world.set_gripper("left", command.left)
        world.set_gripper("right", command.right)
        world.set_twist(command.twist)
        world.step()
        self._latest = self._sample()

    def _sample(self) -> Observation:
        world = self.__world
        states = []
        for arm in ARMS:
            position, orientation = world.gripper_pose(arm)
            states.append(
                GripperState(
                    position=position,
                    orientation=orientation,
                    opening=world.gripper_opening(arm),
                    grip_force=world.gripper_grip_force(arm),
                )
            )
        wrenches = tuple(
            sensor.measure(*world.wrench(sensor.arm, copy=False)) for sensor in self._sensors
        )
        return Observation(world.time, states[0], states[1], wrenches)
