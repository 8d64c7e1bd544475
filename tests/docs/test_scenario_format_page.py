"""docs/scenario-format.md documents the schema exactly: every key, its default and unit.

The page has one section per schema model, its heading ending in
``{#ModelName}``, with a table whose rows start with the key in backticks:
``| `key` | type | unit | default | meaning |``. The primitives' and moves'
parameters are in the sections ``{#primitives}`` and ``{#moves}``:
``| letter | `name` | `parameter` | type | unit | default | meaning |``. A row
whose default says **planned** documents a key the schema does not take yet.
"""

from __future__ import annotations

import re
import types
import typing
from pathlib import Path
from typing import Any

import pytest
from pydantic import BaseModel
from pydantic.fields import FieldInfo

from tautwire.scenario import models
from tautwire.scenario import primitive_catalogue as catalogue

PAGE = Path(__file__).resolve().parents[2] / "docs" / "scenario-format.md"
PLANNED = "**planned**"


def sections(text: str) -> dict[str, list[list[str]]]:
    """Table rows (cells, stripped) of every section with a ``{#id}`` heading, by id."""
    found: dict[str, list[list[str]]] = {}
    current: str | None = None
    for line in text.splitlines():
        heading = re.match(r"^#+ .*\{#(\w+)\}\s*$", line)
        if heading:
            current = heading.group(1)
            found[current] = []
        elif line.startswith("#"):
            current = None
        elif current is not None and line.startswith("| `"):
            found[current].append([c.strip() for c in line.strip().strip("|").split("|")])
    return found


def schema_models() -> dict[str, type[BaseModel]]:
    """Every model reachable from :class:`Scenario`, by class name."""
    seen: dict[str, type[BaseModel]] = {}

    def walk(annotation: Any) -> None:
        if isinstance(annotation, type) and issubclass(annotation, BaseModel):
            if annotation.__name__ not in seen:
                seen[annotation.__name__] = annotation
                for field in annotation.model_fields.values():
                    walk(field.annotation)
            return
        for arg in typing.get_args(annotation):
            walk(arg)

    walk(models.Scenario)
    return seen


def shown(value: Any) -> str:
    """A default as the page writes it."""
    if value is None:
        return "none"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return f"{value:g}"
    if isinstance(value, str):
        return value or '""'
    if isinstance(value, list | tuple):
        return "[" + ", ".join(shown(v) for v in value) + "]"
    raise TypeError(value)


def unit_of(text: str | None) -> str | None:
    """The unit in brackets at the end of a description (``[N]``), if any."""
    if not text:
        return None
    units = [u for u in re.findall(r"\[[^\]]*\]", text) if "," not in u]
    return units[-1] if units else None


def check_default(where: str, cell: str, required: bool, default: Any) -> None:
    plain = cell.replace("`", "")
    if required:
        assert plain == "required", f"{where}: the schema requires it, the page says {cell!r}"
    elif isinstance(default, BaseModel):
        assert plain != "required", f"{where}: optional, the page says required"
    else:
        assert plain.startswith(shown(default)), (
            f"{where}: default {shown(default)!r} in the schema, {cell!r} on the page"
        )


TEXT = PAGE.read_text(encoding="utf-8")
SECTIONS = sections(TEXT)
MODELS = schema_models()


def test_the_page_has_a_section_per_model() -> None:
    missing = sorted(set(MODELS) - set(SECTIONS))
    assert not missing, f"schema models without a section {{#Name}} on the page: {missing}"


@pytest.mark.parametrize("name", sorted(set(MODELS) - {"TaskStep"}))
def test_every_key_of_a_model_and_nothing_else(name: str) -> None:
    fields: dict[str, FieldInfo] = MODELS[name].model_fields
    rows = {row[0].strip("`"): row for row in SECTIONS[name]}
    undocumented = sorted(set(fields) - set(rows))
    assert not undocumented, f"{name}: keys missing on the page: {undocumented}"
    for key, row in rows.items():
        if key not in fields:
            assert PLANNED in row[3], f"{name}: {key!r} is on the page but not in the schema"
            continue
        field = fields[key]
        assert PLANNED not in row[3], f"{name}: {key!r} is in the schema now, not planned"
        check_default(f"{name}.{key}", row[3], field.is_required(), field.default)
        unit = unit_of(field.description)
        if unit is not None:
            assert row[2] == unit, f"{name}.{key}: unit {unit} in the schema, {row[2]} on the page"


def test_a_task_step_names_its_primitive_and_the_parameters_every_step_has() -> None:
    rows = {row[0].strip("`"): row for row in SECTIONS["TaskStep"]}
    common = {p.name for p in getattr(catalogue, "STEP_PARAMETERS", ())}
    for key, row in rows.items():
        if key in common or key == "primitive":
            assert PLANNED not in row[3], f"task step: {key!r} is in the schema now, not planned"
        else:
            assert PLANNED in row[3], f"task step: {key!r} is not a key every step takes"
    missing = sorted(({"primitive"} | common) - set(rows))
    assert not missing, f"task step keys missing on the page: {missing}"


def catalogue_rows(section: str) -> dict[tuple[str, str], list[str]]:
    return {(row[1].strip("`"), row[2].strip("`")): row for row in _rows_with_letter(section)}


def _rows_with_letter(section: str) -> list[list[str]]:
    rows = []
    for line in TEXT.split("{#" + section + "}", 1)[1].splitlines()[1:]:
        if line.startswith("#"):
            break
        if line.startswith("| ") and "`" in line.split("|")[2]:
            rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows


@pytest.mark.parametrize(
    ("section", "specs"),
    [
        ("primitives", catalogue.PRIMITIVES),
        ("moves", getattr(catalogue, "MOVES", ())),
    ],
)
def test_every_parameter_of_every_primitive(
    section: str, specs: tuple[catalogue.PrimitiveSpec, ...]
) -> None:
    rows = catalogue_rows(section)
    expected = {(spec.name, p.name): (spec, p) for spec in specs for p in spec.parameters}
    expected |= {(spec.name, ""): (spec, None) for spec in specs if not spec.parameters}
    for key, row in rows.items():
        if key not in expected:
            assert PLANNED in row[5], f"{section}: {key} is on the page but not in the catalogue"
    for key, (spec, param) in expected.items():
        assert key in rows, f"{section}: {key} missing on the page"
        row = rows[key]
        assert row[0].replace("`", "") == (spec.letter or "-"), f"{key}: letter {row[0]}"
        assert PLANNED not in row[5], f"{section}: {key} is in the catalogue now, not planned"
        if param is None:
            continue
        if param.default is None and param not in spec.required:  # the primitive chooses
            assert row[5].replace("`", "") != "required", f"{key}: optional, the page says required"
        else:
            check_default(f"{key}", row[5], param in spec.required, param.default)
        unit = unit_of(param.meaning)
        if unit is not None:
            assert row[4] == unit, f"{key}: unit {unit} in the catalogue, {row[4]} on the page"


def test_the_page_parses() -> None:
    # guards the parser above: a page it cannot read would pass everything
    assert len(SECTIONS) >= 15
    assert sum(len(rows) for rows in SECTIONS.values()) >= 50
    assert len(catalogue_rows("primitives")) >= 20
    assert isinstance(models.Scenario, type) and not isinstance(models, types.FunctionType)
