"""Force controller along the tension direction (the paper's equ:force_controller).

    x_dot_f = k_f (f_d - f_c)

with f_d the **desired** and f_c the **current** tension [N] (the paper's
sentence after the equation swaps the two words) and x_dot_f [m/s] the speed
of the gripper **away from** the contact: too little tension (f_d > f_c) pulls
the gripper back along -f_hat, where f_hat is the unit tension direction,
pointing from the gripper towards the contact (the measured force that the
cable exerts on the gripper points that way).

Adaptive gain. The paper sets k_f = 1 / k_hat with k_hat the online stiffness
estimate (equ:spring_measurement); that has the units m/N, not m/(N s). Here
k_f = lambda / k_hat with lambda a bandwidth [1/s], and k_hat is clamped to
[k_hat_min, k_hat_max] so that one bad estimate cannot drive the force past
the robot's limit (the paper's three tensioning failures).

Stability (discrete time, control period dt, cable f = k x with x the
extension): one step gives f_{n+1} = f_n + k dt k_f (f_d - f_n), so the error
obeys

    e_{n+1} = (1 - a) e_n,    a = lambda dt k / k_hat,

which converges iff 0 < a < 2 (monotonically iff a <= 1). If the measurement
lags the command by one period (the robot acts on f_{n-1}),
e_{n+1} = e_n - a e_{n-1}, whose roots of z^2 - z + a stay inside the unit
circle iff a < 1. The stiffness ratio that is tolerated is therefore

    k / k_hat < 2 / (lambda dt)    (no delay),    k / k_hat < 1 / (lambda dt)    (one-period delay).

For k_hat anywhere in [0.1 k, 10 k], lambda < 0.2 / dt (no delay) or
lambda < 0.1 / dt (delay) suffices: 50 1/s and 25 1/s at dt = 4 ms. The
default lambda = 10 1/s has a = 0.04 at k_hat = k (time constant 0.1 s),
a = 0.4 at k_hat = k / 10 and a = 0.004 at k_hat = 10 k (time constant 1 s).
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError

FloatArray = NDArray[np.float64]


def _check_positive(name: str, value: float, unit: str) -> float:
    if not math.isfinite(value) or value <= 0.0:
        raise InvalidArgumentError(f"{name} must be a finite number > 0 [{unit}], got {value}")
    return float(value)


class ForceController(ABC):
    """Inverse-damping force controller x_dot_f = k_f (f_d - f_c) (equ:force_controller).

    Args:
        max_speed: Optional bound [m/s] on |x_dot_f|; None for no bound.
    """

    def __init__(self, max_speed: float | None = None) -> None:
        self.max_speed = (
            None if max_speed is None else _check_positive("max_speed", max_speed, "m/s")
        )

    @abstractmethod
    def gain(self, k_hat: float | None = None) -> float:
        """Damping factor k_f [m/(N s)] for the stiffness estimate ``k_hat`` [N/m]."""

    def speed(self, f_desired: float, f_current: float, k_hat: float | None = None) -> float:
        """x_dot_f = k_f (f_d - f_c) [m/s], positive away from the contact.

        Args:
            f_desired: Desired tension f_d [N].
            f_current: Current tension f_c [N] (weight compensated).
            k_hat: Stiffness estimate [N/m] (used by the adaptive controller).

        Returns:
            Speed [m/s] of the gripper away from the contact, bounded by
            ``max_speed`` when set.
        """
        v = self.gain(k_hat) * (f_desired - f_current)
        if self.max_speed is not None:
            v = min(max(v, -self.max_speed), self.max_speed)
        return v

    def velocity(
        self,
        f_desired: float,
        f_current: float,
        direction: ArrayLike,
        k_hat: float | None = None,
    ) -> FloatArray:
        """Linear velocity [m/s] of the gripper, world frame.

        Args:
            f_desired: Desired tension f_d [N].
            f_current: Current tension f_c [N].
            direction: Unit tension direction f_hat from the gripper towards
                the contact.  # (3,)
            k_hat: Stiffness estimate [N/m].

        Returns:
            -x_dot_f f_hat: too little tension moves the gripper away from the
            contact.  # (3,)
        """
        return -self.speed(f_desired, f_current, k_hat) * np.asarray(direction, dtype=float)


class AdaptiveForceController(ForceController):
    """Adaptive force controller with k_f = lambda / clamp(k_hat).

    Args:
        bandwidth: lambda [1/s], > 0; the closed-loop rate at k_hat = k.
        k_hat_min: Lower clamp [N/m] of the stiffness estimate (bounds the gain).
        k_hat_max: Upper clamp [N/m] of the stiffness estimate.
        max_speed: Optional bound [m/s] on |x_dot_f|.

    Raises:
        InvalidArgumentError: if a parameter is not finite and positive, or
            k_hat_min > k_hat_max.
    """

    def __init__(
        self,
        bandwidth: float = 10.0,
        k_hat_min: float = 5.0,
        k_hat_max: float = 5000.0,
        max_speed: float | None = None,
    ) -> None:
        super().__init__(max_speed)
        self.bandwidth = _check_positive("bandwidth", bandwidth, "1/s")
        self.k_hat_min = _check_positive("k_hat_min", k_hat_min, "N/m")
        self.k_hat_max = _check_positive("k_hat_max", k_hat_max, "N/m")
        if self.k_hat_min > self.k_hat_max:
            raise InvalidArgumentError(
                f"k_hat_min ({k_hat_min} N/m) must not exceed k_hat_max ({k_hat_max} N/m)"
            )

    def clamp(self, k_hat: float | None) -> float:
        """k_hat [N/m] clamped to [k_hat_min, k_hat_max]; None or NaN gives k_hat_max.

        An unknown estimate falls back to the stiffest (slowest, safest) value.
        """
        if k_hat is None or not math.isfinite(k_hat):
            return self.k_hat_max
        return min(max(float(k_hat), self.k_hat_min), self.k_hat_max)

    def gain(self, k_hat: float | None = None) -> float:
        """k_f = lambda / clamp(k_hat) [m/(N s)]."""
        return self.bandwidth / self.clamp(k_hat)

    def max_stiffness_ratio(self, dt: float, delayed: bool = False) -> float:
        """Largest k / k_hat for which the loop with the plant f = k x converges.

        Args:
            dt: Control period [s].
            delayed: Whether the measurement lags the command by one period.

        Returns:
            2 / (lambda dt) without delay, 1 / (lambda dt) with one period of delay.
        """
        _check_positive("dt", dt, "s")
        return (1.0 if delayed else 2.0) / (self.bandwidth * dt)


class FixedGainForceController(ForceController):
    """Baseline force controller with a constant damping factor k_f.

    With the plant f = k x, it converges iff k k_f dt < 2 (one-period delay:
    < 1), and its speed of response scales with the unknown k.

    Args:
        k_f: Damping factor [m/(N s)], > 0.
        max_speed: Optional bound [m/s] on |x_dot_f|.

    Raises:
        InvalidArgumentError: if k_f is not finite and positive.
    """

    def __init__(self, k_f: float = 0.01, max_speed: float | None = None) -> None:
        super().__init__(max_speed)
        self.k_f = _check_positive("k_f", k_f, "m/(N s)")

    def gain(self, k_hat: float | None = None) -> float:
        """The constant k_f [m/(N s)]; ``k_hat`` is ignored."""
        return self.k_f
