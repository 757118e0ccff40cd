"""The C core of mipcodec built freestanding for a Cortex-M4F with Debian's gcc-arm-none-eabi and
newlib (`make test-cortexm`, run by .ci/run; tools/bootstrap --ci installs the toolchain), with the
toolchain file the C package ships (cmake/arm-none-eabi.cmake, docs/packaging.md "Firmware"):

- the consumer project tests/consumer/cortexm/ vendors the package with add_subdirectory and links
  a minimal image (ping + stream parser + scaled-accel decode) at -Os. Prints the image's code size
  (arm-none-eabi-size) and checks that nothing of stdio, the heap or JSON is in it;
- the package itself configured top-level with only the toolchain file (no option: its tests need
  no googletest unless asked for), built and installed: ARM static libraries, no POSIX library."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
HERE = ROOT / "tests" / "consumer" / "cortexm"
OUT = ROOT / "build" / "consumer" / "cortexm"
C_SRC = ROOT / "generated" / "c" / "mipcodec"
TOOLCHAIN = C_SRC / "cmake" / "arm-none-eabi.cmake"


def run(cmd: list) -> str:
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
    assert r.returncode == 0, f"{' '.join(map(str, cmd))} failed ({r.returncode}):\n{r.stdout}\n{r.stderr}"
    return r.stdout + r.stderr


def need_toolchain() -> None:
    missing = [t for t in ("arm-none-eabi-gcc", "arm-none-eabi-size", "arm-none-eabi-nm") if not shutil.which(t)]
    assert not missing, f"missing {missing}: apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi"


def test_cortex_m4_image():
    need_toolchain()
    shutil.rmtree(OUT, ignore_errors=True)
    run(
        [
            "cmake",
            "-G",
            "Ninja",
            "-S",
            HERE,
            "-B",
            OUT,
            f"-DCMAKE_TOOLCHAIN_FILE={TOOLCHAIN}",
            "-DCMAKE_BUILD_TYPE=MinSizeRel",
            f"-DMIPCODEC_C_DIR={C_SRC}",
            "-DMIPCODEC_WERROR=ON",
        ]
    )
    log = run(["cmake", "--build", OUT])
    assert "warning" not in log
    image = OUT / "firmware.elf"
    size = run(["arm-none-eabi-size", image])
    print(f"\nCortex-M4 image (ping + parser + scaled-accel decode, -Os, newlib-nano):\n{size}")
    text, data, bss = (int(x) for x in size.splitlines()[1].split()[:3])
    symbols = {ln.split()[-1] for ln in run(["arm-none-eabi-nm", image]).splitlines() if ln.split()}
    # what the image is made of: the parser, the decoder and the packet builder it calls ...
    assert {"mipc_parser_feed", "mipc_sensor_scaled_accel_decode", "mipc_packet_finish", "vectors"} <= symbols
    # ... and no stdio, heap or JSON (a JSON or printf call would bring tens of kilobytes)
    unwanted = [
        s
        for s in symbols
        if s in {"malloc", "free", "printf", "snprintf", "vsnprintf", "_printf_i", "strtod", "_malloc_r"}
        or "json" in s
        or s.startswith("_svfprintf")
    ]
    assert unwanted == []
    assert 0 < text < 16384 and bss < 4096, size


def test_top_level_cortex_m_build():
    """The README's recipe for a firmware team: the C package configured as the top-level project
    with the shipped toolchain file and nothing else, built and installed. No googletest, C++ or
    POSIX is needed; the libraries are ARM objects."""
    need_toolchain()
    top = OUT.parent / "cortexm-top"
    out, prefix = top / "build", top / "prefix"
    shutil.rmtree(top, ignore_errors=True)
    log = run(["cmake", "-S", C_SRC, "-B", out, f"-DCMAKE_TOOLCHAIN_FILE={TOOLCHAIN}"])
    assert "gtest" not in log.lower()
    run(["cmake", "--build", out])
    run(["cmake", "--install", out, "--prefix", prefix])
    libs = sorted(p.name for p in prefix.rglob("*.a"))
    assert libs == ["libmipcodec.a", "libmipcodec_json.a"], libs
    objdump = run(["arm-none-eabi-objdump", "-f", next(prefix.rglob("libmipcodec.a"))])
    assert "file format elf32-littlearm" in objdump
    assert (prefix / "share" / "mipcodec" / "arm-none-eabi.cmake").read_bytes() == TOOLCHAIN.read_bytes()
