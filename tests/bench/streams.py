"""Writes the benchmark streams (issue 8) into build/bench/, deterministically.

    python -m tests.bench.streams [--out build/bench] [--scale 1.0]      (from the project root)

Streams (MIP, little packets to large ones):
  accel_gyro          1,000,000 packets of set 0x80, each scaled accel (0x04) + scaled gyro (0x05):
                      4 + 2 * 14 + 2 = 34 bytes a packet, the stream the vendor SDK was measured on
  mixed               200,000 packets cycling filter 0x82 (position, velocity, attitude, their
                      uncertainties, status, GPS time), GNSS 0x81 (position, velocity, DOP, UTC and
                      GPS time, fix info) and GNSS receiver 0x91 with a satellite status list
  accel_gyro_garbage  the accel_gyro packets with 0..15 garbage bytes between packets
  mixed_garbage       the mixed packets likewise

Garbage never contains the sync byte 0x75 except as a deliberate false sync (0x75 0x65 set
length), whose stated length runs into the next packet, so the parser has to resynchronise; the
expected packet count is therefore exactly the number of packets written.

Each stream is `<name>.bin` with a sidecar `<name>.json`: packets, fields, bytes, garbage_bytes,
packet_bytes. Benchmarks assert the packet and field counts they saw against it (so the work
cannot be optimised away and a wrong parser cannot post a fast figure).

Field contents are random bytes of each field's fixed size from generated/ir.json, kept only
when the Python decoder accepts them (bool bytes, for instance, must be 0 or 1), so every field
of every stream decodes to a typed value in every language.
"""

from __future__ import annotations

import argparse
import json
import random
import sys
from pathlib import Path

from tests.helpers.generated import python_package
from tests.helpers.packets import fletcher16

ROOT = Path(__file__).resolve().parents[2]
mipcodec = python_package("mipcodec")

SYNC = b"\x75\x65"

# (set, [descriptors]) packet kinds of the mixed stream, in cycle order.
MIXED = [
    (0x82, [0x11, 0x10, 0x01, 0x02, 0x03, 0x05, 0x08, 0x09, 0x0A, 0x0D, 0x0E]),
    (0x82, [0x11, 0x10, 0x01, 0x02, 0x03, 0x05, 0x08, 0x09, 0x0A, 0x0D, 0x0E]),
    (0x81, [0x09, 0x08, 0x03, 0x05, 0x07, 0x0B, 0x0D]),
    (0x82, [0x11, 0x10, 0x01, 0x02, 0x03, 0x05, 0x08, 0x09, 0x0A, 0x0D, 0x0E]),
    (0x91, [0x09, 0x03, 0x05, 0x0B, 0x20, 0x20, 0x20, 0x20]),
]
ACCEL_GYRO = [(0x80, [0x04, 0x05])]


def field_sizes() -> dict[tuple[int, int], int]:
    ir = json.loads((ROOT / "generated" / "ir.json").read_text())
    mip = next(p for p in ir["protocols"] if p["package"] == "mipcodec")
    out = {}
    for s in mip["sets"]:
        for f in s["fields"]:
            size = f.get("size")
            if size and size["fixed"]:
                out[(s["id"], f["id"])] = size["min"]
    return out


def field_data(rng: random.Random, set_id: int, descriptor: int, size: int) -> bytes:
    for _ in range(1000):
        data = bytes(rng.getrandbits(8) for _ in range(size))
        try:
            entry = mipcodec.decode_field(set_id, descriptor, data)
        except mipcodec.DecodeError:
            continue
        # decode_field reports a field that does not decode as a RawField (it does not raise)
        if isinstance(entry, mipcodec.RawField):
            continue
        return data
    raise SystemExit(f"streams.py: no random bytes decode as field 0x{set_id:02x},0x{descriptor:02x}")


def templates(rng: random.Random, kinds, sizes, variants: int) -> list[tuple[list[bytes], int]]:
    """`variants` distinct packets of each kind: (packet bytes, field count)."""
    out = []
    for set_id, descs in kinds:
        group = []
        for _ in range(variants):
            b = mipcodec.PacketBuilder(set_id)
            for d in descs:
                b.add_field(d, field_data(rng, set_id, d, sizes[(set_id, d)]))
            group.append(b.build())
        out.append((group, len(descs)))
    return out


def garbage(rng: random.Random) -> bytes:
    n = rng.randrange(16)
    g = bytearray(rng.randbytes(n).replace(b"\x75", b"\x76"))
    if n >= 4 and rng.random() < 0.25:
        # a false sync whose length runs past the garbage into the next packet
        g[0:4] = SYNC + bytes([rng.getrandbits(8), 0xF0 | rng.getrandbits(4)])
    return bytes(g)


def defuse_false_syncs(buf: bytearray, offsets: list[int]) -> None:
    """A false sync spans 246+ bytes of the packets behind it; about one in 65536 has a valid
    checksum by chance and would be a packet that hides the real ones. Change its set byte
    until it does not (later offsets first: a change can only affect earlier false syncs)."""
    for off in reversed(offsets):
        for _ in range(256):
            end = off + 4 + buf[off + 3]
            if end + 2 > len(buf) or fletcher16(buf[off:end]) != buf[end : end + 2]:
                break
            buf[off + 2] = (buf[off + 2] + 1) & 0xFF


def write(out: Path, name: str, kinds, count: int, with_garbage: bool, seed: int, sizes) -> None:
    rng = random.Random(seed)
    groups = templates(rng, kinds, sizes, 64)
    parts = []
    packets = fields = garbage_bytes = offset = 0
    false_syncs: list[int] = []
    for i in range(count):
        group, nfields = groups[i % len(groups)]
        if with_garbage:
            g = garbage(rng)
            if g[:2] == SYNC:
                false_syncs.append(offset)
            parts.append(g)
            offset += len(g)
            garbage_bytes += len(g)
        parts.append(group[rng.randrange(len(group))])
        offset += len(parts[-1])
        packets += 1
        fields += nfields
    buf = bytearray(b"".join(parts))
    if with_garbage:
        defuse_false_syncs(buf, false_syncs)
    buf = bytes(buf)
    (out / f"{name}.bin").write_bytes(buf)
    meta = {
        "name": name,
        "packets": packets,
        "fields": fields,
        "bytes": len(buf),
        "garbage_bytes": garbage_bytes,
        "packet_bytes": len(buf) - garbage_bytes,
    }
    (out / f"{name}.json").write_text(json.dumps(meta, indent=1) + "\n")
    print(f"streams.py: {name}: {packets} packets, {fields} fields, {len(buf)} bytes", file=sys.stderr)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(ROOT / "build" / "bench"))
    ap.add_argument("--scale", type=float, default=1.0, help="multiply the packet counts (quick runs)")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    sizes = field_sizes()
    n_small = max(1, int(1_000_000 * args.scale))
    n_mixed = max(1, int(200_000 * args.scale))
    write(out, "accel_gyro", ACCEL_GYRO, n_small, False, 1, sizes)
    write(out, "mixed", MIXED, n_mixed, False, 2, sizes)
    write(out, "accel_gyro_garbage", ACCEL_GYRO, n_small, True, 3, sizes)
    write(out, "mixed_garbage", MIXED, n_mixed, True, 4, sizes)
    return 0


if __name__ == "__main__":
    sys.exit(main())
