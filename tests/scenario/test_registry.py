"""The registry of shipped scenarios: names, descriptions and how an argument resolves."""

from __future__ import annotations

from pathlib import Path

import pytest

from tautwire.scenario import ScenarioError, load_scenario
from tautwire.scenario.registry import (
    registered_scenarios,
    resolve_scenario,
    scenario_folder,
    scenario_names,
    scenario_path,
)

#: The scenarios the commands and reproductions rely on by name.
USED_BY_COMMANDS = {"anchor-rotate", "peg-change", "harness", "peg-and-clip"}


def test_the_scenarios_the_commands_use_are_registered() -> None:
    assert set(scenario_names()) >= USED_BY_COMMANDS


@pytest.mark.parametrize("entry", registered_scenarios(), ids=lambda e: e.name)
def test_every_registered_scenario_is_valid_named_and_described_in_one_line(entry) -> None:  # type: ignore[no-untyped-def]
    scenario = load_scenario(entry.path)
    assert scenario.name == entry.name
    assert entry.description == scenario.description
    assert entry.description and "\n" not in entry.description
    assert len(entry.description) <= 100
    assert entry.path == scenario_path(entry.name)
    assert entry.path.parent == scenario_folder()


def test_a_registered_name_resolves_to_its_packaged_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    path = resolve_scenario("anchor-rotate")
    assert path == scenario_folder() / "anchor-rotate.yaml"
    assert path.is_file()


def test_a_path_that_exists_wins_over_a_registered_name(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "anchor-rotate").write_text("not a scenario", encoding="utf-8")
    assert resolve_scenario("anchor-rotate") == Path("anchor-rotate")
    other = tmp_path / "mine.yaml"
    other.write_text("version: 1\n", encoding="utf-8")
    assert resolve_scenario(str(other)) == other


@pytest.mark.parametrize(
    ("argument", "near"),
    [
        ("anchr-rotate", "'anchor-rotate'"),
        ("peg-chnge", "'peg-change'"),
        ("scenarios/anchor-rotate.yaml", "'anchor-rotate'"),
    ],
)
def test_a_near_miss_gives_one_line_with_did_you_mean(
    argument: str, near: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ScenarioError) as caught:
        resolve_scenario(argument)
    message = str(caught.value)
    assert "\n" not in message
    assert message.startswith(argument + ": no such file or registered scenario")
    assert f"did you mean {near}" in message


def test_a_name_close_to_nothing_lists_the_registered_names(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ScenarioError) as caught:
        resolve_scenario("zzzz")
    message = str(caught.value)
    assert "did you mean" not in message
    assert all(name in message for name in scenario_names())


def test_scenario_path_refuses_an_unknown_name() -> None:
    with pytest.raises(ScenarioError, match="did you mean 'harness'"):
        scenario_path("harnes")
