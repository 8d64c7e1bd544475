"""Values as a user wrote them in YAML, for error messages."""

from __future__ import annotations


def show(value: object) -> str:
    """A value as YAML writes it (``null``, ``true``, ``3.0``), at most 60 characters."""
    if value is None:
        text = "null"
    elif isinstance(value, bool):
        text = "true" if value else "false"
    elif isinstance(value, str):
        text = repr(value)
    else:
        text = str(value)
    return text if len(text) <= 60 else text[:57] + "..."
