"""Safety limits: per-arm speed limits and the force limit.

Speeds are limited per arm and per block (linear, angular) of the individual
12-D twist [v_left, w_left, v_right, w_right]: a block whose norm exceeds its
limit is scaled down to the limit, keeping its direction. The force limit is a
check on the measured force [N]; a breach is reported as a small result and,
on request, raised as :class:`ForceLimitExceededError`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError, TautwireError

FloatArray = NDArray[np.float64]

_ARMS = ("left", "right")


class ForceLimitExceededError(TautwireError):
    """The force measured at a wrist exceeded the force limit.

    Attributes:
        force: Magnitude [N] of the measured force.
        limit: The force limit [N].
        arm: The arm whose sensor measured it (``"left"`` or ``"right"``).
    """

    def __init__(self, force: float, limit: float, arm: str) -> None:
        super().__init__(
            f"force {force:.3g} N on the {arm} wrist exceeds the force limit {limit:.3g} N"
        )
        self.force = force
        self.limit = limit
        self.arm = arm


class ForceCheck(NamedTuple):
    """Result of :meth:`SafetyLimits.check_force`.

    Attributes:
        within_limit: Whether |f| <= limit.
        force: Magnitude [N] of the measured force.
        limit: The force limit [N].
        arm: The arm of the sensor.
    """

    within_limit: bool
    force: float
    limit: float
    arm: str


class SafetyLimits:
    """Speed limits per arm and a force limit.

    Args:
        max_force: Force limit [N] on the magnitude of a measured force, > 0.
        max_linear_speed: Limit [m/s] on |v| of each arm, > 0, or a pair
            (left, right).
        max_angular_speed: Limit [rad/s] on |w| of each arm, > 0, or a pair
            (left, right).

    Raises:
        InvalidArgumentError: if a limit is not finite and positive.
    """

    def __init__(
        self,
        max_force: float,
        max_linear_speed: float | tuple[float, float] = 0.1,
        max_angular_speed: float | tuple[float, float] = 1.0,
    ) -> None:
        self.max_force = _positive("max_force", max_force, "N")
        self.max_linear_speed = _pair("max_linear_speed", max_linear_speed, "m/s")
        self.max_angular_speed = _pair("max_angular_speed", max_angular_speed, "rad/s")
        # block limits in task-space order: v_left, w_left, v_right, w_right
        self._block_limits = (
            self.max_linear_speed[0],
            self.max_angular_speed[0],
            self.max_linear_speed[1],
            self.max_angular_speed[1],
        )

    def limit_twist(self, twist: ArrayLike) -> FloatArray:
        """Scale each 3-D block of the twist down to its speed limit, keeping its direction.

        Args:
            twist: Individual twist [v_left, w_left, v_right, w_right]
                in [m/s, rad/s].  # (12,)

        Returns:
            The limited twist (a new array).  # (12,)

        Raises:
            InvalidArgumentError: if the twist does not have shape (12,) or is not finite.
        """
        out = np.array(twist, dtype=float)
        if out.shape != (12,):
            raise InvalidArgumentError(f"a twist is 12 finite numbers, got shape {out.shape}")
        values = out.tolist()
        if not all(map(math.isfinite, values)):
            raise InvalidArgumentError("a twist is 12 finite numbers, got a NaN or infinity")
        for block, limit in enumerate(self._block_limits):
            i = 3 * block
            x, y, z = values[i : i + 3]
            norm = math.sqrt(x * x + y * y + z * z)
            if norm > limit:
                out[i : i + 3] *= limit / norm
        return out

    def check_force(self, force: ArrayLike, arm: str = "left") -> ForceCheck:
        """Compare the magnitude of a measured force with the force limit.

        Args:
            force: Measured force [N].  # (3,)
            arm: ``"left"`` or ``"right"``.

        Returns:
            The comparison; ``within_limit`` is False on a breach.

        Raises:
            InvalidArgumentError: for another arm name or a force that is not
                3 finite numbers.
        """
        if arm not in _ARMS:
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
        f = np.asarray(force, dtype=float)
        if f.shape != (3,) or not np.all(np.isfinite(f)):
            raise InvalidArgumentError(f"a force is 3 finite numbers [N], got {force!r}")
        magnitude = float(np.linalg.norm(f))
        return ForceCheck(magnitude <= self.max_force, magnitude, self.max_force, arm)

    def enforce_force(self, force: ArrayLike, arm: str = "left") -> ForceCheck:
        """Like :meth:`check_force`, but raise on a breach.

        Raises:
            ForceLimitExceededError: if |force| exceeds the force limit.
        """
        check = self.check_force(force, arm)
        if not check.within_limit:
            raise ForceLimitExceededError(check.force, check.limit, arm)
        return check


def _positive(name: str, value: float, unit: str) -> float:
    if not isinstance(value, int | float) or not math.isfinite(value) or value <= 0.0:
        raise InvalidArgumentError(f"{name} must be a finite number > 0 [{unit}], got {value!r}")
    return float(value)


def _pair(name: str, value: float | tuple[float, float], unit: str) -> tuple[float, float]:
    if isinstance(value, tuple | list):
        if len(value) != 2:
            raise InvalidArgumentError(
                f"{name} is one limit [{unit}] or a pair (left, right), got {value!r}"
            )
        return (_positive(name, value[0], unit), _positive(name, value[1], unit))
    v = _positive(name, value, unit)
    return (v, v)
