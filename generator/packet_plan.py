"""The straight-line packet decoders of issue 38, decided once for every back end (docs/design.md).

A data set's straight-line decoder fills a packet struct: one member per entry of the set's lookup
(its own fields, the reserved fields of its kind, the shared data fields, in the IR's lookup order)
whose field has ONE layout; a field with per-device variants is left to the general dispatch, as the
device chooses among them. A member whose layout is a fixed sequence of plain values (numbers, enums,
bitfields, bools, chars; scalars or fixed arrays, nothing optional) has a fast path: the layout's size
and one load per value at a constant offset. The back ends (C, C++, Rust) map this plan to their
names and types; the decision itself (which members, which loads) lives here, on the IR.
"""

from __future__ import annotations

from dataclasses import dataclass

from generator import model

# The element kinds a constant-offset load reads (one primitive base type each).
_LOADABLE = ("primitive", "enum", "bitfield")


@dataclass(frozen=True)
class Load:
    """One value of a fast layout: parameter `param` (element `index` of a fixed array, None for a
    scalar) is the primitive `primitive` (an IR primitive name: u8, float, bool, ...) at byte
    offset `off` of the field data."""

    param: str
    index: int | None
    primitive: str
    off: int


@dataclass(frozen=True)
class FastLayout:
    """The constant-offset decode of a layout: `size` bytes of field data, `loads` in order."""

    size: int
    loads: tuple[Load, ...]

    @property
    def bools(self) -> tuple[int, ...]:
        """Offsets of the bool bytes (a byte other than 0 or 1 does not decode: general path)."""
        return tuple(x.off for x in self.loads if x.primitive == "bool")


@dataclass(frozen=True)
class Member:
    """One member of a set's packet struct: the lookup entry (descriptor, source: own, reserved or
    shared), the field it resolves to (`field`, IR; `field_set` its set id, None for a reserved
    field), its one layout (`variant`, IR) and that layout's fast path (None: the layout's decoder)."""

    descriptor: int
    source: str
    field: dict
    field_set: int | None
    variant: dict
    fast: FastLayout | None


@dataclass(frozen=True)
class SetPlan:
    """The straight-line decoder of one data set (IR `set`)."""

    set: dict
    members: tuple[Member, ...]


def fast_layout(params: model.ParamList | tuple[model.Param, ...] | list[model.Param]) -> FastLayout | None:
    """The constant-offset decode of a parameter list of the layout model (model.params), or None
    when it has anything but plain values (optional, counted, remaining, string, struct, union)."""
    if isinstance(params, model.ParamList):
        params = params.params
    if not params:
        return None
    loads: list[Load] = []
    off = 0
    for q in params:
        if q.optional or q.kind not in (model.SCALAR, model.FIXED) or q.elem.kind not in _LOADABLE:
            return None
        size = q.elem.size.min
        if q.kind == model.SCALAR:
            loads.append(Load(q.name, None, q.elem.primitive, off))
            off += size
        else:
            for i in range(q.count):
                loads.append(Load(q.name, i, q.elem.primitive, off))
                off += size
    return FastLayout(off, tuple(loads))


def data_kind(proto: dict) -> str | None:
    """The set kind whose sets get straight-line decoders ("data"), None if the protocol has none."""
    return "data" if "data" in proto.get("set_kinds", {}) else None


def packet_plans(proto: dict) -> dict[int, SetPlan | None]:
    """Set id -> the plan of its straight-line decoder, None for a set that has none (not data)."""
    kind = data_kind(proto)
    fields = {(s["id"], f["id"]): f for s in proto["sets"] for f in s["fields"]}
    reserved = {(r["applies_to"], r["id"]): r for r in proto["reserved_fields"]}
    tables = {t["set"]: t["fields"] for t in proto["lookup"]["sets"]}
    plans: dict[int, SetPlan | None] = {}
    for s in proto["sets"]:
        if kind is None or s["kind"] != kind:
            plans[s["id"]] = None
            continue
        members = []
        for e in tables[s["id"]]:
            if e["source"] == "reserved":
                f, field_set = reserved[(s["kind"], e["descriptor"])], None
            else:
                f, field_set = fields[(e["set"], e["descriptor"])], e["set"]
            if model.per_device(f):
                continue
            v = f["variants"][0]
            members.append(Member(e["descriptor"], e["source"], f, field_set, v, fast_layout(model.layout(proto, v))))
        plans[s["id"]] = SetPlan(s, tuple(members))
    return plans
