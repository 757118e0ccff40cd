"""Sample grouping of continuation packets (docs/conformance.md §6) through `decode --samples`,
in every language, against sample numbers derived by hand from the rule.

The stream is built here from hand-written fields (Fletcher-16 over sync, header and payload by
the tests' one Fletcher-16, tests/helpers/packets.py). Shared descriptors: 0xD5 reference timestamp (u64 ns, a
sample key), 0xD6 reference time delta (u64 ns, not a key); 0x04/0x05/0x06 are the scaled
accel/gyro/mag vectors of set 0x80; 0xA0 is the system data set.
"""

import json
import subprocess
from pathlib import Path

import pytest

from tests.helpers import packets
from tests.helpers.langs import langs

ROOT = Path(__file__).resolve().parents[2]
LANGS = langs()  # the target registry (generator/targets/__init__.py)


# The MIP framing, written down here (docs/conformance.md §1): sync 75 65, set byte, payload
# length byte, Fletcher-16 sum1 then sum2.
MIP_FRAMING = {
    "sync": [0x75, 0x65],
    "header_size": 4,
    "set_offset": 2,
    "length_offset": 3,
    "checksum": {"order": ["sum1", "sum2"]},
}


def packet(set_id: int, *fields: str) -> bytes:
    return packets.packet(MIP_FRAMING, set_id, bytes.fromhex("".join(fields)))


def d5(ns: int) -> str:  # reference timestamp: length 10, descriptor D5, u64 big-endian
    return "0AD5" + f"{ns:016X}"


D6 = "0AD6" + "00000000007A1200"  # reference time delta 8,000,000 ns (the capture's value)
ACCEL = "0E04" + "3F800000" * 3
GYRO = "0E05" + "00000000" * 3
MAG = "0E06" + "3F000000" * 3
SHORT_D5 = "09D5" + "00000000000001"  # D5 with 7 data bytes: not a key (wrong size)

# (packet, expected sample number or None for a command packet), with the reason.
STREAM = [
    (packet(0x80, d5(1000), D6, ACCEL, GYRO), 0),  # first packet: sample 0
    (packet(0x80, d5(1000), MAG), 0),  # same set, same key 0AD5..03E8: continues 0
    (packet(0x80, d5(2000), ACCEL), 1),  # new key: sample 1
    (packet(0xA0, d5(2000)), 2),  # same key, other set: its own sample 2
    (packet(0x80, d5(2000), GYRO), 1),  # previous 0x80 packet had this key: continues 1
    (packet(0x80, ACCEL), 3),  # no shared run, no key: sample 3
    (packet(0x80, d5(2000), MAG), 4),  # previous 0x80 packet had no key: sample 4
    (packet(0x80, D6, d5(3000), ACCEL), 5),  # key is D5 even after D6 in the leading run: 5
    (packet(0x80, D6, d5(3000), GYRO), 5),  # continues 5
    (packet(0x80, ACCEL, d5(3000)), 6),  # D5 after a standard field: not leading, no key: 6
    (packet(0x01, "04F10100"), None),  # a command-set packet has no sample
    (packet(0x80, SHORT_D5, d5(3000), MAG), 7),  # wrong-size D5 skipped, key D5(3000); prev had none: 7
    (packet(0x80, d5(3000), ACCEL), 7),  # same key: continues 7
]


@pytest.fixture(scope="module")
def stream_file(tmp_path_factory):
    f = tmp_path_factory.mktemp("samples") / "continuation.bin"
    f.write_bytes(b"".join(p for p, _ in STREAM))
    return f


def decode(lang: str, path: Path, *extra: str) -> str:
    proc = subprocess.run([str(ROOT / "tests/conformance/decode"), lang, str(path), *extra], capture_output=True)
    assert proc.returncode == 0, proc.stderr.decode(errors="replace")
    return proc.stdout.decode()


@pytest.mark.parametrize("lang", LANGS)
def test_sample_numbers(lang, stream_file):
    lines = [json.loads(line) for line in decode(lang, stream_file, "--samples").splitlines()]
    assert [rec.get("sample") for rec in lines] == [n for _, n in STREAM]
    offsets = [0]
    for p, _ in STREAM[:-1]:
        offsets.append(offsets[-1] + len(p))
    assert [rec["offset"] for rec in lines] == offsets


@pytest.mark.parametrize("lang", LANGS)
def test_samples_only_add_the_sample_key(lang, stream_file):
    plain = decode(lang, stream_file).splitlines()
    numbered = decode(lang, stream_file, "--samples").splitlines()
    for a, b, (_, n) in zip(plain, numbered, STREAM):
        expect = a if n is None else a.replace(',"fields":', f',"sample":{n},"fields":', 1)
        assert b == expect


def test_published_style_continuation_vector_is_one_sample(tmp_path):
    """The shared.yaml continuation vector (two packets, every shared field repeated) is one sample."""
    import yaml

    cases = yaml.safe_load((ROOT / "tests/vectors/mip/shared.yaml").read_text())["cases"]
    case = next(c for c in cases if c["name"] == "continuation_packets_share_timestamps")
    f = tmp_path / "c.bin"
    f.write_bytes(bytes.fromhex("".join(case["hex"].split())))
    for lang in LANGS:
        samples = [json.loads(line).get("sample") for line in decode(lang, f, "--samples").splitlines()]
        assert samples == [0, 0], lang
