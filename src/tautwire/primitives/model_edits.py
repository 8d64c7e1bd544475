"""How primitives change the path graph when they change the cable's state.

The path graph is the robot's only picture of the cable (paper section
"Model Representation"): when a gripper lets the cable slide, grasps it or
clips it, the primitive records that here. Points added, fixed, moved along
the cable; edge lengths d_i at rest; stiffnesses k_i = EA / d_i.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.model import FeatureKind, PathGraph
from tautwire.primitives.model_estimator import ModelEstimator

FloatArray = NDArray[np.float64]


def move_hold(graph: PathGraph, index: int, delta: float) -> None:
    """Move the grasp of gripper point ``index`` by ``delta`` [m] of rest length.

    The cable slid through the gripper: with ``delta`` > 0 the gripper now
    holds it further along (the edge before the point grows, the edge after
    it shrinks); < 0 the other way. Each edge keeps EA = k d. Free inner
    points the slide passes are merged into the shrinking edge.

    Raises:
        InvalidArgumentError: if the shrinking edge is missing or too short.
    """
    grow, shrink = (index - 1, index) if delta > 0.0 else (index, index - 1)
    d = abs(delta)
    if not (0 <= grow < len(graph.edges) and 0 <= shrink < len(graph.edges)):
        raise InvalidArgumentError("the cable can only slide through a gripper it passes through")
    # a free inner point beyond (where a gripper let go: a hand-over's
    # release) holds nothing back; cable sliding past it merges it into the
    # edge (random board 1808415002: E after a hand-over)
    far = shrink + 1 if delta > 0.0 else shrink
    while (
        graph.edges[shrink].length <= d
        and 0 < far < len(graph.points) - 1
        and not graph.points[far].is_constrained
    ):
        graph.remove_point(far)
        if delta < 0.0:  # the points before the gripper shifted down by one
            grow, shrink, far = grow - 1, shrink - 1, far - 1
    if graph.edges[shrink].length <= d:
        raise InvalidArgumentError(
            f"only {graph.edges[shrink].length:.3f} m of cable is left beyond the gripper,"
            f" {d:.3f} m cannot slide through"
        )
    for i, change in ((grow, d), (shrink, -d)):
        e = graph.edges[i]
        new = e.length + change
        if np.isfinite(e.stiffness) and new > 0.0:
            e.stiffness = e.stiffness * e.length / new
        e.length = new
    graph.refresh()


def rescale_elasticity(estimator: ModelEstimator, factor: float) -> None:
    """Restart the elasticity estimate at ``factor`` times its trusted k_hat.

    After the gripper's edge changed length (sliding, a new contact), the
    stiffness of the new edge is k * d_old / d_new and the fit's offset
    (the rest length) is stale: the estimator starts afresh from there.
    """
    elasticity = estimator.elasticity
    elasticity.reset(k_initial=elasticity.k_trusted * factor)


def add_point(
    graph: PathGraph, arc_length: float, position: FloatArray, kind: FeatureKind, label: str
) -> int:
    """Insert a constrained point at ``arc_length`` [m] with a known position.

    The orientation is Slerp-interpolated (the paper's goal points); the
    position [m] is the constraint that the primitive established (a clip's
    seat, a gripper's tool centre point).

    Returns:
        The new point's index.
    """
    i = graph.insert_at_arc_length(arc_length, kind=kind, label=label)
    point = graph.points[i]
    point.kind, point.label = kind, label
    point.position = np.asarray(position, dtype=float).copy()
    graph.refresh()
    return i


def add_on_sensing_edge(
    estimator: ModelEstimator,
    arc_length: float,
    position: FloatArray,
    kind: FeatureKind,
    label: str,
) -> int:
    """Insert a constrained point on the sensing gripper's edge (a grasp, a clip).

    The gripper's edge now ends at the new point: shorter, so stiffer
    (k d constant); the elasticity estimate restarts from k_hat d_old / d_new.

    Returns:
        The new point's index.
    """
    graph = estimator.graph
    s = graph.arc_lengths()
    c = estimator.contact_index
    old = abs(float(s[estimator.gripper_index]) - float(s[c if c is not None else 0]))
    i = add_point(graph, arc_length, position, kind, label)
    new = abs(float(graph.arc_lengths()[estimator.gripper_index]) - arc_length)
    if new > 0.0:
        rescale_elasticity(estimator, old / new)
    return i


def drop_new_points(graph: PathGraph, known: list[int]) -> None:
    """Remove the inner contact points not among ``known`` (ids of points).

    While a primitive bends the cable over a fixture on purpose (clipping),
    the contact filter may declare the bend a new contact; once the
    primitive adds the fixture itself, those estimates are dropped.
    """
    keep = set(known)
    i = 1
    while i < len(graph.points) - 1:
        point = graph.points[i]
        if id(point) not in keep and point.kind == "contact":
            graph.remove_point(i)
        else:
            i += 1
