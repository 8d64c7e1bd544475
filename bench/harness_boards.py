"""Random harness boards per minute on the campaign pool; prints one JSON object.

    .venv/bin/python bench/harness_boards.py [--boards N] [--workers W] [--seed S]

Runs ``N`` random boards (default 4) of ``tautwire reproduce harness
--boards`` on ``W`` worker processes (default 2, this project's machine),
each board drawn, planned, simulated closed loop and scored exactly as the
campaign does it, and prints:

- ``boards_per_minute``: boards finished per minute of wall time;
- ``seconds_per_board``: wall time per board and worker;
- ``sim_seconds_per_board`` and ``realtime_factor``: simulated time per
  board, and simulated over wall time summed over the workers;
- ``minutes_for_50``: what the issue's 50-board campaign would take at this
  rate (goal: 15 minutes on 2 workers);
- ``completed``, ``false_successes``: what the boards gave (a benchmark
  that ran wrong boards would be no benchmark).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import tempfile
import time
from typing import Any

from tautwire.experiments.harness import reproduce_harness_boards


def measure(boards: int, workers: int, seed: int) -> dict[str, Any]:
    """Run the boards in a scratch folder; the rates."""
    with tempfile.TemporaryDirectory() as out:
        t0 = time.perf_counter()
        report = reproduce_harness_boards(boards, workers=workers, seed=seed, out_dir=out)
        wall = time.perf_counter() - t0
    records = report.get("board_records", [])
    sim = sum(float(r.get("sim_time") or 0.0) for r in records)
    return {
        "boards": boards,
        "workers": workers,
        "seed": seed,
        "wall_time_s": round(wall, 1),
        "boards_per_minute": round(60.0 * boards / wall, 3),
        "seconds_per_board": round(wall * workers / boards, 1),
        "sim_seconds_per_board": round(sim / max(len(records), 1), 1),
        "realtime_factor": round(sim / (wall * workers), 3),
        "minutes_for_50": round(50.0 * wall / boards / 60.0, 1),
        "completed": report.get("completed"),
        "false_successes": report.get("false_successes"),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--boards", type=int, default=4)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    result = measure(args.boards, args.workers, args.seed)
    result["machine"] = {
        "cpus": os.cpu_count(),
        "processor": platform.processor() or platform.machine(),
        "python": platform.python_version(),
    }
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()
