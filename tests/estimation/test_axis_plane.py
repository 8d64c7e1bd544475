import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.axis_plane import axis_plane

finite = st.floats(-10.0, 10.0)


@given(finite, finite, finite)
def test_the_basis_is_orthonormal_and_right_handed(x: float, y: float, z: float) -> None:
    v = np.array([x, y, z])
    if np.linalg.norm(v) < 1e-3:
        return
    a, B = axis_plane(v)
    assert np.allclose(a, v / np.linalg.norm(v))
    assert np.allclose(B @ B.T, np.eye(2), atol=1e-12)
    assert np.allclose(B @ a, 0.0, atol=1e-12)
    assert np.allclose(np.cross(B[0], B[1]), a, atol=1e-12)


@pytest.mark.parametrize("bad", [[0.0, 0.0, 0.0], [np.nan, 0.0, 1.0], [np.inf, 0.0, 0.0]])
def test_a_zero_or_non_finite_axis_is_refused(bad: list[float]) -> None:
    with pytest.raises(InvalidArgumentError, match="axis"):
        axis_plane(bad)
