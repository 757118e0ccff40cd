"""Sizes in bytes of field data (`{min, max, fixed}`, docs/ir.md), the capacity of counted arrays
and the fixed offsets of parameters: the arithmetic every pass that builds parameters shares."""

from __future__ import annotations


def fixed(n: int) -> dict:
    return {"min": n, "max": n, "fixed": True}


def param_size(q: dict) -> dict:
    """Size of one parameter: its type's size times its count (0..capacity for counted arrays)."""
    t = q["type"]["size"]
    c = q["count"]
    if c is None:
        return dict(t)
    if c["kind"] == "fixed":
        return {"min": t["min"] * c["value"], "max": t["max"] * c["value"], "fixed": t["fixed"]}
    return {"min": 0, "max": t["max"] * q["max_count"], "fixed": False}


def layout_size(params: list[dict], selector: bool = False) -> dict:
    """Data size of a layout (after the field header), including the function selector byte."""
    sel = 1 if selector else 0
    mn = sel + sum(q["size"]["min"] for q in params if not q["optional"])
    mx = sel + sum(q["size"]["max"] for q in params)
    is_fixed = all(q["size"]["fixed"] and not q["optional"] for q in params)
    return {"min": mn, "max": mx, "fixed": is_fixed}


def max_field_data(framing: dict) -> int:
    """Largest data a single field can carry, from the protocol file's framing."""
    adj = 2 if framing["field_length_counts_header"] else 0
    return min(framing["max_payload"] - 2, 255 - adj)


def fill_capacities(params: list[dict], max_data: int, selector: bool) -> None:
    """Default capacity of a counted array (`max_count` -1 until here): what fits in one field
    beside the selector byte and the smallest size of every other parameter."""
    for q in params:
        if q["max_count"] == -1:
            others = sum(o["size"]["min"] for o in params if o is not q)
            budget = max_data - (1 if selector else 0) - others
            q["max_count"] = max(budget // max(q["type"]["size"]["min"], 1), 0)
            q["size"] = param_size(q)


def fill_offsets(params: list[dict]) -> None:
    """Each parameter's fixed offset in the data after the selector, or None once it depends on
    earlier values (a variable-size or optional parameter before it)."""
    off: int | None = 0
    for q in params:
        q["offset"] = off
        if off is not None and q["size"]["fixed"] and not q["optional"]:
            off += q["size"]["min"]
        else:
            off = None
