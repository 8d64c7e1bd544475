import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.peg_axis_fit import MIN_SPREAD, PegAxisFit

Z = np.array([0.0, 0.0, 1.0])


def wrap_lines(centre, radius, start, turn, n=120, distance=0.25, wobble=0.0, seed=0):
    """Lines tangent to a circle about ``centre`` (sense +1 about z), offsets sawing by +-wobble."""
    rng = np.random.default_rng(seed)
    out = []
    for j, a in enumerate(np.linspace(start, start + turn, n)):
        u = np.array([math.cos(a), math.sin(a), 0.0])  # from the peg towards the gripper
        side = -np.cross(Z, u)  # from the line towards the axis
        saw = wobble * (2.0 * ((j / 15.0) % 1.0) - 1.0)
        q = centre - (radius + saw) * side + distance * u + rng.normal(0.0, 1e-4, 3)
        f = -3.0 * u
        out.append((q, f, side))
    return out


@settings(max_examples=25, deadline=None)
@given(
    start=st.floats(0.0, 2.0 * math.pi),
    turn=st.floats(math.radians(40.0), 2.0 * math.pi),
    cx=st.floats(-0.5, 0.5),
    cy=st.floats(-0.5, 0.5),
)
def test_exact_tangents_give_the_axis(start, turn, cx, cy):
    centre = np.array([cx, cy, 0.1])
    fit = PegAxisFit(Z, 0.012, 0.0)
    for q, f, side in wrap_lines(centre, 0.012, start, turn):
        fit.add(q, f, side, 1e-6)
    est = fit.estimate(centre)
    assert est is not None
    assert np.linalg.norm(est[0][:2] - centre[:2]) < 5e-4
    assert est[0][2] == pytest.approx(0.1)


def test_nothing_before_the_lines_spread():
    fit = PegAxisFit(Z, 0.012, 0.002)
    for q, f, side in wrap_lines(np.zeros(3), 0.012, 0.3, 0.5 * MIN_SPREAD, n=30):
        fit.add(q, f, side, 1e-6)
    assert fit.estimate(np.zeros(3)) is None


@pytest.mark.parametrize("prior", [0.010, 0.012, 0.014])
def test_sawing_offsets_and_a_wrong_radius_stay_within_the_reported_covariance(prior):
    # a third of a turn whose offsets saw by +-3 mm, the radius prior up to 2 mm off:
    # the error lies within the reported covariance (chi-square, 2 dof, 99.7 %)
    for seed in range(5):
        centre = np.array([0.3, -0.2, 0.05])
        fit = PegAxisFit(Z, prior, 0.002)
        for q, f, side in wrap_lines(centre, 0.012, 0.2 + seed, 2.1, wobble=0.003, seed=seed):
            fit.add(q, f, side, 1e-6)
        est = fit.estimate(centre)
        assert est is not None
        err = est[0][:2] - centre[:2]
        nees = float(err @ np.linalg.solve(est[1][:2, :2], err))
        assert nees <= 11.8
        assert np.linalg.norm(err) < 6e-3


def test_bad_lines_are_skipped_and_bad_arguments_refused():
    fit = PegAxisFit(Z, 0.01, 0.001)
    fit.add([np.nan, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], 1e-6)
    fit.add([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0], 1e-6)  # along the axis
    fit.add([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], 0.0)  # no weight
    assert fit.count == 0
    with pytest.raises(InvalidArgumentError):
        PegAxisFit([0.0, 0.0, 0.0], 0.01, 0.001)
    with pytest.raises(InvalidArgumentError):
        PegAxisFit(Z, -0.01, 0.001)


def drifting_lines(centre, radius, start, turn, drift, distance=0.18, n=60):
    """Tangent lines whose offset from the axis drifts from radius + drift to radius - drift."""
    out = []
    for j, a in enumerate(np.linspace(start, start + turn, n)):
        u = np.array([math.cos(a), math.sin(a), 0.0])
        side = -np.cross(Z, u)
        r = radius + drift * (1.0 - 2.0 * j / (n - 1))
        out.append((centre - r * side + distance * u, -3.0 * u, side))
    return out


def test_an_offset_drift_along_a_short_wrap_stays_within_the_reported_covariance():
    # random board 1098434850's I about F4: a cable just caught on the peg,
    # turned 34 deg, its lines' offsets drifting 4 mm from end to middle; the
    # axis ends about 13 mm along the lines from the peg
    centre = np.array([0.24, -0.13, 0.08])
    fit = PegAxisFit(Z, 0.0115, 0.002)
    for q, f, side in drifting_lines(centre, 0.0115, -0.1, math.radians(34.0), 0.004):
        fit.add(q, f, side, 1e-6)
    est = fit.estimate(centre)
    assert est is not None
    err = est[0][:2] - centre[:2]
    assert np.linalg.norm(err) > 0.008  # the drift moves the axis far along the lines
    nees = float(err @ np.linalg.solve(est[1][:2, :2], err))
    assert nees <= 11.8  # chi-square, 2 dof, 99.7 %


def test_an_offset_drift_matters_less_the_further_the_cable_wraps():
    centre = np.array([0.24, -0.13, 0.08])
    stds = []
    for turn in (34.0, 130.0, 360.0):
        fit = PegAxisFit(Z, 0.0115, 0.002)
        for q, f, side in drifting_lines(centre, 0.0115, 0.0, math.radians(turn), 0.0, n=120):
            fit.add(q, f, side, 1e-6)
        est = fit.estimate(centre)
        assert est is not None
        stds.append(math.sqrt(float(np.linalg.eigvalsh(est[1][:2, :2]).max())))
    assert stds[0] > stds[1] > stds[2]
    assert stds[1] < 0.005  # a third of a turn keeps its trust (tolerance 9 mm and more)
