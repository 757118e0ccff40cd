"""The stream corpus (tests/streams/) and the golden vectors against an independent model of the
parser, and the corpus against the list of hostile inputs it must contain.

`frame()` below is a direct transcription of docs/conformance.md §1, written for this test and
sharing no code with the generator or the generated parsers. The expected events of every case
were written by hand; this test checks them against the prose contract a second way, so a
mistake in a hand-written case and a mistake in all four parsers alike cannot both pass. (The
four languages are held to the same cases, whole and in chunks of every size, by their own
generated test suites: `make test-c`, `test-cpp`, `test-python`, `test-rust`.)
"""

import json
import re
from pathlib import Path

import pytest

from generator.spec import load_spec
from generator.vectors import load_corpus
from tests.helpers.packets import checksum

ROOT = Path(__file__).resolve().parents[2]
IR = load_spec()
PROTOCOLS = {p["name"]: p for p in IR["protocols"]}
CASES = load_corpus(IR, ROOT)
STREAMS = [c for c in CASES if c["corpus"] == "streams"]


def crc24(data: bytes) -> int:
    """CRC-24Q (RTCM 10403): polynomial 0x1864CFB, register starting at 0, MSB first."""
    reg = 0
    for byte in data:
        for bit in range(7, -1, -1):
            top = (reg >> 23) & 1
            reg = (reg << 1) & 0xFFFFFF
            if top ^ ((byte >> bit) & 1):
                reg ^= 0x864CFB
    return reg


def foreign_at(data: bytes, i: int, framing: dict) -> int:
    """Size of the whole valid NMEA sentence or RTCM3 frame at data[i] (§1, foreign frames), else 0."""
    kinds = (framing.get("foreign_frames") or {}).get("kinds", [])
    if "rtcm3" in kinds and data[i] == 0xD3 and i + 3 <= len(data) and data[i + 1] < 4:
        size = ((data[i + 1] << 8) | data[i + 2]) + 6
        tail = data[i + size - 3 : i + size]
        ok = size >= 8 and i + size <= len(data) and crc24(data[i : i + size - 3]) == int.from_bytes(tail, "big")
        return size if ok else 0
    if "nmea" in kinds and data[i] in b"$!":
        end = i + 1
        while end < len(data) and 32 <= data[end] <= 126 and chr(data[end]) not in "$!*":
            end += 1
        tail = data[end : end + 5]
        size = end + 5 - i
        if size > framing["nmea_max"] or len(tail) < 5 or tail[0:1] != b"*" or tail[3:] != b"\r\n":
            return 0
        if not all(chr(c) in "0123456789abcdefABCDEF" for c in tail[1:3]):
            return 0
        xor = 0
        for c in data[i + 1 : end]:
            xor ^= c
        return size if xor == int(tail[1:3], 16) else 0
    return 0


def frame(data: bytes, framing: dict) -> list[tuple]:
    """Events of §1 for the whole input followed by the end of the stream: ("packet", offset,
    size), ("frame", offset, size) for an NMEA sentence or RTCM3 frame, and ("skip", offset,
    count), skip runs merged."""
    sync = bytes(framing["sync"])
    hsize, lpos = framing["header_size"], framing["length_offset"]
    events: list[tuple] = []
    skipped: list[int] = []

    def skip(i: int) -> None:
        skipped.append(i)

    def flush_skips() -> None:
        if skipped:
            events.append(("skip", skipped[0], len(skipped)))
            skipped.clear()

    pos = 0
    while pos < len(data):
        i = data.find(sync, pos)
        # no whole sync before `end`; at the end of the stream a partial one is skipped too
        end = i if i >= 0 else len(data)
        j = pos
        while j < end:  # where bytes would be skipped, a foreign frame is one event
            n = foreign_at(data, j, framing)
            if n:
                flush_skips()
                events.append(("frame", j, n))
                j += n
            else:
                skip(j)
                j += 1
        if i < 0 or j > end:  # the end, or a frame that ran over the sync
            pos = j
            continue
        if i + hsize > len(data):  # header incomplete at the end: a false sync
            skip(i)
            pos = i + 1
            continue
        length = data[i + lpos]
        total = hsize + length + 2
        if length > framing["max_payload"] or i + total > len(data):
            skip(i)
            pos = i + 1
            continue
        check = checksum(framing, data[i : i + hsize + length])
        if data[i + hsize + length : i + total] != check:
            skip(i)
            pos = i + 1
            continue
        flush_skips()
        events.append(("packet", i, total))
        pos = i + total
    flush_skips()
    return events


def expected_events(case: dict) -> list[tuple]:
    out = []
    lines = [json.loads(x) for x in case["expect"]]
    for k, ev in enumerate(lines):
        if "skipped" in ev:
            out.append(("skip", ev["offset"], len(ev["skipped"]) // 2))
        elif "nmea" in ev or "rtcm" in ev:
            end = lines[k + 1]["offset"] if k + 1 < len(lines) else case["size"]
            out.append(("frame", ev["offset"], end - ev["offset"]))
        else:
            end = lines[k + 1]["offset"] if k + 1 < len(lines) else case["size"]
            out.append(("packet", ev["offset"], end - ev["offset"]))
    return out


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_model_agrees_with_the_expected_events(case):
    framing = PROTOCOLS[case["protocol"]]["framing"]
    assert frame(bytes.fromhex(case["hex"]), framing) == expected_events(case), f"{case['file']}:{case['line']}"


def _features(case: dict) -> set[str]:
    """What a case exercises, computed from its bytes and expected lines."""
    proto = PROTOCOLS[case["protocol"]]
    fr = proto["framing"]
    data = bytes.fromhex(case["hex"])
    sync = bytes(fr["sync"])
    events = expected_events(case)
    lines = [json.loads(x) for x in case["expect"]]
    out: set[str] = set()
    if not data:
        out.add("empty input")
    packets = [e for e in events if e[0] == "packet"]
    skips = [e for e in events if e[0] == "skip"]
    for f in (e for e in events if e[0] == "frame"):
        out.add("rtcm3 frame" if data[f[1]] == 0xD3 else "nmea sentence")
    for s in skips:
        chunk = data[s[1] : s[1] + s[2]]
        if re.match(rb"[$!][\x20-\x7e]*?\*[0-9A-Fa-f]{2}\r\n", chunk):
            shape = re.match(rb"[$!][\x20-\x7e]*?\*[0-9A-Fa-f]{2}\r\n", chunk)
            out.add("overlong nmea sentence" if shape.end() > fr.get("nmea_max", 0) else "nmea with a bad checksum")
        if chunk[:1] == b"\xd3" and len(chunk) >= 3 and chunk[1] < 4:
            claimed = ((chunk[1] << 8) | chunk[2]) + 6
            out.add("rtcm3 frame cut short" if s[1] + claimed > len(data) else "rtcm3 frame with a bad crc")
            if any(s[1] < p[1] < s[1] + claimed for p in packets):
                out.add("packet inside a failed rtcm3 frame")
    for p in packets:
        if 0xD3 in data[p[1] + fr["header_size"] : p[1] + p[2] - 2]:
            out.add("0xD3 inside a packet's payload")
    for s in skips:
        chunk = data[s[1] : s[1] + s[2]]
        if s[1] == 0 and packets:
            out.add("garbage before a packet")
        if packets and s[1] > packets[0][1] and s[1] + s[2] < len(data):
            out.add("garbage between packets")
        if s[1] + s[2] == len(data) and packets:
            out.add("garbage after the last packet")
        if chunk.startswith(sync) and len(chunk) >= fr["header_size"]:
            claimed = fr["header_size"] + chunk[fr["length_offset"]] + 2
            if s[1] + claimed > len(data):
                out.add("false sync whose length runs past the data")
            elif any(p[1] > s[1] for p in packets):
                out.add("bad checksum (complete false packet)")
            if any(s[1] < p[1] < s[1] + claimed for p in packets):
                out.add("valid packet inside a false one")
        if s[1] + s[2] == len(data) and sync in data[s[1] :]:
            out.add("truncated packet at the end")
    for p in packets:
        payload = p[2] - fr["header_size"] - 2
        if payload == fr["max_payload"]:
            out.add("longest legal packet")
        if payload == 0:
            out.add("empty payload")
        if sync in data[p[1] + fr["header_size"] : p[1] + p[2] - 2]:
            out.add("sync bytes inside a valid payload")
    kinds = proto["set_kinds"]
    for ln in lines:
        for f in ln.get("fields", []):
            err = f.get("error", "")
            if "data" in f and f["data"] == "":
                out.add("zero-length field")
            if "overruns the payload" in err:
                out.add("field length overruns the payload")
            if "shorter than the field header" in err or "needs 2 bytes" in err:
                out.add("field header cut short")
            if "needs" in err and "data" in f:
                out.add("field too short for its type")
            if "unexpected bytes" in err:
                out.add("field longer than its type")
            if err == "unknown descriptor set":
                out.add("unknown set")
            if err == "unknown descriptor":
                out.add("unknown descriptor")
            if "invalid bool" in err:
                out.add("invalid bool")
            if "exceeds maximum" in err:
                out.add("count past the maximum")
        if "set" in ln and not any(r["first"] <= ln["set"] <= r["last"] for r in kinds.values()):
            out.add("set of no kind")
    # Continuation: two packets of one data set whose payloads start with the same shared field.
    shared = proto.get("shared_data")
    if shared:
        heads: dict = {}
        for p in packets:
            s = data[p[1] + fr["set_offset"]]
            payload = data[p[1] + fr["header_size"] : p[1] + p[2] - 2]
            hs = fr["field_header_size"]
            if len(payload) < hs:
                continue
            size = payload[fr["field_length_offset"]] + (0 if fr["field_length_counts_header"] else hs)
            first = payload[:size]
            desc = payload[fr["field_descriptor_offset"]]
            if s >= kinds["data"]["first"] and len(first) > hs and desc >= shared["first_descriptor"]:
                if heads.get(s) == first:
                    out.add("continuation packets")
                heads[s] = first
    return out


REQUIRED = {
    "empty input",
    "garbage before a packet",
    "garbage between packets",
    "garbage after the last packet",
    "false sync whose length runs past the data",
    "bad checksum (complete false packet)",
    "valid packet inside a false one",
    "truncated packet at the end",
    "longest legal packet",
    "empty payload",
    "sync bytes inside a valid payload",
    "zero-length field",
    "field length overruns the payload",
    "field header cut short",
    "field too short for its type",
    "field longer than its type",
    "unknown set",
    "unknown descriptor",
}


# A protocol with foreign frames (framing.foreign_frames, §1) needs these too.
REQUIRED_FOREIGN = {
    "nmea sentence",
    "rtcm3 frame",
    "nmea with a bad checksum",
    "overlong nmea sentence",
    "rtcm3 frame with a bad crc",
    "rtcm3 frame cut short",
    "packet inside a failed rtcm3 frame",
    "0xD3 inside a packet's payload",
}


@pytest.mark.parametrize("protocol", sorted(PROTOCOLS))
def test_stream_corpus_covers_every_hostile_input(protocol):
    """The corpus of each protocol has at least one case of every kind the parser must survive
    (every chunking comes with every case)."""
    have: set[str] = set()
    for c in STREAMS:
        if c["protocol"] == protocol:
            have |= _features(c)
    required = set(REQUIRED)
    if PROTOCOLS[protocol]["framing"].get("foreign_frames"):
        required |= REQUIRED_FOREIGN
    if PROTOCOLS[protocol].get("shared_data"):
        required.add("continuation packets")
    assert required <= have, f"tests/streams/{protocol}/ has no case of: {sorted(required - have)}"


def test_model_detects_a_wrong_expectation():
    """The model check can fail: a case whose skip run is one byte short disagrees with it."""
    case = next(c for c in STREAMS if c["name"] == "garbage_inside_packet")
    framing = PROTOCOLS["mip"]["framing"]
    wrong = [("skip", 0, 10), ("packet", 10, 9)]
    assert frame(bytes.fromhex(case["hex"]), framing) != wrong
