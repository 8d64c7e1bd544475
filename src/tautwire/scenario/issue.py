"""A problem found in a scenario, located by its path in the document."""

from __future__ import annotations

from typing import Any, NamedTuple

from pydantic_core import PydanticCustomError

Location = tuple[str | int, ...]
"""Path of keys and list indices from a model to the offending value,
e.g. ``("cables", 0, "stiffness")``."""

LOCATION_KEY = "tautwire_location"
"""Context key under which a located validation error carries its path."""

MORE_KEY = "tautwire_more"
"""Context key under which a located validation error carries further issues."""


class Issue(NamedTuple):
    """One thing wrong with a scenario.

    Attributes:
        location: path from the scenario's top level to the offending value.
        message: what is wrong and, in parentheses, what is expected.
    """

    location: Location
    message: str


def located_error(
    message: str, location: Location = (), more: tuple[Issue, ...] = ()
) -> PydanticCustomError:
    """A validation error whose position is ``location`` below the model that raises it.

    Pydantic locates an error raised in a validator at the model being
    validated; the loader appends ``location`` (kept in the error's context)
    to find the exact field and line.

    Args:
        message: what is wrong (what is expected).
        location: path below the validating model.
        more: further issues found by the same check (each listed too).
    """
    context: dict[str, Any] = {"message": message, LOCATION_KEY: tuple(location)}
    if more:
        context[MORE_KEY] = tuple((tuple(i.location), i.message) for i in more)
    return PydanticCustomError("tautwire", "{message}", context)
