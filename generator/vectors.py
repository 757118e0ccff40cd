"""Load the language-neutral golden vectors (tests/vectors/<protocol>/*.yaml) and the stream
corpus (tests/streams/<protocol>/*.yaml, the same case format).

Each case is checked against the IR (every parameter present, values in range, names known) and
turned into the exact canonical JSON lines (docs/conformance.md) that every language must print
for its bytes. Values in the YAML are written as a person reads them (enum names, bit names,
decimal floats); generator/corpus.py re-spells them canonically.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import jsonschema

from .corpus import CorpusFile, fletcher16, packet_line
from .diagnostics import SpecError, SpecErrors
from .passes.context import SpecFile
from .resources import SCHEMA_DIR
from .schema_check import schema_errors
from .yamlpos import load

CASE_KEYS = {
    "name",
    "sources",
    "derivation",
    "erratum",
    "hex",
    "device",
    "packets",
    "rejected",
    "notes",
    "skipped",
    "foreign",
    "quoted",
    "encode_inputs",
    "refused_inputs",
}
ERRATUM_KINDS = {"bad_checksum", "bad_length", "table_mismatch", "copy_paste_mismatch", "bad_decimal", "bad_bytes"}


def load_corpus(ir: dict, root: Path) -> list[dict]:
    """The golden vectors and the stream corpus of the project at root, vectors first. Every case
    carries `corpus`: "vectors" or "streams"; both are checked the same way in every language."""
    cases = load_vectors(ir, root / "tests" / "vectors")
    streams = root / "tests" / "streams"
    if streams.is_dir():
        seen = {c["name"]: c["file"] for c in cases}
        more = load_vectors(ir, streams)
        clash = [
            SpecError(None, f"case '{c['name']}' of {c['file']} is also in {seen[c['name']]}", "unique names")
            for c in more
            if c["name"] in seen
        ]
        if clash:
            raise SpecErrors(clash)
        cases += more
    return cases


def load_vectors(ir: dict, vectors_dir: Path, root: Path | None = None) -> list[dict]:
    """The cases of vectors_dir/<protocol>/*.yaml; their file names are relative to root (by
    default the directory two levels up, the project of tests/vectors)."""
    cases: list[dict] = []
    errors: list[SpecError] = []
    protos = {p["name"]: p for p in ir["protocols"]}
    root = root or vectors_dir.parent.parent
    names: dict[str, str] = {}
    for proto_dir in sorted(p for p in vectors_dir.iterdir() if p.is_dir()):
        proto = protos.get(proto_dir.name)
        for path in sorted(proto_dir.glob("*.yaml")):
            rel = str(path.relative_to(root))
            try:
                data, locate = load(str(path), rel)
            except SpecError as e:
                errors.append(e)
                continue
            sf = SpecFile(rel, data, locate)
            shape = _shape_errors(sf)
            if shape:
                errors.extend(shape)
                continue
            if proto is None:
                errors.append(
                    SpecError(
                        locate(()), f"no protocol '{proto_dir.name}' in spec/", "a directory named after a protocol"
                    )
                )
                continue
            ctx = CorpusFile(sf, proto)
            if not isinstance(data, dict) or not isinstance(data.get("cases"), list):
                ctx.err((), "a vector file is a mapping with a 'cases' list", "cases: [...]")
                errors.extend(ctx.errors)
                continue
            for i, c in enumerate(data["cases"]):
                case = _case(ctx, ("cases", i), c, rel)
                if case is None:
                    continue
                case["corpus"] = vectors_dir.name
                if case["name"] in names:
                    ctx.err(
                        ("cases", i, "name"),
                        f"vector '{case['name']}' is defined twice (also in {names[case['name']]})",
                        "unique vector names",
                    )
                names[case["name"]] = rel
                cases.append(case)
            errors.extend(ctx.errors)
    for c in cases:
        corr = (c.get("erratum") or {}).get("corrected")
        if corr and corr not in names:
            errors.append(
                SpecError(
                    None, f"vector '{c['name']}': corrected case '{corr}' does not exist", "the name of another vector"
                )
            )
    if errors:
        raise SpecErrors(errors)
    return cases


SCHEMA = SCHEMA_DIR / "vectors.schema.json"


def _shape_errors(sf: SpecFile) -> list[SpecError]:
    validator = jsonschema.Draft202012Validator(json.loads(SCHEMA.read_text(encoding="utf-8")))
    return schema_errors(validator, sf.data, sf.locate)


def _case(ctx: CorpusFile, path: tuple, c: dict, rel: str) -> dict | None:
    if not isinstance(c, dict):
        ctx.err(path, "a case is a mapping")
        return None
    for k in c:
        if k not in CASE_KEYS:
            ctx.err(path + (k,), f"unknown key '{k}' in vector case", "one of " + ", ".join(sorted(CASE_KEYS)))
    for k in ("name", "hex"):
        if k not in c:
            ctx.err(path, f"vector case lacks '{k}'")
            return None
    if not c.get("sources") and not c.get("derivation"):
        ctx.err(path, f"vector '{c['name']}' has neither sources nor a derivation", "where the bytes come from")
    hex_clean = re.sub(r"[\s_]", "", str(c["hex"])).lower()
    if not re.fullmatch(r"([0-9a-f]{2})*", hex_clean):
        ctx.err(
            path + ("hex",),
            f"vector '{c['name']}': hex is not an even number of hex digits",
            "pairs of hex digits, spaces allowed",
        )
        return None
    raw = bytes.fromhex(hex_clean)
    er = c.get("erratum")
    if er is not None:
        if not isinstance(er, dict) or er.get("kind") not in ERRATUM_KINDS or not er.get("evidence"):
            ctx.err(
                path + ("erratum",),
                "an erratum needs kind and evidence",
                "kind: one of " + ", ".join(sorted(ERRATUM_KINDS)) + "; evidence: text",
            )
    lines: list[str] = []
    if c.get("rejected"):
        if c.get("packets"):
            ctx.err(path + ("packets",), "a rejected case has no packets")
        lines.append('{"offset":0,"skipped":"%s"}' % hex_clean)
    else:
        pkts = c.get("packets") or []
        if not pkts and (raw or c.get("skipped")):
            ctx.err(
                path, f"vector '{c['name']}' has no packets and is not rejected", "packets: [...] or rejected: true"
            )
        for j, p in enumerate(pkts):
            lines.append(packet_line(ctx, path + ("packets", j), p, c.get("device")))
        for k, s in enumerate(c.get("skipped") or []):
            if "hex" in s:
                skipped = re.sub(r"\s", "", s["hex"]).lower()
            else:  # {offset, count}: the bytes are the input's
                skipped = raw[s["offset"] : s["offset"] + s["count"]].hex()
                if len(skipped) != 2 * s["count"]:
                    ctx.err(
                        path + ("skipped", k), f"skip run at {s['offset']} of {s['count']} bytes runs past the input"
                    )
            lines.append('{"offset":%d,"skipped":"%s"}' % (s["offset"], skipped))
        for f in c.get("foreign") or []:
            lines.append(foreign_line(f))
        lines.sort(key=lambda line: int(re.match(r'\{"offset":(\d+)', line).group(1)))
        _check_tiling(ctx, path, c["name"], raw, lines)
    return {
        "name": c["name"],
        "protocol": ctx.proto["name"],
        "file": rel,
        "line": ctx.sf.locate(path).line,
        "sources": c.get("sources") or [],
        "derivation": c.get("derivation"),
        "erratum": er,
        "notes": c.get("notes"),
        "hex": hex_clean,
        "size": len(raw),
        "device": c.get("device"),
        "rejected": bool(c.get("rejected")),
        "quoted": c.get("quoted"),
        # Encoder input (docs/conformance.md §5): other spellings that must encode to `hex`, and
        # lines every encoder must refuse, as lowercase hex of their bytes ({hex} in the YAML
        # gives bytes that are not UTF-8 text).
        "encode_inputs": list(c.get("encode_inputs") or []),
        "refused_inputs": [
            re.sub(r"\s", "", r["hex"]).lower() if isinstance(r, dict) else r.encode("utf-8").hex()
            for r in c.get("refused_inputs") or []
        ],
        "expect": lines,
    }


def _check_tiling(ctx: CorpusFile, path: tuple, name: str, raw: bytes, lines: list[str]) -> None:
    """The expected events must account for every input byte exactly once, in order: a skip run
    holds the input's own bytes and is maximal (never followed by another run), a packet starts
    with the sync bytes, has the set the case names, spans header + payload length + checksum and
    carries a valid checksum. This catches a mistyped offset or byte count in a hand-written case
    with a message, before any language is asked to agree with it."""
    fr = ctx.proto["framing"]
    sync = bytes(fr["sync"])
    pos = 0
    last_skip = False

    def bad(msg: str) -> None:
        ctx.err(path, f"vector '{name}': {msg}", "events that cover the input exactly, in order")

    for line in lines:
        ev = json.loads(line)
        off = ev["offset"]
        if off != pos:
            return bad(f"an event starts at offset {off}, but the previous one ends at {pos}")
        if "nmea" in ev or "rtcm" in ev:
            n = foreign_length(raw, off, fr)
            if n == 0:
                return bad(f"no whole valid NMEA sentence or RTCM3 frame at offset {off}")
            if json.loads(foreign_line(foreign_fields(raw[off : off + n]))) != {**ev, "offset": 0}:
                return bad(f"the frame at offset {off} is {raw[off : off + n]!r}, not the line's")
            pos += n
            last_skip = False
            continue
        if "skipped" in ev:
            if last_skip:
                return bad(f"skip runs at offset {off} and before it are adjacent; they are one run")
            got = bytes.fromhex(ev["skipped"])
            if raw[off : off + len(got)] != got:
                return bad(f"skipped bytes at offset {off} are not the input's ({raw[off : off + len(got)].hex()})")
            pos += len(got)
            last_skip = True
            continue
        last_skip = False
        head = raw[off : off + fr["header_size"]]
        if len(head) < fr["header_size"] or not head.startswith(sync):
            return bad(f"no packet header at offset {off}")
        if head[fr["set_offset"]] != ev["set"]:
            return bad(f"the packet at offset {off} is of set {head[fr['set_offset']]}, not {ev['set']}")
        end = off + fr["header_size"] + head[fr["length_offset"]] + fr["checksum_size"]
        body = raw[off : end - fr["checksum_size"]]
        check = fletcher16(body) if fr["checksum"]["order"] == ["sum1", "sum2"] else fletcher16(body)[::-1]
        if end > len(raw) or check != raw[end - fr["checksum_size"] : end]:
            return bad(f"the packet at offset {off} is truncated or its checksum is wrong")
        pos = end
    if pos != len(raw):
        bad(f"the events end at offset {pos}, the input at {len(raw)}")


def crc24q(data: bytes) -> int:
    """CRC-24Q of RTCM3 from its definition: polynomial 0x1864CFB (x^24 + x^23 + x^18 + x^17 +
    x^14 + x^11 + x^10 + x^7 + x^6 + x^5 + x^4 + x^3 + x + 1), initial value 0, not reflected, no
    final XOR, bit by bit."""
    crc = 0
    for b in data:
        crc ^= b << 16
        for _ in range(8):
            crc <<= 1
            if crc & 0x1000000:
                crc ^= 0x1864CFB
    return crc


# The check value of this CRC (CRC-24/LTE-A in the CRC catalogue, the same parameters) for the
# ASCII bytes "123456789" is 0xCDE703: a wrong polynomial or bit order would not give it.
assert crc24q(b"123456789") == 0xCDE703


def foreign_length(raw: bytes, off: int, framing: dict) -> int:
    """The length of the whole, valid NMEA-0183 sentence or RTCM3 frame at raw[off] under the
    protocol's framing (docs/conformance.md section 1), else 0. Written from the definitions,
    apart from the runtimes."""
    kinds = (framing.get("foreign_frames") or {}).get("kinds", [])
    data = raw[off:]
    if data[:1] == b"\xd3" and "rtcm3" in kinds and len(data) >= 6 and data[1] >> 2 == 0:
        n = (data[1] & 3) * 256 + data[2]
        if n >= 2 and len(data) >= n + 6 and crc24q(data[: n + 3]) == int.from_bytes(data[n + 3 : n + 6], "big"):
            return n + 6
        return 0
    if data[:1] in (b"$", b"!") and "nmea" in kinds:
        m = re.match(rb"[$!]([\x20-\x23\x25-\x29\x2b-\x7e]*)\*([0-9A-Fa-f]{2})\r\n", data)
        if m is None or m.end() > framing["nmea_max"] or b"!" in m.group(1):
            return 0
        x = 0
        for b in m.group(1):
            x ^= b
        return m.end() if x == int(m.group(2), 16) else 0
    return 0


def foreign_fields(frame: bytes) -> dict:
    """The line fields of a frame foreign_length accepted (offset 0)."""
    if frame[0] == 0xD3:
        return {"offset": 0, "rtcm": (frame[3] << 4) | (frame[4] >> 4), "length": len(frame) - 6}
    return {"offset": 0, "nmea": frame[:-2].decode("ascii")}


def foreign_line(f: dict) -> str:
    """The decode line of a foreign frame (docs/conformance.md section 5)."""
    if "rtcm" in f:
        return '{"offset":%d,"rtcm":%d,"length":%d}' % (f["offset"], f["rtcm"], f["length"])
    return '{"offset":%d,"nmea":%s}' % (f["offset"], json.dumps(f["nmea"]))
