"""Check a device capture: it decodes completely and identically in all four languages.

    python tests/conformance/check_capture.py [--device ID] FILE

Decodes FILE with `tests/conformance/decode LANG` for every target of generator/targets/__init__.py and fails (exit 1,
one line per problem) unless
- the four outputs are byte-identical,
- no byte is skipped (no `skipped` line), no packet has trailing bytes, and no field is left raw
  (`data` + `error`: unknown descriptor or a decode error),
- the C encoder turns the decoded lines back into exactly the bytes of FILE.
Prints a summary: packets per set and fields per (set, descriptor). Exit 2 on usage errors.
"""

from __future__ import annotations

import argparse
import collections
import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))  # run as a script: the target registry is generator/targets/__init__.py
from generator.targets import NAMES as LANGS  # noqa: E402

sys.path.pop(0)


def run(cmd: list[str], stdin: bytes | None = None) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, input=stdin, capture_output=True)


def problems_in(lines: list[str]) -> tuple[list[str], collections.Counter, collections.Counter]:
    problems: list[str] = []
    packets: collections.Counter = collections.Counter()
    fields: collections.Counter = collections.Counter()
    for line in lines:
        rec = json.loads(line)
        where = f"offset {rec['offset']}"
        if "skipped" in rec:
            problems.append(f"{where}: {len(rec['skipped']) // 2} skipped bytes")
            continue
        packets[rec["set"]] += 1
        for f in rec["fields"]:
            if "trailing" in f:
                problems.append(f"{where}: trailing bytes ({f['error']})")
            elif "data" in f:
                problems.append(
                    f"{where}: field (0x{rec['set']:02X},0x{f['descriptor']:02X}) left raw: {f.get('error')}"
                )
            else:
                fields[(rec["set"], f["descriptor"], f["name"])] += 1
    return problems, packets, fields


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="check_capture", description=__doc__.splitlines()[0])
    ap.add_argument("--device", help="decode as this device (default: any)")
    ap.add_argument("file", type=Path)
    args = ap.parse_args(argv)
    if not args.file.is_file():
        print(f"check_capture: no such file: {args.file}", file=sys.stderr)
        return 2
    extra = ["--device", args.device] if args.device else []
    outputs: dict[str, bytes] = {}
    failed = False
    for lang in LANGS:
        proc = run([str(ROOT / "tests/conformance/decode"), lang, str(args.file), *extra])
        if proc.returncode != 0:
            print(f"{lang}: decode failed: {proc.stderr.decode(errors='replace').strip()}")
            failed = True
        outputs[lang] = proc.stdout
    if failed:
        return 1
    for lang in LANGS[1:]:
        if outputs[lang] != outputs["c"]:
            a, b = outputs["c"].decode().splitlines(), outputs[lang].decode().splitlines()
            first = next((i for i, (x, y) in enumerate(zip(a, b)) if x != y), min(len(a), len(b)))
            print(f"{lang} differs from c at line {first + 1}")
            failed = True
    lines = outputs["c"].decode().splitlines()
    problems, packets, fields = problems_in(lines)
    for p in problems[:50]:
        print(p)
    if len(problems) > 50:
        print(f"... and {len(problems) - 50} more problems")
    enc = run([str(ROOT / "tests/conformance/encode"), "c"], stdin=outputs["c"])
    if enc.returncode != 0 or enc.stdout != args.file.read_bytes():
        print("c encode of the decoded lines does not reproduce the capture")
        failed = True
    total = sum(packets.values())
    print(f"{args.file.name}: {args.file.stat().st_size} bytes, {total} packets, {sum(fields.values())} fields")
    for s, n in sorted(packets.items()):
        print(f"  set 0x{s:02X}: {n} packets")
    for (s, d, name), n in sorted(fields.items()):
        print(f"    (0x{s:02X},0x{d:02X}) {name}: {n}")
    if problems or failed:
        print(f"FAIL: {len(problems)} problems" + (", languages disagree or re-encoding differs" if failed else ""))
        return 1
    print("OK: every byte decoded, identically in c, cpp, python and rust")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
