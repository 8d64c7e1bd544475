"""The robot protocol that the simulated world and real drivers implement."""

from __future__ import annotations

from typing import Protocol, runtime_checkable

from tautwire.robot.command import Command
from tautwire.robot.observation import Observation


@runtime_checkable
class Robot(Protocol):
    """A dual-arm robot with at least one wrist force-torque sensor."""

    @property
    def control_period(self) -> float:
        """Period [s] of one :meth:`act` call (the robot's 250 Hz interface: 0.004)."""
        ...

    def observe(self) -> Observation:
        """Return the latest measurement."""
        ...

    def act(self, command: Command) -> None:
        """Apply ``command`` for one control period."""
        ...
