"""Model update by constraints (the paper's sec:constraintmapping).

Constraints (grippers from forward kinematics, estimated contact points,
known fixed points) fix some feature points; the map F: C x P -> P carries
them onto the whole path graph:

- points between two constrained points are interpolated by the fraction of
  cable length, which is a linear map of the constrained positions; for the
  paper's example (v2 and v4 held by the grippers, goal point v3 between)

      [p2; p3; p4] = ([[1, 0], [d3/(d2+d3), d2/(d2+d3)], [0, 1]] kron I3) [p_g,right; p_g,left];

- points beyond the outermost constrained points are free ends that hang
  under gravity: straight down from the last constrained point by their
  cable length, resting on the board when its height is given (or the
  graph knows it: :attr:`PathGraph.rest_height`).
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.model.path_graph import PathGraph

FloatArray = NDArray[np.float64]


def constraint_matrix(arc_lengths: ArrayLike, constrained: list[int]) -> FloatArray:
    """The linear part M of the constraint map, p = (M kron I3) p_constrained.

    Args:
        arc_lengths: Arc length [m] of every feature point from v_1.  # (N,)
        constrained: Indices of the constrained points, strictly increasing.

    Returns:
        M, row i the weights of point i on the constrained points; points
        outside the constrained range copy the nearest one (their hanging
        offset is added by :func:`map_constraints`).  # (N, C)
    """
    s = np.asarray(arc_lengths, dtype=float).reshape(-1)
    if not constrained:
        raise InvalidArgumentError("at least one feature point must be constrained")
    if any(b <= a for a, b in itertools.pairwise(constrained)):
        raise InvalidArgumentError(f"constrained indices must increase strictly, got {constrained}")
    if constrained[0] < 0 or constrained[-1] >= s.size:
        raise InvalidArgumentError(f"constrained indices must lie in [0, {s.size - 1}]")
    M = np.zeros((s.size, len(constrained)))
    arc = s.tolist()
    j = -1  # index in ``constrained`` of the last constrained point at or before i
    last = len(constrained) - 1
    for i in range(s.size):
        while j < last and constrained[j + 1] <= i:
            j += 1
        if j < 0:
            M[i, 0] = 1.0
        elif j == last or constrained[j] == i:
            M[i, j] = 1.0
        else:
            a, b = constrained[j], constrained[j + 1]
            span = arc[b] - arc[a]
            w = (arc[i] - arc[a]) / span if span > 0.0 else 0.0
            M[i, j] = 1.0 - w  # weight of the constrained point before
            M[i, j + 1] = w  # and of the one after
    return M


def map_constraints(
    graph: PathGraph,
    constraints: Mapping[int, ArrayLike],
    board_height: float | None = None,
) -> FloatArray:
    """Positions of all feature points implied by ``constraints``.

    Args:
        graph: The current model (its edge lengths are used).
        constraints: Position [m] of each constrained point, by index.
        board_height: z [m] that hanging ends rest on (the board's surface
            plus the cable's radius); default the graph's ``rest_height``.

    Returns:
        New positions [m].  # (N, 3)
    """
    idx = sorted(constraints)
    P_c = np.array([np.asarray(constraints[i], dtype=float).reshape(3) for i in idx])  # (C, 3)
    s = graph.arc_lengths()
    M = constraint_matrix(s, idx)
    P = M @ P_c  # same as (M kron I3) applied to the stacked positions
    down = np.array([0.0, 0.0, -1.0])
    for i in range(idx[0]):  # free end before the first constraint hangs below it
        P[i] = P_c[0] + down * (s[idx[0]] - s[i])
    for i in range(idx[-1] + 1, len(graph)):  # and after the last one
        P[i] = P_c[-1] + down * (s[i] - s[idx[-1]])
    if board_height is None:
        board_height = graph.rest_height
    if board_height is not None:
        P[:, 2] = np.maximum(P[:, 2], board_height)
    out: FloatArray = P
    return out


def update_by_constraints(
    graph: PathGraph,
    constraints: Mapping[int, ArrayLike],
    board_height: float | None = None,
) -> None:
    """Apply :func:`map_constraints` to ``graph`` in place.

    Positions, point masses and sags are updated; points that are not held
    by a gripper are re-oriented with x along the cable (no twist).
    """
    graph.set_positions(map_constraints(graph, constraints, board_height))
    graph.orient_along_edges()
