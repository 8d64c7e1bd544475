"""The simulated world: MuJoCo physics behind the robot interface.

The only package that imports :mod:`mujoco`.
"""

from tautwire.sim.diverged import SimulationDiverged
from tautwire.sim.options import SimOptions
from tautwire.sim.spec import (
    AnchorSpec,
    CableSpec,
    ClipSpec,
    GripperSpec,
    HoldSpec,
    PegSpec,
    WorldSpec,
)
from tautwire.sim.world import SimWorld

__all__ = [
    "AnchorSpec",
    "CableSpec",
    "ClipSpec",
    "GripperSpec",
    "HoldSpec",
    "PegSpec",
    "SimOptions",
    "SimWorld",
    "SimulationDiverged",
    "WorldSpec",
]
