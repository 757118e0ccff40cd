"""The benchmark streams (tests/bench/streams.py) are what their sidecars say (run by `make test-bench`).

Every benchmark checks the packets and fields it saw against the sidecar `<name>.json`, so a
wrong sidecar would fail every language's benchmark, and a stream whose garbage hid a packet
would let a wrong parser pass. Here, on a small scale:
  - the clean streams are walked with nothing but the framing rules (sync, length byte, field
    length bytes) and the tests' byte-serial Fletcher-16 (tests/helpers/packets.py): every packet is where the previous
    one ends, its checksum holds, and the packet and field counts and byte total equal the sidecar;
  - the garbage streams give exactly the sidecar's packets to the Python stream parser (no false
    sync turned into a packet, none lost), with packet bytes + garbage bytes = file size;
  - every field of every stream decodes to a typed value (the benchmarks count errors).
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from tests.helpers.generated import python_package
from tests.helpers.packets import fletcher16

ROOT = Path(__file__).resolve().parents[2]
mipcodec = python_package("mipcodec")

SCALE = "0.002"  # 2000 accel+gyro packets, 400 mixed ones


@pytest.fixture(scope="module")
def streams(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("bench")
    subprocess.run(
        [sys.executable, "-m", "tests.bench.streams", "--out", str(out), "--scale", SCALE],
        check=True,
        capture_output=True,
        cwd=ROOT,
    )
    return out


def sidecar(out: Path, name: str) -> dict:
    return json.loads((out / f"{name}.json").read_text())


@pytest.mark.parametrize("name", ["accel_gyro", "mixed"])
def test_clean_streams_are_back_to_back_packets(streams: Path, name: str) -> None:
    data = (streams / f"{name}.bin").read_bytes()
    meta = sidecar(streams, name)
    pos = packets = fields = 0
    while pos < len(data):
        assert data[pos : pos + 2] == b"\x75\x65", f"no sync at offset {pos}"
        payload_len = data[pos + 3]
        end = pos + 4 + payload_len
        assert data[end : end + 2] == fletcher16(data[pos:end]), f"bad checksum at offset {pos}"
        fpos = pos + 4
        while fpos < end:  # MIP field: length byte (header included), descriptor, data
            assert data[fpos] >= 2 and fpos + data[fpos] <= end, f"bad field at offset {fpos}"
            fpos += data[fpos]
            fields += 1
        packets += 1
        pos = end + 2
    assert (packets, fields, len(data)) == (meta["packets"], meta["fields"], meta["bytes"])
    assert meta["garbage_bytes"] == 0 and meta["packet_bytes"] == len(data)


@pytest.mark.parametrize("name", ["accel_gyro_garbage", "mixed_garbage"])
def test_garbage_streams_hold_exactly_the_sidecar_packets(streams: Path, name: str) -> None:
    data = (streams / f"{name}.bin").read_bytes()
    meta = sidecar(streams, name)
    clean = sidecar(streams, name.removesuffix("_garbage"))
    events = mipcodec.parse(data)
    packets = [e for e in events if isinstance(e, mipcodec.RawPacket)]
    assert len(packets) == meta["packets"] == clean["packets"]
    assert sum(len(p.data) for p in packets) == meta["packet_bytes"]
    assert meta["packet_bytes"] + meta["garbage_bytes"] == meta["bytes"] == len(data)
    assert meta["garbage_bytes"] > 0


@pytest.mark.parametrize("name", ["accel_gyro", "mixed", "accel_gyro_garbage", "mixed_garbage"])
def test_every_field_decodes(streams: Path, name: str) -> None:
    meta = sidecar(streams, name)
    decoded = [p for p in mipcodec.decode_all((streams / f"{name}.bin").read_bytes()) if isinstance(p, mipcodec.Packet)]
    entries = [f for p in decoded for f in p.fields]
    assert len(decoded) == meta["packets"]
    assert len(entries) == meta["fields"]
    assert all(isinstance(f, mipcodec.DecodedField) for f in entries)
