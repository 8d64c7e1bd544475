"""tautwire benchmarks: prints one JSON object.

    .venv/bin/python bench/run.py --json            # everything
    .venv/bin/python bench/run.py --json --quick    # fewer repetitions

Figures (medians over thousands of repetitions, microseconds unless named):
- control_tick_us: one full control tick of primitive I's loop: model update
  by constraints + contact filter update + elasticity update + hybrid
  controller for both arms;
- kf_update_us: one ContactPointFilter.update;
- filterpy_kf_update_us: the same measurement fused by filterpy's textbook
  KalmanFilter (predict + update, z/H/R built the same way) as the reference;
- control_tick_filterpy_us: the control tick with filterpy's filter instead;
- guarded_tick_us: the control tick as a run makes it: through the fault
  layer (RobotGuard: act + observe) with the whole-wrench observation (the
  line of action from force and torque); guarded_tick_filterpy_us: the same
  tick with filterpy's KalmanFilter fed the same line; their ratio
  guarded_tick_ratio_vs_filterpy (< 1: ours is faster);
- elasticity_update_us, hybrid_controller_us, model_update_us: the parts;
- the simulated world, where available (``bench/sim_speed.py``, interleaved
  control period by control period with a bare ``mujoco.mj_step`` of the same
  model from the same states): on the demo scene sim_step_us (the world's
  time per 1 ms physics step), mj_step_us (bare MuJoCo), their ratio
  sim_overhead_ratio and sim_realtime_factor; under sim_cables the same per
  cable of 0.2, 0.4, 0.8 and 1.1 m, with MuJoCo's stage timers, contacts and
  constraint rows, and length_exponent_last_two (cost ~ length^p between
  0.8 and 1.1 m);
- harness_boards (``bench/harness_boards.py``): random harness boards of
  ``tautwire reproduce harness --boards`` per minute on 2 workers
  (boards_per_minute, minutes_for_50, realtime_factor), with what they gave.
"""

from __future__ import annotations

import argparse
import json
import platform
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from tautwire.control import DualPose, HybridController, Pose, SafetyLimits
from tautwire.estimation import (
    ContactPointFilter,
    ElasticityEstimator,
    contact_observation,
    update_by_constraints,
)
from tautwire.experiments.synthetic_circle import circle
from tautwire.model import PathGraph


def median_us(fn: Callable[[int], object], n: int, warmup: int = 200) -> float:
    """Median wall time of fn(i) over n calls after a warm-up [us]."""
    for i in range(warmup):
        fn(i)
    times = np.empty(n)
    for i in range(n):
        t0 = time.perf_counter()
        fn(i)
        times[i] = time.perf_counter() - t0
    return round(float(np.median(times)) * 1e6, 2)


def control_benchmarks(n: int) -> dict[str, Any]:
    data = circle(seed=1, n=n + 400, samples_per_circle=125, tension=4.0)
    p, f = data.p_gripper, data.f_sens
    contact = data.contact[0]

    def fresh_filter() -> ContactPointFilter:
        kf = ContactPointFilter(force_noise=0.05)
        for i in range(40):  # past initialisation: measure the running update
            kf.update(p[i], f[i])
        return kf

    kf = fresh_filter()
    kf_us = median_us(lambda i: kf.update(p[40 + i % n], f[40 + i % n]), n)

    from filterpy.kalman import KalmanFilter

    ref_state = fresh_filter()
    fkf = KalmanFilter(dim_x=3, dim_z=2)
    fkf.x = ref_state.x.copy()
    fkf.P = ref_state.P.copy()
    fkf.F = np.eye(3)
    fkf.Q = ref_state.Q.copy()

    def filterpy_update(i: int) -> None:
        j = 40 + i % n
        obs = contact_observation(p[j], f[j], float(np.linalg.norm(p[j] - fkf.x)), 0.05)
        fkf.predict()
        fkf.update(obs.z, H=obs.H, R=obs.R)

    fp_us = median_us(filterpy_update, n)

    est = ElasticityEstimator(force_noise=0.05)
    lengths = 0.2 + 0.002 * np.sin(np.arange(n + 400) * 0.05)
    tensions = 200.0 * (lengths - 0.19)
    el_us = median_us(lambda i: est.update(tensions[i % n], lengths[i % n]), n)

    q = np.array([1.0, 0.0, 0.0, 0.0])
    controller = HybridController(limits=SafetyLimits(max_force=15.0))
    right = Pose(np.array([0.35, -0.25, 0.12]), q)

    def hybrid(i: int) -> np.ndarray:
        j = i % n
        current = DualPose(Pose(p[j], q), right)
        return controller(current, current, (4.0, None), (f[j], None), 200.0)

    hy_us = median_us(hybrid, n)

    graph = PathGraph.from_positions(
        [contact, p[0], p[0] + [0.0, 0.0, -0.1]],
        mass_per_length=0.03,
        kinds=["contact", "gripper", "free"],
    )
    mu_us = median_us(lambda i: update_by_constraints(graph, {0: contact, 1: p[i % n]}), n)

    def tick(kf_update: Callable[[int], object]) -> Callable[[int], None]:
        def run(i: int) -> None:
            j = 40 + i % n
            kf_update(i)
            estimate = kf.x
            update_by_constraints(graph, {0: estimate, 1: p[j]})
            length = float(np.linalg.norm(p[j] - estimate))
            est.update(float(np.linalg.norm(f[j])), length)
            current = DualPose(Pose(p[j], q), right)
            directions = (estimate - p[j], None)
            controller(current, current, (4.0, None), (f[j], None), est.k_hat, directions)

        return run

    primitive_us = primitive_tick_us(n)
    guarded = guarded_tick_benchmarks(n)

    kf = fresh_filter()
    tick_us = median_us(tick(lambda i: kf.update(p[40 + i % n], f[40 + i % n])), n)
    tick_fp_us = median_us(tick(filterpy_update), n)
    return {
        "control_tick_us": tick_us,
        "primitive_I_tick_us": primitive_us,
        "control_tick_filterpy_us": tick_fp_us,
        "kf_update_us": kf_us,
        "filterpy_kf_update_us": fp_us,
        "kf_speedup_vs_filterpy": round(fp_us / kf_us, 2),
        "elasticity_update_us": el_us,
        "hybrid_controller_us": hy_us,
        "model_update_us": mu_us,
        "control_period_us": 4000.0,
        **guarded,
    }


class ReplayRobot:
    """A robot that replays recorded samples (with torques) and ignores commands."""

    def __init__(self, observations: list[Any]) -> None:
        self._obs = observations
        self._i = 0

    @property
    def control_period(self) -> float:
        return 0.004

    def observe(self) -> Any:
        return self._obs[self._i % len(self._obs)]

    def act(self, command: Any) -> None:
        self._i += 1


def guarded_tick_benchmarks(n: int) -> dict[str, float]:
    """The control tick through the fault layer with the whole-wrench line, ours vs filterpy."""
    from filterpy.kalman import KalmanFilter

    from tautwire.estimation.force_line import line_offset_variance, line_point
    from tautwire.robot import Command, GripperState, Observation, Wrench
    from tautwire.tasks.robot_guard import RobotGuard

    data = circle(seed=3, n=n + 400, samples_per_circle=125, tension=4.0)
    p, f = data.p_gripper, data.f_sens
    contact = data.contact[0]
    rng = np.random.default_rng(3)
    # the cable leaves the fingers 10 mm to the side: a torque about the tcp
    side = np.cross([0.0, 0.0, 1.0], (contact - p) / np.linalg.norm(contact - p, axis=1)[:, None])
    tau = np.cross(0.01 * side, f) + 0.002 * rng.standard_normal(f.shape)
    q = np.array([1.0, 0.0, 0.0, 0.0])
    right = GripperState(np.array([0.35, -0.3, 0.12]), q)
    obs = [
        Observation(0.004 * i, GripperState(p[i], q), right, (Wrench("left", f[i], tau[i]),))
        for i in range(len(p))
    ]
    graph = PathGraph.from_positions(
        [contact, p[0], p[0] + [0.0, 0.0, -0.1]],
        mass_per_length=0.03,
        kinds=["contact", "gripper", "free"],
    )
    controller = HybridController(limits=SafetyLimits(max_force=15.0))
    right_pose = Pose(right.position, q)
    zero = Command()

    def make(update: Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]):  # type: ignore[no-untyped-def]
        guard = RobotGuard(ReplayRobot(obs), force_limit=15.0, force_noise=0.05)
        est = ElasticityEstimator(force_noise=0.05)

        def run(i: int) -> None:
            guard.act(zero)
            o = guard.observe()
            w = o.wrenches[0]
            p_g = o.left.position
            estimate = update(p_g, w.force, w.torque)
            update_by_constraints(graph, {0: estimate, 1: p_g})
            length = float(np.linalg.norm(p_g - estimate))
            est.update(float(np.linalg.norm(w.force)), length)
            current = DualPose(Pose(p_g, q), right_pose)
            directions = (estimate - p_g, None)
            controller(current, current, (4.0, None), (w.force, None), est.k_hat, directions)

        return run

    kf = ContactPointFilter(force_noise=0.05, torque_noise=0.002)
    for i in range(40):
        kf.update(p[i], f[i], torque=tau[i])

    def ours(p_g: np.ndarray, force: np.ndarray, torque: np.ndarray) -> np.ndarray:
        kf.update(p_g, force, torque=torque)
        return kf.x

    fkf = KalmanFilter(dim_x=3, dim_z=2)
    fkf.x = kf.x.copy()
    fkf.P = kf.P.copy()
    fkf.F = np.eye(3)
    fkf.Q = kf.Q.copy()

    def theirs(p_g: np.ndarray, force: np.ndarray, torque: np.ndarray) -> np.ndarray:
        point = line_point(p_g, force, torque)
        fn = float(np.linalg.norm(force))
        extra = line_offset_variance(fn, float(np.linalg.norm(point - p_g)), 0.05, 0.002)
        o = contact_observation(point, force, float(np.linalg.norm(point - fkf.x)), 0.05)
        fkf.predict()
        fkf.update(o.z, H=o.H, R=o.R + extra * np.eye(2))
        return np.asarray(fkf.x, dtype=float).reshape(3)

    ours_us = median_us(make(ours), n)
    theirs_us = median_us(make(theirs), n)
    return {
        "guarded_tick_us": ours_us,
        "guarded_tick_filterpy_us": theirs_us,
        "guarded_tick_ratio_vs_filterpy": round(ours_us / theirs_us, 3),
    }


def primitive_tick_us(n: int) -> float:
    """Median time of one step of primitive I, the real loop: ModelEstimator + controller."""
    from tautwire.primitives import RotateAroundFeaturePoint, make_context
    from tautwire.robot import GripperState, Observation, Wrench

    data = circle(seed=2, n=n + 400, samples_per_circle=125, tension=4.0)
    graph = PathGraph.from_positions(
        [data.contact[0], data.p_gripper[0]],
        0.03,
        kinds=["fixed", "gripper"],
        labels=["A1", "left"],
    )
    ctx = make_context(graph, "left")
    q = np.array([1.0, 0.0, 0.0, 0.0])
    right = GripperState(np.array([0.35, -0.3, 0.12]), q)
    obs = [
        Observation(
            0.004 * i,
            GripperState(data.p_gripper[i], q),
            right,
            (Wrench("left", data.f_sens[i], np.zeros(3)),),
        )
        for i in range(n + 400)
    ]
    primitive = RotateAroundFeaturePoint("left", 100.0, speed=0.5, force=4.0, timeout=1e9)
    primitive.start(obs[0], ctx)
    return median_us(lambda i: primitive.step(obs[1 + i]), n)


def sim_benchmarks(seconds: float) -> dict[str, Any]:
    """The simulated world against bare MuJoCo (``bench/sim_speed.py``), where available."""
    try:
        sys.path.insert(0, str(Path(__file__).resolve().parent))
        from sim_speed import sim_benchmarks as measure
    except ImportError as exc:  # the simulated world is not available
        return {"sim_error": f"not available: {exc}"}
    return measure(seconds)


def harness_benchmarks(boards: int) -> dict[str, Any]:
    """Random harness boards per minute on 2 workers (``bench/harness_boards.py``)."""
    try:
        sys.path.insert(0, str(Path(__file__).resolve().parent))
        from harness_boards import measure
    except ImportError as exc:  # the simulated world is not available
        return {"harness_error": f"not available: {exc}"}
    return {"harness_boards": measure(boards, workers=2, seed=0)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true", help="print one JSON object (default)")
    parser.add_argument("--quick", action="store_true", help="fewer repetitions")
    parser.add_argument("--no-sim", action="store_true", help="skip the simulation figures")
    parser.add_argument(
        "--no-harness", action="store_true", help="skip the harness boards (minutes of simulation)"
    )
    args = parser.parse_args(argv)
    n = 2000 if args.quick else 10000
    result: dict[str, Any] = {
        "machine": {
            "cpu": platform.processor() or platform.machine(),
            "python": platform.python_version(),
            "numpy": np.__version__,
            "platform": platform.platform(),
        },
        "repetitions": n,
    }
    result.update(control_benchmarks(n))
    if not args.no_sim:
        result.update(sim_benchmarks(2.0 if args.quick else 10.0))
    if not (args.no_sim or args.no_harness):
        result.update(harness_benchmarks(2 if args.quick else 4))
    json.dump(result, sys.stdout, indent=2)
    sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
