import json
from pathlib import Path

import pytest

from tautwire.cli.main import main


def test_demo_json_and_files(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["demo", "--synthetic", "--json", "--out", str(tmp_path), "--seed", "1"]) == 0
    result = json.loads(capsys.readouterr().out)
    c = result["contact"]
    assert c["error_half_circle"] <= 0.0015
    assert c["error_full_circle"] <= 0.0010
    assert c["change_declared_after"] is not None and c["change_declared_after"] <= 5
    assert c["samples_to_2mm_after_change"] is not None and c["samples_to_2mm_after_change"] <= 30
    for case in result["stiffness"]:
        assert abs(case["relative_error"]) <= 0.05
    assert (tmp_path / "contact_estimation.png").stat().st_size > 10_000
    assert json.loads((tmp_path / "result.json").read_text()) == result


def test_demo_table(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["demo", "--synthetic", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "error after half a circle" in out and "k_hat" in out


@pytest.mark.slow
def test_simulated_demo_json(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    import importlib.util

    rrd = tmp_path / "demo.rrd"
    recording = importlib.util.find_spec("rerun") is not None  # the extra tautwire[rerun]
    extra = ["--rerun", str(rrd)] if recording else []
    assert main(["demo", "--json", "--no-video", "--out", str(tmp_path), *extra]) == 0
    result = json.loads(capsys.readouterr().out)
    if recording:
        from tests.viz.test_rerun_recorder import _rows

        assert result["files"]["rerun"] == str(rrd)
        rows = _rows(rrd)
        assert rows["/steps"] == 4  # D and I, a start and an end line each
        assert rows["/model/points"] == rows["/truth/cable"] > 100
        assert rows["/contact/estimate"] == rows["/contact/error"] > 100
    run = result["run"]
    assert run["success"] and [s["letter"] for s in run["steps"]] == ["D", "I"]
    anchor = next(c for c in run["contacts"] if c["fixture"] == "A1")
    assert anchor["error"] < 0.003
    assert result["changes"]  # the peg took over and the robot noticed
    assert (tmp_path / "contact_estimation.png").exists()
