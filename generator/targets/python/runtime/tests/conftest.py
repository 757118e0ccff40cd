"""Assembles the package the runtime's unit tests import, without running the generator.

The runtime files (generator/targets/python/runtime/*.py and _speedups.c) and the hand-written test
protocol (protocol/: what the generator would render from a spec) are copied into one package,
build/python/runtime/<framing>/testproto/, which is put first on sys.path. TESTPROTO_FRAMING=b
takes the constants of protocol/framing_b/ instead of protocol/ (framing a): between them, each
branch of the runtime's framing choices. Unless TESTPROTO_PURE=1 asks for the pure-Python code,
the C accelerator is compiled there as the generated packages' setup.py does it (an unchanged
_speedups.c is not recompiled); it must build. tests/lang/python.sh test runs these tests with
both framings, pure and accelerated.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

RUNTIME = Path(__file__).resolve().parent.parent
ROOT = RUNTIME.parents[3]
PACKAGE = "testproto"
PROTOCOL = RUNTIME / "tests" / "protocol"
# grisu3.h: the C runtime's (one source for both), copied beside _speedups.c as the package has it.
GRISU3 = RUNTIME.parents[1] / "c" / "runtime" / "src" / "grisu3.h"
FRAMING = os.environ.get(PACKAGE.upper() + "_FRAMING", "a")
if FRAMING not in ("a", "b"):
    raise pytest.UsageError(f"TESTPROTO_FRAMING={FRAMING!r}: expected a or b")
# One directory per framing: build_ext's timestamp check must not mix the two _protocol.h.
OUT = ROOT / "build" / "python" / "runtime" / FRAMING

# The Extension of the generated setup.py (templates/python/setup.py.j2) for this package.
SETUP = (
    "from setuptools import Extension, setup\n"
    f"setup(name={PACKAGE!r}, ext_modules=[Extension({PACKAGE + '._speedups'!r}, [{PACKAGE + '/_speedups.c'!r}],"
    f" depends=[{PACKAGE + '/_protocol.h'!r}, {PACKAGE + '/grisu3.h'!r}])])\n"
)


def _assemble() -> Path:
    pkg = OUT / PACKAGE
    pkg.mkdir(parents=True, exist_ok=True)
    for old in pkg.glob("*.py"):
        old.unlink()
    sources = [*RUNTIME.glob("*.py"), RUNTIME / "_speedups.c", GRISU3, *PROTOCOL.iterdir()]
    if FRAMING == "b":
        sources += (PROTOCOL / "framing_b").iterdir()  # copied last: replaces framing a's constants
    for src in sources:
        if src.is_file():
            shutil.copy2(src, pkg / src.name)  # timestamps kept: build_ext rebuilds only what changed
    return pkg


def _build_accelerator(pkg: Path) -> None:
    (OUT / "setup.py").write_text(SETUP, encoding="utf-8")
    cmd = [sys.executable, "setup.py", "-q", "build_ext", "--inplace", "--build-temp", str(OUT / "build-temp")]
    env = dict(os.environ, PYTHONPYCACHEPREFIX="")
    run = subprocess.run(cmd, cwd=OUT, env=env, capture_output=True, text=True)
    if run.returncode != 0 or not list(pkg.glob("_speedups*.so")) + list(pkg.glob("_speedups*.pyd")):
        pytest.exit(
            f"building the C accelerator (runtime/_speedups.c) failed (TESTPROTO_PURE=1 runs the pure-Python code):\n"
            f"{run.stdout}{run.stderr}",
            returncode=1,
        )


PURE = os.environ.get(PACKAGE.upper() + "_PURE", "") not in ("", "0")
_pkg = _assemble()
if not PURE:
    _build_accelerator(_pkg)
sys.path.insert(0, str(OUT))
