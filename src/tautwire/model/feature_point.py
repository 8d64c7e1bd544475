"""Feature point v_i = (p_i, Q_i, m_i) of the path graph."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import IDENTITY, as_quaternion

FloatArray = NDArray[np.float64]

#: What constrains a feature point:
#: ``free`` nothing but its neighbours and gravity (e.g. a loose end),
#: ``gripper`` a gripper (position from forward kinematics),
#: ``contact`` an estimated contact with the environment,
#: ``fixed`` a known fixed point (an anchor, a clipped fixture),
#: ``goal`` an interpolated point added to define a goal.
FeatureKind = Literal["free", "gripper", "contact", "fixed", "goal"]
FEATURE_KINDS: tuple[FeatureKind, ...] = ("free", "gripper", "contact", "fixed", "goal")


def _vector3(value: ArrayLike, name: str) -> FloatArray:
    arr = np.asarray(value, dtype=float).reshape(-1)
    if arr.shape != (3,) or not np.all(np.isfinite(arr)):
        raise InvalidArgumentError(f"{name} must be 3 finite numbers [m], got {value!r}")
    return arr


@dataclass
class FeaturePoint:
    """A feature point on the cable.

    Attributes:
        position: p_i [m], world frame.  # (3,)
        orientation: Q_i as [w, x, y, z]; x-axis along the cable.  # (4,)
        mass: m_i [kg] (eq:mass), maintained by the path graph.
        kind: What constrains the point (see :data:`FeatureKind`).
        label: Free text: the gripper's arm, a fixture's name, a goal's name.
        covariance: Uncertainty of an estimated position [m^2], if known.  # (3, 3)
        wrap: The angle [rad] the cable turns round the point, along the cable
            from its start and right-handed about the world's vertical,
            windings counted (a peg wound once: about +-2 pi); None where
            unknown. Followed while a gripper circles the point (primitive I).
    """

    position: FloatArray
    orientation: FloatArray = field(default_factory=lambda: IDENTITY.copy())
    mass: float = 0.0
    kind: FeatureKind = "free"
    label: str = ""
    covariance: FloatArray | None = None
    wrap: float | None = None

    def __post_init__(self) -> None:
        self.position = _vector3(self.position, "position")
        self.orientation = as_quaternion(self.orientation)
        if not np.isfinite(self.mass) or self.mass < 0.0:
            raise InvalidArgumentError(f"mass must be >= 0 kg, got {self.mass}")
        if self.kind not in FEATURE_KINDS:
            raise InvalidArgumentError(f"kind must be one of {FEATURE_KINDS}, got {self.kind!r}")
        if self.covariance is not None:
            cov = np.asarray(self.covariance, dtype=float)
            if cov.shape != (3, 3):
                raise InvalidArgumentError(f"covariance must be 3x3, got {cov.shape}")
            self.covariance = cov

    @property
    def is_constrained(self) -> bool:
        """Whether the point's position is fixed by a gripper, a contact or a known point."""
        return self.kind in ("gripper", "contact", "fixed")

    def copy(self) -> FeaturePoint:
        """A deep copy."""
        return FeaturePoint(
            self.position.copy(),
            self.orientation.copy(),
            self.mass,
            self.kind,
            self.label,
            None if self.covariance is None else self.covariance.copy(),
            self.wrap,
        )
