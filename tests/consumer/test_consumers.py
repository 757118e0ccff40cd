"""The generated C and C++ packages consumed from outside the repository, the ways docs/packaging.md
documents (`make test-consumer`, part of `make test`; the Cortex-M build is `make test-cortexm`,
run by .ci/run):

- Release (-O3) builds of both packages with -Werror (the packages' <PKG>_WERROR option) under gcc,
  and under clang where it is installed (CI installs clang-14), tools and examples asked for;
- the READMEs' install recipes as they stand, taken from the READMEs' blocks marked
  `<!-- consumer: install -->` (`cmake -S . -B build && cmake --build build && cmake --install
  build --prefix /opt/PKG`, nothing asked for, /opt/PKG read as the test's prefix) and run in a copy
  of the package where googletest cannot be found (any find_package(GTest) fails the configure)
  and, for the C package, no C++ compiler exists; both packages installed into one prefix;
- the READMEs' `<!-- consumer: find_package -->` blocks (a project's CMake lines around a program
  `app`) and `<!-- consumer: pkg-config -->` blocks (the compile commands), run as they stand with
  the consumer programs as `app.c`, `session_app.c`, `app.cpp`;
- a consumer project with C and C++ programs that finds them with find_package(mipcodec X.Y
  CONFIG) (the version of VERSION), and the versions mipcodecConfigVersion.cmake accepts and
  refuses (docs/versioning.md);
- the same programs built with pkg-config alone (no CMake), with a session program on the POSIX
  transport (mipcodec-posix) pinging a fake device on 127.0.0.1;
- add_subdirectory of the C package into a C-only project with no C++ compiler: only the linked
  libraries are built;
- (test_cortexm) a minimal Cortex-M4 image on the C core, with its code size printed, and the C
  package built top-level for Cortex-M with only the shipped toolchain file.

Every program decodes the same stream (golden vectors) and must print the vectors' expected lines.
Build directories live under build/consumer/ (kept, so a rerun only rebuilds what changed); the
package builds start together on two threads (the `builds` fixture) and each test waits for its own.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import socket
import struct
import subprocess
import threading
from collections.abc import Iterator
from concurrent.futures import Future, ThreadPoolExecutor
from contextlib import contextmanager
from pathlib import Path

import pytest

from generator.release import parse_version
from generator.vectors import load_vectors

ROOT = Path(__file__).resolve().parents[2]
HERE = ROOT / "tests" / "consumer"
BUILD = ROOT / "build" / "consumer"
PKG = "mipcodec"
C_SRC = ROOT / "generated" / "c" / PKG
CPP_SRC = ROOT / "generated" / "cpp" / PKG
CLANG = shutil.which(os.environ.get("CLANG", "clang-14")) or shutil.which("clang")
VERSION = parse_version((ROOT / "VERSION").read_text(encoding="utf-8"), "VERSION")
# Tests, tools and examples: asked for in the project's own builds (they are OFF by default).
ASKED = ["-DMIPCODEC_BUILD_TESTS=OFF", "-DMIPCODEC_BUILD_TOOLS=ON", "-DMIPCODEC_BUILD_EXAMPLES=ON"]


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


@contextmanager
def fake_device(stream) -> Iterator[str]:
    """A device on 127.0.0.1 for the session programs: answers each connection's ping command (the
    ping_command vector's bytes) with the ping_reply vector's bytes. Yields its address."""
    ir = json.loads((ROOT / "generated" / "ir.json").read_text(encoding="utf-8"))
    cases = {c["name"]: c for c in load_vectors(ir, ROOT / "tests" / "vectors") if c["protocol"] == "mip"}
    command, reply = bytes.fromhex(stream[2]), bytes.fromhex(cases["ping_reply"]["hex"])
    server = socket.create_server(("127.0.0.1", 0))
    server.settimeout(30)

    def serve() -> None:
        while True:
            try:
                conn, _ = server.accept()
            except OSError:
                return
            with conn:
                conn.settimeout(10)
                got = b""
                while command not in got:
                    chunk = conn.recv(256)
                    if not chunk:
                        break
                    got += chunk
                if command in got:
                    conn.sendall(reply)

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    try:
        yield f"tcp:127.0.0.1:{server.getsockname()[1]}"
    finally:
        server.close()
        thread.join(timeout=5)


def check_session(exe: Path, address: str) -> None:
    assert run([exe, address]).stdout.splitlines() == ["ping: ack"]


def compilers() -> list[tuple[str, str, str]]:
    found = [("gcc", "gcc", "g++")]
    if CLANG:
        found.append(("clang", CLANG, CLANG.replace("clang", "clang++")))
    return found


def release_build(name: str, cc: str, cxx: str, lang: str) -> str:
    """A Release (-O3) build of one package with MIPCODEC_WERROR, tools and examples asked for;
    returns its log."""
    common = ["-DCMAKE_BUILD_TYPE=Release", "-DMIPCODEC_WERROR=ON", *ASKED]
    out = BUILD / f"release-{name}" / lang
    if lang == "c":
        return cmake_build(C_SRC, out, f"-DCMAKE_C_COMPILER={cc}", *common)
    # One translation unit that includes every C++ header (the example includes the umbrella
    # header): the C++ tools would only add minutes of compile time.
    return cmake_build(CPP_SRC, out, f"-DCMAKE_CXX_COMPILER={cxx}", *common, "-DMIPCODEC_BUILD_TOOLS=OFF")


@pytest.fixture(scope="module")
def builds() -> Iterator[dict[str, Future]]:
    """Every package build of this module, started at once on two threads (each build's own jobs
    use every core: CMAKE_BUILD_PARALLEL_LEVEL), so that one build's serial steps (configure, link,
    the longest source compiled last and alone) overlap another's compiles: the Release builds per
    compiler and package, and the README recipes' configure and build (their install steps run in
    order in `prefix`). Each test waits for the builds it checks; a failed build fails those."""
    no_gtest()  # the traps, written before any thread reads them
    jobs: dict[str, tuple] = {}
    for name, cc, cxx in compilers():
        if name == "clang" and not shutil.which(cxx):
            cxx = CLANG
        jobs[f"release-{name}-cpp"] = (release_build, name, cc, cxx, "cpp")
        jobs[f"release-{name}-c"] = (release_build, name, cc, cxx, "c")
    jobs["recipe-cpp"] = (recipe_build, "cpp")
    jobs["recipe-c"] = (recipe_build, "c")
    with ThreadPoolExecutor(max_workers=2) as pool:
        futures = {key: pool.submit(*job) for key, job in jobs.items()}
        yield futures
        for f in futures.values():
            f.cancel()


@pytest.mark.parametrize("name,cc,cxx", compilers(), ids=[c[0] for c in compilers()])
def test_release_build_is_warning_free(builds, name, cc, cxx):
    """Release (-O3) builds of both packages, -Werror through MIPCODEC_WERROR (never forced on a
    consumer): libraries, tools and examples (asked for: they are OFF by default) compile without a
    warning under gcc and clang."""
    c_log = builds[f"release-{name}-c"].result()
    cpp_log = builds[f"release-{name}-cpp"].result()
    assert "warning" not in c_log + cpp_log
    for tool in ("decode", "encode", "getting-started"):
        assert (BUILD / f"release-{name}" / "c" / f"{PKG}-{tool}").is_file()
    assert (BUILD / f"release-{name}" / "cpp" / f"{PKG}-getting-started").is_file()
    cache = (BUILD / f"release-{name}" / "c" / "CMakeCache.txt").read_text()
    assert "CMAKE_BUILD_TYPE:STRING=Release" in cache


# A module directory and a prefix where googletest's CMake files would be looked for first, each of
# which fails the configure: the README's recipe must not look for GTest at all (a machine without
# libgtest-dev), which CMAKE_DISABLE_FIND_PACKAGE_GTest would not show.
NO_GTEST = BUILD / "no-gtest"


def no_gtest() -> list[str]:
    for path in (NO_GTEST / "modules" / "FindGTest.cmake", NO_GTEST / "prefix" / "lib/cmake/GTest/GTestConfig.cmake"):
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text('message(FATAL_ERROR "find_package(GTest) was called")\n')
    return [f"-DCMAKE_MODULE_PATH={NO_GTEST / 'modules'}", f"-DCMAKE_PREFIX_PATH={NO_GTEST / 'prefix'}"]


# A README block the consumer tests run, marked by an HTML comment on the line before its fence:
# `<!-- consumer: install -->` the install recipe (sh), `<!-- consumer: find_package -->` the
# CMake lines of a project that uses the installed package (around a program `app`),
# `<!-- consumer: pkg-config -->` the compile commands without CMake (sh; app.c, session_app.c,
# app.cpp). docs/packaging.md "Consumer tests" describes them.
README_BLOCK = re.compile(r"^<!-- consumer: ([\w-]+) -->\n(`{3,})\w*\n(.*?)^\2\n", re.S | re.M)
README_KINDS = {"install", "find_package", "pkg-config"}


def readme_blocks(lang: str) -> dict[str, str]:
    """The package README's blocks marked for the consumer tests, by kind: each kind exactly once."""
    readme = (C_SRC if lang == "c" else CPP_SRC) / "README.md"
    found: dict[str, str] = {}
    for m in README_BLOCK.finditer(readme.read_text(encoding="utf-8")):
        assert m[1] in README_KINDS and m[1] not in found, f"{readme}: marker consumer: {m[1]} unknown or repeated"
        found[m[1]] = m[3]
    assert set(found) == README_KINDS, f"{readme}: no block marked consumer: {sorted(README_KINDS - set(found))}"
    return found


def sh_lines(body: str) -> list[str]:
    """The commands of a sh block: one a line, `\\` continues, comments dropped."""
    out, pending = [], ""
    for raw in body.splitlines():
        line = re.split(r"\s{2,}#\s", raw.rstrip(), maxsplit=1)[0]
        if not pending and (not line.strip() or line.lstrip().startswith("#")):
            continue
        if line.endswith("\\"):
            pending += line[:-1] + " "
            continue
        out.append(pending + line)
        pending = ""
    return out


def readme_env(lang: str) -> dict[str, str]:
    """The recipe's machine: no CMAKE_* variables of ours but every core for the build
    (CMAKE_BUILD_PARALLEL_LEVEL), googletest that fails any find_package(GTest) first on
    CMAKE_PREFIX_PATH (no_gtest(), written by the `builds` fixture), and for the C package a C++
    compiler that does not exist (CXX)."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("CMAKE_")}
    env["CMAKE_BUILD_PARALLEL_LEVEL"] = str(os.cpu_count() or 2)
    env["CMAKE_PREFIX_PATH"] = str(NO_GTEST / "prefix")
    if lang == "c":
        env["CXX"] = "/nonexistent/c++"
    return env


RECIPE = {lang: BUILD / "recipe" / lang / PKG / "build" for lang in ("c", "cpp")}


def recipe_steps(lang: str) -> tuple[str, str]:
    """The README's install command split before its install step: (configure and build, install)."""
    (command,) = sh_lines(readme_blocks(lang)["install"])
    *build, install = command.split(" && ")
    assert build and install == f"cmake --install build --prefix /opt/{PKG}", command
    return " && ".join(build), install


def recipe_build(lang: str) -> str:
    """The README's install command up to its install step, as it stands (default generator and
    build type, nothing asked for), run in a copy of the package made outside the repository where
    googletest cannot be found and, for the C package, no C++ compiler exists. The copy's build
    directory is kept (a rerun only rebuilds what changed). Returns the log."""
    src = C_SRC if lang == "c" else CPP_SRC
    work = RECIPE[lang].parent
    work.mkdir(parents=True, exist_ok=True)
    for old in work.iterdir():  # the package as it is now, the build directory kept
        if old.name != "build":
            shutil.rmtree(old) if old.is_dir() else old.unlink()
    shutil.copytree(src, work, dirs_exist_ok=True, ignore=shutil.ignore_patterns("build", "build-*"))
    r = run(["bash", "-c", recipe_steps(lang)[0]], cwd=work, env=readme_env(lang))
    return r.stdout + r.stderr


@pytest.fixture(scope="module")
def prefix(builds) -> Path:
    """Both packages installed into one fresh prefix by their README recipes (`/opt/PKG` read as
    the prefix), the C package first."""
    out = BUILD / "prefix"
    shutil.rmtree(out, ignore_errors=True)
    for lang in ("c", "cpp"):
        log = builds[f"recipe-{lang}"].result()
        install = recipe_steps(lang)[1].replace(f"/opt/{PKG}", str(out))
        r = run(["bash", "-c", install], cwd=RECIPE[lang].parent, env=readme_env(lang))
        assert "gtest" not in (log + r.stdout + r.stderr).lower()
        cache = (RECIPE[lang] / "CMakeCache.txt").read_text()
        assert not [ln for ln in cache.splitlines() if ln.upper().startswith(("GTEST", "GMOCK"))], "GTest looked for"
        if lang == "c":  # the C project never enables C++ (CXX names no compiler: enabling it would fail)
            assert not list(RECIPE[lang].glob("CMakeFiles/*/CMakeCXXCompiler.cmake")), "C++ was enabled"
    return out


def test_install_tree(prefix):
    """What the README recipes install where (docs/packaging.md lists the same tree): no tools,
    tests or examples unless asked for."""
    files = sorted(p.relative_to(prefix).as_posix() for p in prefix.rglob("*") if p.is_file())
    libdir = next(p.parents[2].relative_to(prefix).as_posix() for p in prefix.rglob(f"{PKG}Config.cmake"))
    expected = {
        f"{libdir}/lib{PKG}.a",
        f"{libdir}/lib{PKG}_json.a",
        f"{libdir}/lib{PKG}_posix.a",
        f"{libdir}/cmake/{PKG}/{PKG}Config.cmake",
        f"{libdir}/cmake/{PKG}/{PKG}ConfigVersion.cmake",
        f"{libdir}/cmake/{PKG}/{PKG}-c-targets.cmake",
        f"{libdir}/cmake/{PKG}/{PKG}-c-abi.cmake",
        f"{libdir}/cmake/{PKG}/{PKG}-cpp-targets.cmake",
        f"{libdir}/cmake/{PKG}/{PKG}-cpp-abi.cmake",
        f"{libdir}/lib{PKG}_cpp.a",
        f"{libdir}/pkgconfig/{PKG}.pc",
        f"{libdir}/pkgconfig/{PKG}-json.pc",
        f"{libdir}/pkgconfig/{PKG}-posix.pc",
        f"{libdir}/pkgconfig/{PKG}-cpp.pc",
        f"include/{PKG}/{PKG}.h",
        f"include/{PKG}/posix_transport.h",
        f"include/{PKG}/{PKG}.hpp",
        f"share/{PKG}/arm-none-eabi.cmake",
    }
    assert expected <= set(files), sorted(expected - set(files))
    # no test, source or internal header is installed, and no program unless asked for
    assert not [f for f in files if f.endswith((".c", ".cpp")) or "/src/" in f or "test" in f or f.startswith("bin/")]
    # the C and the C++ package write the same version file (either may be installed last)
    versions = [(RECIPE[lang] / f"{PKG}ConfigVersion.cmake").read_bytes() for lang in ("c", "cpp")]
    assert versions[0] == versions[1]
    # every linker symbol the C libraries define starts with the package's prefix (mipc_), so a
    # program links them beside the vendor SDK (mip_)
    libs = [prefix / libdir / f"lib{PKG}{suffix}.a" for suffix in ("", "_json", "_posix")]
    syms = run(["nm", "-g", "--defined-only", *libs])
    defined = [ln.split()[-1] for ln in syms.stdout.splitlines() if len(ln.split()) == 3]
    assert defined and [s for s in defined if not s.startswith("mipc_")] == []


def test_find_package_c_and_cpp_in_one_project(prefix, stream):
    """find_package(mipcodec X.Y CONFIG COMPONENTS c c_json c_posix cpp) after cmake --install, X.Y
    the project's VERSION: a C program on mipcodec::c_json, a session program on mipcodec::c_posix
    and a C++ program on mipcodec::cpp and mipcodec::c together."""
    out = BUILD / "installed"
    shutil.rmtree(out, ignore_errors=True)
    want = f"-DMIPCODEC_WANT={VERSION[0]}.{VERSION[1]}"
    cmake_build(HERE / "installed", out, f"-DCMAKE_PREFIX_PATH={prefix}", want)
    check_c(out / "consumer_c", stream)
    check_cpp(out / "consumer_cpp", stream, with_c=True)
    with fake_device(stream) as address:
        check_session(out / "consumer_session", address)


# The programs the READMEs' blocks name, played by the consumer programs.
PROGRAMS = {"app.c": "consumer.c", "session_app.c": "session.c", "app.cpp": "consumer.cpp"}


@pytest.mark.parametrize("lang", ["c", "cpp"])
def test_readme_find_package(prefix, stream, lang):
    """The README's find_package block, as it stands, as the CMake lines of a project whose program
    `app` is the consumer program (consumer.c, consumer.cpp): configured with the prefix the README
    recipes installed into, built and run."""
    out = BUILD / "readme-find-package" / lang
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    main = "app.c" if lang == "c" else "app.cpp"
    shutil.copy2(HERE / PROGRAMS[main], out / main)
    head = (
        "cmake_minimum_required(VERSION 3.16)\n"
        f"project(app LANGUAGES {'C' if lang == 'c' else 'CXX'})\n"
        f"add_executable(app {main})\n"
    )
    (out / "CMakeLists.txt").write_text(head + readme_blocks(lang)["find_package"], encoding="utf-8")
    env = {**readme_env(lang), "CMAKE_PREFIX_PATH": str(prefix)}
    run(["cmake", "-S", out, "-B", out / "build"], env=env)
    run(["cmake", "--build", out / "build"], env=env)
    if lang == "c":
        check_c(out / "build" / "app", stream)
    else:
        check_cpp(out / "build" / "app", stream, with_c=False)


def test_readme_pkg_config(prefix, stream):
    """The READMEs' pkg-config blocks, each command as it stands (`/opt/PKG` read as the prefix the
    recipes installed into), in a directory holding the programs they name (app.c, session_app.c,
    app.cpp: the consumer programs); each program built (a.out) must print what it should."""
    for lang in ("c", "cpp"):
        commands = sh_lines(readme_blocks(lang)["pkg-config"])
        assert commands, lang
        for n, command in enumerate(commands):
            (source,) = [name for name in PROGRAMS if re.search(rf"(^|\s){re.escape(name)}(\s|$)", command)]
            out = BUILD / "readme-pkg-config" / f"{lang}-{n}"
            shutil.rmtree(out, ignore_errors=True)
            out.mkdir(parents=True)
            shutil.copy2(HERE / PROGRAMS[source], out / source)
            assert f"/opt/{PKG}/" in command, command
            run(["bash", "-c", command.replace(f"/opt/{PKG}/", f"{prefix}/")], cwd=out, env=readme_env(lang))
            if source == "app.c":
                check_c(out / "a.out", stream)
            elif source == "app.cpp":
                check_cpp(out / "a.out", stream, with_c=False)
            else:
                with fake_device(stream) as address:
                    check_session(out / "a.out", address)


def compatible(want: str, prefix: Path, tmp_path: Path) -> subprocess.CompletedProcess:
    """Configures a project that asks for find_package(mipcodec WANT CONFIG REQUIRED)."""
    src = tmp_path / want
    src.mkdir()
    (src / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.16)\nproject(p LANGUAGES NONE)\n"
        f"find_package(mipcodec {want} CONFIG REQUIRED)\n"
        'message(STATUS "found mipcodec ${mipcodec_VERSION}")\n'
    )
    return subprocess.run(
        ["cmake", "-S", src, "-B", src / "b", f"-DCMAKE_PREFIX_PATH={prefix}"], capture_output=True, text=True
    )


def test_find_package_version(prefix, tmp_path):
    """mipcodecConfigVersion.cmake accepts what docs/versioning.md calls compatible: while the major
    version is 0 a MINOR bump may break a consumer, so 0.Y asks for 0.Y.z exactly (SameMinorVersion);
    from 1.0.0 on X.Y accepts X.y.z with y >= Y (SameMajorVersion). Another major is refused."""
    major, minor, patch = VERSION
    installed = f"{major}.{minor}.{patch}"
    accepted = [f"{major}.{minor}", installed]
    refused = [f"{major + 1}.0", f"{major}.{minor + 1}"]
    if major == 0:
        refused += [f"0.{minor - 1}"] if minor > 0 else []
    else:
        accepted += [f"{major}.0"]
    for want in accepted:
        r = compatible(want, prefix, tmp_path)
        assert r.returncode == 0 and f"found mipcodec {installed}" in r.stdout, (want, r.stdout, r.stderr)
    for want in refused:
        r = compatible(want, prefix, tmp_path)
        assert r.returncode != 0, want
        assert f'compatible with requested version "{want}"' in r.stderr and f"version: {installed}" in r.stderr, (
            want,
            r.stderr,
        )


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
    # the message names every component and its package
    assert (
        "component nosuch is not installed (c, c_json, c_posix, c_win32: the C package; cpp: the C++ package)"
        in " ".join(r.stderr.split())
    )


def test_find_package_refuses_c_of_another_pointer_size(prefix, tmp_path):
    """The version file is the same for both packages (ARCH_INDEPENDENT), so the config file itself
    keeps the C and C++ libraries (built for this host's pointers) from a project of another
    pointer size (a 32-bit or Cortex-M project finding a 64-bit host's install), with the reason."""
    host = struct.calcsize("P")
    other = 4 if host == 8 else 8
    src = tmp_path / "p"
    src.mkdir()
    (src / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.16)\nproject(p LANGUAGES NONE)\n"
        f"set(CMAKE_SIZEOF_VOID_P {other})\n"
        "find_package(mipcodec CONFIG REQUIRED COMPONENTS ${WANT})\n"
    )

    def configure(want: str) -> subprocess.CompletedProcess:
        build = tmp_path / f"b-{want}"
        cmd = ["cmake", "-S", src, "-B", build, f"-DCMAKE_PREFIX_PATH={prefix}", f"-DWANT={want}"]
        return subprocess.run(cmd, capture_output=True, text=True)

    r = configure("c")
    assert r.returncode != 0
    assert "component c is not installed" in r.stderr
    assert f"was built for {host}-byte pointers, this project has {other}" in " ".join(r.stderr.split())
    r = configure("cpp")
    assert r.returncode != 0
    assert "component cpp is not installed" in r.stderr
    assert "the C++ package in" in " ".join(r.stderr.split())
    assert f"was built for {host}-byte pointers, this project has {other}" in " ".join(r.stderr.split())


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
    # the session API over the POSIX transport: mipcodec-posix (requires the core)
    posix_flags = run(["pkg-config", "--cflags", "--libs", f"{PKG}-posix"], env=env).stdout.split()
    run(
        [
            "gcc",
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-pedantic",
            "-Werror",
            HERE / "session.c",
            *posix_flags,
            "-o",
            out / "session",
        ]
    )
    with fake_device(stream) as address:
        check_session(out / "session", address)


def test_add_subdirectory_c_only(stream):
    """add_subdirectory of the C package into a C-only project whose C++ compiler does not exist:
    the package must not enable C++, builds no tests, tools or examples as a subproject (even when
    the including project sets its options), and builds only the libraries the project links
    (mipcodec::c_json and the core, not mipcodec::c_posix)."""
    out = BUILD / "subdir"
    shutil.rmtree(out, ignore_errors=True)
    cmake_build(
        HERE / "subdir",
        out,
        f"-DMIPCODEC_C_DIR={C_SRC}",
        "-DCMAKE_CXX_COMPILER=/nonexistent/c++",
        "-DMIPCODEC_BUILD_TESTS=ON",
        "-DMIPCODEC_BUILD_TOOLS=ON",
        *no_gtest(),
    )
    check_c(out / "consumer", stream)
    built = {p.name for p in (out / "mipcodec").iterdir()}
    assert {f"lib{PKG}.a", f"lib{PKG}_json.a"} <= built
    assert not built & {f"lib{PKG}_posix.a", f"{PKG}-tests", f"{PKG}-decode", f"{PKG}-encode", f"{PKG}-getting-started"}
