"""Offscreen RGB frames of the simulated scene from a fixed camera.

Rendering needs an offscreen OpenGL backend: ``MUJOCO_GL=egl`` (Mesa's
libEGL) or ``MUJOCO_GL=osmesa``. :mod:`tautwire.sim` picks ``egl`` on Linux
when ``MUJOCO_GL`` is unset (it must be chosen before MuJoCo is imported).
Where no backend works, :class:`SceneRenderer` raises
:class:`~tautwire.errors.SimulationError`, so callers can fall back (e.g.
skip the video).
"""

from __future__ import annotations

import os
import struct
import zlib
from pathlib import Path
from types import TracebackType

import mujoco
import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError, SimulationError
from tautwire.sim.world import SimWorld

UInt8Array = NDArray[np.uint8]


class SceneRenderer:
    """Renders frames of a world; close it (or use ``with``) to free the GL context.

    Args:
        world: The world to draw.
        width: Frame width [pixels], at most 1280.
        height: Frame height [pixels], at most 960.
        camera: Name of a camera in the scene (the builder adds "overview").
        shadows: Draw shadows (about 3x slower).

    Raises:
        SimulationError: if offscreen OpenGL is unavailable.
        InvalidArgumentError: for a bad size or an unknown camera.
    """

    def __init__(
        self,
        world: SimWorld,
        width: int = 640,
        height: int = 480,
        camera: str = "overview",
        shadows: bool = True,
    ) -> None:
        if not (0 < width <= 1280 and 0 < height <= 960):
            raise InvalidArgumentError(
                f"frame size must be within 1280 x 960, got {width} x {height}"
            )
        model = world._model
        if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_CAMERA, camera) < 0:
            raise InvalidArgumentError(f"no camera named {camera!r} in the scene")
        self._world = world
        self._camera = camera
        try:
            self._renderer: mujoco.Renderer | None = mujoco.Renderer(model, height, width)
        except Exception as exc:  # the GL backends raise assorted errors
            backend = os.environ.get("MUJOCO_GL", "<unset>")
            raise SimulationError(
                f"offscreen rendering is unavailable (MUJOCO_GL={backend}): {exc}."
                " Install Mesa's libEGL (MUJOCO_GL=egl) or OSMesa (MUJOCO_GL=osmesa)"
            ) from exc
        self._shadows = shadows
        self._option = mujoco.MjvOption()
        self._option.flags[mujoco.mjtVisFlag.mjVIS_FLEXVERT] = (
            False  # draw the cable, not its vertices
        )

    def frame(self) -> UInt8Array:
        """The scene now, as RGB pixels of shape (height, width, 3).

        Raises:
            SimulationError: if the renderer was closed.
        """
        if self._renderer is None:
            raise SimulationError("the renderer is closed")
        self._renderer.update_scene(
            self._world._data, camera=self._camera, scene_option=self._option
        )
        self._renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = self._shadows
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
    """Write RGB pixels (height, width, 3) as a PNG file (no imaging library needed)."""
    arr = np.ascontiguousarray(pixels, dtype=np.uint8)
    if arr.ndim != 3 or arr.shape[2] != 3:
        raise InvalidArgumentError(f"pixels must have shape (height, width, 3), got {arr.shape}")
    h, w, _ = arr.shape
    raw = b"".join(b"\x00" + arr[row].tobytes() for row in range(h))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return (
            struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
        )

    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 6))
    png += chunk(b"IEND", b"")
    Path(path).write_bytes(png)
