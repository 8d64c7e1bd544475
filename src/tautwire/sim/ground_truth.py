"""The simulator's ground truth, for scoring only.

Experiments and the runner use :class:`GroundTruth` to score estimates; no
primitive or estimator may. It reads the world's private physics state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.robot.arm import ARMS, Arm
from tautwire.sim.spec import AnchorSpec, ClipSpec, PegSpec
from tautwire.sim.world import SimWorld

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]

#: A cable vertex this close [m] to a fixture's surface (beyond the cable's
#: radius) that the cable is in contact with counts as touching it: MuJoCo's
#: contact margin and the polygonal cable keep the vertices a few mm off.
NEAR = 0.005
#: A cable this close [m] to a peg's surface (beyond the cable's radius)
#: lies against it though no contact acts at the instant (:meth:`GroundTruth.against_peg`).
RESTING = 0.001
#: Share of the largest contact force on a peg that a contact needs to count
#: in the band of heights over which the peg holds the cable (:meth:`GroundTruth.peg_band`).
BAND_SHARE = 0.1
#: Segments with a vertex within this rest length [m] of a held vertex run
#: through the fingers (pads 20 mm long): their tendons also carry the pads'
#: contact forces (up to several times the cable's tension where the cable
#: bends round a fingertip), so the span's tension is taken outside them.
GRIP_ZONE = 0.015


@dataclass(frozen=True)
class FixtureContact:
    """A fixture that a cable touches, and its true contact point.

    Attributes:
        fixture: Fixture name.
        cable: Name of the cable touching it.
        point: The true contact [m], world frame: for an anchor or a clip
            where the cable leaves it, for a peg the point on the peg's axis
            at the cable's height (its contact forces' centre of pressure).  # (3,)
        force: Magnitude [N] of the total contact force on the cable there
            (0 for an anchor, which holds the cable by a fixed vertex).
    """

    fixture: str
    cable: str
    point: FloatArray
    force: float


@dataclass(frozen=True)
class TautSpan:
    """The straight part of a cable between a gripper and the last fixture before it.

    Attributes:
        cable: The cable's name.
        arm: The gripper that holds it.
        fixture: The fixture the span leaves from (the nearest along the
            cable towards its start that the cable truly bears on), or None
            when the cable touches none before the gripper (a free end).
        contact: The fixture's true contact point [m] as
            :class:`FixtureContact` defines it (None without a fixture).  # (3,)
        leave: Where the span leaves the fixture [m]: the anchor itself, or
            the point of the last segment touching a peg (nearest its axis)
            or a clip (nearest its seat).  # (3,)
        middle: The cable vertex half way along the span [m].  # (3,)
        held: The held vertex [m] (at the tool centre point).  # (3,)
        tension: Mean elastic tension [N] of the span's free segments (those
            outside the gripper's fingers, see :data:`GRIP_ZONE`).
        taut: Whether every free segment of the span is stretched (tension > 0).
        leave_vertex: Index of the vertex at the span's fixture end: the
            anchor's, or the far end (from the gripper) of the segment that
            touches a peg or a clip.
        held_vertex: Index of the ``held`` vertex.
        rest_length: Rest length [m] of the span, from ``leave`` to the
            held vertex along the cable.
        segments: The free segments' indices, first and past the last.
        entry: The free span's vertex nearest the gripper, where the cable
            enters the fingers' zone (:data:`GRIP_ZONE`) [m]: with ``leave``
            the ends of the straight, free part of the span.  # (3,)
        leave_arc: Rest arc length [m] of ``leave`` from the cable's start.
    """

    cable: str
    arm: Arm
    fixture: str | None
    contact: FloatArray | None
    leave: FloatArray
    middle: FloatArray
    held: FloatArray
    tension: float
    taut: bool
    leave_vertex: int
    held_vertex: int
    rest_length: float
    segments: tuple[int, int]
    entry: FloatArray
    leave_arc: float


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
        self._springs: dict[str, tuple[IntArray, FloatArray, FloatArray]] = {}

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
        springs = self._springs.get(cable)
        if springs is None:  # the tendons' rest lengths and stiffnesses are constants
            idx = self._index(cable)
            m = self._world._model
            springs = (
                idx.tendon_ids,
                m.tendon_lengthspring[idx.tendon_ids, 1].copy(),
                m.tendon_stiffness[idx.tendon_ids].copy(),
            )
            self._springs[cable] = springs
        ids, rest, k = springs
        tension: FloatArray = k * np.maximum(0.0, self._world._data.ten_length[ids] - rest)
        return tension

    def stiffness(self, cable: str) -> float:
        """True axial spring constant k [N/m] of the whole cable."""
        return float(self._index(cable).spec.stiffness)

    def cable_radius(self, cable: str) -> float:
        """Radius [m] of ``cable``."""
        return float(self._index(cable).spec.radius)

    def mass_per_length(self, cable: str) -> float:
        """Mass per length [kg/m] of ``cable``."""
        return float(self._index(cable).spec.mass_per_length)

    def starts_anchored(self, cable: str) -> bool:
        """Whether ``cable``'s first vertex is fixed to an anchor."""
        return self._index(cable).spec.start is not None

    def length(self, cable: str) -> float:
        """Current length [m] of ``cable`` along its polyline."""
        p = self.polyline(cable)
        return float(np.sum(np.linalg.norm(np.diff(p, axis=0), axis=1)))

    @property
    def time(self) -> float:
        """The simulator's time [s] since the run started (it goes on while a sensor freezes)."""
        return self._world.time

    @property
    def max_force(self) -> float:
        """Largest force [N] a gripper truly transmitted since the world's last reset.

        The noise-free force of every control period (:attr:`SimWorld.max_force`).
        """
        return self._world.max_force

    def gripper_position(self, arm: Arm) -> FloatArray:
        """The true tool centre point [m] of ``arm``'s gripper."""
        return self._world._grippers[arm].position.copy()

    def held(self, arm: Arm) -> tuple[str, int] | None:
        """(cable, vertex) that ``arm`` truly holds, or None."""
        return self._world.held(arm)

    def fixture_type(self, name: str) -> str:
        """``"anchor"``, ``"peg"`` or ``"clip"``: the type of fixture ``name``."""
        fixture = self._fixture(name)
        if isinstance(fixture, PegSpec):
            return "peg"
        if isinstance(fixture, ClipSpec):
            return "clip"
        return "anchor"

    def peg_radius(self, name: str) -> float:
        """Radius [m] of peg ``name``."""
        fixture = self._fixture(name)
        if not isinstance(fixture, PegSpec):
            raise InvalidArgumentError(f"fixture {name!r} is not a peg")
        return float(fixture.radius)

    def seat(self, clip: str, cable: str) -> FloatArray:
        """The point [m] of ``cable`` that sits in clip ``clip``: the nearest to its seat."""
        spec = self._fixture(clip)
        if not isinstance(spec, ClipSpec):
            raise InvalidArgumentError(f"fixture {clip!r} is not a clip")
        return closest_on_polyline(self.polyline(cable), spec.position)

    def fixture_names(self) -> tuple[str, ...]:
        """Names of every fixture of the board."""
        return tuple(f.name for f in self._world.spec.fixtures)

    def _fixture(self, name: str) -> AnchorSpec | PegSpec | ClipSpec:
        for f in self._world.spec.fixtures:
            if f.name == name:
                return f
        raise InvalidArgumentError(
            f"no fixture named {name!r} (fixtures: {list(self.fixture_names())})"
        )

    def against_peg(self, peg: str, cable: str) -> FloatArray | None:
        """Where ``cable`` lies against peg ``peg`` with no contact force, or None.

        The point [m] on the peg's axis at the height of the cable's segment
        point nearest the axis (horizontally), when that point lies within
        the peg's radius plus the cable's plus :data:`RESTING` of the axis
        and below the peg's top: a cable that lies against the peg, resting
        or falling, touches it though MuJoCo reports no contact at this
        instant (random board 1808415002: W1 released after its last clip
        fell down the pegs it was wound round, 0.2 mm off F1's surface at
        the step's end, and touched it again a period later).
        """
        spec = self._fixture(peg)
        if not isinstance(spec, PegSpec):
            raise InvalidArgumentError(f"fixture {peg!r} is not a peg")
        pts = self.polyline(cable)
        p, q = pts[:-1], pts[1:]
        t = _nearest_parameters(p[:, :2], q[:, :2], spec.position[:2])
        point = p + t[:, None] * (q - p)
        d = np.hypot(point[:, 0] - spec.position[0], point[:, 1] - spec.position[1])
        top = spec.position[2] + spec.height
        radius = self.cable_radius(cable)
        hits = np.flatnonzero((d <= spec.radius + radius + RESTING) & (point[:, 2] <= top))
        if not len(hits):
            return None
        k = int(hits[np.argmin(d[hits])])
        return np.array([spec.position[0], spec.position[1], float(point[k, 2])])

    def clipped(self, clip: str, cable: str) -> bool:
        """Whether ``cable`` truly sits in the jaws of clip ``clip``.

        The cable's centre line, where it passes nearest the seat, lies within
        the slot (along it within half the clip's length, across it within
        the channel's half width), below the axes of the closed jaws and
        above the channel's floor: it has passed the jaws' narrowest gap,
        which a cable resting on the jaws has not, and not gone through the
        floor (a cable snapping in can, in a time step; on the shipped
        harness's W2 one lay 35 mm under C5's seat, read as clipped).
        """
        spec = self._fixture(clip)
        if not isinstance(spec, ClipSpec):
            raise InvalidArgumentError(f"fixture {clip!r} is not a clip")
        design = self._world.scene.clips[clip]
        pts = self.polyline(cable)
        q = closest_on_polyline(pts, spec.position) - spec.position
        along = float(q @ spec.direction)
        across = float(np.hypot(q[0], q[1]) ** 2 - along**2)
        return (
            abs(along) <= 0.5 * self._world.options.clip_length
            and math.sqrt(max(across, 0.0)) <= design.wall_gap
            and -design.cable_radius <= float(q[2]) < design.jaw_height
        )

    def span(self, cable: str, arm: Arm) -> TautSpan | None:
        """The span of ``cable`` from the last fixture before ``arm``'s gripper to it.

        Scans the cable's segments from the held vertex towards its start
        for the first one at a fixture that the cable is in contact with
        (MuJoCo contacts): a peg (the segment passes within the peg's radius
        plus the cable's radius plus :data:`NEAR` of its axis, below its top)
        or a clip (the segment passes its seat within the slot); else the
        anchored start. When the other gripper holds the same cable the span
        runs towards it instead (parallel primitives), and ends there if no
        fixture comes first (``fixture`` None, the segments inside either
        gripper's fingers left out). A stretched soft cable's vertices may
        lie centimetres apart, so segments, not vertices, are tested. None
        when ``arm`` does not hold ``cable``.
        """
        held = self._world.held(arm)
        if held is None or held[0] != cable:
            return None
        idx = self._index(cable)
        pts = self.polyline(cable)
        arc = self._world.scene.discretizations[cable].arc
        h = held[1]
        step = -1 if h > 0 else 1
        other = self._world.held("right" if arm == "left" else "left")
        partner = other[1] if other is not None and other[0] == cable else None
        if partner is not None and partner != h:
            step = 1 if partner > h else -1
        touched = [
            self._world.spec.fixture(name) for name, c in self._contact_pairs() if c == cable
        ]
        fixture: str | None = None
        leave, leave_arc, i = pts[0], 0.0, 0
        hit = self._first_touching(pts, h, step, idx.spec.radius, touched)
        if hit is not None and partner is not None and (hit[1] - partner) * step >= 0:
            hit = None  # beyond the other gripper
        if hit is not None:  # segment (near, far = near + step) touches ``fixture`` at t
            fixture, near, t = hit
            far = near + step
            leave = pts[near] + t * (pts[far] - pts[near])
            leave_arc = float(arc[near] + t * (arc[far] - arc[near]))
            i = far
        if fixture is None:
            i = 0 if step < 0 else len(pts) - 1
            if partner is not None and partner != h:
                i = partner
            leave, leave_arc = pts[i], float(arc[i])
            if step < 0 and idx.spec.start is not None and partner is None:
                fixture = idx.spec.start
        segments = _free_segments(arc, i, h)
        if partner is not None and i == partner:
            segments = _free_segments(arc, h, partner)  # out of the partner's fingers too
            lo, hi = segments
            both = _free_segments(arc, i, h)
            segments = (max(lo, both[0]), min(hi, both[1]))
            if segments[1] <= segments[0]:
                segments = both
        lo, hi = segments
        if (
            i != h
            and fixture is not None
            and i != (0 if step < 0 else len(pts) - 1)
            and hi - lo > 1
        ):
            # the segment at the fixture may be partly wrapped: not in the
            # free span, unless it is all there is of it (a gripper 45 mm
            # past a clip's exit after C: two segments, one in the fingers;
            # dropping the other too read the taut span as 0 N, slack)
            segments = (lo + 1, hi) if i < h else (lo, hi - 1)
        tension = self._segment_tensions(cable, segments)
        contact = None
        if fixture is not None:
            found = self.contact(fixture)
            contact = None if found is None else found.point
        return TautSpan(
            cable,
            arm,
            fixture,
            contact,
            leave.copy(),
            pts[(i + h) // 2].copy(),
            pts[h].copy(),
            float(np.mean(tension)),
            bool(np.all(tension > 0.0)),
            i,
            h,
            float(abs(arc[h] - leave_arc)),
            segments,
            pts[segments[1] if i < h else segments[0]].copy(),
            leave_arc,
        )

    def span_tension(self, span: TautSpan) -> tuple[float, bool]:
        """Mean elastic tension [N] of ``span``'s segments now, and whether all are stretched.

        Cheaper than :meth:`span` when the span's vertices are known.
        """
        tension = self._segment_tensions(span.cable, span.segments)
        return float(tension.sum()) / len(tension), bool((tension > 0.0).all())

    def _segment_tensions(self, cable: str, segments: tuple[int, int]) -> FloatArray:
        lo, hi = segments
        out: FloatArray = self.tensions(cable)[lo:hi] if hi > lo else np.zeros(1)
        return out

    def _contact_pairs(self) -> set[tuple[str, str]]:
        """(fixture, cable) of every MuJoCo contact between a cable and a fixture."""
        d = self._world._data
        pairs: set[tuple[str, str]] = set()
        for i in range(d.ncon):
            c = d.contact[i]
            geom = int(c.geom[0]) if c.geom[0] >= 0 else int(c.geom[1])
            flex = int(c.flex[1]) if c.flex[1] >= 0 else int(c.flex[0])
            if geom in self._geom_fixture and flex in self._flex_cable:
                pairs.add((self._geom_fixture[geom], self._flex_cable[flex]))
        return pairs

    def _first_touching(
        self,
        pts: FloatArray,
        held: int,
        step: int,
        cable_radius: float,
        fixtures: list[AnchorSpec | PegSpec | ClipSpec],
    ) -> tuple[str, int, float] | None:
        """The first segment from the held vertex outwards that touches one of ``fixtures``.

        A segment touches a peg where its point nearest the axis
        (horizontally) lies within the peg's radius plus the cable's plus
        :data:`NEAR` of it and below the peg's top; a clip where its point
        nearest the seat lies within the slot. Returns the fixture's name,
        the segment's vertex nearer the held one and the segment parameter t
        in [0, 1] of that point, or None.
        """
        if not fixtures:
            return None
        order = np.arange(held, 0, -1) if step < 0 else np.arange(held, len(pts) - 1)
        near = order
        p, q = pts[near], pts[near + step]  # (S, 3) each
        best: tuple[int, str, float] | None = None
        for f in fixtures:
            if isinstance(f, PegSpec):
                t = _nearest_parameters(p[:, :2], q[:, :2], f.position[:2])
                point = p + t[:, None] * (q - p)
                d = np.hypot(point[:, 0] - f.position[0], point[:, 1] - f.position[1])
                top = f.position[2] + f.height
                hits = (d <= f.radius + cable_radius + NEAR) & (point[:, 2] <= top + cable_radius)
            elif isinstance(f, ClipSpec):
                t = _nearest_parameters(p, q, f.position)
                r = p + t[:, None] * (q - p) - f.position
                along = r @ f.direction
                across = np.sqrt(np.maximum(r[:, 0] ** 2 + r[:, 1] ** 2 - along**2, 0.0))
                design = self._world.scene.clips[f.name]
                # on the jaws at the highest: a cable held over the clip, as
                # after a slide that ends above it with the tail draped in
                # its jaws (random board 1695658280), does not bear on it
                top = design.jaw_height + design.jaw_radius + cable_radius + NEAR
                hits = (
                    (np.abs(along) <= 0.5 * self._world.options.clip_length)
                    & (across <= design.wall_gap + design.jaw_radius + NEAR)
                    & (r[:, 2] <= top)
                )
            else:
                continue
            found = np.flatnonzero(hits)
            if len(found) and (best is None or int(found[0]) < best[0]):
                best = (int(found[0]), f.name, float(t[found[0]]))
        if best is None:
            return None
        k, name, t_hit = best
        return name, int(near[k]), t_hit

    def _hits(self) -> dict[tuple[str, str], list[tuple[FloatArray, float]]]:
        """Every fixture-cable contact: (fixture, cable) -> [(position [m], force [N])]."""
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
        return per

    def peg_band(self, peg: str, cable: str) -> tuple[float, float] | None:
        """The heights [m] over which peg ``peg`` holds ``cable``: (lowest, highest), or None.

        The heights of the contacts that carry at least :data:`BAND_SHARE`
        of the largest one's force (a tail dragged against the peg's foot
        bears next to nothing), at most the peg's top. A cable wound round
        a peg climbs it: random board 1652323633's W1, wound 670 deg round
        F2, bore on it from 89 to 104 mm and left it towards the gripper at
        107 mm, 11 mm above the centre of pressure.
        """
        spec = self._fixture(peg)
        if not isinstance(spec, PegSpec):
            raise InvalidArgumentError(f"fixture {peg!r} is not a peg")
        hits = self._hits().get((peg, cable))
        if not hits:
            return None
        largest = max(f for _, f in hits)
        heights = [float(p[2]) for p, f in hits if f >= BAND_SHARE * largest]
        top = spec.position[2] + spec.height
        return min(min(heights), top), min(max(heights), top)

    def contacts(self) -> tuple[FixtureContact, ...]:
        """Every fixture in contact with a cable, with its true contact point."""
        world = self._world
        per = self._hits()
        out: list[FixtureContact] = []
        for spec in world.spec.cables:
            if spec.start is not None:
                anchor = world.spec.fixture(spec.start)
                out.append(FixtureContact(anchor.name, spec.name, anchor.position.copy(), 0.0))
        for (name, cable), hits in per.items():
            fixture = world.spec.fixture(name)
            total = sum(f for _, f in hits)
            if isinstance(fixture, PegSpec):
                # the centre of pressure along the axis: where the peg holds the
                # cable (a free tail dragged against its foot bears next to
                # nothing; unweighted, on the shipped harness's W2 it put P2 23 mm low)
                heights = np.array([p[2] for p, _ in hits])
                weights = np.array([f for _, f in hits])
                z = float(np.average(heights, weights=weights) if total > 0.0 else np.mean(heights))
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


def closest_on_polyline(polyline: FloatArray, p: FloatArray) -> FloatArray:
    """The point of ``polyline`` (N, 3) nearest ``p`` [m]."""
    a, b = polyline[:-1], polyline[1:]
    ab = b - a
    t = np.clip(
        np.einsum("ij,ij->i", p - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-18), 0, 1
    )
    q = a + t[:, None] * ab
    out: FloatArray = q[int(np.argmin(np.linalg.norm(q - p, axis=1)))]
    return out


def _free_segments(arc: FloatArray, leave: int, held: int) -> tuple[int, int]:
    """Segments between vertices ``leave`` and ``held`` outside the fingers (first, past last).

    Keeps at least the segment furthest from the held vertex.
    """
    lo, hi = min(leave, held), max(leave, held)
    if hi == lo:
        return lo, lo
    inside = np.abs(arc - arc[held]) < GRIP_ZONE
    free = [j for j in range(lo, hi) if not (inside[j] or inside[j + 1])]
    if not free:
        far = lo if held == hi else hi - 1
        return far, far + 1
    return free[0], free[-1] + 1


def _nearest_parameters(p: FloatArray, q: FloatArray, c: FloatArray) -> FloatArray:
    """Per segment p_i -> q_i (rows), the parameter t in [0, 1] of its point nearest ``c``."""
    d = q - p
    dd = np.einsum("ij,ij->i", d, d)
    t = np.einsum("ij,ij->i", c - p, d) / np.maximum(dd, 1e-18)
    out: FloatArray = np.clip(t, 0.0, 1.0)
    return out
