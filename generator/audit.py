"""`make audit MANUALS=dir`: does the spec and the vector corpus cover the manuals?

Lists every `(0xSS,0xDD)` heading in the manuals and every quoted packet (contiguous hex strings
starting with a protocol's sync bytes), and reports those that no spec field or golden vector
covers. A heading is covered when the IR has that descriptor (in its set, the shared data set, or
as a reserved field). A quoted packet is covered when a vector has the same bytes, or names the
exact string in `quoted:` (for published strings that cannot be written as bytes). Example
tables (rows whose cells are the bytes `0x75 0x65 ...`) are packets too: a row is covered when a
vector has the bytes the row spells out, or cites that manual line in its sources (rows that
hold one field of a multi-row packet, or whose bytes are wrong, are matched by line).
Exit status 1 when anything is missing. Not part of `make test`: users do not have the manuals.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from .spec import ROOT, load_spec
from .vectors import load_vectors

PAIR = re.compile(r"\(\s*0x([0-9A-Fa-f]{2})\s*[,.]\s*0x([0-9A-Fa-f]{2})\s*\)")
HEADING = re.compile(r"^\s*(#|\[|\d+(\.\d+)+\s|<b>\d|\*\*)")
# MS-CIP style: a title line ending in the message type and code as one number ("PING COMMAND
# 0x0102", "Scaled Pressure Data Message 0xA286", table-of-contents lines with a page number).
CODE_HEADING = re.compile(
    r"^(?:Table \d+\s*[-\u2013]\s*)?[A-Za-z][A-Za-z0-9 /]*\s0x([0-9A-Fa-f]{2})([0-9A-Fa-f]{2})\b[.\s\d]*$"
)


def headings(text: str):
    for lineno, line in enumerate(text.splitlines(), 1):
        m = CODE_HEADING.match(line.strip())
        if m:
            yield lineno, int(m.group(1), 16), int(m.group(2), 16), line.strip()
            continue
        if not HEADING.match(line):
            continue
        for m in PAIR.finditer(line):
            yield lineno, int(m.group(1), 16), int(m.group(2), 16), line.strip()


def quoted_packets(text: str, sync: bytes):
    pattern = re.compile(sync.hex() + r"[0-9A-Fa-f ]{8,}", re.I)
    for m in pattern.finditer(text):
        raw = m.group(0).strip()
        hx = re.sub(r"\s", "", raw).lower()
        yield text.count("\n", 0, m.start()) + 1, hx, raw


def _row_bytes(cells: str) -> bytes:
    out = bytearray()
    for cell in re.sub(r"<[^>]+>", " ", cells).split("\t"):
        after_hex = False
        for tok in cell.split():
            tok = tok.strip(",;")
            if re.fullmatch(r"0x[0-9A-Fa-f]+", tok) and len(tok) % 2 == 0:
                out += bytes.fromhex(tok[2:])
                after_hex = True
            elif after_hex and re.fullmatch(r"[0-9A-Fa-f]{2}", tok):
                out += bytes.fromhex(tok)
            else:
                after_hex = False
    return bytes(out)


def table_rows(text: str, sync: bytes):
    """Rows of example tables: a line with the sync bytes as `0x75<tab>0x65` cells, plus the
    rows right after it that continue the same packet (a further field: empty header cells, no
    sync). The bytes are read in order from `0x..` tokens (several bytes when longer) and the
    bare two-digit hex tokens that follow one inside the same cell (`0x3E 7A 63 A0`).
    Yields (first line, all lines, hex, first row text)."""
    start = re.compile(r"\s+".join(f"0x{b:02X}" for b in sync), re.I)
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        m = start.search(lines[i])
        if not m:
            i += 1
            continue
        data = _row_bytes(lines[i][m.start() :])
        rows = [i + 1]
        j = i + 1
        while j < len(lines) and not start.search(lines[j]) and re.match(r"[^\t]*(Field|Data)[^\t]*\t\t", lines[j]):
            data += _row_bytes(lines[j].split("\t", 1)[1])
            rows.append(j + 1)
            j += 1
        yield i + 1, rows, data.hex(), lines[i].strip()
        i = j


def byte_tables(text: str, sync: bytes):
    """Example tables with one row per byte (MS-CIP): `0<tab>Sync1<tab>0xA5<tab>...`, then rows
    `N<tab>name<tab>0xVV<tab>...` (the byte number may be missing) up to the checksum. Yields
    (first line, all lines, hex, first row text), like table_rows."""
    first = re.compile(r"^0\t[^\t]*\t0x%02X\b" % sync[0], re.I)
    row = re.compile(r"^(\d*)\t[^\t]*\t0x([0-9A-Fa-f]{2})\b")
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        if not first.match(lines[i]):
            i += 1
            continue
        data = bytearray()
        rows = []
        j = i
        while j < len(lines):
            m = row.match(lines[j])
            if not m:
                break
            data.append(int(m.group(2), 16))
            rows.append(j + 1)
            j += 1
        if data[: len(sync)] == sync:
            yield i + 1, rows, data.hex(), lines[i].strip()
        i = j


def packet_lines(text: str, sync: bytes) -> dict[str, list[int]]:
    """Where each packet's bytes appear in a manual (quoted strings and table rows)."""
    where: dict[str, list[int]] = {}
    for lineno, hx, _ in quoted_packets(text, sync):
        where.setdefault(hx, []).append(lineno)
    for _, rows, hx, _ in [*table_rows(text, sync), *byte_tables(text, sync)]:
        where.setdefault(hx, []).extend(rows)
    return where


def covered_descriptor(proto: dict, set_id: int, desc: int) -> bool:
    sets = {s["id"]: s for s in proto["sets"]}
    if set_id in sets and any(f["id"] == desc for f in sets[set_id]["fields"]):
        return True
    kind = next((k for k, r in proto["set_kinds"].items() if r["first"] <= set_id <= r["last"]), None)
    if any(r["id"] == desc and r["applies_to"] == kind for r in proto["reserved_fields"]):
        return True
    shared = proto.get("shared_data")
    if shared and kind == "data" and desc >= shared["first_descriptor"] and shared["set"] in sets:
        return any(f["id"] == desc for f in sets[shared["set"]]["fields"])
    return False


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="make audit", description=__doc__.splitlines()[0])
    ap.add_argument("--manuals", default=str(ROOT.parent / "shared" / "manuals"))
    ap.add_argument("--verbose", action="store_true", help="also list what is covered")
    ap.add_argument(
        "--kinds",
        default="",
        help="comma-separated set kinds to audit (command, data); default: every kind",
    )
    args = ap.parse_args(argv)
    manuals = Path(args.manuals)
    if not manuals.is_dir():
        print(f"audit: no manuals directory at {manuals}", file=sys.stderr)
        return 2
    ir = load_spec()
    vectors = load_vectors(ir, ROOT / "tests" / "vectors")
    vector_hex = {c["hex"] for c in vectors}
    vector_quoted = {re.sub(r"\s", "", c.get("quoted") or "").lower() for c in vectors}
    cited = {(src["manual"], src.get("line")) for c in vectors for src in c.get("sources") or []}
    missing = 0
    total_h = total_p = total_r = 0
    for proto in ir["protocols"]:
        sync = bytes(proto["framing"]["sync"])
        kinds = set(filter(None, args.kinds.split(","))) or set(proto["set_kinds"])
        unknown = kinds - set(proto["set_kinds"])
        if unknown:
            print(
                f"audit: unknown set kind {', '.join(sorted(unknown))} (expected {', '.join(proto['set_kinds'])})",
                file=sys.stderr,
            )
            return 2
        set_at = proto["framing"]["set_offset"]

        def in_scope(set_id: int | None, proto=proto, kinds=kinds) -> bool:
            kind = next((k for k, r in proto["set_kinds"].items() if r["first"] <= (set_id or -1) <= r["last"]), None)
            return kind in kinds

        def packet_set(hx: str, set_at=set_at) -> int | None:
            return int(hx[2 * set_at : 2 * set_at + 2], 16) if len(hx) >= 2 * set_at + 2 else None

        for dev in proto["devices"]:
            path = manuals / dev["manual"]
            if not path.exists():
                print(f"audit: {dev['manual']} not found in {manuals}", file=sys.stderr)
                missing += 1
                continue
            text = path.read_text(encoding="utf-8", errors="replace")
            seen = set()
            for lineno, s, d, line in headings(text):
                if s == (proto.get("shared_data") or {}).get("set") and d < 0xD0 or not in_scope(s):
                    continue
                total_h += 1
                ok = covered_descriptor(proto, s, d)
                if not ok and (s, d) not in seen:
                    print(f"{dev['manual']}:{lineno}: heading (0x{s:02X},0x{d:02X}) not in the spec: {line[:90]}")
                    missing += 1
                seen.add((s, d))
            for lineno, hx, raw in quoted_packets(text, sync):
                if not in_scope(packet_set(hx)):
                    continue
                total_p += 1
                ok = hx in vector_hex or hx in vector_quoted or hx[: len(hx) // 2 * 2] in vector_hex
                if not ok:
                    print(f"{dev['manual']}:{lineno}: quoted packet not in tests/vectors: {raw}")
                    missing += 1
                elif args.verbose:
                    print(f"{dev['manual']}:{lineno}: covered: {raw}")
            for lineno, rows, hx, raw in [*table_rows(text, sync), *byte_tables(text, sync)]:
                if not in_scope(packet_set(hx)):
                    continue
                total_r += 1
                ok = hx in vector_hex or hx in vector_quoted or any((dev["manual"], r) in cited for r in rows)
                if not ok:
                    print(f"{dev['manual']}:{lineno}: example table row not in tests/vectors: {hx}  ({raw[:60]})")
                    missing += 1
                elif args.verbose:
                    print(f"{dev['manual']}:{lineno}: covered row: {hx}")
            # A vector that quotes a packet printed in this manual must cite the line it is on.
            where = packet_lines(text, sync)
            for c in vectors:
                if not in_scope(packet_set(c["hex"])):
                    continue
                lines = where.get(c["hex"]) or where.get(re.sub(r"\s", "", c.get("quoted") or "").lower())
                cites = [
                    src["line"] for src in c.get("sources") or [] if src["manual"] == dev["manual"] and src.get("line")
                ]
                if lines and cites and not set(cites) & set(lines):
                    print(
                        f"{c['file']}:{c['line']}: vector {c['name']} cites {dev['manual']}:{', '.join(map(str, cites))}, "
                        f"but its packet is printed at line {', '.join(map(str, sorted(set(lines))))}"
                    )
                    missing += 1
    print(
        f"audit: {total_h} headings, {total_p} quoted packets, {total_r} example table rows, {missing} not covered",
        file=sys.stderr,
    )
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
