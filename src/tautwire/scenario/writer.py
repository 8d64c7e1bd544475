"""Writing a scenario back as a file: the inverse of the loader."""

from __future__ import annotations

from typing import Any

import yaml

from tautwire.scenario.models import Scenario


def scenario_document(scenario: Scenario) -> dict[str, Any]:
    """The plain data a scenario file holds (steps flat, tuples as lists).

    ``scenario_from_data(scenario_document(s)) == s`` for every scenario.
    """
    document: dict[str, Any] = _plain(scenario.model_dump(exclude={"task"}))
    document["task"] = [
        {"primitive": step.primitive, **_plain(step.params)} for step in scenario.task
    ]
    return document


def dump_scenario(scenario: Scenario) -> str:
    """The YAML text of a scenario file, keys in the documented order."""
    return yaml.safe_dump(scenario_document(scenario), sort_keys=False, default_flow_style=None)


def _plain(value: Any) -> Any:
    """Tuples as lists, recursively, so YAML writes plain sequences."""
    if isinstance(value, dict):
        return {key: _plain(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [_plain(item) for item in value]
    return value
