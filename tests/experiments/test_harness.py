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
    BOARDS_JSONL,
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


def _campaign(out: Path, boards: int, *, seed: int = 5, resume: bool = False) -> dict[str, Any]:
    from tautwire.experiments.harness import reproduce_harness_boards

    from .fake_trials import fake_board

    return reproduce_harness_boards(boards, 1, seed, out, "serial", trial=fake_board, resume=resume)


def test_each_board_is_written_as_it_ends_and_a_resume_runs_only_the_rest(
    tmp_path: Path,
) -> None:
    from .fake_trials import BOARDS_RUN

    BOARDS_RUN.clear()
    first = _campaign(tmp_path, 4)
    assert BOARDS_RUN == [0, 1, 2, 3] and first["resumed"] == 0
    lines = (tmp_path / BOARDS_JSONL).read_text().splitlines()
    assert [json.loads(line)["index"] for line in lines] == [0, 1, 2, 3]
    assert all(json.loads(line)["campaign"] == {"seed": 5, "steps": None} for line in lines)
    # the machine stopped while board 2 ran and the line of board 3 was being written
    (tmp_path / BOARDS_JSONL).write_text("\n".join([lines[0], lines[1], lines[3][:40]]) + "\n")
    BOARDS_RUN.clear()
    again = _campaign(tmp_path, 6, resume=True)
    # boards 0 and 1 (a failure of its own) are reused, the cut line and the rest run
    assert BOARDS_RUN == [2, 3, 4, 5] and again["resumed"] == 2
    assert [r["board"] for r in again["board_records"]] == [0, 1, 2, 3, 4, 5]
    assert (again["boards"], again["completed"]) == (6, 4)
    assert again["causes"] == {"not_clipped": 1, "error": 1}
    # board 3 raised: a resume runs it again, and only it
    BOARDS_RUN.clear()
    third = _campaign(tmp_path, 6, resume=True)
    assert BOARDS_RUN == [3] and third["resumed"] == 5
    assert third["board_records"] == again["board_records"]
    # without --resume the file starts over
    BOARDS_RUN.clear()
    _campaign(tmp_path, 2)
    assert BOARDS_RUN == [0, 1]
    assert len((tmp_path / BOARDS_JSONL).read_text().splitlines()) == 2


def test_a_resume_over_another_campaign_or_a_broken_line_names_the_file_and_line(
    tmp_path: Path,
) -> None:
    from tautwire.errors import InvalidArgumentError

    _campaign(tmp_path, 2)
    with pytest.raises(InvalidArgumentError, match=r"line 1: a board of another campaign"):
        _campaign(tmp_path, 2, seed=6, resume=True)
    lines = (tmp_path / BOARDS_JSONL).read_text().splitlines()
    (tmp_path / BOARDS_JSONL).write_text("\n".join(["{oops", *lines]) + "\n")
    with pytest.raises(InvalidArgumentError, match=rf"{BOARDS_JSONL}, line 1: not JSON"):
        _campaign(tmp_path, 2, resume=True)
    (tmp_path / BOARDS_JSONL).write_text('{"index": 0}\n' + "\n".join(lines) + "\n")
    with pytest.raises(InvalidArgumentError, match=r"line 1: not a board's record"):
        _campaign(tmp_path, 2, resume=True)


def test_resume_is_for_a_board_campaign(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["reproduce", "harness", "--resume"]) != 0
    assert "--resume: only with --boards" in capsys.readouterr().err


def test_the_worst_boards_title_says_how_it_ended() -> None:
    from tautwire.experiments.harness import _ending

    assert _ending(_record(0)) == "completed"
    failed = _record(1, completed=False, cause="not_clipped", failed_step="23 F (W2)")
    assert _ending(failed) == "failed at step 23 F (W2)"
    # every step ran and one was false: no step to name (seed 29's board 144771393)
    false = _record(2, completed=False, cause="false_success", false_successes=1)
    assert _ending(false) == "every step ran (false_success)"
