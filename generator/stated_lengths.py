"""The stated-length lint: every field length a manual states (`stated_length` on a source)
compared with the length computed from the parameter types. Disagreements are listed in
docs/errata.md and by `python -m generator --lint`; they are not spec errors (manuals misstate
lengths, and the spec follows the wire)."""

from __future__ import annotations


def lint_stated_lengths(ir: dict) -> list[dict]:
    """Every disagreement between a manual's stated field length and the computed one."""
    out = []
    for proto in ir["protocols"]:
        adj = proto["framing"]["field_length_adjust"]
        for s in proto["sets"]:
            for f in s["fields"]:
                for v in f["variants"]:
                    size = v["size"]
                    for src in v["sources"]:
                        stated = src.get("stated_length")
                        if stated is None:
                            continue
                        full_min, full_max = size["min"] + adj, size["max"] + adj
                        textual = not isinstance(stated, int)
                        if not textual:
                            # A command with optional parameters may be stated at its full length.
                            ok = stated == full_max if _all_fixed_elements(v["params"]) else False
                            if ok or (size["fixed"] and stated == full_min):
                                continue
                        item = {
                            "protocol": proto["name"],
                            "set": s["id"],
                            "descriptor": f["id"],
                            "name": f"{s['name']}.{f['name']}",
                            "manual": src["manual"],
                            "line": src.get("line"),
                            "stated": stated,
                            "computed": full_min if size["fixed"] else f"{full_min}..{full_max}",
                        }
                        if textual:
                            item["textual"] = True
                        out.append(item)
    return out


def _all_fixed_elements(params: list[dict]) -> bool:
    return all(q["size"]["fixed"] for q in params)
