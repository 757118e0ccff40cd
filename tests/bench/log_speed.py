"""The log path's two single-process rates (issue 50 item 4): the simulated fleet generator
(`python -m mipcodec.fleet`) and the single-log CSV export (`python -m mipcodec export LOG --out
DIR`, default path, with the C accelerator), each as the command users run, in a child process:
MB/s of log (10^6 bytes per second of wall time), MB per CPU second (user + system: steadier on
a shared machine) and the child's peak memory (maximum resident set, from `os.wait4`), and each
as a ratio to a reference measured in the same run on the same log: the columnar decode
(`decode_columns` over the whole log, the best of 3, in a child process with the accelerator)
and a bulk copy of its bytes (the best of 3).

    python -m tests.bench.log_speed [--size BYTES] [--log FILE] [--json PATH]

The generator writes one GX5-45 log of the fleet (seed 0) of about --size bytes (default 18 MiB,
the size of the figures in issue 50) into a temporary directory under build/bench/; the export
and the references run on that log, or on --log FILE. In make bench (tests/bench/run.py section
8, `measure()`), the generator writes GEN_SIZE (16 MiB) and the export takes that log: a log of
at least 16 MiB, where start-up (about 0.3 s of imports) is not most of the figure (the dataset
fleet's logs are 6 MB with CI's 24 MiB).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence, Tuple

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_SIZE = 18 << 20
# The generator's timed log in make bench, which the export then takes: about 0.6 s each with the
# batch path and the accelerator (a smaller log would time mostly the start-up, 0.3 s of imports).
GEN_SIZE = 16 << 20
# The reference rates of the log in one child process: JSON {"decode_s", "copy_s"} (best of 3 each).
REFERENCE = """
import json, sys, time
from mipcodec.codec.packets import decode_columns
data = open(sys.argv[1], "rb").read()
best = {"decode_s": float("inf"), "copy_s": float("inf")}
for _ in range(3):
    t0 = time.perf_counter(); cols = decode_columns(data); t1 = time.perf_counter()
    copy = bytearray(data); t2 = time.perf_counter()
    best = {"decode_s": min(best["decode_s"], t1 - t0), "copy_s": min(best["copy_s"], t2 - t1)}
print(json.dumps(best))
"""


def _timed(cmd: Sequence[str], env: Dict[str, str]) -> Tuple[float, float, float]:
    """Wall and CPU seconds (user + system) and the peak memory (maximum resident set, MB) of a
    child process; raises when it fails."""
    with tempfile.TemporaryFile() as err:
        t0 = time.perf_counter()
        child = subprocess.Popen(list(cmd), env=env, stdout=subprocess.DEVNULL, stderr=err, cwd=ROOT)
        _pid, status, usage = os.wait4(child.pid, 0)
        wall = time.perf_counter() - t0
        child.returncode = os.waitstatus_to_exitcode(status)
        if child.returncode:
            err.seek(0)
            text = err.read().decode(errors="replace").strip()[-500:]
            raise RuntimeError(f"{' '.join(cmd[1:4])}: exit status {child.returncode}: {text}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024


def measure(out: Path, log: Optional[str] = None, gen_size: int = GEN_SIZE) -> Dict[str, Any]:
    """The figures (see the module's docstring) as a dict: the generator timed writing one log of
    about `gen_size` bytes; the export and the references on `log` (default: that log)."""
    if str(ROOT) not in sys.path:
        sys.path.insert(0, str(ROOT))
    from tests.bench import spark_bench

    env = dict(os.environ, PYTHONPATH=str(spark_bench.package_dir()))
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="log-speed-", dir=out) as tmp:
        fleet_dir, csv_dir = Path(tmp) / "fleet", Path(tmp) / "csv"
        gen = [sys.executable, "-m", "mipcodec.fleet", "--out", str(fleet_dir), "--devices", "1"]
        gen_wall, gen_cpu, _gen_peak = _timed([*gen, "--size", str(gen_size)], env)
        generated = next(p for p in fleet_dir.iterdir() if p.suffix == ".mip")
        gen_bytes = generated.stat().st_size
        path = Path(log) if log else generated
        raw = path.stat().st_size
        export = [sys.executable, "-m", "mipcodec", "export", str(path), "--out", str(csv_dir)]
        exp_wall, exp_cpu, exp_peak = _timed(export, env)
        csv_bytes = sum(p.stat().st_size for p in csv_dir.iterdir())
        ref = json.loads(
            subprocess.run(
                [sys.executable, "-c", REFERENCE, str(path)], env=env, check=True, capture_output=True, text=True
            ).stdout
        )
    mb = raw / 1e6
    return {
        "log": path.name,
        "log_bytes": raw,
        "csv_bytes": csv_bytes,
        "generator_bytes": gen_bytes,
        "generator_seconds": gen_wall,
        "generator_cpu_seconds": gen_cpu,
        "generator_mb_s": gen_bytes / 1e6 / gen_wall,
        "generator_mb_per_cpu_s": gen_bytes / 1e6 / gen_cpu,
        "export_csv_seconds": exp_wall,
        "export_csv_cpu_seconds": exp_cpu,
        "export_csv_mb_s": mb / exp_wall,
        "export_csv_mb_per_cpu_s": mb / exp_cpu,
        "export_csv_peak_mb": exp_peak,
        "decode_columns_mb_s": mb / ref["decode_s"],
        "bulk_copy_mb_s": mb / ref["copy_s"],
    }


def lines(r: Dict[str, Any]) -> List[Tuple[str, str]]:
    """The figures as (what, figure) rows of the bench's table."""
    decode, copy = r["decode_columns_mb_s"], r["bulk_copy_mb_s"]
    return [
        ("exported log", f"{r['log']}: {r['log_bytes'] / 1e6:.1f} MB, CSV {r['csv_bytes'] / 1e6:.1f} MB"),
        (
            f"fleet generator, one log of {r['generator_bytes'] / 1e6:.1f} MB",
            f"{r['generator_mb_s']:.2f} MB/s ({r['generator_seconds']:.1f} s), "
            f"{r['generator_mb_per_cpu_s']:.2f} MB per CPU s; x decode {r['generator_mb_s'] / decode:.4f}",
        ),
        (
            "export LOG (CSV, accelerated)",
            f"{r['export_csv_mb_s']:.2f} MB/s ({r['export_csv_seconds']:.2f} s), "
            f"{r['export_csv_mb_per_cpu_s']:.2f} MB per CPU s, peak {r['export_csv_peak_mb']:.0f} MB; "
            f"x decode {r['export_csv_mb_s'] / decode:.4f}",
        ),
        ("reference: decode_columns, bulk copy", f"{decode:.0f} MB/s, {copy:.0f} MB/s"),
    ]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--size", type=int, default=DEFAULT_SIZE, help="bytes of the generated log (default 18 MiB)")
    ap.add_argument("--log", metavar="FILE", help="export this log instead of the generated one")
    ap.add_argument("--json", metavar="PATH", help="write the figures there")
    args = ap.parse_args()
    r = measure(ROOT / "build" / "bench", args.log, args.size)
    for what, figure in lines(r):
        print(f"{what}: {figure}")
    if args.json:
        Path(args.json).write_text(json.dumps(r, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
