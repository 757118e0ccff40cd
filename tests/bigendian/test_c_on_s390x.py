"""The C library on a big-endian host: every golden vector through the C tools built for s390x
(big-endian) and run under qemu-user, plus a long mixed stream compared with the native build.

Run with `make test-bigendian` (needs Debian's gcc-s390x-linux-gnu, libc6-dev-s390x-cross and
qemu-user; `.ci/run` installs them). Not part of `make test`.
"""

import random
import shutil
import subprocess
from pathlib import Path

import pytest

from generator.spec import load_spec
from generator.vectors import load_corpus

ROOT = Path(__file__).resolve().parents[2]
IR = load_spec()
VECTORS = load_corpus(IR, ROOT)


def _foreign(case: dict) -> bool:
    """Whether a case's lines hold an NMEA sentence or RTCM3 frame: encode refuses those lines
    (docs/conformance.md section 5), so such a case is decoded but not encoded back."""
    return any('"nmea":' in line or '"rtcm":' in line for line in case["expect"])


PACKAGES = {p["name"]: p["package"] for p in IR["protocols"]}
CC = "s390x-linux-gnu-gcc"
QEMU = "qemu-s390x"


@pytest.fixture(scope="module")
def tools():
    missing = [t for t in (CC, QEMU) if shutil.which(t) is None]
    assert not missing, f"missing {missing}: apt-get install gcc-s390x-linux-gnu libc6-dev-s390x-cross qemu-user"
    out = ROOT / "build" / "c-s390x"
    out.mkdir(parents=True, exist_ok=True)
    built = {}
    for pkg_dir in sorted((ROOT / "generated" / "c").iterdir()):
        srcs = sorted(str(p) for p in (pkg_dir / "src").rglob("*.c"))
        for tool in ("decode", "encode"):
            exe = out / f"{pkg_dir.name}-{tool}"
            cmd = [
                CC,
                "-std=c99",
                "-O1",
                "-Wall",
                "-Wextra",
                "-Werror",
                "-pedantic",
                "-static",
                f"-I{pkg_dir / 'include'}",
                f"-I{pkg_dir / 'src'}",
                *srcs,
                str(pkg_dir / "tools" / f"{tool}.c"),
                "-o",
                str(exe),
            ]
            subprocess.run(cmd, check=True)
            built[(pkg_dir.name, tool)] = exe
    # the target really is big-endian
    probe = out / "probe"
    (out / "probe.c").write_text("int main(void){unsigned x=1;return *(unsigned char*)&x;}\n")
    subprocess.run([CC, "-static", str(out / "probe.c"), "-o", str(probe)], check=True)
    assert subprocess.run([QEMU, str(probe)]).returncode == 0, "s390x build is not big-endian"
    return built


def _run(tools, tool, *args, data=None, protocol="mip"):
    proc = subprocess.run([QEMU, str(tools[(PACKAGES[protocol], tool)]), *args], input=data, capture_output=True)
    assert proc.returncode == 0, proc.stderr.decode(errors="replace")
    return proc.stdout


def test_every_vector_on_big_endian(tools, tmp_path):
    failures = []
    for c in VECTORS:
        p = tmp_path / f"{c['name']}.bin"
        p.write_bytes(bytes.fromhex(c["hex"]))
        extra = ("--device", c["device"]) if c.get("device") else ()
        got = _run(tools, "decode", *extra, str(p), protocol=c["protocol"]).decode()
        want = "".join(line + "\n" for line in c["expect"])
        if got != want:
            failures.append(f"{c['name']}: got {got!r}")
            continue
        if not _foreign(c) and _run(tools, "encode", data=got.encode(), protocol=c["protocol"]) != p.read_bytes():
            failures.append(f"{c['name']}: encode differs")
    assert not failures, "\n".join(failures)


@pytest.mark.parametrize("protocol", sorted(PACKAGES))
def test_mixed_stream_matches_native(tools, tmp_path, protocol):
    """Every vector of every protocol, with garbage between, decoded as `protocol` (the other
    protocol's packets are skipped bytes) on big-endian and natively: the same lines."""
    rng = random.Random(7)
    parts = []
    for c in [c for c in VECTORS if not _foreign(c)] * 3:  # encoded back below
        parts.append(bytes(rng.randrange(256) for _ in range(rng.randrange(4))))
        parts.append(bytes.fromhex(c["hex"]))
    stream = tmp_path / "mixed.bin"
    stream.write_bytes(b"".join(parts))
    native = subprocess.run(
        [str(ROOT / "tests/conformance/decode"), "c", str(stream), "--protocol", protocol],
        capture_output=True,
        check=True,
    ).stdout
    assert _run(tools, "decode", str(stream), protocol=protocol) == native
    assert _run(tools, "encode", data=native, protocol=protocol) == stream.read_bytes()
