"""Plan and run a route: from a cable's target route to the task, run in the simulator.

A cable fixed at anchor A1 must be pushed into clip C1. The scenario gives
only the route (``route:`` on the cable, no ``task:``); the planner
(:mod:`tautwire.tasks.planner`) turns it into primitives and moves, each with
the reason it is there, and checks every gripper point against the reach,
the clip's height and slot, and the cable's length. The planned task is
itself a valid scenario task: pasted into the file, it validates.

:func:`~tautwire.experiments.run_scenario.run_scenario` then runs the
planned task (a scenario with routes and no task runs the planner's) in the
MuJoCo world. The robot is blind: each step's outcome is what it concluded
from its force-torque sensor, and ``route_done`` is its claim that the cable
is on its route. Each step's truth and the cable's ``route_truth`` are what
the simulator shows, read only to score the run: a success the simulator
denies counts as a false success.

Run: python examples/plan_route.py [--seed N]
"""

from __future__ import annotations

import argparse

import yaml

from tautwire.experiments.run_scenario import RunResult, run_scenario
from tautwire.scenario import parse_scenario
from tautwire.scenario.route_problem import plan_scenario, task_yaml

SCENARIO = """
version: 1
name: anchor-to-clip
seed: 0
robot:
  control_period: 0.004
  force_limit: 15.0
  sensor: {arm: both, noise_force: 0.05, noise_torque: 0.002}
  grippers:
    left:  {position: [0.42, 0.20, 0.10]}
    right: {position: [0.40, -0.05, 0.12]}
board:
  fixtures:
    - {name: A1, type: anchor, position: [0.10, 0.20, 0.08]}
    - {name: C1, type: clip, position: [0.30, 0.20, 0.08], yaw: 0.0, push_force: 2.5}
cables:
  - name: W1
    length: 0.60
    mass_per_length: 0.030
    stiffness: 200.0
    radius: 0.0025
    start: A1
    held_by: {arm: left, at: 0.35}
    route:
      - {fixture: C1}
"""


def main(seed: int = 0) -> RunResult:
    """Plan the route, check the plan validates as a task, run it and score it.

    Args:
        seed: Seed of the simulated world (sensor noise).

    Returns:
        The run's result: per step its outcome and truth, per cable
        ``route_done`` and ``route_truth``.
    """
    scenario = parse_scenario(SCENARIO, source="anchor-to-clip")
    plan = plan_scenario(scenario)
    print("plan:")
    for i, step in enumerate(plan.steps, start=1):
        params = ", ".join(
            f"{k}={v:.3g}" if isinstance(v, float) else f"{k}={v}"
            for k, v in step.params.items()
            if k != "cable"
        )
        print(f"{i:2d}. {step.primitive}({params})  # {step.why}")

    # the plan is a task the schema accepts: paste it into the file and validate
    data = yaml.safe_load(SCENARIO)
    data["task"] = yaml.safe_load(task_yaml(plan))["task"]
    planned = parse_scenario(yaml.safe_dump(data, sort_keys=False), source="planned")
    print(f"the planned task validates: {len(planned.task)} steps")

    # run it: no task in the scenario, so the runner runs the planner's
    result, _, _ = run_scenario(scenario, seed=seed)
    print(f"run (seed {seed}):")
    for i, done in enumerate(result.steps, start=1):
        name = f"{done['letter']} {done['primitive']}" if done["letter"] else done["primitive"]
        print(f"{i:2d}. {name}: {done['outcome']} after {done['sim_time']:.1f} s, {done['detail']}")
        verdict = "agrees" if done["truth"]["agrees"] else "DISAGREES"
        print(f"    truth {verdict}: {done['truth']['detail']}")
    for cable in result.cables:
        truth = cable["route_truth"]
        print(
            f"cable {cable['name']}: route_done {cable['route_done']}; the simulator "
            f"{'agrees' if truth['agrees'] else 'disagrees'}: {truth['detail']}"
        )
    print(
        f"success {result.success}, {result.false_successes} false successes, "
        f"{result.sim_time:.1f} s simulated in {result.wall_time:.1f} s"
    )
    return result


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=0, help="seed of the simulated world")
    main(parser.parse_args().seed)
