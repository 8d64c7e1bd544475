"""A CSV file of trial results, written one row per trial as trials finish.

Each row is :meth:`TrialResult.to_row`: the result's fields, then its
randomised inputs as ``input.<name>`` columns. The columns are the union
over the trials (primitives draw different inputs), in order of first
appearance; a trial that brings a new input column rewrites the file with
the wider header (rare: about once per primitive), every other trial is
appended and flushed, so an interrupted campaign leaves every finished trial
on disk. :meth:`TrialsCsv.finish` rewrites the file ordered by (letter,
index), so a finished campaign's file does not depend on completion order.
"""

from __future__ import annotations

import csv
import os
from collections.abc import Iterable
from dataclasses import fields
from pathlib import Path
from typing import IO, Any

from tautwire.experiments.campaign import result_order
from tautwire.experiments.trial import TrialResult

#: The columns every row has, in order (the result's fields but ``inputs``).
FIXED_COLUMNS: tuple[str, ...] = tuple(f.name for f in fields(TrialResult) if f.name != "inputs")
_INPUT = "input."


class TrialsCsv:
    """The trials file of a campaign, kept up to date trial by trial.

    Args:
        path: The CSV file; created (or truncated) now.
        results: Trials already known (e.g. of an earlier, interrupted run),
            written first.
    """

    def __init__(self, path: str | Path, results: Iterable[TrialResult] = ()) -> None:
        self.path = Path(path)
        self.results: list[TrialResult] = list(results)
        self.columns: list[str] = []
        self._file: IO[str] | None = None
        self._writer: Any = None
        self._rewrite()

    def append(self, result: TrialResult) -> None:
        """Add one finished trial to the file (appended and flushed)."""
        self.results.append(result)
        row = result.to_row()
        if any(key not in self.columns for key in row):
            self._rewrite()
            return
        assert self._file is not None
        self._writer.writerow(row)
        self._file.flush()

    def finish(self) -> None:
        """Rewrite the file ordered by (letter, index) and close it."""
        self.results.sort(key=result_order)
        self.columns = []
        self._rewrite()
        self.close()

    def close(self) -> None:
        """Close the file (its rows are already on disk)."""
        if self._file is not None:
            self._file.close()
            self._file = None

    def _rewrite(self) -> None:
        """Write every known row under the widest header, replacing the file atomically."""
        self.close()
        for result in self.results:
            for key in result.to_row():
                if key not in self.columns:
                    self.columns.append(key)
        if not self.columns:
            self.columns = list(FIXED_COLUMNS)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        partial = self.path.with_name(self.path.name + ".partial")
        with partial.open("w", newline="") as fh:
            writer = csv.DictWriter(fh, fieldnames=self.columns, restval="")
            writer.writeheader()
            writer.writerows(r.to_row() for r in self.results)
        os.replace(partial, self.path)
        self._file = self.path.open("a", newline="")
        self._writer = csv.DictWriter(self._file, fieldnames=self.columns, restval="")


def _number_or_text(text: str) -> float | str:
    try:
        return float(text)
    except ValueError:
        return text


def _result_of(row: dict[str, str | None]) -> TrialResult | None:
    """A result from a CSV row, or None for a row cut short (e.g. by a crash)."""
    if any(row.get(c) is None for c in FIXED_COLUMNS) or None in row:
        return None
    try:
        return TrialResult(
            letter=str(row["letter"]),
            name=str(row["name"]),
            index=int(str(row["index"])),
            seed=int(str(row["seed"])),
            inputs={
                k[len(_INPUT) :]: _number_or_text(v)
                for k, v in row.items()
                if k.startswith(_INPUT) and v
            },
            outcome=str(row["outcome"]),
            cause=row["cause"] or None,
            detail=str(row["detail"]),
            max_force=float(str(row["max_force"])),
            sim_time=float(str(row["sim_time"])),
            wall_time=float(str(row["wall_time"])),
        )
    except ValueError:
        return None


def read_trials(path: str | Path) -> list[TrialResult]:
    """The results in a trials CSV file; rows cut short are skipped.

    Inputs come back as numbers where they parse as numbers, else as text.
    """
    with Path(path).open(newline="") as fh:
        rows = list(csv.DictReader(fh))
    return [r for r in (_result_of(row) for row in rows) if r is not None]
