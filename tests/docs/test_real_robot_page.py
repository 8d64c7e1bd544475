"""The code on docs/real-robot.md runs, on the kinematic robot of examples/own_robot.py."""

from __future__ import annotations

import re
import runpy
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "real-robot.md"


def python_blocks(text: str) -> list[str]:
    return re.findall(r"```python\n(.*?)```", text, flags=re.DOTALL)


def test_running_a_task_on_your_robot(capsys: pytest.CaptureFixture[str]) -> None:
    blocks = [b for b in python_blocks(PAGE.read_text(encoding="utf-8")) if "MyRobot()" in b]
    assert len(blocks) == 1
    example = runpy.run_path(str(ROOT / "examples" / "own_robot.py"), run_name="example")
    true_anchor = np.array([0.303, -0.002, 0.08])  # 3.6 mm from the design's

    def my_robot() -> object:
        return example["KinematicRobot"](
            true_anchor, 0.40, 200.0, 0.030, np.array([0.30, 0.32, 0.10]), yaw=np.pi / 2
        )

    namespace: dict[str, object] = {"MyRobot": my_robot}
    exec(compile(blocks[0], str(PAGE), "exec"), namespace)
    report = namespace["report"]
    assert report.success, report  # type: ignore[attr-defined]
    ctx = namespace["ctx"]
    graph = ctx.graph  # type: ignore[attr-defined]
    anchor = graph.points[graph.index_of("fixed", "A1")].position
    assert np.linalg.norm(anchor - true_anchor) < 2e-3
    assert abs(ctx.estimator.elasticity.k_hat - 200.0) < 10.0  # type: ignore[attr-defined]
    assert "FeaturePoint" in capsys.readouterr().out
