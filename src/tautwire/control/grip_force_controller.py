"""Gripping-force PI controller for sliding (the paper's equ:Gripping_Force_Controller).

The paper sets the finger distance

    p_finger = k_f (f_slid - f_c) + k_i integral (f_slid - f_c) dt

from the error between the desired friction (sliding) tension f_slid and the
measured tension f_c. Our grippers take a **grip-force** command instead of a
finger distance, so the same PI law here outputs the grip force F_grip [N]:

    F_grip = k_p e + k_i integral e dt,    e = f_slid - f_c,

clamped to [min_grip_force, max_grip_force] (YuMi SmartGripper: 20 N). Too little tension
(e > 0) means the cable slides too easily: the gripper squeezes harder. The
integral absorbs the unknown friction coefficient (the paper: different cable
thicknesses). Anti-windup: the integral is frozen while the output is
saturated and the error pushes further into saturation, and it is kept in
[min_grip_force, max_grip_force].

The floor ``min_grip_force`` keeps the fingers on the cable: pads with lips
hold a cable only while they squeeze it; with the grip near zero a hanging
tail or a cable caught beyond the gripper wedges the fingers apart over the
lips and the cable drops out (random boards 1548504588 and 1385678398, seed
16: the grip fell to 0.0-0.4 N under a tension spike, the fingers opened
from 4-6 mm to 7-9.5 mm and the cable left them). Below the floor the
tension simply stays above f_slid.

Stability with a sliding Coulomb contact, f_c = 2 mu F_grip (two finger pads,
unknown mu), measured one period after the command: with g = 2 mu the error
obeys e_{n+1} = (1 - g (k_p + k_i dt)) e_n + g k_p e_{n-1}, which is stable
(Jury) iff

    g k_p < 1    and    g (2 k_p + k_i dt) < 2.

The defaults k_p = 0.1, k_i = 10 1/s at dt = 4 ms allow mu < 4.
"""

from __future__ import annotations

import math

from tautwire.errors import InvalidArgumentError

#: Grip force limit [N] of the YuMi SmartGripper.
YUMI_MAX_GRIP_FORCE = 20.0


class GripForceController:
    """PI controller from the friction-tension error to the grip force.

    Args:
        k_p: Proportional gain [N/N], >= 0.
        k_i: Integral gain [1/s], > 0.
        max_grip_force: Upper limit [N] of the grip-force command, > 0.
        initial_grip_force: Initial value [N] of the integral term (the grip
            force at the start of sliding), in [min_grip_force, max_grip_force].
        min_grip_force: Lower limit [N] of the grip-force command, in
            [0, max_grip_force).

    Raises:
        InvalidArgumentError: for a negative, zero or non-finite gain or limit,
            or an initial grip force outside [min_grip_force, max_grip_force].
    """

    def __init__(
        self,
        k_p: float = 0.1,
        k_i: float = 10.0,
        max_grip_force: float = YUMI_MAX_GRIP_FORCE,
        initial_grip_force: float = 0.0,
        min_grip_force: float = 0.0,
    ) -> None:
        if not math.isfinite(k_p) or k_p < 0.0:
            raise InvalidArgumentError(f"k_p must be a finite gain >= 0 [N/N], got {k_p}")
        if not math.isfinite(k_i) or k_i <= 0.0:
            raise InvalidArgumentError(f"k_i must be a finite gain > 0 [1/s], got {k_i}")
        if not math.isfinite(max_grip_force) or max_grip_force <= 0.0:
            raise InvalidArgumentError(
                f"max_grip_force must be a finite force > 0 [N], got {max_grip_force}"
            )
        if not math.isfinite(min_grip_force) or not 0.0 <= min_grip_force < max_grip_force:
            raise InvalidArgumentError(
                f"min_grip_force must be in [0, {max_grip_force}) N, got {min_grip_force}"
            )
        if (
            not math.isfinite(initial_grip_force)
            or not min_grip_force <= initial_grip_force <= max_grip_force
        ):
            raise InvalidArgumentError(
                f"initial_grip_force must be in [{min_grip_force:g}, {max_grip_force}] N,"
                f" got {initial_grip_force}"
            )
        self.k_p = float(k_p)
        self.k_i = float(k_i)
        self.max_grip_force = float(max_grip_force)
        self.min_grip_force = float(min_grip_force)
        self.initial_grip_force = float(initial_grip_force)
        self.integral = self.initial_grip_force
        self.grip_force = self.initial_grip_force

    def reset(self, grip_force: float | None = None) -> None:
        """Reset the integral to ``grip_force`` [N] (default: the initial grip force)."""
        value = self.initial_grip_force if grip_force is None else float(grip_force)
        self.integral = min(max(value, self.min_grip_force), self.max_grip_force)
        self.grip_force = self.integral

    def update(self, f_slid: float, f_current: float, dt: float) -> float:
        """One control period: the grip force [N] for the next period.

        Args:
            f_slid: Desired friction (sliding) tension f_slid [N].
            f_current: Measured tension f_c [N].
            dt: Control period [s], > 0.

        Returns:
            Grip force command [N] in [min_grip_force, max_grip_force].

        Raises:
            InvalidArgumentError: if dt is not finite and positive.
        """
        if not math.isfinite(dt) or dt <= 0.0:
            raise InvalidArgumentError(f"dt must be a finite period > 0 [s], got {dt}")
        e = f_slid - f_current
        proportional = self.k_p * e
        saturated_high = proportional + self.integral >= self.max_grip_force and e > 0.0
        low = self.min_grip_force
        saturated_low = proportional + self.integral <= low and e < 0.0
        if not (saturated_high or saturated_low):  # conditional integration (anti-windup)
            self.integral = min(max(self.integral + self.k_i * e * dt, low), self.max_grip_force)
        self.grip_force = min(max(proportional + self.integral, low), self.max_grip_force)
        return self.grip_force
