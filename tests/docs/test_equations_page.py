"""docs/equations.md maps every equation label the code cites to code that cites it."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGE = (ROOT / "docs" / "equations.md").read_text(encoding="utf-8")
SRC = ROOT / "src"
LABEL = re.compile(r"\b(?:equ|eq|sec):[A-Za-z_]+")


def code_labels() -> set[str]:
    return {m for path in (SRC / "tautwire").rglob("*.py") for m in LABEL.findall(path.read_text())}


def module_file(identifier: str) -> Path:
    """The source file of the module that defines ``identifier`` (a dotted path)."""
    parts = identifier.split(".")
    for n in range(len(parts), 0, -1):
        path = SRC.joinpath(*parts[:n])
        if path.with_suffix(".py").is_file():
            return path.with_suffix(".py")
        if (path / "__init__.py").is_file():
            return path / "__init__.py"
    raise AssertionError(f"{identifier} names no module under src/")


def sections() -> dict[str, str]:
    """Body of each ``##``/``###`` section, by heading."""
    parts = re.split(r"^(#{2,3} .*)$", PAGE, flags=re.MULTILINE)
    return {parts[i]: parts[i + 1] for i in range(1, len(parts) - 1, 2)}


def test_every_label_of_the_code_is_on_the_page() -> None:
    labels = code_labels()
    assert len(labels) >= 10
    missing = sorted(label for label in labels if label not in PAGE)
    assert not missing, f"equation labels cited in src/ but not on docs/equations.md: {missing}"


def test_each_equation_links_to_code_that_cites_it() -> None:
    checked = 0
    for heading, body in sections().items():
        for label in LABEL.findall(heading):
            targets = re.findall(r"\]\[(tautwire\.[\w.]+)\]", body)
            assert targets, f"{heading}: no link to the code"
            files = {module_file(t) for t in targets}
            assert any(label in f.read_text() for f in files), (
                f"{heading}: none of {sorted(str(f.relative_to(SRC)) for f in files)} cites {label}"
            )
            checked += 1
    assert checked >= 12
