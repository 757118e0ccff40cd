"""The time model (`<package>.timebase`, docs/log-to-csv.md "Time"): GPS week/TOW to UTC around
leap seconds, the clock map's rules (anchors, first anchor, resets), valid flags, the device's
leap second report, and the per-split computation giving the whole log's result.

Golden values are worked out in the comments: calendar dates by counting days, UTC instants with
Python's datetime (calendar arithmetic only, no leap seconds), GPS - UTC from IERS Bulletin C.
"""

from __future__ import annotations

import importlib
import random
from datetime import datetime, timezone
from pathlib import Path

import numpy as np
import pytest

from tests.helpers.generated import python_package

NS = 10**9


def _pkg():
    python_package("mipcodec")
    mods = {}
    for sub in (
        "logs.timebase",
        "shared",
        "sensor",
        "filter_data",
        "gnss_receiver_1",
        "types",
        "codec.framing",
        "codec.packets",
    ):
        mods[sub.split(".")[-1]] = importlib.import_module(f"mipcodec.{sub}")
    return mods


M = _pkg()
tb = M["timebase"]
T = M["types"]


def utc(*args) -> int:
    """UTC ns since the Unix epoch of a calendar instant (datetime's proleptic calendar, which
    counts no leap seconds, as POSIX time does); a float second gives its exact ns."""
    sec = args[5] if len(args) > 5 else 0
    whole = int(sec)
    d = datetime(*args[:5], whole, tzinfo=timezone.utc)
    return int(d.timestamp()) * NS + round((sec - whole) * NS)


# ---------------------------------------------------------------------------- GPS -> UTC


def test_the_gps_epoch():
    # GPS week 0, TOW 0 is 1980-01-06T00:00:00 UTC (GPS - UTC was 0 until 1981-07-01).
    assert tb.GPS_EPOCH_UNIX_S == utc(1980, 1, 6, 0, 0) // NS
    assert tb.gps_to_utc_ns(0, 0.0) == utc(1980, 1, 6, 0, 0)


def test_week_1930_and_the_2016_leap_second():
    # Week 1930 starts 1930 * 7 = 13510 days after 1980-01-06. From 1980-01-01 to 2017-01-01 are
    # 37 years with 10 leap years (1980, 1984, ..., 2016): 37 * 365 + 10 = 13515 days; minus the 5
    # days to 1980-01-06 gives 13510. So week 1930 TOW 0 is 2017-01-01T00:00:00 on the GPS scale.
    # The leap second 2016-12-31T23:59:60 UTC took GPS - UTC from 17 to 18 s (Bulletin C 52).
    # TOW 0: GPS 00:00:00, UTC = GPS - 17 = 2016-12-31T23:59:43.
    assert tb.gps_to_utc_ns(1930, 0.0) == utc(2016, 12, 31, 23, 59, 43)
    # TOW 16.5: 23:59:59.5 UTC, still 17 s.
    assert tb.gps_to_utc_ns(1930, 16.5) == utc(2016, 12, 31, 23, 59, 59.5)
    # TOW 17: the inserted second 23:59:60 UTC, given as 00:00:00 of the next day (POSIX timegm).
    assert tb.gps_to_utc_ns(1930, 17.0) == utc(2017, 1, 1, 0, 0)
    assert tb.gps_to_utc_ns(1930, 17.25) == utc(2017, 1, 1, 0, 0, 0.25)
    # TOW 18: 2017-01-01T00:00:00 UTC with 18 s: the UTC second repeats.
    assert tb.gps_to_utc_ns(1930, 18.0) == utc(2017, 1, 1, 0, 0)
    assert tb.gps_to_utc_ns(1930, 19.0) == utc(2017, 1, 1, 0, 0, 1)
    # The device's own leap seconds win over the table (18 s given for TOW 0: 23:59:42).
    assert tb.gps_to_utc_ns(1930, 0.0, leap=18) == utc(2016, 12, 31, 23, 59, 42)


def test_the_2015_leap_second():
    # 2015-07-01: from 1980-01-01 to 2015-01-01 are 35 years with 9 leap years (1980 ... 2012):
    # 12784 days; January to June 2015: 31 + 28 + 31 + 30 + 31 + 30 = 181; minus 5: 12960 days
    # after the GPS epoch = week 1851 (12957 days) + 3 days, TOW 3 * 86400 = 259200 on the GPS
    # scale. GPS - UTC went from 16 to 17 s (Bulletin C 49) at 2015-07-01T00:00:00 UTC = GPS TOW
    # 259200 + 17. Before it, 16 s.
    assert tb.gps_to_utc_ns(1851, 259215.5) == utc(2015, 6, 30, 23, 59, 59.5)
    assert tb.gps_to_utc_ns(1851, 259216.0) == utc(2015, 7, 1, 0, 0)  # 23:59:60 -> 00:00:00
    assert tb.gps_to_utc_ns(1851, 259217.0) == utc(2015, 7, 1, 0, 0)
    assert tb.gps_to_utc_ns(1851, 259218.0) == utc(2015, 7, 1, 0, 0, 1)


def test_the_first_leap_second_and_the_table():
    # 1981-07-01: 546 days after 1980-01-01 (366 + 181 in 1981 minus... 1980 is a leap year: 366,
    # then January to June 1981: 181 days), minus 5 = 542 days = week 77 + 3 days, TOW 259200.
    # GPS - UTC became 1 s at GPS TOW 259200 + 1.
    assert tb.gps_to_utc_ns(77, 259200.0) == utc(1981, 7, 1, 0, 0)  # still 0 s: the leap second itself
    assert tb.gps_to_utc_ns(77, 259201.0) == utc(1981, 7, 1, 0, 0)  # 1 s
    assert tb.gps_to_utc_ns(77, 259199.0) == utc(1981, 6, 30, 23, 59, 59)
    # 18 entries, 1 to 18 s, each on 1 January or 1 July at midnight, and 18 s from 2017 on.
    assert [leap for _t, leap in tb.LEAP_TABLE] == list(range(1, 19))
    for t, _leap in tb.LEAP_TABLE:
        d = datetime.fromtimestamp(t, tz=timezone.utc)
        assert (d.month, d.day, d.hour, d.minute, d.second) in ((1, 1, 0, 0, 0), (7, 1, 0, 0, 0))
    assert tb.LEAP_TABLE[-1][0] == utc(2017, 1, 1, 0, 0) // NS
    assert tb.table_leap_seconds(tb.gps_ns(2400, 0.0)) == 18


def test_integer_nanoseconds():
    # 0.1 s is the double 0.1000000000000000055...: the nearest ns is exactly 100000000.
    assert tb.tow_ns(0.1) == 100_000_000
    # The double nearest 604799.999999999 is within 1.2e-10 s of it: 604799 s + 999999999 ns.
    assert tb.tow_ns(604799.999999999) == 604799 * NS + 999_999_999
    # A float multiplication would lose it: 604799.999999999 * 1e9 rounds to ...999999000064.
    assert tb.gps_ns(2000, 0.000000001) == 2000 * 604800 * NS + 1


# ---------------------------------------------------------------------------- logs

S, SEN = M["shared"], M["sensor"]
build_packet = M["framing"].build_packet
W = 2300  # a week after 2017: GPS - UTC 18 s from the table
WEEK0 = utc(1980, 1, 6, 0, 0) + W * 604800 * NS - 18 * NS  # UTC ns of week W TOW 0


def packet(dev=None, gps=None, flags=0b11, set_id=0x80):
    vals = []
    if gps is not None:
        vals.append(S.GpsTimestamp(float(gps), W, T.SharedGpsTimestampValidFlags(flags)))
    if dev is not None:
        vals.append(S.ReferenceTimestamp(int(dev)))
    vals.append(SEN.ScaledAccel([0.0, 0.0, 1.0]) if set_id == 0x80 else S.EventSource(0))
    return build_packet(set_id, *vals)


def leap_packet(leap, flags=0b10):
    g1 = M["gnss_receiver_1"]
    return build_packet(0x91, g1.GpsLeapSeconds(leap, T.GnssLeapSecondsValidFlags(flags)))


def decoded(data: bytes):
    P = M["packets"]
    return [e for e in P.decode_all(data) if isinstance(e, P.Packet)]


def whole_times(data: bytes):
    """(offset, Times) of every packet, the whole log as one split, packet by packet."""
    pk = decoded(data)
    clock = tb.log_clock(pk).split(0)
    return [(p.offset, clock.times(p)) for p in pk]


def t_of(data: bytes):
    return [t.t_ns for _o, t in whole_times(data)]


def test_the_clock_map_rules():
    # Device clock 5 s, 6 s (anchor: GPS TOW 100), 7 s, a packet with only GPS time 200.5 s, 9 s
    # (anchor: TOW 300.25), 10 s, 11 s.
    log = [
        packet(dev=5 * NS),  # before the first anchor: uses it, 100 + (5 - 6) = TOW 99
        packet(dev=6 * NS, gps=100.0),  # its own GPS time: TOW 100
        packet(dev=7 * NS),  # latest anchor (6 s, 100): TOW 101
        packet(gps=200.5),  # its own GPS time only: TOW 200.5
        packet(dev=8 * NS),  # still the latest anchor before it: TOW 102
        packet(dev=9 * NS, gps=300.25),  # anchor: TOW 300.25
        packet(dev=10 * NS),  # latest anchor (9 s, 300.25): TOW 301.25
    ]
    got = t_of(b"".join(log))
    want = [99.0, 100.0, 101.0, 200.5, 102.0, 300.25, 301.25]
    assert got == [WEEK0 + round(s * NS) for s in want]


def test_resets_start_epochs():
    log = [
        packet(dev=50 * NS, gps=10.0),  # epoch 0 anchor (50 s, TOW 10)
        packet(dev=51 * NS),  # TOW 11
        packet(dev=int(50.5 * NS)),  # back 0.5 s (<= 1 s: not a reset), TOW 10.5
        packet(dev=2 * NS),  # back 48.5 s: a reset, epoch 1; its first anchor is (4 s, TOW 500): TOW 498
        packet(dev=3 * NS),  # TOW 499
        packet(dev=4 * NS, gps=500.0),  # epoch 1 anchor
        packet(dev=6 * NS),  # TOW 502
        packet(dev=1 * NS),  # a reset: epoch 2 has no anchor: no time
        packet(dev=2 * NS, gps=700.0, flags=0b01),  # week not valid: not an anchor, no time
    ]
    got = t_of(b"".join(log))
    want = [10.0, 11.0, 10.5, 498.0, 499.0, 500.0, 502.0, None, None]
    assert got == [None if s is None else WEEK0 + round(s * NS) for s in want]


def test_raw_times_are_kept_and_flags_honoured():
    data = packet(dev=7, gps=12.5, flags=0b01) + packet(gps=13.0, flags=0b00) + packet(dev=8)
    times = [t for _o, t in whole_times(data)]
    # Raw GPS time kept whatever the flags; no valid GPS time anywhere, so no time at all.
    assert times[0] == tb.Times(None, 7, W, 12.5)
    assert times[1] == tb.Times(None, None, W, 13.0)
    assert times[2] == tb.Times(None, 8, None, None)


def test_the_devices_leap_seconds():
    # A valid report (17 s) applies from the log's start (rows before it use the log's first),
    # then the latest; an invalid one (flag bit 1 clear) is ignored.
    data = (
        packet(gps=0.0)
        + leap_packet(17)
        + packet(gps=1.0)
        + leap_packet(99, flags=0)
        + leap_packet(16)
        + packet(gps=2.0)
    )
    got = [t for t in t_of(data) if t is not None]
    base = WEEK0 + 18 * NS  # week W TOW 0 with no leap seconds
    assert got == [base - 17 * NS, base + 1 * NS - 17 * NS, base + 2 * NS - 16 * NS]


def test_other_gps_fields_and_preference():
    fd = M["filter_data"]
    # The filter's GPS timestamp (0x82,0x11, valid flag 1) gives a time; with the shared 0xD3 in
    # the same packet, 0xD3 (first in the spec's order) wins.
    a = build_packet(0x82, fd.GpsTimestamp(40.0, W, T.FilterOutputValidFlags(1)))
    b = build_packet(
        0x82,
        fd.GpsTimestamp(40.0, W, T.FilterOutputValidFlags(1)),
        S.GpsTimestamp(41.0, W, T.SharedGpsTimestampValidFlags(3)),
    )
    c = build_packet(0x82, fd.GpsTimestamp(40.0, W, T.FilterOutputValidFlags(0)))
    assert t_of(a + b + c) == [WEEK0 + 40 * NS, WEEK0 + 41 * NS, None]


def test_mscip_inverted_flag():
    python_package("mscipcodec")
    m_tb = importlib.import_module("mscipcodec.logs.timebase")
    imu = importlib.import_module("mscipcodec.imu_data")
    mt = importlib.import_module("mscipcodec.types")
    P = importlib.import_module("mscipcodec.codec.packets")
    F = importlib.import_module("mscipcodec.codec.framing")
    # Table 72's example: week 1839, 207000.0 s (2015-04-07T09:30:00 GPS; GPS - UTC 16 s then).
    ok = F.build_packet(0xA2, imu.GpsCorrelatedTime(207000.0, 1839, mt.GpsTimeFlags(0)))
    unset = F.build_packet(0xA2, imu.GpsCorrelatedTime(5.0, 0, mt.GpsTimeFlags(4)))  # time_not_set
    pk = [e for e in P.decode_all(ok + unset) if isinstance(e, P.Packet)]
    clock = m_tb.log_clock(pk).split(0)
    assert [clock.times(p).t_ns for p in pk] == [utc(2015, 4, 7, 9, 29, 44), None]


# ---------------------------------------------------------------------------- splits


def random_log(seed: int, n: int = 400) -> bytes:
    """Packets of a device that resets twice, with GNSS outages, invalid flags, leap reports and
    garbage between packets."""
    rng = random.Random(seed)
    out = []
    dev = 3 * NS
    tow = 1000.0
    for i in range(n):
        r = rng.random()
        if i == n - 30:
            dev = 0  # a reset into an epoch without anchors (the last 30 packets)
        elif i == n - 31:
            dev += 10 * NS  # (a gap forward, so that the next is a reset)
        elif r < 0.01:
            dev = rng.randrange(0, 2 * NS)  # a reset
        elif r < 0.03:
            dev = max(0, dev - rng.randrange(0, NS))  # a small step back (not a reset)
        else:
            dev += rng.randrange(1, 50_000_000)
        tow += rng.random() * 0.05
        kind = rng.random()
        if 150 < i < 200 or i >= n - 30:
            kind = 1.0  # a GNSS outage: device clock only
        if kind < 0.1:
            out.append(packet(dev=dev, gps=tow, flags=rng.choice([0b11, 0b11, 0b01])))
        elif kind < 0.15:
            out.append(packet(gps=tow))
        elif kind < 0.17:
            out.append(leap_packet(rng.choice([17, 18]), flags=rng.choice([0b10, 0])))
        elif kind < 0.2:
            out.append(bytes(rng.randrange(256) for _ in range(rng.randrange(1, 20))))
        else:
            out.append(packet(dev=dev, set_id=rng.choice([0x80, 0x82])))
    return b"".join(out)


def split_times(data: bytes, size: int, block: bool, lookback: int):
    """Every packet's times from a per-split run: phase 1 `split_anchors` of each split, then each
    split decoded from its own bytes (from `lookback` bytes before its start) with its clock."""
    P = M["packets"]
    bounds = [(s, min(s + size, len(data))) for s in range(0, len(data), size)]
    max_packet = 4 + 255 + 2

    def piece(start, end):
        base = max(0, start - lookback)
        return data[base : min(len(data), end + max_packet)], base

    anchors = []
    for start, end in bounds:
        chunk, base = piece(start, end)
        anchors.append(tb.split_anchors(chunk, base, start, end))
    cmap = tb.ClockMap.from_splits(anchors)
    out = {}
    for k, (start, end) in enumerate(bounds):
        chunk, base = piece(start, end)
        clock = cmap.split(k)
        if block:
            bt = clock.block(P.decode_columns(chunk), base, start, end)
            for i in range(len(bt)):
                out[int(bt.offset[i])] = (
                    int(bt.t_ns[i]) if bt.t_valid[i] else None,
                    int(bt.device_ns[i]) if bt.device_valid[i] else None,
                    int(bt.gps_week[i]) if bt.gps_valid[i] else None,
                    float(bt.gps_tow[i]) if bt.gps_valid[i] else None,
                )
        else:
            for e in P.decode_all(chunk):
                if isinstance(e, P.Packet) and start <= e.offset + base < end:
                    p = P.Packet(e.offset + base, e.set, e.fields)
                    out[p.offset] = tuple(clock.times(p))
    return {o: t for o, t in out.items() if t != (None,) * 4}


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_per_split_equals_whole_log(seed):
    data = random_log(seed)
    whole = {o: tuple(t) for o, t in whole_times(data) if tuple(t) != (None,) * 4}
    assert sum(t[0] is not None for t in whole.values()) > 100  # the log does give times
    assert any(t[0] is None and t[1] is not None for t in whole.values())  # and an epoch without anchors
    for size in (5, 37, 97, 256, 1000, 4096, len(data)):
        for block in (False, True):
            got = split_times(data, size, block, lookback=0 if size % 2 else 300)
            assert got == whole, (size, block)


def test_block_path_equals_packet_path():
    data = random_log(7)
    P = M["packets"]
    anchors = tb.split_anchors(data, 0, 0, len(data))  # (vectorised)
    assert anchors == tb.summarize(tb.packet_time(p) for p in decoded(data))
    assert len(anchors.segments) >= 2 and anchors.first_leap is not None
    clock_map = tb.ClockMap.from_splits([anchors])
    bt = clock_map.split(0).block(P.decode_columns(data), 0)
    look = bt.lookup(np.array([o for o, _t in whole_times(data)]))
    whole = [t for _o, t in whole_times(data)]
    assert [int(v) if ok else None for v, ok in zip(look["t_ns"], look["t_valid"])] == [t.t_ns for t in whole]
    assert [int(v) if ok else None for v, ok in zip(look["device_ns"], look["device_valid"])] == [
        t.device_ns for t in whole
    ]


# ---------------------------------------------------------------------------- info


def iso(t_ns: int) -> str:
    sec, ns = divmod(t_ns, NS)
    return datetime.fromtimestamp(sec, tz=timezone.utc).strftime("%Y-%m-%dT%H:%M:%S") + f".{ns // 1000:06d}Z"


def test_info_reports_gaps_jumps_resets_and_invalid_stretches(tmp_path, capsys):
    cli = importlib.import_module("mipcodec.cli")
    fd = M["filter_data"]

    def filt(tow, valid=1):
        return build_packet(0x82, fd.GpsTimestamp(float(tow), W, T.FilterOutputValidFlags(valid)))

    log = [
        packet(dev=1 * NS),  # 0: before the first anchor: TOW 99
        packet(dev=2 * NS, gps=100.0),  # 1: anchor, TOW 100
        filt(100.5),  # 2: own GPS time (set 0x82)
        packet(dev=3 * NS),  # 3: TOW 101
        packet(dev=8 * NS),  # 4: TOW 106: a gap of 5 s after TOW 101
        filt(90.0),  # 5: set 0x82 goes back from 100.5 to 90: a backward jump
        filt(91.0, valid=0),  # 6: invalid GPS time: an invalid-time stretch of 1 packet
        packet(dev=9 * NS),  # 7: TOW 107
        packet(dev=int(0.5 * NS)),  # 8: a reset (9 s -> 0.5 s): epoch 1 has no anchor
        packet(dev=int(0.6 * NS)),  # 9: no time
        packet(dev=int(0.7 * NS)),  # 10: no time (stretch 8-10, 3 packets)
    ]
    data = b"".join(log)
    offs = [sum(len(p) for p in log[:i]) for i in range(len(log))]
    path = tmp_path / "t.bin"
    path.write_bytes(data)
    assert cli.main(["info", str(path)]) == 0
    text = capsys.readouterr().out.splitlines()
    start = next(i for i, line in enumerate(text) if line.startswith("UTC:"))
    at = lambda tow: WEEK0 + round(tow * NS)  # noqa: E731
    end = text.index("synchronization:")  # (tests/export/test_sync.py)
    assert text[start:end] == [
        # 11 data packets, 7 timed: 3 by their own GPS time (1, 2, 5), 4 by the device clock (0, 3, 4, 7)
        f"UTC: first {iso(at(90))}  last {iso(at(107))}  span 17.000000 s"
        "  (7 of 11 data packets: 3 by their own GPS time, 4 by the device clock)",
        "time gaps over 1 s: 1",
        f"  offset {offs[4]}: {iso(at(101))} -> {iso(at(106))} (+5.000 s)",
        "backward jumps: 1",
        f"  set 0x82 offset {offs[5]}: {iso(at(100.5))} -> {iso(at(90))} (-10.500 s)",
        "device clock resets: 1",
        f"  offset {offs[8]}: device clock 9.000000 s -> 0.500000 s",
        "invalid-time stretches: 2",
        f"  offset {offs[6]}: 1 packet (GPS time not valid)",
        f"  offsets {offs[8]}-{offs[10]}: 3 packets (no GPS anchor for the device clock)",
    ]
    # From stdin (read once), the rows before the first anchor have no time.
    import subprocess
    import sys

    env = {"PYTHONPATH": str(Path(M["timebase"].__file__).parents[2])}
    out = subprocess.run(
        [sys.executable, "-m", "mipcodec", "info", "-"], input=data, capture_output=True, env=env, check=True
    )
    lines = out.stdout.decode().splitlines()
    assert (
        lines[lines.index("invalid-time stretches: 3") + 1]
        == f"  offset {offs[0]}: 1 packet (no GPS anchor for the device clock)"
    )


# ---------------------------------------------------------------------------- session


def test_the_session_times_data_packets_live():
    session_mod = importlib.import_module("mipcodec.session")
    log = [
        packet(dev=1 * NS),  # live: no anchor seen yet, no time (the log rule would give TOW 99)
        packet(dev=2 * NS, gps=100.0),  # anchor: TOW 100
        packet(dev=3 * NS),  # TOW 101
        leap_packet(17),  # the device's leap seconds from here on: 17 s
        packet(dev=4 * NS),  # TOW 102, UTC with 17 s
        packet(dev=int(0.5 * NS)),  # a reset: no anchor in the new epoch
    ]
    u = WEEK0 + 18 * NS  # week W TOW 0 as UTC with no leap seconds
    want = [
        (None, 1 * NS),
        (u + 100 * NS - 18 * NS, 2 * NS),
        (u + 101 * NS - 18 * NS, 3 * NS),
        (None, None),  # the leap second packet has no time of its own
        (u + 102 * NS - 17 * NS, 4 * NS),
        (None, NS // 2),
    ]
    data = b"".join(log)
    # A packet handler asking each packet's time (the session's fast path for one handler), the
    # same with a field handler too, and the time model started before any handler.
    for setup in ("handler", "handlers", "started"):
        session = session_mod.Session("cv7_ins")
        seen = []
        if setup == "started":
            assert session.time.latest is None
            events = session.feed(data, 0)
            packets = [e for e in events if hasattr(e, "fields")]
            seen = [(session.utc_ns(p), session.times(p).device_ns) for p in packets]
        else:
            session.on_packet(lambda p, s=session, out=seen: out.append((s.utc_ns(p), s.times(p).device_ns)))
            if setup == "handlers":
                session.on_field(0x80, 0x04, lambda v, p: None)
            # in two pieces (the second packet split), so the model keeps its state across feeds
            session.feed(data[:40], 0)
            session.feed(data[40:], 1)
        session.close(2)
        assert seen == want, setup
        # Another packet, asked about later: against the current state (epoch 1, no anchor).
        assert session.utc_ns(decoded(packet(dev=5 * NS))[0]) is None
        assert session.time.epoch == 1 and session.time.leap_latest == 17
        # An earlier packet again: the same answer as it had (its state is not changed by asking).
        first = decoded(data)[2]
        assert session.utc_ns(first) is None  # (now: epoch 1 has no anchor)


def test_file_clock_in_splits_equals_the_whole_log(tmp_path, monkeypatch):
    # The clock map of a file read in small splits (and, without numpy, packet by packet in parts
    # of 4096 packets) equals the one of the whole log's packets.
    data = random_log(11, n=6000)
    path = tmp_path / "log.bin"
    path.write_bytes(data)
    whole = tb.summarize(tb.packet_time(p) for p in decoded(data))
    want = tb.ClockMap.from_splits([whole]).split(0)
    state = lambda c: (c.prev_device_ns, c.latest, c.epoch, c.firsts, c.leap_latest, c.leap_first)  # noqa: E731
    assert len(whole.segments) >= 2
    for size in (1000, 4096, len(data)):
        assert state(tb.file_clock(str(path), size).split(0)) == state(want), size
    real = importlib.import_module

    def no_numpy(name, *a):
        if name == "numpy":
            raise ImportError(name)
        return real(name, *a)

    monkeypatch.setattr(tb.importlib, "import_module", no_numpy)
    assert state(tb.file_clock(str(path)).split(0)) == state(want)
