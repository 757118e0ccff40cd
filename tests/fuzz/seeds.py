"""Seed corpora for the fuzz targets, from the golden vectors and the stream corpus (generator.vectors.load_corpus).

    python -m tests.fuzz.seeds [--out build/fuzz/corpus]      (from the project root)

writes one file per vector into <out>/<package>/<target>/:
  parser/<vector>: a control byte, then the vector's bytes. The control byte (low 6 bits: chunk
                   plan, top 2 bits: device; see tests/fuzz/c/fuzz_parser.c) varies from vector to
                   vector, and a vector with a device gets that device (vectors of a device-specific
                   layout then decode the way the vector says).
  parser/<vector>.wrapped: the control byte, the set and the payload of the vector's first packet:
                   the harness wraps these into a packet with a valid checksum, so mutations of
                   real field data reach the decoders without the fuzzer repairing checksums.
  json/<vector>:   the vector's expected canonical JSON lines, one per line.
  decode/...:      the parser seeds (the lean `decode` target reads the same input format).
Stream cases under tests/streams/<protocol>/ (*.bin), when that directory exists, are added to the
parser corpus the same way. generator/loader/: the real spec/mscip files and the hostile spec corpus for
the generator's front end (tests/fuzz/spec/harness.py). Existing seed directories are replaced.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import shutil
import sys
from pathlib import Path

from generator.vectors import load_corpus
from tests.helpers.packets import checksum

ROOT = Path(__file__).resolve().parents[2]


def control_byte(name: str, device_index: int) -> int:
    """Chunk plan from the name's hash; device in the top two bits (0: any device)."""
    low = hashlib.sha256(name.encode()).digest()[0] & 0x3F
    return (device_index << 6) | low


def first_packet(framing: dict, data: bytes) -> bytes | None:
    """(set, payload...) of the first complete packet with a valid checksum in data, if any."""
    sync = bytes(framing["sync"])
    header = framing["header_size"]
    for i in range(len(data)):
        if not data.startswith(sync, i) or len(data) - i < header:
            continue
        n = data[i + framing["length_offset"]]
        body = data[i : i + header + n]
        if len(data) - i < header + n + 2:
            continue
        if data[i + header + n : i + header + n + 2] == checksum(framing, body):
            return bytes([data[i + framing["set_offset"]]]) + body[header:]
    return None


def write(out: Path) -> dict[tuple[str, str], int]:
    ir = json.loads((ROOT / "generated" / "ir.json").read_text())
    protocols = {p["name"]: p for p in ir["protocols"]}
    counts: dict[tuple[str, str], int] = {}
    dirs: dict[tuple[str, str], Path] = {}
    for p in protocols.values():
        for target in ("parser", "decode", "json"):
            d = out / p["package"] / target
            if d.exists():
                shutil.rmtree(d)
            d.mkdir(parents=True)
            dirs[(p["package"], target)] = d
            counts[(p["package"], target)] = 0

    def add(package: str, target: str, name: str, data: bytes) -> None:
        for t in ("parser", "decode") if target == "parser" else (target,):
            (dirs[(package, t)] / name).write_bytes(data)
            counts[(package, t)] += 1

    for case in load_corpus(ir, ROOT):
        proto = protocols[case["protocol"]]
        package = proto["package"]
        devices = [d["id"] for d in proto["devices"]]
        device = devices.index(case["device"]) + 1 if case.get("device") in devices else 0
        control = bytes([control_byte(case["name"], device)])
        data = bytes.fromhex(case["hex"])
        add(package, "parser", case["name"], control + data)
        packet = first_packet(proto["framing"], data)
        if packet is not None:
            add(package, "parser", case["name"] + ".wrapped", control + packet)
        if case["expect"]:
            add(package, "json", case["name"], ("\n".join(case["expect"]) + "\n").encode())
    streams = ROOT / "tests" / "streams"
    if streams.is_dir():
        for name, proto in protocols.items():
            for f in sorted((streams / name).glob("*.bin")) if (streams / name).is_dir() else []:
                seed = f"stream-{f.stem}"
                add(proto["package"], "parser", seed, bytes([control_byte(seed, 0)]) + f.read_bytes())
    d = out / "generator" / "loader"  # the generator's front end (tests/fuzz/spec/harness.py)
    if d.exists():
        shutil.rmtree(d)
    d.mkdir(parents=True)
    from tests.fuzz.spec.harness import seeds as spec_seeds

    for name, data in spec_seeds().items():
        (d / name).write_bytes(data)
    counts[("generator", "loader")] = len(list(d.iterdir()))
    return counts


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=ROOT / "build" / "fuzz" / "corpus")
    args = ap.parse_args()
    counts = write(args.out)
    for (package, target), n in sorted(counts.items()):
        print(f"seeds: {package}/{target}: {n} files in {args.out / package / target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
