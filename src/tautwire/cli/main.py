"""Entry point of the ``tautwire`` command.

``main(argv) -> int`` never raises and never prints a traceback: a
:class:`TautwireError` or a usage error becomes one clear line on stderr
(one per problem, for a scenario with several) and status 1 or 2; any other
exception (a defect) one line naming it and status :data:`INTERNAL_ERROR`.
Every message has one style, ``tautwire: error: what is wrong``.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

import click

from tautwire import __version__
from tautwire.errors import TautwireError

#: Exit status of an unexpected exception (sysexits' EX_SOFTWARE).
INTERNAL_ERROR = 70


EPILOG = """\b
Examples:
  tautwire demo                      # the main job, simulated, in about 15 s
  tautwire scenarios                 # the scenarios that ship with tautwire
  tautwire validate my-board.yaml    # every problem of a scenario file, one line each
  tautwire run peg-change --out out/peg-change
  tautwire estimate out/peg-change/force_log.csv
  tautwire reproduce fig5c
  tautwire COMMAND --help            # each command's options and examples
  python -m tautwire --help          # the same command line
"""


@click.group(context_settings={"help_option_names": ["-h", "--help"]}, epilog=EPILOG)
@click.version_option(__version__, prog_name="tautwire")
def cli() -> None:
    """Blind, force-based manipulation of cables with one wrist force-torque sensor."""


def _register() -> None:
    """Attach every command module's command to the group."""
    from tautwire.cli import commands

    for command in commands.ALL:
        cli.add_command(command)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line with ``argv`` (default ``sys.argv[1:]``); return the exit status."""
    _register()
    args = list(sys.argv[1:] if argv is None else argv)
    try:
        result = cli.main(args=args, prog_name="tautwire", standalone_mode=False)
    except click.exceptions.Abort:
        click.echo("tautwire: error: aborted", err=True)
        return 130
    except click.exceptions.ClickException as exc:
        click.echo(f"tautwire: error: {exc.format_message()}", err=True)
        return exc.exit_code if exc.exit_code else 2
    except TautwireError as exc:
        for line in str(exc).splitlines() or ["no message"]:
            click.echo(f"tautwire: error: {line}", err=True)
        return 1
    except KeyboardInterrupt:
        click.echo("tautwire: error: interrupted", err=True)
        return 130
    except Exception as exc:  # a defect: still one line, never a traceback
        message = " ".join(str(exc).split()) or "no message"
        click.echo(f"tautwire: error: internal error: {type(exc).__name__}: {message}", err=True)
        return INTERNAL_ERROR
    return int(result) if isinstance(result, int) else 0


def entry() -> None:
    """Console-script entry point."""
    sys.exit(main())
