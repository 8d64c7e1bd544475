"""Release: the fingers open, the model's gripper point becomes free."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from tautwire.experiments.truth import model_side
from tautwire.model import PathGraph
from tautwire.primitives import make_context
from tautwire.primitives.release import (
    RETREAT_ASIDE,
    RETREAT_BACK,
    RETREAT_TOLERANCE,
    Release,
    release_point,
    retreat_aside,
)
from tautwire.robot import Command, Observation
from tautwire.tasks import run_step

from .conftest import CONTACT, GRIPPER
from .spring_robot import SpringCableRobot

RIGHT = np.array([0.35, -0.3, 0.12])


def _two_held() -> PathGraph:
    """Anchor, left gripper (sensing), right gripper further along, a free end."""
    return PathGraph.from_positions(
        [CONTACT, GRIPPER, RIGHT, RIGHT - np.array([0.0, 0.0, 0.1])],
        mass_per_length=0.03,
        kinds=["fixed", "gripper", "gripper", "free"],
        labels=["A1", "left", "right", "end"],
    )


def test_release_point_frees_the_gripper_s_point_and_lets_the_end_hang() -> None:
    graph = _two_held()
    graph.edges[1].tension = 2.0
    moved = {"left": GRIPPER, "right": RIGHT + np.array([0.0, 0.05, 0.0])}
    assert release_point(graph, "right", moved)
    assert graph.index_of("gripper", "right") is None
    assert graph.points[2].kind == "free"
    assert graph.edges[1].tension == 0.0
    # nothing holds the cable beyond the left gripper now: it hangs from it
    assert np.allclose(graph.points[2].position[:2], GRIPPER[:2])
    assert graph.points[2].position[2] < GRIPPER[2]
    assert not release_point(graph, "right", moved)


class _Fingers(SpringCableRobot):
    """The spring robot with a right gripper whose fingers open at 40 mm/s on command."""

    def __init__(self, opens: bool = True) -> None:
        super().__init__(CONTACT, GRIPPER, stiffness=200.0, slack=0.01)
        self.opening = 0.006
        self.opens = opens

    def observe(self) -> Observation:
        obs = super().observe()
        return replace(obs, right=replace(obs.right, opening=self.opening))

    def act(self, command: Command) -> None:
        super().act(command)
        if command.right.mode == "open" and self.opens:
            self.opening = min(self.opening + 0.04 * self.control_period, 0.04)


def test_release_opens_the_fingers_then_edits_the_model() -> None:
    ctx = make_context(_two_held(), "left")
    robot = _Fingers()
    report = run_step(robot, Release("right"), ctx)
    assert report.success, report.detail
    assert robot.opening > 0.01
    assert ctx.graph.index_of("gripper", "right") is None
    assert ctx.graph.index_of("gripper", "left") == 1


def test_fingers_that_do_not_open_end_the_release_by_timeout_and_keep_the_model() -> None:
    ctx = make_context(_two_held(), "left")
    report = run_step(_Fingers(opens=False), Release("right"), ctx)
    assert report.cause == "timeout"
    assert ctx.graph.index_of("gripper", "right") == 2


def test_a_cable_no_gripper_holds_keeps_no_peg_height() -> None:
    # random board 2082005138: W1, wound round F2 at 94 mm and let go after
    # its last clip, slid down F2 to 27 mm; the model's F2 kept a trusted
    # height. With no gripper left, a peg's height is known only to lie
    # above the board; with the other gripper still holding, it is kept.
    peg = np.array([0.25, 0.05, 0.09])
    clip = np.array([0.35, 0.1, 0.08])

    def graph(arms: list[str]) -> PathGraph:
        points = [CONTACT, peg, clip] + [GRIPPER + 0.05 * k for k in range(len(arms))]
        g = PathGraph.from_positions(
            points,
            mass_per_length=0.03,
            kinds=["fixed", "contact", "fixed"] + ["gripper"] * len(arms),
            labels=["A1", "P1", "C1", *arms],
        )
        g.points[1].covariance = (0.004**2) * np.eye(3)
        return g

    positions = {"left": GRIPPER, "right": GRIPPER + 0.05}
    alone = graph(["left"])
    assert release_point(alone, "left", positions)
    std = np.sqrt(np.diag(alone.points[1].covariance))
    assert np.allclose(std[:2], 0.004) and std[2] >= 0.09 - 1e-9  # down to the board
    assert alone.points[2].covariance is None  # a clip holds its cable where it is
    handed = graph(["left", "right"])
    assert release_point(handed, "left", positions)
    assert np.allclose(handed.points[1].covariance, (0.004**2) * np.eye(3))


def test_a_cable_no_gripper_holds_keeps_no_side_of_a_peg_it_barely_turns_round() -> None:
    # random board 2124379844: W1, turned 32 deg round peg F3 and let go
    # after its last clip, sprang to F3's other side; the model still had it
    # round F3's right. A winding (over half a turn) keeps its side, and so
    # does every peg while the other gripper still pulls the cable round it.
    def graph(
        arms: list[str], wraps: tuple[float | None, float | None], clip: bool = True
    ) -> PathGraph:
        points = [CONTACT, np.array([0.2, 0.05, 0.09]), np.array([0.25, 0.1, 0.09])]
        kinds, labels = ["fixed", "contact", "contact"], ["A1", "P1", "P2"]
        if clip:
            points.append(np.array([0.35, 0.1, 0.08]))
            kinds.append("fixed")
            labels.append("C1")
        points += [GRIPPER + 0.05 * k for k in range(len(arms))]
        g = PathGraph.from_positions(
            points,
            mass_per_length=0.03,
            kinds=kinds + ["gripper"] * len(arms),
            labels=labels + arms,
        )
        g.points[1].wrap, g.points[2].wrap = wraps
        return g

    positions = {"left": GRIPPER, "right": GRIPPER + 0.05}
    alone = graph(["left"], (-0.56, 6.1))
    assert model_side(alone, alone.points[1]) == "right"
    assert release_point(alone, "left", positions)
    assert model_side(alone, alone.points[1]) == ""  # which side: no longer known
    assert model_side(alone, alone.points[2]) == "left"  # wound: kept
    handed = graph(["left", "right"], (-0.56, None), clip=False)
    side = model_side(handed, handed.points[1])
    assert release_point(handed, "left", positions)
    assert model_side(handed, handed.points[1]) == side == "right"


def test_a_peg_behind_a_clip_from_the_gripper_left_keeps_no_side() -> None:
    # random board 1045612557: C into F10 after peg F9 (turned 50 deg); the
    # near gripper let go, the far one held W2 beyond F10, which holds the
    # cable across, not along: W2 had left F9, the model still had it round
    # F9's left (a false success). The far gripper pulls through the clip,
    # not round the peg, so the model no longer says which side.
    peg = np.array([0.25, 0.1, 0.09])
    clip = np.array([0.35, 0.1, 0.08])
    g = PathGraph.from_positions(
        [CONTACT, peg, GRIPPER - np.array([0.05, 0.0, 0.0]), clip, GRIPPER],
        mass_per_length=0.03,
        kinds=["fixed", "contact", "gripper", "fixed", "gripper"],
        labels=["A1", "F9", "left", "F10", "right"],
    )
    g.points[1].wrap = 0.88
    assert model_side(g, g.points[1]) != ""
    assert release_point(g, "left", {"left": g.points[2].position, "right": GRIPPER})
    assert g.index_of("gripper", "right") is not None
    assert model_side(g, g.points[1]) == ""


UP = np.array([1.0, 0.0, 0.0, 0.0])  # tool z up


def _bent(turn_deg: float) -> PathGraph:
    """A clip 60 mm behind the right gripper along x, the cable turning ``turn_deg`` at it."""
    grip = np.array([0.3, 0.0, 0.08])
    turn = np.radians(turn_deg)
    onward = grip + 0.1 * np.array([np.cos(turn), np.sin(turn), 0.0])
    return PathGraph.from_positions(
        [grip - np.array([0.06, 0.0, 0.0]), grip, onward],
        mass_per_length=0.03,
        kinds=["fixed", "gripper", "fixed"],
        labels=["C1", "right", "P1"],
    )


@given(
    turn=st.floats(min_value=25.0, max_value=150.0),
    side=st.sampled_from([1.0, -1.0]),
    roll=st.floats(min_value=-np.pi, max_value=np.pi),
)
def test_the_retreat_moves_into_the_bend_away_from_both_arms(
    turn: float, side: float, roll: float
) -> None:
    # the near gripper of a parallel clip (random board 1695658280): the
    # cable runs along the slot to the clip and turns towards the fixture
    # before it; the open fingers hook it round the inner pad's end. Whatever
    # the tool's roll about its vertical approach axis, the move aside is
    # horizontal, RETREAT_ASIDE long, along the bisector of the two arms.
    graph = _bent(side * turn)
    q = np.array([np.cos(roll / 2), 0.0, 0.0, np.sin(roll / 2)])
    grip = graph.points[1].position
    aside = retreat_aside(graph, "right", grip, q)
    assert abs(aside[2]) < 1e-12
    assert np.isclose(np.linalg.norm(aside), RETREAT_ASIDE)
    for k in (0, 2):
        arm_dir = graph.points[k].position - grip
        arm_dir /= np.linalg.norm(arm_dir)
        # moving aside raises the angle to each arm's line: the inner pad leaves it
        assert aside @ arm_dir > 0.0
    # into the bend: the side the onward arm turns to
    assert side * aside[1] > 0.0


def test_a_straight_cable_an_end_or_an_empty_gripper_backs_straight_out() -> None:
    assert not retreat_aside(_bent(10.0), "right", _bent(10.0).points[1].position, UP).any()
    end = PathGraph.from_positions(
        [CONTACT, GRIPPER], mass_per_length=0.03, kinds=["fixed", "gripper"], labels=["A1", "left"]
    )
    assert not retreat_aside(end, "left", GRIPPER, UP).any()
    assert not retreat_aside(end, "right", GRIPPER, UP).any()


def test_the_release_backs_the_open_gripper_off_along_its_tool_axis() -> None:
    ctx = make_context(_two_held(), "left")
    robot = _Fingers()
    start = robot.observe().right.position.copy()
    report = run_step(robot, Release("right"), ctx)
    assert report.success, report.detail
    moved = robot.observe().right.position - start
    # the cable runs straight through the right gripper here: straight back, up
    assert np.allclose(moved, [0.0, 0.0, RETREAT_BACK], atol=RETREAT_TOLERANCE + 1e-4)
    assert "backed 30 mm off it" in report.detail
