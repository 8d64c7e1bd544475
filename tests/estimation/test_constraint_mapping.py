import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.constraint_mapping import (
    constraint_matrix,
    map_constraints,
    update_by_constraints,
)
from tautwire.model import PathGraph


def five_point_graph(d: list[float]) -> PathGraph:
    """The paper's Fig. 1: v1 .. v5, v2 and v4 held by the grippers, v3 a clip goal."""
    x = np.concatenate(([0.0], np.cumsum(d)))
    positions = np.column_stack([x, np.zeros(5), np.full(5, 0.1)])
    return PathGraph.from_positions(
        positions, 0.03, lengths=d, kinds=["free", "gripper", "goal", "gripper", "free"]
    )


def test_paper_kronecker_example() -> None:
    d1, d2, d3, d4 = 0.1, 0.15, 0.25, 0.2
    g = five_point_graph([d1, d2, d3, d4])
    p_right = np.array([0.3, -0.2, 0.2])
    p_left = np.array([0.4, 0.15, 0.25])
    M = constraint_matrix(g.arc_lengths(), [1, 3])
    paper = np.array([[1, 0], [d3 / (d2 + d3), d2 / (d2 + d3)], [0, 1]])
    assert M[1:4] == pytest.approx(paper)
    stacked = np.kron(paper, np.eye(3)) @ np.concatenate([p_right, p_left])
    P = map_constraints(g, {1: p_right, 3: p_left})
    assert P[1:4].reshape(-1) == pytest.approx(stacked)


def test_free_ends_hang_under_gravity() -> None:
    g = five_point_graph([0.1, 0.15, 0.25, 0.2])
    p_right, p_left = np.array([0.3, -0.2, 0.3]), np.array([0.4, 0.15, 0.35])
    P = map_constraints(g, {1: p_right, 3: p_left})
    assert P[0] == pytest.approx(p_right - [0, 0, 0.1])
    assert P[4] == pytest.approx(p_left - [0, 0, 0.2])
    P = map_constraints(g, {1: p_right, 3: p_left}, board_height=0.25)
    assert P[4][2] == pytest.approx(0.25)


def test_a_graph_that_knows_its_board_rests_its_hanging_ends_on_it() -> None:
    g = five_point_graph([0.1, 0.15, 0.25, 0.2])
    g.rest_height = 0.0025  # the board at z = 0, a 2.5 mm cable
    p_right, p_left = np.array([0.3, -0.2, 0.12]), np.array([0.4, 0.15, 0.05])
    update_by_constraints(g, {1: p_right, 3: p_left})
    assert g.points[0].position == pytest.approx([0.3, -0.2, 0.02])  # 0.1 m below: above it
    assert g.points[4].position == pytest.approx([0.4, 0.15, 0.0025])  # would be 0.15 below it
    assert g.copy().rest_height == 0.0025
    # an explicit height wins over the graph's
    assert map_constraints(g, {1: p_right, 3: p_left}, board_height=0.01)[4][2] == 0.01


def test_a_rest_height_must_be_finite() -> None:
    g = five_point_graph([0.1, 0.15, 0.25, 0.2])
    with pytest.raises(InvalidArgumentError, match="rest_height"):
        PathGraph(g.points, g.edges, 0.03, rest_height=float("nan"))


def test_update_in_place_refreshes_masses_and_orientation() -> None:
    g = five_point_graph([0.1, 0.15, 0.25, 0.2])
    update_by_constraints(g, {1: [0.0, 0.0, 0.3], 3: [0.0, 0.4, 0.3]})
    assert g.points[2].position == pytest.approx([0.0, 0.15 / 0.4 * 0.4, 0.3])
    # x-axis of the goal point along the cable, i.e. along +y
    from tautwire.model.quaternion import rotate

    assert rotate(g.points[2].orientation, [1, 0, 0]) == pytest.approx([0, 1, 0], abs=1e-9)


@settings(max_examples=50, deadline=None)
@given(
    st.lists(st.floats(0.01, 1.0), min_size=2, max_size=10),
    st.data(),
)
def test_rows_are_convex_weights(d: list[float], data: st.DataObject) -> None:
    s = np.concatenate(([0.0], np.cumsum(d)))
    n = s.size
    constrained = sorted(data.draw(st.sets(st.integers(0, n - 1), min_size=1, max_size=n)))
    M = constraint_matrix(s, constrained)
    assert np.all(M >= 0) and M.sum(axis=1) == pytest.approx(np.ones(n))
    for j, i in enumerate(constrained):
        assert M[i, j] == 1.0


def test_rejects_bad_constraints() -> None:
    with pytest.raises(InvalidArgumentError):
        constraint_matrix([0, 1, 2], [])
    with pytest.raises(InvalidArgumentError):
        constraint_matrix([0, 1, 2], [2, 1])
