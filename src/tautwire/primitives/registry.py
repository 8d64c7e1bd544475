"""Every primitive registered by name and by letter, and the moves between them by name."""

from __future__ import annotations

from tautwire.errors import InvalidArgumentError
from tautwire.primitives.grasp_tensioned import GraspTensioned
from tautwire.primitives.gripper_alignment import GripperAlignment
from tautwire.primitives.move import Move
from tautwire.primitives.parallel_clipping import ParallelClipping
from tautwire.primitives.parallel_sliding import ParallelSliding
from tautwire.primitives.parallel_tension import ParallelTension
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.release import Release
from tautwire.primitives.rotate_around_feature_point import RotateAroundFeaturePoint
from tautwire.primitives.single_arm_clipping import SingleArmClipping
from tautwire.primitives.single_arm_sliding import SingleArmSliding
from tautwire.primitives.single_arm_tension import SingleArmTension

#: Primitive classes by name.
PRIMITIVES: dict[str, type[Primitive]] = {
    cls.name: cls
    for cls in (
        ParallelTension,
        ParallelSliding,
        ParallelClipping,
        SingleArmTension,
        SingleArmSliding,
        SingleArmClipping,
        GripperAlignment,
        GraspTensioned,
        RotateAroundFeaturePoint,
    )
}

#: The moves between primitives (SCENARIO.md, "Moves between primitives"), by
#: name: they have no letter.
MOVES: dict[str, type[Primitive]] = {cls.name: cls for cls in (Move, Release)}


def primitive_class(name_or_letter: str) -> type[Primitive]:
    """The class named ``name_or_letter`` (a primitive's name or letter A-I, or a move's name)."""
    for cls in PRIMITIVES.values():
        if name_or_letter in (cls.name, cls.letter):
            return cls
    if name_or_letter in MOVES:
        return MOVES[name_or_letter]
    valid = ", ".join([f"{c.name} ({c.letter})" for c in PRIMITIVES.values()] + list(MOVES))
    raise InvalidArgumentError(f"no primitive {name_or_letter!r} is implemented; valid: {valid}")


def make_primitive(name_or_letter: str, **params: object) -> Primitive:
    """Build a primitive from its scenario parameters.

    A step's ``cable`` chooses which model the step works on (the runner's
    job, :mod:`tautwire.tasks.cable_models`), not how the primitive acts: it
    is not passed on.
    """
    params.pop("cable", None)
    cls = primitive_class(name_or_letter)
    try:
        return cls(**params)  # type: ignore[arg-type]
    except TypeError as exc:
        raise InvalidArgumentError(f"{cls.name}: {exc}") from exc
