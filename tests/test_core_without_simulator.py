"""The core runs on NumPy and SciPy alone: without the ``sim`` extra.

``pip install tautwire`` installs only numpy and scipy; the simulator, the
scenario files' yaml and pydantic, the command line's click and rich and the
plots' matplotlib and imageio come with ``tautwire[sim]``. A subprocess with
a meta-path finder that refuses them imports every module of every core
package.
"""

import subprocess
import sys
import textwrap

CORE = ["model", "estimation", "control", "robot", "primitives", "tasks"]

#: What the ``sim`` extra brings (import names).
SIM_EXTRA = [
    "mujoco",
    "yaml",
    "pydantic",
    "pydantic_core",
    "click",
    "rich",
    "matplotlib",
    "imageio",
]

#: tautwire's own packages that need the extra; the core must not import them.
NOT_CORE = ["scenario", "sim", "viz", "cli", "experiments"]


def _run(code: str) -> subprocess.CompletedProcess[str]:
    blocker = textwrap.dedent(
        f"""
        import sys

        class BlockSimExtra:
            def find_spec(self, name, path=None, target=None):
                if name.split(".")[0] in {SIM_EXTRA!r}:
                    raise ImportError(f"{{name}} is blocked in this test (the sim extra)")
                return None

        sys.meta_path.insert(0, BlockSimExtra())
        for name in list(sys.modules):
            if name.split(".")[0] in {SIM_EXTRA!r}:
                del sys.modules[name]
        """
    )
    return subprocess.run(
        [sys.executable, "-c", blocker + textwrap.dedent(code)], capture_output=True, text=True
    )


def test_every_core_module_imports_without_the_sim_extra() -> None:
    result = _run(
        f"""
        import importlib, pkgutil
        imported = []
        for pkg in {CORE!r}:
            mod = importlib.import_module("tautwire." + pkg)
            imported.append(mod.__name__)
            for info in pkgutil.walk_packages(mod.__path__, mod.__name__ + "."):
                importlib.import_module(info.name)
                imported.append(info.name)
        leaked = sorted(
            name for name in sys.modules
            if name.split(".")[0] in {SIM_EXTRA!r}
            or any(name.startswith("tautwire." + p) for p in {NOT_CORE!r})
        )
        assert not leaked, leaked
        print(len(imported))
        """
    )
    assert result.returncode == 0, result.stderr
    assert int(result.stdout.strip()) > 60  # every module, not an empty walk


def test_the_blocker_refuses_the_sim_extra() -> None:
    for name in SIM_EXTRA:
        if name == "pydantic_core":
            continue
        result = _run(f"import {name}")
        assert result.returncode != 0
        assert "blocked in this test" in result.stderr


def test_the_core_estimates_a_contact_without_the_sim_extra() -> None:
    # not only imports: a context is built and its contact filter finds a
    # contact from noisy forces of a gripper circling it (seeded)
    result = _run(
        """
        import numpy as np
        from tautwire.model import PathGraph
        from tautwire.primitives import make_context
        from tautwire.robot import WORKSPACE

        contact = np.array([0.3, 0.0, 0.08])
        graph = PathGraph.from_positions(
            [contact + [0.01, -0.01, 0.0], [0.3, 0.2, 0.08]],
            mass_per_length=0.0, kinds=["fixed", "gripper"], labels=["A1", "left"],
        )
        context = make_context(graph, "left")
        flt = context.estimator.contact_filter
        rng = np.random.default_rng(0)
        for theta in np.linspace(0.0, 2.0 * np.pi, 125):
            p = contact + 0.2 * np.array([np.sin(theta), np.cos(theta), 0.0])
            f = 4.0 * (contact - p) / 0.2 + rng.normal(0.0, 0.05, 3)
            flt.update(p, f)
        assert WORKSPACE.contains(contact)
        print(f"{1e3 * np.linalg.norm(flt.estimate - contact):.3f}")
        """
    )
    assert result.returncode == 0, result.stderr
    assert float(result.stdout) < 1.0  # mm, a full circle
