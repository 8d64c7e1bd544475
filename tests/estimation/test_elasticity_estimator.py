import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.estimation import ElasticityEstimator


def stretch(k, seed, seconds=2.0, swing=1.5, freq=0.5, rate=250.0, noise=0.05, vibration=0.0):
    """Length oscillation that swings the tension by ``swing`` N around 3 N (Hooke).

    ``vibration`` [m]: amplitude of a 6 Hz oscillation of the measured length
    that the tension does not follow (a cable swinging across its chord).
    """
    rng = np.random.default_rng(seed)
    t = np.arange(int(seconds * rate)) / rate
    amplitude = 0.5 * swing / k
    length = 0.3 + amplitude * np.sin(2 * np.pi * freq * t + rng.uniform(0, 2 * np.pi))
    tension = 3.0 + k * (length - 0.3) + rng.normal(0.0, noise, t.size)
    chord = length + vibration * np.sin(2 * np.pi * 6.0 * t + rng.uniform(0, 2 * np.pi))
    return tension, chord


@pytest.mark.parametrize("k", [10.0, 100.0, 1000.0])
def test_stiffness_within_5_percent_after_2_seconds(k):
    for seed in range(10):
        est = ElasticityEstimator()
        history = [est.update(f, l_) for f, l_ in zip(*stretch(k, seed), strict=True)]
        assert all(math.isfinite(h) and h > 0.0 for h in history)
        assert abs(history[-1] / k - 1.0) <= 0.05
        assert est.is_ready()
        # the reported std is consistent with the error
        assert abs(history[-1] - k) <= 4.0 * est.std


def test_window_means_average_out_a_vibrating_chord():
    # k = 1000 N/m swung by 0.2 N: +-0.1 mm of length against 30 um of vibration
    errors = {1: [], 50: []}
    for window, forgetting in ((1, 0.999), (50, 0.95)):
        for seed in range(20):
            est = ElasticityEstimator(window=window, forgetting=forgetting)
            for f, l_ in zip(*stretch(1000.0, seed, 4.0, swing=0.2, vibration=30e-6), strict=True):
                est.update(f, l_)
            errors[window].append(est.k_hat / 1000.0 - 1.0)
    assert np.mean(errors[1]) < -0.02  # regression dilution: k biased low
    assert abs(np.mean(errors[50])) < 0.01
    assert np.median(np.abs(errors[50])) < 0.05


def test_a_partial_window_changes_nothing():
    est = ElasticityEstimator(window=10)
    for i in range(9):
        assert est.update(3.0 + i, 0.3 + 1e-3 * i) == 100.0
    assert est.samples_used == 0
    est.update(12.0, 0.309)
    assert est.samples_used == 1


def test_excitation_guard_skips_a_standing_gripper():
    est = ElasticityEstimator(min_length_change=1e-5)
    rng = np.random.default_rng(3)
    for _ in range(500):
        est.update(3.0 + rng.normal(0.0, 0.05), 0.3 + rng.normal(0.0, 1e-7))
    assert est.samples_used == 1
    assert est.k_hat == 100.0 and not est.is_ready()


def test_clamped_to_the_range_never_negative():
    est = ElasticityEstimator(k_range=(5.0, 500.0))
    # tension falling while the cable lengthens: the raw fit is negative
    for i in range(100):
        est.update(5.0 - 0.01 * i, 0.3 + 1e-3 * i)
    assert est.k_hat == 5.0 and est.clamped and not est.is_ready()
    est = ElasticityEstimator(k_range=(5.0, 500.0))
    for i in range(100):
        est.update(1.0 + 10.0 * i, 0.3 + 1e-3 * i)  # 10 kN/m
    assert est.k_hat == 500.0


finite = st.floats(-1e3, 1e3, allow_nan=False)


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.one_of(finite, st.just(math.nan)), finite), max_size=50))
def test_never_nan_or_negative(samples):
    est = ElasticityEstimator()
    for f, l_ in samples:
        k = est.update(f, l_ * 1e-3)
        assert math.isfinite(k) and est.k_min <= k <= est.k_max
    assert math.isfinite(est.variance) and est.variance >= 0.0


def test_forgetting_tracks_a_stiffness_change():
    est = ElasticityEstimator(forgetting=0.6)  # per 50-sample window: 0.99 per sample
    for f, l_ in zip(*stretch(100.0, 1, seconds=4.0), strict=True):
        est.update(f, l_)
    for f, l_ in zip(*stretch(300.0, 2, seconds=4.0), strict=True):
        est.update(f, l_)
    assert est.k_hat == pytest.approx(300.0, rel=0.05)


@pytest.mark.parametrize(
    "kwargs",
    [
        {"force_noise": 0.0},
        {"forgetting": 0.0},
        {"forgetting": 1.5},
        {"k_range": (0.0, 10.0)},
        {"k_range": (10.0, 1.0)},
        {"k_initial_std": 0.0},
        {"min_length_change": -1.0},
        {"window": 0},
        {"window": 2.5},
    ],
)
def test_constructor_validates(kwargs):
    with pytest.raises(InvalidArgumentError):
        ElasticityEstimator(**kwargs)


def test_reset_with_a_new_prior_is_clamped() -> None:
    from tautwire.estimation import ElasticityEstimator

    est = ElasticityEstimator(k_initial=100.0, k_range=(5.0, 500.0))
    est.reset(k_initial=250.0)
    assert est.k_hat == 250.0
    est.reset(k_initial=1e6)
    assert est.k_hat == 500.0
    est.reset()
    assert est.k_hat == 500.0  # the prior stays


def _creeping(k: float, seed: int, creep: float, bias_rate: float = 0.0):  # type: ignore[no-untyped-def]
    """A 0.5 Hz stretch (1 N swing) of a cable whose rest length creeps by ``creep`` [m/s].

    The chord grows by the creep while the tension swings about a constant
    mean (a cable settling round a peg); ``bias_rate`` [N/s] drifts the
    measured tension at constant length (a sensor bias).
    """
    rng = np.random.default_rng(seed)
    t = np.arange(1500) / 250.0  # 6 s
    stretch_ = 0.5 / k * np.sin(2.0 * np.pi * 0.5 * t)
    length = 0.3 + creep * t + stretch_
    tension = 3.0 + k * stretch_ + bias_rate * t + rng.normal(0.0, 0.05, t.size)
    return tension, length


@pytest.mark.parametrize(("creep", "bias_rate"), [(3e-4, 0.0), (0.0, 0.1)])
def test_a_slow_drift_is_not_taken_for_stiffness(creep: float, bias_rate: float) -> None:
    k = 1000.0
    errors = {True: [], False: []}
    for drift in (True, False):
        for seed in range(10):
            est = ElasticityEstimator(drift=drift)
            for f, l_ in zip(*_creeping(k, seed, creep, bias_rate), strict=True):
                est.update(f, l_)
            errors[drift].append(abs(est.k_hat / k - 1.0))
    assert max(errors[True]) < 0.05
    assert np.median(errors[False]) > 0.1  # the affine fit reads the drift as stiffness


def test_drift_rate_is_estimated() -> None:
    est = ElasticityEstimator()
    for f, l_ in zip(*_creeping(500.0, 3, 0.0, bias_rate=0.25), strict=True):
        est.update(f, l_)
    # 0.25 N/s is 0.05 N per 0.2 s window
    assert est.drift_rate == pytest.approx(0.05, rel=0.2)
