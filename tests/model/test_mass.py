import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.model.mass import point_masses


def test_end_points_get_half_an_edge_and_inner_points_half_of_two() -> None:
    m = point_masses([0.2, 0.3, 0.1], 0.05)
    assert m == pytest.approx([0.005, 0.0125, 0.01, 0.0025])


@settings(max_examples=50, deadline=None)
@given(st.lists(st.floats(0.0, 1.0), min_size=1, max_size=20), st.floats(0.0, 1.0))
def test_masses_add_up_to_the_cable(lengths: list[float], rho: float) -> None:
    assert float(np.sum(point_masses(lengths, rho))) == pytest.approx(rho * sum(lengths), abs=1e-12)


def test_rejects_negative_values() -> None:
    with pytest.raises(InvalidArgumentError):
        point_masses([0.1, -0.1], 0.03)
    with pytest.raises(InvalidArgumentError):
        point_masses([0.1], -1.0)
