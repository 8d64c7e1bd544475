"""``tautwire reproduce NAME``: regenerate a figure or table of the paper."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import click
from rich.console import Console
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)
from rich.table import Table

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


#: Table I's campaign by default: trials per primitive, and trials at a time.
TABLE1_TRIALS = 100
TABLE1_WORKERS = 2
#: Wall time [s] after which a trial of table1 is stopped as hung (a trial takes seconds).
TABLE1_TRIAL_TIMEOUT = 600.0

#: The robustness campaign by default: trials, and trials at a time.
ROBUSTNESS_TRIALS = 200
ROBUSTNESS_WORKERS = 2
#: The campaigns, which take the campaign options (--trials, --workers, ...).
CAMPAIGNS = ("table1", "robustness")

#: What can be reproduced so far, by name (besides the campaigns, which take more options).
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
@click.option(
    "--trials",
    type=click.IntRange(min=1),
    default=None,
    help=f"table1: trials per primitive, robustness: trials  "
    f"[default: {TABLE1_TRIALS}, robustness {ROBUSTNESS_TRIALS}]",
)
@click.option(
    "--workers",
    type=click.IntRange(min=1),
    default=None,
    help=f"table1, robustness: trials run at a time  [default: {TABLE1_WORKERS}]",
)
@click.option(
    "--backend",
    type=click.Choice(["local", "serial", "ray"]),
    default=None,
    help="table1, robustness: where trials run: local processes, this process, or Ray "
    "(pip install 'tautwire[ray]')  [default: local]",
)
@click.option(
    "--address",
    default=None,
    help="table1, robustness: the Ray cluster to join (default: a local Ray)",
)
@click.option(
    "--letters", default=None, help="table1: the primitives to run, e.g. DI  [default: A-I]"
)
@click.option(
    "--only",
    default=None,
    metavar="TRIALS",
    help="table1, robustness: rerun these trials alone in this process and print them "
    "(table1: D:17, robustness: 17 or 3,17)",
)
@click.option(
    "--trial-timeout",
    type=click.FloatRange(min=0.0, min_open=True),
    default=None,
    help=f"table1, robustness, local backend: seconds after which a trial is stopped as hung  "
    f"[default: {TABLE1_TRIAL_TIMEOUT:g}]",
)
@click.option(
    "--resume",
    is_flag=True,
    help="table1: reuse the trials of the same campaign already in the output folder "
    "(those that crashed, hung or raised an internal error run again)",
)
@click.option(
    "--no-faults",
    is_flag=True,
    help="robustness: run each trial clean only (no fault run)",
)
def reproduce(
    name: str,
    out_dir: str | None,
    seed: int,
    as_json: bool,
    trials: int | None,
    workers: int | None,
    backend: str | None,
    address: str | None,
    letters: str | None,
    only: str | None,
    trial_timeout: float | None,
    resume: bool,
    no_faults: bool,
) -> int:
    """Regenerate the paper's figure or table NAME (fig5a, fig5b, fig5c, table1), or robustness.

    robustness runs the campaign of randomised single-fixture scenes, each
    trial clean and with one fault, scored against the simulator's truth.
    """
    if name not in REPRODUCTIONS and name not in CAMPAIGNS:
        raise InvalidArgumentError(
            f"no reproduction named {name!r}; available: {', '.join([*REPRODUCTIONS, *CAMPAIGNS])}"
        )
    out = Path(out_dir) if out_dir is not None else Path("out") / name
    if name == "robustness":
        table1_only = {"--letters": letters, "--resume": resume or None}
        given = [option for option, value in table1_only.items() if value is not None]
        if given:
            raise InvalidArgumentError(f"{', '.join(given)}: only for table1, not robustness")
        if only is not None:
            return _robustness_only(only, seed, as_json, faults=not no_faults)
        return _robustness(
            out,
            seed,
            as_json,
            trials=ROBUSTNESS_TRIALS if trials is None else trials,
            workers=ROBUSTNESS_WORKERS if workers is None else workers,
            backend=backend or "local",
            address=address,
            faults=not no_faults,
            trial_timeout=TABLE1_TRIAL_TIMEOUT if trial_timeout is None else trial_timeout,
        )
    if no_faults:
        raise InvalidArgumentError(f"--no-faults: only for robustness, not {name}")
    if name == "table1":
        if only is not None:
            return _table1_only(only, seed, as_json)
        return _table1(
            out,
            seed,
            as_json,
            trials=TABLE1_TRIALS if trials is None else trials,
            workers=TABLE1_WORKERS if workers is None else workers,
            backend=backend or "local",
            address=address,
            letters=letters,
            resume=resume,
            trial_timeout=TABLE1_TRIAL_TIMEOUT if trial_timeout is None else trial_timeout,
        )
    campaign_options = {
        "--trials": trials,
        "--workers": workers,
        "--backend": backend,
        "--address": address,
        "--letters": letters,
        "--only": only,
        "--trial-timeout": trial_timeout,
        "--resume": resume or None,
    }
    given = [option for option, value in campaign_options.items() if value is not None]
    if given:
        raise InvalidArgumentError(
            f"{', '.join(given)}: only for {' and '.join(CAMPAIGNS)}, not {name}"
        )
    with Console(stderr=True).status(f"reproducing {name} ..."):
        result = REPRODUCTIONS[name](out, seed)
    if as_json:
        click.echo(json.dumps(result, indent=2))
    else:
        Console().print_json(json.dumps(result))
        Console().print(f"written under {out}/")
    return 0


def _table1(
    out: Path,
    seed: int,
    as_json: bool,
    *,
    trials: int,
    workers: int,
    backend: str,
    address: str | None,
    letters: str | None,
    resume: bool,
    trial_timeout: float,
) -> int:
    """Run the Table I campaign with a progress bar on stderr; 130 if interrupted."""
    from tautwire.experiments.table1 import Progress as CampaignProgress
    from tautwire.experiments.table1 import parse_letters, reproduce_table1
    from tautwire.experiments.trial import LETTERS

    chosen = parse_letters(letters) if letters is not None else LETTERS
    if address is not None and backend != "ray":
        raise InvalidArgumentError("--address is for --backend ray only")
    err = Console(stderr=True)
    columns = (
        TextColumn("{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("{task.fields[failed]} failed"),
        TimeElapsedColumn(),
        TextColumn("ETA"),
        TimeRemainingColumn(),
    )
    with Progress(*columns, console=err) as bar:
        task = bar.add_task(f"table1 ({backend})", total=None, failed=0)

        def show(state: CampaignProgress) -> None:
            bar.update(task, completed=state.finished, total=state.planned, failed=state.failures)

        report = reproduce_table1(
            trials,
            workers,
            seed,
            out,
            backend,
            chosen,
            show,
            address=address,
            resume=resume,
            trial_timeout=trial_timeout if backend == "local" else None,
        )
    if as_json:
        click.echo(json.dumps(report, indent=2))
    else:
        Console().print(_table1_table(report))
        Console().print(f"written under {out}/")
    if report["interrupted"]:
        click.echo(
            f"tautwire: interrupted: {report['finished']} of {report['planned']} trials "
            f"finished; their results are written under {out}/",
            err=True,
        )
        return 130
    return 0


def _progress_columns() -> tuple[Any, ...]:
    return (
        TextColumn("{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("{task.fields[failed]} failed"),
        TimeElapsedColumn(),
        TextColumn("ETA"),
        TimeRemainingColumn(),
    )


def _robustness(
    out: Path,
    seed: int,
    as_json: bool,
    *,
    trials: int,
    workers: int,
    backend: str,
    address: str | None,
    faults: bool,
    trial_timeout: float,
) -> int:
    """Run the robustness campaign with a progress bar on stderr; 130 if interrupted."""
    from tautwire.experiments.robustness import reproduce_robustness
    from tautwire.experiments.table1 import Progress as CampaignProgress

    if address is not None and backend != "ray":
        raise InvalidArgumentError("--address is for --backend ray only")
    err = Console(stderr=True)
    with Progress(*_progress_columns(), console=err) as bar:
        task = bar.add_task(f"robustness ({backend})", total=None, failed=0)

        def show(state: CampaignProgress) -> None:
            bar.update(task, completed=state.finished, total=state.planned, failed=state.failures)

        report = reproduce_robustness(
            trials,
            workers,
            seed,
            out,
            backend,
            show,
            faults=faults,
            address=address,
            trial_timeout=trial_timeout if backend == "local" else None,
        )
    if as_json:
        click.echo(json.dumps(report, indent=2))
    else:
        Console().print(_robustness_table(report))
        Console().print(f"written under {out}/")
    if report["interrupted"]:
        click.echo(
            f"tautwire: interrupted: {report['finished']} of {report['planned']} trials "
            f"finished; their results are written under {out}/",
            err=True,
        )
        return 130
    return 0


def _robustness_table(report: dict[str, Any]) -> Table:
    """The robustness figures as a rich table: clean runs, fault runs, each fault type."""
    table = Table(
        title=f"Robustness: {report['finished']} of {report['planned']} trials, "
        f"{report['wall_time']:.1f} s on {report['workers']} workers ({report['backend']})"
    )
    columns = (
        "runs",
        "n",
        "success",
        "clean",
        "false succ.",
        "force > limit",
        "contact err. median [mm]",
        "k_hat within 10 %",
        "NEES cov.",
        "causes",
    )
    for column in columns:
        table.add_column(column, justify="left" if column in ("runs", "causes") else "right")

    def pct(x: float | None) -> str:
        return "-" if x is None else f"{100 * x:.0f} %"

    rows = [("no fault", report)]
    if report["faulty"] is not None:
        rows.append(("one fault", report["faulty"]))
        rows += [(f"  {k}", f) for k, f in report["per_fault"].items()]
    for label, f in rows:
        median = f["contact_error"]["median"]
        table.add_row(
            label,
            str(f["runs"]),
            pct(f["success_rate"]),
            pct(f["clean_rate"]),
            str(f["false_successes"]),
            str(f["over_force_limit"]),
            "-" if median is None else f"{1e3 * median:.1f}",
            pct(f["k_hat_within_10pct"]),
            pct(f["nees"]["coverage"]),
            ", ".join(f"{c} {n}" for c, n in f["causes"].items()) or "-",
        )
    return table


def _robustness_only(only: str, seed: int, as_json: bool, *, faults: bool) -> int:
    """Rerun single trials of the robustness campaign with ``seed``; print their runs."""
    from tautwire.experiments.robustness import parse_indices, rerun_robustness

    indices = parse_indices(only)
    with Console(stderr=True).status(f"rerunning {only} ..."):
        runs = rerun_robustness(indices, seed, faults=faults)
    if as_json:
        click.echo(json.dumps({"seed": seed, "runs": runs}, indent=2))
        return 0
    out = Console()
    for r in runs:
        run = r["half"] if r["fault"] is None else f"fault {r['fault']} at {r['fault_at']:.2f} s"
        outcome = ("success" if r["success"] else "failure") + (
            f" ({r['cause']})" if r["cause"] else ""
        )
        error = r["contact_error"] if r["contact_estimated"] else None
        ratio = "-" if r["k_ratio"] is None else f"{r['k_ratio']:.2f}"
        out.print(
            f"trial {r['trial']} seed {r['seed']} {r['fixture_type']}, {run}: {outcome}, "
            f"{'clean' if r['clean'] else 'not clean'}, contact error "
            f"{'-' if error is None else f'{1e3 * error:.1f} mm'}, k_hat/k "
            f"{ratio}, "
            f"true max force {r['true_max_force']:.2f} N"
        )
        out.print(f"  {r['detail']}")
    return 0


def _table1_table(report: dict[str, Any]) -> Table:
    """The summary of a Table I report as a rich table."""
    table = Table(
        title=f"Table I: {report['finished']} of {report['planned']} trials, "
        f"{report['wall_time']:.1f} s on {report['workers']} workers ({report['backend']})"
    )
    for column in ("primitive", "trials", "failed", "causes", "max force [N]", "paper"):
        table.add_column(column, justify="left" if column in ("primitive", "causes") else "right")
    total = {"name": "Total", "letter": "", **report["total"]}
    for row in [*report["primitives"], total]:
        causes = ", ".join(f"{c} {n}" for c, n in row["causes"].items()) or "-"
        force = "-" if row["max_force"] is None else f"{row['max_force']:.1f}"
        table.add_row(
            f"{row['letter']} {row['name']}".strip(),
            str(row["trials"]),
            str(row["failures"]),
            causes,
            force,
            f"{row['paper_failures']}/{row['paper_trials']}",
        )
    return table


def _table1_only(only: str, seed: int, as_json: bool) -> int:
    """Rerun single trials of the Table I campaign with ``seed``; print their results."""
    from tautwire.experiments.table1 import parse_only, rerun_trials

    specs = parse_only(only, seed)
    with Console(stderr=True).status(f"rerunning {only} ..."):
        results = rerun_trials(specs)
    if as_json:
        click.echo(json.dumps({"seed": seed, "trials": [r.to_dict() for r in results]}, indent=2))
        return 0
    out = Console()
    for r in results:
        outcome = r.outcome + (f" ({r.cause})" if r.cause else "")
        out.print(
            f"{r.letter}:{r.index} {r.name} seed {r.seed}: {outcome}, "
            f"max force {r.max_force:.2f} N, {r.sim_time:.1f} s simulated in {r.wall_time:.1f} s"
        )
        out.print(f"  {r.detail}")
        out.print(f"  inputs: {json.dumps(r.inputs)}")
    return 0
