"""F's alignment: the cable's exit from the fingers goes onto the line over the seat."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.primitives.context import ClipInfo
from tautwire.primitives.single_arm_clipping import ABOVE, ALIGN_MISS, SingleArmClipping
from tautwire.robot import GripperState, Observation, Wrench

SEAT = np.array([0.30, 0.0, 0.08])
CONTACT = np.array([0.10, 0.0, 0.08])


def _aligning(offset: np.ndarray) -> SingleArmClipping:
    f = SingleArmClipping("left", "C1")
    f.info = ClipInfo(SEAT, 0.0, 2.5, 0.03)
    f._contact = CONTACT.copy()
    f._offset = offset
    return f


def _obs(p: np.ndarray) -> Observation:
    q = np.array([1.0, 0.0, 0.0, 0.0])
    grip = GripperState(p, q)
    zero = Wrench("left", np.zeros(3), np.zeros(3))
    return Observation(0.0, grip, grip, (zero,))


@pytest.mark.parametrize("offset", [np.zeros(3), np.array([-0.009, 0.003, -0.004])])
def test_the_exit_not_the_tool_centre_point_goes_onto_the_line(offset: np.ndarray) -> None:
    f = _aligning(offset)
    p = np.array([0.45, 0.02, 0.12])
    target = f._target(_obs(p), None)  # type: ignore[arg-type]
    through = SEAT + np.array([0.0, 0.0, ABOVE])
    w = (through - CONTACT) / np.linalg.norm(through - CONTACT)
    exit_point = target + offset
    # on the line from the contact over the seat, as far out as the exit is now
    assert np.linalg.norm(np.cross(exit_point - CONTACT, w)) < 1e-12
    assert np.linalg.norm(exit_point - CONTACT) == pytest.approx(
        np.linalg.norm(p + offset - CONTACT)
    )


def test_the_push_waits_for_the_line_to_pass_over_the_seat() -> None:
    f = _aligning(np.zeros(3))
    target = f._target(_obs(np.array([0.45, 0.0, 0.12])), None)  # type: ignore[arg-type]
    assert f._aligned(target, target)
    # 2 mm across at the gripper, 0.35 m out: 1.1 mm beside the seat, 0.2 m in
    beside = target + np.array([0.0, 0.002, 0.0])
    assert ALIGN_MISS < 0.002 * 0.2 / 0.35 and not f._aligned(beside, target)
    # 2 mm along the line: the cable still passes over the seat
    along = target + 0.002 * (target - CONTACT) / np.linalg.norm(target - CONTACT)
    assert f._aligned(along, target)
    # but never farther than the tolerance from the set point
    assert not f._aligned(target + np.array([0.004, 0.0, 0.0]), target)


def test_the_far_contact_moves_onto_the_measured_line() -> None:
    # random board 360400295's F5: the stiff cable leaves F4 bent by 50 deg,
    # and its straight span runs 4 mm beside F4's exit, the model's contact;
    # aligned on the model's line, F pushed the cable 4 mm beside the seat
    f = _aligning(np.zeros(3))
    pivot = CONTACT + np.array([0.0, 0.004, 0.0])  # where the real span's line comes from
    leaves = np.array([0.45, 0.02, 0.12])
    pull = (pivot - leaves) / np.linalg.norm(pivot - leaves)
    for k in range(100):
        f._line_shift = f._measured_shift(0.004 * k, leaves, pull)
    assert np.linalg.norm(f._line_shift - np.array([0.0, 0.004, 0.0])) < 2e-4
    target = f._target(_obs(leaves), None)  # type: ignore[arg-type]
    through = SEAT + np.array([0.0, 0.0, ABOVE])
    flat = np.array([1.0, 1.0, 0.0])
    w = (through - pivot) * flat
    # the real span's line from where the cable leaves the fingers passes over the seat
    assert np.linalg.norm(np.cross((target - pivot) * flat, w)) / np.linalg.norm(w) < 5e-4
    # a line 2 cm beside is not this span (it bears on something else): no shift
    g = _aligning(np.zeros(3))
    far = CONTACT + np.array([0.0, 0.02, 0.0])
    shift = g._measured_shift(0.0, leaves, (far - leaves) / np.linalg.norm(far - leaves))
    assert np.allclose(shift, 0.0)


@pytest.mark.parametrize("slot_side", [1.0, -1.0])
def test_a_line_bent_out_of_a_clip_passes_its_exit_on_the_slot_s_side_only(
    slot_side: float,
) -> None:
    # a stiff cable bent out of the clip before runs straight on from a
    # virtual corner ahead of the exit, along that clip's slot: its line
    # passes the exit on the slot's side. Random board 1986348794's F5, 24
    # deg on from F4: the measured line read 4.2 mm beside the exit on the
    # other side, F aimed from there and the cable went down beside the clip
    f = _aligning(np.zeros(3))
    f._bent_exit = True
    f._exit_way = np.array([np.cos(0.42), slot_side * np.sin(0.42), 0.0])  # out of F4's slot
    pivot = CONTACT + np.array([0.0, 0.004, 0.0])  # the measured line passes 4 mm to +y
    leaves = np.array([0.45, 0.02, 0.12])
    pull = (pivot - leaves) / np.linalg.norm(pivot - leaves)
    for k in range(100):
        f._line_shift = f._measured_shift(0.004 * k, leaves, pull)
    if slot_side > 0:  # the slot turns to +y: the reading is on its side, taken
        assert np.linalg.norm(f._line_shift - np.array([0.0, 0.004, 0.0])) < 2e-4
    else:  # the other side: the line's own error, no shift
        assert np.allclose(f._line_shift, 0.0)
