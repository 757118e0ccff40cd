"""session.py and transport.py: the sans-I/O session core, the blocking Device, the transports
(docs/conformance.md section 8), on the test protocol (ping on every device; set_mode on alpha
only, its ack suppressed by mode AUTO, with 500 ms of allowance)."""

from __future__ import annotations

import socket
import threading

import pytest
from testproto import control, reserved, sensor
from testproto import types as t
from testproto.codec.framing import PacketBuilder, Skip
from testproto.codec.packets import Packet
from testproto.session import (
    CommandRefused,
    CommandTimeout,
    Device,
    Nack,
    Result,
    Session,
    TimedParser,
    command_from_line,
)
from testproto.session.transport import TcpTransport, TransportError, open_transport, parse_address


def ack(descriptor: int, code: int = 0, set_id: int = 0x01, extra: tuple = ()) -> bytes:
    b = PacketBuilder(set_id).add(reserved.AckNack(command_descriptor=descriptor, ack_code=t.AckCode(code)))
    for f in extra:
        b.add(f)
    return b.build()


def data_packet() -> bytes:
    return PacketBuilder(0x80).add_field(0x01, b"\x00\x07\xff\x01").build()  # count 7, offset -1, valid


def results(events):
    return [e for e in events if isinstance(e, Result)]


def test_ack_matches_the_pending_command_whatever_the_split():
    reply = ack(0x01)
    for cut in range(len(reply) + 1):
        s = Session()
        p = s.start(control.Ping(), 0)
        assert p.packet == PacketBuilder(0x01).add(control.Ping()).build()
        events = s.feed(reply[:cut], 1) + s.feed(reply[cut:], 1)
        assert [r.status for r in results(events)] == ["ack"]
        assert p.result.status == "ack" and p.result.code == 0 and p.result.reply == []
        assert not s.pending


def test_nack_carries_the_typed_code():
    s = Session()
    p = s.start(control.Ping(), 0)
    s.feed(ack(0x01, 1), 5)
    assert p.result.status == "nack" and p.result.code == t.AckCode.UNKNOWN_COMMAND
    with pytest.raises(Nack) as e:
        p.result.raise_for_status()
    assert "unknown_command" in str(e.value)


def test_a_reply_for_another_command_or_set_is_a_packet():
    s = Session()
    seen = []
    s.on_packet(seen.append)
    p = s.start(control.Ping(), 0)
    events = s.feed(ack(0x02) + ack(0x01, set_id=0x02), 1)
    assert p.result is None and [type(e) for e in events] == [Packet, Packet] and len(seen) == 2
    s.feed(ack(0x01), 2)
    assert p.result.status == "ack" and len(seen) == 2  # the reply itself is not routed


def test_data_is_routed_while_a_command_is_pending():
    s = Session()
    packets, fields = [], []
    s.on_packet(packets.append)
    s.on_field(0x80, 0x01, lambda value, packet: fields.append((value, packet.set)))
    p = s.start(control.Ping(), 0)
    s.feed(b"\x00" + data_packet() + ack(0x01), 3)
    assert p.result.status == "ack"
    assert [pk.set for pk in packets] == [0x80] and len(fields) == 1 and fields[0][1] == 0x80


def _routing_stream() -> bytes:
    # Data, garbage and false syncs (of the pending command's set too), a reply for another
    # command, then the reply, then more data: what a session sees while a command is pending.
    false_sync = bytes([0x75, 0x65, 0x01, 0x05, 0x00])  # a header of set 0x01 whose packet never checks
    return (
        data_packet() * 3
        + b"\x00\x13"
        + false_sync
        + data_packet()
        + ack(0x02)
        + data_packet() * 2
        + ack(0x01)
        + data_packet()
        + b"\x75"
        + data_packet()
    )


def _kinds(events):
    return [
        (e.status,)
        if isinstance(e, Result)
        else ("skip", e.offset, e.count)
        if isinstance(e, Skip)
        else (e.set, e.offset)
        for e in events
    ]


@pytest.mark.parametrize("handlers", ["none", "packet", "two", "field", "both"])
def test_routing_with_a_pending_command_does_not_depend_on_chunks_or_handlers(handlers):
    # The session's routing (a fast path where no packet of a pending command's set can be among
    # the events, one in C when the accelerator is built) against the events of a plain Decoder:
    # every chunking gives the same events, the reply is matched once, every other packet reaches
    # the handlers in stream order, once, and the interleaving of handlers is per packet.
    from testproto.codec.packets import Decoder

    stream = _routing_stream()
    reference = Decoder().feed(stream) + Decoder().flush()
    replies = [
        i
        for i, e in enumerate(reference)
        if isinstance(e, Packet) and e.set == 0x01 and e.fields[0].value.command_descriptor == 1
    ]
    assert len(replies) == 1
    want = _kinds(reference[: replies[0]]) + [("ack",)] + _kinds(reference[replies[0] + 1 :])
    want_calls = [("p", e.offset) for e in reference if isinstance(e, Packet)]
    want_calls = [c for c in want_calls if c[1] != reference[replies[0]].offset]
    for size in (1, 2, 3, 7, 16, len(stream)):
        s = Session()
        calls: list = []

        def record(key, calls=calls):
            return lambda *args: calls.append((key, args[-1].offset))

        if handlers in ("packet", "two", "both"):
            s.on_packet(record("p"))
        if handlers == "two":
            s.on_packet(record("q"))
        if handlers in ("field", "both"):
            s.on_field(0x80, 0x01, record("f"))
        p = s.start(control.Ping(), 0)
        events = []
        for i in range(0, len(stream), size):
            events += s.feed(stream[i : i + size], 1)
        events += s.close(1)
        assert p.result.status == "ack" and not s.pending
        assert _kinds(events) == want, size
        if handlers == "packet":
            assert calls == want_calls
        elif handlers == "two":
            assert calls == [(k, o) for _p, o in want_calls for k in ("p", "q")]
        elif handlers == "field":
            assert calls == [
                ("f", o)
                for _p, o in want_calls
                if o not in [e.offset for e in reference if isinstance(e, Packet) and e.set != 0x80]
            ]
        elif handlers == "both":
            data = {e.offset for e in reference if isinstance(e, Packet) and e.set == 0x80}
            assert calls == [c for _p, o in want_calls for c in ([("p", o), ("f", o)] if o in data else [("p", o)])]
        else:
            assert calls == []


def test_timeout_then_late_reply_is_a_packet():
    s = Session(timeout_ms=100)
    p = s.start(control.Ping(), 0)
    assert s.next_deadline() == 100
    assert s.poll(99) == [] and p.result is None
    assert [r.status for r in results(s.poll(100))] == ["timeout"]
    events = s.feed(ack(0x01), 150)
    assert [type(e) for e in events] == [Packet]


def test_same_command_twice_first_in_first_out_and_queue_limit():
    s = Session(max_pending=2)
    a, b = s.start(control.Ping(), 0, tag="a"), s.start(control.Ping(), 0, tag="b")
    c = s.start(control.Ping(), 0)
    assert c.result.status == "refused" and not c.packet and "2 commands already pending" in c.result.error
    out = results(s.feed(ack(0x01, 1), 1))
    assert [r.tag for r in out] == ["a"] and a.result.status == "nack" and b.result is None


def test_two_acks_in_one_packet_answer_two_commands():
    s = Session()
    a, b = s.start(control.Ping(), 0), s.start(control.SetMode(mode=t.Mode.ON), 0)
    b2 = PacketBuilder(0x01)
    for d in (0x02, 0x01):
        b2.add(reserved.AckNack(command_descriptor=d, ack_code=t.AckCode.OK))
    assert [r.command.NAME for r in results(s.feed(b2.build(), 1))] == ["set_mode", "ping"]
    assert a.result.ok and b.result.ok


def test_reply_fields_after_the_ack_and_raw_fields_make_it_invalid():
    s = Session()
    p = s.start(control.Ping(), 0)
    packet = PacketBuilder(0x01).add(reserved.AckNack(command_descriptor=1)).add_field(0x33, b"\x01").build()
    s.feed(packet, 1)
    assert p.result.status == "invalid" and p.result.error == "unknown descriptor"
    assert p.result.line(7).startswith('{"line":7,"result":"invalid","code":0,"reply":[{"descriptor":51,')


def test_ack_suppression_allowance_and_device_support():
    s = Session(device="beta", timeout_ms=100)
    p = s.start(control.SetMode(mode=t.Mode.ON), 0)
    assert (
        p.result.status == "refused"
        and p.result.error == "set_mode is not supported by Beta (beta.txt)"
        and not p.packet
    )
    with pytest.raises(CommandRefused):
        p.result.raise_for_status()
    p = s.start(control.SetMode(mode=t.Mode.ON), 0, check_device=False)
    assert p.result is None and p.deadline == 600  # 100 + the spec's 500
    q = s.start(control.SetMode(mode=t.Mode.AUTO), 0, check_device=False)
    assert (
        q.result.status == "sent"
        and q.packet
        and q.result.line(2) == ('{"line":2,"result":"sent","code":null,"reply":[]}')
    )
    with pytest.raises(ValueError):
        Session(device="gamma")
    with pytest.raises(TypeError):
        s.start(sensor.FIELDS[0](), 0)


def test_look_ahead_drops_a_false_candidate_only_for_a_complete_packet_after_it():
    """Section 8: past the inter-packet timeout the parser skips to the first complete packet with
    a valid checksum after the position it waits at; without one it keeps waiting."""
    false = PacketBuilder(0x01).add_field(0x01, b"\x00" * 20).build()[:6]  # a header promising more
    p = TimedParser(100)
    assert p.feed_at(false + ack(0x01), 5) == []  # waits on the false candidate
    assert p.wait_deadline == 106
    assert p.feed_at(b"", 105) == []
    events = p.feed_at(b"", 106)
    assert isinstance(events[0], Skip) and events[0].data == false and events[1].offset == len(false)
    assert events[1].set == 0x01 and len(events) == 2 and p.wait_deadline is None
    # a false candidate with nothing complete after it waits; the ACK arriving later (the wait
    # expired long before) is found after the new bytes are added
    p = TimedParser(100)
    assert p.feed_at(false, 5) == [] and p.wait_deadline == 106
    assert p.feed_at(b"", 106) == [] and p.wait_deadline is None  # expired, nothing to find
    events = p.feed_at(ack(0x01), 300)
    assert [type(e) for e in events] == [Skip, Packet] and events[0].data == false
    assert events[1].offset == len(false)


def test_a_slow_packet_is_never_dropped_by_time():
    whole = ack(0x01)
    for cut in range(1, len(whole)):
        p = TimedParser(100)
        assert p.feed_at(whole[:cut], 0) == [] and p.wait_deadline == 101
        assert p.feed_at(b"", 101) == [] and p.wait_deadline is None
        events = p.feed_at(whole[cut:], 5000)
        assert len(events) == 1 and events[0].offset == 0 and events[0].set == 0x01, cut
    s = Session(timeout_ms=1000)
    q = s.start(control.Ping(), 0)
    s.feed(whole[:5], 5)
    assert s.next_deadline() == 106
    s.poll(106)
    assert s.next_deadline() == 1000  # the wait expired: only the command's deadline is left
    s.feed(whole[5:], 900)
    assert q.result.status == "ack"


def test_skip_runs_are_reported_in_pieces_of_65536_bytes_whatever_the_split():
    """A pending skip run is reported as soon as it reaches SKIP_PIECE bytes; every piece is
    exactly that long and the pieces tile the offsets, however the input is split."""
    from testproto.session import SKIP_PIECE

    assert SKIP_PIECE == 65536
    noise = bytes(200000)  # no sync byte at all
    for chunk in (200000, 65536, 65535, 1000, 77777):
        p = TimedParser(100)
        events = []
        for k in range(0, len(noise), chunk):
            events += p.feed_at(noise[k : k + chunk], 0)
            assert len(p._skip) < SKIP_PIECE and len(p._buf) < 2
        assert [(e.offset, len(e.data)) for e in events] == [(0, 65536), (65536, 65536), (131072, 65536)], chunk
        rest = p.flush()
        assert [(e.offset, len(e.data)) for e in rest] == [(196608, 3392)]
    # a run longer than a piece ending at a packet in the same feed: the pieces, then the rest
    p = TimedParser(100)
    events = p.feed_at(bytes(70000) + ack(0x01), 0)
    assert [(type(e), e.offset, len(e.data)) for e in events[:2]] == [(Skip, 0, 65536), (Skip, 65536, 4464)]
    assert events[2].offset == 70000 and len(events) == 3
    # the session matches the reply behind them (the indexes of the watched packets follow)
    s = Session()
    q = s.start(control.Ping(), 0)
    events = s.feed(bytes(140000) + ack(0x01) + bytes(3), 1)
    assert [len(e.data) for e in events if isinstance(e, Skip)] == [65536, 65536, 8928]
    assert q.result.status == "ack" and events[3] is q.result


def test_a_flood_of_false_syncs_holds_bounded_memory():
    """Repeated false syncs (a length claiming 240 bytes): the parser holds at most one packet
    of undecided bytes and a pending skip run shorter than a piece after every feed."""
    from testproto.codec.framing import MAX_PACKET, SYNC

    flood = (SYNC + b"\x01\xf0") * 50000
    p = TimedParser(100)
    total = 0
    for k, at in zip(range(0, len(flood), 65536), range(0, 10**6, 7)):
        for e in p.feed_at(flood[k : k + 65536], at):
            assert isinstance(e, Skip) and e.offset == total and len(e.data) == 65536
            total += len(e.data)
        assert len(p._buf) <= MAX_PACKET and len(p._skip) < 65536
    assert total + len(p._skip) + len(p._buf) == len(flood)


class FloodTransport:
    """A transport whose reads always return a full read of zeros (a device sending noise)."""

    def __init__(self) -> None:
        self.asked = []

    def write(self, data: bytes) -> None:
        pass

    def read(self, timeout_s: float) -> bytes:
        self.asked.append(timeout_s)
        return bytes(65536)

    def close(self) -> None:
        pass


def test_device_keeps_its_deadline_under_a_flood():
    import time as _time

    seen = []
    tr = FloodTransport()
    dev = Device(tr, device="alpha", timeout_ms=200, on_event=seen.append)
    t0 = _time.monotonic()
    r = dev.run(control.Ping())
    late = _time.monotonic() - t0 - 0.2
    assert r.status == "timeout" and late < 2.0  # a functional bound: one read's handling past it
    skips = [e for e in seen if isinstance(e, Skip)]
    assert skips and all(len(e.data) == 65536 for e in skips)
    assert [e.offset for e in skips] == [65536 * k for k in range(len(skips))]
    assert all(t <= 0.2 for t in tr.asked)  # never waits past the deadline


def test_command_from_line():
    assert isinstance(
        command_from_line('{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}'), control.Ping
    )
    for bad in ("[]", '{"offset":0,"set":1,"fields":[]}', '{"offset":0,"skipped":"00"}'):
        with pytest.raises(ValueError):
            command_from_line(bad)


class FakeTransport:
    """Answers each written command with the scripted bytes (None: nothing)."""

    def __init__(self, answers: list) -> None:
        self.answers = list(answers)
        self.written: list[bytes] = []
        self.pending = b""
        self.closed = False

    def write(self, data: bytes) -> None:
        self.written.append(data)
        self.pending += self.answers.pop(0) or b""

    def read(self, timeout_s: float) -> bytes:
        out, self.pending = self.pending, b""
        return out

    def close(self) -> None:
        self.closed = True


def test_device_blocking_calls_and_typed_api():
    clock = [0.0]

    def tick() -> float:
        clock[0] += 0.01
        return clock[0]

    tr = FakeTransport([data_packet() + ack(0x01), ack(0x02, 1), None])
    seen = []
    with Device(tr, device="alpha", timeout_ms=50, clock=tick) as dev:
        dev.on_packet(seen.append)
        dev.control.ping()
        with pytest.raises(Nack):
            dev.control.set_mode(t.Mode.ON)
        with pytest.raises(CommandTimeout):
            dev.control.ping()
    assert tr.closed and [p.set for p in seen] == [0x80] and len(tr.written) == 3
    dev = Device(FakeTransport([]), device="beta")
    with pytest.raises(CommandRefused):
        dev.control.set_mode(t.Mode.ON)


def test_parse_address_and_tcp_transport():
    assert parse_address("tcp:localhost:5000") == ("tcp", ("localhost", 5000))
    assert parse_address("tcp:[::1]:5000") == ("tcp", ("::1", 5000))
    assert parse_address("/dev/ttyUSB0") == ("serial", "/dev/ttyUSB0")
    for bad in ("tcp:host", "tcp::5", "tcp:h:0", "tcp:h:99999", ""):
        with pytest.raises(ValueError):
            parse_address(bad)
    srv = socket.socket()
    srv.bind(("127.0.0.1", 0))
    srv.listen(1)

    def serve() -> None:
        conn, _ = srv.accept()
        conn.sendall(conn.recv(100)[::-1])
        conn.close()

    th = threading.Thread(target=serve)
    th.start()
    tr = open_transport(f"tcp:127.0.0.1:{srv.getsockname()[1]}")
    assert isinstance(tr, TcpTransport)
    tr.write(b"abc")
    got = b""
    while len(got) < 3:
        got += tr.read(1.0)
    assert got == b"cba"
    th.join()
    with pytest.raises(TransportError, match="closed"):
        while True:
            tr.read(1.0)
    tr.close()
    srv.close()


def test_serial_transport_without_pyserial_says_how_to_get_it():
    try:
        import serial  # noqa: F401
    except ImportError:
        with pytest.raises(TransportError, match="pyserial"):
            open_transport("/dev/ttyUSB0")
    else:
        with pytest.raises(TransportError, match="cannot open"):
            open_transport("/nonexistent/tty")


def test_session_tool_input_lines_are_read_in_bounded_pieces(monkeypatch):
    """A line longer than MAX_LINE bytes (without its newline) is reported as None and read past
    in pieces of at most MAX_LINE + 1 bytes; every line is counted; the last needs no newline."""
    import io

    from testproto import session_tool as st

    assert st.MAX_LINE == 1048576
    monkeypatch.setattr(st, "MAX_LINE", 8)
    reads = []

    class Stream(io.BytesIO):
        def readline(self, size=-1):
            reads.append(size)
            return super().readline(size)

    data = b"12345678\n123456789\n\n" + b"x" * 30 + b"\n \t\r\n12345678"
    got = list(st._lines(Stream(data)))
    assert got == [(1, b"12345678"), (2, None), (3, b""), (4, None), (5, b" \t\r"), (6, b"12345678")]
    assert set(reads) == {9}  # never more than MAX_LINE + 1 bytes asked for


def test_session_tool_option_ranges_and_baud_rates():
    """Section 8's option table: decimal ASCII digits only, leading zeros accepted, the ranges,
    and --baud one of the IR's rates of any model (testproto: alpha 9600, 115200, 921600; beta
    115200, 230400), named by the protocol."""
    from testproto import session_tool as st

    assert st._ranged("--timeout-ms", "0100", 1, 600000) == 100
    assert st._ranged("--timeout-ms", "600000", 1, 600000) == 600000
    for bad in ("0", "600001", "+5", "-1", "1e3", "0x10", "", " 5", "\u0665", "9" * 5000):
        with pytest.raises(st.UsageError) as e:
            st._ranged("--timeout-ms", bad, 1, 600000)
        assert str(e.value) == f"--timeout-ms: expected an integer from 1 to 600000, got {bad}"
    assert st._baud("230400") == 230400 and st._baud("09600") == 9600
    for bad in ("57600", "", "+9600", "9600.0"):
        with pytest.raises(st.UsageError) as e:
            st._baud(bad)
        assert str(e.value) == f"--baud: {bad} is not a baud rate of testproto devices (9600, 115200, 230400, 921600)"
    with pytest.raises(st.UsageError, match=r"^--connect ADDRESS is required$"):
        st._options(["--timeout-ms", "5"])


# The example GGA sentence NMEA references quote (checksum 47) and the RTCM 10403 example frame of
# message 1005 (19 payload bytes, CRC-24Q 36 0B 98).
GGA = b"$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n"
RTCM_1005 = bytes.fromhex("D300133ED7D30202980EDEEF34B4BD62AC0941986F33360B98")


def test_nmea_and_rtcm_between_packets_go_to_the_foreign_handler_whatever_the_split():
    """Framing a carries NMEA and RTCM3 between its packets (docs/conformance.md section 1): the
    sentence and the frame are events of their own and reach on_foreign in stream order with the
    packet handlers, and the reply after them still answers its command. Framing b has none: the
    same bytes are skip runs and the handler is never called."""
    from testproto.codec.framing import FOREIGN_NMEA, FOREIGN_RTCM3, Nmea, Rtcm

    data = data_packet()
    stream = GGA + data + RTCM_1005 + ack(0x01)
    foreign = FOREIGN_NMEA and FOREIGN_RTCM3
    for cut in range(len(stream) + 1):
        s = Session()
        p = s.start(control.Ping(), 0)
        seen = []
        s.on_foreign(seen.append)
        s.on_packet(lambda pk, seen=seen: seen.append(pk.offset))
        events = s.feed(stream[:cut], 1) + s.feed(stream[cut:], 1) + s.close(2)
        assert p.result.status == "ack", cut
        kinds = [type(e).__name__ for e in events]
        if foreign:
            assert kinds == ["Nmea", "Packet", "Rtcm", "Result"], cut
            assert seen == [Nmea(0, GGA), len(GGA), Rtcm(len(GGA) + len(data), RTCM_1005)], cut
            assert seen[0].sentence == GGA[:-2].decode() and seen[2].message_type == 1005 and seen[2].length == 19
        else:
            assert kinds == ["Skip", "Packet", "Skip", "Result"], cut
            assert seen == [len(GGA)], cut


def test_without_a_foreign_handler_frames_are_only_events():
    """The default: no handler, the frames are listed among the events (a caller that does not
    look at them loses nothing else), and a packet handler sees only packets."""
    s = Session()
    seen = []
    s.on_packet(lambda pk: seen.append(pk.offset))
    events = s.feed(RTCM_1005 + data_packet() + GGA, 0) + s.close(0)
    assert seen == [len(RTCM_1005)]
    assert len(events) == 3 and events[1].offset == len(RTCM_1005)
