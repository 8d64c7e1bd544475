import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from tautwire.model.sag import sag, sag_from_span


def catenary_max_vertical_sag(a: float, h: float, d: float) -> float:
    """Largest vertical chord-to-cable distance of an exact (inextensible) catenary."""
    # sqrt(d^2 - h^2) = 2 c sinh(a / (2 c)) fixes the catenary parameter c.
    target = math.sqrt(d * d - h * h)
    c = brentq(lambda c: 2.0 * c * math.sinh(a / (2.0 * c)) - target, a / 1400.0, 1e6 * a)
    # y = c cosh((x - x0) / c) + y0 through (0, 0) and (a, h)
    x0 = a / 2.0 - c * math.asinh(h / (2.0 * c * math.sinh(a / (2.0 * c))))
    y0 = -c * math.cosh(-x0 / c)
    x = np.linspace(0.0, a, 20001)
    y = c * np.cosh((x - x0) / c) + y0
    chord = h * x / a
    return float(np.max(chord - y))


def test_parabolic_limit_for_level_span() -> None:
    a, d = 0.5, 0.52
    assert sag_from_span(a, 0.0, d) == pytest.approx(math.sqrt(6 * a * (d - a)) / 4, rel=1e-12)


@pytest.mark.parametrize("h", [0.0, 0.05, 0.2, -0.15])
@pytest.mark.parametrize("slack", [0.001, 0.005, 0.01])
def test_matches_numerically_solved_catenary(h: float, slack: float) -> None:
    a = 0.4
    d = math.hypot(a, h) * (1.0 + slack)
    exact = catenary_max_vertical_sag(a, h, d)
    # the formula is the inclined-parabola approximation (valid for s / a << 1)
    assert sag_from_span(a, h, d) == pytest.approx(exact, rel=0.03)


def test_sag_uses_horizontal_span_and_height() -> None:
    p0 = np.array([0.1, 0.2, 0.3])
    p1 = p0 + np.array([0.3, 0.4, 0.1])  # a = 0.5, h = 0.1
    assert sag(p0, p1, 0.52) == pytest.approx(sag_from_span(0.5, 0.1, 0.52))
    assert sag(p1, p0, 0.52) == pytest.approx(sag_from_span(0.5, -0.1, 0.52))


def test_vertical_edge_and_taut_edge_have_no_sag() -> None:
    assert sag_from_span(0.0, 0.3, 0.5) == 0.0  # a freely hanging end
    assert sag_from_span(0.4, 0.3, 0.5) == 0.0  # exactly taut
    assert sag_from_span(0.4, 0.3, 0.45) == 0.0  # stretched


@settings(max_examples=200, deadline=None)
@given(
    a=st.floats(0.0, 2.0),
    h=st.floats(-2.0, 2.0),
    d=st.floats(0.0, 5.0),
)
def test_sag_is_finite_and_nonnegative(a: float, h: float, d: float) -> None:
    s = sag_from_span(a, h, d)
    assert math.isfinite(s) and s >= 0.0
