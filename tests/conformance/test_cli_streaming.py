"""The command-line tools stream (docs/conformance.md §5, "Streaming"), in all four languages:

- a live stream (a pipe kept open, as from a serial port) shows each packet's line as soon as the
  packet has arrived, and encode writes each line's bytes as soon as the line has arrived;
- skip runs longer than the tools' read blocks (and than the C tool's 1 MiB spill threshold)
  print the same lines in every language, from a file and from stdin.
"""

import selectors
import subprocess
import time
from pathlib import Path

import pytest

from tests.helpers.langs import langs

ROOT = Path(__file__).resolve().parents[2]
LANGS = langs()  # the target registry (generator/targets/__init__.py)
DECODE = ROOT / "tests/conformance/decode"
ENCODE = ROOT / "tests/conformance/encode"

# Ping (0x01,0x01): sync 75 65, set 01, payload length 02, field 02 01, checksum E0 C6.
PING = bytes.fromhex("756501020201e0c6")
PING_FIELDS = '"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}'


def _read_exactly(proc: subprocess.Popen, n: int, timeout: float) -> bytes:
    """n bytes of proc's stdout, waiting at most `timeout` seconds in all (the pipe stays open)."""
    sel = selectors.DefaultSelector()
    sel.register(proc.stdout, selectors.EVENT_READ)
    got = b""
    end = time.monotonic() + timeout
    while len(got) < n:
        left = end - time.monotonic()
        if left <= 0 or not sel.select(left):
            break
        chunk = proc.stdout.read1(n - len(got))
        if not chunk:
            break
        got += chunk
    sel.close()
    return got


@pytest.mark.parametrize("lang", LANGS)
def test_decode_prints_each_packet_as_it_arrives(lang):
    proc = subprocess.Popen(
        [str(DECODE), lang, "-"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE
    )
    try:
        for k in range(3):
            proc.stdin.write(PING)
            proc.stdin.flush()  # and the pipe stays open: no end of input
            want = ('{"offset":' + str(8 * k) + "," + PING_FIELDS + "\n").encode()
            got = _read_exactly(proc, len(want), timeout=120 if k == 0 else 20)
            assert got == want, f"{lang} decode: packet {k} not printed while the input is open: {got!r}"
        proc.stdin.close()
        assert proc.wait(timeout=60) == 0
        assert proc.stdout.read() == b""
    finally:
        proc.kill()
        proc.wait()


@pytest.mark.parametrize("lang", LANGS)
def test_encode_writes_each_line_as_it_arrives(lang):
    proc = subprocess.Popen([str(ENCODE), lang], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        for k in range(3):
            proc.stdin.write(('{"offset":0,' + PING_FIELDS + "\n").encode())
            proc.stdin.flush()
            got = _read_exactly(proc, len(PING), timeout=120 if k == 0 else 20)
            assert got == PING, f"{lang} encode: line {k + 1} not written while the input is open: {got!r}"
        proc.stdin.close()
        assert proc.wait(timeout=60) == 0
    finally:
        proc.kill()
        proc.wait()


@pytest.fixture(scope="module")
def long_skips(tmp_path_factory):
    """3 MiB of bytes that hold no sync byte, a packet, 1.5 MiB more, a packet, a lone sync byte."""
    head = bytes(range(0x76, 0x100)) * (3 * 1024 * 1024 // 138)
    tail = b"\x00\x01\x02" * (512 * 1024)
    data = head + PING + tail + PING + b"\x75"
    p = tmp_path_factory.mktemp("skips") / "long-skips.bin"
    p.write_bytes(data)
    want = (
        '{"offset":0,"skipped":"' + head.hex() + '"}\n'
        '{"offset":' + str(len(head)) + "," + PING_FIELDS + "\n"
        '{"offset":' + str(len(head) + 8) + ',"skipped":"' + tail.hex() + '"}\n'
        '{"offset":' + str(len(head) + 8 + len(tail)) + "," + PING_FIELDS + "\n"
        '{"offset":' + str(len(data) - 1) + ',"skipped":"75"}\n'
    )
    return p, want


@pytest.mark.parametrize("lang", LANGS)
def test_long_skip_runs(lang, long_skips):
    path, want = long_skips
    from_file = subprocess.run([str(DECODE), lang, str(path)], capture_output=True)
    assert from_file.returncode == 0, from_file.stderr.decode(errors="replace")
    assert from_file.stdout.decode() == want, f"{lang} decode of long skip runs differs"
    with open(path, "rb") as f:
        piped = subprocess.run([str(DECODE), lang, "-"], stdin=f, capture_output=True)
    assert piped.returncode == 0
    assert piped.stdout.decode() == want, f"{lang} decode of long skip runs from stdin differs"
