"""Importing tautwire never chooses matplotlib's backend (issue 12, item 8).

A notebook's ``plt.show()`` must keep working after ``import tautwire.viz...``:
every module is imported in a fresh interpreter, which then checks that the
backend is still unresolved (or still the one the user chose).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

SCRIPT = """
import importlib, json, pkgutil, sys
import matplotlib
import tautwire

skipped = []
for info in pkgutil.walk_packages(tautwire.__path__, "tautwire."):
    if info.name == "tautwire.__main__":
        continue  # running it is its job
    try:
        importlib.import_module(info.name)
    except ImportError as exc:  # an optional extra (rerun, ray) that is not installed
        if exc.name and exc.name.split(".")[0] in ("rerun", "ray", "mujoco"):
            skipped.append(info.name)
            continue
        raise
backend = dict.__getitem__(matplotlib.rcParams, "backend")
print(json.dumps({
    "unresolved": backend is matplotlib.rcsetup._auto_backend_sentinel,
    "backend": None if backend is matplotlib.rcsetup._auto_backend_sentinel else str(backend),
    "modules": sorted(m for m in sys.modules if m.startswith("tautwire")),
    "skipped": skipped,
}))
"""


def _import_everything(backend: str | None) -> dict[str, object]:
    env = {k: v for k, v in os.environ.items() if k != "MPLBACKEND"}
    if backend is not None:
        env["MPLBACKEND"] = backend
    done = subprocess.run(
        [sys.executable, "-c", SCRIPT], cwd=ROOT, env=env, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    result: dict[str, object] = json.loads(done.stdout.strip().splitlines()[-1])
    return result


@pytest.mark.slow
def test_importing_every_module_leaves_the_backend_unchosen() -> None:
    result = _import_everything(None)
    assert "tautwire.viz.contact_estimation_plot" in result["modules"]  # type: ignore[operator]
    assert "tautwire.experiments.fig5a" in result["modules"]  # type: ignore[operator]
    assert result["unresolved"] is True, result["backend"]


@pytest.mark.slow
def test_the_users_backend_is_kept() -> None:
    result = _import_everything("svg")
    assert result["backend"] == "svg"


def test_writing_a_plot_keeps_the_backend(tmp_path: Path) -> None:
    script = (
        "import matplotlib, numpy as np\n"
        "from tautwire.viz.contact_estimation_plot import plot_contact_estimation\n"
        f"plot_contact_estimation({str(tmp_path / 'p.png')!r}, np.arange(3), np.zeros((3, 3)),"
        " np.ones((3, 3)))\n"
        "b = dict.__getitem__(matplotlib.rcParams, 'backend')\n"
        "print(b is matplotlib.rcsetup._auto_backend_sentinel)\n"
    )
    env = {k: v for k, v in os.environ.items() if k != "MPLBACKEND"}
    done = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "True"
    assert (tmp_path / "p.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
