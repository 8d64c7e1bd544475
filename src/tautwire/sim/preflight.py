"""What the simulator would refuse in a valid scenario, found without simulating.

A scenario can be valid and still not simulable: a control period that is
not a whole multiple of the physics timestep, a cable the wave-speed guard
refuses at its force limit, a route the cable is too short for, a model
MuJoCo does not compile, a cable so stiff that the world diverges while it
settles (``stiffness: 1.0e9``). :func:`simulation_issues` runs the checks
the world runs while it is built, each located where it can be, then (with
``build=True``) builds and settles the world itself, so ``tautwire
validate`` reports what a run would fail on before the run.
"""

from __future__ import annotations

import logging
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from tautwire.errors import TautwireError
from tautwire.scenario import Scenario
from tautwire.scenario.issue import Issue
from tautwire.sim.build import world_spec
from tautwire.sim.discretization import discretize_cable
from tautwire.sim.mjcf import scene_model
from tautwire.sim.options import SimOptions, control_substeps
from tautwire.sim.world import SimWorld, compile_model


def simulation_issues(scenario: Scenario, build: bool = True, **options: Any) -> list[Issue]:
    """Everything the simulated world would refuse while it is built from ``scenario``.

    Args:
        scenario: A validated scenario.
        build: Also build and settle the world once the checks pass (a
            second or so; catches a world that diverges while settling).
            MuJoCo's warnings during that build are kept off the terminal:
            the issue says what went wrong.
        **options: Simulation options as :func:`~tautwire.sim.build.build_world` takes them.

    Returns:
        The issues, each located in the scenario where the check knows the
        field (empty: the world builds and settles).

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
        return [Issue((), f"not simulable: {exc}")]
    if build:
        with _quiet_simulator():
            try:
                SimWorld(spec, opt)
            except TautwireError as exc:
                issues.append(Issue((), f"not simulable: {exc}"))
    return issues


@contextmanager
def _quiet_simulator() -> Iterator[None]:
    """Keep the ``tautwire.sim`` logger's MuJoCo warnings off the terminal for a while."""
    logger = logging.getLogger("tautwire.sim")
    handler = logging.NullHandler()
    propagate = logger.propagate
    logger.addHandler(handler)
    logger.propagate = False
    try:
        yield
    finally:
        logger.removeHandler(handler)
        logger.propagate = propagate
