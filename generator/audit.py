"""`make audit MANUALS=dir`: does the spec and the vector corpus cover the manuals?

Lists every `(0xSS,0xDD)` heading in the manuals and every quoted packet (contiguous hex strings
starting with a protocol's sync bytes), and reports those that no spec field or golden vector
covers. A heading is covered when the IR has that descriptor (in its set, the shared data set, or
as a reserved field). A quoted packet is covered when a vector has the same bytes, or names the
exact string in `quoted:` (for published strings that cannot be written as bytes).
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


def headings(text: str):
    for lineno, line in enumerate(text.splitlines(), 1):
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
    args = ap.parse_args(argv)
    manuals = Path(args.manuals)
    if not manuals.is_dir():
        print(f"audit: no manuals directory at {manuals}", file=sys.stderr)
        return 2
    ir = load_spec()
    vectors = load_vectors(ir, ROOT / "tests" / "vectors")
    vector_hex = {c["hex"] for c in vectors}
    vector_quoted = {re.sub(r"\s", "", c.get("quoted") or "").lower() for c in vectors}
    missing = 0
    total_h = total_p = 0
    for proto in ir["protocols"]:
        sync = bytes(proto["framing"]["sync"])
        for dev in proto["devices"]:
            path = manuals / dev["manual"]
            if not path.exists():
                print(f"audit: {dev['manual']} not found in {manuals}", file=sys.stderr)
                missing += 1
                continue
            text = path.read_text(encoding="utf-8", errors="replace")
            seen = set()
            for lineno, s, d, line in headings(text):
                if s == proto.get("shared_data", {}).get("set") and d < 0xD0:
                    continue
                total_h += 1
                ok = covered_descriptor(proto, s, d)
                if not ok and (s, d) not in seen:
                    print(f"{dev['manual']}:{lineno}: heading (0x{s:02X},0x{d:02X}) not in the spec: {line[:90]}")
                    missing += 1
                seen.add((s, d))
            for lineno, hx, raw in quoted_packets(text, sync):
                total_p += 1
                ok = hx in vector_hex or hx in vector_quoted or hx[: len(hx) // 2 * 2] in vector_hex
                if not ok:
                    print(f"{dev['manual']}:{lineno}: quoted packet not in tests/vectors: {raw}")
                    missing += 1
                elif args.verbose:
                    print(f"{dev['manual']}:{lineno}: covered: {raw}")
    print(f"audit: {total_h} headings, {total_p} quoted packets, {missing} not covered", file=sys.stderr)
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
