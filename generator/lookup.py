"""The (set, descriptor) search order of docs/conformance.md section 2, resolved once in Python.

A field is looked up in its set's own fields, then among the reserved fields of the set's kind,
then (in a data set, when the protocol has shared data fields) among the shared data fields; the
first match wins. Every runtime performs this search; the back ends that compile it into
dispatch tables (C, C++, Rust) take the resolved answer from here, so the order lives in one place.
"""

from __future__ import annotations


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
