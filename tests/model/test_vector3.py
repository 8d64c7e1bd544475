import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.model.vector3 import cross3, nearest_on_segment, norm3

vec = st.lists(st.floats(-1e3, 1e3), min_size=3, max_size=3)


@settings(max_examples=100, deadline=None)
@given(vec, vec)
def test_matches_numpy(a: list[float], b: list[float]) -> None:
    assert cross3(a, b) == pytest.approx(np.cross(a, b), rel=1e-12, abs=1e-9)
    assert norm3(a) == pytest.approx(float(np.linalg.norm(a)), rel=1e-12, abs=1e-12)


@settings(max_examples=100, deadline=None)
@given(
    st.lists(st.floats(-1.0, 1.0), min_size=9, max_size=9),
)
def test_nearest_on_segment_is_no_farther_than_any_point_of_the_segment(v: list[float]) -> None:
    p, a, b = np.array(v[0:3]), np.array(v[3:6]), np.array(v[6:9])
    q = nearest_on_segment(p, a, b)
    best = np.linalg.norm(p - q)
    for t in np.linspace(0.0, 1.0, 101):
        assert best <= np.linalg.norm(p - (a + t * (b - a))) + 1e-12
    # on the segment: the distances to its ends add up to its length
    assert np.linalg.norm(q - a) + np.linalg.norm(q - b) == pytest.approx(
        np.linalg.norm(b - a), abs=1e-9
    )


def test_nearest_on_a_point_segment_and_in_the_plane() -> None:
    a = np.array([0.1, 0.2, 0.3])
    assert np.array_equal(nearest_on_segment([5.0, 5.0, 5.0], a, a), a)
    # two-dimensional, as the board's plan view uses it: beyond the end, the end
    q = nearest_on_segment([2.0, 1.0], [0.0, 0.0], [1.0, 0.0])
    assert np.allclose(q, [1.0, 0.0])
