"""SensorTare: an offset well beyond the expected load is removed, a small real load is not."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.tasks.sensor_tare import TARE_SIGMAS, SensorTare


def fed(tare: SensorTare, mean: list[float], noise: float, seed: int = 0) -> SensorTare:
    rng = np.random.default_rng(seed)
    while not tare.done:
        tare.add(np.asarray(mean) + noise * rng.standard_normal(3))
    return tare


def test_threshold_is_the_tolerance_plus_the_noise_of_the_median() -> None:
    tare = SensorTare(12, [0.0, 0.0, -0.1], 0.3, 0.05)
    noise = TARE_SIGMAS * 1.2533 * math.sqrt(3.0) * 0.05 / math.sqrt(12)
    assert tare.threshold == pytest.approx(0.3 + noise)


@pytest.mark.parametrize("seed", range(5))
def test_an_offset_beyond_the_threshold_is_estimated(seed: int) -> None:
    tare = fed(SensorTare(12, [0.0, 0.0, -0.1], 0.3, 0.05), [1.0, -0.5, -0.1], 0.05, seed)
    assert tare.offset == pytest.approx([1.0, -0.5, 0.0], abs=0.06)


@pytest.mark.parametrize("seed", range(5))
def test_a_load_within_the_tolerance_is_kept(seed: int) -> None:
    tare = fed(SensorTare(12, [0.0, 0.0, -0.1], 0.3, 0.05), [0.2, 0.0, -0.25], 0.05, seed)
    assert not np.any(tare.offset)


def test_nothing_is_removed_before_the_samples_are_taken_and_after_it_is_done() -> None:
    tare = SensorTare(3, [0.0, 0.0, 0.0], 0.0, 0.0)
    tare.add([5.0, 0.0, 0.0])
    assert not tare.done and not np.any(tare.offset)
    tare.add([5.0, 0.0, 0.0])
    tare.add([5.0, 0.0, 0.0])
    assert tare.done and tare.offset == pytest.approx([5.0, 0.0, 0.0])
    tare.add([50.0, 0.0, 0.0])
    assert tare.offset == pytest.approx([5.0, 0.0, 0.0])


@pytest.mark.parametrize(
    ("args", "words"),
    [
        ((0, [0, 0, 0], 0.1, 0.05), "samples"),
        ((3, [0, 0], 0.1, 0.05), "expected"),
        ((3, [0, 0, np.nan], 0.1, 0.05), "expected"),
        ((3, [0, 0, 0], -0.1, 0.05), "tolerance"),
        ((3, [0, 0, 0], 0.1, np.inf), "force_noise"),
    ],
)
def test_arguments_are_validated(args: tuple, words: str) -> None:
    with pytest.raises(InvalidArgumentError, match=words):
        SensorTare(*args)
