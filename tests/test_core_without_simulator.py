"""The core (model, estimation, control, robot, primitives) runs without MuJoCo."""

import subprocess
import sys
import textwrap

CORE = ["model", "estimation", "control", "robot", "primitives"]


def test_core_imports_with_mujoco_absent() -> None:
    code = textwrap.dedent(
        f"""
        import importlib, sys

        class BlockSimulator:
            def find_spec(self, name, path=None, target=None):
                if name == "mujoco" or name.startswith("mujoco."):
                    raise ImportError("mujoco is blocked in this test")
                return None

        sys.meta_path.insert(0, BlockSimulator())
        for pkg in {CORE!r}:
            importlib.import_module("tautwire." + pkg)
        import pkgutil, tautwire
        for pkg in {CORE!r}:
            mod = importlib.import_module("tautwire." + pkg)
            for info in pkgutil.walk_packages(mod.__path__, mod.__name__ + "."):
                importlib.import_module(info.name)
        assert "mujoco" not in sys.modules
        print("ok")
        """
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "ok"
