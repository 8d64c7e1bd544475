"""A pure-NumPy test robot whose samples and failures follow a script.

The gripper moves exactly as commanded; the left wrist measures
``force(t)`` plus seeded Gaussian noise. ``edits`` changes the sample taken
after a given number of commands (a NaN, a spike, a repeat); ``failures``
makes given ``act`` calls raise (the command is then lost: the robot goes on
with its previous twist for that period, as a real robot does).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np

from tautwire.robot import Command, GripperState, Observation, Wrench

Edit = Callable[[Observation, Observation | None], Observation]


def nan_force(obs: Observation, previous: Observation | None) -> Observation:
    w = obs.wrenches[0]
    return replace(obs, wrenches=(Wrench(w.arm, np.full(3, np.nan), np.full(3, np.nan)),))


def nan_position(obs: Observation, previous: Observation | None) -> Observation:
    return replace(obs, left=replace(obs.left, position=np.array([np.nan, 0.0, 0.0])))


def nan_time(obs: Observation, previous: Observation | None) -> Observation:
    return replace(obs, time=float("nan"))


def repeat(obs: Observation, previous: Observation | None) -> Observation:
    """The sensor repeats the previous sample's wrench (time and poses go on)."""
    assert previous is not None
    return replace(obs, wrenches=previous.wrenches)


def same_time(obs: Observation, previous: Observation | None) -> Observation:
    assert previous is not None
    return replace(obs, time=previous.time)


def spike(force: list[float]) -> Edit:
    def edit(obs: Observation, previous: Observation | None) -> Observation:
        w = obs.wrenches[0]
        return replace(obs, wrenches=(Wrench(w.arm, w.force + np.asarray(force), w.torque),))

    return edit


class ScriptedRobot:
    def __init__(
        self,
        force: Callable[[float], np.ndarray] | None = None,
        noise: float = 0.05,
        seed: int = 0,
        control_period: float = 0.004,
        position: tuple[float, float, float] = (0.3, 0.3, 0.1),
    ) -> None:
        self.force = force or (lambda t: np.array([0.0, -1.0, 0.0]))
        self.noise = noise
        self.rng = np.random.default_rng(seed)
        self._period = control_period
        self.time = 0.0
        self.p = np.array(position, dtype=float)
        self.p_right = np.array([0.4, -0.3, 0.2])
        self.edits: dict[int, Edit] = {}
        self.failures: dict[int, Exception] = {}
        self.observe_failures: dict[int, Exception] = {}
        self.sent: list[Command] = []  # every command act() was called with
        self.applied: list[Command] = []  # what the robot really did, period by period
        self.acts = 0
        self._previous: Observation | None = None
        self._latest = self._sample()

    @property
    def control_period(self) -> float:
        return self._period

    def observe(self) -> Observation:
        error = self.observe_failures.get(self.acts)
        if error is not None:
            raise error
        return self._latest

    def act(self, command: Command) -> None:
        self.sent.append(command)
        error = self.failures.get(self.acts)
        applied = command if error is None else (self.applied[-1] if self.applied else Command())
        self.applied.append(applied)
        self.p = self.p + applied.twist[0:3] * self._period
        self.p_right = self.p_right + applied.twist[6:9] * self._period
        self.time += self._period
        self.acts += 1
        self._latest = self._sample()
        if error is not None:
            raise error

    def _sample(self) -> Observation:
        f = self.force(self.time) + self.noise * self.rng.standard_normal(3)
        tau = self.noise * 0.04 * self.rng.standard_normal(3)
        q = np.array([1.0, 0.0, 0.0, 0.0])
        obs = Observation(
            self.time,
            GripperState(self.p.copy(), q.copy(), 0.005, 10.0),
            GripperState(self.p_right.copy(), q.copy(), 0.04, 0.0),
            (Wrench("left", f, tau),),
        )
        edit = self.edits.get(self.acts)
        if edit is not None:
            obs = edit(obs, self._previous)
        self._previous = obs
        return obs
