"""``tautwire demo``: the main job on its built-in default."""

from __future__ import annotations

from pathlib import Path

import click
from rich.console import Console
from rich.table import Table


def _mm(value: float | None) -> str:
    return "-" if value is None else f"{1e3 * value:.2f} mm"


@click.command()
@click.option(
    "--out",
    "out_dir",
    type=click.Path(file_okay=False),
    default="out/demo",
    show_default=True,
    help="folder for the plots and result.json",
)
@click.option("--seed", type=int, default=0, show_default=True, help="random seed")
@click.option("--json", "as_json", is_flag=True, help="print one JSON object on stdout")
def demo(out_dir: str, seed: int, as_json: bool) -> int:
    """Run the built-in demonstration and summarise it."""
    from tautwire.experiments.synthetic_demo import run_synthetic_demo

    err = Console(stderr=True)
    with err.status("estimating a contact and three stiffnesses from noisy forces ..."):
        result = run_synthetic_demo(seed, Path(out_dir))
    if as_json:
        click.echo(result.to_json())
        return 0
    c = result.contact
    table = Table(title="Contact point estimation (synthetic circle, 4 N, 0.05 N noise)")
    table.add_column("figure")
    table.add_column("measured", justify="right")
    table.add_row("error after half a circle", _mm(c.error_half_circle))
    table.add_row("error after a full circle", _mm(c.error_full_circle))
    table.add_row("contact change declared after", f"{c.change_declared_after} samples")
    table.add_row("peak error once declared", _mm(c.peak_error_after_declared))
    table.add_row("back under 2 mm after", f"{c.samples_to_2mm_after_change} samples")
    table.add_row("final error", _mm(c.final_error))
    table.add_row("|error| <= 3 std (every axis)", f"{100 * c.within_3_std:.1f} % of samples")
    stiff = Table(title="Elasticity estimate after 2 s of stretching (start 10x too low)")
    stiff.add_column("true k [N/m]", justify="right")
    stiff.add_column("k_hat [N/m]", justify="right")
    stiff.add_column("error", justify="right")
    for case in result.stiffness:
        stiff.add_row(
            f"{case.stiffness:g}", f"{case.k_hat:.1f}", f"{100 * case.relative_error:+.2f} %"
        )
    out = Console()
    out.print(table)
    out.print(stiff)
    out.print(f"plot: {result.plot}\nnumbers: {Path(out_dir) / 'result.json'}")
    return 0
