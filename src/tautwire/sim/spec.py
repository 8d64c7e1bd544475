"""The world description that the scene builder consumes.

These frozen dataclasses are the simulator's own, independent of the scenario
file format: :func:`tautwire.sim.build.build_world` converts a
:class:`tautwire.scenario.Scenario` into a :class:`WorldSpec`, and tests build
worlds from a :class:`WorldSpec` directly.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import IDENTITY, as_quaternion
from tautwire.robot.arm import ARMS, Arm

FloatArray = NDArray[np.float64]


def _vector3(value: ArrayLike, what: str) -> FloatArray:
    arr = np.asarray(value, dtype=float).reshape(-1)
    if arr.shape != (3,) or not np.all(np.isfinite(arr)):
        raise InvalidArgumentError(f"{what} must be 3 finite numbers [m], got {value!r}")
    return arr


def _positive(value: float, what: str) -> float:
    if not np.isfinite(value) or value <= 0.0:
        raise InvalidArgumentError(f"{what} must be finite and > 0, got {value}")
    return float(value)


@dataclass(frozen=True)
class AnchorSpec:
    """A point where a cable end is fixed.

    Attributes:
        name: Fixture name.
        position: Anchor point [m], world frame.  # (3,)
    """

    name: str
    position: FloatArray

    def __post_init__(self) -> None:
        object.__setattr__(
            self, "position", _vector3(self.position, f"anchor {self.name} position")
        )


@dataclass(frozen=True)
class PegSpec:
    """A vertical post from ``position`` (base centre) up by ``height``.

    Attributes:
        name: Fixture name.
        position: Base centre [m], world frame.  # (3,)
        radius: Post radius [m].
        height: Post height [m].
    """

    name: str
    position: FloatArray
    radius: float
    height: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "position", _vector3(self.position, f"peg {self.name} position"))
        object.__setattr__(self, "radius", _positive(self.radius, f"peg {self.name} radius"))
        object.__setattr__(self, "height", _positive(self.height, f"peg {self.name} height"))


@dataclass(frozen=True)
class ClipSpec:
    """A snap-in clip whose slot runs along ``yaw`` and opens upwards.

    Attributes:
        name: Fixture name.
        position: Where a clipped cable's centre line sits [m].  # (3,)
        yaw: Slot direction [rad] about the world z-axis.
        push_force: Force [N] needed to push the cable in.
    """

    name: str
    position: FloatArray
    yaw: float
    push_force: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "position", _vector3(self.position, f"clip {self.name} position"))
        if not np.isfinite(self.yaw):
            raise InvalidArgumentError(f"clip {self.name} yaw must be finite, got {self.yaw}")
        object.__setattr__(
            self, "push_force", _positive(self.push_force, f"clip {self.name} push_force")
        )

    @property
    def direction(self) -> FloatArray:
        """Unit vector along the slot, world frame (shape (3,))."""
        return np.array([np.cos(self.yaw), np.sin(self.yaw), 0.0])


FixtureSpec = AnchorSpec | PegSpec | ClipSpec


@dataclass(frozen=True)
class HoldSpec:
    """A gripper holding a cable at an arc length.

    Attributes:
        arm: Which gripper.
        at: Arc length [m] from the cable's start.
    """

    arm: Arm
    at: float

    def __post_init__(self) -> None:
        if self.arm not in ARMS:
            raise InvalidArgumentError(f"hold arm must be 'left' or 'right', got {self.arm!r}")
        if not np.isfinite(self.at) or self.at < 0.0:
            raise InvalidArgumentError(f"hold arc length must be finite and >= 0 m, got {self.at}")


@dataclass(frozen=True)
class CableSpec:
    """An elastic cable.

    Attributes:
        name: Cable name.
        length: Rest length [m].
        mass_per_length: rho [kg/m].
        stiffness: Axial spring constant of the whole cable [N/m].
        radius: Cable radius [m].
        start: Name of the anchor holding its first end, None for a free end.
        via: Fixtures it initially bears against, in order.
        holds: Grippers holding it, in order of arc length.
    """

    name: str
    length: float
    mass_per_length: float
    stiffness: float
    radius: float
    start: str | None = None
    via: tuple[str, ...] = ()
    holds: tuple[HoldSpec, ...] = ()

    def __post_init__(self) -> None:
        for attr in ("length", "mass_per_length", "stiffness", "radius"):
            object.__setattr__(
                self, attr, _positive(getattr(self, attr), f"cable {self.name} {attr}")
            )
        object.__setattr__(self, "via", tuple(self.via))
        holds = tuple(sorted(self.holds, key=lambda h: h.at))
        for h in holds:
            if h.at > self.length + 1e-12:
                raise InvalidArgumentError(
                    f"cable {self.name} is held at {h.at} m, beyond its length {self.length} m"
                )
        arms = [h.arm for h in holds]
        if len(set(arms)) != len(arms):
            raise InvalidArgumentError(f"cable {self.name} is held twice by the same arm")
        object.__setattr__(self, "holds", holds)


@dataclass(frozen=True)
class GripperSpec:
    """Start pose of a gripper's tool centre point.

    Attributes:
        position: [m], world frame.  # (3,)
        orientation: Unit quaternion [w, x, y, z]; the tool x-axis runs along
            the held cable, the fingers close along the tool y-axis.  # (4,)
    """

    position: FloatArray
    orientation: FloatArray = field(default_factory=lambda: IDENTITY.copy())

    def __post_init__(self) -> None:
        object.__setattr__(self, "position", _vector3(self.position, "gripper position"))
        object.__setattr__(self, "orientation", as_quaternion(self.orientation))


@dataclass(frozen=True)
class WorldSpec:
    """Everything the scene builder needs.

    Attributes:
        fixtures: Anchors, pegs and clips on the board.
        cables: The cables.
        left: Start pose of the left gripper.
        right: Start pose of the right gripper.
        control_period: Period [s] of one robot command.
        force_limit: Largest force [N] a run may see; sets the wave-speed guard.
        sensor_arms: Wrists carrying a force-torque sensor.
        noise_force: Sensor force noise [N], standard deviation per axis.
        noise_torque: Sensor torque noise [N m], standard deviation per axis.
        seed: Seed of the sensor noise.
        start_at_rest: The world is the start of a run that tares its
            sensors with the robot at rest (a scenario's world): no cable may
            start stretched beyond its weight (:func:`tautwire.sim.route.rest_tension_limit`).
            Off, a cable may start stretched up to the force limit.
    """

    fixtures: tuple[FixtureSpec, ...]
    cables: tuple[CableSpec, ...]
    left: GripperSpec
    right: GripperSpec
    control_period: float = 0.004
    force_limit: float = 15.0
    sensor_arms: tuple[Arm, ...] = ("left",)
    noise_force: float = 0.0
    noise_torque: float = 0.0
    seed: int = 0
    start_at_rest: bool = False

    def __post_init__(self) -> None:
        object.__setattr__(self, "fixtures", tuple(self.fixtures))
        object.__setattr__(self, "cables", tuple(self.cables))
        _positive(self.control_period, "control_period")
        _positive(self.force_limit, "force_limit")
        for what in ("noise_force", "noise_torque"):
            v = getattr(self, what)
            if not np.isfinite(v) or v < 0.0:
                raise InvalidArgumentError(f"{what} must be finite and >= 0, got {v}")
        if not self.sensor_arms or any(a not in ARMS for a in self.sensor_arms):
            raise InvalidArgumentError(
                f"sensor_arms must name 'left' and/or 'right', got {self.sensor_arms!r}"
            )
        names = [f.name for f in self.fixtures] + [c.name for c in self.cables]
        if len(set(names)) != len(names):
            raise InvalidArgumentError(f"fixture and cable names must be unique, got {names}")
        fixtures = {f.name: f for f in self.fixtures}
        held: set[str] = set()
        for cable in self.cables:
            if cable.start is not None and not isinstance(fixtures.get(cable.start), AnchorSpec):
                raise InvalidArgumentError(
                    f"cable {cable.name} starts at {cable.start!r}, which is not an anchor"
                    f" (anchors: {[f.name for f in self.fixtures if isinstance(f, AnchorSpec)]})"
                )
            for v in cable.via:
                if v not in fixtures:
                    raise InvalidArgumentError(
                        f"cable {cable.name} is routed via {v!r}, which is not a fixture"
                        f" (fixtures: {sorted(fixtures)})"
                    )
            for h in cable.holds:
                if h.arm in held:
                    raise InvalidArgumentError(f"the {h.arm} gripper holds two cables")
                held.add(h.arm)

    def fixture(self, name: str) -> FixtureSpec:
        """Return the fixture called ``name``.

        Raises:
            InvalidArgumentError: if there is none.
        """
        for f in self.fixtures:
            if f.name == name:
                return f
        raise InvalidArgumentError(f"no fixture named {name!r}")

    def gripper(self, arm: Arm) -> GripperSpec:
        """Start pose of the gripper on ``arm``."""
        return self.left if arm == "left" else self.right
