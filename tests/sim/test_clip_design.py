"""Snap-in clips: the jaw springs from the closed form, and a cable pushed in."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.robot import GripperCommand
from tautwire.sim import AnchorSpec, CableSpec, ClipSpec, GripperSpec, HoldSpec, SimWorld, WorldSpec
from tautwire.sim.clip_design import design_clip
from tautwire.sim.ground_truth import GroundTruth


@pytest.mark.parametrize("push", [0.5, 2.5, 8.0])
def test_peak_push_force_of_the_design_is_the_requested_one(push: float) -> None:
    design = design_clip(push, 0.0025, 0.2)
    xs = np.linspace(0.0, design.cable_radius + design.jaw_radius - design.jaw_offset, 401)
    peak = max(design.push_force_at(float(x)) for x in xs)
    assert peak == pytest.approx(push, rel=1e-3)
    # fully open jaws (contact at the jaws' equator) need only the friction 2 mu H
    x_open = design.cable_radius + design.jaw_radius - design.jaw_offset
    h_open = design.jaw_stiffness * (design.preload + x_open)
    assert design.push_force_at(x_open) == pytest.approx(2.0 * 0.2 * h_open)
    # the jaws overlap the cable when closed and clear it when open
    assert design.jaw_offset - design.jaw_radius < design.cable_radius
    assert design.jaw_offset + design.jaw_travel >= design.cable_radius + design.jaw_radius


def test_frictionless_push_is_two_spring_forces_times_tan_phi() -> None:
    d = design_clip(2.0, 0.003, 0.0)
    reach = d.cable_radius + d.jaw_radius
    x = 0.3 * (reach - d.jaw_offset)
    phi = np.arccos((d.jaw_offset + x) / reach)
    assert d.push_force_at(x) == pytest.approx(
        2.0 * d.jaw_stiffness * (d.preload + x) * np.tan(phi)
    )


def test_self_locking_design_is_refused() -> None:
    with pytest.raises(InvalidArgumentError, match="self-locks"):
        design_clip(2.0, 0.0025, 2.0, contact_angle=np.deg2rad(60.0))


def _push_cable_into_clip(push: float) -> tuple[float, float, float]:
    """Press a slack cable into a clip with the closed right gripper.

    Returns the peak upward force on the gripper, and the height of the cable
    above the seat after pushing and after lifting the gripper away.
    """
    h = 0.3
    seat = np.array([0.15, 0.0, h - 0.03])
    length = 0.33  # slack: sags onto the jaws, and pushing it in stretches nothing
    spec = WorldSpec(
        fixtures=(AnchorSpec("A", [0.0, 0.0, h]), ClipSpec("C", seat, 0.0, push)),
        cables=(CableSpec("W", length, 0.03, 100.0, 0.0025, "A", (), (HoldSpec("left", length),)),),
        left=GripperSpec([0.3, 0.0, h]),
        right=GripperSpec(seat + np.array([0.0, 0.0, 0.04])),
    )
    world = SimWorld(spec)
    truth = GroundTruth(world)

    def cable_height() -> float:
        p = truth.polyline("W")
        return float(p[np.argmin(np.linalg.norm(p - seat, axis=1)), 2] - seat[2])

    assert cable_height() > 0.005  # resting on the jaws
    world.set_gripper("right", GripperCommand("grip_force", 1.0))  # close the fingers
    twist = np.zeros(12)
    twist[8] = -0.01
    world.set_twist(twist)
    pad_half_height = 0.008
    bottom = seat[2] + 0.0025 + pad_half_height + 0.0005
    peak = 0.0
    while world.gripper_pose("right")[0][2] > bottom:
        world.step()
        peak = max(peak, float(world.wrench("right")[0][2]))
    pushed = cable_height()
    twist[8] = 0.01
    world.set_twist(twist)
    for _ in range(750):
        world.step()
    assert "C" in truth.in_contact()
    return peak, pushed, cable_height()


@pytest.mark.parametrize("push", [1.0, 5.0])
def test_a_clip_needs_about_its_push_force_and_keeps_the_cable(push: float) -> None:
    peak, pushed, after = _push_cable_into_clip(push)
    assert peak == pytest.approx(push, rel=0.30)
    assert abs(pushed) < 0.0015 and abs(after) < 0.0015  # seated, and stays seated
