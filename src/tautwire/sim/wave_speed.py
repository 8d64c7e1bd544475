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

from tautwire.errors import InvalidArgumentError


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
