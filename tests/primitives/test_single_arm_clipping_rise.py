"""F moves a peg's leave point up or down onto the measured pull (the cable slides along a peg).

Random board 1627120487's F7 from peg F6: the model held the cable 95.6 mm
high on the peg, it had slid down to 75 mm, and the cable aimed 15 mm over
the seat met the clip's side. The pull's slope tells the height; these
tests check the geometry, the peg's span and the gate on a line that bears
on the clip.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.primitives.clip_sensing import JAW_TOP, ClipHeight
from tautwire.primitives.low_pass import LowPass
from tautwire.primitives.single_arm_clipping import (
    EXIT_TIME,
    MAX_LINE_RISE,
    SingleArmClipping,
)

SEAT = np.array([0.42, -0.155, 0.08])
SLOT = np.array([math.cos(-0.49), math.sin(-0.49), 0.0])


def _f(contact: np.ndarray, span: tuple[float, float] = (0.05, 0.11)) -> SingleArmClipping:
    f = SingleArmClipping("right", "F7")
    f._contact = contact.copy()
    f._line_shift = np.zeros(3)
    f._line_rise = 0.0
    f._line_rise_filter = LowPass(EXIT_TIME)
    f._span = span
    f.sensing = ClipHeight(SEAT, SLOT, 0.015)
    return f


def _pull(gripper: np.ndarray, at: np.ndarray) -> np.ndarray:
    d = at - gripper
    out: np.ndarray = d / np.linalg.norm(d)
    return out


@settings(max_examples=50, deadline=None)
@given(
    truth_z=st.floats(0.055, 0.105),
    model_z=st.floats(0.066, 0.094),
    grip_z=st.floats(0.07, 0.14),
)
def test_the_leave_point_goes_onto_the_pulls_line(
    truth_z: float, model_z: float, grip_z: float
) -> None:
    leave = np.array([0.3077, -0.0945, model_z])
    gripper = np.array([0.5099, -0.1966, grip_z])
    f = _f(leave)
    truth = np.array([leave[0], leave[1], truth_z])
    rise = f._line_rise = f._measured_rise(1.0, gripper, _pull(gripper, truth))
    assert rise == pytest.approx(truth_z - model_z, abs=1e-9)
    assert f._far()[2] == pytest.approx(truth_z, abs=1e-9)


def test_board_1627120487_f7_the_slid_cable_lowers_the_aim() -> None:
    f = _f(np.array([0.3077, -0.0945, 0.0956]))
    gripper = np.array([0.5099, -0.1966, 0.0918])
    for k in range(40):  # 0.16 s of the measured pull, low-passed
        slid = _pull(gripper, np.array([0.3077, -0.0945, 0.075]))
        f._line_rise = f._measured_rise(0.004 * k, gripper, slid)
    assert f._line_rise == pytest.approx(-0.0206, abs=1e-3)


def test_the_leave_point_stays_on_the_peg_and_within_the_largest_move() -> None:
    gripper = np.array([0.5099, -0.1966, 0.0918])
    below = np.array([0.3077, -0.0945, 0.02])  # a line that passes under the peg's foot
    f = _f(np.array([0.3077, -0.0945, 0.08]))
    assert f._measured_rise(1.0, gripper, _pull(gripper, below)) == pytest.approx(-0.03)
    f = _f(np.array([0.3077, -0.0945, 0.08]), span=(-1.0, 1.0))
    assert f._measured_rise(1.0, gripper, _pull(gripper, below)) == -MAX_LINE_RISE


def test_a_pull_that_runs_vertically_or_away_changes_nothing() -> None:
    f = _f(np.array([0.3077, -0.0945, 0.08]))
    gripper = np.array([0.5099, -0.1966, 0.0918])
    assert f._measured_rise(1.0, gripper, np.array([0.1, 0.0, -0.995])) == 0.0
    assert f._measured_rise(1.0, gripper, np.array([0.9, 0.4, 0.0])) == 0.0  # away from it


def test_a_line_low_over_the_slot_bears_on_the_clip_and_says_nothing_of_the_peg() -> None:
    f = _f(np.array([0.3077, -0.0945, 0.08]))
    gripper = SEAT + 0.1 * SLOT + np.array([0.0, 0.0, 0.03])
    exit_point = SEAT + 0.015 * SLOT
    # the cable bent over the jaws: the line passes the exit at the jaws' top
    f.sensing.update(0.0, gripper, _pull(gripper, exit_point + np.array([0.0, 0.0, JAW_TOP])), True)
    assert f._bears()
    # 15 mm over the seat: free of the clip
    f = _f(np.array([0.3077, -0.0945, 0.08]))
    f.sensing.update(0.0, gripper, _pull(gripper, exit_point + np.array([0.0, 0.0, 0.015])), True)
    assert not f._bears()
    # low, but 8 mm beside the slot: beside the clip, not on it
    beside = exit_point + 0.008 * np.array([-SLOT[1], SLOT[0], 0.0]) + np.array([0.0, 0.0, 0.005])
    f = _f(np.array([0.3077, -0.0945, 0.08]))
    f.sensing.update(0.0, gripper, _pull(gripper, beside), True)
    assert not f._bears()
