"""C's choice of which side of the clip each gripper ends on (``near_side``)."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from tautwire.model import PathGraph
from tautwire.primitives import make_context
from tautwire.primitives.parallel_clipping import near_side

SEAT = np.array([0.26, -0.38, 0.08])


def _context(fixed: list[float], left: list[float], right: list[float], fixed_first: bool = True):
    points = [fixed, left, right] if fixed_first else [left, right, fixed]
    kinds = ["fixed", "gripper", "gripper"] if fixed_first else ["gripper", "gripper", "fixed"]
    labels = ["F5", "left", "right"] if fixed_first else ["left", "right", "F5"]
    graph = PathGraph.from_positions(
        [np.array(p) for p in points], mass_per_length=0.0, kinds=kinds, labels=labels
    )
    return make_context(graph, "right", k_initial=100.0)


def test_random_board_905979088_puts_the_near_gripper_on_the_fixed_points_side() -> None:
    # F5 before the pair, F6's slot at 19.9 deg; the pair lay along F5's
    # slot (-65 deg), 96 deg from the slot the right way and 84 the wrong
    # way. The left gripper holds the cable nearer F5: it ends on F5's side.
    slot = np.array([math.cos(0.347), math.sin(0.347), 0.0])
    ctx = _context([0.2859, -0.2409, 0.08], [0.345, -0.381, 0.094], [0.395, -0.486, 0.103])
    sense = near_side(ctx, SEAT, slot)
    assert sense == 1.0
    left_end = SEAT + 0.058 * sense * slot
    right_end = SEAT - 0.058 * sense * slot
    f5 = np.array([0.2859, -0.2409, 0.08])
    assert np.linalg.norm(left_end - f5) < np.linalg.norm(right_end - f5)
    # the rule it replaces (the current line's projection) chose the far side
    rel = np.array([0.345 - 0.395, -0.381 + 0.486, 0.0])
    assert float(rel @ slot) < 0.0


def test_no_fixed_point_or_one_square_to_the_slot_leaves_the_choice_to_the_line() -> None:
    slot = np.array([1.0, 0.0, 0.0])
    graph = PathGraph.from_positions(
        [np.array([0.2, -0.4, 0.09]), np.array([0.3, -0.4, 0.09])],
        mass_per_length=0.0,
        kinds=["gripper", "gripper"],
        labels=["left", "right"],
    )
    assert near_side(make_context(graph, "left", k_initial=100.0), SEAT, slot) is None
    square = _context([0.262, -0.2, 0.08], [0.2, -0.4, 0.09], [0.3, -0.4, 0.09])
    assert near_side(square, SEAT, slot) is None


@given(
    heading=st.floats(-math.pi, math.pi),
    bearing=st.floats(-math.pi, math.pi),
    fixed_first=st.booleans(),
)
def test_the_near_gripper_always_ends_nearer_the_fixed_point(
    heading: float, bearing: float, fixed_first: bool
) -> None:
    slot = np.array([math.cos(heading), math.sin(heading), 0.0])
    fixed = SEAT + 0.15 * np.array([math.cos(bearing), math.sin(bearing), 0.0])
    ctx = _context(list(fixed), [0.2, -0.5, 0.1], [0.3, -0.5, 0.1], fixed_first)
    sense = near_side(ctx, SEAT, slot)
    along = float((fixed - SEAT) @ slot) / 0.15
    if abs(along) < math.sin(math.radians(10.0)) - 1e-9:
        assert sense is None
        return
    if abs(along) <= math.sin(math.radians(10.0)) + 1e-9:
        return  # on the threshold: either answer
    assert sense is not None
    left_end, right_end = SEAT + 0.05 * sense * slot, SEAT - 0.05 * sense * slot
    near, far = (left_end, right_end) if fixed_first else (right_end, left_end)
    assert np.linalg.norm(near - fixed) < np.linalg.norm(far - fixed) - 1e-6
