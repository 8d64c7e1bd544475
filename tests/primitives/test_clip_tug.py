"""The tug: a pull turning about the clip is held, one turning about the far contact is not."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.primitives.clip_tug import (
    DISTINCT,
    MAX_TUG,
    MIN_TUG,
    ClipTug,
    elevation,
    lifted,
    tug_angle,
)


def _lifted(exit_point: np.ndarray, p0: np.ndarray, out: np.ndarray, angle: float) -> np.ndarray:
    """``p0`` turned up by ``angle`` [rad] about ``exit_point`` in the vertical plane of ``out``."""
    v = p0 - exit_point
    ahead, up = float(v @ out), float(v[2])
    c, s = math.cos(angle), math.sin(angle)
    return exit_point + (c * ahead - s * up) * out + np.array([0.0, 0.0, s * ahead + c * up])


def _read(pivot_after: np.ndarray, pivot_before: np.ndarray, offset: np.ndarray, **geo: float):  # type: ignore[no-untyped-def]
    """Tug a synthetic cable: the pull points from where it leaves the fingers to a pivot."""
    yaw, r, far, lift = geo["yaw"], geo["r"], geo["far"], geo["lift"]
    out = np.array([math.cos(yaw), math.sin(yaw), 0.0])
    exit_point = np.array([0.3, 0.1, 0.088])
    contact = exit_point - far * out + np.array([0.0, 0.0, 0.01])
    p0 = exit_point + r * out + np.array([0.0, 0.0, -0.004])
    p1 = _lifted(exit_point, p0, out, lift)
    tug = ClipTug(out)
    pivots = {"clip": exit_point, "far": contact}
    for t in np.arange(0.0, 1.0, 0.004):
        tug.update(float(t), pivots[pivot_before] - (p0 + offset))
    tug.mark_rest(p0)
    for t in np.arange(1.0, 2.0, 0.004):
        tug.update(float(t), pivots[pivot_after] - (p1 + offset))
    return tug.reading(p1, exit_point, contact)


geometry = {
    "yaw": st.floats(-math.pi, math.pi),
    "r": st.floats(0.04, 0.3),
    "far": st.floats(0.1, 0.5),
    "lift": st.floats(MIN_TUG, MAX_TUG),
    "offset": st.tuples(*[st.floats(-0.01, 0.01)] * 3),
}


@settings(max_examples=400, deadline=None)
@given(held=st.booleans(), **geometry)
def test_the_tug_tells_a_held_cable_from_a_loose_one_whatever_its_offset_in_the_fingers(
    held: bool, yaw: float, r: float, far: float, lift: float, offset: tuple[float, float, float]
) -> None:
    pivot = "clip" if held else "far"
    reading = _read(pivot, pivot, np.array(offset), yaw=yaw, r=r, far=far, lift=lift)
    assert reading.holds == held, reading.describe()
    if not held:
        assert reading.loose == pytest.approx(lift * r / (r + far), rel=0.1)
        return
    if lift * far / (r + far) > 1.5 * DISTINCT:  # else F keeps the line's verdict
        assert reading.distinct
    # about the point the cable leaves the fingers: up to 17 mm nearer or farther than r
    assert lift * r / (r + 0.018) <= reading.turned <= lift * r / (r - 0.018)


def test_the_reading_needs_a_rest_pose() -> None:
    tug = ClipTug(np.array([1.0, 0.0, 0.0]))
    tug.update(0.0, np.array([-1.0, 0.0, 0.0]))
    with pytest.raises(RuntimeError, match="rest"):
        tug.reading(np.zeros(3), np.zeros(3), np.ones(3))


def test_a_non_finite_or_zero_force_is_skipped() -> None:
    tug = ClipTug(np.array([1.0, 0.0, 0.0]))
    tug.update(0.0, np.array([-1.0, 0.0, 0.0]))
    tug.update(0.004, np.array([np.nan, 0.0, 0.0]))
    tug.update(0.008, np.zeros(3))
    tug.mark_rest(np.zeros(3))
    assert tug.reading(np.zeros(3), np.array([-0.1, 0, 0]), np.array([-0.3, 0, 0])).turned == 0.0


def test_the_tug_pulls_up_on_the_clip_with_at_most_its_share_of_the_push_force() -> None:
    assert 3.0 * math.sin(tug_angle(1.8, 3.0)) == pytest.approx(0.1 * 1.8)
    assert tug_angle(4.0, 1.0) == MAX_TUG  # a weak pull would lift too little to read
    assert tug_angle(0.5, 12.0) == MIN_TUG


def test_elevation_is_measured_towards_the_clip() -> None:
    out = np.array([0.0, 1.0, 0.0])
    assert elevation(np.array([0.0, -1.0, -1.0]), out) == pytest.approx(-math.pi / 4)
    assert elevation(np.array([0.0, -1.0, 0.0]), out) == pytest.approx(0.0)


@settings(max_examples=200, deadline=None)
@given(
    yaw=st.floats(-math.pi, math.pi),
    ahead=st.floats(0.02, 0.4),
    up=st.floats(-0.05, 0.05),
    side=st.floats(-0.02, 0.02),
    angle=st.floats(-0.2, 0.2),
)
def test_lifting_turns_about_the_horizontal_axis_normal_to_out(
    yaw: float, ahead: float, up: float, side: float, angle: float
) -> None:
    out = np.array([math.cos(yaw), math.sin(yaw), 0.0])
    normal = np.array([-out[1], out[0], 0.0])
    pivot = np.array([0.3, -0.1, 0.09])
    in_plane = pivot + ahead * out + np.array([0.0, 0.0, up])
    p = lifted(in_plane + side * normal, pivot, out, angle)
    # the side offset stays; in the plane it is the rotation about the axis
    assert float((p - pivot) @ normal) == pytest.approx(side, abs=1e-12)
    assert np.allclose(p - side * normal, _lifted(pivot, in_plane, out, angle), atol=1e-12)
    assert np.linalg.norm(p - pivot) == pytest.approx(
        np.linalg.norm(in_plane + side * normal - pivot)
    )
    assert elevation(pivot - in_plane, out) - elevation(pivot - (p - side * normal), out) == (
        pytest.approx(angle, abs=1e-9)
    )


@settings(max_examples=100, deadline=None)
@given(yaw=st.floats(-math.pi, math.pi), ahead=st.floats(0.02, 0.4), angle=st.floats(-0.2, 0.2))
def test_a_swing_aside_turns_about_the_vertical_through_the_pivot(
    yaw: float, ahead: float, angle: float
) -> None:
    out = np.array([math.cos(yaw), math.sin(yaw), 0.0])
    aside = np.array([-out[1], out[0], 0.0])
    pivot = np.array([0.3, -0.1, 0.09])
    p = pivot + ahead * out + np.array([0.0, 0.0, 0.012])
    q = lifted(p, pivot, out, angle, aside)
    assert q[2] == pytest.approx(p[2])  # the height stays
    assert np.linalg.norm((q - pivot)[:2]) == pytest.approx(ahead)
    turned = math.atan2(float((q - pivot) @ aside), float((q - pivot) @ out))
    assert turned == pytest.approx(angle, abs=1e-9)
    # the tug reads the swing in its plane: a pull towards the pivot turned by it
    assert elevation(pivot - p, out, aside) - elevation(pivot - q, out, aside) == pytest.approx(
        angle, abs=1e-9
    )
