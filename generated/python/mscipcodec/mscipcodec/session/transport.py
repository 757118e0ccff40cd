"""Transports for the blocking session API (session.Device): TCP (standard library) and serial
(pyserial, the optional extra `mscipcodec[serial]`).

A transport has `write(data)`, `read(timeout_s) -> bytes` (the bytes available within
`timeout_s` seconds, at most READ_MAX, b"" when none came) and `close()`; a closed connection raises
TransportError. Anything with these three methods works (a test's fake, a USB bridge). Optional,
for getting through (docs/conformance.md section 8): `flush_input()` (drop what was received and
not read yet) and, on a serial port, a settable `baudrate`.
"""

from __future__ import annotations

import errno as _errno
import os
import socket
from typing import Any, Optional, Tuple

from .. import _extras

READ_MAX = 65536  # a read returns at most this many bytes (docs/conformance.md section 8)
FLUSH_MAX_READS = 64  # flush_input reads at most this many times (a flood never ends)


class TransportError(OSError):
    """The connection could not be opened, or it was closed or broke. `reason`: the system's error
    text of the failing call, or "end of file" (the link lines of docs/conformance.md section 8)."""

    def __init__(self, message: str, reason: Optional[str] = None) -> None:
        super().__init__(message)
        self.reason = reason or message


def _reason(e: BaseException) -> str:
    """The system's error text of an OSError (or of pyserial's exception carrying one)."""
    code = getattr(e, "errno", None)
    if isinstance(code, int) and code:
        return os.strerror(code)
    text = str(e)
    if "returned no data" in text:  # pyserial: readable, but the read gave nothing: end of file
        return "end of file"
    for code in (_errno.EIO, _errno.ENXIO, _errno.ENODEV, _errno.EBADF):
        if f"[Errno {code}]" in text:
            return os.strerror(code)
    return text


def parse_address(address: str) -> Tuple[str, Any]:
    """("tcp", (host, port)) for "tcp:HOST:PORT" (an IPv6 host in brackets), else ("serial", path)."""
    if address.startswith("tcp:"):
        rest = address[4:]
        host, sep, port = rest.rpartition(":")
        if not sep or not host or not port.isdigit() or not 0 < int(port) < 65536:
            raise ValueError(f"bad TCP address {address!r} (expected tcp:HOST:PORT)")
        if host.startswith("[") and host.endswith("]"):
            host = host[1:-1]
        return "tcp", (host, int(port))
    if not address:
        raise ValueError("empty address (expected tcp:HOST:PORT or a serial port path)")
    if looks_like_tcp(address) and not os.path.exists(address):
        raise ValueError(f"'{address}' is not a serial port: did you mean tcp:{address}?")
    return "serial", address


def looks_like_tcp(address: str) -> bool:
    """True for HOST:PORT without "tcp:" (127.0.0.1:5000, localhost:5000, [::1]:5000): a numeric
    port, no '/' or '\\' (a path), an IPv6 host in brackets. The four languages share the rule;
    such an address that is not an existing path is refused with "did you mean tcp:...?"."""
    host, sep, port = address.rpartition(":")
    if not sep or not host or not port.isdigit() or "/" in address or "\\" in address:
        return False
    return ":" not in host or (host.startswith("[") and host.endswith("]"))


class TcpTransport:
    """A TCP connection (a device server, a serial-to-TCP bridge, a simulator)."""

    def __init__(self, host: str, port: int, connect_timeout_s: float = 5.0) -> None:
        try:
            self._sock = socket.create_connection((host, port), timeout=connect_timeout_s)
        except OSError as e:
            raise TransportError(f"cannot connect to {host}:{port}: {e.strerror or e}") from None
        self._sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)

    def write(self, data: bytes) -> None:
        try:
            self._sock.sendall(data)
        except OSError as e:
            raise TransportError(f"send failed: {e.strerror or e}", _reason(e)) from None

    def read(self, timeout_s: float) -> bytes:
        self._sock.settimeout(max(timeout_s, 0.0) or 0.000001)
        try:
            data = self._sock.recv(READ_MAX)
        except socket.timeout:
            return b""
        except BlockingIOError:
            return b""
        except OSError as e:
            raise TransportError(f"receive failed: {e.strerror or e}", _reason(e)) from None
        if not data:
            raise TransportError("connection closed by the device", "end of file")
        return data

    def flush_input(self) -> None:
        """Drop what arrived and was not read yet (at most FLUSH_MAX_READS reads: under a flood
        there is always more)."""
        for _ in range(FLUSH_MAX_READS):
            if not self.read(0.0):
                break

    def close(self) -> None:
        self._sock.close()


class SerialTransport:
    """A serial port through pyserial (`pip install mscipcodec[serial]`)."""

    def __init__(self, path: str, baudrate: int = 115200) -> None:
        try:
            import serial  # type: ignore[import-not-found, import-untyped, unused-ignore]
        except ImportError:
            raise TransportError(f"serial ports: {_extras.missing('serial', 'serial')}") from None
        try:
            self._port = serial.Serial(path, baudrate=baudrate, timeout=0)
        except (OSError, ValueError, serial.SerialException) as e:
            raise TransportError(f"cannot open {path} at {baudrate} baud: {e}", _reason(e)) from None
        self._serial = serial

    @property
    def baudrate(self) -> int:
        """The port's baud rate; setting it changes the rate of the open port."""
        return int(self._port.baudrate)

    @baudrate.setter
    def baudrate(self, value: int) -> None:
        try:
            self._port.baudrate = value
        except (OSError, ValueError, self._serial.SerialException) as e:
            raise TransportError(f"cannot set {value} baud: {e}", _reason(e)) from None

    def flush_input(self) -> None:
        """Drop what arrived and was not read yet."""
        try:
            self._port.reset_input_buffer()
        except (OSError, self._serial.SerialException) as e:
            raise TransportError(f"flush failed: {e}", _reason(e)) from None

    def write(self, data: bytes) -> None:
        try:
            self._port.write(data)
        except (OSError, self._serial.SerialException) as e:
            raise TransportError(f"write failed: {e}", _reason(e)) from None

    def read(self, timeout_s: float) -> bytes:
        try:
            self._port.timeout = max(timeout_s, 0.0)
            first = self._port.read(1)
            if not first:
                return b""
            waiting = self._port.in_waiting
            data: bytes = first + (self._port.read(min(waiting, READ_MAX - 1)) if waiting else b"")
            return data
        except (OSError, self._serial.SerialException) as e:
            raise TransportError(f"read failed: {e}", _reason(e)) from None

    def close(self) -> None:
        try:
            self._port.close()
        except (OSError, self._serial.SerialException):
            pass  # a port that went away


def open_transport(address: str, baudrate: int = 115200, connect_timeout_s: Optional[float] = None) -> Any:
    """A transport for `address`: "tcp:HOST:PORT" or a serial port path (at `baudrate`)."""
    kind, where = parse_address(address)
    if kind == "tcp":
        return TcpTransport(where[0], where[1], 5.0 if connect_timeout_s is None else connect_timeout_s)
    return SerialTransport(where, baudrate)


__all__ = ["TransportError", "TcpTransport", "SerialTransport", "looks_like_tcp", "open_transport", "parse_address"]
