"""``tautwire view SCENARIO``: watch the task run live in MuJoCo's viewer."""

from __future__ import annotations

import click
from rich.console import Console

from tautwire.scenario import load_scenario
from tautwire.scenario.registry import resolve_scenario


@click.command(
    epilog="""\b
Examples:
  tautwire view peg-change                  # real time; close the window to quit
  tautwire view my-board.yaml --speed 0.5   # half speed
  xvfb-run -a tautwire view anchor-rotate --speed 0 --no-hold   # headless, as the tests do
"""
)
@click.argument("scenario_file", metavar="SCENARIO", type=click.Path(dir_okay=False))
@click.option("--seed", type=int, default=None, help="override the scenario's seed")
@click.option(
    "--speed",
    type=click.FloatRange(min=0.0),
    default=1.0,
    show_default=True,
    help="simulated seconds per second of wall time (0: as fast as it runs)",
)
@click.option(
    "--hold/--no-hold",
    default=True,
    show_default=True,
    help="keep the window open after the task until it is closed",
)
def view(scenario_file: str, seed: int | None, speed: float, hold: bool) -> int:
    """Run the task of SCENARIO live in MuJoCo's interactive viewer.

    The robot's cable model is drawn into the scene as it estimates it:
    feature points coloured by what holds them (cyan gripper, green anchor,
    gold peg, magenta clip, red unknown contact), white edges and 3-sigma
    uncertainty ellipsoids; the fixtures are coloured by type and named.
    Needs a display.
    """
    from tautwire.experiments.run_scenario import run_scenario
    from tautwire.sim.live_viewer import LiveViewer, display_problem
    from tautwire.sim.world import SimWorld
    from tautwire.tasks import StepReport, TickRecord

    scenario = load_scenario(resolve_scenario(scenario_file))
    problem = display_problem()
    if problem is not None:
        raise click.ClickException(f"cannot open MuJoCo's viewer: {problem}")
    err = Console(stderr=True)
    viewers: list[LiveViewer] = []

    def on_world(world: SimWorld) -> None:
        viewers.append(LiveViewer(world, speed=speed))

    def on_tick(rec: TickRecord) -> None:
        viewers[0].show(rec.context.graph)

    def on_step(i: int, report: StepReport) -> None:
        cause = f" ({report.cause})" if report.cause else ""
        err.print(
            f"step {i + 1} {report.letter} {report.primitive}: {report.outcome}{cause}"
            f" after {report.sim_time:.2f} s",
            markup=False,
            highlight=False,
        )

    try:
        result, ctx, _ = run_scenario(
            scenario, seed, on_world=on_world, on_tick=on_tick, on_step=on_step
        )
        if viewers:
            viewers[0].show(ctx.graph)
            err.print(
                f"{scenario.name}: {'success' if result.success else 'failure'},"
                f" {viewers[0].frames} frames shown"
                + (" (close the window to quit)" if hold and viewers[0].running else ""),
                markup=False,
                highlight=False,
            )
            if hold:
                viewers[0].wait_closed()
    finally:
        for v in viewers:
            v.close()
    return 0 if result.success else 1
