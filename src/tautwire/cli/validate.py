"""``tautwire validate SCENARIO``: check a scenario file and say what is wrong."""

from __future__ import annotations

import click

from tautwire.scenario import Scenario, load_scenario
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


@click.command("validate")
@click.argument("scenario", type=click.Path(dir_okay=False, path_type=str))
def validate(scenario: str) -> int:
    """Check the scenario file SCENARIO; print a summary if it is valid.

    On the first problem found, print one line FILE:LINE: FIELD: what is
    wrong (what is expected) on stderr and exit with status 1.
    """
    loaded = load_scenario(resolve_scenario(scenario))
    for line in summarise(loaded):
        click.echo(line)
    return 0
