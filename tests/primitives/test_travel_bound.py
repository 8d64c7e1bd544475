import math

import numpy as np
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


def test_the_route_runs_on_through_a_clip_with_slack_behind_it() -> None:
    """A clip holds the cable across, not along: a pull draws the slack behind it through."""
    from tautwire.model import PathGraph
    from tautwire.primitives import make_context
    from tautwire.primitives.model_edits import move_hold
    from tautwire.primitives.model_estimator import TensionState
    from tautwire.primitives.travel_bound import route_to_fixed_point

    anchor, released = np.array([0.0, 0.0, 0.1]), np.array([0.06, 0.0, 0.07])
    clip, gripper = np.array([0.1, 0.0, 0.1]), np.array([0.2, 0.0, 0.1])
    graph = PathGraph.from_positions(
        [anchor, released, clip, gripper],
        mass_per_length=0.03,
        kinds=["fixed", "free", "fixed", "gripper"],
        labels=["A1", "released", "F5", "left"],
    )
    ctx = make_context(graph, "left", k_initial=500.0)
    est = ctx.estimator
    assert est.contact_index == 2
    state = TensionState(3.0, -np.array([1.0, 0, 0]), np.zeros(3), np.zeros(3), clip, 0.1, True)
    s = graph.arc_lengths()
    slack = float(s[2]) - 0.1  # the span behind F5: 0.117 m of cable over 0.1 m
    # without the clip's name, the route ends at it, as for an anchor
    plain = route_to_fixed_point(est, state)
    assert plain is not None and plain.through == ()
    assert plain.rest_length == pytest.approx(0.1) and plain.length == pytest.approx(0.1)
    route = route_to_fixed_point(est, state, {"F5"})
    assert route is not None and route.through == ((2, pytest.approx(slack)),)
    assert route.length == pytest.approx(0.2)
    assert route.rest_length == pytest.approx(float(s[3]))
    # drawn through: F5 moves back along the cable by the slack, the span behind it straight
    move_hold(graph, 2, -slack)
    f5 = graph.index_of("fixed", "F5")
    assert f5 == 2  # the released point stays: the slack came out of its edge
    behind = graph.arc_lengths()[f5]
    assert behind == pytest.approx(0.1)
    assert route_to_fixed_point(est, state, {"F5"}).through == ()  # type: ignore[union-attr]


def test_through_all_runs_through_every_clip_to_the_point_that_holds_the_cable() -> None:
    """D's retake: slack the model does not know of was drawn through the clips."""
    from tautwire.primitives.model_estimator import TensionState
    from tautwire.primitives.travel_bound import route_to_fixed_point

    f3 = np.array([0.1, 0.1, 0.08])
    points = {"A1": [0.0, 0.0, 0.08], "F2": [0.1, 0.0, 0.08], "F3": f3, "left": [0.2, 0.1, 0.1]}
    graph, est = _chain(points, ["fixed", "fixed", "fixed", "gripper"])
    assert est.contact_index == 2
    state = TensionState(3.0, -np.array([1.0, 0, 0]), np.zeros(3), np.zeros(3), f3, 0.1, True)
    s = graph.arc_lengths()
    # every span straight in the model: the route ends at F3
    route = route_to_fixed_point(est, state, {"F2", "F3"})
    assert route is not None and route.through == ()
    assert route.rest_length == pytest.approx(float(s[3] - s[2]))
    # through all: on to the anchor, the whole cable from it bounding the travel
    route = route_to_fixed_point(est, state, {"F2", "F3"}, through_all=True)
    assert route is not None
    assert [i for i, _ in route.through] == [2, 1]
    assert all(slack == pytest.approx(0.0, abs=1e-9) for _, slack in route.through)
    assert route.rest_length == pytest.approx(float(s[3]))
    assert route.length == pytest.approx(0.1 + 0.1 + 0.1)  # the span measured, then straight


def _chain(points: dict[str, object], kinds: list[str]):  # type: ignore[no-untyped-def]
    """The path graph through ``points`` (label -> position) and its estimator, k 500 N/m."""
    from tautwire.model import PathGraph
    from tautwire.primitives import make_context

    graph = PathGraph.from_positions(
        [np.asarray(p, dtype=float) for p in points.values()],
        mass_per_length=0.03,
        kinds=kinds,
        labels=list(points),
    )
    return graph, make_context(graph, "left", k_initial=500.0).estimator
