"""Spark throughput of the dataset export (issue 41): `mipcodec.spark.export_dataset` on a simulated
fleet with 1 and 2 local workers, and the scaling ratio.

    python -m tests.bench.spark_bench [--size BYTES] [--devices N] [--split-bytes N]
                                      [--workers 1,2] [--repeat N] [--logs DIR] [--json PATH]

The fleet is `mipcodec.fleet`'s (seed 0, --devices logs of about --size bytes in all), generated
into build/bench/spark-fleet/ (again only when the size, device count or fleet.py changed); --logs
takes an existing directory of logs instead. For each worker count N, a Spark session `local[N]`
(loopback only, no UI) is started and warmed up, not timed: its Python workers started, then the
export of the smallest log into a directory of its own (the workers import the package and the
JVM loads the Parquet writer: 4-8 s that otherwise fell on whichever worker count ran first, so
that the ratio depended on the order of the runs). Then the whole export is timed --repeat times
(3 by default), each into an empty directory: the listing, both stages and the `_files` rows. The
fastest of them is the worker count's figure: the machine is shared, and what it adds to a run
only ever lengthens it (the first timed run still paid 0.5-1.3 s of the JVM's and the workers'
warming in the 7 Dec 2026 runs). The workers run the package with its C accelerator
(`tests/lang/python.sh ext`), as an installed package does. Prints one line per worker count,

    BENCH spark workers=N bytes=B seconds=S MB/s=X runs=S1,S2,S3

(S the fastest run; MB = 10^6 bytes of raw log per second of wall time), then
`scaling local[2]/local[1] = R` (the time with the first worker count over the time with the
last). `measure()` is the function tests/bench/run.py (or anything else) calls; it returns the
same figures as a dict.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence

from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
PKG_DIR = ROOT / "generated" / "python" / "mipcodec"
# The package with its C accelerator, as users run it (`tests/lang/python.sh ext` builds it in place).
ACCEL_DIR = ROOT / "build" / "python" / "ext" / "mipcodec"
FLEET_DIR = ROOT / "build" / "bench" / "spark-fleet"
DEFAULT_SIZE = 200 << 20  # the figures: the Spark scaling on at least 200 MB of logs
DEFAULT_SPLIT = 8 << 20  # several splits per log, so that 2 workers have work to share
REPEAT = 3  # timed runs per worker count, the fastest kept (the module docstring)
CONF = {"spark.driver.memory": "1g", "spark.sql.shuffle.partitions": "2"}


def _pkg() -> Any:
    mod = python_package("mipcodec")
    for sub in ("fleet", "spark", "logs.dataset"):
        __import__(f"mipcodec.{sub}")
    return mod


def fleet_logs(size: int = DEFAULT_SIZE, devices: int = 4, out: Path = FLEET_DIR) -> List[str]:
    """The simulated fleet's logs (generated into `out` when missing or stale)."""
    m = _pkg()
    source = Path(m.fleet.__file__).read_bytes()
    key = hashlib.sha256(source + f"{size}:{devices}".encode()).hexdigest()[:16]
    stamp = out / ".stamp"
    if not (stamp.exists() and stamp.read_text() == key):
        shutil.rmtree(out, ignore_errors=True)
        m.fleet.generate(str(out), devices=devices, seed=0, size=size)
        stamp.write_text(key)
    return sorted(str(p) for p in out.iterdir() if p.is_file() and not p.name.startswith(".") and p.suffix != ".json")


def package_dir() -> Path:
    """The directory to put on PYTHONPATH for a timed run: the mipcodec package with its C
    accelerator (built by `tests/lang/python.sh ext`, again only when its sources changed). A
    build that fails raises: the figures of the pure-Python decoder are not the export's."""
    subprocess.run([str(ROOT / "tests" / "lang" / "python.sh"), "ext"], check=True, capture_output=True, text=True)
    if not list((ACCEL_DIR / "mipcodec").glob("codec/_speedups*.so")):
        raise RuntimeError(f"no C accelerator in {ACCEL_DIR} after tests/lang/python.sh ext")
    return ACCEL_DIR


def measure(
    paths: Sequence[str], workers: Sequence[int] = (1, 2), split_bytes: int = DEFAULT_SPLIT, repeat: int = REPEAT
) -> Dict[str, Any]:
    """Time the Spark export of `paths` `repeat` times with local[N] for each N in `workers`:
    {"bytes", "runs": [{"workers", "seconds" (the fastest), "all_seconds", "mb_s"}], "scaling"}
    (scaling: the first worker count's seconds / the last's)."""
    if repeat < 1:
        raise ValueError("repeat must be at least 1")
    m = _pkg()
    # The executors' Python workers import the accelerated package (the driver only plans and lists).
    os.environ["PYTHONPATH"] = os.pathsep.join([str(package_dir()), str(ROOT), os.environ.get("PYTHONPATH", "")])
    total = sum(os.path.getsize(p) for p in paths)
    runs: List[Dict[str, Any]] = []
    for n in workers:
        spark = m.spark.session(f"local[{n}]", CONF)
        try:
            spark.range(0, 2 * n, 1, 2 * n).count()  # start the executors' Python workers
            with tempfile.TemporaryDirectory(prefix="spark-warm-") as warm:  # the warm-up (docstring)
                m.spark.export_dataset(spark, [min(paths, key=os.path.getsize)], warm, split_bytes=split_bytes)
            times: List[float] = []
            for _ in range(repeat):
                with tempfile.TemporaryDirectory(prefix="spark-bench-") as out:
                    t0 = time.perf_counter()
                    m.spark.export_dataset(spark, list(paths), out, split_bytes=split_bytes)
                    times.append(time.perf_counter() - t0)
        finally:
            spark.stop()
        seconds = min(times)
        runs.append({"workers": n, "seconds": seconds, "all_seconds": times, "mb_s": total / seconds / 1e6})
    scaling = runs[0]["seconds"] / runs[-1]["seconds"] if len(runs) > 1 else 1.0
    return {"bytes": total, "split_bytes": split_bytes, "runs": runs, "scaling": scaling}


def main(argv: Optional[Sequence[str]] = None) -> int:
    p = argparse.ArgumentParser(prog="python -m tests.bench.spark_bench", description=__doc__.split("\n\n")[0])
    p.add_argument("--size", type=int, default=DEFAULT_SIZE, help="bytes of simulated logs (default 200 MiB)")
    p.add_argument("--devices", type=int, default=4, help="simulated devices (default 4)")
    p.add_argument("--split-bytes", type=int, default=DEFAULT_SPLIT, help="bytes per split (default 8 MiB)")
    p.add_argument("--workers", default="1,2", help="local worker counts (default 1,2)")
    p.add_argument("--repeat", type=int, default=REPEAT, help=f"timed runs per worker count (default {REPEAT})")
    p.add_argument("--logs", help="a directory of logs to use instead of the simulated fleet")
    p.add_argument("--json", help="write the figures to this file")
    args = p.parse_args(argv)
    try:
        workers = [int(w) for w in args.workers.split(",")]
    except ValueError:
        print(f"spark_bench: --workers needs numbers like 1,2, not {args.workers!r}", file=sys.stderr)
        return 2
    if args.logs:
        paths = sorted(str(x) for x in Path(args.logs).iterdir() if x.is_file() and not x.name.startswith("."))
    else:
        paths = fleet_logs(args.size, args.devices)
    if args.repeat < 1:
        print(f"spark_bench: --repeat needs a positive number, not {args.repeat}", file=sys.stderr)
        return 2
    result = measure(paths, workers, args.split_bytes, args.repeat)
    for r in result["runs"]:
        print(
            f"BENCH spark workers={r['workers']} bytes={result['bytes']} seconds={r['seconds']:.2f} "
            f"MB/s={r['mb_s']:.2f} runs={','.join(f'{t:.2f}' for t in r['all_seconds'])}"
        )
    if len(workers) > 1:
        print(f"scaling local[{workers[-1]}]/local[{workers[0]}] = {result['scaling']:.2f}")
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
