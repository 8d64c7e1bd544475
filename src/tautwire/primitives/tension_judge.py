"""Whether a tension has been held: the success test of the tensioning primitives."""

from __future__ import annotations

from tautwire.primitives.low_pass import TIME_CONSTANT, LowPass


class TensionJudge:
    """Tracks a low-passed tension and how long it has stayed near a set point.

    Args:
        force: Set point f_d [N].
        tolerance: Allowed error, a fraction of ``force`` (at least 0.05 N).
        hold_time: How long [s] the tension must stay within the band.
        time_constant: Of the low-pass [s] the tension is judged on.
    """

    def __init__(
        self,
        force: float,
        tolerance: float = 0.1,
        hold_time: float = 0.5,
        time_constant: float = TIME_CONSTANT,
    ) -> None:
        self.force = float(force)
        self.band = max(float(tolerance) * self.force, 0.05)
        self.hold_time = float(hold_time)
        self._low_pass: LowPass[float] = LowPass(time_constant)
        self._within_since: float | None = None

    @property
    def smoothed(self) -> float | None:
        """The low-passed tension [N] (None before the first sample)."""
        return self._low_pass.value

    def reset(self) -> None:
        """Start the hold afresh (the low-passed tension is kept)."""
        self._within_since = None

    def update(self, time: float, tension: float) -> bool:
        """Add the tension [N] measured at ``time`` [s]; True once it has been held."""
        smoothed = self._low_pass.update(time, tension)
        if abs(smoothed - self.force) <= self.band:
            if self._within_since is None:
                self._within_since = time
        else:
            self._within_since = None
        return self._within_since is not None and time - self._within_since >= self.hold_time
