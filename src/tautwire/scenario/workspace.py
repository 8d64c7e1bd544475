"""Where a scenario's grippers and fixtures may lie, and how far apart they must be.

The box itself (:class:`Workspace`, :data:`WORKSPACE`) is the robot's
(:mod:`tautwire.robot.workspace`): the guard that keeps a run inside it is
core code and must not need the scenario layer.
"""

from __future__ import annotations

from tautwire.robot.workspace import WORKSPACE, Workspace

__all__ = [
    "GRIPPER_MIN_DISTANCE",
    "HOLD_MIN_SEPARATION",
    "ROUTE_TOLERANCE",
    "WORKSPACE",
    "Workspace",
]

GRIPPER_MIN_DISTANCE = 0.03
"""The two grippers' start positions must be at least this far apart [m]
(the fingers of two parallel grippers side by side)."""

HOLD_MIN_SEPARATION = 0.02
"""Two holds on one cable must be at least this far apart along it [m]
(one finger width): two grippers cannot hold the same point."""

ROUTE_TOLERANCE = 1e-6
"""Slack allowed when comparing a route's straight-line length with the
cable that spans it [m] (rounding in the file's numbers)."""
