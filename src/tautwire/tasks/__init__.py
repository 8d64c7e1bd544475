"""Sequences of primitives and the runner that executes them on any Robot."""

from tautwire.tasks.robot_guard import RobotGuard
from tautwire.tasks.runner import StepReport, TickRecord, run_step

__all__ = ["RobotGuard", "StepReport", "TickRecord", "run_step"]
