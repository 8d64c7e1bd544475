"""Where a harness run's physics time goes; prints one JSON object.

    .venv/bin/python bench/harness_physics.py [--steps K] [--seed S]

Runs the first ``K`` steps (default 12: W1 up to its winding round P1) of
the shipped ``harness`` scenario closed loop, exactly as ``tautwire run``
does, keeping the simulated world, and reads MuJoCo's own counters after
the run (``mjData.timer``, ``mjData.warning``):

- ``step_us`` and the stages of a physics step [us, mean]: ``constraint``,
  ``position`` (``collision`` of it), ``velocity`` and ``smooth_rest``, the
  rest of ``mj_forward``: mostly the PCG solve of the discrete integrator's
  effective metric M + (h^2 + h d) K for the smooth acceleration;
- ``pcg_capped_share``: the share of physics steps whose PCG ran to
  ``opt.iterations`` without reaching ``opt.tolerance`` (MuJoCo counts each
  as ``mjWARN_INERTIA``);
- ``realtime_factor``: simulated over wall time of the whole run (physics,
  primitives, estimators and the truth audit), and ``mj_step_share``, the
  physics steps' part of the wall time.

The microseconds depend on the machine and its load; the shares much less.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
from typing import Any

# tautwire.sim chooses MuJoCo's offscreen GL backend (EGL) before MuJoCo is
# imported: this script imports mujoco only after it
from tautwire.experiments.run_scenario import run_scenario
from tautwire.scenario.loader import load_scenario, scenario_from_data
from tautwire.scenario.registry import scenario_folder
from tautwire.scenario.writer import scenario_document


def measure(steps: int, seed: int) -> dict[str, Any]:
    """Run the shipped harness's first ``steps`` steps; MuJoCo's counters."""
    import mujoco

    document = scenario_document(load_scenario(scenario_folder() / "harness.yaml"))
    document["task"] = document["task"][:steps]
    scenario = scenario_from_data(document, source="harness (first steps)")
    kept: dict[str, Any] = {}
    result, _, _ = run_scenario(scenario, seed, on_world=lambda w: kept.setdefault("world", w))
    data, model = kept["world"].data, kept["world"].model

    def mean_us(timer: mujoco.mjtTimer) -> float:
        t = data.timer[int(timer)]
        return 1e6 * t.duration / max(t.number, 1)

    step = data.timer[int(mujoco.mjtTimer.mjTIMER_STEP)]
    forward = mean_us(mujoco.mjtTimer.mjTIMER_FORWARD)
    stages = {
        "constraint": mean_us(mujoco.mjtTimer.mjTIMER_CONSTRAINT),
        "position": mean_us(mujoco.mjtTimer.mjTIMER_POSITION),
        "collision": mean_us(mujoco.mjtTimer.mjTIMER_POS_COLLISION),
        "velocity": mean_us(mujoco.mjtTimer.mjTIMER_VELOCITY),
    }
    rest = forward - stages["constraint"] - stages["position"] - stages["velocity"]
    capped = int(data.warning[int(mujoco.mjtWarning.mjWARN_INERTIA)].number)
    return {
        "steps_run": len(result.steps),
        "sim_time_s": round(result.sim_time, 3),
        "wall_time_s": round(result.wall_time, 3),
        "realtime_factor": round(result.sim_time / result.wall_time, 3),
        "physics_steps": int(step.number),
        "step_us": round(1e6 * step.duration / max(step.number, 1), 1),
        **{f"{k}_us": round(v, 1) for k, v in stages.items()},
        "smooth_rest_us": round(rest, 1),
        "pcg_capped_share": round(capped / max(step.number, 1), 3),
        "mj_step_share": round(step.duration / result.wall_time, 3),
        "opt_iterations": int(model.opt.iterations),
        "opt_tolerance": float(model.opt.tolerance),
        "nv": int(model.nv),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=12, help="run the first K planned steps")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    report = measure(args.steps, args.seed)
    import mujoco

    report["machine"] = {
        "cpu": platform.processor() or platform.machine(),
        "cores": os.cpu_count(),
        "mujoco": mujoco.__version__,
    }
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
