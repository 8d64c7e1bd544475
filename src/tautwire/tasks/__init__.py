"""Sequences of primitives and the runner that executes them on any Robot."""

from tautwire.tasks.runner import StepReport, TickRecord, run_step

__all__ = ["StepReport", "TickRecord", "run_step"]
