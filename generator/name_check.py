"""The generated names of every target, checked before anything is rendered (issue 37).

Each language target lists the identifiers its code gives to the spec's elements
(`generator/targets/<lang>/identifiers.py`, `names(protocol) -> [Name]`), spelled by the back end's own
naming functions: after case conversion and after the target's escaping of its keywords and
reserved identifiers (`facts.py`). This pass, the same for every target, groups them by the scope
they live in (the package, a namespace or module, a struct, an enum, ...) and reports

- a collision: two spec elements that become one identifier in one scope (`abc_def` and
  `abc__def` -> `AbcDef`; `class` escaped to `class_` beside a parameter `class_`), as one error
  located at one of them that names the other and where it is ("the first at FILE:LINE:COL");
  an element that takes a name the generated code itself uses in that scope is named with it;
- a leftover: an identifier that is still reserved in the language after escaping (a type named
  `None` in Python, `Self` in Rust, `EOF` in C++), located at its element.

Errors read like every spec error (`file:line:column: error: ...`, exit status 1) and are all
reported at once; the pipeline runs this for every target it renders, before rendering any.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

from . import model
from .commands import commands
from .diagnostics import Location, SpecError


@dataclass(frozen=True)
class Name:
    """One identifier of the generated code.

    scope: where it lives, as the message says it ("namespace democodec::data", "struct
        demo_data_klass_t", "the C file scope"); two names collide only in the same scope.
    ident: the identifier, as the back end spells it (cased, prefixed, escaped).
    element: the spec element it names ("parameter class of field data.klass"); for a name the
        generated code itself uses (a runtime member, a module of the package), what it is.
    where: the names leading to the element in the spec (`spec.locate_names`: ("data", "klass",
        "class")); () for the generated code's own names.
    checked: whether the identifier is checked against the language's reserved words (False for
        names the generated code spells itself, and for prefixed names that cannot be reserved).
    owner: the spec element that makes the scope (the struct's type, the layout's field), when
        two elements could give it the same name: their members are not compared (the two
        owners' collision is the error).
    """

    scope: str
    ident: str
    element: str
    where: tuple[str, ...] = ()
    checked: bool = True
    owner: str = ""

    @property
    def generated(self) -> bool:
        return not self.where


def taken(scope: str, idents: Iterable[str], what: str, owner: str = "") -> list[Name]:
    """Names the generated code itself uses in `scope` (a spec element may not take them)."""
    return [Name(scope, i, f"{what} {i}", (), False, owner) for i in sorted(idents)]


def check(
    label: str,
    names: Iterable[Name],
    reserved: Callable[[str], str | None],
    locate: Callable[[tuple[str, ...]], Location],
    rank: Callable[[Location], int] = lambda loc: 0,
) -> list[SpecError]:
    """The errors of one target's names (label: the target's name in messages, "C++").

    reserved(ident): why ident is still reserved in the language ("is a C++ keyword"), or None.
    locate(where): the location of a spec element (never None: the caller falls back to the
    protocol file).
    rank(location): the order in which the spec's directories are read (the spec 0, its overlays
    1, 2, ...): of two colliding entries, the first read is "the first", and the error is at the
    other (an overlay's entry, or the later one in a file)."""
    errors: list[SpecError] = []
    seen_messages: set[str] = set()
    groups: dict[tuple[str, str, str], list[Name]] = {}

    def add(loc: Location, message: str, expected: str) -> None:
        key = f"{loc}: {message}"
        if key not in seen_messages:
            seen_messages.add(key)
            errors.append(SpecError(loc, message, expected))

    for n in names:
        group = groups.setdefault((n.scope, n.owner, n.ident), [])
        if all((m.element, m.where) != (n.element, n.where) for m in group):
            group.append(n)
        if n.checked and not n.generated:
            why = reserved(n.ident)
            if why:
                add(
                    locate(n.where),
                    f"{label}: {n.element} would be named {n.ident} in {n.scope}, which {why}",
                    f"a name that is not reserved in {label}",
                )
    for (scope, _owner, ident), group in groups.items():
        if len(group) < 2:
            continue
        spec = [n for n in group if not n.generated]
        generated = [n for n in group if n.generated]
        for n in spec:
            if generated:
                add(
                    locate(n.where),
                    f"{label}: {n.element} would be named {ident} in {scope}, which is {generated[0].element}",
                    f"a name the generated {label} code does not use there",
                )
        if len(spec) < 2:
            continue
        located = sorted(
            ((locate(n.where), n) for n in spec), key=lambda p: (rank(p[0]), p[0].file, p[0].line, p[0].column)
        )
        first_loc, first = located[0]
        for loc, n in located[1:]:
            add(
                loc,
                f"{label}: {n.element} and {first.element} would both be named {ident} in {scope}"
                f" (the first at {first_loc})",
                f"names that stay distinct in {label} after case conversion and escaping",
            )
    return errors


# ---------------------------------------------------------------------------- shared walks
# What every target names the same way: the layouts of a protocol and where their parameters are.


@dataclass(frozen=True)
class Layout:
    """One field layout: a reserved field's or a set's field's, one per device variant."""

    set: dict | None  # None for a reserved field
    field: dict
    variant: dict
    device: str | None  # the variant's device when the field has per-device layouts
    what: str  # "field data.klass", "reserved field ack" (+ " (device gx5)")
    where: tuple[str, ...]  # the field in the spec
    params_where: tuple[str, ...]  # what a parameter's name is under: the field, or its shared layout


def layouts(proto: dict) -> Iterator[Layout]:
    """Every layout of protocol proto, reserved fields first, then set by set."""
    for s in [None, *proto["sets"]]:
        fields = proto["reserved_fields"] if s is None else s["fields"]
        for f in fields:
            multi = model.per_device(f)
            where = (f["name"],) if s is None else (s["name"], f["name"])
            for v in f["variants"]:
                dev = v["device"] if multi else None
                what = f"reserved field {f['name']}" if s is None else f"field {s['name']}.{f['name']}"
                if dev:
                    what += f" (device {dev})"
                yield Layout(s, f, v, dev, what, where, params_where(s, f, v))


def params_where(s: dict | None, f: dict, v: dict) -> tuple[str, ...]:
    """What the names of variant v's parameters are under in the spec: its shared layout's name
    (`layout:`), else its field."""
    if v.get("layout"):
        return (v["layout"],)
    return (f["name"],) if s is None else (s["name"], f["name"])


def param_element(p, owner: str) -> str:
    """The element a parameter of the layout model is, in messages."""
    return f"the function selector of {owner}" if p.function else f"parameter {p.name} of {owner}"


def calls(proto: dict) -> Iterator[tuple[dict, dict, object]]:
    """Every call of the typed command API (generator/commands.py) with its set and field."""
    sets = {s["id"]: s for s in proto["sets"]}
    for c in commands(proto).calls:
        s = sets[c.set]
        yield s, next(f for f in s["fields"] if f["name"] == c.field), c


def call_arguments(
    scope: str, owner: str, what: str, s: dict, f: dict, call, spell: Callable[[str], str]
) -> list[Name]:
    """The names of a typed call's arguments in one target's spelling (spell: the target's rule
    for a parameter name), each located at its parameter in the spec."""
    v = f["variants"][call.variants[0]]
    return [
        Name(scope, spell(a.name), f"parameter {a.name} of {what}", params_where(s, f, v) + (a.name,), owner=owner)
        for a in call.arguments
    ]


def enum_values(scope: str, owner: str, t: dict, spell: Callable[[str], str]) -> list[Name]:
    """The names of enum t's values in one target's spelling, each located at its value."""
    tw = (t["name"],)
    return [
        Name(scope, spell(v["name"]), f"value {v['name']} of {owner}", tw + (v["name"],), owner=owner)
        for v in t["values"]
    ]


def types(out: list[Name], scope: str, proto: dict, spell: Callable[[str], str]) -> Iterator[tuple[dict, str]]:
    """Adds the name of each type of proto to out (in scope, spelled by spell) and yields the type
    and what messages call it ("enum GpsMode")."""
    for t in proto["types"]:
        out.append(Name(scope, spell(t["name"]), f"type {t['name']}", (t["name"],)))
        yield t, f"{t['kind']} {t['name']}"


def struct_members(scope: str, owner: str, proto: dict, t: dict, spell: Callable[[str], str]) -> list[Name]:
    """The names of struct t's members in one target's spelling, each located at its member."""
    return [
        Name(scope, spell(q.name), param_element(q, owner), (t["name"], q.name), owner=owner)
        for q in model.struct(proto, t)
    ]


def each_member(t: dict, owner: str) -> Iterator[tuple[dict, tuple, str]]:
    """Each member of bitfield or union t with its place in the spec and what messages call it."""
    for b in t["members"]:
        yield b, (t["name"], b["name"]), f"member {b['name']} of {owner}"
