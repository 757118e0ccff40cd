"""The example command of the getting-started programs and pages, chosen from the IR by a rule."""

from __future__ import annotations


def example_command(protocol: dict) -> tuple[dict, dict]:
    """(set, field): the first parameterless command with one layout in the lowest command set."""
    for s in sorted((s for s in protocol["sets"] if s["kind"] == "command"), key=lambda s: s["id"]):
        for f in s["fields"]:
            if f["role"] == "command" and not f["params"] and len(f["variants"]) == 1 and not f["functions"]:
                return s, f
    raise ValueError(f"protocol {protocol['name']} has no parameterless command")
