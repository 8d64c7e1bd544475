from __future__ import annotations

from pathlib import Path

import pytest

from tautwire.cli.main import main
from tautwire.scenario.registry import scenario_folder

SCENARIOS = scenario_folder()


def test_valid_scenario_prints_a_summary(capsys: pytest.CaptureFixture[str]) -> None:
    status = main(["validate", str(SCENARIOS / "harness.yaml")])
    out, err = capsys.readouterr()
    assert status == 0 and err == ""
    assert "scenario 'harness'" in out and "valid" in out
    assert "fixtures: 8" in out and "cables: 2" in out and "task steps: 28" in out
    assert "W1: 0.8 m, 200 N/m, route A1, held by left at 0.35 m" in out
    assert "target route: P1 (left) -> C1 -> C2" in out
    assert "target route: P2 (right, wind 1) -> C3 -> C4" in out
    assert "8. F single_arm_clipping(arm=left, clip=C1, cable=W1)" in out
    assert "2. move(arm=left, to=[0.4455, 0.1605, 0.08], taut=True, cable=W1)" in out


def test_invalid_scenario_gives_one_line_on_stderr(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    text = (SCENARIOS / "peg-and-clip.yaml").read_text(encoding="utf-8")
    path = tmp_path / "bad.yaml"
    path.write_text(text.replace("stiffness: 200.0", "stiffness: -200.0"), encoding="utf-8")
    status = main(["validate", str(path)])
    out, err = capsys.readouterr()
    line = text[: text.index("stiffness: 200.0")].count("\n") + 1
    assert status == 1 and out == ""
    assert err.count("\n") == 1
    assert err.startswith(f"tautwire: error: {path}:{line}: cables[0].stiffness: got -200")


def test_missing_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status = main(["validate", str(tmp_path / "none.yaml")])
    _, err = capsys.readouterr()
    assert status == 1 and "no such file" in err


def test_usage_error_without_argument(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["validate"]) == 2
    assert "SCENARIO" in capsys.readouterr().err
