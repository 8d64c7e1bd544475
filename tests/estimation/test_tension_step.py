import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.tension_step import MIN_SAMPLES, TensionStep, contact_shift


def unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)


def measured(
    u: np.ndarray,
    tensions: tuple[float, float],
    bias: np.ndarray,
    noise: float = 0.05,
    n: int = 250,
    seed: int = 0,
) -> TensionStep:
    """A still gripper's compensated pull at two tensions: T u + b + white noise."""
    rng = np.random.default_rng(seed)
    step = TensionStep()
    for level, tension in enumerate(tensions):
        for _ in range(n):
            step.add(level, tension * u + bias + rng.normal(scale=noise, size=3))
    return step


@settings(max_examples=40, deadline=None)
@given(
    az=st.floats(-math.pi, math.pi),
    el=st.floats(-0.6, 0.6),
    t1=st.floats(1.0, 8.0),
    lower=st.floats(0.4, 0.8),
    b=st.tuples(*(st.floats(-0.8, 0.8),) * 3),
    seed=st.integers(0, 10_000),
)
def test_bias_normal_to_the_cable_is_found(
    az: float, el: float, t1: float, lower: float, b: tuple[float, float, float], seed: int
) -> None:
    u = np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
    bias = np.array(b)
    result = measured(u, (t1, lower * t1), bias, seed=seed).result()
    assert result is not None
    expected = bias - u * float(u @ bias)
    err = result.bias - expected
    # within five stds (Mahalanobis in the plane normal to the cable)
    basis = np.linalg.svd(np.eye(3) - np.outer(u, u))[0][:, :2]
    e2 = basis.T @ err
    c2 = basis.T @ result.bias_covariance @ basis
    assert float(e2 @ np.linalg.solve(c2, e2)) < 25.0
    assert float(np.linalg.norm(result.direction - u)) < 0.05


def test_covariance_is_honest_over_seeds() -> None:
    """The bias's error is within 3 std (along it) in at least 90 % of seeded runs."""
    u = unit(np.array([0.6, -0.8, -0.1]))
    bias = np.array([0.1, 0.2, -0.15])
    expected = bias - u * float(u @ bias)
    within = 0
    for seed in range(100):
        result = measured(u, (2.0, 1.0), bias, noise=0.08, seed=seed).result()
        assert result is not None
        err = result.bias - expected
        along = err / np.linalg.norm(err)
        std = math.sqrt(along @ result.bias_covariance @ along)
        within += int(np.linalg.norm(err) <= 3.0 * std)
    assert within >= 90


def test_bias_along_the_cable_is_not_seen() -> None:
    u = unit(np.array([1.0, 1.0, 0.0]))
    result = measured(u, (3.0, 1.5), 0.5 * u, noise=0.0 + 1e-3).result()
    assert result is not None
    assert float(np.linalg.norm(result.bias)) < 1e-3
    assert result.tensions == pytest.approx((3.5, 2.0), abs=1e-3)


def test_contact_shift_scales_by_lever_over_tension() -> None:
    u = np.array([1.0, 0.0, 0.0])
    bias = np.array([0.0, 0.2, 0.0])
    result = measured(u, (2.0, 1.0), bias, noise=1e-3).result()
    assert result is not None
    shift, cov = contact_shift(result, 0.5, 2.0)
    np.testing.assert_allclose(shift, [0.0, 0.05, 0.0], atol=1e-4)
    assert cov.shape == (3, 3)
    with pytest.raises(InvalidArgumentError, match="lever"):
        contact_shift(result, 0.0, 2.0)
    with pytest.raises(InvalidArgumentError, match="tension"):
        contact_shift(result, 0.5, math.nan)


def test_too_few_samples_or_no_step_say_nothing() -> None:
    u = np.array([0.0, 1.0, 0.0])
    assert measured(u, (2.0, 1.0), np.zeros(3), n=MIN_SAMPLES - 1).result() is None
    assert measured(u, (2.0, 2.0), np.zeros(3)).result() is None


def test_non_finite_samples_are_skipped_and_bad_levels_refused() -> None:
    step = measured(np.array([1.0, 0.0, 0.0]), (2.0, 1.0), np.zeros(3))
    before = step.count(0)
    step.add(0, [math.nan, 0.0, 0.0])
    step.add(0, [math.inf, 0.0, 0.0])
    assert step.count(0) == before
    with pytest.raises(InvalidArgumentError, match="level"):
        step.add(2, [1.0, 0.0, 0.0])


def test_a_steady_level_has_no_drift_and_a_ramp_has_its_own() -> None:
    from tautwire.estimation.tension_step import level_drift

    rng = np.random.default_rng(9)
    steady = rng.normal(scale=0.05, size=(250, 3))
    drift, cov = level_drift(steady)
    assert np.all(np.abs(drift) <= 4.0 * np.sqrt(np.diag(cov)))
    ramp = steady + np.outer(np.linspace(0.0, 1.0, 250), [0.2, 0.0, -0.1])
    drift, cov = level_drift(ramp)
    np.testing.assert_allclose(drift, [0.2, 0.0, -0.1], atol=5.0 * np.sqrt(cov[0, 0]))
