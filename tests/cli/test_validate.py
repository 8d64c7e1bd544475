from __future__ import annotations

import json
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
    assert "fixtures: 10" in out and "cables: 2" in out and "task steps: 48" in out
    assert "W1: 0.8 m, 200 N/m, route A1, held by left at 0.3 m" in out
    assert "target route: C1 -> P1 (left) -> C2 -> C3" in out
    assert "target route: P2 (right, wind 1) -> C4 -> C5 -> P3 (right)" in out
    assert "4. F single_arm_clipping(arm=left, clip=C1, cable=W1)" in out
    assert "2. move(arm=left, to=[0.3777, 0.12, 0.1172], taut=True, observe=True, cable=W1)" in out


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


def test_json_of_a_missing_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["validate", str(tmp_path / "none.yaml"), "--json"]) == 1
    out, err = capsys.readouterr()
    obj = json.loads(out)
    assert obj["valid"] is False and len(obj["problems"]) == 1 and err.count("\n") == 1


def test_usage_error_without_argument(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["validate"]) == 2
    assert "SCENARIO" in capsys.readouterr().err


def _edited(tmp_path: Path, old: str, new: str, name: str = "s.yaml") -> tuple[Path, str]:
    text = (SCENARIOS / "peg-and-clip.yaml").read_text(encoding="utf-8")
    assert text.count(old) == 1
    path = tmp_path / name
    path.write_text(text.replace(old, new), encoding="utf-8")
    return path, text


def test_a_control_period_the_simulator_refuses_is_an_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path, text = _edited(tmp_path, "control_period: 0.004", "control_period: 0.0045")
    assert main(["validate", str(path)]) == 1
    out, err = capsys.readouterr()
    line = text[: text.index("control_period")].count("\n") + 1
    assert out == "" and err.count("\n") == 1
    assert err.startswith(f"tautwire: error: {path}:{line}: robot.control_period: not simulable")
    assert "whole multiple of 0.001 s" in err


def test_a_cable_the_wave_speed_guard_refuses_is_an_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path, _ = _edited(tmp_path, "force_limit: 15.0", "force_limit: 100000.0")
    assert main(["validate", str(path)]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and ": cables[0]: not simulable: cable W1: the wave-speed" in err


def test_json_of_a_valid_and_an_invalid_scenario(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["validate", str(SCENARIOS / "peg-and-clip.yaml"), "--json"]) == 0
    out, err = capsys.readouterr()
    obj = json.loads(out)
    assert err == "" and obj["valid"] is True and obj["problems"] == []
    assert obj["scenario"]["cables"][0]["stiffness"] == 200.0
    path, _ = _edited(tmp_path, "seed: 3", "seed: x\ncolour: red")
    assert main(["validate", str(path), "--json"]) == 1
    out, err = capsys.readouterr()
    obj = json.loads(out)
    assert obj["valid"] is False and "scenario" not in obj
    assert [p["field"] for p in obj["problems"]] == ["seed", "colour"]
    assert err.count("\n") == 2 and all(e.startswith("tautwire: error: ") for e in err.splitlines())


def test_every_problem_is_one_line_of_stderr(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path, _ = _edited(tmp_path, "  force_limit: 15.0", "  force_limt: 15.0\n  colour: red")
    assert main(["validate", str(path)]) == 1
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) == 2 and "did you mean 'force_limit'?" in lines[0]


ALIAS_BOMB = "a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
    f"{b}: &{b} [{', '.join([f'*{a}'] * 9)}]\n" for a, b in zip("abcdefgh", "bcdefghi", strict=True)
)


@pytest.mark.parametrize(
    ("content", "words"),
    [
        (b"version: 1\nname: a\x00b\n", "control character U+0000"),
        (ALIAS_BOMB.encode(), "through aliases"),
        (b"x: " + b"[" * 5000 + b"]" * 5000, "nest"),
        (b"version: 1\n\xff\xfe\n", "not UTF-8 text"),
        (b"version: 1\n  - : : [\n", "invalid YAML"),
        (b"", "empty"),
    ],
    ids=["nul", "alias-bomb", "deep", "not-utf8", "syntax", "empty"],
)
def test_hostile_files_give_one_line_and_status_1(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], content: bytes, words: str
) -> None:
    path = tmp_path / "hostile.yaml"
    path.write_bytes(content)
    assert main(["validate", str(path)]) == 1
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and words in err
    assert err.startswith(f"tautwire: error: {path}")


def test_a_huge_file_is_one_line_and_status_1(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "huge.yaml"
    with path.open("wb") as fh:
        fh.truncate(19_000_000)
    assert main(["validate", str(path)]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "19,000,000 bytes is larger than 1,000,000" in err


def test_a_world_that_diverges_while_it_settles_is_an_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path, _ = _edited(tmp_path, "stiffness: 200.0", "stiffness: 1.0e9")  # a number, not text
    assert main(["validate", str(path)]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1  # MuJoCo's own warnings are kept off the terminal
    assert "not simulable: the simulation diverged" in err
