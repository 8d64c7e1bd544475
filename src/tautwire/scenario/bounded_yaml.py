"""Reading YAML text into a node tree, bounded in time and memory.

A scenario file is small and plain; YAML can be neither. Three things keep
reading any text, however hostile, to a second or so and a few megabytes:

- **Size**: text over :data:`MAX_BYTES` is refused before it is parsed (the
  loader refuses a larger file before reading it).
- **Aliases**: the composed node tree shares an aliased node rather than
  copying it, but everything after it (building Python values, validating
  them, printing them) walks the tree *expanded*, where nine nested lists of
  nine aliases (a 342-byte "billion laughs") hold 9^9 strings. The tree is
  measured as if expanded, without expanding it: more than
  :data:`MAX_ALIASES` alias uses, more than :data:`MAX_EXPANDED_NODES`
  nodes once expanded, nesting deeper than :data:`MAX_DEPTH`, or an alias
  inside its own anchor (a cycle) are refused.
- **Characters**: control characters (a NUL byte) are refused with the line
  and column, before the YAML reader sees them.

Numbers are read as YAML 1.2 writes them: PyYAML follows YAML 1.1, whose
float needs a dot and a signed exponent, so ``1e9`` and ``1.0e9`` would be
strings there; here they are floats (:class:`BoundedLoader`).
"""

from __future__ import annotations

import re
from typing import NamedTuple

import yaml

#: Largest scenario text [bytes] (1 MB); a real scenario is a few kB.
MAX_BYTES = 1_000_000
#: Most alias uses (``*name``) in one document.
MAX_ALIASES = 100
#: Most nodes of the document with every alias expanded.
MAX_EXPANDED_NODES = 200_000
#: Deepest nesting of mappings and lists.
MAX_DEPTH = 64

#: A float as YAML 1.2's core schema writes it (also ``1e9``, ``1.0e9``, ``.5``).
FLOAT_1_2 = re.compile(r"^[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?$")

#: What YAML's reader refuses: C0/C1 control characters except tab, LF, CR, NEL,
#: and the non-characters (as :class:`yaml.reader.Reader` defines printable).
_NOT_PRINTABLE = re.compile(
    "[^\x09\x0a\x0d\x20-\x7e\x85\xa0-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]"
)

_BASE: type[yaml.SafeLoader] = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


class BoundedLoader(_BASE):  # type: ignore[misc, valid-type]
    """PyYAML's safe loader (libyaml's where installed) with YAML 1.2 floats.

    The YAML 1.1 resolvers come first, so what they read keeps its meaning
    (``3`` an int, ``0.5`` a float); a plain scalar they leave a string but
    YAML 1.2 reads as a float (``1e9``, ``-2.5e-3``, ``1.0e9``) is a float.
    """


BoundedLoader.add_implicit_resolver("tag:yaml.org,2002:float", FLOAT_1_2, list("-+.0123456789"))


class YamlError(Exception):
    """The text cannot be read as a bounded YAML document.

    Attributes:
        line: 1-based line, or None when the problem is the whole text.
        column: 1-based column, or None.
        message: what is wrong (what is expected).
    """

    def __init__(self, line: int | None, column: int | None, message: str) -> None:
        self.line = line
        self.column = column
        self.message = message
        super().__init__(message)


class Document(NamedTuple):
    """A composed YAML document.

    Attributes:
        root: The root node (None for an empty document).
        data: The document as plain Python data (None when empty).
    """

    root: yaml.Node | None
    data: object


def compose_bounded(text: str) -> yaml.Node | None:
    """The node tree of the YAML ``text``, checked against every bound.

    Raises:
        YamlError: for text over :data:`MAX_BYTES`, a control character,
            invalid YAML, or a tree past the alias, size or depth bounds.
    """
    if len(text) > MAX_BYTES or len(text.encode("utf-8", "surrogatepass")) > MAX_BYTES:
        raise YamlError(
            None, None, f"larger than {MAX_BYTES:,} bytes (expected a scenario of a few kB)"
        )
    bad = _NOT_PRINTABLE.search(text)
    if bad is not None:
        line = text.count("\n", 0, bad.start()) + 1
        column = bad.start() - (text.rfind("\n", 0, bad.start()) + 1) + 1
        raise YamlError(
            line,
            column,
            f"control character U+{ord(bad.group()):04X} at column {column} "
            "(expected text without NUL or control bytes)",
        )
    loader = BoundedLoader(text)
    try:
        root: yaml.Node | None = loader.get_single_node()
    except yaml.MarkedYAMLError as exc:
        raise _marked(exc) from None
    except yaml.reader.ReaderError as exc:
        raise YamlError(None, None, f"invalid YAML: {exc.reason}") from None
    except yaml.YAMLError as exc:
        raise YamlError(None, None, f"invalid YAML: {' '.join(str(exc).split())}") from None
    except RecursionError:
        raise YamlError(
            None, None, f"nested too deeply (expected at most {MAX_DEPTH} levels)"
        ) from None
    finally:
        loader.dispose()
    check_bounds(root)
    return root


def construct(root: yaml.Node | None) -> object:
    """Plain Python data of a tree that :func:`compose_bounded` accepted."""
    if root is None:
        return None
    loader = BoundedLoader("")
    try:
        return loader.construct_document(root)
    except yaml.MarkedYAMLError as exc:
        raise _marked(exc) from None
    finally:
        loader.dispose()


def _marked(exc: yaml.MarkedYAMLError) -> YamlError:
    """A YAML error with a position as a :class:`YamlError` with line and column."""
    mark = exc.problem_mark or exc.context_mark
    problem = exc.problem or exc.context or "cannot parse"
    if exc.problem and exc.context:
        problem = f"{exc.problem} ({exc.context})"
    line = None if mark is None else mark.line + 1
    column = None if mark is None else mark.column + 1
    where = "" if column is None else f" at column {column}"
    return YamlError(line, column, f"invalid YAML{where}: {problem}")


def read_bounded(text: str) -> Document:
    """Compose and construct the YAML ``text`` within every bound.

    Raises:
        YamlError: as :func:`compose_bounded`.
    """
    root = compose_bounded(text)
    return Document(root, construct(root))


def check_bounds(root: yaml.Node | None) -> None:
    """Refuse a node tree whose expansion would be large, deep or infinite.

    Walks each distinct node once (iteratively: no recursion limit), and
    computes the size of the tree with every alias expanded, bottom up.

    Raises:
        YamlError: naming the line of the alias or node past a bound.
    """
    if root is None:
        return
    uses: dict[int, int] = {}
    size: dict[int, int] = {}
    aliases = 0
    on_path: set[int] = set()
    # (node, depth, whether its children are done, the line where it is used)
    stack: list[tuple[yaml.Node, int, bool, int]] = [(root, 1, False, _line(root))]
    while stack:
        node, depth, done, line = stack.pop()
        key = id(node)
        if done:
            on_path.discard(key)
            size[key] = 1 + sum(size[id(child)] for child, _ in _children(node))
            if size[key] > MAX_EXPANDED_NODES:
                raise YamlError(
                    line,
                    None,
                    f"the document expands to more than {MAX_EXPANDED_NODES:,} values "
                    "through aliases (expected a plain scenario)",
                )
            continue
        if key in on_path:
            raise YamlError(line, None, "an alias inside its own anchor (a recursive document)")
        uses[key] = uses.get(key, 0) + 1
        if uses[key] > 1:
            aliases += 1
            if aliases > MAX_ALIASES:
                raise YamlError(
                    line, None, f"more than {MAX_ALIASES} alias uses (expected a plain scenario)"
                )
            if key in size:
                continue
        if depth > MAX_DEPTH:
            raise YamlError(line, None, f"nested too deeply (expected at most {MAX_DEPTH} levels)")
        on_path.add(key)
        stack.append((node, depth, True, line))
        for child, used_at in reversed(_children(node)):
            stack.append((child, depth + 1, False, used_at))


def _children(node: yaml.Node) -> list[tuple[yaml.Node, int]]:
    """The nodes directly inside ``node``, each with the line where it is used.

    An alias has no position of its own in the tree (it is the anchored
    node): a mapping value is placed at its key's line, a list item that
    starts before its list (an alias of an earlier anchor) at the list's.
    """
    if isinstance(node, yaml.MappingNode):
        return [(part, _line(key)) for key, value in node.value for part in (key, value)]
    if isinstance(node, yaml.SequenceNode):
        here = _line(node)
        return [(item, max(_line(item), here)) for item in node.value]
    return []


def _line(node: yaml.Node) -> int:
    return int(node.start_mark.line) + 1
