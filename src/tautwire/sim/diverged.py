"""The error raised when the simulated physics blows up."""

from tautwire.errors import SimulationError


class SimulationDiverged(SimulationError):  # noqa: N818 (the name the design uses)
    """The physics produced NaN/inf or a velocity or energy blow-up.

    A runner ends the current step with ``cause`` as its failure cause.

    Attributes:
        cause: Always ``"diverged"``.
    """

    cause: str = "diverged"
