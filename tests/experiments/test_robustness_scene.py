"""The robustness scenes and faults: every draw validates and stays within the envelope."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.experiments.robustness_scene import (
    ANGLE_RANGE,
    FAULT_TYPES,
    FORCE_RANGE,
    LENGTH_RANGE,
    MARGIN,
    MIN_HEIGHT,
    NOISE_RANGE,
    PAD_EXIT,
    PEG_RADIUS_RANGE,
    SLACK_RANGE,
    STIFFNESS_RANGE,
    WRAP_RANGE,
    anchor_route_length,
    draw_fault,
    draw_scene,
    peg_route_length,
)
from tautwire.scenario.models import Anchor, Peg
from tautwire.scenario.workspace import WORKSPACE
from tautwire.sim.build import world_spec
from tautwire.sim.mjcf import scene_model
from tautwire.sim.options import SimOptions


def _within(value: float, bounds: tuple[float, float]) -> bool:
    return bounds[0] <= value <= bounds[1]


def _azimuth(v: np.ndarray) -> float:
    return math.atan2(float(v[1]), float(v[0]))


def _wrapped(a: float) -> float:
    return (a + math.pi) % (2.0 * math.pi) - math.pi


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(min_value=0, max_value=2**31 - 1))
def test_every_scene_validates_and_stays_within_the_envelope(seed: int) -> None:
    scene = draw_scene(seed)
    scenario = scene.scenario()  # validates: schema, references, geometry
    cable = scenario.cables[0]
    robot = scenario.robot
    inputs = scene.inputs
    assert _within(cable.length, LENGTH_RANGE)
    assert _within(cable.stiffness, STIFFNESS_RANGE)
    assert cable.start == "A1" and cable.held_by[0].arm == "left"
    assert cable.held_by[0].at == cable.length
    assert _within(robot.sensor.noise_force, NOISE_RANGE)
    d, i = scenario.task
    assert (d.letter, i.letter) == ("D", "I")
    assert _within(float(d.params["force"]), FORCE_RANGE)
    angle = float(i.params["angle"])
    assert _within(abs(angle), ANGLE_RANGE)
    assert i.params["about"] == scene.fixture
    slack = float(inputs["slack"])
    assert _within(slack, SLACK_RANGE)
    gripper = np.array(robot.grippers.left.position)
    lo, hi = np.array(WORKSPACE.lower) + MARGIN, np.array(WORKSPACE.upper) - MARGIN
    assert np.all(gripper >= lo) and np.all(gripper <= hi) and gripper[2] >= MIN_HEIGHT
    q = robot.grippers.left.orientation
    tool_yaw = 2.0 * math.atan2(q[3], q[0])
    assert tool_yaw == pytest.approx(float(inputs["tool_yaw"]), abs=1e-6)
    anchor = next(f for f in scenario.board.fixtures if isinstance(f, Anchor))
    a = np.array(anchor.position)
    if scene.fixture_type == "anchor":
        assert scene.fixture == "A1" and cable.via == []
        start = anchor_route_length(a, gripper, tool_yaw)
        pivot = a
    else:
        peg = next(f for f in scenario.board.fixtures if isinstance(f, Peg))
        assert scene.fixture == "P1" and cable.via == ["P1"]
        assert _within(peg.radius, PEG_RADIUS_RANGE)
        assert peg.position[2] + peg.height > gripper[2]  # the cable cannot slip off the top
        pivot = np.array([peg.position[0], peg.position[1], a[2]])
        rho = peg.radius + scenario.cables[0].radius + 1e-4
        start = peg_route_length(a, pivot, rho, gripper, tool_yaw)
        # the bend round the peg, before and after the rotation, stays in range
        bend = _wrapped(_azimuth(gripper - pivot) - _azimuth(pivot - a))
        assert bend == pytest.approx(float(inputs["bend"]), abs=1e-6)
        assert _within(abs(bend), WRAP_RANGE)
        assert _within(abs(bend + angle), WRAP_RANGE)
    # the route the simulator lays is (1 - slack) times the held length
    assert start == pytest.approx((1.0 - slack) * cable.length, rel=1e-6)
    relative = _wrapped(tool_yaw - _azimuth(gripper - pivot))
    assert relative == pytest.approx(float(inputs["tool_yaw_to_cable"]), abs=1e-6)


def test_scenes_are_reproducible_and_cover_both_fixtures_and_all_yaws() -> None:
    assert draw_scene(7).data == draw_scene(7).data
    scenes = [draw_scene(seed) for seed in range(60)]
    assert {s.fixture_type for s in scenes} == {"anchor", "peg"}
    yaws = [float(s.inputs["tool_yaw_to_cable"]) for s in scenes]
    # tool x pointing at the fixture (|yaw| > 135 deg) is drawn as often as any other grasp
    assert sum(abs(y) > 0.75 * math.pi for y in yaws) >= 8
    assert any(float(s.inputs["angle"]) < 0 for s in scenes)
    assert max(abs(float(s.inputs["angle"])) for s in scenes) > math.pi
    assert draw_scene(3, "peg").fixture_type == "peg"
    with pytest.raises(InvalidArgumentError, match="anchor, peg"):
        draw_scene(3, "clip")


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(min_value=0, max_value=2**31 - 1), run_time=st.floats(0.1, 60.0))
def test_every_fault_lies_inside_the_run_and_validates(seed: int, run_time: float) -> None:
    fault = draw_fault(seed, run_time)
    assert fault["kind"] in FAULT_TYPES
    assert 0.1 * max(run_time, 0.5) <= fault["at"] <= 0.9 * max(run_time, 0.5)
    if fault["kind"] == "freeze_short":
        assert fault["duration"] <= 0.05
    if fault["kind"] == "freeze_long":
        assert fault["duration"] > 0.1
    entry = {k: v for k, v in fault.items() if k != "kind"}
    scenario = draw_scene(seed % 1000).scenario([entry])
    assert len(scenario.faults) == 1 and scenario.faults[0].type == entry["type"]


def test_every_fault_type_is_drawn() -> None:
    kinds = {draw_fault(seed, 10.0)["kind"] for seed in range(100)}
    assert kinds == set(FAULT_TYPES)
    assert draw_fault(5, 10.0, "slip")["type"] == "slip"


@pytest.mark.parametrize("seed", range(0, 40, 3))
def test_the_route_the_simulator_lays_leaves_the_drawn_slack(seed: int) -> None:
    """The laid vertices span (1 - slack) of the cable: a grasp across it or a bend round a
    peg does not start the cable stretched (the vertices cut the arc round a peg short)."""
    scene = draw_scene(seed)
    scenario = scene.scenario()
    laid = scene_model(world_spec(scenario), SimOptions()).vertices["W1"]
    route = float(np.sum(np.linalg.norm(np.diff(laid, axis=0), axis=1)))
    target = (1.0 - float(scene.inputs["slack"])) * scenario.cables[0].length
    assert route <= target + 1e-4
    assert route >= target - (0.006 if scene.fixture_type == "peg" else 1e-4)


def test_route_lengths_of_simple_layouts() -> None:
    a, g = np.zeros(3), np.array([0.3, 0.0, 0.0])
    # tool x along the cable: straight; across it: into the fingers along x
    assert anchor_route_length(a, g, 0.0) == pytest.approx(0.3)
    assert anchor_route_length(a, g, math.pi / 2) == pytest.approx(
        math.hypot(0.3, PAD_EXIT) + PAD_EXIT
    )
    # a half turn round a peg: two tangents and half the circle
    rho, axis = 0.01, np.zeros(3)
    anchor, gripper = np.array([-0.2, rho, 0.0]), np.array([-0.2, -rho, 0.0])
    length = peg_route_length(anchor, axis, rho, gripper, 0.0)
    assert length == pytest.approx(0.2 + math.pi * rho + 0.2, abs=1e-9)
