import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.control.force_controller import AdaptiveForceController
from tautwire.control.hybrid_controller import (
    HybridController,
    hybrid_combination,
    tension_projector,
)
from tautwire.control.motion_controller import MotionController
from tautwire.control.safety_limits import SafetyLimits
from tautwire.control.task_space import DualPose, Pose, coordinated_pose, make_pose
from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import conjugate, multiply, quaternion_log

from .conftest import integrate_orientation, random_quaternion, vectors

DT = 0.004
directions = st.one_of(st.none(), vectors.filter(lambda v: float(np.linalg.norm(v)) > 1e-3))
twists = st.lists(
    st.floats(-5.0, 5.0, allow_nan=False, allow_infinity=False), min_size=12, max_size=12
).map(np.array)


@settings(max_examples=100, deadline=None)
@given(directions, directions)
def test_projector_is_a_true_projector(left: np.ndarray | None, right: np.ndarray | None) -> None:
    P = tension_projector((left, right))
    eye = np.eye(12)
    np.testing.assert_allclose(P, P.T, atol=1e-12)
    np.testing.assert_allclose(P @ P, P, atol=1e-12)
    np.testing.assert_allclose((eye - P) @ P, 0.0, atol=1e-12)
    assert np.linalg.matrix_rank(P) == (left is not None) + (right is not None)
    for arm, d in enumerate((left, right)):
        if d is not None:
            s = slice(6 * arm, 6 * arm + 3)
            np.testing.assert_allclose(P[s, s] @ d, d, atol=1e-9)
    # angular blocks are never force controlled
    np.testing.assert_array_equal(P[3:6], 0.0)
    np.testing.assert_array_equal(P[9:12], 0.0)


@settings(max_examples=100, deadline=None)
@given(directions, directions, twists, twists)
def test_combination_takes_force_along_and_motion_across(
    left: np.ndarray | None, right: np.ndarray | None, zeta_m: np.ndarray, zeta_f: np.ndarray
) -> None:
    P = tension_projector((left, right))
    zeta_t = hybrid_combination(zeta_m, zeta_f, P)
    np.testing.assert_allclose(P @ zeta_t, P @ zeta_f, atol=1e-9)
    np.testing.assert_allclose((np.eye(12) - P) @ zeta_t, (np.eye(12) - P) @ zeta_m, atol=1e-9)


def test_projector_rejects_bad_directions() -> None:
    with pytest.raises(InvalidArgumentError, match="pair"):
        tension_projector([None])
    with pytest.raises(InvalidArgumentError, match="zero"):
        tension_projector(([0.0, 0.0, 0.0], None))
    with pytest.raises(InvalidArgumentError, match="3 finite"):
        tension_projector(([0.0, np.nan, 1.0], None))


def _random_dual(rng: np.random.Generator) -> DualPose:
    return DualPose(
        make_pose(rng.normal(size=3), random_quaternion(rng)),
        make_pose(rng.normal(size=3), random_quaternion(rng)),
    )


@pytest.mark.parametrize("coordinated", [False, True])
def test_call_equals_the_explicit_combination(coordinated: bool) -> None:
    rng = np.random.default_rng(31)
    controller = HybridController()
    for _ in range(20):
        current = _random_dual(rng)
        goal = _random_dual(rng)
        desired = coordinated_pose(goal) if coordinated else goal
        kwargs = {
            "tension_desired": (rng.uniform(0.5, 5.0), rng.uniform(0.5, 5.0)),
            "force_measured": (rng.normal(size=3), rng.normal(size=3)),
            "k_hat": (rng.uniform(10, 1000), None),
            "directions": (None, rng.normal(size=3)),
        }
        twist = controller(current, desired, **kwargs)  # type: ignore[arg-type]
        terms = controller.terms(current, desired, **kwargs)  # type: ignore[arg-type]
        np.testing.assert_allclose(twist, hybrid_combination(*terms), atol=1e-12)


def test_force_controlled_component_is_the_force_controller() -> None:
    controller = HybridController(force=AdaptiveForceController(bandwidth=10.0))
    q = np.array([1.0, 0.0, 0.0, 0.0])
    current = DualPose(Pose(np.zeros(3), q), Pose(np.array([0.0, -0.3, 0.0]), q))
    desired = DualPose(Pose(np.array([0.1, 0.2, 0.3]), q), current.right)
    f = np.array([0.0, 3.0, 0.0])  # the cable pulls the left gripper towards +y
    twist = controller(current, desired, (5.0, None), (f, None), k_hat=100.0)
    # along y: -k_f (f_d - f_c) = -(10 / 100) * 2 = -0.2 m/s (away from the contact)
    np.testing.assert_allclose(twist[0:3], [2.0 * 0.1, -0.2, 2.0 * 0.3])
    np.testing.assert_allclose(twist[6:12], 0.0)


def test_slack_cable_without_direction_stays_under_motion_control() -> None:
    controller = HybridController(min_direction_force=0.5)
    rng = np.random.default_rng(32)
    current, desired = _random_dual(rng), _random_dual(rng)
    slack = controller(current, desired, (2.0, 2.0), ([0.0, 0.0, 0.1], None), 100.0)
    motion = controller(current, desired)
    np.testing.assert_allclose(slack, motion)
    # with the direction from the model, it pulls even when slack
    pulled = controller(
        current, desired, (2.0, None), ([0.0, 0.0, 0.1], None), 100.0, ([1.0, 0.0, 0.0], None)
    )
    assert pulled[0] == pytest.approx(-controller.force.speed(2.0, 0.0, 100.0))


def test_limits_are_applied() -> None:
    controller = HybridController(limits=SafetyLimits(20.0, max_linear_speed=0.05))
    rng = np.random.default_rng(33)
    twist = controller(_random_dual(rng), _random_dual(rng))
    assert np.linalg.norm(twist[0:3]) <= 0.05 + 1e-12
    assert np.linalg.norm(twist[6:9]) <= 0.05 + 1e-12


def test_rejects_bad_arguments() -> None:
    with pytest.raises(InvalidArgumentError, match="min_direction_force"):
        HybridController(min_direction_force=0.0)
    rng = np.random.default_rng(34)
    with pytest.raises(InvalidArgumentError, match="pair"):
        HybridController()(_random_dual(rng), _random_dual(rng), k_hat=(1.0, 2.0, 3.0))


def _cable_force(p_gripper: np.ndarray, p_contact: np.ndarray, k: float, rest: float) -> np.ndarray:
    """Force a straight elastic cable anchored at p_contact exerts on the gripper."""
    d = p_contact - p_gripper
    length = np.linalg.norm(d)
    return k * max(length - rest, 0.0) * d / length


def _step(pose: DualPose, twist: np.ndarray) -> DualPose:
    return DualPose(
        Pose(
            pose.left.position + DT * twist[0:3],
            integrate_orientation(pose.left.orientation, twist[3:6], DT),
        ),
        Pose(
            pose.right.position + DT * twist[6:9],
            integrate_orientation(pose.right.orientation, twist[9:12], DT),
        ),
    )


@pytest.mark.parametrize(("k", "k_hat"), [(10.0, 100.0), (100.0, 100.0), (1000.0, 100.0)])
def test_single_arm_tension_closed_loop(k: float, k_hat: float) -> None:
    # primitive D: left gripper tensions a cable against a fixed point while the
    # motion controller holds the other directions; the right arm goes to its goal
    rng = np.random.default_rng(35)
    p_contact = np.array([0.4, 0.0, 0.1])
    rest = 0.3
    current = DualPose(
        make_pose([0.1, 0.02, 0.1], random_quaternion(rng)),
        make_pose([0.0, -0.3, 0.2], random_quaternion(rng)),
    )
    desired = DualPose(
        make_pose([0.1, 0.0, 0.12], random_quaternion(rng)),
        make_pose([0.05, -0.25, 0.25], random_quaternion(rng)),
    )
    controller = HybridController(MotionController(k_p=2.0, k_o=4.0))
    f = _cable_force(current.left.position, p_contact, k, rest)
    for _ in range(2500):  # 10 s
        # the direction comes from the model: f_g = p_c - p_g (the cable starts slack)
        f_g = p_contact - current.left.position
        twist = controller(current, desired, (2.0, None), (f, None), k_hat, (f_g, None))
        current = _step(current, twist)
        f = _cable_force(current.left.position, p_contact, k, rest)
    assert np.linalg.norm(f) == pytest.approx(2.0, abs=1e-3)
    # across the cable, the gripper sits where the motion controller wants it
    f_hat = f / np.linalg.norm(f)
    across = (np.eye(3) - np.outer(f_hat, f_hat)) @ (desired.left.position - current.left.position)
    assert np.linalg.norm(across) < 1e-3
    for arm in ("left", "right"):
        q_c = getattr(current, arm).orientation
        q_d = getattr(desired, arm).orientation
        assert np.linalg.norm(quaternion_log(multiply(q_d, conjugate(q_c)))) < 1e-3
    np.testing.assert_allclose(current.right.position, desired.right.position, atol=1e-6)


def test_parallel_tension_closed_loop() -> None:
    # primitive A: a cable between the two grippers, the sensor on the left wrist,
    # coordinated motion holds the absolute pose; force control sets the tension
    rng = np.random.default_rng(36)
    q = random_quaternion(rng)
    k, rest = 200.0, 0.35
    current = DualPose(make_pose([0.3, 0.15, 0.2], q), make_pose([0.3, -0.15, 0.2], q))
    desired = coordinated_pose(current)
    controller = HybridController()
    for _ in range(2500):
        f = _cable_force(current.left.position, current.right.position, k, rest)
        f_g = current.right.position - current.left.position  # known by kinematics
        twist = controller(current, desired, (3.0, None), (f, None), 150.0, (f_g, None))
        current = _step(current, twist)
    f = _cable_force(current.left.position, current.right.position, k, rest)
    assert np.linalg.norm(f) == pytest.approx(3.0, abs=1e-3)
    now = coordinated_pose(current)
    # the grippers stay in line (only the length along the cable changed)
    rel = now.relative.position / np.linalg.norm(now.relative.position)
    np.testing.assert_allclose(rel, [0.0, 1.0, 0.0], atol=1e-3)


def test_coordinated_force_control_acts_on_the_distance_only() -> None:
    import numpy as np

    from tautwire.control import (
        AdaptiveForceController,
        DualPose,
        HybridController,
        MotionController,
        Pose,
        coordinated_pose,
    )

    q = np.array([1.0, 0.0, 0.0, 0.0])
    current = DualPose(Pose(np.array([0.0, 0.1, 0.2]), q), Pose(np.array([0.0, -0.1, 0.2]), q))
    ctrl = HybridController(MotionController(), AdaptiveForceController(bandwidth=5.0))
    twist = ctrl.coordinated(current, coordinated_pose(current), 3.0, 2.0, 100.0)
    v_left, v_right = twist[0:3], twist[6:9]
    assert np.allclose(v_left + v_right, 0.0)  # the absolute pose holds
    speed = 5.0 / 100.0 * (3.0 - 2.0)
    assert np.allclose(v_left - v_right, [0.0, speed, 0.0])  # the grippers part
    slide = ctrl.coordinated(current, coordinated_pose(current), None, 0.0, relative_speed=0.02)
    assert np.allclose(slide[0:3] - slide[6:9], [0.0, 0.02, 0.0])


@settings(max_examples=100, deadline=None)
@given(
    st.floats(-np.pi, np.pi),
    st.floats(0.05, 0.5),
    st.floats(0.0, 12.0),
    st.floats(0.1, 0.2),
)
def test_a_coordinated_move_at_the_speed_limit_keeps_the_distance_under_force_control(
    heading: float, travel: float, tension: float, span: float
) -> None:
    # random board 1652323633's C: both grippers carried 111 mm to the clip
    # at the speed limit; scaled arm by arm, the absolute velocity leaked into
    # their distance (2 mm, 3 -> 13.6 N against a set point of 3 N)
    limits = SafetyLimits(20.0, max_linear_speed=0.1, max_angular_speed=1.0)
    ctrl = HybridController(
        MotionController(), AdaptiveForceController(bandwidth=5.0), limits=limits
    )
    q = np.array([1.0, 0.0, 0.0, 0.0])
    u = np.array([np.cos(heading), np.sin(heading), 0.0])
    mid = np.array([0.4, -0.2, 0.09])
    current = DualPose(Pose(mid + 0.5 * span * u, q), Pose(mid - 0.5 * span * u, q))
    goal = coordinated_pose(current)
    away = np.array([np.cos(heading + 1.1), np.sin(heading + 1.1), 0.05])
    desired = type(goal)(Pose(mid + travel * away, q), goal.relative)
    twist = ctrl.coordinated(current, desired, 3.0, tension, 5000.0)
    v_left, v_right = twist[0:3], twist[6:9]
    assert np.linalg.norm(v_left) <= 0.1 + 1e-9 and np.linalg.norm(v_right) <= 0.1 + 1e-9
    # the distance's rate is the force controller's, whatever the absolute move
    rate = float(u @ (v_left - v_right))
    assert rate == pytest.approx(ctrl.force.speed(3.0, tension, 5000.0), abs=1e-9)
    # and the grippers still move towards the goal
    assert float((v_left + v_right) @ away) > 0.0
