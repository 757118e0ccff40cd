"""The C and C++ packages built for Windows (x86-64) with MinGW-w64 from Linux, with the toolchain
file both packages ship (cmake/x86_64-w64-mingw32.cmake, docs/packaging.md "Windows"), and their
programs run under Wine (`make test-mingw`, run by .ci/run; tools/bootstrap --ci installs Debian's
gcc-mingw-w64-x86-64, g++-mingw-w64-x86-64 and wine64):

- each package configured top-level with only the toolchain file, the project's warning flags as
  errors and the tools asked for, built and installed: PE objects; on WIN32 the Win32 transport
  library (mipcodec::c_win32, links ws2_32) in place of the POSIX one, and the session tool;
- a project of its own finds the installed C package (find_package with the c_win32 component)
  and links a program that opens a refused TCP address: the Win32 transport's message;
- under Wine: every golden vector through the C and C++ decode tools (the expected lines come from
  the vectors, i.e. the manuals), their lines back through the encode tools (the same bytes), and
  the session tools over TCP against the Python simulator on 127.0.0.1 (the round trips of
  test_simulator's plan: reads, writes, saves, loads and defaults of every setting of a model)."""

from __future__ import annotations

import json
import os
import re
import shutil
import socket
import subprocess
from collections.abc import Iterator
from pathlib import Path

import pytest

from generator.spec import load_spec
from generator.vectors import load_corpus
from tests.conformance.test_simulator import PROTOCOLS, Sim, check_roundtrips, command_line, results, roundtrip_plan

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "build" / "mingw"
TRIPLE = "x86_64-w64-mingw32"
IR = load_spec()
VECTORS = load_corpus(IR, ROOT)
PACKAGES = {p["name"]: p["package"] for p in IR["protocols"]}
# The C++ tools take minutes to compile (docs/packaging.md, "C++ build cost"): the mip package only.
CPP_PACKAGES = ["mipcodec"]


def run(cmd: list, **kw) -> str:
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, **kw)
    assert r.returncode == 0, f"{' '.join(map(str, cmd))} failed ({r.returncode}):\n{r.stdout}\n{r.stderr}"
    return r.stdout + r.stderr


def need_toolchain() -> None:
    missing = [t for t in (f"{TRIPLE}-gcc", f"{TRIPLE}-g++", f"{TRIPLE}-objdump") if not shutil.which(t)]
    assert not missing, f"missing {missing}: apt-get install gcc-mingw-w64-x86-64 g++-mingw-w64-x86-64"


def build_package(lang: str, pkg: str) -> Path:
    """Configures generated/<lang>/<pkg> top-level with the shipped toolchain file, builds it with
    the tools and installs it; returns the prefix."""
    need_toolchain()
    src = ROOT / "generated" / lang / pkg
    out = OUT / lang / pkg
    prefix = OUT / "prefix" / lang / pkg
    shutil.rmtree(prefix, ignore_errors=True)
    log = run(
        [
            "cmake",
            "-G",
            "Ninja",
            "-S",
            src,
            "-B",
            out / "build",
            f"-DCMAKE_TOOLCHAIN_FILE={src / 'cmake' / f'{TRIPLE}.cmake'}",
            "-DCMAKE_BUILD_TYPE=Release",
            f"-D{pkg.upper()}_BUILD_TOOLS=ON",
            f"-D{pkg.upper()}_WERROR=ON",
        ]
    )
    assert "gtest" not in log.lower()
    log = run(["cmake", "--build", out / "build"])
    assert "warning" not in log.lower(), log
    run(["cmake", "--install", out / "build", "--prefix", prefix])
    return prefix


@pytest.fixture(scope="module")
def c_prefixes() -> dict[str, Path]:
    return {pkg: build_package("c", pkg) for pkg in sorted(PACKAGES.values())}


@pytest.fixture(scope="module")
def cpp_prefixes() -> dict[str, Path]:
    return {pkg: build_package("cpp", pkg) for pkg in CPP_PACKAGES}


def pe(path: Path) -> str:
    return run([f"{TRIPLE}-objdump", "-f", path])


def test_c_package_for_windows(c_prefixes):
    for pkg, prefix in c_prefixes.items():
        files = sorted(p.relative_to(prefix).as_posix() for p in prefix.rglob("*") if p.is_file())
        libs = sorted(p.name for p in prefix.rglob("*.a"))
        # the Win32 transports in place of the POSIX ones
        assert libs == [f"lib{pkg}.a", f"lib{pkg}_json.a", f"lib{pkg}_win32.a"], libs
        exes = sorted(p.name for p in (prefix / "bin").iterdir())
        assert exes == [f"{pkg}-decode.exe", f"{pkg}-encode.exe", f"{pkg}-session.exe"], exes
        for f in [*prefix.rglob("*.a"), *(prefix / "bin").iterdir()]:
            assert re.search(r"file format pei?-x86-64", pe(f)), f  # pe: objects, pei: images
        pcs = {p.name: p.read_text() for p in prefix.rglob("*.pc")}
        assert sorted(pcs) == [f"{pkg}-json.pc", f"{pkg}-win32.pc", f"{pkg}.pc"]
        assert f"-l{pkg}_win32 -lws2_32" in pcs[f"{pkg}-win32.pc"]
        shipped = ROOT / "generated" / "c" / pkg / "cmake" / f"{TRIPLE}.cmake"
        assert (prefix / "share" / pkg / f"{TRIPLE}.cmake").read_bytes() == shipped.read_bytes()
        assert f"include/{pkg}/win32_transport.h" in files
        # every symbol the transport library defines carries the package's C prefix
        syms = run([f"{TRIPLE}-nm", "-g", "--defined-only", prefix.rglob(f"lib{pkg}_win32.a").__next__()])
        defined = [ln.split()[-1] for ln in syms.splitlines() if len(ln.split()) == 3]
        prefix_c = "mipc_" if pkg == "mipcodec" else "mscipc_"
        assert defined and [s for s in defined if not s.startswith(prefix_c)] == [], defined


def test_cpp_package_for_windows(cpp_prefixes):
    for pkg, prefix in cpp_prefixes.items():
        assert (prefix / "include" / pkg / "transport_win32.hpp").is_file()
        exes = sorted(p.name for p in (OUT / "cpp" / pkg / "build").glob("*.exe"))
        assert exes == [f"{pkg}-decode.exe", f"{pkg}-encode.exe", f"{pkg}-session.exe"], exes
        for exe in exes:
            assert "file format pei-x86-64" in pe(OUT / "cpp" / pkg / "build" / exe)


# ------------------------------------------------------------------------------------ under Wine
def wine_binary() -> str:
    for name in ("wine64", "wine", "/usr/lib/wine/wine64"):
        found = shutil.which(name)
        if found:
            return found
    raise AssertionError("Wine is not installed: apt-get install --no-install-recommends wine64")


@pytest.fixture(scope="module")
def wine() -> Iterator[list[str]]:
    """The command prefix that runs a Windows program: Wine with a prefix of its own under build/mingw/
    (created on first use), its messages off; the prefix's wineserver is stopped at the end."""
    binary = wine_binary()
    env = {**os.environ, "WINEPREFIX": str(OUT / "wineprefix"), "WINEDEBUG": "-all"}
    os.environ.update({"WINEPREFIX": env["WINEPREFIX"], "WINEDEBUG": "-all"})
    server = shutil.which("wineserver") or next(
        (str(p) for p in (Path("/usr/lib/wine/wineserver64"), Path("/usr/lib/wine/wineserver")) if p.exists()), None
    )
    # One wineserver for the whole module (otherwise every program starts its own, ~0.5 s each).
    if server:
        # (it goes to the background; no pipe of ours may stay open in it)
        subprocess.run([server, "-p"], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=60)
    # Create and start the prefix first, with no pipe of ours: the services Wine starts with the first
    # program (winedevice.exe) stay as long as the server and keep that program's output open.
    quiet = {"stdin": subprocess.DEVNULL, "stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    subprocess.run([binary, "wineboot"], env=env, timeout=300, **quiet)
    yield [binary]
    if server:
        subprocess.run([server, "-k"], env=env, capture_output=True, timeout=60)


def exe(lang: str, pkg: str, tool: str) -> Path:
    if lang == "c":
        return OUT / "prefix" / "c" / pkg / "bin" / f"{pkg}-{tool}.exe"
    return OUT / "cpp" / pkg / "build" / f"{pkg}-{tool}.exe"


def shifted(line: str, base: int) -> str:
    """A vector's expected line with its stream offset moved by base bytes."""
    m = re.match(r'\{"offset":(\d+)', line)
    assert m, line
    return '{"offset":%d' % (int(m.group(1)) + base) + line[m.end() :]


TOOLS = [("c", pkg) for pkg in sorted(PACKAGES.values())] + [("cpp", pkg) for pkg in CPP_PACKAGES]


@pytest.mark.parametrize("lang,pkg", TOOLS)
def test_every_vector_under_wine(lang, pkg, c_prefixes, cpp_prefixes, wine, tmp_path):
    """Every golden vector of the package's protocol, decoded by the Windows build: the vectors
    whose packets all decode are concatenated per device (one process each; offsets moved), those
    with skipped bytes (whose skip would run into the next vector) run alone. Then all expected
    lines through the encode tool: the vectors' bytes. Output on stdout is binary (LF, no CR)."""
    protocol = next(name for name, p in PACKAGES.items() if p == pkg)
    vectors = [v for v in VECTORS if v["protocol"] == protocol]
    streams: dict[str | None, tuple[bytearray, list[str]]] = {}
    alone = []
    for v in vectors:
        if any('"skipped"' in line for line in v["expect"]):
            alone.append(v)
            continue
        data, lines = streams.setdefault(v["device"], (bytearray(), []))
        lines += [shifted(line, len(data)) for line in v["expect"]]
        data += bytes.fromhex(v["hex"])
    runs = [(dev, bytes(data), lines) for dev, (data, lines) in streams.items()]
    runs += [(v["device"], bytes.fromhex(v["hex"]), v["expect"]) for v in alone]
    failures = []
    for k, (dev, data, lines) in enumerate(runs):
        path = tmp_path / f"{k}.bin"
        path.write_bytes(data)
        extra = ["--device", dev] if dev else []
        r = subprocess.run([*wine, exe(lang, pkg, "decode"), *extra, path], capture_output=True)
        want = "".join(line + "\n" for line in lines).encode()
        if r.returncode != 0 or r.stdout != want:
            failures.append(f"{dev} {len(data)} bytes: exit {r.returncode}, {r.stderr[-300:]!r}")
    assert not failures, "\n".join(failures)
    assert len(runs) < len(vectors) // 4  # the concatenation keeps the run short
    # the lines back to bytes (every vector, in order; one process)
    # (not the cases with NMEA or RTCM3 lines: encode refuses those lines, docs/conformance.md section 5)
    encodable = [v for v in vectors if not any('"nmea":' in line or '"rtcm":' in line for line in v["expect"])]
    text = "".join(line + "\n" for v in encodable for line in v["expect"]).encode()
    r = subprocess.run([*wine, exe(lang, pkg, "encode")], input=text, capture_output=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout == b"".join(bytes.fromhex(v["hex"]) for v in encodable)


@pytest.mark.parametrize("lang", ["c", "cpp"])
def test_session_tool_under_wine_against_the_simulator(lang, c_prefixes, cpp_prefixes, wine):
    """The Windows session tool (Winsock transport) against the Python simulator on 127.0.0.1: a
    ping, then the round trips of every setting of the GX5-45 (test_simulator's plan), checked
    the same way as the native tools'."""
    protocol, device = "mip", "gx5_45"
    proto = PROTOCOLS[protocol]
    ping = next(f for s in proto["sets"] if s["id"] == 1 for f in s["fields"] if f["name"] == "ping")
    lines = [command_line(proto, 1, ping["id"], "ping", {})]
    plans = roundtrip_plan(proto, device)
    for p in plans:
        lines += p[1]
    with Sim(protocol, device, "tcp:127.0.0.1:0") as sim:
        r = subprocess.run(
            [*wine, exe(lang, "mipcodec", "session"), "--connect", sim.address, "--device", device],
            input="\n".join(lines) + "\n",
            capture_output=True,
            text=True,
            timeout=600,
        )
    assert r.returncode == 0, r.stderr
    out = [json.loads(x) for x in r.stdout.splitlines()]
    res = results(out)
    assert res[0] == {"line": 1, "result": "ack", "code": 0, "reply": []}
    assert check_roundtrips(proto, device, res[1:]) == len(plans)


@pytest.mark.parametrize("lang", ["c", "cpp"])
def test_session_tool_under_wine_reports_a_refused_connection(lang, c_prefixes, cpp_prefixes, wine):
    """Nothing listens on the port: one line with the address and the system's reason, exit 2."""
    with socket.socket() as s:  # a free port, closed again before the tool connects
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    r = subprocess.run(
        [*wine, exe(lang, "mipcodec", "session"), "--connect", f"tcp:127.0.0.1:{port}"],
        input="",
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 2, (r.returncode, r.stdout, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "cannot connect to" in lines[0] and str(port) in lines[0], r.stderr


@pytest.mark.parametrize("lang", ["c", "cpp"])
def test_session_tool_under_wine_asks_for_tcp_before_a_host_and_port(lang, c_prefixes, cpp_prefixes, wine):
    """HOST:PORT without "tcp:" is not taken for a COM port (issue 39 item 5): the same one line
    as on POSIX and in Python and Rust, exit 2, before anything is opened."""
    r = subprocess.run(
        [*wine, exe(lang, "mipcodec", "session"), "--connect", "127.0.0.1:5000"],
        input="",
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 2, (r.returncode, r.stdout, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].endswith(
        "'127.0.0.1:5000' is not a serial port: did you mean tcp:127.0.0.1:5000?"
    ), r.stderr


def test_installed_c_package_links_a_windows_program(c_prefixes, wine, tmp_path):
    """A project of its own: find_package(mipcodec CONFIG REQUIRED COMPONENTS c c_win32) with the
    installed toolchain file, a program through mipcodec/native_transport.h (the Win32 transport
    on Windows): a bad address and a COM port that does not exist give the transport's messages."""
    need_toolchain()
    prefix = c_prefixes["mipcodec"]
    (tmp_path / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.16)\nproject(winapp LANGUAGES C)\n"
        "find_package(mipcodec 0.1 CONFIG REQUIRED COMPONENTS c c_win32)\n"
        "add_executable(winapp main.c)\ntarget_link_libraries(winapp PRIVATE mipcodec::c_win32)\n"
    )
    (tmp_path / "main.c").write_text(
        '#include <stdio.h>\n#include "mipcodec/native_transport.h"\n'
        "int main(int argc, char **argv) {\n"
        "    mipc_native_t t;\n"
        "    int i;\n"
        "    for (i = 1; i < argc; i++) {\n"
        "        if (mipc_native_open(&t, argv[i], 115200) == MIPC_OK) {\n"
        '            printf("open\\n");\n'
        "            mipc_native_close(&t);\n"
        "        } else {\n"
        '            printf("%s\\n", t.error);\n'
        "        }\n"
        "    }\n"
        "    return 0;\n"
        "}\n"
    )
    toolchain = prefix / "share" / "mipcodec" / f"{TRIPLE}.cmake"
    run(
        [
            "cmake",
            "-G",
            "Ninja",
            "-S",
            tmp_path,
            "-B",
            tmp_path / "b",
            f"-DCMAKE_TOOLCHAIN_FILE={toolchain}",
            # the toolchain file looks for packages in the MinGW sysroot and the roots given
            f"-DCMAKE_FIND_ROOT_PATH={prefix}",
        ]
    )
    run(["cmake", "--build", tmp_path / "b"])
    r = subprocess.run(
        [*wine, tmp_path / "b" / "winapp.exe", "127.0.0.1:5000", "COM250"], capture_output=True, text=True, timeout=120
    )
    assert r.returncode == 0, r.stderr
    bad_tcp, no_port = r.stdout.splitlines()
    # HOST:PORT without tcp: is refused with a hint (issue 39 item 5, the rule of every language);
    # COM250 is opened as \\.\COM250 and is not there
    assert bad_tcp == "'127.0.0.1:5000' is not a serial port: did you mean tcp:127.0.0.1:5000?", bad_tcp
    assert no_port.startswith("cannot open COM250 at 115200 baud: "), no_port
