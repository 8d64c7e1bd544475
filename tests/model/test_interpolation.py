import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from tautwire.errors import InvalidArgumentError
from tautwire.model.interpolation import lerp, slerp
from tautwire.model.quaternion import as_quaternion, from_rotation

quaternions = st.lists(st.floats(-1, 1), min_size=4, max_size=4).filter(
    lambda q: np.linalg.norm(q) > 0.1
)


def same_rotation(q1: np.ndarray, q2: np.ndarray) -> bool:
    return abs(abs(float(np.dot(q1, q2))) - 1.0) < 1e-9


def test_lerp() -> None:
    assert lerp([0, 0, 0], [1, 2, 4], 0.25) == pytest.approx([0.25, 0.5, 1.0])


@settings(max_examples=50, deadline=None)
@given(quaternions, quaternions)
def test_slerp_endpoints(q_a: list[float], q_b: list[float]) -> None:
    assert same_rotation(slerp(q_a, q_b, 0.0), as_quaternion(q_a))
    assert same_rotation(slerp(q_a, q_b, 1.0), as_quaternion(q_b))


def test_slerp_midpoint_about_one_axis() -> None:
    q0 = from_rotation(Rotation.from_euler("z", 0.0))
    q1 = from_rotation(Rotation.from_euler("z", 1.2))
    mid = slerp(q0, q1, 0.5)
    assert same_rotation(mid, from_rotation(Rotation.from_euler("z", 0.6)))


def test_slerp_follows_the_paper_formula() -> None:
    """Q_k = Q_{k-1} (Q_{k-1}^-1 Q_{k+1})^delta."""
    rng = np.random.default_rng(3)
    r0, r1 = Rotation.random(2, random_state=rng)
    delta = 0.3
    expected = r0 * Rotation.from_rotvec(delta * (r0.inv() * r1).as_rotvec())
    assert same_rotation(
        slerp(from_rotation(r0), from_rotation(r1), delta), from_rotation(expected)
    )


def test_delta_outside_unit_interval_is_rejected() -> None:
    with pytest.raises(InvalidArgumentError):
        lerp([0, 0, 0], [1, 1, 1], 1.5)
