"""The span's turn in a rotation, read from the pull alone (primitives/turn_check.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.primitives.turn_check import START_SAMPLES, TurnCheck, axis_angle

Z = np.array([0.0, 0.0, 1.0])


def _pull(angle: float, size: float = 3.0, sag: float = -0.4) -> np.ndarray:
    return np.array([size * math.cos(angle), size * math.sin(angle), sag])


def test_axis_angle_is_signed_and_ignores_the_axis_part() -> None:
    assert axis_angle([1, 0, 5], [0, 1, -2], Z) == pytest.approx(math.pi / 2)
    assert axis_angle([0, 1, 0], [1, 0, 0], Z) == pytest.approx(-math.pi / 2)
    assert axis_angle([1, 0, 0], [-1, 1e-12, 0], Z) == pytest.approx(math.pi)


@settings(max_examples=200, deadline=None)
@given(
    start=st.floats(-math.pi, math.pi),
    turn=st.floats(-14.0, 14.0),  # past two full turns either way
    count_error=st.floats(-2.5, 2.5),  # a count off by up to 143 deg still picks the winding
    noise_seed=st.integers(0, 2**16),
)
def test_the_pull_reads_the_turn_on_the_counted_winding(
    start: float, turn: float, count_error: float, noise_seed: int
) -> None:
    rng = np.random.default_rng(noise_seed)
    check = TurnCheck(Z)
    for _ in range(START_SAMPLES + 3):  # samples past the start's are not used
        check.add_start(_pull(start) + rng.normal(0.0, 0.05, 3))
    end = _pull(start + turn, size=1.0)
    turned = check.turned(end, turn + count_error)
    assert turned is not None
    assert turned == pytest.approx(turn, abs=math.radians(2.0))


def test_no_reading_without_a_start_or_a_pull_across_the_axis() -> None:
    check = TurnCheck(Z)
    assert check.turned(_pull(0.3), 0.3) is None  # no start yet
    for _ in range(START_SAMPLES):
        check.add_start(np.array([0.01, 0.0, 3.0]))  # along the axis: not a direction
        check.add_start(np.array([np.nan, 0.0, 0.0]))
    assert not check.started
    for _ in range(START_SAMPLES):
        check.add_start(_pull(0.0))
    assert check.started
    assert check.turned(np.array([0.0, 0.0, 1.0]), 0.5) is None
    assert check.turned(np.zeros(3), 0.5) is None
    with pytest.raises(InvalidArgumentError, match="axis"):
        TurnCheck([0.0, 0.0, 0.0])


def test_random_board_483199372_reads_the_turn_the_count_missed() -> None:
    # I circled about the anchor while the cable wrapped the near peg F1: the
    # path counted 20.3 deg; the pull (the measured force, start and end of
    # the turn as the run logged it) turned 41 deg; the simulator 39 deg
    check = TurnCheck(Z)
    for _ in range(START_SAMPLES):
        check.add_start(np.array([-2.52, -1.45, -0.10]))
    turned = check.turned(np.array([-0.95, -2.83, -0.14]), math.radians(20.3))
    assert turned is not None
    assert math.degrees(turned) == pytest.approx(41.5, abs=0.5)
