"""bench/sim_speed.py times a bare mj_step on exactly the states the world steps."""

from __future__ import annotations

import numpy as np

from tautwire.sim.sim_robot import SimRobot
from tests.bench import load_script

sim_speed = load_script("sim_speed")
bare_twin, cable_world, circle_commands, measure = (
    sim_speed.bare_twin,
    sim_speed.cable_world,
    sim_speed.circle_commands,
    sim_speed.measure,
)


def test_the_bare_twin_steps_the_worlds_own_state_to_the_same_result() -> None:
    world = cable_world(0.2)
    robot = SimRobot(world)
    account = dict.fromkeys(("bare", "real", "hook", "steps"), 0.0)
    with bare_twin(world, account) as twin:
        for command in circle_commands(3):
            robot.act(command)
            # same model, same state before the step: the same state after it, bit for bit
            assert np.array_equal(twin.qpos, world.data.qpos)
            assert np.array_equal(twin.qvel, world.data.qvel)
    assert account["steps"] == 3 * world.substeps
    assert account["bare"] > 0.0 and account["real"] > 0.0


def test_measure_reports_the_scene_and_both_timings() -> None:
    out = measure(cable_world(0.2), 0.04)
    assert out["sim_seconds"] == 0.04 and out["nv"] > 0 and out["constraint_rows"] >= 3
    assert out["equality_rows"] == 3  # the one active hold, a connect
    assert out["sim_step_us"] > 0.0 and out["mj_step_us"] > 0.0
    assert set(out["mj_stage_us"]) == {
        "position",
        "velocity",
        "constraint",
        "collision",
        "forward",
        "step",
    }
