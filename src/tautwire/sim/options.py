"""Simulation settings that a scenario file does not carry.

Every field is a documented default; :func:`tautwire.sim.build.build_world`
accepts each as a keyword argument.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from tautwire.errors import InvalidArgumentError, SimulationError
from tautwire.scenario.models import CLIP_LENGTH


@dataclass(frozen=True)
class SimOptions:
    """Physics settings of the simulated world.

    Attributes:
        timestep: Physics step dt [s]; must divide the control period.
        segment_length: Target rest length [m] of one cable segment; the
            actual segments are at most this long and a vertex sits at every
            held arc length.
        segments: If set, the target number of segments per cable (overrides
            ``segment_length``; a vertex at a held point may add one or two).
        min_segments: Fewest segments per cable.
        max_mass_scaling: Largest vertex mass scaling alpha that the
            wave-speed guard may choose before it refuses the scene.
        wave_speed_safety: The guard requires dt <= safety * l sqrt(alpha rho / T_max).
        cable_damping_time: Time constant [s] of light mass-proportional
            damping on the cable vertices (air drag); 0 disables it.
        tendon_damping_ratio: Damping of each segment spring as a fraction of
            its stiffness [s].
        pad_friction: Friction coefficient of the finger pads on the cable.
        peg_friction: Friction coefficient of pegs and clips on the cable.
        table_friction: Friction coefficient of the table on the cable.
        hold_grip_force: Grip force [N] that a gripper in mode "hold" reports
            (its nominal full grip). The simulated hold itself is rigid: a
            ``connect`` equality at the tool centre point, with the fingers
            held closed around the cable without squeezing it, so the cable
            pivots at the grasp point as in the paper's point model.
        hold_clearance: Gap [m] between each finger pad and the held cable.
        pad_exit: Arc distance [m] from a held point to the vertices on
            either side of it; more than the pads' half length (0.01 m), so
            that the initial cable runs straight through the closed fingers.
        open_force: Force [N] that opens the fingers in mode "open".
        max_opening: Largest distance between the finger pads [m].
        grasp_distance: Largest distance [m] from the tool centre point to a
            cable vertex that mode "hold" can grasp.
        table_height: Height of the table plane [m].
        settle_time: Longest settle phase [s] before the run starts.
        settle_damping_time: Damping time constant [s] during settling.
        settle_speed: The settle phase ends once every vertex is slower than
            this [m/s].
        max_speed: Any degree of freedom faster than this [m/s or rad/s]
            counts as divergence.
        clip_length: Length of a clip along its slot [m].
        solver_tolerance: MuJoCo's ``opt.tolerance``, which also ends the
            iterative M+K solve of the flex (MuJoCo 4's discrete integrator).
            The held vertex is tied to the gripper by a stiff ``connect``
            (constraint regulariser R ~ 1e-3), so an acceleration error of
            1e-2 m/s^2 there reads as 10 N: at MuJoCo's default 1e-8 a stiff
            cable's reading jumped by up to 18 N for one physics step while
            the cable itself moved smoothly. 1e-10 removes these spikes.
    """

    timestep: float = 0.001
    segment_length: float = 0.02
    segments: int | None = None
    min_segments: int = 8
    max_mass_scaling: float = 64.0
    wave_speed_safety: float = 0.8
    cable_damping_time: float = 0.5
    tendon_damping_ratio: float = 1e-3
    pad_friction: float = 0.5
    peg_friction: float = 0.2
    table_friction: float = 0.3
    hold_grip_force: float = 10.0
    hold_clearance: float = 2e-4
    pad_exit: float = 0.012
    open_force: float = 5.0
    max_opening: float = 0.04
    grasp_distance: float = 0.012
    table_height: float = 0.0
    settle_time: float = 3.0
    settle_damping_time: float = 0.1
    settle_speed: float = 1e-3
    max_speed: float = 100.0
    clip_length: float = CLIP_LENGTH
    solver_tolerance: float = 1e-10

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name == "segments" and value is None:
                continue
            if not np.isfinite(value):
                raise InvalidArgumentError(f"option {f.name} must be finite, got {value}")
            allow_zero = f.name in (
                "cable_damping_time",
                "tendon_damping_ratio",
                "table_height",
                "settle_time",
                "hold_grip_force",
                "pad_friction",
                "peg_friction",
                "table_friction",
            )
            if f.name == "table_height":
                continue
            if value < 0.0 or (value == 0.0 and not allow_zero):
                raise InvalidArgumentError(
                    f"option {f.name} must be {'>= 0' if allow_zero else '> 0'}, got {value}"
                )
        if not 0.0 < self.wave_speed_safety <= 1.0:
            raise InvalidArgumentError(
                f"wave_speed_safety must be in (0, 1], got {self.wave_speed_safety}"
            )
        if self.pad_exit <= 0.01:
            raise InvalidArgumentError(
                f"pad_exit must exceed the pads' half length 0.01 m, got {self.pad_exit}"
            )
        if self.max_mass_scaling < 1.0:
            raise InvalidArgumentError(
                f"max_mass_scaling must be >= 1, got {self.max_mass_scaling}"
            )

    @classmethod
    def from_kwargs(cls, **kwargs: Any) -> SimOptions:
        """Build options from keyword arguments, naming the valid ones on a typo.

        Raises:
            InvalidArgumentError: for an unknown option.
        """
        valid = {f.name for f in fields(cls)}
        unknown = sorted(set(kwargs) - valid)
        if unknown:
            raise InvalidArgumentError(
                f"unknown simulation option(s) {unknown}; valid options: {sorted(valid)}"
            )
        return cls(**kwargs)


def control_substeps(control_period: float, timestep: float) -> int:
    """Physics steps per control period: the period must be a whole multiple of dt.

    Args:
        control_period: Time between two robot commands [s].
        timestep: Physics step dt [s].

    Raises:
        SimulationError: if the period is not a whole multiple (>= 1) of the timestep.
    """
    substeps = control_period / timestep
    if abs(substeps - round(substeps)) > 1e-6 or round(substeps) < 1:
        nearest = max(round(substeps), 1) * timestep
        raise SimulationError(
            f"the timestep {timestep} s must divide the control period {control_period} s"
            f" (expected a whole multiple of {timestep} s, e.g. {nearest:g})"
        )
    return round(substeps)
