"""The pair's tool axes laid along the line between them: the nearer axis, never a half turn.

Kinematic (no simulator): the coordinated controller's twist is integrated
on both grippers' poses from any pair of start yaws; each controlled frame
(a gripper whose x points from right to left is controlled through its
frame turned half about z) must end with x along the line, each gripper
turned by at most a quarter, the tool centre points where they were.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.control import HybridController, MotionController, SafetyLimits
from tautwire.model.quaternion import multiply, rotate
from tautwire.primitives.pair_alignment import ALIGNED, ALIGNED_TIME, PairAlignment
from tautwire.robot import GripperState, Observation, Wrench

PERIOD = 0.004


def _yaw(yaw: float) -> np.ndarray:
    return np.array([math.cos(0.5 * yaw), 0.0, 0.0, math.sin(0.5 * yaw)])


def _obs(
    time: float, p: tuple[np.ndarray, np.ndarray], q: tuple[np.ndarray, np.ndarray]
) -> Observation:
    wrench = Wrench("left", np.zeros(3), np.zeros(3))
    return Observation(time, GripperState(p[0], q[0]), GripperState(p[1], q[1]), (wrench,))


def _x(q: np.ndarray) -> np.ndarray:
    return rotate(q, [1.0, 0.0, 0.0])


def _angle(a: np.ndarray, b: np.ndarray) -> float:
    """Rotation angle [rad] between two orientations."""
    c = abs(float(np.dot(a, b)))
    return 2.0 * math.acos(min(c, 1.0))


def _integrate(q: np.ndarray, w: np.ndarray, dt: float) -> np.ndarray:
    """q turned by the world-frame angular velocity w [rad/s] for dt [s]."""
    theta = float(np.linalg.norm(w)) * dt
    if theta < 1e-15:
        return q
    axis = w / float(np.linalg.norm(w))
    dq = np.concatenate(([math.cos(0.5 * theta)], math.sin(0.5 * theta) * axis))
    out = multiply(dq, q)
    return out / float(np.linalg.norm(out))


def _run(
    yaw_left: float, yaw_right: float, seconds: float = 4.0
) -> tuple[PairAlignment, list[Observation]]:
    p = (np.array([0.2, 0.1, 0.3]), np.array([0.45, -0.05, 0.3]))
    q = (_yaw(yaw_left), _yaw(yaw_right))
    controller = HybridController(MotionController(2.0, 4.0), limits=SafetyLimits(15.0, 0.1, 1.0))
    obs = _obs(0.0, p, q)
    pair = PairAlignment(obs)
    history = [obs]
    for k in range(round(seconds / PERIOD)):
        twist = controller.coordinated(pair.tool_frames(obs), pair.desired, None, 0.0)
        p = (p[0] + PERIOD * twist[0:3], p[1] + PERIOD * twist[6:9])
        q = (_integrate(q[0], twist[3:6], PERIOD), _integrate(q[1], twist[9:12], PERIOD))
        obs = _obs((k + 1) * PERIOD, p, q)
        history.append(obs)
    return pair, history


def test_a_gripper_pointing_back_along_the_line_is_flipped_not_turned() -> None:
    # left x points from left to right, right x from right to left: both lie
    # along the line already; the right one is controlled through its frame
    # turned half about z, and nothing turns
    line_yaw = math.atan2(-0.15, 0.25)
    pair, history = _run(line_yaw, line_yaw + math.pi, seconds=0.5)
    assert pair.flip == (False, True)
    assert pair.angle(history[0]) < 1e-6
    start, end = history[0], history[-1]
    assert _angle(start.left.orientation, end.left.orientation) < 1e-6
    assert _angle(start.right.orientation, end.right.orientation) < 1e-6


def test_settled_at_once_when_aligned_from_the_start_else_after_aligned_time() -> None:
    line_yaw = math.atan2(-0.15, 0.25)
    pair, history = _run(line_yaw, line_yaw, seconds=0.1)
    assert all(pair.settled(o) for o in history)
    pair, history = _run(line_yaw + 1.2, line_yaw - 0.4)
    settled = [pair.settled(o) for o in history]
    first = settled.index(True)
    aligned_at = next(i for i, o in enumerate(history) if pair.angle(o) <= ALIGNED)
    assert not any(settled[:first])
    assert (first - aligned_at) * PERIOD >= ALIGNED_TIME - 1e-9


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.floats(-math.pi, math.pi), st.floats(-math.pi, math.pi))
def test_any_start_yaws_end_along_the_line_by_at_most_a_quarter_turn_each(
    yaw_left: float, yaw_right: float
) -> None:
    pair, history = _run(yaw_left, yaw_right)
    start, end = history[0], history[-1]
    line = end.right.position - end.left.position
    line /= np.linalg.norm(line)
    # the line and the tool centre points stay where they were
    assert np.allclose(end.left.position, start.left.position, atol=1e-6)
    assert np.allclose(end.right.position, start.right.position, atol=1e-6)
    assert pair.angle(end) < math.radians(0.5)
    for a, b in ((start.left, end.left), (start.right, end.right)):
        # the nearer tool axis, +x or -x, lies on the line: a pure yaw of at
        # most a quarter turn, never a half turn round the fingertip
        assert abs(abs(float(_x(b.orientation) @ line)) - 1.0) < 1e-4
        assert _angle(a.orientation, b.orientation) <= 0.5 * math.pi + 1e-6
        assert abs(float(rotate(b.orientation, [0.0, 0.0, 1.0])[2]) - 1.0) < 1e-6
    # and no gripper ever turned further than where it ends
    for o in history:
        assert _angle(start.left.orientation, o.left.orientation) <= 0.5 * math.pi + 1e-3
        assert _angle(start.right.orientation, o.right.orientation) <= 0.5 * math.pi + 1e-3
