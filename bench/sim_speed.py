"""Speed of the simulated world against bare MuJoCo: prints one JSON object.

    .venv/bin/python bench/sim_speed.py            # the demo scene and the cable lengths
    .venv/bin/python bench/sim_speed.py --quick    # 2 s simulated per scene instead of 10 s

Two figures per scene, taken in the same run, interleaved control period by
control period so that both see the same machine load:

- ``sim_step_us``: the world's time per 1 ms physics step, as a robot drives it
  (``SimRobot.act`` + ``observe``: gripper drive, damping, ``mj_step``, the
  transmitted wrench, the divergence guard, the sensor model), with the
  commands built beforehand;
- ``mj_step_us``: a bare ``mujoco.mj_step`` of the same compiled model from
  the very same states: the world's state is copied (``mj_getState`` with
  ``mjSTATE_INTEGRATION``, which includes the solver's warm start) into a
  second ``MjData`` just before each of the world's own ``mj_step`` calls,
  and stepped there by as many steps. Every other period the bare step runs
  first, in the others after the world's, so cache effects fall on both.

Their ratio ``overhead_ratio`` is the world's cost over bare MuJoCo (robust to
load, unlike the microseconds). For each cable the output also gives MuJoCo's
own stage timers (``mjData.timer``) of the bare steps, the contacts and
constraint rows at the end, and the real-time factor (simulated time over
wall time, 1 ms / ``sim_step_us``).

The cable scene: one cable of the given length from an anchor 0.08 m above
the table to the left gripper, which holds its end 0.92 of the length away
at 0.10 m and circles at 0.02 m/s (the demo scene's motion); from 0.8 m on,
the slack lies on the table. Cable 30 g/m, 200 N/m, radius 2.5 mm, the
default simulation options.
"""

from __future__ import annotations

import argparse
import json
import math
import platform
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import mujoco
import numpy as np

from tautwire.robot import Command
from tautwire.scenario import load_scenario
from tautwire.scenario.registry import scenario_path
from tautwire.sim import (
    AnchorSpec,
    CableSpec,
    GripperSpec,
    HoldSpec,
    SimOptions,
    SimWorld,
    WorldSpec,
)
from tautwire.sim.build import build_world
from tautwire.sim.sim_robot import SimRobot

CABLE_LENGTHS = (0.2, 0.4, 0.8, 1.1)  # m
_STATE = mujoco.mjtState.mjSTATE_INTEGRATION
_STAGES = {
    "position": mujoco.mjtTimer.mjTIMER_POSITION,
    "velocity": mujoco.mjtTimer.mjTIMER_VELOCITY,
    "constraint": mujoco.mjtTimer.mjTIMER_CONSTRAINT,
    "collision": mujoco.mjtTimer.mjTIMER_POS_COLLISION,
    "forward": mujoco.mjtTimer.mjTIMER_FORWARD,
    "step": mujoco.mjtTimer.mjTIMER_STEP,
}


def cable_world(length: float, **options: Any) -> SimWorld:
    """The benchmark's one-cable world (see the module docstring)."""
    spec = WorldSpec(
        fixtures=(AnchorSpec("A", np.array([0.0, 0.0, 0.08])),),
        cables=(
            CableSpec(
                "W", length, 0.03, 200.0, 0.0025, start="A", holds=(HoldSpec("left", length),)
            ),
        ),
        left=GripperSpec(np.array([0.92 * length, 0.0, 0.10]), np.array([1.0, 0.0, 0.0, 0.0])),
        right=GripperSpec(np.array([0.0, -0.5, 0.3])),
        sensor_arms=("left",),
        noise_force=0.05,
        noise_torque=0.002,
        force_limit=15.0,
        seed=0,
    )
    return SimWorld(spec, SimOptions.from_kwargs(**options))


def circle_commands(n: int) -> list[Command]:
    """The left gripper circling at 0.02 m/s, one turn per 1000 control periods."""
    commands = []
    for i in range(n):
        phase = 2.0 * math.pi * i / 1000.0
        twist = np.zeros(12)
        twist[0:3] = (0.02 * math.cos(phase), 0.02 * math.sin(phase), 0.0)
        commands.append(Command(twist))
    return commands


@contextmanager
def bare_twin(world: SimWorld, account: dict[str, float]) -> Iterator[mujoco.MjData]:
    """While active, every ``mj_step`` of ``world`` is also run bare on a copy of its state.

    Yields the twin ``MjData``; ``account`` collects the seconds of the bare
    steps (``bare``), of the world's own (``real``), of the copying (``hook``),
    the steps, and the twin's stage timers (``stage_*``).
    """
    model = world.model
    twin = mujoco.MjData(model)
    state = np.empty(mujoco.mj_stateSize(model, _STATE))
    step = mujoco.mj_step
    clock = time.perf_counter
    calls = [0]

    def timers_off() -> None:
        for stat in twin.timer:
            stat.duration = 0.0
            stat.number = 0

    timers_off()
    stages = dict.fromkeys(_STAGES, 0.0)

    def twin_step(m: mujoco.MjModel, d: mujoco.MjData, n: int = 1) -> None:
        t0 = clock()
        mujoco.mj_getState(m, d, state, _STATE)
        mujoco.mj_setState(m, twin, state, _STATE)
        calls[0] += 1
        if calls[0] % 2:
            t1 = clock()
            step(m, twin, n)
            t2 = clock()
            step(m, d, n)
            t3 = clock()
            bare, real = t2 - t1, t3 - t2
        else:
            t1 = clock()
            step(m, d, n)
            t2 = clock()
            step(m, twin, n)
            t3 = clock()
            real, bare = t2 - t1, t3 - t2
        account["bare"] += bare
        account["real"] += real
        account["hook"] += t3 - t0 - real
        account["steps"] += n

    mujoco.mj_step = twin_step
    try:
        yield twin
    finally:
        mujoco.mj_step = step
        for name, timer in _STAGES.items():
            stages[name] = twin.timer[int(timer)].duration
        account.update({f"stage_{k}": v for k, v in stages.items()})


def measure(world: SimWorld, seconds: float) -> dict[str, Any]:
    """Drive ``world`` for ``seconds``, timed against bare ``mj_step`` (module docstring)."""
    robot = SimRobot(world)
    n = round(seconds / robot.control_period)
    commands = circle_commands(n)
    account = dict.fromkeys(("bare", "real", "hook", "steps"), 0.0)
    act, observe = robot.act, robot.observe
    clock = time.perf_counter
    wall = 0.0
    with bare_twin(world, account):
        for command in commands:
            t0 = clock()
            act(command)
            observe()
            wall += clock() - t0
    steps = account["steps"]
    world_s = wall - account["hook"]
    d = world.data
    rows = d.efc_type[: d.nefc]
    return {
        "sim_seconds": round(n * robot.control_period, 3),
        "sim_step_us": round(world_s / steps * 1e6, 2),
        "mj_step_us": round(account["bare"] / steps * 1e6, 2),
        "overhead_ratio": round(world_s / account["bare"], 3),
        "python_us_per_control_period": round((world_s - account["real"]) / n * 1e6, 2),
        "sim_control_period_us": round(world_s / n * 1e6, 2),
        "sim_realtime_factor": round(n * robot.control_period / world_s, 2),
        "mj_stage_us": {
            k.removeprefix("stage_"): round(v / steps * 1e6, 2)
            for k, v in account.items()
            if k.startswith("stage_")
        },
        "nv": int(world.model.nv),
        "contacts": int(d.ncon),
        "equality_rows": int(np.count_nonzero(rows == mujoco.mjtConstraint.mjCNSTR_EQUALITY)),
        "constraint_rows": int(d.nefc),
    }


def demo_scene(seconds: float) -> dict[str, Any]:
    """The figures of the demo scene ``anchor-rotate`` (0.4 m cable) for ``bench/run.py``."""
    world = build_world(load_scenario(scenario_path("anchor-rotate")))
    out = measure(world, seconds)
    return {
        "sim_scene": "anchor-rotate",
        "sim_timestep": world.timestep,
        **{k: out[k] for k in ("sim_seconds", "sim_realtime_factor", "sim_step_us")},
        "mj_step_us": out["mj_step_us"],
        "sim_overhead_ratio": out["overhead_ratio"],
        "sim_control_period_us": out["sim_control_period_us"],
    }


def cable_lengths(seconds: float, lengths: tuple[float, ...] = CABLE_LENGTHS) -> dict[str, Any]:
    """Per cable length: the world's step against bare MuJoCo, and how the cost grows."""
    per: dict[str, Any] = {}
    for length in lengths:
        world = cable_world(length)
        out = measure(world, seconds)
        out["segments"] = world.scene.discretizations["W"].segments
        per[f"{length:g}"] = out
    result: dict[str, Any] = {"cable_lengths_m": list(lengths), "per_cable": per}
    if len(lengths) >= 2:
        # cost ~ length^p between the two longest cables (p <= 1: no faster than linear)
        a, b = lengths[-2], lengths[-1]
        ta, tb = per[f"{a:g}"]["sim_step_us"], per[f"{b:g}"]["sim_step_us"]
        result["length_exponent_last_two"] = round(math.log(tb / ta) / math.log(b / a), 2)
    return result


def sim_benchmarks(seconds: float) -> dict[str, Any]:
    """Everything this module measures (``bench/run.py`` includes it)."""
    return {**demo_scene(seconds), "sim_cables": cable_lengths(seconds)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true", help="print one JSON object (default)")
    parser.add_argument("--quick", action="store_true", help="2 s simulated per scene")
    parser.add_argument(
        "--lengths", type=float, nargs="+", default=list(CABLE_LENGTHS), help="cable lengths [m]"
    )
    args = parser.parse_args(argv)
    seconds = 2.0 if args.quick else 10.0
    result: dict[str, Any] = {
        "machine": {
            "cpu": platform.processor() or platform.machine(),
            "mujoco": mujoco.__version__,
        },
        **demo_scene(seconds),
        "sim_cables": cable_lengths(seconds, tuple(args.lengths)),
    }
    json.dump(result, sys.stdout, indent=2)
    sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
