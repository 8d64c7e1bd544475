"""A kinematic test robot: a massless elastic cable from a fixed contact to the gripper.

Pure NumPy (no simulator): the gripper moves exactly as commanded; the
cable pulls it towards the contact with k * max(|c - p| - L0, 0) plus the
sensor's Gaussian noise. Optionally the contact moves to a second fixture at
a given time (the cable's rest length shortens by the distance between them).
"""

from __future__ import annotations

import numpy as np

from tautwire.model.quaternion import as_quaternion, multiply
from tautwire.robot import Command, GripperState, Observation, Wrench


class SpringCableRobot:
    def __init__(
        self,
        contact: np.ndarray,
        gripper: np.ndarray,
        stiffness: float,
        slack: float = 0.0,
        noise: float = 0.05,
        seed: int = 0,
        control_period: float = 0.004,
        second_contact: np.ndarray | None = None,
        switch_time: float | None = None,
        switch_on_chord: bool = False,
    ) -> None:
        self.contact = np.asarray(contact, dtype=float)
        self.p = np.asarray(gripper, dtype=float).copy()
        self.q = np.array([1.0, 0.0, 0.0, 0.0])
        self.p_right = np.array([0.35, -0.3, 0.12])
        self.k = stiffness
        self.rest = float(np.linalg.norm(self.contact - self.p)) + slack
        self.noise = noise
        self.rng = np.random.default_rng(seed)
        self._period = control_period
        self.time = 0.0
        self.second = None if second_contact is None else np.asarray(second_contact, dtype=float)
        self.switch_time = switch_time
        # a physical change: the cable comes to bear on the second point when
        # (after switch_time) its straight span passes over it
        self.switch_on_chord = switch_on_chord
        self.true_max_force = 0.0

    @property
    def control_period(self) -> float:
        return self._period

    def _chord_passes(self, point: np.ndarray) -> bool:
        ab = self.p - self.contact
        t = float(np.clip((point - self.contact) @ ab / (ab @ ab), 0.0, 1.0))
        return float(np.linalg.norm(point - (self.contact + t * ab))) < 2e-3

    def true_contact(self) -> np.ndarray:
        return self.contact

    def tension(self) -> float:
        return self.k * max(float(np.linalg.norm(self.contact - self.p)) - self.rest, 0.0)

    def observe(self) -> Observation:
        chord = self.contact - self.p
        f = self.tension() * chord / np.linalg.norm(chord)
        f = f + self.rng.normal(0.0, self.noise, 3)
        q_id = np.array([1.0, 0.0, 0.0, 0.0])
        return Observation(
            self.time,
            GripperState(self.p.copy(), self.q.copy()),
            GripperState(self.p_right.copy(), q_id),
            (Wrench("left", f, np.zeros(3)),),
        )

    def act(self, command: Command) -> None:
        dt = self._period
        self.p = self.p + command.twist[0:3] * dt
        w = command.twist[3:6]
        angle = float(np.linalg.norm(w)) * dt
        if angle > 0:
            axis = w / np.linalg.norm(w)
            dq = np.array([np.cos(angle / 2), *(np.sin(angle / 2) * axis)])
            self.q = as_quaternion(multiply(dq, self.q))
        self.p_right = self.p_right + command.twist[6:9] * dt
        self.time += dt
        self.true_max_force = max(self.true_max_force, self.tension())
        if (
            self.second is not None
            and self.switch_time is not None
            and self.time >= self.switch_time
            and (not self.switch_on_chord or self._chord_passes(self.second))
        ):
            self.rest -= float(np.linalg.norm(self.second - self.contact))
            self.contact = self.second
            self.second = None
