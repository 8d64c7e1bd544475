import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.estimation import contact_normal_equations, contact_point_least_squares
from tautwire.experiments.synthetic_circle import circle

coord = st.floats(-1.0, 1.0)
point = st.tuples(coord, coord, coord).map(np.array)


@settings(max_examples=40, deadline=None)
@given(contact=point, seed=st.integers(0, 10_000))
def test_noise_free_lines_meet_at_the_contact(contact, seed):
    rng = np.random.default_rng(seed)
    p = contact + rng.uniform(0.1, 0.5, (6, 1)) * rng.normal(size=(6, 3))
    tension = rng.uniform(0.5, 10.0, (6, 1))
    f = tension * (contact - p)
    res = contact_point_least_squares(p, f, force_noise=0.05)
    assert res.rank == 3
    np.testing.assert_allclose(res.estimate, contact, atol=1e-9)
    assert res.residual_rms < 1e-9
    assert np.all(np.isfinite(res.covariance))


def test_normal_equations_are_the_papers_unnormalised_g_scaled_by_the_noise():
    rng = np.random.default_rng(0)
    p = rng.normal(size=(5, 3))
    f = rng.normal(size=(5, 3)) * 3.0
    d, sigma = 0.3, 0.05
    u = f / np.linalg.norm(f, axis=1)[:, None]
    var = (d * sigma / np.linalg.norm(f, axis=1)) ** 2
    A, b = contact_normal_equations(p, u, var)
    G = [fj @ fj * np.eye(3) - np.outer(fj, fj) for fj in f]  # equ:ls_observation_model
    A_ref = sum(Gj for Gj in G) / (d * sigma) ** 2
    b_ref = sum(Gj @ pj for Gj, pj in zip(G, p, strict=True)) / (d * sigma) ** 2
    np.testing.assert_allclose(A, A_ref, rtol=1e-12)
    np.testing.assert_allclose(b, b_ref, rtol=1e-12)


def test_parallel_forces_raise_a_clear_error_not_nan():
    p = np.array([[0.0, 0.0, 0.0], [0.1, 0.0, 0.0], [0.3, 0.0, 0.0]])
    f = np.array([[1.0, 0.0, 0.0]] * 3)
    with pytest.raises(InvalidArgumentError, match=r"parallel.*rank 2 of 3"):
        contact_point_least_squares(p, f)
    # with a prior the line is resolved and nothing is NaN
    res = contact_point_least_squares(
        p, f, prior_mean=[0.5, 0.0, 0.0], prior_covariance=0.01 * np.eye(3)
    )
    assert res.rank == 2 and res.spread == pytest.approx(0.0, abs=1e-6)
    assert np.all(np.isfinite(res.estimate)) and np.all(np.isfinite(res.covariance))
    np.testing.assert_allclose(res.estimate, [0.5, 0.0, 0.0], atol=1e-9)


def test_two_samples_spread_is_their_angle():
    p = np.array([[0.0, -1.0, 0.0], [-1.0, 0.0, 0.0]])
    f = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0]])
    res = contact_point_least_squares(p, f)
    assert res.spread == pytest.approx(np.pi / 2)
    np.testing.assert_allclose(res.estimate, [0.0, 0.0, 0.0], atol=1e-12)


def test_covariance_matches_the_error_spread_over_seeds():
    errs, nees = [], []
    for seed in range(200):
        d = circle(seed, n=125)
        res = contact_point_least_squares(d.p_gripper, d.f_sens, force_noise=0.05)
        e = res.estimate - d.contact[0]
        errs.append(e)
        nees.append(e @ np.linalg.solve(res.covariance, e))
        assert res.chi2 == pytest.approx(2 * 125 - 3, rel=0.35)
    # NEES is chi-square(3): mean 3, and the mean of 200 has std 0.17
    assert 2.5 <= np.mean(nees) <= 3.5
    assert np.all(np.abs(np.mean(errs, axis=0)) < 1e-4)


@pytest.mark.parametrize(
    ("p", "f", "kwargs"),
    [
        (np.zeros((2, 2)), np.ones((2, 2)), {}),
        (np.zeros((0, 3)), np.ones((0, 3)), {}),
        (np.zeros((2, 3)), np.array([[1.0, 0, 0], [0, 0, 0]]), {}),
        (np.full((2, 3), np.nan), np.ones((2, 3)), {}),
        (np.zeros((2, 3)), np.ones((2, 3)), {"force_noise": 0.0}),
        (np.zeros((2, 3)), np.ones((2, 3)), {"prior_mean": [0, 0, 0]}),
        (np.zeros((2, 3)), np.ones((2, 3)), {"iterations": 0}),
    ],
)
def test_bad_arguments_raise(p, f, kwargs):
    with pytest.raises(InvalidArgumentError):
        contact_point_least_squares(p, f, **kwargs)
