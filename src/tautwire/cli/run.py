"""``tautwire run SCENARIO``: simulate a scenario, score it, and show what happened.

With ``--out DIR`` it writes there ``result.json``, the force log the
sensing gripper recorded (``force_log.csv``, the format ``tautwire estimate``
reads, with torques; each row the mean over one contact-filter period, 40 ms,
as the online filter fuses it, so its noise is the sensor's over sqrt(10) at
4 ms control periods), ``run.png`` (force, tension against its set point and
the contact error against time, steps marked) and ``model_views.png`` (the
model of every cable over the true one, from the top and the side); with ``--video`` also
``run.gif`` and ``snapshot.png``; ``--rerun FILE.rrd`` records the run for
the Rerun viewer.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import click
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from tautwire.scenario import load_scenario
from tautwire.scenario.registry import resolve_scenario

#: Period [s] of the contact filter's iterations (and of the force log's rows).
ESTIMATION_PERIOD = 0.04
#: Output folder of ``--video`` when ``--out`` is not given.
DEFAULT_VIDEO_OUT = "out/run"


@click.command(
    epilog="""\b
Examples:
  tautwire run peg-change --out out/peg-change
  tautwire run my-board.yaml --seed 3 --video --out out/board
  tautwire run anchor-rotate --rerun out/anchor.rrd   # then: rerun out/anchor.rrd
"""
)
@click.argument("scenario_file", metavar="SCENARIO", type=click.Path(dir_okay=False))
@click.option("--seed", type=int, default=None, help="override the scenario's seed")
@click.option(
    "--out",
    "out_dir",
    type=click.Path(file_okay=False),
    default=None,
    help="folder for result.json, force_log.csv, run.png, model_views.png and the video"
    f" (default with --video: {DEFAULT_VIDEO_OUT})",
)
@click.option("--json", "as_json", is_flag=True, help="print one JSON object on stdout")
@click.option(
    "--video/--no-video",
    default=False,
    show_default=True,
    help="also write run.gif and snapshot.png (where rendering works)",
)
@click.option(
    "--rerun",
    "rerun_file",
    type=click.Path(dir_okay=False),
    default=None,
    help="record the run to this Rerun file (.rrd; needs the extra tautwire[rerun])",
)
def run(
    scenario_file: str,
    seed: int | None,
    out_dir: str | None,
    as_json: bool,
    video: bool,
    rerun_file: str | None,
) -> int:
    """Run the task of SCENARIO (a file or a registered name) in the simulated world.

    The robot works blind, from its wrist force sensor; afterwards the
    simulator's truth scores every step and contact estimate.
    """
    from tautwire.experiments.run_scenario import run_scenario, task_of, write_result
    from tautwire.sim.world import SimWorld
    from tautwire.tasks import StepReport, TickRecord
    from tautwire.viz.run_trace import RunTrace
    from tautwire.viz.scene_recorder import SceneRecorder

    scenario = load_scenario(resolve_scenario(scenario_file))
    err = Console(stderr=True)
    rerun = None
    if rerun_file is not None:
        from tautwire.viz.rerun_recorder import RerunRecorder

        rerun = RerunRecorder(rerun_file, name=f"tautwire run {scenario.name}")
    recorder = SceneRecorder() if video else None
    if video and out_dir is None:
        out_dir = DEFAULT_VIDEO_OUT
    trace = RunTrace(scenario.cables[0].name)
    world_fixtures: dict[str, tuple[str, Any]] = {}

    def on_world(world: SimWorld) -> None:
        from tautwire.sim.model_overlay import fixture_type

        world_fixtures.update({f.name: (fixture_type(f), f.position) for f in world.spec.fixtures})
        if recorder is not None:
            recorder.attach(world)
        if rerun is not None:
            rerun.attach(world)

    def on_tick(rec: TickRecord) -> None:
        trace.tick(rec)
        if recorder is not None:
            recorder.tick(rec.observation.time, rec.context.graph)
        if rerun is not None:
            rerun.tick(rec)

    try:
        steps = len(task_of(scenario))  # a planned task when the scenario has routes only
        with err.status(f"simulating {scenario.name} ...") as status:

            def on_step(i: int, report: StepReport) -> None:
                trace.step(i, report)
                if rerun is not None:
                    rerun.step(i, report)
                status.update(f"simulating {scenario.name}: step {i + 2} of {steps}")

            def on_truth(truth: Any) -> None:
                trace.keep_truth(truth)
                if rerun is not None:
                    rerun.keep_truth(truth)

            result, ctx, truth = run_scenario(
                scenario,
                seed,
                estimation_period=ESTIMATION_PERIOD,
                on_step=on_step,
                on_tick=on_tick,
                on_world=on_world,
                on_truth=on_truth,
            )
        if recorder is not None:
            assert out_dir is not None
            result.files.update(recorder.save(out_dir, "run.gif", "snapshot.png"))
    finally:
        if recorder is not None:
            recorder.close()
        if rerun is not None:
            rerun.close()
    if rerun is not None:
        result.files["rerun"] = str(rerun.path)
    if recorder is not None and recorder.error is not None:
        err.print(f"no video: {recorder.error}", markup=False, highlight=False)
    if out_dir is not None:
        from tautwire.viz.run_plots import plot_model_views, plot_run

        folder = Path(out_dir)
        folder.mkdir(parents=True, exist_ok=True)
        window = max(1, round(ESTIMATION_PERIOD / scenario.robot.control_period))
        if len(trace.t) >= 2 * window:
            log = trace.write_force_log(folder / "force_log.csv", window)
            result.files["force_log"] = str(log)
        result.files["plot"] = str(
            plot_run(folder / "run.png", trace, title=f"{scenario.name} (seed {result.seed})")
        )
        graphs = result.models.graphs if result.models is not None else {trace.cable: ctx.graph}
        cables = [(name, graph, truth.polyline(name)) for name, graph in graphs.items()]
        result.files["model_views"] = str(
            plot_model_views(
                folder / "model_views.png",
                cables,
                world_fixtures,
                title=f"{scenario.name}: the model{'s' if len(cables) > 1 else ''} at the end"
                f" over the true cable{'s' if len(cables) > 1 else ''}",
            )
        )
        result.files["result"] = str(write_result(result, out_dir))
    if as_json:
        click.echo(result.to_json())
        return 0 if result.success else 1
    table = Table(title=f"{scenario.name} (seed {result.seed})")
    for col in ("step", "primitive", "outcome", "cause", "time [s]", "max force [N]"):
        table.add_column(escape(col))  # '[s]' is not rich markup
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
    span = "-" if k["span"] is None else f"{k['span']:.3f} m"
    out.print(f"stiffness: k_hat {estimate} over the model's span of {span}; the cable's k {true}")
    out.print(f"sim time {result.sim_time:.1f} s in {result.wall_time:.1f} s wall")
    return 0 if result.success else 1


def _newtons_per_metre(value: float | None) -> str:
    """A stiffness for the table, or ``-`` where there is none."""
    return "-" if value is None else f"{value:.1f} N/m"
