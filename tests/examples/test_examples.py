"""Every script in examples/ runs, seeded, and gets what its docstring promises."""

from __future__ import annotations

import runpy
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def example_main(name: str) -> Callable[..., Any]:
    """The ``main`` function of ``examples/<name>.py`` (loaded without running it)."""
    namespace = runpy.run_path(str(EXAMPLES / f"{name}.py"), run_name="example")
    main = namespace["main"]
    assert callable(main)
    return main  # type: ignore[no-any-return]


def test_every_example_is_tested() -> None:
    tested = {"contact_filter_on_arrays", "own_robot", "step_by_step", "plan_route"}
    scripts = {p.stem for p in EXAMPLES.glob("*.py")}
    assert scripts <= tested, f"untested examples: {sorted(scripts - tested)}"
    assert len(scripts) >= 4


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_contact_filter_on_arrays(seed: int, capsys: pytest.CaptureFixture[str]) -> None:
    result = example_main("contact_filter_on_arrays")(seed)
    # the README's goals for the synthetic circle, on the example's own data
    assert result["half"] <= 1.5
    assert result["full"] <= 1.0
    assert result["batch"] <= 1.0
    assert 1 <= result["change_samples"] <= 5
    assert result["after_change"] <= 2.0
    assert "Kalman filter" in capsys.readouterr().out


def test_contact_filter_runs_as_a_script() -> None:
    done = subprocess.run(
        [sys.executable, str(EXAMPLES / "contact_filter_on_arrays.py"), "--seed", "3"],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert "batch least squares" in done.stdout


def test_own_robot(capsys: pytest.CaptureFixture[str]) -> None:
    result = example_main("own_robot")(0)
    assert abs(result["k_hat"] - 200.0) / 200.0 < 0.05
    # the force alone moved the estimate from the 5 mm-off design onto the anchor
    assert result["anchor_error"] < 3e-3
    assert result["anchor_error"] < 0.5 * result["design_error"]
    out = capsys.readouterr().out
    assert "D single_arm_tension: success" in out
    assert "I rotate_around_feature_point: success" in out


@pytest.mark.slow
def test_step_by_step(capsys: pytest.CaptureFixture[str]) -> None:
    errors = example_main("step_by_step")("peg-change", 2)
    # both contacts found within the truth check's tolerances: 3 mm for the
    # anchor, the peg's radius (8 mm) + 3 mm for the peg
    assert errors["A1"] < 3.0
    assert errors["P1"] < 11.0
    out = capsys.readouterr().out
    assert out.count("success after") == 2
    assert "contact  P1" in out


def test_plan_route(capsys: pytest.CaptureFixture[str]) -> None:
    result = example_main("plan_route")(0)
    out = capsys.readouterr().out
    assert "the planned task validates: 4 steps" in out
    # the planner's task ran to its end: tension, the move over the clip, G, F
    assert [s["primitive"] for s in result.steps] == [
        "single_arm_tension",
        "move",
        "gripper_alignment",
        "single_arm_clipping",
    ]
    assert all(s["outcome"] == "success" for s in result.steps), result.steps
    # every success is one the simulator agrees with, and the route is truly done
    assert result.false_successes == 0, [s["truth"] for s in result.steps]
    assert all(s["truth"]["agrees"] for s in result.steps)
    (w1,) = result.cables
    assert w1["route_done"] is True
    assert w1["route_truth"]["agrees"], w1["route_truth"]
    assert result.success
    assert "cable W1: route_done True; the simulator agrees: C1: in its jaws" in out
