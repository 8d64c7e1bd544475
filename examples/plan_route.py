"""Plan a route: from a cable's target route to the task that does it.

A cable fixed at anchor A1 must pass peg P1 on its left, wound once round
it, then be pushed into clips C1 and C2. The scenario gives only the route
(``route:`` on the cable, no ``task:``); the planner
(:mod:`tautwire.tasks.planner`) turns it into primitives and moves, each with
the reason it is there, and checks every gripper point against the reach,
each clip's height and slot, and the cable's length. The planned task is
itself a valid scenario task: pasted into the file, it validates. A route
the robot cannot do is refused in one line naming the cable, the route
entry and the reason.

Running a planned task needs the ``move`` and ``release`` steps, which the
runner does not execute yet (the schema and the planner have them): this
example plans and checks, it does not run.

Run: python examples/plan_route.py
"""

from __future__ import annotations

import math

import yaml

from tautwire.scenario import parse_scenario
from tautwire.scenario.route_problem import plan_scenario, task_yaml
from tautwire.tasks.planner import Plan, RouteError

SCENARIO = """
version: 1
name: wind-and-clip
seed: 0
robot:
  sensor: {arm: both}
  grippers:
    left:  {position: [0.30, 0.20, 0.10]}
    right: {position: [0.30, -0.20, 0.10]}
board:
  fixtures:
    - {name: A1, type: anchor, position: [0.05, 0.20, 0.08]}
    - {name: P1, type: peg, position: [0.20, 0.15, 0.05], radius: 0.006, height: 0.06}
    - {name: C1, type: clip, position: [0.35, 0.10, 0.08], yaw: 0.0, push_force: 2.5}
    - {name: C2, type: clip, position: [0.50, 0.10, 0.08], yaw: 0.0, push_force: 2.5}
cables:
  - name: W1
    length: 0.70
    mass_per_length: 0.030
    stiffness: 200.0
    radius: 0.0025
    start: A1
    held_by: {arm: left, at: 0.35}
    route:
      - {fixture: P1, side: left, wind: 1}
      - {fixture: C1}
      - {fixture: C2}
"""


def main() -> Plan:
    """Plan the route, check the plan validates as a task, show a refused route."""
    scenario = parse_scenario(SCENARIO, source="wind-and-clip")
    plan = plan_scenario(scenario)
    for i, step in enumerate(plan.steps, start=1):
        params = ", ".join(
            f"{k}={v:.3g}" if isinstance(v, float) else f"{k}={v}"
            for k, v in step.params.items()
            if k != "cable"
        )
        print(f"{i:2d}. {step.primitive}({params})  # {step.why}")
    (w1,) = plan.cables
    print(
        f"cable W1: {w1.route_length:.3f} m of its 0.70 m routed, "
        f"held by the {w1.arm} gripper at {w1.held_at:.3f} m at the end"
    )
    winding = next(s for s in plan.steps if s.primitive == "rotate_around_feature_point")
    print(f"I winds {math.degrees(float(winding.params['angle'])):.0f} deg about P1")

    # the plan is a task the schema accepts: paste it into the file and validate
    data = yaml.safe_load(SCENARIO)
    data["task"] = yaml.safe_load(task_yaml(plan))["task"]
    planned = parse_scenario(yaml.safe_dump(data, sort_keys=False), source="planned")
    print(f"the planned task validates: {len(planned.task)} steps")

    # too little cable for the route: refused, with the reason
    short = SCENARIO.replace("length: 0.70", "length: 0.40")
    try:
        plan_scenario(parse_scenario(short, source="short"))
    except RouteError as exc:
        print(f"a 0.40 m cable: {exc}")
    return plan


if __name__ == "__main__":
    main()
