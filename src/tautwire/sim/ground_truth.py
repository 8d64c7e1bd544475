"""The simulator's ground truth, for scoring only.

Experiments and the runner use :class:`GroundTruth` to score estimates; no
primitive or estimator may. It reads the world's private physics state.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.robot.arm import ARMS
from tautwire.sim.spec import AnchorSpec, ClipSpec, PegSpec
from tautwire.sim.world import SimWorld

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class FixtureContact:
    """A fixture that a cable touches, and its true contact point.

    Attributes:
        fixture: Fixture name.
        cable: Name of the cable touching it.
        point: The true contact [m], world frame: for an anchor or a clip
            where the cable leaves it, for a peg the point on the peg's axis
            at the cable's height.  # (3,)
        force: Magnitude [N] of the total contact force on the cable there
            (0 for an anchor, which holds the cable by a fixed vertex).
    """

    fixture: str
    cable: str
    point: FloatArray
    force: float


class GroundTruth:
    """Exact cable state and fixture contacts of a :class:`SimWorld`.

    Args:
        world: The world to read.
    """

    def __init__(self, world: SimWorld) -> None:
        self._world = world
        m = world._model
        self._geom_fixture: dict[int, str] = {}
        for f in world.spec.fixtures:
            if isinstance(f, PegSpec):
                names = [f.name]
            elif isinstance(f, ClipSpec):
                names = [f"{f.name}_base", f"{f.name}_wall_a", f"{f.name}_wall_b"]
                names += [f"{f.name}_jaw_a", f"{f.name}_jaw_b"]
            else:
                continue
            for n in names:
                self._geom_fixture[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, n)] = f.name
        self._flex_cable = {idx.flex_id: name for name, idx in world._cables.items()}

    @property
    def cable_names(self) -> tuple[str, ...]:
        """Names of the cables."""
        return tuple(self._world._cables)

    def _index(self, cable: str):  # type: ignore[no-untyped-def]
        try:
            return self._world._cables[cable]
        except KeyError:
            raise InvalidArgumentError(
                f"no cable named {cable!r} (cables: {list(self._world._cables)})"
            ) from None

    def polyline(self, cable: str) -> FloatArray:
        """Vertex positions [m] of ``cable``, world frame, shape (N + 1, 3)."""
        idx = self._index(cable)
        out: FloatArray = self._world._data.xpos[idx.body_ids].copy()
        return out

    def arc_lengths(self, cable: str) -> FloatArray:
        """Rest arc length [m] of each vertex from the cable's start, shape (N + 1,)."""
        self._index(cable)
        return self._world.scene.discretizations[cable].arc.copy()

    def rest_lengths(self, cable: str) -> FloatArray:
        """Rest length [m] of each segment, shape (N,)."""
        self._index(cable)
        return self._world.scene.discretizations[cable].rest_lengths.copy()

    def tensions(self, cable: str) -> FloatArray:
        """Elastic tension [N] of each segment, k_e max(0, length - rest), shape (N,)."""
        idx = self._index(cable)
        m, d = self._world._model, self._world._data
        length = d.ten_length[idx.tendon_ids]
        rest = m.tendon_lengthspring[idx.tendon_ids, 1]
        k = m.tendon_stiffness[idx.tendon_ids]
        tension: FloatArray = k * np.maximum(0.0, length - rest)
        return tension

    def stiffness(self, cable: str) -> float:
        """True axial spring constant k [N/m] of the whole cable."""
        return float(self._index(cable).spec.stiffness)

    def length(self, cable: str) -> float:
        """Current length [m] of ``cable`` along its polyline."""
        p = self.polyline(cable)
        return float(np.sum(np.linalg.norm(np.diff(p, axis=0), axis=1)))

    def contacts(self) -> tuple[FixtureContact, ...]:
        """Every fixture in contact with a cable, with its true contact point."""
        world = self._world
        d = world._data
        per: dict[tuple[str, str], list[tuple[FloatArray, float]]] = {}
        force6 = np.zeros(6)
        for i in range(d.ncon):
            c = d.contact[i]
            geom = int(c.geom[0]) if c.geom[0] >= 0 else int(c.geom[1])
            flex = int(c.flex[1]) if c.flex[1] >= 0 else int(c.flex[0])
            if geom not in self._geom_fixture or flex not in self._flex_cable:
                continue
            mujoco.mj_contactForce(world._model, d, i, force6)
            key = (self._geom_fixture[geom], self._flex_cable[flex])
            per.setdefault(key, []).append((c.pos.copy(), float(np.linalg.norm(force6[:3]))))
        out: list[FixtureContact] = []
        for spec in world.spec.cables:
            if spec.start is not None:
                anchor = world.spec.fixture(spec.start)
                out.append(FixtureContact(anchor.name, spec.name, anchor.position.copy(), 0.0))
        for (name, cable), hits in per.items():
            fixture = world.spec.fixture(name)
            total = sum(f for _, f in hits)
            if isinstance(fixture, PegSpec):
                z = float(np.mean([p[2] for p, _ in hits]))
                z = min(z, fixture.position[2] + fixture.height)
                point = np.array([fixture.position[0], fixture.position[1], z])
            elif isinstance(fixture, ClipSpec):
                point = self._clip_exit(fixture, cable)
            else:  # pragma: no cover - anchors have no contact geoms
                assert isinstance(fixture, AnchorSpec)
                point = fixture.position.copy()
            out.append(FixtureContact(name, cable, point, total))
        return tuple(out)

    def in_contact(self) -> tuple[str, ...]:
        """Names of the fixtures in contact with a cable."""
        return tuple(dict.fromkeys(c.fixture for c in self.contacts()))

    def contact(self, fixture: str) -> FixtureContact | None:
        """The contact at ``fixture``, or None if no cable touches it."""
        for c in self.contacts():
            if c.fixture == fixture:
                return c
        return None

    def _clip_exit(self, clip: ClipSpec, cable: str) -> FloatArray:
        """End of the clip's slot through which ``cable`` runs on towards its holder."""
        world = self._world
        pts = self.polyline(cable)
        i_c = int(np.argmin(np.linalg.norm(pts - clip.position, axis=1)))
        towards = 1
        for arm in ARMS:
            held = world.held(arm)
            if held is not None and held[0] == cable:
                towards = 1 if held[1] >= i_c else -1
                break
        lo, hi = max(i_c - 1, 0), min(i_c + 1, len(pts) - 1)
        tangent = (pts[hi] - pts[lo]) * towards
        sign = 1.0 if float(tangent @ clip.direction) >= 0.0 else -1.0
        exit_point: FloatArray = (
            clip.position + sign * 0.5 * world.options.clip_length * clip.direction
        )
        return exit_point
