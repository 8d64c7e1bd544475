"""Faults injected between the simulated robot and whoever drives it.

A :class:`FaultInjector` wraps a robot (in practice a :class:`SimRobot`) and
is itself a :class:`tautwire.robot.Robot`. It changes what the robot senses
and does at the simulated times of the scenario's ``faults:`` (SCENARIO.md,
"Faults"), and nothing else; it never handles a fault (that is the core's
:class:`~tautwire.tasks.robot_guard.RobotGuard`), and the two do not know
each other.

- ``spike``: ``force`` is added to the measured force of the first sample at
  or after ``at``;
- ``nan``: that sample's force and torque are NaN;
- ``freeze``: from ``at`` for ``duration`` every sample repeats the sensor's
  last sample before the freeze bit for bit (time and gripper poses go on);
- ``bias_drift``: a bias that ramps linearly from 0 at ``at`` to ``force`` at
  ``at + duration`` and then stays is added to the measured force;
- ``slip``: from ``at`` for ``duration`` the arm's gripper squeezes with only
  :data:`SLIP_GRIP_FORCE` whatever it is told, so that the cable slides
  through its fingers; afterwards the primitive's next ``hold`` grasps the
  cable again where it then is;
- ``robot_error``: ``act()`` raises :class:`RobotCommunicationError` (a lost
  packet): the robot applies its previous command for that period, as a real
  robot does. Once, ``count`` times in a row, or on every call within
  ``duration``.

Sensor faults act on every wrist sensor of the robot.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from tautwire.robot import Arm, Command, GripperCommand, Observation, Robot, RobotCommunicationError
from tautwire.robot.observation import Wrench
from tautwire.scenario.models import (
    BiasDriftFault,
    Fault,
    FreezeFault,
    NanFault,
    RobotErrorFault,
    SlipFault,
    SpikeFault,
)

FloatArray = NDArray[np.float64]

#: Grip force [N] of a slipping gripper, 2 % of a hold's: with the pads'
#: friction coefficient 0.5 the fingers resist sliding with 2 mu F = 0.2 N,
#: less than any tension a primitive works at, so the cable slides through;
#: a short cable's weight share does not pull it out of the fingers at once.
SLIP_GRIP_FORCE = 0.2


class FaultInjector:
    """A robot whose sensing and acting fail as a scenario's ``faults:`` say.

    Args:
        robot: The robot to wrap (a :class:`SimRobot`).
        faults: The faults, in any order.
        sensing_arm: The arm a ``slip`` without ``arm`` hits.
    """

    def __init__(self, robot: Robot, faults: Sequence[Fault], sensing_arm: Arm = "left") -> None:
        self._robot = robot
        self._faults = tuple(faults)
        self._sensing_arm: Arm = sensing_arm
        self._spent: set[int] = set()  # spikes and NaNs already injected
        self._errors_left: dict[int, int] = {}  # robot errors still to raise, by fault
        self._previous: Command | None = None  # the last command that got through
        self._latest: Observation | None = None

    @property
    def control_period(self) -> float:
        """Period [s] of one :meth:`act` call."""
        return self._robot.control_period

    @property
    def faults(self) -> tuple[Fault, ...]:
        """The faults this injector injects."""
        return self._faults

    def observe(self) -> Observation:
        """The latest sample, with the sensor faults of its time."""
        if self._latest is None:
            self._latest = self._inject(self._robot.observe(), None)
        return self._latest

    def act(self, command: Command) -> None:
        """Apply ``command`` (with the gripper faults of now) for one period, then sample.

        Raises:
            RobotCommunicationError: while a ``robot_error`` fault is active;
                the previous command was applied for the period instead.
        """
        now = self.observe()
        lost = self._lost(now.time)
        applied = (self._previous or Command()) if lost else command
        self._robot.act(self._slipping(applied, now.time))
        if not lost:
            self._previous = command
        self._latest = self._inject(self._robot.observe(), now)
        if lost:
            raise RobotCommunicationError(
                f"the command at t = {now.time:.3f} s was lost (injected robot_error)"
            )

    # ------------------------------------------------------------- internals
    def _lost(self, t: float) -> bool:
        """Whether the command sent at time ``t`` [s] is lost."""
        for i, fault in enumerate(self._faults):
            if not isinstance(fault, RobotErrorFault) or t < fault.at - 1e-12:
                continue
            if fault.duration is not None:
                if t < fault.at + fault.duration - 1e-12:
                    return True
                continue
            left = self._errors_left.setdefault(i, fault.count or 1)
            if left > 0:
                self._errors_left[i] = left - 1
                return True
        return False

    def _slipping(self, command: Command, t: float) -> Command:
        """``command`` with the grip of every slipping arm dropped."""
        for fault in self._faults:
            if isinstance(fault, SlipFault) and fault.at - 1e-12 <= t < fault.at + fault.duration:
                arm = fault.arm or self._sensing_arm
                loose = GripperCommand("grip_force", SLIP_GRIP_FORCE)
                command = (
                    replace(command, left=loose) if arm == "left" else replace(command, right=loose)
                )
        return command

    def _inject(self, obs: Observation, previous: Observation | None) -> Observation:
        """``obs`` as the faulty sensor reports it; ``previous`` is the last reported sample."""
        t = obs.time
        if previous is not None and any(
            isinstance(f, FreezeFault) and f.at - 1e-12 <= t < f.at + f.duration
            for f in self._faults
        ):
            return replace(obs, wrenches=previous.wrenches)
        offset = np.zeros(3)
        poisoned = False
        for i, fault in enumerate(self._faults):
            if isinstance(fault, BiasDriftFault) and t >= fault.at - 1e-12:
                ramp = 1.0 if fault.duration <= 0.0 else min(1.0, (t - fault.at) / fault.duration)
                offset = offset + ramp * np.asarray(fault.force, dtype=float)
            elif isinstance(fault, SpikeFault | NanFault) and t >= fault.at - 1e-12:
                if i in self._spent:
                    continue
                self._spent.add(i)
                if isinstance(fault, SpikeFault):
                    offset = offset + np.asarray(fault.force, dtype=float)
                else:
                    poisoned = True
        if poisoned:
            nan = np.full(3, np.nan)
            wrenches = tuple(Wrench(w.arm, nan, nan.copy()) for w in obs.wrenches)
            return replace(obs, wrenches=wrenches)
        if not np.any(offset):
            return obs
        return replace(
            obs, wrenches=tuple(Wrench(w.arm, w.force + offset, w.torque) for w in obs.wrenches)
        )
