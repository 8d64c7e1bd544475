"""Every shipped scenario runs to success in the simulator, with every claim true.

The same path as ``tautwire run NAME``: the name resolved to the packaged
file, loaded, planned from its routes where it has no task, simulated and
scored against the simulator's truth.
"""

from __future__ import annotations

import pytest

pytest.importorskip("tautwire.sim")  # sets MUJOCO_GL before MuJoCo is first imported

from tautwire.experiments.run_scenario import run_scenario
from tautwire.scenario import load_scenario
from tautwire.scenario.registry import resolve_scenario, scenario_names

#: Shipped scenarios that do not yet run to success, and why (measured).
NOT_YET: dict[str, str] = {}
#: Shipped scenarios run to success by a test of their own (the same checks and more).
OWN_TEST = {"harness": "tests/tasks/test_harness.py"}


@pytest.mark.slow
@pytest.mark.parametrize(
    "name",
    [
        pytest.param(n, marks=pytest.mark.xfail(reason=NOT_YET[n], strict=False))
        if n in NOT_YET
        else n
        for n in scenario_names()
        if n not in OWN_TEST
    ],
)
def test_a_shipped_scenario_succeeds_truthfully(name: str) -> None:
    result, _, _ = run_scenario(load_scenario(resolve_scenario(name)))
    failed = [(s["primitive"], s["cause"], s.get("detail")) for s in result.steps if s["cause"]]
    assert result.success, failed
    assert result.false_successes == 0, [s["truth"] for s in result.steps]
    for cable in result.cables:
        if cable["route_done"] is not None:
            assert cable["route_done"] and cable["route_truth"]["agrees"], cable


def test_a_scenario_left_to_its_own_test_has_one() -> None:
    from pathlib import Path

    root = Path(__file__).resolve().parents[2]
    for name, path in OWN_TEST.items():
        assert name in scenario_names()
        assert (root / path).is_file()
        assert f'scenario_path("{name}")' in (root / path).read_text()
