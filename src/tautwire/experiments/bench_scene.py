"""Speed of the simulated world, for ``bench/run.py``."""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from tautwire.robot import Command
from tautwire.scenario import load_scenario
from tautwire.scenario.registry import scenario_path
from tautwire.sim.build import build_world, robot_of


def measure_sim_speed(seconds: float = 10.0) -> dict[str, Any]:
    """Real-time factor and physics step time of the demo scene (anchor-rotate).

    The robot is driven at its control period with a slow circular twist for
    ``seconds`` of simulated time, on one core (this process).
    """
    scenario = load_scenario(scenario_path("anchor-rotate"))
    world = build_world(scenario)
    robot = robot_of(world)
    n = round(seconds / robot.control_period)
    twist = np.zeros(12)
    t0 = time.perf_counter()
    for i in range(n):
        phase = 2.0 * np.pi * i / 1000.0
        twist[0:3] = (0.02 * np.cos(phase), 0.02 * np.sin(phase), 0.0)
        robot.act(Command(twist.copy()))
        robot.observe()
    wall = time.perf_counter() - t0
    steps = n * world.substeps
    return {
        "sim_scene": "anchor-rotate",
        "sim_seconds": n * robot.control_period,
        "sim_realtime_factor": round(n * robot.control_period / wall, 2),
        "sim_step_us": round(wall / steps * 1e6, 2),
        "sim_control_period_us": round(wall / n * 1e6, 2),
        "sim_timestep": world.timestep,
    }
