"""Base class of the manipulation primitives: a small state machine."""

from __future__ import annotations

from abc import ABC, abstractmethod
from typing import ClassVar

from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.outcome import RUNNING, Outcome
from tautwire.robot import Command, Observation


class Primitive(ABC):
    """A manipulation primitive: ``Observation -> Command`` until it ends.

    A primitive sees only observations and the shared
    :class:`~tautwire.primitives.context.PrimitiveContext`, never the
    simulator. Call :meth:`start` once, then :meth:`step` each control period
    until :attr:`outcome` is done.

    Attributes:
        name: The primitive's name in scenario files.
        letter: Its letter in the paper (A-I).
        timeout: Longest time [s] it may run before failing with ``timeout``.
    """

    name: ClassVar[str]
    letter: ClassVar[str]

    def __init__(self, timeout: float = 20.0) -> None:
        self.timeout = float(timeout)
        self.outcome: Outcome = RUNNING
        self.ctx: PrimitiveContext | None = None
        self.start_time = 0.0
        self.elapsed = 0.0

    def start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Begin at observation ``obs`` with the shared context ``ctx``."""
        self.ctx = ctx
        self.start_time = obs.time
        self.elapsed = 0.0
        self.outcome = RUNNING
        ctx.estimator.observe_contacts = True  # a primitive may turn it off in on_start
        ctx.estimator.circling = True
        self.on_start(obs, ctx)

    def step(self, obs: Observation) -> Command:
        """One control period: update the model, decide, command."""
        if self.ctx is None:
            raise RuntimeError(f"{self.name}: step() before start()")
        self.elapsed = obs.time - self.start_time
        command = self.on_step(obs, self.ctx)
        if not self.outcome.done and self.elapsed > self.timeout:
            self.outcome = Outcome.failure(
                "timeout", f"{self.name} did not meet its success criteria in {self.timeout:g} s"
            )
        return command

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:  # noqa: B027
        """Hook: prepare at the start (default: nothing)."""

    @abstractmethod
    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Hook: the primitive's control law and success criteria."""

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.letter}, {self.outcome.status})"
