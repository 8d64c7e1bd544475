import csv

from tautwire.experiments.trial import TrialResult, TrialSpec
from tautwire.experiments.trials_csv import FIXED_COLUMNS, TrialsCsv, read_trials

from . import fake_trials


def result(letter: str, index: int) -> TrialResult:
    return fake_trials.quick_trial(TrialSpec(letter, index, 1000 + index))


def rows(path) -> list[dict[str, str]]:  # type: ignore[no-untyped-def]
    with path.open(newline="") as fh:
        return list(csv.DictReader(fh))


def test_each_trial_is_on_disk_as_soon_as_it_is_appended(tmp_path) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "trials.csv"
    trials = TrialsCsv(path)
    assert rows(path) == []
    trials.append(result("D", 1))
    assert [r["index"] for r in rows(path)] == ["1"]
    trials.append(result("I", 0))  # brings a new input column: the file is rewritten wider
    trials.append(result("D", 0))
    written = rows(path)
    assert [(r["letter"], r["index"]) for r in written] == [("D", "1"), ("I", "0"), ("D", "0")]
    assert list(written[0])[: len(FIXED_COLUMNS)] == list(FIXED_COLUMNS)
    assert written[0]["input.sense"] == "" and written[1]["input.sense"] == "positive"
    trials.finish()
    assert [(r["letter"], r["index"]) for r in rows(path)] == [("D", "0"), ("D", "1"), ("I", "0")]
    assert not (tmp_path / "trials.csv.partial").exists()


def test_read_back_equals_what_was_written(tmp_path) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "trials.csv"
    written = [result("D", 0), result("D", 2), result("I", 1)]
    trials = TrialsCsv(path, written)
    trials.close()
    assert read_trials(path) == written


def test_a_row_cut_short_is_skipped(tmp_path) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "trials.csv"
    TrialsCsv(path, [result("D", 0), result("D", 1)]).close()
    text = path.read_text()
    path.write_text(text[: text.rindex("\n", 0, len(text) - 2) + 1] + "D,single_arm")
    assert read_trials(path) == [result("D", 0)]
