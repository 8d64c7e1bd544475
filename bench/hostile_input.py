"""Hostile and odd input through the command line: status, lines, wall time; prints JSON.

    .venv/bin/python bench/hostile_input.py

Each case writes a file into a temporary folder and runs ``tautwire
validate`` (scenarios) or ``tautwire estimate`` (force logs) on it as a
user would, in a fresh process: the exit status, the number of lines on
stderr and the first one, and the wall time [s] (interpreter start
included). Issue 12's goal: one line (one per problem for a file with
several), a non-zero exit, within 15 s.
"""

from __future__ import annotations

import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from tautwire.estimation import write_force_log
from tautwire.experiments.synthetic_circle import circle
from tautwire.scenario.registry import scenario_path

EXAMPLE = scenario_path("peg-and-clip").read_text(encoding="utf-8")
BOMB = "a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
    f"{b}: &{b} [{', '.join([f'*{a}'] * 9)}]\n" for a, b in zip("abcdefgh", "bcdefghi", strict=True)
)
STEP = "  - {primitive: single_arm_tension, arm: left, force: 3.0}\n"


def _scenarios(folder: Path) -> dict[str, Path]:
    files = {
        "nul_byte": EXAMPLE.replace("name: peg-and-clip", "name: peg\0").encode(),
        "alias_bomb_342_bytes": BOMB.encode(),
        "deep_nesting": b"x: " + b"[" * 400_000 + b"]" * 400_000,
        "stiffness_1.0e9": EXAMPLE.replace("stiffness: 200.0", "stiffness: 1.0e9").encode(),
        "control_period_0.0045": EXAMPLE.replace(
            "control_period: 0.004", "control_period: 0.0045"
        ).encode(),
        "four_problems": EXAMPLE.replace("seed: 3", "seed: x\ncolour: red")
        .replace("  force_limit", "  force_limt")
        .replace("type: peg", "type: pge")
        .encode(),
        "one_mb_of_bad_steps": (
            EXAMPLE + STEP.replace("single_arm_tension", "tug") * (900_000 // len(STEP))
        ).encode(),
    }
    paths = {}
    for name, content in files.items():
        paths[name] = folder / f"{name}.yaml"
        paths[name].write_bytes(content)
    big = folder / "nineteen_mb.yaml"
    with big.open("wb") as fh:
        fh.write(EXAMPLE.encode())
        fh.write(b"#" * 19_000_000)
    paths["nineteen_mb"] = big
    return paths


def _logs(folder: Path) -> dict[str, Path]:
    header, row0, row1 = (
        "t,px,py,pz,fx,fy,fz\n",
        "0,0.1,0,0.2,-1,0,0\n",
        "0.004,0.1,0.01,0.2,-1,-0.1,0\n",
    )
    paths = {
        "log_with_bom": (b"\xef\xbb\xbf" + (header + row0 + row1).encode(), 0),
        "log_1_0": ((header + row0 + "0.004,0.1,0,1_0,-1,0,0\n").encode(), 1),
    }
    out = {}
    for name, (content, _) in paths.items():
        out[name] = folder / f"{name}.csv"
        out[name].write_bytes(content)
    n = 1_000_000
    data = circle(0, n=n)
    bad = folder / "log_1e6_rows_bad_last.csv"
    write_force_log(bad, np.arange(n) / 250.0, data.p_gripper, data.f_sens)
    text = bad.read_text()
    head, last = text.rstrip("\n").rsplit("\n", 1)
    bad.write_text(head + "\n" + last.replace(".", "_", 1) + "\n")
    out["log_1e6_rows_bad_last"] = bad
    return out


def _run(args: list[str]) -> dict[str, object]:
    cli = Path(sys.executable).with_name("tautwire")
    t0 = time.perf_counter()
    done = subprocess.run([str(cli), *args], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    lines = done.stderr.splitlines()
    return {
        "status": done.returncode,
        "stderr_lines": len(lines),
        "first_line": lines[0][:160] if lines else "",
        "wall_s": round(wall, 2),
    }


def main() -> None:
    report: dict[str, object] = {}
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        for case, path in _scenarios(folder).items():
            report[case] = _run(["validate", str(path)])
        for case, path in _logs(folder).items():
            report[case] = _run(["estimate", str(path)])
    report["machine"] = {
        "cpu": platform.processor() or platform.machine(),
        "cores": os.cpu_count(),
        "load_average_1min": round(os.getloadavg()[0], 1),
        "python": platform.python_version(),
        "platform": platform.platform(),
    }
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
