"""Weight-compensated edge tension (the paper's equ:edge_tension).

Sign convention (world frame, z up): ``GRAVITY = (0, 0, -9.81)`` m/s^2 and
``f_sens`` is the force that the cable exerts on the gripper. At the feature
point v_i held by the sensing gripper,

    p_hat_i f_i = f_sens - m_i g + p_hat_{i-1} f_{i-1},

where p_hat_i is the unit vector from v_i towards v_{i+1}, m_i the point's
mass (eq:mass) and p_hat_{i-1} f_{i-1} the pull of the preceding edge
(p_hat_{i-1} from v_{i-1} towards v_i). With one sensor the preceding edge can
only be a freely hanging end, whose tension is its own weight; with a second
sensor it is the tension measured there. The term is left out at an end
point. Proof by physics: a cable hanging still gives back the tension its
weight implies (tests/model/test_tension.py, and in the simulator).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

#: Gravitational acceleration in the world frame [m/s^2].
GRAVITY: FloatArray = np.array([0.0, 0.0, -9.81])
G: float = 9.81


class EdgeTension(NamedTuple):
    """Result of :func:`edge_tension`.

    Attributes:
        tension: f_i [N], >= 0.
        direction: p_hat_i, unit vector from the gripper towards the next
            feature point (undefined, zeros, when the tension is 0).  # (3,)
        vector: p_hat_i f_i [N].  # (3,)
    """

    tension: float
    direction: FloatArray
    vector: FloatArray


def edge_tension(
    f_sens: ArrayLike,
    point_mass: float,
    previous_direction: ArrayLike | None = None,
    previous_tension: float = 0.0,
) -> EdgeTension:
    """Tension of the edge leaving a sensing gripper, weight compensated.

    Args:
        f_sens: Force [N] the cable exerts on the gripper, world frame.  # (3,)
        point_mass: m_i [kg] of the gripper's feature point (eq:mass).
        previous_direction: p_hat_{i-1}, unit vector from the preceding feature
            point towards the gripper's; None at an end point.  # (3,)
        previous_tension: f_{i-1} [N] of the preceding edge.

    Returns:
        The tension f_i, its direction p_hat_i and the vector p_hat_i f_i.
    """
    vector = np.asarray(f_sens, dtype=float) - point_mass * GRAVITY
    if previous_direction is not None:
        p_prev = np.asarray(previous_direction, dtype=float)
        n = float(np.linalg.norm(p_prev))
        if n > 0.0:
            vector = vector + (p_prev / n) * previous_tension
    tension = float(np.linalg.norm(vector))
    direction = vector / tension if tension > 1e-12 else np.zeros(3)
    return EdgeTension(tension, direction, vector)


def hanging_end_tension(end_point_mass: float) -> float:
    """The paper's f_{i-1} [N] for a freely hanging end below the gripper.

    The hanging end's feature point v_{i-1} has mass m_{i-1} = rho d_{i-1} / 2
    (eq:mass) and f_{i-1} = m_{i-1} |g|; the other half of the hanging
    segment's weight is already in m_i, so the two add up to its whole weight.

    Args:
        end_point_mass: m_{i-1} [kg].
    """
    return float(end_point_mass * G)
