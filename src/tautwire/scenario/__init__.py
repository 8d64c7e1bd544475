"""Scenario files (format version 1): schema, validation, typed objects."""

from tautwire.scenario.models import (
    Anchor,
    Board,
    CableSpec,
    Clip,
    Fixture,
    GrippersSettings,
    GripperStart,
    Hold,
    Peg,
    RobotSettings,
    Scenario,
    SensorSettings,
    SimSettings,
    TaskStep,
)

__all__ = [
    "Anchor",
    "Board",
    "CableSpec",
    "Clip",
    "Fixture",
    "GripperStart",
    "GrippersSettings",
    "Hold",
    "Peg",
    "RobotSettings",
    "Scenario",
    "SensorSettings",
    "SimSettings",
    "TaskStep",
]
