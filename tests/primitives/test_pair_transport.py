"""The pair carried to a clip turns and moves in step (PairTransport)."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.primitives.pair_transport import LEAD_SHARE, PairTransport

#: A kinematic pair: the middle at SPEED [m/s] towards its set point, the
#: line turning at RATE [rad/s] towards its set direction (led by at most
#: LEAD as C does), over PERIOD [s] steps.
SPEED, RATE, LEAD, PERIOD = 0.09, 0.25, math.radians(6.0), 0.004


def _unit(angle: float) -> np.ndarray:
    return np.array([math.cos(angle), math.sin(angle), 0.0])


def _carry(
    start: np.ndarray, heading: float, goal: np.ndarray, end_heading: float, half: float
) -> list[np.ndarray]:
    """The near gripper's path (middle minus ``half`` along the line) under the transport."""
    transport = PairTransport(start, _unit(heading), goal, _unit(end_heading))
    centre, angle = start.copy(), heading
    path = [centre - half * _unit(angle)]
    for _ in range(20000):
        line = _unit(angle)
        target = transport.centre(line)
        want = transport.heading(centre)
        step = target - centre
        n = float(np.linalg.norm(step))
        if n > 0.0:
            centre = centre + step * min(1.0, SPEED * PERIOD / n)
        turn = math.atan2(float(want[1]), float(want[0])) - angle
        turn = (turn + math.pi) % (2 * math.pi) - math.pi
        turn = max(-LEAD, min(LEAD, turn))
        angle += max(-RATE * PERIOD, min(RATE * PERIOD, turn))
        path.append(centre - half * _unit(angle))
        if (
            np.linalg.norm(centre - goal) < 1e-5
            and abs((end_heading - angle + math.pi) % (2 * math.pi) - math.pi) < 1e-5
        ):
            break
    return path


def test_the_middle_waits_for_the_turn_and_the_turn_for_the_middle() -> None:
    start, goal = np.array([0.4, 0.0, 0.09]), np.array([0.27, -0.2, 0.095])
    transport = PairTransport(start, _unit(0.3), goal, _unit(-0.7))
    # nothing turned yet: the middle's set point only LEAD_SHARE of the way
    centre = transport.centre(_unit(0.3))
    assert np.allclose(centre, start + LEAD_SHARE * (goal - start))
    # the middle not moved yet: the line's set point only LEAD_SHARE of the turn
    heading = transport.heading(start)
    assert math.isclose(math.atan2(heading[1], heading[0]), 0.3 - LEAD_SHARE * 1.0, abs_tol=1e-9)
    # both done: the end pose
    assert np.allclose(transport.centre(_unit(-0.7)), goal)
    assert np.allclose(transport.heading(goal), _unit(-0.7))


def test_no_turn_or_no_move_leaves_the_other_free() -> None:
    start, goal = np.array([0.4, 0.0, 0.09]), np.array([0.27, -0.2, 0.095])
    assert np.allclose(PairTransport(start, _unit(0.2), goal, _unit(0.2)).centre(_unit(0.2)), goal)
    still = PairTransport(start, _unit(0.2), start, _unit(-1.0))
    assert np.allclose(still.heading(start), _unit(-1.0))


def test_random_board_402445297_the_near_gripper_stays_within_its_span() -> None:
    """C into F6: the near gripper no further from F5's exit than at its start or end."""
    exit_f5 = np.array([0.191, -0.0961, 0.08])
    start = np.array([0.345, -0.049, 0.0875])  # the middle when C began
    goal = np.array([0.2711, -0.2055, 0.095])  # over F6's seat
    # the line from the right gripper to the left, as C holds it: from -158
    # deg (along the taut cable) onto F6's slot at 139 deg, a 63 deg turn
    heading, end = math.radians(-158.0), math.radians(139.2)
    # the near (left) gripper is the middle plus half the span along that line
    path = _carry(start, heading, goal, end, -0.06)
    reach = [float(np.linalg.norm(p - exit_f5)) for p in path]
    assert max(reach) <= max(reach[0], reach[-1]) + 1e-3


@settings(max_examples=40, deadline=None)
@given(
    x=st.floats(-0.15, 0.15),
    y=st.floats(-0.15, 0.15),
    heading=st.floats(-math.pi, math.pi),
    turn=st.floats(-math.radians(90.0), math.radians(90.0)),
)
def test_the_pair_always_reaches_its_end_pose(
    x: float, y: float, heading: float, turn: float
) -> None:
    start = np.array([0.3, 0.0, 0.09])
    goal = start + np.array([x, y, 0.005])
    path = _carry(start, heading, goal, heading + turn, 0.06)
    centre = path[-1] + 0.06 * _unit(heading + turn)
    assert np.linalg.norm(centre - goal) < 1e-4
