"""``tautwire demo``: the main job on its built-in default."""

from __future__ import annotations

import json
import os
from pathlib import Path

import click
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table


def _mm(value: float | None) -> str:
    return "-" if value is None else f"{1e3 * value:.2f} mm"


@click.command(
    epilog="""\b
Examples:
  tautwire demo                          # tables; plot, GIF and snapshot under out/demo/
  tautwire demo --no-video --json        # one JSON object on stdout
  tautwire demo --rerun out/demo.rrd     # then: rerun out/demo.rrd
  tautwire demo --synthetic              # the estimators alone, no simulator
"""
)
@click.option(
    "--out",
    "out_dir",
    type=click.Path(file_okay=False),
    default="out/demo",
    show_default=True,
    help="folder for the plots, video and result.json",
)
@click.option("--seed", type=int, default=None, help="random seed (default: the scenario's)")
@click.option("--json", "as_json", is_flag=True, help="print one JSON object on stdout")
@click.option(
    "--video/--no-video",
    default=True,
    show_default=True,
    help="render a GIF and a snapshot (where rendering works)",
)
@click.option(
    "--rerun",
    "rerun_file",
    type=click.Path(dir_okay=False),
    default=None,
    help="also record the run to this Rerun file (.rrd; needs the extra tautwire[rerun])",
)
@click.option(
    "--synthetic", is_flag=True, help="the estimators alone on synthetic data (no simulator)"
)
def demo(
    out_dir: str,
    seed: int | None,
    as_json: bool,
    video: bool,
    rerun_file: str | None,
    synthetic: bool,
) -> int:
    """Watch a robot find, blind, where a cable touches the board (simulated)."""
    if synthetic:
        return _synthetic(out_dir, seed or 0, as_json)
    os.environ.setdefault("MUJOCO_GL", "egl")  # before mujoco is imported
    from tautwire.experiments.sim_demo import DEMO_SCENARIO, run_sim_demo
    from tautwire.scenario import load_scenario

    scenario = load_scenario(DEMO_SCENARIO)
    err = Console(stderr=True)
    columns = (
        TextColumn("{task.description}"),
        BarColumn(),
        TextColumn("{task.fields[t]}"),
        TimeElapsedColumn(),
    )
    with Progress(*columns, console=err, transient=True) as bar:
        task = bar.add_task(f"simulating {scenario.name}", total=25.0, t="")
        result = run_sim_demo(
            out_dir,
            seed,
            video=video,
            rerun=rerun_file,
            progress=lambda t: bar.update(task, completed=min(t, 25.0), t=f"{t:5.1f} s"),
        )
    if as_json:
        click.echo(
            json.dumps(
                {
                    "run": result.run,
                    "changes": result.changes,
                    "files": result.files,
                    "video_error": result.video_error,
                },
                indent=2,
            )
        )
        return 0 if result.run["success"] else 1
    run = result.run
    out = Console()
    steps = Table(title=f"{run['scenario']}: primitives run blind (seed {run['seed']})")
    for col in ("primitive", "outcome", "time [s]", "max force [N]"):
        steps.add_column(escape(col))  # '[s]' is not rich markup
    for s in run["steps"]:
        steps.add_row(
            f"{s['letter']} {s['primitive']}",
            s["outcome"] + (f" ({s['cause']})" if s["cause"] else ""),
            f"{s['sim_time']:.1f}",
            f"{s['max_force']:.2f}",
        )
    out.print(steps)
    contacts = Table(title="Where the cable touches the board: estimate vs truth")
    for col in ("fixture", "estimate [m]", "error", "std [mm]"):
        contacts.add_column(escape(col))
    for c in run["contacts"]:
        contacts.add_row(
            c["fixture"],
            str([round(v, 4) for v in c["estimate"]]),
            _mm(c["error"]),
            str([round(1e3 * v, 2) for v in c["std"]]),
        )
    out.print(contacts)
    k = run["stiffness"]
    out.print(f"contact changes declared at filter iterations {result.changes}")
    out.print(f"stiffness: k_hat {k['estimate']:.1f} N/m (truth {k['truth']:.1f} N/m)")
    out.print(f"{run['sim_time']:.1f} s simulated in {run['wall_time']:.1f} s")
    if result.video_error:
        out.print(f"no video: {result.video_error}")
    for name, path in result.files.items():
        out.print(f"{name}: {path}")
    return 0 if run["success"] else 1


def _synthetic(out_dir: str, seed: int, as_json: bool) -> int:
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
