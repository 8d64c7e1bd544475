"""``tautwire reproduce NAME``: regenerate a figure or table of the paper."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import click
from rich.console import Console

from tautwire.errors import InvalidArgumentError


def _fig5a(out: Path, seed: int) -> dict[str, Any]:
    from tautwire.experiments.fig5a import reproduce_fig5a

    return reproduce_fig5a(out, seed)


def _fig5b(out: Path, seed: int) -> dict[str, Any]:
    from tautwire.experiments.fig5bc import reproduce_fig5b

    return reproduce_fig5b(out, seed)


def _fig5c(out: Path, seed: int) -> dict[str, Any]:
    from tautwire.experiments.fig5bc import reproduce_fig5c

    return reproduce_fig5c(out, seed)


#: What can be reproduced so far, by name.
REPRODUCTIONS: dict[str, Callable[[Path, int], dict[str, Any]]] = {
    "fig5a": _fig5a,
    "fig5b": _fig5b,
    "fig5c": _fig5c,
}


@click.command()
@click.argument("name")
@click.option(
    "--out",
    "out_dir",
    type=click.Path(file_okay=False),
    default=None,
    help="output folder (default out/NAME)",
)
@click.option("--seed", type=int, default=0, show_default=True, help="random seed")
@click.option("--json", "as_json", is_flag=True, help="print one JSON object on stdout")
def reproduce(name: str, out_dir: str | None, seed: int, as_json: bool) -> int:
    """Regenerate the paper's figure or table NAME (fig5a, fig5b, fig5c)."""
    if name not in REPRODUCTIONS:
        raise InvalidArgumentError(
            f"no reproduction named {name!r}; available: {', '.join(REPRODUCTIONS)}"
        )
    out = Path(out_dir) if out_dir is not None else Path("out") / name
    with Console(stderr=True).status(f"reproducing {name} ..."):
        result = REPRODUCTIONS[name](out, seed)
    if as_json:
        click.echo(json.dumps(result, indent=2))
    else:
        Console().print_json(json.dumps(result))
        Console().print(f"written under {out}/")
    return 0
