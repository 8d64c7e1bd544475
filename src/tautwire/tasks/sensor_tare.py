"""Taring a wrist force sensor before the cable is loaded.

A real force-torque sensor reads an offset that has nothing to do with the
cable (mounting, temperature). At the start of a run the robot holds still
and reads the sensor a few times; what the held, slack cable explains is the
``expected`` load (e.g. its weight share) give or take ``tolerance``. Only an
offset well beyond that is removed: a small real load must not be tared away,
since the estimators need it. Drift during the run is the estimators' job
(cause ``sensor_bias``).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError

FloatArray = NDArray[np.float64]

#: Noise allowance of the tare's decision, in standard deviations of the
#: median of the samples (per axis, combined over three axes).
TARE_SIGMAS = 5.0


class SensorTare:
    """Estimates one sensor's force offset from samples taken at rest.

    The offset is the per-axis median of the samples (a single spike among
    them does not move it) minus the ``expected`` load. It is removed only
    if its magnitude exceeds ``tolerance`` plus the noise of the median,
    ``TARE_SIGMAS * 1.2533 * sqrt(3) * force_noise / sqrt(samples)``
    (1.2533 sigma / sqrt(n) is the standard error of a median of n normal
    samples); otherwise the offset is zero.

    Args:
        samples: Number of samples to take (>= 1).
        expected: Force [N] the held cable should exert at rest, world frame.  # (3,)
        tolerance: How far [N] the true load at rest may be from ``expected``
            (e.g. a multiple of the held cable's weight), >= 0.
        force_noise: Standard deviation [N] of the sensor noise per axis, >= 0.

    Raises:
        InvalidArgumentError: for a non-positive ``samples``, a negative or
            non-finite ``tolerance`` or ``force_noise``, or an ``expected``
            that is not 3 finite numbers.
    """

    def __init__(
        self, samples: int, expected: ArrayLike, tolerance: float, force_noise: float
    ) -> None:
        if samples < 1:
            raise InvalidArgumentError(f"samples must be >= 1, got {samples}")
        e = np.asarray(expected, dtype=float)
        if e.shape != (3,) or not np.all(np.isfinite(e)):
            raise InvalidArgumentError(f"expected must be 3 finite numbers [N], got {expected!r}")
        for what, value in (("tolerance", tolerance), ("force_noise", force_noise)):
            if not (math.isfinite(value) and value >= 0.0):
                raise InvalidArgumentError(f"{what} must be finite and >= 0 N, got {value}")
        self._samples = int(samples)
        self._expected = e
        noise = TARE_SIGMAS * 1.2533 * math.sqrt(3.0) * force_noise / math.sqrt(samples)
        self._threshold = float(tolerance) + noise
        self._forces: list[FloatArray] = []
        self._offset = np.zeros(3)

    @property
    def done(self) -> bool:
        """Whether all samples have been taken."""
        return len(self._forces) >= self._samples

    @property
    def threshold(self) -> float:
        """Smallest offset magnitude [N] that is removed."""
        return self._threshold

    @property
    def offset(self) -> FloatArray:
        """The offset [N] to subtract from every later sample (zeros until done)."""
        return self._offset.copy()

    def add(self, force: ArrayLike) -> None:
        """Take one sample of the measured force [N] (3,); ignored once done."""
        if self.done:
            return
        self._forces.append(np.asarray(force, dtype=float).copy())
        if self.done:
            offset = np.median(np.array(self._forces), axis=0) - self._expected
            if float(np.linalg.norm(offset)) > self._threshold:
                self._offset = offset
