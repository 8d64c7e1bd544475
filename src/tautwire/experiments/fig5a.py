"""Fig. 5a: adaptive tensioning (primitive D) of cables of 10, 100 and 1000 N/m.

The controller does not know k: its initial guess is off by a factor of ten
(too soft: the direction the paper's failures came from). Each cable is
tensioned for ``DURATION`` s by primitive D with the adaptive
inverse-damping controller (k_f = lambda / k_hat, k_hat learnt online), and
again with a fixed-gain controller (the baseline, k_f tuned for 100 N/m).
Both run D as designed: its set point swings by +-20 % while it learns k
(the excitation that makes a stiff cable's k observable), then by +-5 %
while it holds. So each case reports three errors, as fractions of the
2 N set point:

- ``tracking_rms_error``: the true tension against D's set point f_d(t),
  after ``SETTLE`` s: how well the controller follows what it is told;
- ``hold_rms_error``: the true tension against the constant 2 N in D's
  hold phase (after learning), which includes the +-5 % swing;
- ``tension_rms_error``: against the constant 2 N after ``SETTLE`` s,
  including the learning swing.
"""

from __future__ import annotations

import csv
import json
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np

from tautwire.control import FixedGainForceController
from tautwire.primitives import SingleArmTension
from tautwire.scenario import Scenario
from tautwire.scenario.loader import scenario_from_data
from tautwire.sim.build import build_world, robot_of, truth_of
from tautwire.tasks import TickRecord, run_step
from tautwire.tasks.initial_model import initial_context

STIFFNESSES = (10.0, 100.0, 1000.0)
SET_POINT = 2.0  # N
SETTLE = 2.0  # s: the errors are measured after this
DURATION = 8.0  # s


def tension_scenario(stiffness: float, seed: int = 0) -> Scenario:
    """An anchor and a 0.5 m cable held taut-ish by the left gripper along +x."""
    return scenario_from_data(
        {
            "version": 1,
            "name": f"fig5a-k{stiffness:g}",
            "seed": seed,
            "robot": {
                "force_limit": 15.0,
                "sensor": {"arm": "left", "noise_force": 0.05},
                "grippers": {
                    "left": {"position": [0.495, 0.0, 0.1]},
                    "right": {"position": [0.3, -0.45, 0.35]},
                },
            },
            "board": {"fixtures": [{"name": "A1", "type": "anchor", "position": [0.0, 0.0, 0.1]}]},
            "cables": [
                {
                    "name": "W1",
                    "length": 0.5,
                    "mass_per_length": 0.03,
                    "stiffness": stiffness,
                    "radius": 0.0025,
                    "start": "A1",
                    "held_by": {"arm": "left", "at": 0.5},
                }
            ],
            "task": [{"primitive": "D", "arm": "left", "force": SET_POINT}],
        }
    )


@dataclass
class Fig5aCase:
    """One cable, one controller."""

    stiffness: float
    controller: str
    tracking_rms_error: float  # against D's set point f_d(t), after SETTLE
    hold_rms_error: float | None  # against SET_POINT in the hold phase
    tension_rms_error: float  # against SET_POINT after SETTLE (with the learning swing)
    max_force: float  # N, largest measured force
    k_hat_final: float | None  # N/m (adaptive only)
    learn_time: float | None  # s, D's learning phase
    outcome: str


def run_case(
    stiffness: float, adaptive: bool, seed: int = 0
) -> tuple[Fig5aCase, dict[str, list[float]]]:
    """Tension one cable for DURATION s; return the figures and the series."""
    scenario = tension_scenario(stiffness, seed)
    world = build_world(scenario)
    robot = robot_of(world)
    truth = truth_of(world)
    ctx = initial_context(scenario, k_initial=stiffness / 10.0)
    if not adaptive:
        ctx.controller.force = FixedGainForceController(k_f=5.0 / 100.0)
    series: dict[str, list[float]] = {
        "t": [],
        "tension": [],
        "true_tension": [],
        "set_point": [],
        "hold": [],
        "k_hat": [],
    }
    step = SingleArmTension("left", SET_POINT, duration=DURATION)

    def record(rec: TickRecord) -> None:
        state = ctx.estimator.state
        if state is None:
            return
        series["t"].append(rec.observation.time)
        series["tension"].append(state.tension)
        series["true_tension"].append(float(np.median(truth.tensions("W1"))))
        series["set_point"].append(step.set_point(step.elapsed))
        series["hold"].append(float(step.phase == "hold"))
        series["k_hat"].append(ctx.estimator.elasticity.k_hat)

    report = run_step(robot, step, ctx, on_tick=record)
    t = np.asarray(series["t"])
    true_t = np.asarray(series["true_tension"])
    late = t >= t[0] + SETTLE if t.size else np.zeros(0, bool)
    hold = np.asarray(series["hold"]) > 0.5

    def rms(error: np.ndarray, where: np.ndarray) -> float:
        return float(np.sqrt(np.mean(error[where] ** 2)) / SET_POINT)

    case = Fig5aCase(
        stiffness,
        "adaptive" if adaptive else "fixed-gain",
        rms(true_t - np.asarray(series["set_point"]), late) if late.any() else float("nan"),
        rms(true_t - SET_POINT, hold) if hold.any() else None,
        rms(true_t - SET_POINT, late) if late.any() else float("nan"),
        report.max_force,
        ctx.estimator.elasticity.k_hat if adaptive else None,
        step.learn_time,
        report.outcome,
    )
    return case, series


def reproduce_fig5a(out_dir: str | Path, seed: int = 0) -> dict[str, Any]:
    """Run all cases; write fig5a.png, fig5a.csv and fig5a.json under ``out_dir``."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    default = SingleArmTension("left", SET_POINT)  # D's own excitation
    excitation, learn_excitation = default.excitation, default.learn_excitation
    cases = []
    rows = []
    fig = Figure(figsize=(8, 6), layout="constrained")  # no pyplot: the backend is left alone
    FigureCanvasAgg(fig)
    ax_e, ax_k = fig.subplots(2, 1, sharex=True)
    colours = {10.0: "tab:blue", 100.0: "tab:orange", 1000.0: "tab:green"}
    for k in STIFFNESSES:
        for adaptive in (True, False):
            case, s = run_case(k, adaptive, seed)
            cases.append(case)
            t = np.asarray(s["t"]) - (s["t"][0] if s["t"] else 0.0)
            err = np.asarray(s["true_tension"]) - np.asarray(s["set_point"])
            style = "-" if adaptive else ":"
            ax_e.plot(t, err, style, color=colours[k], lw=1.1, label=f"{k:g} N/m {case.controller}")
            if adaptive:
                ax_k.plot(t, s["k_hat"], color=colours[k], lw=1.2, label=f"k_hat ({k:g} N/m)")
                ax_k.axhline(k, color=colours[k], ls="--", lw=0.8)
            for i in range(len(t)):
                rows.append(
                    [
                        k,
                        case.controller,
                        t[i],
                        s["tension"][i],
                        s["true_tension"][i],
                        s["set_point"][i],
                        s["k_hat"][i],
                    ]
                )
    ax_e.axhline(0.0, color="k", lw=0.6)
    ax_e.set_ylabel("tension - set point f_d(t) [N]")
    ax_e.set_title(
        f"Fig. 5a: primitive D, {SET_POINT:g} N (swing +-{100 * learn_excitation:g} % learning,"
        f" +-{100 * excitation:g} % holding), k unknown (guess k/10)"
    )
    ax_e.legend(fontsize=7, ncols=2)
    ax_k.set_yscale("log")
    ax_k.set_ylabel("k_hat [N/m]")
    ax_k.set_xlabel("time [s]")
    ax_k.legend(fontsize=7)
    for ax in (ax_e, ax_k):
        ax.grid(alpha=0.3)
    fig.savefig(out / "fig5a.png", dpi=120)
    with (out / "fig5a.csv").open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(
            [
                "stiffness",
                "controller",
                "t",
                "measured_tension",
                "true_tension",
                "set_point",
                "k_hat",
            ]
        )
        w.writerows(rows)
    result = {
        "set_point": SET_POINT,
        "settle": SETTLE,
        "excitation": excitation,
        "learn_excitation": learn_excitation,
        "cases": [asdict(c) for c in cases if c.controller == "adaptive"],
        "baseline": [asdict(c) for c in cases if c.controller == "fixed-gain"],
    }
    (out / "fig5a.json").write_text(json.dumps(result, indent=2) + "\n")
    return result
