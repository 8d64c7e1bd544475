"""MkDocs hook: one API reference page per package, listing every module.

Each page renders the package's docstring and then each public module of the
package (files not starting with an underscore) in file-name order, so a new
module appears in the reference without editing the docs. Objects are shown
once, under the module that defines them (not again where a package
re-exports them), so every cross-reference has one target.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from mkdocs.structure.files import File, Files

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "src" / "tautwire"

#: Reference pages in navigation order: package -> one line on what it holds.
PACKAGES: dict[str, str] = {
    "model": "The reduced cable model {G, rho}: feature points, edges, the path graph.",
    "estimation": "Contact points, contact changes, elasticity, the model update.",
    "control": "Task space, motion and force control, the hybrid controller, limits.",
    "robot": "The robot interface: Observation, Command, the Robot protocol.",
    "primitives": "The nine primitives A-I and the model estimator they share.",
    "tasks": "Running primitives on any Robot: the runner and the guard.",
    "scenario": "Scenario files: schema, loading, checks.",
    "sim": "The MuJoCo world (the only package that imports mujoco).",
    "experiments": "Reproductions of the paper's figures and tables, campaigns.",
    "viz": "Plots and recordings.",
    "cli": "The command line.",
}


def modules(package: str) -> list[str]:
    """Public module names of ``tautwire.<package>``, sorted."""
    folder = PACKAGE / package
    return sorted(
        p.stem for p in folder.glob("*.py") if not p.stem.startswith("_") and p.stem != "__init__"
    )


def page(package: str) -> str:
    """Markdown of the reference page of ``tautwire.<package>``."""
    lines = [
        f"# tautwire.{package}",
        "",
        PACKAGES[package],
        "",
        f"::: tautwire.{package}",
        "    options:",
        "      members: false",
        "      show_root_heading: false",
        "",
    ]
    for name in modules(package):
        lines += [f"::: tautwire.{package}.{name}", ""]
    return "\n".join(lines)


def on_files(files: Files, config: Any) -> Files:
    """Add the generated reference pages to the site's files."""
    for package in PACKAGES:
        files.append(File.generated(config, f"reference/{package}.md", content=page(package)))
    files.append(
        File.generated(
            config,
            "reference/tautwire.md",
            content="# tautwire\n\n::: tautwire\n    options:\n      members: false\n"
            "      show_root_heading: false\n\n::: tautwire.errors\n",
        )
    )
    return files
