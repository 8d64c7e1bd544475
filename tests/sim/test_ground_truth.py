"""GroundTruth: polyline, tensions, stiffness, fixture contacts."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.sim.ground_truth import GroundTruth
from tests.sim.scenes import anchor_and_gripper, peg_scene, rest


def test_polyline_tension_and_stiffness_of_a_taut_cable() -> None:
    k = 200.0
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.3, 0.0, 0.3], 0.29, k)
    rest(world, 0.5)
    truth = GroundTruth(world)
    p = truth.polyline("W")
    assert p.shape == (len(truth.arc_lengths("W")), 3)
    assert np.allclose(p[0], [0.0, 0.0, 0.3]) and np.allclose(p[-1], [0.3, 0.0, 0.3], atol=1e-4)
    tension = truth.tensions("W")
    assert tension.shape == (len(p) - 1,)
    # tension along a light taut cable is nearly uniform and equals k * stretch
    assert tension.mean() == pytest.approx(k * (truth.length("W") - 0.29), rel=0.01)
    assert np.ptp(tension) < 0.02 * tension.mean()
    assert truth.stiffness("W") == k
    assert truth.rest_lengths("W").sum() == pytest.approx(0.29)
    with pytest.raises(InvalidArgumentError, match="cables"):
        truth.polyline("nope")


def test_peg_contact_lies_on_the_axis_at_the_cable_height() -> None:
    world = peg_scene()
    twist = np.zeros(12)
    twist[0:3] = [0.02, 0.01, 0.0]  # take up the slack: the cable wraps the peg
    world.set_twist(twist)
    for _ in range(500):
        world.step()
    truth = GroundTruth(world)
    assert set(truth.in_contact()) == {"A", "P"}
    peg = truth.contact("P")
    assert peg is not None and peg.force > 0.1
    assert np.allclose(peg.point[:2], [0.15, 0.05])
    p = truth.polyline("W")
    near = p[np.argmin(np.linalg.norm(p[:, :2] - [0.15, 0.05], axis=1))]
    assert peg.point[2] == pytest.approx(near[2], abs=2e-3)
    anchor = truth.contact("A")
    assert anchor is not None and np.allclose(anchor.point, [0.0, 0.0, 0.12])
    assert truth.contact("nothing") is None
