"""The guard between any :class:`~tautwire.robot.Robot` and the primitives.

A :class:`RobotGuard` wraps a robot (simulated or real) and is itself a
``Robot``. It makes sure that what reaches a primitive, filter or controller
is usable, and that the robot stays safe when it is not:

- **Non-finite samples** (force, torque, gripper pose or fingers, time) are
  never passed on: the last good sample stands in.
- **Stale data**: a sample whose time does not advance, or a wrench repeated
  bit for bit (a noisy sensor never repeats itself, so this is checked only
  when ``force_noise > 0``), or a sample lost in transmission. While the data
  are unusable the robot holds still (zero twist, gripper commands kept),
  from the first such period on; once they have been unusable for more than
  :data:`STALE_TIME` the step fails with ``sensor_stale``.
- **Outliers**: a force that jumps from the last good sample by more than
  :func:`spike_bound` is rejected, but never two samples in a row: a force
  that stays up is a real force, and a sustained force above the limit
  reaches the runner's force-limit check one sample late at most.
- **Tare**: with ``tare_samples``, the guard first holds still and reads the
  sensor(s) to estimate an offset (:class:`SensorTare`), removed from every
  later sample.
- **Robot errors**: a :class:`~tautwire.robot.RobotCommunicationError` from
  ``act`` (a lost command: the robot kept its previous command for that
  period) is survived; when they repeat for more than :data:`ERROR_TIME`, or
  on any other exception from ``observe``/``act``, the step fails with
  ``robot_error`` after a zero twist has been tried. An exception that names
  its own cause (the simulator's ``SimulationDiverged``: ``diverged``) keeps
  it; a diverged simulation is not commanded again.
- **Workspace**: a command that would take a gripper's tool centre point out
  of the workspace box is stopped at the boundary; if the primitive keeps
  pushing out for more than :data:`PUSH_TIME`, the step fails with
  ``workspace``.

The guard's state (last good sample, tare, counters) lasts for a whole run:
the caller creates it once and hands it to every step (see
:func:`tautwire.tasks.runner.run_step`). Pure NumPy: it knows nothing of the
simulator, so a real robot gets the same protection.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.primitives.outcome import CAUSES, Outcome
from tautwire.robot import (
    Command,
    GripperCommand,
    GripperState,
    Observation,
    Robot,
    RobotCommunicationError,
    Wrench,
)
from tautwire.robot.workspace import Workspace
from tautwire.tasks.sensor_tare import SensorTare

FloatArray = NDArray[np.float64]

#: Longest stretch [s] of unusable sensor data that a step survives.
STALE_TIME = 0.1
#: Longest stretch [s] of lost commands in a row that a step survives.
ERROR_TIME = 0.1
#: Longest stretch [s] that a primitive may keep pushing a gripper out of the workspace.
PUSH_TIME = 0.1
#: Stiffest cable [N/m] the outlier bound allows for (the envelope's is 1500 N/m).
MAX_STIFFNESS = 2000.0
#: Default number of samples of the tare (about 50 ms at 250 Hz).
TARE_SAMPLES = 12

_EPS = 1e-9


def spike_bound(
    force_limit: float,
    force_noise: float,
    max_linear_speed: float,
    control_period: float,
    max_stiffness: float = MAX_STIFFNESS,
) -> float:
    """Largest change [N] of the measured force between two samples that a cable explains.

    ``0.5 F_max + k_max v_max dt + 6 sqrt(6) sigma``:

    - a cable pulls the gripper with less than the force limit ``F_max``, so a
      real change is a fraction of it; half the limit in one period means a
      stretch rate that needs ``0.5 F_max / (v_max dt)`` N/m (18750 N/m at
      15 N, 0.1 m/s, 4 ms: nine times the stiffest cable allowed for);
    - ``k_max v_max dt`` is what the stiffest cable (``MAX_STIFFNESS``) adds
      in one period at the speed limit;
    - the difference of two noisy samples has std ``sqrt(2) sigma`` per
      axis, ``sqrt(6) sigma`` over three axes: six of those.

    A real release (a cable slipping or snapping into a clip) can drop the
    force faster; rejecting it costs one sample of delay, since the guard
    never rejects two samples in a row.

    Args:
        force_limit: Force limit [N].
        force_noise: Sensor noise [N], std per axis.
        max_linear_speed: Gripper speed limit [m/s].
        control_period: Control period [s].
        max_stiffness: Stiffest cable allowed for [N/m].
    """
    return (
        0.5 * force_limit
        + max_stiffness * max_linear_speed * control_period
        + 6.0 * math.sqrt(6.0) * force_noise
    )


def _cause_of(exc: BaseException) -> str:
    """The cause an exception names for itself (e.g. ``diverged``), else ``robot_error``."""
    cause = getattr(exc, "cause", None)
    return cause if isinstance(cause, str) and cause in CAUSES else "robot_error"


def _finite(obs: Observation) -> bool:
    """Whether every number of ``obs`` is finite.

    A sum of numbers is finite exactly when all of them are (NaN and inf
    propagate; finite magnitudes near 1e308 that overflow count as
    unusable too), which is much cheaper than testing each array.
    """
    total = (
        float(obs.time)
        + float(obs.left.opening)
        + float(obs.left.grip_force)
        + float(obs.right.opening)
        + float(obs.right.grip_force)
        + sum(obs.left.position.tolist())
        + sum(obs.left.orientation.tolist())
        + sum(obs.right.position.tolist())
        + sum(obs.right.orientation.tolist())
    )
    for w in obs.wrenches:
        total += sum(w.force.tolist()) + sum(w.torque.tolist())
    return math.isfinite(total)


def _repeated(obs: Observation, previous: Observation) -> bool:
    """Whether every wrench of ``obs`` equals ``previous``'s bit for bit."""
    if not obs.wrenches or len(obs.wrenches) != len(previous.wrenches):
        return False
    return all(
        a.force.tolist() == b.force.tolist() and a.torque.tolist() == b.torque.tolist()
        for a, b in zip(obs.wrenches, previous.wrenches, strict=True)
    )


class RobotGuard:
    """A :class:`~tautwire.robot.Robot` that checks every sample and command of another.

    Args:
        robot: The robot to guard.
        force_limit: Force limit [N] (for the outlier bound; the runner checks
            the limit itself).
        force_noise: Sensor noise [N], std per axis; 0 (unknown or noise
            free) disables the frozen-sensor check.
        max_linear_speed: Gripper speed limit [m/s] (for the outlier bound).
        workspace: Box the grippers' tool centre points must stay in (None:
            no bound).
        tare_samples: Samples of the tare at the start (0: no tare).
        expected_load: Force [N] each sensing arm's cable should exert at
            rest, by arm (default zero), see :class:`SensorTare`.
        tare_tolerance: How far [N] the true load at rest may be from the
            expected one.

    Raises:
        InvalidArgumentError: for a non-positive force limit or speed, a
            negative noise, tare sample count or tolerance.
    """

    def __init__(
        self,
        robot: Robot,
        *,
        force_limit: float,
        force_noise: float = 0.0,
        max_linear_speed: float = 0.1,
        workspace: Workspace | None = None,
        tare_samples: int = 0,
        expected_load: Mapping[str, ArrayLike] | None = None,
        tare_tolerance: float = 0.0,
    ) -> None:
        for what, value in (("force_limit", force_limit), ("max_linear_speed", max_linear_speed)):
            if not (math.isfinite(value) and value > 0.0):
                raise InvalidArgumentError(f"{what} must be finite and > 0, got {value}")
        if not (math.isfinite(force_noise) and force_noise >= 0.0):
            raise InvalidArgumentError(f"force_noise must be finite and >= 0 N, got {force_noise}")
        if tare_samples < 0:
            raise InvalidArgumentError(f"tare_samples must be >= 0, got {tare_samples}")
        self._robot = robot
        self._dt = float(robot.control_period)
        self._frozen_check = force_noise > 0.0
        self._bound = spike_bound(force_limit, force_noise, max_linear_speed, self._dt)
        self._workspace = workspace
        self._lower = None if workspace is None else tuple(float(v) for v in workspace.lower)
        self._upper = None if workspace is None else tuple(float(v) for v in workspace.upper)
        loads = dict(expected_load or {})
        self._tares: dict[str, SensorTare] = {}
        self._tare_samples = int(tare_samples)
        self._tare_tolerance = float(tare_tolerance)
        self._force_noise = float(force_noise)
        self._loads = {arm: np.asarray(v, dtype=float) for arm, v in loads.items()}
        self._offsets: dict[str, FloatArray] = {}
        self._sampled = False
        self._good: Observation | None = None  # last accepted sample (tared)
        self._raw: Observation | None = None  # last finite sample as the robot gave it
        self._placeholder: Observation | None = None
        self._time = 0.0
        self._fresh = False
        self._bad = 0
        self._bad_reason = ""
        self._outlier_before = False
        self._lost = 0
        self._pushing = 0
        self._grippers: tuple[GripperCommand, GripperCommand] = (
            GripperCommand(),
            GripperCommand(),
        )
        self._fault: Outcome | None = None
        self._stopped = False
        self._events: dict[str, int] = {
            "non_finite": 0,
            "stale_time": 0,
            "frozen": 0,
            "lost_sample": 0,
            "outlier": 0,
            "lost_command": 0,
            "workspace_stop": 0,
        }

    # ----------------------------------------------------------- Robot protocol
    @property
    def control_period(self) -> float:
        """Period [s] of one :meth:`act` call (the guarded robot's)."""
        return self._dt

    def observe(self) -> Observation:
        """The last good sample, tared; finite in every number.

        Between two commands it returns the same sample, however often it is
        called. Before any good sample it returns the robot's first sample
        with its non-finite numbers replaced by zeros (``fresh`` is False).
        """
        if not self._sampled:
            self._sample()
        if self._good is not None:
            return self._good
        assert self._placeholder is not None
        return self._placeholder

    def act(self, command: Command) -> None:
        """Send ``command`` (stopped at the workspace boundary) for one period, then sample."""
        if self._fault is not None:
            return
        if not self._sampled:
            self._sample()
        command = self._bounded(command)
        if self._fault is not None:
            return
        self._grippers = (command.left, command.right)
        self._send(command)

    # ------------------------------------------------------------------ state
    @property
    def fresh(self) -> bool:
        """Whether :meth:`observe` holds a new, accepted sample for the primitive."""
        if not self._sampled:
            self._sample()
        return self._fresh

    @property
    def fault(self) -> Outcome | None:
        """The failure the current step must end with, or None."""
        return self._fault

    @property
    def time(self) -> float:
        """Latest finite time [s] the robot reported."""
        return self._time

    @property
    def offsets(self) -> dict[str, FloatArray]:
        """Force offset [N] removed from each arm's sensor by the tare (empty before it)."""
        if not all(t.done for t in self._tares.values()):
            return {}
        return {arm: t.offset for arm, t in self._tares.items()}

    @property
    def events(self) -> dict[str, int]:
        """How often each kind of fault was met, by kind.

        Kinds: ``non_finite``, ``stale_time``, ``frozen``, ``lost_sample``,
        ``outlier``, ``lost_command``, ``workspace_stop``.
        """
        return dict(self._events)

    @property
    def spike_bound(self) -> float:
        """The outlier bound [N] in use (see :func:`spike_bound`)."""
        return self._bound

    def begin_step(self) -> None:
        """Start a new step: forget the previous step's fault and workspace push."""
        self._fault = None
        self._stopped = False
        self._pushing = 0
        self._lost = 0

    def hold(self) -> None:
        """Hold still for one period (zero twist, gripper commands kept), then sample."""
        if self._fault is not None:
            return
        self._send(Command(np.zeros(12), self._grippers[0], self._grippers[1]))

    def stop(self) -> None:
        """Try one zero twist (gripper commands kept); never raises.

        Not sent after a ``diverged`` failure (the simulation is gone) or
        when the guard has already stopped in this step.
        """
        if self._stopped or (self._fault is not None and self._fault.cause == "diverged"):
            return
        self._stopped = True
        try:
            self._robot.act(Command(np.zeros(12), self._grippers[0], self._grippers[1]))
            obs = self._robot.observe()
            if math.isfinite(obs.time):
                self._time = max(self._time, float(obs.time))
        except Exception:  # stopping is best effort: the step ends anyway
            return

    # -------------------------------------------------------------- internals
    def _fail(self, cause: str, detail: str) -> None:
        if self._fault is None:
            self._fault = Outcome.failure(cause, detail)
            self.stop()

    def _send(self, command: Command) -> None:
        try:
            self._robot.act(command)
        except RobotCommunicationError as exc:
            self._lost += 1
            self._events["lost_command"] += 1
            if self._lost * self._dt > ERROR_TIME + _EPS:
                self._fail(
                    "robot_error",
                    f"{self._lost} commands in a row were lost"
                    f" ({self._lost * self._dt:.3f} s, over {ERROR_TIME:g} s): {exc}",
                )
                return
        except Exception as exc:  # any robot failure ends the step cleanly
            self._fail(_cause_of(exc), f"the robot failed to act: {type(exc).__name__}: {exc}")
            return
        else:
            self._lost = 0
        self._sample()

    def _sample(self) -> None:
        self._sampled = True
        try:
            raw = self._robot.observe()
        except RobotCommunicationError as exc:
            self._unusable("lost_sample", f"a sample was lost ({exc})")
            return
        except Exception as exc:  # any robot failure ends the step cleanly
            self._fail(_cause_of(exc), f"the robot failed to observe: {type(exc).__name__}: {exc}")
            return
        if not _finite(raw):
            if self._good is None and self._placeholder is None:
                self._placeholder = _zeroed(raw)
            self._unusable("non_finite", "non-finite numbers in the sample")
            return
        if self._placeholder is None:
            self._placeholder = raw
        time = float(raw.time)
        previous = self._raw
        if previous is not None and time <= previous.time:
            self._unusable("stale_time", f"the robot's time did not advance ({time:.4f} s)")
            return
        self._time = time
        self._raw = raw
        if self._frozen_check and previous is not None and _repeated(raw, previous):
            self._unusable("frozen", "the sensor repeated its last sample bit for bit")
            return
        if self._tare_samples and not self._tares_done(raw):
            self._fresh = False
            self._bad = 0
            return
        cleaned = self._tared(raw)
        if self._good is not None and not self._outlier_before and self._jumped(cleaned):
            self._events["outlier"] += 1
            self._outlier_before = True
            self._fresh = False
            return
        self._outlier_before = False
        self._good = cleaned
        self._fresh = True
        self._bad = 0

    def _unusable(self, kind: str, reason: str) -> None:
        self._events[kind] += 1
        self._fresh = False
        self._bad += 1
        self._bad_reason = reason
        if self._bad * self._dt > STALE_TIME + _EPS:
            self._fail(
                "sensor_stale",
                f"the sensor data were unusable for {self._bad} samples in a row"
                f" ({self._bad * self._dt:.3f} s, over {STALE_TIME:g} s); last: {reason}",
            )

    def _tares_done(self, raw: Observation) -> bool:
        """Feed the tare; True once it is done (the offsets are then set)."""
        if not self._tares:
            self._tares = {
                w.arm: SensorTare(
                    self._tare_samples,
                    self._loads.get(w.arm, np.zeros(3)),
                    self._tare_tolerance,
                    self._force_noise,
                )
                for w in raw.wrenches
            }
        if all(t.done for t in self._tares.values()):
            return True
        for w in raw.wrenches:
            if w.arm in self._tares:
                self._tares[w.arm].add(w.force)
        if all(t.done for t in self._tares.values()):
            self._offsets = {arm: t.offset for arm, t in self._tares.items() if np.any(t.offset)}
            self._good = self._tared(raw)
        return False

    def _tared(self, raw: Observation) -> Observation:
        if not self._offsets:
            return raw
        wrenches = tuple(
            Wrench(w.arm, w.force - self._offsets[w.arm], w.torque) if w.arm in self._offsets else w
            for w in raw.wrenches
        )
        return Observation(raw.time, raw.left, raw.right, wrenches)

    def _jumped(self, obs: Observation) -> bool:
        assert self._good is not None
        good = {w.arm: w.force.tolist() for w in self._good.wrenches}
        bound2 = self._bound * self._bound
        for w in obs.wrenches:
            before = good.get(w.arm)
            if before is not None:
                x, y, z = w.force.tolist()
                if (x - before[0]) ** 2 + (y - before[1]) ** 2 + (z - before[2]) ** 2 > bound2:
                    return True
        return False

    def _bounded(self, command: Command) -> Command:
        """``command`` with every linear velocity that leaves the workspace stopped at it."""
        if self._lower is None or self._upper is None or self._good is None:
            return command
        dt = self._dt
        v = command.twist.tolist()
        pushed = False
        for k, p in enumerate((self._good.left.position, self._good.right.position)):
            for axis, (p_i, lo, hi) in enumerate(
                zip(p.tolist(), self._lower, self._upper, strict=True)
            ):
                i = 6 * k + axis
                after = p_i + v[i] * dt
                if after > hi and v[i] > 0.0:
                    v[i] = max(0.0, (hi - p_i) / dt)
                    pushed = True
                elif after < lo and v[i] < 0.0:
                    v[i] = min(0.0, (lo - p_i) / dt)
                    pushed = True
        if not pushed:
            self._pushing = 0
            return command
        self._events["workspace_stop"] += 1
        self._pushing += 1
        bounded_command = Command(np.array(v), command.left, command.right)
        if self._pushing * dt > PUSH_TIME + _EPS:
            assert self._workspace is not None
            self._grippers = (command.left, command.right)
            self._fail(
                "workspace",
                f"the primitive kept driving a gripper out of the workspace"
                f" ({self._workspace.describe()}) for {self._pushing * dt:.3f} s",
            )
        return bounded_command


def _zeroed(obs: Observation) -> Observation:
    """``obs`` with every non-finite number replaced by zero (a placeholder only)."""

    def state(g: GripperState) -> GripperState:
        return GripperState(
            np.nan_to_num(np.asarray(g.position, dtype=float), nan=0.0, posinf=0.0, neginf=0.0),
            np.nan_to_num(np.asarray(g.orientation, dtype=float), nan=0.0, posinf=0.0, neginf=0.0)
            if np.all(np.isfinite(g.orientation))
            else np.array([1.0, 0.0, 0.0, 0.0]),
            float(g.opening) if math.isfinite(g.opening) else 0.0,
            float(g.grip_force) if math.isfinite(g.grip_force) else 0.0,
        )

    wrenches = tuple(
        Wrench(
            w.arm,
            np.nan_to_num(np.asarray(w.force, dtype=float), nan=0.0, posinf=0.0, neginf=0.0),
            np.nan_to_num(np.asarray(w.torque, dtype=float), nan=0.0, posinf=0.0, neginf=0.0),
        )
        for w in obs.wrenches
    )
    time = float(obs.time) if math.isfinite(obs.time) else 0.0
    return Observation(time, state(obs.left), state(obs.right), wrenches)
