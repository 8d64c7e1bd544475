"""The wave-speed guard on the cable's explicitly integrated tension.

MuJoCo integrates the segment springs explicitly, so a transverse wave must
not cross more than one segment per step:

    dt < l sqrt(rho / T),

with l the segment length, rho the mass per length and T the tension. Beyond
it the simulated force reads 9-26 % low with no warning. Scaling every vertex
mass by alpha (and compensating gravity with ``gravcomp = 1 - 1/alpha``, so
the weight stays rho l g) raises the limit by sqrt(alpha) and keeps the
statics exact; only the cable's dynamics become alpha times more sluggish.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError

FloatArray = NDArray[np.float64]


def max_stable_timestep(
    segment_length: float, mass_per_length: float, tension: float, mass_scaling: float = 1.0
) -> float:
    """Largest dt [s] the wave-speed limit allows.

    Args:
        segment_length: l [m].
        mass_per_length: rho [kg/m].
        tension: T [N], the largest tension expected.
        mass_scaling: alpha, the vertex mass scaling (>= 1).

    Returns:
        l sqrt(alpha rho / T) [s].
    """
    if segment_length <= 0.0 or mass_per_length <= 0.0 or tension <= 0.0 or mass_scaling <= 0.0:
        raise InvalidArgumentError(
            "segment_length, mass_per_length, tension and mass_scaling must be > 0"
        )
    return segment_length * math.sqrt(mass_scaling * mass_per_length / tension)


def required_mass_scaling(
    timestep: float,
    segment_length: float,
    mass_per_length: float,
    tension: float,
    safety: float = 1.0,
) -> float:
    """Smallest alpha >= 1 with dt <= safety * l sqrt(alpha rho / T).

    Args:
        timestep: dt [s].
        segment_length: l [m].
        mass_per_length: rho [kg/m].
        tension: T [N].
        safety: Fraction (0, 1] of the limit to stay within.

    Returns:
        alpha = max(1, T (dt / (safety l))^2 / rho).
    """
    if timestep <= 0.0 or not 0.0 < safety <= 1.0:
        raise InvalidArgumentError("timestep must be > 0 and safety in (0, 1]")
    max_stable_timestep(segment_length, mass_per_length, tension)  # validates
    alpha = tension * (timestep / (safety * segment_length)) ** 2 / mass_per_length
    return max(1.0, alpha)


def vertex_mass_scaling(
    timestep: float,
    rest_lengths: FloatArray,
    masses: FloatArray,
    tension: float,
    safety: float = 1.0,
) -> FloatArray:
    """Smallest mass scaling alpha_i >= 1 of each vertex that keeps it stable.

    A vertex of mass m_i between segments of lengths l_a and l_b under
    tension T oscillates sideways at omega^2 = T (1/l_a + 1/l_b) / m_i, so it
    needs alpha_i m_i >= T dt^2 (1/l_a + 1/l_b) / (2 safety^2). For uniform
    segments (m = rho l) this is :func:`required_mass_scaling`; with
    non-uniform ones only the vertices next to a short segment get heavier.

    Args:
        timestep: dt [s].
        rest_lengths: Segment lengths [m].  # (N,)
        masses: True vertex masses [kg].  # (N + 1,)
        tension: T [N].
        safety: Fraction (0, 1] of the limit to stay within.

    Returns:
        alpha_i.  # (N + 1,)
    """
    if timestep <= 0.0 or tension <= 0.0 or not 0.0 < safety <= 1.0:
        raise InvalidArgumentError("timestep and tension must be > 0 and safety in (0, 1]")
    lengths = np.asarray(rest_lengths, dtype=float)
    m = np.asarray(masses, dtype=float)
    if np.any(lengths <= 0.0) or np.any(m <= 0.0) or len(m) != len(lengths) + 1:
        raise InvalidArgumentError("need N > 0 positive segment lengths and N + 1 positive masses")
    inverse = np.zeros(len(m))
    inverse[:-1] += 1.0 / lengths
    inverse[1:] += 1.0 / lengths
    alpha: FloatArray = np.maximum(1.0, tension * timestep**2 * inverse / (2.0 * safety**2 * m))
    return alpha


def vertex_timestep_limit(rest_lengths: FloatArray, masses: FloatArray, tension: float) -> float:
    """Largest dt [s] at which every (scaled) vertex is stable: min sqrt(2 m_i / (T sum 1/l))."""
    lengths = np.asarray(rest_lengths, dtype=float)
    m = np.asarray(masses, dtype=float)
    inverse = np.zeros(len(m))
    inverse[:-1] += 1.0 / lengths
    inverse[1:] += 1.0 / lengths
    return float(np.min(np.sqrt(2.0 * m / (tension * inverse))))
