"""A force sensor's bias, seen from a still gripper at two tensions.

A cable pulls along itself. Held still at the tension T1, then at T2, it
pulls along the same direction u both times, and a sensor bias b adds to
both measured (weight-compensated) forces:

    f1 = T1 u + b,    f2 = T2 u + b.

Their difference lies along the cable, u = (f1 - f2) / |f1 - f2|, without
any small-angle approximation, and what is left of either normal to it is
the bias's part normal to the cable, b_n = (I - u u^T) f1. The part along
the cable only scales the tension; it tilts no line and cannot be seen.

A bias normal to the cable tilts each of the contact filter's lines by
b_n / T, which at the lever L (gripper to contact) moves the line by
L b_n / T. A circling gripper's lines then all pass by the same shifted
point, so they stay consistent and the contact's covariance stays small
(robustness trials 6, 9 and 94 trusted pegs 24-39 mm off): the shift is
what :func:`contact_shift` gives, with its covariance.

Each level's mean force has a covariance from its samples' own scatter,
counted by their effective number (lag-1 correlation), so the cable's
vibration counts and not only the noise model.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.effective_samples import effective_samples, mean_covariance

FloatArray = NDArray[np.float64]

#: Fewest samples per tension level for a result.
MIN_SAMPLES = 20


class TensionStepResult(NamedTuple):
    """What two still tension levels say (:meth:`TensionStep.result`).

    Attributes:
        direction: The cable's direction u from the difference of the means.  # (3,)
        bias: The bias's part b_n [N] normal to the cable.  # (3,)
        bias_covariance: Its covariance [N^2].  # (3, 3)
        tensions: The two levels' mean pulls along u [N].
        drifts: How much each level's pull changed normal to u [N] from its
            first sample to its last (a linear trend): a still gripper's
            cable pulls the same way throughout, a drifting bias does not.  # (3,) each
        drift_covariances: Their covariances [N^2].  # (3, 3) each
    """

    direction: FloatArray
    bias: FloatArray
    bias_covariance: FloatArray
    tensions: tuple[float, float]
    drifts: tuple[FloatArray, FloatArray]
    drift_covariances: tuple[FloatArray, FloatArray]


def level_drift(samples: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """The linear trend of ``samples`` (n, 3) over their span, first to last, and its covariance.

    The samples are taken as evenly spaced in time; the covariance comes
    from the residuals' scatter, counted by their effective number.
    """
    x = np.asarray(samples, dtype=float)
    n = len(x)
    t = np.arange(n, dtype=float) - 0.5 * (n - 1)
    tt = float(t @ t)
    if n < 3 or tt <= 0.0:
        return np.zeros(3), np.full((3, 3), math.inf)
    slope = (t @ (x - x.mean(axis=0))) / tt
    r = x - x.mean(axis=0) - np.outer(t, slope)
    scatter = (r.T @ r) / max(n - 2, 1)
    scale = np.sqrt([n / effective_samples(r[:, i]) for i in range(3)])
    span = float(n - 1)
    drift: FloatArray = slope * span
    cov: FloatArray = scatter * np.outer(scale, scale) / tt * span**2
    return drift, cov


def _normal_part(f1: FloatArray, f2: FloatArray) -> tuple[FloatArray, FloatArray]:
    d = f1 - f2
    u = d / float(np.linalg.norm(d))
    return u, f1 - u * float(u @ f1)


class TensionStep:
    """Collects a still gripper's weight-compensated force at two tension levels."""

    def __init__(self) -> None:
        self._samples: tuple[list[FloatArray], list[FloatArray]] = ([], [])

    def count(self, level: int) -> int:
        """Number of samples kept at ``level`` (0 or 1)."""
        return len(self._samples[self._level(level)])

    @staticmethod
    def _level(level: int) -> int:
        if level not in (0, 1):
            raise InvalidArgumentError(f"level must be 0 or 1, got {level!r}")
        return level

    def add(self, level: int, force: ArrayLike) -> None:
        """Add one force sample [N] (world frame) at ``level``; non-finite samples are skipped."""
        f = np.asarray(force, dtype=float).reshape(3)
        samples = self._samples[self._level(level)]
        if np.all(np.isfinite(f)):
            samples.append(f.copy())

    def result(self) -> TensionStepResult | None:
        """The cable's direction and the bias normal to it; None with too few samples or no step.

        The covariance is propagated from the two means' (a central-difference
        Jacobian of b_n in (f1, f2)).
        """
        if min(len(s) for s in self._samples) < MIN_SAMPLES:
            return None
        (f1, c1), (f2, c2) = (mean_covariance(np.array(s)) for s in self._samples)
        step = float(np.linalg.norm(f1 - f2))
        if not step > 3.0 * math.sqrt(float(np.trace(c1 + c2))):
            return None  # the tension did not step: no direction to speak of
        u, b = _normal_part(f1, f2)
        h = 1e-6 * max(float(np.linalg.norm(f1)), 1.0)
        jac = np.zeros((3, 6))
        for i in range(6):
            e = np.zeros(6)
            e[i] = h
            plus = _normal_part(f1 + e[:3], f2 + e[3:])[1]
            minus = _normal_part(f1 - e[:3], f2 - e[3:])[1]
            jac[:, i] = (plus - minus) / (2.0 * h)
        cov = np.zeros((6, 6))
        cov[:3, :3], cov[3:, 3:] = c1, c2
        keep = np.eye(3) - np.outer(u, u)
        drifts = [level_drift(np.array(x)) for x in self._samples]
        return TensionStepResult(
            u,
            b,
            jac @ cov @ jac.T,
            (float(u @ f1), float(u @ f2)),
            (keep @ drifts[0][0], keep @ drifts[1][0]),
            (keep @ drifts[0][1] @ keep, keep @ drifts[1][1] @ keep),
        )


def contact_shift(
    result: TensionStepResult, lever: float, tension: float
) -> tuple[FloatArray, FloatArray]:
    """How far [m] the bias moves a contact estimated from lines at ``tension``, and its covariance.

    Args:
        result: The tension step's result.
        lever: Distance [m] from the gripper to the contact (> 0).
        tension: The tension [N] the contact's lines were measured at (> 0).

    Returns:
        The shift L b_n / T (3,) [m] and its covariance (3, 3) [m^2].

    Raises:
        InvalidArgumentError: for a lever or tension that is not > 0.
    """
    for name, value in (("lever", lever), ("tension", tension)):
        if not (value > 0.0 and math.isfinite(value)):
            raise InvalidArgumentError(f"{name} must be > 0, got {value}")
    scale = lever / tension
    return scale * result.bias, scale**2 * result.bias_covariance
