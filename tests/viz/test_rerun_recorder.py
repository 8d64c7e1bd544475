"""The Rerun recording of a run, read back with Rerun's own reader."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tautwire.cli.main import main
from tests.cli.test_run import TENSION_ROTATE

rerun_chunk = pytest.importorskip("rerun.chunk")


def _rows(path: Path) -> dict[str, int]:
    """Rows logged per entity path (static ones included)."""
    rows: dict[str, int] = {}
    for chunk in rerun_chunk.RrdReader(path).stream().collect().stream():
        rows[chunk.entity_path] = rows.get(chunk.entity_path, 0) + chunk.num_rows
    return rows


def test_run_records_the_model_over_the_truth(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    from tautwire.viz import rerun_recorder

    counts: dict[str, int] = {}
    real_close = rerun_recorder.RerunRecorder.close

    def close(self: rerun_recorder.RerunRecorder) -> Path:
        counts.update(ticks=self.ticks, snapshots=self.snapshots, estimates=self.estimates)
        return real_close(self)

    monkeypatch.setattr(rerun_recorder.RerunRecorder, "close", close)
    scenario = tmp_path / "tension-rotate.yaml"
    scenario.write_text(TENSION_ROTATE)
    rrd = tmp_path / "run.rrd"
    assert main(["run", str(scenario), "--rerun", str(rrd), "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["files"]["rerun"] == str(rrd)
    rows = _rows(rrd)
    ticks, snapshots, estimates = counts["ticks"], counts["snapshots"], counts["estimates"]
    sim_time = sum(s["sim_time"] for s in result["steps"])
    assert ticks == pytest.approx(sim_time / 0.004, rel=0.01)  # every period the robot acted
    assert snapshots == pytest.approx(sim_time / 0.04, rel=0.05)
    for axis in ("x", "y", "z", "norm"):
        assert rows[f"/wrench/force/{axis}"] == ticks
    for axis in ("x", "y", "z"):
        assert rows[f"/wrench/torque/{axis}"] == ticks
    assert rows["/grippers/left"] == rows["/grippers/right"] == ticks + 1  # + the static axes
    assert rows["/model/points"] == rows["/model/edges"] == snapshots
    assert rows["/truth/cable"] == snapshots
    assert rows["/model/uncertainty"] == snapshots
    assert 0 < estimates <= snapshots
    assert rows["/contact/estimate"] == rows["/contact/truth"] == estimates
    assert rows["/contact/error"] == estimates
    assert rows["/steps"] == 2 * len(result["steps"])  # a start and an end line each
    assert rows["/board/fixtures"] == 1


def test_missing_rerun_is_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    import builtins

    real_import = builtins.__import__

    def no_rerun(name: str, *args: object, **kwargs: object) -> object:
        if name == "rerun" or name.startswith("rerun."):
            raise ImportError(f"No module named {name!r}")
        return real_import(name, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(builtins, "__import__", no_rerun)
    scenario = tmp_path / "tension-rotate.yaml"
    scenario.write_text(TENSION_ROTATE)
    assert main(["run", str(scenario), "--rerun", str(tmp_path / "x.rrd")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "tautwire[rerun]" in err[0]
