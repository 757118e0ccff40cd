"""`export --dataset DIR LOGS...` (the package's dataset.py, docs/dataset.md): the Hive-partitioned
Parquet dataset of logs, its split grid and exactly-once decoding, `_files`, re-runs, failed
writes, the schema's metadata and its growth with the spec.

Expected values come from elsewhere than the dataset code: the whole-log decode of the same bytes
(splits), `export --format csv` (the device capture ../shared/captures/mip_data.bin), the byte
counts of the log as built here (truncated log), the spec's own tables (metadata), and the
wire-compatibility diff (generator/wirediff.py) for schema growth.
"""

from __future__ import annotations

import copy
import csv
import datetime
import importlib
import os
import random
import resource
import struct
import subprocess
import sys
from pathlib import Path

import pyarrow as pa
import pyarrow.dataset as pads
import pyarrow.parquet as pq
import pytest

from generator import columns as gencolumns
from generator import wirediff
from generator.spec import load_spec
from tests.export.test_export import CAPTURE, ROOT, ext_build, pkg, vector_stream

PARTITIONING = pads.partitioning(
    pa.schema([("model", pa.string()), ("serial", pa.string()), ("date", pa.string())]), flavor="hive"
)


def ds(package: str = "mipcodec"):
    pkg(package)
    return importlib.import_module(f"{package}.logs.dataset")


def capture_bytes() -> bytes:
    if not CAPTURE.exists():
        pytest.skip(f"no device capture at {CAPTURE}")
    return CAPTURE.read_bytes()


def messy_log() -> bytes:
    """Packets of every golden vector, a piece of the device capture when it is there, garbage
    with sync bytes in it, a packet with a bad checksum, and a packet cut by the end."""
    rng = random.Random(41)
    vectors = vector_stream("mip")
    capture = CAPTURE.read_bytes()[:6000] if CAPTURE.exists() else vectors
    garbage = bytes(rng.randrange(256) for _ in range(300)) + b"\x75\x65\x80\x04" + bytes(7) + b"\x75\x65"
    good = bytes.fromhex("7565800e0e04") + struct.pack(">fff", 0.5, -0.25, 1.0)
    from tests.export.test_export import pkg as _pkg

    framing = _pkg("mipcodec").codec.framing
    packet = good + framing.checksum_bytes(good)
    bad = bytearray(packet)
    bad[-1] ^= 0xFF
    return vectors + garbage + capture + bytes(bad) + packet + vectors[:2000] + packet[:9]


# The device these tests decode their logs as (the golden vectors hold per-device fields; a log of
# unknown device with them is unreadable, tests/export/test_pipeline.py).
GX5 = ds().Identity("gx5_45")


def union_of_splits(dsm, data: bytes, split_bytes: int):
    """Every split decoded with its clock from the log's clock map (the two phases)."""
    size = len(data)
    read_at = lambda o, n: data[o : o + n]  # noqa: E731
    clocks = dsm.clock_maps(read_at, size, split_bytes)
    results = []
    for k, (start, end) in enumerate(dsm.splits(size, split_bytes)):
        window, base = dsm.read_split(read_at, size, start, end)
        results.append(dsm.decode_split(window, base, start, end, clocks[k], GX5, "L", size))
    return results


def _bits(v):
    """A cell compared by its bits (NaN equal to itself, payload included)."""
    return ("f", struct.pack(">d", v)) if isinstance(v, float) else v


def rows_by_table(results, samples: bool = False):
    out: dict = {}
    for r in results:
        for name, t in r.tables.items():
            if name.endswith(".samples") != samples:
                continue
            out.setdefault(name, []).extend({k: _bits(v) for k, v in row.items()} for row in t.to_pylist())
    for rows in out.values():
        rows.sort(key=lambda row: row["offset"])  # stable: fields of one packet keep their order
    return out


@pytest.mark.parametrize("split_bytes", [11, 97, 257, 1009, 4099, 1 << 20])
def test_splits_decode_every_packet_exactly_once(monkeypatch, split_bytes):
    """For split sizes that cut packets (small primes) and that do not, the union of the splits'
    tables is the whole-log decode row for row, and the counts add up to the whole log's."""
    dsm = ds()
    monkeypatch.setattr(dsm, "LOOKBACK", 1024)  # any size above MAX_PACKET resynchronises here
    data = messy_log()
    whole = dsm.decode_split(data, 0, 0, len(data), None, GX5, "L", len(data))
    assert whole.skipped_bytes > 300 and whole.bad_checksums >= 1 and whole.truncated
    parts = union_of_splits(dsm, data, split_bytes)
    want, got = rows_by_table([whole]), rows_by_table(parts)
    assert sorted(got) == sorted(want)
    for name in want:
        assert got[name] == want[name], name
    assert sum(r.packets for r in parts) == whole.packets > 100
    assert sum(r.skipped_bytes for r in parts) == whole.skipped_bytes
    assert sum(r.bad_checksums for r in parts) == whole.bad_checksums
    assert [r.truncated for r in parts] == [False] * (len(parts) - 1) + [True]


# UTC 2026-11-27 23:59:59.5 as GPS week and time of week, worked out with datetime (not the
# dataset's or timebase's code): GPS = UTC + 18 leap seconds (IERS Bulletin C, since 2017).
UTC0 = datetime.datetime(2026, 11, 27, 23, 59, 59, 500000, tzinfo=datetime.timezone.utc)
UTC0_NS = (
    (UTC0 - datetime.datetime(1970, 1, 1, tzinfo=datetime.timezone.utc)) // datetime.timedelta(microseconds=1) * 1000
)
GPS0 = UTC0 + datetime.timedelta(seconds=18) - datetime.datetime(1980, 1, 6, tzinfo=datetime.timezone.utc)
WEEK0, TOW0 = divmod(GPS0.total_seconds(), 604800)
DEV0 = 5_000_000_000


def timed_log(n: int = 30) -> bytes:
    """A filter packet with the device clock and a valid GPS time (the anchor), then sensor
    packets every 100 ms with the device clock only, across UTC midnight."""
    mod = pkg()
    shared, sensor, filter_data = (
        importlib.import_module(f"mipcodec.{m}") for m in ("shared", "sensor", "filter_data")
    )
    out = mod.codec.framing.build_packet(
        0x82,
        shared.ReferenceTimestamp(nanoseconds=DEV0),
        filter_data.GpsTimestamp(tow=TOW0, week_number=int(WEEK0), valid_flags=1),
    )
    for i in range(n):
        out += mod.codec.framing.build_packet(
            0x80,
            shared.ReferenceTimestamp(nanoseconds=DEV0 + i * 100_000_000),
            sensor.ScaledAccel(scaled_accel=[0.0, 0.0, float(i)]),
        )
    return out


def test_time_columns_and_date_partitions(tmp_path):
    """t_ns / time from the GPS anchor through the device clock (UTC0 + i * 100 ms), the device
    clock kept raw, GPS week and time of week where the packet carries them, and rows partitioned
    by UTC date: the same over splits as over the whole log."""
    dsm = ds()
    data = timed_log()
    want = [UTC0_NS + i * 100_000_000 for i in range(30)]
    for split in (len(data), 97, 31):
        rows = rows_by_table(union_of_splits(dsm, data, split))
        accel = rows["sensor.scaled_accel"]
        assert [r["t_ns"] for r in accel] == want, split
        assert [r["device_ns"] for r in accel] == [DEV0 + i * 100_000_000 for i in range(30)]
        assert {r["gps_week"] for r in accel} == {None}
        gps = rows["filter_data.gps_timestamp"]
        assert [(r["gps_week"], r["gps_tow"], r["t_ns"]) for r in gps] == [
            (int(WEEK0), ("f", struct.pack(">d", TOW0)), UTC0_NS)
        ]
    log = tmp_path / "t.bin"
    log.write_bytes(data)
    run = export_dataset_cli(tmp_path / "ds", str(log), extra=("--model", "3DM-GX5-45", "--serial", "SN1"))
    assert run.returncode == 0, run.stderr
    t = read_dataset(tmp_path / "ds", "sensor.scaled_accel")
    by_date = {}
    for r in t.to_pylist():
        by_date.setdefault(r["date"], []).append(r["time"])
    assert sorted(by_date) == ["2026-11-27", "2026-11-28"]
    assert len(by_date["2026-11-27"]) == 5  # 23:59:59.5 .. 23:59:59.9
    assert all(x.date() == datetime.date(2026, 11, 28) for x in by_date["2026-11-28"])
    assert set(t.column("model").to_pylist()) == {"3DM-GX5-45"} and set(t.column("serial").to_pylist()) == {"SN1"}
    files = read_dataset(tmp_path / "ds", "_files").to_pylist()
    assert files[0]["first_t_ns"] == UTC0_NS and files[0]["last_t_ns"] == want[-1]
    assert files[0]["status"] == "ok" and files[0]["packets"] == 31
    part = next((tmp_path / "ds" / "sensor.scaled_accel").rglob("*.parquet"))
    times = pq.read_table(part).column("t_ns").to_pylist()
    assert times == sorted(times)


def test_whole_log_counts_match_info(tmp_path):
    """The whole-log counts equal what `info` reports for the same bytes."""
    dsm = ds()
    data = messy_log()
    log = tmp_path / "m.bin"
    log.write_bytes(data)
    whole = dsm.decode_split(data, 0, 0, len(data), None, GX5, "L", len(data))
    mod = pkg()
    summary = mod.logs.info.Summary()
    for e in mod.logs.writers.events(mod.logs.writers.Source(str(log), progress=False), None):
        summary.add(e)
    assert whole.packets == sum(summary.packets.values())
    assert whole.skipped_bytes == summary.skipped
    assert whole.bad_checksums == summary.bad_checksums


def export_dataset_cli(out: Path, *logs: str, extra=(), package="mipcodec", env=None):
    return subprocess.run(
        [sys.executable, "-m", package, "export", "--dataset", str(out), *logs, *extra],
        env=dict(os.environ, PYTHONPATH=ext_build(package), **(env or {})),
        capture_output=True,
        text=True,
    )


def read_dataset(out: Path, table: str):
    return pads.dataset(out / table, format="parquet", partitioning=PARTITIONING).to_table()


def visible_files(out: Path):
    return sorted(str(p.relative_to(out)) for p in out.rglob("*") if p.is_file())


def test_accelerated_export_same_rows_for_any_split_size(tmp_path):
    """The C columnar decoder through the command: the dataset of split sizes that cut packets is
    the one of a single split (rows of every table), and file names follow the grid."""
    log = tmp_path / "m.bin"
    log.write_bytes(messy_log())
    tables = {}
    for split in (1 << 26, 4099, 997):
        out = tmp_path / f"d{split}"
        run = export_dataset_cli(out, str(log), extra=("--split-bytes", str(split)))
        assert run.returncode == 0, run.stderr
        names = sorted(p.name for p in out.iterdir() if p.is_dir() and p.name != "_files")
        tables[split] = {}
        for name in names:
            t = read_dataset(out, name).sort_by([("offset", "ascending")])
            rows = t.drop_columns(["model", "serial", "date"]).to_pylist()
            tables[split][name] = [{k: _bits(v) for k, v in row.items()} for row in rows]
        starts = {p.name.split("-")[-1].split(".")[0] for p in out.rglob("part-*.parquet") if "_files" not in str(p)}
        assert starts <= {f"{k * split:012x}" for k in range(len(messy_log()) // split + 1)}
    base = tables[1 << 26]
    for split in (4099, 997):
        per_field = {n for n in base if not n.endswith(".samples")}
        assert {n for n in tables[split] if not n.endswith(".samples")} == per_field
        for name in per_field:
            assert tables[split][name] == base[name], (split, name)


def test_capture_accelerations_equal_the_csv_export(tmp_path):
    """The device capture: sensor.scaled_accel in the dataset (read back by pyarrow with hive
    partitioning) holds the scaled accelerations `export --format csv` writes, row for row."""
    data = capture_bytes()
    log = tmp_path / "cap.bin"
    log.write_bytes(data)
    run = export_dataset_cli(tmp_path / "ds", str(log))
    assert run.returncode == 0, run.stderr
    assert "ok, 8384 packets" in run.stdout  # info on the capture: 8384 packets, nothing skipped
    csv_run = subprocess.run(
        [sys.executable, "-m", "mipcodec", "export", str(log), "--format", "csv", "--out", str(tmp_path / "csv")],
        env=dict(os.environ, PYTHONPATH=ext_build("mipcodec")),
        capture_output=True,
        text=True,
    )
    assert csv_run.returncode == 0, csv_run.stderr
    with (tmp_path / "csv" / "sensor.scaled_accel.csv").open(newline="") as fh:
        rows = list(csv.reader(fh))
    head, body = rows[0], rows[1:]
    assert head[2:] == ["offset", "scaled_accel.x [g]", "scaled_accel.y [g]", "scaled_accel.z [g]"]
    t = read_dataset(tmp_path / "ds", "sensor.scaled_accel").sort_by([("offset", "ascending")])
    assert t.num_rows == len(body) == 4473
    f32 = lambda text: struct.unpack("<f", struct.pack("<f", float(text)))[0]  # noqa: E731
    assert t.column("offset").to_pylist() == [int(r[2]) for r in body]
    for axis, j in (("x", 3), ("y", 4), ("z", 5)):
        assert t.column(f"scaled_accel_{axis}").to_pylist() == [f32(r[j]) for r in body]
    assert t.schema.field("scaled_accel_x").type == pa.float32()
    assert set(t.column("model").to_pylist()) == {"unknown"}  # the capture has no device information reply
    assert t.column("device_ns").to_pylist()[0] == 282809000000  # reference timestamp of its first packet


def test_truncated_log_is_a_files_row_with_its_counts(tmp_path):
    """A log cut inside its last packet, a garbage-only file and a missing file: each a `_files`
    row with its counts and status; the run succeeds."""
    data = capture_bytes()
    last = data.rfind(b"\x75\x65")  # the capture's last packet starts at its last sync
    assert data[last:].count(b"\x75\x65") == 1
    cut = data[: last + 5]
    (tmp_path / "cut.bin").write_bytes(cut)
    rng = random.Random(7)
    (tmp_path / "noise.bin").write_bytes(bytes(rng.randrange(256) for _ in range(5000)).replace(b"\x75\x65", b"xx"))
    run = export_dataset_cli(
        tmp_path / "ds", str(tmp_path / "cut.bin"), str(tmp_path / "noise.bin"), str(tmp_path / "missing.bin")
    )
    assert run.returncode == 0, run.stderr
    files = {r["path"]: r for r in read_dataset(tmp_path / "ds", "_files").to_pylist()}
    cutrow = files[str(tmp_path / "cut.bin")]
    assert cutrow["status"] == "truncated"
    assert cutrow["bytes"] == len(cut)
    assert cutrow["packets"] == 8384 - 1
    assert cutrow["skipped_bytes"] == 5 and cutrow["bad_checksums"] == 0
    import hashlib

    assert cutrow["log"] == hashlib.sha256(cut).hexdigest()[:16]
    noise = files[str(tmp_path / "noise.bin")]
    assert (noise["status"], noise["packets"], noise["skipped_bytes"]) == ("corrupt", 0, 5000)
    missing = files[str(tmp_path / "missing.bin")]
    assert missing["status"] == "unreadable" and "No such file" in missing["error"]
    assert "missing.bin: unreadable" in run.stdout


def test_rerun_replaces_and_drops_stale_parts(tmp_path):
    """Running again on the same log replaces its parts (same names, no duplicate rows); with
    another split size the parts of the old grid are removed."""
    log = tmp_path / "m.bin"
    log.write_bytes(messy_log())
    out = tmp_path / "ds"
    assert export_dataset_cli(out, str(log), extra=("--split-bytes", "4096")).returncode == 0
    first = visible_files(out)
    n = read_dataset(out, "sensor.scaled_accel").num_rows
    assert export_dataset_cli(out, str(log), extra=("--split-bytes", "4096")).returncode == 0
    assert visible_files(out) == first
    assert read_dataset(out, "sensor.scaled_accel").num_rows == n
    assert export_dataset_cli(out, str(log), extra=("--split-bytes", "5000")).returncode == 0
    again = visible_files(out)
    assert not any(f.endswith("-000000001000.parquet") for f in again)  # 4096 was a start of the old grid
    assert any(f.endswith("-000000001388.parquet") for f in again)  # 5000 is one of the new grid
    assert read_dataset(out, "sensor.scaled_accel").num_rows == n
    assert len(read_dataset(out, "_files")) == 1


def test_unwritable_dataset_is_one_error_line(tmp_path):
    """A dataset directory that cannot be made: one line on stderr, exit status 2."""
    log = tmp_path / "m.bin"
    log.write_bytes(messy_log())
    (tmp_path / "file").write_text("x")
    run = export_dataset_cli(tmp_path / "file" / "ds", str(log))
    assert run.returncode == 2
    assert len(run.stderr.strip().splitlines()) == 1 and "cannot write" in run.stderr, run.stderr


def test_full_disk_leaves_no_visible_partial_file(tmp_path):
    """A write that fails part way (the file size limit standing in for a full disk): one line,
    exit 2, and every visible file of the dataset is a whole Parquet file (no temporary left)."""
    log = tmp_path / "m.bin"
    log.write_bytes(capture_bytes() * 3)
    out = tmp_path / "ds"

    def limit():
        import signal

        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (40_000, 40_000))

    run = subprocess.run(
        [sys.executable, "-m", "mipcodec", "export", "--dataset", str(out), str(log)],
        env=dict(os.environ, PYTHONPATH=ext_build("mipcodec")),
        capture_output=True,
        text=True,
        preexec_fn=limit,
    )
    assert run.returncode == 2, run.stderr
    assert len(run.stderr.strip().splitlines()) == 1 and "cannot write" in run.stderr, run.stderr
    files = [p for p in out.rglob("*") if p.is_file()]
    assert not [p for p in files if p.name.startswith(".")]
    for p in files:
        pq.read_metadata(p)  # whole files only


def test_metadata_from_the_spec(tmp_path):
    """Arrow field metadata (units, description, frame, set, descriptor, title) and file metadata."""
    dsm = ds()
    mod = pkg()
    schema = dsm.table_schema(0x80, (0x80, 0x04, None))
    f = schema.field("scaled_accel_x")
    md = {k.decode(): v.decode() for k, v in f.metadata.items()}
    assert md["units"] == "g" and md["set"] == "0x80" and md["descriptor"] == "0x04"
    assert md["title"] == mod._columns.TITLES[(0x80, 0x04, None)]
    assert md["description"] == "(x, y, z) acceleration."  # the parameter's description, spec/mip/sensor.yaml
    # the frame spec/mip/sensor.yaml states per device: the GX5-45's "local coordinate system"
    # (3dm-gx5-45-dcp.txt line 2037), the CV7's vehicle frame (3dm-cv7-ins-docs.txt line 6393)
    assert md["frame"] == "cv7_ins: vehicle; gx5_45: sensor"
    vel = dsm.table_schema(0x82, (0x82, 0x02, None))
    assert {vel.field(f"ned_velocity_{n}").metadata[b"frame"] for n in ("north", "east", "down")} == {b"ned"}
    assert b"frame" not in vel.field("ned_velocity_valid_flags").metadata  # no frame stated for the flags
    assert schema.names[:7] == ["t_ns", "time", "offset", "log", "device_ns", "gps_week", "gps_tow"]
    assert schema.field("time").type == pa.timestamp("us", tz="UTC")
    data = capture_bytes()[:3000]
    r = dsm.decode_split(data, 0, 0, len(data), None, dsm.Identity("3dm-gx5-45", "6251.1", "1.2"), "abc", len(data))
    written = dsm.write_split(str(tmp_path), r)
    assert written and all(w.startswith(tuple(r.tables)) for w in written)
    meta = pq.read_schema(tmp_path / written[0]).metadata
    assert meta[b"mipcodec.model"] == b"3dm-gx5-45" and meta[b"mipcodec.serial"] == b"6251.1"
    assert meta[b"mipcodec.firmware"] == b"1.2" and meta[b"mipcodec.log"] == b"abc"
    assert meta[b"mipcodec.spec_hash"] == mod.SPEC_HASH.encode()
    assert "model=3dm-gx5-45/serial=6251.1/date=unknown" in written[0]


def test_identity_from_the_device_information_reply(tmp_path):
    """A log with a Get Device Information reply is partitioned by the model and serial it reports."""
    mod = pkg()
    dsm = ds()
    base = importlib.import_module("mipcodec.base")
    types = importlib.import_module("mipcodec.types")
    info = types.DeviceInfo(firmware_version=1534, model_name=b"3DM-GX5-45      ", serial_number=b"6232-00122      ")
    reply = mod.codec.framing.build_packet(0x01, base.DeviceInfo(info=info))
    data = capture_bytes()[:5000] + reply + capture_bytes()[5000:9000]
    ident = dsm.log_identity(lambda o, n: data[o : o + n], len(data), "other", "x")
    assert ident == dsm.Identity("3dm-gx5-45", "6232-00122", "1534")
    assert dsm.log_identity(lambda o, n: b"", 0, "My/Model", None) == dsm.Identity("My-Model", "unknown", None)


# ------------------------------------------------------------------------------------ schema
def ir_tables(ir: dict, dsm) -> dict:
    """Dataset tables of a spec computed from its IR (generator/columns.py, the source of the
    generated _columns tables) with the dataset's naming and types: name -> [(column, type)]."""
    proto = next(p for p in ir["protocols"] if p["name"] == "mip")
    shared = proto["shared_data"]["set"] if proto.get("shared_data") else None
    sets = {s["id"]: s for s in proto["sets"]}
    layouts = [(s["id"], f, v) for s, f, v in gencolumns.data_layouts(proto)]
    base = [(f.name, f.type) for f in dsm.base_fields()]
    out: dict = {}
    data_sets = sorted({s for s, _f, _v in layouts if s != shared})
    for set_id in data_sets:
        mine = [x for x in layouts if x[0] == shared] + [x for x in layouts if x[0] == set_id]
        samples = list(base)
        for s, f, v in mine:
            cols = [(dsm.column_name(c.name), dsm.arrow_type(c.kind)) for c in gencolumns.layout_columns(proto, f, v)]
            name = f"{sets[set_id]['name']}.{'shared.' if s != set_id else ''}{f['name']}"
            out[name + (f".{v['device']}" if v["device"] else "")] = base + cols
            samples += [c for c in cols if c[0] not in {x[0] for x in samples}]
        out[f"{sets[set_id]['name']}.samples"] = samples
    return out


@pytest.fixture(scope="module")
def spec_ir():
    return load_spec()


def test_runtime_tables_are_the_spec_tables(spec_ir):
    """The package's tables (from its generated _columns) are those computed from the IR."""
    dsm = ds()
    got = {n: [(f.name, f.type) for f in s] for n, s in dsm.table_names().items()}
    assert got == ir_tables(spec_ir, dsm)


@pytest.mark.parametrize("package", ["mipcodec", "mscipcodec"])
def test_column_names_unique_in_every_table(package):
    """Over the whole spec: a table's column names are unique (dots and brackets mapped to _ must
    not merge two columns) and none is a partition column; a name met twice in a samples table
    (per-device variants) has one type."""
    dsm = ds(package)
    tables = dsm.table_names()
    assert len(tables) >= 5
    for name, schema in tables.items():
        names = schema.names
        assert len(names) == len(set(names)), (name, [n for n in names if names.count(n) > 1])
        assert not set(names) & {"model", "serial", "date"}, name
        assert all(n and all(c.isalnum() or c == "_" for c in n) for n in names), name
    for set_id in dsm.data_sets():
        types: dict = {}
        for key in dsm.set_layouts(set_id):
            for f in dsm.table_schema(set_id, key):
                assert types.setdefault(f.name, f.type) == f.type, (set_id, f.name)


def test_compatible_spec_change_gives_compatible_schema(spec_ir):
    """A change the wire-compatibility diff calls compatible (a data field added to a set, a
    device added) only adds tables and columns: every old table keeps its columns, in order,
    with their types."""
    dsm = ds()
    new = copy.deepcopy(spec_ir)
    mip = next(p for p in new["protocols"] if p["name"] == "mip")
    sensor = next(s for s in mip["sets"] if s["id"] == 0x80)
    added = copy.deepcopy(next(f for f in sensor["fields"] if f["id"] == 0x04))
    added.update(id=0x61, name="scaled_accel_high_range", title="Scaled accelerometer, high range")
    sensor["fields"].append(added)
    mip["devices"].append({"id": "gq9", "title": "GQ9", "manual": "gq9.txt"})
    changes = wirediff.diff(spec_ir, new)
    assert changes and wirediff.verdict(changes) != wirediff.BREAKING
    assert all(c.kind in (wirediff.COMPATIBLE, wirediff.DOC) for c in changes), changes
    old_t, new_t = ir_tables(spec_ir, dsm), ir_tables(new, dsm)
    assert set(old_t) < set(new_t) and "sensor.scaled_accel_high_range" in new_t
    for name, cols in old_t.items():
        assert new_t[name][: len(cols)] == cols, name
    assert len(new_t["sensor.samples"]) > len(old_t["sensor.samples"])


def test_breaking_spec_change_is_seen_in_the_schema(spec_ir):
    """The check can fail: a wire-breaking type change changes an old column's type."""
    dsm = ds()
    new = copy.deepcopy(spec_ir)
    mip = next(p for p in new["protocols"] if p["name"] == "mip")
    f = next(f for s in mip["sets"] if s["id"] == 0x80 for f in s["fields"] if f["id"] == 0x04)
    q = f["variants"][0]["params"][0]
    q["type"] = {**q["type"], "name": "double", "size": {"min": 8, "max": 8, "fixed": True}}
    assert wirediff.verdict(wirediff.diff(spec_ir, new)) == wirediff.BREAKING
    old_t, new_t = ir_tables(spec_ir, dsm), ir_tables(new, dsm)
    assert new_t["sensor.scaled_accel"] != old_t["sensor.scaled_accel"]


def test_dataset_options_need_dataset(capsys):
    mod = pkg()
    assert mod.cli.main(["export", str(ROOT / "README.md"), "--out", "/tmp/x", "--split-bytes", "10"]) == 2
    assert "--split-bytes needs --dataset" in capsys.readouterr().err
    assert mod.cli.main(["export", "a", "b", "--out", "/tmp/x"]) == 2


def test_samples_tables_equal_the_join_export(tmp_path):
    """`<set>.samples` of the capture holds the rows and values of `export --join --format csv`."""
    import re

    data = capture_bytes()
    log = tmp_path / "cap.bin"
    log.write_bytes(data)
    assert export_dataset_cli(tmp_path / "ds", str(log)).returncode == 0
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "mipcodec",
            "export",
            str(log),
            "--join",
            "--format",
            "csv",
            "--out",
            str(tmp_path / "j"),
        ],
        env=dict(os.environ, PYTHONPATH=ext_build("mipcodec")),
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    for set_name, n in (("sensor", 7157), ("filter_data", 714), ("system_data", 512)):  # info: packets per set
        with (tmp_path / "j" / f"{set_name}.csv").open(newline="") as fh:
            head, *body = list(csv.reader(fh))
        t = read_dataset(tmp_path / "ds", f"{set_name}.samples").sort_by([("offset", "ascending")])
        assert t.num_rows == len(body) == n
        assert t.column("offset").to_pylist() == [int(r[2]) for r in body]
        for j, h in enumerate(head[3:], start=3):
            col = t.column(re.sub(r"[.\[\]]+", "_", h.split(" [")[0]).strip("_")).to_pylist()
            for r, v in zip(body, col):
                if r[j] == "":
                    assert v is None
                else:
                    assert v == struct.unpack("<f", struct.pack("<f", float(r[j])))[0] or v == float(r[j]), (h, r[j], v)


def test_continuation_packets_make_one_sample_row():
    """Packets of a set with the same shared timestamp are one row of `<set>.samples` (the first
    value of a column wins); another timestamp starts a new row."""
    dsm = ds()
    mod = pkg()
    shared, sensor = (importlib.import_module(f"mipcodec.{m}") for m in ("shared", "sensor"))
    ts = lambda ns: shared.ReferenceTimestamp(nanoseconds=ns)  # noqa: E731
    data = (
        mod.codec.framing.build_packet(0x80, ts(1000), sensor.ScaledAccel(scaled_accel=[1.0, 2.0, 3.0]))
        + mod.codec.framing.build_packet(0x80, ts(1000), sensor.ScaledGyro(scaled_gyro=[4.0, 5.0, 6.0]))
        + mod.codec.framing.build_packet(0x80, ts(1000), sensor.ScaledAccel(scaled_accel=[9.0, 9.0, 9.0]))
        + mod.codec.framing.build_packet(0x80, ts(2000), sensor.ScaledAccel(scaled_accel=[7.0, 8.0, 9.0]))
    )
    r = dsm.decode_split(data, 0, 0, len(data), None, GX5, "L", len(data))
    rows = r.tables["sensor.samples"].to_pylist()
    assert [(x["offset"], x["device_ns"]) for x in rows] == [(0, 1000), (len(data) - 30, 2000)]
    assert [x["scaled_accel_x"] for x in rows] == [1.0, 7.0]
    assert [x["scaled_gyro_z"] for x in rows] == [6.0, None]
    assert r.tables["sensor.scaled_accel"].num_rows == 3


def test_windows_give_the_parts_of_the_whole_split(tmp_path, monkeypatch):
    """The local export decodes a split in windows and writes its parts as they come: with
    windows that cut packets, row groups of a few rows and a clock that steps back (the timed log
    again after the messy one), every part holds the rows of the one-window export in the same
    order (sorted by t_ns, nulls last, then offset, as docs/dataset.md says), and its columns
    carry the encodings docs/dataset.md names (delta for integers and times, byte-stream-split
    for floats; zstd, none for a column chunk with no value in its row group)."""
    dsm = ds()
    log = tmp_path / "w.bin"
    log.write_bytes(timed_log() + messy_log() + timed_log())
    whole, cut = tmp_path / "whole", tmp_path / "cut"
    dsm.export_dataset([str(log)], str(whole), model="gx5_45")
    monkeypatch.setattr(dsm, "WINDOW_BYTES", 997)
    monkeypatch.setattr(dsm, "ROW_GROUP_BYTES", 2000)
    monkeypatch.setattr(dsm, "PENDING_BYTES", 6000)
    dsm.export_dataset([str(log)], str(cut), model="gx5_45")
    parts = sorted(str(p.relative_to(whole)) for p in whole.rglob("part-*.parquet"))
    assert parts == sorted(str(p.relative_to(cut)) for p in cut.rglob("part-*.parquet"))
    assert not list(cut.rglob(".*"))  # no temporary file left
    groups = uncompressed = 0
    for rel in parts:
        a, b = pq.read_table(whole / rel, partitioning=None), pq.read_table(cut / rel, partitioning=None)
        assert a.schema.equals(b.schema), rel
        assert [{k: _bits(v) for k, v in r.items()} for r in a.to_pylist()] == [
            {k: _bits(v) for k, v in r.items()} for r in b.to_pylist()
        ], rel  # (NaN values compared by their bits)
        if rel.startswith("_files"):
            continue
        keys = [(t is None, t or 0, o) for t, o in zip(b.column("t_ns").to_pylist(), b.column("offset").to_pylist())]
        assert keys == sorted(keys), rel
        meta = pq.ParquetFile(cut / rel).metadata
        groups = max(groups, meta.num_row_groups)
        columns = {
            meta.row_group(0).column(j).path_in_schema: meta.row_group(0).column(j) for j in range(meta.num_columns)
        }
        assert (
            "DELTA_BINARY_PACKED" in columns["t_ns"].encodings and "DELTA_BINARY_PACKED" in columns["offset"].encodings
        )
        assert "BYTE_STREAM_SPLIT" in columns["gps_tow"].encodings
        # zstd, but none for a column chunk without a value in its row group
        for g in range(meta.num_row_groups):
            group = meta.row_group(g)
            for j in range(meta.num_columns):
                chunk = group.column(j)
                empty = chunk.statistics.null_count == group.num_rows
                assert chunk.compression == ("UNCOMPRESSED" if empty else "ZSTD"), (rel, g, chunk.path_in_schema)
                uncompressed += empty
    assert groups > 1  # the small row groups were written as the windows came
    assert uncompressed  # (the samples tables' columns of the fields the log does not carry)


def test_the_api_example_gives_the_exports_dataset(tmp_path, monkeypatch):
    """docs/dataset.md's "The API (for other engines)" example, run as it is shown on a log of two
    splits of several windows each: the same files and rows as `export --dataset`."""
    dsm = ds()
    text = (ROOT / "docs" / "dataset.md").read_text()
    section = text[text.index("## The API (for other engines)") :]
    code = section[
        section.index("```python\n") + len("```python\n") : section.index("```", section.index("```python") + 3)
    ]
    log = tmp_path / "api.bin"
    log.write_bytes(timed_log() + messy_log() + timed_log())
    monkeypatch.setattr(dsm, "SPLIT_BYTES", log.stat().st_size // 2 + 1)
    monkeypatch.setattr(dsm, "WINDOW_BYTES", 3001)
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "docs/dataset.md", "exec"), {"path": str(log)})
    dsm.export_dataset([str(log)], str(tmp_path / "export"), split_bytes=log.stat().st_size // 2 + 1)
    api, export = tmp_path / "fleet", tmp_path / "export"
    parts = sorted(str(p.relative_to(export)) for p in export.rglob("*.parquet"))
    assert parts == sorted(str(p.relative_to(api)) for p in api.rglob("*.parquet"))
    assert len([p for p in parts if "-000000000000.parquet" not in p and not p.startswith("_files")]) > 0
    for rel in parts:
        a, b = pq.read_table(api / rel, partitioning=None), pq.read_table(export / rel, partitioning=None)
        if rel.startswith("_files"):
            a, b = a.drop_columns(["path"]), b.drop_columns(["path"])
        assert a.schema.equals(b.schema, check_metadata=True), rel
        rows = [[{k: _bits(v) for k, v in r.items()} for r in t.to_pylist()] for t in (a, b)]
        assert rows[0] == rows[1], rel  # (NaN values compared by their bits)


def test_progress_bar_only_on_a_terminal(tmp_path):
    """`export --dataset` draws its progress bar (tqdm: percent and bytes) when stderr is a
    terminal, and writes none when stderr is a pipe (what the other tests and scripts see)."""
    import pty

    log = tmp_path / "p.bin"
    log.write_bytes(timed_log())
    piped = export_dataset_cli(tmp_path / "piped", str(log), extra=("--model", "gx5_45"))
    assert piped.returncode == 0, piped.stderr
    assert "%" not in piped.stderr and "\r" not in piped.stderr
    leader, follower = pty.openpty()
    try:
        cmd = [sys.executable, "-m", "mipcodec", "export", "--dataset", str(tmp_path / "tty"), str(log)]
        env = dict(os.environ, PYTHONPATH=ext_build("mipcodec"))
        done = subprocess.run(cmd + ["--model", "gx5_45"], env=env, stdout=subprocess.DEVNULL, stderr=follower)
        os.close(follower)
        follower = -1
        drawn = b""
        while True:
            try:
                chunk = os.read(leader, 4096)
            except OSError:  # the terminal's other end is closed: all read
                break
            if not chunk:
                break
            drawn += chunk
    finally:
        os.close(leader)
        if follower >= 0:
            os.close(follower)
    assert done.returncode == 0
    assert b"100%" in drawn and b"\r" in drawn, drawn
