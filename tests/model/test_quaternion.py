import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from tautwire.errors import InvalidArgumentError
from tautwire.model import quaternion as qf
from tautwire.model.quaternion import (
    as_quaternion,
    conjugate,
    from_rotation,
    multiply,
    orientation_along,
    quaternion_exp,
    quaternion_log,
    quaternion_sqrt,
    rotate,
    to_rotation,
)

vectors = st.lists(st.floats(-1, 1), min_size=3, max_size=3).filter(
    lambda v: np.linalg.norm(v) > 1e-3
)


@settings(max_examples=100, deadline=None)
@given(vectors)
def test_orientation_along_points_x_along_the_direction(v: list[float]) -> None:
    q = orientation_along(v)
    x_axis = rotate(q, [1.0, 0.0, 0.0])
    assert x_axis == pytest.approx(np.asarray(v) / np.linalg.norm(v), abs=1e-9)


def test_multiply_matches_scipy() -> None:
    rng = np.random.default_rng(0)
    a, b = as_quaternion(rng.normal(size=4)), as_quaternion(rng.normal(size=4))
    x, y, z, w = (to_rotation(a) * to_rotation(b)).as_quat()  # SciPy's order
    expected = np.array([w, x, y, z])
    product = multiply(a, b)
    assert abs(abs(np.dot(product, expected)) - 1.0) < 1e-12
    assert multiply(a, conjugate(a)) == pytest.approx([1, 0, 0, 0])


def test_rejects_bad_quaternions() -> None:
    with pytest.raises(InvalidArgumentError):
        as_quaternion([0, 0, 0, 0])
    with pytest.raises(InvalidArgumentError):
        as_quaternion([1, 0, 0])


def test_orientation_along_nearly_minus_x() -> None:
    for v in (
        [-1.0, 0.0, 5.960464477539063e-08],
        [-1.0, 1e-9, 0.0],
        [-1.0, 0.0, 0.0],
        [-0.3, 0.01, 0.0],
    ):
        x_axis = rotate(orientation_along(v), [1.0, 0.0, 0.0])
        assert x_axis == pytest.approx(np.asarray(v) / np.linalg.norm(v), abs=1e-12)


def test_turn_x_onto_takes_the_tool_x_axis_onto_a_direction() -> None:
    import numpy as np

    from tautwire.model.quaternion import rotate, turn_x_onto

    rng = np.random.default_rng(3)
    for _ in range(50):
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        d = rng.normal(size=3)
        turned = turn_x_onto(q, d)
        assert np.allclose(rotate(turned, [1.0, 0.0, 0.0]), d / np.linalg.norm(d))


@pytest.mark.parametrize("angle", [0.3, -1.2, 2.9])
def test_scipy_rotations_keep_the_scalar_first_convention(angle: float) -> None:
    # [w, x, y, z] about z by angle; SciPy's own order is [x, y, z, w] (any SciPy >= 1.11)
    q = np.array([np.cos(angle / 2), 0.0, 0.0, np.sin(angle / 2)])
    rotated = to_rotation(q).apply([1.0, 0.0, 0.0])
    np.testing.assert_allclose(rotated, [np.cos(angle), np.sin(angle), 0.0], atol=1e-12)
    np.testing.assert_allclose(from_rotation(Rotation.from_rotvec([0, 0, angle])), q, atol=1e-12)


def random_quaternion(rng: np.random.Generator) -> np.ndarray:
    """Uniform random unit quaternion [w, x, y, z] with w >= 0."""
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    return q if q[0] >= 0.0 else -q


def same_rotation(q1: np.ndarray, q2: np.ndarray, atol: float = 1e-9) -> bool:
    """Whether two unit quaternions are the same rotation (q or -q)."""
    return bool(np.allclose(q1, q2, atol=atol) or np.allclose(q1, -q2, atol=atol))


def test_exp_of_quarter_turn_about_z() -> None:
    q = quaternion_exp([0.0, 0.0, np.pi / 2])
    np.testing.assert_allclose(q, [np.cos(np.pi / 4), 0.0, 0.0, np.sin(np.pi / 4)])


@pytest.mark.parametrize("scale", [0.0, 1e-9, 1e-3, 1.0, 3.0])
def test_log_inverts_exp(scale: float) -> None:
    rng = np.random.default_rng(1)
    for _ in range(20):
        axis = rng.normal(size=3)
        phi = scale * axis / np.linalg.norm(axis)
        np.testing.assert_allclose(quaternion_log(quaternion_exp(phi)), phi, atol=1e-12)


def test_log_takes_the_shorter_way() -> None:
    rng = np.random.default_rng(2)
    for _ in range(20):
        q = random_quaternion(rng)
        np.testing.assert_allclose(quaternion_log(-q), quaternion_log(q), atol=1e-12)
        assert np.linalg.norm(quaternion_log(q)) <= np.pi + 1e-12


def test_sqrt_squares_back() -> None:
    rng = np.random.default_rng(3)
    for _ in range(50):
        q = random_quaternion(rng)
        h = quaternion_sqrt(q)
        assert same_rotation(multiply(h, h), q, atol=1e-12)
        assert abs(np.linalg.norm(h) - 1.0) < 1e-12


def test_float_fast_path_matches_the_array_functions() -> None:
    rng = np.random.default_rng(41)
    for _ in range(50):
        a = rng.normal(size=4)  # not normalised: positive_floats must normalise
        q1, q2 = random_quaternion(rng), random_quaternion(rng)
        v = rng.normal(size=3)
        f1, f2 = qf.quat_floats(q1), qf.quat_floats(q2)
        assert qf.multiply_floats(f1, f2) == tuple(multiply(q1, q2))  # the same bits
        np.testing.assert_array_equal(qf.conjugate_floats(f1), conjugate(q1))
        np.testing.assert_allclose(
            qf.positive_floats(qf.quat_floats(a)), as_quaternion(a), atol=1e-14
        )
        np.testing.assert_allclose(
            qf.rotate_floats(f1, qf.vec_floats(v)), rotate(q1, v), atol=1e-12
        )
        np.testing.assert_allclose(
            qf.log_floats(qf.quat_floats(-q1)), quaternion_log(q1), atol=1e-12
        )
        np.testing.assert_allclose(
            qf.sqrt_floats(qf.quat_floats(-q1)), quaternion_sqrt(q1), atol=1e-14
        )


def test_log_of_a_tiny_rotation_and_of_nothing() -> None:
    q = (np.cos(1e-8), np.sin(1e-8), 0.0, 0.0)
    np.testing.assert_allclose(qf.log_floats(q), [2e-8, 0.0, 0.0], rtol=1e-9)
    assert qf.log_floats((0.0, 0.0, 0.0, 0.0)) == (0.0, 0.0, 0.0)


@given(
    st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3),
    st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3),
    st.booleans(),
)
@settings(max_examples=200, deadline=None)
@example([0.0, 0.0, 1.192092896e-07], [-1.0, 0.0, 0.0], False)  # nearly opposite x
def test_turn_x_onto_level_lays_x_along_and_y_level(
    v: list[float], d: list[float], down: bool
) -> None:
    direction = np.array(d)
    if np.linalg.norm(direction) < 1e-3 or np.hypot(d[0], d[1]) < 0.01 * np.linalg.norm(direction):
        return  # no level y about a (nearly) vertical x
    q0 = qf.from_rotation(Rotation.from_rotvec(0.3 * np.array(v)))
    if down:  # a grasp whose tool z points down
        q0 = qf.multiply(q0, [0.0, 1.0, 0.0, 0.0])
    q = qf.turn_x_onto_level(q0, direction)
    assert np.linalg.norm(q) == pytest.approx(1.0)
    # (1e-6: the shortest arc to a nearly opposite direction turns half
    # about an axis normal to x, good to about 1e-7)
    x = qf.rotate(q, [1.0, 0.0, 0.0])
    assert np.allclose(x, direction / np.linalg.norm(direction), atol=1e-6)
    assert abs(qf.rotate(q, [0.0, 1.0, 0.0])[2]) < 1e-6
    # only a roll about x follows the shortest arc, and z stays on the side
    # of the horizontal plane the arc leaves it on (the nearer level pose)
    arc = qf.turn_x_onto(q0, direction)
    z_arc, z = qf.rotate(arc, [0.0, 0.0, 1.0]), qf.rotate(q, [0.0, 0.0, 1.0])
    assert z[2] * z_arc[2] >= 0.0
    assert z @ z_arc >= -1e-9


@pytest.mark.parametrize("slope_deg", [-20.0, -40.0])
def test_following_a_cone_keeps_the_tool_level_where_the_shortest_arc_rolls(
    slope_deg: float,
) -> None:
    # a gripper that winds a cable 670 deg round a peg it slopes down to
    slope = np.radians(slope_deg)
    q_arc = q_level = np.array([1.0, 0.0, 0.0, 0.0])
    for a in np.radians(np.arange(0.0, 670.0, 0.25)):
        d = np.array([np.cos(slope) * np.cos(a), np.cos(slope) * np.sin(a), np.sin(slope)])
        q_arc = qf.turn_x_onto(q_arc, d)
        q_level = qf.turn_x_onto_level(q_level, d)
    assert abs(qf.rotate(q_level, [0.0, 1.0, 0.0])[2]) < 1e-9
    # the shortest arc alone has rolled the tool's y-axis far off level
    assert abs(qf.rotate(q_arc, [0.0, 1.0, 0.0])[2]) > np.sin(np.radians(30.0))
