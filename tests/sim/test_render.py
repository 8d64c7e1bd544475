"""Offscreen frames of the scene (EGL here; a clear SimulationError elsewhere)."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError, SimulationError
from tautwire.sim.render import SceneRenderer, render_frame, scene_points, write_png
from tests.sim.scenes import peg_scene


def test_frame_shows_the_orange_cable(tmp_path) -> None:
    world = peg_scene()
    try:
        frame = render_frame(world, 320, 240)
    except SimulationError as exc:  # no offscreen GL on this machine
        assert "MUJOCO_GL" in str(exc)
        pytest.skip(str(exc))
    assert frame.shape == (240, 320, 3) and frame.dtype == np.uint8
    r, g, b = (frame[..., i].astype(int) for i in range(3))
    orange = (r - b > 100) & (r > g) & (g > 0.48 * r)
    assert orange.sum() > 50  # the cable is in view
    path = tmp_path / "scene.png"
    write_png(frame, path)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_renderer_closes_and_validates() -> None:
    world = peg_scene()
    with pytest.raises(InvalidArgumentError, match="camera"):
        SceneRenderer(world, camera="nope")
    with pytest.raises(InvalidArgumentError, match="size"):
        SceneRenderer(world, width=5000)
    try:
        renderer = SceneRenderer(world, 64, 48, shadows=False)
    except SimulationError as exc:
        pytest.skip(str(exc))
    renderer.close()
    renderer.close()
    with pytest.raises(SimulationError, match="closed"):
        renderer.frame()


def test_write_png_rejects_wrong_shape(tmp_path) -> None:
    with pytest.raises(InvalidArgumentError):
        write_png(np.zeros((4, 4)), tmp_path / "x.png")


def test_the_framing_camera_shows_the_cable_larger_than_the_overview() -> None:
    world = peg_scene()

    def orange_pixels(camera: str | None) -> int:
        try:
            with SceneRenderer(world, 320, 240, camera=camera, shadows=False) as renderer:
                frame = renderer.frame()
        except SimulationError as exc:
            pytest.skip(str(exc))
        r, g, b = (frame[..., i].astype(int) for i in range(3))
        return int(((r - b > 100) & (r > g) & (g > 0.48 * r)).sum())

    assert orange_pixels(None) > 2 * orange_pixels("overview")


def test_scene_points_and_look_at() -> None:
    world = peg_scene()
    now, reach = scene_points(world), scene_points(world, reach=True)
    assert now.shape[1] == 3 and reach.shape[0] > now.shape[0]
    try:
        renderer = SceneRenderer(world, 64, 48, shadows=False)
    except SimulationError as exc:
        pytest.skip(str(exc))
    with renderer, pytest.raises(InvalidArgumentError, match="fixed camera"):
        renderer.look_at(now)


def test_write_png_round_trips_exactly(tmp_path) -> None:
    import imageio.v3 as iio

    pixels = np.random.default_rng(0).integers(0, 256, size=(7, 11, 3), dtype=np.uint8)
    write_png(pixels, tmp_path / "x.png")
    np.testing.assert_array_equal(iio.imread(tmp_path / "x.png"), pixels)
