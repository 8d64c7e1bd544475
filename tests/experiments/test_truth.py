"""Truth checks on crafted cases: a wrong or made-up model reads as disagreeing."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.experiments.truth import (
    ANGLE_TOLERANCE,
    CONTACT_TOLERANCE,
    FilterSample,
    StepWatch,
    _direction,
    check_contacts,
    check_step,
    coverage,
    judge_model,
    point_deviations,
)
from tautwire.model import PathGraph
from tautwire.primitives import PrimitiveContext, make_context
from tautwire.sim import ClipSpec, PegSpec, SimWorld
from tautwire.sim.ground_truth import GroundTruth, TautSpan
from tests.sim.scenes import anchor_and_gripper, rest

ANCHOR = np.array([0.0, 0.0, 0.12])
PEG_AXIS = np.array([0.15, 0.05])
PEG_RADIUS = 0.006


@pytest.fixture(scope="module")
def peg_world() -> tuple[SimWorld, GroundTruth]:
    """A taut cable from an anchor round a peg to the left gripper; a second peg far away."""
    world = anchor_and_gripper(
        list(ANCHOR),
        [0.35, 0.15, 0.12],
        0.42,
        stiffness=200.0,
        fixtures=(
            PegSpec("P", [0.15, 0.05, 0.10], PEG_RADIUS, 0.05),
            PegSpec("Q", [0.6, -0.4, 0.0], 0.005, 0.05),
        ),
        via=("P",),
    )
    twist = np.zeros(12)
    twist[0:3] = [0.02, 0.01, 0.0]  # take up the slack
    world.set_twist(twist)
    for _ in range(500):
        world.step()
    rest(world, 0.3)
    return world, GroundTruth(world)


def _graph(
    points: list[tuple[str, str, np.ndarray, float | None]], gripper: np.ndarray
) -> PathGraph:
    """A model: (kind, label, position, std or None) per point, then the left gripper."""
    positions = [p for _, _, p, _ in points] + [gripper]
    graph = PathGraph.from_positions(
        np.array(positions),
        0.03,
        kinds=[k for k, _, _, _ in points] + ["gripper"],  # type: ignore[list-item]
        labels=[lab for _, lab, _, _ in points] + ["left"],
    )
    for pt, (_, _, _, std) in zip(graph.points, points, strict=False):
        pt.covariance = None if std is None else std**2 * np.eye(3)
    return graph


def _peg_truth(truth: GroundTruth) -> np.ndarray:
    contact = truth.contact("P")
    assert contact is not None
    return contact.point


def test_a_right_model_agrees(peg_world: tuple[SimWorld, GroundTruth]) -> None:
    world, truth = peg_world
    graph = _graph(
        [("fixed", "A", ANCHOR, 5e-4), ("contact", "P", _peg_truth(truth) + 0.002, 1e-3)],
        world.gripper_pose("left")[0],
    )
    checks = check_contacts(graph, truth, "W", trusted_std=0.01)
    assert [(c.fixture, c.fixture_type, c.made_up, c.within) for c in checks] == [
        ("A", "anchor", False, True),
        ("P", "peg", False, True),
    ]
    assert checks[1].tolerance == pytest.approx(CONTACT_TOLERANCE + PEG_RADIUS)
    verdict = judge_model(checks)
    assert verdict.agrees and "P" in verdict.detail


def test_a_wrong_trusted_estimate_disagrees(peg_world: tuple[SimWorld, GroundTruth]) -> None:
    world, truth = peg_world
    off = _peg_truth(truth) + np.array([PEG_RADIUS + 0.005, 0.0, 0.0])  # beyond radius + 3 mm
    graph = _graph(
        [("fixed", "A", ANCHOR, None), ("contact", "P", off, 1e-3)], world.gripper_pose("left")[0]
    )
    verdict = judge_model(check_contacts(graph, truth, "W", trusted_std=0.01))
    assert not verdict.agrees and "P: 11.0 mm" in verdict.detail
    # the same error with an honest, large std is not a claim the robot acts on
    graph.points[1].covariance = 0.02**2 * np.eye(3)
    assert judge_model(check_contacts(graph, truth, "W", trusted_std=0.01)).agrees


def test_an_anchor_estimate_4_mm_off_disagrees(peg_world: tuple[SimWorld, GroundTruth]) -> None:
    world, truth = peg_world
    graph = _graph(
        [("fixed", "A", ANCHOR + np.array([0.0, 0.004, 0.0]), 5e-4)], world.gripper_pose("left")[0]
    )
    (check,) = check_contacts(graph, truth, "W", trusted_std=0.01)
    assert check.error == pytest.approx(0.004) and not check.within
    assert not judge_model([check]).agrees


def test_made_up_points_disagree(peg_world: tuple[SimWorld, GroundTruth]) -> None:
    world, truth = peg_world
    gripper = world.gripper_pose("left")[0]
    far = np.array([0.25, 0.1, 0.12])  # on no fixture
    graph = _graph([("fixed", "A", ANCHOR, None), ("contact", "estimated", far, None)], gripper)
    checks = check_contacts(graph, truth, "W", trusted_std=0.01)
    assert [c.made_up for c in checks] == [False, True]
    verdict = judge_model(checks)
    assert not verdict.agrees and "made up" in verdict.detail
    # a point named after a fixture the cable does not touch stands for nothing
    graph = _graph([("fixed", "A", ANCHOR, None), ("contact", "Q", far, None)], gripper)
    checks = check_contacts(graph, truth, "W", trusted_std=0.01)
    assert checks[1].made_up and "does not touch Q" in checks[1].reason


def test_an_estimated_point_stands_for_the_contact_it_is_near(
    peg_world: tuple[SimWorld, GroundTruth],
) -> None:
    world, truth = peg_world
    gripper = world.gripper_pose("left")[0]
    near = _peg_truth(truth) + np.array([0.0, 0.004, 0.0])
    graph = _graph([("fixed", "A", ANCHOR, None), ("contact", "estimated", near, 1e-3)], gripper)
    checks = check_contacts(graph, truth, "W", trusted_std=0.01)
    assert checks[1].fixture == "P" and checks[1].within
    assert judge_model(checks).agrees
    # a second point for the same peg is made up
    graph = _graph(
        [
            ("fixed", "A", ANCHOR, None),
            ("contact", "P", _peg_truth(truth), 1e-3),
            ("contact", "estimated", near, 1e-3),
        ],
        gripper,
    )
    checks = check_contacts(graph, truth, "W", trusted_std=0.01)
    assert [c.made_up for c in checks] == [False, False, True]


def _context(world: SimWorld, truth: GroundTruth) -> PrimitiveContext:
    graph = _graph(
        [("fixed", "A", ANCHOR, None), ("contact", "P", _peg_truth(truth), None)],
        world.gripper_pose("left")[0],
    )
    return make_context(graph, "left")


def test_a_tension_claim_is_checked_against_the_true_tension(
    peg_world: tuple[SimWorld, GroundTruth],
) -> None:
    world, truth = peg_world
    watch = StepWatch(truth, "W", "left")
    for _ in range(50):
        world.step()
        watch.tick(world.time)
    watch.finish()
    true = watch.mean_tension()
    assert true is not None and true > 1.0
    assert watch.span is not None and watch.span.fixture == "P"
    ctx = _context(world, truth)
    assert check_step("D", {"force": true}, True, watch, ctx, truth).agrees
    wrong = check_step("D", {"force": 1.5 * true}, True, watch, ctx, truth)
    assert not wrong.agrees and "true tension" in wrong.detail
    # a failure claims nothing
    failed = check_step("D", {"force": 1.5 * true}, False, watch, ctx, truth)
    assert failed.agrees and "claims nothing" in failed.detail


def test_a_rotation_claim_is_checked_against_the_angle_truly_turned() -> None:
    """The gripper circles the anchor of a taut cable by 0.4 rad."""
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.3, 0.0, 0.3], 0.295, 200.0)
    rest(world, 0.3)
    truth = GroundTruth(world)
    watch = StepWatch(truth, "W", "left", np.array([0.0, 0.0, 1.0]))
    omega = 0.4  # rad/s about +z
    for _ in range(round(1.0 / world.control_period)):
        p = world.gripper_pose("left")[0]
        twist = np.zeros(12)
        twist[0:3] = np.cross([0.0, 0.0, omega], p - [0.0, 0.0, 0.3])
        twist[5] = omega
        world.set_twist(twist)
        world.step()
        watch.tick(world.time)
    watch.finish()
    p = world.gripper_pose("left")[0]
    moved = math.atan2(p[1], p[0])
    assert watch.turned == pytest.approx(moved, abs=0.01)
    graph = _graph([("fixed", "A", np.array([0.0, 0.0, 0.3]), None)], p)
    ctx = make_context(graph, "left")
    assert check_step("I", {"angle": moved}, True, watch, ctx, truth).agrees
    short = check_step("I", {"angle": moved + 2 * ANGLE_TOLERANCE}, True, watch, ctx, truth)
    assert not short.agrees and "truly turned" in short.detail


def test_coverage_counts_converged_samples_within_3_std_on_every_axis() -> None:
    def sample(error: list[float], std: float) -> FilterSample:
        return FilterSample(
            0.0, 1, "A", False, np.array(error), np.zeros(3), np.full(3, std), std <= 0.01
        )

    samples = [
        sample([0.001, 0.0, 0.0], 0.001),  # 1 std: within
        sample([0.0, 0.0029, 0.0], 0.001),  # 2.9 std: within
        sample([0.0, 0.0, 0.0031], 0.001),  # 3.1 std on one axis: not
        sample([0.5, 0.0, 0.0], 0.05),  # not converged: not counted
    ]
    assert coverage(samples) == (3, pytest.approx(2 / 3))
    assert coverage([]) == (0, None)
    with_p = FilterSample(
        0.0,
        1,
        "A",
        False,
        np.array([0.002, 0.0, 0.0]),
        np.zeros(3),
        np.full(3, 0.001),
        True,
        np.diag([1e-6, 4e-6, 1e-6]),
    )
    assert with_p.nees == pytest.approx(4.0) and samples[0].nees is None


def test_the_span_from_a_peg_turns_with_its_tangent_not_with_the_axis() -> None:
    """A span leaving a peg of 12 mm tangentially along +x: its direction is +x, while the
    direction from the axis to where it enters the fingers is atan(12 / 100) = 6.8 deg off."""
    rho = 0.012
    entry = np.array([0.1, rho, 0.0])
    span = TautSpan(
        "W",
        "left",
        "P",
        np.zeros(3),
        np.array([0.0, rho, 0.0]),
        entry / 2,
        entry + np.array([0.02, 0.0, 0.0]),
        2.0,
        True,
        3,
        9,
        0.12,
        (3, 8),
        entry,
        0.05,
    )
    z = np.array([0.0, 0.0, 1.0])
    round_direction = _direction(span, z, round_contact=True)
    assert round_direction is not None and np.allclose(round_direction, [1.0, 0.0, 0.0])
    point_direction = _direction(span, z, round_contact=False)
    assert point_direction is not None
    assert math.degrees(math.atan2(point_direction[1], point_direction[0])) == pytest.approx(
        math.degrees(math.atan(rho / 0.1))
    )


def _swing_along_the_span(world: SimWorld, truth: GroundTruth, watch: StepWatch) -> float:
    """Swing the gripper +-0.5 mm along the span (2 s a period, as D's set point); return the
    slope of the true tension against the gripper's displacement along the span [N/m]."""
    span = truth.span("W", "left")
    assert span is not None
    u = span.entry - span.leave
    u /= np.linalg.norm(u)
    p0 = world.gripper_pose("left")[0].copy()
    xs, fs = [], []
    for k in range(round(4.0 / world.control_period)):
        t = k * world.control_period
        twist = np.zeros(12)
        twist[0:3] = 0.0005 * math.pi * math.cos(math.pi * t) * u  # 0.5 mm sin(pi t)
        world.set_twist(twist)
        world.step()
        watch.tick(truth.time)
        xs.append(float((world.gripper_pose("left")[0] - p0) @ u))
        fs.append(watch.tensions[-1])
    watch.finish()
    return float(np.polyfit(xs[250:], fs[250:], 1)[0])


@pytest.mark.parametrize("bend", [0.0, 1.2])
def test_the_true_stiffness_is_what_the_gripper_feels(bend: float) -> None:
    """From an anchor (no peg), and round a peg the cable bends round by 1.2 rad (where it
    sticks or slips as its friction decides), the measured true spring constant is the
    slope of the true tension against the gripper's displacement along the span."""
    anchor, peg = np.array([0.0, 0.0, 0.12]), np.array([0.15, 0.05, 0.12])
    u_in = (peg - anchor) / np.linalg.norm(peg - anchor)
    out = math.atan2(u_in[1], u_in[0]) + bend
    gripper = peg + 0.2 * np.array([math.cos(out), math.sin(out), 0.0])
    fixtures = (PegSpec("P", [0.15, 0.05, 0.05], 0.006, 0.12),) if bend else ()
    length = float(np.linalg.norm(peg - anchor)) + 0.2 + 0.0085 * bend
    world = anchor_and_gripper(
        list(anchor), list(gripper), length, 200.0, fixtures=fixtures, via=("P",) if bend else ()
    )
    truth = GroundTruth(world)
    span = truth.span("W", "left")
    assert span is not None
    pull = span.entry - span.leave
    twist = np.zeros(12)
    twist[0:3] = 0.01 * pull / np.linalg.norm(pull)
    world.set_twist(twist)
    while truth.span("W", "left").tension < 2.0:  # type: ignore[union-attr]
        world.step()
    rest(world, 0.3)
    watch = StepWatch(truth, "W", "left")
    slope = _swing_along_the_span(world, truth, watch)
    assert watch.span is not None and watch.span.fixture == ("P" if bend else "A")
    truth_k = watch.measured_stiffness()
    assert truth_k is not None and truth_k == pytest.approx(slope, rel=0.05)
    nominal = watch.edge_stiffness
    assert nominal is not None
    if not bend:  # from an anchor the closed form holds
        assert nominal == pytest.approx(200.0) and truth_k == pytest.approx(200.0, rel=0.03)


@pytest.mark.parametrize(
    ("seat", "via"),
    [
        ([0.15, 0.0, 0.3], True),  # routed through the clip: in its jaws
        ([0.15, 0.012, 0.3], False),  # the cable runs 12 mm beside the slot
        ([0.15, 0.0, 0.29], False),  # the cable lies over the jaws, not pushed in
    ],
)
def test_a_missed_clip_reads_as_a_false_success(seat: list[float], via: bool) -> None:
    """F or C reporting a clip that the cable is not in disagrees with the simulator."""
    world = anchor_and_gripper(
        [0.0, 0.0, 0.3],
        [0.3, 0.0, 0.3],
        0.31,
        fixtures=(ClipSpec("C", seat, 0.0, 2.0),),
        via=("C",) if via else (),
    )
    rest(world, 0.3)
    truth = GroundTruth(world)
    watch = StepWatch(truth, "W", "left")
    for _ in range(20):
        world.step()
        watch.tick(world.time)
    watch.finish()
    graph = _graph([("fixed", "A", np.array([0.0, 0.0, 0.3]), None)], world.gripper_pose("left")[0])
    if via:  # the clipping primitives put the clip's point at its seat
        graph = _graph(
            [("fixed", "A", np.array([0.0, 0.0, 0.3]), None), ("fixed", "C", np.array(seat), None)],
            world.gripper_pose("left")[0],
        )
    ctx = make_context(graph, "left")
    for letter in ("F", "C"):
        claim = check_step(letter, {"clip": "C"}, True, watch, ctx, truth)
        assert claim.agrees is via, claim.detail
        assert ("not in the jaws of C" in claim.detail) is not via
        # the same step reported failed claims nothing
        assert check_step(letter, {"clip": "C"}, False, watch, ctx, truth).agrees


def test_a_trusted_clip_point_is_right_anywhere_along_its_slot() -> None:
    """The cable runs straight through a clip: its seat and its exit both stand for it."""
    seat = np.array([0.15, 0.0, 0.3])
    world = anchor_and_gripper(
        [0.0, 0.0, 0.3],
        [0.3, 0.0, 0.3],
        0.31,
        fixtures=(ClipSpec("C", list(seat), 0.0, 2.0),),
        via=("C",),
    )
    rest(world, 0.3)
    truth = GroundTruth(world)
    gripper = world.gripper_pose("left")[0]

    def judged(point: np.ndarray) -> bool:
        graph = _graph(
            [("fixed", "A", np.array([0.0, 0.0, 0.3]), None), ("fixed", "C", point, 0.001)],
            gripper,
        )
        return judge_model(check_contacts(graph, truth, "W", 0.01)).agrees

    assert judged(seat)  # where F and C put it
    assert judged(seat + np.array([0.014, 0.0, 0.0]))  # near the slot's exit
    assert not judged(seat + np.array([0.0, 0.01, 0.0]))  # 10 mm beside the slot
    assert not judged(seat + np.array([0.05, 0.0, 0.0]))  # 35 mm past the exit

    # and model_error scores it as the truth check judges it: against the
    # cable's point in the slot (random board 635178977: a point at the
    # slot's end read 15 mm off against the seat)
    def scored(point: np.ndarray) -> tuple[float, float]:
        graph = _graph(
            [("fixed", "A", np.array([0.0, 0.0, 0.3]), None), ("fixed", "C", point, 0.001)],
            gripper,
        )
        (dev,) = [d for d in point_deviations(graph, truth, "W") if d.label == "C"]
        return dev.horizontal, dev.vertical

    true_seat = truth.seat("C", "W")
    at_seat = scored(true_seat)
    at_end = scored(true_seat + np.array([0.014, 0.0, 0.0]))
    assert at_end[0] == pytest.approx(at_seat[0], abs=1e-3)
    assert at_end[0] < 0.002
    assert scored(true_seat + np.array([0.0, 0.01, 0.0]))[0] == pytest.approx(0.01, abs=2e-3)


def test_a_peg_estimate_is_scored_against_the_band_the_peg_holds_the_cable_over(
    peg_world: tuple[SimWorld, GroundTruth],
) -> None:
    # a winding climbs its peg: the model's point is where the span leaves it,
    # anywhere in the band of loaded contacts, not their centre of pressure
    world, truth = peg_world
    band = truth.peg_band("P", "W")
    assert band is not None
    lo, hi = band
    centre = _peg_truth(truth)
    assert lo - 1e-9 <= centre[2] <= hi + 1e-9
    assert hi <= 0.10 + 0.05  # at most the peg's top
    for z, error in ((lo, 0.0), (hi, 0.0), (hi + 0.012, 0.012)):
        estimate = np.array([centre[0], centre[1], z])
        graph = _graph(
            [("fixed", "A", ANCHOR, 5e-4), ("contact", "P", estimate, 1e-3)],
            world.gripper_pose("left")[0],
        )
        check = check_contacts(graph, truth, "W", trusted_std=0.01)[1]
        assert check.error == pytest.approx(error, abs=1e-9)
    assert not check.within  # 12 mm above the band: beyond radius + 3 mm
    with pytest.raises(InvalidArgumentError):
        truth.peg_band("A", "W")


def test_a_peg_on_the_wrong_side_of_the_modelled_cable_disagrees(
    peg_world: tuple[SimWorld, GroundTruth],
) -> None:
    # the cable bends left round P (towards +y, seen from its anchor): a model
    # that has it turning right there is wrong whatever its std
    world, truth = peg_world
    gripper = world.gripper_pose("left")[0]
    for position, agrees in (((0.15, 0.0), True), ((0.15, 0.10), False)):
        estimate = np.array([*position, 0.12])
        graph = _graph([("fixed", "A", ANCHOR, 5e-4), ("contact", "P", estimate, 0.05)], gripper)
        checks = check_contacts(graph, truth, "W", trusted_std=0.01)
        assert checks[1].true_side == "left" and not checks[1].trusted
        assert checks[1].side == ("left" if agrees else "right")
        verdict = judge_model(checks)
        assert verdict.agrees is agrees
    assert "truly passes it on its left, the model on its right" in verdict.detail
    # a wound point's side is its wrap's sign
    graph = _graph(
        [("fixed", "A", ANCHOR, 5e-4), ("contact", "P", _peg_truth(truth), 1e-3)], gripper
    )
    for wrap, agrees in ((2.0 * math.pi, True), (-2.0 * math.pi, False), (0.05, True)):
        graph.points[1].wrap = wrap
        assert judge_model(check_contacts(graph, truth, "W", trusted_std=0.01)).agrees is agrees
