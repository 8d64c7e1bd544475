"""The robustness campaign: randomised single-fixture scenes, clean and with one fault.

Each trial draws a scene over the whole envelope
(:func:`~tautwire.experiments.robustness_scene.draw_scene`: anchor or peg,
any grasp yaw, any stiffness and length, long rotations), runs D then I on
it once clean and, with faults on, once more with one random fault inside
the run (:func:`~tautwire.experiments.robustness_scene.draw_fault`), and
scores both runs against the simulator's truth
(:mod:`tautwire.experiments.truth`). Trials run through the campaign
machinery (:func:`~tautwire.experiments.campaign.run_campaign`: local worker
processes or Ray; a crash is a recorded failure).

What a run counts as:

success
    Every step reported success and the simulator agrees with each
    (``false_successes`` is 0).
clean
    A success whose model found the fixture: the fixture's point carries a
    filter estimate within tolerance (3 mm of an anchor, the radius + 3 mm
    of a peg's axis point at the cable's height), no point is made up, and
    every trusted estimate is within tolerance.
over the force limit
    The force the cable truly exerted on the gripper (noise-free, every
    control period) went above the scenario's limit (15 N).
k_hat error
    |k_hat / k - 1| at the end of a successful D, k the spring constant the
    gripper truly pulls against, measured in the simulator over D's last
    set-point swing (:meth:`StepWatch.measured_stiffness`: from an anchor
    k L / L_s; round a peg the cable slides or sticks as its friction
    decides). ``k_nominal`` in the CSV is k L / L_s.
NEES coverage
    Over every contact filter iteration after convergence (largest std at
    most the estimator's trusted_std, 10 mm), the fraction whose error is
    within 3 reported std on every axis (pooled over the runs).

Written under the output folder: ``robustness.json`` (the figures, clean
at the top level, ``faulty`` over every fault run and ``per_fault`` by fault
type), ``robustness.md`` (the table, then the runs that were not clean),
``robustness_trials.csv`` (every run: inputs, fault, outcome, errors and
each step's detail),
``robustness_error_vs_yaw.png`` and ``robustness_stiffness.png``.
"""

from __future__ import annotations

import csv
import json
import math
import os
import time
from collections import Counter
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from tautwire.errors import InvalidArgumentError
from tautwire.experiments.campaign import run_campaign
from tautwire.experiments.robustness_scene import FAULT_TYPES, FORCE_LIMIT, draw_fault, draw_scene
from tautwire.experiments.table1 import Progress, ProgressCallback
from tautwire.experiments.trial import TrialResult, TrialSpec, trial_seed

#: The campaign's letter in its trial specs and seeds (not a primitive's).
LETTER = "R"
JSON_FILE = "robustness.json"
MD_FILE = "robustness.md"
CSV_FILE = "robustness_trials.csv"
YAW_PLOT = "robustness_error_vs_yaw.png"
STIFFNESS_PLOT = "robustness_stiffness.png"
LOG_DIR = "robustness_logs"
#: A k_hat within this relative error of the truth counts as right.
K_TOLERANCE = 0.10


@dataclass(frozen=True)
class RobustnessTrial(TrialResult):
    """A trial of the campaign: the clean run and the fault run, each scored.

    The :class:`TrialResult` fields describe the clean run; ``runs`` holds
    one flat, JSON-ready record per run (see :func:`score_run`).
    """

    runs: tuple[dict[str, Any], ...] = ()


def _first_failure(steps: list[dict[str, Any]]) -> dict[str, Any] | None:
    return next((s for s in steps if s["outcome"] != "success"), None)


def score_run(scene: Any, result: Any, half: str, fault: dict[str, Any] | None) -> dict[str, Any]:
    """One run's record: inputs, fault, outcome, truth, errors.

    Args:
        scene: The :class:`RobustnessScene`.
        result: The run's :class:`RunResult` (with its audit).
        half: ``"clean"`` or ``"fault"``.
        fault: The fault entry (with ``kind``) for a fault run.
    """
    audit = result.audit
    steps = result.steps
    failed = _first_failure(steps)
    false_step = next(
        (s for s in steps if s["outcome"] == "success" and not s["truth"]["agrees"]), None
    )
    target = next((c for c in audit.contacts if c.fixture == scene.fixture), None)
    made_up = [c for c in audit.contacts if c.made_up]
    wrong_trusted = [c for c in audit.contacts if c.trusted and not c.made_up and not c.within]
    estimated = target is not None and target.std is not None
    contact_ok = estimated and target is not None and target.within
    clean = bool(result.success and contact_ok and not made_up and not wrong_trusted)
    tension = audit.watches[0] if audit.watches else None
    k_hat = None if tension is None else tension.k_hat
    k_true = None if tension is None else tension.measured_stiffness()
    k_nominal = None if tension is None else tension.edge_stiffness
    ratio = k_hat / k_true if k_hat is not None and k_true else None
    converged = [s for s in audit.samples if s.trusted]
    if result.success:
        cause = None
    elif failed is not None:
        cause = failed["cause"] or "error"
    else:
        cause = "false_success"
    if failed is not None:
        detail = f"{failed['letter']}: {failed['detail']}"
    elif false_step is not None:
        detail = f"{false_step['letter']} reported success; truth: {false_step['truth']['detail']}"
    else:
        detail = "; ".join(f"{s['letter']}: {s['truth']['detail']}" for s in steps)
    record: dict[str, Any] = {
        "half": half,
        "fault": None if fault is None else fault["kind"],
        "fault_at": None if fault is None else round(float(fault["at"]), 4),
        "fault_entry": None
        if fault is None
        else json.dumps({k: v for k, v in fault.items() if k != "kind"}),
        "fixture_type": scene.fixture_type,
        "reported_success": bool(steps)
        and failed is None
        and len(steps) == len(scene.data["task"]),
        "tension_success": bool(steps) and steps[0]["outcome"] == "success",
        "success": bool(result.success),
        "clean": clean,
        "cause": cause,
        "failed_step": None if failed is None else failed["letter"],
        "detail": detail,
        "steps": " | ".join(
            f"{s['letter']}: {s['outcome']}"
            + (f" ({s['cause']})" if s.get("cause") else "")
            + f": {s['detail']}"
            for s in steps
        ),
        "false_successes": int(result.false_successes),
        "max_force": float(result.max_force),
        "true_max_force": float(result.true_max_force),
        "over_force_limit": bool(result.true_max_force > FORCE_LIMIT),
        "contact_estimated": estimated,
        "contact_error": None if target is None or target.error is None else float(target.error),
        "contact_tolerance": None
        if target is None or target.tolerance is None
        else float(target.tolerance),
        "contact_std": None if target is None or target.std is None else float(np.max(target.std)),
        "contact_within": bool(contact_ok),
        "made_up": len(made_up),
        "wrong_trusted": len(wrong_trusted),
        "k_hat": k_hat,
        "k_true": k_true,
        "k_nominal": k_nominal,
        "k_ratio": ratio,
        "nees_samples": len(converged),
        "nees_within": sum(1 for s in converged if s.within_3std),
        "sim_time": float(result.sim_time),
        "wall_time": float(result.wall_time),
    }
    return record


def _failed_run(
    half: str, fault: dict[str, Any] | None, scene: Any, cause: str, detail: str
) -> dict[str, Any]:
    """The record of a run that raised (no result to score)."""
    return {
        "half": half,
        "fault": None if fault is None else fault["kind"],
        "fault_at": None if fault is None else round(float(fault["at"]), 4),
        "fault_entry": None
        if fault is None
        else json.dumps({k: v for k, v in fault.items() if k != "kind"}),
        "fixture_type": None if scene is None else scene.fixture_type,
        "reported_success": False,
        "tension_success": False,
        "success": False,
        "clean": False,
        "cause": cause,
        "failed_step": None,
        "detail": detail,
        "steps": "",
        "false_successes": 0,
        "max_force": 0.0,
        "true_max_force": 0.0,
        "over_force_limit": False,
        "contact_estimated": False,
        "contact_error": None,
        "contact_tolerance": None,
        "contact_std": None,
        "contact_within": False,
        "made_up": 0,
        "wrong_trusted": 0,
        "k_hat": None,
        "k_true": None,
        "k_nominal": None,
        "k_ratio": None,
        "nees_samples": 0,
        "nees_within": 0,
        "sim_time": 0.0,
        "wall_time": 0.0,
    }


def _run(scene: Any, seed: int, half: str, fault: dict[str, Any] | None) -> dict[str, Any]:
    """Simulate one half of a trial; an exception is a failed run, never raised."""
    from tautwire.experiments.run_scenario import run_scenario

    try:
        entry = None if fault is None else [{k: v for k, v in fault.items() if k != "kind"}]
        result, _, _ = run_scenario(scene.scenario(entry), seed)
    except Exception as exc:  # a campaign keeps every other run
        cause = getattr(exc, "cause", None) or "error"
        return _failed_run(half, fault, scene, str(cause), f"{type(exc).__name__}: {exc}")
    return score_run(scene, result, half, fault)


@dataclass(frozen=True)
class RobustnessTrialFunction:
    """The campaign's trial function (picklable, for worker processes and Ray).

    Attributes:
        faults: Whether to run the fault half of each trial.
    """

    faults: bool = True

    def __call__(self, spec: TrialSpec) -> TrialResult:
        """Run the clean half, then (with faults) the fault half; a crash is a failed run."""
        t0 = time.perf_counter()
        try:
            scene = draw_scene(spec.seed)
        except Exception as exc:
            detail = f"the scene could not be drawn: {type(exc).__name__}: {exc}"
            runs = [_failed_run("clean", None, None, "error", detail)]
            return RobustnessTrial(
                LETTER,
                "robustness",
                spec.index,
                spec.seed,
                {},
                "failure",
                "error",
                detail,
                wall_time=time.perf_counter() - t0,
                runs=tuple(runs),
            )
        runs = [_run(scene, spec.seed, "clean", None)]
        if self.faults:
            fault = draw_fault(spec.seed, max(runs[0]["sim_time"], 0.5))
            runs.append(_run(scene, spec.seed, "fault", fault))
        clean = runs[0]
        return RobustnessTrial(
            LETTER,
            "robustness",
            spec.index,
            spec.seed,
            dict(scene.inputs),
            "success" if clean["success"] else "failure",
            clean["cause"],
            clean["detail"],
            clean["max_force"],
            clean["sim_time"],
            time.perf_counter() - t0,
            runs=tuple(runs),
        )


def runs_of(result: TrialResult, faults: bool) -> list[dict[str, Any]]:
    """The run records of a finished trial, with its index, seed and inputs.

    A trial that crashed or hung (a plain :class:`TrialResult` from the
    campaign) counts as failed runs with its cause.
    """
    if isinstance(result, RobustnessTrial) and result.runs:
        runs = list(result.runs)
    else:  # the scene and the fault's type follow from the seed alone
        try:
            scene: Any = draw_scene(result.seed)
        except Exception:
            scene = None
        cause = result.cause or "error"
        runs = [_failed_run("clean", None, scene, cause, result.detail)]
        if faults:
            fault = draw_fault(result.seed, 1.0)
            runs.append(_failed_run("fault", fault, scene, cause, result.detail))
            runs[-1]["fault_at"] = None  # drawn from the clean run's time, which is unknown
    inputs = result.inputs
    if not inputs and not isinstance(result, RobustnessTrial):
        try:
            inputs = dict(draw_scene(result.seed).inputs)
        except Exception:
            inputs = {}
    out = []
    for run in runs:
        row = {"trial": result.index, "seed": result.seed, **run}
        row.update({f"input.{k}": v for k, v in inputs.items()})
        out.append(row)
    return out


def _quantiles(values: Sequence[float]) -> dict[str, float | int | None]:
    if not values:
        return {"n": 0, "median": None, "p90": None, "max": None}
    a = np.asarray(values, dtype=float)
    return {
        "n": len(values),
        "median": float(np.median(a)),
        "p90": float(np.quantile(a, 0.9)),
        "max": float(np.max(a)),
    }


def figures(runs: Sequence[dict[str, Any]]) -> dict[str, Any]:
    """The campaign's figures over ``runs`` (see the module docstring)."""
    n = len(runs)

    def rate(count: int) -> float | None:
        return None if n == 0 else count / n

    successes = sum(1 for r in runs if r["success"])
    clean = sum(1 for r in runs if r["clean"])
    errors = [
        r["contact_error"]
        for r in runs
        if r["contact_estimated"] and r["contact_error"] is not None
    ]
    beyond = [
        r["contact_error"] / r["contact_tolerance"]
        for r in runs
        if r["contact_estimated"] and r["contact_error"] is not None and r["contact_tolerance"]
    ]
    # the stiffness D reports: only where D succeeded (a failed D may end before learning)
    k_errors = [
        abs(r["k_ratio"] - 1.0) for r in runs if r["k_ratio"] is not None and r["tension_success"]
    ]
    samples = sum(int(r["nees_samples"]) for r in runs)
    within = sum(int(r["nees_within"]) for r in runs)
    causes = Counter(r["cause"] or "unknown" for r in runs if not r["success"])
    return {
        "runs": n,
        "successes": successes,
        "success_rate": rate(successes),
        "reported_successes": sum(1 for r in runs if r["reported_success"]),
        "clean": clean,
        "clean_rate": rate(clean),
        "false_successes": sum(int(r["false_successes"]) for r in runs),
        "runs_with_false_successes": sum(1 for r in runs if r["false_successes"]),
        "over_force_limit": sum(1 for r in runs if r["over_force_limit"]),
        "true_max_force": max((float(r["true_max_force"]) for r in runs), default=None),
        "contact_estimated": sum(1 for r in runs if r["contact_estimated"]),
        "contact_error": _quantiles(errors),
        "contact_error_over_tolerance": _quantiles(beyond),
        "made_up_points": sum(int(r["made_up"]) for r in runs),
        "runs_with_made_up_points": sum(1 for r in runs if r["made_up"]),
        "k_hat_error": _quantiles(k_errors),
        "k_hat_within_10pct": None
        if not k_errors
        else sum(1 for e in k_errors if e <= K_TOLERANCE) / len(k_errors),
        "nees": {
            "samples": samples,
            "within_3std": within,
            "coverage": None if samples == 0 else within / samples,
        },
        "causes": dict(sorted(causes.items())),
    }


def summarise(rows: Sequence[dict[str, Any]], **about: Any) -> dict[str, Any]:
    """The report: clean figures at the top level, ``faulty`` and ``per_fault`` beside."""
    clean = [r for r in rows if r["half"] == "clean"]
    faulty = [r for r in rows if r["half"] == "fault"]
    kinds = [k for k in FAULT_TYPES if any(r["fault"] == k for r in faulty)]
    return {
        "trials": len(clean),
        **figures(clean),
        "faulty": figures(faulty) if faulty else None,
        "per_fault": {k: figures([r for r in faulty if r["fault"] == k]) for k in kinds},
        "per_fixture": {
            t: figures([r for r in clean if r["fixture_type"] == t])
            for t in ("anchor", "peg")
            if any(r["fixture_type"] == t for r in clean)
        },
        **about,
    }


def _pct(x: float | None) -> str:
    return "-" if x is None else f"{100 * x:.0f} %"


def _mm(q: dict[str, Any], key: str) -> str:
    v = q[key]
    return "-" if v is None else f"{1e3 * v:.1f}"


def _row(name: str, f: dict[str, Any]) -> str:
    ce, ke = f["contact_error"], f["k_hat_error"]
    causes = ", ".join(f"{c} {n}" for c, n in f["causes"].items()) or "-"
    return (
        f"| {name} | {f['runs']} | {_pct(f['success_rate'])} | {_pct(f['clean_rate'])} "
        f"| {f['false_successes']} | {f['over_force_limit']} "
        f"| {_mm(ce, 'median')} / {_mm(ce, 'p90')} / {_mm(ce, 'max')} ({ce['n']}) "
        f"| {_pct(ke['median'])} / {_pct(ke['p90'])} | {_pct(f['k_hat_within_10pct'])} "
        f"| {_pct(f['nees']['coverage'])} ({f['nees']['samples']}) "
        f"| {f['runs_with_made_up_points']} | {causes} |"
    )


def robustness_markdown(report: dict[str, Any], rows: Sequence[dict[str, Any]]) -> str:
    """The Markdown page of a campaign's report."""
    lines = [
        "# Robustness: single-fixture scenes over the whole envelope",
        "",
        f"Seed {report['seed']}, {report['trials']} trials "
        f"({'each clean and with one fault' if report['faults'] else 'clean only'}), "
        f"backend {report['backend']} with {report['workers']} workers, "
        f"wall time {report['wall_time']:.1f} s; {report['finished']} of {report['planned']} "
        "trials finished.",
        "",
        "Success: every step reported success and the simulator agrees. Clean: a success whose "
        "model estimated the fixture within tolerance (3 mm anchor, radius + 3 mm peg), with no "
        "made-up point. Contact error of the runs with an estimate; k_hat error "
        "|k_hat/k - 1| at the end of a successful D; NEES coverage: contact filter iterations "
        "after convergence within 3 std on every axis.",
        "",
        "| runs | n | success | clean | false successes | true force > limit "
        "| contact error median / p90 / max [mm] (n) | k_hat error median / p90 "
        "| k_hat within 10 % | NEES coverage (samples) | runs with made-up points "
        "| failures by cause |",
        "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|",
        _row("no fault", report),
    ]
    for t, f in report["per_fixture"].items():
        lines.append(_row(f"no fault, {t}", f))
    if report["faulty"] is not None:
        lines.append(_row("one fault", report["faulty"]))
        for kind, f in report["per_fault"].items():
            lines.append(_row(f"fault: {kind}", f))
    bad = [r for r in rows if not r["clean"]]
    lines += ["", f"## Runs that were not clean ({len(bad)})", ""]
    if bad:
        lines += [
            f"Rerun one trial alone with `tautwire reproduce robustness --seed {report['seed']} "
            f"--only {bad[0]['trial']}`; its inputs are in `{CSV_FILE}`.",
            "",
            "| trial | run | fixture | yaw to cable [deg] | k [N/m] | outcome | cause "
            "| contact error [mm] (- no estimate) | detail |",
            "|--:|---|---|--:|--:|---|---|--:|---|",
        ]
        for r in bad:
            yaw = r.get("input.tool_yaw_to_cable")
            err = r["contact_error"] if r["contact_estimated"] else None
            run = r["half"] if r["fault"] is None else f"fault {r['fault']}"
            detail = str(r["detail"]).replace("|", "\\|").replace("\n", " ")
            lines.append(
                f"| {r['trial']} | {run} | {r['fixture_type']} "
                f"| {'-' if yaw is None else f'{math.degrees(float(yaw)):.0f}'} "
                f"| {_num(r.get('input.stiffness'))} | {'success' if r['success'] else 'failure'} "
                f"| {r['cause'] or '-'} | {'-' if err is None else f'{1e3 * err:.1f}'} | {detail} |"
            )
    else:
        lines.append("None.")
    return "\n".join(lines) + "\n"


def _num(v: Any) -> str:
    return "-" if v is None or v == "" else f"{float(v):.0f}"


def write_csv(path: Path, rows: Sequence[dict[str, Any]]) -> None:
    """Every run, one row each, columns in order of first appearance (atomic rewrite)."""
    columns: list[str] = []
    for r in rows:
        columns += [k for k in r if k not in columns]
    partial = path.with_name(path.name + ".partial")
    with partial.open("w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=columns or ["trial"], restval="")
        writer.writeheader()
        writer.writerows(rows)
    os.replace(partial, path)


def robustness_specs(trials: int, seed: int, only: Sequence[int] | None = None) -> list[TrialSpec]:
    """The campaign's trials (or those of ``only``), seeded from the campaign ``seed``.

    Raises:
        InvalidArgumentError: for ``trials < 1`` or a negative index.
    """
    if trials < 1:
        raise InvalidArgumentError(f"trials must be at least 1, got {trials}")
    indices = range(trials) if only is None else only
    if any(i < 0 for i in indices):
        raise InvalidArgumentError(f"trial indices must be >= 0, got {list(indices)}")
    return [TrialSpec(LETTER, i, trial_seed(seed, LETTER, i)) for i in indices]


@dataclass
class _Collector:
    """Streams each finished trial's runs to the CSV file and the progress callback."""

    path: Path
    faults: bool
    planned: int
    progress: ProgressCallback | None
    rows: list[dict[str, Any]] = field(default_factory=list)
    finished: int = 0
    failures: int = 0

    def __call__(self, result: TrialResult) -> None:
        self.rows += runs_of(result, self.faults)
        self.rows.sort(key=lambda r: (r["trial"], r["half"] != "clean"))
        write_csv(self.path, self.rows)
        self.finished += 1
        self.failures += 0 if result.success else 1
        if self.progress is not None:
            self.progress(Progress(self.finished, self.planned, self.failures, result))


def reproduce_robustness(
    trials: int = 200,
    workers: int = 2,
    seed: int = 0,
    out_dir: str | Path = "out/robustness",
    backend: str = "local",
    progress: ProgressCallback | None = None,
    *,
    faults: bool = True,
    address: str | None = None,
    trial_timeout: float | None = None,
    only: Sequence[int] | None = None,
    plots: bool = True,
    trial: Callable[[TrialSpec], TrialResult] | None = None,
) -> dict[str, Any]:
    """Run the robustness campaign; write its JSON, Markdown, CSV and plots.

    Args:
        trials: Trials (each one clean run, and one fault run with ``faults``).
        workers: Trials at a time (see :func:`~tautwire.experiments.campaign.run_campaign`).
        seed: The campaign's seed; each trial's seed derives from it and its index.
        out_dir: The output folder (created).
        backend: ``"local"``, ``"serial"`` or ``"ray"``.
        progress: Called before the first trial and after each trial.
        faults: Whether each trial also runs with one random fault.
        address: A Ray cluster's address (``ray`` only).
        trial_timeout: ``local`` only: wall time [s] after which a trial is
            stopped and recorded as failed with cause ``"hung"``.
        only: Run only these trial indices (of the campaign ``seed``).
        plots: Whether to draw the plots.
        trial: The trial function (tests pass fakes); default
            :class:`RobustnessTrialFunction` with ``faults``.

    Returns:
        The report, as written to robustness.json.
    """
    specs = robustness_specs(trials, seed, only)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    logs = out / LOG_DIR
    for old in logs.glob("worker-*.log"):
        old.unlink()
    collect = _Collector(out / CSV_FILE, faults, len(specs), progress)
    if progress is not None:
        progress(Progress(0, len(specs), 0, None))
    campaign = run_campaign(
        specs,
        RobustnessTrialFunction(faults) if trial is None else trial,
        backend=backend,
        workers=workers,
        address=address,
        on_result=collect,
        log_dir=logs if backend == "local" else None,
        trial_timeout=trial_timeout if backend == "local" else None,
    )
    rows = collect.rows
    write_csv(out / CSV_FILE, rows)
    report = summarise(
        rows,
        seed=seed,
        faults=faults,
        backend=campaign.backend,
        workers=campaign.workers,
        wall_time=round(campaign.wall_time, 3),
        finished=campaign.finished,
        planned=campaign.planned,
        interrupted=campaign.interrupted,
        files={"json": JSON_FILE, "markdown": MD_FILE, "csv": CSV_FILE},
    )
    if plots and rows:
        from tautwire.viz.robustness_plots import plot_error_vs_yaw, plot_stiffness

        plot_error_vs_yaw(rows, out / YAW_PLOT)
        plot_stiffness(rows, out / STIFFNESS_PLOT)
        report["files"].update({"error_vs_yaw": YAW_PLOT, "stiffness": STIFFNESS_PLOT})
    (out / JSON_FILE).write_text(json.dumps(report, indent=2) + "\n")
    (out / MD_FILE).write_text(robustness_markdown(report, rows))
    return report


def parse_indices(text: str) -> list[int]:
    """Trial indices from ``"17"`` or ``"3,17"``.

    Raises:
        InvalidArgumentError: for text that is not INDEX[,INDEX...].
    """
    out = []
    for item in (part.strip() for part in text.split(",")):
        if not item.isdigit():
            raise InvalidArgumentError(
                f"cannot read trial {item!r} (expected trial indices like 17 or 3,17)"
            )
        out.append(int(item))
    return out


def rerun_robustness(
    indices: Sequence[int], seed: int, *, faults: bool = True
) -> list[dict[str, Any]]:
    """Run the given trials of campaign ``seed`` in this process; their run records (no files)."""
    specs = [TrialSpec(LETTER, i, trial_seed(seed, LETTER, i)) for i in indices]
    campaign = run_campaign(specs, RobustnessTrialFunction(faults), backend="serial")
    return [row for result in campaign.results for row in runs_of(result, faults)]
