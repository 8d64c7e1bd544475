import numpy as np
import pytest

from tautwire.control.motion_controller import (
    MotionController,
    coordinated_motion_command,
    coordinated_motion_twist,
    individual_motion_twist,
)
from tautwire.control.task_space import (
    CoordinatedPose,
    DualPose,
    Pose,
    coordinated_pose,
    coordinated_twist,
    make_pose,
)
from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import conjugate, multiply, quaternion_log

from .conftest import integrate_orientation, random_quaternion


def _step(pose: DualPose, twist: np.ndarray, dt: float) -> DualPose:
    return DualPose(
        Pose(
            pose.left.position + dt * twist[0:3],
            integrate_orientation(pose.left.orientation, twist[3:6], dt),
        ),
        Pose(
            pose.right.position + dt * twist[6:9],
            integrate_orientation(pose.right.orientation, twist[9:12], dt),
        ),
    )


def _angle(q1: np.ndarray, q2: np.ndarray) -> float:
    return float(np.linalg.norm(quaternion_log(multiply(q1, conjugate(q2)))))


def _tilted(rng: np.random.Generator, q: np.ndarray, max_angle: float) -> np.ndarray:
    axis = rng.normal(size=3)
    angle = rng.uniform(0.0, max_angle)
    return integrate_orientation(q, angle * axis / np.linalg.norm(axis), 1.0)


@pytest.mark.parametrize(("k_p", "k_o"), [(0.0, 1.0), (1.0, -1.0), (np.nan, 1.0), (1.0, np.inf)])
def test_rejects_bad_gains(k_p: float, k_o: float) -> None:
    with pytest.raises(InvalidArgumentError, match="> 0"):
        MotionController(k_p, k_o)


def test_one_frame_twist() -> None:
    c = MotionController(k_p=2.0, k_o=3.0)
    q = np.array([1.0, 0.0, 0.0, 0.0])
    twist = c(Pose(np.array([1.0, 0.0, 0.0]), q), Pose(np.zeros(3), q))
    np.testing.assert_allclose(twist, [2.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    np.testing.assert_allclose(c.linear([0.0, 1.0, 0.0], [0.0, 0.5, 0.0]), [0.0, 1.0, 0.0])


def test_individual_control_converges() -> None:
    rng = np.random.default_rng(11)
    c = MotionController(k_p=2.0, k_o=4.0)
    dt = 0.004
    for _ in range(3):
        current = DualPose(
            make_pose(rng.normal(size=3), random_quaternion(rng)),
            make_pose(rng.normal(size=3), random_quaternion(rng)),
        )
        desired = DualPose(
            make_pose(rng.normal(size=3), random_quaternion(rng)),
            make_pose(rng.normal(size=3), random_quaternion(rng)),
        )
        e0 = np.linalg.norm(desired.left.position - current.left.position)
        for _ in range(1000):  # 4 s
            current = _step(current, individual_motion_twist(c, desired, current), dt)
        # linear error decays as (1 - k_p dt)^n
        np.testing.assert_allclose(
            np.linalg.norm(desired.left.position - current.left.position),
            e0 * (1 - 2.0 * dt) ** 1000,
            rtol=1e-9,
        )
        assert _angle(current.left.orientation, desired.left.orientation) < 1e-3
        assert _angle(current.right.orientation, desired.right.orientation) < 1e-3


def test_coordinated_control_converges_in_absolute_and_relative_pose() -> None:
    rng = np.random.default_rng(12)
    c = MotionController(k_p=2.0, k_o=4.0)
    dt = 0.004
    for _ in range(3):
        q = random_quaternion(rng)
        current = DualPose(
            make_pose(rng.normal(size=3), _tilted(rng, q, 1.0)),
            make_pose(rng.normal(size=3), _tilted(rng, q, 1.0)),
        )
        goal = DualPose(
            make_pose(rng.normal(size=3), _tilted(rng, q, 1.0)),
            make_pose(rng.normal(size=3), _tilted(rng, q, 1.0)),
        )
        desired = coordinated_pose(goal)
        start = coordinated_pose(current)
        e0 = np.linalg.norm(desired.absolute.position - start.absolute.position)
        for _ in range(1500):  # 6 s
            current = _step(current, coordinated_motion_twist(c, desired, current), dt)
        now = coordinated_pose(current)
        np.testing.assert_allclose(
            np.linalg.norm(desired.absolute.position - now.absolute.position),
            e0 * (1 - 2.0 * dt) ** 1500,
            rtol=1e-6,
        )
        np.testing.assert_allclose(now.relative.position, desired.relative.position, atol=1e-4)
        assert _angle(now.absolute.orientation, desired.absolute.orientation) < 1e-4
        assert _angle(now.relative.orientation, desired.relative.orientation) < 1e-4
        # which also puts each gripper where the goal has it
        np.testing.assert_allclose(current.left.position, goal.left.position, atol=1e-4)
        assert _angle(current.right.orientation, goal.right.orientation) < 1e-4


def test_coordinated_twist_realises_the_coordinated_command() -> None:
    rng = np.random.default_rng(13)
    c = MotionController()
    current = DualPose(
        make_pose(rng.normal(size=3), random_quaternion(rng)),
        make_pose(rng.normal(size=3), random_quaternion(rng)),
    )
    desired = CoordinatedPose(
        make_pose(rng.normal(size=3), random_quaternion(rng)),
        make_pose(rng.normal(size=3), random_quaternion(rng)),
    )
    command = coordinated_motion_command(c, desired, current)
    twist = coordinated_motion_twist(c, desired, current)
    np.testing.assert_allclose(coordinated_twist(twist, current), command, atol=1e-12)


def test_relative_goal_only_keeps_the_absolute_pose() -> None:
    # the paper's sliding: x_dot_abs = 0 and w_abs = 0 while the relative pose changes
    rng = np.random.default_rng(14)
    c = MotionController()
    q = random_quaternion(rng)
    current = DualPose(make_pose([0.0, 0.1, 0.2], q), make_pose([0.0, -0.1, 0.2], q))
    now = coordinated_pose(current)
    desired = CoordinatedPose(
        now.absolute, Pose(np.array([0.0, 0.3, 0.0]), now.relative.orientation)
    )
    twist = coordinated_motion_twist(c, desired, current)
    np.testing.assert_allclose(twist[0:3] + twist[6:9], 0.0, atol=1e-12)  # v_abs = 0
    np.testing.assert_allclose(twist[3:6], 0.0, atol=1e-12)
    np.testing.assert_allclose(twist[9:12], 0.0, atol=1e-12)
    np.testing.assert_allclose(twist[0:3] - twist[6:9], c.k_p * np.array([0.0, 0.1, 0.0]))
