"""Load a scenario and run its primitives one at a time, reading the model after each.

The scenario ``peg-change`` (the paper's Fig. 5c) holds a cable fixed at an
anchor A1: primitive D tensions it, then primitive I circles the anchor,
until the taut cable swings onto the peg P1. The robot is blind: after each
step, the path graph (the robot's only picture of the cable) shows what the
force alone told it, feature points with their uncertainty and edges with
their tension. The simulator's truth is read at the end, to score only.

Run: python examples/step_by_step.py [SCENARIO] [--seed N]
"""

from __future__ import annotations

import argparse

import numpy as np

from tautwire.model import PathGraph
from tautwire.primitives import make_primitive
from tautwire.scenario import load_scenario
from tautwire.scenario.registry import scenario_path
from tautwire.sim import build_world, robot_of, truth_of
from tautwire.tasks import run_step
from tautwire.tasks.initial_model import initial_context
from tautwire.tasks.scenario_guard import scenario_guard


def show(graph: PathGraph) -> None:
    """Print the path graph: points (kind, label, position, std) and edges."""
    for i, point in enumerate(graph.points):
        where = np.array2string(point.position, precision=4, suppress_small=True)
        std = ""
        if point.covariance is not None:
            sigma = 1e3 * np.sqrt(np.diag(point.covariance))
            std = f"  std {np.array2string(sigma, precision=1)} mm"
        print(f"    v{i + 1} {point.kind:8s} {point.label:6s} {where} m{std}")
        if i < len(graph.edges):
            edge = graph.edges[i]
            print(
                f"       e{i + 1}: {edge.length:.3f} m, tension {edge.tension:.2f} N, "
                f"sag {1e3 * edge.sag:.1f} mm"
            )


def main(name: str = "peg-change", seed: int | None = None) -> dict[str, float]:
    """Run scenario ``name`` step by step; return each contact's error [mm] by fixture."""
    scenario = load_scenario(scenario_path(name))
    seed = scenario.seed if seed is None else seed
    world = build_world(scenario, seed=seed)
    # what the primitives get: the robot's observations, screened by the guard
    robot = scenario_guard(robot_of(world, seed, scenario.faults), scenario)
    ctx = initial_context(scenario, estimation_period=0.04)
    print(f"{scenario.name}, seed {seed}: the model before the first step")
    show(ctx.graph)

    for step in scenario.task:
        primitive = make_primitive(step.primitive, **step.params)
        report = run_step(robot, primitive, ctx)
        print(
            f"{report.letter} {report.primitive}: {report.outcome}"
            f"{'' if report.cause is None else ' (' + report.cause + ')'} "
            f"after {report.sim_time:.1f} s; k_hat {ctx.estimator.elasticity.k_hat:.0f} N/m"
        )
        show(ctx.graph)
        if not report.success:
            break

    # the truth, for scoring only: never handed to a primitive
    truth = truth_of(world)
    errors: dict[str, float] = {}
    for point in ctx.graph.points:
        true = truth.contact(point.label) if point.kind in ("contact", "fixed") else None
        if true is not None and point.covariance is not None:
            errors[point.label] = 1e3 * float(np.linalg.norm(point.position - true.point))
            print(f"{point.label}: estimate {errors[point.label]:.1f} mm from the truth")
    print(f"k_hat {ctx.estimator.elasticity.k_hat:.1f} N/m, true {truth.stiffness('W1'):.0f} N/m")
    return errors


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenario", nargs="?", default="peg-change")
    parser.add_argument("--seed", type=int, default=None)
    args = parser.parse_args()
    main(args.scenario, args.seed)
