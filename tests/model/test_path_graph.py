import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.model import Edge, FeaturePoint, PathGraph


def graph() -> PathGraph:
    return PathGraph.from_positions(
        [[0.0, 0.0, 0.1], [0.3, 0.0, 0.1], [0.3, 0.4, 0.1]],
        mass_per_length=0.03,
        stiffness=200.0,
        kinds=["fixed", "contact", "gripper"],
    )


def test_masses_and_edge_stiffness_follow_the_cable() -> None:
    g = graph()
    assert g.total_length == pytest.approx(0.7)
    assert [pt.mass for pt in g.points] == pytest.approx([0.0045, 0.0105, 0.006])
    # springs in series add up to the whole cable's stiffness
    assert 1.0 / sum(1.0 / e.stiffness for e in g.edges) == pytest.approx(200.0)


def test_insert_goal_point_interpolates_and_splits_the_edge() -> None:
    g = graph()
    i = g.insert_point(1, 0.25, label="clip")
    assert i == 2 and len(g) == 4
    assert g.points[i].position == pytest.approx([0.3, 0.1, 0.1])
    assert g.points[i].kind == "goal"
    assert g.lengths == pytest.approx([0.3, 0.1, 0.3])
    assert 1.0 / sum(1.0 / e.stiffness for e in g.edges) == pytest.approx(200.0)
    assert sum(pt.mass for pt in g.points) == pytest.approx(0.03 * 0.7)


def test_remove_point_joins_edges() -> None:
    g = graph()
    i = g.insert_at_arc_length(0.55)
    g.remove_point(i)
    assert len(g) == 3
    assert g.lengths == pytest.approx([0.3, 0.4])
    assert 1.0 / sum(1.0 / e.stiffness for e in g.edges) == pytest.approx(200.0)
    with pytest.raises(InvalidArgumentError):
        g.remove_point(0)


def test_locate_and_insert_at_arc_length() -> None:
    g = graph()
    assert g.locate(0.45) == (1, pytest.approx(0.375))
    assert g.insert_at_arc_length(0.3) == 1  # an existing point is reused
    with pytest.raises(InvalidArgumentError):
        g.locate(0.8)


def test_sag_is_kept_up_to_date() -> None:
    g = PathGraph.from_positions([[0, 0, 0], [0.4, 0, 0]], 0.03, lengths=[0.41])
    assert g.edges[0].sag == pytest.approx(np.sqrt(6 * 0.4 * 0.01) / 4)
    g.set_positions([[0, 0, 0], [0.41, 0, 0]])
    assert g.edges[0].sag == 0.0


def test_constructor_validates() -> None:
    p = [FeaturePoint([0, 0, 0]), FeaturePoint([1, 0, 0])]
    with pytest.raises(InvalidArgumentError):
        PathGraph(p, [], 0.03)
    with pytest.raises(InvalidArgumentError):
        PathGraph(p, [Edge(1.0)], -0.1)
    with pytest.raises(InvalidArgumentError):
        FeaturePoint([0, 0, np.nan])
    with pytest.raises(InvalidArgumentError):
        Edge(-1.0)
