"""scenario_guard: the run's guard from the scenario; the tare's expected load at rest."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tautwire.model import GRAVITY
from tautwire.scenario import WORKSPACE, load_scenario
from tautwire.scenario.registry import scenario_folder
from tautwire.sim.build import build_world, robot_of
from tautwire.tasks.robot_guard import TARE_SAMPLES, spike_bound
from tautwire.tasks.scenario_guard import (
    REACH,
    REACH_MARGIN,
    TARE_LOAD_FACTOR,
    rest_loads,
    scenario_guard,
)

SCENARIOS = scenario_folder()


def test_rest_load_is_the_weight_share_and_the_tolerance_a_multiple_of_the_weight() -> None:
    scenario = load_scenario(SCENARIOS / "anchor-rotate.yaml")
    expected, tolerance = rest_loads(scenario)
    assert set(expected) == {"left"}
    # one edge, anchor to gripper (0.40 m): half of it hangs on the gripper
    np.testing.assert_allclose(expected["left"], 0.5 * 0.40 * 0.030 * GRAVITY)
    assert tolerance == pytest.approx(TARE_LOAD_FACTOR * 0.40 * 0.030 * 9.81)


@pytest.mark.parametrize("path", sorted(SCENARIOS.glob("*.yaml")), ids=lambda p: p.name)
def test_the_true_load_at_rest_is_within_the_tare_tolerance(path: Path) -> None:
    """So the tare never removes a real load of the shipped scenes (measured: at most 0.3 of it)."""
    scenario = load_scenario(path)
    world = build_world(scenario)
    expected, tolerance = rest_loads(scenario)
    for arm, load in expected.items():
        force, _ = world.wrench(arm)  # noise-free
        assert np.linalg.norm(force - load) < 0.5 * tolerance


def test_the_guard_takes_the_scenarios_limits_noise_and_workspace() -> None:
    scenario = load_scenario(SCENARIOS / "anchor-rotate.yaml")
    world = build_world(scenario)
    guard = scenario_guard(robot_of(world), scenario)
    assert guard.spike_bound == pytest.approx(spike_bound(15.0, 0.05, 0.1, 0.004))
    fresh = []
    for _ in range(TARE_SAMPLES + 2):
        fresh.append(guard.fresh)
        guard.hold()
    assert fresh == [False] * TARE_SAMPLES + [True, True]
    assert not np.any(guard.offsets["left"])  # a clean sensor: nothing to tare


def test_the_reach_is_the_placement_box_grown_sideways_and_up_but_not_below_the_board() -> None:
    assert REACH.lower == (
        WORKSPACE.lower[0] - REACH_MARGIN,
        WORKSPACE.lower[1] - REACH_MARGIN,
        0.0,
    )
    assert REACH.upper == tuple(v + REACH_MARGIN for v in WORKSPACE.upper)
