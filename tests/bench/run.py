"""Builds and runs the benchmarks of every language (issues 8 and 30) and prints one table.

    python tests/bench/run.py [--langs c,cpp,rust,python] [--scale 1.0] [--passes 5] [--processes 5]
                              [--python-processes N]
                              [--instructions | --instructions-only] [--no-cli] [--json PATH]

`make bench` runs it (BENCH_ARGS="..." passes arguments); `make bench-instructions` runs
--instructions-only. Steps:
  1. the streams of tests/bench/streams.py in build/bench/ (written again only when missing, when
     --scale changed or when streams.py changed);
  2. each language's benchmark, built with release flags into build/bench/bin/ (C: gcc -O2,
     C++: g++ -O2; Rust: cargo --release; Python: the package as installed in this interpreter);
  3. each benchmark run in --processes processes (the languages interleaved: round 1 of every
     language, then round 2, ...), each process printing the best of --passes passes per row as
     `BENCH lang=.. stream=.. mode=.. packets=N bytes=B seconds=S` lines. Every process also
     measures mode `bulk`, one memcpy of the whole stream into another buffer; each row's figure is
     the median over the processes of its best time, its spread the half range of the processes'
     figures over that median (±%), and its fraction of bulk the median over the processes of
     bulk's time over the row's time in the same process (the same bytes: bytes/s over bulk's
     bytes/s). Columns: language, stream, mode, Mpkt/s, GB/s, ±%, x bulk (and its spread),
     decode/frame (decode and decode-* rows: the same language's frame time over decode time, per process),
     the session column (session-ingest: its rate as a fraction of the same language's decode;
     session-roundtrip, stream loopback-tcp, packets = round trips: round trips per second and
     microseconds per round trip) and, with --instructions, instructions per packet. The rows go
     to build/bench/results.json (--json): a list of {lang, stream, mode, packets, bytes, seconds,
     processes (each process's seconds), spread_pct, bulk_fraction, bulk_fraction_spread_pct,
     decode_over_frame, instructions_per_packet, ...}, a key present only where it applies.
  4. --instructions / --instructions-only: instructions per packet of C, C++ and Rust frame and
     decode, counted by valgrind --tool=callgrind on 1%-scale streams (10,000 packets of
     accel_gyro, 2,000 of mixed) in build/bench/small/: one pass of `--stream S --mode M`, minus
     the same program with `--mode none` (loading the stream, its fixed cost), over the packets;
     --instructions-only adds them to the rows of an existing results.json (replacing older counts).
  5. each language's decode CLI (lang=<lang>-cli mode=decode-cli, issue 22), built with release
     flags into build/bench/cli/ (C and C++: CMake Release; Rust: cargo --release in build/rust/target,
     shared with tests/lang/rust.sh; Python: the package with its C accelerator, build/python/ext/),
     run once on accel_gyro.bin and on the device capture (../shared/captures/mip_data.bin, when
     there) repeated 200 x --scale times, output to a file: wall time and maximum resident memory of
     each process (wait4), and the outputs must be byte-identical across languages (--no-cli skips it).
  6. the session tools under a noise flood (issue 37; tests/bench/session_flood.py): per language
     and flood kind (zeros, random, false syncs), one ping with --timeout-ms 500 against a loopback
     device flooding it: peak resident memory and milliseconds past the deadline, one table
     (--no-flood leaves it out; about 5 s a language).
  7. compile cost (issue 39; --no-compile skips it, --compile-only runs only it): compile CPU
     seconds (user + system) and peak memory (GNU time's maximum resident set) of a few translation
     units, compiled one at a time with -O2 and the packages' strict warnings (-c, no link): the
     C++ session tool and examples, tests/bench/compile/minimal.cpp (the umbrella header, one
     command and the parser) and minimal.c (the same with the C package), whose figures are each
     row's divisor (the "x C" columns); rows lang=compile in results.json.
  8. the dataset (issue 41; --no-dataset leaves it out, --dataset-size BYTES sets the fleet's
     size, default 200 MiB, the issue's size for the Spark scaling): the simulated fleet of tests/bench/spark_bench.py (mipcodec.fleet,
     build/bench/spark-fleet/), exported with `export --dataset`'s function in this process (one
     core): MB/s of raw log (10^6 bytes per second of wall time), MB per CPU second, its peak
     memory (maximum resident set) and the dataset's size over the raw logs'; then the Spark job with local[1] and local[2] (each the fastest of three
     timed runs, all three shown) and the scaling ratio (spark_bench.measure; needs pyspark and
     Java, else reported as skipped). build/bench/dataset.json.
     Then the fleet generator's MB/s (one 16 MiB GX5-45 log) and the single-log CSV export's MB/s,
     MB per CPU second and peak memory (that log), each over the columnar decode's rate of the exported log
     (tests/bench/log_speed.py), build/bench/log_speed.json.
A language whose benchmark directory does not exist is skipped with a message. The exit status
is non-zero when a benchmark failed to build or run, or reported counts that do not match the
stream's sidecar (each benchmark checks them and exits non-zero).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import platform
import re
import shlex
import shutil
import statistics
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BENCH = ROOT / "tests" / "bench"
STREAMS = ("accel_gyro", "mixed", "accel_gyro_garbage", "mixed_garbage")
# Row order of the table: the languages in --langs order. Every target of the registry
# (generator/targets/__init__.py) has a benchmark (tests/generator/test_targets.py checks it).
LANG_ROWS = {
    "c": ("c",),
    "cpp": ("cpp",),
    "rust": ("rust",),
    "python": ("python", "python-columns", "python-export", "python-pure"),
}
LANGS = tuple(LANG_ROWS)


def log(msg: str) -> None:
    print(f"bench: {msg}", file=sys.stderr, flush=True)


def streams(out: Path, scale: float) -> None:
    """Writes the streams unless they exist for this scale and this version of streams.py."""
    script = BENCH / "streams.py"
    stamp = out / "streams.stamp"
    want = f"scale={scale!r} streams.py={hashlib.sha256(script.read_bytes()).hexdigest()}\n"
    have = all((out / f"{s}{ext}").is_file() for s in STREAMS for ext in (".bin", ".json"))
    if have and stamp.is_file() and stamp.read_text() == want:
        return
    log(f"writing the streams (scale {scale}) into {shown(out)}/")
    subprocess.run(
        [sys.executable, "-m", "tests.bench.streams", "--out", str(out), "--scale", repr(scale)], check=True, cwd=ROOT
    )
    stamp.write_text(want)


def shown(path: Path) -> str:
    """path relative to the project when it is inside, else as given (--out may be anywhere)."""
    try:
        return str(path.relative_to(ROOT))
    except ValueError:
        return str(path)


def stale(target: Path, inputs: list[Path]) -> bool:
    if not target.is_file():
        return True
    t = target.stat().st_mtime
    return any(p.stat().st_mtime > t for p in inputs)


def compile_and_link(
    compiler: str, flags: list[str], sources: list[Path], objdir: Path, exe: Path, link: list[str]
) -> None:
    """Compiles each source with FLAGS into OBJDIR, one compiler per core at a time (the C++
    package's sources at -O2 took minutes as one serial compiler command), then links EXE."""
    objdir.mkdir(parents=True, exist_ok=True)
    objs = [objdir / (str(src.relative_to(ROOT)).replace("/", "_") + ".o") for src in sources]

    def one(pair: tuple[Path, Path]) -> None:
        subprocess.run([compiler, *flags, "-c", str(pair[0]), "-o", str(pair[1])], check=True)

    with ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        list(pool.map(one, zip(sources, objs)))  # the first failure raises here
    subprocess.run([compiler, *link, *map(str, objs), "-o", str(exe)], check=True)


def build_c(bindir: Path) -> Path:
    pkg = ROOT / "generated" / "c" / "mipcodec"
    sources = sorted((pkg / "src").glob("*.c")) + sorted((pkg / "src" / "sets").glob("*.c"))
    main = BENCH / "c" / "bench.c"
    exe = bindir / "bench-c"
    headers = sorted((pkg / "include").rglob("*.h")) + sorted((pkg / "src").glob("*.h"))
    if stale(exe, [main, *sources, *headers]):
        cc = os.environ.get("CC", "gcc")
        flags = ["-O2", "-std=c99", "-Wall", "-Wextra", "-Werror", "-I", str(pkg / "include"), "-I", str(pkg / "src")]
        log("building the C benchmark: " + shlex.join([cc, "-O2", "-std=c99", "..."]))
        compile_and_link(cc, flags, [main, *sources], bindir / "obj-c", exe, [])
    return exe


def build_cpp(bindir: Path) -> Path:
    inc = ROOT / "generated" / "cpp" / "mipcodec" / "include"
    # The library's sources (the C++ package compiles like a library: docs/packaging.md).
    sources = sorted((inc.parent / "src").rglob("*.cpp"))
    main = BENCH / "cpp" / "bench.cpp"
    exe = bindir / "bench-cpp"
    if stale(exe, [main, *sources, *sorted(inc.rglob("*.hpp"))]):
        cxx = os.environ.get("CXX", "g++")
        flags = ["-O2", "-std=c++17", "-pthread", "-Wall", "-Wextra", "-Werror", "-I", str(inc)]
        log("building the C++ benchmark: " + shlex.join([cxx, "-O2", "-std=c++17", "..."]))
        compile_and_link(cxx, flags, [main, *sources], bindir / "obj-cpp", exe, ["-pthread"])
    return exe


def build_rust() -> Path | None:
    """The Rust benchmark's binary (cargo build --release, out of the source tree), or None when
    its crate has not landed."""
    manifest = BENCH / "rust" / "Cargo.toml"
    if not manifest.is_file():
        return None
    target = ROOT / "build" / "bench" / "rust"
    log("building the Rust benchmark (cargo --release)")
    subprocess.run(
        ["cargo", "build", "--quiet", "--release", "--manifest-path", str(manifest)],
        check=True,
        env=dict(os.environ, CARGO_TARGET_DIR=str(target)),
    )
    return target / "release" / "mipcodec-bench"


def commands(langs: list[str], out: Path) -> dict[str, list[str] | str]:
    """The benchmark program of each language in langs (without its per-run options), or the
    reason it is skipped."""
    bindir = out / "bin"
    bindir.mkdir(parents=True, exist_ok=True)
    progs: dict[str, list[str] | str] = {}
    if "c" in langs:
        progs["c"] = [str(build_c(bindir))]
    if "cpp" in langs:
        progs["cpp"] = [str(build_cpp(bindir))]
    if "rust" in langs:
        exe = build_rust()
        progs["rust"] = [str(exe)] if exe else f"{(BENCH / 'rust' / 'Cargo.toml').relative_to(ROOT)} not found"
    if "python" in langs:
        script = BENCH / "python" / "bench.py"
        progs["python"] = [sys.executable, str(script)] if script.is_file() else f"{script.relative_to(ROOT)} not found"
    return progs


def timed_command(lang: str, prog: list[str], out: Path, passes: int, first: bool) -> list[str]:
    """The command of one timed process: every stream and mode, best of `passes` passes. Python's
    pure-Python fallback (about a minute per stream at scale 1) runs in the first process only."""
    if lang == "rust":
        return [*prog, str(out), str(passes)]
    if lang == "python":
        return [*prog, str(out), "--passes", str(passes), "--pure-passes", "1" if first else "0"]
    return [*prog, str(out), "--passes", str(passes)]


def counting_command(lang: str, prog: list[str], small: Path, stream: str, mode: str) -> list[str]:
    """One pass of one stream and mode (`none`: the program's fixed cost), for callgrind."""
    if lang == "rust":
        return [*prog, str(small), "1", stream, "--mode", mode]
    return [*prog, str(small), "--passes", "1", "--stream", stream, "--mode", mode]


CAPTURE = ROOT.parent / "shared" / "captures" / "mip_data.bin"


def build_clis(langs: list[str], out: Path) -> dict[str, list[str]]:
    """The decode command of each language in langs, built with release flags."""
    cmds: dict[str, list[str]] = {}
    for lang in ("c", "cpp"):
        if lang not in langs:
            continue
        build = out / "cli" / lang
        if not (build / "build.ninja").is_file():
            log(f"configuring the {lang} decode CLI (CMake Release) in {shown(build)}/")
            src = ROOT / "generated" / lang / "mipcodec"
            # The tools are OFF unless asked for (docs/packaging.md).
            cfg = ["cmake", "-G", "Ninja", "-S", str(src), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"]
            cfg.append("-DMIPCODEC_BUILD_TOOLS=ON")
            subprocess.run(cfg, check=True, stdout=subprocess.DEVNULL)
        subprocess.run(
            ["cmake", "--build", str(build), "--target", f"mipcodec_{lang}_decode"],
            check=True,
            stdout=subprocess.DEVNULL,
        )
        cmds[lang] = [str(build / "mipcodec-decode")]
    if "rust" in langs:
        target = ROOT / "build" / "rust" / "target"  # the one tests/lang/rust.sh builds
        manifest = ROOT / "generated" / "rust" / "mipcodec" / "Cargo.toml"
        log("building the Rust decode CLI (cargo --release)")
        subprocess.run(
            # --features serial as tests/lang/rust.sh builds them: the same target directory, so the
            # session tool it would otherwise replace keeps opening serial ports (pseudo-terminals)
            [
                "cargo",
                "build",
                "--quiet",
                "--release",
                "--manifest-path",
                str(manifest),
                "--bins",
                "--features",
                "serial",
            ],
            check=True,
            env=dict(os.environ, CARGO_TARGET_DIR=str(target)),
        )
        cmds["rust"] = [str(target / "release" / "mipcodec-decode")]
    if "python" in langs:
        ext = subprocess.run(
            [str(ROOT / "tests" / "lang" / "python.sh"), "ext"], check=True, capture_output=True, text=True
        ).stdout.split()
        where = next(d for d in ext if d.endswith("/mipcodec"))
        cmds["python"] = ["env", f"PYTHONPATH={where}", sys.executable, "-m", "mipcodec", "decode"]
    return cmds


def cli_inputs(out: Path, scale: float) -> list[tuple[str, Path]]:
    """accel_gyro.bin and the device capture repeated 200 x scale times (when it is there)."""
    inputs = [("accel_gyro", out / "accel_gyro.bin")]
    if CAPTURE.is_file():
        times = max(1, round(200 * scale))
        path = out / f"capture_x{times}.bin"
        if not path.is_file() or path.stat().st_size != times * CAPTURE.stat().st_size:
            path.write_bytes(CAPTURE.read_bytes() * times)
        inputs.append((path.stem, path))
    else:
        log(f"{CAPTURE} not found: the decode CLIs run on accel_gyro only")
    return inputs


def cli_bench(langs: list[str], out: Path, scale: float) -> tuple[list[dict[str, str]], bool]:
    """BENCH rows of the decode CLIs (with rss_kb=), and False when one failed or they disagree."""
    rows: list[dict[str, str]] = []
    ok = True
    cmds = build_clis(langs, out)
    result = out / "cli-output.jsonl"
    # GNU time measures each CLI's maximum resident memory and CPU time; without it, wait4's
    # figures (whose maximum RSS also counts the pages the child had from this process).
    timed = out / "cli-time.txt"
    timer = ["/usr/bin/time", "-f", "%M %U %S", "-o", str(timed)] if os.access("/usr/bin/time", os.X_OK) else []
    for stream, path in cli_inputs(out, scale):
        digests: dict[str, str] = {}
        for lang, cmd in cmds.items():
            with open(result, "wb") as sink:
                t0 = time.perf_counter()
                proc = subprocess.Popen([*timer, *cmd, str(path)], stdout=sink, cwd=ROOT)
                _pid, status, usage = os.wait4(proc.pid, 0)
                seconds = time.perf_counter() - t0
            if status != 0:
                log(f"{lang} decode CLI on {path.name}: exit status {status}")
                ok = False
                continue
            rss, cpu = usage.ru_maxrss, usage.ru_utime + usage.ru_stime
            if timer:
                fields = timed.read_text().split()
                rss, cpu = int(fields[0]), float(fields[1]) + float(fields[2])
            digest = hashlib.sha256()
            lines = skips = 0
            with open(result, "rb") as f:
                for block in iter(lambda: f.read(1 << 20), b""):
                    digest.update(block)
                    lines += block.count(b"\n")
                    skips += block.count(b'"skipped":')
            digests[lang] = digest.hexdigest()
            line = (
                f"BENCH lang={lang}-cli stream={stream} mode=decode-cli packets={lines - skips}"
                f" bytes={path.stat().st_size} seconds={seconds:.6f} rss_kb={rss} cpu={cpu:.6f}"
            )
            print(line, file=sys.stderr, flush=True)
            row = parse(line)
            assert row is not None
            rows.append(row)
        if len(set(digests.values())) > 1:
            log(f"the decode CLIs disagree on {path.name}: {digests}")
            ok = False
    result.unlink(missing_ok=True)
    timed.unlink(missing_ok=True)
    return rows, ok


def cli_table(rows: list[dict[str, str]]) -> str:
    """The decode CLIs per stream: wall seconds, MB/s of input, max RSS, the ratio to the fastest,
    and the same for CPU seconds (user + system: steadier than wall time on a shared machine)."""
    head = "| CLI | stream | seconds | MB/s | max RSS MB | x fastest | CPU s | x fastest CPU |"
    lines = [head, "|---|---|---:|---:|---:|---:|---:|---:|"]
    for stream in dict.fromkeys(r["stream"] for r in rows):
        mine = [r for r in rows if r["stream"] == stream]
        fastest = min(float(r["seconds"]) for r in mine)
        least = min(float(r.get("cpu", "0")) for r in mine)
        for r in mine:
            sec = float(r["seconds"])
            mbs = int(r["bytes"]) / sec / 1e6 if sec > 0 else 0.0
            rss = int(r.get("rss_kb", "0")) / 1024
            ratio = sec / fastest if fastest > 0 else 0.0
            cpu = float(r.get("cpu", "0"))
            cpu_ratio = f"{cpu / least:.2f}" if least > 0 else "-"
            lines.append(
                f"| {r['lang']} | {stream} | {sec:.2f} | {mbs:.1f} | {rss:.1f} | {ratio:.2f} | {cpu:.2f} | {cpu_ratio} |"
            )
    return "\n".join(lines)


# The translation units of the compile-cost section: (name, language, source relative to ROOT).
# minimal.c is the divisor of the "x C" columns.
COMPILE_UNITS = (
    ("minimal.c", "c", "tests/bench/compile/minimal.c"),
    ("minimal.cpp", "cpp", "tests/bench/compile/minimal.cpp"),
    ("getting_started.cpp", "cpp", "generated/cpp/mipcodec/examples/getting_started.cpp"),
    ("configure_and_stream.cpp", "cpp", "generated/cpp/mipcodec/examples/configure_and_stream.cpp"),
    ("session.cpp", "cpp", "generated/cpp/mipcodec/tools/session.cpp"),
)


def compile_command(lang: str, source: Path, obj: Path) -> list[str]:
    """The -O2 compile (no link) of one translation unit, with the package's strict warnings."""
    if lang == "c":
        pkg = ROOT / "generated" / "c" / "mipcodec"
        cc = os.environ.get("CC", "gcc")
        flags = ["-O2", "-std=c99", "-Wall", "-Wextra", "-Werror"]
        return [cc, *flags, "-I", str(pkg / "include"), "-c", str(source), "-o", str(obj)]
    pkg = ROOT / "generated" / "cpp" / "mipcodec"
    cxx = os.environ.get("CXX", "g++")
    flags = ["-O2", "-std=c++17", "-pthread", "-Wall", "-Wextra", "-pedantic", "-Wshadow", "-Werror"]
    return [cxx, *flags, "-I", str(pkg / "include"), "-c", str(source), "-o", str(obj)]


# The floor under minimal.cpp: a translation unit of nothing but the standard headers minimal.cpp
# reaches through the umbrella header (what any C++ API of std::string, std::vector and
# std::optional costs), generated at bench time from `g++ -H` so that it follows the package.
STD_UNIT = "std headers of minimal.cpp"
_STD_HEADER = re.compile(r"^\.+ \S*/c\+\+/[0-9]+/([a-z_]+)$")


def std_headers(h_output: str) -> list[str]:
    """The standard headers named in `g++ -H` output (its stderr): the extension-less names directly
    under the compiler's C++ include directory (not bits/ and the C headers under them), sorted."""
    return sorted({m.group(1) for line in h_output.splitlines() if (m := _STD_HEADER.match(line))})


def std_headers_unit(where: Path) -> Path | None:
    """Writes the STD_UNIT source (where/std_headers.cpp); None when g++ -H fails."""
    pkg = ROOT / "generated" / "cpp" / "mipcodec"
    cxx = os.environ.get("CXX", "g++")
    minimal = ROOT / "tests" / "bench" / "compile" / "minimal.cpp"
    proc = subprocess.run(
        [cxx, "-std=c++17", "-H", "-fsyntax-only", "-I", str(pkg / "include"), str(minimal)],
        capture_output=True,
        text=True,
    )
    names = std_headers(proc.stderr)
    if proc.returncode != 0 or not names:
        return None
    source = where / "std_headers.cpp"
    lines = [f"#include <{n}>" for n in names]
    source.write_text("\n".join([*lines, "", "int main() {", "    return 0;", "}", ""]))
    return source


def compile_bench(out: Path) -> tuple[list[dict], bool]:
    """One row per translation unit of COMPILE_UNITS (and STD_UNIT after minimal.cpp): CPU seconds
    and peak memory of its compile."""
    if not os.access("/usr/bin/time", os.X_OK):
        log("compile cost: needs GNU time (/usr/bin/time)")
        return [], False
    where = out / "compile"
    where.mkdir(parents=True, exist_ok=True)
    timed = where / "time.txt"
    rows: list[dict] = []
    ok = True
    units: list[tuple[str, str, Path]] = [(name, lang, ROOT / rel) for name, lang, rel in COMPILE_UNITS]
    floor = std_headers_unit(where)
    if floor is None:
        log("compile cost: g++ -H of minimal.cpp failed: no standard-header row")
        ok = False
    else:
        units.insert(2, (STD_UNIT, "cpp", floor))
    for name, lang, source in units:
        rel = str(source.relative_to(ROOT) if source.is_relative_to(ROOT) else source)
        obj = where / (re.sub(r"[^A-Za-z0-9_.]+", "_", name) + ".o")
        cmd = compile_command(lang, source, obj)
        log(f"compiling {rel} (-O2, one at a time)")
        proc = subprocess.run(["/usr/bin/time", "-f", "%U %S %M", "-o", str(timed), *cmd], cwd=ROOT)
        if proc.returncode != 0:
            log(f"compile cost: {rel} did not compile")
            ok = False
            continue
        user, system, rss = timed.read_text().split()[-3:]
        rows.append(
            {
                "lang": "compile",
                "unit": name,
                "source": rel,
                "cpu_seconds": round(float(user) + float(system), 2),
                "peak_rss_kb": int(rss),
            }
        )
    timed.unlink(missing_ok=True)
    return rows, ok


def compile_table(rows: list[dict]) -> str:
    """The compile-cost rows: CPU s, peak MB, and both as multiples of minimal.c's."""
    base = next((r for r in rows if r["unit"] == COMPILE_UNITS[0][0]), None)
    floor = next((r for r in rows if r["unit"] == STD_UNIT), None)
    head = "| translation unit | CPU s | peak MB | x C CPU | x C memory | x std headers CPU |"
    lines = [head, "|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        cpu, mb = r["cpu_seconds"], r["peak_rss_kb"] / 1024
        x_cpu = f"{cpu / base['cpu_seconds']:.0f}" if base and base["cpu_seconds"] > 0 else "-"
        x_mem = f"{r['peak_rss_kb'] / base['peak_rss_kb']:.1f}" if base and base["peak_rss_kb"] > 0 else "-"
        cpp = r["source"].endswith(".cpp") if "source" in r else r["unit"].endswith(".cpp")
        x_std = f"{cpu / floor['cpu_seconds']:.1f}" if floor and floor["cpu_seconds"] > 0 and cpp else "-"
        lines.append(f"| {r['unit']} | {cpu:.2f} | {mb:.0f} | {x_cpu} | {x_mem} | {x_std} |")
    return "\n".join(lines)


def dataset_bench(out: Path, size: int) -> tuple[str, bool]:
    """Section 8 (issue 41): the dataset export's throughput on one core, its CPU time and peak
    memory, the dataset's size over the raw logs', and Spark's throughput with 1 and 2 local
    workers (scaling ratio)."""
    import importlib
    import subprocess
    import tempfile

    if str(ROOT) not in sys.path:  # run as a script: the tests package from the repository's root
        sys.path.insert(0, str(ROOT))
    from tests.bench import spark_bench

    paths = spark_bench.fleet_logs(size)
    raw = sum(os.path.getsize(p) for p in paths)
    # The command users run, `python -m mipcodec export --dataset`, on the package with its C
    # accelerator (spark_bench.package_dir), in a child process: its wall and CPU time.
    env = dict(os.environ, PYTHONPATH=str(spark_bench.package_dir()))
    with tempfile.TemporaryDirectory(prefix="dataset-bench-", dir=out) as tmp:
        t0 = time.perf_counter()
        child = subprocess.Popen(
            [sys.executable, "-m", "mipcodec", "export", "--dataset", tmp, *paths],
            env=env,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
        )
        errors = child.stderr.read() if child.stderr else b""
        _pid, status, usage = os.wait4(child.pid, 0)  # this child's own CPU time and peak memory
        child.returncode = os.waitstatus_to_exitcode(status)
        seconds = time.perf_counter() - t0
        if child.returncode != 0:
            raise subprocess.CalledProcessError(child.returncode, child.args, stderr=errors)
        cpu = usage.ru_utime + usage.ru_stime
        peak = usage.ru_maxrss * 1024  # kilobytes on Linux
        stored = sum(f.stat().st_size for f in Path(tmp).rglob("*") if f.is_file())
    record: dict = {
        "logs": len(paths),
        "raw_bytes": raw,
        "export_seconds": seconds,
        "export_cpu_seconds": cpu,
        "export_mb_s": raw / seconds / 1e6,
        "export_mb_per_cpu_s": raw / cpu / 1e6,
        "export_peak_bytes": peak,
        "dataset_bytes": stored,
        "dataset_over_raw": stored / raw,
    }
    lines = [
        ("what", "figure"),
        ("raw logs", f"{len(paths)} logs, {raw / 1e6:.1f} MB"),
        ("export --dataset, 1 core", f"{record['export_mb_s']:.2f} MB/s ({seconds:.1f} s)"),
        ("export --dataset, per CPU second", f"{record['export_mb_per_cpu_s']:.2f} MB ({cpu:.1f} s CPU)"),
        ("export --dataset, peak memory", f"{peak / 1e6:.0f} MB (maximum resident set)"),
        ("dataset / raw logs", f"{stored / 1e6:.1f} MB, {record['dataset_over_raw']:.2f}"),
    ]
    ok = True
    try:
        importlib.import_module("pyspark")
    except ImportError:
        lines.append(("Spark", "skipped: pyspark not installed (tools/bootstrap installs requirements-spark.txt)"))
    else:
        try:
            spark = spark_bench.measure(paths, (1, 2))
        except Exception as e:  # a Spark failure is a failed section, reported on one line
            lines.append(("Spark", f"failed: {type(e).__name__}: {str(e).splitlines()[0] if str(e) else ''}"))
            ok = False
        else:
            record["spark"] = spark
            for r in spark["runs"]:
                every = ", ".join(f"{t:.1f}" for t in r["all_seconds"])
                lines.append(
                    (f"Spark local[{r['workers']}]", f"{r['mb_s']:.2f} MB/s ({r['seconds']:.1f} s; runs {every} s)")
                )
            lines.append(("Spark scaling local[2] / local[1]", f"{spark['scaling']:.2f}"))
    (out / "dataset.json").write_text(json.dumps(record, indent=1) + "\n")
    return markdown(lines, 1), ok


def parse(line: str) -> dict[str, str] | None:
    if not line.startswith("BENCH "):
        return None
    fields = dict(kv.split("=", 1) for kv in line.split()[1:] if "=" in kv)
    need = ("lang", "stream", "mode", "packets", "bytes", "seconds")
    return fields if all(k in fields for k in need) else None


def run(name: str, cmd: list[str], process: int) -> tuple[list[dict[str, str]], bool]:
    """The BENCH rows of one process, each tagged process=N, and False when it failed."""
    log(f"running {name} (process {process + 1}): {shlex.join(cmd)}")
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.PIPE, text=True)
    rows = []
    assert proc.stdout is not None
    for line in proc.stdout:
        row = parse(line.strip())
        if row:
            row["process"] = str(process)
            rows.append(row)
            print(line.rstrip(), file=sys.stderr, flush=True)
        elif line.strip():
            print(f"  {name}: {line.rstrip()}", file=sys.stderr, flush=True)
    ok = proc.wait() == 0
    log(f"{name} (process {process + 1}) took {time.perf_counter() - t0:.1f} s")
    if not ok:
        log(f"{name}: exit status {proc.returncode}")
    if not rows:
        log(f"{name}: no BENCH lines")
        ok = False
    return rows, ok


# The modes of a stream in table order; other modes (CLIs, round trips) after them.
MODE_RANK = {
    "bulk": 0,
    "frame": 1,
    "decode": 2,
    "decode-straight": 2.5,
    "decode-cached": 2.5,
    "session-ingest": 3,
    "copy-per-packet": 4,
    "csv": 5,
    "parquet": 6,
}


def bulk_lang(lang: str) -> str:
    """The language whose process measured bulk for a row of `lang`: python-columns and
    python-export rows come from the `python` process (python-pure has its own)."""
    return "python" if lang in ("python-columns", "python-export") else lang


def spread_pct(values: list[float]) -> float | None:
    """Half the range of `values` over their median, in percent (None for fewer than two)."""
    if len(values) < 2:
        return None
    mid = statistics.median(values)
    return (max(values) - min(values)) / 2 / mid * 100 if mid > 0 else None


def aggregate(rows: list[dict[str, str]]) -> list[dict]:
    """One record per (lang, stream, mode) from the BENCH rows of every process (key `process`,
    "0" when absent): seconds = the median of the processes' figures (each the best of its passes),
    processes = those figures in process order, spread_pct; bulk_fraction = the median over the
    processes of bulk's seconds over the row's seconds in the same process and stream (and its
    spread); decode_over_frame (decode rows) = the same for the language's frame row. Other keys of
    the BENCH line (rss_kb, cpu, ...) are kept from the first process."""
    groups: dict[tuple[str, str, str], list[dict[str, str]]] = {}
    for r in rows:
        groups.setdefault((r["lang"], r["stream"], r["mode"]), []).append(r)
    per_process = {
        (lang, stream, mode, r.get("process", "0")): float(r["seconds"])
        for (lang, stream, mode), rs in groups.items()
        for r in rs
    }

    def ratios(base: tuple[str, str, str], rs: list[dict[str, str]]) -> list[float]:
        out = []
        for r in rs:
            b = per_process.get((*base, r.get("process", "0")))
            s = float(r["seconds"])
            if b is not None and b > 0 and s > 0:
                out.append(b / s)
        return out

    records = []
    for (lang, stream, mode), rs in groups.items():
        rs = sorted(rs, key=lambda r: int(r.get("process", "0")))
        secs = [float(r["seconds"]) for r in rs]
        rec: dict = {k: v for k, v in rs[0].items() if k != "process"}
        rec.update(
            lang=lang,
            stream=stream,
            mode=mode,
            packets=int(rs[0]["packets"]),
            bytes=int(rs[0]["bytes"]),
            seconds=statistics.median(secs),
        )
        for key in ("rss_kb",):
            if key in rec:
                rec[key] = int(rec[key])
        if "cpu" in rec:
            rec["cpu"] = float(rec["cpu"])
        rec["processes"] = secs
        spread = spread_pct(secs)
        if spread is not None:
            rec["spread_pct"] = spread
        fractions = ratios((bulk_lang(lang), stream, "bulk"), rs)
        if fractions:
            rec["bulk_fraction"] = statistics.median(fractions)
            s = spread_pct(fractions)
            if s is not None:
                rec["bulk_fraction_spread_pct"] = s
        if mode == "decode" or mode.startswith("decode-"):
            over = ratios((lang, stream, "frame"), rs)
            if over:
                rec["decode_over_frame"] = statistics.median(over)
        records.append(rec)
    return records


def order(records: list[dict], langs: list[str]) -> list[dict]:
    """Records in table order: language (--langs order), stream, mode."""
    names = [row for lang in langs for row in LANG_ROWS.get(lang, (lang,))]
    lang_rank = {name: i for i, name in enumerate(names)}
    stream_rank = {s: i for i, s in enumerate(STREAMS + ("loopback-tcp",))}

    def key(r: dict):
        return (
            lang_rank.get(r["lang"], len(names)),
            r["lang"],
            stream_rank.get(r["stream"], len(STREAMS) + 1),
            r["stream"],
            MODE_RANK.get(r["mode"], 9),
            r["mode"],
        )

    return sorted(records, key=key)


def pct(value: float | None) -> str:
    return "-" if value is None else f"±{value:.0f}%" if value >= 1 else f"±{value:.1f}%"


def table(records: list[dict], langs: list[str]) -> str:
    """The main table (records of aggregate(); rows without seconds, such as instruction counts
    alone, are left out)."""
    seconds_of = {(r["lang"], r["stream"], r["mode"]): r["seconds"] for r in records if r.get("seconds")}
    with_instr = any("instructions_per_packet" in r for r in records)
    head = ["language", "stream", "mode", "Mpkt/s", "GB/s", "±", "x bulk", "±", "decode/frame", "session"]
    if with_instr:
        head.append("instr/pkt")
    lines = [tuple(head)]
    for r in order(records, langs):
        seconds = r.get("seconds")
        if not seconds:
            continue
        pps = r["packets"] / seconds / 1e6 if seconds > 0 else 0.0
        gbs = r["bytes"] / seconds / 1e9 if seconds > 0 else 0.0
        frac = r.get("bulk_fraction")
        dof = r.get("decode_over_frame")
        cells = [
            r["lang"],
            r["stream"],
            r["mode"],
            f"{pps:.2f}",
            f"{gbs:.3f}" if gbs < 1 else f"{gbs:.2f}",
            pct(r.get("spread_pct")),
            "-" if frac is None else f"{frac:.2f}" if frac >= 0.1 else f"{frac:.2g}",
            pct(r.get("bulk_fraction_spread_pct")) if frac is not None else "",
            "" if dof is None else f"{dof:.2f}",
            session_note(r, seconds_of),
        ]
        if with_instr:
            ipp = r.get("instructions_per_packet")
            cells.append("" if ipp is None else f"{ipp:.0f}")
        lines.append(tuple(cells))
    return markdown(lines, left=3)


def markdown(lines: list[tuple[str, ...]], left: int) -> str:
    """A markdown table: the first `left` columns left-aligned, the others right-aligned."""
    widths = [max(len(line[i]) for line in lines) for i in range(len(lines[0]))]
    out = []
    for n, line in enumerate(lines):
        cells = [c.ljust(w) if i < left else c.rjust(w) for i, (c, w) in enumerate(zip(line, widths))]
        out.append("| " + " | ".join(cells) + " |")
        if n == 0:
            out.append(
                "|" + "|".join("-" * (w + 2) if i < left else "-" * (w + 1) + ":" for i, w in enumerate(widths)) + "|"
            )
    return "\n".join(out)


def session_note(r: dict, seconds_of: dict[tuple[str, str, str], float]) -> str:
    """The session column: session-ingest as a fraction of the same language's decode rate on the
    same stream (same packets: the ratio of the times), session-roundtrip as round trips per
    second and microseconds per round trip."""
    seconds = float(r["seconds"])
    if r["mode"] == "session-ingest":
        d = seconds_of.get((r["lang"], r["stream"], "decode"))
        return f"{d / seconds:.2f} x decode" if d and seconds > 0 else "-"
    if r["mode"] == "session-roundtrip" and seconds > 0 and int(r["packets"]) > 0:
        n = int(r["packets"])
        return f"{n / seconds:,.0f}/s, {seconds / n * 1e6:.1f} us each"
    return ""


# ---- instructions per packet (callgrind) ----

COUNT_LANGS = ("c", "cpp", "rust")
COUNT_STREAMS = ("accel_gyro", "mixed")
COUNT_MODES = ("frame", "decode")
# The other decode paths of issue 38, counted beside `decode` (each language's `decode` row is the path
# it recommends for throughput: C's layout cache, C++'s and Rust's decode_field), and the session's
# data ingest (its target is a fraction of `decode`: the instructions say what the session adds).
COUNT_EXTRA_MODES = {
    "c": ("decode-straight", "session-ingest"),
    "cpp": ("decode-cached", "decode-straight", "session-ingest"),
    "rust": ("decode-cached", "decode-straight", "session-ingest"),
}
COUNT_SCALE = 0.01


def callgrind_total(stderr: str) -> int:
    """The instruction count of a `valgrind --tool=callgrind` run from its summary on stderr
    (`==PID== Collected : N`)."""
    m = re.search(r"^==\d+== Collected\s*:\s*(\d+)\s*$", stderr, re.MULTILINE)
    if not m:
        raise ValueError("no 'Collected :' line in callgrind's output")
    return int(m.group(1))


def per_packet(total: int, fixed: int, packets: int) -> float:
    """Instructions per packet: the run's count minus the program's fixed cost, over the packets."""
    if packets <= 0:
        raise ValueError("no packets")
    return (total - fixed) / packets


def count_instructions(cmd: list[str]) -> int:
    proc = subprocess.run(
        ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *cmd],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    if proc.returncode != 0:
        raise RuntimeError(f"{shlex.join(cmd)} under callgrind: exit status {proc.returncode}\n{proc.stderr[-2000:]}")
    return callgrind_total(proc.stderr)


def instructions(progs: dict[str, list[str] | str], out: Path, streams_: tuple[str, ...]) -> list[dict]:
    """Instructions per packet of frame and decode for C, C++ and Rust on the 1%-scale streams."""
    small = out / "small"
    small.mkdir(parents=True, exist_ok=True)
    streams(small, COUNT_SCALE)
    records = []
    for lang in COUNT_LANGS:
        prog = progs.get(lang)
        if not isinstance(prog, list):
            continue
        for stream in streams_:
            side = json.loads((small / f"{stream}.json").read_text())
            fixed = count_instructions(counting_command(lang, prog, small, stream, "none"))
            for mode in COUNT_MODES + COUNT_EXTRA_MODES.get(lang, ()):
                total = count_instructions(counting_command(lang, prog, small, stream, mode))
                ipp = per_packet(total, fixed, side["packets"])
                log(
                    f"{lang} {stream} {mode}: {total} - {fixed} instructions over {side['packets']} packets = {ipp:.1f}"
                )
                records.append(
                    {
                        "lang": lang,
                        "stream": stream,
                        "mode": mode,
                        "instructions": total,
                        "instructions_fixed": fixed,
                        "instructions_packets": side["packets"],
                        "instructions_per_packet": ipp,
                    }
                )
    return records


def merge_instructions(records: list[dict], counts: list[dict]) -> list[dict]:
    """The instruction counts added to the timed records of the same lang, stream and mode; a count
    without a timed record becomes a record of its own (packets and bytes of the counted stream,
    seconds None)."""
    by_key = {(r["lang"], r["stream"], r["mode"]): r for r in records}
    out = list(records)
    for c in counts:
        r = by_key.get((c["lang"], c["stream"], c["mode"]))
        if r is None:
            r = {"lang": c["lang"], "stream": c["stream"], "mode": c["mode"], "seconds": None}
            r["packets"] = c["instructions_packets"]
            r["bytes"] = None
            out.append(r)
        r.update({k: v for k, v in c.items() if k.startswith("instructions")})
    return out


def previous(results: Path) -> list[dict]:
    """The rows of an earlier results.json without their instruction counts (rows that held only
    counts dropped), or nothing when it cannot be read."""
    try:
        rows = json.loads(results.read_text())
    except (OSError, ValueError):
        return []
    if not isinstance(rows, list):
        return []
    kept = []
    for r in rows:
        if not isinstance(r, dict) or not {"lang", "stream", "mode"} <= set(r) or r.get("seconds") is None:
            continue
        kept.append({k: v for k, v in r.items() if not k.startswith("instructions")})
    return kept


def instructions_table(counts: list[dict]) -> str:
    lines = [("language", "stream", "mode", "instructions/packet", "packets", "total", "fixed")]
    for c in counts:
        lines.append(
            (
                c["lang"],
                c["stream"],
                c["mode"],
                f"{c['instructions_per_packet']:.0f}",
                f"{c['instructions_packets']:,}",
                f"{c['instructions']:,}",
                f"{c['instructions_fixed']:,}",
            )
        )
    return markdown(lines, left=3)


def machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} CPUs, {platform.system()} {platform.release()}"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--langs", default=",".join(LANGS), help="comma-separated subset of c,cpp,rust,python")
    ap.add_argument("--scale", type=float, default=1.0, help="stream size factor (streams.py --scale)")
    ap.add_argument("--passes", type=int, default=5, help="passes per measurement in each process, best kept")
    ap.add_argument("--processes", type=int, default=5, help="processes per benchmark (figure: their median)")
    ap.add_argument(
        "--python-processes",
        type=int,
        help="processes of the Python benchmark (default: --processes; at scale 1 each takes minutes)",
    )
    ap.add_argument("--out", default=str(ROOT / "build" / "bench"), help="stream and binary directory")
    ap.add_argument("--json", help="where the rows go (default: OUT/results.json)")
    ap.add_argument("--no-cli", action="store_true", help="leave out the decode CLIs")
    ap.add_argument("--no-flood", action="store_true", help="leave out the session tools under a noise flood")
    ap.add_argument("--no-compile", action="store_true", help="leave out the compile-cost section")
    ap.add_argument("--compile-only", action="store_true", help="only measure the compile cost (issue 39)")
    ap.add_argument("--no-dataset", action="store_true", help="leave out the dataset and Spark section (issue 41)")
    ap.add_argument("--dataset-size", type=int, default=200 << 20, help="bytes of simulated fleet logs (section 8)")
    ap.add_argument(
        "--instructions", action="store_true", help="also count instructions per packet (valgrind --tool=callgrind)"
    )
    ap.add_argument("--instructions-only", action="store_true", help="only count instructions per packet")
    ap.add_argument(
        "--instruction-streams",
        default=",".join(COUNT_STREAMS),
        help="streams whose instructions are counted (default accel_gyro,mixed)",
    )
    args = ap.parse_args()
    langs = [x for x in (s.strip() for s in args.langs.split(",")) if x]
    unknown = [x for x in langs if x not in LANGS]
    if unknown or not langs:
        ap.error(f"unknown language(s) {','.join(unknown)}: choose from {','.join(LANGS)}")
    if args.passes < 1 or args.processes < 1 or (args.python_processes is not None and args.python_processes < 1):
        ap.error("--passes, --processes and --python-processes must be at least 1")
    count_streams = tuple(x for x in args.instruction_streams.split(",") if x)
    if any(x not in STREAMS for x in count_streams):
        ap.error(f"--instruction-streams: choose from {','.join(STREAMS)}")
    counting = args.instructions or args.instructions_only
    if counting and not shutil.which("valgrind"):
        ap.error("--instructions needs valgrind (tools/bootstrap --ci installs it)")
    out = Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    results = Path(args.json) if args.json else out / "results.json"
    if args.compile_only:
        crows, ok = compile_bench(out)
        (out / "compile.json").write_text(json.dumps(crows, indent=1) + "\n")
        print(f"Compile cost (issue 39): {machine()}; load average {' '.join(f'{x:.1f}' for x in os.getloadavg())}\n")
        print(compile_table(crows))
        print(f"\nrows written to {shown(out / 'compile.json')}")
        return 0 if ok else 1
    timing = not args.instructions_only
    if timing:
        streams(out, args.scale)
    failed: list[str] = []
    skipped: list[str] = []
    rows: list[dict[str, str]] = []
    try:
        progs = commands(langs, out)
    except subprocess.CalledProcessError as e:
        log(f"build failed: {e}")
        return 1
    for name, prog in progs.items():
        if isinstance(prog, str):
            log(f"{name}: skipped ({prog}; its benchmark has not landed)")
            skipped.append(name)
    python_processes = args.processes if args.python_processes is None else args.python_processes
    for process in range(max(args.processes, python_processes) if timing else 0):
        for name, prog in progs.items():
            if isinstance(prog, str) or name in failed:
                continue
            if process >= (python_processes if name == "python" else args.processes):
                continue
            cmd = timed_command(name, prog, out, args.passes, process == 0)
            try:
                got, ok = run(name, cmd, process)
            except OSError as e:
                got, ok = [], False
                log(f"{name}: cannot run: {e}")
            rows += got
            if not ok:
                failed.append(name)
    records = aggregate(rows)
    counts: list[dict] = []
    if counting:
        try:
            t0 = time.perf_counter()
            counts = instructions(progs, out, count_streams)
            log(f"instruction counts took {time.perf_counter() - t0:.1f} s")
        except (RuntimeError, ValueError, OSError, subprocess.CalledProcessError) as e:
            log(f"instruction counts: {e}")
            failed.append("instructions")
        records = merge_instructions(records, counts)
    cli_rows: list[dict[str, str]] = []
    if timing and not args.no_cli:
        try:
            cli_rows, ok = cli_bench(langs, out, args.scale)
        except (subprocess.CalledProcessError, OSError) as e:
            log(f"decode CLIs: {e}")
            ok = False
        if not ok:
            failed.append("decode-cli")
    compile_rows: list[dict] = []
    if timing and not args.no_compile:
        compile_rows, ok = compile_bench(out)
        (out / "compile.json").write_text(json.dumps(compile_rows, indent=1) + "\n")
        if not ok:
            failed.append("compile")
    if args.instructions_only and results.is_file() and not failed:
        # the timed rows of the last `make bench` keep their place; the counts replace the old ones
        records = merge_instructions(previous(results), counts)
    results.parent.mkdir(parents=True, exist_ok=True)
    results.write_text(json.dumps(order(records, langs) + aggregate(cli_rows) + compile_rows, indent=1) + "\n")
    if timing:
        print(
            f"Benchmarks (issues 8 and 30): {machine()}; each figure the median of {args.processes}"
            f" processes ({python_processes} for Python), each the best of {args.passes} passes;"
            f" scale {args.scale}; load average"
            f" {' '.join(f'{x:.1f}' for x in os.getloadavg())}"
        )
        print()
        print(table(records, langs))
    if counts:
        print(
            f"\nInstructions per packet (valgrind --tool=callgrind, one pass minus --mode none,"
            f" {COUNT_SCALE:g}-scale streams):\n"
        )
        print(instructions_table(counts))
    if cli_rows:
        print("\nDecode CLIs (one run each, output to a file):\n")
        print(cli_table(cli_rows))
    if compile_rows:
        print("\nCompile cost (issue 39: -O2, one translation unit at a time, no link):\n")
        print(compile_table(compile_rows))
    print(f"\nrows written to {shown(results)}")
    if timing and not args.no_flood:
        print()
        sys.stdout.flush()
        flood = [sys.executable, "-m", "tests.bench.session_flood", "--langs", ",".join(langs)]
        flood += ["--json", str(out / "session_flood.json")]
        if subprocess.run(flood, cwd=ROOT).returncode != 0:
            failed.append("session-flood")
    if timing and not args.no_dataset:
        print(f"\nDataset export and Spark (issue 41; simulated fleet, {machine()}):\n")
        sys.stdout.flush()
        text, ok = dataset_bench(out, args.dataset_size)
        print(text)
        if not ok:
            failed.append("dataset")
        print(f"\nFleet generator and single-log CSV export (issue 50; tests/bench/log_speed.py, {machine()}):\n")
        sys.stdout.flush()
        from tests.bench import log_speed  # (dataset_bench put the repository's root on sys.path)

        speed = log_speed.measure(out)  # the export takes the generator's 16 MiB log
        (out / "log_speed.json").write_text(json.dumps(speed, indent=1) + "\n")
        print(markdown([("what", "figure"), *log_speed.lines(speed)], 1))
    if skipped:
        print(f"\nskipped: {', '.join(skipped)}")
    if failed:
        print(f"\nFAILED: {', '.join(failed)}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
