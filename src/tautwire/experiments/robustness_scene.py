"""Randomised single-fixture scenes over the whole envelope, and one random fault.

The robustness campaign (:mod:`tautwire.experiments.robustness`) draws each
trial's scene from its seed with :func:`draw_scene`: one fixture the robot
must find by force alone, a cable from it to the left gripper, the task
D (``single_arm_tension``) then I (``rotate_around_feature_point`` about the
fixture). The envelope (issue 10):

- the fixture: an anchor, or a peg (radius 4-10 mm) that the cable bears on
  with its far end anchored behind it;
- the cable: 0.15-1.0 m long (held at its end), stiffness 10-1500 N/m
  log-uniform, 30 g/m, radius 2.5 mm;
- the gripper's start yaw uniform over the full circle, independent of the
  cable's direction (tool x may point at the fixture);
- the rotation: 0.8-6.3 rad of either sign about an anchor; about a peg at
  most what keeps the cable wrapped round it by 0.25 to pi - 0.25 rad
  (0.8-2.6 rad): wound further the cable would cross itself, which the
  simulated cable (no self-collision) cannot do faithfully;
- slack 2-15 %: the start distance along the route is (1 - slack) times the
  held length, measured along the route the simulator lays (round the peg
  at its radius plus the cable's, and into the fingers along the tool's
  x-axis, :mod:`tautwire.sim.route`): a straight-line distance would let a
  sideways grasp or a wide bend round a peg start the cable stretched;
- force noise 0.03-0.1 N per axis (torque noise 0.04 m times it);
- tension set point 1.5-4 N.

Every scene must be doable: the start, and the whole circle arc the gripper
sweeps at the taut radius (held length plus the stretch at the set point),
stay inside the robot's workspace with a 5 cm margin and 5 cm above the
board. Draws that cannot be placed are redrawn from the same generator
(``redraws`` in the inputs): long cables meet small angles more often than
short ones.

:func:`draw_fault` draws one fault of SCENARIO.md's ``faults:`` inside the
run: its time is a random fraction (0.1-0.9) of the clean run's duration.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.scenario import Scenario
from tautwire.scenario.loader import scenario_from_data
from tautwire.scenario.workspace import WORKSPACE
from tautwire.sim.options import SimOptions

FloatArray = NDArray[np.float64]

LENGTH_RANGE = (0.15, 1.0)  # m, uniform
STIFFNESS_RANGE = (10.0, 1500.0)  # N/m, log-uniform
ANGLE_RANGE = (0.8, 6.3)  # rad, either sign
SLACK_RANGE = (0.02, 0.15)
NOISE_RANGE = (0.03, 0.1)  # N
PEG_RADIUS_RANGE = (0.004, 0.010)  # m
FORCE_RANGE = (1.5, 4.0)  # N
#: Torque noise [N m] per N of force noise (0.002 N m at 0.05 N, as the project's scenes).
TORQUE_NOISE_ARM = 0.04
#: The wrap [rad] a peg keeps the cable bent by, at least and at most (no self-crossing).
WRAP_RANGE = (0.25, math.pi - 0.25)
MASS_PER_LENGTH = 0.03  # kg/m
RADIUS = 0.0025  # m
FORCE_LIMIT = 15.0  # N
SPEED = 0.5  # rad/s, primitive I
MARGIN = 0.05  # m, from the workspace's faces
#: Most redraws of a scene's cable and angle before giving up.
MAX_REDRAWS = 200
MIN_HEIGHT = 0.05  # m, least gripper height over the board
#: How far [m] the simulator lays a held cable along the tool's x-axis into the fingers.
PAD_EXIT = SimOptions().pad_exit
#: Fixture types the campaign draws.
FIXTURE_TYPES: tuple[str, ...] = ("anchor", "peg")
#: Fault types the campaign draws (a freeze is short, <= 50 ms, or long, > 0.1 s).
FAULT_TYPES: tuple[str, ...] = (
    "spike",
    "nan",
    "freeze_short",
    "freeze_long",
    "bias_drift",
    "slip",
    "robot_error",
)


@dataclass(frozen=True)
class RobustnessScene:
    """A randomised single-fixture scene.

    Attributes:
        data: The scenario as plain data (add ``faults`` to it for a fault run).
        inputs: The randomised inputs, flat and JSON-ready.
        fixture: Name of the fixture the robot must find.
        fixture_type: ``"anchor"`` or ``"peg"``.
    """

    data: dict[str, Any]
    inputs: dict[str, float | str]
    fixture: str
    fixture_type: str

    def scenario(self, faults: list[dict[str, Any]] | None = None) -> Scenario:
        """The validated scenario, with ``faults`` if given."""
        data = dict(self.data)
        if faults:
            data["faults"] = faults
        return scenario_from_data(data, source=f"<robustness scene {data['name']}>")


def _inside(p: FloatArray) -> bool:
    lo = np.asarray(WORKSPACE.lower) + MARGIN
    hi = np.asarray(WORKSPACE.upper) - MARGIN
    return bool(np.all(p >= lo) and np.all(p <= hi) and p[2] >= MIN_HEIGHT)


def _arc_inside(centre: FloatArray, radius: float, start: float, angle: float, z: float) -> bool:
    """Whether the horizontal arc about ``centre`` from azimuth ``start`` by ``angle`` fits."""
    n = max(8, int(abs(angle) / 0.05))
    a = np.linspace(start, start + angle, n + 1)
    lo = np.asarray(WORKSPACE.lower) + MARGIN
    hi = np.asarray(WORKSPACE.upper) - MARGIN
    x = centre[0] + radius * np.cos(a)
    y = centre[1] + radius * np.sin(a)
    inside = (x >= lo[0]) & (x <= hi[0]) & (y >= lo[1]) & (y <= hi[1])
    return bool(np.all(inside) and lo[2] <= z <= hi[2] and z >= MIN_HEIGHT)


def _yaw_quaternion(yaw: float) -> list[float]:
    return [math.cos(0.5 * yaw), 0.0, 0.0, math.sin(0.5 * yaw)]


class SceneDraws:
    """Random draws of one scene (robustness scene, Table I trial), remembered as its inputs."""

    def __init__(self, seed: int) -> None:
        self.rng = np.random.default_rng(seed)
        self.inputs: dict[str, float | str] = {}

    def uniform(self, name: str, low: float, high: float) -> float:
        """A uniform draw in [low, high), recorded as ``name``."""
        value = float(self.rng.uniform(low, high))
        self.inputs[name] = round(value, 6)
        return value

    def log_uniform(self, name: str, low: float, high: float) -> float:
        """A log-uniform draw in [low, high), recorded as ``name``."""
        value = float(np.exp(self.rng.uniform(math.log(low), math.log(high))))
        self.inputs[name] = round(value, 6)
        return value

    def choice(self, name: str, options: tuple[str, ...]) -> str:
        """One of ``options``, uniformly, recorded as ``name``."""
        value = options[int(self.rng.integers(len(options)))]
        self.inputs[name] = value
        return value

    def point(self, name: str, p: FloatArray) -> list[float]:
        """Record a point [m] as ``name_x``, ``name_y``, ``name_z``; return it as a list."""
        for axis, v in zip("xyz", p, strict=True):
            self.inputs[f"{name}_{axis}"] = round(float(v), 6)
        return [float(v) for v in p]


def _horizontal(azimuth: float) -> FloatArray:
    return np.array([math.cos(azimuth), math.sin(azimuth), 0.0])


def _entry(gripper: FloatArray, tool_yaw: float, towards: FloatArray) -> FloatArray:
    """Where the laid route enters the fingers: ``PAD_EXIT`` along tool +-x, towards ``towards``."""
    x_tool = _horizontal(tool_yaw)
    sign = -1.0 if float(x_tool @ (towards - gripper)) > 0.0 else 1.0
    out: FloatArray = gripper - sign * PAD_EXIT * x_tool
    return out


def anchor_route_length(anchor: FloatArray, gripper: FloatArray, tool_yaw: float) -> float:
    """Length [m] of the route the simulator lays from an anchor to a held end.

    Straight to the point where the route enters the fingers, then along
    the tool's x-axis to the tool centre point (``tautwire.sim.route``).
    """
    entry = _entry(gripper, tool_yaw, anchor)
    return float(np.linalg.norm(entry - anchor)) + PAD_EXIT


def _tangent(point: FloatArray, centre: FloatArray, rho: float, side: FloatArray) -> FloatArray:
    """The horizontal tangent point on the circle (centre, rho) from ``point``, on ``side``."""
    rel = point[:2] - centre[:2]
    dist = float(np.linalg.norm(rel))
    if dist <= rho:
        return np.array([centre[0] + rho * side[0], centre[1] + rho * side[1]])
    beta = math.acos(rho / dist)
    u = rel / dist
    best, best_dot = u, -math.inf
    for b in (beta, -beta):
        c, s = math.cos(b), math.sin(b)
        cand = np.array([c * u[0] - s * u[1], s * u[0] + c * u[1]])
        if float(cand @ side) > best_dot:
            best, best_dot = cand, float(cand @ side)
    out: FloatArray = centre[:2] + rho * best
    return out


def peg_route_length(
    anchor: FloatArray, axis: FloatArray, rho: float, gripper: FloatArray, tool_yaw: float
) -> float:
    """Length [m] of the route the simulator lays from an anchor round a peg to a held end.

    Anchor, the tangent to the circle of radius ``rho`` (peg + cable radius)
    about the peg's ``axis`` point on the side away from the bend's inside,
    the arc, the tangent towards the gripper, then into the fingers as
    :func:`anchor_route_length` (``tautwire.sim.route``); the arc lies half
    way between the anchor's and the gripper's heights.
    """
    ua = (anchor - axis)[:2] / float(np.linalg.norm((anchor - axis)[:2]))
    ub = (gripper - axis)[:2] / float(np.linalg.norm((gripper - axis)[:2]))
    inner = ua + ub
    side = -inner / float(np.linalg.norm(inner))
    t1 = _tangent(anchor, axis, rho, side)
    t2 = _tangent(gripper, axis, rho, side)
    a1 = math.atan2(t1[1] - axis[1], t1[0] - axis[0])
    a2 = math.atan2(t2[1] - axis[1], t2[0] - axis[0])
    ao = math.atan2(side[1], side[0])
    d12 = (a2 - a1) % (2.0 * math.pi)
    sweep = d12 if (ao - a1) % (2.0 * math.pi) <= d12 else 2.0 * math.pi - d12
    z = 0.5 * (float(anchor[2]) + float(gripper[2]))
    p1, p2 = np.array([t1[0], t1[1], z]), np.array([t2[0], t2[1], z])
    entry = _entry(gripper, tool_yaw, p2)
    return float(np.linalg.norm(p1 - anchor) + rho * sweep + np.linalg.norm(entry - p2) + PAD_EXIT)


def _reach(route: Callable[[float], float], target: float, low: float, high: float) -> float | None:
    """The distance r in [low, high] at which the increasing ``route(r)`` is ``target``, or None."""
    if route(low) > target or route(high) < target:
        return None
    for _ in range(32):  # to 0.3 um over 1.2 m
        mid = 0.5 * (low + high)
        if route(mid) < target:
            low = mid
        else:
            high = mid
    return 0.5 * (low + high)


def _anchor_route(
    anchor: FloatArray, u: FloatArray, dz: float, tool_yaw: float
) -> Callable[[float], float]:
    """The laid route's length [m] with the gripper at horizontal distance r along ``u``."""

    def route(r: float) -> float:
        return anchor_route_length(anchor, anchor + r * u + np.array([0.0, 0.0, dz]), tool_yaw)

    return route


def _peg_route(
    anchor: FloatArray, axis: FloatArray, rho: float, u: FloatArray, dz: float, tool_yaw: float
) -> Callable[[float], float]:
    """The laid route's length [m] with the gripper at distance r from the peg along ``u``."""

    def route(r: float) -> float:
        gripper = axis + r * u + np.array([0.0, 0.0, dz])
        return peg_route_length(anchor, axis, rho, gripper, tool_yaw)

    return route


def _place_anchor(
    d: SceneDraws, length: float, angle: float, stretch: float, tool_yaw: float
) -> dict[str, Any] | None:
    """Anchor, gripper start, and the fixtures, or None if this draw does not fit.

    The gripper's distance is the one at which the route the simulator lays
    is (1 - slack) times the cable.
    """
    slack = d.inputs["slack"]
    assert isinstance(slack, float)
    target = (1.0 - slack) * length
    for _ in range(400):
        anchor = np.array(
            [
                d.rng.uniform(WORKSPACE.lower[0] + MARGIN, WORKSPACE.upper[0] - MARGIN),
                d.rng.uniform(WORKSPACE.lower[1] + MARGIN, WORKSPACE.upper[1] - MARGIN),
                d.rng.uniform(0.06, 0.14),
            ]
        )
        azimuth = float(d.rng.uniform(-math.pi, math.pi))
        dz = float(d.rng.uniform(-0.02, 0.03))
        u = _horizontal(azimuth)
        # the laid route is at most 2 PAD_EXIT longer than the straight line: check the
        # circle at the largest radius it can have first (cheap), then solve for r
        if not _arc_inside(anchor, length + stretch + PAD_EXIT, azimuth, angle, anchor[2] + dz):
            continue
        r = _reach(_anchor_route(anchor, u, dz, tool_yaw), target, 0.05, 1.2)
        if r is None:
            continue
        gripper = anchor + r * u + np.array([0.0, 0.0, dz])
        taut = r + slack * length + stretch + PAD_EXIT
        if _inside(gripper) and _arc_inside(anchor, taut, azimuth, angle, float(gripper[2])):
            return {
                "anchor": anchor,
                "gripper": gripper,
                "azimuth": azimuth,
                "fixtures": [
                    {"name": "A1", "type": "anchor", "position": [float(v) for v in anchor]}
                ],
                "via": [],
            }
    return None


def _place_peg(
    d: SceneDraws, length: float, angle: float, stretch: float, tool_yaw: float
) -> dict[str, Any] | None:
    """Peg, anchor behind it, gripper start, or None if this draw does not fit.

    The cable comes from the anchor along u_in, bends round the peg by
    ``bend`` (positive: to the left, about +z) and leaves towards the
    gripper. Turning the gripper about the peg by ``angle`` changes the bend
    by ``angle``; both the start and the end bend lie in :data:`WRAP_RANGE`.
    The gripper's distance is the one at which the route the simulator lays
    is (1 - slack) times the cable.
    """
    slack = d.inputs["slack"]
    radius = d.inputs["peg_radius"]
    assert isinstance(slack, float) and isinstance(radius, float)
    rho = radius + RADIUS + 1e-4
    target = (1.0 - slack) * length
    sense = math.copysign(1.0, angle)
    w_lo, w_hi = WRAP_RANGE
    for _ in range(400):
        z = float(d.rng.uniform(0.06, 0.14))
        peg = np.array(
            [
                d.rng.uniform(WORKSPACE.lower[0] + MARGIN, WORKSPACE.upper[0] - MARGIN),
                d.rng.uniform(WORKSPACE.lower[1] + MARGIN, WORKSPACE.upper[1] - MARGIN),
                0.0,
            ]
        )
        winds = bool(d.rng.uniform() < 0.5)
        if winds:  # the rotation winds the cable on: the bend has the angle's sign
            bend = sense * float(d.rng.uniform(w_lo, w_hi - abs(angle)))
        else:  # the rotation unwinds it
            bend = -sense * float(d.rng.uniform(w_lo + abs(angle), w_hi))
        u_in = float(d.rng.uniform(-math.pi, math.pi))
        behind = float(d.rng.uniform(0.04, min(0.3, 0.5 * length)))
        axis = np.array([peg[0], peg[1], z])
        anchor = axis - behind * _horizontal(u_in)
        out = u_in + bend
        dz = float(d.rng.uniform(-0.01, 0.02))
        u = _horizontal(out)
        widest = length - behind + stretch + PAD_EXIT + rho * abs(angle)
        if not (_inside(anchor) and _arc_inside(axis, widest, out, angle, z + dz)):
            continue
        r = _reach(_peg_route(anchor, axis, rho, u, dz, tool_yaw), target, 0.07, 1.2)
        if r is None:
            continue
        gripper = axis + r * u + np.array([0.0, 0.0, dz])
        # taut, and with the wrap the rotation may unwind
        taut = r + slack * length + stretch + PAD_EXIT + rho * abs(angle)
        height = z + float(d.rng.uniform(0.03, 0.06))
        if (
            _inside(gripper)
            and _inside(anchor)
            and peg[2] + height <= WORKSPACE.upper[2] - MARGIN
            and _arc_inside(axis, taut, out, angle, float(gripper[2]))
        ):
            d.inputs["bend"] = round(bend, 6)
            d.inputs["winds"] = "on" if winds else "off"
            d.inputs["behind"] = round(behind, 6)
            d.point("anchor", anchor)
            return {
                "anchor": anchor,
                "gripper": gripper,
                "azimuth": out,
                "fixtures": [
                    {"name": "A1", "type": "anchor", "position": [float(v) for v in anchor]},
                    {
                        "name": "P1",
                        "type": "peg",
                        "position": [float(v) for v in peg],
                        "radius": radius,
                        "height": height,
                    },
                ],
                "via": ["P1"],
            }
    return None


def draw_scene(seed: int, fixture_type: str | None = None) -> RobustnessScene:
    """The randomised scene of trial ``seed`` (see the module docstring).

    Args:
        seed: The trial's seed.
        fixture_type: ``"anchor"`` or ``"peg"`` to force one; None draws it.

    Raises:
        InvalidArgumentError: for an unknown fixture type, or when no
            placement fits after many redraws (not met in practice).
    """
    if fixture_type is not None and fixture_type not in FIXTURE_TYPES:
        raise InvalidArgumentError(
            f"unknown fixture type {fixture_type!r} (expected one of {', '.join(FIXTURE_TYPES)})"
        )
    d = SceneDraws(seed)
    kind = d.choice("fixture", FIXTURE_TYPES) if fixture_type is None else fixture_type
    d.inputs["fixture"] = kind
    place: dict[str, Any] | None = None
    redraws = -1
    while place is None:
        redraws += 1
        if redraws >= MAX_REDRAWS:
            raise InvalidArgumentError(f"no placement of a {kind} scene fits (seed {seed})")
        length = d.uniform("length", *LENGTH_RANGE)
        stiffness = d.log_uniform("stiffness", *STIFFNESS_RANGE)
        force = d.uniform("force", *FORCE_RANGE)
        d.uniform("slack", *SLACK_RANGE)
        noise = d.uniform("noise_force", *NOISE_RANGE)
        sense = 1.0 if d.choice("sense", ("positive", "negative")) == "positive" else -1.0
        if kind == "peg":
            d.uniform("peg_radius", *PEG_RADIUS_RANGE)
            top = min(ANGLE_RANGE[1], WRAP_RANGE[1] - WRAP_RANGE[0])
            angle = sense * d.uniform("angle_magnitude", ANGLE_RANGE[0], top)
        else:
            angle = sense * d.uniform("angle_magnitude", *ANGLE_RANGE)
        d.inputs["angle"] = round(angle, 6)
        tool_yaw = d.uniform("tool_yaw", -math.pi, math.pi)
        stretch = force / stiffness
        place = (_place_peg if kind == "peg" else _place_anchor)(
            d, length, angle, stretch, tool_yaw
        )
    d.inputs["redraws"] = redraws
    gripper = place["gripper"]
    d.point("gripper", gripper)
    if kind == "anchor":
        d.point("anchor", place["anchor"])
    # the tool's x-axis against the cable's direction (fixture -> gripper):
    # 0 along it (the project's own scenes), +-pi pointing at the fixture
    relative = (tool_yaw - place["azimuth"] + math.pi) % (2.0 * math.pi) - math.pi
    d.inputs["tool_yaw_to_cable"] = round(relative, 6)
    fixture = "P1" if kind == "peg" else "A1"
    data: dict[str, Any] = {
        "version": 1,
        "name": f"robustness-{kind}-{seed}",
        "seed": seed,
        "robot": {
            "control_period": 0.004,
            "force_limit": FORCE_LIMIT,
            "sensor": {
                "arm": "left",
                "noise_force": noise,
                "noise_torque": TORQUE_NOISE_ARM * noise,
            },
            "grippers": {
                "left": {
                    "position": [float(v) for v in gripper],
                    "orientation": _yaw_quaternion(tool_yaw),
                },
                "right": {"position": [0.7, -0.5 if gripper[1] > -0.1 else 0.5, 0.5]},
            },
        },
        "board": {"fixtures": place["fixtures"]},
        "cables": [
            {
                "name": "W1",
                "length": length,
                "mass_per_length": MASS_PER_LENGTH,
                "stiffness": stiffness,
                "radius": RADIUS,
                "start": "A1",
                "via": place["via"],
                "held_by": {"arm": "left", "at": length},
            }
        ],
        "task": [
            {"primitive": "D", "arm": "left", "force": force},
            {"primitive": "I", "arm": "left", "angle": angle, "speed": SPEED, "about": fixture},
        ],
    }
    return RobustnessScene(data, d.inputs, fixture, kind)


def draw_fault(seed: int, run_time: float, kind: str | None = None) -> dict[str, Any]:
    """One random fault (a ``faults:`` entry of SCENARIO.md) inside a run of ``run_time`` [s].

    The fault's own generator is seeded from ``seed`` apart from the scene's,
    so the scene does not depend on it. Types are drawn uniformly from
    :data:`FAULT_TYPES`; ``at`` uniformly in 10-90 % of ``run_time``.

    - spike: 10-40 N in a random direction, one sample;
    - nan: one sample;
    - freeze_short: 4-50 ms; freeze_long: 0.15-2 s;
    - bias_drift: a ramp of 0.5-10 s to 0.2-1 N in a random direction;
    - slip: the left grip lost for 0.2-1 s;
    - robot_error: one failed ``act()``.

    Returns:
        The entry, plus the key ``kind`` (the type as the campaign names it,
        e.g. ``freeze_short``), which must be removed before validation.
    """
    rng = np.random.default_rng([seed, 1])
    chosen = FAULT_TYPES[int(rng.integers(len(FAULT_TYPES)))] if kind is None else kind
    if chosen not in FAULT_TYPES:
        raise InvalidArgumentError(
            f"unknown fault type {chosen!r} (expected one of {', '.join(FAULT_TYPES)})"
        )
    at = float(rng.uniform(0.1, 0.9)) * max(run_time, 0.5)

    def direction() -> list[float]:
        v = rng.normal(size=3)
        return [float(x) for x in v / np.linalg.norm(v)]

    fault: dict[str, Any]
    if chosen == "spike":
        magnitude = float(rng.uniform(10.0, 40.0))
        fault = {"type": "spike", "at": at, "force": [magnitude * x for x in direction()]}
    elif chosen == "nan":
        fault = {"type": "nan", "at": at}
    elif chosen == "freeze_short":
        fault = {"type": "freeze", "at": at, "duration": float(rng.uniform(0.004, 0.05))}
    elif chosen == "freeze_long":
        fault = {"type": "freeze", "at": at, "duration": float(rng.uniform(0.15, 2.0))}
    elif chosen == "bias_drift":
        magnitude = float(rng.uniform(0.2, 1.0))
        fault = {
            "type": "bias_drift",
            "at": at,
            "duration": float(rng.uniform(0.5, 10.0)),
            "force": [magnitude * x for x in direction()],
        }
    elif chosen == "slip":
        fault = {"type": "slip", "at": at, "duration": float(rng.uniform(0.2, 1.0)), "arm": "left"}
    else:
        fault = {"type": "robot_error", "at": at}
    fault["kind"] = chosen
    return fault
