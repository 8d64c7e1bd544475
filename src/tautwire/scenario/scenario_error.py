"""The error raised for anything wrong with a scenario file."""

from __future__ import annotations

from collections.abc import Sequence

from tautwire.errors import InputFileError


class ScenarioError(InputFileError):
    """A scenario file is missing, not YAML, or not a valid scenario.

    Its string is one line per problem, ``FILE:LINE: FIELD: what is wrong
    (what is expected)``; the line and the field are left out when unknown.
    The attributes describe the first problem (the one highest in the file);
    :attr:`problems` holds them all.

    Attributes:
        path: the file (or ``"<string>"``, or the source name given).
        line: 1-based line of the offending key or value, or ``None``.
        field: dotted path of the offending value, e.g. ``cables[0].stiffness``;
            empty when the problem is the whole file.
        message: what is wrong (what is expected).
        problems: this problem and every further one, each a ScenarioError.
    """

    def __init__(
        self,
        path: str,
        line: int | None,
        field: str,
        message: str,
        more: Sequence[ScenarioError] = (),
    ) -> None:
        self.path = path
        self.line = line
        self.field = field
        self.message = message
        self.problems: tuple[ScenarioError, ...] = (self, *more)
        super().__init__(str(self))

    @property
    def first_line(self) -> str:
        """This problem alone, on one line."""
        where = self.path if self.line is None else f"{self.path}:{self.line}"
        text = (
            f"{where}: {self.field}: {self.message}" if self.field else f"{where}: {self.message}"
        )
        return " ".join(text.split())

    def __str__(self) -> str:
        return "\n".join(p.first_line for p in self.problems)
