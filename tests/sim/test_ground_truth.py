"""GroundTruth: polyline, tensions, stiffness, fixture contacts."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.sim import ClipSpec, SimWorld
from tautwire.sim.ground_truth import GRIP_ZONE, GroundTruth, TautSpan
from tests.sim.scenes import anchor_and_gripper, peg_scene, rest


def test_polyline_tension_and_stiffness_of_a_taut_cable() -> None:
    k = 200.0
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.3, 0.0, 0.3], 0.29, k)
    rest(world, 0.5)
    truth = GroundTruth(world)
    p = truth.polyline("W")
    assert p.shape == (len(truth.arc_lengths("W")), 3)
    assert np.allclose(p[0], [0.0, 0.0, 0.3]) and np.allclose(p[-1], [0.3, 0.0, 0.3], atol=1e-4)
    tension = truth.tensions("W")
    assert tension.shape == (len(p) - 1,)
    # tension along a light taut cable is nearly uniform and equals k * stretch
    assert tension.mean() == pytest.approx(k * (truth.length("W") - 0.29), rel=0.01)
    assert np.ptp(tension) < 0.02 * tension.mean()
    assert truth.stiffness("W") == k
    assert truth.rest_lengths("W").sum() == pytest.approx(0.29)
    with pytest.raises(InvalidArgumentError, match="cables"):
        truth.polyline("nope")


def test_peg_contact_lies_on_the_axis_at_the_cable_height() -> None:
    world = peg_scene()
    twist = np.zeros(12)
    twist[0:3] = [0.02, 0.01, 0.0]  # take up the slack: the cable wraps the peg
    world.set_twist(twist)
    for _ in range(500):
        world.step()
    truth = GroundTruth(world)
    assert set(truth.in_contact()) == {"A", "P"}
    peg = truth.contact("P")
    assert peg is not None and peg.force > 0.1
    assert np.allclose(peg.point[:2], [0.15, 0.05])
    p = truth.polyline("W")
    near = p[np.argmin(np.linalg.norm(p[:, :2] - [0.15, 0.05], axis=1))]
    assert peg.point[2] == pytest.approx(near[2], abs=2e-3)
    anchor = truth.contact("A")
    assert anchor is not None and np.allclose(anchor.point, [0.0, 0.0, 0.12])
    assert truth.contact("nothing") is None


@pytest.mark.parametrize(
    ("gap", "height", "lies"),
    [(0.0005, 0.12, True), (0.002, 0.12, False), (0.0005, 0.16, False)],
)
def test_a_cable_lying_against_a_peg_touches_it_without_a_contact(
    monkeypatch: pytest.MonkeyPatch, gap: float, height: float, lies: bool
) -> None:
    """Random board 1808415002: a released cable fell down its pegs, 0.2 mm off one."""
    from tautwire.experiments.truth import true_contacts

    truth = GroundTruth(peg_scene())  # P: axis (0.15, 0.05), radius 6 mm, top 0.15 m
    off = 0.006 + truth.cable_radius("W") + gap
    line = np.array([[0.0, 0.05 + off, height], [0.3, 0.05 + off, height]])
    monkeypatch.setattr(truth, "polyline", lambda cable: line)
    monkeypatch.setattr(truth, "contacts", lambda: ())  # no contact acts at this instant
    point = truth.against_peg("P", "W")
    if lies:
        assert point is not None and np.allclose(point, [0.15, 0.05, height])
        assert np.allclose(true_contacts(truth, "W")["P"], point)
    else:
        assert point is None and "P" not in true_contacts(truth, "W")
    with pytest.raises(InvalidArgumentError, match="not a peg"):
        truth.against_peg("A", "W")


def _through_the_fingers_left_out(truth: GroundTruth, span: TautSpan) -> bool:
    """Whether the span's segments are exactly those with no vertex within GRIP_ZONE of the hold."""
    arc = truth.arc_lengths(span.cable)
    near = np.abs(arc - arc[span.held_vertex]) < GRIP_ZONE
    lo, hi = span.segments
    kept = all(not (near[j] or near[j + 1]) for j in range(lo, hi))
    return kept and bool(near[hi] or near[hi + 1]) and hi < span.held_vertex


def test_span_of_a_taut_cable_from_its_anchor() -> None:
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.3, 0.0, 0.3], 0.29, 200.0)
    rest(world, 0.5)
    truth = GroundTruth(world)
    span = truth.span("W", "left")
    assert span is not None and span.fixture == "A"
    assert span.contact is not None and np.allclose(span.contact, [0.0, 0.0, 0.3])
    assert span.leave_vertex == 0 and span.held_vertex == len(truth.polyline("W")) - 1
    assert span.rest_length == pytest.approx(0.29)
    # the mean elastic tension outside the fingers, and the noise-free force the gripper feels
    lo, hi = span.segments
    assert lo == 0 and _through_the_fingers_left_out(truth, span)
    assert span.taut and span.tension == pytest.approx(truth.tensions("W")[lo:hi].mean())
    assert span.tension == pytest.approx(float(np.linalg.norm(world.wrench("left")[0])), rel=0.02)
    assert truth.span_tension(span) == pytest.approx((span.tension, True))
    assert truth.max_force >= 0.98 * span.tension
    assert truth.span("W", "right") is None  # the right gripper holds nothing
    assert truth.starts_anchored("W") and truth.fixture_type("A") == "anchor"


def test_span_leaves_from_the_peg_the_cable_bears_on() -> None:
    world = peg_scene()
    twist = np.zeros(12)
    twist[0:3] = [0.02, 0.01, 0.0]
    world.set_twist(twist)
    for _ in range(500):
        world.step()
    truth = GroundTruth(world)
    span = truth.span("W", "left")
    assert span is not None and span.fixture == "P"
    assert truth.fixture_type("P") == "peg" and truth.peg_radius("P") == 0.006
    peg = truth.contact("P")
    assert peg is not None and span.contact is not None and np.allclose(span.contact, peg.point)
    # the cable leaves the peg at its radius plus the cable's (and MuJoCo's margin)
    off_axis = float(np.hypot(*(span.leave[:2] - [0.15, 0.05])))
    assert 0.006 + 0.0025 - 1e-3 <= off_axis <= 0.006 + 0.0025 + 0.005
    assert 0 < span.leave_vertex < span.held_vertex
    # the free span starts past the segment that touches the peg (it may be partly wrapped)
    assert span.segments[0] == span.leave_vertex + 1
    assert _through_the_fingers_left_out(truth, span)
    arc = truth.arc_lengths("W")
    assert arc[span.leave_vertex] <= span.leave_arc <= arc[span.leave_vertex + 1]
    assert span.rest_length == pytest.approx(arc[span.held_vertex] - span.leave_arc)
    tensions = truth.tensions("W")[slice(*span.segments)]
    assert span.tension == pytest.approx(tensions.mean()) and span.taut
    with pytest.raises(InvalidArgumentError, match="not a peg"):
        truth.peg_radius("A")
    with pytest.raises(InvalidArgumentError, match="fixtures"):
        truth.fixture_type("nope")


def _clip_world(via: bool) -> SimWorld:
    """An anchor and a clip on the line to the gripper, the cable routed through it or not."""
    seat = [0.15, 0.0, 0.3] if via else [0.15, 0.0, 0.25]
    return anchor_and_gripper(
        [0.0, 0.0, 0.3],
        [0.3, 0.0, 0.3],
        0.31,
        fixtures=(ClipSpec("C", seat, 0.0, 2.0),),
        via=("C",) if via else (),
    )


@pytest.mark.parametrize("via", [True, False])
def test_a_cable_is_clipped_only_when_it_sits_in_the_jaws(via: bool) -> None:
    world = _clip_world(via)
    rest(world, 0.3)
    truth = GroundTruth(world)
    assert truth.clipped("C", "W") is via
    assert truth.fixture_type("C") == "clip"
    with pytest.raises(InvalidArgumentError, match="not a clip"):
        truth.clipped("A", "W")


@pytest.mark.parametrize(("height", "touches"), [(0.0, True), (0.008, True), (0.025, False)])
def test_a_span_bears_on_a_clip_only_down_at_its_jaws(height: float, touches: bool) -> None:
    """A cable held 25 mm over a clip (its tail draped into the jaws) does not bear on it.

    Random board 1695658280: the slide ended with the gripper above F8, the
    tail beyond the fingers hung into F8's jaws, and the span from the
    gripper back to F6 counted as leaving F8, slack: a false success of D.
    """
    world = _clip_world(True)
    truth = GroundTruth(world)
    clip = world.spec.fixture("C")
    seat = np.asarray(clip.position)
    # a straight cable over the clip along its slot, held at its last vertex
    xs = np.linspace(0.3, 0.0, 16)
    pts = np.stack([xs, np.zeros_like(xs), np.full_like(xs, seat[2] + height)], axis=1)
    hit = truth._first_touching(pts, 0, 1, 0.0025, [clip])
    assert (hit is not None and hit[0] == "C") is touches


def test_a_short_span_past_a_clip_keeps_a_segment_to_read_its_tension() -> None:
    """A gripper 45 mm past a clip's exit (as after C): the span is two segments.

    One runs through the fingers, the other leaves the clip; dropping that
    one as partly wrapped too left none, and the taut span read 0 N, slack.
    """
    world = anchor_and_gripper(
        [0.0, 0.0, 0.3],
        [0.3, 0.0, 0.3],
        0.29,
        200.0,
        fixtures=(ClipSpec("C", [0.24, 0.0, 0.3], 0.0, 2.0),),
        via=("C",),
    )
    rest(world, 0.5)
    truth = GroundTruth(world)
    span = truth.span("W", "left")
    assert span is not None and span.fixture == "C"
    lo, hi = span.segments
    assert hi > lo
    assert span.taut and span.tension > 0.5
    assert span.tension == pytest.approx(float(np.linalg.norm(world.wrench("left")[0])), rel=0.1)
