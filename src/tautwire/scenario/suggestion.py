"""'Did you mean' suggestions for names a user misspelt (keys, types, primitives)."""

from __future__ import annotations

import difflib
from collections.abc import Iterable


def did_you_mean(given: object, choices: Iterable[str]) -> str:
    """``", did you mean 'stiffness'?"`` for the choice closest to ``given``, or ``""``.

    Close means difflib's ratio of at least 0.6, or equal but for case.

    Args:
        given: what the file says (a key, a tag, a name).
        choices: the valid names.
    """
    if not isinstance(given, str) or not given:
        return ""
    names = list(choices)
    close = difflib.get_close_matches(given, names, n=1, cutoff=0.6)
    if not close:
        close = [c for c in names if c.lower() == given.lower()]
    return f", did you mean {close[0]!r}?" if close else ""
