"""The list of commands the ``tautwire`` group offers (one module each)."""

from __future__ import annotations

import click

from tautwire.cli.demo import demo
from tautwire.cli.estimate import estimate
from tautwire.cli.plan import plan
from tautwire.cli.reproduce import reproduce
from tautwire.cli.run import run
from tautwire.cli.scenarios import scenarios
from tautwire.cli.validate import validate
from tautwire.cli.view import view

ALL: list[click.Command] = [demo, run, validate, estimate, reproduce, scenarios, plan, view]
