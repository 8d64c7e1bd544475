import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.control.force_controller import (
    AdaptiveForceController,
    FixedGainForceController,
    ForceController,
)
from tautwire.errors import InvalidArgumentError

DT = 0.004  # the robot's 250 Hz interface


def simulate(
    controller: ForceController,
    k: float,
    k_hat: float | None,
    f_d: float,
    steps: int,
    delayed: bool = False,
    f_0: float = 0.0,
) -> np.ndarray:
    """Tension history of the plant f = k x under x_{n+1} = x_n + dt x_dot_f."""
    x = f_0 / k
    x_prev = x
    history = np.empty(steps + 1)
    history[0] = f_0
    for n in range(steps):
        f_measured = k * (x_prev if delayed else x)
        x_prev = x
        x = x + DT * controller.speed(f_d, f_measured, k_hat)
        history[n + 1] = k * x
    return history


def test_matches_the_closed_form_geometric_decay() -> None:
    controller = AdaptiveForceController(bandwidth=10.0)
    for k, k_hat in ((10.0, 10.0), (100.0, 30.0), (1000.0, 5000.0)):
        f = simulate(controller, k, k_hat, f_d=2.0, steps=200)
        a = 10.0 * DT * k / k_hat
        n = np.arange(201)
        np.testing.assert_allclose(2.0 - f, 2.0 * (1.0 - a) ** n, rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("k", [10.0, 100.0, 1000.0])  # the paper's Fig. 5a cables
@pytest.mark.parametrize("ratio", [0.1, 0.3, 1.0, 3.0, 10.0])  # k_hat / k
@pytest.mark.parametrize("delayed", [False, True])
def test_converges_for_k_hat_from_a_tenth_to_ten_times_k(
    k: float, ratio: float, delayed: bool
) -> None:
    controller = AdaptiveForceController()  # lambda = 10 1/s, clamp [5, 5000] N/m
    f = simulate(controller, k, ratio * k, f_d=2.0, steps=2500, delayed=delayed)  # 10 s
    assert abs(f[-1] - 2.0) < 1e-3
    # the first overshoot stays modest (a <= 0.4 even with one period of delay)
    assert f.max() < 2.0 * 1.2


def test_stability_bound() -> None:
    controller = AdaptiveForceController(bandwidth=10.0, k_hat_min=0.01, k_hat_max=1e6)
    assert controller.max_stiffness_ratio(DT) == pytest.approx(50.0)
    assert controller.max_stiffness_ratio(DT, delayed=True) == pytest.approx(25.0)
    k = 100.0
    for delayed in (False, True):
        bound = controller.max_stiffness_ratio(DT, delayed=delayed)
        inside = simulate(controller, k, k / (0.95 * bound), 2.0, 2000, delayed=delayed)
        outside = simulate(controller, k, k / (1.05 * bound), 2.0, 2000, delayed=delayed)
        assert abs(inside[-1] - 2.0) < 1e-3
        assert abs(outside[-1] - 2.0) > 1e3


@settings(max_examples=40, deadline=None)
@given(
    k=st.floats(1.0, 1e4),
    log_ratio=st.floats(-1.0, 1.0),
    f_d=st.floats(0.5, 10.0),
    delayed=st.booleans(),
)
def test_property_converges_within_the_bound(
    k: float, log_ratio: float, f_d: float, delayed: bool
) -> None:
    controller = AdaptiveForceController(bandwidth=10.0, k_hat_min=0.01, k_hat_max=1e6)
    f = simulate(controller, k, k * 10.0**log_ratio, f_d, steps=3000, delayed=delayed)
    assert abs(f[-1] - f_d) < 1e-3 * f_d


def test_sign_too_little_tension_moves_away_from_the_contact() -> None:
    controller = AdaptiveForceController()
    towards_contact = np.array([0.0, 1.0, 0.0])
    v = controller.velocity(f_desired=3.0, f_current=1.0, direction=towards_contact, k_hat=100.0)
    assert v @ towards_contact < 0.0
    np.testing.assert_allclose(v, [0.0, -10.0 / 100.0 * 2.0, 0.0])
    v = controller.velocity(f_desired=1.0, f_current=3.0, direction=towards_contact, k_hat=100.0)
    assert v @ towards_contact > 0.0


def test_k_hat_is_clamped() -> None:
    controller = AdaptiveForceController(bandwidth=10.0, k_hat_min=5.0, k_hat_max=5000.0)
    assert controller.gain(1e-9) == pytest.approx(10.0 / 5.0)
    assert controller.gain(-3.0) == pytest.approx(10.0 / 5.0)
    assert controller.gain(1e9) == pytest.approx(10.0 / 5000.0)
    assert controller.gain(None) == pytest.approx(10.0 / 5000.0)
    assert controller.gain(float("nan")) == pytest.approx(10.0 / 5000.0)
    assert controller.gain(200.0) == pytest.approx(10.0 / 200.0)


def test_clamp_protects_against_a_bad_estimate() -> None:
    # a k_hat far too low would diverge; the clamp keeps the ratio inside the bound
    k = 100.0
    unclamped = AdaptiveForceController(k_hat_min=1e-3, k_hat_max=1e6)
    clamped = AdaptiveForceController(k_hat_min=5.0, k_hat_max=5000.0)
    assert abs(simulate(unclamped, k, 1.0, 2.0, 500)[-1]) > 1e3
    assert abs(simulate(clamped, k, 1.0, 2.0, 500)[-1] - 2.0) < 1e-3


def test_max_speed_bounds_the_speed() -> None:
    controller = AdaptiveForceController(max_speed=0.05)
    assert controller.speed(100.0, 0.0, 10.0) == pytest.approx(0.05)
    assert controller.speed(0.0, 100.0, 10.0) == pytest.approx(-0.05)


def test_fixed_gain_ignores_k_hat_and_slows_down_with_soft_cables() -> None:
    fixed = FixedGainForceController(k_f=0.01)
    assert fixed.gain(1.0) == fixed.gain(1000.0) == 0.01
    soft = simulate(fixed, 10.0, None, 2.0, 500)
    stiff = simulate(fixed, 1000.0, None, 2.0, 500)
    adaptive = AdaptiveForceController(bandwidth=10.0)
    soft_adaptive = simulate(adaptive, 10.0, 10.0, 2.0, 500)
    # after 2 s: the fixed gain has reached only 1 - (1 - k k_f dt)^500 of the soft target
    np.testing.assert_allclose(soft[-1], 2.0 * (1 - (1 - 10.0 * 0.01 * DT) ** 500), rtol=1e-9)
    assert soft[-1] < 0.2 * 2.0
    assert abs(stiff[-1] - 2.0) < 1e-3
    assert abs(soft_adaptive[-1] - 2.0) < 1e-3
    # and it diverges on a cable stiff enough: k k_f dt > 2
    assert abs(simulate(fixed, 60000.0, None, 2.0, 200)[-1]) > 1e3


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"bandwidth": 0.0}, "bandwidth"),
        ({"k_hat_min": -1.0}, "k_hat_min"),
        ({"k_hat_max": float("inf")}, "k_hat_max"),
        ({"k_hat_min": 10.0, "k_hat_max": 5.0}, "must not exceed"),
        ({"max_speed": 0.0}, "max_speed"),
    ],
)
def test_adaptive_rejects_bad_arguments(kwargs: dict[str, float], match: str) -> None:
    with pytest.raises(InvalidArgumentError, match=match):
        AdaptiveForceController(**kwargs)


def test_fixed_rejects_bad_gain() -> None:
    with pytest.raises(InvalidArgumentError, match="k_f"):
        FixedGainForceController(k_f=-0.1)
    with pytest.raises(InvalidArgumentError, match="dt"):
        AdaptiveForceController().max_stiffness_ratio(0.0)
