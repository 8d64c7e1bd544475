"""The simulated world: MuJoCo physics behind the robot interface.

The only package that imports :mod:`mujoco`. On Linux, offscreen rendering
uses EGL unless ``MUJOCO_GL`` says otherwise; MuJoCo reads the variable when
it is first imported, so it is set here, before that.
"""

import os
import sys

if sys.platform.startswith("linux"):
    os.environ.setdefault("MUJOCO_GL", "egl")


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
