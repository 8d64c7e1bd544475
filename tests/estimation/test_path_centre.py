import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.path_centre import PathCentre

AXIS = np.array([0.0, 0.0, 1.0])


def circle(
    centre: np.ndarray,
    free_length: float,
    k: float,
    turn: float,
    n: int = 300,
    radius: float = 0.0,
    sense: float = 1.0,
    seed: int = 0,
    noise: float = 2e-4,
) -> list[tuple[np.ndarray, float]]:
    """A taut gripper's path about ``centre``: tension swinging 20 % at 1.5 Hz."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        phi = turn * i / (n - 1)
        t = 0.04 * i
        T = 3.0 * (1.0 + 0.2 * math.sin(2.0 * math.pi * 1.5 * t))
        L = free_length - sense * radius * phi + T / k
        D = math.hypot(L, radius)
        p = centre + D * np.array([math.cos(phi), math.sin(phi), 0.0])
        p = p + rng.normal(scale=noise, size=3)
        out.append((p, T))
    return out


@given(
    st.floats(0.15, 1.0),
    st.floats(50.0, 1500.0),
    st.floats(0.6, 6.0),
    st.integers(0, 1000),
)
@settings(max_examples=25, deadline=None)
def test_a_point_contact_is_the_centre_of_the_path(
    length: float, k: float, turn: float, seed: int
) -> None:
    centre = np.array([0.2, -0.1, 0.05])
    fit = PathCentre(AXIS, 0.0, 1.0, k)
    for p, T in circle(centre, length, k, turn, seed=seed):
        fit.add(p, T)
    start = centre + np.array([0.02, -0.015, 0.0])  # where the force's lines say
    result = fit.estimate(start)
    assert result is not None
    c, cov = result
    err = c - centre
    assert abs(err[2] - 0.0) < 1e-12 + abs(start[2] - centre[2])  # along the axis: the start's
    assert np.linalg.norm(err[:2]) < 2e-3
    # honest: the error within 4 std of the reported covariance in the plane
    S = cov[:2, :2] + 1e-12 * np.eye(2)
    assert float(err[:2] @ np.linalg.solve(S, err[:2])) < 16.0
    assert np.allclose(cov[2, :], 0.0) and np.allclose(cov[:, 2], 0.0)


@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_a_peg_wound_or_unwound_is_found_from_the_shrinking_circle(sense: float) -> None:
    centre = np.array([0.0, 0.3, 0.0])
    fit = PathCentre(AXIS, 0.012, sense, 300.0)
    for p, T in circle(centre, 0.3, 300.0, 2.5, radius=0.012, sense=sense, seed=4):
        fit.add(p, T)
    result = fit.estimate(centre + np.array([-0.01, 0.01, 0.0]))
    assert result is not None
    assert np.linalg.norm(result[0][:2] - centre[:2]) < 1.5e-3
    # the same path read as a point contact is off: the wound length matters
    as_point = PathCentre(AXIS, 0.0, sense, 300.0)
    for p, T in circle(centre, 0.3, 300.0, 2.5, radius=0.012, sense=sense, seed=4):
        as_point.add(p, T)
    wrong = as_point.estimate(centre)
    assert wrong is not None
    assert np.linalg.norm(wrong[0][:2] - centre[:2]) > 3e-3


def test_the_stretch_is_modelled_from_the_tension() -> None:
    # a soft cable: the radius swings 12 mm with the tension; without the
    # stretch the centre is off, with it found
    centre = np.zeros(3)
    path = circle(centre, 0.3, 50.0, 1.5, seed=2)
    fit = PathCentre(AXIS, 0.0, 1.0, 50.0)
    rigid = PathCentre(AXIS, 0.0, 1.0, None)
    for p, T in path:
        fit.add(p, T)
        rigid.add(p, T)
    good, bad = fit.estimate(centre), rigid.estimate(centre)
    assert good is not None and bad is not None
    assert np.linalg.norm(good[0][:2]) < 1e-3
    # the rigid reading is honestly less sure
    assert np.trace(bad[1]) > 4.0 * np.trace(good[1])


def test_no_estimate_before_the_gripper_turned() -> None:
    fit = PathCentre(AXIS, 0.0, 1.0, 200.0)
    assert fit.estimate(np.zeros(3)) is None
    for p, T in circle(np.zeros(3), 0.3, 200.0, math.radians(10.0), n=50):
        fit.add(p, T)
    assert fit.estimate(np.zeros(3)) is None  # 10 deg: below MIN_TURN


def test_non_finite_samples_are_skipped() -> None:
    fit = PathCentre(AXIS, 0.0, 1.0, 200.0)
    for p, T in circle(np.zeros(3), 0.3, 200.0, 1.0, n=100):
        fit.add(p, T)
    fit.add(np.array([np.nan, 0.0, 0.0]), 3.0)
    fit.add(np.array([0.3, 0.0, 0.0]), math.inf)
    assert fit.count == 100
    assert fit.estimate(np.zeros(3)) is not None


def test_bad_arguments_are_named() -> None:
    with pytest.raises(InvalidArgumentError, match="axis"):
        PathCentre(np.zeros(3), 0.0, 1.0, 100.0)
    with pytest.raises(InvalidArgumentError, match="radius"):
        PathCentre(AXIS, -0.01, 1.0, 100.0)
