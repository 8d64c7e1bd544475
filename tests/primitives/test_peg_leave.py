"""The tangent point where a taut cable leaves a peg."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from tautwire.primitives.peg_leave import (
    axis_offset,
    leave_point,
    path_turn,
    turn_side,
    wrap_side,
)

AXIS = np.array([0.25, 0.15, 0.08])


@given(st.floats(-math.pi, math.pi), st.floats(0.05, 0.3), st.sampled_from([1.0, -1.0]))
def test_the_line_from_the_leave_point_is_tangent_and_keeps_the_peg_on_its_side(
    bearing: float, distance: float, side: float
) -> None:
    rho = 0.0085
    through = AXIS + distance * np.array([math.cos(bearing), math.sin(bearing), 0.0])
    t = leave_point(AXIS, rho, through, side)
    assert float(np.linalg.norm((t - AXIS)[:2])) == pytest.approx(rho)
    assert t[2] == AXIS[2]
    # tangent: the radius is normal to the line
    assert float((t - AXIS)[:2] @ (through - t)[:2]) == pytest.approx(0.0, abs=1e-9)
    # a gripper beyond ``through`` on that line sees the peg on that side
    gripper = t + 1.5 * (through - t)
    direction = (t - gripper) / np.linalg.norm(t - gripper)
    assert wrap_side(AXIS, gripper, direction) == side
    # and its line passes a radius beside the axis, also when it slopes
    assert axis_offset(AXIS, gripper, direction) == pytest.approx(side * rho, rel=1e-6)
    above = gripper + np.array([0.0, 0.0, 0.03])
    sloped = (t - above) / np.linalg.norm(t - above)
    assert axis_offset(AXIS, above, sloped) == pytest.approx(side * rho, rel=1e-6)


def test_without_a_side_or_from_inside_the_circle_it_is_the_axis_point() -> None:
    far = AXIS + np.array([0.1, 0.0, 0.0])
    assert np.array_equal(leave_point(AXIS, 0.008, far, 0.0), AXIS)
    assert np.array_equal(leave_point(AXIS, 0.008, AXIS + np.array([0.005, 0, 0]), 1.0), AXIS)


def test_a_line_beside_the_axis_says_which_side_the_peg_is_on() -> None:
    gripper = AXIS + np.array([0.2, 0.0, 0.0])
    # the line from the gripper passes 8 mm south of the axis: heading east from the
    # peg to the gripper, the axis is on the cable's left (north)
    towards = AXIS + np.array([0.0, -0.008, 0.0]) - gripper
    assert wrap_side(AXIS, gripper, towards / np.linalg.norm(towards)) == 1.0
    towards = AXIS + np.array([0.0, 0.008, 0.0]) - gripper
    assert wrap_side(AXIS, gripper, towards / np.linalg.norm(towards)) == -1.0


def test_the_path_turning_round_the_peg_gives_its_side() -> None:
    # from the west, round the peg, to the north-east: a left turn, the peg on the left
    before = AXIS + np.array([-0.12, -0.025, 0.0])
    gripper = AXIS + np.array([0.15, 0.25, 0.04])
    assert turn_side(before, AXIS, gripper) == 1.0
    # to the south-east: a right turn
    assert turn_side(before, AXIS, AXIS + np.array([0.15, -0.25, 0.0])) == -1.0
    # straight on: no side
    assert turn_side(before, AXIS, AXIS + 2.0 * (AXIS - before)) == 0.0
    # the leave point on that side puts the line from it to the gripper beside the
    # axis with the peg on the cable's left, as the force's line of the real cable
    t = leave_point(AXIS, 0.0085, gripper, 1.0)
    direction = (t - gripper) / np.linalg.norm(t - gripper)
    assert wrap_side(AXIS, gripper, direction) == 1.0


@given(
    st.floats(0.1, math.pi - 0.2),
    st.sampled_from([1.0, -1.0]),
    st.integers(-2, 2),
    st.floats(-0.4, 0.4),
)
def test_a_wound_peg_takes_its_side_from_the_windings_followed(
    size: float, sign: float, windings: int, drift: float
) -> None:
    # a cable wound round the peg by angle + 2 pi k (the shipped harness's W2:
    # -359 deg round P2, whose path alone reads a 1 deg left turn): the turn
    # followed last, off by what a move turned it since, picks the winding
    angle = sign * size
    before = AXIS - np.array([0.1, 0.0, 0.0])
    gripper = AXIS + 0.2 * np.array([math.cos(angle), math.sin(angle), 0.0])
    turn = angle + 2.0 * math.pi * windings
    assert turn_side(before, AXIS, gripper, turn + drift) == math.copysign(1.0, turn)
    # without it, the path's angle alone
    assert turn_side(before, AXIS, gripper) == math.copysign(1.0, angle)


@given(st.floats(-math.pi + 0.05, math.pi - 0.05), st.integers(-2, 2))
def test_the_path_s_turn_is_the_angle_from_the_way_in_to_the_way_out(
    angle: float, windings: int
) -> None:
    # F takes the side from the path where it turns by PATH_SIDE_TURN or
    # more (the shipped harness's P1 at seeds 0 and 1: the force's line
    # passed the model's axis 5 mm on the wrong side)
    before = AXIS - np.array([0.1, 0.0, 0.0])
    gripper = AXIS + 0.2 * np.array([math.cos(angle), math.sin(angle), 0.0])
    assert path_turn(before, AXIS, gripper) == pytest.approx(angle, abs=1e-9)
    turn = angle + 2.0 * math.pi * windings
    assert path_turn(before, AXIS, gripper, turn + 0.3) == pytest.approx(turn, abs=1e-9)
    if abs(turn) > 1e-6:
        assert turn_side(before, AXIS, gripper, turn) == math.copysign(1.0, turn)
