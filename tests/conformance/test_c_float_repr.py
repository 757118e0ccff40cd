"""The C package's float printer (json_writer.c: shortest round-trip digits in exact integer
arithmetic) against Python's repr(float) on many doubles: random bit patterns, random float32
values widened, and the edges of every binary exponent. The canonical table of
generator/testcases.py checks fewer values in every package's own suite."""

from __future__ import annotations

import random
import struct
import subprocess
from pathlib import Path

from generator.targets.c.backend import c_prefix

ROOT = Path(__file__).resolve().parents[2]
PKG = ROOT / "generated" / "c" / "mipcodec"
HARNESS = r"""
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mipcodec/json.h"
int main(void) {
    char line[64], out[PFX_JSON_NUMBER_MAX];
    while (fgets(line, sizeof line, stdin)) {
        uint64_t b = strtoull(line, NULL, 16);
        double v;
        memcpy(&v, &b, sizeof v);
        pfx_json_format_double(v, out, sizeof out);
        puts(out);
    }
    return 0;
}
""".replace("PFX_", c_prefix("mipcodec").upper() + "_").replace("pfx_", c_prefix("mipcodec") + "_")


def canonical(bits: int) -> str:
    v = struct.unpack("<d", struct.pack("<Q", bits))[0]
    if v != v:
        return '"nan"' if bits == 0x7FF8000000000000 else f'"nan:0x{bits:016x}"'
    if v in (float("inf"), float("-inf")):
        return '"inf"' if v > 0 else '"-inf"'
    return repr(v)


def test_c_doubles_print_as_python_repr(tmp_path):
    src = tmp_path / "fmt.c"
    src.write_text(HARNESS)
    exe = tmp_path / "fmt"
    subprocess.run(
        [
            "gcc",
            "-O2",
            "-std=c99",
            "-Wall",
            "-Werror",
            f"-I{PKG / 'include'}",
            f"-I{PKG / 'src'}",
            str(src),
            str(PKG / "src" / "json_writer.c"),
            "-o",
            str(exe),
        ],
        check=True,
    )
    rng = random.Random(20261125)
    values = [rng.getrandbits(64) for _ in range(200_000)]
    for _ in range(200_000):
        f = struct.unpack("<f", struct.pack("<I", rng.getrandbits(32)))[0]
        values.append(struct.unpack("<Q", struct.pack("<d", f))[0])
    values += [(e << 52) | m for e in range(0x800) for m in (0, 1, 2, (1 << 52) - 1, 1 << 51) if e or m]
    values += [b | (1 << 63) for b in values[-100:]]
    run = subprocess.run(
        [str(exe)], input="".join(f"{v:016x}\n" for v in values), capture_output=True, text=True, check=True
    )
    got = run.stdout.splitlines()
    assert len(got) == len(values)
    wrong = [(f"{v:016x}", g, canonical(v)) for v, g in zip(values, got) if g != canonical(v)]
    assert not wrong, wrong[:10]
