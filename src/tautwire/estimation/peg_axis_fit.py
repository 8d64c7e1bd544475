"""A peg's axis by batch least squares over every tangent line, its radius held fixed.

A cable that leaves a peg runs along a tangent of the circle of radius R
about the peg's axis. In the plane normal to the axis, each line (a point q
on it, the unit normal n from the line towards the axis) then says

    n . c = n . q + R,

one linear equation for the axis's position c. With R held at its prior
(peg radius + cable radius + :data:`~tautwire.estimation.round_contact.RADIUS_MARGIN`)
the lines of a partial wrap fix c; estimating R as well leaves R and c's
position along the wrap's bisector nearly interchangeable. The batch weighs
every line alike, however old: the Kalman filter's process noise let its
axis follow the lines of the last part of the wrap, whose offsets wander
by millimetres as the coarse cable's vertices leave the peg (robustness
trials 29, 38, 49, 59: the filter's axis 8-17 mm off, this fit 0.4-2.7 mm on
the same lines).

The covariance is honest about that wander: the weighted residuals' scatter
replaces the noise model's, and counts only as many independent lines as the
wrap has :data:`BLOCK_ANGLE` steps (neighbouring lines err together), plus
what R's prior std does to c (a consider parameter).

A second consider parameter is R's drift along the wrap: where the cable
first bears on a peg it bends round it less tightly than after it has
wrapped further, so the lines' offsets drift from one end of the wrap to
the other (:data:`OFFSET_DRIFT`). A drift that R held fixed cannot absorb
moves the axis along the lines, by about 2 drift / spread [rad]: over a
short wrap that is the largest error of the fit, however well the lines
fit one another.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.axis_plane import axis_plane

FloatArray = NDArray[np.float64]

#: Turn [rad] of the cable's direction over which its lines' errors count as one.
BLOCK_ANGLE = math.radians(5.0)
#: Smallest spread [rad] of line directions before the fit gives an estimate.
MIN_SPREAD = math.radians(15.0)
#: Std [m] of the lines' offset drift between the middle of a wrap and either
#: end (a consider parameter, see the module docstring). Measured against the
#: true axis: robustness trials 2, 3, 4, 6, 9 of seed 0 (wraps of 49-138 deg)
#: drifted 0.3-2.2 mm; random board 1098434850's I about peg F4, a cable just
#: caught on the peg and turned 34 deg, 4.0 mm, which left the axis 13.6 mm
#: along the lines at a reported 4.6 mm std.
OFFSET_DRIFT = 0.002


class PegAxisFit:
    """Accumulates a peg's tangent lines and fits its axis (see the module docstring).

    Args:
        axis: The peg's axis direction (normalised here).  # (3,)
        radius: R [m], held fixed: the distance of the cable's centre line
            from the axis where it leaves it.
        radius_std: Prior std [m] of R (its effect on the axis is reported).
    """

    def __init__(self, axis: ArrayLike, radius: float, radius_std: float) -> None:
        self.axis, self._basis = axis_plane(axis)  # plane coordinates: rows of the basis
        if not (radius >= 0.0 and math.isfinite(radius)):
            raise InvalidArgumentError(f"radius must be >= 0 m, got {radius}")
        if not (radius_std >= 0.0 and math.isfinite(radius_std)):
            raise InvalidArgumentError(f"radius_std must be >= 0 m, got {radius_std}")
        self.radius = float(radius)
        self.radius_std = float(radius_std)
        self._A = np.zeros((2, 2))  # sum w n n'
        self._b = np.zeros(2)  # sum w n y
        self._yy = 0.0  # sum w y^2
        self._n_w = np.zeros(2)  # sum w n  (for dc/dR)
        self._w = 0.0  # sum w
        self._n_phi = np.zeros(2)  # sum w n phi  (for dc/d(drift))
        self.count = 0
        self._angle: float | None = None  # the last line's direction, unwrapped [rad]
        self._angle_range = (0.0, 0.0)  # (smallest, largest) unwrapped direction [rad]

    def add(self, point: ArrayLike, force: ArrayLike, side: ArrayLike, variance: float) -> None:
        """Add one line: a point [m] on it, the force [N] along it, its normal towards the axis.

        Args:
            point: A point of the line (e.g. the whole wrench's line point).  # (3,)
            force: The force along the line (its direction is used).  # (3,)
            side: Unit vector normal to the line, towards the axis.  # (3,)
            variance: Variance [m^2] of the line's offset (its weight is 1 / variance).
        """
        q = self._basis @ np.asarray(point, dtype=float).reshape(3)
        f = self._basis @ np.asarray(force, dtype=float).reshape(3)
        s = self._basis @ np.asarray(side, dtype=float).reshape(3)
        fn, sn = float(np.linalg.norm(f)), float(np.linalg.norm(s))
        if not (fn > 1e-9 and sn > 1e-9 and variance > 0.0 and math.isfinite(variance)):
            return
        if not (np.all(np.isfinite(q)) and np.all(np.isfinite(f)) and np.all(np.isfinite(s))):
            return
        u = f / fn
        n = s - u * float(u @ s)  # normal to the line, in the plane
        nn = float(np.linalg.norm(n))
        if nn < 1e-9:
            return
        n /= nn
        w = 1.0 / variance
        y = float(n @ q) + self.radius
        self._A += w * np.outer(n, n)
        self._b += w * n * y
        self._yy += w * y * y
        self._n_w += w * n
        self._w += w
        self.count += 1
        angle = math.atan2(float(u[1]), float(u[0]))
        if self._angle is None:
            self._angle_range = (angle, angle)
        else:
            angle = self._angle + math.remainder(angle - self._angle, 2.0 * math.pi)
            lo, hi = self._angle_range
            self._angle_range = (min(lo, angle), max(hi, angle))
        self._angle = angle
        self._n_phi += w * angle * n

    @property
    def spread(self) -> float:
        """Range [rad] of the lines' directions so far."""
        lo, hi = self._angle_range
        return hi - lo

    def estimate(self, height_point: ArrayLike) -> tuple[FloatArray, FloatArray] | None:
        """The axis's point at the height of ``height_point`` and its covariance, or None.

        Args:
            height_point: A point [m] whose position along the axis the result
                takes (e.g. the filter's estimate: where along the peg the
                cable bears).  # (3,)

        Returns:
            (position [m], covariance [m^2]) with the covariance normal to the
            axis only (along it the caller knows better), or None before the
            lines spread ``MIN_SPREAD``.  # (3,), (3, 3)
        """
        if self.count < 3 or self.spread < MIN_SPREAD:
            return None
        try:
            A_inv = np.linalg.inv(self._A)
        except np.linalg.LinAlgError:
            return None
        c = A_inv @ self._b
        rss = max(self._yy - 2.0 * float(c @ self._b) + float(c @ self._A @ c), 0.0)
        scatter = rss / max(self.count - 2, 1)  # variance of unit weight
        blocks = max(1.0, self.spread / BLOCK_ANGLE)
        # A^-1 s^2 is the covariance if every line erred independently;
        # neighbouring lines err together: count the wrap's blocks, not its lines
        cov2 = A_inv * scatter * (self.count / blocks)
        dc_dR = A_inv @ self._n_w
        cov2 = cov2 + self.radius_std**2 * np.outer(dc_dR, dc_dR)
        # R drifting from -drift at the wrap's first direction to +drift at its last
        lo, hi = self._angle_range
        dc_drift = A_inv @ (self._n_phi - 0.5 * (lo + hi) * self._n_w) / max(0.5 * (hi - lo), 1e-9)
        cov2 = cov2 + OFFSET_DRIFT**2 * np.outer(dc_drift, dc_drift)
        h = np.asarray(height_point, dtype=float).reshape(3)
        along = float(self.axis @ h)
        position: FloatArray = self._basis.T @ c + self.axis * along
        covariance: FloatArray = self._basis.T @ cov2 @ self._basis
        return position, covariance
