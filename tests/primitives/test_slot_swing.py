import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from tautwire.primitives.slot_swing import (
    BEND_PER_TURN,
    LEAST_TURN,
    STALL_TIME,
    SWING_BEND,
    SWING_RATE,
    SlotSwing,
    turn_onto,
    turned,
)

PERIOD = 0.004
JAW_TOP = 0.008


def _slot(yaw: float) -> np.ndarray:
    return np.array([math.cos(yaw), math.sin(yaw), 0.0])


@given(st.floats(-math.pi, math.pi), st.floats(-1.4, 1.4), st.sampled_from([1.0, -1.0]))
def test_turn_onto_lands_on_the_slot_axis(out_yaw: float, across: float, sign: float) -> None:
    out = _slot(out_yaw)
    slot = sign * _slot(out_yaw + across)
    turn = turn_onto(out, slot)
    assert abs(turn) <= 0.5 * math.pi + 1e-9
    landed = turned(out, turn)
    # the slot's direction that points the same way as out, whatever its sign
    assert np.allclose(landed, slot * math.copysign(1.0, float(slot @ out)), atol=1e-9)


def test_turn_onto_is_zero_along_the_slot() -> None:
    assert turn_onto(_slot(0.3), -_slot(0.3)) == pytest.approx(0.0, abs=1e-12)


def _descend(swing: SlotSwing, rest: float, rate: float = 0.15) -> list[tuple[float, float]]:
    """A push: the line drops 8 mm/s from 15 mm until it rests at ``rest`` [m]."""
    angle, time, turns = -0.2, 0.0, []
    height = 0.015
    for _ in range(3000):
        turn = swing.step(time, height, angle, PERIOD)
        turns.append((angle, turn))
        angle += rate * PERIOD
        height = max(height - 0.008 * PERIOD, rest)
        time += PERIOD
    return turns


def test_no_turn_while_the_line_still_drops() -> None:
    swing = SlotSwing(math.radians(8.0), JAW_TOP)
    turns = _descend(swing, rest=-1.0)  # never stops: falls through past the jaws
    assert swing.touch is None
    assert all(t == 0.0 for _, t in turns)


def test_no_turn_when_the_line_stalls_high_above_the_jaws() -> None:
    swing = SlotSwing(math.radians(8.0), JAW_TOP)
    _descend(swing, rest=0.02)  # held up 12 mm over the jaws' top: not on them
    assert swing.touch is None


def test_turns_with_the_bend_past_the_touch_then_stops() -> None:
    total = math.radians(8.0)
    swing = SlotSwing(total, JAW_TOP)
    turns = _descend(swing, rest=0.009)  # rests 1 mm over the jaws' top
    assert swing.touch is not None
    made = [(a, t) for a, t in turns if t != 0.0]
    assert sum(t for _, t in made) == pytest.approx(total, abs=1e-9)
    assert all(abs(t) <= SWING_RATE * PERIOD + 1e-12 for _, t in made)
    bend = max(SWING_BEND, BEND_PER_TURN * total)
    # from the touch on, in step with the bend: done once bent by ``bend``
    assert min(a for a, _ in made) >= swing.touch
    assert max(a for a, _ in made) <= swing.touch + bend + 0.15 * PERIOD
    done = 0.0
    for a, t in turns:
        done += t
        if a > swing.touch:
            share = min((a - swing.touch) / bend, 1.0)
            assert done == pytest.approx(total * share, abs=SWING_RATE * PERIOD + 1e-9)
    # the touch is read within a stall window of the rest
    rest_time = (0.015 - 0.009) / 0.008
    rest_angle = -0.2 + 0.15 * rest_time
    assert swing.touch == pytest.approx(rest_angle + 0.15 * STALL_TIME, abs=0.01)


def test_a_small_turn_is_not_made() -> None:
    swing = SlotSwing(0.5 * LEAST_TURN, JAW_TOP)
    turns = _descend(swing, rest=0.009)
    assert all(t == 0.0 for _, t in turns)
