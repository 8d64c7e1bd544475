"""The one family of exceptions that tautwire raises on purpose."""


class TautwireError(Exception):
    """Base class of every error tautwire raises deliberately."""


class InvalidArgumentError(TautwireError, ValueError):
    """A constructor or function was given a value outside its valid range."""


class InputFileError(TautwireError):
    """A user file (scenario, force log) is missing or malformed.

    The message names the file, the line or field, and what was expected.
    """


class SimulationError(TautwireError):
    """The simulated world could not be built or stepped."""
