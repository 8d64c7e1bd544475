"""Offscreen RGB frames of the simulated scene from a fixed camera.

Rendering needs an offscreen OpenGL backend: ``MUJOCO_GL=egl`` (Mesa's
libEGL) or ``MUJOCO_GL=osmesa``. :mod:`tautwire.sim` picks ``egl`` on Linux
when ``MUJOCO_GL`` is unset (it must be chosen before MuJoCo is imported).
Where no backend works, :class:`SceneRenderer` raises
:class:`~tautwire.errors.SimulationError`, so callers can fall back (e.g.
skip the video).

The builder's fixed "overview" camera takes in everything, the parked second
gripper included, which leaves the cable a few dozen pixels long. A
renderer made with ``camera=None`` looks instead at points given to
:meth:`SceneRenderer.look_at`: :func:`scene_points` gives the fixtures and
the cables, now or everywhere a cable can reach (within its length of its
start anchor: what a video of a whole run needs).
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from types import TracebackType

import mujoco
import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError, SimulationError
from tautwire.sim.model_overlay import (
    ModelShapes,
    draw_shapes,
    fixture_colours,
    fixture_labels,
    style_scene,
)
from tautwire.sim.world import SimWorld

UInt8Array = NDArray[np.uint8]
FloatArray = NDArray[np.float64]

#: View direction of the framing camera: from the front (-y), looking down.
AZIMUTH = 90.0  # deg
ELEVATION = -40.0  # deg
#: Camera distance [m] beyond which the drawn model thickens in proportion.
OVERLAY_DISTANCE = 0.6


def scene_points(world: SimWorld, reach: bool = False) -> FloatArray:
    """Points [m] that a view of ``world`` should take in: fixtures, cables, holding grippers.

    Args:
        world: The world.
        reach: Also the circle, at its start's height, of a cable's length
            around its start anchor: wherever the cable can go in a run.

    Returns:
        The points, world frame.  # (N, 3)
    """
    pts = [np.asarray(f.position, dtype=float) for f in world.spec.fixtures]
    for idx in world._cables.values():
        pts.extend(world.data.xpos[idx.body_ids])
        start = idx.spec.start
        if reach and start is not None:
            c = np.asarray(world.spec.fixture(start).position, dtype=float)
            r = idx.spec.length
            for a in np.linspace(0.0, 2.0 * math.pi, 16, endpoint=False):
                pts.append(c + r * np.array([math.cos(a), math.sin(a), 0.0]))
    for arm, state in world._grippers.items():
        if state.held is not None:  # a parked gripper stays out of the picture
            bodies = world.data.xpos[world._gripper_bodies[arm]]
            pts.extend(bodies)
            pts.append(bodies[0] + np.array([0.0, 0.0, 0.06]))  # the gripper's top
    return np.array(pts, dtype=float).reshape(-1, 3)


class SceneRenderer:
    """Renders frames of a world; close it (or use ``with``) to free the GL context.

    Args:
        world: The world to draw.
        width: Frame width [pixels], at most 1280.
        height: Frame height [pixels], at most 960.
        camera: Name of a camera in the scene (the builder adds "overview"),
            or None for a free camera that frames :func:`scene_points` (see
            :meth:`look_at`).
        shadows: Draw shadows (about 3x slower).
        labels: Write the fixtures' names and types above them.

    Raises:
        SimulationError: if offscreen OpenGL is unavailable.
        InvalidArgumentError: for a bad size or an unknown camera.
    """

    def __init__(
        self,
        world: SimWorld,
        width: int = 640,
        height: int = 480,
        camera: str | None = "overview",
        shadows: bool = True,
        labels: bool = True,
    ) -> None:
        if not (0 < width <= 1280 and 0 < height <= 960):
            raise InvalidArgumentError(
                f"frame size must be within 1280 x 960, got {width} x {height}"
            )
        model = world.model
        if camera is not None and mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_CAMERA, camera) < 0:
            raise InvalidArgumentError(f"no camera named {camera!r} in the scene")
        self._world = world
        self._camera: str | mujoco.MjvCamera = camera if camera is not None else mujoco.MjvCamera()
        self._aspect = width / height
        try:
            self._renderer: mujoco.Renderer | None = mujoco.Renderer(model, height, width)
        except Exception as exc:  # the GL backends raise assorted errors
            backend = os.environ.get("MUJOCO_GL", "<unset>")
            raise SimulationError(
                f"offscreen rendering is unavailable (MUJOCO_GL={backend}): {exc}."
                " Install Mesa's libEGL (MUJOCO_GL=egl) or OSMesa (MUJOCO_GL=osmesa)"
            ) from exc
        self._shadows = shadows
        self._labels = labels
        self._overlay_scale = 1.0
        self._fixture_colours = fixture_colours(model, world.spec.fixtures)
        self._fixture_labels = fixture_labels(world.spec.fixtures)
        self._option = mujoco.MjvOption()
        self._option.flags[mujoco.mjtVisFlag.mjVIS_FLEXVERT] = (
            False  # draw the cable, not its vertices
        )
        if camera is None:
            self.look_at(scene_points(world))

    def look_at(self, points: ArrayLike, margin: float = 1.1) -> None:
        """Aim the free camera (``camera=None``) so that ``points`` [m] fill the frame.

        Args:
            points: World points to take in.  # (N, 3)
            margin: Room around them, a factor on the distance.

        Raises:
            InvalidArgumentError: for a named camera, or no finite points.
        """
        cam = self._camera
        if isinstance(cam, str):
            raise InvalidArgumentError(f"the renderer uses the fixed camera {cam!r}")
        pts = np.asarray(points, dtype=float).reshape(-1, 3)
        pts = pts[np.all(np.isfinite(pts), axis=1)]
        if pts.shape[0] == 0:
            raise InvalidArgumentError("no finite points to look at")
        centre = 0.5 * (pts.min(axis=0) + pts.max(axis=0))
        az, el = math.radians(AZIMUTH), math.radians(ELEVATION)
        forward = np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
        right = np.cross(forward, [0.0, 0.0, 1.0])
        right /= np.linalg.norm(right)
        up = np.cross(right, forward)
        tan_v = math.tan(math.radians(float(self._world.model.vis.global_.fovy)) / 2.0)
        tan_h = tan_v * self._aspect
        rel = pts - centre
        depth = rel @ forward  # a point at distance D + depth from the eye
        across = np.maximum(np.abs(rel @ right) / tan_h, np.abs(rel @ up) / tan_v)
        distance = max(float(np.max(margin * across - depth)), 0.1)
        cam.type = mujoco.mjtCamera.mjCAMERA_FREE
        cam.lookat[:] = centre
        cam.distance = distance
        self._overlay_scale = max(1.0, distance / OVERLAY_DISTANCE)
        cam.azimuth = AZIMUTH
        cam.elevation = ELEVATION

    def frame(self, model: ModelShapes | None = None) -> UInt8Array:
        """The scene now, as RGB pixels of shape (height, width, 3).

        Fixtures are drawn in their type's colour (anchor green, peg blue,
        clip magenta) with their names above them.

        Args:
            model: The robot's cable model to draw over the scene
                (:func:`~tautwire.sim.model_overlay.model_shapes`), or None.

        Raises:
            SimulationError: if the renderer was closed.
        """
        if self._renderer is None:
            raise SimulationError("the renderer is closed")
        self._renderer.update_scene(
            self._world.data, camera=self._camera, scene_option=self._option
        )
        scene = self._renderer.scene
        style_scene(scene, self._fixture_colours, self._fixture_labels if self._labels else [])
        if model is not None:
            draw_shapes(scene, model, scale=self._overlay_scale)
        for i in range(scene.nlight):  # even light: the scene's key light is a spot
            if not scene.lights[i].headlight:
                scene.lights[i].type = mujoco.mjtLightType.mjLIGHT_DIRECTIONAL
        scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = self._shadows
        pixels: UInt8Array = self._renderer.render().copy()
        return pixels

    def close(self) -> None:
        """Free the renderer and its GL context (idempotent)."""
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None

    def __enter__(self) -> SceneRenderer:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()


def render_frame(world: SimWorld, width: int = 640, height: int = 480) -> UInt8Array:
    """One RGB frame (height, width, 3) of ``world`` from the overview camera.

    Raises:
        SimulationError: if offscreen OpenGL is unavailable.
    """
    with SceneRenderer(world, width, height) as renderer:
        return renderer.frame()


def write_png(pixels: UInt8Array, path: str | Path) -> None:
    """Write RGB pixels (height, width, 3) as a PNG file (through imageio).

    Raises:
        InvalidArgumentError: if ``pixels`` is not (height, width, 3).
    """
    import imageio.v3 as iio

    arr = np.ascontiguousarray(pixels, dtype=np.uint8)
    if arr.ndim != 3 or arr.shape[2] != 3:
        raise InvalidArgumentError(f"pixels must have shape (height, width, 3), got {arr.shape}")
    iio.imwrite(Path(path), arr, extension=".png")
