"""The error raised for anything wrong with a scenario file."""

from __future__ import annotations

from tautwire.errors import InputFileError


class ScenarioError(InputFileError):
    """A scenario file is missing, not YAML, or not a valid scenario.

    Its string is one line, ``FILE:LINE: FIELD: what is wrong (what is
    expected)``; the line and the field are left out when unknown.

    Attributes:
        path: the file (or ``"<string>"``, or the source name given).
        line: 1-based line of the offending key or value, or ``None``.
        field: dotted path of the offending value, e.g. ``cables[0].stiffness``;
            empty when the problem is the whole file.
        message: what is wrong (what is expected).
    """

    def __init__(self, path: str, line: int | None, field: str, message: str) -> None:
        self.path = path
        self.line = line
        self.field = field
        self.message = message
        super().__init__(str(self))

    def __str__(self) -> str:
        where = self.path if self.line is None else f"{self.path}:{self.line}"
        text = (
            f"{where}: {self.field}: {self.message}" if self.field else f"{where}: {self.message}"
        )
        return " ".join(text.split())
