"""Placing vertices on a cable."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.sim import CableSpec, HoldSpec, SimOptions
from tautwire.sim.discretization import discretize_cable

END_HOLD = (HoldSpec("left", 0.42),)


def _cable(holds=END_HOLD, start="A", length=0.42) -> CableSpec:
    return CableSpec("W", length, 0.03, 200.0, 0.0025, start=start, holds=holds)


def test_held_points_and_pad_exits_are_vertices() -> None:
    opt = SimOptions()
    d = discretize_cable(_cable((HoldSpec("left", 0.2), HoldSpec("right", 0.42))), 15.0, opt)
    for a in (0.2 - opt.pad_exit, 0.2, 0.2 + opt.pad_exit, 0.42 - opt.pad_exit, 0.42):
        assert np.min(np.abs(d.arc - a)) < 1e-12
    assert d.rest_lengths.max() <= opt.segment_length + 1e-12
    assert d.vertex_at(0.2) == int(np.argmin(np.abs(d.arc - 0.2)))


def test_mass_and_series_stiffness_are_the_cable_s() -> None:
    d = discretize_cable(_cable(), 15.0, SimOptions())
    assert d.masses.sum() == pytest.approx(0.03 * 0.42)
    assert 1.0 / np.sum(1.0 / d.segment_stiffness) == pytest.approx(200.0)
    assert d.rest_lengths.sum() == pytest.approx(0.42)


def test_a_tiny_free_tail_is_merged_keeping_its_mass() -> None:
    d = discretize_cable(_cable((HoldSpec("left", 0.418),)), 15.0, SimOptions())
    assert d.arc[-1] == pytest.approx(0.418)
    assert d.masses.sum() == pytest.approx(0.03 * 0.42)


def test_segments_option_sets_the_count() -> None:
    d = discretize_cable(_cable(), 15.0, SimOptions(segments=30))
    assert d.segments in (30, 31)


def test_mass_scaling_keeps_the_wave_speed_limit() -> None:
    opt = SimOptions(timestep=0.001)
    d = discretize_cable(_cable(), 15.0, opt)
    assert d.max_timestep * opt.wave_speed_safety >= opt.timestep * (1 - 1e-9)
    assert np.all(d.mass_scaling >= 1.0)
