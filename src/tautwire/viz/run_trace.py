"""The time series of a simulated run: what the robot sensed and believed, and the truth.

A :class:`RunTrace` is fed by a runner's hooks (``on_tick``, ``on_step``,
``on_truth``) and keeps, every control period, the sensing gripper's pose
and the measured wrench (what the robot saw: noisy, with any injected
fault), the weight-compensated tension the model estimates and the set
point; every ``sample_every`` s (the contact filter's period), the contact
estimate with its reported covariance, and, from the simulator's ground truth, the true
contact of the span the gripper pulls on, the true tension and the error.
The truth is read for these scores only, never handed to a primitive.

It writes the force log of ``tautwire estimate`` (:meth:`write_force_log`)
and feeds the run plots (:mod:`tautwire.viz.run_plots`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from tautwire.estimation.force_log import ZERO_FORCE, write_force_log
from tautwire.robot import Arm
from tautwire.sim.ground_truth import GroundTruth
from tautwire.tasks import StepReport, TickRecord

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class StepMark:
    """Where a step of the task began and ended.

    Attributes:
        letter: The primitive's letter.
        primitive: Its name.
        start: Time [s] of its first tick.
        end: Time [s] of its last tick.
        outcome: ``success`` or ``failure`` (and the cause).
    """

    letter: str
    primitive: str
    start: float
    end: float
    outcome: str


@dataclass
class RunTrace:
    """Per-tick and sampled series of one run (see the module's docstring).

    Args:
        cable: The cable the sensing gripper holds (for the truth).
        arm: The sensing gripper's arm (default: the context's, at the first tick).
        sample_every: Simulated time [s] between samples of the contact
            estimate and the truth (the contact filter's period by default).
    """

    cable: str
    arm: Arm | None = None
    t: list[float] = field(default_factory=list)
    position: list[FloatArray] = field(default_factory=list)
    orientation: list[FloatArray] = field(default_factory=list)
    force: list[FloatArray] = field(default_factory=list)
    torque: list[FloatArray] = field(default_factory=list)
    tension: list[float] = field(default_factory=list)
    set_point: list[float] = field(default_factory=list)
    #: Every ``sample_every`` [s] once there is a contact estimate:
    sample_t: list[float] = field(default_factory=list)
    estimate: list[FloatArray] = field(default_factory=list)
    covariance: list[FloatArray] = field(default_factory=list)
    true_contact: list[FloatArray | None] = field(default_factory=list)
    true_fixture: list[str | None] = field(default_factory=list)
    true_tension: list[float] = field(default_factory=list)
    steps: list[StepMark] = field(default_factory=list)
    truth: GroundTruth | None = None
    sample_every: float = 0.04
    _next_sample: float = 0.0
    _step_start: float | None = None

    def keep_truth(self, truth: GroundTruth) -> None:
        """The runner's ``on_truth`` hook (scoring only)."""
        self.truth = truth

    def tick(self, rec: TickRecord) -> None:
        """The runner's ``on_tick`` hook: one control period."""
        obs = rec.observation
        if self.arm is None:
            self.arm = rec.context.arm
        if not obs.has_sensor(self.arm):
            return
        t = float(obs.time)
        if self.t and t <= self.t[-1]:
            return  # a repeated sample: the log's time must increase
        if self._step_start is None:
            self._step_start = t
        g = obs.gripper(self.arm)
        w = obs.wrench(self.arm)
        self.t.append(t)
        self.position.append(np.array(g.position, dtype=float))
        self.orientation.append(np.array(g.orientation, dtype=float))
        self.force.append(np.array(w.force, dtype=float))
        self.torque.append(np.array(w.torque, dtype=float))
        est = rec.context.estimator
        state = est.state
        self.tension.append(float("nan") if state is None else float(state.tension))
        sp = rec.context.tension
        self.set_point.append(float("nan") if sp is None else float(sp))
        if t >= self._next_sample - 1e-9:  # on the grid of sample_every, as time rounds
            while self._next_sample <= t + 1e-9:
                self._next_sample += self.sample_every
            self._sample(rec, t)

    def _sample(self, rec: TickRecord, t: float) -> None:
        ce = rec.context.estimator.contact_estimate()
        if ce is None:
            return
        self.sample_t.append(t)
        self.estimate.append(np.array(ce.position, dtype=float))
        self.covariance.append(np.array(ce.covariance, dtype=float))
        arm = rec.context.arm
        span = None if self.truth is None else self.truth.span(self.cable, arm)
        if span is None or span.contact is None:
            self.true_contact.append(None)
            self.true_fixture.append(None)
            self.true_tension.append(float("nan"))
        else:
            self.true_contact.append(np.array(span.contact, dtype=float))
            self.true_fixture.append(span.fixture)
            self.true_tension.append(float(span.tension))

    def step(self, index: int, report: StepReport) -> None:
        """The runner's ``on_step`` hook: a step ended."""
        end = self.t[-1] if self.t else 0.0
        start = end if self._step_start is None else self._step_start
        outcome = report.outcome + (f" ({report.cause})" if report.cause else "")
        self.steps.append(StepMark(report.letter, report.primitive, start, end, outcome))
        self._step_start = None

    @property
    def contact_error(self) -> FloatArray:
        """Distance [m] of each sample's estimate from the true contact (NaN: none)."""
        out = np.full(len(self.estimate), np.nan)
        for i, (e, c) in enumerate(zip(self.estimate, self.true_contact, strict=True)):
            if c is not None:
                out[i] = float(np.linalg.norm(e - c))
        return out

    def write_force_log(self, path: str | Path, window: int = 1) -> Path:
        """Write the sensing gripper's samples as a force log (``tautwire estimate``'s input).

        Columns ``t,px,py,pz,fx,fy,fz,qw,qx,qy,qz,tx,ty,tz``: time [s], the
        tool centre point [m], the measured force [N] and the torque [N m]
        about the tool centre point, world frame, as the robot saw them
        (samples with no force, shorter than ``ZERO_FORCE``, left out).

        Args:
            path: The CSV file (overwritten).
            window: Each row the mean of this many consecutive samples (the
                time of the last): the online contact filter fuses the mean
                of each estimation period, and so should an offline one.
                The rows' noise is the sensor's over ``sqrt(window)``.

        Raises:
            InvalidArgumentError: if nothing was recorded.
        """
        f = np.asarray(self.force, dtype=float).reshape(-1, 3)
        p = np.asarray(self.position, dtype=float).reshape(-1, 3)
        q = np.asarray(self.orientation, dtype=float).reshape(-1, 4)
        tau = np.asarray(self.torque, dtype=float).reshape(-1, 3)
        t = np.asarray(self.t, dtype=float)
        w = max(1, int(window))
        n = (len(t) // w) * w
        if w > 1 and n >= w:
            t = t[w - 1 : n : w]
            f, p, q, tau = (a[:n].reshape(-1, w, a.shape[1]).mean(axis=1) for a in (f, p, q, tau))
            q = q / np.linalg.norm(q, axis=1, keepdims=True)
        keep = np.linalg.norm(f, axis=1) >= ZERO_FORCE  # no direction: not a log row
        write_force_log(path, t[keep], p[keep], f[keep], q[keep], tau[keep])
        return Path(path)
