"""Median call time of HybridController (not a test: run it by hand).

    .venv/bin/python tests/control/bench_hybrid_controller.py

Prints one JSON object: median microseconds per call for individual and
coordinated control, both with force control on the left arm and speed limits.
"""

import json
import platform
import time

import numpy as np

from tautwire.control import (
    DualPose,
    HybridController,
    Pose,
    SafetyLimits,
    coordinated_pose,
)


def main() -> None:
    rng = np.random.default_rng(1)

    def quaternion() -> np.ndarray:
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        return q if q[0] >= 0 else -q

    current = DualPose(
        Pose(rng.normal(size=3), quaternion()), Pose(rng.normal(size=3), quaternion())
    )
    desired = DualPose(
        Pose(rng.normal(size=3), quaternion()), Pose(rng.normal(size=3), quaternion())
    )
    controller = HybridController(limits=SafetyLimits(max_force=20.0))
    force = np.array([1.0, 2.0, 0.5])
    result = {
        "machine": platform.processor() or platform.machine(),
        "python": platform.python_version(),
    }
    for name, goal in (("individual", desired), ("coordinated", coordinated_pose(desired))):
        times = []
        for _ in range(5000):
            t0 = time.perf_counter()
            controller(current, goal, (2.0, None), (force, None), 300.0)
            times.append(time.perf_counter() - t0)
        result[f"{name}_median_us"] = round(float(np.median(times[1000:])) * 1e6, 1)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
