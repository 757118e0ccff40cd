"""Cross-language conformance through the command-line tools (docs/conformance.md §5).

For every golden vector and every language: `decode` prints exactly the expected canonical JSON
lines, and `encode` turns them back into the same bytes. Then one long stream made of every
vector with garbage between them must decode to byte-identical output in all four languages and
round-trip through decode | encode in each. Every protocol (MIP, MS-CIP) separately.
"""

import concurrent.futures
import json
import os
import random
import re
import subprocess
from pathlib import Path

import pytest

from generator.spec import load_spec
from generator.vectors import load_corpus
from tests.helpers.langs import langs

ROOT = Path(__file__).resolve().parents[2]
LANGS = langs()  # the target registry (generator/targets/__init__.py)
IR = load_spec()
VECTORS = load_corpus(IR, ROOT)
PROTOCOLS = [p["name"] for p in IR["protocols"]]


def decode(lang: str, path: Path, *extra: str, protocol: str = "mip") -> str:
    proc = subprocess.run(
        [str(ROOT / "tests/conformance/decode"), lang, str(path), *extra, "--protocol", protocol], capture_output=True
    )
    assert proc.returncode == 0, f"{lang} decode failed: {proc.stderr.decode(errors='replace')}"
    return proc.stdout.decode()


def encode(lang: str, text: str, protocol: str = "mip") -> bytes:
    proc = subprocess.run(
        [str(ROOT / "tests/conformance/encode"), lang, "--protocol", protocol], input=text.encode(), capture_output=True
    )
    assert proc.returncode == 0, f"{lang} encode failed: {proc.stderr.decode(errors='replace')}"
    return proc.stdout


@pytest.fixture(scope="module")
def vector_files(tmp_path_factory):
    d = tmp_path_factory.mktemp("vectors")
    out = {}
    for c in VECTORS:
        p = d / f"{c['name']}.bin"
        p.write_bytes(bytes.fromhex(c["hex"]))
        out[c["name"]] = p
    return out


@pytest.mark.parametrize("lang", LANGS)
def test_every_vector_decodes_and_encodes(lang, vector_files):
    def check(c: dict) -> list[str]:
        extra = ("--device", c["device"]) if c.get("device") else ()
        got = decode(lang, vector_files[c["name"]], *extra, protocol=c["protocol"])
        want = "".join(line + "\n" for line in c["expect"])
        if got != want:
            return [f"{c['name']} ({c['file']}:{c['line']}):\n  want {want!r}\n  got  {got!r}"]
        if any('"nmea":' in x or '"rtcm":' in x for x in c["expect"]):
            return _foreign_encode_failures(lang, c, got)
        back = encode(lang, got, protocol=c["protocol"])
        if back.hex() != c["hex"]:
            return [f"{c['name']}: encode gave {back.hex()}, want {c['hex']}"]
        return []

    # One tool process per vector and direction (the contract is a file per run): each protocol's
    # first vector alone (it builds that package's tools when needed), then the others one a
    # processor at once; the failures keep the corpus's order.
    first = {id(next(c for c in VECTORS if c["protocol"] == p)) for p in {c["protocol"] for c in VECTORS}}
    found = {id(c): check(c) for c in VECTORS if id(c) in first}
    rest = [c for c in VECTORS if id(c) not in first]
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        found.update(zip(map(id, rest), pool.map(check, rest)))
    failures = [f for c in VECTORS for f in found[id(c)]]
    assert not failures, f"{len(failures)} of {len(VECTORS)} vectors fail in {lang}:\n" + "\n".join(failures)


def _foreign_encode_failures(lang: str, c: dict, text: str) -> list[str]:
    """An NMEA or RTCM3 line is not encoder input (docs/conformance.md section 5: an rtcm line
    does not hold the frame's bytes): encode refuses each with one message naming its line (exit
    1) and writes the other lines, so the output is the input without the foreign frames."""
    lines = text.splitlines()
    refused = [k + 1 for k, x in enumerate(lines) if '"nmea":' in x or '"rtcm":' in x]
    raw = bytes.fromhex(c["hex"])
    kept = b""
    for k, x in enumerate(lines):
        if k + 1 not in refused:
            start = json.loads(x)["offset"]
            end = json.loads(lines[k + 1])["offset"] if k + 1 < len(lines) else len(raw)
            kept += raw[start:end]
    proc = subprocess.run(
        [str(ROOT / "tests/conformance/encode"), lang, "--protocol", c["protocol"]],
        input=text.encode(),
        capture_output=True,
    )
    messages = proc.stderr.decode(errors="replace").splitlines()
    named = all(any(f"line {k}:" in m for m in messages) for k in refused)
    if proc.returncode != 1 or proc.stdout != kept or len(messages) != len(refused) or not named:
        return [
            f"{c['name']}: encode of its nmea/rtcm lines: status {proc.returncode}, {messages}, {proc.stdout.hex()}"
        ]
    return []


@pytest.fixture(scope="module")
def mixed_streams(tmp_path_factory):
    """Per protocol: its vectors, in order, separated by seeded random garbage (the seed is in
    the file name), then a lone first sync byte."""
    seed = int(os.environ.get("CONFORMANCE_SEED", "20261121"))
    out = {}
    for proto in IR["protocols"]:
        # "<protocol>:encodable": the same without the cases with NMEA or RTCM3 lines, which encode
        # refuses (docs/conformance.md section 5), for the round trip
        for key, keep in ((proto["name"], lambda c: True), (proto["name"] + ":encodable", _encodable)):
            rng = random.Random(seed)
            parts = []
            for c in VECTORS:
                if c["protocol"] == proto["name"] and keep(c):
                    parts.append(bytes(rng.randrange(256) for _ in range(rng.randrange(0, 6))))
                    parts.append(bytes.fromhex(c["hex"]))
            parts.append(bytes(proto["framing"]["sync"][:1]))  # a lone sync byte at the very end
            p = tmp_path_factory.mktemp("stream") / f"mixed-{key.replace(':', '-')}-{seed}.bin"
            p.write_bytes(b"".join(parts))
            out[key] = p
    return out


def _encodable(case: dict) -> bool:
    return not any('"nmea":' in line or '"rtcm":' in line for line in case["expect"])


@pytest.mark.parametrize("protocol", PROTOCOLS)
def test_mixed_stream_identical_in_all_languages(mixed_streams, protocol):
    stream = mixed_streams[protocol]
    outputs = {lang: decode(lang, stream, protocol=protocol) for lang in LANGS}
    ref = outputs["python"]
    assert ref.count('"set":') >= len([c for c in VECTORS if c["protocol"] == protocol and not c["rejected"]])
    for lang, out in outputs.items():
        assert out == ref, f"{lang} differs from python on {stream.name}"


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("protocol", PROTOCOLS)
def test_mixed_stream_round_trips(lang, mixed_streams, protocol):
    stream = mixed_streams[protocol + ":encodable"]
    assert encode(lang, decode(lang, stream, protocol=protocol), protocol=protocol) == stream.read_bytes()


@pytest.mark.parametrize("protocol", PROTOCOLS)
def test_other_protocols_packets_are_skipped_bytes(mixed_streams, protocol):
    """A stream of another protocol's packets holds no packet of this one: all four languages
    report it as skipped bytes only (or, by chance, a packet that really checks out), identically."""
    others = [p for p in PROTOCOLS if p != protocol]
    for other in others:
        stream = mixed_streams[other]
        outputs = {lang: decode(lang, stream, protocol=protocol) for lang in LANGS}
        assert len(set(outputs.values())) == 1, f"languages differ decoding {other} bytes as {protocol}"
        assert '"skipped"' in outputs["python"]


@pytest.mark.parametrize("lang", LANGS)
def test_encode_reports_a_bad_line_and_keeps_the_others(lang):
    lines = [
        '{"offset":0,"skipped":"00ff"}',
        '{"offset":2,"set":1,"fields":[{"descriptor":9,"name":"comm_port_speed","values":{"function":1,"port":1,"baud":-5}}]}',
        "{not json",
        "",
        '{"offset":9,"skipped":"01"}',
    ]
    proc = subprocess.run(
        [str(ROOT / "tests/conformance/encode"), lang], input="\n".join(lines).encode() + b"\n", capture_output=True
    )
    assert proc.returncode == 1
    assert proc.stdout == b"\x00\xff\x01"
    err = proc.stderr.decode()
    assert "line 2" in err and "line 3" in err and "baud" in err
    assert "Traceback" not in err and "panicked" not in err


@pytest.mark.parametrize("lang", LANGS)
def test_decode_of_a_missing_file_is_a_usage_error(lang, tmp_path):
    proc = subprocess.run(
        [str(ROOT / "tests/conformance/decode"), lang, str(tmp_path / "missing.bin")], capture_output=True
    )
    assert proc.returncode == 2
    assert proc.stdout == b""
    assert b"missing.bin" in proc.stderr


# Encoder input (docs/conformance.md §5): spellings of a vector's lines other than the canonical
# one, which must encode to its bytes, and lines every encoder must refuse.
ENCODE_INPUTS = [(c, text) for c in VECTORS for text in c["encode_inputs"]]
REFUSED = [(c, bytes.fromhex(h)) for c in VECTORS for h in c["refused_inputs"]]


def _encode_raw(lang: str, data: bytes, protocol: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(ROOT / "tests/conformance/encode"), lang, "--protocol", protocol], input=data, capture_output=True
    )


@pytest.mark.parametrize("lang", LANGS)
def test_other_spellings_encode_to_the_vector_bytes(lang):
    assert ENCODE_INPUTS, "no vector has encode_inputs"
    for protocol in PROTOCOLS:
        cases = [(c, t) for c, t in ENCODE_INPUTS if c["protocol"] == protocol]
        if not cases:
            continue
        text = "".join(t.rstrip("\n") + "\n" for _, t in cases).encode()
        proc = _encode_raw(lang, text, protocol)
        if proc.returncode == 0 and proc.stdout == b"".join(bytes.fromhex(c["hex"]) for c, _ in cases):
            continue
        bad = []  # one run per input to name the ones that fail
        for c, t in cases:
            one = _encode_raw(lang, t.rstrip("\n").encode() + b"\n", protocol)
            if one.returncode != 0 or one.stdout.hex() != c["hex"]:
                err = one.stderr.decode(errors="replace").strip()
                bad.append(f"{c['name']}: {t[:160]}\n  gave {one.stdout.hex() or '(nothing)'} (want {c['hex']}) {err}")
        assert not bad, f"{lang} encode:\n" + "\n".join(bad)


@pytest.mark.parametrize("lang", LANGS)
def test_refused_inputs_are_refused_and_the_other_lines_kept(lang):
    assert REFUSED, "no vector has refused_inputs"
    good = b'{"offset":0,"skipped":"aa"}'
    for protocol in PROTOCOLS:
        lines = [(c, b) for c, b in REFUSED if c["protocol"] == protocol]
        if not lines:
            continue
        assert all(b"\n" not in b for _, b in lines)
        data = good + b"\n" + b"".join(b + b"\n" + good + b"\n" for _, b in lines)
        proc = _encode_raw(lang, data, protocol)
        err = proc.stderr.decode(errors="replace")
        # "line N: what is wrong": the reason must be there too.
        named = {int(n) for n in re.findall(r"\bline (\d+):[ \t]*\S", err)}
        missed = [f"{c['name']}: {b[:160]!r}" for k, (c, b) in enumerate(lines) if 2 * k + 2 not in named]
        assert not missed, f"{lang} encode accepted (or did not name) refused lines:\n" + "\n".join(missed)
        assert proc.returncode == 1
        assert proc.stdout == b"\xaa" * (len(lines) + 1), f"{lang} wrote bytes for a refused line"
        assert "Traceback" not in err and "panicked" not in err
