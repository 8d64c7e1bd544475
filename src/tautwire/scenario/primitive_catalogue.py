"""The nine primitives and the moves a task step may name, with their parameters.

The table follows SCENARIO.md ("Primitives") and the letters of the paper's
results table (paper/NOTES.md): A-C coordinated (both arms), D-I individual.
A step names its primitive by canonical name or by letter. The moves
between primitives (``move``, ``release``; SCENARIO.md, "Moves between
primitives") have names but no letter. Every step may name its ``cable``
(SCENARIO.md, "A step names its cable").
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

from tautwire.errors import InvalidArgumentError
from tautwire.scenario.suggestion import did_you_mean
from tautwire.scenario.value_text import show

ParamKind = Literal[
    "number", "arm", "clip", "fixture", "cable", "vector3", "position", "quaternion", "flag"
]
"""How a parameter's value is written: a number, an arm name (``left`` or
``right``), the name of a clip, of any fixture or of a cable, three numbers
(a direction, normalised; or a position or offset, as given), four numbers
(a quaternion [w, x, y, z], normalised), or ``true``/``false``."""

Bound = Literal["any", "positive", "non_negative", "non_zero"]
"""The range a number must lie in."""

ParamValue = bool | float | str | list[float]
"""A checked parameter value (flags as bool, numbers as float, names as str,
vectors as list)."""


class ParameterError(InvalidArgumentError):
    """A task step's parameter is missing, unknown or has a wrong value.

    Attributes:
        parameter: the parameter's name.
    """

    def __init__(self, parameter: str, message: str) -> None:
        super().__init__(message)
        self.parameter = parameter


@dataclass(frozen=True)
class ParamSpec:
    """One parameter of a primitive.

    Attributes:
        name: key in the task step.
        kind: how the value is written.
        meaning: what it is, with its unit in brackets.
        bound: the range of a number (ignored for names).
        default: value used when an optional parameter is omitted (``None``:
            the primitive chooses).
    """

    name: str
    kind: ParamKind
    meaning: str
    bound: Bound = "any"
    default: ParamValue | None = None

    def expected(self) -> str:
        """Describe a valid value, e.g. ``'a number > 0 (pulling force [N])'``."""
        what = {
            "number": {
                "any": "a number",
                "positive": "a number > 0",
                "non_negative": "a number >= 0",
                "non_zero": "a non-zero number",
            }[self.bound],
            "arm": "'left' or 'right'",
            "clip": "the name of a clip",
            "fixture": "the name of a fixture",
            "cable": "the name of a cable",
            "vector3": "a non-zero list of 3 numbers",
            "position": "a list of 3 numbers",
            "quaternion": "a non-zero list of 4 numbers [w, x, y, z]",
            "flag": "true or false",
        }[self.kind]
        return f"{what}: {self.meaning}"

    def check(self, value: object) -> ParamValue:
        """Return ``value`` in canonical form (floats, unit vectors).

        Raises:
            InvalidArgumentError: if the value has the wrong type or range;
                the message says what was expected.
        """
        wrong = InvalidArgumentError(f"got {show(value)} (expected {self.expected()})")
        if self.kind == "number":
            number = _as_number(value)
            if number is None or not _in_bound(number, self.bound):
                raise wrong
            return number
        if self.kind == "flag":
            if not isinstance(value, bool):
                raise wrong
            return value
        if self.kind in ("vector3", "position", "quaternion"):
            size = 4 if self.kind == "quaternion" else 3
            if not isinstance(value, list | tuple) or len(value) != size:
                raise wrong
            components = [_as_number(c) for c in value]
            if any(c is None for c in components):
                raise wrong
            vector = [float(c) for c in components if c is not None]
            if self.kind == "position":
                return vector
            norm = math.sqrt(sum(c * c for c in vector))
            if norm < 1e-9:
                raise wrong
            return [c / norm for c in vector]
        if not isinstance(value, str) or not value:
            raise wrong
        if self.kind == "arm" and value not in ("left", "right"):
            raise wrong
        return value


def _as_number(value: object) -> float | None:
    """``value`` as a finite float, or ``None`` if it is not a number (bools are not)."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return None
    number = float(value)
    return number if math.isfinite(number) else None


def _in_bound(number: float, bound: Bound) -> bool:
    """Whether ``number`` lies in ``bound``."""
    if bound == "positive":
        return number > 0.0
    if bound == "non_negative":
        return number >= 0.0
    if bound == "non_zero":
        return number != 0.0
    return True


@dataclass(frozen=True)
class PrimitiveSpec:
    """A primitive (or a move): its names and parameters.

    Attributes:
        name: canonical name, e.g. ``"single_arm_tension"``.
        letter: the paper's letter, e.g. ``"D"`` (``""`` for a move, which has none).
        title: the paper's name, e.g. ``"Single arm DLO Tension"``.
        required: parameters that every step must give.
        optional: parameters that a step may give.
        one_of: optional parameters of which a step must give exactly one.
    """

    name: str
    letter: str
    title: str
    required: tuple[ParamSpec, ...]
    optional: tuple[ParamSpec, ...] = ()
    one_of: tuple[str, ...] = ()

    @property
    def parameters(self) -> tuple[ParamSpec, ...]:
        """Required then optional parameters (without the ones every step has)."""
        return self.required + self.optional

    def check_params(self, values: Mapping[str, object]) -> dict[str, ParamValue]:
        """Check a step's parameters; return them in canonical form with defaults.

        Args:
            values: parameter values by name, as written in the file.

        Returns:
            Every given parameter (numbers as float, axes normalised) plus the
            defaults of omitted optional parameters that have one.

        Raises:
            ParameterError: for the first unknown, missing or invalid parameter.
        """
        names = ", ".join(p.name for p in self.parameters + STEP_PARAMETERS)
        for name in values:
            if self.parameter(name) is None:
                hint = did_you_mean(name, [p.name for p in self.parameters + STEP_PARAMETERS])
                raise ParameterError(
                    name, f"unknown parameter of {self.name}{hint} (expected only: {names})"
                )
        given = [name for name in self.one_of if name in values]
        if self.one_of and len(given) != 1:
            choice = " or ".join(self.one_of)
            raise ParameterError(
                given[-1] if given else self.one_of[0],
                f"{'both given' if given else 'missing'} (expected {choice}, one of them,"
                f" in a {self.name} step)",
            )
        checked: dict[str, ParamValue] = {}
        for spec in self.parameters + STEP_PARAMETERS:
            if spec.name in values:
                try:
                    checked[spec.name] = spec.check(values[spec.name])
                except InvalidArgumentError as exc:
                    raise ParameterError(spec.name, str(exc)) from exc
            elif spec in self.required:
                raise ParameterError(
                    spec.name,
                    f"missing parameter of {self.name} (expected {spec.expected()})",
                )
            elif spec.default is not None:
                checked[spec.name] = spec.default
        return checked

    def parameter(self, name: str) -> ParamSpec | None:
        """The parameter called ``name`` (its own or one every step has), or ``None``."""
        for spec in self.parameters + STEP_PARAMETERS:
            if spec.name == name:
                return spec
        return None


_ARM = ParamSpec("arm", "arm", "the gripper that acts")
_FORCE = ParamSpec("force", "number", "desired cable tension [N]", "positive")
_DISTANCE = ParamSpec(
    "distance", "number", "how far the gripper slides along the cable [m]", "positive"
)
_FRICTION = ParamSpec("friction_force", "number", "tension kept while sliding [N]", "positive")
_CLIP = ParamSpec("clip", "clip", "the clip to push the cable into")

STEP_PARAMETERS: tuple[ParamSpec, ...] = (
    ParamSpec("cable", "cable", "the cable the step works on (default: the one its gripper holds)"),
)
"""Optional parameters of every step, primitive or move."""

PRIMITIVES: tuple[PrimitiveSpec, ...] = (
    PrimitiveSpec("parallel_tension", "A", "Parallel DLO Tension", (_FORCE,)),
    PrimitiveSpec(
        "parallel_sliding",
        "B",
        "Parallel DLO Sliding",
        (
            ParamSpec("slide_arm", "arm", "the gripper the cable slides through"),
            _DISTANCE,
            _FRICTION,
        ),
    ),
    PrimitiveSpec("parallel_clipping", "C", "Parallel DLO Clipping", (_CLIP,)),
    PrimitiveSpec("single_arm_tension", "D", "Single arm DLO Tension", (_ARM, _FORCE)),
    PrimitiveSpec(
        "single_arm_sliding", "E", "Single arm DLO Sliding", (_ARM, _DISTANCE, _FRICTION)
    ),
    PrimitiveSpec("single_arm_clipping", "F", "Single arm DLO Clipping", (_ARM, _CLIP)),
    PrimitiveSpec("gripper_alignment", "G", "Gripper Alignment", (_ARM,)),
    PrimitiveSpec(
        "grasp_tensioned",
        "H",
        "Grasp a Tensioned DLO",
        (
            _ARM,
            ParamSpec(
                "at", "number", "arc length from the cable start to grasp at [m]", "non_negative"
            ),
        ),
    ),
    PrimitiveSpec(
        "rotate_around_feature_point",
        "I",
        "Rotate Around Feature Point",
        (
            _ARM,
            ParamSpec(
                "angle",
                "number",
                "turn, right-handed about axis; negative turns the other way [rad]",
                "non_zero",
            ),
        ),
        (
            ParamSpec("axis", "vector3", "rotation axis, normalised [-]", default=[0.0, 0.0, 1.0]),
            ParamSpec("speed", "number", "angular speed [rad/s]", "positive"),
            ParamSpec(
                "about",
                "fixture",
                "the fixture circled; a peg must end as the contact (else not_wound)",
            ),
        ),
    ),
)
"""The nine primitives, in letter order."""

MOVES: tuple[PrimitiveSpec, ...] = (
    PrimitiveSpec(
        "move",
        "",
        "Move a gripper",
        (_ARM,),
        (
            ParamSpec("to", "position", "where the tool centre point goes, world frame [m]"),
            ParamSpec("by", "position", "offset of the tool centre point, world frame [m]"),
            ParamSpec("orientation", "quaternion", "end orientation [w, x, y, z], normalised"),
            ParamSpec(
                "taut", "flag", "keep the held cable under its present tension", default=True
            ),
            ParamSpec(
                "observe",
                "flag",
                "let the contact filter take the move's force lines (off: sweeping onto a peg)",
                default=True,
            ),
            ParamSpec(
                "catch",
                "fixture",
                "the peg the move sweeps the cable onto: the model takes it as the contact",
            ),
        ),
        one_of=("to", "by"),
    ),
    PrimitiveSpec("release", "", "Release the cable", (_ARM,)),
)
"""The moves between primitives (no letter)."""


def primitive_choices() -> str:
    """The valid names and letters, e.g. ``'parallel_tension (A), ..., move, release'``."""
    return ", ".join(f"{p.name} ({p.letter})" if p.letter else p.name for p in PRIMITIVES + MOVES)


def find_primitive(name_or_letter: str) -> PrimitiveSpec:
    """Return the primitive or move with this canonical name or letter.

    Raises:
        InvalidArgumentError: if there is none; the message lists the choices.
    """
    for spec in PRIMITIVES + MOVES:
        if name_or_letter == spec.name or (spec.letter and name_or_letter == spec.letter):
            return spec
    hint = did_you_mean(name_or_letter, [p.name for p in PRIMITIVES + MOVES])
    raise InvalidArgumentError(
        f"unknown primitive {name_or_letter!r}{hint} (expected one of: {primitive_choices()})"
    )
