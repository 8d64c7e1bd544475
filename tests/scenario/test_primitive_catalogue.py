from __future__ import annotations

import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.scenario.primitive_catalogue import PRIMITIVES, ParameterError, find_primitive

# SCENARIO.md's table: name, letter, required parameters.
TABLE = [
    ("parallel_tension", "A", ["force"]),
    ("parallel_sliding", "B", ["slide_arm", "distance", "friction_force"]),
    ("parallel_clipping", "C", ["clip"]),
    ("single_arm_tension", "D", ["arm", "force"]),
    ("single_arm_sliding", "E", ["arm", "distance", "friction_force"]),
    ("single_arm_clipping", "F", ["arm", "clip"]),
    ("gripper_alignment", "G", ["arm"]),
    ("grasp_tensioned", "H", ["arm", "at"]),
    ("rotate_around_feature_point", "I", ["arm", "angle"]),
]


def test_catalogue_matches_the_table() -> None:
    rows = [(p.name, p.letter, [q.name for q in p.required]) for p in PRIMITIVES]
    assert rows == TABLE


def test_only_rotation_has_optional_parameters() -> None:
    optional = {p.letter: [q.name for q in p.optional] for p in PRIMITIVES if p.optional}
    assert optional == {"I": ["axis", "speed", "about"]}


@pytest.mark.parametrize(("name", "letter", "_"), TABLE)
def test_found_by_name_and_by_letter(name: str, letter: str, _: list[str]) -> None:
    assert find_primitive(name) is find_primitive(letter)
    assert find_primitive(letter).name == name


def test_unknown_primitive_lists_the_choices() -> None:
    with pytest.raises(InvalidArgumentError, match=r"parallel_tension \(A\).*\(I\)"):
        find_primitive("d")


def test_parameters_in_canonical_form_with_defaults() -> None:
    spec = find_primitive("I")
    params = spec.check_params({"arm": "right", "angle": 3, "axis": [0, 0, 2], "speed": 0.5})
    assert params == {"arm": "right", "angle": 3.0, "axis": [0.0, 0.0, 1.0], "speed": 0.5}
    assert isinstance(params["angle"], float)


@pytest.mark.parametrize(
    ("values", "parameter"),
    [
        ({"arm": "left"}, "force"),
        ({"arm": "left", "force": 1.0, "grip": 2.0}, "grip"),
        ({"arm": "left", "force": 0.0}, "force"),
        ({"arm": "left", "force": True}, "force"),
        ({"arm": "left", "force": [1.0]}, "force"),
        ({"arm": "both", "force": 1.0}, "arm"),
        ({"arm": 1, "force": 1.0}, "arm"),
    ],
)
def test_bad_parameters_name_the_parameter(values: dict[str, object], parameter: str) -> None:
    with pytest.raises(ParameterError) as info:
        find_primitive("D").check_params(values)
    assert info.value.parameter == parameter


def test_rotation_angle_must_not_be_zero_but_may_be_negative() -> None:
    spec = find_primitive("I")
    assert spec.check_params({"arm": "left", "angle": -6.28})["angle"] == -6.28
    with pytest.raises(ParameterError, match="non-zero"):
        spec.check_params({"arm": "left", "angle": 0})


def test_grasp_arc_length_may_be_zero() -> None:
    assert find_primitive("H").check_params({"arm": "left", "at": 0})["at"] == 0.0
    with pytest.raises(ParameterError):
        find_primitive("H").check_params({"arm": "left", "at": -0.1})
