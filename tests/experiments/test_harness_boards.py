"""Random harness boards: drawn from a seed, inside the workspace, plannable, repeatable."""

from __future__ import annotations

import pytest

pytest.importorskip("yaml")

import numpy as np

from tautwire.experiments.harness_boards import (
    BOX_X,
    BOX_Y,
    ENTRIES,
    SPACING,
    SPAN_CLEARANCE,
    START_CLEARANCE,
    draw_board,
    random_board,
)
from tautwire.robot.workspace import WORKSPACE
from tautwire.scenario.route_problem import plan_scenario


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_a_board_has_two_routed_cables_inside_the_workspace(seed: int) -> None:
    drawn = draw_board(seed)
    scenario = drawn.scenario
    assert [c.name for c in scenario.cables] == ["W1", "W2"]
    for cable in scenario.cables:
        assert ENTRIES[0] <= len(cable.route) <= ENTRIES[1]
        assert cable.start is not None
    kinds = {f.type for f in scenario.board.fixtures}
    assert "anchor" in kinds and kinds <= {"anchor", "peg", "clip"}
    for f in scenario.board.fixtures:
        assert WORKSPACE.contains(list(f.position))
        if f.type != "anchor":
            assert BOX_X[0] <= f.position[0] <= BOX_X[1]
            assert BOX_Y[0] <= abs(f.position[1]) <= BOX_Y[1]
    plan = plan_scenario(scenario)  # the planner accepts it
    assert {c.name for c in plan.cables} == {"W1", "W2"}
    assert drawn.redraws == len(drawn.refusals)


def test_the_same_seed_draws_the_same_board_and_others_differ() -> None:
    a, b, c = draw_board(5), draw_board(5), draw_board(6)
    assert a.document == b.document and a.redraws == b.redraws
    assert a.document["board"] != c.document["board"]


def test_boards_mix_pegs_windings_and_clips() -> None:
    entries = [e for s in range(8) for c in draw_board(s).scenario.cables for e in c.route]
    fixtures = {
        f.name: f for s in range(8) for f in draw_board(s).scenario.board.fixtures
    }  # names repeat across boards; the kinds are what matter here
    assert any(e.wind for e in entries)
    assert {e.side for e in entries if e.side} == {"left", "right"}
    assert len({f.type for f in fixtures.values()}) == 3


def _off(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    ab = b - a
    t = float(np.clip((p - a) @ ab / float(ab @ ab), 0.0, 1.0))
    return float(np.linalg.norm(p - a - t * ab))


@pytest.mark.parametrize("seed", range(40))
def test_no_fixture_stands_on_an_anchor_or_on_a_span_of_its_route(seed: int) -> None:
    """Random board 360400295 had its F2 10 mm from its anchor, on the span A1 -> F1."""
    board = random_board(np.random.default_rng(seed))
    if board is None:
        return
    where = {
        f["name"]: np.array(f["position"][:2], dtype=float) for f in board["board"]["fixtures"]
    }
    names = list(where)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            assert float(np.linalg.norm(where[a] - where[b])) >= SPACING - 1e-4, (a, b)
    for cable in board["cables"]:
        path = [cable["start"]] + [e["fixture"] for e in cable["route"]]
        for k in range(1, len(path)):
            a, b = where[path[k - 1]], where[path[k]]
            for name in names:
                if name not in (path[k - 1], path[k]):
                    assert _off(where[name], a, b) >= SPAN_CLEARANCE - 1e-4, (name, a, b)

    # the cable as it lies at the start, from its anchor towards its gripper
    arms = {"W1": "left", "W2": "right"}
    for cable in board["cables"]:
        a = where[cable["start"]]
        g = np.array(board["robot"]["grippers"][arms[cable["name"]]]["position"][:2], dtype=float)
        for f in board["board"]["fixtures"]:
            if f["type"] != "anchor":
                assert _off(where[f["name"]], a, g) >= START_CLEARANCE - 1e-4, f["name"]
