"""External time in the log time model and `info`'s synchronization section (runtime
logs/timebase.py and logs/sync.py; docs/time.md "Logs"; issue 52 item 5).

The logs are made here, packet by packet, with the package's field classes and `build_packet`.
Expected values are reasoned from the manuals in the comments, never read from the code:

- CV7 External Timestamp (0xFF,0xD7) is "Equivalent to the GPS Timestamp but in nanoseconds"
  (3dm-cv7-ins-docs.txt:6650): ns since the GPS epoch; UTC = GPS epoch + ns - (GPS - UTC), 18 s
  from 2017 on (IERS Bulletin C). Its valid flag is bit 0 (:6655); "To be valid, external clock
  sync must be achieved using the PPS input" (:6650).
- Time Sync Status (0xA0,0x02) `time_sync`: "True if sync with the PPS signal is currently
  valid. False if ... a PPS signal is not detected" (:6707).
- GX5-45 GPS Correlation Timestamp (0x80,0x12) flags: "Bit0 - PPS Beacon Good If set, GNSS PPS
  signal is present", "Bit2 - GPS Time Initialized" (3dm-gx5-45-dcp.txt:2159).
- The order of a packet's clocks (docs/time.md): its valid GPS time, else its valid external
  time, else the device clock through the clock map (anchored on the packets with both).
"""

from __future__ import annotations

import csv
import importlib
import os
import subprocess
import sys
from datetime import datetime, timezone

import numpy as np
import pytest

from tests.export.test_export import ext_build
from tests.helpers.generated import python_package

python_package("mipcodec")
tb = importlib.import_module("mipcodec.logs.timebase")
P = importlib.import_module("mipcodec.codec.packets")
S = importlib.import_module("mipcodec.shared")
SD = importlib.import_module("mipcodec.system_data")
SEN = importlib.import_module("mipcodec.sensor")
T = importlib.import_module("mipcodec.types")
cli = importlib.import_module("mipcodec.cli")
build_packet = importlib.import_module("mipcodec.codec.framing").build_packet

NS = 10**9
W = 2300  # GPS week 2300 (2024): GPS - UTC = 18 s
GPS_EPOCH = int(datetime(1980, 1, 6, tzinfo=timezone.utc).timestamp()) * NS
WEEK0 = W * 604800 * NS  # ns since the GPS epoch of week W, TOW 0


def utc_of_gps(gps_ns: int) -> int:
    return GPS_EPOCH + gps_ns - 18 * NS


def ext(d: float, step: float = 0.0) -> int:
    """The external time (GPS scale) of device clock d s: TOW 99 + d (+ step after a jump)."""
    return WEEK0 + round((99 + d + step) * NS)


def sensor(d: float, ext_ns: int, valid: bool) -> bytes:
    return build_packet(
        0x80,
        S.ReferenceTimestamp(round(d * NS)),
        S.ExternalTimestamp(ext_ns, T.ExternalTimestampValidFlags(1 if valid else 0)),
        SEN.ScaledAccel([0.0, 0.0, 1.0]),
    )


def status(d: float, synced: bool, last: int) -> bytes:
    return build_packet(0xA0, S.ReferenceTimestamp(round(d * NS)), SD.TimeSyncStatus(synced, last))


def cv7_log():
    """A CV7 log: (packets, expected UTC ns per packet, description). Set 0x80 every 0.5 s with the
    device clock and the external time; Time Sync Status (set 0xA0) every second."""
    pk, want = [], []
    # d 1.0-2.5: PPS sync, external time valid: its own time.
    for d in (1.0, 1.5, 2.0, 2.5):
        if d in (1.0, 2.0):
            pk.append(status(d, True, 0))
            want.append(utc_of_gps(ext(d)))  # mapped through the anchor (d, ext(d)) of set 0x80
        pk.append(sensor(d, ext(d), True))
        want.append(utc_of_gps(ext(d)))
    # d 3.0-4.5: PPS lost (Time Sync Status false at 3 and 4 s), external time not valid (its
    # raw value keeps counting): the device clock through the latest anchor (2.5 s, ext(2.5)),
    # with zero drift there: ext(d) again.
    for d in (3.0, 3.5, 4.0, 4.5):
        if d in (3.0, 4.0):
            pk.append(status(d, False, int(d - 2)))
            want.append(utc_of_gps(ext(d)))
        pk.append(sensor(d, ext(d), False))
        want.append(utc_of_gps(ext(d)))
    # d 5.0-6.0: PPS back; a GPS Time Update stepped the external time by +2 s: its own time.
    for d in (5.0, 5.5, 6.0):
        if d in (5.0, 6.0):
            pk.append(status(d, True, 0))
            # the status packet at 5.0 comes before the sensor packet of 5.0: the latest anchor is
            # still (2.5 s, ext(2.5)): ext(5.0); at 6.0 the anchor (5.5, ext(5.5, 2)): ext(6.0, 2)
            want.append(utc_of_gps(ext(d, 0 if d == 5.0 else 2)))
        pk.append(sensor(d, ext(d, 2), True))
        want.append(utc_of_gps(ext(d, 2)))
    # A set 0x82 packet with both a valid GPS time (TOW 500) and a valid external time: the GPS
    # time comes first.
    pk.append(
        build_packet(
            0x82,
            S.ReferenceTimestamp(round(6.2 * NS)),
            S.GpsTimestamp(500.0, W, T.SharedGpsTimestampValidFlags(0b11)),
            S.ExternalTimestamp(ext(6.2, 2), T.ExternalTimestampValidFlags(1)),
            S.EventSource(0),
        )
    )
    want.append(utc_of_gps(WEEK0 + 500 * NS))
    return pk, want


def offsets(pk):
    return [sum(len(p) for p in pk[:i]) for i in range(len(pk))]


def packet_path(data: bytes):
    pkts = [e for e in P.decode_all(data) if isinstance(e, P.Packet)]
    clock = tb.log_clock(pkts).split(0)
    return [clock.times(p).t_ns for p in pkts]


def block_path(data: bytes, offs):
    clock = tb.ClockMap.from_splits([tb.split_anchors(data, 0, 0, len(data))]).split(0)
    got = clock.block(P.decode_columns(data), 0).lookup(np.array(offs))
    return [int(v) if ok else None for v, ok in zip(got["t_ns"], got["t_valid"])]


def test_external_time_in_the_order_on_both_paths():
    pk, want = cv7_log()
    data = b"".join(pk)
    assert packet_path(data) == want
    assert block_path(data, offsets(pk)) == want
    # Split anywhere, the block path still gives the whole log's times.
    offs = offsets(pk)
    cut = offs[7]
    maps = tb.ClockMap.from_splits([tb.split_anchors(data, 0, 0, cut), tb.split_anchors(data, 0, cut, len(data))])
    a = maps.split(0).block(P.decode_columns(data[:cut]), 0).lookup(np.array(offs[:7]))
    b = maps.split(1).block(P.decode_columns(data), 0, cut, len(data)).lookup(np.array(offs[7:]))
    assert [int(v) for v in np.concatenate([a["t_ns"], b["t_ns"]])] == want


def test_an_invalid_external_time_without_device_clock_is_no_time():
    one = build_packet(0x80, S.ExternalTimestamp(ext(1.0), T.ExternalTimestampValidFlags(0)), SEN.ScaledAccel())
    good = build_packet(0x80, S.ExternalTimestamp(ext(2.0), T.ExternalTimestampValidFlags(1)), SEN.ScaledAccel())
    assert packet_path(one + good) == [None, utc_of_gps(ext(2.0))]
    assert block_path(one + good, [0, len(one)]) == [None, utc_of_gps(ext(2.0))]


def info_lines(path, capsys):
    assert cli.main(["info", str(path)]) == 0
    return capsys.readouterr().out.splitlines()


def test_info_synchronization_of_a_cv7_log(tmp_path, capsys):
    pk, _want = cv7_log()
    offs = offsets(pk)
    path = tmp_path / "cv7.bin"
    path.write_bytes(b"".join(pk))
    lines = info_lines(path, capsys)
    # Packet indices: 0 status 1.0, 1 s1.0, 2 s1.5, 3 status 2.0, 4 s2.0, 5 s2.5, 6 status 3.0,
    # 7 s3.0, 8 s3.5, 9 status 4.0, 10 s4.0, 11 s4.5, 12 status 5.0, 13 s5.0, 14 s5.5, 15 status
    # 6.0, 16 s6.0, 17 the set 0x82 packet.
    start = lines.index("synchronization:")
    assert lines[start:] == [
        "synchronization:",
        # 6 status packets, 2 without PPS (3 s, 4 s), ended by the status packet of 5 s
        "  PPS (system_data 0xA0,0x02 time_sync_status): packets 6, without PPS 2, stretches 1",
        f"    offsets {offs[6]}-{offs[9]}: 2 packets, device clock 3.000000 s to 5.000000 s (2.000 s)",
        # the one packet with a GPS time field has it valid
        "  GPS time fields: packets 1, not valid 0, stretches 0",
        # 12 packets carry the external time; 4 not valid (3.0-4.5 s), ended by the packet of 5.0 s
        "  external time fields: packets 12, not valid 4, stretches 1",
        f"    offsets {offs[7]}-{offs[11]}: 4 packets, device clock 3.000000 s to 5.000000 s (2.000 s)",
        # set 0x80: from (2.5 s, ext(2.5)) to (5.0 s, ext(5.0) + 2 s): the external time stepped
        # 4.5 s over a device clock step of 2.5 s: +2 s, over 1 ms + 1000 ppm of 2.5 s (3.5 ms)
        "  time jumps against the device clock (over 1 ms + 1000 ppm): 1",
        f"    set 0x80 offset {offs[13]}: +2.000000 s at device clock 5.000000 s"
        f" (UTC {tb.iso(utc_of_gps(ext(5.0, 2)))})",
    ]
    # The UTC line counts the clocks: 9 by the external time (sensor packets 1.0-2.5, 5.0-6.0),
    # 1 by its own GPS time, 8 by the device clock (6 status packets, 4 sensor packets 3.0-4.5).
    utc = next(x for x in lines if x.startswith("UTC:"))
    assert "(18 of 18 data packets: 1 by their own GPS time, 7 by their external time, 10 by the device clock)" in utc
    ext_line = next(x for x in lines if x.startswith("external time:"))
    assert "(8 of 18 data packets)" in ext_line and "backward jumps: 0" in ext_line


def test_info_synchronization_of_a_gx5_45_log(tmp_path, capsys):
    # GX5-45 IMU packets every 1 s with the correlation timestamp: at TOW 8 and 9 neither PPS
    # Beacon Good (bit 0) nor GPS Time Initialized (bit 2): no PPS and no valid time, stretches
    # whose start has no time (no device clock, no UTC yet): "until" the UTC of TOW 10. Then time
    # initialized all along, PPS clear at TOW 12 and 13: a stretch without PPS, its span in UTC,
    # ended by TOW 14. No device clock: no jumps to compare.
    def flags(t):
        return 0 if t < 10 else 0b100 | (0 if t in (12, 13) else 1)

    tows = [8, 9, 10, 11, 12, 13, 14, 15]
    pk = [
        build_packet(0x80, SEN.GpsTimestamp(float(t), W, T.SensorGpsTimestampFlags(flags(t))), SEN.ScaledAccel())
        for t in tows
    ]
    offs = offsets(pk)
    path = tmp_path / "gx5.bin"
    path.write_bytes(b"".join(pk))
    lines = info_lines(path, capsys)
    at = lambda tow: tb.iso(utc_of_gps(WEEK0 + tow * NS))  # noqa: E731
    start = lines.index("synchronization:")
    assert lines[start:] == [
        "synchronization:",
        "  PPS (sensor 0x80,0x12 gps_timestamp): packets 8, without PPS 4, stretches 2",
        f"    offsets {offs[0]}-{offs[1]}: 2 packets, until UTC {at(10)}",
        f"    offsets {offs[4]}-{offs[5]}: 2 packets, UTC {at(12)} to {at(14)} (2.000 s)",
        "  GPS time fields: packets 8, not valid 2, stretches 1",
        f"    offsets {offs[0]}-{offs[1]}: 2 packets, until UTC {at(10)}",
        "  time jumps: no packet with both a device clock and a valid time to compare",
    ]


def test_info_without_synchronization_fields(tmp_path, capsys):
    path = tmp_path / "plain.bin"
    path.write_bytes(b"".join(build_packet(0x80, S.ReferenceTimestamp(i * NS), SEN.ScaledAccel()) for i in range(3)))
    assert info_lines(path, capsys)[-1] == "synchronization: no synchronization fields"


def exported_t_ns(out) -> list:
    with (out / "sensor.scaled_accel.csv").open(newline="") as fh:
        return [int(r["t_ns"]) for r in csv.DictReader(fh)]


def test_export_and_dataset_rows_agree(tmp_path):
    """The CSV export (packet path here, columnar path with the C accelerator) and the dataset
    (block path) give the sensor packets the times reasoned in `cv7_log`."""
    pq = pytest.importorskip("pyarrow.parquet")
    pk, want = cv7_log()
    path = tmp_path / "cv7.bin"
    path.write_bytes(b"".join(pk))
    sensor_want = [w for p, w in zip(pk, want) if p[2] == 0x80]
    out = tmp_path / "csv"
    assert cli.main(["export", str(path), "--out", str(out)]) == 0
    assert exported_t_ns(out) == sensor_want
    fast = tmp_path / "fast"
    run = subprocess.run(
        [sys.executable, "-m", "mipcodec", "export", str(path), "--out", str(fast)],
        env=dict(os.environ, PYTHONPATH=ext_build("mipcodec")),
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0 and "(columnar path)" in run.stderr, run.stderr
    assert exported_t_ns(fast) == sensor_want
    ds = tmp_path / "ds"
    assert cli.main(["export", "--dataset", str(ds), str(path), "--model", "cv7_ins"]) == 0
    parts = sorted((ds / "sensor.scaled_accel").glob("**/*.parquet"))
    assert parts
    t = sorted(v for p in parts for v in pq.read_table(p, columns=["t_ns"]).column("t_ns").to_pylist())
    assert t == sorted(sensor_want)
