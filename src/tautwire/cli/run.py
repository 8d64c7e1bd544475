"""``tautwire run SCENARIO``: simulate a scenario and score it (optionally on video)."""

from __future__ import annotations

import click
from rich.console import Console
from rich.table import Table

from tautwire.scenario import load_scenario
from tautwire.scenario.registry import resolve_scenario

#: Output folder of ``--video`` when ``--out`` is not given.
DEFAULT_VIDEO_OUT = "out/run"


@click.command()
@click.argument("scenario_file", metavar="SCENARIO", type=click.Path(dir_okay=False))
@click.option("--seed", type=int, default=None, help="override the scenario's seed")
@click.option(
    "--out",
    "out_dir",
    type=click.Path(file_okay=False),
    default=None,
    help=f"folder for result.json and the video (default with --video: {DEFAULT_VIDEO_OUT})",
)
@click.option("--json", "as_json", is_flag=True, help="print one JSON object on stdout")
@click.option(
    "--video", is_flag=True, help="also write run.gif and snapshot.png (where rendering works)"
)
def run(
    scenario_file: str, seed: int | None, out_dir: str | None, as_json: bool, video: bool
) -> int:
    """Run the task of SCENARIO in the simulated world and score it against the truth."""
    from tautwire.experiments.run_scenario import run_scenario, write_result
    from tautwire.tasks import TickRecord
    from tautwire.viz.scene_recorder import SceneRecorder

    scenario = load_scenario(resolve_scenario(scenario_file))
    err = Console(stderr=True)
    recorder = SceneRecorder() if video else None
    if video and out_dir is None:
        out_dir = DEFAULT_VIDEO_OUT

    def on_tick(rec: TickRecord) -> None:
        if recorder is not None:
            recorder.tick(rec.observation.time)

    try:
        with err.status(f"simulating {scenario.name} ...") as status:

            def on_step(i: int, report: object) -> None:
                status.update(f"simulating {scenario.name}: step {i + 2} of {len(scenario.task)}")

            result, _, _ = run_scenario(
                scenario,
                seed,
                on_step=on_step,
                on_tick=on_tick if recorder is not None else None,
                on_world=recorder.attach if recorder is not None else None,
            )
        if recorder is not None:
            assert out_dir is not None
            result.files.update(recorder.save(out_dir, "run.gif", "snapshot.png"))
    finally:
        if recorder is not None:
            recorder.close()
    if recorder is not None and recorder.error is not None:
        err.print(f"no video: {recorder.error}", markup=False, highlight=False)
    if out_dir is not None:
        result.files["result"] = str(write_result(result, out_dir))
    if as_json:
        click.echo(result.to_json())
        return 0 if result.success else 1
    table = Table(title=f"{scenario.name} (seed {result.seed})")
    for col in ("step", "primitive", "outcome", "cause", "time [s]", "max force [N]"):
        table.add_column(col)
    for i, s in enumerate(result.steps):
        table.add_row(
            str(i + 1),
            f"{s['letter']} {s['primitive']}",
            s["outcome"],
            s["cause"] or "",
            f"{s['sim_time']:.2f}",
            f"{s['max_force']:.2f}",
        )
    out = Console()
    out.print(table)
    for c in result.contacts:
        err_txt = "-" if c.error is None else f"{1e3 * c.error:.1f} mm"
        out.print(
            f"contact {c.fixture}: estimate {[round(v, 4) for v in c.estimate]}, error {err_txt}"
        )
    k = result.stiffness
    estimate, true = _newtons_per_metre(k["estimate"]), _newtons_per_metre(k["truth"])
    out.print(f"stiffness: estimate {estimate}, truth {true}")
    out.print(f"sim time {result.sim_time:.1f} s in {result.wall_time:.1f} s wall")
    return 0 if result.success else 1


def _newtons_per_metre(value: float | None) -> str:
    """A stiffness for the table, or ``-`` where there is none."""
    return "-" if value is None else f"{value:.1f} N/m"
