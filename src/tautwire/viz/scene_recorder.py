"""A GIF of a simulated run and a PNG snapshot of its end, where rendering works.

Used by ``tautwire demo`` and ``tautwire run --video``: attach the recorder to
the world (the runners' ``on_world`` hook), call :meth:`SceneRecorder.tick`
with the simulated time every control period, then :meth:`SceneRecorder.save`.
Where offscreen OpenGL is unavailable nothing is rendered and
:attr:`SceneRecorder.error` says why; the run itself is unaffected.

The video's camera frames everywhere the cables can reach (fixed for the
whole run); the snapshot's frames the cables and fixtures as they end up.
Given the robot's path graph, both draw it over the simulated cable
(:mod:`tautwire.sim.model_overlay`: feature points coloured by what holds
them, edges, 3-sigma ellipsoids); fixtures show in their type's colour with
their names. Frames are 800 x 600; a long run keeps at most ``max_frames``
of them, evenly spaced (every other one is dropped, and the spacing
doubled, whenever the count would pass it), so the GIF stays a few MB.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from tautwire.errors import SimulationError
from tautwire.model import PathGraph
from tautwire.sim.world import SimWorld


class SceneRecorder:
    """Grabs a frame every ``every`` seconds of simulated time.

    Args:
        every: Simulated time [s] between frames (doubled as needed to keep
            at most ``max_frames``).
        width: Frame width [pixels].
        height: Frame height [pixels].
        max_frames: Most frames kept.
        frame_duration: How long [s] each frame shows in the GIF.
    """

    def __init__(
        self,
        every: float = 0.25,
        width: int = 800,
        height: int = 600,
        max_frames: int = 80,
        frame_duration: float = 0.1,
    ) -> None:
        self.every = float(every)
        self.size = (width, height)
        self.max_frames = max(2, int(max_frames))
        self.frame_duration = float(frame_duration)
        self.frames: list[np.ndarray] = []
        self.error: str | None = None
        self._renderer: Any = None
        self._world: SimWorld | None = None
        self._fixture_types: dict[str, str] = {}
        self._graph: PathGraph | None = None
        self._next = 0.0

    @property
    def rendering(self) -> bool:
        """Whether frames are being rendered."""
        return self._renderer is not None

    def attach(self, world: SimWorld) -> None:
        """Start rendering ``world`` (records why not in :attr:`error`)."""
        try:
            from tautwire.sim.model_overlay import fixture_type
            from tautwire.sim.render import SceneRenderer, scene_points

            self._renderer = SceneRenderer(world, *self.size, camera=None, shadows=False)
            self._renderer.look_at(scene_points(world, reach=True))
            self._world = world
            self._fixture_types = {f.name: fixture_type(f) for f in world.spec.fixtures}
        except (SimulationError, ImportError, RuntimeError) as exc:
            self.error = str(exc)

    def tick(self, time: float, graph: PathGraph | None = None) -> None:
        """Grab a frame if ``every`` s of simulated time [s] have passed since the last.

        Args:
            time: Simulated time [s].
            graph: The robot's cable model now, drawn over the scene (also
                kept for the snapshot), or None.
        """
        if graph is not None:
            self._graph = graph
        if self._renderer is None or time < self._next:
            return
        self._next = time + self.every
        self.frames.append(self._renderer.frame(self._shapes()))
        if len(self.frames) > self.max_frames:
            self.frames = self.frames[::2]
            self.every *= 2.0
            self._next = time + self.every

    def _shapes(self) -> Any:
        if self._graph is None:
            return None
        from tautwire.sim.model_overlay import model_shapes

        return model_shapes(self._graph, self._fixture_types)

    def snapshot(self) -> np.ndarray | None:
        """The scene now, framed on the cables and fixtures (None if not rendering)."""
        if self._renderer is None or self._world is None:
            return None
        from tautwire.sim.render import scene_points

        self._renderer.look_at(scene_points(self._world))
        frame: np.ndarray = self._renderer.frame(self._shapes())
        return frame

    def close(self) -> None:
        """Free the renderer (idempotent)."""
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None

    def save(self, out_dir: str | Path, video: str, snapshot: str) -> dict[str, str]:
        """Write the GIF and a snapshot of the scene now; close the renderer.

        Args:
            out_dir: Output folder (created).
            video: File name of the GIF.
            snapshot: File name of the PNG.

        Returns:
            Paths of the files written: ``video`` and ``snapshot`` keys.
        """
        files: dict[str, str] = {}
        out = Path(out_dir)
        try:
            still = self.snapshot()
        finally:
            self.close()
        if self.frames or still is not None:
            out.mkdir(parents=True, exist_ok=True)
        if self.frames:
            import imageio.v2 as imageio

            imageio.mimsave(
                out / video, list[Any](self.frames), duration=1000.0 * self.frame_duration, loop=0
            )
            files["video"] = str(out / video)
        if still is not None:
            from tautwire.sim.render import write_png

            write_png(still, out / snapshot)
            files["snapshot"] = str(out / snapshot)
        return files
