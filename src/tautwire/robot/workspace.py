"""The region that the robot's grippers can reach and fixtures may occupy."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass


@dataclass(frozen=True)
class Workspace:
    """An axis-aligned box in the world frame.

    Attributes:
        lower: smallest x, y, z [m].
        upper: largest x, y, z [m].
    """

    lower: tuple[float, float, float]
    upper: tuple[float, float, float]

    def contains(self, point: Sequence[float]) -> bool:
        """Whether ``point`` (3,) [m] lies in the box (boundary included)."""
        return all(lo <= p <= hi for lo, p, hi in zip(self.lower, point, self.upper, strict=True))

    def describe(self) -> str:
        """The box in words, e.g. ``'x in [-0.2, 0.8], y in [-0.6, 0.6], z in [0, 0.6] m'``."""
        axes = (
            f"{axis} in [{lo:g}, {hi:g}]"
            for axis, lo, hi in zip("xyz", self.lower, self.upper, strict=True)
        )
        return ", ".join(axes) + " m"


WORKSPACE = Workspace(lower=(-0.2, -0.6, 0.0), upper=(0.8, 0.6, 0.6))
"""A generous box for a table-top board in front of a dual-arm robot: the
board surface is z = 0 and the robot stands behind x = 0 facing +x, with its
two arms reaching left (+y) and right (-y). Gripper start positions and every
fixture (a peg up to its top) must lie inside it."""
