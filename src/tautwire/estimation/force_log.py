"""The force log CSV of DESIGN.md: reading (validated) and writing.

Header ``t,px,py,pz,fx,fy,fz`` is required, ``qw,qx,qy,qz`` (gripper
orientation, [w, x, y, z]) and ``tx,ty,tz`` (torque [N m]) are optional
groups, in any column order. Time t [s] must increase; p [m] is the gripper
position and f [N] the force that the cable exerts on the gripper, both in
the world frame, sensor bias removed. Blank lines are skipped. Every problem
raises :class:`~tautwire.errors.InputFileError` with one line naming the
file, the line number, the column and what was expected.
"""

from __future__ import annotations

import csv
import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InputFileError, InvalidArgumentError

FloatArray = NDArray[np.float64]

#: Required columns, in the order the writer uses.
REQUIRED_COLUMNS = ("t", "px", "py", "pz", "fx", "fy", "fz")
#: Optional column groups (all of a group or none).
OPTIONAL_GROUPS = (("qw", "qx", "qy", "qz"), ("tx", "ty", "tz"))
#: Fewest data rows an estimation needs (two lines fix a point).
MIN_ROWS = 2
#: Forces shorter than this [N] count as zero (no direction).
ZERO_FORCE = 1e-6


@dataclass(frozen=True)
class ForceLog:
    """A validated force log.

    Attributes:
        path: The file it was read from ("" when built in memory).
        t: Time [s], strictly increasing.  # (N,)
        p_gripper: Gripper position [m], world frame.  # (N, 3)
        f_sens: Force [N] the cable exerts on the gripper, world frame.  # (N, 3)
        q_gripper: Gripper orientation [w, x, y, z], or None.  # (N, 4)
        torque: Torque [N m], world frame, or None.  # (N, 3)
        lines: Line number in the file of each data row (1-based).  # (N,)
    """

    path: str
    t: FloatArray
    p_gripper: FloatArray
    f_sens: FloatArray
    q_gripper: FloatArray | None = None
    torque: FloatArray | None = None
    lines: tuple[int, ...] = ()

    def __len__(self) -> int:
        return int(self.t.shape[0])


def _header_columns(path: str, header: list[str], line: int) -> dict[str, int]:
    names = [h.strip().lower() for h in header]
    valid = set(REQUIRED_COLUMNS) | {c for g in OPTIONAL_GROUPS for c in g}
    columns: dict[str, int] = {}
    for i, name in enumerate(names):
        if name not in valid:
            raise InputFileError(
                f"{path}: line {line}, column {i + 1}: unknown column {name!r}; expected "
                f"{','.join(REQUIRED_COLUMNS)} and optionally "
                f"{','.join(OPTIONAL_GROUPS[0])} and {','.join(OPTIONAL_GROUPS[1])}"
            )
        if name in columns:
            raise InputFileError(f"{path}: line {line}, column {i + 1}: duplicate column {name!r}")
        columns[name] = i
    for name in REQUIRED_COLUMNS:
        if name not in columns:
            raise InputFileError(
                f"{path}: line {line}: missing column {name!r}; the header must contain "
                f"{','.join(REQUIRED_COLUMNS)}"
            )
    for group in OPTIONAL_GROUPS:
        present = [c for c in group if c in columns]
        if present and len(present) != len(group):
            missing = [c for c in group if c not in columns]
            raise InputFileError(
                f"{path}: line {line}: missing column {missing[0]!r}; give all of "
                f"{','.join(group)} or none"
            )
    return columns


def _parse_value(path: str, line: int, column: str, text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise InputFileError(
            f"{path}: line {line}, column {column!r}: expected a number, got {text.strip()!r}"
        ) from None
    if not math.isfinite(value):
        raise InputFileError(
            f"{path}: line {line}, column {column!r}: expected a finite number, "
            f"got {text.strip()!r}"
        )
    return value


def read_force_log(path: str | os.PathLike[str]) -> ForceLog:
    """Read and validate a force log CSV.

    Args:
        path: The CSV file.

    Returns:
        The validated log.

    Raises:
        InputFileError: Missing or unreadable file, empty file, bad header,
            a malformed, non-finite or zero-force row, time not increasing,
            or fewer than :data:`MIN_ROWS` data rows.
    """
    name = os.fspath(path)
    file = Path(name)
    if not file.exists():
        raise InputFileError(f"{name}: file not found")
    if not file.is_file():
        raise InputFileError(f"{name}: not a regular file, expected a force log CSV")
    try:
        text = file.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputFileError(f"{name}: cannot read the file as UTF-8 text ({exc})") from None
    rows = list(enumerate(csv.reader(text.splitlines()), start=1))
    rows = [(n, r) for n, r in rows if r and any(c.strip() for c in r)]
    if not rows:
        raise InputFileError(
            f"{name}: line 1: empty file, expected the header {','.join(REQUIRED_COLUMNS)}"
        )
    header_line, header = rows[0]
    columns = _header_columns(name, header, header_line)
    order = list(columns.items())
    n_cols = len(header)
    data: dict[str, list[float]] = {c: [] for c in columns}
    lines: list[int] = []
    for line, row in rows[1:]:
        if len(row) != n_cols:
            raise InputFileError(
                f"{name}: line {line}: expected {n_cols} fields as in the header, got {len(row)}"
            )
        for column, index in order:
            data[column].append(_parse_value(name, line, column, row[index]))
        lines.append(line)
    if len(lines) < MIN_ROWS:
        last = lines[-1] if lines else header_line
        raise InputFileError(
            f"{name}: line {last}: too few data rows ({len(lines)}), need at least {MIN_ROWS}"
        )
    t = np.array(data["t"])
    p = np.stack([np.array(data[c]) for c in ("px", "py", "pz")], axis=1)
    f = np.stack([np.array(data[c]) for c in ("fx", "fy", "fz")], axis=1)
    f_norm = np.linalg.norm(f, axis=1)
    zero = np.flatnonzero(f_norm <= ZERO_FORCE)
    if zero.size:
        i = int(zero[0])
        raise InputFileError(
            f"{name}: line {lines[i]}, columns 'fx','fy','fz': zero force "
            f"(|f| = {f_norm[i]:.3g} N), expected a taut cable with |f| > {ZERO_FORCE:g} N"
        )
    bad_t = np.flatnonzero(np.diff(t) <= 0.0)
    if bad_t.size:
        i = int(bad_t[0]) + 1
        raise InputFileError(
            f"{name}: line {lines[i]}, column 't': time must increase, "
            f"got {t[i]!r} after {t[i - 1]!r}"
        )
    q = None
    if "qw" in columns:
        q = np.stack([np.array(data[c]) for c in OPTIONAL_GROUPS[0]], axis=1)
    torque = None
    if "tx" in columns:
        torque = np.stack([np.array(data[c]) for c in OPTIONAL_GROUPS[1]], axis=1)
    return ForceLog(name, t, p, f, q, torque, tuple(lines))


def write_force_log(
    path: str | os.PathLike[str],
    t: ArrayLike,
    p_gripper: ArrayLike,
    f_sens: ArrayLike,
    q_gripper: ArrayLike | None = None,
    torque: ArrayLike | None = None,
) -> None:
    """Write a force log CSV that :func:`read_force_log` reads back exactly.

    Args:
        path: The CSV file (overwritten).
        t: Time [s].  # (N,)
        p_gripper: Gripper position [m], world frame.  # (N, 3)
        f_sens: Force [N] the cable exerts on the gripper, world frame.  # (N, 3)
        q_gripper: Optional orientation [w, x, y, z].  # (N, 4)
        torque: Optional torque [N m].  # (N, 3)
    """
    blocks = [np.asarray(t, dtype=float).reshape(-1, 1)]
    header = list(REQUIRED_COLUMNS)
    n = blocks[0].shape[0]
    for arr, width, label in ((p_gripper, 3, "p_gripper"), (f_sens, 3, "f_sens")):
        a = np.asarray(arr, dtype=float)
        if a.shape != (n, width):
            raise InvalidArgumentError(f"{label} must have shape ({n}, {width}), got {a.shape}")
        blocks.append(a)
    for opt, group, label in (
        (q_gripper, OPTIONAL_GROUPS[0], "q_gripper"),
        (torque, OPTIONAL_GROUPS[1], "torque"),
    ):
        if opt is None:
            continue
        a = np.asarray(opt, dtype=float)
        if a.shape != (n, len(group)):
            raise InvalidArgumentError(
                f"{label} must have shape ({n}, {len(group)}), got {a.shape}"
            )
        blocks.append(a)
        header.extend(group)
    table = np.hstack(blocks)
    with open(path, "w", encoding="utf-8", newline="") as fh:
        fh.write(",".join(header) + "\n")
        for row in table:
            fh.write(",".join(repr(float(v)) for v in row) + "\n")
