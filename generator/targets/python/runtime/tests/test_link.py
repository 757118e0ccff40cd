"""Getting through (docs/conformance.md section 8): the link corpus tests/link/cases.txt (format and
the fake device's rules in tests/link/README.md), run by Device.to_idle, find_baud, the reconnect
and the settings it re-applies, as the C, C++ and Rust runtimes run it; then the cases of this
language's API only (the search order, the bound on the recorded settings).

The test protocol has no idle command (tests/runtime_specs/README.md): a case gives the ping its
place (`_link.IDLE`) unless it says `set idle none`. The end-to-end cases over a pty and TCP, in
every language, are tests/conformance/test_link.py.
"""

from __future__ import annotations

import re
import time
from pathlib import Path
from typing import Any, Dict, List, Optional

import pytest
from testproto import _link, control
from testproto.codec.framing import PacketBuilder
from testproto.session import (
    MAX_SETTINGS,
    CommandFailed,
    Device,
    LinkError,
    LinkLost,
    baud_search_order,
)
from testproto.session.transport import TransportError

CASES = Path(__file__).resolve().parents[5] / "tests" / "link" / "cases.txt"
REASON = "Input/output error"
DATA = PacketBuilder(0x80).add_field(0x01, bytes([0x01, 0x00, 0x00, 0x01])).build()
PING = PacketBuilder(0x01).add(control.Ping()).build()


def _ack(descriptor: int) -> bytes:
    return PacketBuilder(0x01).add_field(0xF1, bytes([descriptor, 0x00])).build()


class FakeDevice:
    """The scripted device of tests/link/README.md: a fake clock in ms, a port that can be lost."""

    def __init__(self, settings: Dict[str, str]) -> None:
        self.now = 0
        self.to_host = bytearray()
        self.sent: List[bytes] = []
        self.streaming = "streaming" in settings
        self.unanswered = int(settings.get("unanswered", "0"))
        self.answers_at = int(settings.get("answers_at", "0"))
        baud = settings.get("baud", "115200")
        self.rate: Optional[int] = None if baud == "none" else int(baud)
        self.lost = False
        self.reopen_failures = 0
        self.flushes = 0
        self.sleeps: List[int] = []

    def reopen(self) -> FakePort:
        if self.reopen_failures > 0:
            self.reopen_failures -= 1
            raise TransportError("cannot open", "No such file or directory")
        self.lost = False
        return FakePort(self)


class FakePort:
    def __init__(self, dev: FakeDevice) -> None:
        self.dev = dev

    def __getattr__(self, name: str) -> Any:
        if name == "baudrate" and self.dev.rate is not None:  # no baud rate over TCP
            return self.dev.rate
        raise AttributeError(name)

    def __setattr__(self, name: str, value: Any) -> None:
        if name == "baudrate":
            self.dev.rate = value
        else:
            object.__setattr__(self, name, value)

    def write(self, data: bytes) -> None:
        d = self.dev
        if d.lost:
            raise TransportError("write failed", REASON)
        d.sent.append(bytes(data))
        if (d.answers_at and d.rate != d.answers_at) or d.unanswered > 0:
            d.unanswered -= 1
            return
        if bytes(data) == PING:  # the idle command of these cases
            d.streaming = False
        d.to_host += _ack(0x01 if bytes(data) == PING else 0x03)  # ping, else gain

    def read(self, timeout_s: float) -> bytes:
        d = self.dev
        if d.lost:
            raise TransportError("read failed", REASON)
        if not d.to_host and d.streaming:
            d.to_host += DATA
            d.now += 10
        if not d.to_host:
            d.now += round(timeout_s * 1000)
            return b""
        data, d.to_host = bytes(d.to_host), bytearray()
        return data

    def flush_input(self) -> None:
        self.dev.flushes += 1
        self.dev.to_host.clear()

    def close(self) -> None:
        pass


def _cases() -> List[Any]:
    cases, case = [], None
    for line in CASES.read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        what, _, rest = line.partition(" ")
        if what == "case":
            case = {"name": rest, "set": {}, "steps": [], "log": [], "expect": {}}
        elif what == "set":
            key, _, value = rest.partition(" ")
            case["set"][key] = value
        elif what == "step":
            case["steps"].append(rest.split())
        elif what == "log":
            case["log"].append(rest)
        elif what in ("sent", "flushes", "packets", "sleeps", "rate"):
            case["expect"][what] = rest
        elif what == "end":
            cases.append(pytest.param(case, id=case["name"]))
        else:
            raise AssertionError(f"{CASES}: unknown line {line!r}")
    return cases


def _expanded(line: str) -> str:
    sizes = {"data": len(DATA), "ack": len(_ack(0x01))}
    return re.sub(r"\{(data|ack) (\d+)\}", lambda m: str(sizes[m[1]] * int(m[2])), line)


def _packet(token: str) -> bytes:
    if token == "ping":
        return PING
    if token == "read":
        return PacketBuilder(0x01).add(control.Gain(function=2)).build()
    assert token.startswith("write:"), token
    return PacketBuilder(0x01).add(control.Gain(function=1, gain=int(token[6:]))).build()


def _command_result(dev: Device, command: Any) -> str:
    try:
        return dev.run(command).status
    except LinkError:  # the port did not come back: the command was lost with it
        return "lost"
    except TransportError:
        return "error"


def _to_idle(dev: Device) -> str:
    try:
        return dev.to_idle().status
    except LinkLost:
        return "lost"
    except CommandFailed as e:
        return e.result.status
    except LinkError as e:
        result = getattr(e, "result", None)
        return result.status if result is not None else "refused"


def _find_baud(dev: Device) -> str:
    try:
        return "none" if dev.find_baud() is None else "ack"
    except LinkError:
        return "fail"


def _step(dev: Device, fake: FakeDevice, step: List[str]) -> Optional[str]:
    what = step[0]
    if what == "lose":
        fake.lost, fake.reopen_failures = True, int(step[1])
        return None
    if what == "stream":
        fake.streaming = True
        return None
    if what == "to_idle":
        return _to_idle(dev)
    if what == "find_baud":
        return _find_baud(dev)
    if what == "listen":
        try:
            dev.listen(int(step[1]))
            return "ok"
        except (LinkError, TransportError):
            return "fail"
    if what == "ping":
        return _command_result(dev, control.Ping())
    if what == "read":
        return _command_result(dev, control.Gain(function=2))
    assert what == "write", step
    return _command_result(dev, control.Gain(function=1, gain=int(step[1])))


@pytest.mark.parametrize("case", _cases())
def test_link_corpus(case: Dict[str, Any], monkeypatch: pytest.MonkeyPatch) -> None:
    settings = case["set"]
    if settings.get("idle") != "none":
        monkeypatch.setattr(_link, "IDLE", _link.PING)
    fake = FakeDevice(settings)

    def sleep(seconds: float) -> None:
        fake.sleeps.append(round(seconds * 1000))
        fake.now += round(seconds * 1000)

    monkeypatch.setattr(time, "sleep", sleep)
    reconnect = settings.get("reconnect", "10000")
    model = settings.get("model", "alpha")
    lines: List[str] = []
    packets: List[Any] = []
    dev = Device(
        FakePort(fake),
        None if model == "none" else model,
        clock=lambda: fake.now / 1000.0,
        log=lines.append,
        reopen=fake.reopen,
        address="/tmp/x/dev",
        reconnect_ms=None if reconnect == "off" else int(reconnect),
    )
    dev.on_packet(packets.append)
    for step in case["steps"]:
        got = _step(dev, fake, step)
        want = step[-1] if step[0] not in ("lose", "stream") else None
        if want is not None and want != "any":
            assert got == want, f"{step}: {got}"
    assert lines == [_expanded(x) for x in case["log"]]
    expect = case["expect"]
    if "sent" in expect:
        assert fake.sent == [_packet(t) for t in expect["sent"].split()]
    if "flushes" in expect:
        assert fake.flushes == int(expect["flushes"])
    if "packets" in expect:
        assert len(packets) == int(expect["packets"])
    if "sleeps" in expect:
        assert fake.sleeps == [int(x) for x in expect["sleeps"].split()]
    if "rate" in expect:
        assert str(fake.rate).lower() == expect["rate"]


# ------------------------------------------------------------------ this language's API only


def test_baud_search_order_from_the_spec() -> None:
    # alpha: 9600, 115200 (default), 921600; beta: 115200, 230400, no default
    assert baud_search_order("alpha", 9600) == (9600, 115200, 921600)
    assert baud_search_order("alpha", 921600) == (921600, 115200, 9600)
    assert baud_search_order("beta", 9600) == (9600, 230400, 115200)
    assert baud_search_order(None, 230400) == (230400, 115200, 921600, 9600)


def test_the_recorded_settings_are_bounded_and_keyed() -> None:
    fake = FakeDevice({})
    dev = Device(FakePort(fake), "alpha", clock=lambda: fake.now / 1000.0)
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


def test_a_lost_command_raises_link_lost() -> None:
    fake = FakeDevice({})
    dev = Device(
        FakePort(fake), "alpha", clock=lambda: fake.now / 1000.0, log=lambda _: None,
        reopen=fake.reopen, address="/tmp/x/dev", reconnect_ms=1000,
    )  # fmt: skip
    fake.lost = True
    result = dev.run(control.Ping())
    assert result.error == f"link lost: {REASON}"
    with pytest.raises(LinkLost):
        result.raise_for_status()


def test_the_handlers_are_back_after_a_reconnect_inside_to_idle(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(_link, "IDLE", _link.PING)
    seen: List[Any] = []
    fake = FakeDevice({})
    dev = Device(
        FakePort(fake), "alpha", clock=lambda: fake.now / 1000.0, log=lambda _: None,
        reopen=fake.reopen, address="/tmp/x/dev", reconnect_ms=2000,
    )  # fmt: skip
    dev.on_packet(seen.append)
    fake.lost = True
    with pytest.raises(LinkLost):
        dev.to_idle()
    assert dev.session._packet_handlers == [seen.append]
