"""NMEA-0183 out and in of the simulated CV7 (issue 53 item 2; docs/simulator-world.md "NMEA").

The sentences are read with a parser written here from NMEA-0183 ('$', the address, comma
separated fields, '*', two hex digits of the XOR of the characters between '$' and '*', CR LF;
latitude ddmm.mmmm and longitude dddmm.mmmm with their hemisphere), not with the simulator's.
Golden values come from the CV7 manual: the sentences, talker IDs and applicable sources (line
1013), the rate limits of 10 Hz from IMU and filter sources and 2 Hz from a GNSS source, above
which the command is NACKed (line 1062), the code 0x03 Invalid Parameter (line 8878) the simulator
answers (a decision: the manual names no code), the base rates 1000 Hz (0x80, 0x82) and 5 Hz
(0x91) (line 2688), the PMSRA/PMSRR layouts and their examples (lines 1027-1052), NMEA input on
the main port mirrored into 0x94 after two updates with the sentences' timestamps (lines
1102-1112); the sentence and talker codes (GGA 1, RMC 4, VTG 5, ZDA 7, GST 8, GSV 3, PMSRA 129,
PMSRR 130; GN 1, GP 2) are those of the spec (an unresolved note: the manual gives none). The
circle scenario: a 50 m circle at 5 m/s from the world's origin (docs/simulator-world.md).

1. In process (the sans-I/O Simulator): the manual's proprietary examples, the rate limits and bad
   entries, the sentences' fields and rates against the scenario, idle, and NMEA input.
2. End to end over TCP through the Python session API: NMEA output parsed and checked against the
   MIP data of the same stream, the rate-limit NACK, NMEA input showing up in 0x94.
"""

from __future__ import annotations

import datetime
import math
import time

import pytest

from tests.conformance.test_simulator import Sim, open_device, pump_for
from tests.conformance.test_simulator_world import pkg, sim_mod, t, world_mod

GGA, GLL, GSV, RMC, VTG, HDT, ZDA, GST, PMSRA, PMSRR = 1, 2, 3, 4, 5, 6, 7, 8, 129, 130
GN, GP = 1, 2
INVALID_PARAMETER = 0x03  # CV7 line 8878
PMSRA_EXAMPLE = b"$PMSRA,221336.93,-0.172,-0.681,3.072*5D"  # CV7 line 1036
PMSRR_EXAMPLE = b"$PMSRR,221336.93,-0.012996,0.004631,-1.000471,0.280331,0.130576,0.207637*4D"  # line 1052


# ----------------------------------------------------------------------- NMEA-0183, written here
def parse(line: bytes) -> list[str]:
    """The fields of one sentence (address first); AssertionError unless it is well formed."""
    assert line.endswith(b"\r\n") and line[:1] == b"$", line
    text = line[:-2].decode("ascii")
    star = text.rindex("*")
    body, given = text[1:star], text[star + 1 :]
    assert len(given) == 2 and given == given.upper(), line
    xor = 0
    for ch in body.encode("ascii"):
        xor ^= ch
    assert int(given, 16) == xor, f"bad checksum in {line!r}"
    assert len(line) <= 82 or body.startswith("P"), line  # NMEA-0183: at most 82 characters
    return body.split(",")


def degrees(value: str, hemisphere: str) -> float:
    whole = int(float(value) // 100)
    d = whole + (float(value) - 100 * whole) / 60.0
    return -d if hemisphere in "SW" else d


def seconds_of(hms: str) -> float:
    return int(hms[0:2]) * 3600 + int(hms[2:4]) * 60 + float(hms[4:])


def sentences(chunks) -> list[list[str]]:
    return [parse(c) for _, c in chunks if c[:1] == b"$"]


def command(sim, value, now: float) -> list:
    """Feeds one command at real time `now`: the (time, ack code) of its replies (the MIP packets
    of the command's set among what the simulator sends)."""
    raw = pkg.codec.framing.PacketBuilder(value.SET).add(value).build()
    out = []
    for when, data in sim.feed(raw, now):
        if data[:2] == b"ue" and data[2] == value.SET:
            fields = [f.value for f in pkg.codec.packets.decode_packet(data).fields]
            out.append((when, int(getattr(fields[0], sim_mod._meta.ACK_CODE))))
    return out


def entry(sentence: int, talker: int, source: int, decimation: int):
    return t.NmeaMessage(message_id=sentence, talker_id=talker, source_desc_set=source, decimation=decimation)


def run(sim, start: float, end: float) -> list[list[str]]:
    """The sentences sent from `start` to `end` (real seconds), polled every 0.1 s as a host reads."""
    out = []
    for i in range(round((end - start) * 10)):
        out += sentences(sim.poll(start + 0.1 * (i + 1)))
    return out


def nmea_format(sim, entries, at: float = 0.0) -> int:
    value = pkg.threedm.NmeaMessageFormat(function=1, count=len(entries), format_entries=entries)
    return command(sim, value, at)[0][1]


def utc_seconds(week: int, tow: float) -> float:
    """Seconds of the UTC day of a GPS time (the simulator's leap seconds)."""
    return (tow - world_mod.LEAP_SECONDS) % 86400.0


# ------------------------------------------------------------------------------- in process
def test_the_manual_proprietary_examples_parse_and_are_rebuilt() -> None:
    nmea = sim_mod.nmea
    for example in (PMSRA_EXAMPLE, PMSRR_EXAMPLE):
        fields = parse(example + b"\r\n")
        assert nmea.sentence(",".join(fields)) == example + b"\r\n"
    assert nmea.split(PMSRA_EXAMPLE.replace(b"5D", b"5E")) is None  # a bad checksum


@pytest.mark.parametrize(
    "source, allowed, refused",
    [(0x91, 3, 2), (0x82, 100, 99), (0x80, 100, 50)],  # 5 Hz / 3 <= 2 Hz < 5 / 2; 1000 / 100 = 10 Hz
)
def test_rate_limits_nack_with_invalid_parameter(source: int, allowed: int, refused: int) -> None:
    sim = sim_mod.Simulator("cv7_ins")
    sentence = {0x91: GGA, 0x82: PMSRA, 0x80: PMSRR}[source]
    talker = GN if sentence == GGA else 0
    assert nmea_format(sim, [entry(sentence, talker, source, allowed)]) == 0
    assert nmea_format(sim, [entry(sentence, talker, source, refused)]) == INVALID_PARAMETER
    assert nmea_format(sim, [entry(sentence, talker, source, 0)]) == INVALID_PARAMETER


def test_bad_entries_nack() -> None:
    sim = sim_mod.Simulator("cv7_ins")
    for bad in (
        entry(PMSRA, 0, 0x80, 100),  # PMSRA comes from the filter only
        entry(PMSRR, 0, 0x82, 100),  # PMSRR from the IMU only
        entry(ZDA, GN, 0x82, 100),  # ZDA from a GNSS source only
        entry(GSV, GP, 0x91, 5),  # GSV has no talker ID to choose
        entry(GGA, 9, 0x91, 5),  # no such talker
        entry(99, GN, 0x91, 5),  # no such sentence
    ):
        assert nmea_format(sim, [entry(GGA, GN, 0x91, 5), bad]) == INVALID_PARAMETER, bad
    assert nmea_format(sim, [entry(GGA, GN, 0x92, 5), entry(GST, GP, 0x82, 100)]) == 0


def test_sentences_follow_the_world_at_their_rates() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="circle", seed=4)
    entries = [
        entry(GGA, GN, 0x91, 5),
        entry(RMC, GP, 0x91, 5),
        entry(VTG, GN, 0x91, 5),
        entry(ZDA, GN, 0x91, 5),
        entry(GSV, 0, 0x91, 5),
        entry(PMSRA, 0, 0x82, 100),
        entry(PMSRR, 0, 0x80, 100),
    ]
    assert nmea_format(sim, entries) == 0
    before = run(sim, 0.0, 1.9)  # no fix before 2 s: no GNSS sentence
    assert before and {f[0] for f in before} == {"PMSRA", "PMSRR"}
    got = run(sim, 1.9, 5.0)
    counts = {}
    for f in got:
        counts[f[0]] = counts.get(f[0], 0) + 1
    assert counts["GNGGA"] == 4 and counts["GPRMC"] == 4 and counts["GNVTG"] == 4  # 1 Hz: 2, 3, 4, 5 s (the fix at 2 s)
    assert 30 <= counts["PMSRA"] <= 32 and counts["PMSRA"] == counts["PMSRR"]  # 10 Hz
    assert counts["GPGSV"] + counts.get("GAGSV", 0) >= 3
    for f in got:
        if f[0] == "GNGGA":
            at = seconds_of(f[1]) - utc_seconds(0, world_mod.GPS_TOW0)
            a = 5.0 / 50.0 * at  # the circle's truth (50 m, 5 m/s, from north turning right)
            north, east = 50.0 * math.sin(a), 50.0 * (1.0 - math.cos(a))
            lat0 = math.radians(world_mod.ORIGIN[0])
            got_n = math.radians(degrees(f[2], f[3]) - world_mod.ORIGIN[0]) * world_mod.EARTH_RADIUS
            got_e = math.radians(degrees(f[4], f[5]) - world_mod.ORIGIN[1]) * world_mod.EARTH_RADIUS * math.cos(lat0)
            assert math.hypot(got_n - north, got_e - east) < 3.0, (f, north, east)
            assert f[6] == "1" and int(f[7]) > 0 and f[10] == "M"
            assert abs(float(f[9]) - world_mod.ORIGIN[2]) < 5.0
        elif f[0] == "GPRMC":
            assert f[2] == "A" and abs(float(f[7]) * 1852.0 / 3600.0 - 5.0) < 0.5  # knots
        elif f[0] == "GNZDA":
            day = datetime.date(int(f[4]), int(f[3]), int(f[2]))
            gps = datetime.datetime(1980, 1, 6) + datetime.timedelta(weeks=world_mod.GPS_WEEK)
            assert day == (gps + datetime.timedelta(seconds=world_mod.GPS_TOW0 - world_mod.LEAP_SECONDS)).date()
        elif f[0] == "PMSRR":
            assert len(f) == 8 and all(len(x.split(".")[1]) == 6 for x in f[2:])  # 6 decimals (line 1039)
            assert abs(float(f[4]) + 1.0) < 0.05  # gravity on z, in g, as the manual's example
        elif f[0] == "PMSRA":
            assert len(f) == 5 and all(len(x.split(".")[1]) == 3 for x in f[2:])  # 3 decimals (line 1034)
            assert len(f[1]) == 9 and f[1][6] == "."  # HHMMSS.mm


def test_sentences_are_whole_between_mip_packets() -> None:
    # Line 1076: "Each type of packet will be transmitted whole": the stream as written parses into
    # MIP packets and NMEA sentences only, no skipped byte.
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    fmt = [t.DescriptorRate(descriptor=d, decimation=10) for d in (0xD3, 0x04, 0x05)]
    value = pkg.threedm.MessageFormat(function=1, desc_set=0x80, num_descriptors=len(fmt), descriptors=fmt)
    assert command(sim, value, 0.0)[0][1] == 0
    assert nmea_format(sim, [entry(PMSRR, 0, 0x80, 100), entry(GGA, GN, 0x91, 5)]) == 0
    chunks = [c for i in range(30) for c in sim.poll(0.1 * (i + 1))]
    chunks.sort(key=lambda c: c[0])
    parser = pkg.codec.framing.Parser()
    events = parser.feed(b"".join(c for _, c in chunks)) + parser.flush()
    kinds = [type(e).__name__ for e in events]
    assert "Skip" not in kinds and kinds.count("Nmea") == sum(c[:1] == b"$" for _, c in chunks) >= 30
    assert kinds.count("RawPacket") >= 300  # 1000 Hz / 10 for 3 s


def test_idle_stops_the_sentences_and_poll_sends_once() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    empty = pkg.threedm.PollNmeaData(suppress_ack=False, count=0, format_entries=[])
    assert command(sim, empty, 0.0) == [(0.0, INVALID_PARAMETER)]  # no format given, none stored (line 6796)
    assert nmea_format(sim, [entry(PMSRR, 0, 0x80, 100)]) == 0
    assert sentences(sim.poll(0.5))
    assert command(sim, pkg.base.SetToIdle(), 0.5)[0][1] == 0
    assert sentences(sim.poll(1.5)) == []
    polled = pkg.threedm.PollNmeaData(suppress_ack=False, count=1, format_entries=[entry(PMSRR, 0, 0x80, 0)])
    raw = pkg.codec.framing.PacketBuilder(polled.SET).add(polled).build()
    got = sentences(sim.feed(raw, 1.6))
    assert [f[0] for f in got] == ["PMSRR"]


def _gga(stamp: str) -> bytes:
    return sim_mod.nmea.sentence(f"GPGGA,{stamp},4807.0380,N,01131.0000,E,4,12,0.7,545.4,M,46.9,M,1.0,0000")


def _rmc(stamp: str) -> bytes:
    return sim_mod.nmea.sentence(f"GNRMC,{stamp},A,4807.0380,N,01131.0000,E,010.0,084.4,070126,,,A")


def _external(sim, data: bytes, at: float) -> list:
    return [pkg.codec.packets.decode_packet(c) for _, c in sim.feed(data, at) if c[:1] == b"u" and c[2] == 0x94]


def test_nmea_input_is_mirrored_into_0x94_after_two_updates() -> None:
    sim = sim_mod.Simulator("cv7_ins")
    fmt = [t.DescriptorRate(descriptor=d, decimation=1) for d in (0xD3, 0x03, 0x05, 0x08, 0x0B)]
    value = pkg.threedm.MessageFormat(function=1, desc_set=0x94, num_descriptors=len(fmt), descriptors=fmt)
    assert command(sim, value, 0.0)[0][1] == 0
    assert _external(sim, _gga("101500.50"), 0.1) == []
    assert _external(sim, _rmc("101500.50"), 0.1) == []  # the same update
    bad = _gga("101501.50")[:-4] + b"00\r\n"  # a bad checksum: ignored
    assert _external(sim, bad, 0.2) == []
    [packet] = _external(sim, _gga("101501.50"), 1.1)  # the second update begins: the first is out
    f = {x.value.NAME: x.value for x in packet.fields}
    assert f["llh_position"].latitude == pytest.approx(48 + 7.038 / 60, abs=1e-9)
    assert f["llh_position"].longitude == pytest.approx(11 + 31.0 / 60, abs=1e-9)
    assert f["llh_position"].msl_height == pytest.approx(545.4)
    assert f["llh_position"].ellipsoid_height == pytest.approx(545.4 + 46.9)
    assert f["fix_info"].fix_type == t.GnssFixTypeCv7.FIX_RTK_FIXED and f["fix_info"].num_sv == 12
    assert f["ned_velocity"].ground_speed == pytest.approx(10.0 * 1852 / 3600, rel=1e-6)
    assert f["ned_velocity"].heading == pytest.approx(84.4, abs=1e-4)
    utc = f["utc_time"]
    assert (utc.year, utc.month, utc.day, utc.hour, utc.minute, utc.second, utc.millisecond) == (
        2026, 1, 7, 10, 15, 0, 500,
    )  # fmt: skip
    since = datetime.datetime(2026, 1, 7, 10, 15, 0, 500000) - datetime.datetime(1980, 1, 6)
    gps = since.total_seconds() + world_mod.LEAP_SECONDS
    assert f["gps_timestamp"].week_number == int(gps // 604800)
    assert f["gps_timestamp"].tow == pytest.approx(gps % 604800, abs=1e-6)


# ------------------------------------------------------------------------------- end to end
def test_nmea_over_tcp_against_the_mip_stream_and_input_into_0x94() -> None:
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", "--speed", "4", "--scenario", "circle") as sim:
        dev = open_device(pkg, sim.address, "cv7_ins")
        try:
            threedm = dev.threedm
            with pytest.raises(pkg.session.Nack) as refused:
                threedm.nmea_message_format.write(format_entries=[entry(GGA, GN, 0x91, 2)])  # 2.5 Hz > 2 Hz
            assert int(refused.value.code) == INVALID_PARAMETER
            threedm.nmea_message_format.write(format_entries=[entry(GGA, GN, 0x91, 5), entry(RMC, GP, 0x91, 5)])
            fmt = [t.DescriptorRate(descriptor=d, decimation=1) for d in (0xD3, 0x03)]
            threedm.message_format.write(desc_set=0x91, descriptors=fmt)
            threedm.data_stream_control.write_cv7_ins(desc_set=0x91, enable=True)
            fmt94 = [t.DescriptorRate(descriptor=d, decimation=1) for d in (0xD3, 0x03, 0x0B)]
            threedm.message_format.write(desc_set=0x94, descriptors=fmt94)
            threedm.data_stream_control.write_cv7_ins(desc_set=0x94, enable=True)
            foreign, llh, external = [], {}, []
            dev.on_foreign(lambda frame: foreign.append(frame))
            stamps = {}
            dev.on_field(0x91, 0xD3, lambda v, p: stamps.__setitem__(p.offset, v.tow))
            dev.on_field(0x91, 0x03, lambda v, p: llh.__setitem__(round(stamps.get(p.offset, -1.0), 2), v))
            dev.on_field(0x94, 0x03, lambda v, p: external.append(v))
            pump_for(dev, 1.6)  # 6.4 s simulated: GNSS from 2 s on
            ggas = [parse(x.data) for x in foreign if x.data[3:6] == b"GGA"]
            assert len(ggas) >= 3 and all(g[0] == "GNGGA" for g in ggas)
            matched = 0
            for g in ggas:
                gps = seconds_of(g[1]) + world_mod.LEAP_SECONDS  # of the day; the day of GPS_TOW0's
                tow = round((gps - world_mod.GPS_TOW0 + 43200) % 86400 - 43200 + world_mod.GPS_TOW0, 2)
                mip = llh.get(tow)
                if mip is None:
                    continue
                matched += 1
                lat, lon = degrees(g[2], g[3]), degrees(g[4], g[5])
                north = math.radians(lat - mip.latitude) * world_mod.EARTH_RADIUS
                east = math.radians(lon - mip.longitude) * world_mod.EARTH_RADIUS * math.cos(math.radians(lat))
                assert math.hypot(north, east) < 5.0, (g, mip)  # the receiver's noise, 0.5 m 1 sigma
            assert matched >= 2, (ggas, sorted(llh))
            assert any(x.data[3:6] == b"RMC" for x in foreign)
            assert external == []
            for i, stamp in enumerate(("101500.00", "101501.00", "101502.00")):
                dev.transport.write(_gga(stamp))
                dev.transport.write(_rmc(stamp))
                deadline = time.monotonic() + (3.0 if i else 0.2)  # a busy machine: wait for it
                while len(external) < i and time.monotonic() < deadline:
                    pump_for(dev, 0.05)
                pump_for(dev, 0.05)
                assert len(external) == i, (i, external)  # each update out when the next begins
            assert external[0].latitude == pytest.approx(48 + 7.038 / 60, abs=1e-9)
        finally:
            dev.transport.close()
