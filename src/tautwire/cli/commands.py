"""The list of commands the ``tautwire`` group offers (one module each)."""

from __future__ import annotations

import click

ALL: list[click.Command] = []
