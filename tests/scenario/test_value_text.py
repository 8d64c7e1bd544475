from __future__ import annotations

from tautwire.scenario.value_text import show


def test_values_as_yaml_writes_them() -> None:
    assert [show(None), show(True), show("a"), show(2.5)] == ["null", "true", "'a'", "2.5"]
    assert len(show(list(range(100)))) == 60
