from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tautwire.scenario.bounded_yaml import (
    MAX_ALIASES,
    MAX_BYTES,
    MAX_DEPTH,
    YamlError,
    read_bounded,
)

#: Nine lists of nine aliases each (342 bytes): 9^9 strings once expanded.
BILLION_LAUGHS = "a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
    f"{b}: &{b} [{', '.join([f'*{a}'] * 9)}]\n" for a, b in zip("abcdefgh", "bcdefghi", strict=True)
)


def problem(text: str) -> YamlError:
    with pytest.raises(YamlError) as info:
        read_bounded(text)
    return info.value


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("1e9", 1e9),
        ("1.0e9", 1e9),
        ("-2.5E-3", -2.5e-3),
        ("+1E+3", 1e3),
        (".5", 0.5),
        ("2.5", 2.5),
        ("3", 3),
        ("'1e9'", "1e9"),
        ("1e", "1e"),
        ("e9", "e9"),
    ],
)
def test_numbers_are_read_as_yaml_1_2_writes_them(text: str, value: object) -> None:
    data = read_bounded(f"x: {text}\n").data
    assert data == {"x": value}
    assert type(data["x"]) is type(value)  # type: ignore[index]


@given(st.floats(allow_nan=False, allow_infinity=False))
def test_every_python_float_text_reads_back(x: float) -> None:
    assert read_bounded(f"x: {x!r}\n").data == {"x": x}


def test_numbers_elsewhere_keep_their_meaning() -> None:
    import yaml

    assert yaml.safe_load("x: 1e9") == {"x": "1e9"}  # the global loader is untouched
    assert read_bounded("x: [1, 2.0, true, null, abc]").data == {"x": [1, 2.0, True, None, "abc"]}


def test_an_alias_bomb_is_refused_without_expanding_it() -> None:
    assert len(BILLION_LAUGHS) < 400
    err = problem(BILLION_LAUGHS)
    assert "expands to more than" in err.message and err.line is not None


def test_a_few_aliases_are_fine_and_too_many_are_not() -> None:
    ok = "a: &a {b: 1}\n" + "".join(f"k{i}: *a\n" for i in range(MAX_ALIASES))
    assert read_bounded(ok).data["k0"] == {"b": 1}  # type: ignore[index]
    many = ok + "last: *a\n"
    err = problem(many)
    assert f"more than {MAX_ALIASES} alias uses" in err.message
    assert err.line == many.count("\n")


def test_a_recursive_alias_is_refused() -> None:
    assert "its own anchor" in problem("a: &a [1, *a]\n").message


def test_deep_nesting_is_refused() -> None:
    assert (
        "nested too deeply"
        in problem("x: " + "[" * (MAX_DEPTH + 1) + "]" * (MAX_DEPTH + 1)).message
    )
    assert "nest" in problem("[" * 100_000 + "]" * 100_000).message


def test_text_over_the_size_bound_is_refused() -> None:
    assert "larger than" in problem("#" * (MAX_BYTES + 1)).message
    assert "larger than" in problem("# " + "é" * (MAX_BYTES // 2)).message  # bytes, not characters


@pytest.mark.parametrize("char", ["\x00", "\x07", "\x1b", "\ufffe"])
def test_a_control_character_is_named_with_line_and_column(char: str) -> None:
    err = problem(f"a: 1\nname: ab{char}c\n")
    assert (err.line, err.column) == (2, 9)
    assert f"U+{ord(char):04X}" in err.message


def test_syntax_errors_have_line_and_column() -> None:
    err = problem("a: [1,\nb: 2\n")
    assert (err.line, err.column) == (3, 1)  # the end of the text, where the list is unclosed
    assert err.message.startswith("invalid YAML at column 1: ")
