"""MCAP files with ROS 2 messages and JSON schemas (issue 54; runtime logs/mcap.py, logs/ros.py,
device/record_mcap.py; docs/mcap.md), read back with readers independent of the writer: the
`mcap` library's reader and `mcap-ros2-support`'s ROS 2 decoder, which parses the files' own
`ros2msg` schema text and decodes the CDR bytes by it.

Logs: a small simulated fleet (docs/fleet.md: a 3DM-GX5-45 and a 3DM-CV7-GNSS/INS, 10 s each, the
level circle), and a live recording of the simulated GX5-45. Expected values come from the CSV export
of the same log (the issue: "the values equal the CSV export's"), the spec's units (g to m/s^2 by
the standard 9.80665, gauss to tesla by 1e-4) and REP-103's axes (y and z negated), and from
reasoning written beside each check; never from the writer under test.
"""

from __future__ import annotations

import csv
import importlib
import json
import math
import os
import resource
import signal
import statistics
import struct
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.conformance.test_device_c import tool  # noqa: F401 - the C tool's fixture
from tests.conformance.test_device_cli import Sim
from tests.helpers.generated import GENERATED_PYTHON, python_package
from tests.helpers.procs import as_in_a_terminal

pkg = python_package("mipcodec")
fleet = importlib.import_module("mipcodec.fleet")
columns = importlib.import_module("mipcodec._columns")
ros = importlib.import_module("mipcodec.logs.ros")

GENERATED = str(GENERATED_PYTHON / "mipcodec")
SECONDS = 10
G = 9.80665  # m/s^2 per g: the CGPM's standard gravity (the spec's accelerations are in g)
SERIALS = {"gx5_45": "6232-10100", "cv7_ins": "6284.170401"}  # the fleet's (docs/fleet.md), seed 3


def cli(*args: str, cwd=None) -> subprocess.CompletedProcess:
    """python -m mipcodec ARGS (the pure-Python package: the MCAP export takes the packet path)."""
    path = os.pathsep.join(p for p in (GENERATED, os.environ.get("PYTHONPATH")) if p)
    env = dict(os.environ, PYTHONPATH=path)
    return subprocess.run([sys.executable, "-m", "mipcodec", *args], env=env, capture_output=True, text=True, cwd=cwd)


def rows(path: Path) -> list:
    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


@pytest.fixture(scope="module")
def made(tmp_path_factory) -> dict:
    """model -> (log, its MCAP file, its CSV tables' directory)."""
    out = tmp_path_factory.mktemp("fleet")
    fleet.generate(str(out), devices=2, hours=SECONDS / 3600, seed=3)
    manifest = json.loads((out / "fleet.json").read_text())
    found = {}
    for d in manifest["devices"]:
        log = out / d["log"]
        mcap_file = out / f"{d['model']}.mcap"
        run = cli("export", str(log), "--format", "mcap", "--out", str(mcap_file))
        assert run.returncode == 0, run.stderr
        run = cli("export", str(log), "--out", str(out / d["model"]))
        assert run.returncode == 0, run.stderr
        found[d["model"]] = (log, mcap_file, out / d["model"])
    return found


def read(path: Path):
    """(summary, [(channel, schema, message, decoded or None)]) in file order."""
    reader_mod = importlib.import_module("mcap.reader")
    decoder = importlib.import_module("mcap_ros2.decoder")
    with path.open("rb") as fh:
        reader = reader_mod.make_reader(fh)
        summary = reader.get_summary()
        metadata = {m.name: dict(m.metadata) for m in reader.iter_metadata()}
    factory = decoder.DecoderFactory()
    decoders: dict = {}
    with path.open("rb") as fh:
        out = []
        for schema, channel, message in reader_mod.make_reader(fh).iter_messages(log_time_order=False):
            decoded = None
            if channel.message_encoding == "cdr":
                if schema.id not in decoders:
                    decoders[schema.id] = factory.decoder_for("cdr", schema)
                decoded = decoders[schema.id](message.data)
            out.append((channel, schema, message, decoded))
    return summary, metadata, out


def check_file(path: Path, validate: int = 0) -> dict:
    """The checks every MCAP file passes; returns topic -> [(message, decoded or JSON)]. Every
    JSON message is checked against its schema, or (`validate`) the first so many of each topic
    (jsonschema checks about 5,000 messages a second)."""
    jsonschema = importlib.import_module("jsonschema")
    summary, metadata, messages = read(path)
    # chunked, compressed, indexed (the summary's chunk and message indexes)
    assert summary.chunk_indexes and {c.compression for c in summary.chunk_indexes} == {"zstd"}
    assert all(c.message_index_offsets for c in summary.chunk_indexes)
    assert summary.statistics.message_count == len(messages)
    assert metadata["protocol"]["spec_hash"] == pkg.SPEC_HASH
    by_topic: dict = {}
    validators: dict = {}
    last: dict = {}
    for channel, schema, message, decoded in messages:
        assert message.publish_time == message.log_time
        assert message.log_time >= last.get(channel.topic, 0), channel.topic  # never decreasing on a channel
        last[channel.topic] = message.log_time
        if channel.message_encoding == "json":
            assert schema.encoding == "jsonschema" and channel.topic.startswith("/mip/")
            v = validators.get(schema.id)
            if v is None:
                body = json.loads(schema.data)
                jsonschema.Draft7Validator.check_schema(body)
                v = validators[schema.id] = jsonschema.Draft7Validator(body)
            value = json.loads(message.data)
            seen = by_topic.setdefault(channel.topic, [])
            if not validate or len(seen) < validate:
                errors = [e.message for e in v.iter_errors(value)]
                assert not errors, (channel.topic, errors[:3])
            seen.append((message, value))
        else:
            assert (channel.message_encoding, schema.encoding) == ("cdr", "ros2msg")
            assert message.data[:4] == b"\x00\x01\x00\x00"  # CDR little endian, no options
            by_topic.setdefault(channel.topic, []).append((message, decoded))
    by_topic["_metadata"] = metadata
    return by_topic


def utc_span(tables: Path) -> tuple:
    times = [int(r["t_ns"]) for p in tables.iterdir() for r in rows(p) if r["t_ns"]]
    return min(times), max(times)


@pytest.mark.parametrize("model", ["gx5_45", "cv7_ins"])
def test_ros_messages_of_each_device(made, model):
    log, path, tables = made[model]
    got = check_file(path)
    meta = got["_metadata"]["device"]
    assert (meta["device"], meta["serial"], meta["source"]) == (model, SERIALS[model], "reply")
    lo, hi = utc_span(tables)
    for topic, msgs in got.items():
        if topic != "_metadata":
            assert all(lo <= m.log_time <= hi for m, _v in msgs), topic  # inside the log's UTC span
    # one Imu per accel+gyro sample with a known time (both fields in each sensor packet: the
    # CSV tables have the same offsets), its values the CSV's in m/s^2 and REP-103 axes
    accel = [r for r in rows(tables / "sensor.scaled_accel.csv") if r["t_ns"]]
    gyro = {r["offset"]: r for r in rows(tables / "sensor.scaled_gyro.csv")}
    imu = [d for _m, d in got["/imu/data"]]
    assert len(imu) == len(accel) > 0
    for r, d in zip(accel, imu):
        assert d.header.stamp.sec * 10**9 + d.header.stamp.nanosec == int(r["t_ns"])
        la = d.linear_acceleration
        assert (la.x, la.y, la.z) == pytest.approx(
            (
                float(r["scaled_accel.x [g]"]) * G,
                -float(r["scaled_accel.y [g]"]) * G,
                -float(r["scaled_accel.z [g]"]) * G,
            ),
            rel=1e-6,
        )
        g = gyro[r["offset"]]
        av = d.angular_velocity
        assert (av.x, av.y, av.z) == pytest.approx(
            (float(g["scaled_gyro.x [rad/s]"]), -float(g["scaled_gyro.y [rad/s]"]), -float(g["scaled_gyro.z [rad/s]"])),
            rel=1e-6,
        )
        assert d.orientation_covariance[0] == -1  # no filter attitude in a sensor packet
    # on the level circle the specific force is 1 g up: +9.8 m/s^2 on ROS's z (up)
    assert statistics.mean(d.linear_acceleration.z for d in imu) == pytest.approx(G, abs=0.1)
    frame = "imu_link" if model == "gx5_45" else "base_link"  # the spec's frames: sensor / vehicle
    assert {d.header.frame_id for d in imu} == {frame}
    if model == "gx5_45":  # GNSS position: the GX5-45's gnss_data set
        fixes = [d for _m, d in got["/gnss_data/fix"]]
        llh = [r for r in rows(tables / "gnss_data.llh_position.csv") if r["t_ns"]]
        assert len(fixes) == len(llh) > 0
        for r, d in zip(llh, fixes):
            assert -90 <= d.latitude <= 90 and -180 <= d.longitude <= 180
            assert (d.latitude, d.longitude, d.altitude) == (
                float(r["llh_position.latitude [deg]"]),
                float(r["llh_position.longitude [deg]"]),
                float(r["llh_position.ellipsoid_height [m]"]),
            )
            h = float(r["llh_position.horizontal_accuracy [m]"])
            assert d.position_covariance[0] == pytest.approx(h * h) and d.position_covariance_type == 1
    odometry = [d for _m, d in got["/odometry/filtered"]]
    assert odometry and odometry[0].header.frame_id == "odom" and odometry[0].child_frame_id == "base_link"
    first = odometry[0].pose.pose.position
    assert (first.x, first.y, first.z) == (0.0, 0.0, 0.0)  # the odom frame's origin: the first position


# column name -> (its path in the decoded value, its kind): the JSON message nests by the path
PATHS = {name: (path, kind) for specs in columns.COLUMNS.values() for name, path, _u, kind, _e in specs}


def same(leaf, cell: str, kind: str) -> bool:
    """A JSON leaf and its CSV cell hold the same value (JSON has null for an absent value, NaN
    and infinities; a `json` column is JSON text in the CSV)."""
    if leaf is None:
        return cell.lower() in ("", "nan", "inf", "-inf")
    if kind == "json":
        return json.loads(cell) == leaf
    if kind in ("float32", "float64"):
        return leaf == float(cell)
    if kind == "bool":
        return cell.lower() in (("true", "1") if leaf else ("false", "0"))
    return str(leaf) == cell


@pytest.mark.parametrize("model", ["gx5_45", "cv7_ins"])
def test_json_messages_equal_the_csv(made, model):
    """Every CSV table's rows are the messages of its topic, value for value (the CSV cell as
    text, the JSON leaf at the column's path)."""
    log, path, tables = made[model]
    got = check_file(path)
    compared = 0
    for table in sorted(tables.iterdir()):
        parts = table.stem.split(".")
        if parts[-1] in ("gx5_45", "cv7_ins"):
            parts = parts[:-1]
        topic = "/mip/" + "/".join(parts)
        msgs = [v for _m, v in got[topic]]
        table_rows = rows(table)
        assert len(msgs) == len(table_rows), topic
        for r, v in zip(table_rows, msgs):
            assert str(v["log_offset"]) == r["offset"]
            assert ("" if v["t_ns"] is None else str(v["t_ns"])) == r["t_ns"]
            for header, cell in r.items():
                if header in ("t_ns", "time", "offset"):
                    continue
                path, kind = PATHS[header.split(" [")[0]]
                leaf = v
                for step in path:
                    leaf = leaf[step]
                assert same(leaf, cell, kind), (topic, header, leaf, cell)
                compared += 1
    assert compared > 10000


def test_live_recording_of_the_simulator(tmp_path):
    """`device ADDRESS record FILE.mcap` of the simulated GX5-45, stopped by Ctrl-C: a whole MCAP
    file (no temporary file left), read back as above, naming the simulator's serial."""
    serial = "6232-51515"
    target = tmp_path / "live.mcap"
    path = os.pathsep.join(p for p in (GENERATED, os.environ.get("PYTHONPATH")) if p)
    started = time.monotonic()
    with Sim("gx5_45", "tcp:127.0.0.1:0", "--stream-full", "--speed", "1", "--serial", serial) as sim:
        proc = subprocess.Popen(
            [sys.executable, "-m", "mipcodec", "device", sim.address, "record", str(target)],
            env=dict(os.environ, PYTHONPATH=path),
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            preexec_fn=as_in_a_terminal,
        )
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and not list(tmp_path.glob(".live.mcap.part-*.bin")):
            time.sleep(0.05)  # the log exists once the device has answered
        # the simulated GPS time is valid from 2 s after the simulator's start (its clock is real
        # time, and it starts after `started`): a recording that goes on past 3.2 s has timed packets
        time.sleep(max(0.5, started + 3.2 - time.monotonic()))
        proc.send_signal(signal.SIGINT)  # Ctrl-C: the way to stop a recording
        out, err = proc.communicate(timeout=60)
    assert proc.returncode == 0 and "Traceback" not in err, err
    assert "stopped: interrupted" in err and "live.mcap: " in err and not out, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["live.mcap"]
    got = check_file(target, validate=50)  # 40,000 messages: the first 50 of each of its 60 topics
    assert got["_metadata"]["device"]["serial"] == serial
    times = [v["t_ns"] for t, msgs in got.items() if t.startswith("/mip/") for _m, v in msgs if v["t_ns"] is not None]
    assert all(min(times) <= m.log_time <= max(times) for t, msgs in got.items() if t != "_metadata" for m, _v in msgs)
    timed = [v for _m, v in got["/mip/sensor/scaled_accel"] if v["t_ns"] is not None]
    imu = [d for _m, d in got["/imu/data"]]
    assert len(imu) == len(timed) > 50
    assert statistics.mean(d.linear_acceleration.z for d in imu) == pytest.approx(G, abs=0.5)
    fixes = [d for _m, d in got["/gnss_data/fix"]]
    assert fixes and all(-90 <= d.latitude <= 90 and -180 <= d.longitude <= 180 for d in fixes)


def test_missing_mcap_is_one_line(tmp_path, made):
    """Without the `mcap` library: one line naming it and the extra, exit 2, nothing written."""
    blocker = tmp_path / "block"
    blocker.mkdir()
    (blocker / "mcap.py").write_text("raise ImportError('No module named mcap', name='mcap')\n")
    log, _path, _tables = made["gx5_45"]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join((str(blocker), GENERATED)))
    out = tmp_path / "x.mcap"
    run = subprocess.run(
        [sys.executable, "-m", "mipcodec", "export", str(log), "--format", "mcap", "--out", str(out)],
        env=env,
        capture_output=True,
        text=True,
    )
    assert run.returncode == 2 and run.stderr.count("\n") == 1, run.stderr
    assert "mcap is not installed: pip install 'mipcodec[mcap]'" in run.stderr
    assert not out.exists()
    run = subprocess.run(  # the recorder says so before it connects (port 1 of loopback: closed)
        [sys.executable, "-m", "mipcodec", "device", "tcp:127.0.0.1:1", "record", str(out)],
        env=env,
        capture_output=True,
        text=True,
    )
    assert run.returncode == 2 and run.stderr.count("\n") == 1, run.stderr
    assert "mcap is not installed: pip install 'mipcodec[mcap]'" in run.stderr
    assert not out.exists()


def test_a_full_disk_writes_no_mcap(tmp_path, made):
    """The file size limit (RLIMIT_FSIZE: a write fails with EFBIG, as a full disk with ENOSPC)
    below the MCAP file's size: one line, exit 2, no FILE.mcap and no temporary file left."""
    log, _path, _tables = made["gx5_45"]
    out = tmp_path / "x.mcap"

    def small_files() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (100_000, 100_000))

    path = os.pathsep.join(p for p in (GENERATED, os.environ.get("PYTHONPATH")) if p)
    run = subprocess.run(
        [sys.executable, "-m", "mipcodec", "export", str(log), "--format", "mcap", "--out", str(out)],
        env=dict(os.environ, PYTHONPATH=path),
        capture_output=True,
        text=True,
        preexec_fn=small_files,
    )
    assert run.returncode == 2 and run.stderr.count("\n") == 1, run.stderr
    assert f"cannot write {str(out)!r}: File too large" in run.stderr, run.stderr
    assert list(tmp_path.iterdir()) == []


def test_the_c_tool_refuses_an_mcap_file(tool, tmp_path):  # noqa: F811 - the fixture
    """The C package's recorder writes raw logs only: FILE.mcap is one line, exit 2, before it
    connects (port 1 of loopback: closed), nothing written."""
    out = tmp_path / "x.MCAP"
    run = subprocess.run([str(tool), "tcp:127.0.0.1:1", "record", str(out)], capture_output=True, text=True)
    assert run.returncode == 2 and run.stderr.count("\n") == 1, run.stderr
    assert "MCAP files are written by the Python package's recorder" in run.stderr
    assert list(tmp_path.iterdir()) == []


def test_topic_prefix_and_frames(tmp_path, made):
    """--topic-prefix puts every topic under /P; --frame NAME=ID renames a frame; a bad --frame is
    one line, exit 2."""
    log, _path, _tables = made["gx5_45"]
    out = tmp_path / "p.mcap"
    run = cli(
        "export", str(log), "--format", "mcap", "--out", str(out), "--topic-prefix", "robot1", "--frame", "sensor=imu0"
    )
    assert run.returncode == 0, run.stderr
    _summary, _meta, messages = read(out)
    assert messages and all(c.topic.startswith("/robot1/") for c, _s, _m, _d in messages)
    imu = [d for c, _s, _m, d in messages if c.topic == "/robot1/imu/data"]
    assert imu and {d.header.frame_id for d in imu} == {"imu0"}
    run = cli("export", str(log), "--format", "mcap", "--out", str(tmp_path / "q.mcap"), "--frame", "lidar=x")
    assert run.returncode == 2 and run.stderr.count("\n") == 1 and "unknown frame 'lidar'" in run.stderr, run.stderr
    assert not (tmp_path / "q.mcap").exists()


@pytest.mark.parametrize("package", ["mipcodec", "mscipcodec"])
def test_every_schema_is_valid_and_carries_the_units(package):
    """Every generated JSON Schema (both packages, every data field layout) is a valid draft-07
    schema; every column with units in the export table has them in its leaf (`units`, and in
    the description), every enum column lists the spec's names."""
    jsonschema = importlib.import_module("jsonschema")
    python_package(package)
    schemas = importlib.import_module(f"{package}._mcap_schemas").SCHEMAS
    table = importlib.import_module(f"{package}._columns")
    assert set(schemas) == set(table.COLUMNS)
    for key, text in schemas.items():
        body = json.loads(text)
        jsonschema.Draft7Validator.check_schema(body)
        for name, path, units, kind, enum in table.COLUMNS[key]:
            leaf = body
            for step in path:
                leaf = leaf["items"] if isinstance(step, int) else leaf["properties"][step]
            if units:
                assert leaf["units"] == units and leaf["description"].endswith(f"[{units}]"), (key, name)
            if kind == "enum":
                assert set(leaf["anyOf"][0]["enum"]) == set(table.ENUMS[enum].values()), (key, name)


# ------------------------------------------------------------------------------ the rules
def test_cdr_bytes_follow_the_rules():
    """TimeReference from the CDR rules (module docstring of ros.py): header 00 01 00 00; int32
    sec, uint32 nanosec; frame_id "gnss" as uint32 5 + b"gnss\\0"; the next Time's int32 aligned
    to 4 (3 bytes of padding after 17 bytes); source "gps" as uint32 4 + b"gps\\0"."""
    msg = {"header": {"stamp": {"sec": 7, "nanosec": 9}, "frame_id": "gnss"}, "time_ref": {"sec": 1, "nanosec": 2}}
    data = ros.encode("sensor_msgs/TimeReference", {**msg, "source": "gps"})
    want = (
        b"\x00\x01\x00\x00"
        + struct.pack("<iI", 7, 9)
        + struct.pack("<I", 5)
        + b"gnss\x00"
        + b"\x00\x00\x00"
        + struct.pack("<iI", 1, 2)
        + struct.pack("<I", 4)
        + b"gps\x00"
    )
    assert data == want
    # a float64 after a 4-byte value is aligned to 8 from the end of the header
    w = ros.Cdr()
    w.primitive("uint32", 1)
    w.primitive("float64", 2.0)
    assert w.bytes() == b"\x00\x01\x00\x00" + struct.pack("<I", 1) + b"\x00" * 4 + struct.pack("<d", 2.0)


def test_attitude_in_enu():
    """A vehicle facing east (MIP yaw +90 deg: q = (cos 45, 0, 0, sin 45) in NED) faces ROS's x
    (east): the identity; facing north (MIP yaw 0: the identity) is ROS yaw +90 deg about up."""
    c = math.cos(math.pi / 4)
    east = ros.enu_orientation((c, 0.0, 0.0, c))
    assert (east["w"], east["x"], east["y"], east["z"]) == pytest.approx((1, 0, 0, 0), abs=1e-12)
    north = ros.enu_orientation((1.0, 0.0, 0.0, 0.0))
    assert (north["w"], north["x"], north["y"], north["z"]) == pytest.approx((c, 0, 0, c), abs=1e-12)
    # 1 m/s north seen from a vehicle facing east: to its left (FLU +y)
    v = ros.rotate_to_body((c, 0.0, 0.0, c), (1.0, 0.0, 0.0))
    assert (v["x"], v["y"], v["z"]) == pytest.approx((0, 1, 0), abs=1e-12)


def sensor_values(accel_z: float) -> object:
    v = ros.Values()
    v.add((0x80, 0x04, None), [0.0, 0.0, accel_z])  # scaled_accel [g]
    v.add((0x80, 0x05, None), [0.0, 0.0, 0.0])  # scaled_gyro [rad/s]
    return v


def filter_values(q: tuple, valid: int = 1) -> object:
    v = ros.Values()
    v.add((0x82, 0x03, None), [*q, valid])  # attitude_quaternion (w, x, y, z), valid_flags
    return v


def test_the_imu_takes_the_attitude_of_its_sample():
    """The sample rule (packets sharing a time): a filter attitude with the Imu's time, coming
    right after the sensor packet or before it, is the Imu's orientation (facing north, MIP's
    identity, is ROS yaw +90 deg: (cos 45, 0, 0, sin 45) as x, y, z, w = (0, 0, s, c)); another
    time's attitude, or one flagged not valid, is not (orientation_covariance[0] = -1)."""
    c = math.cos(math.pi / 4)
    m = ros.Mapper(ros.Topics(), "gx5_45")
    assert m.messages("sensor", sensor_values(-1.0), 1000, 1000) == []  # held: its attitude may follow
    out = m.messages("filter_data", filter_values((1.0, 0.0, 0.0, 0.0)), 1000, 1000)
    (_t, (topic, ros_type, msg)), *_rest = out
    assert (topic, ros_type) == ("/imu/data", "sensor_msgs/Imu")
    o = msg["orientation"]
    assert (o["x"], o["y"], o["z"], o["w"]) == pytest.approx((0, 0, c, c)) and msg["orientation_covariance"][0] == 0
    assert msg["linear_acceleration"]["z"] == pytest.approx(G)  # -1 g down is +9.80665 m/s^2 up
    # the attitude first, then the sensor packet of the same time: at once
    m.messages("filter_data", filter_values((1.0, 0.0, 0.0, 0.0)), 2000, 2000)
    out = m.messages("sensor", sensor_values(-1.0), 2000, 2000)
    assert len(out) == 1 and out[0][1][2]["orientation_covariance"][0] == 0
    # a later packet of another time gives the held Imu out without an orientation
    assert m.messages("sensor", sensor_values(-1.0), 3000, 3000) == []
    out = m.messages("sensor", sensor_values(-1.0), 4000, 4000)
    assert [t for t, _msg in out] == [3000] and out[0][1][2]["orientation_covariance"][0] == -1
    # an attitude flagged not valid is not taken; the last Imu comes out with flush()
    assert m.messages("filter_data", filter_values((1.0, 0.0, 0.0, 0.0), valid=0), 4000, 4000) == []
    out = m.messages("sensor", sensor_values(-1.0), 5000, 5000)
    assert [t for t, _msg in out] == [4000] and out[0][1][2]["orientation_covariance"][0] == -1
    assert [t for t, _msg in m.flush()] == [5000] and m.flush() == []
