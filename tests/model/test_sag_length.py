import math

import numpy as np
import pytest

from tautwire.model.sag_length import sag_excess_length
from tautwire.model.tension import G


@pytest.mark.parametrize("tension", [0.5, 2.0, 10.0])
def test_level_edge_matches_the_catenary(tension: float) -> None:
    # a level catenary of horizontal tension H spans c with length 2 a sinh(c / 2a), a = H / w
    c, rho = 0.5, 0.03
    a = tension / (rho * G)
    exact = 2.0 * a * math.sinh(c / (2.0 * a)) - c
    assert sag_excess_length([c, 0.0, 0.0], tension, rho) == pytest.approx(exact, rel=0.01)


def test_only_the_weight_across_the_chord_sags() -> None:
    level = sag_excess_length([0.4, 0.0, 0.0], 2.0, 0.03)
    inclined = sag_excess_length([0.4 / math.sqrt(2), 0.0, 0.4 / math.sqrt(2)], 2.0, 0.03)
    assert inclined == pytest.approx(0.5 * level, rel=1e-12)  # (w cos 45 deg)^2
    assert sag_excess_length([0.0, 0.0, -0.4], 2.0, 0.03) == 0.0


def test_shrinks_with_the_square_of_the_tension() -> None:
    chord = np.array([0.3, 0.2, 0.0])
    assert sag_excess_length(chord, 1.0, 0.05) == pytest.approx(
        4.0 * sag_excess_length(chord, 2.0, 0.05), rel=1e-12
    )


@pytest.mark.parametrize("tension", [0.0, -1.0, math.nan, math.inf])
def test_zero_without_a_positive_tension(tension: float) -> None:
    assert sag_excess_length([0.5, 0.0, 0.0], tension, 0.03) == 0.0
    assert sag_excess_length([0.0, 0.0, 0.0], 2.0, 0.03) == 0.0
