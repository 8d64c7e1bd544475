"""The harness experiment's model validation figure: each cable's model over the true cable.

Like the paper's figure of its harness board: per cable a top view (x-y)
and a side view (x-z) of the simulated cable, the robot's model (feature
points and the edges between them), the board's fixtures, and beside each
point that stands for a fixture or a gripper its deviation from the true
point it stands for (horizontal / vertical, mm). It draws plain data
(:class:`CableFigure`), so a campaign's worker can hand a board's figure
back to the parent without the simulator.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from tautwire.sim.model_overlay import FIXTURE_COLOURS
from tautwire.viz.run_plots import CABLE_COLOUR, FIXTURE_MARKERS

#: Colour of the model's points by kind.
POINT_COLOURS = {
    "gripper": (0.1, 0.75, 0.85),
    "fixed": (0.15, 0.65, 0.2),
    "contact": (0.95, 0.75, 0.1),
    "free": (1.0, 1.0, 1.0),
}


@dataclass(frozen=True)
class ModelPoint:
    """One feature point of a cable's model, as drawn.

    Attributes:
        position: Where the model has it [m].  # (3,)
        kind: ``gripper``, ``fixed``, ``contact`` or ``free``.
        label: Its label (a fixture's or gripper's name, or empty).
        horizontal: Its horizontal deviation [m] from the true point it
            stands for (None: it stands for nothing).
        vertical: Its vertical deviation [m] (None as ``horizontal``).
    """

    position: tuple[float, float, float]
    kind: str
    label: str = ""
    horizontal: float | None = None
    vertical: float | None = None


@dataclass(frozen=True)
class CableFigure:
    """One cable's part of the figure.

    Attributes:
        name: The cable's name.
        true_cable: The simulated cable's polyline [m], one (x, y, z) a vertex.
        points: The model's feature points, in order along the cable.
        route_done: Whether its route was done (None: it had none).
    """

    name: str
    true_cable: Sequence[Sequence[float]]
    points: Sequence[ModelPoint] = field(default_factory=tuple)
    route_done: bool | None = None

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data (for a campaign's worst board)."""
        return {
            "name": self.name,
            "true_cable": [[float(v) for v in p] for p in self.true_cable],
            "points": [
                {
                    "position": list(p.position),
                    "kind": p.kind,
                    "label": p.label,
                    "horizontal": p.horizontal,
                    "vertical": p.vertical,
                }
                for p in self.points
            ],
            "route_done": self.route_done,
        }

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> CableFigure:
        """The inverse of :meth:`to_dict`."""
        points = tuple(
            ModelPoint(
                (float(p["position"][0]), float(p["position"][1]), float(p["position"][2])),
                str(p["kind"]),
                str(p.get("label", "")),
                p.get("horizontal"),
                p.get("vertical"),
            )
            for p in data.get("points", ())
        )
        return cls(str(data["name"]), data["true_cable"], points, data.get("route_done"))


def plot_harness_model(
    path: str | Path,
    cables: Sequence[CableFigure],
    fixtures: Mapping[str, tuple[str, Sequence[float]]],
    title: str = "",
) -> Path:
    """Write the figure (PNG): a row per cable, top view left, side view right.

    Args:
        path: Output PNG file.
        cables: Each cable's true polyline and model.
        fixtures: The board: name -> (``anchor``/``peg``/``clip``, position [m]).
        title: Figure title.

    Returns:
        The path written.
    """
    rows = max(1, len(cables))
    fig = Figure(figsize=(12, 4.6 * rows), constrained_layout=True)
    axes = np.asarray(fig.subplots(rows, 2, squeeze=False))
    for row, cable in enumerate(cables):
        line = 1e3 * np.asarray(cable.true_cable, dtype=float).reshape(-1, 3)
        pts = 1e3 * np.array([p.position for p in cable.points], dtype=float).reshape(-1, 3)
        done = {True: "route done", False: "route not done", None: "no route"}[cable.route_done]
        for col, ((a, b), view) in enumerate((((0, 1), "top (x-y)"), ((0, 2), "side (x-z)"))):
            ax = axes[row, col]
            ax.plot(line[:, a], line[:, b], color=CABLE_COLOUR, lw=3.0, zorder=1)
            if len(pts):
                ax.plot(pts[:, a], pts[:, b], color="k", lw=1.0, zorder=2)
            for p, xyz in zip(cable.points, pts, strict=True):
                ax.scatter(
                    xyz[a],
                    xyz[b],
                    s=36,
                    color=POINT_COLOURS.get(p.kind, (0.5, 0.5, 0.5)),
                    edgecolors="k",
                    linewidths=0.6,
                    zorder=4,
                )
                if p.horizontal is not None and p.vertical is not None and p.kind != "free":
                    error = 1e3 * (p.horizontal if col == 0 else p.vertical)
                    ax.annotate(
                        f"{error:.1f}",
                        (xyz[a], xyz[b]),
                        textcoords="offset points",
                        xytext=(5, -11),
                        fontsize=7,
                        color="k",
                    )
            for name, (kind, pos) in fixtures.items():
                q = 1e3 * np.asarray(pos, dtype=float)
                colour = FIXTURE_COLOURS[kind][:3]
                ax.scatter(
                    q[a],
                    q[b],
                    s=80,
                    marker=FIXTURE_MARKERS[kind],
                    facecolors="none",
                    edgecolors=[colour],
                    linewidths=1.6,
                    zorder=3,
                )
                if col == 0:
                    ax.annotate(
                        name,
                        (q[a], q[b]),
                        textcoords="offset points",
                        xytext=(6, 5),
                        fontsize=7,
                        color=colour,
                    )
            ax.set_aspect("equal", adjustable="datalim")
            ax.set_xlabel("x [mm]")
            ax.set_ylabel("y [mm]" if b == 1 else "z [mm]")
            ax.set_title(
                f"{cable.name}: {view}, {done}; beside each point its "
                f"{'horizontal' if col == 0 else 'vertical'} error [mm]",
                fontsize=9,
            )
            ax.grid(alpha=0.3)
    handles = [
        Line2D([], [], color=CABLE_COLOUR, lw=3.0, label="true cable"),
        Line2D([], [], color="k", lw=1.0, label="model edges"),
    ]
    for kind, colour in POINT_COLOURS.items():
        handles.append(
            Line2D([], [], ls="", marker="o", color=colour, mec="k", mew=0.6, label=f"{kind} point")
        )
    for kind, marker in FIXTURE_MARKERS.items():
        handles.append(
            Line2D(
                [],
                [],
                ls="",
                marker=marker,
                mfc="none",
                mec=FIXTURE_COLOURS[kind][:3],
                mew=1.6,
                label=kind,
            )
        )
    axes[0, 0].legend(handles=handles, loc="best", fontsize=7)
    fig.suptitle(title or "harness: each cable's model over the true cable")
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=110)
    return out
