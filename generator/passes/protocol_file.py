"""Pass: the protocol file's own entries: the framing with its derived constants, the function
selector enum (it must be defined; its values name the selector bytes) and the protocol's sources.
"""

from __future__ import annotations

from .context import Context
from .sizes import max_field_data


def run(ctx: Context) -> None:
    p = ctx.pf.data
    ctx.framing = derive_framing(p["framing"])
    fs_enum = (p.get("function_selector") or {}).get("enum")
    if fs_enum and fs_enum not in ctx.types:
        ctx.err(
            ctx.pf,
            ("function_selector", "enum"),
            f"function selector enum '{fs_enum}' is not defined",
            "an enum defined in the spec",
        )
    if fs_enum in ctx.types and ctx.types[fs_enum]["kind"] == "enum":
        ctx.function_values = {v["name"]: v["value"] for v in ctx.types[fs_enum]["values"]}
    ctx.sources = ctx.check_sources(ctx.pf, ("sources",), p["sources"])


def derive_framing(spec: dict) -> dict:
    """The framing of the protocol file plus the offsets and sizes every runtime needs."""
    f = dict(spec)
    header_size = len(f["sync"]) + 2
    f["header_size"] = header_size
    f["set_offset"] = len(f["sync"]) + f["header"].index("set")
    f["length_offset"] = len(f["sync"]) + f["header"].index("payload_length")
    f["field_header_size"] = 2
    f["field_length_offset"] = f["field_header"].index("length")
    f["field_descriptor_offset"] = f["field_header"].index("descriptor")
    f["field_length_adjust"] = 2 if f["field_length_counts_header"] else 0
    f["checksum_size"] = 2
    f["max_packet"] = header_size + f["max_payload"] + 2
    f["max_field_data"] = max_field_data(f)  # largest data a single field can carry
    return f
