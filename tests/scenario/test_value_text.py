from __future__ import annotations

from tautwire.scenario.value_text import show


def test_values_as_yaml_writes_them() -> None:
    assert [show(None), show(True), show("a"), show(2.5)] == ["null", "true", "'a'", "2.5"]
    assert len(show(list(range(100)))) == 60


def test_a_huge_value_is_not_rendered_whole() -> None:
    # 10^9 items once expanded: rendering it whole would never end
    level: list[object] = ["lol"] * 10
    for _ in range(8):
        level = [level] * 10
    text = show(level)
    assert len(text) == 60 and text.startswith("[[[[[[[[['lol', 'lol'") and text.endswith("...")


def test_mappings_long_strings_and_huge_integers() -> None:
    assert show({"a": 1, "b": [2.5, None]}) == "{'a': 1, 'b': [2.5, null]}"
    assert show("x" * 10_000) == repr("x" * 56)[:57] + "..."
    assert show(10**5000).startswith("<an integer of about 50")
    assert show(object()) == "<object>"
    assert len(show(list(range(100)), width=20)) == 20
