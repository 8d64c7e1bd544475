"""The typed objects of a scenario file (format version 1, see SCENARIO.md).

Every model is frozen and forbids unknown keys. Numbers are strict (a quoted
``"0.4"`` is rejected, an integer is accepted where a float is expected) and
finite. Units are SI, quaternions are ``[w, x, y, z]``.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    field_validator,
    model_validator,
)

from tautwire.errors import InvalidArgumentError
from tautwire.scenario.geometry import check_geometry
from tautwire.scenario.issue import located_error
from tautwire.scenario.primitive_catalogue import (
    ParameterError,
    PrimitiveSpec,
    find_primitive,
    primitive_choices,
)
from tautwire.scenario.references import check_references
from tautwire.scenario.route_check import check_routes


def _sequence_to_tuple(value: Any) -> Any:
    """Let a YAML list stand for a fixed-length tuple."""
    return tuple(value) if isinstance(value, list) else value


Vector3 = Annotated[tuple[float, float, float], BeforeValidator(_sequence_to_tuple)]
"""A point or direction in the world frame [m] (3 numbers)."""

Quaternion = Annotated[tuple[float, float, float, float], BeforeValidator(_sequence_to_tuple)]
"""An orientation as a quaternion [w, x, y, z] (4 numbers)."""


class _Model(BaseModel):
    """Common configuration: frozen, unknown keys rejected, strict finite numbers."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True, allow_inf_nan=False)


class SensorSettings(_Model):
    """The wrist force-torque sensor(s).

    Attributes:
        arm: which wrist carries the FT sensor.
        noise_force: standard deviation of the force noise, per axis [N].
        noise_torque: standard deviation of the torque noise, per axis [N m].
    """

    arm: Literal["left", "right", "both"] = "left"
    noise_force: float = Field(0.05, ge=0.0, description="force noise std per axis [N]")
    noise_torque: float = Field(0.002, ge=0.0, description="torque noise std per axis [N m]")


class GripperStart(_Model):
    """A gripper's start pose in the world frame.

    Attributes:
        position: tool centre point [m].
        orientation: quaternion [w, x, y, z], normalised on load.
    """

    position: Vector3 = Field(description="gripper start position [m]")
    orientation: Quaternion = Field(
        (1.0, 0.0, 0.0, 0.0), description="unit quaternion [w, x, y, z]"
    )

    @field_validator("orientation")
    @classmethod
    def _normalise(cls, q: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
        norm = math.sqrt(sum(c * c for c in q))
        if norm < 1e-9:
            raise ValueError(
                "a quaternion must not be zero (expected [w, x, y, z], e.g. [1, 0, 0, 0])"
            )
        w, x, y, z = (c / norm for c in q)
        return (w, x, y, z)


class GrippersSettings(_Model):
    """Start poses of both grippers."""

    left: GripperStart
    right: GripperStart


class RobotSettings(_Model):
    """The robot's interface, limits, sensor and start poses.

    Attributes:
        control_period: time between two commands [s].
        force_limit: a measured force above this ends the step as a failure [N].
        sensor: the FT sensor settings.
        grippers: start poses.
    """

    control_period: float = Field(0.004, gt=0.0, le=0.1, description="control period [s]")
    force_limit: float = Field(15.0, gt=0.0, description="force limit [N]")
    sensor: SensorSettings = SensorSettings()
    grippers: GrippersSettings


class Anchor(_Model):
    """A point where a cable end is fixed.

    Attributes:
        name: unique fixture name.
        type: ``"anchor"``.
        position: the fixed point [m].
    """

    name: str = Field(min_length=1)
    type: Literal["anchor"]
    position: Vector3 = Field(description="anchor position [m]")


class Peg(_Model):
    """A vertical post the cable can bear against or wind around.

    Attributes:
        name: unique fixture name.
        type: ``"peg"``.
        position: centre of the peg's base [m].
        radius: peg radius [m].
        height: the peg rises this far above ``position`` [m].
    """

    name: str = Field(min_length=1)
    type: Literal["peg"]
    position: Vector3 = Field(description="peg base centre [m]")
    radius: float = Field(gt=0.0, description="peg radius [m]")
    height: float = Field(gt=0.0, description="peg height [m]")


#: Length [m] of a clip along its slot (one design for every clip; the cable
#: model's segments, 2 cm at rest, must not be able to span it).
CLIP_LENGTH = 0.03


class Clip(_Model):
    """A snap-in clip whose slot opens upwards.

    Attributes:
        name: unique fixture name.
        type: ``"clip"``.
        position: where a clipped cable sits [m].
        yaw: direction of the slot, about world z [rad].
        push_force: force needed to push the cable in [N].
    """

    name: str = Field(min_length=1)
    type: Literal["clip"]
    position: Vector3 = Field(description="clip seat position [m]")
    yaw: float = Field(0.0, description="slot direction about z [rad]")
    push_force: float = Field(2.5, gt=0.0, description="push-in force [N]")


Fixture = Annotated[Anchor | Peg | Clip, Field(discriminator="type")]
"""Any fixture on the board, told apart by its ``type`` key."""


class Board(_Model):
    """The fixtures on the board (names unique)."""

    fixtures: list[Fixture]

    def fixture(self, name: str) -> Anchor | Peg | Clip:
        """Return the fixture called ``name``.

        Raises:
            InvalidArgumentError: if there is none; the message lists the names.
        """
        for fixture in self.fixtures:
            if fixture.name == name:
                return fixture
        names = ", ".join(f.name for f in self.fixtures) or "none"
        raise InvalidArgumentError(f"no fixture named {name!r} (fixtures: {names})")


class Hold(_Model):
    """Where a gripper holds a cable.

    Attributes:
        arm: the holding gripper.
        at: arc length from the cable's start to the held point [m].
    """

    arm: Literal["left", "right"]
    at: float = Field(ge=0.0, description="arc length from the cable start [m]")


def _one_or_list(value: Any) -> Any:
    """Accept a single mapping where a list of holds is expected."""
    return [value] if isinstance(value, dict) else value


class RouteEntry(_Model):
    """One fixture of a cable's target route (SCENARIO.md, "Target routes and the planner").

    Attributes:
        fixture: the peg or clip the cable passes.
        side: for a peg, the side of the cable the peg stays on, seen along
            the route from the cable's start (required for a peg, not
            allowed for a clip).
        wind: for a peg, full turns of the cable around it (>= 0).
    """

    fixture: str = Field(min_length=1)
    side: Literal["left", "right"] | None = None
    wind: int = Field(0, ge=0, description="full turns around a peg")


class CableSpec(_Model):
    """One cable: its physics, where it starts, its routing and who holds it.

    Attributes:
        name: unique cable name.
        length: rest length [m].
        mass_per_length: linear density rho [kg/m].
        stiffness: axial spring constant of the whole cable [N/m].
        radius: cable radius [m].
        start: the anchor that holds the first end (``None``: a free end).
        via: fixtures the cable initially bears against, in order.
        held_by: one or two holds, by different arms.
        route: the target route, in order from the cable's start (empty:
            none; the planner turns routes into a task).
    """

    name: str = Field(min_length=1)
    length: float = Field(gt=0.0, description="cable length [m]")
    mass_per_length: float = Field(gt=0.0, description="mass per length [kg/m]")
    stiffness: float = Field(gt=0.0, description="axial stiffness of the whole cable [N/m]")
    radius: float = Field(gt=0.0, description="cable radius [m]")
    start: str | None = None
    via: list[str] = []
    held_by: Annotated[list[Hold], BeforeValidator(_one_or_list)] = Field(
        min_length=1, max_length=2, description="one hold or a list of two"
    )
    route: list[RouteEntry] = []


class TaskStep(_Model):
    """One primitive of the task, with its parameters.

    In a file a step is written flat, ``{primitive: D, arm: left, force: 3.0}``;
    on load the primitive becomes its canonical name and the rest ``params``.

    Attributes:
        primitive: canonical name, e.g. ``"single_arm_tension"``.
        letter: the paper's letter, e.g. ``"D"``.
        params: parameter values by name (numbers in SI units).
    """

    primitive: str
    letter: str
    params: dict[str, bool | float | str | list[float]] = {}

    @model_validator(mode="before")
    @classmethod
    def _from_file(cls, data: Any) -> Any:
        """Resolve the primitive and check its parameters against the catalogue."""
        if not isinstance(data, dict):
            return data
        if "primitive" not in data:
            raise located_error(
                f"missing (expected a primitive name or letter: {primitive_choices()})",
                ("primitive",),
            )
        key = data["primitive"]
        if not isinstance(key, str):
            raise located_error(
                f"got {key!r} (expected a primitive name or letter: {primitive_choices()})",
                ("primitive",),
            )
        try:
            spec = find_primitive(key)
        except InvalidArgumentError as exc:
            raise located_error(str(exc), ("primitive",)) from exc
        canonical = "params" in data or "letter" in data
        if canonical:
            extra = sorted(set(data) - {"primitive", "letter", "params"})
            if extra:
                raise located_error("unknown key (expected primitive, letter, params)", (extra[0],))
            letter = data.get("letter", spec.letter)
            if letter != spec.letter:
                raise located_error(
                    f"got {letter!r} (expected {spec.letter!r}, the letter of {spec.name})",
                    ("letter",),
                )
            values = data.get("params", {})
            if not isinstance(values, dict):
                raise located_error(
                    f"got {values!r} (expected a mapping of parameters)", ("params",)
                )
        else:
            values = {k: v for k, v in data.items() if k != "primitive"}
        try:
            params = spec.check_params(values)
        except ParameterError as exc:
            where = ("params", exc.parameter) if canonical else (exc.parameter,)
            raise located_error(str(exc), where) from exc
        return {"primitive": spec.name, "letter": spec.letter, "params": params}

    @property
    def spec(self) -> PrimitiveSpec:
        """The catalogue entry of this step's primitive."""
        return find_primitive(self.primitive)


# ------------------------------------------------------------------ faults
# Faults are injected by the simulator only (SCENARIO.md, "Faults"); the
# robot never reads them: handling them is the core's job.


class SpikeFault(_Model):
    """One sample of the measured force carries an added force.

    Attributes:
        type: ``"spike"``.
        at: simulated time from the start of the run [s]; the first sample at
            or after it is hit.
        force: force added to that sample [N], world frame.
    """

    type: Literal["spike"]
    at: float = Field(ge=0.0, description="time from the start of the run [s]")
    force: Vector3 = Field(description="force added to one sample [N]")


class NanFault(_Model):
    """One sample of NaN force and torque.

    Attributes:
        type: ``"nan"``.
        at: simulated time from the start of the run [s].
    """

    type: Literal["nan"]
    at: float = Field(ge=0.0, description="time from the start of the run [s]")


class FreezeFault(_Model):
    """The sensor repeats its last sample while time goes on.

    Attributes:
        type: ``"freeze"``.
        at: simulated time from the start of the run [s].
        duration: how long the sensor repeats itself [s].
    """

    type: Literal["freeze"]
    at: float = Field(ge=0.0, description="time from the start of the run [s]")
    duration: float = Field(gt=0.0, description="freeze duration [s]")


class BiasDriftFault(_Model):
    """The sensor's bias ramps linearly from 0 to ``force``, then stays.

    Attributes:
        type: ``"bias_drift"``.
        at: simulated time from the start of the run [s].
        duration: time of the ramp [s]; 0 is a step (a constant offset).
        force: the bias at the end of the ramp [N], world frame.
    """

    type: Literal["bias_drift"]
    at: float = Field(ge=0.0, description="time from the start of the run [s]")
    duration: float = Field(ge=0.0, description="ramp duration [s]")
    force: Vector3 = Field(description="final bias [N]")


class SlipFault(_Model):
    """A gripper's grip drops to near zero, so the cable can slide.

    Attributes:
        type: ``"slip"``.
        at: simulated time from the start of the run [s].
        duration: how long the grip stays lost [s].
        arm: the gripper that loses its grip (``None``: the sensing arm).
    """

    type: Literal["slip"]
    at: float = Field(ge=0.0, description="time from the start of the run [s]")
    duration: float = Field(gt=0.0, description="slip duration [s]")
    arm: Literal["left", "right"] | None = None


class RobotErrorFault(_Model):
    """The robot's ``act()`` fails (a lost packet), once or repeatedly.

    Attributes:
        type: ``"robot_error"``.
        at: simulated time from the start of the run [s].
        count: number of consecutive failing ``act()`` calls (default 1).
        duration: alternatively, every ``act()`` within this time fails [s].
    """

    type: Literal["robot_error"]
    at: float = Field(ge=0.0, description="time from the start of the run [s]")
    count: int | None = Field(None, ge=1, description="consecutive failed commands")
    duration: float | None = Field(None, gt=0.0, description="time of repeated failures [s]")

    @model_validator(mode="after")
    def _count_or_duration(self) -> RobotErrorFault:
        if self.count is not None and self.duration is not None:
            raise located_error(
                "give count or duration, not both (expected one way to repeat the error)",
                ("duration",),
            )
        return self


Fault = Annotated[
    SpikeFault | NanFault | FreezeFault | BiasDriftFault | SlipFault | RobotErrorFault,
    Field(discriminator="type"),
]
"""Any injected fault, told apart by its ``type`` key."""


class Scenario(_Model):
    """A whole scenario file: robot, board, cables and task.

    Attributes:
        version: format version, 1.
        name: free text.
        description: one line saying what the scenario shows (free text;
            ``tautwire scenarios`` lists it).
        seed: makes noise and randomisation repeatable.
        robot: robot settings.
        board: the fixtures.
        cables: the cables.
        task: primitives run in order (may be left out when cables carry routes).
        faults: faults the simulator injects (simulation only).
    """

    version: Literal[1]
    name: str
    description: str = ""
    seed: int = 0
    robot: RobotSettings
    board: Board
    cables: list[CableSpec]
    task: list[TaskStep] = []
    faults: list[Fault] = []

    @model_validator(mode="after")
    def _consistent(self) -> Scenario:
        """Check names, references and geometry; raise every issue found.

        Geometry is checked only once the references hold (a wrong name
        would make it meaningless).
        """
        issues = check_references(self) + check_routes(self)
        if not issues:
            issues = check_geometry(self)
        if issues:
            raise located_error(issues[0].message, issues[0].location, tuple(issues[1:]))
        return self

    def fixture(self, name: str) -> Anchor | Peg | Clip:
        """Return the fixture called ``name`` (see :meth:`Board.fixture`)."""
        return self.board.fixture(name)

    def cable(self, name: str) -> CableSpec:
        """Return the cable called ``name``.

        Raises:
            InvalidArgumentError: if there is none; the message lists the names.
        """
        for cable in self.cables:
            if cable.name == name:
                return cable
        names = ", ".join(c.name for c in self.cables) or "none"
        raise InvalidArgumentError(f"no cable named {name!r} (cables: {names})")
