"""Edge e_i = (d_i, s_i, f_i, k_i) between feature points v_i and v_{i+1}."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tautwire.errors import InvalidArgumentError


@dataclass
class Edge:
    """The cable between two adjacent feature points.

    Attributes:
        length: d_i, cable length of the edge at rest [m].
        sag: s_i, largest vertical chord-to-cable distance [m] (equ:catenarySlack).
        tension: f_i [N], >= 0.
        stiffness: k_i, axial spring constant of this edge [N/m]. A uniform
            cable's k scales as 1/length: splitting an edge makes both parts
            stiffer.
    """

    length: float
    sag: float = 0.0
    tension: float = 0.0
    stiffness: float = float("inf")

    def __post_init__(self) -> None:
        if not np.isfinite(self.length) or self.length < 0.0:
            raise InvalidArgumentError(f"edge length must be finite and >= 0 m, got {self.length}")
        if not np.isfinite(self.sag) or self.sag < 0.0:
            raise InvalidArgumentError(f"sag must be finite and >= 0 m, got {self.sag}")
        if not np.isfinite(self.tension) or self.tension < 0.0:
            raise InvalidArgumentError(f"tension must be finite and >= 0 N, got {self.tension}")
        if np.isnan(self.stiffness) or self.stiffness <= 0.0:
            raise InvalidArgumentError(f"stiffness must be > 0 N/m, got {self.stiffness}")

    def split(self, delta: float) -> tuple[Edge, Edge]:
        """Split at fraction ``delta`` of its length into two edges.

        Each part keeps the tension; its stiffness is k d / d_part (EA is
        constant along a uniform cable).
        """
        if not 0.0 < delta < 1.0:
            raise InvalidArgumentError(f"an edge splits at a fraction in (0, 1), got {delta}")
        first = Edge(self.length * delta, 0.0, self.tension, self.stiffness / delta)
        second = Edge(
            self.length * (1.0 - delta), 0.0, self.tension, self.stiffness / (1.0 - delta)
        )
        return first, second

    def join(self, other: Edge) -> Edge:
        """The edge made of this one followed by ``other`` (springs in series)."""
        length = self.length + other.length
        compliance = float(1.0 / self.stiffness + 1.0 / other.stiffness)
        stiffness = 1.0 / compliance if compliance > 0.0 else math.inf  # two rigid edges: rigid
        total = length if length > 0.0 else 1.0
        tension = (self.tension * self.length + other.tension * other.length) / total
        return Edge(length, 0.0, tension, stiffness)
