"""Sessions over links that misbehave (issue 37; docs/conformance.md section 8), every session tool.

For every language of TOOL_LANGS (the target registry), through `tests/conformance/session LANG`:

1. A slow reply: over a pseudo-terminal, a scripted responder answers `get_device_descriptors`
   with a 132-byte reply paced at 9600 baud (10 bits a byte: 1.04 ms a byte, 137 ms in all, longer
   than the 100 ms inter-packet timeout). Replies are recognised by content, so the result is `ack`
   with the whole reply. (The old timed rule threw the reply away as noise: `timeout`.)
2. Noise floods (tests/conformance/noise_device.py: zeros, random bytes, repeated false syncs)
   while a ping waits with `--timeout-ms 500`: the result is `timeout`, printed within a tolerant
   margin after the deadline (a functional bound on a loaded machine, not a speed test), every
   stdout line is JSON, no skip line holds more than 65536 bytes (the skip pieces) and the skip
   lines tile the stream offsets from 0; the peak memory of the tool does not grow with the
   flood's length (a 2000 ms flood against a 500 ms one) and stays under an absolute bound.
3. The input line classes and the option table of section 8 "The session tool": the same exit
   status and the same TEXT after `PROG: ` in every language.
"""

from __future__ import annotations

import json
import os
import re
import socket
import subprocess
import threading
import time
import tty
from pathlib import Path

import pytest

from generator.sessions import load_sessions
from generator.spec import load_spec
from tests.conformance.fake_device import FakeDevice
from tests.conformance.noise_device import NOISE_KINDS, PING_LINE, noise_block, run_flood
from tests.helpers.langs import langs
from tests.helpers.packets import packet

ROOT = Path(__file__).resolve().parents[2]
IR = load_spec()
PROTOCOLS = {p["name"]: p for p in IR["protocols"]}
MIP = PROTOCOLS["mip"]["framing"]
CASES = load_sessions(IR, ROOT / "tests" / "sessions")
TOOL = ROOT / "tests" / "conformance" / "session"
TOOL_LANGS = langs()  # the target registry (generator/targets/__init__.py)

SKIP_PIECE = 65536  # section 8: no skip line holds more bytes
LATE_MARGIN_MS = 5000  # result after the deadline: a functional bound on a loaded 2-core machine
RSS_GROWTH_KIB = 16 * 1024  # peak memory of a 2000 ms flood over a 500 ms one
RSS_BOUND_KIB = 256 * 1024  # peak memory of any flood run (the interpreter or program included)


def _ready(lang: str) -> None:
    """Builds the tool of each protocol first (`--help`): the devices below time their replies."""
    for proto in PROTOCOLS:
        subprocess.run([str(TOOL), lang, "--help", "--protocol", proto], capture_output=True, timeout=900)


# ----------------------------------------------------------------------------- 1. slow reply
# get_device_descriptors (set 0x01, descriptor 0x04; 3dm-gx5-45-dcp.txt line 789) and its reply:
# the ACK field (04 F1 echo 04, code 00) and device_descriptors (descriptor 0x82, line 797), an array
# of 60 16-bit descriptors (set << 8 | descriptor): a 126-byte payload, 132 bytes with the header
# and checksum.
DESCRIPTORS = [0x0100 + d for d in range(1, 31)] + [0x0C00 + d for d in range(1, 31)]
REPLY = packet(
    MIP,
    0x01,
    bytes([0x04, 0xF1, 0x04, 0x00, 2 + 2 * len(DESCRIPTORS), 0x82])
    + b"".join(d.to_bytes(2, "big") for d in DESCRIPTORS),
)
DESCRIPTORS_LINE = '{"offset":0,"set":1,"fields":[{"descriptor":4,"name":"get_device_descriptors","values":{}}]}'
BYTE_S = 10 / 9600  # one byte at 9600 baud (start, 8 data bits, stop)


def _respond_slowly(master: int, out: dict) -> None:
    """Reads one packet from the pty master, then writes REPLY one byte at a time at 9600 baud."""
    buf = bytearray()
    deadline = time.monotonic() + 120
    sync = bytes(MIP["sync"])
    try:
        while time.monotonic() < deadline:
            import select

            ready, _, _ = select.select([master], [], [], 0.5)
            if not ready:
                continue
            buf += os.read(master, 4096)
            i = buf.find(sync)
            if i >= 0 and len(buf) - i >= 4 and len(buf) - i >= 4 + buf[i + 3] + 2:
                out["command"] = bytes(buf[i : i + 4 + buf[i + 3] + 2])
                break
        else:
            out["error"] = "no command within 120 s"
            return
        start = time.monotonic()
        for k, b in enumerate(REPLY):
            wait = start + k * BYTE_S - time.monotonic()
            if wait > 0:
                time.sleep(wait)
            os.write(master, bytes([b]))
        out["took_s"] = time.monotonic() - start
        time.sleep(0.5)  # the tool reads the rest before the master goes away
    except OSError as e:
        out["error"] = str(e)


def test_the_slow_reply_is_longer_than_the_inter_packet_timeout():
    assert len(REPLY) >= 100 and len(REPLY) == 132
    assert len(REPLY) * BYTE_S * 1000 > 100  # 137.5 ms: the old timed rule dropped it


@pytest.mark.parametrize("lang", TOOL_LANGS)
def test_slow_reply_at_9600_baud_over_a_pty(lang):
    _ready(lang)
    master, slave = os.openpty()
    tty.setraw(slave)
    path = os.ttyname(slave)
    seen: dict = {}
    responder = threading.Thread(target=_respond_slowly, args=(master, seen), daemon=True)
    responder.start()
    try:
        proc = subprocess.run(
            [str(TOOL), lang, "--connect", path, "--baud", "9600", "--timeout-ms", "1000"],
            input=DESCRIPTORS_LINE + "\n",
            capture_output=True,
            text=True,
            timeout=180,
        )
        responder.join(30)
    finally:
        os.close(slave)
        os.close(master)
    assert "error" not in seen, seen
    assert seen.get("command") == packet(MIP, 0x01, bytes([0x02, 0x04])), seen  # the command, no parameters
    assert seen["took_s"] > 0.1, seen  # the reply really took longer than the inter-packet timeout
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert len(lines) == 1, lines
    result = json.loads(lines[0])
    assert result["line"] == 1 and result["result"] == "ack" and result["code"] == 0, result
    (field,) = result["reply"]
    assert field["descriptor"] == 0x82 and field["values"] == {"descriptors": DESCRIPTORS}, field


# ----------------------------------------------------------------------------- 2. noise floods
def test_noise_blocks_hold_no_packet():
    """The fixture: every noise kind repeated holds no valid packet (the tool prints skip lines
    only), and false syncs are what they claim (a sync, set 0x01, length 0xF0)."""
    for kind in NOISE_KINDS:
        assert len(noise_block(kind, MIP)) == 65536
    assert noise_block("false_syncs", MIP)[:8] == bytes.fromhex("756501F0756501F0")
    assert noise_block("random", MIP).count(bytes(MIP["sync"])) > 0  # syncs among the random bytes


def _check_flood(run, timeout_ms: int) -> None:
    where = f"{run.kind} {timeout_ms} ms: exit {run.exit_status}, stderr {run.stderr[:300]!r}"
    assert run.device_errors == [], where + f", device {run.device_errors}"
    assert run.result is not None, where + ": no result line"
    assert run.result["line"] == 1 and run.result["result"] == "timeout", where + f": {run.result}"
    assert run.late_ms is not None and run.late_ms < LATE_MARGIN_MS, where + f": {run.late_ms:.0f} ms late"
    assert run.exit_status == 0 and run.exit_ms < LATE_MARGIN_MS, where + f": exit after {run.exit_ms:.0f} ms"
    assert run.bad_lines == [], where + f": lines that are not JSON {run.bad_lines}"
    assert run.others == [], where + f": lines that are neither skip runs nor the result {run.others}"
    assert run.skips, where + ": no skip line"
    longest = max(n for _, n in run.skips)
    assert longest <= SKIP_PIECE, where + f": a skip line of {longest} bytes"
    assert all(n == SKIP_PIECE for _, n in run.skips[:-1]), where + ": a skip piece shorter than 65536 bytes"
    assert run.tiling_error() is None, where + ": " + str(run.tiling_error())
    assert 0 < run.peak_rss_kib < RSS_BOUND_KIB, where + f": peak RSS {run.peak_rss_kib} KiB"


@pytest.mark.parametrize("kind", NOISE_KINDS)
@pytest.mark.parametrize("lang", TOOL_LANGS)
def test_noise_flood_times_out_on_time_in_bounded_memory(lang, kind):
    _ready(lang)
    run = run_flood(lang, kind, 500, MIP)
    _check_flood(run, 500)
    # the skip lines account for every byte the tool read: nothing lost or duplicated
    total = sum(n for _, n in run.skips)
    assert 0 < total <= run.sent


@pytest.mark.parametrize("lang", TOOL_LANGS)
def test_peak_memory_does_not_grow_with_the_flood(lang):
    _ready(lang)
    short = run_flood(lang, "zeros", 500, MIP)
    long = run_flood(lang, "zeros", 2000, MIP)
    _check_flood(short, 500)
    _check_flood(long, 2000)
    grown = long.peak_rss_kib - short.peak_rss_kib
    assert grown < RSS_GROWTH_KIB, (
        f"peak RSS {short.peak_rss_kib} KiB after {short.sent} bytes, {long.peak_rss_kib} KiB after {long.sent} bytes"
    )


# ----------------------------------------------------------------------------- 3. lines and options
def _case(proto: str, name: str) -> dict:
    return next(c for c in CASES if c["protocol"] == proto and c["name"] == name)


LONG = 1048576  # section 8: a longer line (without its newline) is a bad line
NOT_UTF8 = [b"\xff", b"\xc0\xaf", b"\xed\xa0\x80", b"\xf4\x90\x80\x80", b"{\x80}"]  # RFC 3629: all refused
NOT_BLANK = ["\x0c", "\x0b", "\u00a0", "\u2028", "\u3000", "\u0085", " \x0c "]  # not RFC 8259 whitespace


@pytest.mark.parametrize("lang", TOOL_LANGS)
def test_input_line_classes(lang):
    """Blank lines (RFC 8259 whitespace only, up to 1048576 bytes) are skipped; every other line is
    counted: too long, not UTF-8, other spaces (parsed as JSON: bad), listen ms out of range."""
    _ready(lang)
    lines: list[bytes] = [b"", b" \t \r", b" " * LONG, b" " * (LONG + 1), b"x" * (3 * LONG)]
    expect: dict[int, str | None] = {4: f"longer than {LONG} bytes", 5: f"longer than {LONG} bytes"}
    for raw in NOT_UTF8:
        lines.append(raw)
        expect[len(lines)] = "not UTF-8"
    for text in NOT_BLANK:
        lines.append(text.encode())
        expect[len(lines)] = None  # a bad line; its reason is the JSON parser's
    for ms in ("3600001", "-1", "1.5", '"5"', "true", "99999999999999999999"):
        lines.append(('{"link":"listen","ms":' + ms + "}").encode())
        expect[len(lines)] = '"ms" must be an integer from 0 to 3600000'
    lines.append(PING_LINE.encode())
    ping = len(lines)
    lines.append(b"\r")  # blank, the last line, without a newline
    case = _case("mip", "ping_ack")
    dev = FakeDevice(case, MIP).start()
    proc = subprocess.run(
        [str(TOOL), lang, "--connect", f"tcp:127.0.0.1:{dev.port}"],
        input=b"\n".join(lines),
        capture_output=True,
        timeout=120,
    )
    dev.join(10)
    stderr = proc.stderr.decode("utf-8", "replace")
    assert proc.returncode == 1, stderr
    assert proc.stdout.decode().splitlines() == ['{"line":%d,"result":"ack","code":0,"reply":[]}' % ping]
    got = stderr.splitlines()
    assert len(got) == len(expect), got
    for line, (number, why) in zip(got, sorted(expect.items())):
        m = re.fullmatch(r"(\S+): line (\d+): (.*)", line)
        assert m and int(m.group(2)) == number, (line, number)
        if why is not None:
            assert m.group(3) == why, line
    assert dev.errors == []


BAUD = {proto: sorted({r for b in p["link"]["baud_rates"] for r in b["rates"]}) for proto, p in PROTOCOLS.items()}


def test_baud_lists_are_the_manuals_rates():
    # 3dm-gx5-45-dcp.txt line 1296, 3dm-cv7-ins-docs.txt line 2718; ms-cip-doc00419-revM.txt line 539
    assert BAUD["mip"] == [9600, 19200, 115200, 230400, 460800, 921600, 3000000]
    assert BAUD["mscip"] == [9600, 19200, 115200, 230400, 460800, 921600]


def _refusals(proto: str) -> list[tuple[list[str], str]]:
    rates = ", ".join(map(str, BAUD[proto]))
    out: list[tuple[list[str], str]] = [
        ([], "--connect ADDRESS is required"),
        (["--timeout-ms", "500"], "--connect ADDRESS is required"),
    ]
    for v in ("0", "600001", "+5", "-1", "1e3", "0x10", "", " 5", "5 ", "\u0665", "99999999999999999999999"):
        out.append((["--timeout-ms", v], f"--timeout-ms: expected an integer from 1 to 600000, got {v}"))
    for v in ("0", "3600001", "-5", "", "1.5"):
        out.append((["--reconnect-ms", v], f"--reconnect-ms: expected an integer from 1 to 3600000, got {v}"))
    for v in ("57600", "0", "1e3", "+9600", "", "9600.0", "4000000"):
        out.append((["--baud", v], f"--baud: {v} is not a baud rate of {proto} devices ({rates})"))
    return out


@pytest.mark.parametrize("proto", sorted(PROTOCOLS))
@pytest.mark.parametrize("lang", TOOL_LANGS)
def test_option_table(lang, proto):
    """Each refused option value: exit 2, exactly one stderr line `PROG: TEXT`, nothing on stdout,
    no connection opened (a listener sees none)."""
    _ready(lang)
    srv = socket.socket()
    srv.bind(("127.0.0.1", 0))
    srv.listen(8)
    srv.setblocking(False)
    address = f"tcp:127.0.0.1:{srv.getsockname()[1]}"
    failures = []
    try:
        for args, text in _refusals(proto):
            connect = ["--connect", address] if "required" not in text else []
            proc = subprocess.run(
                [str(TOOL), lang, *args, *connect, "--protocol", proto],
                input=PING_LINE + "\n",
                capture_output=True,
                text=True,
                timeout=120,
            )
            err = proc.stderr.splitlines()
            ok = proc.returncode == 2 and proc.stdout == "" and len(err) == 1
            ok = ok and re.fullmatch(r"\S+: " + re.escape(text), err[0]) is not None
            if not ok:
                failures.append(f"{args}: exit {proc.returncode}, stderr {proc.stderr!r}, want '{text}'")
        try:
            srv.accept()
            failures.append("a refused run opened a connection")
        except BlockingIOError:
            pass
    finally:
        srv.close()
    assert not failures, "\n".join(failures)


@pytest.mark.parametrize("lang", TOOL_LANGS)
def test_option_values_accepted(lang):
    """The edges of the table: leading zeros are decimal, the range ends are in, any listed rate."""
    _ready(lang)
    case = _case("mip", "ping_ack")
    dev = FakeDevice(case, MIP).start()
    proc = subprocess.run(
        [str(TOOL), lang, "--connect", f"tcp:127.0.0.1:{dev.port}"]
        + ["--timeout-ms", "0600000", "--reconnect-ms", "3600000", "--baud", "0009600"],
        input=PING_LINE + "\n" + '{"link":"listen","ms":0}\n',
        capture_output=True,
        text=True,
        timeout=120,
    )
    dev.join(10)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == [
        '{"line":1,"result":"ack","code":0,"reply":[]}',
        '{"line":2,"listened":0}',
    ]
    assert dev.errors == []
