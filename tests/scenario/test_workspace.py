from __future__ import annotations

from tautwire.scenario.workspace import WORKSPACE, Workspace


def test_workspace_box_bounds_are_inclusive() -> None:
    assert WORKSPACE.contains((-0.2, -0.6, 0.0))
    assert WORKSPACE.contains((0.8, 0.6, 0.6))
    assert not WORKSPACE.contains((0.8001, 0.0, 0.1))
    assert not WORKSPACE.contains((0.3, 0.0, -0.001))


def test_describe() -> None:
    box = Workspace(lower=(0.0, -1.0, 0.0), upper=(1.0, 1.0, 0.5))
    assert box.describe() == "x in [0, 1], y in [-1, 1], z in [0, 0.5] m"
