"""Weight compensation of the measured force (equ:edge_tension, eq:mass).

A cable span of length d hanging between a contact and the gripper pulls the
gripper along the chord with the tension and, in addition, down with the
gripper point's share of the span's weight (for a shallow, uniformly loaded
span exactly half of it: moments about the contact). So the raw force
direction dips below the chord, and the line through the gripper misses the
contact by about d^2 rho |g| / (2 f) vertically (3 mm for 30 g/m, 0.2 m, 2 N).
Compensation adds back m_g g with m_g = rho d / 2, the gripper's point mass of
the span (``tautwire.model.point_masses``), via
``tautwire.model.edge_tension``:

    p_hat f = f_sens - m_g g      (world z up, g = (0, 0, -9.81) m/s^2).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.model.mass import point_masses
from tautwire.model.tension import edge_tension

FloatArray = NDArray[np.float64]


def gripper_point_mass(span_length: float, mass_per_length: float) -> float:
    """Mass [kg] the gripper carries of a span between it and a contact (eq:mass).

    Args:
        span_length: Cable length d [m] between the contact and the gripper.
        mass_per_length: rho [kg/m].

    Returns:
        m_g = rho d / 2 [kg].
    """
    return float(point_masses([max(span_length, 0.0)], mass_per_length)[1])


def compensate_weight(f_sens: ArrayLike, span_length: float, mass_per_length: float) -> FloatArray:
    """Chord tension vector [N] of the span from the measured force.

    Args:
        f_sens: Force [N] the cable exerts on the gripper, world frame.  # (3,)
        span_length: Cable length d [m] between the contact and the gripper
            (e.g. the distance from the gripper to the contact estimate).
        mass_per_length: rho [kg/m]; 0 returns ``f_sens`` unchanged.

    Returns:
        f_sens - m_g g [N], pointing from the gripper along the chord.  # (3,)
    """
    if mass_per_length == 0.0:
        return np.asarray(f_sens, dtype=float).reshape(3).copy()
    return edge_tension(f_sens, gripper_point_mass(span_length, mass_per_length)).vector
