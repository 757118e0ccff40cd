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
    foreign = p["framing"].get("foreign_frames")
    if foreign:
        ctx.framing["foreign_frames"]["sources"] = ctx.check_sources(
            ctx.pf, ("framing", "foreign_frames", "sources"), foreign["sources"]
        )
        starts = foreign_starts(ctx.framing)
        if p["framing"]["sync"][0] in starts:
            ctx.err(
                ctx.pf,
                ("framing", "sync"),
                f"the sync's first byte 0x{p['framing']['sync'][0]:02X} starts a foreign frame too",
                "a sync byte that is none of " + ", ".join(f"0x{b:02X}" for b in sorted(starts)),
            )


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
    # Foreign frames (NMEA-0183 sentences, RTCM3 frames; docs/conformance.md section 1): which
    # the parser recognises, their longest lengths, and the parser's buffer (the longest
    # candidate it may have to wait for).
    kinds = (f.get("foreign_frames") or {}).get("kinds", [])
    f["nmea"] = "nmea" in kinds
    f["rtcm3"] = "rtcm3" in kinds
    f["nmea_max"] = (f.get("foreign_frames") or {}).get("nmea_max_length", NMEA_MAX_DEFAULT) if f["nmea"] else 0
    f["rtcm3_max"] = RTCM3_MAX if f["rtcm3"] else 0
    f["parser_capacity"] = max(f["max_packet"], f["nmea_max"], f["rtcm3_max"])
    return f


# NMEA-0183: 82 characters from '$' to LF; the default when a protocol file names no limit.
NMEA_MAX_DEFAULT = 82
# RTCM3 (RTCM 10403): 3 header bytes, a payload of at most 1023 (10-bit length), 3 CRC bytes.
RTCM3_MAX = 3 + 1023 + 3


def foreign_starts(framing: dict) -> set[int]:
    """The first bytes of the foreign frames the framing recognises."""
    return ({0x24, 0x21} if framing["nmea"] else set()) | ({0xD3} if framing["rtcm3"] else set())
