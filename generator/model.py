"""The language-neutral layout model: every parameter of a layout or struct, classified once.

The IR says what a parameter is on the wire (its type reference, its count, whether it may be
left out); every back end needs the same reading of it: is it one value, a fixed array, an array
counted by an earlier parameter, an array that runs to the end of the data, a string, or a union
selected by an earlier enum? Which parameter holds its count or selector, and may that one be
absent? This module answers those questions once, as typed records, so that a back end only maps
the kinds and type references to its own names and types and its templates own the syntax.

`params(proto, params, functions)` is a pure function of the IR (no naming, no target syntax).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from generator.primitives import PRIMITIVES, int_range

# Kinds of parameter, in the order the templates usually test them.
SCALAR = "scalar"  # one value: a number, bool, char, enum, bitfield or struct
FIXED = "fixed"  # an array of `count` values
COUNTED = "counted"  # an array whose length is the value of the earlier parameter `count_param`
REMAINING = "remaining"  # an array that runs to the end of the field data
STRING = "string"  # a fixed-length character string (never an array: the IR refuses those)
UNION = "union"  # the member of a union that the earlier enum parameter `selector` selects
KINDS = (SCALAR, FIXED, COUNTED, REMAINING, STRING, UNION)
ARRAYS = (FIXED, COUNTED, REMAINING)


def per_device(field: dict) -> bool:
    """Whether a field of the IR (or a reserved field) has per-device layouts: the spec gives it
    `variants`, one layout per device, where every other field has one layout shared by all its
    devices (docs/ir.md). The back ends then name a type, a decoder, a call per device."""
    return len(field["variants"]) > 1


def layout_device(field: dict, variant: dict) -> str | None:
    """The device a layout of field is for, or None for the one layout every device shares."""
    return variant["device"] if per_device(field) else None


@dataclass(frozen=True)
class Size:
    """Encoded size in bytes: `min`..`max`, and whether every value has the same size."""

    min: int
    max: int
    fixed: bool

    @staticmethod
    def of(ir_size: dict) -> Size:
        return Size(ir_size["min"], ir_size["max"], ir_size["fixed"])


@dataclass(frozen=True)
class Elem:
    """The type of one value of a parameter: the scalar itself, or one element of an array.

    `kind` is the IR's type kind ("primitive", "enum", "bitfield", "struct", "union" or
    "string"); `name` is the primitive's name ("u16") or the named type ("DeviceInfo"), or
    "string"; `primitive` is what goes on the wire for the number-like kinds (the primitive
    itself, or the base of an enum or bitfield) and None for structs, unions and strings."""

    kind: str
    name: str
    primitive: str | None
    size: Size
    length: int | None = None  # strings: number of characters
    padding: str | None = None  # strings: "nul" or "space"
    justify: str | None = None  # strings: "left" or "right"

    @property
    def named(self) -> bool:
        """True for a type defined in the spec (enum, bitfield, struct, union)."""
        return self.kind in ("enum", "bitfield", "struct", "union")


@dataclass(frozen=True)
class UnionMember:
    """One member of a union: the selector value (`when` by name), and its struct (None when
    the member carries no data)."""

    when: str
    value: int
    type: str | None


@dataclass(frozen=True)
class Param:
    """One parameter of a layout or struct, classified (see KINDS)."""

    name: str
    kind: str
    elem: Elem
    optional: bool  # may be left out at the end of the data (with every later parameter)
    size: Size
    # True for the function selector that a layout with functions sends first; it is not a
    # parameter of the IR (its elem is the protocol's function-selector enum).
    function: bool = False
    count: int | None = None  # FIXED: number of elements
    max_count: int | None = None  # COUNTED and REMAINING: most elements the field data can hold
    count_param: str | None = None  # COUNTED: the earlier parameter that holds the count
    count_optional: bool = False  # COUNTED: that parameter is optional (absent reads as 0)
    # COUNTED: the count parameter can hold a value above max_count, so decoding must check it;
    # REMAINING: always True (the data left decides the count).
    count_check: bool = False
    selector: str | None = None  # UNION: the earlier enum parameter that selects the member
    selector_optional: bool = False  # UNION: that parameter is optional (absent reads as 0)
    selector_enum: str | None = None  # UNION: the enum type of the selector parameter
    members: tuple[UnionMember, ...] = ()  # UNION: the union's members, in spec order
    # Every byte pattern of the parameter's fixed size decodes: a scalar or fixed array, not
    # optional, of numbers (not bool), chars, strings, enums, bitfields or structs of such.
    plain: bool = False
    description: str = ""
    units: str | None = None
    functions: tuple[str, ...] | None = None  # the functions the parameter is sent for, if limited
    ir: dict = field(default_factory=dict, compare=False, repr=False)  # the IR parameter ({} for `function`)

    @property
    def array(self) -> bool:
        return self.kind in ARRAYS


@dataclass(frozen=True)
class ParamList:
    """The parameters of one field layout (with its function selector first, if any) or struct."""

    params: tuple[Param, ...]
    functions: tuple[str, ...] | None  # the layout's functions (None when it has no selector)

    @property
    def has_optional(self) -> bool:
        return any(p.optional for p in self.params)

    @property
    def has_array(self) -> bool:
        return any(p.array for p in self.params)

    @property
    def plain(self) -> bool:
        return all(p.plain for p in self.params)

    def __iter__(self):
        return iter(self.params)

    def __len__(self) -> int:
        return len(self.params)


# ---------------------------------------------------------------------------------------- building
def elem(tref: dict) -> Elem:
    """The model of one IR type reference."""
    kind = tref["kind"]
    size = Size.of(tref["size"])
    if kind == "primitive":
        return Elem(kind, tref["name"], tref["name"], size)
    if kind in ("enum", "bitfield"):
        return Elem(kind, tref["name"], tref["base"], size)
    if kind == "string":
        return Elem(kind, "string", None, size, tref["length"], tref.get("padding"), tref.get("justify"))
    if kind in ("struct", "union"):
        return Elem(kind, tref["name"], None, size)
    raise ValueError(f"unknown type kind {kind!r}")


class _Plain:
    """Which types decode from every byte pattern of their fixed size."""

    def __init__(self, types: dict[str, dict]):
        self.types = types

    def tref(self, tref: dict, seen: tuple = ()) -> bool:
        kind = tref["kind"]
        if kind == "primitive":
            return tref["name"] != "bool"
        if kind in ("string", "enum", "bitfield"):
            return True
        if kind == "struct" and tref["name"] not in seen:
            return all(self.param(q, seen + (tref["name"],)) for q in self.types[tref["name"]]["params"])
        return False

    def param(self, q: dict, seen: tuple = ()) -> bool:
        c = q["count"]
        return (
            not q["optional"]
            and q["type"]["kind"] != "union"
            and (c is None or c["kind"] == "fixed")
            and self.tref(q["type"], seen)
        )


def param(q: dict, earlier: dict[str, dict], types: dict[str, dict]) -> Param:
    """The model of IR parameter `q`; `earlier` maps the names of the parameters before it to
    their IR dicts (count and selector parameters always come first), `types` the protocol's types."""
    tref = q["type"]
    count = q["count"]
    common = dict(
        name=q["name"],
        elem=elem(tref),
        optional=bool(q["optional"]),
        size=Size.of(q["size"]),
        plain=_Plain(types).param(q),
        description=q.get("description") or "",
        units=q.get("units"),
        functions=tuple(q["functions"]) if q.get("functions") is not None else None,
        ir=q,
    )
    if tref["kind"] == "string":
        return Param(kind=STRING, **common)
    if tref["kind"] == "union":
        sel = earlier[tref["selector"]]
        members = tuple(UnionMember(m["when"], m["value"], m["type"]) for m in types[tref["name"]]["members"])
        return Param(
            kind=UNION,
            selector=sel["name"],
            selector_optional=bool(sel["optional"]),
            selector_enum=types[tref["name"]]["selector_enum"],
            members=members,
            **common,
        )
    if count is None:
        return Param(kind=SCALAR, **common)
    if count["kind"] == "fixed":
        return Param(kind=FIXED, count=count["value"], **common)
    if count["kind"] == "param":
        cq = earlier[count["param"]]
        ctype = cq["type"]
        cprim = ctype["name"] if ctype["kind"] == "primitive" else ctype.get("base")
        return Param(
            kind=COUNTED,
            max_count=q["max_count"],
            count_param=cq["name"],
            count_optional=bool(cq["optional"]),
            count_check=cprim is None or q["max_count"] < int_range(cprim)[1],
            **common,
        )
    if count["kind"] == "remaining":
        return Param(kind=REMAINING, max_count=q["max_count"], count_check=True, **common)
    raise ValueError(f"parameter {q['name']}: unknown count kind {count['kind']!r}")


def function_param(proto: dict, functions: list[str]) -> Param:
    """The function selector a layout with functions sends first: one value of the protocol's
    function-selector enum."""
    enum = next(t for t in proto["types"] if t["name"] == proto["function_selector"]["enum"])
    nbytes = PRIMITIVES[enum["base"]][0]
    size = Size(nbytes, nbytes, True)
    return Param(
        name="function",
        kind=SCALAR,
        elem=Elem("enum", enum["name"], enum["base"], size),
        optional=False,
        size=size,
        function=True,
        plain=True,
        functions=tuple(functions),
    )


def params(proto: dict, ir_params: list[dict], functions: list[str] | None = None) -> ParamList:
    """The model of a parameter list of protocol `proto`: a field layout's `params` (with its
    `functions`, if it has a function selector) or a struct's `params` (functions None)."""
    types = {t["name"]: t for t in proto["types"]}
    out: list[Param] = []
    if functions is not None:
        out.append(function_param(proto, functions))
    earlier: dict[str, dict] = {}
    for q in ir_params:
        out.append(param(q, earlier, types))
        earlier[q["name"]] = q
    return ParamList(tuple(out), tuple(functions) if functions is not None else None)


def layout(proto: dict, variant: dict) -> ParamList:
    """The model of one field layout (a variant of a field) of protocol `proto`."""
    return params(proto, variant["params"], variant["functions"])


def layouts_of(fields: list[dict]):
    """Every layout of `fields`: (field, variant, device), where device is the variant's device
    when the field has per-device layouts and None when it has one (the key back ends name a
    layout by)."""
    for f in fields:
        multi = len(f["variants"]) > 1
        for v in f["variants"]:
            yield f, v, (v["device"] if multi else None)


def struct(proto: dict, struct_type: dict) -> ParamList:
    """The model of the parameters of a struct type of protocol `proto`."""
    return params(proto, struct_type["params"], None)


def type_order(proto: dict) -> list[dict]:
    """The protocol's types in declaration order: the enums and bitfields (in IR order, by name),
    then every struct and union after the structs and unions it contains (depth first, IR order),
    so that a language that declares before use can print them in this order."""
    types = {t["name"]: t for t in proto["types"]}
    order = [t for t in proto["types"] if t["kind"] in ("enum", "bitfield")]
    done: set[str] = set()

    def visit(t: dict) -> None:
        if t["name"] in done:
            return
        done.add(t["name"])
        if t["kind"] == "struct":
            inner = [q["type"]["name"] for q in t["params"] if q["type"]["kind"] in ("struct", "union")]
        else:
            inner = [m["type"] for m in t["members"] if m["type"] and types[m["type"]]["kind"] in ("struct", "union")]
        for name in inner:
            visit(types[name])
        order.append(t)

    for t in proto["types"]:
        if t["kind"] in ("struct", "union"):
            visit(t)
    return order
