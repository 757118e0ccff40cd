"""Write generated/ir.json: the IR exactly as back ends consume it, deterministic."""

from __future__ import annotations

import json


def ir_to_json(ir: dict) -> str:
    return json.dumps(ir, indent=1, sort_keys=False, ensure_ascii=True) + "\n"
