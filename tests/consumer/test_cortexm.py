"""The C core of mipcodec built freestanding for a Cortex-M4F with Debian's gcc-arm-none-eabi and
newlib (`make test-cortexm`, run by .ci/run; tools/bootstrap --ci installs the toolchain): the
consumer project tests/consumer/cortexm/ vendors the package with add_subdirectory and links a
minimal image (ping + stream parser + scaled-accel decode) at -Os. Prints the image's code size
(arm-none-eabi-size) and checks that nothing of stdio, the heap or JSON is in it."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
HERE = ROOT / "tests" / "consumer" / "cortexm"
OUT = ROOT / "build" / "consumer" / "cortexm"
C_SRC = ROOT / "generated" / "c" / "mipcodec"


def run(cmd: list) -> str:
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
    assert r.returncode == 0, f"{' '.join(map(str, cmd))} failed ({r.returncode}):\n{r.stdout}\n{r.stderr}"
    return r.stdout + r.stderr


def test_cortex_m4_image():
    missing = [t for t in ("arm-none-eabi-gcc", "arm-none-eabi-size", "arm-none-eabi-nm") if not shutil.which(t)]
    assert not missing, f"missing {missing}: apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi"
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
            f"-DCMAKE_TOOLCHAIN_FILE={HERE / 'arm-none-eabi.cmake'}",
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
