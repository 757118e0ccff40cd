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


def _construct(node: yaml.Node, path: Path, file: str, marks: dict) -> Any:
    marks[path] = Location(file, node.start_mark.line + 1, node.start_mark.column + 1)
    if isinstance(node, yaml.MappingNode):
        out: dict = {}
        for key_node, value_node in node.value:
            if not isinstance(key_node, yaml.ScalarNode):
                raise SpecError(marks[path], "mapping keys must be plain scalars")
            key = (
                yaml.safe_load(yaml.serialize(key_node)) if key_node.tag != "tag:yaml.org,2002:str" else key_node.value
            )
            if key in out:
                loc = Location(file, key_node.start_mark.line + 1, key_node.start_mark.column + 1)
                raise SpecError(loc, f"duplicate key '{key}'", "each key once per mapping")
            marks[path + (("key", key),)] = Location(file, key_node.start_mark.line + 1, key_node.start_mark.column + 1)
            out[key] = _construct(value_node, path + (key,), file, marks)
        return out
    if isinstance(node, yaml.SequenceNode):
        return [_construct(v, path + (i,), file, marks) for i, v in enumerate(node.value)]
    return _scalar(node, file)


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
        with open(file_path, encoding="utf-8") as fh:
            text = fh.read()
    except OSError as exc:
        raise SpecError(Location(name, 1, 1), f"cannot read file: {exc.strerror}") from None
    try:
        node = yaml.compose(text, Loader=_LOADER)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        loc = Location(name, mark.line + 1, mark.column + 1) if mark else Location(name, 1, 1)
        raise SpecError(loc, f"invalid YAML: {exc.problem or exc.context}") from None
    except yaml.YAMLError as exc:  # pragma: no cover - defensive
        raise SpecError(Location(name, 1, 1), f"invalid YAML: {exc}") from None
    marks: dict = {}
    if node is None:
        raise SpecError(Location(name, 1, 1), "empty file", "a YAML mapping")
    data = _construct(node, (), name, marks)

    def locate(path: Path) -> Location:
        p = tuple(path)
        while p not in marks and p:
            p = p[:-1]
        return marks.get(p, Location(name, 1, 1))

    return data, locate
