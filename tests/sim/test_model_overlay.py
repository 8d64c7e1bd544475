"""The model drawn over the scene, and fixtures told apart by colour and label."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import SimulationError
from tautwire.model import PathGraph
from tautwire.scenario import load_scenario
from tautwire.scenario.registry import scenario_path
from tautwire.sim.build import build_world
from tautwire.sim.model_overlay import (
    FIXTURE_COLOURS,
    KIND_COLOURS,
    SIGMAS,
    covariance_ellipsoid,
    draw_shapes,
    fixture_colours,
    model_shapes,
)
from tautwire.sim.render import SceneRenderer, scene_points


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-1.0, 1.0), min_size=9, max_size=9), st.floats(1e-8, 1e-4))
def test_ellipsoid_axes_are_three_sigma_of_the_covariance(values: list[float], eps: float) -> None:
    a = np.array(values).reshape(3, 3)
    cov = 1e-4 * a @ a.T + eps * np.eye(3)
    e = covariance_ellipsoid([0, 0, 0], cov, (1, 0, 0, 1))
    assert np.linalg.det(e.rotation) == pytest.approx(1.0)
    back = e.rotation @ np.diag((e.half_sizes / SIGMAS) ** 2) @ e.rotation.T
    np.testing.assert_allclose(back, cov, atol=1e-12)


def _graph() -> PathGraph:
    graph = PathGraph.from_positions(
        [[0, 0, 0.1], [0.15, 0.05, 0.1], [0.2, 0.1, 0.1], [0.35, 0.15, 0.1]],
        mass_per_length=0.03,
        kinds=["fixed", "contact", "contact", "gripper"],
        labels=["A1", "P1", "", "left"],
    )
    for pt in graph.points[:3]:
        pt.covariance = np.diag([1e-6, 4e-6, 9e-6])
    return graph


def test_points_take_their_fixtures_colour_and_estimates_get_ellipsoids() -> None:
    import mujoco  # after tautwire.sim chose the GL backend

    shapes = model_shapes(_graph(), {"A1": "anchor", "P1": "peg"})
    assert shapes.colours == (
        FIXTURE_COLOURS["anchor"],
        FIXTURE_COLOURS["peg"],
        KIND_COLOURS["contact"],
        KIND_COLOURS["gripper"],
    )
    assert len(shapes.ellipsoids) == 3  # the gripper's pose is known, not estimated
    np.testing.assert_allclose(shapes.ellipsoids[0].half_sizes, [3e-3, 6e-3, 9e-3])
    scene = mujoco.MjvScene(mujoco.MjModel.from_xml_string("<mujoco/>"), 100)
    assert draw_shapes(scene, shapes) == 3 + 4 + 3  # edges, points, ellipsoids
    small = mujoco.MjvScene(mujoco.MjModel.from_xml_string("<mujoco/>"), 5)
    assert draw_shapes(small, shapes) == 5  # a full scene takes what fits


def test_anchor_peg_and_clip_render_in_their_own_colours() -> None:
    import mujoco

    world = build_world(load_scenario(scenario_path("peg-and-clip")), seed=0)
    colours = fixture_colours(world.model, world.spec.fixtures)
    names = {mujoco.mj_id2name(world.model, mujoco.mjtObj.mjOBJ_GEOM, g) for g in colours}
    assert {"A1", "P1", "C1_base", "C1_jaw_a"} <= names
    try:
        renderer = SceneRenderer(world, 400, 300, camera=None, shadows=False)
    except SimulationError as exc:
        pytest.skip(str(exc))
    with renderer:
        renderer.look_at(scene_points(world))
        frame = renderer.frame().astype(int)
    r, g, b = frame[..., 0], frame[..., 1], frame[..., 2]
    gold = (r > 150) & (g > 100) & (b < 60) & (r - g < 90)
    green = (g > r + 40) & (g > b + 40)
    magenta = (r > g + 50) & (b > g + 50)
    assert gold.sum() > 50 and green.sum() > 20 and magenta.sum() > 50
