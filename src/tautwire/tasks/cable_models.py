"""One model per cable for the whole run, and which context a step works on.

Every cable has its own path graph for the whole task (SCENARIO.md, "A step
names its cable"). Each gripper that holds a cable and carries a wrist
force-torque sensor has its own :class:`~tautwire.primitives.PrimitiveContext`
on that graph: its contact filter and elasticity estimate belong to the
edge that leaves its fingers, so with ``sensor.arm: both`` each gripper
senses its own side. The contexts of one cable share its graph: what one
step edits (a clip, a grasp, a released point), the next step of that cable
sees, whichever gripper senses it.

Who holds which cable is read from the models (a gripper point labelled with
the arm), never from the simulator: a grasp (H) adds one, a release turns it
into a free point.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from tautwire.model import PathGraph
from tautwire.primitives import PrimitiveContext
from tautwire.robot import Arm

#: Primitives (letters) whose ``arm`` senses the cable it works on.
SENSING_LETTERS = frozenset("DEFGI")
#: Builds the context of ``arm`` on ``graph`` (of cable ``cable``), from an
#: initial stiffness guess k [N/m] (None: the default).
ContextFactory = Callable[[str, Arm, PathGraph, float | None], PrimitiveContext]


@dataclass(frozen=True)
class StepModel:
    """The model a step works on.

    Attributes:
        cable: The cable's name (None: the step works on no cable, e.g.
            moving a free gripper).
        context: The context the primitive runs with: the sensing gripper's
            on the cable's graph (for a step on no cable, any context, for
            its controller and limits).
    """

    cable: str | None
    context: PrimitiveContext


class StepModelError(Exception):
    """No model fits the step (a precondition failure of the step, not of the code)."""


@dataclass
class CableModels:
    """The path graphs of all cables and the contexts of the grippers sensing them.

    Args:
        graphs: Path graph by cable name, in the scenario's order.
        sensors: The arms whose wrists carry a force-torque sensor.
        factory: Builds a context for a gripper that came to hold a cable
            (after a grasp) or that senses it first.
    """

    graphs: dict[str, PathGraph]
    sensors: frozenset[Arm]
    factory: ContextFactory
    contexts: dict[tuple[str, Arm], PrimitiveContext] = field(default_factory=dict)
    #: The context each cable's last step ran with.
    last: dict[str, PrimitiveContext] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for cable in self.graphs:
            for arm in self.holders(cable):
                if arm in self.sensors:
                    self.context(cable, arm)

    # ------------------------------------------------------------- queries
    @property
    def cables(self) -> tuple[str, ...]:
        """The cables' names, in order."""
        return tuple(self.graphs)

    def holders(self, cable: str) -> tuple[Arm, ...]:
        """The arms whose gripper holds ``cable``, as its model has it."""
        graph = self.graphs[cable]
        arms: list[Arm] = []
        for arm in ("left", "right"):
            if graph.index_of("gripper", arm) is not None:
                arms.append(arm)
        return tuple(arms)

    def held_by(self, arm: Arm) -> str | None:
        """The cable ``arm``'s gripper holds (the first, by the models), or None."""
        for cable in self.graphs:
            if arm in self.holders(cable):
                return cable
        return None

    def context(self, cable: str, arm: Arm) -> PrimitiveContext:
        """The context of ``arm`` sensing ``cable`` (built on first use).

        A context built after the cable's first carries the cable's
        tension set point and trusted stiffness over.
        """
        key = (cable, arm)
        if key not in self.contexts:
            before = self.last.get(cable) or next(
                (c for (name, _), c in self.contexts.items() if name == cable), None
            )
            k = None if before is None else before.estimator.elasticity.k_trusted
            ctx = self.factory(cable, arm, self.graphs[cable], k)
            if before is not None:
                ctx.tension = before.tension
            self.contexts[key] = ctx
        return self.contexts[key]

    def primary(self, cable: str) -> PrimitiveContext | None:
        """The context a step that names no sensing gripper uses for ``cable``.

        The cable's last step's context while that gripper still holds it,
        else the context of a gripper with a sensor that holds it (None: no
        gripper with a sensor holds it).
        """
        holders = self.holders(cable)
        last = self.last.get(cable)
        if last is not None and last.arm in holders:
            return last
        for arm in holders:
            if arm in self.sensors:
                return self.context(cable, arm)
        return None

    def final(self, cable: str) -> PrimitiveContext | None:
        """The context whose graph is ``cable``'s model at the end (any of them shares it)."""
        return (
            self.last.get(cable)
            or self.primary(cable)
            or next((c for (name, _), c in self.contexts.items() if name == cable), None)
        )

    # ----------------------------------------------------------- selection
    def select(self, letter: str, params: Mapping[str, object], primitive: str = "") -> StepModel:
        """The cable and context for a step of primitive ``letter`` with ``params``.

        The cable is the step's ``cable``, else the one its gripper holds,
        else the only cable. A single-arm primitive that senses (D, E, F, G,
        I) and a taut ``move`` of a gripper that holds the cable run with
        their own arm's context: that arm must hold the cable and carry a
        sensor. A ``release`` and an untaut move run on the cable's context
        (any gripper sensing it); a move or a release of a gripper that holds
        no cable runs on no cable.

        Args:
            letter: The primitive's letter ("" for a move).
            params: The step's parameters.
            primitive: The primitive's name (tells ``move`` from ``release``).

        Raises:
            StepModelError: naming what is missing.
        """
        arm = params.get("arm")
        step_arm: Arm | None = "left" if arm == "left" else "right" if arm == "right" else None
        named = params.get("cable")
        cable: str | None
        if isinstance(named, str):
            if named not in self.graphs:
                raise StepModelError(f"no cable named {named!r} (cables: {', '.join(self.graphs)})")
            cable = named
        elif step_arm is not None and self.held_by(step_arm) is not None:
            cable = self.held_by(step_arm)
        elif len(self.graphs) == 1:
            cable = next(iter(self.graphs))
        else:
            cable = None
        move = letter == ""
        if cable is None:
            if not move:
                raise StepModelError(
                    f"the {step_arm} gripper holds no cable and the step names none"
                    if step_arm is not None
                    else "the step names no cable"
                )
            return StepModel(None, self._any())
        holders = self.holders(cable)
        taut_move = primitive == "move" and bool(params.get("taut", True))
        if letter in SENSING_LETTERS or (taut_move and step_arm in holders):
            assert step_arm is not None  # these primitives all take an arm
            if step_arm not in holders:
                raise StepModelError(f"the {step_arm} gripper does not hold {cable}")
            if step_arm not in self.sensors:
                raise StepModelError(
                    f"the {step_arm} gripper holds {cable} but carries no force sensor"
                )
            return StepModel(cable, self.context(cable, step_arm))
        ctx = self.primary(cable)
        if ctx is None:
            if move:  # a free gripper moves near a cable it does not hold
                return StepModel(None, self._any())
            raise StepModelError(f"no gripper with a force sensor holds {cable}")
        return StepModel(cable, ctx)

    def ran(self, model: StepModel) -> None:
        """Record that a step ran on ``model`` (its context is the cable's latest)."""
        if model.cable is not None:
            self.last[model.cable] = model.context
        self.prune()

    def prune(self) -> None:
        """Forget the contexts of grippers that no longer hold their cable (released)."""
        for key in [k for k in self.contexts if k[1] not in self.holders(k[0])]:
            ctx = self.contexts.pop(key)
            if self.last.get(key[0]) is ctx:
                # the graph stays the cable's model: keep it reachable for scoring
                self.last[key[0]] = ctx

    def _any(self) -> PrimitiveContext:
        """Some context (its controller and limits), for a step on no cable."""
        if self.contexts:
            return next(iter(self.contexts.values()))
        if self.last:
            return next(iter(self.last.values()))
        raise StepModelError("no gripper with a force sensor holds any cable")
