"""C's pair gives way along the slot when the cable outside the pair pulls on it."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.model import PathGraph
from tautwire.primitives import make_context
from tautwire.primitives.context import ClipInfo
from tautwire.primitives.parallel_clipping import (
    GIVE_WAY_MARGIN,
    OUTSIDE_PULL,
    ParallelClipping,
)
from tautwire.robot import GripperState, Observation, Wrench

SEAT = np.array([0.205, 0.3465, 0.08])
YAW = 2.1445  # random board 467180584's F3
LENGTH = 0.03
Q = np.array([1.0, 0.0, 0.0, 0.0])


def _slot() -> np.ndarray:
    return np.array([math.cos(YAW), math.sin(YAW), 0.0])


def _observation(
    time: float, left_force: np.ndarray, right_force: np.ndarray | None
) -> Observation:
    slot = _slot()
    left = GripperState(SEAT + 0.06 * slot + [0.0, 0.0, 0.015], Q)
    right = GripperState(SEAT - 0.06 * slot + [0.0, 0.0, 0.015], Q)
    wrenches = [Wrench("left", np.asarray(left_force, dtype=float), np.zeros(3))]
    if right_force is not None:
        wrenches.append(Wrench("right", np.asarray(right_force, dtype=float), np.zeros(3)))
    return Observation(time, left, right, tuple(wrenches))


def _started(right_sensed: bool = True) -> tuple[ParallelClipping, object]:
    # F2 behind the right (near) gripper, on the slot's minus side
    slot = _slot()
    f2 = SEAT - 0.13 * slot
    positions = [f2, SEAT - 0.06 * slot + [0, 0, 0.015], SEAT + 0.06 * slot + [0, 0, 0.015]]
    graph = PathGraph.from_positions(
        [np.array(p) for p in positions],
        mass_per_length=0.0,
        kinds=["fixed", "gripper", "gripper"],
        labels=["F2", "right", "left"],
    )
    ctx = make_context(
        graph, "left", k_initial=200.0, clips={"F3": ClipInfo(SEAT, YAW, 2.5, LENGTH)}
    )
    c = ParallelClipping("F3")
    between = 3.0 * slot  # the span between the grippers pulls them together
    c.on_start(_observation(0.0, -between, between if right_sensed else None), ctx)
    assert not c.outcome.done, c.outcome
    return c, ctx


def test_a_taut_near_span_moves_the_pair_towards_it_and_no_further_than_the_clip_allows() -> None:
    c, _ = _started()
    slot = _slot()
    between = 3.0 * slot
    # the near span back to F2 pulls the right gripper with 8 N along -slot
    near = -8.0 * slot
    for i in range(1, 2000):
        c._give_way(_observation(0.004 * i, -between, between + near), 0.004)
    # the pair's set point moved towards F2 (the left is on +slot: rel_dir = +slot)
    assert c.shift < 0.0
    reach = 0.06 - 0.5 * LENGTH - GIVE_WAY_MARGIN
    assert math.isclose(c.shift, -reach, abs_tol=1e-12)
    goal = c._goal()
    assert np.allclose(goal[:2], (SEAT - reach * slot)[:2])


def test_no_pull_from_outside_and_one_sensor_leave_the_pair_over_the_seat() -> None:
    c, _ = _started()
    slot = _slot()
    between = 3.0 * slot
    # below the limit (noise and the between span's weight): no shift
    small = 0.8 * OUTSIDE_PULL * slot
    for i in range(1, 500):
        c._give_way(_observation(0.004 * i, -between, between + small), 0.004)
    assert c.shift == 0.0
    one, _ = _started(right_sensed=False)
    for i in range(1, 500):
        one._give_way(_observation(0.004 * i, -between, None), 0.004)
    assert one.shift == 0.0


@settings(max_examples=30, deadline=None)
@given(pull=st.floats(-20.0, 20.0), across=st.floats(-10.0, 10.0))
def test_the_shift_follows_the_pull_along_the_line_and_stays_within_reach(
    pull: float, across: float
) -> None:
    c, _ = _started()
    slot = _slot()
    normal = np.array([-slot[1], slot[0], 0.0])
    between = 3.0 * slot
    extra = pull * slot + across * normal  # a pull across the line moves nothing
    for i in range(1, 300):
        c._give_way(_observation(0.004 * i, -between, between + extra), 0.004)
    reach = 0.06 - 0.5 * LENGTH - GIVE_WAY_MARGIN
    assert abs(c.shift) <= reach + 1e-12
    if abs(pull) <= OUTSIDE_PULL:
        assert c.shift == 0.0
    elif abs(pull) > 1.2 * OUTSIDE_PULL:
        assert c.shift * pull > 0.0
