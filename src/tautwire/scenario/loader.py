"""Reading scenario files: YAML text to a validated :class:`Scenario`."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import yaml
from pydantic import ValidationError

from tautwire.scenario.error_messages import describe_error
from tautwire.scenario.models import Scenario
from tautwire.scenario.scenario_error import ScenarioError
from tautwire.scenario.source_map import SourceMap, find_duplicate_key

_TOP_LEVEL = ", ".join(Scenario.model_fields)


def load_scenario(path: str | Path) -> Scenario:
    """Read and validate the scenario file at ``path``.

    Raises:
        ScenarioError: if the file cannot be read, is not YAML, or is not a
            valid scenario; its one-line message names the file, the line,
            the field, what is wrong and what is expected.
    """
    name = str(path)
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise ScenarioError(
            name, None, "", "no such file (expected a scenario YAML file)"
        ) from None
    except IsADirectoryError:
        raise ScenarioError(
            name, None, "", "is a directory (expected a scenario YAML file)"
        ) from None
    except UnicodeDecodeError as exc:
        raise ScenarioError(name, None, "", f"not UTF-8 text ({exc.reason})") from None
    except OSError as exc:
        raise ScenarioError(name, None, "", f"cannot read: {exc.strerror}") from None
    return parse_scenario(text, source=name)


def parse_scenario(text: str, source: str = "<string>") -> Scenario:
    """Validate the scenario written in the YAML ``text``.

    Args:
        text: the file's contents.
        source: the name used in error messages.

    Raises:
        ScenarioError: as :func:`load_scenario`.
    """
    loader = yaml.SafeLoader(text)
    try:
        root = loader.get_single_node()
        duplicate = find_duplicate_key(root)
        if duplicate is not None:
            node, field = duplicate
            raise ScenarioError(
                source, node.start_mark.line + 1, field, "repeated key (expected each key once)"
            )
        data: Any = None if root is None else loader.construct_document(root)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = None if mark is None else mark.line + 1
        problem = exc.problem or exc.context or "cannot parse"
        if exc.problem and exc.context:
            problem = f"{exc.problem} ({exc.context})"
        raise ScenarioError(source, line, "", f"invalid YAML: {problem}") from None
    except yaml.YAMLError as exc:
        raise ScenarioError(source, None, "", f"invalid YAML: {exc}") from None
    finally:
        loader.dispose()
    if data is None:
        raise ScenarioError(source, None, "", f"the file is empty (expected the keys {_TOP_LEVEL})")
    return _validate(data, source, SourceMap(root))


def scenario_from_data(data: Mapping[str, Any], source: str = "<data>") -> Scenario:
    """Validate a scenario given as plain data (as YAML would load it).

    Useful for scenarios built in code, e.g. randomised trials. Errors carry
    the field but no line.

    Raises:
        ScenarioError: as :func:`load_scenario`, with ``line`` ``None``.
    """
    return _validate(data, source, SourceMap(None))


def _validate(data: Any, source: str, source_map: SourceMap) -> Scenario:
    """Validate ``data``; turn the topmost validation error into a ScenarioError."""
    if not isinstance(data, Mapping):
        line, _ = source_map.locate(())
        raise ScenarioError(
            source, line, "", f"the document is not a mapping (expected the keys {_TOP_LEVEL})"
        )
    try:
        return Scenario.model_validate(data)
    except ValidationError as exc:
        found = []
        for order, error in enumerate(exc.errors()):
            location, message = describe_error(Scenario, error)
            line, field = source_map.locate(location)
            found.append((line if line is not None else 0, order, line, field, message))
        _, _, line, field, message = min(found)
        raise ScenarioError(source, line, field or "scenario", message) from None
