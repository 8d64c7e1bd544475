"""The command line under faults: every fault ends in a result with a named cause, no traceback."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tautwire.cli.main import INTERNAL_ERROR, main
from tests.cli.test_run import TENSION_ONLY

FROZEN = TENSION_ONLY + "faults:\n  - {type: freeze, at: 0.5, duration: 1.0}\n"


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "faulty.yaml"
    path.write_text(text)
    return path


def test_a_fault_ends_in_a_json_result_with_its_cause(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    status = main(["run", str(_write(tmp_path, FROZEN)), "--json"])
    captured = capsys.readouterr()
    result = json.loads(captured.out)
    assert status == 1 and result["success"] is False
    assert result["steps"][-1]["cause"] == "sensor_stale"
    assert "Traceback" not in captured.err


def test_a_fault_ends_in_the_table_with_its_cause(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    status = main(["run", str(_write(tmp_path, FROZEN))])
    captured = capsys.readouterr()
    assert status == 1 and "sensor_stale" in captured.out
    assert "stiffness: k_hat" in captured.out and "Traceback" not in captured.err


def test_an_unexpected_exception_is_one_line_and_status_70(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    def broken(*args: object, **kwargs: object) -> None:
        raise RuntimeError("something\nunforeseen")

    monkeypatch.setattr("tautwire.experiments.run_scenario.run_scenario", broken)
    status = main(["run", str(_write(tmp_path, TENSION_ONLY)), "--json"])
    captured = capsys.readouterr()
    assert status == INTERNAL_ERROR == 70
    assert captured.out == ""
    lines = captured.err.strip().splitlines()
    assert lines == ["tautwire: error: internal error: RuntimeError: something unforeseen"]


def test_a_stiffness_that_was_not_estimated_is_a_dash() -> None:
    from tautwire.cli.run import _newtons_per_metre

    assert _newtons_per_metre(None) == "-"
    assert _newtons_per_metre(199.26) == "199.3 N/m"


def test_validate_lists_the_faults(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    text = TENSION_ONLY + (
        "faults:\n  - {type: nan, at: 1.0}\n  - {type: spike, at: 2, force: [0, 0, 40]}\n"
    )
    assert main(["validate", str(_write(tmp_path, text))]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[-3:] == [
        "faults (simulation only): 2",
        "  nan at 1 s",
        "  spike at 2 s (force=[0, 0, 40])",
    ]
