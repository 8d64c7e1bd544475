import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.control.task_space import (
    CoordinatedPose,
    DualPose,
    Pose,
    absolute_rate_matrix,
    coordinated_pose,
    coordinated_twist,
    coordinated_velocity_matrix,
    individual_pose,
    individual_twist,
    individual_velocity_matrix,
    make_pose,
    relative_rotation_vector,
)
from tautwire.errors import InvalidArgumentError
from tautwire.model.interpolation import slerp
from tautwire.model.quaternion import conjugate, multiply, quaternion_exp, quaternion_log

from .conftest import integrate_orientation, quaternions, random_quaternion, same_rotation, vectors

# A relative rotation of exactly a half turn has no unique midpoint: keep clear of it.
HALF_TURN_MARGIN = 1e-3


def _dual(p_l, q_l, p_r, q_r) -> DualPose:  # type: ignore[no-untyped-def]
    return DualPose(make_pose(p_l, q_l), make_pose(p_r, q_r))


def _relative_angle(pose: DualPose) -> float:
    return float(np.linalg.norm(relative_rotation_vector(pose)))


dual_poses = st.builds(_dual, vectors, quaternions, vectors, quaternions).filter(
    lambda p: _relative_angle(p) < np.pi - HALF_TURN_MARGIN
)
twists = st.lists(
    st.floats(-5.0, 5.0, allow_nan=False, allow_infinity=False), min_size=12, max_size=12
).map(np.array)


def _random_pose(rng: np.random.Generator) -> DualPose:
    while True:
        pose = _dual(
            rng.normal(size=3), random_quaternion(rng), rng.normal(size=3), random_quaternion(rng)
        )
        if _relative_angle(pose) < np.pi - HALF_TURN_MARGIN:
            return pose


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


def test_parallel_grippers() -> None:
    q = random_quaternion(np.random.default_rng(0))
    pose = _dual([0.1, 0.2, 0.3], q, [0.1, -0.2, 0.3], q)
    c = coordinated_pose(pose)
    np.testing.assert_allclose(c.absolute.position, [0.1, 0.0, 0.3])
    np.testing.assert_allclose(c.relative.position, [0.0, 0.4, 0.0])
    assert same_rotation(c.absolute.orientation, q)
    assert same_rotation(c.relative.orientation, np.array([1.0, 0.0, 0.0, 0.0]))
    np.testing.assert_allclose(absolute_rate_matrix(pose), 0.5 * np.eye(3), atol=1e-12)


def test_absolute_orientation_is_the_slerp_midpoint() -> None:
    rng = np.random.default_rng(1)
    for _ in range(20):
        pose = _random_pose(rng)
        c = coordinated_pose(pose)
        midpoint = slerp(pose.right.orientation, pose.left.orientation, 0.5)
        assert same_rotation(c.absolute.orientation, midpoint, atol=1e-9)
        # relative orientation: the left tool frame seen from the right one
        q_rel = multiply(conjugate(pose.right.orientation), pose.left.orientation)
        assert same_rotation(c.relative.orientation, q_rel)


@settings(max_examples=100, deadline=None)
@given(dual_poses)
def test_pose_round_trip(pose: DualPose) -> None:
    back = individual_pose(coordinated_pose(pose))
    np.testing.assert_allclose(back.left.position, pose.left.position, atol=1e-12)
    np.testing.assert_allclose(back.right.position, pose.right.position, atol=1e-12)
    assert same_rotation(back.left.orientation, pose.left.orientation, atol=1e-9)
    assert same_rotation(back.right.orientation, pose.right.orientation, atol=1e-9)


@settings(max_examples=100, deadline=None)
@given(dual_poses)
def test_coordinated_pose_round_trip(pose: DualPose) -> None:
    c = coordinated_pose(pose)
    back = coordinated_pose(individual_pose(c))
    np.testing.assert_allclose(back.absolute.position, c.absolute.position, atol=1e-12)
    np.testing.assert_allclose(back.relative.position, c.relative.position, atol=1e-12)
    assert same_rotation(back.absolute.orientation, c.absolute.orientation, atol=1e-9)
    assert same_rotation(back.relative.orientation, c.relative.orientation, atol=1e-9)


@settings(max_examples=100, deadline=None)
@given(dual_poses, twists)
def test_twist_round_trip(pose: DualPose, twist: np.ndarray) -> None:
    np.testing.assert_allclose(
        individual_twist(coordinated_twist(twist, pose), pose), twist, atol=1e-9
    )
    np.testing.assert_allclose(
        coordinated_twist(individual_twist(twist, pose), pose), twist, atol=1e-9
    )


@settings(max_examples=50, deadline=None)
@given(dual_poses, twists)
def test_matrices_agree_with_functions_and_invert_each_other(
    pose: DualPose, twist: np.ndarray
) -> None:
    C = coordinated_velocity_matrix(pose)
    C_inv = individual_velocity_matrix(pose)
    np.testing.assert_allclose(C_inv @ C, np.eye(12), atol=1e-9)
    np.testing.assert_allclose(C @ twist, coordinated_twist(twist, pose), atol=1e-9)
    np.testing.assert_allclose(C_inv @ twist, individual_twist(twist, pose), atol=1e-9)


def test_coordinated_twist_against_finite_differences() -> None:
    # every block of [v_abs, w_abs, v_rel, w_rel] is the rate of the coordinated pose
    rng = np.random.default_rng(2)
    h = 1e-6
    worst_mean_error = 0.0
    for _ in range(30):
        pose = _random_pose(rng)
        twist = rng.normal(size=12)
        c0 = coordinated_pose(pose)
        c1 = coordinated_pose(_step(pose, twist, h))
        zeta = coordinated_twist(twist, pose)
        np.testing.assert_allclose(
            (c1.absolute.position - c0.absolute.position) / h, zeta[0:3], atol=1e-6
        )
        w_abs = quaternion_log(
            multiply(c1.absolute.orientation, conjugate(c0.absolute.orientation))
        )
        np.testing.assert_allclose(w_abs / h, zeta[3:6], atol=1e-5)
        np.testing.assert_allclose(
            (c1.relative.position - c0.relative.position) / h, zeta[6:9], atol=1e-6
        )
        # Q_rel evolves with the right-tool-frame rate R_right^T w_rel
        w_rel_right = quaternion_log(
            multiply(c1.relative.orientation, conjugate(c0.relative.orientation))
        )
        R_right_T_w_rel = multiply(
            multiply(conjugate(pose.right.orientation), np.concatenate(([0.0], zeta[9:12]))),
            pose.right.orientation,
        )[1:]
        np.testing.assert_allclose(w_rel_right / h, R_right_T_w_rel, atol=1e-5)
        mean = 0.5 * (twist[3:6] + twist[9:12])
        worst_mean_error = max(worst_mean_error, float(np.linalg.norm(w_abs / h - mean)))
    # the plain mean (w_left + w_right) / 2 is not the rate of the midpoint in general
    assert worst_mean_error > 0.05


def test_mean_is_exact_for_small_relative_rotation() -> None:
    rng = np.random.default_rng(3)
    q = random_quaternion(rng)
    tilt = quaternion_exp([1e-4, 0.0, 0.0])
    pose = _dual(rng.normal(size=3), multiply(tilt, q), rng.normal(size=3), q)
    np.testing.assert_allclose(absolute_rate_matrix(pose), 0.5 * np.eye(3), atol=1e-4)


def test_relative_rotation_vector_of_a_known_pose() -> None:
    q_right = quaternion_exp([0.0, 0.0, np.pi / 2])
    q_left = multiply(q_right, quaternion_exp([0.3, 0.0, 0.0]))  # 0.3 rad about the tool x
    pose = _dual(np.zeros(3), q_left, np.ones(3), q_right)
    # the right tool x-axis is the world y-axis
    np.testing.assert_allclose(relative_rotation_vector(pose), [0.0, 0.3, 0.0], atol=1e-12)


def test_invalid_arguments() -> None:
    with pytest.raises(InvalidArgumentError, match="position"):
        make_pose([0.0, 1.0], [1.0, 0.0, 0.0, 0.0])
    with pytest.raises(InvalidArgumentError, match="quaternion"):
        make_pose([0.0, 1.0, 2.0], [0.0, 0.0, 0.0, 0.0])
    pose = _random_pose(np.random.default_rng(4))
    with pytest.raises(InvalidArgumentError, match=r"\(12,\)"):
        coordinated_twist(np.zeros(6), pose)


def test_coordinated_pose_type() -> None:
    pose = _random_pose(np.random.default_rng(5))
    assert isinstance(coordinated_pose(pose), CoordinatedPose)
    assert isinstance(individual_pose(coordinated_pose(pose)), DualPose)
