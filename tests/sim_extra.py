"""Which test modules need the ``sim`` extra, for a run without it.

``pip install tautwire`` has numpy and scipy only; the core's tests must run
there too (CI runs them at the lowest versions allowed, ``.ci/packaging``).
A test module that imports the simulator, the scenario layer, the command
line or the plots, directly or through the modules it imports at their top
level, is skipped there with the import chain as the reason; every other
import error still fails. With the extra installed nothing is skipped.
"""

from __future__ import annotations

import ast
import importlib.util
from functools import cache
from pathlib import Path

#: Import names of what the ``sim`` extra brings.
SIM_EXTRA = frozenset({"mujoco", "yaml", "pydantic", "click", "rich", "matplotlib", "imageio"})

#: The checkout (for the ``tests`` helper modules).
ROOT = Path(__file__).resolve().parents[1]


def sim_extra_installed() -> bool:
    """Whether every module of the ``sim`` extra can be imported."""
    return all(importlib.util.find_spec(name) is not None for name in SIM_EXTRA)


def needs_sim_extra(path: Path) -> str | None:
    """Why the test module at ``path`` cannot be imported without the extra, or None.

    Returns:
        The chain of imports that reaches the extra, e.g. ``'tautwire.sim.build
        -> mujoco'``; None if the module's top-level imports never reach it.
    """
    return _chain_of_file(path.resolve(), _package_of(path.resolve()))


def _package_of(path: Path) -> str:
    """The dotted package a file under the checkout or the installed tautwire belongs to."""
    try:
        parts = path.relative_to(ROOT).with_suffix("").parts
    except ValueError:
        return ""
    return ".".join(parts[:-1])


@cache
def _tautwire_base() -> Path | None:
    """The folder that holds the imported ``tautwire`` package (src/ or site-packages)."""
    spec = importlib.util.find_spec("tautwire")
    if spec is None or spec.origin is None:
        return None
    return Path(spec.origin).parents[1]


def _module_file(name: str) -> Path | None:
    """The source file of a ``tautwire`` or ``tests`` module, or None for others."""
    parts = name.split(".")
    base = ROOT if parts[0] == "tests" else _tautwire_base() if parts[0] == "tautwire" else None
    if base is None:
        return None
    candidate = base.joinpath(*parts)
    for file in (candidate / "__init__.py", candidate.with_suffix(".py")):
        if file.is_file():
            return file
    return None


@cache
def _chain_of_module(name: str) -> str | None:
    """The import chain from module ``name`` to the extra, or None."""
    if name.split(".")[0] in SIM_EXTRA:
        return name
    parts = name.split(".")
    for i in range(1, len(parts) + 1):  # importing a.b.c runs a, a.b and a.b.c
        prefix = ".".join(parts[:i])
        file = _module_file(prefix)
        if file is None:
            continue
        package = prefix if file.name == "__init__.py" else ".".join(parts[: i - 1])
        chain = _chain_of_file(file, package)
        if chain is not None:
            return f"{prefix} -> {chain}"
    return None


def _chain_of_file(file: Path, package: str) -> str | None:
    """The import chain from the top-level imports of ``file`` to the extra, or None."""
    if file in _VISITING:
        return None
    _VISITING.add(file)
    try:
        tree = ast.parse(file.read_text(encoding="utf-8"))
        for name in _top_level_imports(tree, package):
            chain = _chain_of_module(name)
            if chain is not None:
                return chain
        return None
    finally:
        _VISITING.discard(file)


_VISITING: set[Path] = set()


def _top_level_imports(tree: ast.Module, package: str) -> list[str]:
    """Modules imported when the module runs (not those under TYPE_CHECKING or in functions)."""
    names: list[str] = []
    for node in tree.body:
        if isinstance(node, ast.Import):
            names.extend(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*anchor, base] if base else anchor)
            names.append(base)
            names.extend(
                f"{base}.{alias.name}"
                for alias in node.names
                if _module_file(f"{base}.{alias.name}")
            )
    return names
