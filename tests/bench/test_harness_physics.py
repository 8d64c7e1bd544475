"""bench/harness_physics.py reads MuJoCo's own counters of a harness run."""

from __future__ import annotations

import pytest

from tests.bench import load_script

harness_physics = load_script("harness_physics")


def test_the_first_step_is_timed_stage_by_stage() -> None:
    report = harness_physics.measure(1, 0)  # D on W1: a few seconds simulated
    assert report["steps_run"] == 1
    # one physics step per millisecond of the run (the settle is not counted)
    assert report["physics_steps"] >= 1000 * report["sim_time_s"]
    stages = ("constraint_us", "position_us", "velocity_us", "smooth_rest_us")
    assert all(report[k] > 0.0 for k in stages)
    assert sum(report[k] for k in stages) == pytest.approx(report["step_us"], rel=0.1)
    assert report["collision_us"] < report["position_us"]
    assert 0.0 <= report["pcg_capped_share"] <= 1.0
    assert 0.0 < report["mj_step_share"] < 1.0
