"""MuJoCo's interactive viewer on a running task, with the robot's model drawn in.

:class:`LiveViewer` opens the viewer in passive mode
(``mujoco.viewer.launch_passive``): the task steps the world as usual and
the viewer shows it, at most as fast as real time (or ``speed`` times it).
Every frame the viewer's ``user_scn`` gets the robot's path graph
(:mod:`tautwire.sim.model_overlay`: feature points coloured by what holds
them, edges, 3-sigma uncertainty ellipsoids) and the fixtures' names; the
fixtures themselves are recoloured by type in the world's model (a visual
attribute only: the physics does not read it).

The viewer needs a display (X11 or Wayland, GLFW); :func:`display_problem`
says why there is none, before any window is tried.
"""

from __future__ import annotations

import os
import sys
import threading
import time
from types import TracebackType
from typing import Any

import numpy as np

from tautwire.errors import SimulationError
from tautwire.model import PathGraph
from tautwire.sim.model_overlay import (
    add_labels,
    draw_shapes,
    fixture_colours,
    fixture_labels,
    fixture_type,
    model_shapes,
)
from tautwire.sim.render import scene_points
from tautwire.sim.world import SimWorld


def display_problem() -> str | None:
    """Why MuJoCo's viewer cannot open a window here, or None if it can try."""
    if sys.platform.startswith("linux") and not (
        os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")
    ):
        return "no display: DISPLAY and WAYLAND_DISPLAY are unset (run under a desktop or xvfb-run)"
    try:
        import glfw
    except ImportError as exc:  # pragma: no cover - glfw comes with mujoco
        return f"MuJoCo's viewer needs glfw: {exc}"
    if not glfw.init():
        return "no display: GLFW could not open a connection to the display"
    return None


class LiveViewer:
    """A passive MuJoCo viewer on ``world``; close it (or use ``with``).

    Args:
        world: The world the task runs in.
        speed: Simulated seconds shown per wall-clock second (``0``: as fast
            as the simulation runs).
        frame_rate: Most viewer updates per wall-clock second.

    Raises:
        SimulationError: if there is no display or the viewer cannot start.
    """

    def __init__(self, world: SimWorld, speed: float = 1.0, frame_rate: float = 60.0) -> None:
        problem = display_problem()
        if problem is not None:
            raise SimulationError(problem)
        import mujoco.viewer

        self._world = world
        self.speed = float(speed)
        self._period = 1.0 / float(frame_rate)
        model = world.model
        for gid, rgba in fixture_colours(model, world.spec.fixtures).items():
            model.geom_rgba[gid] = rgba  # visual only
        self._types = {f.name: fixture_type(f) for f in world.spec.fixtures}
        self._labels = fixture_labels(world.spec.fixtures)
        before = set(threading.enumerate())
        try:
            self._handle: Any = mujoco.viewer.launch_passive(
                model, world.data, show_left_ui=False, show_right_ui=False
            )
        except Exception as exc:  # GLFW and the viewer raise assorted errors
            raise SimulationError(f"MuJoCo's viewer could not start: {exc}") from exc
        self._threads = [t for t in threading.enumerate() if t not in before]
        self._aim()
        self._wall0 = time.perf_counter()
        self._sim0 = world.time
        self._last = -1.0
        self.frames = 0
        self.drawn = 0

    def _aim(self) -> None:
        pts = scene_points(self._world, reach=True)
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        with self._handle.lock():
            cam = self._handle.cam
            cam.lookat[:] = 0.5 * (lo + hi)
            cam.distance = max(1.6 * float(np.max(hi - lo)), 0.3)
            cam.azimuth, cam.elevation = 90.0, -40.0

    @property
    def running(self) -> bool:
        """Whether the window is open (the user may close it)."""
        return bool(self._handle is not None and self._handle.is_running())

    def show(self, graph: PathGraph | None = None) -> None:
        """Show the world now, with ``graph`` drawn in; wait to keep ``speed``.

        Call it every control period; it updates the window at most
        ``frame_rate`` times a second.
        """
        if not self.running:
            return
        if self.speed > 0.0:
            ahead = (self._world.time - self._sim0) / self.speed - (
                time.perf_counter() - self._wall0
            )
            if ahead > 0.0:
                time.sleep(ahead)
        now = time.perf_counter()
        if now - self._last < self._period:
            return
        self._last = now
        with self._handle.lock():
            scene = self._handle.user_scn
            scene.ngeom = 0
            if graph is not None:
                self.drawn = draw_shapes(scene, model_shapes(graph, self._types))
            add_labels(scene, self._labels)
        self._handle.sync()
        self.frames += 1

    def wait_closed(self, timeout: float | None = None) -> None:
        """Keep the window open until the user closes it (or ``timeout`` [s] passes)."""
        start = time.perf_counter()
        while self.running and (timeout is None or time.perf_counter() - start < timeout):
            self._handle.sync()
            time.sleep(0.05)

    def close(self) -> None:
        """Close the window and wait for the viewer's thread (idempotent)."""
        if self._handle is None:
            return
        self._handle.close()
        self._handle = None
        for t in self._threads:  # exiting while it renders crashes the process
            t.join(timeout=5.0)

    def __enter__(self) -> LiveViewer:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()
