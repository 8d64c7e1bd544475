import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.model.vector3 import cross3, norm3

vec = st.lists(st.floats(-1e3, 1e3), min_size=3, max_size=3)


@settings(max_examples=100, deadline=None)
@given(vec, vec)
def test_matches_numpy(a: list[float], b: list[float]) -> None:
    assert cross3(a, b) == pytest.approx(np.cross(a, b), rel=1e-12, abs=1e-9)
    assert norm3(a) == pytest.approx(float(np.linalg.norm(a)), rel=1e-12, abs=1e-12)
