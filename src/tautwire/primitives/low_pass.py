"""A first-order low-pass filter of a measured value (a tension, a direction, a height)."""

from __future__ import annotations

from typing import Generic, TypeVar

import numpy as np

T = TypeVar("T", float, np.ndarray)

#: The primitives' default time constant [s]: 12 control periods at 4 ms.
TIME_CONSTANT = 0.048


class LowPass(Generic[T]):
    """x += alpha (sample - x) with alpha = dt / time_constant (at most 1).

    Single samples carry the sensor's noise; the primitives judge levels
    (tension held, cable seated, direction) on the low-passed value.

    Args:
        time_constant: tau [s], > 0.
    """

    def __init__(self, time_constant: float = TIME_CONSTANT) -> None:
        self.time_constant = float(time_constant)
        self.value: T | None = None
        self._last = 0.0

    def update(self, time: float, sample: T) -> T:
        """Add the ``sample`` measured at ``time`` [s]; return the low-passed value."""
        if self.value is None:
            self.value = sample
        else:
            alpha = min(max(time - self._last, 0.0) / self.time_constant, 1.0)
            self.value = self.value + alpha * (sample - self.value)
        self._last = time
        return self.value

    def reset(self) -> None:
        """Forget the value."""
        self.value = None
