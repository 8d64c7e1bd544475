"""Scenario files (format version 1): schema, validation, typed objects.

``load_scenario(path)`` reads a YAML file into a validated, frozen
:class:`Scenario`; anything wrong raises :class:`ScenarioError`, whose
message is one line ``FILE:LINE: FIELD: what is wrong (what is expected)``.
"""

from tautwire.scenario.loader import load_scenario, parse_scenario, scenario_from_data
from tautwire.scenario.models import (
    Anchor,
    BiasDriftFault,
    Board,
    CableSpec,
    Clip,
    Fault,
    Fixture,
    FreezeFault,
    GrippersSettings,
    GripperStart,
    Hold,
    NanFault,
    Peg,
    RobotErrorFault,
    RobotSettings,
    Scenario,
    SensorSettings,
    SlipFault,
    SpikeFault,
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
    "BiasDriftFault",
    "Board",
    "CableSpec",
    "Clip",
    "Fault",
    "Fixture",
    "FreezeFault",
    "GripperStart",
    "GrippersSettings",
    "Hold",
    "NanFault",
    "ParamSpec",
    "Peg",
    "PrimitiveSpec",
    "RobotErrorFault",
    "RobotSettings",
    "Scenario",
    "ScenarioError",
    "SensorSettings",
    "SlipFault",
    "SpikeFault",
    "TaskStep",
    "Workspace",
    "dump_scenario",
    "find_primitive",
    "load_scenario",
    "parse_scenario",
    "scenario_document",
    "scenario_from_data",
]
