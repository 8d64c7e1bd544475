import pytest

from tautwire.cli.main import main
from tautwire.experiments.fig5a import run_case


def test_unknown_reproduction_is_one_line(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["reproduce", "fig9z"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "fig5a" in err[0]


@pytest.mark.slow
def test_fig5a_stiff_cable_adaptive_beats_fixed_gain() -> None:
    adaptive, _ = run_case(1000.0, adaptive=True)
    fixed, _ = run_case(1000.0, adaptive=False)
    assert adaptive.outcome == "success"
    assert adaptive.tension_rms_error <= 0.05
    assert adaptive.max_force < 15.0
    assert adaptive.tension_rms_error < fixed.tension_rms_error


@pytest.mark.slow
def test_fig5b_files_and_convergence(tmp_path) -> None:  # type: ignore[no-untyped-def]
    from tautwire.experiments.fig5bc import reproduce_fig5b

    result = reproduce_fig5b(tmp_path)
    assert 110 <= result["iterations"] <= 140  # about 125 iterations a circle
    assert result["final_error"] < 0.002
    assert result["run"]["success"]
    for ext in ("png", "csv", "json"):
        assert (tmp_path / f"fig5b.{ext}").stat().st_size > 100
