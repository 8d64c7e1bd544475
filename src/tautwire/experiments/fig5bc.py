"""Fig. 5b and 5c: contact estimation while rotating around a feature point (I).

5b: the gripper circles an anchor with the cable taut; the contact filter
runs about 125 iterations per circle; the uncertainty along x is plotted
against the gripper's velocity along x (the paper's persistence of
excitation). 5c: as 5b, but a peg placed in the cable's path takes over as
the contact mid-run; estimation error and uncertainty per axis, the true and
the declared change marked.
"""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from tautwire.experiments.run_scenario import run_scenario
from tautwire.scenario import Scenario, load_scenario
from tautwire.scenario.registry import scenario_path
from tautwire.sim.ground_truth import GroundTruth
from tautwire.sim.world import SimWorld
from tautwire.tasks import StepReport, TickRecord

ITERATIONS_PER_CIRCLE = 125
MAX_LINEAR_SPEED = 0.09  # m/s: primitive I's speed within the 0.1 m/s limit


def _estimation_period(scenario: Scenario) -> float:
    """Filter period [s] giving ~125 iterations a circle at I's actual speed."""
    cable = scenario.cables[0]
    radius = cable.length  # the gripper circles at about the cable's length
    speed = min(float(scenario.task[-1].params.get("speed", 0.3)), MAX_LINEAR_SPEED / radius)  # type: ignore[arg-type]
    return 2.0 * math.pi / speed / ITERATIONS_PER_CIRCLE


def record_rotation(
    scenario: Scenario,
    seed: int | None = None,
    on_time: Callable[[float], None] | None = None,
    on_world: Callable[[SimWorld], None] | None = None,
    on_tick: Callable[[TickRecord], None] | None = None,
    on_step: Callable[[int, StepReport], None] | None = None,
    on_truth: Callable[[GroundTruth], None] | None = None,
) -> dict[str, Any]:
    """Run ``scenario`` (D then I) and record every contact-filter iteration of I.

    Args:
        scenario: A scenario whose task is D then I.
        seed: Overrides the scenario's seed.
        on_time: Called every control period with the time [s] (progress, video).
        on_world: Called once with the simulated world (rendering).
        on_tick: Passed on to :func:`run_scenario` (recording).
        on_step: Passed on to :func:`run_scenario`.
        on_truth: Called once with the ground truth (recording; never fed back).
    """
    series: dict[str, list[Any]] = {
        "iteration": [],
        "t": [],
        "estimate": [],
        "std": [],
        "truth": [],
        "truth_fixture": [],
        "gripper": [],
    }
    state: dict[str, Any] = {"last": -1, "truth": None}

    def tick(rec: TickRecord) -> None:
        if on_time is not None:
            on_time(rec.observation.time)
        if on_tick is not None:
            on_tick(rec)
        est = rec.context.estimator
        if rec.primitive.letter != "I" or est.iterations == state["last"]:
            return
        state["last"] = est.iterations
        kf = est.contact_filter
        truth = state["truth"]
        p = rec.observation.gripper(est.arm).position
        contacts = truth.contacts() if truth is not None else ()
        nearest = None
        if contacts:
            # the gripper's edge is taut against the contact last along the cable
            line = truth.polyline(contacts[0].cable)

            def along(c: Any) -> int:
                return int(np.argmin(np.linalg.norm(line - c.point, axis=1)))

            nearest = max(contacts, key=along)
        series["iteration"].append(est.iterations)
        series["t"].append(rec.observation.time)
        series["estimate"].append(None if kf.estimate is None else kf.estimate.tolist())
        series["std"].append(None if kf.std is None else kf.std.tolist())
        series["truth"].append(None if nearest is None else nearest.point.tolist())
        series["truth_fixture"].append(None if nearest is None else nearest.fixture)
        series["gripper"].append(p.tolist())

    period = _estimation_period(scenario)

    def keep_truth(truth: GroundTruth) -> None:  # for scoring only
        state["truth"] = truth
        if on_truth is not None:
            on_truth(truth)

    result, ctx, _ = run_scenario(
        scenario,
        seed,
        estimation_period=period,
        on_tick=tick,
        on_truth=keep_truth,
        on_world=on_world,
        on_step=on_step,
    )
    first = series["iteration"][0] if series["iteration"] else 0
    # a change declared at filter iteration c shows from the record of iteration c + 1 on
    declared = [c + 1 - first for c in ctx.estimator.changes if c + 1 >= first]
    return {"series": series, "result": result.to_dict(), "changes": declared, "period": period}


def series_arrays(
    series: dict[str, list[Any]],
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Iteration index, estimate, std and truth of a recorded rotation, NaN where missing."""
    n = len(series["iteration"])
    est = np.full((n, 3), np.nan)
    std = np.full((n, 3), np.nan)
    truth = np.full((n, 3), np.nan)
    for i in range(n):
        if series["estimate"][i] is not None:
            est[i], std[i] = series["estimate"][i], series["std"][i]
        if series["truth"][i] is not None:
            truth[i] = series["truth"][i]
    return np.arange(n), est, std, truth


def _write_csv(path: Path, series: dict[str, list[Any]]) -> None:
    k, est, std, truth = series_arrays(series)
    grip = np.asarray(series["gripper"])
    with path.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(
            [
                "iteration",
                "t",
                "ex",
                "ey",
                "ez",
                "sx",
                "sy",
                "sz",
                "tx",
                "ty",
                "tz",
                "truth_fixture",
                "gx",
                "gy",
                "gz",
            ]
        )
        for i in k:
            w.writerow(
                [
                    i,
                    series["t"][i],
                    *est[i],
                    *std[i],
                    *truth[i],
                    series["truth_fixture"][i],
                    *grip[i],
                ]
            )


def reproduce_fig5b(out_dir: str | Path, seed: int = 0) -> dict[str, Any]:
    """Fig. 5b on the shipped scenario ``anchor-rotate``; writes fig5b.png/csv/json."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    run = record_rotation(load_scenario(scenario_path("anchor-rotate")), seed)
    s = run["series"]
    k, est, std, truth = series_arrays(s)
    t = np.asarray(s["t"])
    grip = np.asarray(s["gripper"])
    vx = np.gradient(grip[:, 0], t) if len(t) > 2 else np.zeros(len(t))
    fig = Figure(figsize=(8, 4), layout="constrained")  # no pyplot: the backend is left alone
    FigureCanvasAgg(fig)
    ax = fig.subplots()
    ax.plot(k, 1e3 * std[:, 0], color="tab:red", label="uncertainty std_x [mm]")
    ax2 = ax.twinx()
    ax2.plot(k, -vx, color="tab:blue", lw=1.0, label="-v_x [m/s] (mirrored, as the paper)")
    ax.set_yscale("log")
    ax.set_xlabel("estimator iteration")
    ax.set_ylabel("std_x [mm]")
    ax2.set_ylabel("-v_x [m/s]")
    ax.set_title(
        "Fig. 5b: uncertainty along x vs gripper velocity along x"
        f" (~{ITERATIONS_PER_CIRCLE} iterations a circle)"
    )
    ax.legend(loc="upper left", fontsize=8)
    ax2.legend(loc="upper right", fontsize=8)
    ax.grid(alpha=0.3)
    fig.savefig(out / "fig5b.png", dpi=120)
    _write_csv(out / "fig5b.csv", s)
    err = np.linalg.norm(est - truth, axis=1)
    valid = ~np.isnan(std[:, 0])
    # persistence of excitation: std_x falls fastest where |v_x| is large
    dstd = np.diff(np.log(std[:, 0]))
    ok = valid[1:] & valid[:-1] & np.isfinite(dstd)
    corr = float(np.corrcoef(np.abs(vx[1:][ok]), dstd[ok])[0, 1]) if ok.sum() > 3 else float("nan")
    result = {
        "iterations": len(k),
        "iterations_per_circle": ITERATIONS_PER_CIRCLE,
        "estimation_period": run["period"],
        "final_error": float(err[valid][-1]) if valid.any() else None,
        "final_std": std[valid][-1].tolist() if valid.any() else None,
        "corr_speed_x_vs_std_x_decrease": corr,
        "run": run["result"],
    }
    (out / "fig5b.json").write_text(json.dumps(result, indent=2) + "\n")
    return result


def reproduce_fig5c(out_dir: str | Path, seed: int = 0) -> dict[str, Any]:
    """Fig. 5c on the shipped scenario ``peg-change``; writes fig5c.png/csv/json."""
    from tautwire.viz.contact_estimation_plot import plot_contact_estimation

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    run = record_rotation(load_scenario(scenario_path("peg-change")), seed)
    s = run["series"]
    k, est, std, truth = series_arrays(s)
    fixtures = s["truth_fixture"]
    true_change = next((i for i in range(1, len(fixtures)) if fixtures[i] != fixtures[i - 1]), None)
    declared = run["changes"]
    plot_contact_estimation(
        out / "fig5c.png",
        k,
        est - truth,
        std,
        changes=[c for c in [true_change, *declared[:1]] if c is not None],
        title="Fig. 5c: contact error and uncertainty; dashed: true change, then declared",
        error_limit_mm=20.0,
    )
    _write_csv(out / "fig5c.csv", s)
    err = np.linalg.norm(est - truth, axis=1)
    half = ITERATIONS_PER_CIRCLE // 2
    after = [d - true_change for d in declared if true_change is not None and d >= true_change - 5]
    settled = None
    if true_change is not None:
        e = err[true_change:]
        below = [i for i in range(len(e)) if np.all(e[i : i + 10] <= 0.002)]
        settled = below[0] if below else None
    result = {
        "error_half_circle": float(err[half]) if len(err) > half else None,
        "true_change_iteration": true_change,
        "declared_changes": declared,
        "change_declared_after": after[0] if after else None,
        "peak_error_after_change": float(np.nanmax(err[true_change:]))
        if true_change is not None
        else None,
        "peak_error_after_declared": (float(np.nanmax(err[declared[0] :])) if declared else None),
        "samples_to_2mm_after_change": settled,
        "final_error": float(err[-1]) if len(err) else None,
        "final_within_3std": bool(
            len(err) and np.all(np.abs(est[-1] - truth[-1]) <= 3.0 * std[-1])
        ),
        "final_fixture": fixtures[-1] if fixtures else None,
        "run": run["result"],
    }
    (out / "fig5c.json").write_text(json.dumps(result, indent=2) + "\n")
    return result
