import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.model import PathGraph
from tautwire.primitives.model_edits import add_point, drop_new_points, move_hold


def _graph() -> PathGraph:
    g = PathGraph.from_positions(
        [[0.0, 0, 0], [0.3, 0, 0], [0.5, 0, 0]],
        mass_per_length=0.03,
        kinds=["fixed", "gripper", "free"],
        labels=["A1", "left", "end"],
    )
    for e in g.edges:
        e.stiffness = 100.0 * 0.5 / e.length  # EA = 50 N
    return g


def test_sliding_moves_the_hold_and_keeps_ea() -> None:
    g = _graph()
    move_hold(g, 1, 0.05)
    assert g.edges[0].length == pytest.approx(0.35) and g.edges[1].length == pytest.approx(0.15)
    assert [e.stiffness * e.length for e in g.edges] == pytest.approx([50.0, 50.0])
    assert g.total_length == pytest.approx(0.5)
    with pytest.raises(InvalidArgumentError, match="beyond the gripper"):
        move_hold(g, 1, 0.2)


@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_sliding_past_a_released_point_merges_it(sense: float) -> None:
    """A hand-over leaves a free point where the first gripper let go: it holds nothing back."""
    xs = [0.0, 0.3, 0.35, 0.8] if sense > 0 else [0.0, 0.45, 0.5, 0.8]
    kinds = (
        ["free", "gripper", "free", "free"] if sense > 0 else ["free", "free", "gripper", "fixed"]
    )
    g = PathGraph.from_positions(
        [[x, 0.0, 0.0] for x in xs],
        mass_per_length=0.03,
        kinds=kinds,  # type: ignore[arg-type]
    )
    g.points[0].kind = "fixed" if sense > 0 else "free"
    for e in g.edges:
        e.stiffness = 50.0 / e.length  # EA = 50 N
    held = 1 if sense > 0 else 2
    move_hold(g, held, sense * 0.1)
    assert len(g.points) == 3 and g.total_length == pytest.approx(0.8)
    gripper = g.index_of("gripper")
    assert gripper is not None
    assert g.arc_lengths()[gripper] == pytest.approx(0.4)
    assert [e.stiffness * e.length for e in g.edges] == pytest.approx([50.0, 50.0])
    # nor is the cable's end
    with pytest.raises(InvalidArgumentError, match="beyond the gripper"):
        move_hold(g, gripper, sense * 0.5)


def test_added_points_and_dropped_estimates() -> None:
    g = _graph()
    known = [id(p) for p in g.points]
    i = add_point(g, 0.1, np.array([0.1, 0.0, -0.01]), "contact", "estimated")
    assert g.points[i].kind == "contact" and len(g.points) == 4
    drop_new_points(g, known)
    assert len(g.points) == 3
    j = add_point(g, 0.2, np.array([0.2, 0.0, 0.0]), "fixed", "C1")
    assert g.points[j].label == "C1" and g.arc_lengths()[j] == pytest.approx(0.2)


def test_a_point_on_the_sensing_edge_shortens_it_and_stiffens_k() -> None:
    from tests.primitives.conftest import context

    ctx = context(k_initial=100.0)
    # the edge from A1 (0.1 m) to the gripper (0.4 m) is 0.3 m long
    from tautwire.primitives.model_edits import add_on_sensing_edge

    add_on_sensing_edge(ctx.estimator, 0.2, np.array([0.3, 0.0, 0.1]), "gripper", "right")
    assert len(ctx.graph.points) == 3
    assert ctx.estimator.contact_index == 1  # the new gripper point
    assert ctx.estimator.elasticity.k_hat == pytest.approx(300.0)  # 100 * 0.3 / 0.1
