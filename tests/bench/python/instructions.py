"""Instructions per packet of the Python benchmark's modes with the C accelerator (issue 38).

    python tests/bench/python/instructions.py [--streams accel_gyro,mixed] [--modes decode,...]
                                              [--package DIR]

For each stream (written at scale 0.01 into build/bench/small/ by tests/bench/streams.py) and
mode, `valgrind --tool=callgrind` counts `bench.py --count MODE` once with one pass and once with
two; the difference over the stream's packets is the figure: one pass in steady state, without
the interpreter's start-up, the imports and the first use of each layout (which the one-pass run
holds too). The package is the one `tests/lang/python.sh ext` builds (build/python/ext/mipcodec),
or --package DIR (a directory holding an importable mipcodec, e.g. a copy of an older build).
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
BENCH = Path(__file__).resolve().parent / "bench.py"


def count(cmd: list[str], env: dict[str, str]) -> int:
    proc = subprocess.run(
        ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *cmd],
        env=env,
        capture_output=True,
        text=True,
    )
    m = re.search(r"^==\d+== Collected\s*:\s*(\d+)\s*$", proc.stderr, re.MULTILINE)
    if proc.returncode != 0 or not m:
        raise SystemExit(f"instructions.py: {' '.join(cmd)}: exit status {proc.returncode}\n{proc.stderr[-2000:]}")
    return int(m.group(1))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--streams", default="accel_gyro,mixed")
    ap.add_argument("--modes", default="decode,decode-values,decode_all,columns")
    ap.add_argument("--package", type=Path, help="directory to put on PYTHONPATH (default: the ext build)")
    args = ap.parse_args()
    small = ROOT / "build" / "bench" / "small"
    subprocess.run(
        [sys.executable, "-m", "tests.bench.streams", "--out", str(small), "--scale", "0.01"],
        cwd=ROOT,
        check=True,
        capture_output=True,
    )
    if args.package is None:
        built = subprocess.run(
            [str(ROOT / "tests/lang/python.sh"), "ext"], check=True, capture_output=True, text=True
        ).stdout.split()
        args.package = Path(next(d for d in built if d.endswith("/mipcodec")))
    env = dict(os.environ, PYTHONPATH=str(args.package.resolve()))
    env.pop("MIPCODEC_PURE", None)
    print("| stream | mode | instructions/packet | packets |")
    print("|---|---|---:|---:|")
    for stream in [s for s in args.streams.split(",") if s]:
        packets = json.loads((small / f"{stream}.json").read_text())["packets"]
        for mode in [m for m in args.modes.split(",") if m]:
            base = [sys.executable, str(BENCH), str(small), "--streams", stream, "--count", mode]
            one = count([*base, "--passes", "1"], env)
            two = count([*base, "--passes", "2"], env)
            print(f"| {stream} | {mode} | {(two - one) / packets:.0f} | {packets:,} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
