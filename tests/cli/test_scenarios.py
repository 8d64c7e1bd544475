"""``tautwire scenarios`` and registered names in place of scenario files."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tautwire.cli.main import main
from tautwire.scenario.registry import registered_scenarios


def test_scenarios_lists_each_registered_scenario_on_one_line(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["scenarios"]) == 0
    lines = capsys.readouterr().out.splitlines()
    entries = registered_scenarios()
    assert len(lines) == len(entries)
    for line, entry in zip(lines, entries, strict=True):
        assert line.split()[0] == entry.name
        assert line.endswith(entry.description)


def test_scenarios_json_is_one_object_with_name_description_and_path(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["scenarios", "--json"]) == 0
    listed = json.loads(capsys.readouterr().out)["scenarios"]
    assert [s["name"] for s in listed] == [e.name for e in registered_scenarios()]
    for s in listed:
        assert Path(s["path"]).is_file()
        assert s["description"]


def test_validate_takes_a_registered_name_from_any_directory(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["validate", "peg-change"]) == 0
    assert "scenario 'peg-change'" in capsys.readouterr().out


@pytest.mark.parametrize("command", ["run", "validate"])
def test_an_unknown_name_is_one_line_with_did_you_mean(
    command: str,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    monkeypatch.chdir(tmp_path)
    assert main([command, "peg-chnge"]) == 1
    captured = capsys.readouterr()
    assert captured.out == ""
    lines = captured.err.splitlines()
    assert len(lines) == 1
    assert "peg-chnge" in lines[0]
    assert "did you mean 'peg-change'" in lines[0]
