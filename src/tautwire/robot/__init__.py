"""The narrow robot interface that primitives talk to.

Both the simulated world (``tautwire.sim``) and any real-robot driver
implement :class:`Robot`; primitives see only :class:`Observation` and send
only :class:`Command`.
"""

from tautwire.robot.arm import ARMS, Arm, arm_index
from tautwire.robot.command import Command, GripperCommand
from tautwire.robot.communication_error import RobotCommunicationError
from tautwire.robot.observation import GripperState, Observation, Wrench
from tautwire.robot.robot import Robot
from tautwire.robot.workspace import WORKSPACE, Workspace

__all__ = [
    "ARMS",
    "WORKSPACE",
    "Arm",
    "Command",
    "GripperCommand",
    "GripperState",
    "Observation",
    "Robot",
    "RobotCommunicationError",
    "Workspace",
    "Wrench",
    "arm_index",
]
