"""Manipulation primitives A-I: small state machines from Observation to Command.

Each sees only observations and the shared context (model, estimators,
controller), never the simulator.
"""

from tautwire.primitives.context import PrimitiveContext, make_context
from tautwire.primitives.model_estimator import ModelEstimator, TensionState
from tautwire.primitives.outcome import CAUSES, Outcome
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.registry import PRIMITIVES, make_primitive, primitive_class
from tautwire.primitives.rotate_around_feature_point import RotateAroundFeaturePoint
from tautwire.primitives.single_arm_tension import SingleArmTension

__all__ = [
    "CAUSES",
    "PRIMITIVES",
    "ModelEstimator",
    "Outcome",
    "Primitive",
    "PrimitiveContext",
    "RotateAroundFeaturePoint",
    "SingleArmTension",
    "TensionState",
    "make_context",
    "make_primitive",
    "primitive_class",
]
