"""Run a task, a sequence of primitives and moves, on any robot, one model per cable.

Each step names its cable (or works on the one its gripper holds) and runs
with the context of the gripper that senses it
(:class:`~tautwire.tasks.cable_models.CableModels`); a failure ends the
task. A gripper that let its cable go keeps its fingers open until it
grasps again.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Protocol

from tautwire.errors import TautwireError
from tautwire.primitives.registry import make_primitive
from tautwire.robot import Arm, Robot
from tautwire.tasks.cable_models import CableModels, StepModel, StepModelError
from tautwire.tasks.runner import StepReport, TickRecord, run_step


class TaskStep(Protocol):
    """One step of a task as a scenario gives it."""

    @property
    def primitive(self) -> str:
        """The primitive's (or move's) canonical name."""
        ...

    @property
    def letter(self) -> str:
        """Its letter ("" for a move)."""
        ...

    @property
    def params(self) -> Mapping[str, object]:
        """Its parameters, ``cable`` included."""
        ...


@dataclass(frozen=True)
class PlainStep:
    """A task step as plain data (what a planner or a script writes)."""

    primitive: str
    letter: str
    params: Mapping[str, object]


@dataclass
class TaskHooks:
    """Callbacks of a task's run (recording, scoring); each may be None.

    Attributes:
        on_start: Before step ``i`` runs on its model (not called for a
            step that no model fits).
        on_tick: After every control period of a step.
        on_end: After step ``i`` ended with its report, on its model (None:
            no model fitted the step).
    """

    on_start: Callable[[int, TaskStep, StepModel], None] | None = None
    on_tick: Callable[[TickRecord], None] | None = None
    on_end: Callable[[int, TaskStep, StepModel | None, StepReport], None] | None = None


def run_task(
    robot: Robot,
    steps: Sequence[TaskStep],
    models: CableModels,
    hooks: TaskHooks | None = None,
    force_limit: float | None = None,
) -> list[StepReport]:
    """Run ``steps`` in order on ``robot`` until one fails.

    Args:
        robot: The robot; pass one :class:`~tautwire.tasks.RobotGuard` for
            the whole task (its tare and last good sample last across steps).
        steps: The task.
        models: The cables' models and the contexts sensing them; steps
            edit them.
        hooks: Callbacks for recording and scoring.
        force_limit: Force limit [N]; default each context's.

    Returns:
        One report per step that ran (the last one failed, unless all succeeded).
    """
    hooks = hooks or TaskHooks()
    reports: list[StepReport] = []
    released: set[Arm] = set()  # grippers that let go and have not grasped since
    for i, step in enumerate(steps):
        params = dict(step.params)
        named = params.get("arm")
        arm: Arm | None = "left" if named == "left" else "right" if named == "right" else None
        try:
            model = models.select(step.letter, params, step.primitive)
        except StepModelError as exc:
            report = StepReport(
                step.primitive, step.letter, "failure", "precondition", str(exc), 0.0, 0.0
            )
            if hooks.on_end is not None:
                hooks.on_end(i, step, None, report)
            reports.append(report)
            break
        if hooks.on_start is not None:
            hooks.on_start(i, step, model)
        try:
            primitive = make_primitive(step.primitive, **params)
        except TautwireError as exc:
            report = StepReport(
                step.primitive, step.letter, "failure", "error", str(exc), 0.0, 0.0, model.cable
            )
        else:
            grasping = {arm} if step.letter == "H" and arm is not None else set()
            report = run_step(
                robot,
                primitive,
                model.context,
                on_tick=hooks.on_tick,
                force_limit=force_limit,
                keep_open=frozenset(released - grasping),
                cable=model.cable,
            )
        if report.success and arm is not None:
            if step.primitive == "release":
                released.add(arm)
            elif step.letter == "H":
                released.discard(arm)
        models.ran(model)
        if hooks.on_end is not None:
            hooks.on_end(i, step, model, report)
        reports.append(report)
        if not report.success:
            break
    return reports
