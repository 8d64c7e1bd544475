"""The robot's cable model drawn over the simulated scene, and the fixtures told apart.

The path graph {G, rho} is what the robot believes; the simulated cable is
what is there. Drawing one over the other shows at a glance where the blind
estimate is right. :func:`model_shapes` turns a graph into coloured shapes
(no MuJoCo needed: the Rerun recording and the plots use them too):
feature points as spheres coloured by what holds them (the gripper, an
anchor, a peg, a clip, an unknown contact), edges as segments, and each
estimated point's covariance as its 3-sigma ellipsoid. :func:`draw_shapes`
adds them to a :class:`mujoco.MjvScene` (a renderer's scene, or the passive
viewer's ``user_scn``); :func:`fixture_colours` and :func:`fixture_labels`
make an anchor, a peg and a clip distinguishable in any view.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.model import FeaturePoint, PathGraph
from tautwire.sim.spec import AnchorSpec, ClipSpec, FixtureSpec, PegSpec

FloatArray = NDArray[np.float64]
RGBA = tuple[float, float, float, float]

#: Colour of each fixture type, in the renders, the viewer and the plots.
FIXTURE_COLOURS: dict[str, RGBA] = {
    "anchor": (0.10, 0.70, 0.25, 1.0),  # green
    "peg": (0.95, 0.75, 0.05, 1.0),  # gold (the left gripper is blue, the right red)
    "clip": (0.80, 0.25, 0.80, 1.0),  # magenta
}
#: Colour of a feature point that no fixture name labels, by kind.
KIND_COLOURS: dict[str, RGBA] = {
    "gripper": (0.0, 0.85, 0.90, 1.0),  # cyan
    "contact": (0.95, 0.15, 0.15, 1.0),  # red: a contact with no known fixture
    "fixed": FIXTURE_COLOURS["anchor"],
    "goal": (0.60, 0.60, 0.60, 1.0),  # grey
    "free": (0.95, 0.95, 0.95, 1.0),  # white
}
#: Colour of the model's edges.
EDGE_COLOUR: RGBA = (1.0, 1.0, 1.0, 0.9)
#: Opacity of the uncertainty ellipsoids.
ELLIPSOID_ALPHA = 0.35
#: Radius [m] of a feature point's sphere and of an edge's capsule.
POINT_RADIUS = 0.006
EDGE_RADIUS = 0.0015
#: Sigmas of the drawn uncertainty ellipsoids.
SIGMAS = 3.0


def fixture_type(fixture: FixtureSpec) -> str:
    """``anchor``, ``peg`` or ``clip``."""
    if isinstance(fixture, AnchorSpec):
        return "anchor"
    if isinstance(fixture, PegSpec):
        return "peg"
    assert isinstance(fixture, ClipSpec)
    return "clip"


@dataclass(frozen=True)
class Ellipsoid:
    """An uncertainty ellipsoid.

    Attributes:
        centre: Centre [m], world frame.  # (3,)
        half_sizes: Semi-axes [m] (``SIGMAS`` standard deviations).  # (3,)
        rotation: Its axes as the columns of a rotation matrix.  # (3, 3)
        colour: RGBA in [0, 1].
        label: What it estimates.
    """

    centre: FloatArray
    half_sizes: FloatArray
    rotation: FloatArray
    colour: RGBA
    label: str


@dataclass(frozen=True)
class ModelShapes:
    """A path graph as shapes to draw.

    Attributes:
        points: Feature point positions [m].  # (N, 3)
        colours: RGBA of each point.
        labels: Text of each point (kind and label).
        kinds: The feature kind of each point.
        ellipsoids: One per point with a covariance.
    """

    points: FloatArray
    colours: tuple[RGBA, ...]
    labels: tuple[str, ...]
    kinds: tuple[str, ...]
    ellipsoids: tuple[Ellipsoid, ...]

    @property
    def edges(self) -> FloatArray:
        """Each edge's end points [m], shape (N - 1, 2, 3)."""
        return np.stack([self.points[:-1], self.points[1:]], axis=1)


def point_colour(point: FeaturePoint, fixture_types: Mapping[str, str]) -> RGBA:
    """A feature point's colour: its fixture's type if a fixture labels it, else its kind's."""
    if point.kind != "gripper" and point.label in fixture_types:
        return FIXTURE_COLOURS[fixture_types[point.label]]
    return KIND_COLOURS[point.kind]


def covariance_ellipsoid(
    centre: ArrayLike, covariance: ArrayLike, colour: RGBA, label: str = "", sigmas: float = SIGMAS
) -> Ellipsoid:
    """The ``sigmas`` ellipsoid of a position covariance [m^2].

    Args:
        centre: The estimate [m].  # (3,)
        covariance: Its covariance [m^2] (symmetrised; negative eigenvalues,
            rounding, count as 0).  # (3, 3)
        colour: RGBA; the ellipsoid is drawn with ``ELLIPSOID_ALPHA``.
        label: What it estimates.
        sigmas: Standard deviations per semi-axis.
    """
    cov = np.asarray(covariance, dtype=float).reshape(3, 3)
    values, vectors = np.linalg.eigh(0.5 * (cov + cov.T))
    if np.linalg.det(vectors) < 0.0:
        vectors[:, 0] = -vectors[:, 0]
    half = sigmas * np.sqrt(np.maximum(values, 0.0))
    rgba = (colour[0], colour[1], colour[2], ELLIPSOID_ALPHA)
    return Ellipsoid(np.asarray(centre, dtype=float).reshape(3), half, vectors, rgba, label)


def model_shapes(graph: PathGraph, fixture_types: Mapping[str, str]) -> ModelShapes:
    """The path graph's feature points, edges and 3-sigma ellipsoids.

    Args:
        graph: The robot's cable model.
        fixture_types: ``anchor``/``peg``/``clip`` by fixture name (the
            board's design), to colour points that a fixture labels.
    """
    colours, labels, kinds, ellipsoids = [], [], [], []
    for pt in graph.points:
        colour = point_colour(pt, fixture_types)
        colours.append(colour)
        labels.append(f"{pt.kind} {pt.label}".strip())
        kinds.append(pt.kind)
        if pt.covariance is not None and pt.kind != "gripper":
            ellipsoids.append(covariance_ellipsoid(pt.position, pt.covariance, colour, pt.label))
    return ModelShapes(
        graph.positions.copy(), tuple(colours), tuple(labels), tuple(kinds), tuple(ellipsoids)
    )


def _next_geom(scene: mujoco.MjvScene) -> mujoco.MjvGeom | None:
    """The scene's next free geom (counted in), or None when the scene is full."""
    if scene.ngeom >= scene.maxgeom:
        return None
    geom = scene.geoms[scene.ngeom]
    scene.ngeom += 1
    return geom


def _add(
    scene: mujoco.MjvScene,
    kind: int,
    size: ArrayLike,
    pos: ArrayLike,
    mat: ArrayLike,
    rgba: RGBA,
    label: str = "",
) -> bool:
    geom = _next_geom(scene)
    if geom is None:
        return False
    mujoco.mjv_initGeom(
        geom,
        kind,
        np.asarray(size, dtype=float),
        np.asarray(pos, dtype=float),
        np.asarray(mat, dtype=float).reshape(9),
        np.asarray(rgba, dtype=np.float32),
    )
    geom.label = label
    return True


def draw_shapes(
    scene: mujoco.MjvScene, shapes: ModelShapes, labels: bool = False, scale: float = 1.0
) -> int:
    """Append the model's shapes to ``scene`` (as many as it has room for).

    Args:
        scene: A scene after its ``update_scene`` (a renderer's) or a
            viewer's ``user_scn`` (reset ``ngeom`` before redrawing).
        shapes: From :func:`model_shapes`.
        labels: Write each contact, fixed and goal point's kind and label
            beside it (off by default: the fixtures' own labels name them).
        scale: Factor on the points' and edges' radii (a distant camera
            needs thicker ones to show them).

    Returns:
        The number of geoms added.
    """
    start = int(scene.ngeom)
    eye = np.eye(3)
    for a, b in shapes.edges:
        if float(np.linalg.norm(b - a)) < 1e-9:
            continue
        geom = _next_geom(scene)
        if geom is None:
            return int(scene.ngeom) - start
        mujoco.mjv_initGeom(
            geom,
            mujoco.mjtGeom.mjGEOM_CAPSULE,
            np.zeros(3),
            np.zeros(3),
            eye.reshape(9),
            np.asarray(EDGE_COLOUR, dtype=np.float32),
        )
        mujoco.mjv_connector(geom, mujoco.mjtGeom.mjGEOM_CAPSULE, scale * EDGE_RADIUS, a, b)
    for p, colour, label, kind in zip(
        shapes.points, shapes.colours, shapes.labels, shapes.kinds, strict=True
    ):
        text = label if labels and kind in ("contact", "fixed", "goal") else ""
        size = [scale * POINT_RADIUS] * 3
        if not _add(scene, mujoco.mjtGeom.mjGEOM_SPHERE, size, p, eye, colour, text):
            return int(scene.ngeom) - start
    for e in shapes.ellipsoids:
        half = np.maximum(e.half_sizes, 1e-4)  # a point known exactly still shows
        if not _add(scene, mujoco.mjtGeom.mjGEOM_ELLIPSOID, half, e.centre, e.rotation, e.colour):
            break
    return int(scene.ngeom) - start


def fixture_geoms(model: mujoco.MjModel, fixtures: tuple[FixtureSpec, ...]) -> dict[int, str]:
    """The geoms of each fixture: geom id -> fixture name.

    A peg's and an anchor's geom carry the fixture's name, an anchor's stand
    stands below it, a clip's geoms belong to its body and its jaws' bodies.
    """
    out: dict[int, str] = {}
    by_body: dict[int, str] = {}
    for f in fixtures:
        gid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, f.name)
        if gid >= 0:
            out[gid] = f.name
        if isinstance(f, ClipSpec):
            bid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, f.name)
            for b in range(model.nbody):
                root, parent = b, int(model.body_parentid[b])
                while parent != 0 and root != bid:
                    root, parent = parent, int(model.body_parentid[parent])
                if root == bid:
                    by_body[b] = f.name
    anchors = [f for f in fixtures if isinstance(f, AnchorSpec)]
    for g in range(model.ngeom):
        body = int(model.geom_bodyid[g])
        if body in by_body:
            out[g] = by_body[body]
        elif (
            body == 0
            and g not in out
            and mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_GEOM, g) is None
        ):
            pos = model.geom_pos[g]
            for a in anchors:  # the unnamed stand right below an anchor
                if math.hypot(*(pos[:2] - a.position[:2])) < 1e-6 and pos[2] < a.position[2]:
                    out[g] = a.name
    return out


def fixture_colours(model: mujoco.MjModel, fixtures: tuple[FixtureSpec, ...]) -> dict[int, RGBA]:
    """The colour of each fixture geom (geom id -> RGBA), by fixture type.

    A clip's jaws keep a lighter shade of the clip's colour, so they show.
    """
    types = {f.name: fixture_type(f) for f in fixtures}
    out: dict[int, RGBA] = {}
    for gid, name in fixture_geoms(model, fixtures).items():
        r, g, b, a = FIXTURE_COLOURS[types[name]]
        geom_name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_GEOM, gid) or ""
        if "_jaw_" in geom_name:
            r, g, b = (0.5 * (c + 1.0) for c in (r, g, b))
        elif gid != mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, name) and types[name] == (
            "anchor"
        ):
            r, g, b = (0.7 * c for c in (r, g, b))  # the anchor's stand, darker
        out[gid] = (r, g, b, a)
    return out


def fixture_labels(fixtures: tuple[FixtureSpec, ...]) -> list[tuple[FloatArray, str]]:
    """Where to write each fixture's name and type (above it) [m], and the text."""
    out = []
    for f in fixtures:
        p = np.asarray(f.position, dtype=float).copy()
        p[2] += (f.height if isinstance(f, PegSpec) else 0.0) + 0.02
        out.append((p, f"{f.name} ({fixture_type(f)})"))
    return out


def style_scene(
    scene: mujoco.MjvScene,
    colours: Mapping[int, RGBA],
    labels: list[tuple[FloatArray, str]],
) -> None:
    """Recolour the fixture geoms of a scene after ``update_scene`` and add their labels.

    Args:
        scene: The scene (its model geoms are recoloured, nothing in the
            model changes).
        colours: From :func:`fixture_colours`.
        labels: From :func:`fixture_labels`.
    """
    for i in range(scene.ngeom):
        geom = scene.geoms[i]
        if geom.objtype == mujoco.mjtObj.mjOBJ_GEOM and int(geom.objid) in colours:
            geom.rgba[:] = colours[int(geom.objid)]
    add_labels(scene, labels)


def add_labels(scene: mujoco.MjvScene, labels: list[tuple[FloatArray, str]]) -> None:
    """Append text labels at world points [m] to ``scene``."""
    eye = np.eye(3)
    for pos, text in labels:
        if not _add(
            scene, mujoco.mjtGeom.mjGEOM_LABEL, [0.0, 0.0, 0.0], pos, eye, (1, 1, 1, 1), text
        ):
            return
