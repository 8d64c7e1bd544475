"""Kalman filter of a contact point (equ:kalmanUpdate) with change detection.

The state x is the static contact position p_c [m] (F = I); each sample gives
the 2-D measurement z = H p_g of :mod:`tautwire.estimation.contact_observation`
(the normalised form of equ:ls_observation_model) with noise R = r^2 I_2,
r = d sigma_f / |f|, where d is the distance from the gripper to the current
estimate (or a known ``edge_length``), floored at ``min_distance``. The
covariance P is the paper's "uncertainty"; ``std = sqrt(diag(P))``.

Initialisation: samples are buffered until their force directions span
``init_spread`` [rad]; then a batch least squares over the buffer
(:func:`~tautwire.estimation.contact_point_least_squares`) gives x and P.
Before that there is no estimate (``None``). A Kalman filter with Q = 0
started this way gives exactly the batch least-squares answer over all
samples (tested).

Change detection: see :mod:`tautwire.estimation.contact_change_detector`.
On a declared change the filter restarts (a round contact keeps its estimate:
its gated lines cannot be refitted without their sides) with a batch least
squares over the gated run with a weak prior on the current line (centred at the point of the
line nearest the old estimate, isotropic std equal to its distance from the
gripper); the sample reports ``changed=True`` and its index is appended to
:attr:`ContactPointFilter.changes`.

Process noise: Q = q I per step. The paper tuned q = 1e-7 m^2 by hand to trade
precision for responsiveness after a contact change. Change detection now
provides the responsiveness, so q only sets the memory of the filter: in
steady state std ~ (q r^2)^(1/4) and the memory is about r / sqrt(q) samples.
Measured on the synthetic circle (radius 0.2 m, 125 samples per circle, 4 N,
sigma_f = 0.05 N, median over 20 seeds of the error after a full circle):
q = 0: 0.43 mm, 1e-9: 0.44 mm, 1e-8: 0.56 mm, 1e-7: 0.91 mm. The default
q = 1e-9 m^2 costs nothing measurable against q = 0, yet keeps P from
collapsing (std floor about 0.3 mm, memory about 80 samples at r = 2.5 mm), so
the filter still follows slow drifts and the 3-sigma consistency holds
(worst seed 95 % of samples, against 49 % with q = 0). A cable around a round
peg does not give one point: its lines are tangent to the peg and the
estimate settles near the peg's axis, about the peg radius from the moving
tangent point, for every q.

Round contacts: :meth:`ContactPointFilter.make_round` adds the radius R at
which the cable passes the axis as a 4th state; each line then comes with the
side on which it passes (known from the rotation's sense), and the estimate
is the axis. R is not just peg radius + cable radius: the simulated cable
keeps 12-16 mm from the axis of a peg where that sum is 10.5 mm, and a fixed
R left the estimate 2.4-3.3 mm off the axis in Fig. 5c (1.1-1.5 mm with R
estimated, seeds 0-5).
"""

from __future__ import annotations

import math
from collections import deque
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.contact_change_detector import ContactChangeDetector
from tautwire.estimation.contact_observation import MIN_DISTANCE, normal_plane_basis
from tautwire.estimation.contact_point_least_squares import (
    ContactPointLeastSquares,
    contact_point_least_squares,
)
from tautwire.estimation.force_line import MIN_FORCE, line_offset_variance
from tautwire.estimation.weight_compensation import compensate_weight
from tautwire.model.tension import G as GRAVITY_ABS

FloatArray = NDArray[np.float64]

#: Default process noise q [m^2 per step, per axis] (see the module docstring).
DEFAULT_PROCESS_NOISE = 1e-9
#: Process noise [m^2 per step] of a round contact's radius (see
#: :meth:`ContactPointFilter.make_round`): 0.01 mm a step. On a partial wrap
#: the radius and the axis's position along the wrap's bisector are nearly
#: interchangeable, and 0.2 mm a step let the radius run to 35 mm where the
#: cable kept 12-16 mm (robustness trial 38: 19.6 mm off the axis; 16.5 mm now).
RADIUS_PROCESS_NOISE = 1e-10
#: Default angular spread [rad] of the first samples before the first estimate.
DEFAULT_INIT_SPREAD = math.radians(10.0)


_FLOAT64 = np.dtype(np.float64)


def _floats3(v: ArrayLike) -> list[float]:
    """A 3-vector as three Python floats."""
    if type(v) is np.ndarray and v.dtype is _FLOAT64 and v.shape == (3,):
        fast: list[float] = v.tolist()
        return fast
    out: list[float] = np.asarray(v, dtype=float).reshape(3).tolist()
    return out


def _finite3(a: float, b: float, c: float) -> bool:
    """All three are finite (0 x is NaN for an infinite or NaN x, 0 otherwise)."""
    return math.isfinite(0.0 * a + 0.0 * b + 0.0 * c)


def _unit_outer(f: FloatArray) -> tuple[float, ...]:
    """The outer product u u' of u = f / |f| (uxx, uxy, uxz, uyy, uyz, uzz)."""
    fx, fy, fz = f.tolist()
    n = math.sqrt(fx * fx + fy * fy + fz * fz)
    ux, uy, uz = fx / n, fy / n, fz / n
    return (ux * ux, ux * uy, ux * uz, uy * uy, uy * uz, uz * uz)


class ContactPointUpdate(NamedTuple):
    """Result of :meth:`ContactPointFilter.update`.

    Attributes:
        estimate: Contact position [m], or None before the first estimate.  # (3,)
        covariance: Its covariance P [m^2], or None.  # (3, 3)
        std: sqrt(diag(P)) [m], or None.  # (3,)
        changed: A new contact was declared at this sample.
        nis: Normalised innovation squared of this sample (None when the
            filter was not yet running or the sample was not used).
        used: The sample was fused into the estimate (False for slack
            cable, gated samples, or buffered samples before the first estimate).
    """

    estimate: FloatArray | None
    covariance: FloatArray | None
    std: FloatArray | None
    changed: bool
    nis: float | None
    used: bool


class FilterState(NamedTuple):
    """A copy of a filter's estimate, to go back to (see :meth:`ContactPointFilter.snapshot`).

    Attributes:
        running: Whether the filter had an estimate.
        x: Contact position [m].  # (3,)
        P: Its covariance [m^2].  # (3, 3)
        radius: A round contact's radius [m], or None.
        p_cr: cov(x, radius) [m^2].  # (3,)
        p_rr: var(radius) [m^2].
    """

    running: bool
    x: FloatArray
    P: FloatArray
    radius: float | None
    p_cr: FloatArray
    p_rr: float


class ContactPointFilter:
    """Kalman filter of one contact point from gripper positions and forces.

    Args:
        force_noise: sigma_f [N], force sensor noise, std per axis.
        process_noise: q [m^2 per step], per axis (a scalar or 3 values).
        position_noise: sigma_p [m], gripper position noise, std per axis.
        torque_noise: sigma_tau [N m], torque sensor noise, std per axis: the
            noise of a line offset when :meth:`update` is given the torque.
        mass_per_length: rho [kg/m] for weight compensation (0 = off).
        edge_length: Known gripper-contact cable length [m] for R and the
            weight compensation; None uses the distance to the estimate.
        min_distance: Floor [m] of the distance in R.
        min_tension: Samples with |f| below this [N] (slack cable) are skipped.
        init_spread: Angular spread [rad] of the buffered force directions
            that triggers the first estimate.
        init_max_samples: Most samples kept in the buffer before the first
            estimate (oldest dropped).
        init_max_std: The first estimate is taken only once the batch fit's
            largest std [m] is below this (noise alone can spread the force
            directions of a nearly slack cable).
        detector: Contact change detector; None for the default one.
        detect_changes: False disables change detection (no gating).
        x0: Optional prior mean [m]: start running at once from (x0, P0).  # (3,)
        P0: Prior covariance [m^2] with ``x0``.  # (3, 3)
    """

    def __init__(
        self,
        force_noise: float = 0.05,
        process_noise: float | ArrayLike = DEFAULT_PROCESS_NOISE,
        position_noise: float = 0.0,
        mass_per_length: float = 0.0,
        torque_noise: float = 0.0,
        edge_length: float | None = None,
        min_distance: float = MIN_DISTANCE,
        min_tension: float = 0.1,
        init_spread: float = DEFAULT_INIT_SPREAD,
        init_max_samples: int = 250,
        init_max_std: float = 0.02,
        detector: ContactChangeDetector | None = None,
        detect_changes: bool = True,
        x0: ArrayLike | None = None,
        P0: ArrayLike | None = None,
    ) -> None:
        if not (force_noise > 0.0 and math.isfinite(force_noise)):
            raise InvalidArgumentError(f"force_noise must be > 0 N, got {force_noise}")
        q = np.broadcast_to(np.asarray(process_noise, dtype=float), (3,)).copy()
        if np.any(q < 0.0) or not np.all(np.isfinite(q)):
            raise InvalidArgumentError(f"process_noise must be >= 0 m^2 per step, got {q}")
        if position_noise < 0.0 or not math.isfinite(position_noise):
            raise InvalidArgumentError(f"position_noise must be >= 0 m, got {position_noise}")
        if mass_per_length < 0.0 or not math.isfinite(mass_per_length):
            raise InvalidArgumentError(f"mass_per_length must be >= 0 kg/m, got {mass_per_length}")
        if edge_length is not None and not (edge_length > 0.0 and math.isfinite(edge_length)):
            raise InvalidArgumentError(f"edge_length must be > 0 m or None, got {edge_length}")
        if not (min_distance > 0.0 and math.isfinite(min_distance)):
            raise InvalidArgumentError(f"min_distance must be > 0 m, got {min_distance}")
        if min_tension < 0.0 or not math.isfinite(min_tension):
            raise InvalidArgumentError(f"min_tension must be >= 0 N, got {min_tension}")
        if not 0.0 < init_spread < math.pi:
            raise InvalidArgumentError(f"init_spread must be in (0, pi) rad, got {init_spread}")
        if init_max_samples < 3:
            raise InvalidArgumentError(f"init_max_samples must be >= 3, got {init_max_samples}")
        if (x0 is None) != (P0 is None):
            raise InvalidArgumentError("give both x0 and P0, or neither")
        self.force_noise = float(force_noise)
        self.Q: FloatArray = np.diag(q)  # (3, 3)
        self.position_noise = float(position_noise)
        if torque_noise < 0.0 or not math.isfinite(torque_noise):
            raise InvalidArgumentError(f"torque_noise must be >= 0 N m, got {torque_noise}")
        self.torque_noise = float(torque_noise)
        self.mass_per_length = float(mass_per_length)
        self.edge_length = edge_length
        self.min_distance = float(min_distance)
        self.min_tension = float(min_tension)
        self.init_spread = float(init_spread)
        if not (init_max_std > 0.0 and math.isfinite(init_max_std)):
            raise InvalidArgumentError(f"init_max_std must be > 0 m, got {init_max_std}")
        self.init_max_std = float(init_max_std)
        self.detector = detector if detector is not None else ContactChangeDetector()
        self.detect_changes = bool(detect_changes)
        self.x: FloatArray = np.zeros(3)  # (3,)
        self.P: FloatArray = np.zeros((3, 3))  # (3, 3)
        self.running = False
        #: Radius [m] of a round contact (its 4th state), None for a point contact.
        self.radius: float | None = None
        self._p_cr: FloatArray = np.zeros(3)  # cov(x, radius) [m^2]  # (3,)
        self._p_rr = 0.0  # var(radius) [m^2]
        self._radius_considered = False  # R a consider parameter (make_round)
        self.changes: list[int] = []
        #: The estimate that the last declared change replaced (None before any).
        self.replaced: FilterState | None = None
        self._count = 0
        # (line point, raw force, line offset variance) of each sample
        self._buffer: deque[tuple[FloatArray, FloatArray, float]] = deque(maxlen=init_max_samples)
        # u u' (uxx, uxy, uxz, uyy, uyz, uzz) of each buffered force direction, their sum
        self._uu: deque[tuple[float, ...]] = deque(maxlen=init_max_samples)
        self._uu_sum = [0.0] * 6
        self._uu_dropped = 0  # samples dropped from the buffer since the sum was made afresh
        self._recent: deque[tuple[int, FloatArray, FloatArray, float]] = deque(
            maxlen=self.detector.window
        )
        if x0 is not None and P0 is not None:
            self.x = np.asarray(x0, dtype=float).reshape(3).copy()
            self.P = np.asarray(P0, dtype=float).reshape(3, 3).copy()
            self.running = True

    # ------------------------------------------------------------------ queries
    @property
    def estimate(self) -> FloatArray | None:
        """Current contact estimate [m], shape (3,), or None before the first one."""
        return self.x.copy() if self.running else None

    @property
    def std(self) -> FloatArray | None:
        """sqrt(diag(P)) [m], shape (3,), or None before the first estimate."""
        return np.sqrt(np.diag(self.P)) if self.running else None

    @property
    def sample_count(self) -> int:
        """Number of samples given to :meth:`update` so far."""
        return self._count

    def reset(self) -> None:
        """Forget the estimate and the buffered samples: start afresh for a new contact."""
        self.x = np.zeros(3)
        self.P = np.zeros((3, 3))
        self.running = False
        self.radius = None
        self._buffer.clear()
        self._recent.clear()
        self.detector.reset()

    def start(self, x0: ArrayLike, P0: ArrayLike) -> None:
        """Start running at once from a prior (x0 [m], P0 [m^2]), forgetting buffered samples."""
        self.reset()
        self.x = np.asarray(x0, dtype=float).reshape(3).copy()
        self.P = np.asarray(P0, dtype=float).reshape(3, 3).copy()
        self.running = True

    def predict(self) -> None:
        """Let one step pass with nothing measured: P = F P F' + Q."""
        if self.running:
            self.P = self.P + self.Q

    def snapshot(self) -> FilterState:
        """A copy of the current estimate (e.g. before a change is accepted)."""
        return FilterState(
            self.running, self.x.copy(), self.P.copy(), self.radius, self._p_cr.copy(), self._p_rr
        )

    def restore(self, state: FilterState) -> None:
        """Go back to an estimate from :meth:`snapshot`; the gated run is forgotten."""
        self.running = state.running
        self.x = state.x.copy()
        self.P = state.P.copy()
        self.radius = state.radius
        self._p_cr = state.p_cr.copy()
        self._p_rr = state.p_rr
        self._recent.clear()
        self.detector.reset()

    def line_test(
        self, state: FilterState, p_line: ArrayLike, f_sens: ArrayLike
    ) -> tuple[float, float]:
        """How far a line misses an estimate: (NIS, |innovation| [m]).

        The line through ``p_line`` along the weight-compensated ``f_sens``
        against the point contact ``state`` (x, P), with this filter's
        measurement noise: the test the change detector makes, against an
        estimate the filter no longer holds.

        Args:
            state: The estimate to test against.
            p_line: A point of the line [m] (gripper or wrench line point).  # (3,)
            f_sens: The raw force [N].  # (3,)
        """
        p = np.asarray(p_line, dtype=float).reshape(3)
        fx, fy, fz = (float(v) for v in np.asarray(f_sens, dtype=float).reshape(3))
        span = (
            self.edge_length if self.edge_length is not None else float(np.linalg.norm(p - state.x))
        )
        fz += 0.5 * self.mass_per_length * span * GRAVITY_ABS
        fn = math.sqrt(fx * fx + fy * fy + fz * fz)
        if not (fn > 0.0 and math.isfinite(fn)):
            return math.inf, math.inf
        H = normal_plane_basis([fx, fy, fz])  # (2, 3)
        d = max(span, self.min_distance)
        r2 = (d * self.force_noise / fn) ** 2 + self.position_noise**2
        y = H @ (p - state.x)  # y = z - H x
        S = H @ (state.P + self.Q) @ H.T + r2 * np.eye(2)  # S = H P H' + R
        return float(y @ np.linalg.solve(S, y)), float(np.linalg.norm(y))

    # --------------------------------------------------------------- internals
    def _span(self, p: FloatArray) -> float:
        if self.edge_length is not None:
            return self.edge_length
        return float(np.linalg.norm(p - self.x)) if self.running else 0.0

    def _result(
        self,
        changed: bool,
        nis: float | None,
        used: bool,
        variances: tuple[float, float, float] | None = None,
    ) -> ContactPointUpdate:
        """The update's result; ``variances``: diag(P) [m^2] when the caller has it."""
        if not self.running:
            return ContactPointUpdate(None, None, None, changed, nis, used)
        P = self.P.copy()
        v0, v1, v2 = P.diagonal().tolist() if variances is None else variances
        if v0 >= 0.0 and v1 >= 0.0 and v2 >= 0.0:  # not NaN, not negative
            std = np.array((math.sqrt(v0), math.sqrt(v1), math.sqrt(v2)))
        else:
            std = np.sqrt(P.diagonal())  # NaN where a variance is not >= 0
        return ContactPointUpdate(self.x.copy(), P, std, changed, nis, used)

    def batch(
        self,
        p_grippers: FloatArray,
        f_sens: FloatArray,
        prior_mean: FloatArray | None = None,
        prior_covariance: FloatArray | None = None,
        offset_variances: FloatArray | None = None,
    ) -> ContactPointLeastSquares:
        """Batch least squares with this filter's noise and weight model.

        With weight compensation on, the span lengths come from a first,
        uncompensated solve (or ``edge_length``) and two refinements.

        Args:
            p_grippers: Gripper positions [m], or the points of the wrench's
                lines of action nearest them.  # (N, 3)
            f_sens: Raw forces [N] on the gripper.  # (N, 3)
            prior_mean: Optional prior mean [m].  # (3,)
            prior_covariance: Its covariance [m^2].  # (3, 3)
            offset_variances: Variance [m^2] of each line point's offset
                (see :mod:`~tautwire.estimation.force_line`).  # (N,)

        Returns:
            The least-squares result.
        """
        kwargs = dict(
            force_noise=self.force_noise,
            prior_mean=prior_mean,
            prior_covariance=prior_covariance,
            position_noise=self.position_noise,
            min_distance=self.min_distance,
            offset_variances=offset_variances,
        )
        res = contact_point_least_squares(
            p_grippers,
            f_sens,
            distances=self.edge_length,
            **kwargs,  # type: ignore[arg-type]
        )
        if self.mass_per_length > 0.0:
            for _ in range(2):
                if self.edge_length is not None:
                    spans = np.full(p_grippers.shape[0], self.edge_length)
                else:
                    spans = np.linalg.norm(p_grippers - res.estimate, axis=1)
                f_comp = np.array(
                    [
                        compensate_weight(f, s, self.mass_per_length)
                        for f, s in zip(f_sens, spans, strict=True)
                    ]
                )
                res = contact_point_least_squares(
                    p_grippers,
                    f_comp,
                    distances=spans,
                    **kwargs,  # type: ignore[arg-type]
                )
        return res

    def _buffer_sample(self, p: FloatArray, f_raw: FloatArray, v_offset: float) -> None:
        """Buffer a sample before the first estimate; keep the sum of u u' of its direction.

        The sum over the buffer (``self._uu_sum``: uxx, uxy, uxz, uyy, uyz,
        uzz) is kept up to date as samples enter and leave the bounded
        buffer, and summed afresh each time the buffer has turned over (so
        that rounding errors of the running sum cannot accumulate).
        """
        if len(self._uu) != len(self._buffer):  # the buffer was cleared
            self._uu.clear()
            for _, f, _ in self._buffer:
                self._uu.append(_unit_outer(f))
            self._uu_sum = [math.fsum(c) for c in zip(*self._uu, strict=True)] or [0.0] * 6
            self._uu_dropped = 0
        outer = _unit_outer(f_raw)
        total = self._uu_sum
        if len(self._buffer) == self._buffer.maxlen:
            for i, v in enumerate(self._uu[0]):  # the oldest sample leaves
                total[i] -= v
            self._uu_dropped += 1
        self._buffer.append((p, f_raw, v_offset))
        self._uu.append(outer)
        for i, v in enumerate(outer):
            total[i] += v
        if self._uu_dropped >= len(self._uu):
            self._uu_sum = [math.fsum(c) for c in zip(*self._uu, strict=True)]
            self._uu_dropped = 0

    def _try_initialise(self) -> bool:
        n = len(self._buffer)
        if n < 3:
            return False
        # mean of u u' over the buffered unit force directions u (_buffer_sample)
        uu00, uu01, uu02, uu11, uu12, uu22 = (v / n for v in self._uu_sum)
        M = np.array(
            [[1.0 - uu00, -uu01, -uu02], [-uu01, 1.0 - uu11, -uu12], [-uu02, -uu12, 1.0 - uu22]]
        )
        lam = float(np.linalg.eigvalsh(M)[0])
        spread = 2.0 * math.asin(math.sqrt(min(max(lam, 0.0), 1.0)))
        if spread < self.init_spread:
            return False
        p = np.array([s[0] for s in self._buffer])
        f = np.array([s[1] for s in self._buffer])
        try:
            res = self.batch(p, f, offset_variances=np.array([s[2] for s in self._buffer]))
        except InvalidArgumentError:
            return False  # lines through one point (the gripper did not move): wait
        # variance of unit weight: unmodelled effects (dynamics, sag, a round
        # peg) show as chi2 above its degrees of freedom and widen P
        # (only when chi2 exceeds dof by more than three of its std)
        dof = max(2 * len(p) - 3, 1)
        significant = res.chi2 > dof + 3.0 * math.sqrt(2.0 * dof)
        P0 = res.covariance * (res.chi2 / dof if significant else 1.0)
        if float(np.max(np.diag(P0))) > self.init_max_std**2:
            return False  # the spread is noise (e.g. a nearly slack cable): wait
        u = f[-1] / np.linalg.norm(f[-1])
        if float(u @ (res.estimate - p[-1])) < self.min_distance:
            return False  # the cable pulls towards its contact: not behind the gripper
        self.x = res.estimate.copy()
        self.P = P0
        self.running = True
        self._buffer.clear()
        return True

    def _restart(self, first_gated: int, p: FloatArray, f_chord: FloatArray) -> None:
        self.replaced = self.snapshot()
        if self.radius is not None:
            # a round contact's gated lines come without the sides they pass
            # on: they cannot be refitted here; the change is declared, the
            # estimate kept, and the caller tests the change on its own lines
            self._recent.clear()
            self.detector.reset()
            return
        samples = [(pp, ff, vv) for (i, pp, ff, vv) in self._recent if i >= first_gated]
        self.restart(
            np.array([s[0] for s in samples]),
            np.array([s[1] for s in samples]),
            f_chord=f_chord,
            offset_variances=np.array([s[2] for s in samples]),
        )

    def restart(
        self,
        p_grippers: ArrayLike,
        f_sens: ArrayLike,
        prior_mean: ArrayLike | None = None,
        prior_covariance: ArrayLike | None = None,
        f_chord: ArrayLike | None = None,
        radius: tuple[float, float] | None = None,
        offset_variances: ArrayLike | None = None,
        consider_radius: bool = False,
    ) -> None:
        """Start afresh at a new contact from the samples that saw it.

        A batch least squares over the samples with a prior: the given one,
        else a weak prior on the last sample's line, centred at its point
        nearest the current estimate, isotropic std equal to that point's
        distance from the gripper.

        Args:
            p_grippers: Gripper positions [m] (lines through them).  # (N, 3)
            f_sens: Their raw forces [N].  # (N, 3)
            prior_mean: Prior mean [m] of the new contact.  # (3,)
            prior_covariance: Its covariance [m^2].  # (3, 3)
            f_chord: Weight-compensated force [N] of the last sample, for the
                default prior's line (default: the last raw force).  # (3,)
            radius: (R, std) [m] of a round contact (see :meth:`make_round`),
                whose samples ``p_grippers`` are already shifted by R onto
                its axis; None for a point contact.
            offset_variances: Variance [m^2] of each sample's line offset.  # (N,)
            consider_radius: Keep R at its prior (see :meth:`make_round`).
        """
        ps = np.asarray(p_grippers, dtype=float).reshape(-1, 3)
        fs = np.asarray(f_sens, dtype=float).reshape(-1, 3)
        if prior_mean is None or prior_covariance is None:
            p = ps[-1]
            f = fs[-1] if f_chord is None else np.asarray(f_chord, dtype=float).reshape(3)
            u = f / np.linalg.norm(f)
            along = max(float(u @ (self.x - p)), 0.0)
            prior_mean = p + along * u
            sigma = max(along, self.min_distance)
            prior_covariance = sigma * sigma * np.eye(3)
        res = self.batch(
            ps,
            fs,
            np.asarray(prior_mean, dtype=float).reshape(3),
            np.asarray(prior_covariance, dtype=float).reshape(3, 3),
            None if offset_variances is None else np.asarray(offset_variances, dtype=float),
        )
        self.x = res.estimate.copy()
        self.P = res.covariance.copy()
        self.running = True
        self._recent.clear()
        self.detector.reset()
        self.radius = None
        if radius is not None:
            self.make_round(*radius, consider=consider_radius)

    def make_round(self, radius: float, std: float, consider: bool = False) -> None:
        """Treat the contact as round: add its radius R [m] (prior std [m]) as a 4th state.

        A cable leaves a round contact tangentially, so its lines miss the
        axis by R on the side the rotation gives: with the unit vector ``side``
        from a line towards the axis (see :meth:`update`),

            z = H p_g = H p_c - R H side,

        which is linear in (p_c, R). R starts uncorrelated with p_c.

        With ``consider`` (a peg), R is a consider parameter (the Schmidt-
        Kalman filter): its gain is zero, so R stays at its prior, but its
        variance and its covariance with p_c are carried, and the reported
        P of p_c includes what R's uncertainty does to it. On a partial wrap R
        and the axis's position along the wrap's bisector are nearly
        interchangeable: estimated, R ran to 18-22 mm where the lines kept
        11-15 mm (robustness trials 29 and 38: the axis 15-17 mm off at a
        reported std of 4 mm). Without ``consider`` R is estimated and takes a
        random walk (``RADIUS_PROCESS_NOISE``): the signed offset at which a
        circled point's lines pass it.

        Args:
            radius: Prior mean of R [m].
            std: Its prior std [m].
            consider: Keep R at its prior (a consider parameter).
        """
        self.radius = float(radius)
        self._radius_considered = bool(consider)
        self._p_cr = np.zeros(3)
        self._p_rr = float(std) ** 2

    def declare_change(
        self,
        p_grippers: ArrayLike,
        f_sens: ArrayLike,
        prior_mean: ArrayLike,
        prior_covariance: ArrayLike,
        radius: tuple[float, float] | None = None,
        consider_radius: bool = False,
    ) -> None:
        """Declare a contact change at the last sample given to :meth:`update`.

        For a caller that knows more than the innovations (e.g. a gated line
        that meets a fixture of the board design): restart from the samples
        with that prior and record the change in :attr:`changes`
        (``radius`` and ``consider_radius`` as in :meth:`restart`).
        """
        self.restart(
            p_grippers,
            f_sens,
            prior_mean,
            prior_covariance,
            radius=radius,
            consider_radius=consider_radius,
        )
        self.changes.append(self._count - 1)

    # ------------------------------------------------------------------ update
    def update(
        self,
        p_gripper: ArrayLike,
        f_sens: ArrayLike,
        side: ArrayLike | None = None,
        torque: ArrayLike | None = None,
    ) -> ContactPointUpdate:
        """Fuse one sample (equ:kalmanUpdate).

        A sample with a non-finite position, force or torque is not used
        (time passes, nothing is measured).

        Args:
            p_gripper: Gripper position p_g [m], world frame.  # (3,)
            f_sens: Force [N] the cable exerts on the gripper, world frame,
                bias removed (raw: weight compensation happens here when
                ``mass_per_length`` > 0).  # (3,)
            side: For a round contact (:meth:`make_round`), the unit vector
                normal to the line towards the contact's axis; ignored for a
                point contact.  # (3,)
            torque: Torque [N m] about p_g, world frame, measured with
                ``f_sens``: the line then runs through the whole wrench's
                line of action (:mod:`~tautwire.estimation.force_line`)
                instead of through p_g. None: through p_g.  # (3,)

        Returns:
            The estimate (or None), its covariance and std, the change flag,
            the NIS and whether the sample was used.
        """
        index = self._count
        self._count += 1
        # Python floats, not small numpy arrays: a 3x3 update in numpy spends
        # most of its time in call overhead (bench/force_log.py); the numpy
        # arrays x and P stay the public state
        px, py, pz = _floats3(p_gripper)
        fx, fy, fz = _floats3(f_sens)
        v_offset = 0.0  # variance [m^2] of the line's offset from p_g
        # all finite (0 v is NaN for an infinite or NaN v, 0 otherwise)
        finite = math.isfinite(0.0 * px + 0.0 * py + 0.0 * pz + 0.0 * fx + 0.0 * fy + 0.0 * fz)
        if torque is not None and finite:
            tx, ty, tz = _floats3(torque)
            if _finite3(tx, ty, tz):
                # o = (f x tau) / |f|^2 (force_line.line_offset), its variance
                f2 = fx * fx + fy * fy + fz * fz
                if f2 > MIN_FORCE * MIN_FORCE and math.isfinite(f2):
                    ox = (fy * tz - fz * ty) / f2
                    oy = (fz * tx - fx * tz) / f2
                    oz = (fx * ty - fy * tx) / f2
                else:
                    ox = oy = oz = 0.0
                px, py, pz = px + ox, py + oy, pz + oz
                v_offset = line_offset_variance(
                    math.sqrt(f2),
                    math.sqrt(ox * ox + oy * oy + oz * oz),
                    self.force_noise,
                    self.torque_noise,
                )
            else:
                finite = False
        if not finite:
            if self.running:
                self.P += self.Q  # P = F P F' + Q (time passes, nothing measured)
            return self._result(False, None, False)
        f_raw = (fx, fy, fz)
        x0, x1, x2 = self.x.tolist() if self.running else (0.0, 0.0, 0.0)
        dx, dy, dz = px - x0, py - x1, pz - x2
        if self.edge_length is not None:
            span = self.edge_length
        else:
            span = math.sqrt(dx * dx + dy * dy + dz * dz) if self.running else 0.0
        if self.mass_per_length > 0.0 and self.running:
            # f = f_sens - m_g g with m_g = rho d / 2 (eq:mass, equ:edge_tension)
            fz += 0.5 * self.mass_per_length * span * GRAVITY_ABS
        fn = math.sqrt(fx * fx + fy * fy + fz * fz)
        if not self.running:
            if fn >= self.min_tension and math.isfinite(fn):
                self._buffer_sample(np.array([px, py, pz]), np.array(f_raw), v_offset)
                self._try_initialise()
            return self._result(False, None, False)
        if fn < self.min_tension or not math.isfinite(fn):
            self.P += self.Q  # P = F P F' + Q (time passes, nothing measured)
            return self._result(False, None, False)

        # observation model (equ:ls_observation_model), normalised, see contact_observation
        x_, y_, z_ = fx / fn, fy / fn, fz / fn
        sign = 1.0 if z_ >= 0.0 else -1.0
        a = -1.0 / (sign + z_)
        b = x_ * y_ * a
        h00, h01, h02 = 1.0 + sign * x_ * x_ * a, sign * b, -sign * x_  # H, first row
        h10, h11, h12 = b, sign + y_ * y_ * a, -y_  # H, second row
        d = max(span, self.min_distance)
        r = d * self.force_noise / fn
        r2 = r * r + self.position_noise * self.position_noise + v_offset  # R = r^2 I

        if side is not None and self.radius is not None:
            H = np.array([[h00, h01, h02], [h10, h11, h12]])
            f_chord = np.array([fx, fy, fz])
            p = np.array([px, py, pz])
            return self._update_round(index, p, np.array(f_raw), f_chord, H, r2, side, v_offset)
        # P = F P F' + Q  (F = I: x = F x is x)
        (p00, p01, p02), (p10, p11, p12), (p20, p21, p22) = self.P.tolist()
        (q00, q01, q02), (q10, q11, q12), (q20, q21, q22) = self.Q.tolist()
        p00, p01, p02 = p00 + q00, p01 + q01, p02 + q02
        p10, p11, p12 = p10 + q10, p11 + q11, p12 + q12
        p20, p21, p22 = p20 + q20, p21 + q21, p22 + q22
        y0 = h00 * dx + h01 * dy + h02 * dz  # y = z - H x,  z = H p_g
        y1 = h10 * dx + h11 * dy + h12 * dz
        c00 = p00 * h00 + p01 * h01 + p02 * h02  # P H'  (3, 2)
        c10 = p10 * h00 + p11 * h01 + p12 * h02
        c20 = p20 * h00 + p21 * h01 + p22 * h02
        c01 = p00 * h10 + p01 * h11 + p02 * h12
        c11 = p10 * h10 + p11 * h11 + p12 * h12
        c21 = p20 * h10 + p21 * h11 + p22 * h12
        s00 = h00 * c00 + h01 * c10 + h02 * c20 + r2  # S = H P H' + R
        s01 = h00 * c01 + h01 * c11 + h02 * c21
        s11 = h10 * c01 + h11 * c11 + h12 * c21 + r2
        det = s00 * s11 - s01 * s01
        nis = (s11 * y0 * y0 - 2.0 * s01 * y0 * y1 + s00 * y1 * y1) / det  # NIS = y' S^-1 y

        if self.detect_changes:
            test = self.detector.test(index, nis, math.hypot(y0, y1))
            if test.gated:
                P_pred = [[p00, p01, p02], [p10, p11, p12], [p20, p21, p22]]
                self.P = np.array(P_pred)
                p = np.array([px, py, pz])
                self._recent.append((index, p, np.array(f_raw), v_offset))
                if test.changed and test.first_gated is not None:
                    self._restart(test.first_gated, p, np.array([fx, fy, fz]))
                    self.changes.append(index)
                    return self._result(True, nis, True)
                return self._result(False, nis, False)
            self._recent.clear()

        i00, i01, i11 = s11 / det, -s01 / det, s00 / det  # S^-1
        k00, k01 = c00 * i00 + c01 * i01, c00 * i01 + c01 * i11  # K = P H' S^-1
        k10, k11 = c10 * i00 + c11 * i01, c10 * i01 + c11 * i11
        k20, k21 = c20 * i00 + c21 * i01, c20 * i01 + c21 * i11
        x0 += k00 * y0 + k01 * y1  # x = x + K y
        x1 += k10 * y0 + k11 * y1
        x2 += k20 * y0 + k21 * y1
        a00 = 1.0 - (k00 * h00 + k01 * h10)  # A = I - K H
        a01 = -(k00 * h01 + k01 * h11)
        a02 = -(k00 * h02 + k01 * h12)
        a10 = -(k10 * h00 + k11 * h10)
        a11 = 1.0 - (k10 * h01 + k11 * h11)
        a12 = -(k10 * h02 + k11 * h12)
        a20 = -(k20 * h00 + k21 * h10)
        a21 = -(k20 * h01 + k21 * h11)
        a22 = 1.0 - (k20 * h02 + k21 * h12)
        b00 = a00 * p00 + a01 * p10 + a02 * p20  # A P
        b01 = a00 * p01 + a01 * p11 + a02 * p21
        b02 = a00 * p02 + a01 * p12 + a02 * p22
        b10 = a10 * p00 + a11 * p10 + a12 * p20
        b11 = a10 * p01 + a11 * p11 + a12 * p21
        b12 = a10 * p02 + a11 * p12 + a12 * p22
        b20 = a20 * p00 + a21 * p10 + a22 * p20
        b21 = a20 * p01 + a21 * p11 + a22 * p21
        b22 = a20 * p02 + a21 * p12 + a22 * p22
        # P = (I - K H) P (I - K H)' + K R K'  (Joseph form; symmetric: upper triangle)
        n00 = b00 * a00 + b01 * a01 + b02 * a02 + r2 * (k00 * k00 + k01 * k01)
        n01 = b00 * a10 + b01 * a11 + b02 * a12 + r2 * (k00 * k10 + k01 * k11)
        n02 = b00 * a20 + b01 * a21 + b02 * a22 + r2 * (k00 * k20 + k01 * k21)
        n11 = b10 * a10 + b11 * a11 + b12 * a12 + r2 * (k10 * k10 + k11 * k11)
        n12 = b10 * a20 + b11 * a21 + b12 * a22 + r2 * (k10 * k20 + k11 * k21)
        n22 = b20 * a20 + b21 * a21 + b22 * a22 + r2 * (k20 * k20 + k21 * k21)
        self.x = np.array((x0, x1, x2))
        self.P = np.array((n00, n01, n02, n01, n11, n12, n02, n12, n22)).reshape(3, 3)
        return self._result(False, nis, True, (n00, n11, n22))

    def _update_round(
        self,
        index: int,
        p: FloatArray,
        f_raw: FloatArray,
        f_chord: FloatArray,
        H: FloatArray,
        r2: float,
        side: ArrayLike,
        v_offset: float = 0.0,
    ) -> ContactPointUpdate:
        """The update with the state (p_c, R) of a round contact (see :meth:`make_round`)."""
        assert self.radius is not None
        h_r = -(H @ np.asarray(side, dtype=float).reshape(3))  # dz/dR  # (2,)
        H4 = np.hstack([H, h_r[:, None]])  # (2, 4)
        x4 = np.append(self.x, self.radius)
        P4 = np.zeros((4, 4))
        P4[:3, :3] = self.P + self.Q  # P = F P F' + Q
        P4[:3, 3] = P4[3, :3] = self._p_cr
        P4[3, 3] = self._p_rr + (0.0 if self._radius_considered else RADIUS_PROCESS_NOISE)
        y = H @ p - H4 @ x4  # y = z - H x
        PHt = P4 @ H4.T  # (4, 2)
        S = H4 @ PHt + r2 * np.eye(2)  # S = H P H' + R
        SI = np.linalg.inv(S)
        nis = float(y @ SI @ y)  # NIS = y' S^-1 y
        if self.detect_changes:
            test = self.detector.test(index, nis, float(np.linalg.norm(y)))
            if test.gated:
                self._store(P4)
                self._recent.append((index, p, f_raw, v_offset))
                if test.changed and test.first_gated is not None:
                    self._restart(test.first_gated, p, f_chord)
                    self.changes.append(index)
                    return self._result(True, nis, True)
                return self._result(False, nis, False)
            self._recent.clear()
        K = PHt @ SI  # K = P H' S^-1
        if self._radius_considered:
            K[3, :] = 0.0  # Schmidt-Kalman: R is considered, not estimated
        x4 = x4 + K @ y  # x = x + K y
        I_KH = np.eye(4) - K @ H4  # the Joseph form below holds for any gain
        P4 = I_KH @ P4 @ I_KH.T + r2 * (K @ K.T)  # P = (I - K H) P (I - K H)' + K R K'
        self.x = x4[:3].copy()
        self.radius = float(x4[3])
        self._store(P4)
        return self._result(False, nis, True)

    def _store(self, P4: FloatArray) -> None:
        self.P = P4[:3, :3].copy()
        self._p_cr = P4[:3, 3].copy()
        self._p_rr = float(P4[3, 3])
