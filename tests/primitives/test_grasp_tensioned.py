"""H's goal: the model's point, its height from the measured pull where the model's is unsure."""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from tautwire.model import PathGraph
from tautwire.primitives import PrimitiveContext, make_context
from tautwire.primitives.grasp_tensioned import LINE_HEIGHT_STD, GraspTensioned

ANCHOR = np.array([0.05, -0.16, 0.08])
PEG = np.array([0.541, -0.2175, 0.0995])  # the model's peg point (design position)
GRIP = np.array([0.806, -0.182, 0.1005])
UP = np.array([1.0, 0.0, 0.0, 0.0])


def _context(peg_std: float | None) -> tuple[PrimitiveContext, float]:
    graph = PathGraph.from_positions(
        [ANCHOR, PEG, GRIP],
        mass_per_length=0.0,  # no sag: the chord itself
        kinds=["fixed", "contact", "gripper"],
        labels=["A2", "F9", "right"],
    )
    if peg_std is not None:
        graph.points[1].covariance = peg_std**2 * np.eye(3)
    ctx = make_context(graph, "right")
    s = graph.arc_lengths()
    return ctx, float(0.5 * (s[1] + s[2]))


@given(drop=st.floats(min_value=-0.015, max_value=0.015))
def test_an_uncertain_contact_s_chord_height_comes_from_the_measured_pull(drop: float) -> None:
    # random board 1045612557: F9 claimed at its design height (10 mm std),
    # the cable truly left it lower; the pull's line from the gripper meets it there
    ctx, at = _context(0.01)
    true_peg = PEG + np.array([0.0, 0.0, -drop])
    h = GraspTensioned("left", at=at)
    h._line = 3.0 * (true_peg - GRIP) / np.linalg.norm(true_peg - GRIP)  # scale is irrelevant
    goal, _ = h._goal(ctx, 3.0, UP)
    truth = 0.5 * (true_peg + GRIP)
    assert abs(goal[2] - truth[2]) < 1e-9
    assert np.allclose(goal[:2], 0.5 * (PEG + GRIP)[:2])


def test_a_known_contact_or_no_reading_keeps_the_model_s_chord() -> None:
    for std in (None, 0.5 * LINE_HEIGHT_STD):
        ctx, at = _context(std)
        h = GraspTensioned("left", at=at)
        h._line = np.array([-1.0, 0.0, -0.5])  # a pull far from the model's chord
        goal, _ = h._goal(ctx, 3.0, UP)
        assert np.isclose(goal[2], 0.5 * (PEG + GRIP)[2])
    ctx, at = _context(0.01)
    goal, _ = GraspTensioned("left", at=at)._goal(ctx, 3.0, UP)  # nothing measured yet
    assert np.isclose(goal[2], 0.5 * (PEG + GRIP)[2])
