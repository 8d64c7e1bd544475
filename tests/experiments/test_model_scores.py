"""Whole-cable scoring: the modelled cable sampled along its arc length against the truth."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("mujoco")

from tautwire.experiments.truth import (
    SHAPE_STEP,
    deviation_summary,
    model_samples,
    shape_deviations,
)
from tautwire.model import PathGraph


def _taut() -> PathGraph:
    return PathGraph.from_positions(
        [[0.0, 0.0, 0.1], [0.3, 0.0, 0.1], [0.3, 0.0, 0.0]],
        0.03,
        kinds=["fixed", "gripper", "free"],
        labels=["A1", "left", "end"],
    )


def test_a_taut_model_is_sampled_every_5_mm_along_its_edges() -> None:
    samples = model_samples(_taut())
    assert len(samples) == 1 + round(0.3 / SHAPE_STEP) + round(0.1 / SHAPE_STEP)
    steps = np.linalg.norm(np.diff(samples, axis=0), axis=1)
    assert np.allclose(steps, SHAPE_STEP)


def test_a_slack_edge_sags_by_its_sag_at_mid_span() -> None:
    graph = PathGraph.from_positions(
        [[0.0, 0.0, 0.1], [0.3, 0.0, 0.1]],
        0.03,
        lengths=[0.32],
        kinds=["fixed", "gripper"],
        labels=["A1", "left"],
    )
    sag = graph.edges[0].sag
    assert sag > 0.01
    samples = model_samples(graph)
    assert float(np.min(samples[:, 2])) == pytest.approx(0.1 - sag, abs=1e-4)


def test_the_model_on_the_true_cable_scores_zero_and_an_offset_its_size() -> None:
    graph = _taut()
    polyline = model_samples(graph)
    assert np.allclose(shape_deviations(graph, polyline), 0.0, atol=1e-12)
    shifted = polyline + np.array([0.0, 0.004, -0.002])
    # every sample of the straight horizontal edge is 4 mm beside, 2 mm above the true cable
    d = shape_deviations(graph, shifted)[1:60]
    assert np.allclose(d[:, 0], 0.004, atol=1e-9)
    assert np.allclose(d[:, 1], 0.002, atol=1e-9)


def test_deviation_summary() -> None:
    assert deviation_summary([], []) is None
    s = deviation_summary([0.001, 0.003], [0.002, 0.0])
    assert s == pytest.approx(
        {
            "horizontal_mean": 0.002,
            "horizontal_max": 0.003,
            "vertical_mean": 0.001,
            "vertical_max": 0.002,
        }
    )
