"""Plots of the robustness campaign: contact error against grasp yaw, k_hat/k against k.

Each takes the campaign's run records (:func:`tautwire.experiments.robustness.runs_of`)
and writes one PNG through Matplotlib's Agg canvas (no pyplot, no global backend).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

#: Marker per fixture type, colour per run kind.
MARKERS = {"anchor": "o", "peg": "s"}
COLOURS = {"clean": "tab:blue", "fault": "tab:orange"}
#: How the legends name the two runs of a trial.
HALVES = {"clean": "no fault", "fault": "one fault"}
#: Where runs without an estimate are drawn on the error plot (error / tolerance).
NO_ESTIMATE = 300.0


def _save(fig: Figure, path: str | Path) -> Path:
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    FigureCanvasAgg(fig)
    fig.savefig(out, dpi=120)
    return out


def plot_error_vs_yaw(runs: Sequence[dict[str, Any]], path: str | Path) -> Path:
    """Contact error over its tolerance against the gripper's start yaw to the cable.

    x: the angle [deg] from the direction fixture -> gripper to the tool's
    x-axis at the start (0: tool x along the cable, +-180: pointing at the
    fixture). y: the final contact error over its tolerance (3 mm; a peg's
    radius + 3 mm), log scale; 1 is the tolerance. Runs whose model has no
    estimate of the fixture sit on the top line; filled markers are
    successes, open ones failures.
    """
    fig = Figure(figsize=(9, 5), constrained_layout=True)
    ax = fig.add_subplot()
    for half, colour in COLOURS.items():
        for fixture, marker in MARKERS.items():
            mine = [
                r
                for r in runs
                if r["half"] == half
                and r["fixture_type"] == fixture
                and r.get("input.tool_yaw_to_cable") not in (None, "")
            ]
            for success in (True, False):
                pts = [r for r in mine if bool(r["success"]) is success]
                xs = [math.degrees(float(r["input.tool_yaw_to_cable"])) for r in pts]
                ys = [
                    float(r["contact_error"]) / float(r["contact_tolerance"])
                    if r["contact_estimated"] and r["contact_error"] is not None
                    else NO_ESTIMATE
                    for r in pts
                ]
                if not xs:
                    continue
                label = f"{HALVES[half]}, {fixture}, {'success' if success else 'failure'}"
                ax.scatter(
                    xs,
                    np.clip(ys, 1e-3, NO_ESTIMATE),
                    marker=marker,
                    s=28,
                    label=label,
                    facecolors=colour if success else "none",
                    edgecolors=colour,
                    linewidths=1.0,
                )
    ax.axhline(1.0, color="k", ls="--", lw=1.0, label="tolerance")
    ax.axhline(NO_ESTIMATE, color="0.6", lw=0.8)
    ax.text(-178, NO_ESTIMATE * 0.75, "no estimate of the fixture", fontsize=8, color="0.4")
    ax.set_yscale("log")
    ax.set_ylim(1e-2, NO_ESTIMATE * 1.5)
    ax.set_xlim(-180, 180)
    ax.set_xticks(range(-180, 181, 45))
    ax.set_xlabel("start yaw of the tool x-axis from the cable (fixture -> gripper) [deg]")
    ax.set_ylabel("contact error / tolerance")
    ax.set_title("Final contact error against the grasp's start yaw")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="lower right", ncols=2)
    return _save(fig, path)


#: The k_hat / k range drawn; a ratio outside it is drawn on the edge, with its value.
K_RATIO_RANGE = (0.5, 2.0)


def plot_stiffness(runs: Sequence[dict[str, Any]], path: str | Path) -> Path:
    """k_hat / k at the end of D against the true k (log x), with the +-10 % band.

    k is the spring constant the gripper truly pulls against, measured in the
    simulator at the end of D; only runs whose D succeeded (the figures' k_hat
    error counts those); filled markers are runs that succeeded, open ones
    runs that failed later. Ratios outside :data:`K_RATIO_RANGE` are drawn
    on its edge with their value written beside them.
    """
    fig = Figure(figsize=(8, 5), constrained_layout=True)
    ax = fig.add_subplot()
    low, high = K_RATIO_RANGE
    for half, colour in COLOURS.items():
        for fixture, marker in MARKERS.items():
            for success in (True, False):
                pts = [
                    r
                    for r in runs
                    if r["half"] == half
                    and r["fixture_type"] == fixture
                    and bool(r["success"]) is success
                    and r["k_ratio"] is not None
                    and r["tension_success"]
                ]
                if not pts:
                    continue
                ax.scatter(
                    [float(r["k_true"]) for r in pts],
                    [min(max(float(r["k_ratio"]), low), high) for r in pts],
                    marker=marker,
                    s=28,
                    label=f"{HALVES[half]}, {fixture}, {'success' if success else 'failure'}",
                    facecolors=colour if success else "none",
                    edgecolors=colour,
                    linewidths=1.0,
                )
    ax.axhspan(0.9, 1.1, color="tab:green", alpha=0.15, label="within 10 %")
    ax.axhline(1.0, color="k", lw=0.8)
    # a ratio off the range sits on its edge, its value written beside it
    for r in runs:
        if r["k_ratio"] is None or not r["tension_success"]:
            continue
        ratio = float(r["k_ratio"])
        if low <= ratio <= high:
            continue
        edge = low if ratio < low else high
        ax.annotate(
            f"{ratio:.2g}",
            (float(r["k_true"]), edge),
            textcoords="offset points",
            xytext=(6, 4 if edge == low else -10),
            fontsize=7,
        )
    ax.set_yscale("log")
    ticks = [0.5, 0.7, 0.9, 1.0, 1.1, 1.4, 2.0]
    ax.set_ylim(low / 1.05, high * 1.05)
    ax.set_yticks([t for t in ticks if low <= t <= high])
    ax.set_yticklabels([f"{t:g}" for t in ticks if low <= t <= high])
    ax.minorticks_off()
    ax.set_xscale("log")
    ax.set_xlim(8.0, 2000.0)
    ax.set_xticks([10, 30, 100, 300, 1000])
    ax.set_xticklabels(["10", "30", "100", "300", "1000"])
    ax.set_xlabel("true stiffness k the gripper pulls against [N/m]")
    ax.set_ylabel("k_hat / k at the end of D")
    ax.set_title("Stiffness estimate against the true stiffness")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="best", ncols=2)
    return _save(fig, path)
