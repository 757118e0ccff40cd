"""The generated C and C++ packages consumed from outside the repository, the ways docs/packaging.md
documents (`make test-consumer`, part of `make test`; the Cortex-M build is `make test-cortexm`,
run by .ci/run):

- Release (-O3) builds of both packages with -Werror (the packages' <PKG>_WERROR option) under gcc,
  and under clang where it is installed (CI installs clang-14);
- `cmake --install` of both packages into one temporary prefix, then a consumer project with C and
  C++ programs that finds them with find_package(mipcodec CONFIG);
- the same programs built with pkg-config alone (no CMake);
- add_subdirectory of the C package into a C-only project with no C++ compiler;
- (test_cortexm) a minimal Cortex-M4 image on the C core, with its code size printed.

Every program decodes the same stream (golden vectors) and must print the vectors' expected lines.
Build directories live under build/consumer/ (kept, so a rerun only rebuilds what changed).
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from generator.vectors import load_vectors

ROOT = Path(__file__).resolve().parents[2]
HERE = ROOT / "tests" / "consumer"
BUILD = ROOT / "build" / "consumer"
PKG = "mipcodec"
C_SRC = ROOT / "generated" / "c" / PKG
CPP_SRC = ROOT / "generated" / "cpp" / PKG
CLANG = shutil.which(os.environ.get("CLANG", "clang-14")) or shutil.which("clang")


def run(cmd: list, **kw) -> subprocess.CompletedProcess:
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, **kw)
    assert r.returncode == 0, f"{' '.join(map(str, cmd))} failed ({r.returncode}):\n{r.stdout}\n{r.stderr}"
    return r


def cmake_build(src: Path, out: Path, *defs: str, env: dict | None = None) -> str:
    """Configures (once) and builds; returns the build log (warnings would show in it)."""
    if not (out / "CMakeCache.txt").is_file():
        run(["cmake", "-G", "Ninja", "-S", src, "-B", out, *defs], env=env)
    return run(["cmake", "--build", out], env=env).stdout


@pytest.fixture(scope="module")
def stream() -> tuple[Path, list[str], str]:
    """A stream of two golden vectors (ping reply, scaled accel), the lines every consumer must
    print for it, and the ping command's bytes (the ping_command vector)."""
    ir = json.loads((ROOT / "generated" / "ir.json").read_text(encoding="utf-8"))
    cases = {c["name"]: c for c in load_vectors(ir, ROOT / "tests" / "vectors") if c["protocol"] == "mip"}
    data = b""
    lines = []
    for name in ("ping_reply", "scaled_accel_example"):
        case = cases[name]
        (line,) = case["expect"]
        assert line.startswith('{"offset":0,')
        lines.append('{"offset":%d,' % len(data) + line[len('{"offset":0,') :])
        data += bytes.fromhex(case["hex"])
    BUILD.mkdir(parents=True, exist_ok=True)
    path = BUILD / "stream.bin"
    path.write_bytes(data)
    return path, lines, cases["ping_command"]["hex"]


def check_c(exe: Path, stream) -> None:
    path, lines, command = stream
    assert run([exe, path]).stdout.splitlines() == [f"command {command}", *lines]


def check_cpp(exe: Path, stream, with_c: bool) -> None:
    path, lines, command = stream
    assert run([exe, path]).stdout.splitlines() == [*lines, *([f"command {command}"] if with_c else [])]


def compilers() -> list[tuple[str, str, str]]:
    found = [("gcc", "gcc", "g++")]
    if CLANG:
        found.append(("clang", CLANG, CLANG.replace("clang", "clang++")))
    return found


@pytest.mark.parametrize("name,cc,cxx", compilers(), ids=[c[0] for c in compilers()])
def test_release_build_is_warning_free(name, cc, cxx):
    """Release (-O3) builds of both packages, -Werror through MIPCODEC_WERROR (never forced on a
    consumer): libraries, tools and examples compile without a warning under gcc and clang. The gcc
    build is also the one installed by the next test."""
    if name == "clang" and not shutil.which(cxx):
        cxx = CLANG
    common = ["-DCMAKE_BUILD_TYPE=Release", "-DMIPCODEC_WERROR=ON", "-DMIPCODEC_BUILD_TESTS=OFF"]
    c_log = cmake_build(C_SRC, BUILD / f"release-{name}" / "c", f"-DCMAKE_C_COMPILER={cc}", *common)
    # One translation unit that includes every C++ header (the example includes the umbrella
    # header): the C++ tools would only add minutes of compile time.
    cpp_log = cmake_build(
        CPP_SRC, BUILD / f"release-{name}" / "cpp", f"-DCMAKE_CXX_COMPILER={cxx}", *common, "-DMIPCODEC_BUILD_TOOLS=OFF"
    )
    assert "warning" not in c_log + cpp_log
    for tool in ("decode", "encode", "getting-started"):
        assert (BUILD / f"release-{name}" / "c" / f"{PKG}-{tool}").is_file()
    assert (BUILD / f"release-{name}" / "cpp" / f"{PKG}-getting-started").is_file()
    cache = (BUILD / f"release-{name}" / "c" / "CMakeCache.txt").read_text()
    assert "CMAKE_BUILD_TYPE:STRING=Release" in cache


@pytest.fixture(scope="module")
def prefix() -> Path:
    """Both packages installed into one fresh prefix (the gcc Release builds)."""
    out = BUILD / "prefix"
    shutil.rmtree(out, ignore_errors=True)
    for lang in ("c", "cpp"):
        build = BUILD / "release-gcc" / lang
        if not (build / "build.ninja").is_file():
            cmake_build(
                C_SRC if lang == "c" else CPP_SRC, build, "-DCMAKE_BUILD_TYPE=Release", "-DMIPCODEC_BUILD_TESTS=OFF"
            )
        run(["cmake", "--install", build, "--prefix", out])
    return out


def test_install_tree(prefix):
    """What `cmake --install` puts where (docs/packaging.md lists the same tree)."""
    files = sorted(p.relative_to(prefix).as_posix() for p in prefix.rglob("*") if p.is_file())
    libdir = next(p.parents[2].relative_to(prefix).as_posix() for p in prefix.rglob(f"{PKG}Config.cmake"))
    expected = {
        f"{libdir}/lib{PKG}.a",
        f"{libdir}/lib{PKG}_json.a",
        f"{libdir}/cmake/{PKG}/{PKG}Config.cmake",
        f"{libdir}/cmake/{PKG}/{PKG}-c-targets.cmake",
        f"{libdir}/cmake/{PKG}/{PKG}-cpp-targets.cmake",
        f"{libdir}/pkgconfig/{PKG}.pc",
        f"{libdir}/pkgconfig/{PKG}-json.pc",
        f"{libdir}/pkgconfig/{PKG}-cpp.pc",
        f"include/{PKG}/{PKG}.h",
        f"include/{PKG}/{PKG}.hpp",
        f"bin/{PKG}-decode",
        f"bin/{PKG}-encode",
    }
    assert expected <= set(files), sorted(expected - set(files))
    # no test, source or internal header is installed
    assert not [f for f in files if f.endswith((".c", ".cpp")) or "/src/" in f or "test" in f]
    # every linker symbol the C libraries define starts with the package's prefix (mipc_), so a
    # program links them beside the vendor SDK (mip_)
    syms = run(["nm", "-g", "--defined-only", prefix / libdir / f"lib{PKG}.a", prefix / libdir / f"lib{PKG}_json.a"])
    defined = [ln.split()[-1] for ln in syms.stdout.splitlines() if len(ln.split()) == 3]
    assert defined and [s for s in defined if not s.startswith("mipc_")] == []


def test_find_package_c_and_cpp_in_one_project(prefix, stream):
    """find_package(mipcodec CONFIG COMPONENTS c c_json cpp) after cmake --install: a C program on
    mipcodec::c_json and a C++ program on mipcodec::cpp and mipcodec::c together."""
    out = BUILD / "installed"
    shutil.rmtree(out, ignore_errors=True)
    cmake_build(HERE / "installed", out, f"-DCMAKE_PREFIX_PATH={prefix}")
    check_c(out / "consumer_c", stream)
    check_cpp(out / "consumer_cpp", stream, with_c=True)


def test_find_package_reports_a_missing_component(prefix, tmp_path):
    """Asking for a component that is not installed fails at configure time with a clear message."""
    (tmp_path / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.16)\nproject(p LANGUAGES C)\n"
        "find_package(mipcodec CONFIG REQUIRED COMPONENTS c nosuch)\n"
    )
    r = subprocess.run(
        ["cmake", "-S", tmp_path, "-B", tmp_path / "b", f"-DCMAKE_PREFIX_PATH={prefix}"],
        capture_output=True,
        text=True,
    )
    assert r.returncode != 0
    assert "component nosuch is not installed" in r.stderr


def test_pkg_config(prefix, stream):
    """The same programs built without CMake: flags from pkg-config (mipcodec-json, mipcodec-cpp)."""
    env = {**os.environ, "PKG_CONFIG_PATH": ":".join(str(p.parent) for p in prefix.rglob(f"{PKG}.pc"))}
    out = BUILD / "pkg-config"
    out.mkdir(parents=True, exist_ok=True)
    c_flags = run(["pkg-config", "--cflags", "--libs", f"{PKG}-json"], env=env).stdout.split()
    run(
        [
            "gcc",
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-pedantic",
            "-Werror",
            HERE / "consumer.c",
            *c_flags,
            "-o",
            out / "consumer_c",
        ]
    )
    check_c(out / "consumer_c", stream)
    cpp_flags = run(["pkg-config", "--cflags", "--libs", f"{PKG}-cpp"], env=env).stdout.split()
    run(
        [
            "g++",
            "-std=c++17",
            "-Wall",
            "-Wextra",
            "-pedantic",
            "-Werror",
            HERE / "consumer.cpp",
            *cpp_flags,
            "-o",
            out / "consumer_cpp",
        ]
    )
    check_cpp(out / "consumer_cpp", stream, with_c=False)


def test_add_subdirectory_c_only(stream):
    """add_subdirectory of the C package into a C-only project whose C++ compiler does not exist:
    the package must not enable C++, and builds no tests, tools or examples as a subproject."""
    out = BUILD / "subdir"
    shutil.rmtree(out, ignore_errors=True)
    cmake_build(HERE / "subdir", out, f"-DMIPCODEC_C_DIR={C_SRC}", "-DCMAKE_CXX_COMPILER=/nonexistent/c++")
    check_c(out / "consumer", stream)
    built = {p.name for p in (out / "mipcodec").iterdir()}
    assert {f"lib{PKG}.a", f"lib{PKG}_json.a"} <= built
    assert not built & {f"{PKG}-tests", f"{PKG}-decode", f"{PKG}-encode", f"{PKG}-getting-started"}
