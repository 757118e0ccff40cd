"""Builds and runs the fuzz harnesses of every language over every generated package.

    python -m tests.fuzz.fuzz run [--seconds N | --runs N [--python-runs M]] [--jobs J] [--only LANG[/PACKAGE[/TARGET]] ...]
    python -m tests.fuzz.fuzz build [--only ...]
    python -m tests.fuzz.fuzz replay

`run` builds what is missing or out of date, writes the seed corpora (tests/fuzz/seeds.py), then
runs the targets one at a time (the machine is shared: never two fuzzers at once; `--jobs J`
runs J at once on a machine of your own, as CI does with one a core) and prints a table, in the
order of the targets whatever the jobs: target, executions, exec/s, wall time, findings. Targets: LANG in c, cpp, rust, python;
PACKAGE in the generated packages (mipcodec, mscipcodec); TARGET in parser, decode, json
(decode: the lean parse + decode-every-field target, for execution count); and spec/generator/loader,
the generator's front end (tests/fuzz/spec/harness.py: spec files through the YAML loader, the
schema and the IR passes; regressions in tests/fuzz/regressions/generator/loader/).

  build/fuzz/corpus/<package>/<target>/     seeds (golden vectors), rewritten by every run
  build/fuzz/work/<lang>/<package>/<target>/ what the fuzzer added (kept between runs)
  build/fuzz/findings/<lang>/<package>/<target>/  crash-*, timeout-*, slow-unit-*, oom-* inputs
  build/fuzz/logs/<lang>-<package>-<target>.log   the fuzzer's output

A finding (a saved input, or a non-zero exit) fails the target and the command exits 1. To keep a
finding as a regression case, copy its input to tests/fuzz/regressions/<package>/<target>/.

`replay` (what `make test-fuzz-regressions` runs) needs no clang or libFuzzer: it builds the C
and C++ harnesses with gcc/g++ -fsanitize=address,undefined and a plain main()
(tests/fuzz/c/replay_main.c) and runs them over tests/fuzz/regressions/<package>/<target>/ and
the seed corpus, then runs the Rust harnesses (cargo test) and the Python ones (pytest) over the
same files.

Environment: FUZZ_PYTHON (interpreter with atheris for the Python targets, default: this one),
CLANG / CLANGXX (default clang-14 / clang++-14), CARGO_FUZZ_TOOLCHAIN (default nightly).
"""

from __future__ import annotations

import argparse
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

from generator.targets import NAMES
from generator.targets.c.backend import c_prefix

ROOT = Path(__file__).resolve().parents[2]
HERE = ROOT / "tests" / "fuzz"
BUILD = ROOT / "build" / "fuzz"
LANGS = NAMES  # the target registry (generator/targets/__init__.py); each needs its harnesses here
TARGETS = ("parser", "decode", "json")
# Inputs larger than this are not tried (a few maximum packets; a long JSON line). `decode` is the
# lean target for execution count: two maximum MIP packets or a few MS-CIP ones.
MAX_LEN = {"parser": 1100, "decode": 600, "json": 4096, "loader": 8192}
# The generator's front end (tests/fuzz/spec/harness.py): spec files through the YAML loader, the
# schema and the IR passes, under atheris; selected as spec/generator/loader (--only spec).
SPEC_TARGET = ("spec", "generator", "loader")
SANITIZE_FUZZ = ["-fsanitize=fuzzer-no-link,address,undefined", "-fno-sanitize-recover=undefined"]
SANITIZE_REPLAY = ["-fsanitize=address,undefined", "-fno-sanitize-recover=all"]
WARN = ["-Wall", "-Wextra", "-Werror"]


def packages() -> list[str]:
    return sorted(p.name for p in (ROOT / "generated" / "c").iterdir() if (p / "CMakeLists.txt").is_file())


def prefix(package: str) -> str:
    """mipcodec -> mipc (the C prefix of the package's names, as the C back end derives it)."""
    return c_prefix(package)


def log(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def sh(cmd: list[str], **kw) -> None:
    r = subprocess.run(cmd, **kw)
    if r.returncode != 0:
        raise SystemExit(f"fuzz.py: command failed ({r.returncode}): {' '.join(map(str, cmd))}")


def newest(paths) -> float:
    return max((p.stat().st_mtime for p in paths), default=0.0)


def stale(out: Path, deps: float) -> bool:
    return not out.exists() or out.stat().st_mtime < deps


# --------------------------------------------------------------------------------------- C / C++
def build_c(package: str, mode: str) -> dict[str, Path]:
    """The C harness binaries of a package: libFuzzer (mode fuzz) or gcc replay (mode replay)."""
    src = ROOT / "generated" / "c" / package
    out = BUILD / mode / "c" / package
    obj = out / "obj"
    obj.mkdir(parents=True, exist_ok=True)
    fuzz = mode == "fuzz"
    cc = os.environ.get("CLANG", "clang-14") if fuzz else "gcc"
    flags = ["-g", "-O1", "-fno-omit-frame-pointer", *(SANITIZE_FUZZ if fuzz else SANITIZE_REPLAY)]
    incs = [f"-I{src / 'include'}", f"-I{src / 'src'}"]
    defs = [
        f'-DFZ_PACKAGE_HEADER="{package}/{package}.h"',
        f"-DFZ_PREFIX={prefix(package)}_",
        f"-DFZ_UPREFIX={prefix(package).upper()}_",
    ]
    headers = newest([*src.rglob("*.h")])
    harness_deps = max(headers, newest(HERE.glob("c/*")))
    lib_objs = []
    for c in sorted([*(src / "src").glob("*.c"), *(src / "src" / "sets").glob("*.c")]):
        o = obj / (c.relative_to(src / "src").as_posix().replace("/", "_") + ".o")
        if stale(o, max(headers, c.stat().st_mtime)):
            sh([cc, "-std=c99", *flags, *WARN, *incs, "-c", str(c), "-o", str(o)])
        lib_objs.append(o)
    extra = []
    if not fuzz:
        main_o = obj / "replay_main.o"
        if stale(main_o, harness_deps):
            sh([cc, *flags, *WARN, "-c", str(HERE / "c" / "replay_main.c"), "-o", str(main_o)])
        extra.append(main_o)
    bins = {}
    for target in TARGETS:
        ho = obj / f"fuzz_{target}.o"
        if stale(ho, harness_deps):
            sh([cc, "-std=c99", *flags, *WARN, *incs, *defs, "-c", str(HERE / "c" / f"fuzz_{target}.c"), "-o", str(ho)])
        exe = out / target
        if stale(exe, newest([ho, *lib_objs, *extra])):
            link = ["-fsanitize=fuzzer,address,undefined"] if fuzz else SANITIZE_REPLAY
            sh([cc, *link, str(ho), *map(str, lib_objs), *map(str, extra), "-o", str(exe)])
        bins[target] = exe
    return bins


def compile_parallel(jobs: list[list[str]]) -> None:
    """Runs independent compile commands on every core (the C++ library's sources are many
    translation units: one after another they took minutes of wall time on a 2-core machine)."""
    if not jobs:
        return
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=max(1, os.cpu_count() or 1)) as pool:
        for f in [pool.submit(sh, cmd) for cmd in jobs]:
            f.result()  # the first failure (SystemExit with the command) stops the build


def build_cpp(package: str, mode: str) -> dict[str, Path]:
    """The C++ harness binaries: fuzz_targets.cpp compiled once, entry.cpp once per target, the
    library's sources once each; the compiles run in parallel, then one link per target."""
    inc = ROOT / "generated" / "cpp" / package / "include"
    out = BUILD / mode / "cpp" / package
    out.mkdir(parents=True, exist_ok=True)
    fuzz = mode == "fuzz"
    cxx = os.environ.get("CLANGXX", "clang++-14") if fuzz else "g++"
    cc = os.environ.get("CLANG", "clang-14") if fuzz else "gcc"
    # replay: -O0, the generated headers compile much faster and a few hundred inputs run anyway
    flags = ["-g", "-O1" if fuzz else "-O0", "-fno-omit-frame-pointer", *(SANITIZE_FUZZ if fuzz else SANITIZE_REPLAY)]
    deps = max(newest(inc.rglob("*.hpp")), newest(HERE.glob("cpp/*")), newest(HERE.glob("c/replay_main.c")))
    jobs: list[list[str]] = []
    main_o = out / "fuzz_targets.o"
    if stale(main_o, deps):
        log(f"fuzz.py: compiling the C++ harnesses of {package} ({mode}; takes a few minutes)")
        jobs.append(
            [
                cxx,
                "-std=c++17",
                *flags,
                *WARN,
                f"-I{inc}",
                f'-DFZ_PACKAGE_HEADER="{package}/json_lines.hpp"',
                f'-DFZ_PACKETS_HEADER="{package}/packets.hpp"',
                f"-DFZ_NS={package}",
                "-c",
                str(HERE / "cpp" / "fuzz_targets.cpp"),
                "-o",
                str(main_o),
            ]
        )
    # The library's sources (src/: the codecs, the session facts, the typed API), instrumented like
    # the harness, one object each; for replay, the sanitized library of `tests/lang/cpp.sh test`
    # when that build exists (CMake Debug with the same instrumentation: -O0 -g,
    # -fsanitize=address,undefined -fno-sanitize-recover=all; make test runs test-cpp first), so
    # CI compiles the library's sources under ASan once, not twice.
    extra: list[Path] = []
    shared = ROOT / "build" / "cpp-sanitize" / package
    sources = [] if not fuzz and (shared / "build.ninja").is_file() else sorted((inc.parent / "src").rglob("*.cpp"))
    if not sources:
        log(f"fuzz.py: the C++ library of {package} from {shared.relative_to(ROOT)} (tests/lang/cpp.sh test)")
        sh(["cmake", "--build", str(shared), "--target", f"{package}_cpp"], stdout=subprocess.DEVNULL)
        extra.append(shared / f"lib{package}_cpp.a")
    for c in sources:
        o = out / "lib" / (c.relative_to(inc.parent / "src").as_posix().replace("/", "_") + ".o")
        o.parent.mkdir(parents=True, exist_ok=True)
        if stale(o, max(deps, c.stat().st_mtime)):
            jobs.append([cxx, "-std=c++17", *flags, *WARN, f"-I{inc}", "-c", str(c), "-o", str(o)])
        extra.append(o)
    if not fuzz:
        replay_o = out / "replay_main.o"
        if stale(replay_o, deps):
            jobs.append([cc, *flags, *WARN, "-c", str(HERE / "c" / "replay_main.c"), "-o", str(replay_o)])
        extra.append(replay_o)
    entries = {}
    for target in TARGETS:
        # entry.cpp defines LLVMFuzzerTestOneInput (called by libFuzzer, or by replay_main.c)
        entry = entries[target] = out / f"entry_{target}.o"
        if stale(entry, deps):
            jobs.append(
                [
                    cxx,
                    "-std=c++17",
                    *flags,
                    *WARN,
                    f"-DFZ_ENTRY=fz_cpp_{target}",
                    "-c",
                    str(HERE / "cpp" / "entry.cpp"),
                    "-o",
                    str(entry),
                ]
            )
    compile_parallel(jobs)
    bins = {}
    for target in TARGETS:
        objs = [entries[target], main_o, *extra]
        exe = out / target
        if stale(exe, newest(objs)):
            link = ["-fsanitize=fuzzer,address,undefined"] if fuzz else SANITIZE_REPLAY
            sh([cxx, *link, *map(str, objs), "-o", str(exe)])
        bins[target] = exe
    return bins


# ------------------------------------------------------------------------------------------ Rust
RUST_DIR = HERE / "rust"


def cargo_env() -> dict[str, str]:
    env = dict(os.environ)
    home = Path(env.get("CARGO_HOME", Path.home() / ".cargo")) / "bin"
    if home.is_dir() and str(home) not in env.get("PATH", ""):
        env["PATH"] = f"{home}:{env.get('PATH', '')}"
    return env


def rust_sanitizer() -> str:
    """AddressSanitizer only where it can find something: the generated crates declare
    #![forbid(unsafe_code)], and safe Rust cannot read out of bounds (a slice index past the end
    panics, which libFuzzer reports as a crash; overflow checks and debug assertions stay on). The
    sanitizer costs the Rust targets about a factor of eight in executions (decode target: 5,900
    against 49,000 exec/s); it comes back on its own if a crate ever drops the forbid."""
    crates = [ROOT / "generated" / "rust" / p / "src" / "lib.rs" for p in packages()]
    safe = all("#![forbid(unsafe_code)]" in c.read_text() for c in crates)
    return "none" if safe else "address"


def rust_fuzz_cmd(sub: str, *args: str) -> list[str]:
    toolchain = os.environ.get("CARGO_FUZZ_TOOLCHAIN", "nightly")
    return [
        "cargo",
        f"+{toolchain}",
        "fuzz",
        sub,
        f"--sanitizer={rust_sanitizer()}",
        "--fuzz-dir",
        str(RUST_DIR),
        "--target-dir",
        str(BUILD / "rust" / "target"),
        *args,
    ]


def build_rust() -> None:
    sh(rust_fuzz_cmd("build"), env=cargo_env(), stdout=sys.stderr)


# --------------------------------------------------------------------------------------- running
def seeds() -> None:
    sh([sys.executable, "-m", "tests.fuzz.seeds", "--out", str(BUILD / "corpus")], stdout=subprocess.DEVNULL, cwd=ROOT)


def fuzz_command(lang: str, package: str, target: str, bins: dict) -> tuple[list[str], dict]:
    env = dict(os.environ)
    if lang in ("c", "cpp"):
        env.setdefault("ASAN_OPTIONS", "abort_on_error=1:detect_leaks=1:symbolize=1")
        env.setdefault("UBSAN_OPTIONS", "print_stacktrace=1:halt_on_error=1")
        sym = shutil.which("llvm-symbolizer-14") or shutil.which("llvm-symbolizer")
        if sym:
            env.setdefault("ASAN_SYMBOLIZER_PATH", sym)
        return [str(bins[(lang, package)][target])], env
    if lang == "rust":
        return rust_fuzz_cmd("run", f"{package}_{target}", "--"), cargo_env()
    python = os.environ.get("FUZZ_PYTHON", sys.executable)
    if lang == "spec":
        env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(ROOT), env.get("PYTHONPATH")]))
        return [python, "-m", "tests.fuzz.spec.fuzz_target"], env
    # the harness is the module tests.fuzz.python.fuzz_target: the project root is on its path
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(ROOT), env.get("PYTHONPATH")]))
    return [python, "-m", "tests.fuzz.python.fuzz_target", package, target], env


def run_one(lang: str, package: str, target: str, bins: dict, seconds: int | None, runs: int | None) -> dict:
    name = f"{lang}/{package}/{target}"
    work = BUILD / "work" / lang / package / target
    findings = BUILD / "findings" / lang / package / target
    logs = BUILD / "logs"
    for d in (work, findings, logs):
        d.mkdir(parents=True, exist_ok=True)
    before = set(findings.iterdir())
    cmd, env = fuzz_command(lang, package, target, bins)
    limit = f"-runs={runs}" if runs else f"-max_total_time={seconds}"
    args = [
        limit,
        "-print_final_stats=1",
        f"-max_len={MAX_LEN[target]}",
        "-timeout=10",
        "-rss_limit_mb=4096",
        "-report_slow_units=5",
        f"-artifact_prefix={findings}/",
    ]
    if lang == "rust":
        # cargo fuzz passes the corpus directories before `--`
        cmd = cmd[:-1] + [str(work), str(BUILD / "corpus" / package / target), "--", *args]
    else:
        cmd = cmd + args + [str(work), str(BUILD / "corpus" / package / target)]
    log(f"fuzz.py: {name}: {' '.join(cmd)}")
    start = time.monotonic()
    logfile = logs / f"{lang}-{package}-{target}.log"
    with open(logfile, "w") as out:
        rc = subprocess.run(cmd, env=env, stdout=out, stderr=subprocess.STDOUT, cwd=ROOT).returncode
    wall = time.monotonic() - start
    text = logfile.read_text(errors="replace")
    execs = re.findall(r"stat::number_of_executed_units:\s*(\d+)", text)
    rate = re.findall(r"stat::average_exec_per_sec:\s*(\d+)", text)
    new = sorted(set(findings.iterdir()) - before)
    slow = [p for p in new if p.name.startswith("slow-unit-")]
    failed = rc != 0 or len(new) > 0
    if failed:
        tail = "\n".join(text.splitlines()[-40:])
        log(f"fuzz.py: {name}: FINDING (exit {rc}); log {logfile}\n{tail}")
        for p in new:
            log(f"fuzz.py: {name}: saved {p}")
    return {
        "target": name,
        "execs": int(execs[-1]) if execs else 0,
        "rate": int(rate[-1]) if rate else 0,
        "wall": wall,
        "findings": len(new) if new else (1 if rc != 0 else 0),
        "slow": len(slow),
        "failed": failed,
    }


def table(rows: list[dict]) -> str:
    head = f"{'target':<28} {'executions':>12} {'exec/s':>8} {'wall s':>8} {'findings':>9}  result"
    lines = [head, "-" * len(head)]
    for r in rows:
        lines.append(
            f"{r['target']:<28} {r['execs']:>12} {r['rate']:>8} {r['wall']:>8.0f} {r['findings']:>9}  "
            + ("FAIL" if r["failed"] else "ok")
        )
    return "\n".join(lines)


def selected(only: list[str]) -> list[tuple[str, str, str]]:
    out = []
    for lang in LANGS:
        for package in packages():
            for target in TARGETS:
                key = f"{lang}/{package}/{target}"
                if not only or any(key == o or key.startswith(o.rstrip("/") + "/") for o in only):
                    out.append((lang, package, target))
    key = "/".join(SPEC_TARGET)
    if not only or any(key == o or key.startswith(o.rstrip("/") + "/") for o in only):
        out.append(SPEC_TARGET)
    return out


def build(chosen: list[tuple[str, str, str]]) -> dict:
    bins = {}
    for lang, package in sorted({(lang, p) for lang, p, _ in chosen}):
        if lang == "c":
            bins[(lang, package)] = build_c(package, "fuzz")
        elif lang == "cpp":
            bins[(lang, package)] = build_cpp(package, "fuzz")
    if any(lang == "rust" for lang, _, _ in chosen):
        build_rust()
    return bins


def cmd_run(args) -> int:
    chosen = selected(args.only)
    bins = build(chosen)
    seeds()

    def one(chosen_target: tuple[str, str, str]) -> dict:
        lang, package, target = chosen_target
        runs = args.runs
        if runs and lang in ("python", "spec"):
            runs = args.python_runs or max(1, runs // 10)
        return run_one(lang, package, target, bins, args.seconds, runs)

    # Each target has its own work, findings and log directories, so targets run side by side
    # without sharing a file; the table keeps the targets' order.
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        rows = list(pool.map(one, chosen))
    print(table(rows))
    bad = [r["target"] for r in rows if r["failed"]]
    if bad:
        print(f"fuzz.py: findings in {', '.join(bad)}: inputs under build/fuzz/findings/ (logs in build/fuzz/logs/)")
        return 1
    return 0


def cmd_replay(_args) -> int:
    seeds()
    regressions = HERE / "regressions"
    corpus = BUILD / "corpus"
    total = 0
    for package in packages():
        for lang, builder in (("c", build_c), ("cpp", build_cpp)):
            bins = builder(package, "replay")
            for target in TARGETS:
                dirs = [d for d in (regressions / package / target, corpus / package / target) if d.is_dir()]
                log(f"fuzz.py: replay {lang}/{package}/{target}: {', '.join(str(d.relative_to(ROOT)) for d in dirs)}")
                env = dict(os.environ, UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")
                r = subprocess.run([str(bins[target]), *map(str, dirs)], env=env, stderr=subprocess.DEVNULL)
                if r.returncode != 0:
                    # run again with the per-input progress lines, to show which input failed
                    subprocess.run([str(bins[target]), *map(str, dirs)], env=env)
                    print(f"fuzz.py: replay {lang}/{package}/{target} FAILED")
                    return 1
                total += 1
    env = cargo_env()
    env["CARGO_TARGET_DIR"] = str(BUILD / "rust" / "test-target")
    env["FUZZ_SEED_CORPUS"] = str(corpus)
    sh(["cargo", "test", "--quiet", "--manifest-path", str(RUST_DIR / "Cargo.toml"), "-p", "fuzz-harness"], env=env)
    env = dict(os.environ, FUZZ_SEED_CORPUS=str(corpus))
    sh(
        [
            sys.executable,
            "-m",
            "pytest",
            "-q",
            "-p",
            "no:cacheprovider",
            str(HERE / "python" / "test_regressions.py"),
            str(HERE / "spec" / "test_regressions.py"),
        ],
        env=env,
        cwd=ROOT,
    )
    print(
        f"fuzz.py: regressions and seeds replayed by {total} C/C++ harness runs, the Rust and the Python tests"
        " and the spec loader's"
    )
    return 0


def _jobs(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        n = 0
    if n < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number of targets at once, at least 1: {text!r}")
    return n


def main() -> int:
    ap = argparse.ArgumentParser(description="Fuzzing harnesses: build, run, replay (see tests/fuzz/fuzz.py).")
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run", help="run the fuzz targets one at a time and print a table")
    g = r.add_mutually_exclusive_group()
    g.add_argument("--seconds", type=int, default=10, help="time per target (default 10)")
    g.add_argument("--runs", type=int, help="executions per target instead of a time")
    r.add_argument("--python-runs", type=int, help="executions per Python target with --runs (default: runs / 10)")
    r.add_argument("--only", action="append", default=[], help="LANG[/PACKAGE[/TARGET]] (repeatable)")
    r.add_argument("--jobs", type=_jobs, default=1, help="targets run at once (default 1: the machine is shared)")
    b = sub.add_parser("build", help="build the libFuzzer binaries")
    b.add_argument("--only", action="append", default=[])
    sub.add_parser("replay", help="replay tests/fuzz/regressions and the seeds without libFuzzer")
    args = ap.parse_args()
    if args.cmd == "run":
        if args.runs:
            args.seconds = None
        return cmd_run(args)
    if args.cmd == "build":
        build(selected(args.only))
        return 0
    return cmd_replay(args)


if __name__ == "__main__":
    sys.exit(main())
