"""Named scenarios: the scenario files that ship inside the package.

Every ``*.yaml`` file in the package's ``scenarios`` folder is registered
under its file name without the extension (``anchor-rotate`` for
``anchor-rotate.yaml``). The files are found with :mod:`importlib.resources`,
so they are there in any install (a wheel, an editable checkout), whatever
the working directory.

A command that takes a scenario accepts a registered name as well as a
path: :func:`resolve_scenario` decides which one was meant.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from importlib.resources import files
from pathlib import Path

import yaml

from tautwire.scenario.scenario_error import ScenarioError

#: The package folder that holds the shipped scenario files.
PACKAGE_FOLDER = "scenarios"

#: Extension of a scenario file.
SUFFIX = ".yaml"


@dataclass(frozen=True)
class RegisteredScenario:
    """One shipped scenario.

    Attributes:
        name: The registered name (the file name without ``.yaml``).
        path: Where the installed file is.
        description: One line from the file's ``description`` (else its
            ``name``).
    """

    name: str
    path: Path
    description: str


def scenario_folder() -> Path:
    """The installed folder of the shipped scenario files.

    Raises:
        ScenarioError: if the package is not installed as plain files (e.g.
            imported from a zip archive), where the scenarios have no path.
    """
    folder = files("tautwire").joinpath(PACKAGE_FOLDER)
    if not isinstance(folder, Path):
        raise ScenarioError(
            str(folder),
            None,
            "",
            "the shipped scenarios are not plain files here "
            "(install tautwire as a normal package: pip install tautwire[sim])",
        )
    return folder


def scenario_names() -> list[str]:
    """The registered names, sorted."""
    return sorted(p.name.removesuffix(SUFFIX) for p in scenario_folder().glob("*" + SUFFIX))


def scenario_path(name: str) -> Path:
    """The installed file of the registered scenario ``name``.

    Raises:
        ScenarioError: if no scenario is registered under ``name``; the
            message names the closest registered names.
    """
    names = scenario_names()
    if name in names:
        return scenario_folder() / (name + SUFFIX)
    raise _unknown(name, names)


def registered_scenarios() -> list[RegisteredScenario]:
    """Every shipped scenario with its one-line description, sorted by name.

    The description is read from the file's top-level ``description`` (or
    ``name``) without validating the whole file; ``tautwire validate NAME``
    does that.
    """
    return [_entry(name) for name in scenario_names()]


def resolve_scenario(argument: str) -> Path:
    """The scenario file a command's argument means.

    A path that exists wins (the loader says if it is not a scenario file);
    otherwise a registered name; otherwise an error.

    Args:
        argument: What the user typed: a path or a registered name.

    Returns:
        The file to load.

    Raises:
        ScenarioError: if ``argument`` is neither a file nor a registered
            name: one line naming it, with "did you mean" when a registered
            name is close.
    """
    path = Path(argument)
    if path.exists():
        return path
    names = scenario_names()
    if argument in names:
        return scenario_folder() / (argument + SUFFIX)
    raise _unknown(argument, names)


def _entry(name: str) -> RegisteredScenario:
    """The registry entry of the shipped file ``name``."""
    path = scenario_folder() / (name + SUFFIX)
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as exc:
        message = " ".join(str(exc).split())
        raise ScenarioError(str(path), None, "", f"cannot be read: {message}") from exc
    top = data if isinstance(data, dict) else {}
    text = top.get("description") or top.get("name") or name
    return RegisteredScenario(name, path, " ".join(str(text).split()))


def _unknown(argument: str, names: list[str]) -> ScenarioError:
    """The error for an argument that is neither a file nor a registered name.

    One line, with "did you mean" and the closest registered names (their
    file name's stem is compared, so ``scenarios/anchr-rotate.yaml`` finds
    ``anchor-rotate``); the registered names when none is close.
    """
    stem = Path(argument).name.removesuffix(SUFFIX)
    close = difflib.get_close_matches(stem, names, n=3, cutoff=0.6)
    if close:
        hint = "did you mean " + " or ".join(repr(c) for c in close) + "?"
    else:
        hint = "registered: " + (", ".join(names) or "none") + " (tautwire scenarios)"
    return ScenarioError(argument, None, "", f"no such file or registered scenario; {hint}")
