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
from rich.text import Text

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
#: The harness campaign by default: boards run at a time.
HARNESS_WORKERS = 2
#: Wall time [s] after which a harness board is stopped as hung (a board takes minutes).
HARNESS_TRIAL_TIMEOUT = 1800.0
#: The campaigns, which take the campaign options (--trials, --workers, ...).
CAMPAIGNS = ("table1", "robustness", "harness")

#: What can be reproduced so far, by name (besides the campaigns, which take more options).
REPRODUCTIONS: dict[str, Callable[[Path, int], dict[str, Any]]] = {
    "fig5a": _fig5a,
    "fig5b": _fig5b,
    "fig5c": _fig5c,
}


EPILOG = """\b
Examples:
  tautwire reproduce fig5a                      # Fig. 5a: a table in N, fig5a.png under out/fig5a/
  tautwire reproduce fig5c --out out/c --json   # one JSON object on stdout
  tautwire reproduce table1 --trials 20 --workers 2
  tautwire reproduce table1 --resume            # finish an interrupted campaign
  tautwire reproduce table1 --only D:17         # rerun one trial and print it
  tautwire reproduce robustness --trials 40 --no-faults
  tautwire reproduce harness                    # the harness board: figure, GIF, steps, JSON
  tautwire reproduce harness --boards 10 --workers 2 --seed 0
  tautwire reproduce harness --boards 10 --seed 0 --resume   # finish a campaign that stopped

\b
Without --json, a table (lengths in mm, forces in N) on stdout and the
files under --out; a campaign shows a progress bar on stderr.
"""


@click.command(epilog=EPILOG)
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
    help="table1, harness --boards: reuse the trials of the same campaign already in the "
    "output folder (those that crashed, hung or raised an internal error run again)",
)
@click.option(
    "--no-faults",
    is_flag=True,
    help="robustness: run each trial clean only (no fault run)",
)
@click.option(
    "--boards",
    type=click.IntRange(min=1),
    default=None,
    help="harness: run this many random boards instead of the built-in one",
)
@click.option(
    "--steps",
    type=click.IntRange(min=1),
    default=None,
    help="harness --boards: run only each board's first N planned steps (a quick look: "
    "its routes are then not done)",
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
    boards: int | None,
    steps: int | None,
) -> int:
    """Regenerate the paper's figure or table NAME (fig5a-c, table1, harness), or robustness.

    robustness runs the campaign of randomised single-fixture scenes, each
    trial clean and with one fault, scored against the simulator's truth.
    harness runs the paper's harness experiment on the built-in board, or
    with --boards N a campaign of N random boards.
    """
    if name not in REPRODUCTIONS and name not in CAMPAIGNS:
        raise InvalidArgumentError(
            f"no reproduction named {name!r}; available: {', '.join([*REPRODUCTIONS, *CAMPAIGNS])}"
        )
    out = Path(out_dir) if out_dir is not None else Path("out") / name
    if boards is not None and name != "harness":
        raise InvalidArgumentError(f"--boards: only for harness, not {name}")
    if steps is not None and name != "harness":
        raise InvalidArgumentError(f"--steps: only for harness --boards, not {name}")
    if name == "harness":
        others = {
            "--trials": trials,
            "--letters": letters,
            "--only": only,
            "--no-faults": no_faults or None,
        }
        given = [option for option, value in others.items() if value is not None]
        if given:
            raise InvalidArgumentError(f"{', '.join(given)}: not for harness")
        if boards is None:
            campaign_only = {
                "--workers": workers,
                "--backend": backend,
                "--address": address,
                "--trial-timeout": trial_timeout,
                "--steps": steps,
                "--resume": resume or None,
            }
            given = [option for option, value in campaign_only.items() if value is not None]
            if given:
                raise InvalidArgumentError(f"{', '.join(given)}: only with --boards")
            return _harness(out, seed, as_json)
        return _harness_boards(
            out,
            seed,
            as_json,
            boards=boards,
            workers=HARNESS_WORKERS if workers is None else workers,
            backend=backend or "local",
            address=address,
            trial_timeout=HARNESS_TRIAL_TIMEOUT if trial_timeout is None else trial_timeout,
            steps=steps,
            resume=resume,
        )
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
        Console().print(FIGURE_TABLES[name](result))
        Console().print(f"written under {out}/ (the figure, its data as CSV, {name}.json)")
    return 0


def _add_row(table: Table, *cells: str) -> None:
    """A row of plain text (a unit such as [mm] is not read as rich markup)."""
    table.add_row(*(Text(cell) for cell in cells))


def _mm(metres: float | None) -> str:
    """A length [m] in mm, or "-"."""
    return "-" if metres is None else f"{1e3 * metres:.2f}"


def _num(value: float | None, digits: int = 3) -> str:
    """A number, or "-"."""
    return "-" if value is None else f"{value:.{digits}f}"


def _run_caption(run: dict[str, Any]) -> str:
    """The simulated run's outcome under a figure's table."""
    outcome = "success" if run.get("success") else "failure"
    false = run.get("false_successes") or []
    force = run.get("true_max_force")
    parts = [f"run: {outcome}", f"{len(false)} false success(es)"]
    if force is not None:
        parts.append(f"true max force {force:.2f} N")
    return ", ".join(parts)


def fig5a_table(result: dict[str, Any]) -> Table:
    """Fig. 5a's cases as a table: tension errors [N] and k_hat [N/m] per stiffness."""
    table = Table(
        title=Text(
            f"Fig. 5a: primitive D at {result['set_point']:g} N, k unknown "
            f"(errors after {result['settle']:g} s)"
        )
    )
    for column in (
        "k [N/m]",
        "controller",
        "tracking RMS [N]",
        "hold RMS [N]",
        "tension RMS [N]",
        "max force [N]",
        "k_hat [N/m]",
        "learning [s]",
        "outcome",
    ):
        table.add_column(
            Text(column), justify="left" if column in ("controller", "outcome") else "right"
        )
    for case in [*result["cases"], *result["baseline"]]:
        _add_row(
            table,
            f"{case['stiffness']:g}",
            case["controller"],
            _num(case["tracking_rms_error"]),
            _num(case["hold_rms_error"]),
            _num(case["tension_rms_error"]),
            _num(case["max_force"], 2),
            _num(case["k_hat_final"], 1),
            _num(case["learn_time"], 2),
            case["outcome"],
        )
    return table


def fig5b_table(result: dict[str, Any]) -> Table:
    """Fig. 5b's figures as a table: the contact error and std [mm] after the rotation."""
    table = Table(title=Text("Fig. 5b: contact estimation while rotating about an anchor"))
    table.add_column(Text("quantity"))
    table.add_column(Text("value"), justify="right")
    std = result["final_std"]
    rows = [
        ("filter iterations", str(result["iterations"])),
        ("iterations per circle", str(result["iterations_per_circle"])),
        ("estimation period [s]", _num(result["estimation_period"])),
        ("final contact error [mm]", _mm(result["final_error"])),
        ("final std x, y, z [mm]", "-" if std is None else ", ".join(_mm(v) for v in std)),
        ("corr(speed x, decrease of std x)", _num(result["corr_speed_x_vs_std_x_decrease"], 2)),
    ]
    for row in rows:
        table.add_row(*(Text(cell) for cell in row))
    table.caption = Text(_run_caption(result["run"]))
    return table


def fig5c_table(result: dict[str, Any]) -> Table:
    """Fig. 5c's figures as a table: the contact change and the errors [mm] around it."""
    table = Table(title=Text("Fig. 5c: contact estimation through a change of contact"))
    table.add_column(Text("quantity"))
    table.add_column(Text("value"), justify="right")
    declared = result["declared_changes"]
    rows = [
        ("contact error half a circle in [mm]", _mm(result["error_half_circle"])),
        ("true change at iteration", str(result["true_change_iteration"])),
        ("declared changes at iterations", ", ".join(map(str, declared)) or "none"),
        ("declared after the true change [iterations]", str(result["change_declared_after"])),
        ("peak error after the true change [mm]", _mm(result["peak_error_after_change"])),
        ("peak error after the declared change [mm]", _mm(result["peak_error_after_declared"])),
        ("iterations to <= 2 mm after the change", str(result["samples_to_2mm_after_change"])),
        ("final contact error [mm]", _mm(result["final_error"])),
        ("final fixture", str(result["final_fixture"])),
    ]
    for row in rows:
        table.add_row(*(Text(cell) for cell in row))
    table.caption = Text(_run_caption(result["run"]))
    return table


#: The table printed (without ``--json``) for each figure.
FIGURE_TABLES: dict[str, Callable[[dict[str, Any]], Table]] = {
    "fig5a": fig5a_table,
    "fig5b": fig5b_table,
    "fig5c": fig5c_table,
}


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
            f"tautwire: error: interrupted: {report['finished']} of {report['planned']} trials "
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
            f"tautwire: error: interrupted: {report['finished']} of {report['planned']} trials "
            f"finished; their results are written under {out}/",
            err=True,
        )
        return 130
    return 0


def _harness(out: Path, seed: int, as_json: bool) -> int:
    """Run the built-in harness board; print its steps and errors (or the JSON)."""
    from tautwire.experiments.harness import reproduce_harness

    with Console(stderr=True).status("reproducing harness (the built-in board) ..."):
        report = reproduce_harness(out, seed)
    if as_json:
        click.echo(json.dumps(report, indent=2))
    else:
        Console().print(_harness_table(report))
        Console().print(f"written under {out}/")
    return 0


def _harness_table(report: dict[str, Any]) -> Table:
    """model_error and shape_error beside the paper's numbers, and the run's outcome."""
    table = Table(
        title=f"harness {report['board']} (seed {report['seed']}): "
        f"{'success' if report['success'] else 'failure'}, "
        f"{report['false_successes']} false successes, {len(report['steps'])} steps"
    )
    for column in ("[mm]", "paper (model)", "goal (model)", "model_error", "shape_error"):
        table.add_column(column, justify="right" if column != "[mm]" else "left")
    for key in ("horizontal_mean", "horizontal_max", "vertical_mean", "vertical_max"):
        _add_row(
            table,
            key.replace("_", " "),
            _mm(report["paper"]["model_error"][key]),
            _mm(report["goal"]["model_error"][key]),
            _mm((report["model_error"] or {}).get(key)),
            _mm((report["shape_error"] or {}).get(key)),
        )
    return table


def _harness_boards(
    out: Path,
    seed: int,
    as_json: bool,
    *,
    boards: int,
    workers: int,
    backend: str,
    address: str | None,
    trial_timeout: float,
    steps: int | None = None,
    resume: bool = False,
) -> int:
    """Run the random-board campaign with a progress bar on stderr; 130 if interrupted."""
    from tautwire.experiments.harness import reproduce_harness_boards

    if address is not None and backend != "ray":
        raise InvalidArgumentError("--address is for --backend ray only")
    err = Console(stderr=True)
    with Progress(*_progress_columns(), console=err) as bar:
        task = bar.add_task(f"harness boards ({backend})", total=boards, failed=0)

        def show(finished: int, planned: int, failures: int) -> None:
            bar.update(task, completed=finished, total=planned, failed=failures)

        report = reproduce_harness_boards(
            boards,
            workers,
            seed,
            out,
            backend,
            show,
            address=address,
            trial_timeout=trial_timeout if backend == "local" else None,
            steps=steps,
            resume=resume,
        )
    if as_json:
        click.echo(json.dumps(report, indent=2))
    else:
        table = Table(
            title=f"harness: {report['completed']} of {report['boards']} boards completed, "
            f"{report['false_successes']} false successes, {report['over_force_limit']} over "
            f"the force limit, {report['wall_time']:.0f} s"
            + (f" ({report['resumed']} boards reused)" if report["resumed"] else "")
        )
        for column in ("[mm]", "model median", "model p90", "shape median", "shape p90"):
            table.add_column(column, justify="right" if column != "[mm]" else "left")
        for key in ("horizontal_mean", "horizontal_max", "vertical_mean", "vertical_max"):
            m, s = report["model_error"][key], report["shape_error"][key]
            _add_row(
                table,
                key.replace("_", " "),
                _mm(m["median"]),
                _mm(m["p90"]),
                _mm(s["median"]),
                _mm(s["p90"]),
            )
        Console().print(table)
        Console().print(f"written under {out}/")
    if report["interrupted"]:
        click.echo(
            f"tautwire: error: interrupted: {report['boards']} of {report['planned']} boards "
            f"finished; their results are written under {out}/",
            err=True,
        )
        return 130
    return 0


def _robustness_table(report: dict[str, Any]) -> Table:
    """The robustness figures as a rich table: clean runs, fault runs, each fault type."""
    table = Table(
        title=Text(
            f"Robustness: {report['finished']} of {report['planned']} trials, "
            f"{report['wall_time']:.1f} s on {report['workers']} workers ({report['backend']})"
        )
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
        table.add_column(Text(column), justify="left" if column in ("runs", "causes") else "right")

    def pct(x: float | None) -> str:
        return "-" if x is None else f"{100 * x:.0f} %"

    rows = [("no fault", report)]
    if report["faulty"] is not None:
        rows.append(("one fault", report["faulty"]))
        rows += [(f"  {k}", f) for k, f in report["per_fault"].items()]
    for label, f in rows:
        median = f["contact_error"]["median"]
        _add_row(
            table,
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
        title=Text(
            f"Table I: {report['finished']} of {report['planned']} trials, "
            f"{report['wall_time']:.1f} s on {report['workers']} workers ({report['backend']})"
        )
    )
    for column in ("primitive", "trials", "failed", "causes", "max force [N]", "paper"):
        table.add_column(
            Text(column), justify="left" if column in ("primitive", "causes") else "right"
        )
    total = {"name": "Total", "letter": "", **report["total"]}
    for row in [*report["primitives"], total]:
        causes = ", ".join(f"{c} {n}" for c, n in row["causes"].items()) or "-"
        force = "-" if row["max_force"] is None else f"{row['max_force']:.1f}"
        _add_row(
            table,
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
