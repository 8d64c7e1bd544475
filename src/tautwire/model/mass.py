"""Mass of each feature point (the paper's eq:mass).

The cable's mass is shared out to the feature points: an end point gets half
of its one edge, an inner point half of each of its two edges,

    m_i = rho d_i / 2                     (end point)
    m_i = rho (d_{i-1} + d_i) / 2         (between feature points).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError

FloatArray = NDArray[np.float64]


def point_masses(lengths: ArrayLike, mass_per_length: float) -> FloatArray:
    """Masses [kg] of the |E| + 1 feature points of a path graph.

    Args:
        lengths: Cable length of each edge, d_1 ... d_|E| [m].  # (E,)
        mass_per_length: rho [kg/m].

    Returns:
        m_1 ... m_|V| [kg].  # (E + 1,)
    """
    d = np.asarray(lengths, dtype=float).reshape(-1)
    if not (mass_per_length >= 0.0 and math.isfinite(mass_per_length)):
        raise InvalidArgumentError(f"mass_per_length must be >= 0 kg/m, got {mass_per_length}")
    if d.size and not (d.min() >= 0.0 and math.isfinite(d.sum())):
        raise InvalidArgumentError("edge lengths must be finite and >= 0 m")
    half = (0.5 * mass_per_length) * d
    masses = np.zeros(d.size + 1)
    masses[:-1] += half
    masses[1:] += half
    return masses
