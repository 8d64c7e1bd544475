"""The harness experiment: the board campaign's figures, files and the CLI end to end."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("tautwire.sim")  # sets MUJOCO_GL before MuJoCo is first imported

from tautwire.cli.main import main
from tautwire.experiments.harness import (
    BOARDS_CSV,
    BOARDS_JSON,
    BOARDS_MD,
    _untrue_routes,
    summarise_boards,
    worst_board,
)


def _record(board: int, **changes: Any) -> dict[str, Any]:
    record: dict[str, Any] = {
        "board": board,
        "seed": board,
        "redraws": 1,
        "completed": True,
        "false_successes": 0,
        "false_steps": [],
        "true_max_force": 5.0,
        "over_force_limit": False,
        "steps": 20,
        "failed_step": None,
        "cause": None,
        "detail": None,
        "routes_done": 2,
        "model_horizontal_mean": 0.002,
        "model_horizontal_max": 0.004,
        "model_vertical_mean": 0.001,
        "model_vertical_max": 0.002,
        "sim_time": 60.0,
        "wall_time": 50.0,
    }
    record.update(changes)
    return record


def test_the_summary_counts_boards_and_quantiles() -> None:
    records = [
        _record(0),
        _record(1, completed=False, cause="not_clipped", model_horizontal_mean=0.004),
        _record(2, false_successes=2, model_horizontal_mean=0.006),
    ]
    report = summarise_boards(records, seed=0)
    assert (report["boards"], report["completed"], report["false_successes"]) == (3, 2, 2)
    assert report["boards_with_false_successes"] == 1 and report["redraws"] == 3
    assert report["model_error"]["horizontal_mean"]["median"] == pytest.approx(0.004)
    assert report["causes"] == {"not_clipped": 1}
    # false successes are worse than a failure, which is worse than a large error
    assert worst_board(records)["board"] == 2  # type: ignore[index]
    assert worst_board(records[:2])["board"] == 1  # type: ignore[index]
    # a route the model has done and the simulator denies is counted apart
    untrue = _record(3, completed=False, cause="route_untrue", false_routes=1)
    report = summarise_boards([*records, untrue], seed=0)
    assert report["false_routes"] == 1 and report["false_successes"] == 2
    assert report["causes"] == {"not_clipped": 1, "route_untrue": 1}


def test_a_board_whose_steps_agree_but_a_route_does_not_names_it() -> None:
    """Random board 285895290 (seed 2): 46 steps, each true, and W1 ended on F1's wrong side."""
    from tautwire.experiments.harness import BoardRun, _board_record

    cables = [
        {"name": "W1", "route_done": True, "route_truth": {"agrees": False, "detail": "F1: right"}},
        {"name": "W2", "route_done": True, "route_truth": {"agrees": True, "detail": ""}},
    ]
    steps = [{"primitive": "move", "outcome": "success", "truth": {"agrees": True}}]
    result = {"success": False, "steps": steps, "cables": cables, "sim_time": 1.0}
    result["wall_time"] = 1.0
    record = _board_record(0, 7, 0, BoardRun(result, [], {}, 15.0))
    assert record["cause"] == "route_untrue" and record["false_routes"] == 1
    assert record["false_successes"] == 0 and record["detail"] == "W1: F1: right"
    # a false step is still named as such
    steps.append({"primitive": "move", "outcome": "success", "truth": {"agrees": False}})
    result["false_successes"] = 1
    record = _board_record(0, 7, 0, BoardRun(result, [], {}, 15.0))
    assert record["cause"] == "false_success" and record["false_successes"] == 1


@pytest.mark.slow
def test_a_two_board_campaign_through_the_cli(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "h"
    # each board's first three planned steps (its whole task is the harness test's)
    argv = ["reproduce", "harness", "--boards", "2", "--workers", "1", "--seed", "3"]
    assert main([*argv, "--steps", "3", "--backend", "serial", "--out", str(out), "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["boards"] == 2 and len(report["board_records"]) == 2
    assert report["steps"] == 3
    for r in report["board_records"]:
        assert r["steps"] <= 3 and r["routes_done"] == 0, r
    for key in ("completed", "false_successes", "over_force_limit", "wall_time"):
        assert key in report
    assert report["false_successes"] == sum(r["false_successes"] for r in report["board_records"])
    for r in report["board_records"]:
        assert r["completed"] or r["cause"], r  # a failure names its cause
        # every false success is named, with what the simulator showed
        assert len(r["false_steps"]) == r["false_successes"], r
        assert r["over_force_limit"] == (r["true_max_force"] > 15.0)
    assert set(report["model_error"]) == {
        "horizontal_mean",
        "horizontal_max",
        "vertical_mean",
        "vertical_max",
    }
    for name in (BOARDS_JSON, BOARDS_MD, BOARDS_CSV, "harness_worst_board.png"):
        assert (out / name).stat().st_size > 0, name
    assert len((out / BOARDS_CSV).read_text().splitlines()) == 3


def test_harness_options_are_checked(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["reproduce", "harness", "--trials", "3"]) != 0
    assert "not for harness" in capsys.readouterr().err
    assert main(["reproduce", "harness", "--workers", "2"]) != 0
    assert "only with --boards" in capsys.readouterr().err
    assert main(["reproduce", "fig5a", "--boards", "2"]) != 0
    assert "only for harness" in capsys.readouterr().err
    assert main(["reproduce", "harness", "--steps", "2"]) != 0
    assert "only with --boards" in capsys.readouterr().err
    assert main(["reproduce", "table1", "--steps", "2"]) != 0
    assert "only for harness --boards" in capsys.readouterr().err


def test_a_run_whose_steps_all_agreed_says_which_route_the_simulator_denies() -> None:
    done = {"name": "W1", "route_done": True, "route_truth": {"agrees": True, "detail": "ok"}}
    denied = {
        "name": "W2",
        "route_done": True,
        "route_truth": {"agrees": False, "detail": "F6 does not hold the cable"},
    }
    assert _untrue_routes({"cables": [done]}) == []
    assert _untrue_routes({"cables": [done, denied]}) == ["W2: F6 does not hold the cable"]
