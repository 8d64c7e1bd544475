"""Plots of one simulated run: its time series, and the model over the true cable.

:func:`plot_run` draws, against time, the measured force, the tension the
model estimates against the set point (and the simulator's true tension),
and the contact estimate's error with its reported 3-sigma bound, each
step's start and end marked. :func:`plot_model_views` draws the robot's
path graph over the simulated cable from the top (x-y) and the side (x-z):
feature points coloured by what holds them, the 3-sigma ellipses of their
covariance, and the fixtures in their type's colour with their names.

Figures are :class:`matplotlib.figure.Figure` on the Agg canvas: nothing
here changes the process's matplotlib backend.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Ellipse
from numpy.typing import ArrayLike, NDArray

from tautwire.model import PathGraph
from tautwire.sim.model_overlay import FIXTURE_COLOURS, RGBA, SIGMAS, model_shapes
from tautwire.viz.run_trace import RunTrace, StepMark

FloatArray = NDArray[np.float64]

#: Marker of each fixture type in the views.
FIXTURE_MARKERS = {"anchor": "s", "peg": "o", "clip": "D"}
CABLE_COLOUR = (0.95, 0.55, 0.1)
#: True cables of a run with several, in the scenario's order (the first is ``CABLE_COLOUR``).
TRUE_CABLE_COLOURS = (CABLE_COLOUR, (0.35, 0.7, 0.95), (0.6, 0.8, 0.3), (0.85, 0.45, 0.65))


def _save(fig: Figure, path: str | Path) -> Path:
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    FigureCanvasAgg(fig)
    fig.savefig(out, dpi=110)
    return out


def _mark_steps(axes: Sequence[object], steps: Sequence[StepMark]) -> None:
    for ax in axes:
        for s in steps:
            colour = "k" if s.outcome == "success" else "tab:red"
            ax.axvline(s.start, color=colour, ls="--", lw=0.8)  # type: ignore[attr-defined]
            ax.axvline(s.end, color=colour, ls=":", lw=0.8)  # type: ignore[attr-defined]
    top = axes[0]
    for s in steps:
        top.text(  # type: ignore[attr-defined]
            0.5 * (s.start + s.end),
            1.01,
            f"{s.letter}: {s.outcome}",
            transform=top.get_xaxis_transform(),  # type: ignore[attr-defined]
            ha="center",
            va="bottom",
            fontsize=8,
            color="k" if s.outcome == "success" else "tab:red",
        )


def plot_run(path: str | Path, trace: RunTrace, title: str = "") -> Path:
    """Write a three-panel PNG of the run: force, tension, contact error; steps marked.

    Args:
        path: Output PNG file.
        trace: The run's series.
        title: Figure title.

    Returns:
        The path written.
    """
    t = np.asarray(trace.t, dtype=float)
    f = np.asarray(trace.force, dtype=float).reshape(-1, 3)
    fig = Figure(figsize=(9, 8), constrained_layout=True)
    ax_f, ax_t, ax_e = fig.subplots(3, 1, sharex=True)
    for i, (name, colour) in enumerate(
        zip("xyz", ("tab:red", "tab:green", "tab:blue"), strict=True)
    ):
        ax_f.plot(t, f[:, i], color=colour, lw=0.6, alpha=0.7, label=f"f{name}")
    ax_f.plot(t, np.linalg.norm(f, axis=1), color="k", lw=1.0, label="|f|")
    ax_f.set_ylabel("measured force [N]")
    ax_f.legend(loc="upper right", ncols=4, fontsize=8)
    ax_t.plot(t, trace.tension, color="tab:purple", lw=1.0, label="tension (model)")
    ax_t.plot(t, trace.set_point, color="k", lw=1.2, ls="--", label="set point")
    ti = np.asarray(trace.sample_t, dtype=float)
    if len(ti):
        ax_t.plot(ti, trace.true_tension, color=CABLE_COLOUR, lw=1.0, label="true tension")
    ax_t.set_ylabel("tension [N]")
    ax_t.legend(loc="upper right", ncols=3, fontsize=8)
    if len(ti):
        err = 1e3 * trace.contact_error
        cov = np.asarray(trace.covariance, dtype=float).reshape(-1, 3, 3)
        bound = 1e3 * SIGMAS * np.sqrt(np.max(np.linalg.eigvalsh(cov), axis=1).clip(min=0.0))
        ax_e.plot(ti, err, color="tab:red", lw=1.2, label="|estimate - truth|")
        ax_e.plot(ti, bound, color="0.4", lw=1.0, ls="--", label="3 sigma (largest axis)")
        ax_e.set_yscale("log")
        ax_e.legend(loc="upper right", ncols=2, fontsize=8)
    else:
        ax_e.text(0.5, 0.5, "no contact estimate", ha="center", transform=ax_e.transAxes)
    ax_e.set_ylabel("contact error [mm]")
    ax_e.set_xlabel("time [s]")
    for ax in (ax_f, ax_t, ax_e):
        ax.grid(alpha=0.3)
    _mark_steps((ax_f, ax_t, ax_e), trace.steps)
    if title:
        fig.suptitle(title)
    return _save(fig, path)


def _ellipse(centre: FloatArray, cov: FloatArray, colour: tuple[float, ...]) -> Ellipse:
    """The ``SIGMAS`` ellipse of a 2-D covariance [mm^2] about ``centre`` [mm]."""
    values, vectors = np.linalg.eigh(0.5 * (cov + cov.T))
    values = np.maximum(values, 0.0)
    angle = float(np.degrees(np.arctan2(vectors[1, 1], vectors[0, 1])))
    width, height = 2.0 * SIGMAS * np.sqrt(values[1]), 2.0 * SIGMAS * np.sqrt(values[0])
    return Ellipse(
        (float(centre[0]), float(centre[1])),
        float(width),
        float(height),
        angle=angle,
        facecolor=(*colour[:3], 0.25),
        edgecolor=colour[:3],
        lw=0.8,
    )


def plot_model_views(
    path: str | Path,
    cables: Sequence[tuple[str, PathGraph, ArrayLike]],
    fixtures: Mapping[str, tuple[str, ArrayLike]],
    title: str = "",
) -> Path:
    """Write a PNG of the models over the true cables, from the top (x-y) and the side (x-z).

    Args:
        path: Output PNG file.
        cables: Per cable: its name, the robot's path graph of it and the
            simulated cable's polyline [m] (ground truth, (N, 3)). The true
            cables take one colour each (the first the run plot's), named
            in the legend where there are several.
        fixtures: The board: name -> (``anchor``/``peg``/``clip``, position [m]).
        title: Figure title.

    Returns:
        The path written.
    """
    return _save(model_views_figure(cables, fixtures, title), path)


def model_views_figure(
    cables: Sequence[tuple[str, PathGraph, ArrayLike]],
    fixtures: Mapping[str, tuple[str, ArrayLike]],
    title: str = "",
) -> Figure:
    """The figure :func:`plot_model_views` writes (arguments as there)."""
    types = {name: kind for name, (kind, _) in fixtures.items()}
    drawn = [
        (name, 1e3 * np.asarray(cable, dtype=float).reshape(-1, 3), model_shapes(graph, types))
        for name, graph, cable in cables
    ]
    fig = Figure(figsize=(11, 5.2), constrained_layout=True)
    views = fig.subplots(1, 2)
    for ax, (a, b), name in zip(views, ((0, 1), (0, 2)), ("top (x-y)", "side (x-z)"), strict=True):
        for k, (cable_name, line, shapes) in enumerate(drawn):
            label = "true cable" if len(drawn) == 1 else f"true cable {cable_name}"
            true_colour = TRUE_CABLE_COLOURS[k % len(TRUE_CABLE_COLOURS)]
            ax.plot(line[:, a], line[:, b], color=true_colour, lw=3.0, label=label, zorder=1)
            pts = 1e3 * shapes.points
            edges = "model edges" if k == 0 else None
            ax.plot(pts[:, a], pts[:, b], color="k", lw=1.0, label=edges, zorder=2)
            for p, c in zip(pts, shapes.colours, strict=True):
                ax.scatter(p[a], p[b], s=36, color=c[:3], edgecolors="k", linewidths=0.6, zorder=4)
            for e in shapes.ellipsoids:
                cov = e.rotation @ np.diag((e.half_sizes / SIGMAS) ** 2) @ e.rotation.T
                sub = 1e6 * cov[np.ix_((a, b), (a, b))]
                ax.add_patch(_ellipse(1e3 * e.centre[[a, b]], sub, e.colour))
        for fname, (kind, pos) in fixtures.items():
            p = 1e3 * np.asarray(pos, dtype=float)
            ax.scatter(
                p[a],
                p[b],
                s=90,
                marker=FIXTURE_MARKERS[kind],
                facecolors="none",
                edgecolors=[FIXTURE_COLOURS[kind][:3]],
                linewidths=2.0,
                zorder=3,
            )
            ax.annotate(
                f"{fname} ({kind})",
                (p[a], p[b]),
                textcoords="offset points",
                xytext=(6, 6),
                fontsize=8,
                color=FIXTURE_COLOURS[kind][:3],
            )
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]" if b == 1 else "z [mm]")
        ax.set_title(name)
        ax.grid(alpha=0.3)
    handles, _ = views[0].get_legend_handles_labels()
    seen: dict[str, RGBA] = {}
    for _, _, shapes in drawn:
        for colour, kind, label in zip(shapes.colours, shapes.kinds, shapes.labels, strict=True):
            name = label.split(" ", 1)[-1] if kind != "gripper" else ""
            key = f"{kind} point" + (f" ({types[name]})" if name in types else "")
            seen.setdefault(key, colour)
    for key, rgba in seen.items():
        handles.append(Line2D([], [], ls="", marker="o", color=rgba, mec="k", mew=0.6, label=key))
    views[0].legend(handles=handles, loc="best", fontsize=8)
    fig.suptitle(title or f"model (points, {SIGMAS:g}-sigma ellipses) over the true cable")
    return fig
