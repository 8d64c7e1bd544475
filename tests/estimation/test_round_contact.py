import math

import numpy as np
import pytest

from tautwire.estimation.round_contact import line_meets_peg, shift_onto_axis, side_towards_axis

Z = np.array([0.0, 0.0, 1.0])
AXIS_POINT = np.array([0.15, 0.0, 0.08])
R = 0.0105


def tangent_line(angle: float, sense: float, radius: float = R, distance: float = 0.3):
    """Gripper and force of a cable leaving the peg tangentially towards ``angle``.

    The gripper circles the peg in ``sense`` about z; the cable touches the
    peg at the tangent point on the side the rotation gives.
    """
    out = np.array([math.cos(angle), math.sin(angle), 0.0])  # from the peg to the gripper
    normal = sense * np.cross(Z, out)  # the tangent point lies behind, against the rotation
    tangent_point = AXIS_POINT - radius * normal
    p = tangent_point + distance * out
    return p, -out * 2.0  # the cable pulls the gripper back towards the peg


@pytest.mark.parametrize("sense", [1.0, -1.0])
@pytest.mark.parametrize("angle", [0.0, 1.0, 2.5, -2.0])
def test_the_shifted_line_passes_the_axis(angle: float, sense: float) -> None:
    p, f = tangent_line(angle, sense)
    q = shift_onto_axis(p, f, Z, sense, R)
    u = f / np.linalg.norm(f)
    d = AXIS_POINT - q
    miss = d - u * float(u @ d)
    assert np.linalg.norm(miss[:2]) == pytest.approx(0.0, abs=1e-12)
    side = side_towards_axis(f, Z, sense)
    assert side is not None and np.linalg.norm(side) == pytest.approx(1.0)


def test_a_vertical_force_has_no_side() -> None:
    assert side_towards_axis(np.array([0.0, 0.0, 3.0]), Z, 1.0) is None
    p = np.array([0.1, 0.2, 0.3])
    assert shift_onto_axis(p, np.array([0.0, 0.0, 3.0]), Z, 1.0, R) is p


def test_a_tangent_line_meets_the_peg_between_gripper_and_contact() -> None:
    p, f = tangent_line(0.3, 1.0)
    far_contact = AXIS_POINT + 0.2 * (f / np.linalg.norm(f))
    meet = line_meets_peg(p, f, Z, 1.0, AXIS_POINT, R, far_contact)
    assert meet is not None
    assert np.allclose(meet[:2], AXIS_POINT[:2]) and meet[2] == pytest.approx(p[2])


def test_lines_that_do_not_rest_on_the_peg() -> None:
    p, f = tangent_line(0.3, 1.0)
    far_contact = AXIS_POINT + 0.2 * (f / np.linalg.norm(f))
    # the other side of the peg: the shift goes the wrong way, 2 R off
    assert line_meets_peg(p, f, Z, -1.0, AXIS_POINT, R, far_contact) is None
    # passing 5 mm wide of the tangent, with a 2 mm tolerance
    assert line_meets_peg(p, f, Z, 1.0, AXIS_POINT, R + 0.005, far_contact, 0.002) is None
    # the old contact lies between the gripper and the peg
    near_contact = p + 0.1 * (f / np.linalg.norm(f))
    assert line_meets_peg(p, f, Z, 1.0, AXIS_POINT, R, near_contact) is None


@pytest.mark.parametrize("sense", [1.0, -1.0])
@pytest.mark.parametrize("slope", [-0.6, -0.2, 0.3, 0.8])
def test_a_sloped_tangent_line_meets_the_peg_at_its_height(slope: float, sense: float) -> None:
    # a gripper above or below the peg: the line is tangent in the top view,
    # and meets the axis where it passes it (the miss measured normal to the
    # axis, not along the sloped line: 6 mm off at a 0.2 rad slope over 0.15 m)
    p, f = tangent_line(0.7, sense, distance=0.15)
    rise = slope * 0.15
    p = p + np.array([0.0, 0.0, rise])
    f = f - np.array([0.0, 0.0, rise]) * np.linalg.norm(f) / 0.15
    far_contact = AXIS_POINT + 0.2 * (f / np.linalg.norm(f))
    meet = line_meets_peg(p, f, Z, sense, AXIS_POINT, R, far_contact, 1e-6)
    assert meet is not None
    assert np.allclose(meet[:2], AXIS_POINT[:2]) and meet[2] == pytest.approx(AXIS_POINT[2])
