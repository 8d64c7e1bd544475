"""Whether a cable that should be taut has gone slack for too long."""

from __future__ import annotations


class SlackWatch:
    """Times how long the tension stays below a fraction of its set point.

    Args:
        duration: Longest time [s] the cable may stay slack.
        fraction: Below this fraction of the set point the cable counts as slack.
    """

    def __init__(self, duration: float, fraction: float = 0.2) -> None:
        self.duration = float(duration)
        self.fraction = float(fraction)
        self._since: float | None = None

    def update(self, time: float, tension: float, set_point: float) -> bool:
        """Add the tension [N] at ``time`` [s]; True once it has been slack too long."""
        if tension >= self.fraction * set_point:
            self._since = None
            return False
        if self._since is None:
            self._since = time
        return time - self._since > self.duration

    def reset(self) -> None:
        """Forget a slack spell in progress."""
        self._since = None
