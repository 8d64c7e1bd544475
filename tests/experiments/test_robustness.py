"""The robustness campaign's bookkeeping: runs, figures, files (fake trials, no simulation)."""

from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Any

import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.experiments.campaign import failed_trial
from tautwire.experiments.robustness import (
    CSV_FILE,
    JSON_FILE,
    LETTER,
    MD_FILE,
    STIFFNESS_PLOT,
    YAW_PLOT,
    RobustnessTrial,
    figures,
    parse_indices,
    reproduce_robustness,
    robustness_specs,
    runs_of,
)
from tautwire.experiments.robustness_scene import draw_fault
from tautwire.experiments.trial import TrialResult, TrialSpec, trial_seed


def _run(half: str, **fields: Any) -> dict[str, Any]:
    run: dict[str, Any] = {
        "half": half,
        "fault": None if half == "clean" else "spike",
        "fault_at": None if half == "clean" else 1.0,
        "fault_entry": None,
        "fixture_type": "anchor",
        "reported_success": True,
        "tension_success": True,
        "success": True,
        "clean": True,
        "cause": None,
        "failed_step": None,
        "detail": "ok",
        "false_successes": 0,
        "max_force": 3.0,
        "true_max_force": 3.1,
        "over_force_limit": False,
        "contact_estimated": True,
        "contact_error": 0.001,
        "contact_tolerance": 0.003,
        "contact_std": 0.0005,
        "contact_within": True,
        "made_up": 0,
        "wrong_trusted": 0,
        "k_hat": 100.0,
        "k_true": 100.0,
        "k_nominal": 100.0,
        "k_ratio": 1.0,
        "nees_samples": 10,
        "nees_within": 9,
        "sim_time": 5.0,
        "wall_time": 1.0,
    }
    run.update(fields)
    return run


def fake_trial(spec: TrialSpec) -> TrialResult:
    """Trial 1: a false success on the clean run; trial 2 crashes (plain failure); else clean."""
    if spec.index == 2:
        return failed_trial(spec, "crashed", "the worker died")
    clean = _run("clean", **{"input.tool_yaw_to_cable": 0.1 * spec.index})
    if spec.index == 1:
        clean.update(
            success=False, clean=False, cause="false_success", false_successes=1, k_ratio=0.5
        )
    fault = _run("fault", contact_error=0.01, contact_within=False, clean=False)
    inputs: dict[str, float | str] = {"tool_yaw_to_cable": 0.1 * spec.index, "stiffness": 50.0}
    return RobustnessTrial(
        LETTER,
        "robustness",
        spec.index,
        spec.seed,
        inputs,
        "success",
        None,
        "",
        runs=(clean, fault),
    )


def test_figures_count_rates_quantiles_and_nees() -> None:
    runs = [
        _run("clean"),
        _run("clean", contact_error=0.004, contact_within=False, clean=False, k_ratio=1.2),
        _run(
            "clean",
            success=False,
            clean=False,
            cause="timeout",
            contact_estimated=False,
            over_force_limit=True,
            true_max_force=16.0,
            made_up=2,
            nees_samples=0,
            nees_within=0,
        ),
    ]
    f = figures(runs)
    assert (f["runs"], f["successes"], f["clean"]) == (3, 2, 1)
    assert f["success_rate"] == pytest.approx(2 / 3) and f["clean_rate"] == pytest.approx(1 / 3)
    assert f["over_force_limit"] == 1 and f["true_max_force"] == 16.0
    assert f["contact_error"]["n"] == 2 and f["contact_error"]["max"] == 0.004
    assert f["k_hat_within_10pct"] == pytest.approx(2 / 3)
    assert f["k_hat_error"]["max"] == pytest.approx(0.2)
    assert f["nees"] == {"samples": 20, "within_3std": 18, "coverage": pytest.approx(0.9)}
    assert f["causes"] == {"timeout": 1}
    assert f["runs_with_made_up_points"] == 1 and f["made_up_points"] == 2
    assert figures([])["success_rate"] is None


def test_a_crashed_trial_counts_as_failed_runs() -> None:
    spec = TrialSpec(LETTER, 4, 99)
    rows = runs_of(failed_trial(spec, "crashed", "the worker died"), faults=True)
    assert [(r["half"], r["success"], r["cause"]) for r in rows] == [
        ("clean", False, "crashed"),
        ("fault", False, "crashed"),
    ]
    assert all(r["trial"] == 4 and r["seed"] == 99 for r in rows)
    assert len(runs_of(failed_trial(spec, "hung", "slow"), faults=False)) == 1


def test_specs_and_indices() -> None:
    specs = robustness_specs(3, 5)
    assert [(s.letter, s.index, s.seed) for s in specs] == [
        (LETTER, i, trial_seed(5, LETTER, i)) for i in range(3)
    ]
    assert [s.index for s in robustness_specs(3, 5, only=[7])] == [7]
    assert parse_indices("3, 17") == [3, 17]
    with pytest.raises(InvalidArgumentError, match="trial indices"):
        parse_indices("D:3")
    with pytest.raises(InvalidArgumentError, match="at least 1"):
        robustness_specs(0, 0)


def test_files_of_a_campaign(tmp_path: Path) -> None:
    seen: list[int] = []
    report = reproduce_robustness(
        3, 1, 0, tmp_path, "serial", lambda p: seen.append(p.finished), trial=fake_trial
    )
    assert seen == [0, 1, 2, 3]
    assert (report["trials"], report["finished"], report["planned"]) == (3, 3, 3)
    assert report["successes"] == 1 and report["false_successes"] == 1
    assert report["causes"] == {"crashed": 1, "false_success": 1}
    assert report["faulty"]["runs"] == 3 and report["faulty"]["clean"] == 0
    crashed = draw_fault(trial_seed(0, LETTER, 2), 1.0)["kind"]  # its fault type, from its seed
    assert set(report["per_fault"]) == {"spike", crashed}
    assert json.loads((tmp_path / JSON_FILE).read_text()) == report
    with (tmp_path / CSV_FILE).open(newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [(r["trial"], r["half"]) for r in rows] == [
        (str(i), h) for i in range(3) for h in ("clean", "fault")
    ]
    assert "input.stiffness" in rows[0]
    md = (tmp_path / MD_FILE).read_text()
    assert "| no fault | 3 | 33 % | 33 % | 1 | 0 |" in md
    assert "| fault: spike | 2 |" in md
    assert "--only 0" in md  # the first run that was not clean: trial 0's fault run
    for plot in (YAW_PLOT, STIFFNESS_PLOT):
        assert (tmp_path / plot).stat().st_size > 1000
