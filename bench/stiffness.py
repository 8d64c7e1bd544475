"""Primitive D's stiffness estimate over the whole envelope: prints one JSON object.

    .venv/bin/python bench/stiffness.py --trials 24 --seed 0 --json
    .venv/bin/python bench/stiffness.py --trials 24 --profile   # where the error comes from

Each trial draws a single-fixture scene over the envelope of issue 10 (seeded):
cable length 0.15-1.0 m, stiffness k 10-1500 N/m log-uniform, slack 2-15 %
(the start distance from the gripper to the fixture is (1 - slack) times the
held length), force noise 0.03-0.1 N per axis, the fixture an anchor or a
peg (the cable then runs from an anchor round the peg to the gripper), a
tension set point of 1.5-4 N, the robot's stiffness guess the generic
100 N/m. It runs primitive D (single_arm_tension) closed loop in MuJoCo and
reports, per trial and as quantiles, k_hat at D's end against the true
stiffness of the gripper's edge (the cable's k scaled by the cable length
over the edge's rest length, k L / l: the whole cable for an anchor held at
its end), D's outcome, its simulated time and the true largest force.

``--profile`` also fits, offline over D's learning phase, the measured
tension against several lengths (the estimator's regressor, the true
gripper-fixture distance, the true cable length of the edge) to show which
part of the chain (world, regressor, estimator) loses the stiffness.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np

from tautwire.model.sag_length import sag_excess_length
from tautwire.primitives import SingleArmTension
from tautwire.scenario import Scenario
from tautwire.scenario.loader import scenario_from_data
from tautwire.scenario.workspace import WORKSPACE
from tautwire.sim.build import build_world, robot_of, truth_of
from tautwire.tasks import TickRecord, run_step
from tautwire.tasks.initial_model import initial_context

LENGTH_RANGE = (0.15, 1.0)  # m
STIFFNESS_RANGE = (10.0, 1500.0)  # N/m, log-uniform
SLACK_RANGE = (0.02, 0.15)
NOISE_RANGE = (0.03, 0.1)  # N
FORCE_RANGE = (1.5, 4.0)  # N
RHO = 0.03  # kg/m
PEG_RADIUS = 0.006  # m


@dataclass
class EnvelopeScene:
    """One drawn scene and what the bench scores it against."""

    scenario: Scenario
    inputs: dict[str, Any]
    edge_stiffness: float  # N/m, k L / l of the gripper's edge (its rest length l)
    fixture: str  # the fixture the gripper's edge bears on


def _inside(p: np.ndarray, margin: float = 0.05) -> bool:
    lo = np.asarray(WORKSPACE.lower) + margin
    hi = np.asarray(WORKSPACE.upper) - margin
    return bool(np.all(p >= lo) and np.all(p <= hi))


def _quaternion_of_yaw(u: np.ndarray) -> list[float]:
    yaw = math.atan2(float(u[1]), float(u[0]))
    return [math.cos(0.5 * yaw), 0.0, 0.0, math.sin(0.5 * yaw)]


def envelope_scene(seed: int, fixture: str | None = None) -> EnvelopeScene:
    """A seeded single-fixture D scene over the envelope (see the module docstring)."""
    rng = np.random.default_rng(seed)
    length = float(rng.uniform(*LENGTH_RANGE))
    k = float(np.exp(rng.uniform(*np.log(STIFFNESS_RANGE))))
    slack = float(rng.uniform(*SLACK_RANGE))
    noise = float(rng.uniform(*NOISE_RANGE))
    force = float(rng.uniform(*FORCE_RANGE))
    kind = fixture or ("anchor", "peg")[int(rng.integers(2))]
    fixtures: list[dict[str, Any]] = []
    for _ in range(1000):
        anchor = np.array(
            [rng.uniform(-0.1, 0.4), rng.uniform(-0.35, 0.35), rng.uniform(0.06, 0.14)]
        )
        yaw = float(rng.uniform(-math.pi, math.pi))
        if kind == "anchor":
            held = length  # the gripper holds the cable's end
            u = np.array([math.cos(yaw), math.sin(yaw), 0.0])
            gripper = anchor + (1.0 - slack) * held * u
            edge_rest = held
            via: list[str] = []
            fixtures = [{"name": "A1", "type": "anchor", "position": anchor.tolist()}]
            name = "A1"
        else:
            # anchor -> peg (a fraction of the cable), a bend of 30-90 deg, peg -> gripper
            first = float(rng.uniform(0.3, 0.5)) * length
            u1 = np.array([math.cos(yaw), math.sin(yaw), 0.0])
            peg_axis = anchor + first * u1
            peg_axis[2] = anchor[2] - 0.02
            bend = float(rng.uniform(math.radians(30), math.radians(90))) * (
                1.0 if rng.integers(2) else -1.0
            )
            u = np.array([math.cos(yaw + bend), math.sin(yaw + bend), 0.0])
            held = length
            edge_rest = length - first  # about: the route wraps a few mm of peg
            peg_point = peg_axis.copy()
            peg_point[2] = anchor[2]
            gripper = peg_point + (1.0 - slack) * edge_rest * u
            # the first part is drawn taut by D; keep it nearly so at the start
            fixtures = [
                {"name": "A1", "type": "anchor", "position": anchor.tolist()},
                {
                    "name": "P1",
                    "type": "peg",
                    "position": peg_axis.tolist(),
                    "radius": PEG_RADIUS,
                    "height": 0.06,
                },
            ]
            via = ["P1"]
            name = "P1"
            if not _inside(peg_axis):
                continue
        if _inside(gripper) and _inside(anchor):
            break
    else:  # pragma: no cover - the ranges always leave room
        raise RuntimeError("could not place the scene in the workspace")
    park = [0.7, -0.5 if gripper[1] > -0.1 else 0.5, 0.5]
    scenario = scenario_from_data(
        {
            "version": 1,
            "name": f"stiffness-{seed}",
            "seed": seed,
            "robot": {
                "force_limit": 15.0,
                "sensor": {"arm": "left", "noise_force": noise, "noise_torque": 0.002},
                "grippers": {
                    "left": {"position": gripper.tolist(), "orientation": _quaternion_of_yaw(u)},
                    "right": {"position": park},
                },
            },
            "board": {"fixtures": fixtures},
            "cables": [
                {
                    "name": "W1",
                    "length": length,
                    "mass_per_length": RHO,
                    "stiffness": k,
                    "radius": 0.0025,
                    "start": "A1",
                    "via": via,
                    "held_by": {"arm": "left", "at": held},
                }
            ],
            "task": [{"primitive": "D", "arm": "left", "force": force}],
        },
        source=f"<stiffness bench seed {seed}>",
    )
    inputs = {
        "seed": seed,
        "fixture": kind,
        "length": round(length, 4),
        "stiffness": round(k, 2),
        "slack": round(slack, 4),
        "noise": round(noise, 4),
        "force": round(force, 3),
    }
    return EnvelopeScene(scenario, inputs, k * length / edge_rest, name)


@dataclass
class Trace:
    """Per-tick series of one D run (learning phase only where marked)."""

    t: list[float] = field(default_factory=list)
    tension: list[float] = field(default_factory=list)  # measured, weight-compensated [N]
    regressor: list[float] = field(default_factory=list)  # the estimator's length [m]
    design_span: list[float] = field(default_factory=list)  # |p_g - design contact| + sag [m]
    learning: list[bool] = field(default_factory=list)
    k_hat: list[float] = field(default_factory=list)
    true_tension: list[float] = field(default_factory=list)  # the held segment's [N]
    true_distance: list[float] = field(default_factory=list)  # |p_g - fixture point| [m]
    true_edge_length: list[float] = field(default_factory=list)  # polyline, contact..grip [m]
    true_length: list[float] = field(default_factory=list)  # true distance + its sag excess [m]


def run_trial(
    scene: EnvelopeScene,
    profile: bool = False,
    duration: float | None = None,
    d_options: dict[str, float] | None = None,
) -> tuple[dict[str, Any], Trace]:
    """Run D on ``scene``; the trial's figures and (with ``profile``) its trace."""
    scenario = scene.scenario
    world = build_world(scenario)
    robot = robot_of(world)
    truth = truth_of(world)
    ctx = initial_context(scenario)
    step = scenario.task[0]
    force = float(step.params["force"])
    trace = Trace()
    design = np.asarray(ctx.fixtures[scene.fixture], dtype=float)
    arc = truth.arc_lengths("W1")
    held = int(np.argmin(np.abs(arc - float(scenario.cables[0].held_by[0].at))))
    rho = scenario.cables[0].mass_per_length

    def record(rec: TickRecord) -> None:
        state = ctx.estimator.state
        if state is None:
            return
        p_g = rec.observation.left.position
        trace.t.append(rec.observation.time)
        trace.tension.append(state.tension)
        chord = state.contact - p_g
        trace.regressor.append(state.span + sag_excess_length(chord, state.tension, rho))
        d_chord = design - p_g
        trace.design_span.append(
            float(np.linalg.norm(d_chord)) + sag_excess_length(d_chord, state.tension, rho)
        )
        trace.learning.append(ctx.estimator.learn_elasticity and state.taut)
        trace.k_hat.append(ctx.estimator.elasticity.k_hat)
        tensions = truth.tensions("W1")
        trace.true_tension.append(float(tensions[held - 1]))
        contact = truth.contact(scene.fixture)
        point = design if contact is None else contact.point
        trace.true_distance.append(float(np.linalg.norm(point - p_g)))
        true_chord = point - p_g
        trace.true_length.append(
            trace.true_distance[-1] + sag_excess_length(true_chord, trace.true_tension[-1], rho)
        )
        poly = truth.polyline("W1")
        j = int(np.argmin(np.linalg.norm(poly[:held] - point, axis=1)))
        trace.true_edge_length.append(
            float(np.sum(np.linalg.norm(np.diff(poly[j : held + 1], axis=0), axis=1)))
        )

    primitive = SingleArmTension("left", force, duration=duration, **(d_options or {}))
    t0 = time.perf_counter()
    report = run_step(robot, primitive, ctx, on_tick=record)
    wall = time.perf_counter() - t0
    k_hat = ctx.estimator.elasticity.k_hat
    k_world = world_stiffness(trace)
    edge_k = scene.edge_stiffness
    if scene.fixture != "A1":  # the peg: the edge starts where the cable meets it now
        edge_k = (
            float(scene.inputs["stiffness"])
            * float(arc[-1])
            / (float(arc[held]) - _arc_at(truth.polyline("W1"), arc, design))
        )
    result = {
        **scene.inputs,
        "edge_stiffness": round(edge_k, 2),
        "k_hat": round(k_hat, 2),
        "ratio": round(k_hat / edge_k, 4),
        "ratio_to_cable_k": round(k_hat / float(scene.inputs["stiffness"]), 4),
        "k_world": None if k_world is None else round(k_world, 2),
        "ratio_to_world": None if k_world is None else round(k_hat / k_world, 4),
        "learn_time": primitive.learn_time,
        "k_std": round(ctx.estimator.elasticity.std, 2),
        "outcome": report.outcome,
        "cause": report.cause,
        "sim_time": round(report.sim_time, 3),
        "true_max_force": round(world.max_force, 3),
        "wall_time": round(wall, 2),
    }
    return result, trace


def _arc_at(poly: np.ndarray, arc: np.ndarray, axis_point: np.ndarray) -> float:
    """Rest arc length [m] of the cable's point nearest (horizontally) to a peg's axis."""
    best, best_arc = math.inf, 0.0
    for i in range(len(poly) - 1):
        a, b = poly[i, :2], poly[i + 1, :2]
        ab = b - a
        t = float(np.clip(np.dot(axis_point[:2] - a, ab) / max(float(ab @ ab), 1e-18), 0.0, 1.0))
        d = float(np.linalg.norm(a + t * ab - axis_point[:2]))
        if d < best:
            best, best_arc = d, float(arc[i] + t * (arc[i + 1] - arc[i]))
    return best_arc


def _slope(x: np.ndarray, y: np.ndarray) -> float:
    """Least-squares slope of y on x (with an intercept)."""
    if x.size < 3 or float(np.ptp(x)) == 0.0:
        return float("nan")
    return float(np.polyfit(x, y, 1)[0])


def _window_means(v: np.ndarray, n: int = 50) -> np.ndarray:
    m = v.size // n
    return v[: m * n].reshape(m, n).mean(axis=1)


def world_stiffness(trace: Trace) -> float | None:
    """The stiffness [N/m] the simulated world presents to the gripper over D's learning phase.

    Slope of the true tension of the held segment against the true distance
    from the gripper to the fixture's contact plus that chord's sag excess
    (the closed form, at the true tension), with a linear drift in time,
    over 0.2 s means of the second half of the learning phase: the spring
    the gripper pulls against, as the simulator has it (for a peg, whatever
    friction lets slide).
    """
    on = np.asarray(trace.learning)
    if on.sum() < 200:
        return None
    f = _window_means(np.asarray(trace.true_tension)[on])
    x = _window_means(np.asarray(trace.true_length)[on])
    t = _window_means(np.asarray(trace.t)[on])
    late = slice(len(f) // 2, None)
    if f[late].size < 4:
        return None
    # f = k x + c + d t: a slow creep of the length (a cable settling round a peg) is not k
    a = np.column_stack([x[late] - x[late].mean(), np.ones(f[late].size), t[late] - t[late].mean()])
    k = float(np.linalg.lstsq(a, f[late], rcond=None)[0][0])
    return k if math.isfinite(k) and k > 0.0 else None


def profile_fits(trace: Trace, edge_stiffness: float) -> dict[str, float]:
    """Slopes dT/dl over D's learning phase, as fractions of the edge's true stiffness."""
    on = np.asarray(trace.learning)
    if on.sum() < 100:
        return {}
    pick = {
        name: np.asarray(getattr(trace, name))[on] for name in asdict(trace) if name != "learning"
    }
    w = {name: _window_means(v) for name, v in pick.items()}
    fits = {
        # the world: true tension against the true cable length of the edge (k L / l itself)
        "true_T_vs_true_edge_length": _slope(w["true_edge_length"], w["true_tension"]),
        # the world as the robot can see it: against the gripper-fixture distance
        "true_T_vs_true_distance": _slope(w["true_distance"], w["true_tension"]),
        "measured_T_vs_true_distance": _slope(w["true_distance"], w["tension"]),
        # the regressor: the estimator's length, and the design point's span
        "measured_T_vs_regressor": _slope(w["regressor"], w["tension"]),
        "measured_T_vs_design_span": _slope(w["design_span"], w["tension"]),
        "true_T_vs_regressor": _slope(w["regressor"], w["true_tension"]),
    }
    late = slice(len(w["t"]) // 2, None)
    fits["late_true_T_vs_true_distance"] = _slope(w["true_distance"][late], w["true_tension"][late])
    fits["late_measured_T_vs_regressor"] = _slope(w["regressor"][late], w["tension"][late])
    out = {name: round(v / edge_stiffness, 4) for name, v in fits.items()}
    out["regressor_minus_distance_std_um"] = round(
        float(np.std(w["regressor"] - w["true_distance"])) * 1e6, 2
    )
    out["distance_swing_um"] = round(float(np.ptp(w["true_distance"])) * 1e6, 2)
    out["learning_time"] = round(float(pick["t"][-1] - pick["t"][0]), 3)
    return out


def _quantiles(values: list[float]) -> dict[str, float]:
    if not values:
        return {}
    a = np.asarray(values)
    return {
        q: round(float(np.quantile(a, p)), 4) for q, p in (("min", 0), ("median", 0.5), ("max", 1))
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--trials", type=int, default=24)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--fixture", choices=("anchor", "peg"), default=None)
    parser.add_argument("--profile", action="store_true")
    parser.add_argument("--duration", type=float, default=None, help="run D this long [s]")
    parser.add_argument(
        "--option",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="a keyword argument of SingleArmTension (repeatable), e.g. excitation_period=1",
    )
    parser.add_argument("--json", action="store_true", help="only the JSON object")
    args = parser.parse_args(argv)
    options = {k: float(v) for k, v in (o.split("=", 1) for o in args.option)}
    rows = []
    for i in range(args.trials):
        scene = envelope_scene(args.seed + i, args.fixture)
        row, trace = run_trial(scene, args.profile, args.duration, options)
        if args.profile:
            row["profile"] = profile_fits(trace, scene.edge_stiffness)
        rows.append(row)
        if not args.json:
            print(json.dumps(row), file=sys.stderr)
    summary: dict[str, Any] = {"trials": len(rows)}
    for kind in ("anchor", "peg"):
        some = [r for r in rows if r["fixture"] == kind]
        if not some:
            continue
        ratios = [r["ratio"] for r in some]
        world = [r["ratio_to_world"] for r in some if r["ratio_to_world"] is not None]
        summary[kind] = {
            "trials": len(some),
            "within_10_percent_of_edge_k": sum(abs(v - 1.0) <= 0.1 for v in ratios),
            "ratio_to_edge_k": _quantiles(ratios),
            "ratio_to_cable_k": _quantiles([r["ratio_to_cable_k"] for r in some]),
            "within_10_percent_of_world_k": sum(abs(v - 1.0) <= 0.1 for v in world),
            "ratio_to_world_k": _quantiles(world),
            "world_k_to_edge_k": _quantiles(
                [r["k_world"] / r["edge_stiffness"] for r in some if r["k_world"] is not None]
            ),
        }
    summary.update(
        {
            "successes": sum(r["outcome"] == "success" for r in rows),
            "sim_time": _quantiles([r["sim_time"] for r in rows]),
            "true_max_force": _quantiles([r["true_max_force"] for r in rows]),
            "rows": rows,
        }
    )
    print(json.dumps(summary, indent=None if args.json else 2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
