"""Whether a tension has been held: the success test of the tensioning primitives."""

from __future__ import annotations

#: Weight of a new sample in the low-passed tension (time constant 12 control
#: periods, ~0.05 s at 4 ms): single samples carry the sensor's noise, not
#: the tension's level.
SMOOTHING = 1.0 / 12.0


class TensionJudge:
    """Tracks a low-passed tension and how long it has stayed near a set point.

    Args:
        force: Set point f_d [N].
        tolerance: Allowed error, a fraction of ``force`` (at least 0.05 N).
        hold_time: How long [s] the tension must stay within the band.
    """

    def __init__(self, force: float, tolerance: float = 0.1, hold_time: float = 0.5) -> None:
        self.force = float(force)
        self.band = max(float(tolerance) * self.force, 0.05)
        self.hold_time = float(hold_time)
        self.smoothed: float | None = None
        self._within_since: float | None = None

    def update(self, time: float, tension: float) -> bool:
        """Add the tension [N] measured at ``time`` [s]; True once it has been held."""
        if self.smoothed is None:
            self.smoothed = tension
        else:
            self.smoothed += SMOOTHING * (tension - self.smoothed)
        if abs(self.smoothed - self.force) <= self.band:
            if self._within_since is None:
                self._within_since = time
        else:
            self._within_since = None
        return self._within_since is not None and time - self._within_since >= self.hold_time
