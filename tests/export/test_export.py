"""The user commands of the Python packages (`python -m mipcodec export|info|plot`) and
Table.arrays / Table.dataframe, against the canonical decode (docs/conformance.md).

Exported tables are compared value by value with the canonical JSON lines of the same bytes: the
device capture (../shared/captures/mip_data.bin) when it is there, and always a stream of every
golden vector of both protocols (every layout kind), through CSV, JSON lines and Parquet.
"""

from __future__ import annotations

import csv
import importlib
import io
import json
import math
import os
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
import pytest

from generator.vectors import load_vectors
from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
CAPTURE = Path(os.environ.get("CAPTURE", ROOT.parent / "shared" / "captures" / "mip_data.bin"))
IR = json.loads((ROOT / "generated" / "ir.json").read_text())
PACKAGES = {p["name"]: p["package"] for p in IR["protocols"]}


def pkg(name: str = "mipcodec"):
    """The generated package with the submodules these tests use imported."""
    mod = python_package(name)
    for sub in (
        "cli",
        "logs.commands",
        "logs.info",
        "logs.plot",
        "_columns",
        "registry",
        "codec.framing",
        "shared",
        "sensor",
    ):
        try:
            importlib.import_module(f"{name}.{sub}")
        except ModuleNotFoundError:
            pass  # (mscipcodec has no shared or sensor module)
    return mod


def vector_stream(protocol: str) -> bytes:
    cases = load_vectors(IR, ROOT / "tests" / "vectors")
    return b"".join(bytes.fromhex(c["hex"]) for c in cases if c["protocol"] == protocol and not c["rejected"])


def run(package: str, *args: str, capsys=None) -> int:
    return pkg(package).cli.main(list(args))


def canonical(package: str, data: bytes) -> dict:
    """(set, descriptor) -> [(offset, values)] from the canonical JSON lines of the bytes."""
    out: dict = {}
    shared = {s["id"] for s in next(p for p in IR["protocols"] if p["package"] == package)["sets"] if s["shared"]}
    del shared
    for line in pkg(package).decode_bytes(data):
        obj = json.loads(line)
        if "fields" not in obj:
            continue
        for f in obj["fields"]:
            if "values" in f:
                out.setdefault((obj["set"], f["descriptor"]), []).append((obj["offset"], f["values"]))
    return out


def walk(values, path):
    for step in path:
        if values is None:
            return None
        if isinstance(step, int):
            values = values[step] if step < len(values) else None
        else:
            values = values.get(step, values.get(step.rstrip("_")))
    return values


def same(kind: str, cell, want, enum_names=None) -> bool:
    """An exported cell (text from CSV, or a typed Parquet / JSON value) equals the canonical value."""
    if want is None:
        return cell in (None, "")
    if kind in ("float32", "float64"):
        if isinstance(want, str):  # "nan", "nan:0x..", "inf", "-inf"
            x = float(cell)
            return math.isnan(x) if want.startswith("nan") else x == float(want)
        x = float(cell)
        if kind == "float32":
            x = struct.unpack("<f", struct.pack("<f", x))[0]  # the text must name this float32 exactly
        return x == want
    if kind == "bool":
        return cell in (True, "true") if want else cell in (False, "false")
    if kind == "enum" and enum_names is not None:
        return cell == enum_names.get(want, str(want)) or cell == want
    if kind in ("int", "bits", "enum"):
        return int(cell) == want
    if isinstance(cell, str):
        cell = json.loads(cell)
    return norm(cell) == norm(want)


def norm(v):
    """JSON cells: bytes are latin-1 text in both; NaN payloads are not kept in a JSON cell."""
    if isinstance(v, list):
        return [norm(x) for x in v]
    if isinstance(v, dict):
        return {k: norm(x) for k, x in v.items()}
    if isinstance(v, str) and v.startswith("nan"):
        return "nan"
    return v


def read_table(path: Path):
    if path.suffix == ".csv":
        with path.open(newline="", encoding="utf-8") as fh:
            rows = list(csv.reader(fh))
        return rows[0], rows[1:]
    if path.suffix == ".jsonl":
        lines = [json.loads(x) for x in path.read_text().splitlines()]
        headers = list(lines[0]) if lines else []
        return headers, [[obj[h] for h in headers] for obj in lines]
    t = pq.read_table(path)
    return t.column_names, [list(r.values()) for r in t.to_pylist()]


def ext_build(package: str) -> str:
    """The package built with its C accelerator (build/python/ext/<package>, by tests/lang/python.sh ext)."""
    ext = subprocess.run(["tests/lang/python.sh", "ext"], cwd=ROOT, capture_output=True, text=True, check=True)
    return next(line for line in ext.stdout.splitlines() if line.endswith("/" + package))


def check_export(package: str, data: bytes, out: Path, fmt: str, enum_numbers: bool, accelerated: bool = False) -> int:
    """Exports `data` and compares every table with the canonical decode; returns the values checked."""
    mod = pkg(package)
    log = out / "log.bin"
    log.write_bytes(data)
    args = ["export", str(log), "--format", fmt, "--out", str(out / fmt)] + (["--enum-numbers"] if enum_numbers else [])
    if accelerated:
        run = subprocess.run(
            [sys.executable, "-m", package] + args,
            env=dict(os.environ, PYTHONPATH=ext_build(package)),
            capture_output=True,
            text=True,
        )
        assert run.returncode == 0 and "(columnar path)" in run.stderr, run.stderr
    else:
        assert mod.cli.main(args) == 0
    want = canonical(package, data)
    cols = mod._columns
    set_ids = {v: k for k, v in mod.registry.SET_NAMES.items()}
    checked = 0
    tables = sorted((out / fmt).iterdir())
    assert tables, "no table written"
    seen = set()
    for path in tables:
        parts = path.stem.split(".")
        sid = set_ids[parts[0]]
        home = mod.registry.SHARED_SET if parts[1] == "shared" else sid
        field = parts[2] if parts[1] == "shared" else parts[1]
        device = parts[-1] if len(parts) > (3 if parts[1] == "shared" else 2) else None
        key = next(
            k for k in cols.COLUMNS if k[0] == home and k[2] == device and mod.registry.FIELDS[k[:2]][0].NAME == field
        )
        specs = cols.COLUMNS[key]
        headers, rows = read_table(path)
        assert headers[:3] == ["t_ns", "time", "offset"]
        entries = want[(sid, key[1])]
        seen.add((sid, key[1]))
        assert len(rows) == len(entries), path.name
        for header, spec in zip(headers[3:], specs):
            assert header == (f"{spec[0]} [{spec[2]}]" if spec[2] else spec[0])
        for row, (offset, values) in zip(rows, entries):
            assert int(row[2]) == offset
            for cell, (name, path_, _units, kind, enum) in zip(row[3:], specs):
                names = None if enum_numbers or kind != "enum" else {int(k): v for k, v in cols.ENUMS[enum].items()}
                assert same(kind, cell, walk(values, path_), names), (
                    path.name,
                    offset,
                    name,
                    cell,
                    walk(values, path_),
                )
                checked += 1
    # Every decoded field of a data set has its table.
    data_sets = {k[0] for k in cols.COLUMNS}
    assert {k for k in want if k[0] in data_sets} == seen
    return checked


@pytest.mark.parametrize("fmt", ["csv", "jsonl", "parquet"])
@pytest.mark.parametrize("protocol", sorted(PACKAGES))
def test_golden_vectors_export_equals_canonical_decode(tmp_path, protocol, fmt):
    package = PACKAGES[protocol]
    data = vector_stream(protocol)
    assert check_export(package, data, tmp_path, fmt, enum_numbers=(fmt == "jsonl")) > (
        400 if protocol == "mip" else 50
    )


def test_every_layout_kind_is_exported():
    """The golden vectors of the two protocols reach every column kind the data fields have."""
    kinds, reached = set(), set()
    for protocol, package in PACKAGES.items():
        mod = pkg(package)
        want = canonical(package, vector_stream(protocol))
        shared = mod.registry.SHARED_SET
        for key, specs in mod._columns.COLUMNS.items():
            kinds |= {s[3] for s in specs}
            if any(k[1] == key[1] and (k[0] == key[0] or key[0] == shared) for k in want):
                reached |= {s[3] for s in specs}
    assert reached == kinds >= {"float32", "float64", "int", "enum", "bits", "bool"}


@pytest.mark.parametrize("fmt", ["csv", "parquet"])
@pytest.mark.parametrize("protocol", sorted(PACKAGES))
def test_golden_vectors_columnar_export_equals_canonical_decode(tmp_path, protocol, fmt):
    """The columnar path (C accelerator, numpy, pyarrow) gives the same values."""
    package = PACKAGES[protocol]
    data = vector_stream(protocol)
    assert check_export(package, data, tmp_path, fmt, enum_numbers=(fmt == "csv"), accelerated=True) > 50


@pytest.mark.skipif(not CAPTURE.exists(), reason="device capture absent (the golden-vector tests cover export)")
@pytest.mark.parametrize("fmt", ["csv", "parquet"])
def test_device_capture_export_equals_canonical_decode(tmp_path, fmt):
    data = CAPTURE.read_bytes()
    assert check_export("mipcodec", data, tmp_path, fmt, enum_numbers=False, accelerated=(fmt == "csv")) > 40000
    headers, rows = read_table(tmp_path / fmt / f"sensor.scaled_accel.{fmt}")
    assert headers == ["t_ns", "time", "offset", "scaled_accel.x [g]", "scaled_accel.y [g]", "scaled_accel.z [g]"]
    # the capture has a device clock and no GPS time: no UTC time (t_ns and time empty / null)
    assert all(r[0] in ("", None) and r[1] in ("", None) for r in rows)


def test_join_one_row_per_sample(tmp_path):
    """--join: one table per set, a row per sample (continuation packets share a timestamp)."""
    mod = pkg("mipcodec")
    b = mod.codec.framing.PacketBuilder
    ts = mod.shared.ReferenceTimestamp(nanoseconds=5_000_000_000).encode()
    accel = mod.sensor.ScaledAccel(scaled_accel=[1.0, 2.0, 3.0]).encode()
    gyro = mod.sensor.ScaledGyro(scaled_gyro=[0.5, 0.25, 0.125]).encode()
    p1 = b(0x80).add_field(0xD5, ts).add_field(0x04, accel).build()
    p2 = b(0x80).add_field(0xD5, ts).add_field(0x05, gyro).build()  # continuation: same timestamp
    ts2 = mod.shared.ReferenceTimestamp(nanoseconds=5_010_000_000).encode()
    p3 = b(0x80).add_field(0xD5, ts2).add_field(0x04, accel).build()
    (tmp_path / "log.bin").write_bytes(p1 + p2 + p3)
    assert mod.cli.main(["export", str(tmp_path / "log.bin"), "--out", str(tmp_path / "o"), "--join"]) == 0
    headers, rows = read_table(tmp_path / "o" / "sensor.csv")
    assert headers[:4] == ["t_ns", "time", "offset", "reference_timestamp.nanoseconds [ns]"]
    assert len(rows) == 2
    row = dict(zip(headers, rows[0]))
    assert row["t_ns"] == "" and row["scaled_accel.y [g]"] == "2.0" and row["scaled_gyro.z [rad/s]"] == "0.125"
    assert dict(zip(headers, rows[1]))["scaled_gyro.z [rad/s]"] == ""


def test_fields_enum_names_stdin(tmp_path, monkeypatch):
    mod = pkg("mipcodec")
    data = vector_stream("mip")
    out = tmp_path / "o"
    monkeypatch.setattr("sys.stdin", io.TextIOWrapper(io.BytesIO(data)))
    assert mod.cli.main(["export", "-", "--out", str(out), "--fields", "scaled_accel.z,gps_timestamp"]) == 0
    names = sorted(p.name for p in out.iterdir())
    assert "sensor.scaled_accel.csv" in names and "sensor.shared.gps_timestamp.csv" in names
    assert all(n.split(".")[-2] in ("scaled_accel", "gps_timestamp") for n in names), names
    headers, _rows = read_table(out / "sensor.scaled_accel.csv")
    assert headers == ["t_ns", "time", "offset", "scaled_accel.z [g]"]


def test_enum_names_come_from_the_spec():
    mod = pkg("mipcodec")
    proto = next(p for p in IR["protocols"] if p["package"] == "mipcodec")
    for t in proto["types"]:
        if t["kind"] == "enum" and t["name"] in mod._columns.ENUMS:
            for v in t["values"]:
                assert mod._columns.ENUMS[t["name"]][v["value"]] in {
                    w["name"] for w in t["values"] if w["value"] == v["value"]
                }


def test_follow_a_growing_file(tmp_path):
    """--follow reads what is appended; --idle ends it after that many quiet seconds."""
    import threading
    import time

    mod = pkg("mipcodec")
    ts = lambda n: mod.shared.ReferenceTimestamp(nanoseconds=n).encode()  # noqa: E731
    accel = mod.sensor.ScaledAccel(scaled_accel=[1.0, 2.0, 3.0]).encode()
    pkt = lambda n: mod.codec.framing.PacketBuilder(0x80).add_field(0xD5, ts(n)).add_field(0x04, accel).build()  # noqa: E731
    log = tmp_path / "grow.bin"
    log.write_bytes(pkt(1))

    def grow():
        time.sleep(0.3)
        with log.open("ab") as fh:
            fh.write(pkt(2) + pkt(3)[:10])
            fh.flush()
            time.sleep(0.3)
            fh.write(pkt(3)[10:])

    th = threading.Thread(target=grow)
    th.start()
    assert mod.cli.main(["export", str(log), "--out", str(tmp_path / "o"), "--follow", "--idle", "1.0"]) == 0
    th.join()
    _h, rows = read_table(tmp_path / "o" / "sensor.scaled_accel.csv")
    n = len(pkt(1))
    assert [r[2] for r in rows] == [str(0), str(n), str(2 * n)]  # each packet once, the cut one whole


def gap_stream(mod) -> tuple[bytes, dict]:
    """100 Hz accel samples, samples 20-22 and 50 missing, 5 garbage bytes, one bad checksum."""
    b = mod.codec.framing.PacketBuilder
    accel = mod.sensor.ScaledAccel(scaled_accel=[0.0, 0.0, -1.0]).encode()
    out = bytearray()
    n = 0
    for i in range(100):
        if i in (20, 21, 22, 50):
            continue
        out += (
            b(0x80)
            .add_field(0xD5, mod.shared.ReferenceTimestamp(nanoseconds=1_000_000_000 + i * 10_000_000).encode())
            .add_field(0x04, accel)
            .build()
        )
        n += 1
        if i == 10:
            out += b"\x00\x01\x02\x03\x04"
        if i == 60:
            bad = bytearray(b(0x80).add_field(0x04, accel).build())
            bad[-1] ^= 0xFF
            out += bad
    return bytes(out), {"packets": n, "skipped": 5 + 20}


def test_info_on_a_stream_with_known_gaps(tmp_path, capsys):
    mod = pkg("mipcodec")
    data, facts = gap_stream(mod)
    (tmp_path / "gaps.bin").write_bytes(data)
    assert mod.cli.main(["info", str(tmp_path / "gaps.bin")]) == 0
    text = capsys.readouterr().out
    assert f"packets: {facts['packets']}" in text
    assert f"skipped bytes: {facts['skipped']} in 2 runs" in text
    assert "bad checksums: 1" in text
    assert "device clock: first 1.000000 s  last 1.990000 s  span 0.990000 s" in text
    line = next(x for x in text.splitlines() if "scaled_accel" in x)
    assert line.split()[2] == str(facts["packets"])
    assert "100.000 Hz" in line and "gaps 2" in line and "dropped 4" in line


def test_plot_writes_a_labelled_image(tmp_path):
    import matplotlib.image

    mod = pkg("mipcodec")
    data, _ = gap_stream(mod)
    log = tmp_path / "gaps.bin"
    log.write_bytes(data)
    fig = mod.logs.plot.figure(str(log), ["scaled_accel"])
    ax = fig.axes[0]
    assert ax.get_xlabel() == "packet offset [bytes]" and ax.get_ylabel() == "g"  # no UTC time in it
    assert [line.get_label() for line in ax.lines] == ["scaled_accel.x", "scaled_accel.y", "scaled_accel.z"]
    assert len(ax.lines[2].get_xdata()) == 96
    for ext in ("png", "svg", "html"):
        assert mod.cli.main(["plot", str(log), "--fields", "scaled_accel", "--out", str(tmp_path / f"p.{ext}")]) == 0
    img = matplotlib.image.imread(tmp_path / "p.png")
    assert img.shape[0] > 200 and img.shape[1] > 400
    assert np.unique(img.reshape(-1, img.shape[2]), axis=0).shape[0] > 10  # not a blank image
    assert "<svg" in (tmp_path / "p.svg").read_text() and "<svg" in (tmp_path / "p.html").read_text()


def test_usage_errors_are_one_line(tmp_path, capsys):
    mod = pkg("mipcodec")
    assert mod.cli.main(["export", str(tmp_path / "missing.bin"), "--out", str(tmp_path)]) == 2
    assert "cannot open" in capsys.readouterr().err
    (tmp_path / "x.bin").write_bytes(b"")
    assert mod.cli.main(["export", str(tmp_path / "x.bin"), "--out", str(tmp_path), "--fields", "nope"]) == 2
    assert "no column named 'nope'" in capsys.readouterr().err
    assert (
        mod.cli.main(["plot", str(tmp_path / "x.bin"), "--fields", "scaled_accel", "--out", str(tmp_path / "a.jpg")])
        == 2
    )
    with pytest.raises(SystemExit) as e:
        mod.cli.main(["export", "--help"])
    assert e.value.code == 0
    assert "--format" in capsys.readouterr().out


def test_missing_extra_is_named(monkeypatch):
    import builtins

    mod = pkg("mipcodec")
    real = builtins.__import__

    def fake(name, *a, **k):
        if name.startswith("pyarrow"):
            raise ImportError(name)
        return real(name, *a, **k)

    monkeypatch.setattr(builtins, "__import__", fake)
    monkeypatch.delitem(__import__("sys").modules, "pyarrow", raising=False)
    with pytest.raises(mod.logs.writers.ToolError, match=r"pip install 'mipcodec\[export\]'"):
        mod.logs.writers.need("pyarrow")


ARRAYS_CHECK = """
import sys, numpy as np, mipcodec
assert mipcodec.ACCELERATED
cols = mipcodec.decode_columns(open(sys.argv[1], "rb").read())
shapes = {}
for key, t in cols.tables.items():
    for attr, a in t.arrays().items():
        shapes[attr] = a.shape
        for i in range(t.rows):
            assert np.array_equal(np.asarray(getattr(t.row(i), attr), dtype=a.dtype).reshape(a[i].shape), a[i]), (key, attr, i)
assert shapes["scaled_accel"][1:] == (3,), shapes
assert shapes["dcm"][1:] == (3, 3), shapes
q = cols.tables[(0x80, 0x0A)].arrays()["q"]  # the complementary filter's quaternion
assert q.shape == (cols.tables[(0x80, 0x0A)].rows, 4) and q.dtype == np.float64, q.shape
m = cols.tables[(0x80, 0x09)].arrays()["m"]  # its orientation matrix, row-major
assert m.shape[1:] == (3, 3) and m[0, 0, 1] == cols.tables[(0x80, 0x09)].row(0).m[1], m.shape
df = cols.tables[(0x80, 0x04)].dataframe()
assert list(df.columns) == ["offset", "scaled_accel.x", "scaled_accel.y", "scaled_accel.z"], list(df.columns)
assert df["scaled_accel.y"].tolist() == cols.tables[(0x80, 0x04)].arrays()["scaled_accel"][:, 1].tolist()
print(len(cols.tables))
"""


def test_table_arrays_shaped_by_the_spec(tmp_path):
    """decode_columns tables as numpy arrays shaped by the spec (vectors n x 3) and as a DataFrame,
    equal to the typed rows; run with the C accelerator (the tables are its output)."""
    where = ext_build("mipcodec")
    log = tmp_path / "v.bin"
    log.write_bytes(vector_stream("mip"))
    run = subprocess.run(
        [sys.executable, "-c", ARRAYS_CHECK, str(log)],
        env=dict(os.environ, PYTHONPATH=where),
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    assert int(run.stdout) > 20
