"""``tautwire estimate LOG.csv``: offline contact and stiffness estimation of a force log."""

from __future__ import annotations

import json
from typing import Any

import click
import numpy as np

from tautwire.estimation import (
    DEFAULT_PROCESS_NOISE,
    OfflineEstimate,
    estimate_force_log,
    read_force_log,
)


def _vec(a: np.ndarray[Any, Any] | None) -> list[Any] | None:
    return None if a is None else [float(v) for v in np.asarray(a).reshape(-1)]


def estimate_to_json(result: OfflineEstimate) -> dict[str, Any]:
    """The ``--json`` object of an offline estimate (plain Python types)."""
    return {
        "contact": _vec(result.contact),
        "covariance": None
        if result.covariance is None
        else [[float(v) for v in row] for row in result.covariance],
        "history": [
            {"t": h.t, "contact": _vec(h.contact), "std": _vec(h.std)} for h in result.history
        ],
        "changes": list(result.changes),
        "stiffness": result.stiffness,
        "stiffness_std": result.stiffness_std,
    }


def _summary(path: str, result: OfflineEstimate) -> str:
    lines = [f"force log: {path} ({len(result.history)} rows)"]
    if result.contact is None or result.covariance is None:
        lines.append("contact: no estimate (the force direction never changed enough)")
    else:
        std = np.sqrt(np.diag(result.covariance))
        xyz = ", ".join(f"{c:.4f}" for c in result.contact)
        lines.append(f"contact: [{xyz}] m  (std {', '.join(f'{s * 1e3:.2f}' for s in std)} mm)")
    if result.changes:
        lines.append(f"contact changes at rows: {', '.join(str(c) for c in result.changes)}")
    else:
        lines.append("contact changes: none")
    if result.stiffness is None or result.stiffness_std is None:
        lines.append("stiffness: not estimable (the cable length hardly changed)")
    else:
        lines.append(f"stiffness: {result.stiffness:.1f} N/m (std {result.stiffness_std:.1f})")
    return "\n".join(lines)


EPILOG = """\b
The force log (CSV, UTF-8, comma-separated, one header line, any column order):
  t,px,py,pz,fx,fy,fz          required
    t           time [s], strictly increasing
    px,py,pz    gripper position [m], world frame
    fx,fy,fz    force [N] that the cable exerts on the gripper, world frame,
                sensor bias removed (|f| > 0: a taut cable)
  qw,qx,qy,qz  optional: gripper orientation, quaternion [w, x, y, z]
  tx,ty,tz     optional: torque [N m] about the logged gripper point, world
               frame (each row is then the wrench's line of action)
Numbers are decimal (0.25, -1.5e-3; not 1_0, nan or inf); blank lines are
skipped. A bad file exits 1 with one line naming the file, the line and
the column. `tautwire run SCENARIO --out DIR` writes DIR/force_log.csv.

\b
Example log:
  t,px,py,pz,fx,fy,fz
  0.000,0.300,0.000,0.120,-3.98,0.02,-0.31
  0.004,0.300,0.002,0.120,-3.97,-0.01,-0.30

\b
Examples:
  tautwire estimate out/run/force_log.csv
  tautwire estimate log.csv --json > estimate.json
  tautwire estimate log.csv --mass-per-length 0.03 --force-noise 0.1
"""


@click.command("estimate", epilog=EPILOG)
@click.argument("log", metavar="LOG.csv")
@click.option("--json", "as_json", is_flag=True, help="print one JSON object on stdout")
@click.option(
    "--mass-per-length",
    "mass_per_length",
    type=float,
    default=0.0,
    show_default=True,
    metavar="RHO",
    help="cable mass per length [kg/m] for weight compensation (0 = off)",
)
@click.option(
    "--process-noise",
    type=float,
    default=DEFAULT_PROCESS_NOISE,
    show_default=True,
    metavar="Q",
    help="Kalman process noise [m^2 per sample, per axis]",
)
@click.option(
    "--force-noise",
    type=float,
    default=0.05,
    show_default=True,
    metavar="SIGMA",
    help="force sensor noise [N], std per axis",
)
@click.option(
    "--torque-noise",
    type=float,
    default=0.002,
    show_default=True,
    metavar="SIGMA",
    help="torque sensor noise [N m], std per axis (used when the log has tx,ty,tz)",
)
@click.option(
    "--edge-length",
    type=float,
    default=None,
    metavar="D",
    help="known gripper-contact cable length [m] (default: from the estimate)",
)
def estimate(
    log: str,
    as_json: bool,
    mass_per_length: float,
    process_noise: float,
    force_noise: float,
    torque_noise: float,
    edge_length: float | None,
) -> int:
    """Estimate the contact point(s) and the cable stiffness from a force log."""
    data = read_force_log(log)
    result = estimate_force_log(
        data,
        force_noise=force_noise,
        process_noise=process_noise,
        mass_per_length=mass_per_length,
        edge_length=edge_length,
        torque_noise=torque_noise,
    )
    if as_json:
        click.echo(json.dumps(estimate_to_json(result), allow_nan=False))
    else:
        click.echo(_summary(log, result))
    return 0
