"""Control: task space, motion and force controllers, hybrid combination, safety limits.

Paper section "Manipulation Primitives and Control": equ:HybridMFC_combination,
equ:Motion_controller_error, equ:quaternion_error, equ:force_controller and
equ:Gripping_Force_Controller, with the errata of NOTES.md. Pure NumPy/SciPy.
"""

from tautwire.control.force_controller import (
    AdaptiveForceController,
    FixedGainForceController,
    ForceController,
)
from tautwire.control.grip_force_controller import YUMI_MAX_GRIP_FORCE, GripForceController
from tautwire.control.hybrid_controller import (
    HybridController,
    HybridTerms,
    hybrid_combination,
    tension_projector,
)
from tautwire.control.motion_controller import (
    MotionController,
    coordinated_motion_command,
    coordinated_motion_twist,
    individual_motion_twist,
)
from tautwire.control.quaternion_error import quaternion_error
from tautwire.control.safety_limits import ForceCheck, ForceLimitExceededError, SafetyLimits
from tautwire.control.task_space import (
    CoordinatedPose,
    DualPose,
    Pose,
    absolute_rate_matrix,
    coordinated_pose,
    coordinated_twist,
    coordinated_velocity_matrix,
    individual_pose,
    individual_twist,
    individual_velocity_matrix,
    make_pose,
    relative_rotation_vector,
)

__all__ = [
    "YUMI_MAX_GRIP_FORCE",
    "AdaptiveForceController",
    "CoordinatedPose",
    "DualPose",
    "FixedGainForceController",
    "ForceCheck",
    "ForceController",
    "ForceLimitExceededError",
    "GripForceController",
    "HybridController",
    "HybridTerms",
    "MotionController",
    "Pose",
    "SafetyLimits",
    "absolute_rate_matrix",
    "coordinated_motion_command",
    "coordinated_motion_twist",
    "coordinated_pose",
    "coordinated_twist",
    "coordinated_velocity_matrix",
    "hybrid_combination",
    "individual_motion_twist",
    "individual_pose",
    "individual_twist",
    "individual_velocity_matrix",
    "make_pose",
    "quaternion_error",
    "relative_rotation_vector",
    "tension_projector",
]
