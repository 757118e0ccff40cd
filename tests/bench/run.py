"""Builds and runs the benchmarks of every language (issue 8) and prints one table.

    python tests/bench/run.py [--langs c,cpp,rust,python] [--scale 1.0] [--passes 5]

`make bench` runs it (BENCH_ARGS="..." passes arguments). Steps:
  1. the streams of tests/bench/streams.py in build/bench/ (written again only when missing, when
     --scale changed or when streams.py changed);
  2. each language's benchmark, built with release flags into build/bench/bin/ (C: gcc -O2,
     C++: g++ -O2; Rust: cargo --release; Python: the package as installed in this interpreter);
  3. their `BENCH lang=.. stream=.. mode=.. packets=N bytes=B seconds=S` lines, collected into a
     table: language, stream, mode, Mpkt/s, MB/s and the ratio to the baseline (a memchr+memcpy
     pass in C over the same bytes, measured in the same run) so figures from a noisy machine
     can be compared; the last column gives, for mode session-ingest, its ratio to the same
     language's decode of the same stream, and for session-roundtrip (stream loopback-tcp,
     packets = round trips) the round trips per second and microseconds per round trip.
  4. each language's decode CLI (lang=<lang>-cli mode=decode-cli, issue 22), built with release
     flags into build/bench/cli/ (C and C++: CMake Release; Rust: cargo --release in build/rust/target,
     shared with tests/lang/rust.sh; Python: the package with its C accelerator, build/python/ext/),
     run on accel_gyro.bin and on the device capture (../shared/captures/mip_data.bin, when there)
     repeated 200 x --scale times, output to a file: wall time and maximum resident memory of each
     process (wait4), and the outputs must be byte-identical across languages (--no-cli skips it).
A language whose benchmark directory does not exist is skipped with a message. The exit status
is non-zero when a benchmark failed to build or run, or reported counts that do not match the
stream's sidecar (each benchmark checks them and exits non-zero).
"""

from __future__ import annotations

import argparse
import hashlib
import os
import platform
import shlex
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BENCH = ROOT / "tests" / "bench"
STREAMS = ("accel_gyro", "mixed", "accel_gyro_garbage", "mixed_garbage")
LANGS = ("c", "cpp", "rust", "python")
# Row order of the table: the baseline first, then the languages in --langs order.
LANG_ROWS = {
    "c": ("c",),
    "cpp": ("cpp",),
    "rust": ("rust",),
    "python": ("python", "python-columns", "python-export", "python-pure"),
}


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


def build_c(bindir: Path) -> Path:
    pkg = ROOT / "generated" / "c" / "mipcodec"
    sources = sorted((pkg / "src").glob("*.c")) + sorted((pkg / "src" / "sets").glob("*.c"))
    main = BENCH / "c" / "bench.c"
    exe = bindir / "bench-c"
    headers = sorted((pkg / "include").rglob("*.h")) + sorted((pkg / "src").glob("*.h"))
    if stale(exe, [main, *sources, *headers]):
        cc = os.environ.get("CC", "gcc")
        cmd = [cc, "-O2", "-std=c99", "-Wall", "-Wextra", "-Werror", "-I", str(pkg / "include")]
        cmd += ["-I", str(pkg / "src"), str(main), *map(str, sources), "-o", str(exe)]
        log("building the C benchmark: " + shlex.join([cc, "-O2", "-std=c99", "..."]))
        subprocess.run(cmd, check=True)
    return exe


def build_cpp(bindir: Path) -> Path:
    inc = ROOT / "generated" / "cpp" / "mipcodec" / "include"
    main = BENCH / "cpp" / "bench.cpp"
    exe = bindir / "bench-cpp"
    if stale(exe, [main, *sorted(inc.rglob("*.hpp"))]):
        cxx = os.environ.get("CXX", "g++")
        cmd = [
            cxx,
            "-O2",
            "-std=c++17",
            "-pthread",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-I",
            str(inc),
            str(main),
            "-o",
            str(exe),
        ]
        log("building the C++ benchmark: " + shlex.join([cxx, "-O2", "-std=c++17", "..."]))
        subprocess.run(cmd, check=True)
    return exe


def commands(langs: list[str], out: Path, passes: int) -> list[tuple[str, list[str] | None, str]]:
    """(name, command or None when skipped, skip reason) per benchmark to run."""
    bindir = out / "bin"
    bindir.mkdir(parents=True, exist_ok=True)
    runs: list[tuple[str, list[str] | None, str]] = []
    c_args = [str(out), "--passes", str(passes)]
    # The C benchmark also measures the baseline; without C in --langs it measures only that.
    runs.append(("c" if "c" in langs else "baseline", [str(build_c(bindir)), *c_args], ""))
    if "c" not in langs:
        runs[-1][1].append("--baseline-only")
    if "cpp" in langs:
        runs.append(("cpp", [str(build_cpp(bindir)), *c_args], ""))
    if "rust" in langs:
        manifest = BENCH / "rust" / "Cargo.toml"
        if manifest.is_file():
            # the build stays out of the source tree (CARGO_TARGET_DIR, set in run())
            cmd = ["cargo", "run", "--quiet", "--release", "--manifest-path", str(manifest), "--", str(out)]
            runs.append(("rust", cmd, ""))
        else:
            runs.append(("rust", None, f"{manifest.relative_to(ROOT)} not found"))
    if "python" in langs:
        script = BENCH / "python" / "bench.py"
        if script.is_file():
            runs.append(("python", [sys.executable, str(script), str(out)], ""))
        else:
            runs.append(("python", None, f"{script.relative_to(ROOT)} not found"))
    return runs


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
            cfg = ["cmake", "-G", "Ninja", "-S", str(src), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"]
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
            ["cargo", "build", "--quiet", "--release", "--manifest-path", str(manifest), "--bins"],
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


def parse(line: str) -> dict[str, str] | None:
    if not line.startswith("BENCH "):
        return None
    fields = dict(kv.split("=", 1) for kv in line.split()[1:] if "=" in kv)
    need = ("lang", "stream", "mode", "packets", "bytes", "seconds")
    return fields if all(k in fields for k in need) else None


def run(name: str, cmd: list[str]) -> tuple[list[dict[str, str]], bool]:
    log(f"running {name}: {shlex.join(cmd)}")
    env = dict(os.environ, CARGO_TARGET_DIR=str(ROOT / "build" / "bench" / "rust"))
    proc = subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.PIPE, text=True, env=env)
    rows = []
    assert proc.stdout is not None
    for line in proc.stdout:
        row = parse(line.strip())
        if row:
            rows.append(row)
            print(line.rstrip(), file=sys.stderr, flush=True)
        elif line.strip():
            print(f"  {name}: {line.rstrip()}", file=sys.stderr, flush=True)
    ok = proc.wait() == 0
    if not ok:
        log(f"{name}: exit status {proc.returncode}")
    if not rows:
        log(f"{name}: no BENCH lines")
        ok = False
    return rows, ok


def table(rows: list[dict[str, str]], langs: list[str]) -> str:
    base: dict[str, float] = {}
    for r in rows:
        if r["lang"] == "baseline" and r["mode"] == "copy":
            base[r["stream"]] = int(r["bytes"]) / float(r["seconds"])
    order = ["baseline"] + [row for lang in langs for row in LANG_ROWS[lang]]
    lang_rank = {name: i for i, name in enumerate(order)}
    mode_rank = {"copy": 0, "frame": 1, "decode": 2, "session-ingest": 3, "csv": 4, "parquet": 5}
    stream_rank = {s: i for i, s in enumerate(STREAMS + ("loopback-tcp",))}
    decode = {(r["lang"], r["stream"]): float(r["seconds"]) for r in rows if r["mode"] == "decode"}

    def key(r: dict[str, str]):
        return (
            lang_rank.get(r["lang"], len(order)),
            r["lang"],
            stream_rank.get(r["stream"], len(STREAMS)),
            r["stream"],
            mode_rank.get(r["mode"], 9),
        )

    head = ("language", "stream", "mode", "Mpkt/s", "MB/s", "x baseline", "session")
    lines = [head]
    for r in sorted(rows, key=key):
        seconds = float(r["seconds"])
        pps = int(r["packets"]) / seconds / 1e6 if seconds > 0 else 0.0
        bps = int(r["bytes"]) / seconds if seconds > 0 else 0.0
        ratio = f"{bps / base[r['stream']]:.2f}" if r["stream"] in base and base[r["stream"]] > 0 else "-"
        lines.append(
            (r["lang"], r["stream"], r["mode"], f"{pps:.2f}", f"{bps / 1e6:.0f}", ratio, session_note(r, decode))
        )
    widths = [max(len(line[i]) for line in lines) for i in range(len(head))]
    out = []
    for n, line in enumerate(lines):
        cells = [c.ljust(w) if i < 3 else c.rjust(w) for i, (c, w) in enumerate(zip(line, widths))]
        out.append("| " + " | ".join(cells) + " |")
        if n == 0:
            out.append(
                "|" + "|".join("-" * (w + 2) if i < 3 else "-" * (w + 1) + ":" for i, w in enumerate(widths)) + "|"
            )
    return "\n".join(out)


def session_note(r: dict[str, str], decode: dict[tuple[str, str], float]) -> str:
    """The session column: session-ingest as a fraction of the same language's decode rate on the
    same stream (same packets: the ratio of the times), session-roundtrip as round trips per
    second and microseconds per round trip."""
    seconds = float(r["seconds"])
    if r["mode"] == "session-ingest":
        d = decode.get((r["lang"], r["stream"]))
        return f"{d / seconds:.2f} x decode" if d and seconds > 0 else "-"
    if r["mode"] == "session-roundtrip" and seconds > 0 and int(r["packets"]) > 0:
        n = int(r["packets"])
        return f"{n / seconds:,.0f}/s, {seconds / n * 1e6:.1f} us each"
    return ""


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
    ap.add_argument("--passes", type=int, default=5, help="passes per measurement, best kept (C and C++)")
    ap.add_argument("--out", default=str(ROOT / "build" / "bench"), help="stream and binary directory")
    ap.add_argument("--no-cli", action="store_true", help="leave out the decode CLIs (step 4)")
    args = ap.parse_args()
    langs = [x for x in (s.strip() for s in args.langs.split(",")) if x]
    unknown = [x for x in langs if x not in LANGS]
    if unknown or not langs:
        ap.error(f"unknown language(s) {','.join(unknown)}: choose from {','.join(LANGS)}")
    out = Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    streams(out, args.scale)
    failed: list[str] = []
    skipped: list[str] = []
    rows: list[dict[str, str]] = []
    try:
        runs = commands(langs, out, args.passes)
    except subprocess.CalledProcessError as e:
        log(f"build failed: {e}")
        return 1
    for name, cmd, why in runs:
        if cmd is None:
            log(f"{name}: skipped ({why}; its benchmark has not landed)")
            skipped.append(name)
            continue
        try:
            got, ok = run(name, cmd)
        except OSError as e:
            got, ok = [], False
            log(f"{name}: cannot run: {e}")
        rows += got
        if not ok:
            failed.append(name)
    cli_rows: list[dict[str, str]] = []
    if not args.no_cli:
        try:
            cli_rows, ok = cli_bench(langs, out, args.scale)
        except (subprocess.CalledProcessError, OSError) as e:
            log(f"decode CLIs: {e}")
            ok = False
        if not ok:
            failed.append("decode-cli")
    print(f"Benchmarks (issue 8): {machine()}; best of {args.passes} passes; scale {args.scale}")
    print()
    print(table(rows, langs))
    if cli_rows:
        print("\nDecode CLIs (one run each, output to a file):\n")
        print(cli_table(cli_rows))
    if skipped:
        print(f"\nskipped: {', '.join(skipped)}")
    if failed:
        print(f"\nFAILED: {', '.join(failed)}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
