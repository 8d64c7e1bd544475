"""Accuracy of the simulated cable against closed forms, at given simulation options.

    .venv/bin/python bench/sim_accuracy.py                          # the defaults
    .venv/bin/python bench/sim_accuracy.py segment_length=0.03      # any SimOptions field

Prints one JSON object with the relative errors [%] that ``tests/sim`` bounds
(the same scenes): Hooke's law of a hanging cable (k = 10, 100, 1000 N/m),
the stiffness a tensioning primitive would learn through the hold (slope of
tension over gripper travel, 1500 N/m), the mid-span sag against the elastic
catenary (100 N/m over 0.30 m, 10 N/m over 0.36 m, 0.4 m cable), and the
sliding friction through closed fingers against 2 mu F_grip (grip 1 and 4 N).
Use it to see what a change of the discretisation or the solver does to the
physics before taking it.
"""

from __future__ import annotations

import json
import sys
from typing import Any

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

from tautwire.model.tension import G
from tautwire.robot import GripperCommand
from tautwire.sim import (
    AnchorSpec,
    CableSpec,
    GripperSpec,
    HoldSpec,
    SimOptions,
    SimWorld,
    WorldSpec,
)
from tautwire.sim.ground_truth import GroundTruth

X_UP = np.array([np.sqrt(0.5), 0.0, -np.sqrt(0.5), 0.0])  # tool x-axis straight up
MU_PAD = SimOptions().pad_friction


def _world(
    anchor: list[float],
    gripper: list[float],
    length: float,
    k: float,
    orientation: np.ndarray,
    held_at: float | None = None,
    **options: Any,
) -> SimWorld:
    spec = WorldSpec(
        fixtures=(AnchorSpec("A", np.array(anchor)),),
        cables=(
            CableSpec(
                "W",
                length,
                0.03,
                k,
                0.0025,
                start="A",
                holds=(HoldSpec("left", length if held_at is None else held_at),),
            ),
        ),
        left=GripperSpec(np.array(gripper), orientation),
        right=GripperSpec(np.array([0.0, -0.5, 0.3])),
        sensor_arms=("left",),
        noise_force=0.0,
        noise_torque=0.0,
        force_limit=15.0,
        seed=0,
    )
    return SimWorld(spec, SimOptions.from_kwargs(**options))


def _rest(world: SimWorld, seconds: float) -> None:
    world.set_twist(np.zeros(12))
    for _ in range(round(seconds / world.control_period)):
        world.step()


def _vertical(k: float, extra: float, **options: Any) -> float:
    """Mean tension [N] of a 0.3 m cable hanging from an anchor, stretched to 2 N / k + extra."""
    length, rho = 0.3, 0.03
    top = np.array([0.0, 0.0, 0.9])
    gripper = top - np.array([0.0, 0.0, length + 2.0 / k + extra])
    world = _world(top.tolist(), gripper.tolist(), length, k, X_UP, **options)
    _rest(world, 0.5)
    return float(world.wrench("left")[0][2] + 0.5 * rho * length * G)


def hooke_error(k: float, **options: Any) -> float:
    """Mean tension against k dl [%]."""
    return 100.0 * (_vertical(k, 0.0, **options) / 2.0 - 1.0)


def hold_slope_error(**options: Any) -> float:
    """Learned stiffness (tension over 0.2 mm gripper steps) against k = 1500 N/m [%]."""
    steps = np.array([0.0, 2e-4, 4e-4])
    tensions = [_vertical(1500.0, float(s), **options) for s in steps]
    return 100.0 * (float(np.polyfit(steps, tensions, 1)[0]) / 1500.0 - 1.0)


def _elastic_catenary(span: float, length: float, rho: float, k: float) -> tuple[float, float]:
    """Mid-span sag [m] and end slope [rad] of an elastic catenary, supports level."""
    w = rho * G
    ea = k * length
    v0 = 0.5 * w * length

    def dx(s: float, h: float) -> float:
        return float(h * (1.0 / ea + 1.0 / np.hypot(h, v0 - w * s)))

    h = brentq(lambda h: quad(dx, 0.0, length, args=(h,))[0] - span, 1e-6, 1e3)

    def dz(s: float) -> float:
        v = v0 - w * s
        return float(v * (1.0 / ea + 1.0 / np.hypot(h, v)))

    return float(quad(dz, 0.0, 0.5 * length)[0]), float(np.arctan2(v0, h))


def sag_error(k: float, span: float, **options: Any) -> float:
    """Mid-span sag against the elastic catenary [%] (0.4 m cable, supports level)."""
    length, height = 0.4, 0.5
    expected, slope = _elastic_catenary(span, length, 0.03, k)
    q = np.array([np.cos(0.5 * slope), 0.0, -np.sin(0.5 * slope), 0.0])
    world = _world([0.0, 0.0, height], [span, 0.0, height], length, k, q, **options)
    _rest(world, 1.0)
    truth = GroundTruth(world)
    arc, z = truth.arc_lengths("W"), truth.polyline("W")[:, 2]
    i = int(np.argmin(np.abs(arc - 0.5 * length)))
    fit = np.polyfit(arc[i - 1 : i + 2], z[i - 1 : i + 2], 2)
    sag = height - float(np.polyval(fit, 0.5 * length))
    return 100.0 * (sag / expected - 1.0)


def friction_error(grip: float, **options: Any) -> float:
    """Pull while sliding through the fingers against 2 mu F_grip [%]."""
    world = _world(
        [0.0, 0.0, 0.3], [0.32, 0.0, 0.3], 0.4, 1000.0, np.array([1.0, 0, 0, 0]), 0.32, **options
    )
    _rest(world, 0.2)
    world.set_gripper("left", GripperCommand("grip_force", grip))
    twist = np.zeros(12)
    twist[0] = 0.01
    world.set_twist(twist)
    steps = round(3.0 / world.control_period)
    window = round(1.0 / world.control_period)
    pulls = []
    for i in range(steps):
        world.step()
        if i >= steps - window:
            pulls.append(-world.wrench("left")[0][0])
    return 100.0 * (float(np.mean(pulls)) / (2.0 * MU_PAD * grip) - 1.0)


def accuracy(**options: Any) -> dict[str, Any]:
    """Every figure, as relative errors [%] rounded to 1e-4 %."""

    def r(x: float) -> float:
        return round(x, 4)

    return {
        "options": options,
        "hooke_error_pct": {f"{k:g}": r(hooke_error(k, **options)) for k in (10.0, 100.0, 1000.0)},
        "hold_slope_error_pct": r(hold_slope_error(**options)),
        "sag_error_pct": {
            f"k={k:g},span={s:g}": r(sag_error(k, s, **options))
            for k, s in ((100.0, 0.3), (10.0, 0.36))
        },
        "friction_error_pct": {f"{g:g}N": r(friction_error(g, **options)) for g in (1.0, 4.0)},
    }


def main(argv: list[str] | None = None) -> int:
    options: dict[str, Any] = {}
    for item in sys.argv[1:] if argv is None else argv:
        key, _, value = item.partition("=")
        options[key] = None if value == "None" else float(value)
        if key == "segments" and options[key] is not None:
            options[key] = int(options[key])
    json.dump(accuracy(**options), sys.stdout, indent=2)
    sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
