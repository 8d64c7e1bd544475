"""Commanding one arm under D's hybrid control, the other holding its pose.

Every individual-control primitive (D, E, F, G, H, I) does the same per
period: the arm that holds the cable with the sensor runs the hybrid
controller with force control along the cable towards its contact
(equ:HybridMFC_combination), motion control elsewhere; the other arm
tracks its own set point. These helpers say that once.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from tautwire.control import DualPose, Pose
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.model_estimator import TensionState
from tautwire.robot import Arm, Observation

FloatArray = NDArray[np.float64]


def current_pose(obs: Observation) -> DualPose:
    """Both grippers' poses from an observation."""
    return DualPose(
        Pose(obs.left.position, obs.left.orientation),
        Pose(obs.right.position, obs.right.orientation),
    )


def with_pose(poses: DualPose, arm: Arm, pose: Pose) -> DualPose:
    """``poses`` with ``arm``'s pose replaced by ``pose``."""
    return DualPose(pose, poses.right) if arm == "left" else DualPose(poses.left, pose)


def tension_twist(
    ctx: PrimitiveContext,
    obs: Observation,
    arm: Arm,
    desired: DualPose,
    force: float,
    state: TensionState,
    k_hat: float | None = None,
) -> FloatArray:
    """The individual twist (12,) with ``arm`` keeping tension ``force`` [N].

    Args:
        ctx: The primitives' context (controller, estimators).
        obs: The current observation.
        arm: The arm that holds the cable and measures its force.
        desired: Set points of both grippers (motion control).
        force: Desired tension f_d [N] along the cable.
        state: The model estimator's tension state of ``arm``'s edge.
        k_hat: Stiffness [N/m] for the force gain; default the trusted estimate.
    """
    left = arm == "left"
    return ctx.controller(
        current_pose(obs),
        desired,
        (force, None) if left else (None, force),
        (state.force, None) if left else (None, state.force),
        ctx.estimator.elasticity.k_trusted if k_hat is None else k_hat,
        (state.direction, None) if left else (None, state.direction),
    )
