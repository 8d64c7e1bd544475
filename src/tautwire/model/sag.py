"""Sag of an edge (the paper's equ:catenarySlack).

For an edge of cable length d between two points a horizontal distance a and
a height h apart, the largest vertical distance between the chord and the
hanging cable is approximately

    s = 1/4 sqrt( 6 (a^2 + h^2)^2 / a^2 [ d / sqrt(a^2 + h^2) - 1 ] ),

the inclined-parabola approximation of the catenary (valid for s/a << 1).
For h = 0 it is the slack-cable formula s = sqrt(6 a (d - a)) / 4.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

#: Horizontal spans below this [m] count as a vertical edge (a = 0: sag 0).
MIN_SPAN = 1e-9


def sag_from_span(a: float, h: float, d: float) -> float:
    """Sag [m] of an edge from its span, height difference and cable length.

    Args:
        a: Horizontal span [m].
        h: Height difference [m].
        d: Cable length of the edge [m].

    Returns:
        The sag [m]; 0 for a = 0 (a freely hanging end, where the formula
        is undefined) and for a taut edge (d no longer than the chord);
        never NaN.
    """
    a = abs(float(a))
    h = float(h)
    d = float(d)
    if a < MIN_SPAN or not (math.isfinite(a) and math.isfinite(h) and math.isfinite(d)):
        return 0.0
    chord_sq = a * a + h * h
    chord = math.sqrt(chord_sq)
    slack = d / chord - 1.0
    if slack <= 0.0:
        return 0.0
    return 0.25 * math.sqrt(6.0 * chord_sq * chord_sq / (a * a) * slack)


def sag(p_i: ArrayLike, p_j: ArrayLike, d: float) -> float:
    """Sag [m] of an edge of cable length ``d`` [m] between two positions [m].

    The span ``a`` is the horizontal (x-y) distance and ``h`` the height (z)
    difference of the end points, world frame with z up.
    """
    delta = np.asarray(p_j, dtype=float) - np.asarray(p_i, dtype=float)
    a = float(np.hypot(delta[0], delta[1]))
    return sag_from_span(a, float(delta[2]), d)
