"""The simulated world: MuJoCo physics behind the robot interface.

The only package that imports :mod:`mujoco`. On Linux, offscreen rendering
uses EGL unless ``MUJOCO_GL`` says otherwise; MuJoCo reads the variable when
it is first imported, so it is set here, before that.

Typical use::

    world = build_world(scenario)          # build and settle
    robot = robot_of(world)                # what primitives get (tautwire.robot.Robot)
    truth = truth_of(world)                # for scoring only
    robot.act(command); robot.observe()
    world.max_force; world.reset_max_force()
"""

import os
import sys

if sys.platform.startswith("linux"):
    os.environ.setdefault("MUJOCO_GL", "egl")

from tautwire.sim.build import build_world, robot_of, truth_of, world_spec
from tautwire.sim.diverged import SimulationDiverged
from tautwire.sim.fault_injector import FaultInjector
from tautwire.sim.ft_sensor import FTSensor
from tautwire.sim.ground_truth import FixtureContact, GroundTruth
from tautwire.sim.options import SimOptions
from tautwire.sim.render import SceneRenderer, render_frame, write_png
from tautwire.sim.sim_robot import SimRobot
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
    "FTSensor",
    "FaultInjector",
    "FixtureContact",
    "GripperSpec",
    "GroundTruth",
    "HoldSpec",
    "PegSpec",
    "SceneRenderer",
    "SimOptions",
    "SimRobot",
    "SimWorld",
    "SimulationDiverged",
    "WorldSpec",
    "build_world",
    "render_frame",
    "robot_of",
    "truth_of",
    "world_spec",
    "write_png",
]
