"""One model per cable: which cable and which sensing context a step works on."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.model import PathGraph
from tautwire.primitives import PrimitiveContext, make_context
from tautwire.primitives.release import release_point
from tautwire.robot import Arm
from tautwire.tasks.cable_models import CableModels, StepModelError


def _graph(y: float, holders: list[Arm]) -> PathGraph:
    points = [np.array([0.1, y, 0.1])]
    kinds = ["fixed"]
    labels = ["A"]
    for k, arm in enumerate(holders):
        points.append(np.array([0.3 + 0.1 * k, y, 0.1]))
        kinds.append("gripper")
        labels.append(arm)
    return PathGraph.from_positions(points, 0.03, kinds=kinds, labels=labels)  # type: ignore[arg-type]


def _factory(cable: str, arm: Arm, graph: PathGraph, k: float | None) -> PrimitiveContext:
    return make_context(graph, arm, k_initial=100.0 if k is None else k)


def _models(sensors: frozenset[Arm], **cables: list[Arm]) -> CableModels:
    graphs = {name: _graph(0.1 * i, arms) for i, (name, arms) in enumerate(cables.items())}
    return CableModels(graphs, sensors, _factory)


BOTH: frozenset[Arm] = frozenset(("left", "right"))


def test_each_cable_has_its_own_graph_and_each_holding_sensor_its_own_context() -> None:
    models = _models(BOTH, W1=["left"], W2=["right"])
    w1 = models.select("D", {"arm": "left", "force": 3.0})
    w2 = models.select("D", {"arm": "right", "cable": "W2", "force": 3.0})
    assert (w1.cable, w1.context.arm) == ("W1", "left")
    assert (w2.cable, w2.context.arm) == ("W2", "right")
    assert w1.context.graph is models.graphs["W1"]
    assert w2.context.graph is models.graphs["W2"]
    assert w1.context.estimator is not w2.context.estimator


def test_a_step_without_a_cable_works_on_the_one_its_gripper_holds() -> None:
    models = _models(BOTH, W1=["left"], W2=["right"])
    assert models.select("G", {"arm": "right"}).cable == "W2"


def test_a_sensing_primitive_on_a_cable_its_gripper_does_not_hold_is_refused() -> None:
    models = _models(BOTH, W1=["left"], W2=["right"])
    with pytest.raises(StepModelError, match="does not hold W2"):
        models.select("D", {"arm": "left", "cable": "W2", "force": 3.0})
    with pytest.raises(StepModelError, match="no cable named 'W3'"):
        models.select("D", {"arm": "left", "cable": "W3", "force": 3.0})


def test_a_gripper_without_a_sensor_cannot_run_a_sensing_primitive() -> None:
    models = _models(frozenset(("left",)), W1=["left", "right"])
    with pytest.raises(StepModelError, match="carries no force sensor"):
        models.select("D", {"arm": "right", "force": 3.0})
    # a parallel primitive runs on the sensing gripper's context
    assert models.select("A", {"force": 3.0}).context.arm == "left"


def test_with_two_sensors_each_gripper_of_one_cable_senses_its_own_side() -> None:
    models = _models(BOTH, W1=["left", "right"])
    left = models.select("D", {"arm": "left", "force": 3.0}).context
    right = models.select("D", {"arm": "right", "force": 3.0}).context
    assert left.arm == "left" and right.arm == "right"
    assert left.graph is right.graph  # one model of the cable


def test_a_grasp_runs_on_the_holding_gripper_s_context_and_a_later_context_inherits() -> None:
    models = _models(BOTH, W1=["left"])
    first = models.select("D", {"arm": "left", "force": 3.0})
    first.context.tension = 3.0
    models.ran(first)
    grasp = models.select("H", {"arm": "right", "at": 0.2})
    assert grasp.context is first.context
    # the right gripper grasped: the model has its point now
    graph = models.graphs["W1"]
    i = graph.insert_at_arc_length(0.1, kind="gripper", label="right")
    graph.points[i].kind, graph.points[i].label = "gripper", "right"
    right = models.select("D", {"arm": "right", "force": 3.0}).context
    assert right is not first.context and right.tension == 3.0


def test_after_a_release_the_gripper_holds_nothing_and_only_moves_can_use_it() -> None:
    models = _models(BOTH, W1=["left"], W2=["right"])
    step = models.select("", {"arm": "right"}, "release")
    assert step.cable == "W2"
    positions = {"left": np.array([0.3, 0.0, 0.1]), "right": np.array([0.3, 0.1, 0.1])}
    release_point(models.graphs["W2"], "right", positions)
    models.ran(step)
    assert models.held_by("right") is None
    assert ("W2", "right") not in models.contexts
    assert models.final("W2") is step.context  # the model stays, for scoring
    with pytest.raises(StepModelError, match="holds no cable"):
        models.select("G", {"arm": "right"})
    free = models.select("", {"arm": "right", "to": [0.3, 0.0, 0.2]}, "move")
    assert free.cable is None


def test_with_one_cable_a_step_of_a_free_gripper_works_on_it() -> None:
    models = _models(frozenset(("left",)), W1=["left"])
    assert models.select("H", {"arm": "right", "at": 0.1}).cable == "W1"


def test_a_release_or_an_untaut_move_needs_no_sensor_on_its_gripper() -> None:
    models = _models(frozenset(("left",)), W1=["left", "right"])
    assert models.select("", {"arm": "right"}, "release").context.arm == "left"
    untaut = models.select("", {"arm": "right", "by": [0, 0, 0.01], "taut": False}, "move")
    assert untaut.context.arm == "left"
    with pytest.raises(StepModelError, match="carries no force sensor"):
        models.select("", {"arm": "right", "by": [0, 0, 0.01]}, "move")
