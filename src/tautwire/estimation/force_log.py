"""The force log CSV of DESIGN.md: reading (validated) and writing.

Header ``t,px,py,pz,fx,fy,fz`` is required, ``qw,qx,qy,qz`` (gripper
orientation, [w, x, y, z]) and ``tx,ty,tz`` (torque [N m]) are optional
groups, in any column order. Time t [s] must increase; p [m] is the gripper
position and f [N] the force that the cable exerts on the gripper, both in
the world frame, sensor bias removed. Blank lines are skipped; a UTF-8
byte-order mark is accepted. Numbers are decimal (``0.25``, ``-1.5e-3``):
``1_0``, which Python's ``float`` reads as 10, is refused. Every problem
raises :class:`~tautwire.errors.InputFileError` with one line naming the
file, the line number, the column and what was expected.
"""

from __future__ import annotations

import codecs
import csv
import itertools
import os
import re
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InputFileError, InvalidArgumentError

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]

#: Required columns, in the order the writer uses.
REQUIRED_COLUMNS = ("t", "px", "py", "pz", "fx", "fy", "fz")
#: Optional column groups (all of a group or none).
OPTIONAL_GROUPS = (("qw", "qx", "qy", "qz"), ("tx", "ty", "tz"))
#: Fewest data rows an estimation needs (two lines fix a point).
MIN_ROWS = 2
#: Lines parsed at a time: each block in one numpy pass if it is plain, else
#: field by field (so the first bad line is found without parsing the rest).
CHUNK_LINES = 50_000
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
    lines: IntArray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))

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


#: A number as the log may write it: decimal, optional exponent, no underscores.
_NUMBER = re.compile(r"\s*[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?\s*")
#: Non-finite spellings that Python's float() reads ("nan", "inf", "-Infinity").
_NON_FINITE = re.compile(r"\s*[-+]?(?:nan|inf|infinity)\s*", re.IGNORECASE)
#: Characters a data block of plain decimal numbers can hold; anything else
#: (quotes, underscores, letters but e/E) sends the block to the line-by-line parser.
_PLAIN_DATA = re.compile(r"[^0-9eE+\-.,\s]")


def _parse_value(path: str, line: int, column: str, text: str) -> float:
    if _NUMBER.fullmatch(text) is None:
        if _NON_FINITE.fullmatch(text) is not None:
            raise InputFileError(
                f"{path}: line {line}, column {column!r}: expected a finite number, "
                f"got {text.strip()!r}"
            )
        raise InputFileError(
            f"{path}: line {line}, column {column!r}: expected a number such as 0.25 or "
            f"-1.5e-3, got {text.strip()[:40]!r}"
        )
    value = float(text)
    if not np.isfinite(value):
        raise InputFileError(
            f"{path}: line {line}, column {column!r}: expected a finite number, "
            f"got {text.strip()[:40]!r}"
        )
    return value


def _line_blocks(name: str) -> Iterator[tuple[int, list[str]]]:
    """The file's lines, :data:`CHUNK_LINES` at a time, each block with its first index.

    Streams the file (a block in memory at a time); line ends (LF or CRLF)
    are dropped, and so is a UTF-8 byte-order mark.
    """
    file = Path(name)
    if not file.exists():
        raise InputFileError(f"{name}: file not found")
    if not file.is_file():
        raise InputFileError(f"{name}: not a regular file, expected a force log CSV")
    try:
        with file.open("rb") as fh:
            start = 0
            while raw_lines := list(itertools.islice(fh, CHUNK_LINES)):
                raw = b"".join(raw_lines)
                if start == 0 and raw.startswith(codecs.BOM_UTF8):
                    raw = raw[len(codecs.BOM_UTF8) :]
                try:
                    text = raw.decode("utf-8")
                except UnicodeDecodeError as exc:
                    line = start + raw.count(b"\n", 0, exc.start) + 1
                    raise InputFileError(
                        f"{name}: line {line}: not UTF-8 text ({exc.reason})"
                    ) from None
                lines = text.split("\n")
                if text.endswith("\n"):
                    lines.pop()
                yield start, [t[:-1] if t.endswith("\r") else t for t in lines]
                start += len(raw_lines)
    except OSError as exc:
        raise InputFileError(f"{name}: cannot read the file ({exc.strerror})") from None


def _fast_table(lines: list[str], first: int, n_cols: int) -> tuple[FloatArray, IntArray] | None:
    """Data rows as an (N, n_cols) array, with their line numbers, in one numpy parse.

    Only for a block of plain decimal numbers, each line ``n_cols`` fields;
    None otherwise (then the field-by-field parser finds and names the
    first bad field).

    Args:
        lines: lines of the file, without line ends.
        first: the 0-based line index of ``lines[0]`` in the file.
        n_cols: fields per line, as in the header.
    """
    body = lines
    kept = [i for i, text in enumerate(body) if text.strip()]
    if len(kept) != len(body):
        body = [body[i] for i in kept]
    if not body:
        return np.zeros((0, n_cols)), np.zeros(0, dtype=np.int64)
    if any(text.count(",") != n_cols - 1 for text in body):
        return None
    block = ",".join(body)
    if _PLAIN_DATA.search(block) is not None:
        return None
    try:
        values = np.fromstring(block, dtype=float, sep=",")
    except ValueError:
        return None
    if values.size != len(body) * n_cols or not np.all(np.isfinite(values)):
        return None
    numbers = np.asarray(kept, dtype=np.int64) + (first + 1)
    return values.reshape(len(body), n_cols), numbers


def _slow_table(
    name: str, lines: list[str], first: int, order: list[tuple[str, int]], n_cols: int
) -> tuple[FloatArray, IntArray]:
    """Data rows parsed field by field; the first bad field raises, naming its line.

    Args are as :func:`_fast_table`'s, with the file's name for messages and
    the header's (column, index) pairs in ``order``.
    """
    rows: list[list[float]] = []
    numbers: list[int] = []
    for index, row in enumerate(csv.reader(lines)):
        line = first + index + 1
        if not row or not any(c.strip() for c in row):
            continue
        if len(row) != n_cols:
            raise InputFileError(
                f"{name}: line {line}: expected {n_cols} fields as in the header, got {len(row)}"
            )
        values = [0.0] * n_cols
        for column, i in order:
            values[i] = _parse_value(name, line, column, row[i])
        rows.append(values)
        numbers.append(line)
    table = np.asarray(rows, dtype=float).reshape(len(rows), n_cols)
    return table, np.asarray(numbers, dtype=np.int64)


def read_force_log(path: str | os.PathLike[str]) -> ForceLog:
    """Read and validate a force log CSV.

    A file of plain decimal numbers is parsed by numpy in one pass (a
    million rows in a few seconds); anything else is parsed field by field,
    so that every problem still names its line and column.

    Args:
        path: The CSV file (UTF-8, with or without a byte-order mark).

    Returns:
        The validated log.

    Raises:
        InputFileError: Missing or unreadable file, empty file, bad header,
            a malformed (``1_0`` included), non-finite or zero-force row,
            time not increasing, or fewer than :data:`MIN_ROWS` data rows.
    """
    name = os.fspath(path)
    columns: dict[str, int] | None = None
    header_line = 1
    tables: list[FloatArray] = []
    numbered: list[IntArray] = []
    for start, lines in _line_blocks(name):
        if columns is None:
            found = next((i for i, text in enumerate(lines) if text.strip(", \t")), None)
            if found is None:
                continue
            header_line = start + found + 1
            header = next(csv.reader([lines[found]]))
            columns = _header_columns(name, header, header_line)
            start, lines = start + found + 1, lines[found + 1 :]
        n_cols = len(header)
        part = _fast_table(lines, start, n_cols) or _slow_table(
            name, lines, start, list(columns.items()), n_cols
        )
        tables.append(part[0])
        numbered.append(part[1])
    if columns is None:
        raise InputFileError(
            f"{name}: line 1: empty file, expected the header {','.join(REQUIRED_COLUMNS)}"
        )
    numbers = np.concatenate(numbered) if numbered else np.zeros(0, dtype=np.int64)
    if len(numbers) < MIN_ROWS:
        last = int(numbers[-1]) if len(numbers) else header_line
        raise InputFileError(
            f"{name}: line {last}: too few data rows ({len(numbers)}), need at least {MIN_ROWS}"
        )

    def block(names: tuple[str, ...]) -> FloatArray:
        index = [columns[c] for c in names]
        return np.ascontiguousarray(np.concatenate([part[:, index] for part in tables]))

    t = block(("t",)).reshape(-1)
    p = block(("px", "py", "pz"))
    f = block(("fx", "fy", "fz"))
    f_norm = np.linalg.norm(f, axis=1)
    zero = np.flatnonzero(f_norm <= ZERO_FORCE)
    if zero.size:
        i = int(zero[0])
        raise InputFileError(
            f"{name}: line {numbers[i]}, columns 'fx','fy','fz': zero force "
            f"(|f| = {f_norm[i]:.3g} N), expected a taut cable with |f| > {ZERO_FORCE:g} N"
        )
    bad_t = np.flatnonzero(np.diff(t) <= 0.0)
    if bad_t.size:
        i = int(bad_t[0]) + 1
        raise InputFileError(
            f"{name}: line {numbers[i]}, column 't': time must increase, "
            f"got {t[i]!r} after {t[i - 1]!r}"
        )
    q = block(OPTIONAL_GROUPS[0]) if "qw" in columns else None
    torque = block(OPTIONAL_GROUPS[1]) if "tx" in columns else None
    return ForceLog(name, t, p, f, q, torque, numbers)


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
