"""tests.sim_extra: which test modules a core-only install must skip, and why."""

from __future__ import annotations

from pathlib import Path

from tests.sim_extra import ROOT, needs_sim_extra, sim_extra_installed


def _module(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "test_probe.py"
    path.write_text(text, encoding="utf-8")
    return path


def test_the_dev_install_has_the_extra() -> None:
    assert sim_extra_installed()


def test_a_simulator_test_needs_it_through_its_imports() -> None:
    chain = needs_sim_extra(ROOT / "tests" / "sim" / "test_world.py")
    assert chain is not None
    assert chain.startswith("tautwire.")
    assert chain.split(" -> ")[-1].split(".")[0] in {"mujoco", "pydantic", "yaml"}


def test_core_tests_do_not() -> None:
    for path in [
        ROOT / "tests" / "test_core_without_simulator.py",
        ROOT / "tests" / "estimation" / "test_kalman.py",  # filterpy is not the extra
        ROOT / "tests" / "estimation" / "test_contact_point_least_squares.py",
        ROOT / "tests" / "tasks" / "test_robot_guard.py",
    ]:
        assert needs_sim_extra(path) is None, path


def test_direct_and_package_imports_are_found(tmp_path: Path) -> None:
    assert needs_sim_extra(_module(tmp_path, "import yaml\n")) == "yaml"
    assert needs_sim_extra(_module(tmp_path, "from matplotlib import pyplot\n")) == "matplotlib"
    chain = needs_sim_extra(_module(tmp_path, "from tautwire.scenario import registry\n"))
    assert chain is not None and chain.startswith("tautwire.scenario -> ")


def test_imports_that_do_not_run_at_import_time_are_not(tmp_path: Path) -> None:
    text = (
        "from typing import TYPE_CHECKING\n"
        "if TYPE_CHECKING:\n"
        "    import mujoco\n"
        "def later():\n"
        "    import yaml\n"
        "import numpy\n"
        "from tautwire.model import PathGraph\n"
    )
    assert needs_sim_extra(_module(tmp_path, text)) is None
