"""Run a primitive on any :class:`~tautwire.robot.Robot` until it ends.

The runner enforces what no primitive may forget: the force limit (a
measured force above its protective stop, :data:`PROTECTIVE_STOP` of the
limit, ends the step with cause ``force_limit``), the
primitive's timeout, and a clean end when the robot or its data fail. Every
sample and command goes through a :class:`~tautwire.tasks.robot_guard.RobotGuard`
(non-finite, stale and outlying samples, lost commands, robot exceptions,
the workspace): the primitive is stepped only on a fresh, accepted sample,
and the robot holds still otherwise. A failed step ends with a zero twist.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Collection
from dataclasses import dataclass, replace

from tautwire.errors import TautwireError
from tautwire.primitives import Outcome, Primitive, PrimitiveContext
from tautwire.robot import Arm, Command, GripperCommand, Observation, Robot
from tautwire.tasks.robot_guard import RobotGuard

#: Share of the force limit at which a measured force stops the step. The
#: stop comes a control period after the force that trips it, and the
#: guard holds back a jump for one sample (an outlier, or the start of a
#: real force): stopped at the limit itself, random boards 303464894,
#: 1652323633, 1695658280 and 2071274635 (seed 0) read 15.1-16.2 N when the
#: step ended and truly transmitted 15.1-16.5 N. 90 % leaves 1.5 N for that.
PROTECTIVE_STOP = 0.9


@dataclass(frozen=True)
class StepReport:
    """How one primitive ended (the ``steps`` entries of a run's result).

    Attributes:
        primitive: The primitive's name.
        letter: Its letter A-I.
        outcome: ``success`` or ``failure``.
        cause: Why it failed (None on success).
        detail: A sentence for the reader.
        sim_time: Duration [s] of the step (robot time).
        max_force: Largest measured force magnitude [N] during the step.
        cable: The cable the step worked on (None: none, or not known).
    """

    primitive: str
    letter: str
    outcome: str
    cause: str | None
    detail: str
    sim_time: float
    max_force: float
    cable: str | None = None

    @property
    def success(self) -> bool:
        """Whether the step succeeded."""
        return self.outcome == "success"


@dataclass(frozen=True)
class TickRecord:
    """What a tick callback receives: the observation and the command sent."""

    observation: Observation
    command: Command
    primitive: Primitive
    context: PrimitiveContext


def _max_measured_force(obs: Observation) -> float:
    best = 0.0
    for w in obs.wrenches:
        fx, fy, fz = (float(v) for v in w.force)
        best = max(best, math.sqrt(fx * fx + fy * fy + fz * fz))
    return best


def keep_fingers_open(command: Command, arms: Collection[Arm]) -> Command:
    """``command`` with the fingers of ``arms`` kept open.

    A primitive that does not use a gripper sends it the default ``hold``;
    to a gripper that let its cable go (a release), ``hold`` would close
    it again on whatever cable lies between its fingers. Its fingers stay
    open until a grasp closes them.
    """
    if not arms:
        return command
    opened = GripperCommand("open")
    return replace(
        command,
        left=opened if "left" in arms else command.left,
        right=opened if "right" in arms else command.right,
    )


def run_step(
    robot: Robot,
    primitive: Primitive,
    ctx: PrimitiveContext,
    on_tick: Callable[[TickRecord], None] | None = None,
    force_limit: float | None = None,
    keep_open: Collection[Arm] = (),
    cable: str | None = None,
) -> StepReport:
    """Run ``primitive`` on ``robot`` until it succeeds or fails.

    Args:
        robot: The robot (simulated or real). A :class:`RobotGuard` is used
            as it is: create one per run, so that its state (last good
            sample, tare) lasts across the steps. Any other robot is wrapped
            in a guard for this step only (no tare, no workspace, no
            frozen-sensor check: those need the run's settings).
        primitive: A fresh primitive.
        ctx: The shared context (model, estimators, controller).
        on_tick: Called after every control period in which the primitive
            was stepped (recording, plotting).
        force_limit: Force limit [N]; default ``ctx.limits.max_force``. The step
            stops at :data:`PROTECTIVE_STOP` of it.
        keep_open: Grippers whose fingers stay open (they let their cable
            go; see :func:`keep_fingers_open`).
        cable: The cable the step works on (for the report).

    Returns:
        The step's report. Failures of the robot or its data end the step
        with the guard's cause (``sensor_stale``, ``robot_error``,
        ``workspace``, ``diverged``); an exception of the primitive with
        ``error`` (or the cause the exception names).
    """
    limit = ctx.limits.max_force if force_limit is None else force_limit
    guard = robot if isinstance(robot, RobotGuard) else RobotGuard(robot, force_limit=limit)
    guard.begin_step()
    max_force = 0.0
    obs = guard.observe()
    t0 = guard.time
    started = False
    outcome: Outcome
    try:
        while True:
            fault = guard.fault
            if fault is not None:
                outcome = fault
                break
            if not guard.fresh:
                guard.hold()
                obs = guard.observe()
                continue
            force = _max_measured_force(obs)
            max_force = max(max_force, force)
            if force > PROTECTIVE_STOP * limit:
                outcome = Outcome.failure(
                    "force_limit",
                    f"measured {force:.2f} N, above the protective stop at"
                    f" {PROTECTIVE_STOP * limit:.1f} N ({PROTECTIVE_STOP:.0%} of the"
                    f" {limit:g} N limit)",
                )
                break
            if not started:
                primitive.start(obs, ctx)
                started = True
            command = primitive.step(obs)
            if primitive.outcome.done:
                outcome = primitive.outcome
                break
            guard.act(keep_fingers_open(command, keep_open))
            if on_tick is not None:
                on_tick(TickRecord(obs, command, primitive, ctx))
            obs = guard.observe()
    except TautwireError as exc:
        cause = getattr(exc, "cause", None) or "error"
        outcome = Outcome.failure(str(cause), f"{type(exc).__name__}: {exc}")
    except (FloatingPointError, ValueError, ArithmeticError) as exc:
        outcome = Outcome.failure("error", f"{type(exc).__name__}: {exc}")
    if outcome.status == "failure" and outcome.cause != "diverged":
        guard.stop()
    return StepReport(
        primitive.name,
        primitive.letter,
        outcome.status,
        outcome.cause,
        outcome.detail,
        guard.time - t0,
        max_force,
        cable,
    )
