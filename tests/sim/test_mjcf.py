"""The MJCF a scene is built from: the clip's channel holds a cable pulled sideways."""

from __future__ import annotations

import numpy as np
import pytest

from tests.sim.scenes import anchor_and_gripper, rest


@pytest.mark.parametrize(("aside", "rest_length"), [(0.2, 0.37), (0.1, 0.29)])
def test_a_clip_s_walls_hold_a_cable_kinked_in_it_under_tension(
    aside: float, rest_length: float
) -> None:
    """A cable from an anchor through a clip, turned 34 or 53 deg at its exit, at 12 and 8.4 N.

    The kink presses the cable against a wall with 2 T sin(bend / 2), 7-7.5 N:
    it must stay in the channel (2 mm walls let the 53 deg one through, and
    it fell 61 mm beside the clip).
    """
    pytest.importorskip("mujoco")
    from tautwire.sim import ClipSpec
    from tautwire.sim.ground_truth import GroundTruth

    seat = np.array([0.15, 0.0, 0.3])
    world = anchor_and_gripper(
        [0.0, 0.0, 0.3],
        [0.3, aside, 0.3],
        rest_length,
        250.0,
        fixtures=(ClipSpec("C", seat.tolist(), 0.0, 2.0),),
        via=("C",),
    )
    truth = GroundTruth(world)
    tensions = []
    for _ in range(10):
        rest(world, 0.2)
        assert truth.clipped("C", "W"), truth.seat("C", "W") - seat
        tensions.append(float(np.median(truth.tensions("W"))))
    assert min(tensions[-3:]) > 8.0  # the load is there: 2 T sin(bend / 2) >= 7 N
