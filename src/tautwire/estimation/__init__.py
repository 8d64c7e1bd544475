"""Online estimation of the cable model (paper section "Model Estimation")."""

from tautwire.estimation.constraint_mapping import (
    constraint_matrix,
    map_constraints,
    update_by_constraints,
)
from tautwire.estimation.contact_change_detector import (
    CHI2_2DOF_999,
    ChangeTest,
    ContactChangeDetector,
)
from tautwire.estimation.contact_observation import (
    ContactObservation,
    contact_observation,
    line_noise_variance,
    normal_plane_basis,
)
from tautwire.estimation.contact_point_filter import (
    DEFAULT_PROCESS_NOISE,
    ContactPointFilter,
    ContactPointUpdate,
)
from tautwire.estimation.contact_point_least_squares import (
    ContactPointLeastSquares,
    NormalEquations,
    contact_normal_equations,
    contact_point_least_squares,
)
from tautwire.estimation.elasticity_estimator import ElasticityEstimator
from tautwire.estimation.force_log import ForceLog, read_force_log, write_force_log
from tautwire.estimation.kalman import KalmanUpdate, kalman_predict, kalman_update
from tautwire.estimation.offline import HistoryEntry, OfflineEstimate, estimate_force_log
from tautwire.estimation.weight_compensation import compensate_weight, gripper_point_mass

__all__ = [
    "CHI2_2DOF_999",
    "DEFAULT_PROCESS_NOISE",
    "ChangeTest",
    "ContactChangeDetector",
    "ContactObservation",
    "ContactPointFilter",
    "ContactPointLeastSquares",
    "ContactPointUpdate",
    "ElasticityEstimator",
    "ForceLog",
    "HistoryEntry",
    "KalmanUpdate",
    "NormalEquations",
    "OfflineEstimate",
    "compensate_weight",
    "constraint_matrix",
    "contact_normal_equations",
    "contact_observation",
    "contact_point_least_squares",
    "estimate_force_log",
    "gripper_point_mass",
    "kalman_predict",
    "kalman_update",
    "line_noise_variance",
    "map_constraints",
    "normal_plane_basis",
    "read_force_log",
    "update_by_constraints",
    "write_force_log",
]
