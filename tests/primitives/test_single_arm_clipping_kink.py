"""F where the cable comes in at an angle: from an anchor, and out of a clip it turns back from.

A taut cable held from a fixed point over a clip is straight in plan view:
coming in at alpha to the slot, it crosses the clip's 30 mm diagonally,
15 mm tan(alpha) to either side at its ends, and the jaws' axes stand
2.6 mm off the centre line for a 2.5 mm cable. At 8 deg that leaves 0.5 mm
of aim: F's line must pass within ``ALIGN_MISS`` of the seat, and from an
anchor (a point the cable turns freely about) it must not move its far
contact onto the measured pull's line, which adds only the line's own
error (3.9 mm in the 7 deg scene below, and the cable slid off the jaws).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from tautwire.primitives.context import ClipInfo
from tautwire.primitives.single_arm_clipping import ALIGN_MISS, SingleArmClipping

ANCHOR = np.array([0.10, 0.15, 0.08])


def _scene(angle_deg: float, seed: int) -> dict:
    """An anchor, a clip 0.12 m on whose slot is ``angle_deg`` off the line to it."""
    held = 0.26
    grip = [0.10 + 0.85 * held * math.cos(0.1), 0.15 + 0.85 * held * math.sin(0.1), 0.12]
    return {
        "version": 1,
        "name": f"f-kink-{angle_deg:g}",
        "seed": seed,
        "robot": {
            "control_period": 0.004,
            "force_limit": 15.0,
            "sensor": {"arm": "both", "noise_force": 0.05, "noise_torque": 0.002},
            "grippers": {"left": {"position": grip}, "right": {"position": [0.25, -0.25, 0.12]}},
        },
        "board": {
            "fixtures": [
                {"name": "A1", "type": "anchor", "position": ANCHOR.tolist()},
                {"name": "F1", "type": "clip", "position": [0.22, 0.15, 0.08],
                 "yaw": round(math.radians(angle_deg), 4), "push_force": 2.5},
            ]
        },
        "cables": [
            {"name": "W1", "length": 0.8, "mass_per_length": 0.035, "stiffness": 250.0,
             "radius": 0.0025, "start": "A1", "held_by": {"arm": "left", "at": held},
             "route": [{"fixture": "F1"}]}
        ],
    }  # fmt: skip


@pytest.mark.slow
@pytest.mark.parametrize(("angle", "seed"), [(7.0, 0), (10.0, 0), (-10.0, 0), (12.0, 1)])
def test_one_arm_clips_a_cable_that_comes_in_at_an_angle_from_an_anchor(
    angle: float, seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    pytest.importorskip("mujoco")
    from tautwire.experiments.run_scenario import run_scenario
    from tautwire.scenario.loader import scenario_from_data
    from tautwire.tasks import planner

    # one arm (G, F), as where the other gripper holds the other cable
    monkeypatch.setattr(planner, "F_ANGLE", math.radians(30.0))
    monkeypatch.setattr(planner, "SLOT_ANGLE", math.radians(30.0))
    shifts: list[float] = []
    step = SingleArmClipping.on_step

    def watched(self, obs, ctx):  # type: ignore[no-untyped-def]
        command = step(self, obs, ctx)
        shifts.append(float(np.linalg.norm(self._line_shift)))
        return command

    monkeypatch.setattr(SingleArmClipping, "on_step", watched)
    result, _, _ = run_scenario(scenario_from_data(_scene(angle, seed)))
    f = result.steps[-1]
    assert f["outcome"] == "success", f
    assert f["truth"]["agrees"] and "is in the jaws of F1" in f["truth"]["detail"]
    assert result.false_successes == 0
    # from an anchor the far contact stays where the design has it
    assert shifts and max(shifts) == 0.0


def _leave_from_clip(before: np.ndarray) -> np.ndarray:
    """F's far contact for a cable that came to clip F6 from ``before`` and goes on to F7."""
    f6 = ClipInfo(np.array([0.29, -0.065, 0.08]), 0.9476, 2.5, 0.03)
    f7 = ClipInfo(np.array([0.14, -0.10, 0.08]), -2.7966, 1.6, 0.03)
    points = [
        SimpleNamespace(label="P1", kind="contact", position=before),
        SimpleNamespace(label="F6", kind="fixed", position=f6.position),
    ]
    est = SimpleNamespace(
        contact_index=1,
        round_fixtures={},
        point_before=lambda i: points[i - 1],
    )
    ctx = SimpleNamespace(
        estimator=est,
        graph=SimpleNamespace(points=points),
        clips={"F6": f6, "F7": f7},
        fixtures={"F6": f6.position, "F7": f7.position},
    )
    state = SimpleNamespace(contact=f6.position.copy())
    f = SingleArmClipping("right", "F7")
    leave: np.ndarray = f._leave(ctx, state, np.array([0.06, -0.13, 0.10]), f7)  # type: ignore[arg-type]
    return leave - f6.position


def test_a_cable_leaves_a_clip_by_the_end_away_from_where_it_came_in() -> None:
    slot = np.array([math.cos(0.9476), math.sin(0.9476), 0.0])
    # random board 914356660's W2: in from F5 at the slot's south-west end,
    # out by its north-east end, then turned back 163 deg towards F7 (south-west)
    came_from_south_west = _leave_from_clip(np.array([0.21, -0.199, 0.05]))
    assert float(came_from_south_west @ slot) == pytest.approx(0.015)
    # the same clip entered from the north-east leaves by its south-west end
    came_from_north_east = _leave_from_clip(np.array([0.37, 0.05, 0.05]))
    assert float(came_from_north_east @ slot) == pytest.approx(-0.015)


def test_the_aim_is_finer_than_a_diagonal_crossing_leaves() -> None:
    pytest.importorskip("mujoco")
    from tautwire.sim.clip_design import design_clip

    # 8 deg across a 30 mm clip: its ends 2.1 mm off the centre line, the
    # jaws' axes 2.6 mm off it for a 2.5 mm cable
    jaws = design_clip(2.5, 0.0025, 0.5).jaw_offset
    inside = jaws - 0.015 * math.tan(math.radians(8.0))
    assert 0.0 < ALIGN_MISS < inside


def _short_span_scene() -> dict:
    """Random board 225583068's W1 up to its first clip: an anchor 117 mm before it, 8 deg off."""
    return {
        "version": 1,
        "name": "f-short-kink",
        "seed": 1636633814,
        "robot": {
            "control_period": 0.004,
            "force_limit": 15.0,
            "sensor": {"arm": "both", "noise_force": 0.05, "noise_torque": 0.002},
            "grippers": {"left": {"position": [0.3722, 0.1107, 0.12]},
                         "right": {"position": [0.2658, -0.3097, 0.12]}},
        },
        "board": {
            "fixtures": [
                {"name": "A1", "type": "anchor", "position": [0.119, 0.2015, 0.08]},
                {"name": "F1", "type": "clip", "position": [0.2363, 0.1897, 0.08],
                 "yaw": 0.0415, "push_force": 1.98},
            ]
        },
        "cables": [
            {"name": "W1", "length": 1.181, "mass_per_length": 0.0463, "stiffness": 195.2,
             "radius": 0.0028, "start": "A1", "held_by": {"arm": "left", "at": 0.316},
             "route": [{"fixture": "F1"}]}
        ],
    }  # fmt: skip


@pytest.mark.slow
def test_a_cable_the_turn_onto_the_slot_slid_off_the_jaws_is_pushed_again_with_half_the_turn(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    pytest.importorskip("mujoco")
    from tautwire.experiments.run_scenario import run_scenario
    from tautwire.scenario.loader import scenario_from_data

    # the whole turn onto the slot leaves the far side's kink at the entry,
    # pulling the cable across towards the anchor: it slid off the jaws
    # beside the clip (3.8 mm across when it fell), and the same turn after
    # the new alignment slid it off again (REALIGN_SWING = 1: not_clipped)
    realigns: list[int] = []
    step = SingleArmClipping.on_step

    def watched(self, obs, ctx):  # type: ignore[no-untyped-def]
        command = step(self, obs, ctx)
        realigns.append(self.realigns)
        return command

    monkeypatch.setattr(SingleArmClipping, "on_step", watched)
    result, _, _ = run_scenario(scenario_from_data(_short_span_scene()))
    f = result.steps[-1]
    assert f["primitive"] == "single_arm_clipping"
    assert max(realigns) == 1  # the first push missed: the scene still tests the retry
    assert f["outcome"] == "success", f
    assert f["truth"]["agrees"] and "is in the jaws of F1" in f["truth"]["detail"]
    assert result.false_successes == 0
