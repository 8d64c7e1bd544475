"""Fake trial functions for campaign tests: module-level, so worker processes can load them.

They return at once (or after a few milliseconds, to mix up completion order)
and never simulate anything.
"""

from __future__ import annotations

import os
import signal
import time

from tautwire.experiments.trial import TrialResult, TrialSpec


def quick_trial(spec: TrialSpec) -> TrialResult:
    """Every third trial fails with a timeout; inputs depend on the letter."""
    time.sleep(0.002 * ((spec.index * 7 + ord(spec.letter)) % 5))  # scramble completion order
    failed = spec.index % 3 == 2
    inputs: dict[str, float | str] = {"stiffness": float(spec.seed % 1000), "length": 0.5}
    if spec.letter == "I":
        inputs["sense"] = "negative" if spec.index % 2 else "positive"
    return TrialResult(
        spec.letter,
        f"primitive_{spec.letter}",
        spec.index,
        spec.seed,
        inputs,
        "failure" if failed else "success",
        "timeout" if failed else None,
        "did not reach the set point | in 10 s" if failed else "done",
        1.0 + spec.index,
        2.0,
        0.01,
    )


def raising_trial(spec: TrialSpec) -> TrialResult:
    """Trial 1 raises (as run_trial should never do); the others succeed."""
    if spec.index == 1:
        raise RuntimeError("boom in the trial")
    return quick_trial(spec)


def wrong_type_trial(spec: TrialSpec) -> TrialResult:
    """Returns something that is not a TrialResult."""
    return "not a result"  # type: ignore[return-value]


def dying_trial(spec: TrialSpec) -> TrialResult:
    """Trial D:1 kills its worker process (os._exit); D:2 segfaults; the others succeed."""
    if (spec.letter, spec.index) == ("D", 1):
        os._exit(3)
    if (spec.letter, spec.index) == ("D", 2):
        os.kill(os.getpid(), signal.SIGSEGV)
    return quick_trial(spec)


def exiting_trial(spec: TrialSpec) -> TrialResult:
    """Trial 0 calls sys.exit (a BaseException, not an Exception)."""
    if spec.index == 0:
        raise SystemExit(4)
    return quick_trial(spec)


def printing_trial(spec: TrialSpec) -> TrialResult:
    """Prints a line to stderr, as the simulator's warnings do."""
    import sys

    print(f"warning from {spec.letter}:{spec.index}", file=sys.stderr)
    return quick_trial(spec)


def mixed_trial(spec: TrialSpec) -> TrialResult:
    """D:1 raises, D:2 kills its worker (os._exit), the others are quick_trial."""
    if (spec.letter, spec.index) == ("D", 1):
        raise RuntimeError("boom in the trial")
    if (spec.letter, spec.index) == ("D", 2):
        os._exit(3)
    return quick_trial(spec)


def slow_trial(spec: TrialSpec) -> TrialResult:
    """quick_trial after a fifth of a second (long enough to interrupt a campaign)."""
    time.sleep(0.2)
    return quick_trial(spec)


def hanging_trial(spec: TrialSpec) -> TrialResult:
    """D:1 never returns (well, after ten minutes); the others are quick_trial."""
    if (spec.letter, spec.index) == ("D", 1):
        time.sleep(600.0)
    return quick_trial(spec)


#: Board indices that :func:`fake_board` ran, in this process (serial backend).
BOARDS_RUN: list[int] = []


def fake_board(spec: TrialSpec) -> TrialResult:
    """A harness board without simulation: board 1 fails (not_clipped), board 3 raises."""
    from tautwire.experiments.harness import LETTER, HarnessTrial

    BOARDS_RUN.append(spec.index)
    failed = spec.index == 1
    cause = "error" if spec.index == 3 else ("not_clipped" if failed else None)
    record = {
        "board": spec.index,
        "seed": spec.seed,
        "redraws": 0,
        "completed": cause is None,
        "false_successes": 0,
        "false_steps": [],
        "true_max_force": 5.0,
        "over_force_limit": False,
        "steps": 12,
        "failed_step": None if cause is None else "7 single_arm_clipping (W1)",
        "cause": cause,
        "detail": None if cause is None else "the cable lies 9 mm beside the slot",
        "routes_done": 2 if cause is None else 0,
        "false_routes": 0,
        "model_horizontal_mean": 0.001 * (spec.index + 1),
        "model_horizontal_max": 0.002,
        "model_vertical_mean": 0.001,
        "model_vertical_max": 0.002,
        "sim_time": 30.0,
        "wall_time": 0.01,
    }
    return HarnessTrial(
        LETTER,
        "harness",
        spec.index,
        spec.seed,
        {},
        "success" if cause is None else "failure",
        cause,
        record["detail"] or "",
        5.0,
        30.0,
        0.01,
        record=record,
    )
