"""Pass: how deep and how long a value path can get, so a runtime can size its error path
buffers and its JSON nesting limit from ir.json alone.

A value path names one value inside a field's data: a parameter name, then for an array an
index, then for a struct (or the struct a union selects) a member name, and so on, written
`name[index].member` (docs/conformance.md section 3). A layout with a function selector has the path
`function`. Over every layout (set fields and reserved fields) and every struct type:

- `depth`: the most steps in a path, a name or an index being one step each (at least 1);
- `names`: the most names in a path, indexes not counted (at least 1);
- `length`: the most characters in a path's text, an index counted with the digits of the
  array's element count (for a counted array: its capacity + 1), so it is an upper bound.
"""

from __future__ import annotations

from .context import Context


def run(ctx: Context) -> None:
    ctx.value_paths = measure(ctx.types, _layouts(ctx))


def _layouts(ctx: Context) -> list[dict]:
    out = [v for f in ctx.reserved for v in f["variants"]]
    out += [v for s in ctx.sets for f in s["fields"] for v in f["variants"]]
    return out


def measure(types: dict[str, dict], layouts: list[dict]) -> dict:
    """`depth`, `names` and `length` (see above) of the layouts and of the struct types."""
    roots = [(v["params"], v["functions"] is not None) for v in layouts]
    roots += [(t["params"], False) for t in types.values() if t["kind"] == "struct"]
    paths = _Paths(types)
    return {
        "depth": max([1] + [paths.depth(q) for params, _ in roots for q in params]),
        "names": max([1] + [paths.names(q) for params, _ in roots for q in params]),
        "length": max(
            [len("function") for _, selector in roots if selector]
            + [paths.length(q) for params, _ in roots for q in params]
            + [0]
        ),
    }


class _Paths:
    """Per parameter: the deepest path below it and the longest path text from it."""

    def __init__(self, types: dict[str, dict]):
        self.types = types

    def _inner(self, tref: dict) -> list[list[dict]]:
        """The parameter lists a value of this type reference contains (a union: each member's)."""
        t = self.types.get(tref.get("name", ""))
        if t is None:
            return []
        if tref["kind"] == "struct":
            return [t["params"]]
        if tref["kind"] == "union":
            return [self.types[m["type"]]["params"] for m in t["members"] if m["type"]]
        return []

    def depth(self, q: dict) -> int:
        inner = [self.depth(p) for params in self._inner(q["type"]) for p in params]
        return 1 + (1 if q["count"] is not None else 0) + max(inner + [0])

    def names(self, q: dict) -> int:
        return 1 + max([self.names(p) for params in self._inner(q["type"]) for p in params] + [0])

    def length(self, q: dict) -> int:
        n = len(q["name"])
        c = q["count"]
        if c is not None:
            top = c["value"] if c["kind"] == "fixed" else (q["max_count"] or 0) + 1
            n += 2 + len(str(max(top, 1)))  # "[" index "]"
        # A struct (or a union's struct) adds "." and its longest member path (none: just ".").
        inner = [1 + max([self.length(p) for p in params] + [0]) for params in self._inner(q["type"])]
        return n + max(inner + [0])
