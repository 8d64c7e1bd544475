"""``tautwire validate SCENARIO``: check a scenario file and say what is wrong."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import click

from tautwire.scenario import Scenario, ScenarioError, load_scenario
from tautwire.scenario.issue import Issue
from tautwire.scenario.loader import issues_error, read_scenario_text
from tautwire.scenario.registry import resolve_scenario


def summarise(scenario: Scenario) -> list[str]:
    """A few lines saying what a valid scenario holds.

    Args:
        scenario: a validated scenario.

    Returns:
        Lines of text: name, fixtures, cables with their routes, task
        steps, and the faults to inject, if any.
    """
    fixtures = scenario.board.fixtures
    lines = [
        f"scenario {scenario.name!r} (version {scenario.version}, seed {scenario.seed}): valid",
        f"fixtures: {len(fixtures)}"
        + (": " + ", ".join(f"{f.name} ({f.type})" for f in fixtures) if fixtures else ""),
        f"cables: {len(scenario.cables)}",
    ]
    for cable in scenario.cables:
        route = [cable.start or "free end", *cable.via]
        holds = ", ".join(f"{h.arm} at {h.at:g} m" for h in cable.held_by)
        lines.append(
            f"  {cable.name}: {cable.length:g} m, {cable.stiffness:g} N/m, "
            f"route {' -> '.join(route)}, held by {holds}"
        )
        if cable.route:
            entries = []
            for e in cable.route:
                how = ([e.side] if e.side else []) + ([f"wind {e.wind}"] if e.wind else [])
                entries.append(e.fixture + (f" ({', '.join(how)})" if how else ""))
            lines.append(f"    target route: {' -> '.join(entries)}")
    lines.append(f"task steps: {len(scenario.task)}")
    for n, step in enumerate(scenario.task, start=1):
        params = ", ".join(f"{k}={_value(v)}" for k, v in step.params.items())
        letter = f"{step.letter} " if step.letter else ""
        lines.append(f"  {n}. {letter}{step.primitive}({params})")
    if scenario.faults:
        lines.append(f"faults (simulation only): {len(scenario.faults)}")
        for fault in scenario.faults:
            fields = fault.model_dump(exclude={"type", "at"}, exclude_none=True)
            details = ", ".join(f"{k}={_value(_plain(v))}" for k, v in fields.items())
            lines.append(f"  {fault.type} at {fault.at:g} s" + (f" ({details})" if details else ""))
    return lines


def _plain(value: object) -> float | str | list[float]:
    """A fault field as a parameter value (tuples as lists)."""
    if isinstance(value, tuple):
        return [float(c) for c in value]
    if isinstance(value, int | float):
        return float(value)
    return str(value)


def _value(value: float | str | list[float]) -> str:
    """A parameter value, compactly."""
    if isinstance(value, list):
        return "[" + ", ".join(f"{c:g}" for c in value) + "]"
    if isinstance(value, float):
        return f"{value:g}"
    return value


def problems_to_json(error: ScenarioError) -> list[dict[str, Any]]:
    """The problems of a scenario error as ``--json`` data (line null when unknown)."""
    return [
        {"file": p.path, "line": p.line, "field": p.field, "message": p.message}
        for p in error.problems
    ]


EPILOG = """\b
Examples:
  tautwire validate my-board.yaml
  tautwire validate peg-and-clip          # a scenario that ships with tautwire
  tautwire validate my-board.yaml --json  # {"valid": ..., "problems": [...], "scenario": ...}

\b
Checks the schema (every key, type, range and unit), names and references,
geometry (reach, cable length along its route), and what the simulator
would refuse when it builds the world: the control period against the
physics timestep (a whole multiple of it), the wave-speed guard at the
force limit, the initial route, the compiled MuJoCo model. Every problem
is listed, one line each: FILE:LINE: FIELD: what is wrong (what is
expected). Exit status 0 if valid, 1 otherwise.
"""


@click.command("validate", epilog=EPILOG)
@click.argument("scenario", metavar="SCENARIO")
@click.option(
    "--json",
    "as_json",
    is_flag=True,
    help="print one JSON object on stdout: valid, problems, and the scenario as read",
)
def validate(scenario: str, as_json: bool) -> int:
    """Check the scenario SCENARIO (a file, or a registered name); summarise it if valid.

    Every problem found goes to stderr, one line each, and the exit status is 1.
    """
    path = Path(scenario)
    try:
        path = resolve_scenario(scenario)
        loaded = load_scenario(path)
        issues = _simulation_issues(loaded)
        if issues:
            raise issues_error(read_scenario_text(path), str(path), issues)
    except ScenarioError as exc:
        if as_json:
            click.echo(
                json.dumps({"file": str(path), "valid": False, "problems": problems_to_json(exc)})
            )
        raise
    if as_json:
        click.echo(
            json.dumps(
                {
                    "file": str(path),
                    "valid": True,
                    "problems": [],
                    "scenario": loaded.model_dump(mode="json"),
                },
                allow_nan=False,
            )
        )
        return 0
    for line in summarise(loaded):
        click.echo(line)
    return 0


def _simulation_issues(scenario: Scenario) -> list[Issue]:
    """What the simulated world would refuse (:mod:`tautwire.sim.preflight`)."""
    from tautwire.sim.preflight import simulation_issues

    return simulation_issues(scenario)
