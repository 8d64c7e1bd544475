"""What the simulator would refuse in a valid scenario, found without simulating.

A scenario can be valid and still not simulable: a control period that is
not a whole multiple of the physics timestep, a cable the wave-speed guard
refuses at its force limit, a route the cable is too short for, a model
MuJoCo does not compile. :func:`simulation_issues` runs the same checks the
world runs while it is built (up to compiling the model, not settling it),
so ``tautwire validate`` reports them before a run would fail on them.
"""

from __future__ import annotations

from typing import Any

from tautwire.errors import TautwireError
from tautwire.scenario import Scenario
from tautwire.scenario.issue import Issue
from tautwire.sim.build import world_spec
from tautwire.sim.discretization import discretize_cable
from tautwire.sim.mjcf import scene_model
from tautwire.sim.options import SimOptions, control_substeps
from tautwire.sim.world import compile_model


def simulation_issues(scenario: Scenario, **options: Any) -> list[Issue]:
    """Everything the simulated world would refuse while it is built from ``scenario``.

    Args:
        scenario: A validated scenario.
        **options: Simulation options as :func:`~tautwire.sim.build.build_world` takes them.

    Returns:
        The issues, each located in the scenario (empty: the world builds,
        short of settling, which only a simulation can show).

    Raises:
        InvalidArgumentError: for an unknown or invalid option.
    """
    opt = SimOptions.from_kwargs(**options)
    issues: list[Issue] = []
    try:
        control_substeps(scenario.robot.control_period, opt.timestep)
    except TautwireError as exc:
        issues.append(Issue(("robot", "control_period"), f"not simulable: {exc}"))
    try:
        spec = world_spec(scenario)
    except TautwireError as exc:
        return [*issues, Issue((), f"not simulable: {exc}")]
    for n, cable in enumerate(spec.cables):
        try:
            discretize_cable(cable, spec.force_limit, opt)
        except TautwireError as exc:
            issues.append(Issue(("cables", n), f"not simulable: {exc}"))
    if issues:
        return issues
    try:
        compile_model(scene_model(spec, opt).xml)
    except TautwireError as exc:
        issues.append(Issue((), f"not simulable: {exc}"))
    return issues
