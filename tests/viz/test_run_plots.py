import numpy as np
import pytest

from tautwire.model import PathGraph
from tautwire.viz.run_plots import TRUE_CABLE_COLOURS, model_views_figure, plot_model_views

FIXTURES = {"A1": ("anchor", [0.1, 0.0, 0.08]), "P1": ("peg", [0.3, 0.05, 0.05])}


def _cable(y: float) -> tuple[PathGraph, np.ndarray]:
    graph = PathGraph.from_positions(
        [[0.1, y, 0.08], [0.3, y, 0.08], [0.5, y, 0.1]],
        mass_per_length=0.03,
        stiffness=200.0,
        kinds=["fixed", "contact", "gripper"],
        labels=["A1", "P1", "left"],
    )
    truth = np.column_stack([np.linspace(0.1, 0.5, 9), np.full(9, y), np.full(9, 0.08)])
    return graph, truth


def _labels(fig: object) -> list[str]:
    return [line.get_label() for line in fig.axes[0].get_lines()]  # type: ignore[attr-defined]


def test_one_cable_is_the_true_cable() -> None:
    graph, truth = _cable(0.0)
    labels = _labels(model_views_figure([("W1", graph, truth)], FIXTURES))
    assert "true cable" in labels and "model edges" in labels


def test_every_cable_is_drawn_in_its_own_colour() -> None:
    """A two-cable run shows both models over both true cables, not the first alone."""
    (g1, t1), (g2, t2) = _cable(0.0), _cable(-0.2)
    fig = model_views_figure([("W1", g1, t1), ("W2", g2, t2)], FIXTURES)
    for ax in fig.axes[:2]:
        true = {
            line.get_label(): line.get_color()
            for line in ax.get_lines()
            if str(line.get_label()).startswith("true cable")
        }
        assert set(true) == {"true cable W1", "true cable W2"}
        assert true["true cable W1"] == TRUE_CABLE_COLOURS[0]
        assert true["true cable W2"] == TRUE_CABLE_COLOURS[1]
        # both models' edges: 3 points each
        edges = [line for line in ax.get_lines() if line.get_color() == "k"]
        assert len(edges) == 2
    y = sorted(float(line.get_ydata()[0]) for line in fig.axes[0].get_lines()[:4])
    assert y == pytest.approx([-200.0, -200.0, 0.0, 0.0])


def test_the_png_is_written(tmp_path) -> None:  # type: ignore[no-untyped-def]
    graph, truth = _cable(0.0)
    path = plot_model_views(tmp_path / "views.png", [("W1", graph, truth)], FIXTURES)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
