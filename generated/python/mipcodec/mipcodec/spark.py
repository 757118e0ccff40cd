"""Raw logs to the partitioned Parquet dataset on Apache Spark (`python -m mipcodec.spark`).

    python -m mipcodec.spark LOGS... --out DIR [--master URL] [--split-bytes N]
                                [--model NAME] [--serial SN]

The same dataset as `python -m mipcodec export --dataset DIR LOGS...` (docs/dataset.md), the
same file names and rows, written by the same functions of `mipcodec.dataset`: this module is a
second driver of them, not a second decoder. From a Spark application of your own:

    from mipcodec import spark as spark_job
    summary = spark_job.export_dataset(spark_session, ["/data/logs/"], "/data/dataset")

The job, in two Spark stages after a listing:

1. The logs are listed as Spark binary files (`spark.read.format("binaryFile")`, path and length
   only: a log's content never travels as one row). A LOG may be a file, a directory (every file
   under it) or a glob, on any filesystem Spark lists and every executor reads: a local or shared
   path, or a URI pyarrow's filesystems open (s3://, gs://, hdfs://; s3a:// is read as s3://).
2. A cheap pass, one task per `PHASE1_BYTES` (256 MiB) of a log's splits: the log's id (SHA-256
   of its content) and identity (`dataset.log_id`, `dataset.log_identity`) in its first task, and
   the time anchors of each window of each split (`dataset.windows`, `timebase.split_anchors`).
   The driver builds each log's clock map from them (`timebase.ClockMap.from_splits`), so each
   window is decoded with what the log before it implies. (A task costs Spark about 0.1 s
   however little it does, on the 2-core machine of docs/benchmarks.md: a task per split here
   was 40% of the job's time on 8 MiB splits.)
3. One task per split of the fixed grid (`dataset.splits`, `--split-bytes`, 64 MiB by default):
   `dataset.export_split`, the local export's own loop (the split decoded one window at a time,
   `dataset.read_split` and `dataset.decode_split`, its part files written atomically in the
   output directory as the windows come); then the driver removes the log's stale parts
   (`dataset.remove_parts`) and writes its `_files` row (`dataset.files_row`,
   `dataset.write_files_row`). A log that cannot be listed or read is an `unreadable` row there,
   never a failed run.

The tasks run as `DataFrame.mapInArrow` over a range of task numbers, one task per partition:
the decoder is columnar and produces Arrow tables, mapInArrow hands a task Arrow batches with no
pandas conversion, and (unlike RDD.mapPartitions) it works on Spark Connect sessions too.

The output directory must be a path the driver and every executor see (local mode: any path; on
a cluster: a shared filesystem such as NFS, or a mounted bucket). Nothing but the master URL
changes between local mode and a cluster; the executors need this package and its `[spark]`
extra installed.

Exit status: 0 (also when some logs are unreadable: they are `_files` rows); 2 on a usage error,
a missing pyspark or Java, a dataset that cannot be written or a failed Spark job (one line on
stderr); 130 on Ctrl-C.
"""

from __future__ import annotations

import argparse
import gc
import hashlib
import importlib
import os
import pickle
import shutil
import sys
from typing import Any, Callable, Dict, Iterator, List, Optional, Sequence, Tuple
from urllib.parse import unquote, urlparse

from ._protocol import PACKAGE as PROG
from .codec.stdio import closed_stdout
from .logs import dataset, timebase
from .logs.commands import positive  # the option type of export --split-bytes
from .logs.writers import ToolError, need

DEFAULT_MASTER = "local[*]"
GLOB_CHARS = "*?[{"
# Phase 1's bytes of splits per task (the module docstring): a log's id, identity and anchors in
# few tasks, a large log's spread over several.
PHASE1_BYTES = 256 << 20
# Spark settings of the session the command starts: no web UI, no progress bar; in local mode the
# driver binds to the loopback interface only (nothing listens on the network), and its JVM
# compiles with the client compiler only (C1, `-XX:TieredStopAtLevel=1`). In local mode that one
# JVM is the driver and the executor, and here it only schedules tasks and moves small Arrow
# batches: the Python workers do the work. With the server compiler (C2) the JVM spent 2.4 CPU s
# of a 6-8 s job compiling, and 0.4-0.5 s of each run after (docs/benchmarks.md), on the cores
# the workers need; with C1 alone, 0.15-0.3 s. A `spark.driver.extraJavaOptions` of your own
# (`--conf`) replaces this one.
SESSION_CONF = {
    "spark.ui.enabled": "false",
    "spark.ui.showConsoleProgress": "false",
    "spark.sql.execution.arrow.pyspark.enabled": "true",
}
LOCAL_CONF = {
    "spark.driver.host": "127.0.0.1",
    "spark.driver.bindAddress": "127.0.0.1",
    "spark.driver.extraJavaOptions": "-XX:TieredStopAtLevel=1",
}

ReadAt = Callable[[int, int], bytes]


# ------------------------------------------------------------------------------------ libraries
def need_pyspark() -> Any:
    """The pyspark module, or the one-line error that names the extra installing it."""
    return need("pyspark.sql", "spark")


def java_missing() -> Optional[str]:
    """Why a local Spark cannot start for want of Java (None when a java is found)."""
    home = os.environ.get("JAVA_HOME")
    if home:
        if os.access(os.path.join(home, "bin", "java"), os.X_OK):
            return None
        return f"JAVA_HOME={home} has no bin/java"
    if shutil.which("java"):
        return None
    return "no java on PATH and JAVA_HOME is not set"


def session_conf(master: str, conf: Optional[Dict[str, str]] = None) -> Dict[str, str]:
    """The settings `session` gives Spark: SESSION_CONF, LOCAL_CONF on a local master, then
    `conf`, each replacing the ones before it key by key."""
    return {**SESSION_CONF, **(LOCAL_CONF if master.startswith("local") else {}), **(conf or {})}


def session(master: str = DEFAULT_MASTER, conf: Optional[Dict[str, str]] = None) -> Any:
    """A SparkSession for the command: `master` (local[*] by default), the settings above plus
    `conf`. In local mode the Python workers run this interpreter (PYSPARK_PYTHON unless set),
    and a missing Java is one ToolError line rather than Spark's gateway error."""
    sql = need_pyspark()
    local = master.startswith("local")
    if local:
        missing = java_missing()
        if missing:
            raise ToolError(
                f"Spark needs a Java 17 or 21 runtime: {missing} (Debian: apt-get install openjdk-17-jre-headless)"
            )
        os.environ.setdefault("PYSPARK_PYTHON", sys.executable)
        os.environ.setdefault("SPARK_LOCAL_IP", "127.0.0.1")  # every service on the loopback interface
    builder = sql.SparkSession.builder.master(master).appName(f"{PROG}.spark")
    for key, value in session_conf(master, conf).items():
        builder = builder.config(key, value)
    try:
        spark = builder.getOrCreate()
    except Exception as e:  # the JVM did not start (a bad master URL, a broken Java)
        raise ToolError(f"cannot start Spark (master {master}): {_first_line(e)}") from None
    spark.sparkContext.setLogLevel("ERROR")
    return spark


def _first_line(e: BaseException) -> str:
    text = str(e).strip()
    return text.splitlines()[0] if text else type(e).__name__


# ----------------------------------------------------------------------------------- the files
def _local_path(uri: str) -> Optional[str]:
    """The local path of a `file:` URI or of a plain path, else None."""
    parsed = urlparse(uri)
    if parsed.scheme == "file":
        return unquote(parsed.path)
    if parsed.scheme == "" or (len(parsed.scheme) == 1 and os.name == "nt"):
        return uri
    return None


def open_log(uri: str) -> Tuple[ReadAt, int]:
    """(read_at, size) of a listed log: a local file through `dataset.file_reader`, anything else
    through pyarrow's filesystems (s3://, gs://, hdfs://, ...). dataset.ReadError when unreadable."""
    local = _local_path(uri)
    if local is not None:
        return dataset.file_reader(local)
    fs_mod = need("pyarrow.fs", "spark")
    parsed = urlparse(uri)
    if parsed.scheme in ("s3a", "s3n"):
        uri = "s3" + uri[len(parsed.scheme) :]
    try:
        fs, path = fs_mod.FileSystem.from_uri(uri)
        info = fs.get_file_info(path)
        size = int(info.size)
    except (OSError, ValueError) as e:
        raise dataset.ReadError(_first_line(e)) from None

    def read_at(offset: int, length: int) -> bytes:
        try:
            with fs.open_input_file(path) as f:
                return bytes(f.read_at(length, offset))
        except OSError as e:
            raise dataset.ReadError(_first_line(e)) from None

    return read_at, size


def log_id_of(uri: str, read_at: ReadAt, size: int) -> str:
    """`dataset.log_id` of a listed log (the same digest, read through `read_at` when remote)."""
    local = _local_path(uri)
    if local is not None:
        return dataset.log_id(local)
    h = hashlib.sha256()
    for pos in range(0, size, 1 << 22):
        h.update(read_at(pos, min(1 << 22, size - pos)))
    return h.hexdigest()[:16]


class Listed:
    """A log the listing found: the path `_files` records (as given when it was given as a file),
    the URI executors read and its size."""

    def __init__(self, path: str, uri: str, size: int) -> None:
        self.path = path
        self.uri = uri
        self.size = size


def list_logs(spark: Any, paths: Sequence[str]) -> Tuple[List[Listed], List[Tuple[str, str]]]:
    """The logs under `paths` as Spark lists them (binary files: path and length only), and the
    (path, error) of the paths that cannot be listed."""
    reader = spark.read.format("binaryFile").option("recursiveFileLookup", "true")

    def load(ps: Sequence[str]) -> List[Any]:
        return list(reader.load(list(ps)).select("path", "length").collect())

    rows: List[Any] = []
    bad: List[Tuple[str, str]] = []
    try:
        rows = load(paths) if paths else []
    except Exception:  # some path cannot be listed: find which, one by one
        for p in paths:
            try:
                rows += load([p])
            except Exception as e:
                bad.append((p, _unlisted_error(p, e)))
    given: Dict[str, str] = {}
    for p in paths:
        local = _local_path(p)
        if local is not None and not any(c in p for c in GLOB_CHARS):
            given.setdefault(os.path.abspath(local), p)
        given.setdefault(p, p)
    logs: List[Listed] = []
    seen = set()
    for row in sorted(rows, key=lambda r: str(r["path"])):
        uri = str(row["path"])
        if uri in seen:
            continue
        seen.add(uri)
        local = _local_path(uri)
        key = os.path.abspath(local) if local is not None else uri
        logs.append(Listed(given.get(key, local if local is not None else uri), uri, int(row["length"])))
    # Spark's file index leaves out empty files: a local log given by name is still recorded
    listed = {os.path.abspath(x) for x in (_local_path(log.uri) for log in logs) if x is not None}
    for p in paths:
        local = _local_path(p)
        if local is None or any(c in p for c in GLOB_CHARS) or os.path.abspath(local) in listed:
            continue
        if os.path.isfile(local) and p not in {b[0] for b in bad}:
            listed.add(os.path.abspath(local))
            logs.append(Listed(p, "file://" + os.path.abspath(local), os.path.getsize(local)))
    return logs, bad


def _unlisted_error(path: str, e: BaseException) -> str:
    """The error of a path Spark cannot list: the operating system's, as `export --dataset` gives
    it, for a local path; Spark's first line otherwise."""
    local = _local_path(path)
    if local is not None and not any(c in path for c in GLOB_CHARS):
        try:
            dataset.file_reader(local)
        except dataset.ReadError as r:
            return str(r)
    msg = _first_line(e)
    return msg.split("] ", 1)[1] if msg.startswith("[") and "] " in msg else msg


# ------------------------------------------------------------------------------------ the tasks
def _run_tasks(spark: Any, tasks: List[Any], work: Callable[[Any], Any]) -> List[Any]:
    """`work(task)` for every task in Spark, one task per partition (mapInArrow over the task
    numbers); the results (pickled by the tasks) in task order."""
    if not tasks:
        return []

    def one(task: Any) -> bytes:
        try:
            result = work(task)
        except Exception as e:  # a bug, not a bad log: the job fails naming the log and split
            where = (
                f"{task[1]}"
                if task[0] == "log"
                else f"{task[1]} splits from {task[3][0][0]}"
                if task[0] == "splits"
                else f"{task[0]} split at {task[2]}"
            )
            result = _Failed(f"{where}: {type(e).__name__}: {e}")
        return pickle.dumps(result, protocol=pickle.HIGHEST_PROTOCOL)

    def run(batches: Iterator[Any]) -> Iterator[Any]:
        worker_ready()
        pa = importlib.import_module("pyarrow")
        for batch in batches:
            ids = batch.column(0).to_pylist()
            out = [one(tasks[i]) for i in ids]
            yield pa.RecordBatch.from_arrays([pa.array(ids, pa.int64()), pa.array(out, pa.binary())], ["id", "result"])

    n = len(tasks)
    df = spark.range(0, n, 1, n).mapInArrow(run, "id long, result binary")
    results: List[Any] = [None] * n
    for row in df.collect():
        results[int(row["id"])] = pickle.loads(bytes(row["result"]))
    failed = next((r for r in results if isinstance(r, _Failed)), None)
    if failed is not None:
        raise RuntimeError(failed.error)
    return results


def worker_ready() -> None:
    """What a task does first in its Python worker, against two costs PySpark's worker adds to
    every task on top of the task's own work (measured on Python 3.11 in docs/benchmarks.md: a
    no-op task cost 0.11 s, 0.06 s with both, the rest the JVM's):
    `lazy_zip_invalidation`, and the full garbage collection the worker runs after each task
    (`gc.collect()`: about 30 ms once the worker has imported pyarrow, pandas and this package).
    `gc.freeze()` moves the objects alive now (after the previous task's collection: modules,
    their tables and caches) out of the collector's reach, so the collection after this task
    walks only what this task made. Reference counting still frees a frozen object no longer
    used; only a reference cycle among them would stay."""
    gc.freeze()
    lazy_zip_invalidation()


def lazy_zip_invalidation() -> bool:
    """Make `importlib.invalidate_caches()` cheap in this Python worker on Python 3.10 and 3.11
    (True when it patched, now or before). PySpark's worker calls it before every task, and
    on those versions it makes each `zipimport.zipimporter` read its whole archive's directory
    again, in Python: for the `pyspark.zip` Spark puts on the workers' path, about 0.06 s of every
    task (CPython gh-103200; Python 3.12 reads the directory only when next used). The patched
    `invalidate_caches` reads it again only when the archive's size, inode or modification time
    changed since its last read, so a changed archive is still seen. Python 3.12 and later are
    left alone."""
    if not (3, 10) <= sys.version_info[:2] < (3, 12):
        return False
    zipimport = importlib.import_module("zipimport")
    cls = zipimport.zipimporter
    original = cls.invalidate_caches
    if getattr(original, "_mipcodec_lazy", False):
        return True

    def invalidate_caches(self: Any) -> None:
        try:
            st = os.stat(self.archive)
            key: Optional[Tuple[int, int, int]] = (st.st_mtime_ns, st.st_size, st.st_ino)
        except OSError:
            key = None
        if key is not None and self.__dict__.get("_mipcodec_stat") == key:
            return
        original(self)
        self.__dict__["_mipcodec_stat"] = key

    patched: Any = invalidate_caches
    patched._mipcodec_lazy = True
    cls.invalidate_caches = patched
    return True


class _Failed:
    """A task's unexpected exception (its log and the error), raised on the driver."""

    def __init__(self, error: str) -> None:
        self.error = error


def _identify(uri: str, model: Optional[str], serial: Optional[str]) -> Any:
    """A log's ("ok", log id, identity, size) or ("unreadable", error)."""
    try:
        read_at, size = open_log(uri)
        return ("ok", log_id_of(uri, read_at, size), dataset.log_identity(read_at, size, model, serial), size)
    except dataset.ReadError as e:
        return ("unreadable", str(e))


def _anchors(uri: str, size: int, ranges: Sequence[Tuple[int, int]]) -> List[Any]:
    """The time anchors of each of `ranges` (the windows of some splits, `dataset.windows`, in log
    order: `timebase.split_anchors`), or ("unreadable", error) for each from the first that cannot
    be read."""
    out: List[Any] = []
    try:
        read_at, _ = open_log(uri)
        for start, end in ranges:
            data, base = dataset.read_split(read_at, size, start, end)
            out.append(timebase.split_anchors(data, base, start, end))
    except dataset.ReadError as e:
        out += [("unreadable", str(e))] * (len(ranges) - len(out))
    return out


def _phase1(task: Tuple[Any, ...]) -> Any:
    """Phase 1: ("log", uri, size, model, serial, windows) -> (the log's identity, anchors);
    ("splits", uri, size, windows) -> anchors."""
    if task[0] == "log":
        _kind, uri, size, model, serial, group = task
        return (_identify(uri, model, serial), _anchors(uri, size, group))
    _kind, uri, size, group = task
    return _anchors(uri, size, group)


def phase1_groups(grid: Sequence[Tuple[int, int]], limit: int = 0) -> List[List[Tuple[int, int]]]:
    """A log's splits in runs of at most `limit` bytes (PHASE1_BYTES; at least one split each): the
    splits of one phase-1 task. A log without splits (empty) still has one run, empty."""
    limit = limit or PHASE1_BYTES
    groups: List[List[Tuple[int, int]]] = [[]]
    held = 0
    for start, end in grid:
        if groups[-1] and held + (end - start) > limit:
            groups.append([])
            held = 0
        groups[-1].append((start, end))
        held += end - start
    return groups


def _decode(out_dir: str, task: Tuple[str, int, int, Any, str, Any, Any]) -> Any:
    """Phase 2, per split: decode and write it one window at a time (`dataset.export_split`, as
    the local export does: the memory of one window; the windows and their clocks from the
    driver). ("ok", its windows' results without their tables, the parts written, rows per
    table), ("unreadable", error) or ("write", error)."""
    uri, size, start, ws, log, identity, clocks = task
    results: List[Any] = []
    try:
        read_at, _ = open_log(uri)
        parts, rows = dataset.export_split(out_dir, read_at, size, identity, log, start, ws, clocks, results)
    except dataset.ReadError as e:  # also a log of unknown device with per-device fields
        return ("unreadable", str(e))
    except OSError as e:
        return ("write", e.strerror or str(e))
    return ("ok", results, parts, rows)


# --------------------------------------------------------------------------------------- the job
def export_dataset(
    spark: Any,
    paths: Sequence[str],
    out_dir: str,
    split_bytes: int = dataset.SPLIT_BYTES,
    model: Optional[str] = None,
    serial: Optional[str] = None,
) -> dataset.Summary:
    """Decode the logs at `paths` (files, directories or globs Spark can list) into the dataset at
    `out_dir` on the SparkSession `spark`: the same files and rows as the single-machine
    `dataset.export_dataset`. `out_dir` must be a path the driver and every executor see.
    Returns the `_files` rows, the part files written and the rows per table. A log that cannot
    be read is an `unreadable` row in `_files`; a dataset that cannot be written raises OSError."""
    if split_bytes <= 0:
        raise ValueError("split_bytes must be positive")
    out_dir = os.path.abspath(out_dir)
    os.makedirs(out_dir, exist_ok=True)
    fallback = dataset.Identity(
        dataset.partition_value(model) if model else dataset.UNKNOWN,
        dataset.partition_value(serial) if serial else dataset.UNKNOWN,
    )
    summary = dataset.Summary()
    logs, bad = list_logs(spark, paths)
    unreadable: List[Tuple[str, str]] = list(bad)

    # phase 1: ids and identities per log, time anchors per split (a task per run of splits)
    grids = [dataset.splits(log.size, split_bytes) for log in logs]
    groups = [phase1_groups(grid) for grid in grids]
    tasks1: List[Tuple[Any, ...]] = []
    for log, runs in zip(logs, groups):
        ranges = [[w for start, end in run for w in dataset.windows(start, end)] for run in runs]
        tasks1.append(("log", log.uri, log.size, model, serial, ranges[0]))
        tasks1 += [("splits", log.uri, log.size, r) for r in ranges[1:]]
    results1 = _run_tasks(spark, tasks1, _phase1)
    pos = 0
    ready: List[Tuple[Listed, str, dataset.Identity, int, List[Tuple[int, int]], Any]] = []
    for log, grid, runs in zip(logs, grids, groups):
        ident, anchors = results1[pos]
        for more in results1[pos + 1 : pos + len(runs)]:
            anchors = anchors + more
        pos += len(runs)
        if ident[0] != "ok":
            unreadable.append((log.path, ident[1]))
            continue
        _ok, log_hash, identity, size = ident
        failed = next((a for a in anchors if not isinstance(a, timebase.SplitAnchors)), None)
        if failed is not None:
            unreadable.append((log.path, failed[1]))
            continue
        if size != log.size:  # changed since the listing
            unreadable.append((log.path, f"changed while read ({log.size} bytes listed, {size} read)"))
            continue
        ready.append((log, log_hash, identity, size, grid, timebase.ClockMap.from_splits(anchors)))

    # phase 2: every split decoded and written (each window with its clock)
    tasks2: List[Tuple[str, int, int, Any, str, Any, Any]] = []
    for log, log_hash, identity, size, grid, maps in ready:
        k = 0
        for s, e in grid:
            ws = dataset.windows(s, e)
            tasks2.append((log.uri, size, s, ws, log_hash, identity, [maps.split(k + j) for j in range(len(ws))]))
            k += len(ws)
    results2 = _run_tasks(spark, tasks2, lambda task: _decode(out_dir, task))
    pos = 0
    for log, log_hash, identity, size, grid, _maps in ready:
        mine = results2[pos : pos + len(grid)]
        pos += len(grid)
        for r in mine:
            if r[0] == "write":
                raise OSError(f"{out_dir}: {r[1]}")
        split_results = [w for r in mine if r[0] == "ok" for w in r[1]]
        parts = [p for r in mine if r[0] == "ok" for p in r[2]]
        for r in mine:
            if r[0] == "ok":
                for name, n in r[3].items():
                    summary.rows[name] = summary.rows.get(name, 0) + n
        error = next((r[1] for r in mine if r[0] == "unreadable"), None)
        if error is None:
            dataset.remove_parts(out_dir, log_hash, keep=parts)
        row = dataset.files_row(log_hash, log.path, size, identity, split_results, error=error)
        dataset.write_files_row(out_dir, row)
        summary.logs.append(row)
        summary.parts += parts
    for path, error in unreadable:
        row = dataset.files_row(dataset.unreadable_id(path), path, 0, fallback, [], error=error)
        dataset.write_files_row(out_dir, row)
        summary.logs.append(row)
    return summary


# ----------------------------------------------------------------------------------- the command
def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog=f"python -m {PROG}.spark",
        description="Decode raw logs into the partitioned Parquet dataset on Apache Spark "
        f"(the same dataset as `{PROG} export --dataset`; docs/dataset.md).",
    )
    p.add_argument("logs", nargs="+", metavar="LOG", help="log files, directories or globs (any path Spark lists)")
    p.add_argument("--out", required=True, metavar="DIR", help="the dataset directory (seen by every executor)")
    p.add_argument("--master", default=DEFAULT_MASTER, metavar="URL", help=f"Spark master (default {DEFAULT_MASTER})")
    p.add_argument("--split-bytes", type=positive, metavar="N", help="bytes of log per task (default 64 MiB)")
    p.add_argument("--model", metavar="NAME", help="the model of logs without a device information reply")
    p.add_argument("--serial", metavar="SN", help="the serial of logs without a device information reply")
    p.add_argument("--conf", action="append", default=[], metavar="KEY=VALUE", help="a Spark setting (repeatable)")
    return p


def main(argv: Optional[List[str]] = None) -> int:
    args = parser().parse_args(sys.argv[1:] if argv is None else argv)
    try:
        conf: Dict[str, str] = {}
        for item in args.conf:
            key, sep, value = item.partition("=")
            if not sep or not key:
                raise ToolError(f"--conf needs KEY=VALUE, not {item!r}")
            conf[key] = value
        if "-" in args.logs:
            raise ToolError("reads log files only (not - for stdin)")
        need_pyspark()
        need("pandas", "spark")  # pyspark's mapInArrow imports it
        need("pyarrow", "spark")
        need("numpy", "spark")
        try:
            os.makedirs(args.out, exist_ok=True)
        except OSError as e:
            raise ToolError(f"cannot create {args.out!r}: {e.strerror or e}") from None
        spark = session(args.master, conf)
        try:
            summary = export_dataset(
                spark, args.logs, args.out, args.split_bytes or dataset.SPLIT_BYTES, args.model, args.serial
            )
        except OSError as e:
            raise ToolError(f"cannot write {args.out!r}: {e.strerror or e}") from None
        except ToolError:
            raise
        except Exception as e:  # a failed Spark job (lost executors, ...)
            raise ToolError(f"the Spark job failed: {_first_line(e)}") from None
        finally:
            spark.stop()
    except ToolError as e:
        print(f"{PROG}.spark: {e}", file=sys.stderr)
        return e.status
    except KeyboardInterrupt:
        return 130
    try:
        for row in summary.logs:
            error = f" ({row['error']})" if row["error"] else ""
            print(
                f"{row['path']}: {row['status']}{error}, {row['packets']} packets, {row['skipped_bytes']} bytes "
                f"skipped, {row['bad_checksums']} bad checksums -> log {row['log']}"
            )
        sys.stdout.flush()
    except BrokenPipeError:  # stdout closed by its reader: quietly, by SIGPIPE (codec.stdio)
        return closed_stdout()
    print(f"{args.out}: {len(summary.parts)} part files, {sum(summary.rows.values())} rows", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())


__all__ = ["export_dataset", "session", "session_conf", "list_logs", "open_log", "main", "DEFAULT_MASTER"]
