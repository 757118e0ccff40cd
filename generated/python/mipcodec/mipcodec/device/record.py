"""The recorder of the device command line (docs/record.md):

    mipcodec-device ADDRESS record FILE [--duration S] [--split-size BYTES] [--split-time S]

asks the device for its Device Information, writes the reply packet first, then every byte the
device sends as it arrives, in whole packets: a packet cut by a read waits for its end; bytes that
are not part of a packet are kept (the log is the device's stream) but a write never ends inside a
packet. At the end (--duration, Ctrl-C or SIGTERM, the device gone, a failed write) the bytes of a
packet not finished yet are left out, so the log is whole. `--split-size`/`--split-time` start a
new file FILE-stem.NNN.ext (000, 001, ...), each beginning with the Device Information reply
again. A FILE ending in `.mcap` is an MCAP file (record_mcap.py, docs/mcap.md). The C tool's tools/device/record.c is the same rule, message for message.

Exit status (the C tool's too): 0 stopped by --duration, Ctrl-C or SIGTERM; 1 the device did not
answer the Device Information command, or went away (end of file, a closed socket, a read error);
2 a usage error, no connection, a file that exists or cannot be created, or a failed write (a full
disk: the file is cut back to its last whole packet, `cannot write FILE: No space left on device`).
"""

from __future__ import annotations

import errno
import os
import signal
import sys
import time
from typing import Any, List, Optional, Tuple, Union

from .._protocol import PACKAGE
from ..codec.framing import (
    CHECKSUM_SIZE,
    HEADER_SIZE,
    LENGTH_OFFSET,
    MAX_PAYLOAD,
    SET_OFFSET,
    SYNC,
    build_packet,
    checksum_ok,
    iter_fields,
)
from ..session import identity_command
from ..session.transport import TransportError, open_transport

PROG = f"{PACKAGE}-device"
READ_WAIT_S = 0.2  # a read waits at most this long (a stop request is seen within it)

# exit statuses (docs/record.md)
STOPPED = 0
DEVICE = 1
TROUBLE = 2


def whole(buf: Union[bytes, bytearray]) -> Tuple[int, List[Tuple[int, int]]]:
    """(end, packets): buf[:end] is whole packets and bytes that are not part of any packet, the
    rest the start of a packet that has not ended yet (waits for more bytes); packets: the (start,
    end) of every complete packet in buf[:end]. The framing rule of docs/conformance.md section 1:
    a sync, a length at most MAX_PAYLOAD and a matching checksum make a packet; a false sync is one
    byte that is not part of a packet."""
    n = len(buf)
    pos = 0
    packets: List[Tuple[int, int]] = []
    view = buf if isinstance(buf, bytearray) else bytearray(buf)
    while pos < n:
        i = view.find(SYNC, pos)
        if i < 0:
            # a partial sync at the very end may be the start of a packet
            keep = n
            for j in range(max(pos, n - len(SYNC) + 1), n):
                if view[j:] == SYNC[: n - j]:
                    keep = j
                    break
            return keep, packets
        if n - i < HEADER_SIZE:
            return i, packets
        length = view[i + LENGTH_OFFSET]
        if length <= MAX_PAYLOAD:
            body = HEADER_SIZE + length
            if n - i < body + CHECKSUM_SIZE:
                return i, packets
            if checksum_ok(view, i, body):
                packets.append((i, i + body + CHECKSUM_SIZE))
                pos = i + body + CHECKSUM_SIZE
                continue
        pos = i + 1  # a false sync: one byte that is not part of a packet
    return n, packets


def split_name(path: str, index: int) -> str:
    """The name of the index-th file of a split recording: FILE's stem, .NNN, its extension
    (run.bin -> run.000.bin, run -> run.000)."""
    head, tail = os.path.split(path)
    stem, ext = os.path.splitext(tail)
    if not stem:  # ".bin": the name is its stem
        stem, ext = ext, ""
    return os.path.join(head, f"{stem}.{index:03d}{ext}")


class WriteFailed(Exception):
    """A write or file creation failed: the message is the one line to print."""


class Log:
    """The log file(s): writes whole chunks, and cuts a file back to its last whole packet when a
    write fails part way (a full disk, a file size limit)."""

    def __init__(self, path: str, reply: bytes, split_size: float, split_time: float) -> None:
        self.path = path
        self.reply = reply
        self.split_size = split_size
        self.split_time = split_time
        self.split = bool(split_size or split_time)
        self.index = 0
        self.fd = -1
        self.size = 0
        self.started = 0.0
        self.total = 0
        self.files: List[str] = []
        self._open()

    def _name(self) -> str:
        return split_name(self.path, self.index) if self.split else self.path

    def _open(self) -> None:
        name = self._name()
        try:
            self.fd = os.open(name, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0), 0o666)
        except OSError as e:
            what = "exists" if e.errno == errno.EEXIST else (e.strerror or str(e))
            raise WriteFailed(f"cannot create {name}: {what}") from None
        self.files.append(name)
        self.size = 0
        self.started = time.monotonic()
        self._write(self.reply)

    def _write(self, data: bytes) -> None:
        """All of data, or what was written of it cut back to its last whole packet (WriteFailed)."""
        done = 0
        try:
            while done < len(data):
                done += os.write(self.fd, data[done:])
        except OSError as e:
            if done:
                keep, _ = whole(data[:done])
                try:
                    os.ftruncate(self.fd, self.size + keep)
                    self.size += keep
                    self.total += keep
                except OSError:
                    pass
            raise WriteFailed(f"cannot write {self.files[-1]}: {e.strerror or e}") from None
        self.size += len(data)
        self.total += len(data)

    def write(self, data: bytes) -> None:
        """Whole packets (and bytes between packets); a new file first when the current one is
        full (--split-size: it holds BYTES or more) or old (--split-time)."""
        if not data:
            return
        if self.split and self.size > len(self.reply):
            full = self.split_size and self.size >= self.split_size
            old = self.split_time and time.monotonic() - self.started >= self.split_time
            if full or old:
                self.close()
                self.index += 1
                self._open()
        self._write(data)

    def close(self) -> None:
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1


def _is_reply(packet: Union[bytes, bytearray], set_id: int, descriptor: int) -> bool:
    if packet[SET_OFFSET] != set_id:
        return False
    payload = packet[HEADER_SIZE : len(packet) - CHECKSUM_SIZE]
    try:
        return any(f.descriptor == descriptor for f in iter_fields(set_id, payload) if hasattr(f, "descriptor"))
    except ValueError:
        return False


def _note(text: str) -> None:
    print(f"{PROG}: {text}", file=sys.stderr, flush=True)


def record(
    address: str,
    path: str,
    baud: int,
    timeout_ms: int,
    duration: Optional[float] = None,
    split_size: float = 0,
    split_time: float = 0.0,
) -> int:
    """Records the device at address into path; returns the exit status (messages on stderr)."""
    if path.lower().endswith(".mcap"):  # an MCAP file: recorded, then exported (record_mcap.py, docs/mcap.md)
        from .record_mcap import record_mcap

        return record_mcap(record, address, path, baud, timeout_ms, duration, split_size, split_time)
    found = identity_command()
    if found is None:
        _note("the spec names no device information command")
        return TROUBLE
    command, reply_cls = found
    if split_size < 0 or (split_time or 0) < 0 or (duration is not None and duration < 0):
        _note("record: --duration, --split-size and --split-time take a number >= 0")
        return TROUBLE
    existing = split_name(path, 0) if (split_size or split_time) else path
    if os.path.lexists(existing):
        _note(f"cannot create {existing}: exists")
        return TROUBLE
    try:
        transport = open_transport(address, baud)
    except (TransportError, ValueError) as e:
        _note(str(e))
        return TROUBLE
    stop: List[str] = []

    def on_signal(signum: int, _frame: Any) -> None:
        stop.append("interrupted" if signum == signal.SIGINT else "terminated")

    previous = {s: signal.signal(s, on_signal) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        return _run(transport, command, reply_cls, path, timeout_ms, duration, split_size, split_time, stop)
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
        transport.close()


def _run(
    transport: Any,
    command: Any,
    reply_cls: Any,
    path: str,
    timeout_ms: int,
    duration: Optional[float],
    split_size: float,
    split_time: float,
    stop: List[str],
) -> int:
    held = bytearray()  # received, not written yet
    reply: Optional[bytes] = None
    try:
        transport.write(build_packet(command.SET, command()))
        deadline = time.monotonic() + timeout_ms / 1000.0
        while reply is None:
            left = deadline - time.monotonic()
            if left <= 0 or stop:
                _note(f"no answer to the device information command ({command.NAME}: no reply before the timeout)")
                return DEVICE
            held += transport.read(min(left, READ_WAIT_S))
            _, packets = whole(held)
            for a, b in packets:
                if _is_reply(held[a:b], reply_cls.SET, reply_cls.DESCRIPTOR):
                    reply = bytes(held[a:b])
                    del held[a:b]  # written first, not again among the bytes around it
                    break
    except TransportError as e:
        _note(f"the device went away before it answered ({e.reason})")
        return DEVICE
    try:
        log = Log(path, reply, split_size, split_time)
    except WriteFailed as e:
        _note(str(e))
        return TROUBLE
    end = time.monotonic() + duration if duration else None
    status, why = STOPPED, "--duration"
    try:
        while True:
            end_at, _ = whole(held)
            log.write(bytes(held[:end_at]))
            del held[:end_at]
            if stop:
                why = stop[0]
                break
            now = time.monotonic()
            if end is not None and now >= end:
                break
            wait = READ_WAIT_S if end is None else min(READ_WAIT_S, end - now)
            try:
                held += transport.read(wait)
            except TransportError as e:
                status, why = DEVICE, f"the device went away ({e.reason})"
                end_at, _ = whole(held)
                log.write(bytes(held[:end_at]))
                del held[:end_at]
                break
    except WriteFailed as e:
        _note(str(e))
        status, why = TROUBLE, "the write failed"
        held.clear()  # not written: the disk is full, not a packet unfinished
    finally:
        log.close()
    left_out = f"; {len(held)} bytes of an unfinished packet left out" if held else ""
    _note(f"{log.total} bytes in {len(log.files)} file(s) ({', '.join(log.files)}); stopped: {why}{left_out}")
    return status
