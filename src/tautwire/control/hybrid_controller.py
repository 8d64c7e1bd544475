"""Hybrid motion-force control (the paper's equ:HybridMFC_combination).

    zeta_t = (I_12 - P) zeta_m + P zeta_f

zeta_m is the motion-control twist (P controllers, individual or coordinated,
converted to the individual task space [v_left, w_left, v_right, w_right]),
zeta_f the force-control twist (equ:force_controller, along the tension
direction) and P the 12x12 projector onto the force-controlled directions.

The paper writes P = diag(f_g, 0, 0, 0); the projector onto the tension
direction is the 3x3 block f_hat f_hat^T (f_hat = f_g / |f_g|, the unit
vector from the gripper towards the contact) in the linear block of each arm
under force control, zeros elsewhere (NOTES.md). It is symmetric and
idempotent, I - P is its complement, and its rank is the number of
force-controlled arms. The combination is done in the individual task space,
also under coordinated control: the relative and absolute motion then acts
on everything but the tension direction of the sensing arm.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.control.force_controller import AdaptiveForceController, ForceController
from tautwire.control.motion_controller import (
    MotionController,
    coordinated_motion_command,
    coordinated_motion_twist,
)
from tautwire.control.quaternion_error import quaternion_error
from tautwire.control.safety_limits import SafetyLimits
from tautwire.control.task_space import CoordinatedPose, DualPose, individual_twist
from tautwire.errors import InvalidArgumentError

FloatArray = NDArray[np.float64]

#: Per-arm optional values, ordered (left, right).
PerArm = Sequence[ArrayLike | None]


def tension_projector(directions: PerArm) -> FloatArray:
    """The projector P onto the force-controlled tension directions.

    Args:
        directions: For (left, right), the tension direction (any non-zero
            length; normalised here) of an arm under force control, or None.

    Returns:
        P with the block f_hat f_hat^T in the linear block of each
        force-controlled arm.  # (12, 12)

    Raises:
        InvalidArgumentError: if ``directions`` does not have two entries or a
            direction is not a finite, non-zero 3-vector.
    """
    if len(directions) != 2:
        raise InvalidArgumentError(
            "directions is a pair (left, right) of 3-vectors or None, "
            f"got {len(directions)} entries"
        )
    P = np.zeros((12, 12))
    for arm, direction in enumerate(directions):
        if direction is None:
            continue
        f_hat = _unit(direction)
        s = slice(6 * arm, 6 * arm + 3)
        P[s, s] = np.outer(f_hat, f_hat)  # (3, 3)
    return P


def hybrid_combination(zeta_m: ArrayLike, zeta_f: ArrayLike, P: ArrayLike) -> FloatArray:
    """zeta_t = (I - P) zeta_m + P zeta_f (equ:HybridMFC_combination).

    Args:
        zeta_m: Motion-control twist.  # (12,)
        zeta_f: Force-control twist.  # (12,)
        P: Projector onto the force-controlled directions.  # (12, 12)

    Returns:
        The task-space twist zeta_t.  # (12,)
    """
    zm = np.asarray(zeta_m, dtype=float)
    P_arr = np.asarray(P, dtype=float)
    zeta_t: FloatArray = zm - P_arr @ zm + P_arr @ np.asarray(zeta_f, dtype=float)
    return zeta_t


class HybridTerms(NamedTuple):
    """The three terms of equ:HybridMFC_combination, for inspection.

    Attributes:
        zeta_m: Motion-control twist, individual task space.  # (12,)
        zeta_f: Force-control twist, individual task space.  # (12,)
        P: Projector onto the force-controlled directions.  # (12, 12)
    """

    zeta_m: FloatArray
    zeta_f: FloatArray
    P: FloatArray


class HybridController:
    """Motion control for both arms with force control along the tension.

    Each call takes the current and desired poses, the desired tension of
    each arm (None: no force control), the measured forces (the force the
    cable exerts on the gripper, weight compensated, world frame; None for an
    arm without sensor), the stiffness estimate k_hat and optionally the
    tension directions from the model (e.g. f_g = p_c - p_g towards the
    estimated contact). Without a direction from the model, f_hat is the
    measured force's direction, and an arm whose measured force is below
    ``min_direction_force`` (slack cable: no direction) stays under motion
    control. The current tension is f_c = f_meas . f_hat.

    Args:
        motion: P controller for each frame (default ``MotionController()``).
        force: Force controller (default ``AdaptiveForceController()``).
        limits: Optional speed limits applied to the output.
        min_direction_force: Smallest measured force [N] whose direction is
            trusted as the tension direction, > 0.

    Raises:
        InvalidArgumentError: if ``min_direction_force`` is not finite and positive.
    """

    def __init__(
        self,
        motion: MotionController | None = None,
        force: ForceController | None = None,
        limits: SafetyLimits | None = None,
        min_direction_force: float = 0.5,
    ) -> None:
        if not math.isfinite(min_direction_force) or min_direction_force <= 0.0:
            raise InvalidArgumentError(
                f"min_direction_force must be a finite force > 0 [N], got {min_direction_force}"
            )
        self.motion = motion if motion is not None else MotionController()
        self.force = force if force is not None else AdaptiveForceController()
        self.limits = limits
        self.min_direction_force = float(min_direction_force)

    def __call__(
        self,
        current: DualPose,
        desired: DualPose | CoordinatedPose,
        tension_desired: Sequence[float | None] = (None, None),
        force_measured: PerArm = (None, None),
        k_hat: float | Sequence[float | None] | None = None,
        directions: PerArm = (None, None),
    ) -> FloatArray:
        """The individual task-space twist zeta_t for one control period.

        Args:
            current: Current poses of both grippers, world frame.
            desired: Desired poses (individual control) or desired absolute
                and relative pose (coordinated control).
            tension_desired: f_d [N] for (left, right), None for no force control.
            force_measured: Measured force [N] for (left, right), world frame,
                or None.  # (3,) each
            k_hat: Stiffness estimate [N/m], one for both arms or a pair.
            directions: Tension directions from the model for (left, right),
                or None to use the measured force's direction.  # (3,) each

        Returns:
            zeta_t = [v_left, w_left, v_right, w_right] [m/s, rad/s], world
            frame, speed-limited when ``limits`` is set.  # (12,)
        """
        twist = self._motion(current, desired)
        k_hats = _per_arm_k_hat(k_hat)
        for arm in (0, 1):
            f_d = tension_desired[arm]
            if f_d is None:
                continue
            resolved = self._tension(force_measured[arm], directions[arm])
            if resolved is None:
                continue
            f_hat, f_c = resolved
            speed = self.force.speed(f_d, f_c, k_hats[arm])
            # (I - P) v_m + P v_f with P = f_hat f_hat^T and v_f = -speed f_hat
            v = twist[6 * arm : 6 * arm + 3]
            v -= f_hat * (float(f_hat @ v) + speed)
        if self.limits is not None:
            return self.limits.limit_twist(twist)
        return twist

    def terms(
        self,
        current: DualPose,
        desired: DualPose | CoordinatedPose,
        tension_desired: Sequence[float | None] = (None, None),
        force_measured: PerArm = (None, None),
        k_hat: float | Sequence[float | None] | None = None,
        directions: PerArm = (None, None),
    ) -> HybridTerms:
        """zeta_m, zeta_f and P of equ:HybridMFC_combination, built explicitly.

        Same arguments as :meth:`__call__`; ``hybrid_combination(*terms)``
        equals the call's result before speed limiting.
        """
        zeta_m = self._motion(current, desired)
        zeta_f = np.zeros(12)
        k_hats = _per_arm_k_hat(k_hat)
        used: list[FloatArray | None] = [None, None]
        for arm in (0, 1):
            f_d = tension_desired[arm]
            if f_d is None:
                continue
            resolved = self._tension(force_measured[arm], directions[arm])
            if resolved is None:
                continue
            f_hat, f_c = resolved
            zeta_f[6 * arm : 6 * arm + 3] = self.force.velocity(f_d, f_c, f_hat, k_hats[arm])
            used[arm] = f_hat
        return HybridTerms(zeta_m, zeta_f, tension_projector(used))

    def coordinated(
        self,
        current: DualPose,
        desired: CoordinatedPose,
        tension_desired: float | None,
        tension_current: float,
        k_hat: float | None = None,
        relative_speed: float = 0.0,
    ) -> FloatArray:
        """Coordinated hybrid control: force control of the relative distance.

        The cable runs between the two grippers, so its tension is set by
        their distance |p_rel|. With u = p_rel / |p_rel|, the projector acts
        on the relative linear block of the coordinated task space
        [v_abs, w_abs, v_rel, w_rel]: P = u u^T there, zeros elsewhere, and

            v_rel = (I - u u^T) v_rel,m + u (k_f (f_d - f_c) + relative_speed),

        the absolute motion and the relative orientation stay under motion
        control. A growing distance raises the tension, so the force
        controller's speed is along +u.

        Args:
            current: Current poses of both grippers, world frame.
            desired: Desired absolute and relative pose.
            tension_desired: f_d [N], or None for pure motion control along u
                (then ``relative_speed`` alone sets the distance's rate).
            tension_current: Measured tension f_c [N] of the cable between them.
            k_hat: Stiffness estimate [N/m] of the cable between them.
            relative_speed: Feed-forward rate [m/s] of the distance |p_rel|
                (sliding: the grippers part at this speed).

        Returns:
            The individual task-space twist [v_left, w_left, v_right, w_right]
            [m/s, rad/s], speed-limited when ``limits`` is set.  # (12,)
        """
        zeta = coordinated_motion_command(self.motion, desired, current)
        p_rel = current.left.position - current.right.position
        distance = math.sqrt(float(p_rel @ p_rel))
        if distance > 1e-9:
            u = p_rel / distance
            along = relative_speed
            if tension_desired is not None:
                along += self.force.speed(tension_desired, tension_current, k_hat)
            v_rel = zeta[6:9]
            v_rel -= u * (float(u @ v_rel) - along)
        if self.limits is not None:
            _limit_coordinated(zeta, self.limits)
        twist = individual_twist(zeta, current)
        if self.limits is not None:
            return self.limits.limit_twist(twist)
        return twist

    def _motion(self, current: DualPose, desired: DualPose | CoordinatedPose) -> FloatArray:
        if isinstance(desired, CoordinatedPose):
            return coordinated_motion_twist(self.motion, desired, current)
        k_p, k_o = self.motion.k_p, self.motion.k_o
        twist = np.empty(12)
        twist[0:3] = desired.left.position
        twist[0:3] -= current.left.position
        twist[0:3] *= k_p
        twist[3:6] = quaternion_error(desired.left.orientation, current.left.orientation)
        twist[3:6] *= k_o
        twist[6:9] = desired.right.position
        twist[6:9] -= current.right.position
        twist[6:9] *= k_p
        twist[9:12] = quaternion_error(desired.right.orientation, current.right.orientation)
        twist[9:12] *= k_o
        return twist

    def _tension(
        self, force: ArrayLike | None, direction: ArrayLike | None
    ) -> tuple[FloatArray, float] | None:
        """(f_hat, f_c) of one arm, or None when the arm stays under motion control."""
        if force is None:
            return None
        f = np.asarray(force, dtype=float)
        if direction is not None:
            f_hat = _unit(direction)
            return f_hat, float(f_hat @ f)
        x, y, z = f
        magnitude = math.sqrt(x * x + y * y + z * z)
        if not magnitude >= self.min_direction_force:  # also catches NaN
            return None
        return f / magnitude, magnitude


def _unit(direction: ArrayLike) -> FloatArray:
    d = np.asarray(direction, dtype=float)
    if d.shape != (3,) or not np.all(np.isfinite(d)):
        raise InvalidArgumentError(f"a tension direction is 3 finite numbers, got {direction!r}")
    x, y, z = d
    n = math.sqrt(x * x + y * y + z * z)
    if n < 1e-12:
        raise InvalidArgumentError("a tension direction must not be zero")
    return d / n


def _per_arm_k_hat(
    k_hat: float | Sequence[float | None] | None,
) -> tuple[float | None, float | None]:
    if k_hat is None or isinstance(k_hat, int | float):
        return (k_hat, k_hat)
    if len(k_hat) != 2:
        raise InvalidArgumentError(
            f"k_hat is one stiffness [N/m] or a pair (left, right), got {k_hat!r}"
        )
    return (k_hat[0], k_hat[1])


def _limit_coordinated(zeta: FloatArray, limits: SafetyLimits) -> None:
    """Bring a coordinated twist within each arm's speed limits, the relative motion first.

    Scaling each arm's velocity on its own (``limit_twist``) scales the two
    by different factors while the absolute motion runs at the limit, and
    the difference leaks the absolute velocity into the grippers' distance:
    random board 1652323633's C carried both grippers 111 mm to the clip at
    the limit, their distance grew by 2 mm, and the tension between them
    rose from 3 to 13.6 N against a force controller asking for 3. Here the
    relative velocity (the tension's force control) is kept whole, and only
    the absolute velocity is scaled: by the largest s in [0, 1] with
    |s v_abs +- v_rel / 2| within each arm's limit. The angular velocities of
    both arms are scaled by one common factor. In place.

    Args:
        zeta: [v_abs, w_abs, v_rel, w_rel] [m/s, rad/s], world frame.  # (12,)
        limits: The arms' speed limits.
    """
    v_abs, v_rel = zeta[0:3], zeta[6:9]
    half = 0.5 * v_rel
    scale = 1.0
    for sign, limit in zip((1.0, -1.0), limits.max_linear_speed, strict=True):
        b = sign * half
        bb = float(b @ b)
        if bb >= limit * limit:  # the relative motion alone is at the limit
            v_rel *= limit / math.sqrt(bb)
            half = 0.5 * v_rel
            bb = limit * limit
        aa = float(v_abs @ v_abs)
        if aa < 1e-18:
            continue
        ab = float(v_abs @ b)
        root = (-ab + math.sqrt(max(ab * ab - aa * (bb - limit * limit), 0.0))) / aa
        scale = min(scale, max(root, 0.0))
    v_abs *= scale
    w_abs, w_rel = zeta[3:6], zeta[9:12]
    # each arm's angular velocity is about bounded by |w_abs| + |w_rel|: one
    # common factor keeps their ratio (the last limit_twist bounds it exactly)
    w_size = math.sqrt(float(w_abs @ w_abs)) + math.sqrt(float(w_rel @ w_rel))
    w_limit = min(limits.max_angular_speed)
    if w_size > w_limit:
        w_abs *= w_limit / w_size
        w_rel *= w_limit / w_size
