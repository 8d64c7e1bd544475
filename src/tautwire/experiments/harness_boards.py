"""Random harness boards: two cables, each from its anchor through 3-5 fixtures.

A board is drawn from a seed: each cable gets its own half of the board
(``y > 0`` for W1, held by the left gripper; ``y < 0`` for W2, right), an
anchor near the robot, and a route that walks away from it in steps of
``STEP`` m, turning by up to ``TURN`` at each fixture. Each route entry is
a clip (its slot along the cable within ``SLOT_SPREAD``, or with
probability ``ACROSS`` at any yaw: then only the parallel clip C can do it),
or a peg (on the side the route bends round it, with probability ``WIND``
wound once). The stiffness, mass, radius and length of each cable, the
gripper's start and where it holds the cable are drawn too. Everything
lies in the workspace; the planner then decides: a board it refuses (too
little cable, a sweep into another fixture, a slot it cannot reach, ...)
is redrawn from the same seed's stream, and the redraws are counted.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from tautwire.errors import InvalidArgumentError, TautwireError
from tautwire.model.vector3 import nearest_on_segment
from tautwire.scenario import Scenario
from tautwire.scenario.loader import scenario_from_data
from tautwire.scenario.route_problem import plan_scenario

#: Distance [m] between consecutive fixtures of a route (uniform).
STEP = (0.11, 0.16)
#: Largest turn [rad] of the route at a fixture.
TURN = math.radians(75.0)
#: Least turn [rad] of the route at a peg.
PEG_TURN = math.radians(45.0)
#: Largest angle [rad] between a clip's slot and the route into it.
SLOT_SPREAD = math.radians(12.0)
#: Probability that a clip's slot has any yaw.
ACROSS = 0.1
#: Probability that a route entry is a peg.
PEG = 0.4
#: Probability that a peg is wound once.
WIND = 0.3
#: Route entries per cable.
ENTRIES = (3, 5)
#: The box the fixtures are drawn in [m] (x, |y|).
BOX_X = (0.12, 0.70)
BOX_Y = (0.06, 0.52)
#: Least distance [m] between two fixtures (anchors included).
SPACING = 0.07
#: Least distance [m] between a fixture and a straight span of a route that
#: does not end at it (random board 360400295 had drawn its F2 10 mm from
#: its anchor A1, on the span A1 -> F1: F into F1 pressed the cable onto F2).
SPAN_CLEARANCE = 0.03
#: Least distance [m] between a fixture and the cable as it lies at the
#: start (straight from its anchor towards the gripper, sagging): a cable
#: laid across a clip slid under its base (random board 360400295's F1, 3 deg
#: off the route, then could not be pressed in).
START_CLEARANCE = 0.025
#: Most boards drawn for one seed before giving up. The planner accepts few
#: draws: 19 of 1327 over campaign seed 24's twenty board seeds (1.4 %;
#: 557 left the box or came too near a fixture, the rest it refused with a
#: reason), so 300 draws found none for one seed in twenty (816280147), a
#: board the campaign then counted as failed without running it. At 1000
#: that happens about once in 2 million boards.
MAX_DRAWS = 1000


@dataclass(frozen=True)
class DrawnBoard:
    """A board the planner accepts.

    Attributes:
        scenario: The board as a validated scenario (routes, no task).
        document: The same as plain data (a scenario file's content).
        redraws: Boards drawn from the seed's stream and refused before it.
        refusals: Why each refused board was refused (the planner's or the
            scenario check's one line), in order.
    """

    scenario: Scenario
    document: dict[str, Any]
    redraws: int
    refusals: tuple[str, ...]


def _off_span(point: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    """Horizontal distance [m] of ``point`` from the segment ``a`` -> ``b``."""
    flat = point[:2]
    return float(np.linalg.norm(flat - nearest_on_segment(flat, a[:2], b[:2])))


def _route(
    rng: np.random.Generator, side: float, taken: list[np.ndarray], prefix: str, names: list[str]
) -> tuple[np.ndarray, float, list[dict[str, Any]], list[dict[str, Any]]] | None:
    """One cable's anchor, last heading and route entries with their fixtures (or None).

    Each step tries up to 30 draws of its length and turn for a point inside
    the box and clear of the fixtures drawn before; a peg's turn is at least
    ``PEG_TURN`` (I must turn the cable round it far enough to find it).
    """
    anchor = np.array([rng.uniform(0.05, 0.12), side * rng.uniform(0.10, 0.22), 0.08])
    taken.append(anchor)
    spans: list[tuple[np.ndarray, np.ndarray]] = []
    heading = side * float(rng.uniform(-0.3, 0.5))  # away from the robot's centre line
    n = int(rng.integers(ENTRIES[0], ENTRIES[1] + 1))
    kinds = ["peg" if rng.random() < PEG else "clip" for _ in range(n)]
    fixtures: list[dict[str, Any]] = []
    entries: list[dict[str, Any]] = []
    here = anchor  # never changed in place: "is not here" below picks it out of taken
    turn = 0.0  # the turn at the fixture before the one being placed
    for k in range(n):
        for _ in range(30):
            step = float(rng.uniform(*STEP))
            point = here + step * np.array([math.cos(heading), math.sin(heading), 0.0])
            x, y = float(point[0]), float(point[1])
            inside = BOX_X[0] <= x <= BOX_X[1] and BOX_Y[0] <= side * y <= BOX_Y[1]
            clear = (
                all(float(np.linalg.norm(point[:2] - p[:2])) >= SPACING for p in taken)
                and all(_off_span(point, a, b) >= SPAN_CLEARANCE for a, b in spans[:-1])
                and all(_off_span(p, here, point) >= SPAN_CLEARANCE for p in taken if p is not here)
            )
            if inside and clear:
                break
            heading += float(rng.uniform(-0.5, 0.5))
        else:
            return None
        # the turn the route takes at this fixture, towards the next
        if kinds[k] == "peg":
            turn = math.copysign(float(rng.uniform(PEG_TURN, TURN)), float(rng.uniform(-1, 1)))
        else:
            turn = float(rng.uniform(-TURN, TURN))
        name = f"{prefix}{len(names) + 1}"
        names.append(name)
        taken.append(point)
        spans.append((here, point))
        if kinds[k] == "peg":
            base = [round(x, 4), round(y, 4), 0.05]
            fixtures.append(
                {"name": name, "type": "peg", "position": base, "radius": 0.006, "height": 0.06}
            )
            entry: dict[str, Any] = {"fixture": name, "side": "left" if turn >= 0.0 else "right"}
            if rng.random() < WIND:
                entry["wind"] = 1
            entries.append(entry)
        else:
            yaw = (
                float(rng.uniform(-math.pi / 2, math.pi / 2))
                if rng.random() < ACROSS
                else heading + float(rng.uniform(-SLOT_SPREAD, SLOT_SPREAD))
            )
            yaw = math.atan2(math.sin(yaw), math.cos(yaw))
            fixtures.append(
                {
                    "name": name,
                    "type": "clip",
                    "position": [round(x, 4), round(y, 4), 0.08],
                    "yaw": round(yaw, 4),
                    "push_force": round(float(rng.uniform(1.5, 3.0)), 2),
                }
            )
            entries.append({"fixture": name})
        here = point
        heading += turn
    return anchor, heading, fixtures, entries


def _cable(
    rng: np.random.Generator, name: str, anchor_name: str, arm: str, entries: list[dict[str, Any]]
) -> tuple[dict[str, Any], float]:
    held = float(rng.uniform(0.22, 0.32))
    cable = {
        "name": name,
        "length": round(0.45 + 0.16 * len(entries) + float(rng.uniform(0.0, 0.15)), 3),
        "mass_per_length": round(float(rng.uniform(0.02, 0.05)), 4),
        "stiffness": round(float(np.exp(rng.uniform(np.log(100.0), np.log(600.0)))), 1),
        "radius": round(float(rng.uniform(0.002, 0.003)), 4),
        "start": anchor_name,
        "held_by": {"arm": arm, "at": round(held, 3)},
        "route": entries,
    }
    return cable, held


def random_board(rng: np.random.Generator, name: str = "harness-board") -> dict[str, Any] | None:
    """One board drawn from ``rng`` as a scenario document (None: it left the box)."""
    taken: list[np.ndarray] = []
    fixtures: list[dict[str, Any]] = []
    cables: list[dict[str, Any]] = []
    grippers: dict[str, dict[str, Any]] = {}
    names: list[str] = []
    for cable_name, arm, side, anchor_name in (
        ("W1", "left", 1.0, "A1"),
        ("W2", "right", -1.0, "A2"),
    ):
        drawn = _route(rng, side, taken, "F", names)
        if drawn is None:
            return None
        anchor, _, own, entries = drawn
        fixtures.append(
            {
                "name": anchor_name,
                "type": "anchor",
                "position": [round(float(v), 4) for v in anchor],
            }
        )
        fixtures += own
        cable, held = _cable(rng, cable_name, anchor_name, arm, entries)
        cables.append(cable)
        first = np.array(own[0]["position"], dtype=float)
        towards = (first - anchor)[:2]
        towards /= max(float(np.linalg.norm(towards)), 1e-9)
        # the gripper starts short of taut, turned a little off the first
        # fixture, the cable clear of every fixture
        for _ in range(20):
            off = float(rng.uniform(-0.25, 0.25))
            c, s = math.cos(off), math.sin(off)
            d = np.array([c * towards[0] - s * towards[1], s * towards[0] + c * towards[1]])
            start = anchor[:2] + 0.85 * held * d
            ends = (np.append(anchor[:2], 0.0), np.append(start, 0.0))
            if all(
                _off_span(np.append(np.asarray(f["position"][:2], dtype=float), 0.0), *ends)
                >= START_CLEARANCE
                for f in fixtures
                if f["type"] != "anchor"
            ):
                break
        else:
            return None
        grippers[arm] = {"position": [round(float(start[0]), 4), round(float(start[1]), 4), 0.12]}
    return {
        "version": 1,
        "name": name,
        "seed": int(rng.integers(0, 2**31 - 1)),
        "robot": {
            "control_period": 0.004,
            "force_limit": 15.0,
            "sensor": {"arm": "both", "noise_force": 0.05, "noise_torque": 0.002},
            "grippers": grippers,
        },
        "board": {"fixtures": fixtures},
        "cables": cables,
    }


def draw_board(seed: int, name: str | None = None) -> DrawnBoard:
    """The first board of ``seed``'s stream that the scenario checks and the planner accept.

    Raises:
        InvalidArgumentError: no board of the first ``MAX_DRAWS`` was plannable.
    """
    rng = np.random.default_rng(seed)
    refusals: list[str] = []
    for _ in range(MAX_DRAWS):
        doc = random_board(rng, name or f"harness-board-{seed}")
        if doc is None:
            refusals.append("a route left the board's box or came too near a fixture")
            continue
        try:
            scenario = scenario_from_data(doc, source=f"<harness board {seed}>")
            plan_scenario(scenario)
        except TautwireError as exc:
            refusals.append(str(exc).splitlines()[0])
            continue
        return DrawnBoard(scenario, doc, len(refusals), tuple(refusals))
    raise InvalidArgumentError(
        f"no plannable harness board in {MAX_DRAWS} draws of seed {seed}; the last refusal: "
        f"{refusals[-1] if refusals else 'none'}"
    )
