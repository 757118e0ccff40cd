"""Smoke test of an installed generated Python package, run by the clean virtualenv's interpreter.

    python smoke.py PACKAGE CASES.json accelerated|pure

Uses only the standard library and the installed package (tests/consumer/test_python_package.py
builds the wheel, installs it with --no-index and runs this). Checks that the package is the
installed copy (not a source tree on sys.path) with its py.typed marker, that its C accelerator is
in use or not as expected, then decodes every golden vector of CASES.json (name, hex, expected
canonical JSON lines) whole and fed one chunk at a time and encodes the lines back to the bytes.
Prints one summary line; exits 1 with the first difference.
"""

from __future__ import annotations

import importlib
import json
import sys
from pathlib import Path


def fail(message: str) -> None:
    print(f"smoke: {message}", file=sys.stderr)
    sys.exit(1)


def main(argv: list[str]) -> int:
    if len(argv) != 4 or argv[3] not in ("accelerated", "pure"):
        print("usage: smoke.py PACKAGE CASES.json accelerated|pure", file=sys.stderr)
        return 2
    name, cases_path, mode = argv[1], argv[2], argv[3]  # a case: name, hex, device (or null), expect
    pkg = importlib.import_module(name)
    where = Path(pkg.__file__).resolve().parent
    if Path(sys.prefix).resolve() not in where.parents:
        fail(f"{name} imported from {where}, not from the virtualenv {sys.prefix}")
    if not (where / "py.typed").is_file():
        fail(f"{where}/py.typed is missing: type checkers would skip the package")
    if pkg.ACCELERATED != (mode == "accelerated"):
        fail(f"{name}.ACCELERATED is {pkg.ACCELERATED}, expected {mode}")
    cases = json.loads(Path(cases_path).read_text(encoding="utf-8"))
    if not cases:
        fail(f"{cases_path} holds no case")
    for case in cases:
        data = bytes.fromhex(case["hex"])
        lines = pkg.decode_bytes(data, case["device"])
        if lines != case["expect"]:
            fail(f"{case['name']}: decode printed {lines}, expected {case['expect']}")
        decoder = pkg.Decoder(case["device"])
        events = [e for i in range(len(data)) for e in decoder.feed(data[i : i + 1])] + decoder.flush()
        chunked = [pkg.codec.packets.event_line(e) if isinstance(e, pkg.Skip) else e.line() for e in events]
        if chunked != lines:
            fail(f"{case['name']}: fed byte by byte, Decoder gave {chunked}, expected {lines}")
        encoded = pkg.encode_lines(case["expect"])
        if encoded != data:
            fail(f"{case['name']}: encode gave {encoded.hex()}, expected {case['hex']}")
    print(
        f"smoke: {name} from {where}: {len(cases)} vectors decoded (whole and byte by byte) and encoded back,"
        f" accelerated={pkg.ACCELERATED}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
