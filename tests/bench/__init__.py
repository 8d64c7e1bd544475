"""Tests of the benchmark scripts under ``bench/``."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType


def load_script(name: str) -> ModuleType:
    """``bench/<name>.py`` as a module: bench/ is not a package, and sys.path stays as it is.

    :mod:`tautwire.sim` is imported first: it chooses MuJoCo's offscreen GL
    backend, which MuJoCo reads once, when it is first imported. A script
    that imports mujoco before it, loaded at collection, left every test
    worker with MuJoCo's default GLFW, and the render tests aborted.
    """
    import tautwire.sim  # noqa: F401

    path = Path(__file__).resolve().parents[2] / "bench" / f"{name}.py"
    spec = importlib.util.spec_from_file_location(f"bench_{name}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[f"bench_{name}"] = module
    spec.loader.exec_module(module)
    return module
