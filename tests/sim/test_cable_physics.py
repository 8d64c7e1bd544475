"""The cable against closed forms: Hooke's law and the elastic catenary."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from tautwire.model.tension import G
from tautwire.sim.ground_truth import GroundTruth
from tests.sim.scenes import X_UP, anchor_and_gripper, rest


@pytest.mark.parametrize("k", [10.0, 100.0, 1000.0])
def test_static_stretch_matches_hooke(k: float) -> None:
    # A vertical cable from an anchor above to the gripper below. Its mean
    # tension is the sensed pull plus half its weight, and Hooke's law for the
    # whole cable says k * dl equals that mean tension.
    length, rho = 0.3, 0.03
    pull = 2.0  # N, roughly
    dl = pull / k
    top = np.array([0.0, 0.0, 0.9])
    gripper = top - np.array([0.0, 0.0, length + dl])
    world = anchor_and_gripper(top.tolist(), gripper.tolist(), length, k, rho, orientation=X_UP)
    rest(world, 0.5)
    force, _ = world.wrench("left")
    weight = rho * length * G
    mean_tension = force[2] + 0.5 * weight
    assert mean_tension == pytest.approx(k * dl, rel=0.02)
    assert np.hypot(force[0], force[1]) < 1e-3 * np.linalg.norm(force)


def test_hold_and_anchor_add_no_compliance_to_a_stiff_cable() -> None:
    # D learns k from how far the gripper moves per newton: any give of the
    # hold (a connect equality) or the anchor in series would read as a
    # softer cable. Vertical (no sag), k = 1500 N/m: steps of 0.2 mm of the
    # gripper must change the mean tension by k times the step.
    k, length, rho = 1500.0, 0.3, 0.03
    top = np.array([0.0, 0.0, 0.9])
    steps = np.array([0.0, 2e-4, 4e-4])
    tensions = []
    for extra in steps:
        gripper = top - np.array([0.0, 0.0, length + 1.5 / k + extra])
        world = anchor_and_gripper(top.tolist(), gripper.tolist(), length, k, rho, orientation=X_UP)
        rest(world, 0.5)
        tensions.append(world.wrench("left")[0][2] + 0.5 * rho * length * G)
    slope = np.polyfit(steps, tensions, 1)[0]
    assert slope == pytest.approx(k, rel=1e-3)


def _elastic_catenary(span: float, length: float, rho: float, k: float) -> tuple[float, float]:
    """Mid-span sag [m] and end slope [rad] of an elastic catenary, supports level."""
    w = rho * G
    ea = k * length  # axial rigidity EA [N]
    v0 = 0.5 * w * length  # vertical support force at each end

    def dx(s: float, h: float) -> float:
        t = np.hypot(h, v0 - w * s)
        return h * (1.0 / ea + 1.0 / t)

    def span_of(h: float) -> float:
        return quad(dx, 0.0, length, args=(h,))[0] - span

    h = brentq(span_of, 1e-6, 1e3)

    def dz(s: float) -> float:
        v = v0 - w * s
        return v * (1.0 / ea + 1.0 / np.hypot(h, v))

    return float(quad(dz, 0.0, 0.5 * length)[0]), float(np.arctan2(v0, h))


@pytest.mark.parametrize(("k", "span"), [(100.0, 0.3), (10.0, 0.36)])
def test_slack_cable_sag_matches_elastic_catenary(k: float, span: float) -> None:
    length, rho, height = 0.4, 0.03, 0.5
    expected, slope = _elastic_catenary(span, length, rho, k)
    # the gripper holds the end along the cable's tangent (tool x out of the cable)
    q = np.array([np.cos(0.5 * slope), 0.0, -np.sin(0.5 * slope), 0.0])
    world = anchor_and_gripper([0.0, 0.0, height], [span, 0.0, height], length, k, rho, q)
    rest(world, 1.0)
    truth = GroundTruth(world)
    # height at arc length L/2: a parabola through the three vertices around it
    arc, z = truth.arc_lengths("W"), truth.polyline("W")[:, 2]
    i = int(np.argmin(np.abs(arc - 0.5 * length)))
    fit = np.polyfit(arc[i - 1 : i + 2], z[i - 1 : i + 2], 2)
    sag = height - float(np.polyval(fit, 0.5 * length))
    assert sag == pytest.approx(expected, rel=0.02)
