from __future__ import annotations

import yaml

from tautwire.scenario.source_map import SourceMap, find_duplicate_key

TEXT = """\
a: 1
b:
  c: [1, 2]
  d:
    - {e: 1}
    - e: 2
      f: 3
g: {h: 4}
"""


def source_map() -> SourceMap:
    return SourceMap(yaml.compose(TEXT, Loader=yaml.SafeLoader))


def test_keys_are_located_at_their_own_line() -> None:
    m = source_map()
    assert m.locate(("a",)) == (1, "a")
    assert m.locate(("b", "c")) == (3, "b.c")
    assert m.locate(("b", "d", 1, "f")) == (7, "b.d[1].f")
    assert m.locate(("b", "d", 0, "e")) == (5, "b.d[0].e")


def test_missing_key_is_located_at_its_parent() -> None:
    assert source_map().locate(("b", "d", 1, "zz")) == (6, "b.d[1].zz")


def test_parts_not_in_the_document_are_skipped_unless_last() -> None:
    assert source_map().locate(("b", "d", 1, "tag", "f")) == (7, "b.d[1].f")


def test_index_into_a_single_mapping_is_dropped() -> None:
    assert source_map().locate(("g", 0, "h")) == (8, "g.h")


def test_empty_document() -> None:
    assert SourceMap(None).locate(("a", 0)) == (None, "a[0]")


def test_duplicate_key_is_found_with_its_path() -> None:
    root = yaml.compose("a:\n  - {b: 1, c: 2, b: 3}\n", Loader=yaml.SafeLoader)
    found = find_duplicate_key(root)
    assert found is not None
    node, path = found
    assert (node.start_mark.line + 1, path) == (2, "a[0].b")
    assert find_duplicate_key(yaml.compose(TEXT, Loader=yaml.SafeLoader)) is None
