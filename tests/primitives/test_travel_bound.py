import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.primitives.travel_bound import TravelBound


def test_bound_is_rest_length_plus_stretch_at_the_force_limit_plus_margins() -> None:
    bound = TravelBound(15.0, margin=0.03, relative_margin=0.05)
    assert not bound.update(0.5, 0.5, 0.0, 1000.0)
    assert bound.allowed == pytest.approx(0.5 * 1.05 + 0.03 + 15.0 / 1000.0)


def test_an_intact_stiff_cable_never_trips_it() -> None:
    bound = TravelBound(15.0)
    k, rest = 1000.0, 0.4
    for tension in (0.5, 2.0, 8.0, 14.9):
        assert not bound.update(rest + tension / k, rest, tension, k)


def test_a_soft_cable_on_a_stiff_estimate_is_bounded_by_its_secant() -> None:
    # k_route says 100 N/m, the cable is 10 N/m: the peak's secant widens the bound
    bound = TravelBound(15.0)
    rest = 0.3
    for tension in (0.5, 1.0, 2.0, 4.0):
        assert not bound.update(rest + tension / 10.0, rest, tension, 100.0)
    assert bound.stiffness(100.0) == pytest.approx(10.0)
    assert bound.allowed >= rest + 15.0 / 10.0


def test_a_slip_keeps_the_bound_where_the_peak_left_it() -> None:
    bound = TravelBound(15.0)
    rest, k = 0.3, 500.0
    assert not bound.update(rest + 3.0 / k, rest, 3.0, k)
    allowed = bound.allowed
    route = rest + 3.0 / k
    tripped = False
    for _ in range(200):  # the cable slides through: the tension drops, the gripper pulls on
        route += 0.004
        tripped = bound.update(route, rest, 0.2, k)
        if tripped:
            break
    assert tripped
    assert bound.allowed == pytest.approx(allowed)
    assert route <= allowed + 0.004


def test_non_finite_input_never_trips_it() -> None:
    bound = TravelBound(15.0)
    assert not bound.update(math.nan, 0.3, 1.0, 100.0)
    assert not bound.update(10.0, 0.3, math.inf, 100.0)


def test_arguments_are_checked() -> None:
    with pytest.raises(InvalidArgumentError):
        TravelBound(0.0)
    with pytest.raises(InvalidArgumentError):
        TravelBound(15.0, margin=-0.01)
    with pytest.raises(InvalidArgumentError):
        TravelBound(15.0, relative_margin=math.nan)


@given(
    k=st.floats(10.0, 5000.0),
    rest=st.floats(0.05, 1.5),
    tensions=st.lists(st.floats(0.0, 15.0), min_size=1, max_size=20),
    k_estimate=st.floats(1.0, 1e5),
)
def test_a_cable_that_obeys_hooke_never_trips_it_below_the_force_limit(
    k: float, rest: float, tensions: list[float], k_estimate: float
) -> None:
    # whatever the estimate: once taut, the peak's secant is k itself; below the
    # taut tension, a cable of 10 N/m or stiffer stretches less than the margin
    bound = TravelBound(15.0)
    for t in tensions:
        assert not bound.update(rest + t / k, rest, t, k_estimate)
