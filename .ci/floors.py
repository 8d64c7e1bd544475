"""Print the lowest versions pyproject allows, as pip pins, one a line.

Usage: python .ci/floors.py GROUP... where GROUP is ``core`` (the
dependencies) or an extra's name (``sim``). A requirement ``name>=A.B`` (an
upper bound after a comma may follow) is pinned to ``name==A.B.*``: the
lowest minor release series allowed, at its latest patch. A requirement of
another form is an error, so every floor is tested.
"""

import re
import sys
import tomllib
from pathlib import Path

PYPROJECT = Path(__file__).resolve().parents[1] / "pyproject.toml"
FLOOR = re.compile(r"([A-Za-z0-9_.-]+)\s*>=\s*(\d+\.\d+)\s*(,.*)?")


def main(groups: list[str]) -> int:
    """Print the pins of ``groups``; return the exit status."""
    project = tomllib.loads(PYPROJECT.read_text(encoding="utf-8"))["project"]
    for group in groups:
        reqs = (
            project["dependencies"] if group == "core" else project["optional-dependencies"][group]
        )
        for req in reqs:
            m = FLOOR.fullmatch(req)
            if m is None:
                print(f"floors: {req!r} ({group}) is not of the form name>=A.B", file=sys.stderr)
                return 1
            print(f"{m[1]}=={m[2]}.*")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
