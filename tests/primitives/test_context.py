"""The board design as primitives see it (primitives/context.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.primitives.context import ClipInfo


@settings(max_examples=100, deadline=None)
@given(
    yaw=st.floats(-math.pi, math.pi),
    towards=st.floats(-math.pi, math.pi),
    distance=st.floats(0.05, 0.5),
)
def test_a_clipped_cable_leaves_by_the_slot_s_end_towards_where_it_goes(
    yaw: float, towards: float, distance: float
) -> None:
    seat = np.array([0.3, -0.2, 0.08])
    clip = ClipInfo(seat, yaw, 2.0, 0.03)
    target = seat + distance * np.array([math.cos(towards), math.sin(towards), 0.0])
    end = clip.exit_towards(target)
    assert float(np.linalg.norm(end - seat)) == pytest.approx(0.015)
    assert end[2] == pytest.approx(seat[2])
    along = float((end - seat) @ clip.slot)
    # the end on the target's side of the clip, along its slot
    assert along * float((target - seat) @ clip.slot) >= 0.0
    assert abs(along) == pytest.approx(0.015)
