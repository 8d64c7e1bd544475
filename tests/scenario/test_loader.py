from __future__ import annotations

from pathlib import Path

import pytest

from tautwire.errors import InputFileError
from tautwire.scenario import (
    Anchor,
    Clip,
    Peg,
    ScenarioError,
    load_scenario,
    parse_scenario,
    scenario_from_data,
)
from tests.scenario.cases import EXAMPLE, SCENARIOS, edit, error_of, line_of


def test_example_of_scenario_md_loads_with_every_field() -> None:
    s = load_scenario(SCENARIOS / "peg-and-clip.yaml")
    assert (s.version, s.name, s.seed) == (1, "peg-and-clip", 3)
    assert s.robot.control_period == 0.004
    assert s.robot.force_limit == 15.0
    assert s.robot.sensor.arm == "left"
    assert (s.robot.sensor.noise_force, s.robot.sensor.noise_torque) == (0.05, 0.002)
    assert s.robot.grippers.left.position == (0.35, 0.15, 0.12)
    assert s.robot.grippers.left.orientation == (1.0, 0.0, 0.0, 0.0)
    assert s.robot.grippers.right.position == (0.35, -0.25, 0.12)
    a1, p1, c1 = s.board.fixtures
    assert isinstance(a1, Anchor) and a1.position == (0.0, 0.0, 0.12)
    assert isinstance(p1, Peg) and (p1.radius, p1.height) == (0.006, 0.05)
    assert isinstance(c1, Clip) and (c1.yaw, c1.push_force) == (0.0, 2.5)
    (w1,) = s.cables
    assert (w1.name, w1.length, w1.mass_per_length, w1.stiffness, w1.radius) == (
        "W1",
        0.42,
        0.030,
        200.0,
        0.0025,
    )
    assert (w1.start, w1.via) == ("A1", ["P1"])
    assert [(h.arm, h.at) for h in w1.held_by] == [("left", 0.42)]
    assert [(t.primitive, t.letter) for t in s.task] == [
        ("single_arm_tension", "D"),
        ("rotate_around_feature_point", "I"),
    ]
    assert s.task[0].params == {"arm": "left", "force": 3.0}
    assert s.task[1].params == {"arm": "left", "angle": 3.14, "axis": [0.0, 0.0, 1.0]}


@pytest.mark.parametrize("path", sorted(SCENARIOS.glob("*.yaml")), ids=lambda p: p.name)
def test_every_example_scenario_is_valid(path: Path) -> None:
    scenario = load_scenario(path)
    assert scenario.task, "an example should do something"


def test_letter_and_name_give_the_same_step() -> None:
    by_name = parse_scenario(EXAMPLE)
    by_letter = parse_scenario(
        edit("{primitive: single_arm_tension,", "{primitive: D,"),
    )
    assert by_letter == by_name


def test_unknown_top_level_key() -> None:
    text = edit("seed: 3", "seed: 3\ncolour: red")
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, "colour"), "colour")
    assert "unknown key" in err.message and "robot" in err.message


def test_unknown_nested_key() -> None:
    text = edit("    radius: 0.0025", "    radius: 0.0025\n    colour: red")
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, "colour"), "cables[0].colour")
    assert "stiffness" in err.message  # the valid keys are listed


def test_unknown_key_in_flow_mapping_of_a_fixture() -> None:
    text = edit("radius: 0.006, height", "radius: 0.006, colour: red, height")
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, "colour"), "board.fixtures[1].colour")


def test_wrong_type_names_field_line_and_unit() -> None:
    text = edit("stiffness: 200.0", "stiffness: stiff")
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, "stiffness"), "cables[0].stiffness")
    assert str(err) == (
        f"s.yaml:{err.line}: cables[0].stiffness: got 'stiff' (expected a number [N/m])"
    )


def test_quoted_number_is_rejected() -> None:
    err = error_of(edit("length: 0.42 ", "length: '0.42' "))
    assert err.field == "cables[0].length"


def test_out_of_range_value() -> None:
    err = error_of(edit("noise_force: 0.05", "noise_force: -0.05"))
    assert err.field == "robot.sensor.noise_force"
    assert "greater than or equal to 0" in err.message and "[N]" in err.message


def test_missing_field_is_reported_at_its_parent() -> None:
    text = edit("    mass_per_length: 0.030         # kg/m\n", "")
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, "  - name: W1"), "cables[0].mass_per_length")
    assert err.message.startswith("missing") and "[kg/m]" in err.message


def test_missing_top_level_section() -> None:
    text = edit("version: 1\n", "")
    err = error_of(text)
    assert (err.line, err.field) == (1, "version")


def test_bad_fixture_type_lists_the_types() -> None:
    text = edit("type: peg,", "type: post,")
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, "name: P1"), "board.fixtures[1].type")
    assert "'anchor', 'peg', 'clip'" in err.message


def test_position_with_two_numbers() -> None:
    text = edit("{position: [0.35, 0.15, 0.12]}", "{position: [0.35, 0.15]}")
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, "left:"), "robot.grippers.left.position")
    assert "exactly 3" in err.message


def test_bad_primitive_lists_names_and_letters() -> None:
    text = edit("{primitive: single_arm_tension,", "{primitive: tug,")
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, "tug"), "task[0].primitive")
    assert "single_arm_tension (D)" in err.message
    assert "rotate_around_feature_point (I)" in err.message


@pytest.mark.parametrize(
    ("step", "field", "words"),
    [
        ("{primitive: D, arm: left}", "task[0].force", "missing parameter"),
        ("{primitive: D, arm: left, force: 3.0, speed: 1}", "task[0].speed", "unknown parameter"),
        ("{primitive: D, arm: left, force: strong}", "task[0].force", "got 'strong'"),
        ("{primitive: D, arm: left, force: -1}", "task[0].force", "> 0"),
        ("{primitive: D, arm: middle, force: 3.0}", "task[0].arm", "'left' or 'right'"),
        ("{primitive: I, arm: left, angle: 1, axis: [0, 0]}", "task[0].axis", "3 numbers"),
        ("{primitive: F, arm: left, clip: P1}", "task[0].clip", "is a peg"),
        ("{primitive: C, clip: C9}", "task[0].clip", "is unknown"),
        ("{primitive: I, arm: left, angle: 1, about: Z9}", "task[0].about", "is unknown"),
        ("{primitive: H, arm: right, at: 0.9}", "task[0].at", "beyond the end"),
        ("{arm: left, force: 3.0}", "task[0].primitive", "missing"),
        ("D", "task[0]", "expected a mapping"),
    ],
)
def test_bad_step_parameter(step: str, field: str, words: str) -> None:
    text = edit("{primitive: single_arm_tension, arm: left, force: 3.0}", step)
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, step), field)
    assert words in err.message


def test_geometry_error_names_the_field() -> None:
    text = edit("length: 0.42 ", "length: 0.35 ")
    text = edit("at: 0.42}", "at: 0.35}", text)
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, "length:"), "cables[0].length")
    assert "A1 -> P1 -> left gripper" in err.message


def test_repeated_key_is_an_error() -> None:
    text = edit("seed: 3", "seed: 3\nseed: 4")
    err = error_of(text)
    assert (err.line, err.field) == (line_of(text, "seed: 4"), "seed")


def test_yaml_syntax_error_has_its_line() -> None:
    text = edit("    - {name: A1,", "    - {name: A1,,")
    err = error_of(text)
    assert err.line == line_of(text, "A1,,")
    assert "invalid YAML" in err.message


def test_error_message_is_one_line() -> None:
    err = error_of(edit("{primitive: single_arm_tension,", "{primitive: tug,"))
    assert "\n" not in str(err)
    assert str(err).startswith(f"s.yaml:{err.line}: task[0].primitive: ")


@pytest.mark.parametrize(
    ("text", "words"),
    [("", "empty"), ("# nothing\n", "empty"), ("- 1\n", "not a mapping")],
)
def test_documents_that_are_not_scenarios(text: str, words: str) -> None:
    assert words in error_of(text).message


def test_missing_file(tmp_path: Path) -> None:
    path = tmp_path / "absent.yaml"
    with pytest.raises(InputFileError) as info:
        load_scenario(path)
    assert str(info.value) == f"{path}: no such file (expected a scenario YAML file)"


def test_load_reports_the_file_name(tmp_path: Path) -> None:
    path = tmp_path / "bad.yaml"
    path.write_text(edit("stiffness: 200.0", "stiffness: -1"), encoding="utf-8")
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert str(info.value).startswith(f"{path}:{line_of(path.read_text(), 'stiffness')}: ")


def test_scenario_from_data_reports_field_without_line() -> None:
    import yaml

    data = yaml.safe_load(edit("force_limit: 15.0", "force_limit: 0"))
    with pytest.raises(ScenarioError) as info:
        scenario_from_data(data)
    assert (info.value.line, info.value.field) == (None, "robot.force_limit")


def test_every_problem_of_a_file_is_listed_in_file_order() -> None:
    text = edit("seed: 3", "seed: three")
    text = edit("  force_limit: 15.0", "  force_limt: 15.0", text)
    text = edit("radius: 0.006, height: 0.05", "radius: 0.006, hieght: 0.05", text)
    err = error_of(text)
    found = [(p.line, p.field) for p in err.problems]
    assert found == [
        (line_of(text, "seed:"), "seed"),
        (line_of(text, "force_limt"), "robot.force_limt"),
        (line_of(text, "hieght"), "board.fixtures[1].height"),
        (line_of(text, "hieght"), "board.fixtures[1].hieght"),
    ]
    assert str(err).count("\n") == len(found) - 1
    assert "did you mean 'force_limit'?" in err.problems[1].message
    assert "did you mean 'height'?" in err.problems[3].message


def test_every_reference_problem_is_listed() -> None:
    text = edit("start: A1", "start: A9")
    text = edit("via: [P1]", "via: [P7]", text)
    fields = [p.field for p in error_of(text).problems]
    assert fields == ["cables[0].start", "cables[0].via[0]"]


def test_a_misspelt_fixture_type_gets_a_suggestion() -> None:
    err = error_of(edit("type: anchor", "type: anchr"))
    assert "did you mean 'anchor'?" in err.message


@pytest.mark.parametrize("number", ["2e2", "2.0e2", "2.0E+2", "200.0"])
def test_numbers_with_an_exponent_are_numbers(number: str) -> None:
    s = parse_scenario(edit("stiffness: 200.0", f"stiffness: {number}"))
    assert s.cables[0].stiffness == 200.0


def test_a_file_over_one_megabyte_is_refused_before_it_is_read(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from tautwire.scenario.bounded_yaml import MAX_BYTES

    path = tmp_path / "big.yaml"
    with path.open("wb") as fh:
        fh.truncate(20 * MAX_BYTES)  # sparse: 20 MB that cost no disk

    def no_reading(*args: object, **kwargs: object) -> None:
        raise AssertionError("the file was opened")

    monkeypatch.setattr(Path, "open", no_reading)
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert str(info.value) == (
        f"{path}: 20,000,000 bytes is larger than 1,000,000 (expected a scenario of a few kB)"
    )


def test_a_nul_byte_is_one_line_with_line_and_column(tmp_path: Path) -> None:
    path = tmp_path / "nul.yaml"
    path.write_bytes(EXAMPLE.replace("name: peg-and-clip", "name: peg\0").encode())
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert str(info.value) == (
        f"{path}:{line_of(EXAMPLE, 'name:')}: control character U+0000 at column 10 "
        "(expected text without NUL or control bytes)"
    )


def test_a_byte_order_mark_is_accepted_and_bad_utf8_is_located(tmp_path: Path) -> None:
    path = tmp_path / "bom.yaml"
    path.write_bytes(b"\xef\xbb\xbf" + EXAMPLE.encode())
    assert load_scenario(path).name == "peg-and-clip"
    path.write_bytes(EXAMPLE.replace("free text", "caf\xe9").encode("latin-1"))
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert str(info.value).startswith(f"{path}:{line_of(EXAMPLE, 'free text')}: not UTF-8 text")


def test_an_alias_bomb_is_one_line() -> None:
    from tests.scenario.test_bounded_yaml import BILLION_LAUGHS

    err = error_of(BILLION_LAUGHS)
    assert "\n" not in str(err) and "through aliases" in err.message


def test_many_problems_are_capped() -> None:
    from tautwire.scenario.loader import MAX_LISTED

    steps = "".join("  - {primitive: tug}\n" for _ in range(MAX_LISTED + 5))
    text = EXAMPLE[: EXAMPLE.index("task:")] + "task:\n" + steps
    err = error_of(text)
    assert len(err.problems) == MAX_LISTED + 1
    assert err.problems[-1].message == "and 5 more problem(s) not listed"
