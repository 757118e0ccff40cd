"""One pipeline for the log tools (runtime logs/pipeline.py, issue 50 items 1, 2 and 6): the log's
device, its UTC time and the dataset's readers, on a small simulated fleet (docs/fleet.md: device
0 a 3DM-GX5-45, device 1 a 3DM-CV7-GNSS/INS; 20 s each, made once for the module).

Expected values come from the fleet's manifest (computed from the simulation's parameters, never
by decoding) and from the spec: the CV7's filter states (`ahrs`, `full_nav`) are its own layout's
enum names, which the GX5-45's layout does not have (it names the same numbers
`run_solution_error`, `4`, issue 50)."""

from __future__ import annotations

import csv
import importlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.export.test_export import ext_build
from tests.helpers.generated import GENERATED_PYTHON, python_package

pkg = python_package("mipcodec")
fleet = importlib.import_module("mipcodec.fleet")
framing = importlib.import_module("mipcodec.codec.framing")

GENERATED = str(GENERATED_PYTHON / "mipcodec")
SECONDS = 20
# Filter states of each device's own layout (spec/mip: the GX5-45's and the CV7's filter status).
# (the GX5-45's FilterStateGx5, the CV7's FilterModeCv7), and the states each fleet log reaches.
STATES = {
    "gx5_45": {"startup", "init", "run_solution_valid", "run_solution_error"},
    "cv7_ins": {"init", "vert_gyro", "ahrs", "full_nav"},
}
REACHED = {"gx5_45": {"run_solution_valid"}, "cv7_ins": {"ahrs", "full_nav"}}


@pytest.fixture(scope="module")
def logs(tmp_path_factory) -> dict:
    out = tmp_path_factory.mktemp("fleet")
    fleet.generate(str(out), devices=2, hours=SECONDS / 3600, seed=3)
    manifest = json.loads((out / "fleet.json").read_text())
    found = {d["model"]: out / d["log"] for d in manifest["devices"]}
    assert set(found) == {"gx5_45", "cv7_ins"}
    # the CV7 log without its Device Information reply: the device is unknown
    data = found["cv7_ins"].read_bytes()
    kept = [
        bytes(e.data)
        for e in framing.Parser().feed(data)
        if not (isinstance(e, framing.RawPacket) and e.data[2] == 0x01)
    ]
    (out / "cv7-noid.mip").write_bytes(b"".join(kept))
    found["cv7-noid"] = out / "cv7-noid.mip"
    return found


def tool(*args: str, mode: str = "columnar", cwd=None) -> subprocess.CompletedProcess:
    """python -m mipcodec ARGS on a path: columnar (C accelerator), packets (accelerator, packet
    path) or pure (MIPCODEC_PURE=1, no accelerator)."""
    env = dict(os.environ)
    env.pop("MIPCODEC_EXPORT_SLOW", None)
    env.pop("MIPCODEC_PURE", None)
    env["PYTHONPATH"] = GENERATED if mode == "pure" else ext_build("mipcodec")
    if mode == "packets":
        env["MIPCODEC_EXPORT_SLOW"] = "1"
    if mode == "pure":
        env["MIPCODEC_PURE"] = "1"
    return subprocess.run([sys.executable, "-m", "mipcodec", *args], env=env, capture_output=True, text=True, cwd=cwd)


def rows(path: Path) -> list:
    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


MODES = ["columnar", "packets", "pure"]
REFERENCE: dict = {}


@pytest.mark.parametrize("mode", MODES)
def test_each_device_exports_with_its_own_layouts(tmp_path, logs, mode):
    """Both devices on every path: the per-device table is the log's device's, its states its
    own; the three paths write the same bytes (compared with the columnar path's)."""
    for model in ("gx5_45", "cv7_ins"):
        out = tmp_path / model
        run = tool("export", str(logs[model]), "--out", str(out), mode=mode)
        assert run.returncode == 0, run.stderr
        names = sorted(p.name for p in out.iterdir())
        assert f"filter_data.filter_status.{model}.csv" in names
        assert not [n for n in names if n.startswith("filter_data.filter_status.") and model not in n], names
        states = {r["filter_status.filter_state"] for r in rows(out / f"filter_data.filter_status.{model}.csv")}
        assert REACHED[model] <= states <= STATES[model], states
        if mode == "columnar":
            REFERENCE[model] = out
        else:
            ref = REFERENCE[model]  # the columnar path's tables (its case runs first)
            assert sorted(p.name for p in ref.iterdir()) == names
            for name in names:
                assert (out / name).read_bytes() == (ref / name).read_bytes(), (mode, name)


@pytest.mark.parametrize("mode", MODES)
def test_unknown_or_contradicted_device_is_one_error_line(tmp_path, logs, mode):
    run = tool("export", str(logs["cv7-noid"]), "--out", str(tmp_path / "a"), mode=mode)
    assert run.returncode == 2 and run.stderr.count("\n") == 1, run.stderr
    assert "device is unknown" in run.stderr and "filter_data.filter_status" in run.stderr
    assert not list((tmp_path / "a").iterdir())  # nothing half written
    run = tool("export", str(logs["cv7_ins"]), "--out", str(tmp_path / "b"), "--device", "gx5_45", mode=mode)
    assert run.returncode == 2 and "contradicts the log's Device Information reply" in run.stderr, run.stderr
    # --device names the device of a log without a reply
    run = tool("export", str(logs["cv7-noid"]), "--out", str(tmp_path / "c"), "--device", "cv7_ins", mode=mode)
    assert run.returncode == 0, run.stderr
    states = {r["filter_status.filter_state"] for r in rows(tmp_path / "c" / "filter_data.filter_status.cv7_ins.csv")}
    assert states >= {"ahrs", "full_nav"}


def test_export_and_dataset_have_the_same_timed_rows(tmp_path, logs):
    """For each log of the fleet: every table's rows with a known UTC time are the same (count
    and t_ns) in `export` and in `export --dataset`; the export's `time` is its t_ns in UTC."""
    pq = pytest.importorskip("pyarrow.parquet")
    from mipcodec.logs import timebase

    ds = tmp_path / "ds"
    run = tool("export", "--dataset", str(ds), str(logs["gx5_45"]), str(logs["cv7_ins"]))
    assert run.returncode == 0, run.stderr
    for model in ("gx5_45", "cv7_ins"):
        out = tmp_path / model
        assert tool("export", str(logs[model]), "--out", str(out)).returncode == 0
        serial = "6232-10100" if model == "gx5_45" else "6284.170401"
        compared = 0
        for path in sorted(out.iterdir()):
            table = rows(path)
            exported = sorted(int(r["t_ns"]) for r in table if r["t_ns"])
            for r in table[:50]:
                assert (r["time"] == "") == (r["t_ns"] == "")
                if r["t_ns"]:
                    assert r["time"] == timebase.iso(int(r["t_ns"]))
            parts = sorted((ds / path.stem).glob(f"model=*/serial={serial}/date=*/*.parquet"))
            assert parts, path.stem
            t = [v for p in parts for v in pq.read_table(p, columns=["t_ns"]).column("t_ns").to_pylist()]
            assert exported == sorted(v for v in t if v is not None), path.name
            compared += len(exported)
        assert compared > 50 * SECONDS  # the 50 Hz and 100 Hz tables' timed rows


def test_info_reports_each_clock(logs):
    """info: the device from the reply, then a line per clock; the CV7's 20 s log spans 20 s on
    every clock (its GPS time crosses the week's end at UTC midnight: not 604,799 s)."""
    for model in ("gx5_45", "cv7_ins"):
        run = tool("info", str(logs[model]))
        assert run.returncode == 0, run.stderr
        lines = run.stdout.splitlines()
        assert lines[1].startswith(f"device: {model} (model 3dm-"), lines[1]
        clock = next(x for x in lines if x.startswith("device clock:"))
        gps = next(x for x in lines if x.startswith("GPS time:"))
        utc = next(x for x in lines if x.startswith("UTC:"))
        # GPS time is valid from the first fix (2 s) on; the CV7's device clock runs from 0
        assert f"span {SECONDS - 2}.000000 s" in gps, gps
        # UTC: the CV7's device clock times its first 2 s through the first anchor; the GX5-45's not
        assert f"span {SECONDS if model == 'cv7_ins' else SECONDS - 2}.000000 s" in utc, utc
        if model == "cv7_ins":
            assert f"first 0.000000 s  last {SECONDS}.000000 s  span {SECONDS}.000000 s" in clock, clock
        else:
            assert clock.startswith("device clock: none of"), clock  # the GX5-45's fleet log has none
    run = tool("info", str(logs["cv7-noid"]))
    assert run.returncode == 0 and run.stdout.splitlines()[1].startswith("device: unknown"), run.stdout


def test_plot_uses_utc(logs):
    tools = importlib.import_module("mipcodec.logs.plot")
    fig = tools.figure(str(logs["gx5_45"]), ["scaled_accel"])
    assert fig.axes[-1].get_xlabel() == "time (UTC)"
    assert str(fig.axes[-1].lines[0].get_xdata()[0]).startswith("2026-03-14T09:14:02")  # its first UTC time


def test_dataset_of_a_log_of_unknown_device_is_unreadable(tmp_path, logs):
    ds = tmp_path / "ds"
    run = tool("export", "--dataset", str(ds), str(logs["cv7-noid"]))
    assert run.returncode == 0 and "unreadable (" in run.stdout and "device is unknown" in run.stdout, run.stdout
    run = tool("export", "--dataset", str(ds), str(logs["cv7-noid"]), "--model", "cv7_ins")
    assert run.returncode == 0 and "unreadable" not in run.stdout, run.stdout
    assert list(ds.glob("filter_data.filter_status.cv7_ins/model=cv7_ins/*/*/*.parquet"))


@pytest.fixture(scope="module")
def capture_dataset(tmp_path_factory) -> Path:
    """The dataset of a log without GPS time (the device capture, else a fleet-like log without
    any: the capture's shape, a device clock only): every row's date is unknown."""
    capture = Path(__file__).resolve().parents[2].parent / "shared" / "captures" / "mip_data.bin"
    out = tmp_path_factory.mktemp("capds")
    mod = pkg
    if capture.exists():
        log = capture
    else:
        ts = lambda n: mod.shared.ReferenceTimestamp(nanoseconds=n).encode()  # noqa: E731
        accel = mod.sensor.ScaledAccel(scaled_accel=[1.0, 2.0, 3.0]).encode()
        log = out / "clock-only.bin"
        log.write_bytes(
            b"".join(
                mod.PacketBuilder(0x80).add_field(0xD5, ts(k * 10**7)).add_field(0x04, accel).build()
                for k in range(200)
            )
        )
    run = tool("export", "--dataset", str(out / "ds"), str(log))
    assert run.returncode == 0, run.stderr
    parts = list((out / "ds" / "sensor.scaled_accel").rglob("*.parquet"))
    assert parts and all("date=unknown" in str(p) for p in parts)
    return out / "ds" / "sensor.scaled_accel"


def test_dataset_without_dates_opens_with_pyarrow_polars_duckdb(capture_dataset):
    import duckdb
    import polars
    import pyarrow.dataset as pads

    n = pads.dataset(str(capture_dataset), format="parquet", partitioning="hive").to_table().num_rows
    assert n > 100
    lf = polars.scan_parquet(str(capture_dataset / "**" / "*.parquet"), hive_partitioning=True)
    got = lf.select(polars.len(), polars.col("date").first()).collect()
    assert got.row(0) == (n, "unknown")
    pattern = str(capture_dataset / "**" / "*.parquet")
    assert duckdb.sql(
        f"SELECT count(*), any_value(date) FROM read_parquet('{pattern}', hive_partitioning=true)"
    ).fetchone() == (
        n,
        "unknown",
    )
