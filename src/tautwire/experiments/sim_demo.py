"""The main demonstration: a robot finds, blind, where a cable touches the board.

The built-in scenario (``tautwire/data/demo.yaml``, the paper's Fig. 5c
set-up): a cable from an anchor is tensioned (D) and rotated around the
anchor (I) until it swings against a peg, which becomes the new contact.
The robot sees only its gripper poses and the noisy wrist force; the
simulator's truth scores it afterwards. Writes plots, ``result.json`` and,
where offscreen rendering works, a GIF and a PNG snapshot of the scene.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from tautwire.errors import SimulationError
from tautwire.experiments.fig5bc import record_rotation, series_arrays
from tautwire.scenario import load_scenario
from tautwire.sim.world import SimWorld

DEMO_SCENARIO = Path(__file__).parents[1] / "data" / "demo.yaml"
log = logging.getLogger(__name__)


@dataclass
class SimDemoResult:
    """What the demo measured and wrote."""

    run: dict[str, Any]
    contact_iterations: int
    changes: list[int]
    files: dict[str, str] = field(default_factory=dict)
    video_error: str | None = None


class _Recorder:
    """Grabs a frame every ``every`` seconds of simulated time."""

    def __init__(self, every: float = 0.25, width: int = 480, height: int = 360) -> None:
        self.every = every
        self.size = (width, height)
        self.frames: list[np.ndarray] = []
        self.renderer: Any = None
        self.error: str | None = None
        self._next = 0.0

    def attach(self, world: SimWorld) -> None:
        try:
            from tautwire.sim.render import SceneRenderer

            self.renderer = SceneRenderer(world, *self.size, shadows=False)
        except (SimulationError, ImportError, RuntimeError) as exc:
            self.error = str(exc)

    def tick(self, time: float) -> None:
        if self.renderer is None or time < self._next:
            return
        self._next = time + self.every
        self.frames.append(self.renderer.frame())

    def close(self) -> None:
        if self.renderer is not None:
            self.renderer.close()
            self.renderer = None


def run_sim_demo(
    out_dir: str | Path,
    seed: int | None = None,
    video: bool = True,
    progress: Callable[[float], None] | None = None,
) -> SimDemoResult:
    """Run the built-in scenario; write the plot, the result and the video.

    Args:
        out_dir: Output folder.
        seed: Overrides the scenario's seed.
        video: Try to render a GIF and a snapshot (skipped cleanly where
            offscreen rendering is unavailable).
        progress: Called with the simulated time [s] now and then.
    """
    from tautwire.viz.contact_estimation_plot import plot_contact_estimation

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    scenario = load_scenario(DEMO_SCENARIO)
    recorder = _Recorder() if video else None

    def on_tick(t: float) -> None:
        if recorder is not None:
            recorder.tick(t)
        if progress is not None:
            progress(t)

    try:
        run = record_rotation(
            scenario,
            seed,
            on_time=on_tick,
            on_world=recorder.attach if recorder is not None else None,
        )
        snapshot = recorder.renderer.frame() if recorder and recorder.renderer else None
    finally:
        if recorder is not None:
            recorder.close()
    s = run["series"]
    k, est, std, truth = series_arrays(s)
    n = len(k)
    result = SimDemoResult(run["result"], n, run["changes"])
    if n:
        result.files["plot"] = str(
            plot_contact_estimation(
                out / "contact_estimation.png",
                k,
                est - truth,
                std,
                changes=run["changes"],
                title="Blind contact estimation in MuJoCo (dashed: contact change declared)",
            )
        )
    if recorder is not None:
        result.video_error = recorder.error
        if recorder.frames:
            import imageio.v2 as imageio

            gif = out / "demo.gif"
            imageio.mimsave(gif, list[Any](recorder.frames), duration=0.1, loop=0)
            result.files["video"] = str(gif)
        if snapshot is not None:
            from tautwire.sim.render import write_png

            write_png(snapshot, out / "snapshot.png")
            result.files["snapshot"] = str(out / "snapshot.png")
    import json

    (out / "result.json").write_text(
        json.dumps(
            {
                "run": result.run,
                "changes": result.changes,
                "files": result.files,
                "video_error": result.video_error,
            },
            indent=2,
        )
        + "\n"
    )
    result.files["result"] = str(out / "result.json")
    return result
