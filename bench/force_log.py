"""Reading and estimating a large force log: wall time and peak memory; prints JSON.

    .venv/bin/python bench/force_log.py              # 1e6 rows (issue 12's case)
    .venv/bin/python bench/force_log.py --rows 100000

Writes a seeded synthetic log (a gripper circling a contact, 4 N, 0.05 N
noise; :func:`tautwire.experiments.synthetic_circle.circle`) with
:func:`~tautwire.estimation.write_force_log`, then in a fresh child process
(so that the peak memory is the reader's and the estimator's alone):
``read_s`` for :func:`~tautwire.estimation.read_force_log`, ``estimate_s``
for :func:`~tautwire.estimation.estimate_force_log`, and ``peak_rss_mb``,
the child's maximum resident set size (Python and numpy included, about
67 MB on their own). ``cli_s`` / ``cli_peak_rss_mb``: the same through
``tautwire estimate LOG.csv`` (text output), as a user runs it. ``goal``:
issue 12's bound for 1e6 rows (reported for that size only), read and
estimated in <= 20 s and <= 500 MB.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from tautwire.estimation import write_force_log
from tautwire.experiments.synthetic_circle import circle

#: Issue 12's bound for a 1e6-row log: read and estimated within [s] and [MB].
GOAL_ROWS = 1_000_000
GOAL_TOTAL_S = 20.0
GOAL_PEAK_RSS_MB = 500.0

_CHILD = """
import json, resource, sys, time
from tautwire.estimation import estimate_force_log, read_force_log
t0 = time.perf_counter()
log = read_force_log(sys.argv[1])
t1 = time.perf_counter()
result = estimate_force_log(log)
t2 = time.perf_counter()
print(json.dumps({"read_s": t1 - t0, "estimate_s": t2 - t1, "rows": len(log),
                  "rss_kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss}))
"""


def _child_rss_mb(before: int) -> float:
    """Peak RSS [MB] of the largest child waited for since ``before`` was taken."""
    return max(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, before) / 1024.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--no-cli", action="store_true", help="skip the tautwire estimate run")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "log.csv"
        t0 = time.perf_counter()
        data = circle(0, n=args.rows)
        write_force_log(path, np.arange(args.rows) / 250.0, data.p_gripper, data.f_sens)
        write_s = time.perf_counter() - t0
        child = subprocess.run(
            [sys.executable, "-c", _CHILD, str(path)], check=True, capture_output=True, text=True
        )
        inner = json.loads(child.stdout)
        report = {
            "rows": inner["rows"],
            "file_mb": round(path.stat().st_size / 1e6, 1),
            "write_s": round(write_s, 2),
            "read_s": round(inner["read_s"], 2),
            "estimate_s": round(inner["estimate_s"], 2),
            "total_s": round(inner["read_s"] + inner["estimate_s"], 2),
            "peak_rss_mb": round(inner["rss_kb"] / 1024.0, 1),
        }
        if args.rows == GOAL_ROWS:
            report["goal"] = {
                "total_s_max": GOAL_TOTAL_S,
                "peak_rss_mb_max": GOAL_PEAK_RSS_MB,
                "met": (
                    report["total_s"] <= GOAL_TOTAL_S and report["peak_rss_mb"] <= GOAL_PEAK_RSS_MB
                ),
            }
        if not args.no_cli:
            cli = Path(sys.executable).with_name("tautwire")
            t0 = time.perf_counter()
            run = subprocess.run([str(cli), "estimate", str(path)], capture_output=True, text=True)
            report["cli_s"] = round(time.perf_counter() - t0, 2)
            report["cli_status"] = run.returncode
            report["cli_peak_rss_mb"] = round(_child_rss_mb(0), 1)
        report["machine"] = {
            "cpu": platform.processor() or platform.machine(),
            "cores": os.cpu_count(),
            "python": platform.python_version(),
            "numpy": np.__version__,
            "platform": platform.platform(),
        }
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
