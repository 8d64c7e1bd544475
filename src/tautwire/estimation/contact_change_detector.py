"""Contact change detection by innovation gating (an addition to the paper).

When a second fixture enters the cable's path the measured lines stop passing
through the estimated contact. The paper's filter only noticed through its
process noise (about half a circle, an 86 mm error spike). Here each Kalman
innovation y (2-D, in the plane normal to the force) is tested with its
normalised innovation squared

    NIS = y' S^-1 y,     S = H P H' + R,

which is chi-square with 2 degrees of freedom while the contact is static.
A sample is *gated* when NIS > ``threshold`` and |y| > ``min_innovation``;
gated samples are not fused. ``window`` consecutive gated samples declare a
change at the last of them; the filter then restarts from the gated run.

False alarms: with the default threshold (the chi-square(2) 0.999 quantile,
13.82) a correct model gates one sample in 1000, and ``window = 3``
consecutive ones happen about once in 10^9 samples. ``min_innovation``
(default 1 mm) keeps unmodelled millimetre effects (cable radius, a peg's
rolling tangent point, residual sag) from raising alarms once P is tiny.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from tautwire.errors import InvalidArgumentError

#: chi-square quantile with 2 degrees of freedom: -2 ln(1 - p), p = 0.999.
CHI2_2DOF_999 = -2.0 * math.log(1.0 - 0.999)


class ChangeTest(NamedTuple):
    """Result of :meth:`ContactChangeDetector.test`.

    Attributes:
        gated: The sample is inconsistent with the current contact (do not fuse).
        changed: A change is declared at this sample.
        first_gated: Sample index of the first gated sample of the current
            run (None when the sample is not gated).
    """

    gated: bool
    changed: bool
    first_gated: int | None


class ContactChangeDetector:
    """Declare a contact change after ``window`` consecutive gated innovations.

    Args:
        threshold: NIS gate (> 0); default the chi-square(2) 0.999 quantile.
        window: Consecutive gated samples that declare a change (>= 1).
        min_innovation: Innovations shorter than this [m] are never gated.
    """

    def __init__(
        self,
        threshold: float = CHI2_2DOF_999,
        window: int = 3,
        min_innovation: float = 1e-3,
    ) -> None:
        if not (threshold > 0.0 and math.isfinite(threshold)):
            raise InvalidArgumentError(f"threshold must be a finite NIS > 0, got {threshold}")
        if window < 1:
            raise InvalidArgumentError(f"window must be >= 1 sample, got {window}")
        if min_innovation < 0.0 or not math.isfinite(min_innovation):
            raise InvalidArgumentError(f"min_innovation must be >= 0 m, got {min_innovation}")
        self.threshold = float(threshold)
        self.window = int(window)
        self.min_innovation = float(min_innovation)
        self._run = 0
        self._first: int | None = None

    @property
    def run_length(self) -> int:
        """Number of consecutive gated samples so far."""
        return self._run

    def reset(self) -> None:
        """Forget the current run of gated samples."""
        self._run = 0
        self._first = None

    def test(self, index: int, nis: float, innovation_norm: float) -> ChangeTest:
        """Test one innovation.

        Args:
            index: The sample's index.
            nis: y' S^-1 y.
            innovation_norm: |y| [m].

        Returns:
            Whether it is gated, whether a change is declared, and where the
            run of gated samples began.
        """
        if nis > self.threshold and innovation_norm > self.min_innovation:
            if self._run == 0:
                self._first = index
            self._run += 1
            first = self._first
            if self._run >= self.window:
                self.reset()
                return ChangeTest(True, True, first)
            return ChangeTest(True, False, first)
        self.reset()
        return ChangeTest(False, False, None)
