"""The model a run starts from: the board design's picture of each cable."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("pydantic")  # scenario files are the sim extra's

from tautwire.scenario import load_scenario
from tautwire.scenario.registry import scenario_path
from tautwire.tasks.initial_model import BOARD_SURFACE, initial_graph


@pytest.mark.parametrize("name", ["harness", "peg-and-clip", "anchor-rotate"])
def test_a_hanging_end_rests_on_the_board_not_below_it(name: str) -> None:
    scenario = load_scenario(scenario_path(name))
    for spec in scenario.cables:
        graph = initial_graph(scenario, spec)
        assert graph.rest_height == pytest.approx(BOARD_SURFACE + spec.radius)
        z = graph.positions[:, 2]
        assert np.all(z >= BOARD_SURFACE + spec.radius - 1e-12), (spec.name, z)
        # the cable's length is kept: the end lies on the board at the gripper's feet
        assert graph.total_length == pytest.approx(spec.length)
        end = graph.points[-1]
        if end.kind == "free":
            assert end.position[2] == pytest.approx(BOARD_SURFACE + spec.radius)
            held = graph.points[-2].position
            assert end.position[:2] == pytest.approx(held[:2])
