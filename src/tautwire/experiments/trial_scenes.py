"""Randomised states for the trials of each primitive (the paper's Table I).

The paper changed, between trials, "the placement of the fixtures, the
initial position of the end effectors, as well as the elasticity and length
of the DLOs". Each builder here draws exactly those from its seed: cable
stiffness log-uniform in [10, 1000] N/m, cable length uniform in
[0.4, 1.0] m, fixture positions on the board and gripper start poses
(uniform within ranges that keep the task feasible for the robot's
workspace), and writes a scenario: the preparatory steps the primitive needs
(e.g. D before I: a cable must be taut before it can be rotated), then the
primitive under test. The robot's initial stiffness guess stays the generic
100 N/m, so it is off by up to ten times.

Start yaw (issue 10, as the robustness campaign): every gripper that holds
the cable at the start gets its own start yaw about z, uniform in
[-pi, pi), independent of the cable's direction: tool x may point along the
cable, across it, or back at the fixture or the other gripper. The
simulator lays a held cable straight through the fingers along tool x and
then to where it goes (:mod:`tautwire.sim.route`), so such a cable starts
bent round a fingertip; the drawn slack is measured along that laid route
(:func:`~tautwire.experiments.robustness_scene.anchor_route_length`,
:func:`pair_route_length`), not as a straight distance, so that no grasp
starts the cable stretched. A gripper that does not hold the cable at the
start (H's grasping arm, a parked arm) keeps its orientation rule.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.experiments.robustness_scene import PAD_EXIT, SceneDraws, anchor_route_length
from tautwire.experiments.trial import LETTERS, TrialResult, TrialSpec
from tautwire.model.quaternion import multiply
from tautwire.primitives.clip_sensing import JAW_TOP, PivotPress
from tautwire.primitives.single_arm_clipping import MAX_ANGLE, TABLE_CLEARANCE
from tautwire.scenario import Scenario
from tautwire.scenario.loader import scenario_from_data
from tautwire.scenario.models import CLIP_LENGTH
from tautwire.scenario.primitive_catalogue import find_primitive
from tautwire.scenario.workspace import WORKSPACE

FloatArray = NDArray[np.float64]

STIFFNESS_RANGE = (10.0, 1000.0)  # N/m, log-uniform
LENGTH_RANGE = (0.4, 1.0)  # m, uniform
MASS_PER_LENGTH = 0.03  # kg/m
RADIUS = 0.0025  # m
FORCE_NOISE = 0.05  # N
FORCE_LIMIT = 15.0  # N
#: F: a clip needs at most the hardest press one arm can make on it, over this.
PRESS_RESERVE = 1.2
#: Margin [m] kept from the workspace's faces.
MARGIN = 0.05


def primitive_name(letter: str) -> str:
    """The canonical name of the primitive with ``letter``."""
    return find_primitive(letter).name


@dataclass(frozen=True)
class TrialScene:
    """A randomised scenario whose last step is the primitive under test.

    Attributes:
        letter: The tested primitive's letter.
        scenario: The scenario (preparatory steps, then the primitive).
        inputs: The randomised inputs, flat and JSON-ready.
    """

    letter: str
    scenario: Scenario
    inputs: dict[str, float | str]

    def run(self, spec: TrialSpec, t0: float | None = None) -> TrialResult:
        """Simulate the scenario; the trial's outcome is its first failure or success.

        A step that reported success while the simulator disagrees (its
        ``truth``) makes the trial a failure with cause ``false_success``,
        whatever came after: the worst defect a trial can show.
        """
        from tautwire.experiments.run_scenario import run_scenario

        start = time.perf_counter() if t0 is None else t0
        result, _, _ = run_scenario(self.scenario, spec.seed)
        steps = result.steps
        failed = next((s for s in steps if s["outcome"] != "success"), None)
        false = next(
            (s for s in steps if s["outcome"] == "success" and not s["truth"]["agrees"]), None
        )
        last = steps[-1] if steps else None
        if false is not None:
            outcome, cause = "failure", "false_success"
            detail = (
                f"step {false['letter']} reported success ({false['detail']}) but the simulator"
                f" disagrees: {false['truth']['detail']}"
            )
        elif failed is not None:
            tested = failed is last and len(steps) == len(self.scenario.task)
            where = "" if tested else f" (in the preparatory step {failed['letter']})"
            outcome, cause = "failure", failed["cause"] or "error"
            detail = f"{failed['detail']}{where}"
        elif last is None:
            outcome, cause, detail = "failure", "error", "the scenario has no steps"
        else:
            outcome, cause, detail = "success", None, str(last["detail"])
        return TrialResult(
            self.letter,
            primitive_name(self.letter),
            spec.index,
            spec.seed,
            self.inputs,
            outcome,
            cause,
            detail,
            result.max_force,
            result.sim_time,
            time.perf_counter() - start,
        )


def _inside(p: np.ndarray, margin: float = MARGIN) -> bool:
    lo = np.asarray(WORKSPACE.lower) + margin
    hi = np.asarray(WORKSPACE.upper) - margin
    return bool(np.all(p >= lo) and np.all(p <= hi))


def _yaw_quaternion(yaw: float) -> list[float]:
    """[w, x, y, z] of a tool frame turned by ``yaw`` [rad] about the world z-axis."""
    return [math.cos(0.5 * yaw), 0.0, 0.0, math.sin(0.5 * yaw)]


def _horizontal(yaw: float) -> FloatArray:
    """The horizontal unit vector at azimuth ``yaw`` [rad] (a yawed tool's x-axis)."""
    return np.array([math.cos(yaw), math.sin(yaw), 0.0])


def _azimuth(direction: FloatArray) -> float:
    return math.atan2(float(direction[1]), float(direction[0]))


def _yaw_to(yaw: float, direction: FloatArray) -> float:
    """``yaw`` [rad] against the azimuth of ``direction``, wrapped to [-pi, pi)."""
    return (yaw - _azimuth(direction) + math.pi) % (2.0 * math.pi) - math.pi


def _bisect(length: Callable[[float], float], target: float, low: float, high: float) -> float:
    """The r in [low, high] at which the increasing ``length(r)`` is ``target`` (clamped)."""
    for _ in range(40):  # to 1 nm over 1 m
        mid = 0.5 * (low + high)
        if length(mid) < target:
            low = mid
        else:
            high = mid
    return 0.5 * (low + high)


def pair_route_length(
    left: FloatArray, right: FloatArray, x_left: FloatArray, x_right: FloatArray
) -> float:
    """Length [m] of the route the simulator lays between two held points of one cable.

    From the left tool centre point along +-``x_left`` (the sense towards
    the right gripper) for ``PAD_EXIT``, straight to the point ``PAD_EXIT``
    from the right tool centre point along +-``x_right`` (the sense towards
    the left exit), and along it to the right tool centre point
    (``tautwire.sim.route``).

    Args:
        left: Left tool centre point [m].  # (3,)
        right: Right tool centre point [m].  # (3,)
        x_left: The left tool's x-axis (unit).  # (3,)
        x_right: The right tool's x-axis (unit).  # (3,)
    """
    exit_left = left + (1.0 if float(x_left @ (right - left)) >= 0.0 else -1.0) * PAD_EXIT * x_left
    towards = 1.0 if float(x_right @ (exit_left - right)) > 0.0 else -1.0
    entry_right = right + towards * PAD_EXIT * x_right
    return 2.0 * PAD_EXIT + float(np.linalg.norm(entry_right - exit_left))


def _hold_distance(
    route: float, anchor: FloatArray, u: FloatArray, dz: float, tool_yaw: float
) -> float:
    """Horizontal distance [m] along ``u`` from ``anchor`` at which the laid route is ``route``.

    The gripper sits at anchor + r u + dz z with its x-axis at ``tool_yaw``;
    the route (:func:`anchor_route_length`) grows with r.
    """
    rise = np.array([0.0, 0.0, dz])

    def length(r: float) -> float:
        return anchor_route_length(anchor, anchor + r * u + rise, tool_yaw)

    return _bisect(length, route, 0.0, 2.0 * route)


def _pair_distance(
    route: float, middle: FloatArray, u: FloatArray, yaw_left: float, yaw_right: float
) -> float:
    """Distance [m] of two grippers about ``middle`` along ``u`` whose laid route is ``route``."""
    x_left, x_right = _horizontal(yaw_left), _horizontal(yaw_right)

    def length(d: float) -> float:
        return pair_route_length(middle - 0.5 * d * u, middle + 0.5 * d * u, x_left, x_right)

    return _bisect(length, route, 2.0 * PAD_EXIT, 2.0 * route)


def _cable(draw: SceneDraws, **fields: Any) -> dict[str, Any]:
    stiffness = draw.log_uniform("stiffness", *STIFFNESS_RANGE)
    length = draw.uniform("length", *LENGTH_RANGE)
    return {
        "name": "W1",
        "length": length,
        "mass_per_length": MASS_PER_LENGTH,
        "stiffness": stiffness,
        "radius": RADIUS,
        **fields,
    }


def _scenario(
    letter: str,
    seed: int,
    grippers: dict[str, Any],
    fixtures: list[dict[str, Any]],
    cable: dict[str, Any],
    task: list[dict[str, Any]],
) -> Scenario:
    return scenario_from_data(
        {
            "version": 1,
            "name": f"table1-{letter}-{seed}",
            "seed": seed,
            "robot": {
                "control_period": 0.004,
                "force_limit": FORCE_LIMIT,
                "sensor": {"arm": "left", "noise_force": FORCE_NOISE, "noise_torque": 0.002},
                "grippers": grippers,
            },
            "board": {"fixtures": fixtures},
            "cables": [cable],
            "task": task,
        },
        source=f"<table1 trial {letter} seed {seed}>",
    )


def _parked(away_from: np.ndarray) -> dict[str, Any]:
    """The unused right gripper, parked high and away from the cable."""
    y = -0.5 if away_from[1] > -0.1 else 0.5
    return {"position": [0.7, y, 0.5]}


def _anchor_and_hold(
    draw: SceneDraws, max_hold: float, min_hold: float = 0.25
) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, dict[str, Any]]:
    """An anchor, a hold on a cable from it and a slack start pose of the gripper.

    The gripper's start yaw (``tool_yaw``) is uniform over the full circle,
    independent of the cable's direction; its distance from the anchor is
    the one at which the route the simulator lays (through the fingers
    along the tool x-axis) is ``slack`` times the held length.

    Returns the anchor, the gripper's start position, the unit horizontal
    direction anchor -> gripper, the start yaw and the cable's fields (the
    left gripper holds it).
    """
    cable = _cable(draw)
    length = float(cable["length"])
    yaw = draw.uniform("tool_yaw", -math.pi, math.pi)
    for _ in range(1000):
        anchor = np.array(
            [float(draw.rng.uniform(0.0, 0.35)), float(draw.rng.uniform(-0.3, 0.3)), 0.0]
        )
        anchor[2] = float(draw.rng.uniform(0.06, 0.14))
        at = float(draw.rng.uniform(min_hold, min(max_hold, length)))
        slack = float(draw.rng.uniform(0.85, 0.97))
        u = _horizontal(float(draw.rng.uniform(-math.pi, math.pi)))
        dz = float(draw.rng.uniform(-0.02, 0.04))
        r = _hold_distance(slack * at, anchor, u, dz, yaw)
        gripper = anchor + r * u + np.array([0.0, 0.0, dz])
        if _inside(gripper) and gripper[2] > 0.05:
            draw.point("anchor", anchor)
            draw.point("gripper", gripper)
            draw.inputs["hold_at"] = round(at, 6)
            draw.inputs["slack"] = round(slack, 6)
            draw.inputs["dz"] = round(dz, 6)
            # 0: tool x along the cable, away from the anchor; +-pi: pointing at it
            draw.inputs["tool_yaw_to_cable"] = round(_yaw_to(yaw, u), 6)
            cable.update(start="A1", held_by={"arm": "left", "at": at})
            return anchor, gripper, u, yaw, cable
    raise InvalidArgumentError("could not place an anchor and a hold inside the workspace")


def _two_holds(
    draw: SceneDraws,
    span_range: tuple[float, float],
    tail_max: float = 0.25,
    long_tail: float = 0.0,
) -> tuple[np.ndarray, np.ndarray, dict[str, Any], dict[str, Any]]:
    """A cable with free ends held by both grippers, slack between them.

    The left gripper (with the sensor) holds at s1, the right at s2 > s1;
    one of the two free ends is at least ``long_tail`` [m] long. Each
    gripper's start yaw is uniform over the full circle (``yaw_left``,
    ``yaw_right``); their distance is the one at which the route the
    simulator lays between them (:func:`pair_route_length`) is ``slack``
    times the span.
    Returns the left and right start positions, both grippers' fields and
    the cable's fields.
    """
    cable = _cable(draw)
    length = float(cable["length"])
    for _ in range(1000):
        span = float(draw.rng.uniform(*span_range))
        span = min(span, length - 0.04)
        tails = length - span
        low, high = max(0.02, tails - tail_max), min(tail_max, tails - 0.02)
        if low > high:
            continue
        s1 = float(draw.rng.uniform(low, high))
        if max(s1, tails - s1) < long_tail:
            continue
        slack = float(draw.rng.uniform(0.85, 0.97))
        u = _horizontal(float(draw.rng.uniform(-math.pi, math.pi)))
        middle = np.array(
            [
                float(draw.rng.uniform(0.15, 0.55)),
                float(draw.rng.uniform(-0.3, 0.3)),
                float(draw.rng.uniform(0.22, 0.35)),
            ]
        )
        yaws = (
            float(draw.rng.uniform(-math.pi, math.pi)),
            float(draw.rng.uniform(-math.pi, math.pi)),
        )
        d = _pair_distance(slack * span, middle, u, *yaws)
        left = middle - 0.5 * d * u
        right = middle + 0.5 * d * u
        if _inside(left) and _inside(right):
            draw.point("left", left)
            draw.point("right", right)
            draw.inputs["hold_left"] = round(s1, 6)
            draw.inputs["hold_right"] = round(s1 + span, 6)
            draw.inputs["slack"] = round(slack, 6)
            grippers = _pair_grippers(draw, left, right, u, yaws)
            cable.update(held_by=[{"arm": "left", "at": s1}, {"arm": "right", "at": s1 + span}])
            return left, right, grippers, cable
    raise InvalidArgumentError("could not place two holds inside the workspace")


def _one_arm(gripper: np.ndarray, yaw: float) -> dict[str, Any]:
    """The left gripper at ``gripper`` with its x-axis at ``yaw`` [rad]; the right one parked."""
    return {
        "left": {"position": list(gripper), "orientation": _yaw_quaternion(yaw)},
        "right": _parked(gripper),
    }


def _anchor(position: np.ndarray) -> dict[str, Any]:
    """The anchor A1 that holds the cable's start."""
    return {"name": "A1", "type": "anchor", "position": list(position)}


def _pair_grippers(
    draw: SceneDraws, left: np.ndarray, right: np.ndarray, u: np.ndarray, yaws: tuple[float, float]
) -> dict[str, Any]:
    """Both grippers holding the cable, with their start yaws [rad] (noted in the inputs).

    ``u`` is the direction left -> right; ``yaw_left_to_cable`` is the left
    tool's x-axis against -u (the cable leaves the left gripper away from
    the right one), ``yaw_right_to_cable`` the right one's against u.
    """
    for name, yaw, away in (("yaw_left", yaws[0], -u), ("yaw_right", yaws[1], u)):
        draw.inputs[name] = round(yaw, 6)
        draw.inputs[f"{name}_to_cable"] = round(_yaw_to(yaw, away), 6)
    return {
        "left": {"position": list(left), "orientation": _yaw_quaternion(yaws[0])},
        "right": {"position": list(right), "orientation": _yaw_quaternion(yaws[1])},
    }


def scene_a(seed: int) -> TrialScene:
    """A: a cable held by both grippers, slack between them: tension it."""
    draw = SceneDraws(seed)
    _, _, grippers, cable = _two_holds(draw, (0.15, 0.5))
    force = draw.uniform("force", 1.5, 4.0)
    scenario = _scenario(
        "A",
        seed,
        grippers,
        [],
        cable,
        [{"primitive": "A", "force": force}],
    )
    return TrialScene("A", scenario, draw.inputs)


def scene_b(seed: int) -> TrialScene:
    """B: tension (A), then part the grippers letting the cable slide through one."""
    draw = SceneDraws(seed)
    _, _, grippers, cable = _two_holds(draw, (0.15, 0.4), tail_max=0.3, long_tail=0.1)
    force = draw.uniform("force", 1.5, 3.0)
    holds = cable["held_by"]
    tails = {"left": holds[0]["at"], "right": cable["length"] - holds[1]["at"]}
    slide_arm = draw.choice("slide_arm", ("left", "right"))
    if tails[slide_arm] < 0.1:  # the cable must have room to slide through it
        slide_arm = max(tails, key=lambda arm: tails[arm])
        draw.inputs["slide_arm"] = slide_arm
    tail = tails[slide_arm]
    distance = draw.uniform("distance", 0.05, max(0.0501, min(0.15, tail - 0.05)))
    friction = draw.uniform("friction_force", 1.0, 2.5)
    scenario = _scenario(
        "B",
        seed,
        grippers,
        [],
        cable,
        [
            {"primitive": "A", "force": force},
            {
                "primitive": "B",
                "slide_arm": slide_arm,
                "distance": distance,
                "friction_force": friction,
            },
        ],
    )
    return TrialScene("B", scenario, draw.inputs)


def scene_d(seed: int) -> TrialScene:
    """D: a cable from an anchor, slack, held by the left gripper: tension it."""
    draw = SceneDraws(seed)
    anchor, gripper, _, yaw, cable = _anchor_and_hold(draw, 0.8)
    force = draw.uniform("force", 1.5, 4.0)
    scenario = _scenario(
        "D",
        seed,
        _one_arm(gripper, yaw),
        [_anchor(anchor)],
        cable,
        [{"primitive": "D", "arm": "left", "force": force}],
    )
    return TrialScene("D", scenario, draw.inputs)


def scene_i(seed: int) -> TrialScene:
    """I: tension (D), then rotate around the anchor by a random angle."""
    draw = SceneDraws(seed)
    anchor, gripper, _, yaw, cable = _anchor_and_hold(draw, 0.5)
    force = draw.uniform("force", 1.5, 4.0)
    angle = draw.uniform("angle", 0.5 * math.pi, math.pi) * (
        1.0 if draw.choice("sense", ("positive", "negative")) == "positive" else -1.0
    )
    scenario = _scenario(
        "I",
        seed,
        _one_arm(gripper, yaw),
        [_anchor(anchor)],
        cable,
        [
            {"primitive": "D", "arm": "left", "force": force},
            {"primitive": "I", "arm": "left", "angle": angle, "speed": 0.5, "about": "A1"},
        ],
    )
    return TrialScene("I", scenario, draw.inputs)


def scene_e(seed: int) -> TrialScene:
    """E: tension (D), then move away from the anchor letting the cable slide."""
    draw = SceneDraws(seed)
    anchor, gripper, u, yaw, cable = _anchor_and_hold(draw, 0.6)
    tail = float(cable["length"]) - float(cable["held_by"]["at"])
    if tail < 0.1:  # room to slide: hold the cable further from its end
        at = float(cable["length"]) - 0.1
        cable["held_by"]["at"] = at
        draw.inputs["hold_at"] = round(at, 6)
        dz = float(draw.inputs["dz"])
        r = _hold_distance(float(draw.inputs["slack"]) * at, anchor, u, dz, yaw)
        gripper = anchor + r * u + np.array([0.0, 0.0, dz])
        draw.point("gripper", gripper)
        tail = 0.1
    force = draw.uniform("force", 1.5, 3.0)
    distance = draw.uniform("distance", 0.04, max(0.0401, min(0.15, tail - 0.05)))
    friction = draw.uniform("friction_force", 1.0, 2.5)
    scenario = _scenario(
        "E",
        seed,
        _one_arm(gripper, yaw),
        [_anchor(anchor)],
        cable,
        [
            {"primitive": "D", "arm": "left", "force": force},
            {"primitive": "E", "arm": "left", "distance": distance, "friction_force": friction},
        ],
    )
    return TrialScene("E", scenario, draw.inputs)


def scene_g(seed: int) -> TrialScene:
    """G: a gripper at any start yaw, pitched up to 20 deg: tension (D), then align (G).

    The pitch tilts the fingers' exit by at most ``PAD_EXIT`` sin(20 deg)
    (4 mm) out of the yawed route that the slack is measured along.
    """
    draw = SceneDraws(seed)
    anchor, gripper, _, yaw, cable = _anchor_and_hold(draw, 0.6)
    force = draw.uniform("force", 1.5, 3.0)
    pitch = draw.uniform("pitch_offset", -math.radians(20.0), math.radians(20.0))
    qz = np.array([math.cos(0.5 * yaw), 0.0, 0.0, math.sin(0.5 * yaw)])
    qy = np.array([math.cos(0.5 * pitch), 0.0, math.sin(0.5 * pitch), 0.0])
    q = multiply(qz, qy)
    scenario = _scenario(
        "G",
        seed,
        {
            "left": {"position": list(gripper), "orientation": [float(v) for v in q]},
            "right": _parked(gripper),
        },
        [_anchor(anchor)],
        cable,
        [
            {"primitive": "D", "arm": "left", "force": force},
            {"primitive": "G", "arm": "left"},
        ],
    )
    return TrialScene("G", scenario, draw.inputs)


def scene_h(seed: int) -> TrialScene:
    """H: tension (D), then the right gripper grasps the taut cable between anchor and gripper."""
    draw = SceneDraws(seed)
    anchor, gripper, u, left_yaw, cable = _anchor_and_hold(draw, 0.6, min_hold=0.3)
    force = draw.uniform("force", 1.5, 3.0)
    hold = float(cable["held_by"]["at"])
    at = draw.uniform("grasp_at", 0.35 * hold, 0.65 * hold)
    nominal = anchor + (at / hold) * (gripper - anchor)
    for _ in range(1000):
        offset = draw.rng.normal(size=3)
        offset[2] = abs(offset[2]) + 0.5
        start = nominal + draw.rng.uniform(0.1, 0.25) * offset / np.linalg.norm(offset)
        start[2] = max(start[2], nominal[2] + 0.06)
        if _inside(start) and np.linalg.norm(start - gripper) > 0.08:
            break
    else:
        raise InvalidArgumentError("could not place the grasping gripper inside the workspace")
    draw.point("right", start)
    yaw = _azimuth(u) + draw.uniform("right_yaw", -0.5, 0.5)
    scenario = _scenario(
        "H",
        seed,
        {
            "left": {"position": list(gripper), "orientation": _yaw_quaternion(left_yaw)},
            # the grasping gripper holds nothing at the start: x about along the cable
            "right": {"position": list(start), "orientation": _yaw_quaternion(yaw)},
        },
        [_anchor(anchor)],
        cable,
        [
            {"primitive": "D", "arm": "left", "force": force},
            {"primitive": "H", "arm": "right", "at": at},
        ],
    )
    return TrialScene("H", scenario, draw.inputs)


def _pivot_press(
    anchor: FloatArray, seat: FloatArray, u: FloatArray, at: float, span_stiffness: float
) -> float:
    """The hardest press [N] primitive F can make on a clip, from the true geometry.

    The cable runs from the anchor over the clip's jaws to the gripper,
    ``at`` [m] of it stretched by f / ``span_stiffness``; :class:`PivotPress`
    over the tensions up to 60 % of the force limit, with F's own limits
    (the table clearance, the steepest bend).
    """
    half = 0.5 * CLIP_LENGTH * u + np.array([0.0, 0.0, JAW_TOP])
    exit_point, entry = seat + half, seat - half
    entry[2] = exit_point[2]
    far = anchor - entry
    tension = 2.0  # the reference of r(f), which is linear in f: any value gives the same press
    plan = PivotPress(
        radius=at + tension / span_stiffness - float(np.linalg.norm(far)) - CLIP_LENGTH,
        tension=tension,
        stiffness=span_stiffness,
        drop=float(exit_point[2]) - TABLE_CLEARANCE,
        sin_far=float(far[2]) / float(np.linalg.norm(far)),
        sin_max=math.sin(MAX_ANGLE),
    )
    return max(plan.press(float(f)) for f in np.linspace(1.0, 0.6 * FORCE_LIMIT, 50))


def scene_f(seed: int) -> TrialScene:
    """F: tension (D), then press the cable into a clip between the anchor and the gripper."""
    draw = SceneDraws(seed)
    cable = _cable(draw)
    length = float(cable["length"])
    share = float(draw.rng.uniform(0.0, 1.0))  # where the clip's push force lies in its range
    tool_yaw = draw.uniform("tool_yaw", -math.pi, math.pi)
    for _ in range(1000):
        anchor = np.array(
            [
                float(draw.rng.uniform(0.0, 0.35)),
                float(draw.rng.uniform(-0.3, 0.3)),
                float(draw.rng.uniform(0.15, 0.25)),
            ]
        )
        beyond = float(draw.rng.uniform(0.06, 0.12))
        to_clip = float(draw.rng.uniform(0.15, 0.35))
        at = min(to_clip + beyond, length)
        yaw = float(draw.rng.uniform(-math.pi, math.pi))
        u = _horizontal(yaw)
        slack = float(draw.rng.uniform(0.95, 0.98))  # along the route the simulator lays
        gripper = anchor + _hold_distance(slack * at, anchor, u, 0.0, tool_yaw) * u
        # below the slack cable's sag, so that it does not start on the clip
        seat = anchor + to_clip * u - np.array([0.0, 0.0, 0.05])
        if not (_inside(gripper) and _inside(seat, 0.02) and at > to_clip + 0.05):
            continue
        # one arm presses with the held span's tension only, bending the cable
        # over the clip as far as the table lets it: the clip needs at most
        # the hardest press over PRESS_RESERVE, 1-4 N (redrawn if under 1 N)
        span_stiffness = float(cable["stiffness"]) * length / at
        top = min(_pivot_press(anchor, seat, u, at, span_stiffness) / PRESS_RESERVE, 4.0)
        if top >= 1.0:
            break
    else:
        raise InvalidArgumentError("could not place an anchor, a clip and a hold")
    draw.point("anchor", anchor)
    draw.point("gripper", gripper)
    draw.point("clip", seat)
    draw.inputs["hold_at"] = round(at, 6)
    draw.inputs["slack"] = round(slack, 6)
    draw.inputs["tool_yaw_to_cable"] = round(_yaw_to(tool_yaw, u), 6)
    push = 1.0 + share * (top - 1.0)
    draw.inputs["push_force"] = round(push, 6)
    slot = yaw + draw.uniform("slot_offset", -math.radians(10.0), math.radians(10.0))
    cable.update(start="A1", held_by={"arm": "left", "at": at})
    force = draw.uniform("force", 1.5, 3.0)
    scenario = _scenario(
        "F",
        seed,
        _one_arm(gripper, tool_yaw),
        [
            _anchor(anchor),
            {"name": "C1", "type": "clip", "position": list(seat), "yaw": slot, "push_force": push},
        ],
        cable,
        [
            {"primitive": "D", "arm": "left", "force": force},
            {"primitive": "F", "arm": "left", "clip": "C1"},
        ],
    )
    return TrialScene("F", scenario, draw.inputs)


def scene_c(seed: int) -> TrialScene:
    """C: tension (A), then press the cable between the grippers into a clip below them."""
    draw = SceneDraws(seed)
    push = draw.uniform("push_force", 1.0, 4.0)
    seat = np.array(
        [
            draw.uniform("clip_x", 0.15, 0.55),
            draw.uniform("clip_y", -0.3, 0.3),
            draw.uniform("clip_z", 0.1, 0.2),
        ]
    )
    slot = draw.uniform("clip_yaw", -math.pi, math.pi)
    cable = _cable(draw)
    length = float(cable["length"])
    span = draw.uniform("span", 0.12, 0.3)
    s1 = draw.uniform("hold_left", 0.05, length - span - 0.05)
    slack = draw.uniform("slack", 0.9, 0.97)
    u = _horizontal(slot + draw.uniform("yaw_offset", -0.5, 0.5))
    middle = seat + np.array(
        [draw.uniform("dx", -0.05, 0.05), draw.uniform("dy", -0.05, 0.05), 0.0]
    )
    middle[2] = seat[2] + draw.uniform("height", 0.05, 0.1)
    yaws = (
        draw.uniform("yaw_left", -math.pi, math.pi),
        draw.uniform("yaw_right", -math.pi, math.pi),
    )
    d = _pair_distance(slack * span, middle, u, *yaws)  # along the route the simulator lays
    left = middle - 0.5 * d * u
    right = middle + 0.5 * d * u
    draw.point("left", left)
    draw.point("right", right)
    cable.update(held_by=[{"arm": "left", "at": s1}, {"arm": "right", "at": s1 + span}])
    force = draw.uniform("force", 1.5, 3.0)
    scenario = _scenario(
        "C",
        seed,
        _pair_grippers(draw, left, right, u, yaws),
        [{"name": "C1", "type": "clip", "position": list(seat), "yaw": slot, "push_force": push}],
        cable,
        [{"primitive": "A", "force": force}, {"primitive": "C", "clip": "C1"}],
    )
    return TrialScene("C", scenario, draw.inputs)


#: Scene builders by letter.
SCENES: dict[str, Callable[[int], TrialScene]] = {
    "A": scene_a,
    "B": scene_b,
    "C": scene_c,
    "D": scene_d,
    "E": scene_e,
    "F": scene_f,
    "G": scene_g,
    "H": scene_h,
    "I": scene_i,
}


def trial_scene(letter: str, seed: int) -> TrialScene:
    """The randomised scene of a trial of primitive ``letter`` with ``seed``.

    Raises:
        InvalidArgumentError: for a letter without a scene.
    """
    if letter not in LETTERS:
        raise InvalidArgumentError(f"no primitive letter {letter!r} (expected one of {LETTERS})")
    builder = SCENES.get(letter)
    if builder is None:
        raise InvalidArgumentError(f"no trial scene for primitive {letter} yet")
    return builder(seed)
