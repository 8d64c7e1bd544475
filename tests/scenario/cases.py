"""Shared text for the scenario tests: the SCENARIO.md example and edits of it."""

from __future__ import annotations

import pytest

from tautwire.scenario import ScenarioError, parse_scenario
from tautwire.scenario.registry import scenario_folder

SCENARIOS = scenario_folder()
EXAMPLE = (SCENARIOS / "peg-and-clip.yaml").read_text(encoding="utf-8")


def edit(old: str, new: str, text: str = EXAMPLE) -> str:
    """``text`` with the one occurrence of ``old`` replaced by ``new``."""
    assert text.count(old) == 1, f"{old!r} must occur exactly once"
    return text.replace(old, new)


def line_of(text: str, needle: str) -> int:
    """The 1-based line of the first occurrence of ``needle`` in ``text``."""
    assert needle in text, needle
    return text[: text.index(needle)].count("\n") + 1


def error_of(text: str) -> ScenarioError:
    """The error that parsing ``text`` raises (fails the test if none)."""
    with pytest.raises(ScenarioError) as info:
        parse_scenario(text, source="s.yaml")
    return info.value
