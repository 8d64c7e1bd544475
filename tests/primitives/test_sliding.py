"""Sliding (E, B): the cable beyond the sliding gripper."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.model import PathGraph
from tautwire.primitives import make_context
from tautwire.primitives.sliding import _free_beyond

from .conftest import CONTACT, GRIPPER


def test_the_cable_beyond_runs_through_a_released_point_to_the_next_constrained_one() -> None:
    """Random board 208802845: after a hand-over, E read only the cable to the released point."""
    out = np.array([1.0, 0.0, 0.0])
    released = GRIPPER + 0.09 * out
    end = released + np.array([0.0, 0.0, -0.3])
    graph = PathGraph.from_positions(
        [CONTACT, GRIPPER, released, end],
        mass_per_length=0.03,
        kinds=["fixed", "gripper", "free", "free"],
        labels=["A1", "left", "released", "end"],
    )
    ctx = make_context(graph, "left")
    lengths = [e.length for e in graph.edges]
    assert _free_beyond(ctx, 1, +1.0) == pytest.approx(lengths[1] + lengths[2])
    # towards the anchor it stops there (a constrained point)
    assert _free_beyond(ctx, 1, -1.0) == pytest.approx(lengths[0])
    # a gripper further on holds the cable back: the cable up to it
    graph.points[2].kind, graph.points[2].label = "gripper", "right"
    assert _free_beyond(ctx, 1, +1.0) == pytest.approx(lengths[1])


@pytest.mark.slow
def test_a_slide_shorter_than_the_settling_is_judged_on_all_of_it() -> None:
    # random board 1652323633: a 1.1 mm slide ended before E judged any
    # sample and failed as "slipped" at "nan N"
    pytest.importorskip("mujoco")
    from tautwire.experiments.run_scenario import run_scenario
    from tautwire.experiments.trial_scenes import scene_e

    scenario = scene_e(0).scenario
    e = scenario.task[1]
    short = e.model_copy(update={"params": {**e.params, "distance": 0.0011}})
    result, _, _ = run_scenario(scenario.model_copy(update={"task": [scenario.task[0], short]}))
    slide = result.steps[1]
    assert slide["outcome"] == "success", slide
    assert "nan" not in slide["detail"] and slide["truth"]["agrees"]
