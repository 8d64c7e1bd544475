import numpy as np
import pytest

from tautwire.primitives.clip_sensing import ClipHeight, height_at_clip, push_tension


def test_height_where_the_force_line_passes_the_clip() -> None:
    p = np.array([0.1, 0.0, 0.05])
    seat = np.array([0.0, 0.0, 0.02])
    d = np.array([-1.0, 0.0, -0.2]) / np.hypot(1.0, 0.2)
    assert height_at_clip(p, d, seat) == pytest.approx(0.05 - 0.2 * 0.1)
    assert height_at_clip(p, -d, seat) is None  # pointing away
    assert height_at_clip(p, np.array([0.0, 0.0, -1.0]), seat) is None


def test_seated_from_the_exit_of_the_slot() -> None:
    seat = np.array([0.0, 0.0, 0.0])
    sensing = ClipHeight(seat, np.array([1.0, 0.0, 0.0]), 0.006)
    p = np.array([0.056, 0.0, -0.05])  # 5 cm beyond the slot's exit, 5 cm below
    d = (np.array([0.006, 0.0, 0.0]) - p) / np.linalg.norm(np.array([0.006, 0.0, 0.0]) - p)
    for k in range(50):
        sensing.update(0.004 * k, p, d, True)
    assert sensing.height == pytest.approx(0.0, abs=1e-9) and sensing.seated


def test_push_tension_bounds() -> None:
    assert push_tension(2.0, 1.0, 15.0) == 6.0
    assert push_tension(5.0, 1.0, 15.0) == 9.0  # 60 % of the limit
    assert push_tension(1.0, 4.0, 15.0) == 4.0
