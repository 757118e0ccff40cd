"""The Spark job (`python -m mipcodec.spark`, generator/targets/python/runtime/spark.py) against the
single-machine `export --dataset`: on simulated logs (two devices, a corrupt one, a truncated one,
an empty one, a missing path) and the device capture, split small enough that split boundaries cut
packets, both write the same part files with the same rows and values, compared through DuckDB
(every table, EXCEPT ALL both ways, and the files' key-value metadata).

Exactly once across split boundaries is checked against the whole-log decode, not against the
other engine: the packets `_files` counts for a log are the packets `decode_all` finds in it
unsplit. Spark runs in local mode (`local[2]`, loopback only, no UI); one session serves the
module (starting one takes 5-30 s). pyspark and Java come from tools/bootstrap.
"""

from __future__ import annotations

import json
import os
import random
import re
import subprocess
import sys
from pathlib import Path

import duckdb
import pytest

from tests.export.test_pipeline import capture_dataset  # noqa: F401 (a fixture: the dataset of a log without dates)
from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
CAPTURE = Path(os.environ.get("CAPTURE", ROOT.parent / "shared" / "captures" / "mip_data.bin"))
PKG_DIR = ROOT / "generated" / "python" / "mipcodec"
SPLIT = 50_000  # bytes per split: a packet is at most 261 bytes, so boundaries cut packets


def mip():
    mod = python_package("mipcodec")
    for sub in ("logs.dataset", "spark", "fleet", "codec.packets", "_protocol"):
        __import__(f"mipcodec.{sub}")
    return mod


@pytest.fixture(scope="module")
def logs(tmp_path_factory) -> list:
    """The logs, as paths: a simulated fleet (`mipcodec.fleet`: two GX5-45 and two CV7-INS, one log
    across UTC midnight, GNSS outages, garbage between packets, the last one truncated), one of
    its logs with two 300-byte runs of garbage inserted, an empty file, the device capture when
    it is there, and a missing path."""
    m = mip()
    d = tmp_path_factory.mktemp("logs")
    manifest = m.fleet.generate(str(d / "fleet"), devices=4, seed=0, size=1)  # the shortest logs (10 s)
    paths = [str(d / "fleet" / e["log"]) for e in manifest["devices"]]
    rng = random.Random(7)
    corrupt = bytearray(Path(paths[1]).read_bytes())
    for at in (len(corrupt) // 3, 2 * len(corrupt) // 3):
        corrupt[at:at] = bytes(rng.randrange(256) for _ in range(300))
    (d / "corrupt.bin").write_bytes(bytes(corrupt))
    (d / "empty.bin").write_bytes(b"")
    paths += [str(d / "corrupt.bin"), str(d / "empty.bin")]
    if CAPTURE.exists():
        paths.append(str(CAPTURE))
    paths.append(str(d / "missing.bin"))
    return paths


@pytest.fixture(scope="module")
def spark():
    try:
        import pyspark  # noqa: F401
    except ImportError:
        pytest.fail("pyspark is not installed: run tools/bootstrap (it installs requirements-spark.txt into .venv)")
    mip()
    # the Python workers import the generated package from the source tree
    os.environ["PYTHONPATH"] = os.pathsep.join([str(PKG_DIR), str(ROOT), os.environ.get("PYTHONPATH", "")])
    conf = {
        "spark.driver.memory": "512m",
        "spark.sql.shuffle.partitions": "2",
        "spark.python.worker.memory": "256m",
    }
    session = sys.modules["mipcodec.spark"].session("local[2]", conf)
    yield session
    session.stop()


@pytest.fixture(scope="module")
def datasets(tmp_path_factory, logs, spark):
    """(the Spark job's dataset, export --dataset's dataset) of the logs, and the Spark summary.
    Phase 1 takes at most two splits per task here, so a log's anchors come from several tasks,
    and the Spark job decodes each split in windows of 20,000 bytes (the driver sets them), the
    local export in one window per split."""
    m = mip()
    out = tmp_path_factory.mktemp("out")
    spark_dir, local_dir = out / "spark", out / "local"
    phase1, window = m.spark.PHASE1_BYTES, m.logs.dataset.WINDOW_BYTES
    m.spark.PHASE1_BYTES, m.logs.dataset.WINDOW_BYTES = 2 * SPLIT, 20_000
    try:
        summary = m.spark.export_dataset(spark, logs, str(spark_dir), split_bytes=SPLIT)
    finally:
        m.spark.PHASE1_BYTES, m.logs.dataset.WINDOW_BYTES = phase1, window
    m.logs.dataset.export_dataset(logs, str(local_dir), split_bytes=SPLIT)
    return spark_dir, local_dir, summary


def files(root: Path) -> list:
    """The dataset's visible files (what Spark, DuckDB and pyarrow read), relative."""
    out = []
    for dirpath, dirs, names in os.walk(root):
        dirs[:] = [x for x in dirs if not x.startswith((".", "_")) or x == "_files"]
        out += [os.path.relpath(os.path.join(dirpath, n), root) for n in names if not n.startswith((".", "_"))]
    return sorted(out)


def tables(root: Path) -> list:
    return sorted(p.name for p in root.iterdir() if p.is_dir() and not p.name.startswith("."))


def test_phase1_groups_are_runs_of_splits_within_the_limit():
    groups = mip().spark.phase1_groups
    grid = [(0, 100), (100, 200), (200, 300), (300, 350)]
    assert groups(grid, 200) == [[(0, 100), (100, 200)], [(200, 300), (300, 350)]]
    assert groups(grid, 250) == [[(0, 100), (100, 200)], [(200, 300), (300, 350)]]
    assert groups(grid, 99) == [[(0, 100)], [(100, 200)], [(200, 300)], [(300, 350)]]  # one split each at least
    assert groups(grid, 10**9) == [grid]
    assert groups([], 200) == [[]]  # an empty log: one task (its id and identity), no split


def test_same_file_names(datasets):
    spark_dir, local_dir, _ = datasets
    assert tables(spark_dir) == tables(local_dir)
    assert files(spark_dir) == files(local_dir)
    assert len(files(spark_dir)) > 100
    assert not [f for f in os.listdir(spark_dir) if f.startswith(".")]  # no temporary file left


def test_same_rows_and_values_through_duckdb(datasets):
    """Every table, rows as multisets: A EXCEPT ALL B and B EXCEPT ALL A are empty, with the
    partition columns (model, serial, date) read from the paths as a reader sees them."""
    spark_dir, local_dir, _ = datasets
    con = duckdb.connect()
    total = 0
    for table in tables(local_dir):

        def scan(root: Path, table: str = table) -> str:
            glob = str(root / table / "**" / "*.parquet")
            return f"read_parquet('{glob}', hive_partitioning = true, union_by_name = true)"

        con.execute(f"CREATE OR REPLACE TEMP TABLE a AS SELECT * FROM {scan(spark_dir)}")
        con.execute(f"CREATE OR REPLACE TEMP TABLE b AS SELECT * FROM {scan(local_dir)}")
        a, b = "a", "b"
        n_a = con.execute("SELECT count(*) FROM a").fetchone()[0]
        assert n_a == con.execute("SELECT count(*) FROM b").fetchone()[0], table
        for x, y in ((a, b), (b, a)):
            diff = con.execute(f"SELECT count(*) FROM (SELECT * FROM {x} EXCEPT ALL SELECT * FROM {y})").fetchone()[0]
            assert diff == 0, f"{table}: {diff} rows of one dataset are not in the other"
        total += n_a
    assert total > 10_000
    # the files' key-value metadata (spec hash, model, serial, firmware, log, split, Arrow schema)
    meta = "SELECT replace(file_name, '{root}', '') AS f, key, value FROM parquet_kv_metadata('{root}/**/*.parquet')"
    for x, y in ((spark_dir, local_dir), (local_dir, spark_dir)):
        q = f"SELECT count(*) FROM ({meta.format(root=x)} EXCEPT ALL {meta.format(root=y)})"
        assert con.execute(q).fetchone()[0] == 0


def test_files_table(datasets, logs):
    """_files: one row per log with the statuses the logs were made to have; packets counted
    exactly once across split boundaries (the whole-log decode's packets)."""
    m = mip()
    spark_dir, _, summary = datasets
    con = duckdb.connect()
    rows = con.execute(
        f"SELECT path, status, packets, skipped_bytes, bytes, error FROM read_parquet('{spark_dir}/_files/*.parquet')"
    ).fetchall()
    by_name = {os.path.basename(r[0]): r for r in rows}
    assert len(rows) == len(logs)
    assert by_name["missing.bin"][1] == "unreadable" and by_name["missing.bin"][5]
    assert by_name["corrupt.bin"][1] == "corrupt" and by_name["corrupt.bin"][3] >= 600
    assert by_name["empty.bin"][1:3] == ("ok", 0)
    manifest = json.loads((Path(logs[0]).parent / "fleet.json").read_text())
    for e in manifest["devices"]:
        path, status, _packets, skipped, size, _error = by_name[e["log"]]
        assert size == e["bytes"]
        if e["truncated"]:
            assert status == "truncated"
        else:  # the fleet's garbage never holds a sync byte: skipped exactly
            assert (status, skipped) == ("corrupt" if e["garbage_bytes"] else "ok", e["garbage_bytes"])
    cut = boundaries = 0
    for path in logs:
        if not os.path.exists(path):
            continue
        data = Path(path).read_bytes()
        boundaries += max(0, (len(data) - 1) // SPLIT)  # the split starts after the first
        packets = [e for e in m.codec.packets.decode_all(data) if isinstance(e, m.codec.packets.Packet)]
        assert by_name[os.path.basename(path)][2] == len(packets), path
        proto = m._protocol
        for p in packets:
            last = p.offset + proto.HEADER_SIZE + data[p.offset + proto.LENGTH_OFFSET] + proto.CHECKSUM_SIZE - 1
            cut += p.offset // SPLIT != last // SPLIT
    # split boundaries did cut packets: most boundaries fall inside one (a packet starts on a
    # boundary only by chance, and the fleet's garbage is short), whether or not the device capture
    # is there (without it: 8 packets cut at 8 boundaries)
    assert boundaries >= 4 and cut >= boundaries // 2, (cut, boundaries)
    assert {r["path"] for r in summary.logs} == set(logs)  # paths as given


def test_cli_errors_are_one_line(tmp_path):
    """Bad options and a missing Java are one line on stderr (no traceback), exit status 2."""
    env = {**os.environ, "PYTHONPATH": str(PKG_DIR)}

    def run(*args, **extra):
        return subprocess.run(
            [sys.executable, "-m", "mipcodec.spark", *args],
            capture_output=True,
            text=True,
            env={**env, **extra},
            timeout=120,
        )

    r = run(str(CAPTURE), "--out", str(tmp_path / "d"), "--split-bytes", "0")
    assert r.returncode == 2 and "needs an integer > 0" in r.stderr and "Traceback" not in r.stderr
    r = run(str(CAPTURE))
    assert r.returncode == 2 and "--out" in r.stderr and "Traceback" not in r.stderr
    r = run(str(CAPTURE), "--out", str(tmp_path / "d"), "--conf", "novalue")
    assert r.returncode == 2 and r.stderr.strip() == "mipcodec.spark: --conf needs KEY=VALUE, not 'novalue'"
    r = run(str(CAPTURE), "--out", str(tmp_path / "d"), JAVA_HOME=str(tmp_path / "nojava"))
    assert r.returncode == 2
    assert r.stderr.strip().splitlines() == [
        f"mipcodec.spark: Spark needs a Java 17 or 21 runtime: JAVA_HOME={tmp_path / 'nojava'} has no bin/java "
        "(Debian: apt-get install openjdk-17-jre-headless)"
    ]


def test_cli_without_pyspark(tmp_path):
    """Without pyspark: the one line naming the extra that installs it."""
    code = (
        "import runpy, sys; sys.modules['pyspark'] = None; "
        f"sys.argv = ['spark', 'x.bin', '--out', {str(tmp_path / 'd')!r}]; "
        "runpy.run_module('mipcodec.spark', run_name='__main__')"
    )
    env = {**os.environ, "PYTHONPATH": str(PKG_DIR)}
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)
    assert r.returncode == 2
    assert r.stderr.strip().splitlines() == [
        "mipcodec.spark: pyspark is not installed: pip install 'mipcodec[spark]' (or pip install pyspark)"
    ]


def test_cli_replaces_a_logs_parts(tmp_path, logs):
    """`python -m mipcodec.spark` on a log: exit 0, its line on stdout, its part files, and a stale
    part of the same log (an earlier run's) removed: re-running replaces, never duplicates."""
    m = mip()
    out = tmp_path / "ds"
    path = logs[0]  # the fleet's first GX5-45
    log = m.logs.dataset.log_id(path)
    stale = out / "sensor.scaled_accel" / "model=x" / "serial=y" / "date=z" / f"part-{log}-ffffffffffff.parquet"
    stale.parent.mkdir(parents=True)
    stale.write_bytes(b"old")
    env = {**os.environ, "PYTHONPATH": str(PKG_DIR)}
    r = subprocess.run(
        [sys.executable, "-m", "mipcodec.spark", path, "--out", str(out), "--master", "local[1]"],
        capture_output=True,
        text=True,
        env=env,
        timeout=600,
    )
    assert r.returncode == 0, r.stderr
    assert "Traceback" not in r.stderr
    garbage = json.loads((Path(path).parent / "fleet.json").read_text())["devices"][0]["garbage_bytes"]
    status = f"corrupt, {{}} packets, {garbage} bytes skipped" if garbage else "ok, {} packets, 0 bytes skipped"
    assert re.fullmatch(f"{re.escape(path)}: {status.format('[0-9]+')}, 0 bad checksums -> log {log}\n", r.stdout)
    assert not stale.exists()
    assert (out / "_files" / f"part-{log}.parquet").exists()
    parts = list(out.glob("sensor.scaled_accel/model=3dm-gx5-45/serial=6232-10100/date=*/*.parquet"))
    assert parts and {p.name for p in parts} == {f"part-{log}-000000000000.parquet"}  # one split (< 64 MiB)


def test_dataset_without_dates_opens_with_spark(spark, capture_dataset):  # noqa: F811
    """A table whose every row has an unknown date (`date=unknown`) opens with Spark's partition
    discovery in this module's session (issue 50 item 6; pyarrow, Polars, DuckDB: test_pipeline.py)."""
    df = spark.read.option("basePath", str(capture_dataset)).parquet(str(capture_dataset))
    got = df.groupBy("date").count().collect()
    assert [(r["date"], r["count"] > 100) for r in got] == [("unknown", True)]


def test_local_sessions_compile_with_c1_and_conf_replaces_it(spark):
    """A local session's JVM runs with `-XX:TieredStopAtLevel=1` (spark.LOCAL_CONF: the JIT's
    compiling took the workers' cores, docs/benchmarks.md), checked in the running JVM's own
    arguments; a cluster master does not get it, and a `--conf` of the same key replaces it."""
    m = mip()
    args = list(spark._jvm.java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments())
    assert "-XX:TieredStopAtLevel=1" in args
    conf = m.spark.session_conf
    assert conf("local[2]")["spark.driver.extraJavaOptions"] == "-XX:TieredStopAtLevel=1"
    assert "spark.driver.extraJavaOptions" not in conf("spark://127.0.0.1:7077")
    mine = conf("local[*]", {"spark.driver.extraJavaOptions": "-Xss4m"})
    assert mine["spark.driver.extraJavaOptions"] == "-Xss4m"
    assert mine["spark.driver.host"] == "127.0.0.1" and mine["spark.ui.enabled"] == "false"


def test_tasks_run_in_ready_workers(spark):
    """Every task's Python worker has been through `worker_ready`: its objects frozen out of the
    collector's reach, and (Python 3.10 and 3.11) zipimport's cache invalidation patched."""
    m = mip()

    def probe(_task):
        import gc
        import zipimport

        return gc.get_freeze_count(), getattr(zipimport.zipimporter.invalidate_caches, "_mipcodec_lazy", False)

    got = m.spark._run_tasks(spark, [0, 1, 2, 3], probe)
    patched = (3, 10) <= sys.version_info[:2] < (3, 12)
    assert len(got) == 4
    assert all(frozen > 1000 and lazy == patched for frozen, lazy in got), got


LAZY_ZIP = r"""
import importlib, json, os, sys, zipfile, zipimport
import mipcodec.spark as spark_job

def archive(path, name, body):
    tmp = path + ".new"
    with zipfile.ZipFile(tmp, "w") as z:
        z.writestr(name + ".py", body)
    os.replace(tmp, path)  # a new file in its place, as a reinstall writes it

path = sys.argv[1]
archive(path, "first_mod", "X = 1\n")
sys.path.insert(0, path)
import first_mod
reads = []
original = zipimport._read_directory
zipimport._read_directory = lambda archive: (reads.append(archive), original(archive))[1]
patched = spark_job.lazy_zip_invalidation()
again = spark_job.lazy_zip_invalidation()
importlib.invalidate_caches()
first = len(reads)
importlib.invalidate_caches()
importlib.invalidate_caches()
unchanged = len(reads) - first
archive(path, "second_mod", "Y = 22\n# longer\n")
importlib.invalidate_caches()
import second_mod
print(json.dumps({"patched": patched, "again": again, "unchanged": unchanged, "y": second_mod.Y}))
"""


def test_lazy_zip_invalidation(tmp_path):
    """`lazy_zip_invalidation` (in a fresh interpreter: it patches zipimport for the process): on
    Python 3.10 and 3.11 `importlib.invalidate_caches()` no longer reads an unchanged archive's
    directory again (unpatched it reads it at every call, CPython gh-103200), and an archive
    replaced on disk is still read again: a module only the new archive holds imports. On 3.12
    and later it patches nothing and the same holds."""
    env = {**os.environ, "PYTHONPATH": str(PKG_DIR)}
    r = subprocess.run(
        [sys.executable, "-c", LAZY_ZIP, str(tmp_path / "mods.zip")],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
    )
    assert r.returncode == 0, r.stderr
    got = json.loads(r.stdout)
    patched = (3, 10) <= sys.version_info[:2] < (3, 12)
    assert got == {"patched": patched, "again": patched, "unchanged": 0, "y": 22}


def test_lazy_zip_invalidation_is_needed(tmp_path):
    """The cost the patch removes is there without it on this Python (3.10, 3.11): each
    `importlib.invalidate_caches()` reads the archive's directory again. On 3.12 and later it does
    not, and `lazy_zip_invalidation` leaves zipimport alone (the test above)."""
    code = LAZY_ZIP.replace("patched = spark_job.lazy_zip_invalidation()", "patched = False").replace(
        "again = spark_job.lazy_zip_invalidation()", "again = False"
    )
    env = {**os.environ, "PYTHONPATH": str(PKG_DIR)}
    r = subprocess.run(
        [sys.executable, "-c", code, str(tmp_path / "mods.zip")], capture_output=True, text=True, env=env, timeout=120
    )
    assert r.returncode == 0, r.stderr
    got = json.loads(r.stdout)
    assert got["y"] == 22
    assert got["unchanged"] == (2 if (3, 10) <= sys.version_info[:2] < (3, 12) else 0)
