"""Splitting a cable into segments: vertices, rest lengths, masses, springs."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import SimulationError
from tautwire.sim.options import SimOptions
from tautwire.sim.spec import CableSpec
from tautwire.sim.wave_speed import vertex_mass_scaling, vertex_timestep_limit

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class CableDiscretization:
    """A cable as N segments between N + 1 vertices.

    Attributes:
        arc: Arc length [m] of each vertex from the cable's start.  # (N + 1,)
        rest_lengths: Rest length [m] of each segment.  # (N,)
        masses: True mass [kg] of each vertex (half of each incident
            segment).  # (N + 1,)
        segment_stiffness: Spring constant [N/m] of each segment,
            k L / l_e, so that the segments in series give k.  # (N,)
        mass_scaling: alpha_i; each vertex body carries alpha_i times its
            true mass and gravcomp 1 - 1/alpha_i, so its weight is exact.  # (N + 1,)
        max_timestep: The wave-speed limit [s] with these alpha_i at the force
            limit (before the safety factor).
    """

    arc: FloatArray
    rest_lengths: FloatArray
    masses: FloatArray
    segment_stiffness: FloatArray
    mass_scaling: FloatArray
    max_timestep: float

    @property
    def segments(self) -> int:
        """Number of segments N."""
        return len(self.rest_lengths)

    def vertex_at(self, arc_length: float) -> int:
        """Index of the vertex nearest to ``arc_length`` [m]."""
        return int(np.argmin(np.abs(self.arc - arc_length)))


def discretize_cable(
    cable: CableSpec, force_limit: float, options: SimOptions
) -> CableDiscretization:
    """Place vertices on ``cable`` and apply the wave-speed guard.

    A vertex sits exactly at every held arc length, and one ``pad_exit`` to
    either side of it (just beyond the finger pads, so that the held segment
    starts out along the gripper's channel). A free-end piece shorter
    than a quarter of the target segment length is merged into its
    neighbouring vertex (its mass is kept). Each vertex's mass scaling
    alpha_i is the smallest that satisfies the wave-speed limit at the force
    limit (:func:`tautwire.sim.wave_speed.vertex_mass_scaling`).

    Args:
        cable: The cable.
        force_limit: T_max [N], the largest tension the run may reach.
        options: Simulation options (segment length, timestep, limits).

    Raises:
        SimulationError: if the limit needs alpha beyond
            ``options.max_mass_scaling``.
    """
    length = cable.length
    if options.segments is not None:
        target = length / options.segments
    else:
        target = min(options.segment_length, length / options.min_segments)
    guide = options.pad_exit
    exits = [
        a
        for h in cable.holds
        for a in (h.at - guide, h.at + guide)
        if 0.25 * target < a < length - 0.25 * target
    ]
    breaks = sorted({0.0, length, *(h.at for h in cable.holds), *exits})
    arcs: list[float] = [0.0]
    for a, b in itertools.pairwise(breaks):
        n = max(1, math.ceil((b - a) / target - 1e-9))
        arcs.extend(a + (b - a) * np.arange(1, n + 1) / n)
    arc = np.array(arcs)
    held = {h.at for h in cable.holds}
    # Merge tiny free-end pieces into the neighbouring (held) vertex.
    if len(arc) > 2 and arc[-1] - arc[-2] < 0.25 * target:
        arc = arc[:-1]
        tail_end = length
    else:
        tail_end = float(arc[-1])
    head_start = 0.0
    if cable.start is None and len(arc) > 2 and arc[1] - arc[0] < 0.25 * target and arc[1] in held:
        arc = arc[1:]
        head_start = 0.0
    rest = np.diff(arc)
    masses = np.zeros(len(arc))
    masses[:-1] += 0.5 * rest * cable.mass_per_length
    masses[1:] += 0.5 * rest * cable.mass_per_length
    masses[-1] += (tail_end - arc[-1]) * cable.mass_per_length
    masses[0] += (arc[0] - head_start) * cable.mass_per_length
    stiffness = cable.stiffness * length / rest
    alpha = vertex_mass_scaling(
        options.timestep, rest, masses, force_limit, options.wave_speed_safety
    )
    worst = int(np.argmax(alpha))
    if alpha[worst] > options.max_mass_scaling:
        l_min = float(rest[max(worst - 1, 0) : worst + 1].min())
        raise SimulationError(
            f"cable {cable.name}: the wave-speed limit dt < l sqrt(rho / T) fails for"
            f" dt = {options.timestep} s, segment l = {l_min:.4f} m,"
            f" rho = {cable.mass_per_length} kg/m, T = force limit {force_limit} N;"
            f" it needs mass scaling {alpha[worst]:.1f} > max_mass_scaling"
            f" {options.max_mass_scaling}. Use a smaller timestep, longer segments, a lower"
            " force limit or hold points further apart"
        )
    return CableDiscretization(
        arc=arc,
        rest_lengths=rest,
        masses=masses,
        segment_stiffness=stiffness,
        mass_scaling=alpha,
        max_timestep=vertex_timestep_limit(rest, alpha * masses, force_limit),
    )
