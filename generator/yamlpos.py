"""Load YAML into plain Python values while remembering where every value came from.

`load(path)` returns (data, locate) where `locate(path_tuple)` gives the Location of the node at
that path (a tuple of dict keys and list indexes), falling back to the nearest parent.
"""

from __future__ import annotations

from typing import Any, Callable

import yaml

from .diagnostics import Location, SpecError

Path = tuple

# libyaml's parser (C) when PyYAML was built with it: the same nodes and marks, about 5x faster
# on the spec and vectors; the pure-Python parser otherwise.
_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
# One constructor for every scalar (its construct_object keeps no state between plain scalars).
_SCALARS = yaml.constructor.SafeConstructor()

# Limits for files from outside (overlays, vendor updates): a spec or vector file nests a few
# levels and holds a few thousand values (the largest of the project: 2,524), so these are far
# above any real file and far below what would exhaust the stack or the memory. Aliases are
# allowed (spec/mscip shares notes with them), but every value they expand to counts.
MAX_DEPTH = 64
MAX_VALUES = 200_000
# The largest file of the project is 72 kB (tests/vectors/mip/filter_20_64.yaml).
MAX_BYTES = 4 << 20


class _Budget:
    def __init__(self) -> None:
        self.values = 0


def _construct(node: yaml.Node, path: Path, file: str, marks: dict, budget: _Budget) -> Any:
    loc = Location(file, node.start_mark.line + 1, node.start_mark.column + 1)
    if len(path) > MAX_DEPTH:
        raise SpecError(loc, f"values nested deeper than {MAX_DEPTH} levels", f"at most {MAX_DEPTH} levels")
    budget.values += 1
    if budget.values > MAX_VALUES:
        raise SpecError(
            loc,
            f"the file expands to more than {MAX_VALUES} values (aliases of aliases?)",
            f"at most {MAX_VALUES} values after expanding aliases",
        )
    marks[path] = loc
    if isinstance(node, yaml.MappingNode):
        out: dict = {}
        for key_node, value_node in node.value:
            if not isinstance(key_node, yaml.ScalarNode):
                raise SpecError(marks[path], "mapping keys must be plain scalars")
            key = key_node.value if key_node.tag == "tag:yaml.org,2002:str" else _scalar(key_node, file)
            if key in out:
                loc = Location(file, key_node.start_mark.line + 1, key_node.start_mark.column + 1)
                raise SpecError(loc, f"duplicate key '{key}'", "each key once per mapping")
            marks[path + (("key", key),)] = Location(file, key_node.start_mark.line + 1, key_node.start_mark.column + 1)
            out[key] = _construct(value_node, path + (key,), file, marks, budget)
        return out
    if isinstance(node, yaml.SequenceNode):
        return [_construct(v, path + (i,), file, marks, budget) for i, v in enumerate(node.value)]
    return _scalar(node, file)


def _check_expansion(root: yaml.Node, file: str) -> None:
    """Refuses a file whose aliases expand to more than MAX_VALUES values before building any of
    them: each distinct node's expanded size is counted once (an alias bomb costs a moment, not the
    seconds of constructing 200,000 values), and the error points where construction would stop."""
    sizes: dict[int, int] = {}
    open_nodes: set[int] = set()

    def size(node: yaml.Node, depth: int) -> int:
        key = id(node)
        if key in sizes:
            return sizes[key]
        if depth > MAX_DEPTH or not isinstance(node, (yaml.MappingNode, yaml.SequenceNode)):
            return 1  # too deep: _construct reports it
        if key in open_nodes:  # an alias inside its own anchor: _construct reports the depth
            return 1
        open_nodes.add(key)
        children = [v for _k, v in node.value] if isinstance(node, yaml.MappingNode) else node.value
        n = 1
        for child in children:
            n += size(child, depth + 1)
            if n > MAX_VALUES:
                break
        open_nodes.discard(key)
        sizes[key] = n
        return n

    if size(root, 0) <= MAX_VALUES:
        return
    # Walk to the value at which construction would pass the limit.
    node, left = root, MAX_VALUES - 1
    while isinstance(node, (yaml.MappingNode, yaml.SequenceNode)):
        children = [v for _k, v in node.value] if isinstance(node, yaml.MappingNode) else node.value
        for child in children:
            n = sizes.get(id(child), 1)
            if n > left:
                node, left = child, left - 1
                break
            left -= n
        else:
            break
    loc = Location(file, node.start_mark.line + 1, node.start_mark.column + 1)
    raise SpecError(
        loc,
        f"the file expands to more than {MAX_VALUES} values (aliases of aliases?)",
        f"at most {MAX_VALUES} values after expanding aliases",
    )


def _scalar(node: yaml.Node, file: str):
    """A scalar as the safe loader resolves it: ints (incl. 0x..), floats, bools, null, strings."""
    try:
        return _SCALARS.construct_object(node, deep=True)
    except yaml.YAMLError as exc:
        loc = Location(file, node.start_mark.line + 1, node.start_mark.column + 1)
        raise SpecError(loc, f"invalid YAML value: {getattr(exc, 'problem', None) or exc}") from None


def load(file_path: str, display_name: str | None = None) -> tuple[Any, Callable[[Path], Location]]:
    name = display_name or file_path
    try:
        with open(file_path, "rb") as fh:
            raw = fh.read(MAX_BYTES + 1)
    except OSError as exc:
        raise SpecError(Location(name, 1, 1), f"cannot read file: {exc.strerror}") from None
    if len(raw) > MAX_BYTES:
        raise SpecError(
            Location(name, 1, 1), f"the file is larger than {MAX_BYTES} bytes", f"at most {MAX_BYTES} bytes"
        )
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        before = raw[: exc.start]
        line = before.count(b"\n") + 1
        column = len(before) - (before.rfind(b"\n") + 1) + 1
        raise SpecError(
            Location(name, line, column), f"the file is not UTF-8 (byte 0x{raw[exc.start]:02X})", "UTF-8 text"
        ) from None
    try:
        node = yaml.compose(text, Loader=_LOADER)
    except yaml.reader.ReaderError as exc:  # a character YAML does not allow (NUL, other controls)
        before = text[: exc.position]
        line = before.count("\n") + 1
        column = len(before) - (before.rfind("\n") + 1) + 1
        raise SpecError(
            Location(name, line, column),
            f"invalid YAML: character U+{ord(text[exc.position]):04X} is not allowed ({exc.reason})",
            "printable text (tabs and newlines allowed)",
        ) from None
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        loc = Location(name, mark.line + 1, mark.column + 1) if mark else Location(name, 1, 1)
        raise SpecError(loc, f"invalid YAML: {exc.problem or exc.context}") from None
    except yaml.YAMLError as exc:  # pragma: no cover - defensive
        raise SpecError(Location(name, 1, 1), f"invalid YAML: {exc}") from None
    except RecursionError:  # the pure-Python composer on absurd nesting
        raise SpecError(Location(name, 1, 1), "values nested too deeply", f"at most {MAX_DEPTH} levels") from None
    marks: dict = {}
    if node is None:
        raise SpecError(Location(name, 1, 1), "empty file", "a YAML mapping")
    _check_expansion(node, name)
    data = _construct(node, (), name, marks, _Budget())

    def locate(path: Path) -> Location:
        p = tuple(path)
        while p not in marks and p:
            p = p[:-1]
        return marks.get(p, Location(name, 1, 1))

    return data, locate
