"""The campaign's process pool against concurrent.futures; prints JSON.

    .venv/bin/python bench/campaign_pool.py

Two measurements, both with trials that simulate nothing (so the pool is
all that is measured), 2 workers, ``spawn`` start:

- ``overhead_ms_per_trial``: wall time per trial for 400 trials that return
  at once, :func:`tautwire.experiments.campaign.run_campaign` (local
  backend) against ``concurrent.futures.ProcessPoolExecutor.map``;
- ``one_worker_dies``: 20 trials of which trial 3 kills its worker process
  (``os._exit``): how many results each pool returns. The campaign records
  that one trial as crashed and keeps the other 19; the executor breaks as
  a whole (``BrokenProcessPool``) and every trial not yet returned is lost.

A hung trial is not measured: ``ProcessPoolExecutor`` cannot stop one at
all (``Future.cancel`` does nothing to a running call).
"""

from __future__ import annotations

import json
import os
import platform
import time
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from multiprocessing import get_context

from tautwire.experiments.campaign import run_campaign
from tautwire.experiments.trial import TrialResult, TrialSpec

WORKERS = 2


def instant_trial(spec: TrialSpec) -> TrialResult:
    """A trial that returns at once."""
    return TrialResult(spec.letter, "bench", spec.index, spec.seed, {}, "success")


def dying_trial(spec: TrialSpec) -> TrialResult:
    """Trial 3 kills its worker process; the others return at once (after 20 ms)."""
    if spec.index == 3:
        os._exit(3)
    time.sleep(0.02)
    return instant_trial(spec)


def _specs(n: int) -> list[TrialSpec]:
    return [TrialSpec("D", i, i) for i in range(n)]


def _executor_results(trial: object, n: int) -> tuple[int, float]:
    """Results the executor returned for n trials, and its wall time [s]."""
    t0 = time.perf_counter()
    got = 0
    with ProcessPoolExecutor(WORKERS, mp_context=get_context("spawn")) as pool:
        try:
            for _ in pool.map(trial, _specs(n)):  # type: ignore[arg-type]
                got += 1
        except BrokenProcessPool:
            pass
    return got, time.perf_counter() - t0


def main() -> None:
    n = 400
    t0 = time.perf_counter()
    campaign = run_campaign(_specs(n), instant_trial, backend="local", workers=WORKERS)
    campaign_s = time.perf_counter() - t0
    _, executor_s = _executor_results(instant_trial, n)
    dying = run_campaign(_specs(20), dying_trial, backend="local", workers=WORKERS)
    executor_got, _ = _executor_results(dying_trial, 20)
    report = {
        "trials": n,
        "workers": WORKERS,
        "overhead_ms_per_trial": {
            "campaign": round(1e3 * campaign_s / n, 2),
            "process_pool_executor": round(1e3 * executor_s / n, 2),
        },
        "one_worker_dies": {
            "trials": 20,
            "campaign_results": len(dying.results),
            "campaign_crashed": sum(1 for r in dying.results if r.cause == "crashed"),
            "process_pool_executor_results": executor_got,
        },
        "machine": {
            "cpu": platform.processor() or platform.machine(),
            "cores": os.cpu_count(),
            "python": platform.python_version(),
            "platform": platform.platform(),
        },
    }
    assert len(campaign.results) == n
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
