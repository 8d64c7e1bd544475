"""``tautwire plan SCENARIO [--json]``: the task the planner makes from the cables' routes."""

from __future__ import annotations

import json
from typing import Any

import click

from tautwire.scenario import load_scenario
from tautwire.scenario.registry import resolve_scenario
from tautwire.scenario.route_problem import plan_scenario, task_yaml
from tautwire.tasks.planner import Plan


def plan_to_json(name: str, plan: Plan) -> dict[str, Any]:
    """The ``--json`` object of a plan: the task and what it does with each cable."""
    return {
        "scenario": name,
        "task": plan.task(),
        "why": [step.why for step in plan.steps],
        "cables": [
            {
                "name": c.name,
                "steps": list(c.steps),
                "route_length": round(c.route_length, 4),
                "held_at": round(c.held_at, 4),
                "arm": c.arm,
            }
            for c in plan.cables
        ],
    }


@click.command(
    "plan",
    epilog="\b\nExamples:\n  tautwire plan harness.yaml           # a task: list to paste\n"
    "  tautwire plan my-board.yaml --json\n",
)
@click.argument("scenario", type=click.Path(dir_okay=False, path_type=str))
@click.option("--json", "as_json", is_flag=True, help="print one JSON object on stdout")
def plan(scenario: str, as_json: bool) -> int:
    """Plan the routes of SCENARIO's cables; print the task.

    The task is printed as a ``task:`` list that can be pasted into the
    scenario file (or, with --json, one JSON object). A route the robot
    cannot do is one line on stderr naming the cable, the route entry and
    the reason, and exit status 1.
    """
    loaded = load_scenario(resolve_scenario(scenario))
    planned = plan_scenario(loaded)
    if as_json:
        click.echo(json.dumps(plan_to_json(loaded.name, planned), allow_nan=False))
    else:
        click.echo(task_yaml(planned), nl=False)
    return 0
