"""Test-suite settings: property tests are seeded (derandomised) like every other test.

Set HYPOTHESIS_PROFILE=explore to search with fresh random examples.

Without the ``sim`` extra (a core-only install), test modules that need it
are skipped with the import chain as the reason (:mod:`tests.sim_extra`).
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import settings

from tests.sim_extra import needs_sim_extra, sim_extra_installed

settings.register_profile("seeded", derandomize=True, deadline=None)
settings.register_profile("explore", derandomize=False, deadline=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "seeded"))

SIM_EXTRA_INSTALLED = sim_extra_installed()


class _NeedsSimExtra(pytest.Module):
    """A test module that cannot be imported without the ``sim`` extra: one skip."""

    reason = ""

    def collect(self) -> list[pytest.Item | pytest.Collector]:
        raise pytest.skip.Exception(self.reason, allow_module_level=True)


def pytest_pycollect_makemodule(
    module_path: Path, parent: pytest.Collector
) -> pytest.Module | None:
    if SIM_EXTRA_INSTALLED:
        return None
    chain = needs_sim_extra(module_path)
    if chain is None:
        return None
    module = _NeedsSimExtra.from_parent(parent, path=module_path)
    module.reason = f"{module_path.name} needs the sim extra (tautwire[sim]): {chain}"
    return module
