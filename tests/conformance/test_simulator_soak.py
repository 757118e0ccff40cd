"""Soak (issue 37, docs/conformance.md section 9): the simulator runs 24 simulated hours at
--speed 1440 (one minute of real time), hosts coming and going (readers, hosts that turn a stream
off and on again, hosts that vanish with a reset, hosts that leave half a packet or noise, hosts
that ping while the replies are faulted), GNSS outages and a magnetic disturbance on, with flat
memory and no lost sample.

The counter is the data's own clock: the reference timestamp (0xD5, nanoseconds since the
device started; 3dm-cv7-ins-docs.txt, shared data) leads every packet of the CV7's sensor set
(0x80, 1 kHz base rate, decimation 1000: one sample a simulated second) and filter set (0x82,
decimation 4000). Every host sees consecutive timestamps (exactly one period apart) for as long
as it is connected; a stream it turns off sends nothing until it is on again, then resumes from
now: its first sample is not older than the other set's latest (the device's clock at the time).
The figures (resident memory at the start, the end and its peak, the samples checked, the gaps)
are printed (pytest -s) so they can be quoted."""

from __future__ import annotations

import importlib
import random
import socket
import struct
import time
from typing import Dict, List, Optional

from tests.conformance.test_simulator import Sim
from tests.helpers.generated import python_package

pkg = python_package("mipcodec")
framing = importlib.import_module("mipcodec.codec.framing")
types = importlib.import_module("mipcodec.types")

SPEED = 1440  # 24 simulated hours in 60 s
DAY_NS = 24 * 3600 * 10**9
PERIOD = {0x80: 10**9, 0x82: 4 * 10**9}  # 1 kHz / 1000, 1 kHz / 4000 (ns)
DECIMATION = {0x80: 1000, 0x82: 4000}
FORMATS = {0x80: [0xD5], 0x82: [0xD5, 0x10]}  # reference timestamp; filter status
FAULTS = [
    "--gnss-outage", "3600:7200", "--gnss-outage", "50000:52000", "--mag-disturbance", "20000:21000",
    "--drop", "ping@3", "--delay", "ping:40@3", "--corrupt", "ping@3", "--split", "ping@3",
    "--garbage", "ping:9@3", "--nack", "ping@3",
]  # fmt: skip


def _command(field) -> bytes:
    b = framing.PacketBuilder(field.SET)
    b.add(field)
    return b.build()


def _format(set_id: int) -> bytes:
    items = [types.DescriptorRate(d, DECIMATION[set_id]) for d in FORMATS[set_id]]
    return _command(pkg.threedm.MessageFormat(desc_set=set_id, num_descriptors=len(items), descriptors=items))


def _enable(set_id: int, on: bool) -> bytes:
    return _command(pkg.threedm.DataStreamControl_cv7_ins(desc_set=set_id, enable=on))


def _rss_kb(pid: int, item: str = "VmRSS") -> int:
    with open(f"/proc/{pid}/status") as f:
        return next(int(line.split()[1]) for line in f if line.startswith(item + ":"))


class Host:
    """One connection: reads the stream, checks each set's timestamps are consecutive."""

    def __init__(self, port: int, stats: Dict[str, int]) -> None:
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=5)
        self.sock.settimeout(0.05)
        self.parser = framing.Parser()
        self.last: Dict[int, Optional[int]] = {0x80: None, 0x82: None}
        self.stats = stats
        self.acks: List[int] = []  # echoed descriptors of the acks of set 0x0C, in order
        self.latest = 0  # the latest timestamp seen of any set: the device's clock

    def read(self, seconds: float, until_acks: int = 0) -> None:
        end = time.monotonic() + seconds
        while time.monotonic() < end or len(self.acks) < until_acks:
            if time.monotonic() > end + 5:
                raise AssertionError(f"no ack within 5 s ({self.acks})")
            try:
                data = self.sock.recv(65536)
            except socket.timeout:
                continue
            if not data:
                raise AssertionError("the simulator closed a host that reads")
            for e in self.parser.feed(data):
                if isinstance(e, framing.RawPacket):
                    self._packet(e.data)

    def _packet(self, p: bytes) -> None:
        set_id = p[2]
        if set_id == 0x0C:
            self.acks.append(p[6])
            return
        if set_id not in PERIOD:
            return
        assert p[5] == 0xD5, p.hex()  # the shared timestamp leads every packet
        ns = int.from_bytes(p[6:14], "big")
        last = self.last[set_id]
        self.stats["checked"] += 1
        if last is not None:
            step = ns - last
            if step != PERIOD[set_id]:
                self.stats["gaps"] += 1
                raise AssertionError(f"set {set_id:#x}: {last} then {ns} (a period is {PERIOD[set_id]})")
        self.last[set_id] = ns
        self.latest = max(self.latest, ns)

    def command(self, packet: bytes) -> None:
        self.sock.sendall(packet)

    def off_and_on(self, set_id: int, off_s: float) -> None:
        """Turns `set_id` off, checks nothing of it comes, turns it on: resumes from now."""
        n = len(self.acks)
        self.command(_enable(set_id, False))
        self.read(0.0, until_acks=n + 1)
        stopped = self.last[set_id]
        self.read(off_s)
        assert self.last[set_id] == stopped, "data of a stream turned off"
        clock = self.latest
        self.last[set_id] = None  # the next sample starts a new run
        before = self.stats["checked"]  # before the enable: its first sample can share the ack's read
        self.command(_enable(set_id, True))
        self.read(0.0, until_acks=n + 2)
        while self.last[set_id] is None:
            self.read(0.05)
        assert self.last[set_id] >= clock, (set_id, self.last[set_id], clock)  # from now, no backlog
        self.stats["resumed"] += 1
        assert self.stats["checked"] > before

    def close(self, reset: bool = False) -> None:
        if reset:
            self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
        self.sock.close()
        self.stats["hosts"] += 1


def test_a_day_at_speed_with_hosts_coming_and_going_keeps_memory_flat_and_loses_nothing() -> None:
    rng = random.Random(37)
    stats = {"checked": 0, "gaps": 0, "hosts": 0, "resumed": 0, "rude": 0}
    rss: List[int] = []
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", "--speed", str(SPEED), *FAULTS) as sim:
        port = int(sim.address.rsplit(":", 1)[1])
        pid = sim.proc.pid
        started = time.monotonic()
        first = Host(port, stats)
        for set_id in PERIOD:
            first.command(_format(set_id))
        first.read(0.5, until_acks=len(PERIOD))
        first.close()
        latest = 0
        while latest < DAY_NS:
            assert time.monotonic() - started < 240, f"24 simulated hours not reached ({latest / 3.6e12:.1f} h)"
            rss.append(_rss_kb(pid))
            kind = rng.randrange(5)
            if kind == 4:  # a rude host: half a packet or noise, gone at once
                rude = socket.create_connection(("127.0.0.1", port))
                rude.sendall(rng.choice([b"\x75\x65\x01\xff", bytes(rng.randrange(256) for _ in range(4096))]))
                rude.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
                rude.close()
                stats["rude"] += 1
                continue
            host = Host(port, stats)
            host.read(rng.uniform(0.3, 1.5))
            if kind == 1:
                host.off_and_on(rng.choice(list(PERIOD)), rng.uniform(0.1, 0.4))
                host.read(rng.uniform(0.3, 1.0))
            elif kind == 2:
                for _ in range(3):
                    host.command(_command(pkg.base.Ping()))  # faulted replies: the stream goes on
                    host.read(0.2)
            latest = max(latest, host.latest)
            host.close(reset=kind == 3)
            time.sleep(rng.uniform(0.0, 0.3))  # nobody connected meanwhile
        wall = time.monotonic() - started
        peak = _rss_kb(pid, "VmHWM")
        assert sim.proc.poll() is None
    quarter = max(1, len(rss) // 4)
    head, tail = sum(rss[:quarter]) / quarter, sum(rss[-quarter:]) / quarter
    print(
        f"\nsoak: {latest / 3.6e12:.1f} simulated hours in {wall:.0f} s at --speed {SPEED}; "
        f"{stats['hosts']} hosts ({stats['rude']} rude, {stats['resumed']} streams turned off and on); "
        f"samples checked {stats['checked']}, gaps {stats['gaps']}; RSS start {rss[0]} KiB, "
        f"end {rss[-1]} KiB, peak {peak} KiB, first quarter {head:.0f} KiB, last quarter {tail:.0f} KiB"
    )
    assert stats["gaps"] == 0
    assert stats["resumed"] > 0 and stats["rude"] > 0
    # flat: the last quarter's memory within 2 MiB of the first's
    assert tail - head < 2048, (head, tail)
