"""``tautwire view``: MuJoCo's passive viewer on a running task, under a virtual display."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from tautwire.cli.main import main
from tests.cli.test_run import TENSION_ONLY

XVFB = shutil.which("xvfb-run")
needs_xvfb = pytest.mark.skipif(XVFB is None, reason="xvfb-run is not installed (Debian: xvfb)")


def test_view_without_a_display_says_so_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    scenario = tmp_path / "tension-only.yaml"
    scenario.write_text(TENSION_ONLY)
    assert main(["view", str(scenario)]) != 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "no display" in err[0] and "viewer" in err[0]


def _under_xvfb(script: str, tmp_path: Path) -> subprocess.CompletedProcess[str]:
    assert XVFB is not None
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    return subprocess.run(
        [XVFB, "-a", "-s", "-screen 0 1024x768x24", sys.executable, "-c", script],
        capture_output=True,
        text=True,
        timeout=300,
        cwd=tmp_path,
        env={**env, "PYTHONPATH": str(Path(__file__).parents[2])},
    )


@needs_xvfb
def test_view_runs_the_task_live_and_draws_the_model(tmp_path: Path) -> None:
    scenario = tmp_path / "tension-only.yaml"
    scenario.write_text(TENSION_ONLY)
    script = textwrap.dedent(
        f"""
        import json
        from tautwire.scenario import load_scenario
        from tautwire.experiments.run_scenario import run_scenario
        from tautwire.sim.live_viewer import LiveViewer
        from tautwire.sim.model_overlay import FIXTURE_COLOURS

        viewers, seen = [], []

        def on_world(world):
            viewers.append(LiveViewer(world, speed=0.0, frame_rate=20.0))

        def on_tick(rec):
            v = viewers[0]
            v.show(rec.context.graph)
            scn = v._handle.user_scn
            labels = sorted({{scn.geoms[i].label for i in range(scn.ngeom)}})
            seen.append((scn.ngeom, v.drawn, labels))

        result, ctx, _ = run_scenario(load_scenario({str(scenario)!r}), on_world=on_world,
                                      on_tick=on_tick)
        v = viewers[0]
        import mujoco
        gid = mujoco.mj_name2id(v._world.model, mujoco.mjtObj.mjOBJ_GEOM, "A1")
        rgba = [float(c) for c in v._world.model.geom_rgba[gid]]
        v.close()
        print(json.dumps({{"success": result.success, "frames": v.frames, "last": seen[-1],
                          "anchor_rgba": rgba, "want": list(FIXTURE_COLOURS["anchor"]),
                          "points": len(ctx.graph)}}))
        """
    )
    done = _under_xvfb(script, tmp_path)
    assert done.returncode == 0, done.stderr[-2000:]
    import json

    out = json.loads(done.stdout.strip().splitlines()[-1])
    assert out["success"] is True and out["frames"] > 10
    ngeom, drawn, labels = out["last"]
    # the model: one capsule per edge, one sphere per point (+ ellipsoids), and the label
    assert drawn >= 2 * out["points"] - 1 and ngeom == drawn + 1
    assert "A1 (anchor)" in labels
    assert out["anchor_rgba"] == pytest.approx(out["want"])


@needs_xvfb
def test_view_command_exits_with_the_runs_status(tmp_path: Path) -> None:
    scenario = tmp_path / "tension-only.yaml"
    scenario.write_text(TENSION_ONLY)
    script = (
        "import sys; from tautwire.cli.main import main; "
        f"sys.exit(main(['view', {str(scenario)!r}, '--speed', '0', '--no-hold']))"
    )
    done = _under_xvfb(script, tmp_path)
    assert done.returncode == 0, done.stderr[-2000:]
    assert "step 1 D single_arm_tension: success" in done.stderr
    assert "tension-only: success" in done.stderr
