"""The cable's initial shape: a taut route through its fixtures.

The route runs from the start anchor through the ``via`` fixtures to the
held points. It wraps each peg on the side that a taut route bends around
(tangent lines and an arc at radius peg radius + cable radius), and passes a
clip along its slot at the seat. The vertices are spread along the route by
arc length between the points whose arc length is known (anchor 0, held
points); a route shorter than the cable leaves slack that the settle phase
lets sag, a longer one stretches the cable.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import SimulationError
from tautwire.model import GRAVITY
from tautwire.model.quaternion import rotate
from tautwire.sim.discretization import CableDiscretization
from tautwire.sim.spec import CableSpec, ClipSpec, HoldSpec, PegSpec, WorldSpec

FloatArray = NDArray[np.float64]

_ARC_STEP = np.deg2rad(10.0)


def _horizontal(v: FloatArray) -> FloatArray:
    return np.array([v[0], v[1], 0.0])


def _unit(v: FloatArray) -> FloatArray:
    n = float(np.linalg.norm(v))
    return v / n if n > 1e-12 else np.zeros_like(v)


def _tangent_point(
    point: FloatArray, centre: FloatArray, radius: float, side: FloatArray
) -> FloatArray:
    """Horizontal tangent point on the circle (centre, radius) seen from ``point``."""
    rel = _horizontal(point - centre)
    dist = float(np.linalg.norm(rel))
    if dist <= radius * (1.0 + 1e-9):
        return centre + radius * _unit(side)
    beta = np.arccos(radius / dist)
    u = rel / dist
    best = centre + radius * _unit(side)
    best_dot = -np.inf
    for sign in (1.0, -1.0):
        c, s = np.cos(sign * beta), np.sin(sign * beta)
        cand = np.array([c * u[0] - s * u[1], s * u[0] + c * u[1], 0.0])
        d = float(cand @ side)
        if d > best_dot:
            best, best_dot = centre + radius * cand, d
    return best


def _peg_wrap(
    peg: PegSpec, before: FloatArray | None, after: FloatArray | None, cable_radius: float
) -> list[FloatArray]:
    """Points of a taut route wrapping ``peg`` between its neighbours."""
    rho = peg.radius + cable_radius + 1e-4
    axis = peg.position
    ua = _unit(_horizontal(before - axis)) if before is not None else np.zeros(3)
    ub = _unit(_horizontal(after - axis)) if after is not None else np.zeros(3)
    inner = ua + ub
    if float(np.linalg.norm(inner)) < 1e-9:  # straight through: pick the left side
        ref = ub if after is not None else -ua
        inner = np.array([ref[1], -ref[0], 0.0])
        if float(np.linalg.norm(inner)) < 1e-9:
            inner = np.array([0.0, -1.0, 0.0])
    side = -_unit(inner)
    # height: interpolate the neighbours, keep on the post
    zs = [p[2] for p in (before, after) if p is not None]
    z = float(np.mean(zs)) if zs else axis[2] + 0.5 * peg.height
    lo, hi = axis[2] + cable_radius + 1e-3, axis[2] + peg.height - cable_radius - 1e-3
    z = float(np.clip(z, lo, hi)) if lo < hi else axis[2] + 0.5 * peg.height
    centre = np.array([axis[0], axis[1], z])
    t1 = _tangent_point(before, centre, rho, side) if before is not None else centre + rho * side
    t2 = _tangent_point(after, centre, rho, side) if after is not None else centre + rho * side
    a1 = np.arctan2(t1[1] - centre[1], t1[0] - centre[0])
    a2 = np.arctan2(t2[1] - centre[1], t2[0] - centre[0])
    ao = np.arctan2(side[1], side[0])
    # go from a1 to a2 through ao
    d12 = (a2 - a1) % (2 * np.pi)
    d1o = (ao - a1) % (2 * np.pi)
    sweep = d12 if d1o <= d12 else d12 - 2 * np.pi
    n = max(1, int(np.ceil(abs(sweep) / _ARC_STEP)))
    angles = a1 + sweep * np.arange(n + 1) / n
    return [centre + rho * np.array([np.cos(a), np.sin(a), 0.0]) for a in angles]


def _clip_pass(clip: ClipSpec, before: FloatArray | None, length: float) -> list[FloatArray]:
    half = 0.5 * length * clip.direction
    ends = [clip.position - half, clip.position + half]
    if before is not None and np.linalg.norm(ends[1] - before) < np.linalg.norm(ends[0] - before):
        ends.reverse()
    return ends


def _through_gripper(
    world: WorldSpec,
    cable: CableSpec,
    hold: HoldSpec,
    before: FloatArray | None,
    after: FloatArray | None,
    pad_exit: float,
) -> tuple[list[FloatArray], list[float | None]]:
    """Route points that run straight through a gripper's fingers along its tool x-axis."""
    g = world.gripper(hold.arm)
    x_tool = rotate(g.orientation, [1.0, 0.0, 0.0])
    if before is not None:
        s = -1.0 if float(x_tool @ (before - g.position)) > 0.0 else 1.0
    elif after is not None:
        s = 1.0 if float(x_tool @ (after - g.position)) >= 0.0 else -1.0
    else:
        s = 1.0
    points: list[FloatArray] = []
    arcs: list[float | None] = []
    if hold.at - pad_exit > 0.0:
        points.append(g.position - s * pad_exit * x_tool)
        arcs.append(hold.at - pad_exit)
    points.append(g.position.copy())
    arcs.append(hold.at)
    if hold.at + pad_exit < cable.length:
        points.append(g.position + s * pad_exit * x_tool)
        arcs.append(hold.at + pad_exit)
    return points, arcs


def _interpolate(polyline: FloatArray, arcs: FloatArray, s: float) -> FloatArray:
    """Point at arc length ``s`` on a polyline whose vertices have arc lengths ``arcs``."""
    if s <= arcs[0]:
        i = 0
    elif s >= arcs[-1]:
        i = len(arcs) - 2
    else:
        i = int(np.searchsorted(arcs, s, side="right")) - 1
        i = min(i, len(arcs) - 2)
    span = arcs[i + 1] - arcs[i]
    t = (s - arcs[i]) / span if span > 1e-15 else 0.0
    if s > arcs[-1] or s < arcs[0]:  # straight continuation at rest length
        direction = _unit(polyline[i + 1] - polyline[i])
        base: FloatArray = polyline[-1] if s > arcs[-1] else polyline[0]
        result: FloatArray = base + (s - (arcs[-1] if s > arcs[-1] else arcs[0])) * direction
        return result
    point: FloatArray = polyline[i] + t * (polyline[i + 1] - polyline[i])
    return point


def rest_tension_limit(world: WorldSpec, cable: CableSpec) -> float:
    """Largest tension [N] ``cable`` may start with in ``world``.

    The force limit; in a world that starts a run (``world.start_at_rest``),
    also no more than the cable's weight. Such a run tares its wrist sensors
    against the load a slack held cable explains (its weight share, give or
    take a few cable weights); a cable that starts stretched pulls beyond
    that, the tare takes the pull for a sensor offset and removes it, and
    every tension measured afterwards is short by it.
    """
    if not world.start_at_rest:
        return world.force_limit
    weight = cable.mass_per_length * cable.length * float(-GRAVITY[2])
    return min(world.force_limit, weight)


def _check_stretch(
    world: WorldSpec, cable: CableSpec, sa: float, sb: float, route: float, pad_exit: float
) -> None:
    """Refuse a route between known arc lengths that starts the cable stretched.

    The message names the hold whose ``at`` closes the span (the known arc
    length ``sb`` is a held point or one ``pad_exit`` [m] before it) and the
    smallest ``at`` that would do.

    Raises:
        SimulationError: if the route is longer than the cable between arc
            lengths ``sa`` and ``sb`` [m] by more than a tension of
            :func:`rest_tension_limit` stretches it.
    """
    stretch = route - (sb - sa)
    if stretch <= 0.0:
        return
    tension = cable.stiffness * cable.length * stretch / max(sb - sa, 1e-12)
    limit = rest_tension_limit(world, cable)
    if tension > limit:
        why = (
            "its weight: the sensor's tare at the start would take the pull for an offset"
            if limit < world.force_limit
            else "the force limit"
        )
        hold = next((h for h in cable.holds if 0.0 <= h.at - sb <= pad_exit + 1e-9), None)
        fix = (
            f"held_by (arm {hold.arm}) at >= {hold.at + stretch:.4f} m, or fixtures nearer"
            " the route"
            if hold is not None
            else f"at least {route:.4f} m of cable between the two, or fixtures nearer the route"
        )
        raise SimulationError(
            f"cable {cable.name}: its initial route between arc lengths {sa:g} m and {sb:g} m"
            f" (the fixtures and the gripper's fingers) is {route:.4f} m long, {stretch * 1e3:.1f}"
            f" mm more than the cable there, so it would start stretched at {tension:.2f} N, above"
            f" the {limit:.2f} N its start allows ({why}); expected {fix}"
        )


def initial_vertices(
    world: WorldSpec,
    cable: CableSpec,
    disc: CableDiscretization,
    clip_length: float,
    table_height: float,
    pad_exit: float = 0.012,
) -> FloatArray:
    """Vertex positions [m] of ``cable`` along its initial taut route.

    Args:
        world: The world (fixtures and gripper start poses).
        cable: The cable.
        disc: Its discretisation (vertex arc lengths).
        clip_length: Length of a clip along its slot [m].
        table_height: Height of the table [m] (a cable with no fixture and
            no hold is laid on it).
        pad_exit: The route runs along the gripper's tool x-axis this far [m]
            to either side of a held point.

    Returns:
        Positions of the N + 1 vertices.  # (N + 1, 3)

    Raises:
        SimulationError: if the route is so much longer than the cable that
            the initial tension would exceed the force limit.
    """
    # nominal positions (fixture positions, gripper start points)
    nominal: list[tuple[FloatArray, float | None, object]] = []
    if cable.start is not None:
        nominal.append((world.fixture(cable.start).position, 0.0, None))
    for name in cable.via:
        nominal.append((world.fixture(name).position, None, world.fixture(name)))
    for h in cable.holds:
        nominal.append((world.gripper(h.arm).position, h.at, h))
    if not nominal:
        start = np.array([0.0, 0.0, table_height + cable.radius])
        direction = np.array([1.0, 0.0, 0.0])
        return np.array([start + s * direction for s in disc.arc])
    # expand fixtures into route points
    points: list[FloatArray] = []
    known: list[float | None] = []
    for i, (pos, arc, fixture) in enumerate(nominal):
        before = points[-1] if points else None
        after = nominal[i + 1][0] if i + 1 < len(nominal) else None
        if isinstance(fixture, PegSpec):
            new = _peg_wrap(fixture, before, after, cable.radius)
        elif isinstance(fixture, ClipSpec):
            new = _clip_pass(fixture, before, clip_length)
        elif isinstance(fixture, HoldSpec):
            new, arcs_new = _through_gripper(world, cable, fixture, before, after, pad_exit)
            points.extend(new)
            known.extend(arcs_new)
            continue
        else:
            new = [np.asarray(pos, dtype=float)]
        points.extend(new)
        known.extend([arc] + [None] * (len(new) - 1) if arc is not None else [None] * len(new))
    if len(points) == 1:
        hold = cable.holds[0] if cable.holds else None
        q = world.gripper(hold.arm).orientation if hold else np.array([1.0, 0.0, 0.0, 0.0])
        x_tool = rotate(q, [1.0, 0.0, 0.0])
        points = [points[0] - 0.1 * x_tool, points[0]]
        known = [None, known[0]]
    polyline = np.array(points)
    dist = np.concatenate(([0.0], np.cumsum(np.linalg.norm(np.diff(polyline, axis=0), axis=1))))
    idx = [i for i, k in enumerate(known) if k is not None]
    arcs = np.empty(len(points))
    if not idx:  # only fixtures: start at the first one
        arcs[:] = dist
    else:
        for i in range(len(points)):
            prev = [j for j in idx if j <= i]
            nxt = [j for j in idx if j >= i]
            if prev and nxt and prev[-1] != nxt[0]:
                a, b = prev[-1], nxt[0]
                sa, sb = known[a], known[b]
                assert sa is not None and sb is not None
                arcs[i] = sa + (sb - sa) * (dist[i] - dist[a]) / (dist[b] - dist[a])
                _check_stretch(world, cable, sa, sb, float(dist[b] - dist[a]), pad_exit)
            elif prev:
                ka = known[prev[-1]]
                assert ka is not None
                arcs[i] = ka + dist[i] - dist[prev[-1]]
            else:
                kb = known[nxt[0]]
                assert kb is not None
                arcs[i] = kb - (dist[nxt[0]] - dist[i])
    # remove duplicates in arc (coincident points)
    keep = np.concatenate(([True], np.diff(arcs) > 1e-12))
    polyline, arcs = polyline[keep], arcs[keep]
    if len(arcs) == 1:
        polyline = np.vstack([polyline, polyline[0] + [1e-3, 0.0, 0.0]])
        arcs = np.array([arcs[0], arcs[0] + 1e-3])
    return np.array([_interpolate(polyline, arcs, float(s)) for s in disc.arc])
