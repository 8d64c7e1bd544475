import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.estimation import CHI2_2DOF_999, ContactChangeDetector


def test_threshold_is_the_chi2_quantile():
    # P(chi2_2 > x) = exp(-x / 2)
    assert abs(CHI2_2DOF_999 - 13.8155) < 1e-4


def test_window_consecutive_gated_samples_declare_a_change():
    det = ContactChangeDetector(window=3)
    assert det.test(0, 100.0, 0.01) == (True, False, 0)
    assert det.test(1, 100.0, 0.01) == (True, False, 0)
    assert det.test(2, 100.0, 0.01) == (True, True, 0)
    assert det.run_length == 0


def test_a_passing_sample_resets_the_run():
    det = ContactChangeDetector(window=2)
    det.test(0, 100.0, 0.01)
    assert det.test(1, 1.0, 0.01) == (False, False, None)
    assert det.test(2, 100.0, 0.01) == (True, False, 2)


def test_small_innovations_are_not_gated():
    det = ContactChangeDetector(window=1, min_innovation=1e-3)
    assert not det.test(0, 1e6, 5e-4).gated
    assert det.test(1, 1e6, 2e-3).changed


@pytest.mark.parametrize("kwargs", [{"threshold": 0.0}, {"window": 0}, {"min_innovation": -1.0}])
def test_constructor_validates(kwargs):
    with pytest.raises(InvalidArgumentError):
        ContactChangeDetector(**kwargs)
