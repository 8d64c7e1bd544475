"""The path graph G = (V, E) that is the robot's only picture of a cable."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.model.edge import Edge
from tautwire.model.feature_point import FeatureKind, FeaturePoint
from tautwire.model.interpolation import lerp, slerp
from tautwire.model.mass import point_masses
from tautwire.model.sag import sag_from_span

FloatArray = NDArray[np.float64]


class PathGraph:
    """A cable as ordered feature points v_1 ... v_|V| joined by edges e_1 ... e_|E|.

    The reduced model {G, rho} of the paper: the graph plus the mass per
    length. Point masses (eq:mass) and sags (equ:catenarySlack) are derived
    from the points and edges and kept up to date by :meth:`refresh`, which
    every mutating method calls.

    Args:
        points: The feature points, in order along the cable.
        edges: One edge between each pair of neighbours (len(points) - 1).
        mass_per_length: rho [kg/m].
        rest_height: Height [m] at which the cable's centre line rests on the
            board (the board's surface plus the cable's radius); a free end
            that hangs down lies there (:mod:`~tautwire.estimation.constraint_mapping`).
            None: no board under the cable is known.
    """

    def __init__(
        self,
        points: Sequence[FeaturePoint],
        edges: Sequence[Edge],
        mass_per_length: float,
        rest_height: float | None = None,
    ) -> None:
        if len(points) < 2:
            raise InvalidArgumentError(
                f"a path graph needs at least 2 feature points, got {len(points)}"
            )
        if len(edges) != len(points) - 1:
            raise InvalidArgumentError(
                f"a path graph of {len(points)} points needs {len(points) - 1} edges, "
                f"got {len(edges)}"
            )
        if not np.isfinite(mass_per_length) or mass_per_length < 0.0:
            raise InvalidArgumentError(f"mass_per_length must be >= 0 kg/m, got {mass_per_length}")
        if rest_height is not None and not np.isfinite(rest_height):
            raise InvalidArgumentError(f"rest_height must be finite or None, got {rest_height}")
        self.rest_height = None if rest_height is None else float(rest_height)
        self.points: list[FeaturePoint] = list(points)
        self.edges: list[Edge] = list(edges)
        self.mass_per_length = float(mass_per_length)
        self.refresh()

    @classmethod
    def from_positions(
        cls,
        positions: ArrayLike,
        mass_per_length: float,
        lengths: ArrayLike | None = None,
        stiffness: float = float("inf"),
        kinds: Sequence[FeatureKind] | None = None,
        labels: Sequence[str] | None = None,
    ) -> PathGraph:
        """Build a graph through ``positions``.

        Args:
            positions: Feature point positions [m].  # (N, 3)
            mass_per_length: rho [kg/m].
            lengths: Cable length of each edge [m]; default the straight
                distances.  # (N - 1,)
            stiffness: Axial stiffness of the whole cable [N/m]; each edge gets
                its share k L / d_i.
            kinds: What constrains each point (default all ``free``).
            labels: A label for each point.
        """
        p = np.asarray(positions, dtype=float)
        if p.ndim != 2 or p.shape[1] != 3:
            raise InvalidArgumentError(f"positions must have shape (N, 3), got {p.shape}")
        d = (
            np.linalg.norm(np.diff(p, axis=0), axis=1)
            if lengths is None
            else np.asarray(lengths, dtype=float).reshape(-1)
        )
        if d.shape != (p.shape[0] - 1,):
            raise InvalidArgumentError(f"lengths must have {p.shape[0] - 1} entries, got {d.shape}")
        total = float(np.sum(d))
        edges = [
            Edge(float(di), stiffness=stiffness * total / di if di > 0 else stiffness) for di in d
        ]
        kinds = list(kinds) if kinds is not None else ["free"] * p.shape[0]
        labels = list(labels) if labels is not None else [""] * p.shape[0]
        points = [FeaturePoint(p[i], kind=kinds[i], label=labels[i]) for i in range(p.shape[0])]
        graph = cls(points, edges, mass_per_length)
        graph.orient_along_edges()
        return graph

    # ------------------------------------------------------------------ views
    def __len__(self) -> int:
        return len(self.points)

    @property
    def positions(self) -> FloatArray:
        """Positions of all feature points [m], shape (N, 3)."""
        return np.array([pt.position for pt in self.points])

    @property
    def lengths(self) -> FloatArray:
        """Cable length of every edge [m], shape (N - 1,)."""
        return np.array([e.length for e in self.edges])

    @property
    def total_length(self) -> float:
        """Cable length of the whole graph [m]."""
        return float(np.sum(self.lengths))

    def arc_lengths(self) -> FloatArray:
        """Arc length [m] of each feature point from v_1, shape (N,)."""
        return np.concatenate(([0.0], np.cumsum(self.lengths)))

    def masses(self) -> FloatArray:
        """m_i [kg] of every feature point (eq:mass), shape (N,)."""
        return point_masses(self.lengths, self.mass_per_length)

    def sags(self) -> FloatArray:
        """s_i [m] of every edge (equ:catenarySlack) at the current positions, shape (N - 1,)."""
        delta = np.diff(self.positions, axis=0)  # (N - 1, 3)
        a = np.hypot(delta[:, 0], delta[:, 1]).tolist()
        h = delta[:, 2].tolist()
        return np.array([sag_from_span(a[i], h[i], e.length) for i, e in enumerate(self.edges)])

    def locate(self, arc_length: float) -> tuple[int, float]:
        """The edge index and fraction delta at which ``arc_length`` [m] lies."""
        s = self.arc_lengths()
        if not s[0] <= arc_length <= s[-1]:
            raise InvalidArgumentError(
                f"arc length {arc_length} m is outside the cable [0, {s[-1]:.6g}] m"
            )
        i = int(np.clip(np.searchsorted(s, arc_length, side="right") - 1, 0, len(self.edges) - 1))
        d = self.edges[i].length
        return i, (arc_length - s[i]) / d if d > 0 else 0.0

    def index_of(self, kind: FeatureKind, label: str | None = None) -> int | None:
        """Index of the first point of ``kind`` (and ``label``), or None."""
        for i, pt in enumerate(self.points):
            if pt.kind == kind and (label is None or pt.label == label):
                return i
        return None

    # -------------------------------------------------------------- mutation
    def refresh(self) -> None:
        """Recompute point masses (eq:mass) and edge sags (equ:catenarySlack).

        Call it after changing an edge's length directly; the graph's own
        methods keep both up to date.
        """
        for pt, m in zip(self.points, self.masses(), strict=True):
            pt.mass = float(m)
        self._refresh_sags()

    def _refresh_sags(self) -> None:
        for e, s in zip(self.edges, self.sags(), strict=True):
            e.sag = float(s)

    def set_positions(self, positions: ArrayLike) -> None:
        """Set every point's position [m], shape (N, 3), and refresh the sags.

        Masses depend on the edge lengths only, which moving points leaves
        unchanged.
        """
        p = np.array(positions, dtype=float)  # a copy: the points own its rows
        if p.shape != (len(self.points), 3) or not np.all(np.isfinite(p)):
            raise InvalidArgumentError(
                f"positions must be finite with shape ({len(self.points)}, 3)"
            )
        for pt, pi in zip(self.points, p, strict=True):
            pt.position = pi
        self._refresh_sags()

    def orient_along_edges(self, keep: Sequence[FeatureKind] = ("gripper",)) -> None:
        """Orient points with x along the cable, without twist.

        This is the paper's rule for estimated points; points of a kind in
        ``keep`` keep their orientation.
        """
        from tautwire.model.quaternion import orientation_along

        p = self.positions
        n = len(p)
        for i, pt in enumerate(self.points):
            if pt.kind in keep:
                continue
            direction = p[min(i + 1, n - 1)] - p[max(i - 1, 0)]
            pt.orientation = orientation_along(direction)

    def insert_point(
        self,
        edge_index: int,
        delta: float,
        kind: FeatureKind = "goal",
        label: str = "",
    ) -> int:
        """Insert an interpolated feature point on edge ``edge_index`` at fraction ``delta``.

        Position by linear interpolation, orientation by Slerp, both with
        ``delta``; the edge is split in two (see :meth:`Edge.split`).

        Returns:
            The index of the new point.
        """
        if not 0 <= edge_index < len(self.edges):
            raise InvalidArgumentError(
                f"edge_index must be in [0, {len(self.edges) - 1}], got {edge_index}"
            )
        if not 0.0 < delta < 1.0:
            raise InvalidArgumentError(
                f"a new point lies strictly inside its edge: delta in (0, 1), got {delta}"
            )
        before, after = self.points[edge_index], self.points[edge_index + 1]
        point = FeaturePoint(
            lerp(before.position, after.position, delta),
            slerp(before.orientation, after.orientation, delta),
            kind=kind,
            label=label,
        )
        first, second = self.edges[edge_index].split(delta)
        self.points.insert(edge_index + 1, point)
        self.edges[edge_index : edge_index + 1] = [first, second]
        self.refresh()
        return edge_index + 1

    def insert_at_arc_length(
        self, arc_length: float, kind: FeatureKind = "goal", label: str = ""
    ) -> int:
        """Insert a point at ``arc_length`` [m] from v_1, or return the point already there."""
        i, delta = self.locate(arc_length)
        tol = 1e-9
        if delta * self.edges[i].length <= tol:
            return i
        if (1.0 - delta) * self.edges[i].length <= tol:
            return i + 1
        return self.insert_point(i, delta, kind, label)

    def remove_point(self, index: int) -> None:
        """Remove an inner feature point; its two edges join (see :meth:`Edge.join`)."""
        if not 0 < index < len(self.points) - 1:
            raise InvalidArgumentError(
                f"only inner points (1 .. {len(self.points) - 2}) can be removed, got {index}"
            )
        joined = self.edges[index - 1].join(self.edges[index])
        del self.points[index]
        self.edges[index - 1 : index + 1] = [joined]
        self.refresh()

    def copy(self) -> PathGraph:
        """A deep copy."""
        edges = [Edge(e.length, e.sag, e.tension, e.stiffness) for e in self.edges]
        return PathGraph(
            [pt.copy() for pt in self.points], edges, self.mass_per_length, self.rest_height
        )

    def __repr__(self) -> str:
        kinds = ", ".join(
            f"{pt.kind}{'(' + pt.label + ')' if pt.label else ''}" for pt in self.points
        )
        return f"PathGraph({len(self.points)} points: {kinds}; L={self.total_length:.4g} m)"
