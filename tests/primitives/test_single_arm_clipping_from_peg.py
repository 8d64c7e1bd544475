"""F from a peg aims from where the cable leaves the peg, and a missed clip reads as missed.

The cable runs from an anchor round a peg (its initial routing) to the
gripper, over a clip 80 mm past the peg along the cable (slot along it).
F aims the cable from the peg's tangent point, a peg + cable radius beside
the axis: the cable snaps in, F says so and the simulator agrees. Aimed
from beyond the axis (forced here: 6 mm further from the tangent point),
the cable is pressed down beside the clip: F must report ``not_clipped``
(the force line passes far below the seat), never a success. (Aimed from
the axis itself, a peg + cable radius off, the cable came down on the
clip's wall top since the walls are 5 mm thick, and F's new alignment
seated it: a true success.)
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("mujoco")

from tautwire.experiments.run_scenario import run_scenario
from tautwire.primitives.single_arm_clipping import SingleArmClipping
from tautwire.scenario import Scenario
from tautwire.scenario.loader import scenario_from_data

SCENE = {
    "version": 1,
    "name": "f-from-peg",
    "seed": 3,
    "robot": {
        "control_period": 0.004,
        "force_limit": 15.0,
        "sensor": {"arm": "left", "noise_force": 0.05, "noise_torque": 0.002},
        "grippers": {
            "left": {"position": [0.313, 0.087, 0.10]},
            "right": {"position": [0.40, -0.25, 0.12]},
        },
    },
    "board": {
        "fixtures": [
            {"name": "A1", "type": "anchor", "position": [0.05, 0.20, 0.085]},
            {"name": "P1", "type": "peg", "position": [0.20, 0.20, 0.05], "radius": 0.006,
             "height": 0.06},
            {"name": "C1", "type": "clip", "position": [0.2566, 0.1434, 0.078], "yaw": -0.7854,
             "push_force": 2.5},
        ]
    },
    "cables": [
        {"name": "W1", "length": 0.5, "mass_per_length": 0.03, "stiffness": 200.0,
         "radius": 0.0025, "start": "A1", "via": ["P1"], "held_by": {"arm": "left", "at": 0.325}}
    ],
    "task": [
        {"primitive": "single_arm_tension", "arm": "left", "force": 3.0},
        {"primitive": "gripper_alignment", "arm": "left"},
        {"primitive": "single_arm_clipping", "arm": "left", "clip": "C1"},
    ],
}  # fmt: skip


def _scene() -> Scenario:
    return scenario_from_data(SCENE)


@pytest.mark.slow
def test_f_from_a_peg_aims_from_the_tangent_point_and_clips() -> None:
    result, ctx, _ = run_scenario(_scene())
    assert [s["outcome"] for s in result.steps] == ["success"] * 3, result.steps
    f = result.steps[2]
    assert f["truth"]["agrees"] and "is in the jaws of C1" in f["truth"]["detail"]
    assert result.success and result.false_successes == 0
    assert ctx.graph.index_of("fixed", "C1") is not None


@pytest.mark.slow
def test_a_cable_pressed_beside_the_clip_reads_as_not_clipped(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # aim from 6 mm beyond the peg's axis, away from the tangent point: the
    # cable comes down beside the clip (10.9 mm off the slot when lifted)
    away = 0.006 * np.array([-np.sqrt(0.5), -np.sqrt(0.5), 0.0])
    monkeypatch.setattr(
        SingleArmClipping,
        "_leave",
        lambda self, ctx, state, p, info: np.array(state.contact) + away,
    )
    result, ctx, _ = run_scenario(_scene())
    f = result.steps[2]
    assert f["outcome"] == "failure" and f["cause"] == "not_clipped", f
    assert "is not in the jaws of C1" in f["truth"]["detail"]
    assert result.false_successes == 0
    assert ctx.graph.index_of("fixed", "C1") is None
