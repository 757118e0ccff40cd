"""Pass: the (set, descriptor) search order of docs/conformance.md section 2, resolved once.

A field is looked up in its set's own fields, then among the reserved fields of the set's kind,
then (in a data set, when the protocol has shared data fields) among the shared data fields; the
first match wins. Every runtime performs this search; the IR's `lookup` holds the resolved
answer for every defined set and for a set of each kind the spec does not define, so back ends
(and third-party ones built from ir.json) compile it into dispatch tables without repeating it.
"""

from __future__ import annotations

from .context import Context


def run(ctx: Context) -> None:
    p = ctx.pf.data
    protocol = {
        "set_kinds": p["set_kinds"],
        "sets": ctx.sets,
        "reserved_fields": ctx.reserved,
        "shared_data": p.get("shared_data"),
    }
    defined = {s["id"] for s in ctx.sets}
    ctx.lookup = {
        "sets": [{"set": s["id"], "fields": table(protocol, s["id"])} for s in ctx.sets],
        # A set id of this kind that no set file defines still answers reserved and shared fields.
        "other_sets": {
            kind: table(protocol, next(i for i in range(r["first"], r["last"] + 1) if i not in defined))
            for kind, r in p["set_kinds"].items()
            if any(i not in defined for i in range(r["first"], r["last"] + 1))
        },
    }


def entries(protocol: dict, set_id: int) -> list[dict]:
    """The IR `lookup` entries for packets of set set_id, whether a spec file defines the set or
    not (for readers of a finished IR; no search)."""
    for t in protocol["lookup"]["sets"]:
        if t["set"] == set_id:
            return t["fields"]
    return protocol["lookup"]["other_sets"].get(set_kind(protocol, set_id), [])


def table(protocol: dict, set_id: int) -> list[dict]:
    """The lookup entries of set set_id by descriptor: `source` says where the field is defined
    (`own`: the set itself; `reserved`: a reserved field of the set's kind; `shared`: the shared
    data set), `set` is the defining set's id (null for a reserved field)."""
    out = []
    for d, (owner, f) in sorted(resolve(protocol, set_id).items()):
        if owner is None:
            source = "reserved"
        else:
            source = "own" if owner["id"] == set_id else "shared"
        out.append({"descriptor": d, "name": f["name"], "source": source, "set": owner["id"] if owner else None})
    return out


def set_kind(protocol: dict, set_id: int) -> str | None:
    """Name of the set kind (IR `set_kinds`) whose id range holds set_id, or None."""
    for name, r in protocol["set_kinds"].items():
        if r["first"] <= set_id <= r["last"]:
            return name
    return None


def resolve(protocol: dict, set_id: int) -> dict[int, tuple[dict | None, dict]]:
    """descriptor -> (IR set the field is defined in, or None for a reserved field; IR field),
    for every descriptor that names a field in a packet of set set_id (defined or not)."""
    sets = {s["id"]: s for s in protocol["sets"]}
    kind = set_kind(protocol, set_id)
    search: list[tuple[dict | None, list[dict]]] = []
    if set_id in sets:
        search.append((sets[set_id], sets[set_id]["fields"]))
    search.append((None, [r for r in protocol["reserved_fields"] if r["applies_to"] == kind]))
    shared = protocol.get("shared_data")
    if shared and kind == "data" and shared["set"] in sets:
        search.append((sets[shared["set"]], sets[shared["set"]]["fields"]))
    found: dict[int, tuple[dict | None, dict]] = {}
    for owner, fields in search:
        for f in fields:
            found.setdefault(f["id"], (owner, f))
    return found
