"""Renders the package the runtime's unit tests import with the real back end.

The test protocol `testproto` (tests/runtime_specs/, docs/runtime-contract.md) is rendered by the
Python back end into build/runtime_specs/<framing>/python/testproto/ (tests/runtime_specs/render.py:
the runtime files of this folder's parent copied in, beside the modules the templates render), and
that package is put first on sys.path: the tests run against what the generator produces, not
against hand-written stand-ins. TESTPROTO_FRAMING=b takes the spec's framing b instead of framing a:
between them, each branch of the runtime's framing choices. Unless TESTPROTO_PURE=1 asks for the
pure-Python code, the C accelerator is compiled there by the package's own setup.py (unchanged
_speedups*.c are not recompiled); it must build. tests/lang/python.sh test runs these tests with both
framings, pure and accelerated.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

RUNTIME = Path(__file__).resolve().parent.parent
ROOT = RUNTIME.parents[3]
PACKAGE = "testproto"
FRAMING = os.environ.get(PACKAGE.upper() + "_FRAMING", "a")
if FRAMING not in ("a", "b"):
    raise pytest.UsageError(f"TESTPROTO_FRAMING={FRAMING!r}: expected a or b")

sys.path.insert(0, str(ROOT))
from tests.runtime_specs.render import render  # noqa: E402

try:
    OUT = render("python", FRAMING) / "python" / PACKAGE
except RuntimeError as e:
    raise pytest.UsageError(str(e)) from None


def _build_accelerator(out: Path) -> None:
    pkg = out / PACKAGE
    cmd = [sys.executable, "setup.py", "-q", "build_ext", "--inplace", "--build-temp", str(out.parent / "build-temp")]
    env = dict(os.environ, PYTHONPYCACHEPREFIX="")
    env.pop(PACKAGE.upper() + "_NO_EXTENSION", None)
    run = subprocess.run(cmd, cwd=out, env=env, capture_output=True, text=True)
    if run.returncode != 0 or not list(pkg.glob("codec/_speedups*.so")) + list(pkg.glob("codec/_speedups*.pyd")):
        pytest.exit(
            f"building the C accelerator (runtime/codec/_speedups*.c) failed (TESTPROTO_PURE=1 runs the pure-Python code):\n"
            f"{run.stdout}{run.stderr}",
            returncode=1,
        )


PURE = os.environ.get(PACKAGE.upper() + "_PURE", "") not in ("", "0")
if not PURE:
    _build_accelerator(OUT)
sys.path.insert(0, str(OUT))
