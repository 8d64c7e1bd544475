"""Line numbers of the values in a YAML document, from its composed node tree."""

from __future__ import annotations

import yaml

from tautwire.scenario.issue import Location


class SourceMap:
    """Finds the line and the readable field name of a location in a document.

    Args:
        root: the document's root node (``None`` for an empty document).
    """

    def __init__(self, root: yaml.Node | None) -> None:
        self._root = root

    def locate(self, location: Location) -> tuple[int | None, str]:
        """Return the 1-based line and the dotted field name of ``location``.

        Walks the node tree as far as the document goes: a missing key is
        reported at its parent's line. Location parts that are not in the
        document (a pydantic union tag, the ``params`` level of a flat task
        step) are dropped from the name unless they are the last part. A
        list index into a single mapping (``held_by: {arm: left, at: 0.4}``)
        is dropped too.

        Args:
            location: keys and list indices from the document's top level.
        """
        node = self._root
        line = None if node is None else node.start_mark.line + 1
        name = ""
        for n, part in enumerate(location):
            last = n == len(location) - 1
            if isinstance(part, int):
                if isinstance(node, yaml.SequenceNode) and 0 <= part < len(node.value):
                    node = node.value[part]
                    line = node.start_mark.line + 1
                    name += f"[{part}]"
                elif not (isinstance(node, yaml.MappingNode) and part == 0):
                    node = None
                    name += f"[{part}]"
                continue
            value = _lookup(node, part) if isinstance(node, yaml.MappingNode) else None
            if value is not None:
                key, node = value
                line = key.start_mark.line + 1
            elif last or not isinstance(node, yaml.MappingNode):
                node = None
            else:
                continue
            name += f".{part}" if name else part
        return line, name


def _lookup(node: yaml.MappingNode, key: str) -> tuple[yaml.Node, yaml.Node] | None:
    """The key node and value node of ``key`` in a mapping, or ``None``."""
    for key_node, value_node in node.value:
        if isinstance(key_node, yaml.ScalarNode) and key_node.value == key:
            return key_node, value_node
    return None


def find_duplicate_key(node: yaml.Node | None) -> tuple[yaml.Node, str] | None:
    """The first key that repeats within one mapping, anywhere in the tree.

    YAML loaders keep the last of two equal keys silently; a scenario must
    not say two things about one field.

    Returns:
        The repeated key's node and its path for messages, or ``None``.
    """
    return _duplicate(node, "", set())


def _duplicate(node: yaml.Node | None, path: str, seen: set[int]) -> tuple[yaml.Node, str] | None:
    """Depth-first search for a repeated key (aliases visited once)."""
    if node is None or id(node) in seen:
        return None
    seen.add(id(node))
    if isinstance(node, yaml.MappingNode):
        keys: set[str] = set()
        for key_node, value_node in node.value:
            key = str(key_node.value)
            here = f"{path}.{key}" if path else key
            if key in keys:
                return key_node, here
            keys.add(key)
            found = _duplicate(value_node, here, seen)
            if found is not None:
                return found
    elif isinstance(node, yaml.SequenceNode):
        for i, item in enumerate(node.value):
            found = _duplicate(item, f"{path}[{i}]", seen)
            if found is not None:
                return found
    return None
