"""Extra length of a taut edge that sags under its own weight.

A taut edge of chord length c whose weight per length perpendicular to the
chord is w hangs as a shallow parabola (the approximation of
equ:catenarySlack) with sag s = w c^2 / (8 T) at tension T. Its cable length
exceeds the chord by

    d - c = 8 s^2 / (3 c) = w^2 c^3 / (24 T^2),

so the cable's elastic length is the chord plus this excess. It matters to
the elasticity estimate (equ:spring_measurement): the chord lengthens with
the tension both by stretching and by the sag straightening out, which adds
the compliance d(d - c)/dT = -w^2 c^3 / (12 T^3) in series with 1 / k.
For the 0.5 m, 30 g/m cable of Fig. 5a at 2 N that is 0.11 mm/N, an 11 %
softer chord than a 1000 N/m cable (k_hat 910-950 N/m without the
correction, 1010-1060 N/m with it, seeds 0-2); at 0.5 N it is 7 mm/N.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from tautwire.model.tension import G


def sag_excess_length(chord: ArrayLike, tension: float, mass_per_length: float) -> float:
    """Cable length minus chord length [m] of a taut edge sagging under its weight.

    Args:
        chord: Vector [m] from one end of the edge to the other (world frame,
            z up); only its length and inclination matter.  # (3,)
        tension: Tension T [N] of the edge, > 0.
        mass_per_length: rho [kg/m] of the cable.

    Returns:
        w^2 c^3 / (24 T^2) with w = rho g cos(inclination) [N/m]; 0 for a
        non-positive or non-finite tension or a zero chord.
    """
    v = np.asarray(chord, dtype=float)
    c = float(np.linalg.norm(v))
    t = float(tension)
    if not (c > 0.0 and t > 0.0 and math.isfinite(c) and math.isfinite(t)):
        return 0.0
    w = float(mass_per_length) * G * math.hypot(float(v[0]), float(v[1])) / c  # weight across
    return w * w * c**3 / (24.0 * t * t)
