import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from tautwire.primitives.clip_sensing import (
    PRESS_MARGIN,
    ClipHeight,
    PivotPress,
    far_rise,
    height_at_clip,
    push_tension,
)


def test_height_where_the_force_line_passes_the_clip() -> None:
    p = np.array([0.1, 0.0, 0.05])
    seat = np.array([0.0, 0.0, 0.02])
    d = np.array([-1.0, 0.0, -0.2]) / np.hypot(1.0, 0.2)
    assert height_at_clip(p, d, seat) == pytest.approx(0.05 - 0.2 * 0.1)
    assert height_at_clip(p, -d, seat) is None  # pointing away
    assert height_at_clip(p, np.array([0.0, 0.0, -1.0]), seat) is None


def test_seated_from_the_exit_of_the_slot() -> None:
    seat = np.array([0.0, 0.0, 0.0])
    sensing = ClipHeight(seat, np.array([1.0, 0.0, 0.0]), 0.006)
    p = np.array([0.056, 0.0, -0.05])  # 5 cm beyond the slot's exit, 5 cm below
    d = (np.array([0.006, 0.0, 0.0]) - p) / np.linalg.norm(np.array([0.006, 0.0, 0.0]) - p)
    for k in range(50):
        sensing.update(0.004 * k, p, d, True)
    assert sensing.height == pytest.approx(0.0, abs=1e-9) and sensing.seated


def test_push_tension_bounds() -> None:
    assert push_tension(2.0, 1.0, 15.0) == 6.0
    assert push_tension(5.0, 1.0, 15.0) == 9.0  # 60 % of the limit
    assert push_tension(1.0, 4.0, 15.0) == 4.0


def _pivot(stiffness: float, sin_far: float = 0.2, radius: float = 0.15) -> PivotPress:
    return PivotPress(
        radius=radius,
        tension=2.0,
        stiffness=stiffness,
        drop=0.09,
        sin_far=sin_far,
        sin_max=math.sin(math.radians(60.0)),
    )


def test_pivot_press_from_the_bend_that_the_table_allows() -> None:
    plan = _pivot(50.0)
    # at 4 N the span is 4 cm longer: the gripper 0.19 m from the exit, 9 cm below it
    assert plan.press(4.0) == pytest.approx(4.0 * (0.09 / 0.19 - 0.2))
    assert plan.press(2.0) == pytest.approx(2.0 * (0.09 / 0.15 - 0.2))
    # never steeper than sin_max: a gripper close to the clip
    close = PivotPress(0.05, 2.0, 1e4, 0.09, 0.0, 0.5)
    assert close.press(2.0) == pytest.approx(1.0)


def test_stiff_cable_keeps_three_times_the_push_force() -> None:
    plan = _pivot(1000.0, sin_far=0.1)
    assert plan.press(6.0) >= PRESS_MARGIN * 2.0
    assert plan.tension_for(2.0, 6.0, 9.0) == 6.0


def test_soft_cable_gets_the_tension_nearest_three_times_that_presses_enough() -> None:
    plan = _pivot(20.0, sin_far=0.1, radius=0.1)
    # 3 P = 3.6 N stretches the span by 8 cm: the bend flattens
    assert plan.press(3.6) < PRESS_MARGIN * 1.2
    f = plan.tension_for(1.2, 3.6, 9.0)
    assert plan.press(f) >= PRESS_MARGIN * 1.2 and 2.0 <= f < 3.6


def test_out_of_reach_clip_gets_the_hardest_press() -> None:
    plan = _pivot(10.0, sin_far=0.4)
    f = plan.tension_for(4.0, 9.0, 9.0)
    grid = np.linspace(2.0, 9.0, 200)
    assert plan.press(f) == pytest.approx(max(plan.press(float(g)) for g in grid), rel=0.02)


@given(
    st.floats(5.0, 2000.0),
    st.floats(-0.3, 0.5),
    st.floats(0.5, 4.0),
    st.floats(0.5, 9.0),
)
def test_planned_tension_is_the_preferred_one_or_within_bounds(
    stiffness: float, sin_far: float, push: float, preferred: float
) -> None:
    plan = _pivot(stiffness, sin_far)
    f = plan.tension_for(push, preferred, 9.0)
    assert f == preferred or 2.0 <= f <= 9.0
    if f != preferred:  # the preferred one fell short, and f presses at least as hard
        assert plan.press(preferred) < PRESS_MARGIN * push
        assert plan.press(f) >= min(PRESS_MARGIN * push, plan.press(preferred)) - 1e-9


def _sense(p: np.ndarray, towards: np.ndarray) -> ClipHeight:
    sensing = ClipHeight(np.zeros(3), np.array([1.0, 0.0, 0.0]), 0.006)
    d = (towards - p) / np.linalg.norm(towards - p)
    for k in range(50):
        sensing.update(0.004 * k, p, d, True)
    return sensing


def test_a_line_far_below_the_seat_is_not_seated() -> None:
    # the case: the cable pushed down 15 mm below the seat, beside the clip
    sensing = _sense(np.array([0.056, 0.0, -0.05]), np.array([0.006, 0.0, -0.015]))
    assert sensing.height == pytest.approx(-0.015, abs=1e-6)
    assert not sensing.seated
    assert sensing.verdict("C1").cause == "not_clipped"


def test_a_line_beside_the_slot_is_not_seated() -> None:
    sensing = _sense(np.array([0.056, 0.0, -0.05]), np.array([0.006, 0.012, 0.0]))
    assert abs(sensing.height or 1.0) < 0.004  # at the seat's height, but beside it
    assert sensing.miss == pytest.approx(0.012, rel=0.05)
    assert not sensing.seated
    within = _sense(np.array([0.056, 0.0, -0.05]), np.array([0.006, 0.003, 0.001]))
    assert within.seated and within.verdict("C1").status == "success"


@given(st.floats(-0.5, 0.5), st.floats(0.02, 0.2))
def test_the_miss_is_the_horizontal_distance_of_the_line_from_the_point(
    angle: float, distance: float
) -> None:
    from tautwire.primitives.clip_sensing import miss_at_clip

    p = np.array([distance, 0.0, 0.05])
    d = np.array([-math.cos(angle), math.sin(angle), -0.3])
    d /= np.linalg.norm(d)
    assert miss_at_clip(p, d, np.zeros(3)) == pytest.approx(distance * abs(math.sin(angle)))


@given(st.floats(-math.pi, math.pi), st.floats(0.05, 0.4), st.floats(-0.1, 0.1))
def test_the_far_rise_is_taken_from_the_slot_end_towards_the_contact(
    yaw: float, run: float, rise: float
) -> None:
    seat = np.array([0.3, -0.1, 0.08])
    slot = np.array([math.cos(yaw), math.sin(yaw), 0.0])
    half = 0.015
    for sense in (1.0, -1.0):  # the contact beyond either end of the slot
        entry = seat + sense * half * slot
        contact = entry + sense * run * slot + np.array([0.0, 0.0, rise])
        assert far_rise(contact, seat, slot, half) == pytest.approx(math.atan2(rise, run))
