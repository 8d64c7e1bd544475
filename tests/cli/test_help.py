"""The command line's consistency: help with examples, flags, one message style."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import click
import pytest

from tautwire.cli import commands
from tautwire.cli.main import cli, main


@pytest.mark.parametrize("command", commands.ALL, ids=lambda c: str(c.name))
def test_every_command_has_examples_in_its_help(command: click.Command) -> None:
    assert command.epilog is not None and "Examples:" in command.epilog
    assert f"tautwire {command.name}" in command.epilog
    assert "\\b" not in command.epilog  # click's no-rewrap marker, not its two characters


def test_the_group_help_has_examples(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--help"]) == 0
    out = capsys.readouterr().out
    assert "Examples:" in out and "python -m tautwire" in out
    assert {str(c.name) for c in commands.ALL} <= set(cli.commands)


def test_estimate_help_gives_the_csv_format(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["estimate", "--help"]) == 0
    out = capsys.readouterr().out
    for words in ("t,px,py,pz,fx,fy,fz", "qw,qx,qy,qz", "tx,ty,tz", "[N m]", "world frame"):
        assert words in out


@pytest.mark.parametrize(("name", "default"), [("demo", True), ("run", False)])
def test_video_is_one_flag_pair_everywhere(name: str, default: bool) -> None:
    command = next(c for c in commands.ALL if c.name == name)
    option = next(p for p in command.params if p.name == "video")
    assert isinstance(option, click.Option)
    assert option.opts == ["--video"] and option.secondary_opts == ["--no-video"]
    assert option.default is default


def test_python_dash_m_runs_the_command_line(tmp_path: Path) -> None:
    done = subprocess.run(
        [sys.executable, "-m", "tautwire", "validate", str(tmp_path / "none.yaml")],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 1 and done.stdout == ""
    assert done.stderr.startswith("tautwire: error: ") and done.stderr.count("\n") == 1
    version = subprocess.run(
        [sys.executable, "-m", "tautwire", "--version"], capture_output=True, text=True
    )
    assert version.returncode == 0 and version.stdout.startswith("tautwire, version ")


@pytest.mark.parametrize(
    "args",
    [
        ["validate", "NOPE.yaml"],
        ["run", "NOPE.yaml"],
        ["estimate", "NOPE.csv"],
        ["plan", "NOPE.yaml"],
        ["reproduce", "fig9"],
        ["reproduce", "fig5a", "--trials", "3"],
        ["estimate"],
        ["nonsense"],
    ],
)
def test_every_message_has_one_style(args: list[str], capsys: pytest.CaptureFixture[str]) -> None:
    status = main(args)
    out, err = capsys.readouterr()
    assert status in (1, 2) and out == ""
    assert err.count("\n") == 1 and err.startswith("tautwire: error: ")
