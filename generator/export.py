"""Write generated/ir.json: the IR exactly as back ends consume it, deterministic.

Each protocol entry gets, after its `lookup`, the command model of generator/commands.py as
`commands` (derived from the rest of the entry, so the spec hash leaves it out)."""

from __future__ import annotations

import json

from .commands import export as export_commands


def with_commands(proto: dict) -> dict:
    """The protocol entry as exported: `commands` right after `lookup`."""
    out: dict = {}
    for k, v in proto.items():
        if k == "commands":
            continue
        out[k] = v
        if k == "lookup":
            out["commands"] = export_commands(proto)
    return out


def ir_to_json(ir: dict) -> str:
    exported = {**ir, "protocols": [with_commands(p) for p in ir["protocols"]]}
    return json.dumps(exported, indent=1, sort_keys=False, ensure_ascii=True) + "\n"
