"""Scenario files (format version 1): schema, validation, typed objects.

``load_scenario(path)`` reads a YAML file into a validated, frozen
:class:`Scenario`; anything wrong raises :class:`ScenarioError`, whose
message is one line ``FILE:LINE: FIELD: what is wrong (what is expected)``.
"""

from tautwire.scenario.loader import load_scenario, parse_scenario, scenario_from_data
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
    TaskStep,
)
from tautwire.scenario.primitive_catalogue import (
    PRIMITIVES,
    ParamSpec,
    PrimitiveSpec,
    find_primitive,
)
from tautwire.scenario.scenario_error import ScenarioError
from tautwire.scenario.workspace import (
    GRIPPER_MIN_DISTANCE,
    HOLD_MIN_SEPARATION,
    WORKSPACE,
    Workspace,
)
from tautwire.scenario.writer import dump_scenario, scenario_document

__all__ = [
    "GRIPPER_MIN_DISTANCE",
    "HOLD_MIN_SEPARATION",
    "PRIMITIVES",
    "WORKSPACE",
    "Anchor",
    "Board",
    "CableSpec",
    "Clip",
    "Fixture",
    "GripperStart",
    "GrippersSettings",
    "Hold",
    "ParamSpec",
    "Peg",
    "PrimitiveSpec",
    "RobotSettings",
    "Scenario",
    "ScenarioError",
    "SensorSettings",
    "TaskStep",
    "Workspace",
    "dump_scenario",
    "find_primitive",
    "load_scenario",
    "parse_scenario",
    "scenario_document",
    "scenario_from_data",
]
