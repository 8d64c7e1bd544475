from __future__ import annotations

from tautwire.errors import InputFileError, TautwireError
from tautwire.scenario import ScenarioError


def test_message_shape() -> None:
    err = ScenarioError("f.yaml", 12, "cables[0].stiffness", "got -1 (expected > 0)")
    assert isinstance(err, InputFileError) and isinstance(err, TautwireError)
    assert str(err) == "f.yaml:12: cables[0].stiffness: got -1 (expected > 0)"
    assert (err.path, err.line, err.field) == ("f.yaml", 12, "cables[0].stiffness")


def test_line_and_field_may_be_unknown_and_text_stays_one_line() -> None:
    assert str(ScenarioError("f.yaml", None, "", "empty")) == "f.yaml: empty"
    assert str(ScenarioError("f.yaml", 3, "x", "two\nlines")) == "f.yaml:3: x: two lines"


def test_several_problems_one_line_each() -> None:
    more = [ScenarioError("f.yaml", 20, "task[0]", "bad"), ScenarioError("f.yaml", None, "", "x")]
    err = ScenarioError("f.yaml", 3, "seed", "got 'a' (expected an integer)", more)
    assert str(err).splitlines() == [
        "f.yaml:3: seed: got 'a' (expected an integer)",
        "f.yaml:20: task[0]: bad",
        "f.yaml: x",
    ]
    assert [p.line for p in err.problems] == [3, 20, None]
    assert (err.line, err.field) == (3, "seed")
