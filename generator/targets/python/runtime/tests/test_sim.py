"""sim.py on the test protocol: the sans-I/O Simulator's answers (ACK, the NACKs, suppressed
acks), its faults and its samples split into continuation packets (docs/conformance.md section 9).
The end-to-end tests over a pty and TCP with the generated packages are
tests/conformance/test_simulator.py."""

from __future__ import annotations

import pytest
from testproto import control, sensor, shared
from testproto import types as t
from testproto.codec.framing import PacketBuilder, Parser, RawPacket
from testproto.codec.packets import decode_packet
from testproto.sim import Fault, Simulator


def ask(sim: Simulator, *fields, set_id: int = 0x01, now: float = 0.0):
    b = PacketBuilder(set_id)
    for f in fields:
        b.add(f) if not isinstance(f, tuple) else b.add_field(*f)
    return sim.feed(b.build(), now)


def acks(chunks):
    out = []
    for _, data in chunks:
        for e in Parser().feed(data):
            if isinstance(e, RawPacket):
                out += [(f.value.command_descriptor, int(f.value.ack_code)) for f in decode_packet(e.data).fields]
    return out


def test_answers_as_the_model_does():
    sim = Simulator("alpha")
    assert acks(ask(sim, control.Ping())) == [(0x01, 0)]
    assert acks(ask(sim, control.Ping(), control.SetMode(mode=t.Mode.ON))) == [(0x01, 0), (0x02, 0)]
    assert acks(ask(sim, (0x55, b""))) == [(0x55, 1)]  # unknown descriptor
    assert acks(ask(sim, (0x02, b"\x07"))) == [(0x02, 1)]  # mode 7: not a value of the enum
    assert acks(ask(sim, (0x02, b""))) == [(0x02, 1)]  # does not decode
    assert ask(sim, control.SetMode(mode=t.Mode.AUTO)) == []  # the spec suppresses its ack
    assert acks(ask(Simulator("beta"), control.SetMode(mode=t.Mode.ON))) == [(0x02, 1)]  # alpha only
    assert acks(ask(Simulator("beta"), (0x02, b""))) == [(0x02, 1)]  # alpha only, even undecodable
    assert ask(sim, sensor.Reading(), set_id=0x80) == []  # data sent to the device: ignored


def test_faults():
    faults = [Fault.parse(k, v) for k, v in (("drop", "ping@1"), ("delay", "ping:250@1"), ("split", "ping@1"))]
    faults += [Fault.parse("corrupt", "ping@1"), Fault.parse("garbage", "ping:3@1"), Fault.parse("nack", "ping:9@1")]
    sim = Simulator("alpha", faults=faults)
    assert acks(ask(sim, control.Ping())) == [(0x01, 9)]  # nack first, then the others in order
    assert ask(sim, control.Ping()) == []  # dropped
    [(at, data)] = ask(sim, control.Ping(), now=1.0)
    assert at == pytest.approx(1.25) and acks([(at, data)]) == [(0x01, 0)]
    (a, first), (b, second) = ask(sim, control.Ping(), now=2.0)
    assert b - a == pytest.approx(0.02) and acks([(0, first + second)]) == [(0x01, 0)]
    [(_, corrupt)] = ask(sim, control.Ping())
    assert acks([(0, corrupt)]) == [] and acks([(0, corrupt[:-1] + bytes([corrupt[-1] ^ 0xFF]))]) == [(0x01, 0)]
    [(_, noisy)] = ask(sim, control.Ping())
    assert len(noisy) == 3 + len(first + second) and acks([(0, noisy)]) == [(0x01, 0)]
    assert acks(ask(sim, control.Ping())) == [(0x01, 0)]  # every fault used up


def test_fault_options_are_checked():
    for kind, text in (("delay", "ping"), ("drop", "ping@0"), ("nack", "ping:x"), ("drop", "")):
        with pytest.raises(ValueError):
            Fault.parse(kind, text)
    with pytest.raises(ValueError, match="unknown device"):
        Simulator("gamma")


def test_a_sample_larger_than_a_packet_repeats_its_shared_fields():
    sim = Simulator("alpha", seed=3)
    sim.start_time = 0.0
    packets = sim.sample_packets(0x80, [0xD3] + [0x02] * 12, 0.5)
    assert len(packets) >= 2
    for p in packets:
        fields = decode_packet(p).fields
        assert fields[0].value == shared.Timestamp(ticks=500_000_000)  # the clock, in every packet
        assert all(f.descriptor == 0x02 for f in fields[1:])
        assert all(abs(f.value.scaled_accel[2] + 1.0) < 0.05 for f in fields[1:])  # gravity, in g
    assert sum(len(decode_packet(p).fields) - 1 for p in packets) == 12


def test_world_quantities_through_the_table_and_the_clock_speed():
    sim = Simulator("alpha", seed=1, scenario="circle", speed=4.0)
    sim.start_time = 0.0
    (packet,) = sim.sample_packets(0x80, [0x02, 0x07], 0.5)  # 2 s of simulated time at speed 4
    vector, gps = (f.value for f in decode_packet(packet).fields)
    assert (
        abs(vector.scaled_accel[1] - 0.5 / 9.80665) < 0.005
    )  # centripetal 5^2/50 m/s^2, in g (the table: specific force)
    assert abs(vector.scaled_accel[2] + 1.0) < 0.005
    assert gps.tow == pytest.approx(345602.0)  # GPS time of week at 2 s (the table: gps_tow)
    assert vector.ticks == 2_000_000_000  # the fallback: the clock, in simulated ns
    with pytest.raises(ValueError, match="unknown scenario"):
        Simulator("alpha", scenario="nowhere")


def test_factory_values_hold_on_their_device_and_start_a_message_format(monkeypatch):
    # _sim.FACTORY: device -> class -> values (the spec's defaults, on the devices whose manuals
    # state them); a format list's default streams before any format command (MS-CIP's message).
    from testproto import _sim

    monkeypatch.setattr(_sim, "FACTORY", {"alpha": {control.SetMode: {"mode": [0x02]}}})
    monkeypatch.setattr(_sim, "FORMATS", {control.SetMode: (0x80, "mode", None, None)})
    monkeypatch.setattr(_sim, "UNADDRESSED", {"alpha": (0x80,)})
    alpha, beta = Simulator("alpha"), Simulator("beta")
    assert alpha._factory(control.SetMode) == {"mode": [0x02]}
    assert beta._factory(control.SetMode) == {}
    alpha._replan()
    assert alpha.plan == {0x80: [(0x02, 1)]}
    monkeypatch.setattr(_sim, "FACTORY", {})
    alpha._replan()
    assert alpha.plan == {}  # no default, no format written: nothing streams


def test_identity_flags_are_checked_against_what_the_model_reports():
    # the test protocol reports no identity (its _sim.IDENTITY is empty): every flag is refused
    # with one line naming the device and the item
    from testproto.sim import parse_identity

    with pytest.raises(ValueError, match="^--serial 12: alpha reports no serial number$"):
        parse_identity("alpha", "serial", "12")
    with pytest.raises(ValueError, match="^--firmware 1: beta reports no firmware$"):
        parse_identity("beta", "firmware", "1")
    assert Simulator("alpha", identity={"serial_number": "x"}).identity == {"serial_number": "x"}
    assert Simulator("alpha").descriptor_lists() == []  # no descriptor-list command in the spec
