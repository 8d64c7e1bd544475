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

from tautwire.errors import TautwireError
from tautwire.experiments.truth import RunAudit
from tautwire.model import PathGraph
from tautwire.primitives import PrimitiveContext, make_primitive
from tautwire.scenario import Scenario
from tautwire.sim.build import build_world, robot_of, truth_of
from tautwire.sim.ground_truth import GroundTruth, closest_on_polyline
from tautwire.sim.world import SimWorld
from tautwire.tasks import StepReport, TickRecord, run_step
from tautwire.tasks.initial_model import initial_context
from tautwire.tasks.scenario_guard import scenario_guard

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
    audit: RunAudit | None = field(default=None, repr=False)

    def to_dict(self) -> dict[str, Any]:
        """The result as JSON-ready data (without the ``audit``)."""
        data = asdict(replace(self, audit=None))
        data.pop("audit")
        return data

    def to_json(self) -> str:
        """The result as one JSON document."""
        return json.dumps(self.to_dict(), indent=2)


def nearest_fixture(ctx: PrimitiveContext, point: FloatArray) -> str:
    """Name of the board fixture whose design position is nearest ``point``."""
    if not ctx.fixtures:
        return "unknown"
    return min(ctx.fixtures, key=lambda n: float(np.linalg.norm(ctx.fixtures[n] - point)))


def score_contacts(ctx: PrimitiveContext, truth: GroundTruth) -> list[ContactScore]:
    """Every estimated contact point of the model against the truth."""
    scores = []
    for pt in ctx.graph.points:
        if pt.covariance is None or pt.kind not in ("contact", "fixed"):
            continue
        name = pt.label if pt.label in ctx.fixtures else nearest_fixture(ctx, pt.position)
        true = truth.contact(name)
        t = None if true is None else np.asarray(true.point, dtype=float)
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
    """Horizontal and vertical deviation [m] of the model's constrained points from the cable."""
    horizontal, vertical = [], []
    for pt in graph.points:
        if not pt.is_constrained:
            continue
        d = pt.position - closest_on_polyline(polyline, pt.position)
        horizontal.append(float(np.hypot(d[0], d[1])))
        vertical.append(abs(float(d[2])))
    if not horizontal:
        return None
    return {
        "horizontal_mean": float(np.mean(horizontal)),
        "horizontal_max": float(np.max(horizontal)),
        "vertical_mean": float(np.mean(vertical)),
        "vertical_max": float(np.max(vertical)),
    }


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
    """Simulate ``scenario``'s task and score it.

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
        The result, the final context (model and estimators) and the truth.
    """
    t_wall = time.perf_counter()
    seed = scenario.seed if seed is None else seed
    world = build_world(scenario, seed=seed, **sim_options)
    robot = scenario_guard(robot_of(world, seed, scenario.faults), scenario)  # once per run
    truth = truth_of(world)
    if on_truth is not None:
        on_truth(truth)
    if on_world is not None:
        on_world(world)
    ctx = initial_context(scenario, estimation_period=estimation_period)
    cable = (scenario.cables[0]).name
    audit = RunAudit(truth, cable, ctx.arm)
    reports: list[StepReport] = []
    for i, step in enumerate(scenario.task):
        audit.start_step(step.letter, step.params)

        def tick(record: TickRecord) -> None:
            audit.tick(record.context)
            if on_tick is not None:
                on_tick(record)

        try:
            primitive = make_primitive(step.primitive, **step.params)
        except TautwireError as exc:
            report = StepReport(step.primitive, step.letter, "failure", "error", str(exc), 0.0, 0.0)
        else:
            report = run_step(robot, primitive, ctx, on_tick=tick)
        audit.end_step(report.success, ctx)
        reports.append(report)
        if on_step is not None:
            on_step(i, report)
        if not report.success:
            break
    success = (
        len(reports) == len(scenario.task)
        and all(r.success for r in reports)
        and audit.false_successes == 0
    )
    steps = [
        {
            "primitive": r.primitive,
            "letter": r.letter,
            "outcome": r.outcome,
            "cause": r.cause,
            "detail": r.detail,
            "sim_time": r.sim_time,
            "max_force": r.max_force,
            "cable": cable,
            "truth": check.to_dict(),
        }
        for r, check in zip(reports, audit.checks, strict=True)
    ]
    audit.finish(ctx)
    k_hat = ctx.estimator.elasticity.k_hat
    result = RunResult(
        scenario=scenario.name,
        seed=seed,
        success=success,
        steps=steps,
        contacts=score_contacts(ctx, truth),
        stiffness={
            "estimate": float(k_hat) if math.isfinite(k_hat) else None,
            "truth": truth.stiffness(cable),
        },
        model_error=model_error(ctx.graph, truth.polyline(cable)),
        max_force=max((r.max_force for r in reports), default=0.0),
        sim_time=sum(r.sim_time for r in reports),
        wall_time=time.perf_counter() - t_wall,
        false_successes=audit.false_successes,
        true_max_force=truth.max_force,
        contact_consistency=audit.consistency(),
        audit=audit,
    )
    return result, ctx, truth


def write_result(result: RunResult, out_dir: str | Path) -> Path:
    """Write ``result.json`` under ``out_dir``."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    path = out / "result.json"
    path.write_text(result.to_json() + "\n")
    return path
