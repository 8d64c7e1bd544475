import json
from pathlib import Path

import pytest

from tautwire.cli.main import main

SCENARIOS = Path(__file__).parents[2] / "scenarios"


@pytest.mark.slow
def test_run_json_result(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status = main(["run", str(SCENARIOS / "anchor-rotate.yaml"), "--json", "--out", str(tmp_path)])
    out = capsys.readouterr().out
    result = json.loads(out)  # stdout holds exactly one JSON object
    assert status == 0 and result["success"] is True
    assert [s["letter"] for s in result["steps"]] == ["D", "I"]
    assert all(s["outcome"] == "success" and s["cause"] is None for s in result["steps"])
    (contact,) = result["contacts"]
    assert contact["fixture"] == "A1" and contact["error"] < 0.003
    assert len(contact["std"]) == 3
    assert result["stiffness"]["truth"] == 200.0
    assert result["max_force"] < 15.0
    assert set(result["model_error"]) == {
        "horizontal_mean",
        "horizontal_max",
        "vertical_mean",
        "vertical_max",
    }
    assert json.loads((tmp_path / "result.json").read_text())["steps"] == result["steps"]


def test_run_bad_scenario_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("version: 1\nname: x\nrobot: 3\n")
    assert main(["run", str(bad)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "bad.yaml" in err[0]
