"""Getting through (docs/conformance.md section 8): Device.to_idle, find_baud, the reconnect and
the settings it re-applies, on the test protocol, against its simulator (sim.py, sans-I/O) through
a transport driven by a fake clock, so every case is deterministic and instant.

The test protocol has no idle command (tests/runtime_specs/README.md): these tests give the ping
its place (`_link.IDLE`), as the spec's link section would name a command without parameters.
The end-to-end cases over a pty and TCP, in every language, are tests/conformance/test_link.py.
"""

from __future__ import annotations

from typing import List, Optional, Tuple

import pytest
from testproto import _link, control
from testproto.codec.framing import PacketBuilder
from testproto.session import (
    MAX_SETTINGS,
    Device,
    LinkError,
    LinkLost,
    baud_search_order,
)
from testproto.session.transport import TransportError
from testproto.sim import Fault, Simulator


class Clock:
    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


class SimPort:
    """A transport over a sans-I/O Simulator: reads advance the clock by their timeout (or to the
    next chunk due). `rate`/`baudrate`: the device's and the port's baud rate (None: no baud
    rate, as TCP); bytes at another rate are garbled both ways. `lost`: every call fails."""

    def __init__(self, sim: Simulator, clock: Clock, baudrate: Optional[int] = None, rate: Optional[int] = None):
        self.sim, self.clock = sim, clock
        self.queue: List[Tuple[float, bytes]] = []
        self.lost: Optional[str] = None
        self.sent: List[bytes] = []
        self.rate = rate
        if baudrate is not None:
            self.baudrate = baudrate
        self.flushes = 0

    def _garbled(self) -> bool:
        return self.rate is not None and getattr(self, "baudrate", self.rate) != self.rate

    def write(self, data: bytes) -> None:
        if self.lost:
            raise TransportError("write failed", self.lost)
        self.sent.append(data)
        if self._garbled():
            data = bytes(b ^ 0x5A for b in data)
        self.queue += self.sim.feed(data, self.clock.now)

    def read(self, timeout_s: float) -> bytes:
        if self.lost:
            raise TransportError("read failed", self.lost)
        self.queue += self.sim.poll(self.clock.now)
        self.queue.sort(key=lambda c: c[0])
        due = [c for c in self.queue if c[0] <= self.clock.now]
        if not due:
            nxt = min([c[0] for c in self.queue] + [self.clock.now + timeout_s])
            self.clock.now = max(self.clock.now, min(nxt, self.clock.now + timeout_s))
            self.queue += self.sim.poll(self.clock.now)
            self.queue.sort(key=lambda c: c[0])
            due = [c for c in self.queue if c[0] <= self.clock.now]
        self.queue = self.queue[len(due) :]
        data = b"".join(c[1] for c in due)
        return bytes(b ^ 0x5A for b in data) if self._garbled() else data

    def flush_input(self) -> None:
        self.flushes += 1
        self.queue = [c for c in self.queue if c[0] > self.clock.now]

    def close(self) -> None:
        pass


@pytest.fixture
def ping_is_idle(monkeypatch):
    monkeypatch.setattr(_link, "IDLE", _link.PING)


def streaming_sim(*faults: Fault) -> Simulator:
    sim = Simulator("alpha", faults=list(faults), stream_full=True)
    return sim


def test_to_idle_retries_after_a_lost_reply_and_drops_the_data(ping_is_idle) -> None:
    clock, lines, seen = Clock(), [], []
    sim = streaming_sim(Fault("drop", "ping", None, 1))
    port = SimPort(sim, clock)
    dev = Device(port, "alpha", timeout_ms=300, clock=clock, log=lines.append, on_event=seen.append)
    dev.on_packet(seen.append)
    result = dev.to_idle()
    assert result.status == "ack"
    assert seen == []  # the stream was counted and dropped, no handler saw it
    assert len(lines) == 2
    assert lines[0].startswith("link: idle: no ACK in 300 ms while streaming (")
    assert lines[0].endswith(" bytes dropped), flushing, attempt 2 of 3")
    assert lines[1].startswith("link: idle: ACK on attempt 2 of 3 (")
    assert port.flushes == 2  # before and after the quiet time
    assert len(port.sent) == 2  # the idle command sent twice


def test_to_idle_gives_up_after_the_spec_attempts(ping_is_idle) -> None:
    clock, lines = Clock(), []
    port = SimPort(streaming_sim(Fault("drop", "ping")), clock)
    dev = Device(port, "alpha", timeout_ms=200, clock=clock, log=lines.append)
    start = clock.now
    with pytest.raises(LinkError) as e:
        dev.to_idle()
    assert e.value.result.status == "timeout"  # type: ignore[attr-defined]
    assert len(port.sent) == _link.IDLE_ATTEMPTS == 3
    assert lines[-1] == "link: idle: no ACK after 3 attempts, giving up"
    assert [x.split(", ")[-1] for x in lines[:-1]] == ["attempt 2 of 3", "attempt 3 of 3"]
    assert clock.now - start < 3 * 0.2 + 3 * 0.05 + 0.1  # bounded: the timeouts and quiet times


def test_without_an_idle_command_to_idle_is_refused() -> None:
    clock, lines = Clock(), []
    dev = Device(SimPort(Simulator("alpha"), clock), "alpha", clock=clock, log=lines.append)
    with pytest.raises(LinkError, match="no idle command"):
        dev.to_idle()
    assert lines == ["link: idle: the protocol has no idle command"]


def test_baud_search_order_from_the_spec() -> None:
    # alpha: 9600, 115200 (default), 921600; beta: 115200, 230400, no default
    assert baud_search_order("alpha", 9600) == (9600, 115200, 921600)
    assert baud_search_order("alpha", 921600) == (921600, 115200, 9600)
    assert baud_search_order("beta", 9600) == (9600, 230400, 115200)
    assert baud_search_order(None, 230400) == (230400, 115200, 921600, 9600)


def test_find_baud_tries_the_rates_and_stays_at_the_one_that_answers() -> None:
    clock, lines = Clock(), []
    port = SimPort(Simulator("alpha", stream_full=True), clock, baudrate=9600, rate=921600)
    dev = Device(port, "alpha", timeout_ms=200, clock=clock, log=lines.append)
    assert dev.find_baud() == 921600
    assert port.baudrate == 921600
    assert lines == [
        "link: baud: no answer at 9600, trying 115200",
        "link: baud: no answer at 115200, trying 921600",
        "link: baud: device answers at 921600",
    ]
    assert dev.run(control.Ping()).status == "ack"


def test_find_baud_at_the_right_rate_says_nothing_and_skips_tcp() -> None:
    clock, lines = Clock(), []
    dev = Device(SimPort(Simulator("alpha"), clock, 115200, 115200), "alpha", clock=clock, log=lines.append)
    assert dev.find_baud() == 115200 and lines == []
    tcp = Device(SimPort(Simulator("alpha"), clock), "alpha", clock=clock, log=lines.append)
    assert tcp.find_baud() is None and lines == []


def test_find_baud_fails_when_no_rate_answers() -> None:
    clock, lines = Clock(), []
    port = SimPort(Simulator("beta"), clock, baudrate=115200, rate=9600)
    dev = Device(port, "beta", timeout_ms=100, clock=clock, log=lines.append)
    with pytest.raises(LinkError):
        dev.find_baud()
    assert lines[-1] == "link: baud: no answer at any rate"
    assert port.baudrate == 115200  # back at the configured rate


def test_a_lost_port_fails_the_command_in_flight_then_reconnects_and_reapplies(ping_is_idle, monkeypatch) -> None:
    clock, lines = Clock(), []
    sim = Simulator("alpha")
    ports = [SimPort(sim, clock)]
    opened = []

    def reopen() -> SimPort:
        opened.append(clock.now)
        if len(opened) < 3:  # not back yet: the path is gone
            clock.now += 0.5  # (the session sleeps; the fake clock follows)
            raise TransportError("cannot open", "No such file or directory")
        ports.append(SimPort(sim, clock))
        return ports[-1]

    dev = Device(
        ports[0],
        "alpha",
        timeout_ms=300,
        clock=clock,
        log=lines.append,
        reopen=reopen,
        address="/x/dev",
        reconnect_ms=5000,
    )
    import testproto.session as session_mod

    slept: List[float] = []
    monkeypatch.setattr(session_mod.time, "sleep", slept.append)
    assert dev.run(control.Gain(function=1, gain=7)).ok
    assert dev.run(control.Gain(function=1, gain=9)).ok  # the same key: the latest wins
    ports[0].lost = "Input/output error"
    result = dev.run(control.Gain(function=2))
    assert result.status == "lost" and result.error == "link lost: Input/output error"
    with pytest.raises(LinkLost):
        result.raise_for_status()
    assert lines[0] == "link: port lost (Input/output error), reopening /x/dev every 500 ms"
    assert lines[1].startswith("link: idle: ACK on attempt 1 of 3")
    assert lines[-1].startswith("link: reconnected after ") and lines[-1].endswith(" s, re-applied 1 settings")
    assert slept == [0.5, 0.5]
    # on the new port: the idle command, then the setting re-sent as last written (gain 9)
    reapplied = ports[1].sent
    assert reapplied[0] == PacketBuilder(0x01).add(control.Ping()).build()
    assert reapplied[1] == PacketBuilder(0x01).add(control.Gain(function=1, gain=9)).build()
    assert len(reapplied) == 2  # no resume command in this protocol
    assert dev.run(control.Gain(function=2)).response.gain == 9


def test_a_port_that_stays_away_gives_up(ping_is_idle, monkeypatch) -> None:
    clock, lines = Clock(), []

    def reopen() -> SimPort:
        clock.now += 0.5
        raise TransportError("cannot open", "No such file or directory")

    port = SimPort(Simulator("alpha"), clock)
    dev = Device(port, "alpha", clock=clock, log=lines.append, reopen=reopen, address="/x/dev", reconnect_ms=1200)
    import testproto.session as session_mod

    monkeypatch.setattr(session_mod.time, "sleep", lambda s: None)
    port.lost = "end of file"
    with pytest.raises(LinkError):
        dev.pump(10)
    assert lines == [
        "link: port lost (end of file), reopening /x/dev every 500 ms",
        "link: gave up reopening /x/dev after 1200 ms",
    ]


def test_without_reconnect_a_lost_port_raises() -> None:
    clock = Clock()
    port = SimPort(Simulator("alpha"), clock)
    dev = Device(port, "alpha", clock=clock)
    port.lost = "end of file"
    with pytest.raises(TransportError):
        dev.run(control.Ping())


def test_the_recorded_settings_are_bounded_and_keyed() -> None:
    clock = Clock()
    dev = Device(SimPort(Simulator("alpha"), clock), "alpha", clock=clock)
    for g in range(3):
        dev.run(control.Gain(function=1, gain=g))
    assert len(dev.settings) == 1 and list(dev.settings.values())[0].gain == 2
    dev.run(control.Gain(function=2))  # a read is not a setting
    assert len(dev.settings) == 1
    # more keys than the bound: the oldest are forgotten (fabricated keys, one per value)
    for k in range(MAX_SETTINGS + 5):
        dev.settings[("x", k)] = control.Ping()
    dev.run(control.Gain(function=1, gain=4))
    assert len(dev.settings) == MAX_SETTINGS
    assert list(dev.settings)[-1] == (0x01, 0x03)


def test_a_port_lost_during_to_idle_reconnects_and_keeps_the_handlers(ping_is_idle, monkeypatch) -> None:
    clock, lines, seen = Clock(), [], []
    sim = Simulator("alpha", stream_full=True)
    first = SimPort(sim, clock)
    dev = Device(
        first, "alpha", timeout_ms=300, clock=clock, log=lines.append,
        reopen=lambda: SimPort(sim, clock), address="/x/dev", reconnect_ms=2000,
    )  # fmt: skip
    dev.on_packet(seen.append)
    first.lost = "Input/output error"
    with pytest.raises(LinkLost):
        dev.to_idle()  # its idle command was in flight: lost, not retried
    assert lines[0] == "link: port lost (Input/output error), reopening /x/dev every 500 ms"
    assert lines[1].startswith("link: idle: ACK on attempt 1 of 3")  # the reconnect's own idle
    assert lines[2] == "link: reconnected after 0.0 s, re-applied 0 settings"
    assert seen == []
    dev.run(control.Ping())  # the device is idle: nothing streams, but the handler is back
    assert dev.session._packet_handlers == [seen.append]
