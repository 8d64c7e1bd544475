"""Values as a user wrote them in YAML, for error messages."""

from __future__ import annotations

from collections.abc import Iterator, Mapping

#: Longest text of a shown value [characters], "..." included.
WIDTH = 60


def show(value: object, width: int = WIDTH) -> str:
    """A value as YAML writes it (``null``, ``true``, ``3.0``), at most ``width`` characters.

    The text is built piece by piece and stops as soon as it is long
    enough, so a huge value (a list of a million items, or one that
    aliases expand to billions) costs no more than a short one.

    Args:
        value: Plain data as YAML loads it.
        width: Most characters returned (at least 4).
    """
    budget = max(width, 4)
    parts: list[str] = []
    used = 0
    for piece in _pieces(value):
        parts.append(piece)
        used += len(piece)
        if used > budget:
            break
    text = "".join(parts)
    return text if len(text) <= budget else text[: budget - 3] + "..."


def _pieces(value: object) -> Iterator[str]:
    """The text of ``value`` in small pieces, lazily (containers item by item)."""
    if value is None:
        yield "null"
    elif isinstance(value, bool):
        yield "true" if value else "false"
    elif isinstance(value, str):
        yield repr(value[: 4 * WIDTH]) if len(value) > 4 * WIDTH else repr(value)
    elif isinstance(value, int | float):
        yield _number(value)
    elif isinstance(value, Mapping):
        yield "{"
        for n, (key, item) in enumerate(value.items()):
            yield ", " if n else ""
            yield from _pieces(key)
            yield ": "
            yield from _pieces(item)
        yield "}"
    elif isinstance(value, list | tuple):
        yield "["
        for n, item in enumerate(value):
            yield ", " if n else ""
            yield from _pieces(item)
        yield "]"
    else:
        yield f"<{type(value).__name__}>"


def _number(value: int | float) -> str:
    """A number's text; a huge integer is not converted in full (a DoS in itself)."""
    if isinstance(value, int) and value.bit_length() > 256:
        return f"<an integer of about {int(value.bit_length() * 0.30103)} digits>"
    return str(value)
