"""Pydantic validation errors in the scenario file's words.

Every message has the shape ``what is wrong (what is expected)``; the
expectation carries the field's unit where the schema gives one.
"""

from __future__ import annotations

import re
import types
import typing
from typing import Any, Literal, Union, get_args, get_origin

from pydantic import BaseModel
from pydantic.fields import FieldInfo
from pydantic_core import ErrorDetails

from tautwire.scenario.issue import LOCATION_KEY, MORE_KEY, Location
from tautwire.scenario.suggestion import did_you_mean
from tautwire.scenario.value_text import show


def describe_errors(root: type[BaseModel], error: ErrorDetails) -> list[tuple[Location, str]]:
    """Every problem one validation error stands for, located from the top level.

    A model-level check (references, geometry) reports all its issues in
    one error; any other error is one problem (:func:`describe_error`).

    Args:
        root: the model validated at the top level (``Scenario``).
        error: one entry of ``ValidationError.errors()``.
    """
    found = [describe_error(root, error)]
    if error["type"] == "tautwire":
        location: Location = tuple(error["loc"])
        for where, message in (error.get("ctx") or {}).get(MORE_KEY, ()):
            found.append(((*location, *where), str(message)))
    return found


def describe_error(root: type[BaseModel], error: ErrorDetails) -> tuple[Location, str]:
    """Return where a validation error is, from the top level, and what it says.

    Args:
        root: the model validated at the top level (``Scenario``).
        error: one entry of ``ValidationError.errors()``.
    """
    location: Location = tuple(error["loc"])
    kind = error["type"]
    ctx = error.get("ctx") or {}
    got = show(error.get("input"))
    if kind == "tautwire":
        return (*location, *ctx.get(LOCATION_KEY, ())), str(ctx["message"])
    field = _field_at(root, location)
    unit = _unit(field)
    if kind == "missing" and location and isinstance(location[-1], int):
        outer = _field_at(root, location[:-1])
        items = get_args(_strip(outer.annotation)) if outer is not None else ()
        return location[:-1], f"too few items (expected exactly {len(items)}{_unit(outer)})"
    if kind == "missing":
        return location, f"missing (expected {_expected(field)})"
    if kind == "extra_forbidden":
        parent = _model_at(root, location[:-1])
        names = list(parent.model_fields) if parent is not None else []
        keys = ", ".join(names) or "the documented keys"
        return location, f"unknown key{did_you_mean(location[-1], names)} (expected one of: {keys})"
    if kind in ("union_tag_invalid", "union_tag_not_found"):
        tags = ctx.get("expected_tags") or _type_tags(root, location)
        tag = ctx.get("tag")
        what = "missing" if tag is None else f"got {show(tag)}"
        if tag is not None:
            what += did_you_mean(tag, [t.strip().strip("'") for t in str(tags).split(",")])
        return (*location, "type"), f"{what} (expected one of: {tags})"
    if kind in ("too_short", "too_long"):
        bound = "at least" if kind == "too_short" else "at most"
        limit = ctx.get("min_length" if kind == "too_short" else "max_length")
        if ctx.get("field_type") == "Tuple":
            bound = "exactly"
        return location, f"got {ctx.get('actual_length')} item(s) (expected {bound} {limit}{unit})"
    if kind in ("model_type", "model_attributes_type", "dict_type"):
        model = _model_at(root, location)
        if model is not None and model.__name__ == "TaskStep":
            return location, f"got {got} (expected a mapping such as {_STEP_EXAMPLE})"
        keys = ", ".join(model.model_fields) if model is not None else "keys"
        return location, f"got {got} (expected a mapping with {keys})"
    message = str(error["msg"])
    if kind == "literal_error" and isinstance(error.get("input"), str):
        choices = re.findall(r"'([^']*)'", str(ctx.get("expected", "")))
        hint = did_you_mean(error.get("input"), choices)
        return location, f"got {got}{hint} (expected {ctx.get('expected')}{unit})"
    if message.startswith("Value error, "):
        return location, message.removeprefix("Value error, ")
    if message.startswith("Input should be "):
        expected = message.removeprefix("Input should be ")
        expected = _plain(expected)
        return location, f"got {got} (expected {expected}{unit})"
    return location, f"{message[:1].lower()}{message[1:]} (got {got})"


_STEP_EXAMPLE = "{primitive: D, arm: left, force: 3.0}"


def _plain(expected: str) -> str:
    """Pydantic's expectation in the file's words ('a valid tuple' -> 'a list')."""
    expected = expected.replace(", got a number with a fractional part", "")
    expected = re.sub(r"\ba valid (tuple|list)\b", "a list", expected)
    expected = re.sub(r"\ba valid (dictionary)\b", "a mapping", expected)
    return re.sub(r"\ba valid (?=[aeiou])", "an ", re.sub(r"\ba valid (?![aeiou])", "a ", expected))


def _unit(field: FieldInfo | None) -> str:
    """`` [unit]`` from the field's description, or ``""``."""
    if field is None or not field.description:
        return ""
    found = re.search(r"\[[^\]]+\]", field.description)
    return f" {found.group(0)}" if found else ""


def _expected(field: FieldInfo | None) -> str:
    """What a field holds, in words."""
    if field is None:
        return "a value"
    if field.description:
        return field.description
    annotation = _strip(field.annotation)
    if get_origin(annotation) is Literal:
        return "one of: " + ", ".join(str(a) for a in get_args(annotation))
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return "a mapping with " + ", ".join(annotation.model_fields)
    if get_origin(annotation) is list:
        return "a list"
    if annotation is str:
        return "a name"
    return "a value"


def _type_tags(root: type[BaseModel], location: Location) -> str:
    """The ``type`` values that the union at ``location`` accepts, e.g. ``'anchor', 'peg'``."""
    found = _walk(root, location)
    members = get_args(_strip(found[0])) if found is not None else ()
    tags = [
        repr(tag)
        for member in members
        for tag in get_args(getattr(member, "model_fields", {}).get("type", FieldInfo()).annotation)
    ]
    return ", ".join(tags) or "a type"


def _strip(annotation: Any) -> Any:
    """Drop ``Annotated`` and ``Optional`` wrappers."""
    while get_origin(annotation) is typing.Annotated:
        annotation = get_args(annotation)[0]
    if get_origin(annotation) in (Union, types.UnionType):
        members = [a for a in get_args(annotation) if a is not type(None)]
        if len(members) == 1:
            return _strip(members[0])
    return annotation


def _step(annotation: Any, part: str | int) -> tuple[Any, FieldInfo | None] | None:
    """Follow one location part from a type; return the next type and its field."""
    annotation = _strip(annotation)
    origin = get_origin(annotation)
    if isinstance(part, int):
        if origin in (list, tuple):
            return get_args(annotation)[0], None
        if isinstance(annotation, type) and issubclass(annotation, BaseModel) and part == 0:
            return annotation, None
        return None
    if origin in (Union, types.UnionType):
        for member in get_args(annotation):
            fields = getattr(member, "model_fields", {})
            if "type" in fields and part in get_args(fields["type"].annotation):
                return member, None
        return None
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        field = annotation.model_fields.get(part)
        if field is None:
            return None
        return field.annotation, field
    return None


def _walk(root: type[BaseModel], location: Location) -> tuple[Any, FieldInfo | None] | None:
    """The type and the field at ``location`` below ``root``, or ``None``."""
    current: tuple[Any, FieldInfo | None] = (root, None)
    for part in location:
        following = _step(current[0], part)
        if following is None:
            return None
        current = following
    return current


def _field_at(root: type[BaseModel], location: Location) -> FieldInfo | None:
    """The field definition at ``location``, or ``None``."""
    found = _walk(root, location)
    return None if found is None else found[1]


def _model_at(root: type[BaseModel], location: Location) -> type[BaseModel] | None:
    """The model at ``location``, or ``None``."""
    found = _walk(root, location)
    if found is None:
        return None
    annotation = _strip(found[0])
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    return None
