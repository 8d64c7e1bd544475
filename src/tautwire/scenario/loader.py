"""Reading scenario files: YAML text to a validated :class:`Scenario`.

Any text, however hostile, is answered within about a second and a few
megabytes (:mod:`~tautwire.scenario.bounded_yaml`): a file over 1 MB is
refused before it is read, aliases are bounded, control characters are
named with their line and column. Every problem of a file is reported, one
line each, the highest in the file first.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from tautwire.scenario.bounded_yaml import MAX_BYTES, YamlError, compose_bounded, construct
from tautwire.scenario.error_messages import describe_errors
from tautwire.scenario.issue import Issue
from tautwire.scenario.models import Scenario
from tautwire.scenario.scenario_error import ScenarioError
from tautwire.scenario.source_map import SourceMap, find_duplicate_key

_TOP_LEVEL = ", ".join(Scenario.model_fields)
#: Most problems listed for one file; the rest are counted.
MAX_LISTED = 50


def read_scenario_text(path: str | Path) -> str:
    """The text of the scenario file at ``path``, refused past 1 MB before reading it.

    A UTF-8 byte-order mark is dropped.

    Raises:
        ScenarioError: if the file is missing, not a regular file, larger
            than :data:`~tautwire.scenario.bounded_yaml.MAX_BYTES`, or not
            UTF-8 text.
    """
    name = str(path)
    file = Path(path)
    try:
        size = file.stat().st_size
        if file.is_dir():
            raise IsADirectoryError(name)
        if size > MAX_BYTES:
            raise ScenarioError(
                name,
                None,
                "",
                f"{size:,} bytes is larger than {MAX_BYTES:,} (expected a scenario of a few kB)",
            )
        with file.open("rb") as fh:
            raw = fh.read(MAX_BYTES + 1)  # a device or a growing file stops here
    except FileNotFoundError:
        raise ScenarioError(
            name, None, "", "no such file (expected a scenario YAML file)"
        ) from None
    except IsADirectoryError:
        raise ScenarioError(
            name, None, "", "is a directory (expected a scenario YAML file)"
        ) from None
    except OSError as exc:
        raise ScenarioError(name, None, "", f"cannot read: {exc.strerror}") from None
    if len(raw) > MAX_BYTES:
        raise ScenarioError(
            name, None, "", f"larger than {MAX_BYTES:,} bytes (expected a scenario of a few kB)"
        )
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        raise ScenarioError(
            name, line, "", f"not UTF-8 text ({exc.reason} at byte {exc.start})"
        ) from None


def load_scenario(path: str | Path) -> Scenario:
    """Read and validate the scenario file at ``path``.

    Raises:
        ScenarioError: if the file cannot be read, is not YAML, or is not a
            valid scenario; its message has one line per problem, each
            naming the file, the line, the field, what is wrong and what is
            expected.
    """
    return parse_scenario(read_scenario_text(path), source=str(path))


def parse_scenario(text: str, source: str = "<string>") -> Scenario:
    """Validate the scenario written in the YAML ``text``.

    Args:
        text: the file's contents.
        source: the name used in error messages.

    Raises:
        ScenarioError: as :func:`load_scenario`.
    """
    root, data = _document(text, source)
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


def issues_error(text: str, source: str, issues: Sequence[Issue]) -> ScenarioError:
    """The error that lists ``issues`` found in the scenario ``text`` by a later check.

    For checks beyond the schema (what the simulator would refuse): each
    issue gets the line and the field name of its location in ``text``.

    Args:
        text: the scenario file's text (already accepted by :func:`parse_scenario`).
        source: the name used in messages.
        issues: at least one issue.
    """
    root, _ = _document(text, source)
    source_map = SourceMap(root)
    return _error(source, [(*source_map.locate(i.location), i.message) for i in issues], "scenario")


def _document(text: str, source: str) -> tuple[Any, object]:
    """The node tree and the data of ``text``, every YAML problem as a ScenarioError."""
    try:
        root = compose_bounded(text)
        duplicate = find_duplicate_key(root)
        if duplicate is not None:
            node, field = duplicate
            raise ScenarioError(
                source, node.start_mark.line + 1, field, "repeated key (expected each key once)"
            )
        return root, construct(root)
    except YamlError as exc:
        raise ScenarioError(source, exc.line, "", exc.message) from None


def _validate(data: Any, source: str, source_map: SourceMap) -> Scenario:
    """Validate ``data``; turn every validation error into one ScenarioError."""
    if not isinstance(data, Mapping):
        line, _ = source_map.locate(())
        raise ScenarioError(
            source, line, "", f"the document is not a mapping (expected the keys {_TOP_LEVEL})"
        )
    try:
        return Scenario.model_validate(data)
    except ValidationError as exc:
        found = [
            (*source_map.locate(location), message)
            for error in exc.errors(include_url=False)
            for location, message in describe_errors(Scenario, error)
        ]
        raise _error(source, found, "scenario") from None


def _error(
    source: str, found: Sequence[tuple[int | None, str, str]], default_field: str
) -> ScenarioError:
    """One ScenarioError of the distinct problems ``(line, field, message)``, by line."""
    unique: dict[tuple[int | None, str, str], int] = {}
    for n, problem in enumerate(found):
        unique.setdefault(problem, n)
    ordered = sorted(unique, key=lambda p: (p[0] if p[0] is not None else 0, unique[p]))
    errors = [
        ScenarioError(source, line, field or default_field, msg)
        for line, field, msg in ordered[:MAX_LISTED]
    ]
    if len(ordered) > MAX_LISTED:
        left = len(ordered) - MAX_LISTED
        errors.append(ScenarioError(source, None, "", f"and {left} more problem(s) not listed"))
    first, *more = errors
    return ScenarioError(first.path, first.line, first.field, first.message, more)
