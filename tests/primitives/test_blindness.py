"""No primitive can reach the simulator's ground truth."""

import ast
import pathlib

import tautwire.primitives

FORBIDDEN = ("tautwire.sim", "tautwire.experiments", "tautwire.tasks", "mujoco")


def test_primitives_import_nothing_that_holds_ground_truth() -> None:
    root = pathlib.Path(tautwire.primitives.__file__).parent
    for path in root.glob("*.py"):
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            names: list[str] = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module]
            for name in names:
                assert not name.startswith(FORBIDDEN), f"{path.name} imports {name}"
