"""Run a scenario in the simulated world and score it against the ground truth.

The primitives see only the robot's observations; the ground truth is read
after each step, for the result's ``truth`` fields only.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.experiments.truth import (
    PointDeviation,
    RunAudit,
    TruthCheck,
    deviation_summary,
    point_deviations,
    route_truth,
    shape_deviations,
    true_contacts,
)
from tautwire.model import PathGraph
from tautwire.primitives import PrimitiveContext
from tautwire.scenario import Scenario
from tautwire.scenario.models import TaskStep as ScenarioStep
from tautwire.sim.build import build_world, robot_of, truth_of
from tautwire.sim.ground_truth import GroundTruth, closest_on_polyline
from tautwire.sim.world import SimWorld
from tautwire.tasks import StepReport, TickRecord
from tautwire.tasks.cable_models import CableModels, StepModel
from tautwire.tasks.initial_model import initial_models
from tautwire.tasks.scenario_guard import scenario_guard
from tautwire.tasks.task_runner import TaskHooks, TaskStep, run_task

FloatArray = NDArray[np.float64]


@dataclass
class ContactScore:
    """An estimated contact against the truth (the result's ``contacts``)."""

    fixture: str
    estimate: list[float]
    truth: list[float] | None
    error: float | None
    std: list[float] | None


@dataclass
class RunResult:
    """The result of ``tautwire run`` (SCENARIO.md, "Result")."""

    scenario: str
    seed: int
    success: bool
    steps: list[dict[str, Any]]
    contacts: list[ContactScore]
    stiffness: dict[str, float | None]
    model_error: dict[str, float] | None
    max_force: float
    sim_time: float
    wall_time: float
    files: dict[str, str] = field(default_factory=dict)
    false_successes: int = 0
    true_max_force: float = 0.0
    contact_consistency: dict[str, Any] = field(default_factory=dict)
    cables: list[dict[str, Any]] = field(default_factory=list)
    shape_error: dict[str, float] | None = None
    audit: RunAudit | None = field(default=None, repr=False)
    models: CableModels | None = field(default=None, repr=False)

    def to_dict(self) -> dict[str, Any]:
        """The result as JSON-ready data (without the ``audit`` and the ``models``)."""
        data = asdict(replace(self, audit=None, models=None))
        data.pop("audit")
        data.pop("models")
        return data

    def to_json(self) -> str:
        """The result as one JSON document."""
        return json.dumps(self.to_dict(), indent=2)


def nearest_fixture(ctx: PrimitiveContext, point: FloatArray) -> str:
    """Name of the board fixture whose design position is nearest ``point``."""
    if not ctx.fixtures:
        return "unknown"
    return min(ctx.fixtures, key=lambda n: float(np.linalg.norm(ctx.fixtures[n] - point)))


def score_contacts(
    ctx: PrimitiveContext, truth: GroundTruth, cable: str | None = None
) -> list[ContactScore]:
    """Every estimated contact point of ``ctx``'s model (of ``cable``) against the truth."""
    scores = []
    real = None if cable is None else true_contacts(truth, cable)
    for pt in ctx.graph.points:
        if pt.covariance is None or pt.kind not in ("contact", "fixed"):
            continue
        name = pt.label if pt.label in ctx.fixtures else nearest_fixture(ctx, pt.position)
        if real is None:
            true = truth.contact(name)
            t = None if true is None else np.asarray(true.point, dtype=float)
        else:
            t = real.get(name)
        scores.append(
            ContactScore(
                name,
                [float(v) for v in pt.position],
                None if t is None else [float(v) for v in t],
                None if t is None else float(np.linalg.norm(pt.position - t)),
                [float(v) for v in np.sqrt(np.maximum(np.diag(pt.covariance), 0.0))],
            )
        )
    return scores


def model_error(graph: PathGraph, polyline: FloatArray) -> dict[str, float] | None:
    """Horizontal and vertical deviation [m] of the model's constrained points from the cable.

    Each point against the nearest point of the true cable (the measure
    before ``model_error`` scored each point against the true point it
    stands for, :func:`~tautwire.experiments.truth.point_deviations`).
    """
    horizontal, vertical = [], []
    for pt in graph.points:
        if not pt.is_constrained:
            continue
        d = pt.position - closest_on_polyline(polyline, pt.position)
        horizontal.append(float(np.hypot(d[0], d[1])))
        vertical.append(abs(float(d[2])))
    return deviation_summary(horizontal, vertical)


def task_of(scenario: Scenario) -> list[ScenarioStep]:
    """The steps to run: the scenario's task, or, with routes and no task, the planner's.

    Raises:
        RouteError: a route the robot cannot do (one line: cable, entry, reason).
    """
    if scenario.task or not any(c.route for c in scenario.cables):
        return list(scenario.task)
    from tautwire.scenario.route_problem import plan_scenario

    return [ScenarioStep.model_validate(step) for step in plan_scenario(scenario).task()]


def routed(graph: PathGraph, route: list[tuple[str, str | None]]) -> bool:
    """Whether the model passes the route's fixtures in order (a point named after each)."""
    labels = [p.label for p in graph.points if p.kind in ("contact", "fixed")]
    at = 0
    for fixture, _ in route:
        if fixture not in labels[at:]:
            return False
        at = labels.index(fixture, at) + 1
    return True


def stiffness_report(ctx: PrimitiveContext | None, truth: float) -> dict[str, float | None]:
    """A cable's stiffness as the run reports it.

    ``estimate`` is k_hat [N/m], the stiffness of the sensing gripper's
    span, whose cable length the model holds as ``span`` [m]
    (:meth:`ModelEstimator.span_length`); ``truth`` is the whole cable's k
    [N/m]. Where the span ends at an anchor or a grasp, k_hat estimates
    ``truth`` * L / ``span`` for a cable of length L; a clip lets the cable
    slide, and k_hat is softer. None where there is none.
    """
    k_hat = None if ctx is None else ctx.estimator.elasticity.k_hat
    return {
        "estimate": float(k_hat) if k_hat is not None and math.isfinite(k_hat) else None,
        "span": None if ctx is None else ctx.estimator.span_length(),
        "truth": truth,
    }


def score_cables(
    scenario: Scenario,
    models: CableModels,
    truth: GroundTruth,
    reports: list[StepReport],
    complete: bool,
) -> tuple[list[dict[str, Any]], dict[str, float] | None, dict[str, float] | None]:
    """Per cable: stiffness, model_error, shape_error, route_done; and both errors over all.

    ``route_done`` (a cable with a route; None without) is the robot's blind
    claim: the whole task ran, every step on the cable succeeded and its
    model passes the route's fixtures in order (:func:`routed`);
    ``route_truth`` says whether the simulator shows the cable on its route.
    """
    cables: list[dict[str, Any]] = []
    all_points: list[PointDeviation] = []
    all_shape: list[FloatArray] = []
    for spec in scenario.cables:
        ctx = models.final(spec.name)
        graph = models.graphs[spec.name]
        points = point_deviations(graph, truth, spec.name)
        shape = shape_deviations(graph, truth.polyline(spec.name))
        all_points += points
        all_shape.append(shape)
        own = [r for r in reports if r.cable == spec.name]
        route: list[tuple[str, str | None]] = [(e.fixture, e.side) for e in spec.route]
        entry: dict[str, Any] = {
            "name": spec.name,
            "stiffness": stiffness_report(ctx, truth.stiffness(spec.name)),
            "model_error": deviation_summary(
                [p.horizontal for p in points], [p.vertical for p in points]
            ),
            "shape_error": deviation_summary(list(shape[:, 0]), list(shape[:, 1])),
            "route_done": (complete and all(r.success for r in own) and routed(graph, route))
            if route
            else None,
            "route_truth": route_truth(truth, spec.name, route).to_dict() if route else None,
            "points": [
                {
                    "label": p.label,
                    "stands_for": p.stands_for,
                    "horizontal": p.horizontal,
                    "vertical": p.vertical,
                }
                for p in points
            ],
        }
        cables.append(entry)
    shape_all = np.vstack(all_shape) if all_shape else np.zeros((0, 2))
    return (
        cables,
        deviation_summary([p.horizontal for p in all_points], [p.vertical for p in all_points]),
        deviation_summary(list(shape_all[:, 0]), list(shape_all[:, 1])),
    )


def run_scenario(
    scenario: Scenario,
    seed: int | None = None,
    *,
    estimation_period: float = 0.04,
    on_tick: Callable[[TickRecord], None] | None = None,
    on_step: Callable[[int, StepReport], None] | None = None,
    on_truth: Callable[[GroundTruth], None] | None = None,
    on_world: Callable[[SimWorld], None] | None = None,
    **sim_options: Any,
) -> tuple[RunResult, PrimitiveContext, GroundTruth]:
    """Simulate ``scenario``'s task (planned from its routes if it has none) and score it.

    Args:
        scenario: A validated scenario.
        seed: Overrides the scenario's seed.
        estimation_period: Period [s] of the contact filter's iterations.
        on_tick: Called every control period (recording, video).
        on_step: Called after each step with its index and report.
        on_truth: Called once with the ground truth, for scoring hooks
            (never handed to a primitive).
        on_world: Called once with the simulated world (rendering).
        **sim_options: Options of the simulated world (see ``SimOptions``).

    Returns:
        The result, the final context of the first cable (its model and
        estimators; every cable's is in ``result.models``) and the truth.

    Raises:
        RouteError: the scenario's routes cannot be planned.
    """
    t_wall = time.perf_counter()
    seed = scenario.seed if seed is None else seed
    task = task_of(scenario)
    world = build_world(scenario, seed=seed, **sim_options)
    robot = scenario_guard(robot_of(world, seed, scenario.faults), scenario)  # once per run
    truth = truth_of(world)
    if on_truth is not None:
        on_truth(truth)
    if on_world is not None:
        on_world(world)
    models = initial_models(scenario, estimation_period=estimation_period)
    first = scenario.cables[0].name
    start = models.primary(first)
    audit = RunAudit(truth, first, start.arm if start is not None else "left")
    checks: list[TruthCheck] = []

    def started(i: int, step: TaskStep, model: StepModel) -> None:
        cable = model.cable if model.cable is not None else first
        audit.start_step(step.letter, dict(step.params), cable, model.context.arm, step.primitive)

    def tick(record: TickRecord) -> None:
        audit.tick(record.context)
        if on_tick is not None:
            on_tick(record)

    def ended(i: int, step: TaskStep, model: StepModel | None, report: StepReport) -> None:
        if model is None:
            checks.append(TruthCheck(True, "the step did not run: " + report.detail))
        else:
            checks.append(audit.end_step(report.success, model.context))
        if on_step is not None:
            on_step(i, report)

    reports = run_task(robot, task, models, TaskHooks(started, tick, ended))
    false_successes = sum(
        1 for r, c in zip(reports, checks, strict=True) if r.success and not c.agrees
    )
    complete = len(reports) == len(task) and all(r.success for r in reports)
    success = complete and false_successes == 0
    steps = [
        {
            "primitive": r.primitive,
            "letter": r.letter,
            "outcome": r.outcome,
            "cause": r.cause,
            "detail": r.detail,
            "sim_time": r.sim_time,
            "max_force": r.max_force,
            "cable": r.cable,
            "truth": check.to_dict(),
        }
        for r, check in zip(reports, checks, strict=True)
    ]
    ctx = models.final(first)
    if ctx is None:  # no gripper with a sensor ever held the first cable
        raise InvalidArgumentError(f"cable {first!r}: no gripper with a force sensor holds it")
    audit.finish(ctx, models.graphs)
    cables, model_all, shape_all = score_cables(scenario, models, truth, reports, complete)
    # a route the model claims done that the simulator does not show makes no success
    success = success and not any(
        c["route_done"] and not c["route_truth"]["agrees"] for c in cables
    )
    contacts = [
        score
        for spec in scenario.cables
        if (final := models.final(spec.name)) is not None
        for score in score_contacts(final, truth, spec.name)
    ]
    result = RunResult(
        scenario=scenario.name,
        seed=seed,
        success=success,
        steps=steps,
        contacts=contacts,
        stiffness=stiffness_report(ctx, truth.stiffness(first)),
        model_error=model_all,
        max_force=max((r.max_force for r in reports), default=0.0),
        sim_time=sum(r.sim_time for r in reports),
        wall_time=time.perf_counter() - t_wall,
        false_successes=false_successes,
        true_max_force=truth.max_force,
        contact_consistency=audit.consistency(),
        audit=audit,
        cables=cables,
        shape_error=shape_all,
        models=models,
    )
    return result, ctx, truth


def write_result(result: RunResult, out_dir: str | Path) -> Path:
    """Write ``result.json`` under ``out_dir``."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    path = out / "result.json"
    path.write_text(result.to_json() + "\n")
    return path
