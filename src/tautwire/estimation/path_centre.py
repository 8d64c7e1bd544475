"""The centre a taut gripper circles, from its own path: a check on the force's lines.

A gripper that holds a taut cable and turns about its contact (primitive I)
stays where the cable lets it: at the span's length from the contact, with
the span stretched by T / k. Its path is therefore a circle about the true
contact whatever centre it was told to circle, and the robot measures that
path exactly. The path's centre is found without the force's direction,
which a force-sensor bias tilts: a bias b normal to the cable moves each
line's offset by L b / T at the lever L, and over a wrap that moves the
contact estimate as a whole (its lines stay consistent, its covariance
small: robustness trials 6, 9 and 94 trusted pegs 24-38 mm off).

In the plane normal to the rotation axis, sample i at the gripper's
position g_i, the tension T_i and the turn phi_i from the start is modelled
as

    |g_i - c| = L_i                        about a point,
    |g_i - c| = sqrt(L_i^2 + R^2)          from a peg of radius R,
    L_i = L0 - s R phi_i + T_i / k,

with the free length L0 unknown and s the sense in which the cable bends
round the peg (winding it takes R phi of the free length). Gauss-Newton
gives (c, L0); the covariance is the residuals' scatter times the inverse
normal matrix, counted by the residuals' effective number of samples
(neighbouring samples err together: the swing of the tension, the cable's
wobble).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.axis_plane import axis_plane
from tautwire.estimation.effective_samples import effective_samples

FloatArray = NDArray[np.float64]

#: Smallest turn [rad] before the path's centre is estimated.
MIN_TURN = math.radians(20.0)
#: Gauss-Newton iterations.
ITERATIONS = 8


class PathCentre:
    """Collects a circling gripper's path and fits the centre it circles.

    Args:
        axis: The rotation axis (normalised here).  # (3,)
        radius: R [m] of a peg the cable leaves tangentially (0: a point).
        sense: s, +1 or -1: the sense, right-handed about ``axis``, in which
            the cable bends round the peg.
        stiffness: k [N/m] of the span (its stretch T / k); None or <= 0:
            the stretch is taken as constant.
    """

    def __init__(
        self, axis: ArrayLike, radius: float, sense: float, stiffness: float | None
    ) -> None:
        self.axis, self._basis = axis_plane(axis)  # plane coordinates: rows of the basis
        if not (radius >= 0.0 and math.isfinite(radius)):
            raise InvalidArgumentError(f"radius must be >= 0 m, got {radius}")
        self.radius = float(radius)
        self.sense = 1.0 if sense >= 0.0 else -1.0
        self.compliance = 1.0 / stiffness if stiffness is not None and stiffness > 0.0 else 0.0
        self._g: list[FloatArray] = []
        self._T: list[float] = []

    @property
    def count(self) -> int:
        """Number of samples so far."""
        return len(self._g)

    def add(self, position: ArrayLike, tension: float) -> None:
        """Add one sample: the gripper's position [m] and the tension [N] it holds."""
        g = np.asarray(position, dtype=float).reshape(3)
        if not (np.all(np.isfinite(g)) and math.isfinite(tension)):
            return
        self._g.append(self._basis @ g)
        self._T.append(float(tension))

    def estimate(self, start: ArrayLike) -> tuple[FloatArray, FloatArray] | None:
        """The path's centre [m] and its covariance [m^2] (normal to the axis), or None.

        Args:
            start: Where to start the iterations (e.g. the force's estimate);
                its part along the axis is the result's.  # (3,)

        Returns:
            (centre, covariance), or None before the gripper turned
            ``MIN_TURN`` about it or when the fit fails.  # (3,), (3, 3)
        """
        if len(self._g) < 8:
            return None
        g = np.array(self._g)
        T = np.array(self._T)
        s0 = np.asarray(start, dtype=float).reshape(3)
        c = self._basis @ s0
        turn = _turns(g, c)
        if abs(float(turn[-1])) < MIN_TURN or float(np.ptp(turn)) < MIN_TURN:
            return None
        stretch = self.compliance * T
        wound = self.sense * self.radius * turn
        d = np.linalg.norm(g - c, axis=1)
        L0 = float(np.mean(np.sqrt(np.maximum(d**2 - self.radius**2, 0.0)) + wound - stretch))
        x = np.array([c[0], c[1], L0])
        J = np.zeros((len(g), 3))
        r = np.zeros(len(g))
        for _ in range(ITERATIONS):
            c = x[:2]
            turn = _turns(g, c)
            L = x[2] - self.sense * self.radius * turn + stretch
            D = np.sqrt(L**2 + self.radius**2)
            off = g - c
            dist = np.linalg.norm(off, axis=1)
            if float(np.min(dist)) < 1e-6:
                return None
            r = dist - D
            J[:, :2] = -off / dist[:, None]
            J[:, 2] = -L / D
            try:
                dx = np.linalg.lstsq(J, -r, rcond=None)[0]
            except np.linalg.LinAlgError:
                return None
            x = x + dx
            if float(np.linalg.norm(dx)) < 1e-7:
                break
        N = J.T @ J
        try:
            N_inv = np.linalg.inv(N)
        except np.linalg.LinAlgError:
            return None
        n = len(g)
        scatter = float(r @ r) / max(n - 3, 1)
        cov2 = N_inv[:2, :2] * scatter * (n / effective_samples(r))
        centre: FloatArray = self._basis.T @ x[:2] + self.axis * float(self.axis @ s0)
        covariance: FloatArray = self._basis.T @ cov2 @ self._basis
        return centre, covariance


def _turns(g: FloatArray, c: FloatArray) -> FloatArray:
    """The unwrapped angle [rad] of each point of ``g`` about ``c`` from the first."""
    off = g - c
    angles = np.unwrap(np.arctan2(off[:, 1], off[:, 0]))
    out: FloatArray = angles - angles[0]
    return out
