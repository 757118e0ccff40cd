"""Several TCP hosts at once on the simulator's address (docs/conformance.md section 9, "Several hosts";
runtime `sim/hosts.py`): a device port behind a network bridge with several clients. Every host
receives every byte the device sends; each host's bytes are framed on their own (half a packet
from one host never merges with another's); a host that does not read is dropped without holding
up the others; at most 8 hosts at once, the next connection closed at once.

The hosts are raw TCP sockets. Golden bytes come from the CV7 manual's worked examples
(3dm-cv7-ins-docs.txt): Ping "75650102 0201 E0C6" and its reply 75 65 01 04 04 F1 01 00 D5 6A
(lines 3903, 3911); Get Data Base Rate of the sensor set 0x80, "75650C03 030E80 7A7E", and its
reply "75650C09 04F10E00 058E8003E8 F058" (1000 Hz; lines 3919, 3921). The limits are the stated
ones (docs/conformance.md section 9): 8 hosts; a host that reads nothing for 5 s while output
waits is disconnected with a line on stderr."""

from __future__ import annotations

import importlib
import os
import socket
import time
from typing import List, Optional

from tests.conformance.test_simulator import Sim
from tests.helpers.generated import python_package

pkg = python_package("mipcodec")
framing = importlib.import_module("mipcodec.codec.framing")
types = importlib.import_module("mipcodec.types")

PING = bytes.fromhex("75650102 0201 E0C6")
PING_ACK = bytes.fromhex("7565 0104 04F1 0100 D56A")
BASE_RATE = bytes.fromhex("75650C03 030E80 7A7E")
BASE_RATE_REPLY = bytes.fromhex("75650C09 04F10E00 058E8003E8 F058")
MAX_HOSTS = 8
STALL_S = 5.0


def _command(field) -> bytes:
    b = framing.PacketBuilder(field.SET)
    b.add(field)
    return b.build()


def _format(descriptors: List[int], decimation: int) -> bytes:
    items = [types.DescriptorRate(d, decimation) for d in descriptors]
    return _command(pkg.threedm.MessageFormat(desc_set=0x80, num_descriptors=len(items), descriptors=items))


def _enable(on: bool) -> bytes:
    return _command(pkg.threedm.DataStreamControl_cv7_ins(desc_set=0x80, enable=on))


class Host:
    """A raw TCP host keeping every byte it reads and the packets in them."""

    def __init__(self, port: int, rcvbuf: Optional[int] = None, parse: bool = True) -> None:
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        if rcvbuf is not None:  # before connecting: the window it offers
            self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, rcvbuf)
        self.sock.connect(("127.0.0.1", port))
        self.sock.settimeout(0.05)
        self.data = bytearray()
        self.packets: List[bytes] = []
        self.parser = framing.Parser()
        self.closed = False
        self.parse = parse  # False: the bytes only (a flood)

    def send(self, data: bytes) -> None:
        self.sock.sendall(data)

    def read(self, seconds: float, until=None) -> None:
        """Reads for `seconds` (or until `until(self)` holds, at most `seconds`)."""
        end = time.monotonic() + seconds
        while time.monotonic() < end and not (until and until(self)):
            try:
                got = self.sock.recv(1 << 16)
            except socket.timeout:
                continue
            if not got:
                self.closed = True
                return
            self.data += got
            if self.parse:
                self.packets += [e.data for e in self.parser.feed(got) if isinstance(e, framing.RawPacket)]

    def quiet(self, gap: float = 0.3, most: float = 5.0) -> None:
        """Reads until nothing came for `gap` seconds."""
        end = time.monotonic() + most
        while time.monotonic() < end:
            n = len(self.data)
            self.read(gap)
            if len(self.data) == n:
                return

    def count(self, packet: bytes) -> int:
        return self.packets.count(packet)

    def close(self) -> None:
        self.sock.close()


def _stderr(sim: Sim) -> str:
    os.set_blocking(sim.proc.stderr.fileno(), False)
    try:
        return sim.proc.stderr.read() or ""
    except (BlockingIOError, TypeError):
        return ""


def _served(port: int, within: float) -> Host:
    """A new host whose ping is answered (retried while the simulator closes it at once)."""
    end = time.monotonic() + within
    while True:
        host = Host(port)
        try:
            host.send(PING)
            host.read(2, lambda h: h.count(PING_ACK) == 1)
        except OSError:
            pass
        if host.count(PING_ACK) == 1:
            return host
        host.close()
        assert time.monotonic() < end, f"no new host served within {within} s"
        time.sleep(0.05)


def test_hosts_share_the_line_frame_their_own_bytes_and_are_limited() -> None:
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0") as sim:
        port = int(sim.address.rsplit(":", 1)[1])
        a = Host(port)
        a.send(PING)
        a.read(5, lambda h: h.count(PING_ACK) == 1)
        b = Host(port)
        b.send(PING)
        b.read(5, lambda h: h.count(PING_ACK) == 1)
        a.read(5, lambda h: h.count(PING_ACK) == 2)
        assert a.count(PING_ACK) == 2  # B's reply reached A too: one line, every host hears it
        # A streams the sensor set at 10 Hz (decimation 100 of 1 kHz); both read, A stops it
        a.send(_format([0xD5, 0x04], 100) + _enable(True))
        b.read(0.5)
        a.send(_enable(False))
        for h in (a, b):  # until the third reply of set 0x0C (format, enable, disable), then a while
            h.read(5, lambda h: sum(p[2] == 0x0C for p in h.packets) == 3)
            h.quiet(0.1)
        data = [p for p in b.packets if p[2] == 0x80]
        assert len(data) >= 3, b.packets
        # what B received since it came is exactly the end of what A received
        assert a.data.endswith(b.data) and len(b.data) < len(a.data), (len(a.data), len(b.data))
        assert b.data.startswith(PING_ACK)

        # half a command from A, then a whole ping from B: only the ping is answered (to both);
        # A's other half then completes A's own command
        a.packets.clear()
        b.packets.clear()
        a.send(BASE_RATE[:5])
        time.sleep(0.1)
        b.send(PING)
        for h in (a, b):
            h.read(5, lambda h: bool(h.packets))
        time.sleep(0.1)  # anything else the simulator would send comes meanwhile
        for h in (a, b):
            h.read(0.05)
            assert h.packets == [PING_ACK], h.packets
        a.send(BASE_RATE[5:])
        for h in (a, b):
            h.read(5, lambda h: bool(h.packets[1:]))
        time.sleep(0.1)
        for h in (a, b):
            h.read(0.05)
            assert h.packets == [PING_ACK, BASE_RATE_REPLY], h.packets

        # the limit: 8 hosts at once (A, B and 6 more, each answered); the 9th is closed at once
        more = []
        for k in range(MAX_HOSTS - 2):
            more.append(Host(port))
            more[-1].send(PING)
            more[-1].read(5, lambda h: h.count(PING_ACK) == 1)
            assert more[-1].count(PING_ACK) == 1, k
        ninth = Host(port)
        ninth.read(5)
        assert ninth.closed and not ninth.data
        ninth.close()
        assert f"{MAX_HOSTS} hosts are connected: a connection from 127.0.0.1:" in _stderr(sim)
        more.pop().close()  # one leaves: a new host is served (once the simulator saw it go)
        a.quiet(0.1)
        n = a.count(PING_ACK)
        new = _served(port, 5.0)
        a.read(5, lambda h: h.count(PING_ACK) == n + 1)
        assert a.count(PING_ACK) == n + 1  # the others go on
        for h in [a, b, new, *more]:
            h.close()
        assert sim.proc.poll() is None


def test_a_host_that_does_not_read_is_dropped_without_holding_up_another() -> None:
    # --stream-full: the CV7 streams every documented quantity at its base rates (hundreds of KB/s);
    # N never reads (a small receive window): its kernel buffers and then its backlog fill, it is
    # disconnected after 5 s without reading, and meanwhile R receives the stream and has its
    # pings answered.
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", "--stream-full") as sim:
        port = int(sim.address.rsplit(":", 1)[1])
        r = Host(port, parse=False)
        r.send(PING)
        r.read(5, lambda h: h.data.count(PING_ACK) == 1)
        n = Host(port, rcvbuf=4096)
        n.send(PING)
        r.read(5, lambda h: h.data.count(PING_ACK) == 2)  # N is served: its reply reached R
        assert r.data.count(PING_ACK) == 2
        start = time.monotonic()
        slots: List[int] = []  # R's bytes per half second
        pings = 0
        while time.monotonic() - start < STALL_S + 8:
            before = len(r.data)
            if len(slots) % 2 == 1:
                r.send(PING)
                pings += 1
            r.read(0.5)
            slots.append(len(r.data) - before)
            if "disconnected" in _stderr(sim):
                break
        waited = time.monotonic() - start
        assert STALL_S < waited < STALL_S + 8, waited  # N was dropped, after its 5 s of not reading
        assert min(slots) > 10_000, slots  # R's stream never stopped meanwhile
        r.read(1.0, lambda h: h.data.count(PING_ACK) == 2 + pings)
        assert r.data.count(PING_ACK) == 2 + pings  # and its pings were answered
        n.sock.setblocking(True)
        n.sock.settimeout(5)
        try:  # N's connection is closed (end of file after what was buffered, or a reset)
            while n.sock.recv(1 << 20):
                pass
        except (ConnectionResetError, socket.timeout) as e:
            assert isinstance(e, ConnectionResetError), "N's connection is still open"
        n.close()
        r.close()
        assert sim.proc.poll() is None
