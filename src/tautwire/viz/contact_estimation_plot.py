"""Contact estimation error and uncertainty per axis (as the paper's Fig. 5c).

Drawn on a :class:`matplotlib.figure.Figure` with the Agg canvas, without
pyplot: importing or calling this never changes the process's backend.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from numpy.typing import ArrayLike

AXIS_COLOURS = ("tab:red", "tab:green", "tab:blue")


def plot_contact_estimation(
    path: str | Path,
    samples: ArrayLike,
    error: ArrayLike,
    std: ArrayLike,
    changes: Sequence[int] = (),
    title: str = "Contact point estimation",
    error_limit_mm: float | None = 20.0,
    xlabel: str = "estimator iteration",
) -> Path:
    """Write a two-panel PNG: estimation error (top) and uncertainty (bottom).

    Args:
        path: Output PNG file.
        samples: x values (iterations or seconds).  # (N,)
        error: Estimate minus truth per axis [m]; NaN before an estimate.  # (N, 3)
        std: Reported standard deviation per axis [m]; NaN before.  # (N, 3)
        changes: x values where a contact change was declared or happened.
        title: Figure title.
        error_limit_mm: Crop of the error axis [mm] (the paper crops too);
            None for no crop.
        xlabel: Label of the x axis.

    Returns:
        The path written.
    """
    x = np.asarray(samples, dtype=float)
    e = 1e3 * np.asarray(error, dtype=float)
    s = 1e3 * np.asarray(std, dtype=float)
    fig = Figure(figsize=(8, 6), layout="constrained")  # no pyplot: the backend is left alone
    FigureCanvasAgg(fig)
    ax_e, ax_s = fig.subplots(2, 1, sharex=True)
    for i, (name, colour) in enumerate(zip("xyz", AXIS_COLOURS, strict=True)):
        ax_e.plot(x, e[:, i], color=colour, lw=1.2, label=f"{name}")
        ax_s.plot(x, s[:, i], color=colour, lw=1.2, label=f"{name}")
    for ax in (ax_e, ax_s):
        for c in changes:
            ax.axvline(c, color="k", ls="--", lw=1.0)
        ax.grid(alpha=0.3)
        ax.legend(loc="upper right", ncols=3, fontsize=8)
    if error_limit_mm is not None:
        ax_e.set_ylim(-error_limit_mm, error_limit_mm)
    ax_e.set_ylabel("estimation error [mm]")
    ax_s.set_ylabel("uncertainty (std) [mm]")
    ax_s.set_yscale("log")
    ax_s.set_xlabel(xlabel)
    ax_e.set_title(title)
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=120)
    return out
