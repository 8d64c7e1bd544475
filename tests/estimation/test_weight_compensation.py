import numpy as np
import pytest

from tautwire.estimation import compensate_weight, gripper_point_mass
from tautwire.model import GRAVITY


def test_gripper_carries_half_the_span():
    assert gripper_point_mass(0.4, 0.03) == pytest.approx(0.006)


def test_compensation_gives_back_the_chord_tension():
    chord = np.array([-0.6, 0.8, 0.0])
    rho, span, tension = 0.03, 0.25, 2.0
    f_sens = tension * chord + 0.5 * rho * span * GRAVITY  # the cable's pull plus half its weight
    np.testing.assert_allclose(compensate_weight(f_sens, span, rho), tension * chord, atol=1e-15)
    # the raw direction dips below the chord
    assert f_sens[2] < 0.0


def test_zero_mass_is_identity():
    f = np.array([1.0, 2.0, 3.0])
    np.testing.assert_array_equal(compensate_weight(f, 0.3, 0.0), f)
