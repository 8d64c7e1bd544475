"""One randomised trial of one primitive (a row of the paper's Table I).

A trial draws a random state for its primitive (fixture placement, gripper
start poses, cable stiffness and length, see
:mod:`tautwire.experiments.trial_scenes`), simulates the primitive (after
the preparatory steps it needs, e.g. tensioning before rotating) and records
how it ended. :func:`run_trial` never raises for a failing trial: a crash
inside the trial (the scene cannot be built, the simulation diverges, a bug)
is a failure with a cause, so that a campaign keeps every other result.
"""

from __future__ import annotations

import time
import traceback
import zlib
from dataclasses import asdict, dataclass, field
from typing import Any

#: The paper's letters, in the order of Table I's rows by letter.
LETTERS: tuple[str, ...] = ("A", "B", "C", "D", "E", "F", "G", "H", "I")


def trial_seed(campaign_seed: int, letter: str, index: int) -> int:
    """A trial's seed: a stable function of the campaign's seed, letter and index.

    Independent of the order in which trials run or of the number of
    workers, so that any single trial can be rerun on its own.
    """
    key = f"{campaign_seed}:{letter}:{index}".encode()
    return zlib.crc32(key) & 0x7FFFFFFF


@dataclass(frozen=True)
class TrialSpec:
    """Which trial to run.

    Attributes:
        letter: The primitive's letter, ``"A"`` to ``"I"``.
        index: The trial's index among its primitive's trials.
        seed: The trial's seed (randomised state and sensor noise).
    """

    letter: str
    index: int
    seed: int


@dataclass(frozen=True)
class TrialResult:
    """How one trial ended.

    Attributes:
        letter: The primitive's letter.
        name: The primitive's name.
        index: The trial's index among its primitive's trials.
        seed: The trial's seed.
        inputs: The randomised inputs (stiffness [N/m], length [m], fixture
            and gripper positions [m], ...), flat and JSON-ready.
        outcome: ``"success"`` or ``"failure"``.
        cause: For a failure, its cause (``force_limit``, ``timeout``,
            ``not_clipped``, ``diverged``, ``error``, ...); None on success.
        detail: A sentence a reader can act on (for a failure: which step
            failed and why).
        max_force: Largest measured force [N] during the trial.
        sim_time: Simulated time [s] of the trial's steps.
        wall_time: Wall time [s] of the whole trial (scene building included).
    """

    letter: str
    name: str
    index: int
    seed: int
    inputs: dict[str, float | str] = field(default_factory=dict)
    outcome: str = "failure"
    cause: str | None = None
    detail: str = ""
    max_force: float = 0.0
    sim_time: float = 0.0
    wall_time: float = 0.0

    @property
    def success(self) -> bool:
        """Whether the trial succeeded."""
        return self.outcome == "success"

    def to_dict(self) -> dict[str, Any]:
        """The result as JSON-ready data."""
        return asdict(self)

    def to_row(self) -> dict[str, Any]:
        """A flat row for a CSV file (inputs as ``input.<name>`` columns)."""
        row = {k: v for k, v in asdict(self).items() if k != "inputs"}
        row.update({f"input.{k}": v for k, v in self.inputs.items()})
        return row


def run_trial(spec: TrialSpec) -> TrialResult:
    """Run one randomised trial; a crash is recorded as a failure, never raised."""
    from tautwire.experiments.trial_scenes import primitive_name, trial_scene

    t0 = time.perf_counter()
    name = primitive_name(spec.letter)
    inputs: dict[str, float | str] = {}
    try:
        scene = trial_scene(spec.letter, spec.seed)
        inputs = dict(scene.inputs)
        return scene.run(spec, t0)
    except Exception as exc:  # a campaign must keep every other trial
        last = traceback.extract_tb(exc.__traceback__)[-1] if exc.__traceback__ else None
        where = f" at {last.filename.rsplit('/', 1)[-1]}:{last.lineno}" if last else ""
        return TrialResult(
            spec.letter,
            name,
            spec.index,
            spec.seed,
            inputs,
            "failure",
            getattr(exc, "cause", None) or "error",
            f"{type(exc).__name__}: {exc}{where}",
            0.0,
            0.0,
            time.perf_counter() - t0,
        )
