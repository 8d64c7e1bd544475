"""``tautwire scenarios``: list the scenarios that ship with the package."""

from __future__ import annotations

import json

import click

from tautwire.scenario.registry import registered_scenarios


@click.command(
    "scenarios",
    epilog="\b\nExamples:\n  tautwire scenarios\n  tautwire scenarios --json\n"
    "  tautwire run peg-change       # run one by its name\n",
)
@click.option("--json", "as_json", is_flag=True, help="print one JSON object on stdout")
def scenarios(as_json: bool) -> int:
    """List the shipped scenarios, one line each: name and what it shows.

    A listed NAME can be given wherever a scenario file can, e.g.
    ``tautwire run anchor-rotate`` or ``tautwire validate peg-change``; a
    path that exists is always taken as the file.

    With --json: {"scenarios": [{"name", "description", "path"}, ...]}.
    """
    entries = registered_scenarios()
    if as_json:
        listed = [
            {"name": e.name, "description": e.description, "path": str(e.path)} for e in entries
        ]
        click.echo(json.dumps({"scenarios": listed}))
        return 0
    width = max((len(e.name) for e in entries), default=0)
    for e in entries:
        click.echo(f"{e.name:<{width}}  {e.description}")
    return 0
