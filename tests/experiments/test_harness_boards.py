"""Random harness boards: drawn from a seed, inside the workspace, plannable, repeatable."""

from __future__ import annotations

import pytest

pytest.importorskip("yaml")

from tautwire.experiments.harness_boards import BOX_X, BOX_Y, ENTRIES, draw_board
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
