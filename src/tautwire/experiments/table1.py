"""Table I: reliability of the nine primitives over randomised trials.

The paper ran each primitive 15 to 25 times with random fixture placements,
gripper start poses, cable stiffness and length, and counted the failed
trials (4 in 155). :func:`reproduce_table1` runs ``trials`` randomised
trials of each primitive (:func:`~tautwire.experiments.trial.run_trial`, in
parallel, see :mod:`tautwire.experiments.campaign`) and writes under the
output folder:

``table1_trials.csv``
    Every trial, one row each, written as trials finish (an interrupted
    campaign keeps them; ``resume=True`` reuses them).
``table1.md``
    The table in the paper's layout beside the paper's numbers, then one line
    per failed trial with the command that reruns it.
``table1.json``
    The same summary as data.
``table1_logs/worker-N.log``
    What each local worker printed (simulator warnings), a header per trial.

Each trial's seed is :func:`~tautwire.experiments.trial.trial_seed` of the
campaign's seed, the letter and the index, so one trial can be rerun alone
(:func:`rerun_trials`, ``tautwire reproduce table1 --only D:17``).
"""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, NamedTuple

from tautwire.errors import InvalidArgumentError
from tautwire.experiments.campaign import (
    TrialFunction,
    is_trial_outcome,
    result_order,
    run_campaign,
)
from tautwire.experiments.trial import LETTERS, TrialResult, TrialSpec, run_trial, trial_seed
from tautwire.experiments.trials_csv import TrialsCsv, read_trials


@dataclass(frozen=True)
class PaperRow:
    """A row of the paper's Table I.

    Attributes:
        letter: The primitive's letter.
        name: The row's name in the paper.
        trials: The paper's repetitions.
        failures: The paper's failed trials.
    """

    letter: str
    name: str
    trials: int
    failures: int


#: The paper's Table I, in its row order.
PAPER_TABLE: tuple[PaperRow, ...] = (
    PaperRow("A", "Parallel DLO Tension", 25, 2),
    PaperRow("D", "Single arm DLO Tension", 25, 1),
    PaperRow("C", "Parallel DLO Clipping", 15, 1),
    PaperRow("F", "Single arm DLO Clipping", 15, 0),
    PaperRow("B", "Parallel DLO Sliding", 15, 0),
    PaperRow("E", "Single Arm DLO Sliding", 15, 0),
    PaperRow("G", "Gripper Alignment", 15, 0),
    PaperRow("H", "Grasp a Tensioned DLO", 15, 0),
    PaperRow("I", "Rotate Around Feature Point", 15, 0),
)

#: The files :func:`reproduce_table1` writes, by kind.
MD_FILE = "table1.md"
CSV_FILE = "table1_trials.csv"
JSON_FILE = "table1.json"
#: The folder of the local workers' output (one ``worker-N.log`` each).
LOG_DIR = "table1_logs"


class Progress(NamedTuple):
    """The state of a campaign, reported after each trial.

    Attributes:
        finished: Trials finished so far (those reused by a resume included).
        planned: Trials of the whole campaign.
        failures: Failed trials among the finished.
        last: The trial that just finished; None for the first report.
    """

    finished: int
    planned: int
    failures: int
    last: TrialResult | None


#: Receives a :class:`Progress` once before the first trial and after each one.
ProgressCallback = Callable[[Progress], None]


def parse_letters(letters: str | Iterable[str]) -> tuple[str, ...]:
    """Primitive letters from ``"DI"`` (or an iterable), checked, in :data:`LETTERS` order.

    Raises:
        InvalidArgumentError: for an empty selection or a letter outside A-I.
    """
    chosen = {c.strip().upper() for c in letters if c.strip() not in ("", ",")}
    unknown = sorted(chosen - set(LETTERS))
    if unknown:
        raise InvalidArgumentError(
            f"no primitive letter {', '.join(unknown)} (expected letters among {''.join(LETTERS)})"
        )
    if not chosen:
        raise InvalidArgumentError(
            f"no primitive letters given (expected some of {''.join(LETTERS)})"
        )
    return tuple(c for c in LETTERS if c in chosen)


def parse_only(text: str, seed: int) -> list[TrialSpec]:
    """The trials named by ``"D:17"`` or ``"D:17,I:3"``, with the campaign ``seed``'s seeds.

    Raises:
        InvalidArgumentError: for text that is not LETTER:INDEX[,LETTER:INDEX...].
    """
    specs: list[TrialSpec] = []
    for item in (part.strip() for part in text.split(",")):
        letter, sep, index = item.partition(":")
        letter = letter.strip().upper()
        if not sep or letter not in LETTERS or not index.strip().isdigit():
            raise InvalidArgumentError(
                f"cannot read trial {item!r} (expected LETTER:INDEX like D:17, "
                f"letters among {''.join(LETTERS)})"
            )
        specs.append(TrialSpec(letter, int(index), trial_seed(seed, letter, int(index))))
    return specs


def table1_specs(trials: int, seed: int, letters: Iterable[str] = LETTERS) -> list[TrialSpec]:
    """``trials`` trials of each primitive in ``letters``, seeded from the campaign ``seed``.

    Raises:
        InvalidArgumentError: for ``trials < 1`` or an unknown letter.
    """
    if trials < 1:
        raise InvalidArgumentError(f"trials must be at least 1, got {trials}")
    return [
        TrialSpec(letter, index, trial_seed(seed, letter, index))
        for letter in parse_letters(letters)
        for index in range(trials)
    ]


def _causes(results: Sequence[TrialResult]) -> dict[str, int]:
    counts = Counter(r.cause or "unknown" for r in results if not r.success)
    return dict(sorted(counts.items()))


def summarise(results: Sequence[TrialResult], letters: Iterable[str]) -> list[dict[str, Any]]:
    """One summary per primitive of ``letters``, in the paper's row order.

    Each has the paper's ``name``, ``letter``, ``trials``, ``failures``,
    ``causes`` (failures by cause), ``max_force`` (the largest over the
    trials [N], None without trials) and the paper's ``paper_trials`` and
    ``paper_failures``.
    """
    chosen = set(letters)
    rows = []
    for paper in PAPER_TABLE:
        if paper.letter not in chosen:
            continue
        mine = [r for r in results if r.letter == paper.letter]
        rows.append(
            {
                "name": paper.name,
                "letter": paper.letter,
                "trials": len(mine),
                "failures": sum(1 for r in mine if not r.success),
                "causes": _causes(mine),
                "max_force": max((r.max_force for r in mine), default=None),
                "paper_trials": paper.trials,
                "paper_failures": paper.failures,
            }
        )
    return rows


def _total(rows: Sequence[dict[str, Any]]) -> dict[str, Any]:
    causes: Counter[str] = Counter()
    for row in rows:
        causes.update(row["causes"])
    forces = [row["max_force"] for row in rows if row["max_force"] is not None]
    return {
        "trials": sum(row["trials"] for row in rows),
        "failures": sum(row["failures"] for row in rows),
        "causes": dict(sorted(causes.items())),
        "max_force": max(forces, default=None),
        "paper_trials": sum(row["paper_trials"] for row in rows),
        "paper_failures": sum(row["paper_failures"] for row in rows),
    }


def _cell(text: object) -> str:
    """Text safe inside a Markdown table cell."""
    return str(text).replace("\n", " ").replace("|", "\\|")


def _causes_text(causes: dict[str, int]) -> str:
    return ", ".join(f"{cause} {n}" for cause, n in causes.items()) or "-"


def _force_text(force: float | None) -> str:
    return "-" if force is None else f"{force:.1f}"


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


def table1_markdown(report: dict[str, Any]) -> str:
    """The Markdown page of a :func:`reproduce_table1` report."""
    lines = [
        "# Table I: reliability of the manipulation primitives, randomised trials",
        "",
        f"Seed {report['seed']}, {_count(report['trials_per_primitive'], 'trial')} per primitive, "
        f"backend {report['backend']} with {_count(report['workers'], 'worker')}, "
        f"wall time {report['wall_time']:.1f} s; "
        f"{report['finished']} of {report['planned']} trials finished"
        + (f" ({report['resumed']} reused from an earlier run)" if report["resumed"] else "")
        + ".",
        "",
    ]
    if report["interrupted"]:
        lines += [
            f"**Interrupted**: the rows count the {report['finished']} finished trials only.",
            "",
        ]
    lines += [
        "| Motion primitive | Letter | Repetitions | Failed trials | Failure causes "
        "| Max force [N] | Paper: repetitions | Paper: failed trials |",
        "|---|:-:|--:|--:|---|--:|--:|--:|",
    ]
    total = report["total"]
    for row in [*report["primitives"], {"name": "**Total**", "letter": "", **total}]:
        lines.append(
            f"| {row['name']} | {row['letter']} | {row['trials']} | {row['failures']} "
            f"| {_causes_text(row['causes'])} | {_force_text(row['max_force'])} "
            f"| {row['paper_trials']} | {row['paper_failures']} |"
        )
    failed = report["failed_trials"]
    lines += ["", f"## Failed trials ({len(failed)})", ""]
    if failed:
        example = failed[0]
        lines += [
            "Rerun one trial alone with "
            f"`tautwire reproduce table1 --seed {report['seed']} "
            f"--only {example['letter']}:{example['index']}`; "
            f"its randomised inputs are in `{CSV_FILE}`"
            + (
                f", what the simulator printed in `{LOG_DIR}/` (a header line per trial)."
                if report["backend"] == "local"
                else "."
            ),
            "",
            "| Letter | Index | Seed | Cause | Detail |",
            "|:-:|--:|--:|---|---|",
        ]
        lines += [
            f"| {f['letter']} | {f['index']} | {f['seed']} | {_cell(f['cause'])} "
            f"| {_cell(f['detail'])} |"
            for f in failed
        ]
    else:
        lines.append("None.")
    return "\n".join(lines) + "\n"


def _report(
    results: Sequence[TrialResult],
    *,
    letters: Sequence[str],
    trials: int,
    seed: int,
    planned: int,
    resumed: int,
    interrupted: bool,
    backend: str,
    workers: int,
    wall_time: float,
) -> dict[str, Any]:
    rows = summarise(results, letters)
    return {
        "primitives": rows,
        "total": _total(rows),
        "failed_trials": [
            {
                "letter": r.letter,
                "index": r.index,
                "seed": r.seed,
                "cause": r.cause,
                "detail": r.detail,
            }
            for r in results
            if not r.success
        ],
        "wall_time": round(wall_time, 3),
        "trials_wall_time": round(sum(r.wall_time for r in results), 3),
        "workers": workers,
        "backend": backend,
        "seed": seed,
        "trials_per_primitive": trials,
        "letters": "".join(letters),
        "finished": len(results),
        "planned": planned,
        "resumed": resumed,
        "interrupted": interrupted,
    }


def _reusable(path: Path, specs: Sequence[TrialSpec]) -> list[TrialResult]:
    """The trials of ``specs`` already in the CSV file at ``path`` (for a resume).

    Raises:
        InvalidArgumentError: when the file holds one of these trials with
            another seed (it belongs to another campaign).
    """
    if not path.exists():
        return []
    wanted = {(s.letter, s.index): s for s in specs}
    found: dict[tuple[str, int], TrialResult] = {}
    for result in read_trials(path):
        spec = wanted.get((result.letter, result.index))
        if spec is None:
            continue
        if result.seed != spec.seed:
            raise InvalidArgumentError(
                f"{path} holds trial {result.letter}:{result.index} with seed {result.seed}, "
                f"not {spec.seed}: it is another campaign's (another --seed); "
                "drop --resume or choose another --out"
            )
        if is_trial_outcome(result):  # a crashed, hung or internal-error trial reruns
            found[(result.letter, result.index)] = result
    return sorted(found.values(), key=result_order)


def reproduce_table1(
    trials: int = 100,
    workers: int = 2,
    seed: int = 0,
    out_dir: str | Path = "out/table1",
    backend: str = "local",
    letters: Iterable[str] = LETTERS,
    progress: ProgressCallback | None = None,
    *,
    address: str | None = None,
    resume: bool = False,
    trial_timeout: float | None = None,
    trial: TrialFunction = run_trial,
) -> dict[str, Any]:
    """Run the Table I campaign; write table1.md, table1_trials.csv and table1.json.

    Args:
        trials: Trials per primitive.
        workers: Trials at a time (see :func:`~tautwire.experiments.campaign.run_campaign`).
        seed: The campaign's seed; each trial's seed derives from it.
        out_dir: The output folder (created).
        backend: ``"local"``, ``"serial"`` or ``"ray"``.
        letters: The primitives to run (default all nine).
        progress: Called before the first trial and after each trial.
        address: A Ray cluster's address (``ray`` backend only).
        resume: Reuse the trials of this campaign already in the output
            folder's CSV file (an earlier, interrupted run) instead of
            rerunning them; rows of other trials in it are dropped, and so
            are trials that crashed, hung or raised an internal error
            (:data:`~tautwire.experiments.campaign.INFRASTRUCTURE_CAUSES`):
            those run again.
        trial_timeout: ``local`` only: wall time [s] after which a trial is
            stopped and recorded as failed with cause ``"hung"``.
        trial: The trial function (tests pass fakes).

    Returns:
        The report, as written to table1.json: per primitive (paper's row
        order) the trials, failures, failures by cause and largest force
        [N], beside the paper's numbers; the total; every failed trial; wall
        time [s], workers, backend, seed; ``finished`` of ``planned``
        trials, and ``interrupted`` if Ctrl-C stopped it (the files then
        hold the finished trials).

    Raises:
        InvalidArgumentError: for bad arguments, or a resume over another
            campaign's file.
        CampaignError: when the backend cannot run.
    """
    chosen = parse_letters(letters)
    specs = table1_specs(trials, seed, chosen)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    csv_path = out / CSV_FILE
    reused = _reusable(csv_path, specs) if resume else []
    done = {(r.letter, r.index) for r in reused}
    todo = [s for s in specs if (s.letter, s.index) not in done]

    logs = out / LOG_DIR
    if not resume:
        for old in logs.glob("worker-*.log"):
            old.unlink()
    trials_file = TrialsCsv(csv_path, reused)
    state = Progress(len(reused), len(specs), sum(1 for r in reused if not r.success), None)

    def on_result(result: TrialResult) -> None:
        nonlocal state
        trials_file.append(result)
        state = Progress(
            state.finished + 1,
            state.planned,
            state.failures + (0 if result.success else 1),
            result,
        )
        if progress is not None:
            progress(state)

    try:
        if progress is not None:
            progress(state)
        campaign = run_campaign(
            todo,
            trial,
            backend=backend,
            workers=workers,
            address=address,
            on_result=on_result,
            log_dir=logs if backend == "local" else None,
            trial_timeout=trial_timeout,
        )
    finally:
        trials_file.close()
    results = sorted([*reused, *campaign.results], key=result_order)
    trials_file.results = list(results)
    trials_file.finish()
    report = _report(
        results,
        letters=chosen,
        trials=trials,
        seed=seed,
        planned=len(specs),
        resumed=len(reused),
        interrupted=campaign.interrupted,
        backend=backend,
        workers=campaign.workers,
        wall_time=campaign.wall_time,
    )
    (out / JSON_FILE).write_text(json.dumps(report, indent=2) + "\n")
    (out / MD_FILE).write_text(table1_markdown(report))
    return report


def rerun_trials(specs: Sequence[TrialSpec], trial: TrialFunction = run_trial) -> list[TrialResult]:
    """Run the given trials one after the other in this process (no files written)."""
    return list(run_campaign(specs, trial, backend="serial").results)
