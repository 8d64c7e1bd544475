import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.experiments.table1 import (
    PAPER_TABLE,
    Progress,
    parse_letters,
    parse_only,
    reproduce_table1,
    table1_specs,
)
from tautwire.experiments.trial import LETTERS, TrialResult, TrialSpec, trial_seed

from . import fake_trials

ROOT = Path(__file__).resolve().parents[2]


def rows(path: Path) -> list[dict[str, str]]:
    with path.open(newline="") as fh:
        return list(csv.DictReader(fh))


def test_the_paper_table_has_nine_rows_155_trials_and_4_failures() -> None:
    assert sorted(r.letter for r in PAPER_TABLE) == list(LETTERS)
    assert sum(r.trials for r in PAPER_TABLE) == 155
    assert sum(r.failures for r in PAPER_TABLE) == 4


def test_specs_have_stable_seeds_per_letter_and_index() -> None:
    specs = table1_specs(3, 7, "ID")
    assert [(s.letter, s.index) for s in specs] == [(c, i) for c in "DI" for i in range(3)]
    assert all(s.seed == trial_seed(7, s.letter, s.index) for s in specs)
    assert len(table1_specs(2, 0)) == 18
    with pytest.raises(InvalidArgumentError, match="at least 1"):
        table1_specs(0, 0)


def test_letters_and_single_trials_are_parsed_or_refused() -> None:
    assert parse_letters("id") == ("D", "I")
    assert parse_letters("A,B") == ("A", "B")
    with pytest.raises(InvalidArgumentError, match="no primitive letter X, Z"):
        parse_letters("DXZ")
    with pytest.raises(InvalidArgumentError, match="no primitive letters"):
        parse_letters("")
    assert parse_only("D:17, i:3", 5) == [
        TrialSpec("D", 17, trial_seed(5, "D", 17)),
        TrialSpec("I", 3, trial_seed(5, "I", 3)),
    ]
    for bad in ("D17", "Q:1", "D:x", "D:-1"):
        with pytest.raises(InvalidArgumentError, match="LETTER:INDEX"):
            parse_only(bad, 0)


def test_table_csv_and_json_of_a_campaign(tmp_path: Path) -> None:
    reports: list[Progress] = []

    def progress(state: Progress) -> None:
        reports.append(state)
        # the trials file holds every finished trial at every moment
        assert len(rows(tmp_path / "table1_trials.csv")) == state.finished

    report = reproduce_table1(
        4, 1, 3, tmp_path, "serial", "ID", progress, trial=fake_trials.quick_trial
    )
    assert reports[0] == Progress(0, 8, 0, None)
    assert [p.finished for p in reports] == list(range(9))
    assert reports[-1].failures == 2

    data = json.loads((tmp_path / "table1.json").read_text())
    assert data == report
    assert [p["letter"] for p in data["primitives"]] == ["D", "I"]  # the paper's row order
    d = data["primitives"][0]
    assert d == {
        "name": "Single arm DLO Tension",
        "letter": "D",
        "trials": 4,
        "failures": 1,
        "causes": {"timeout": 1},
        "max_force": 4.0,
        "paper_trials": 25,
        "paper_failures": 1,
    }
    assert data["total"]["trials"] == 8 and data["total"]["failures"] == 2
    assert (data["finished"], data["planned"], data["interrupted"]) == (8, 8, False)
    assert (data["backend"], data["workers"], data["seed"]) == ("serial", 1, 3)
    assert data["failed_trials"][0] == {
        "letter": "D",
        "index": 2,
        "seed": trial_seed(3, "D", 2),
        "cause": "timeout",
        "detail": "did not reach the set point | in 10 s",
    }

    trials = rows(tmp_path / "table1_trials.csv")
    assert [(r["letter"], r["index"]) for r in trials] == [
        (c, str(i)) for c in "DI" for i in range(4)
    ]
    assert {"input.stiffness", "input.length", "input.sense"} <= set(trials[0])
    assert trials[0]["input.sense"] == "" and trials[5]["input.sense"] == "negative"

    md = (tmp_path / "table1.md").read_text()
    assert "| Single arm DLO Tension | D | 4 | 1 | timeout 1 | 4.0 | 25 | 1 |" in md
    assert "| Rotate Around Feature Point | I | 4 | 1 | timeout 1 | 4.0 | 15 | 0 |" in md
    assert "| **Total** |  | 8 | 2 | timeout 2 | 4.0 | 40 | 1 |" in md
    assert md.index("Single arm DLO Tension") < md.index("Rotate Around Feature Point")
    assert "tautwire reproduce table1 --seed 3 --only D:2" in md
    assert (
        f"| D | 2 | {trial_seed(3, 'D', 2)} | timeout | did not reach the set point \\| in 10 s |"
        in md
    )


def test_an_interrupted_campaign_writes_what_finished_and_resumes(tmp_path: Path) -> None:
    def stop_after_three(state: Progress) -> None:
        if state.finished == 3:
            raise KeyboardInterrupt

    report = reproduce_table1(
        3, 1, 0, tmp_path, "serial", "DI", stop_after_three, trial=fake_trials.quick_trial
    )
    assert report["interrupted"] and (report["finished"], report["planned"]) == (3, 6)
    assert len(rows(tmp_path / "table1_trials.csv")) == 3
    assert "**Interrupted**" in (tmp_path / "table1.md").read_text()
    assert json.loads((tmp_path / "table1.json").read_text())["finished"] == 3

    ran: list[TrialSpec] = []

    def counting_trial(spec: TrialSpec) -> TrialResult:
        ran.append(spec)
        return fake_trials.quick_trial(spec)

    resumed = reproduce_table1(3, 1, 0, tmp_path, "serial", "DI", resume=True, trial=counting_trial)
    assert [(s.letter, s.index) for s in ran] == [("I", 0), ("I", 1), ("I", 2)]
    assert (resumed["finished"], resumed["resumed"], resumed["interrupted"]) == (6, 3, False)
    trials = rows(tmp_path / "table1_trials.csv")
    assert [(r["letter"], r["index"]) for r in trials] == [
        (c, str(i)) for c in "DI" for i in range(3)
    ]
    fresh = reproduce_table1(3, 1, 0, tmp_path / "fresh", "serial", "DI", trial=counting_trial)
    assert fresh["primitives"] == resumed["primitives"]

    with pytest.raises(InvalidArgumentError, match="another campaign"):
        reproduce_table1(3, 1, 1, tmp_path, "serial", "DI", resume=True, trial=counting_trial)


def test_ctrl_c_stops_a_local_campaign_and_keeps_its_trials(tmp_path: Path) -> None:
    script = (
        "import json, signal, sys\n"
        # a terminal's foreground job: Ctrl-C raises KeyboardInterrupt. A child
        # inherits an ignored SIGINT, and Python then installs no handler: in
        # make test the Ctrl-C, sent 0.6 s after the start, was ignored for
        # the whole 62 s campaign (some earlier test leaves SIGINT ignored in
        # its pytest worker)
        "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
        "from tautwire.experiments.table1 import reproduce_table1\n"
        "from tests.experiments.fake_trials import slow_trial\n"
        "def progress(p):\n"
        "    print(p.finished, flush=True)\n"
        # 600 trials of 0.2 s: the campaign outlasts a loaded machine's delay
        # in delivering Ctrl-C (with 40 it once ended first under make test,
        # and with 200, 21 s, twice under make test beside the harness run);
        # interrupted, it ends at once
        f"report = reproduce_table1(300, 2, 0, {str(tmp_path)!r}, 'local', 'DI', progress,"
        " trial=slow_trial)\n"
        "print(json.dumps(report), flush=True)\n"
    )
    process = subprocess.Popen(
        [sys.executable, "-c", script],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        text=True,
        start_new_session=True,  # its own process group, as a terminal's foreground job
    )
    assert process.stdout is not None
    started = time.perf_counter()
    for line in process.stdout:
        if line.strip() == "2":
            break
    sent = time.perf_counter() - started
    os.killpg(process.pid, signal.SIGINT)  # Ctrl-C reaches the campaign and its workers
    out, _ = process.communicate(timeout=300)
    assert process.returncode == 0
    report = json.loads(out.strip().splitlines()[-1])
    assert report["interrupted"], (f"Ctrl-C sent {sent:.1f} s after the start", report)
    assert 2 <= report["finished"] < report["planned"] == 600, report
    assert len(rows(tmp_path / "table1_trials.csv")) == report["finished"]


def test_resume_reruns_trials_the_infrastructure_failed(tmp_path: Path) -> None:
    from tautwire.experiments.campaign import failed_trial

    def flaky(spec: TrialSpec) -> TrialResult:
        cause = {1: "crashed", 2: "hung", 3: "error"}.get(spec.index)
        if cause is not None:
            return failed_trial(spec, cause, "the worker process died")
        return fake_trials.quick_trial(spec)  # index 5 fails with a timeout: an outcome

    first = reproduce_table1(6, 1, 0, tmp_path, "serial", "D", trial=flaky)
    assert first["primitives"][0]["causes"] == {"crashed": 1, "hung": 1, "error": 1, "timeout": 1}

    ran: list[int] = []

    def counting(spec: TrialSpec) -> TrialResult:
        ran.append(spec.index)
        return fake_trials.quick_trial(spec)

    resumed = reproduce_table1(6, 1, 0, tmp_path, "serial", "D", resume=True, trial=counting)
    assert ran == [1, 2, 3]  # the timeout of trial 5 is the trial's own outcome: kept
    assert resumed["resumed"] == 3
    assert resumed["primitives"][0]["causes"] == {"timeout": 2}
    csv_causes = [r["cause"] for r in rows(tmp_path / "table1_trials.csv")]
    assert csv_causes == ["", "", "timeout", "", "", "timeout"]
