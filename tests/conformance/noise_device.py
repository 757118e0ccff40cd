"""A fake device that answers a command with noise, as fast as the connection takes it (issue 37).

`run_flood(lang, kind, timeout_ms)` starts the session tool of `lang` (tests/conformance/session)
against a loopback TCP listener, gives it one ping line and keeps its stdin open. The device reads
the ping packet, then sends one kind of noise (NOISE_KINDS: zeros, random bytes holding no valid
packet, repeated false syncs whose length claims 240 payload bytes: `7565 01F0` in MIP) until the
tool prints the ping's result. Then the tool's peak memory is read (VmHWM of its process tree, in
/proc), stdin is closed and the tool exits. Every stdout line is checked as it comes (valid JSON;
the skip runs kept as (offset, length) only, so the test holds no flood in memory).

Used by tests/conformance/test_session_robust.py (the bounds) and tests/bench/session_flood.py
(the figures). Knows nothing of the protocol beyond the IR's framing.
"""

from __future__ import annotations

import json
import os
import random
import socket
import subprocess
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

from tests.helpers.packets import checksum

ROOT = Path(__file__).resolve().parents[2]
TOOL = ROOT / "tests" / "conformance" / "session"
NOISE_KINDS = ("zeros", "random", "false_syncs")
BLOCK = 65536  # the device sends the noise in blocks of this size
PING_LINE = '{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}'


def valid_packet_at(data: bytes, i: int, framing: dict) -> bool:
    """True when a complete packet with a valid checksum starts at i (docs/conformance.md section 1)."""
    sync = bytes(framing["sync"])
    head = framing["header_size"]
    if data[i : i + len(sync)] != sync or len(data) - i < head:
        return False
    length = data[i + framing["length_offset"]]
    if length > framing["max_payload"]:
        return False
    body = head + length
    size = len(framing["checksum"]["order"])
    if len(data) - i < body + size:
        return False
    return checksum(framing, data[i : i + body]) == data[i + body : i + body + size]


def packets_in(block: bytes, framing: dict) -> list[int]:
    """Where a valid packet starts in the endless repetition of `block` (positions in the block)."""
    twice = block + block
    sync = bytes(framing["sync"])
    out = []
    i = twice.find(sync)
    while 0 <= i < len(block):
        if valid_packet_at(twice, i, framing):
            out.append(i)
        i = twice.find(sync, i + 1)
    return out


def noise_block(kind: str, framing: dict) -> bytes:
    """One block of the noise of `kind`; its endless repetition holds no valid packet."""
    if kind == "zeros":
        block = bytes(BLOCK)
    elif kind == "random":
        data = bytearray(random.Random(37).randbytes(BLOCK))
        while True:  # a valid packet by chance (about one flood in fifty): break its checksum
            found = packets_in(bytes(data), framing)
            if not found:
                break
            for i in found:
                data[(i + framing["header_size"]) % BLOCK] ^= 0x01
        block = bytes(data)
    elif kind == "false_syncs":
        header = bytearray(framing["header_size"])
        header[: len(framing["sync"])] = bytes(framing["sync"])
        header[framing["set_offset"]] = 0x01
        header[framing["length_offset"]] = 0xF0
        block = bytes(header) * (BLOCK // len(header))
    else:
        raise ValueError(f"unknown noise kind {kind!r} (one of {', '.join(NOISE_KINDS)})")
    assert not packets_in(block, framing), kind
    return block


class NoiseDevice:
    """Accepts one connection, reads one packet (the command), then sends `block` again and again."""

    def __init__(self, framing: dict, block: bytes) -> None:
        self.framing = framing
        self.block = block
        self.sent = 0
        self.command_at: float | None = None
        self.errors: list[str] = []
        self._stop = threading.Event()
        self._srv = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self._srv.bind(("127.0.0.1", 0))
        self._srv.listen(1)
        self._srv.settimeout(120)
        self.port = self._srv.getsockname()[1]
        self.started = threading.Event()
        self._thread = threading.Thread(target=self._serve, daemon=True)

    def start(self) -> NoiseDevice:
        self._thread.start()
        return self

    def stop(self) -> None:
        self._stop.set()
        self._thread.join(30)

    def _serve(self) -> None:
        fr = self.framing
        sync = bytes(fr["sync"])
        try:
            conn, _ = self._srv.accept()
        except OSError as e:
            self.errors.append(f"no connection: {e}")
            return
        finally:
            self._srv.close()
        conn.settimeout(0.2)
        buf = bytearray()
        try:
            while self.command_at is None and not self._stop.is_set():
                try:
                    data = conn.recv(4096)
                except socket.timeout:
                    continue
                if not data:
                    self.errors.append("the tool closed the connection before sending a command")
                    return
                buf += data
                i = buf.find(sync)
                if i >= 0 and len(buf) - i >= fr["header_size"]:
                    total = fr["header_size"] + buf[i + fr["length_offset"]] + len(fr["checksum"]["order"])
                    if len(buf) - i >= total:
                        self.command_at = time.monotonic()
            self.started.set()
            view = memoryview(self.block)
            while not self._stop.is_set():
                try:
                    self.sent += conn.send(view)
                except socket.timeout:
                    continue
                except OSError:
                    return  # the tool went away
        finally:
            self.started.set()
            conn.close()


@dataclass
class FloodRun:
    """What one flood run saw."""

    kind: str
    timeout_ms: int
    exit_status: int | None = None
    result: dict | None = None
    late_ms: float | None = None  # result line time - (command arrival + timeout)
    exit_ms: float | None = None  # from stdin closed to the tool's exit
    peak_rss_kib: int = 0  # VmHWM of the tool's process tree when the result came
    sent: int = 0  # bytes the device sent
    skips: list[tuple[int, int]] = field(default_factory=list)  # (offset, length) of each skip line
    others: list[str] = field(default_factory=list)  # lines neither a skip run nor the result (cut)
    bad_lines: list[str] = field(default_factory=list)  # stdout lines that are not valid JSON (cut)
    longest_line: int = 0
    stderr: str = ""
    device_errors: list[str] = field(default_factory=list)

    def tiling_error(self) -> str | None:
        """None when the skip lines tile the offsets from 0 without gap or overlap."""
        at = 0
        for offset, length in self.skips:
            if offset != at:
                return f"skip line at offset {offset}, expected {at}"
            if length == 0:
                return f"empty skip line at offset {offset}"
            at = offset + length
        return None


def _tree(pid: int) -> list[int]:
    """pid and its live descendants."""
    parents: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", "rb") as f:
                stat = f.read()
        except OSError:
            continue
        ppid = int(stat[stat.rindex(b")") + 2 :].split()[1])
        parents.setdefault(ppid, []).append(int(entry))
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        out.append(p)
        todo += parents.get(p, [])
    return out


def peak_rss_kib(pid: int) -> int:
    """The largest VmHWM (peak resident set, KiB) of the live processes of pid's tree."""
    peak = 0
    for p in _tree(pid):
        try:
            with open(f"/proc/{p}/status") as f:
                for line in f:
                    if line.startswith("VmHWM:"):
                        peak = max(peak, int(line.split()[1]))
        except OSError:
            continue
    return peak


def run_flood(lang: str, kind: str, timeout_ms: int, framing: dict, protocol: str = "mip") -> FloodRun:
    """One flood run (see the module's doc); the tool must have been built before (its startup
    is not timed, but a build would hold the connection back)."""
    run = FloodRun(kind, timeout_ms)
    dev = NoiseDevice(framing, noise_block(kind, framing)).start()
    args = [str(TOOL), lang, "--connect", f"tcp:127.0.0.1:{dev.port}", "--timeout-ms", str(timeout_ms)]
    proc = subprocess.Popen(
        args + ["--protocol", protocol], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE
    )
    got_result = threading.Event()
    result_at: list[float] = []
    err: list[bytes] = []

    def read_stdout() -> None:
        assert proc.stdout is not None
        for raw in proc.stdout:
            run.longest_line = max(run.longest_line, len(raw) - 1)
            try:
                obj = json.loads(raw)
            except ValueError:
                if len(run.bad_lines) < 5:
                    run.bad_lines.append(raw[:200].decode("latin-1"))
                continue
            if isinstance(obj, dict) and "result" in obj:
                if not result_at:
                    result_at.append(time.monotonic())
                run.result = obj
                got_result.set()
            elif isinstance(obj, dict) and set(obj) == {"offset", "skipped"}:
                hexdigits = obj["skipped"]
                if len(hexdigits) % 2 or any(c not in "0123456789abcdef" for c in hexdigits[:64]):
                    run.bad_lines.append(raw[:200].decode("latin-1"))
                run.skips.append((obj["offset"], len(hexdigits) // 2))
            elif len(run.others) < 5:
                run.others.append(raw[:200].decode("latin-1"))

    def read_stderr() -> None:
        assert proc.stderr is not None
        data = proc.stderr.read(65536)
        while data:
            if sum(map(len, err)) < 65536:
                err.append(data)
            data = proc.stderr.read(65536)

    readers = [threading.Thread(target=read_stdout, daemon=True), threading.Thread(target=read_stderr, daemon=True)]
    for t in readers:
        t.start()
    assert proc.stdin is not None
    try:
        proc.stdin.write((PING_LINE + "\n").encode())
        proc.stdin.flush()
        got_result.wait(timeout_ms / 1000.0 + 120)
        if proc.poll() is None:
            run.peak_rss_kib = peak_rss_kib(proc.pid)
        proc.stdin.close()
    except BrokenPipeError:
        pass
    closed = time.monotonic()
    try:
        run.exit_status = proc.wait(60)
    except subprocess.TimeoutExpired:
        proc.kill()
        run.exit_status = proc.wait(10)
    run.exit_ms = (time.monotonic() - closed) * 1000.0
    for t in readers:
        t.join(30)
    dev.stop()
    run.sent = dev.sent
    run.device_errors = dev.errors
    if result_at and dev.command_at is not None:
        run.late_ms = (result_at[0] - dev.command_at) * 1000.0 - timeout_ms
    run.stderr = b"".join(err).decode("utf-8", "replace")
    return run
