"""The golden packages build and pass their own generated tests, the fixture's hand-derived vectors
(tests/golden/vectors/demo/) among them, in every language. They are built from the complete
rendering in build/golden/tree/ (tests/golden/refresh.py: the golden tree tests/golden/everything/
plus the runtime copies it lists), rendered afresh once per run:

  c, cpp   CMake + Ninja (Debug, the packages' own -Werror flags), then the googletest binary
  rust     cargo test (every test target of the crate)
  python   pytest of the package, pure Python (DEMOCODEC_PURE=1) and with its C accelerator
           built by its own setup.py in a copy; mypy --strict of the package, as its consumers run it

Build directories live under build/golden/ and are reused, so a run after the first one only
rebuilds what the rendering changed. Nothing is written into the golden tree.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from generator.targets import NAMES
from tests.golden.refresh import ROOT, TREE, fresh

PACKAGE = "democodec"
BUILD = ROOT / "build" / "golden"


@pytest.fixture(scope="module", autouse=True)
def rendered() -> None:
    fresh()  # build/golden/tree/ is what the back ends render now


def test_every_target_is_built_here() -> None:
    # a target added to the registry needs its build and test step in this module
    built = {"c", "cpp", "rust", "python"}
    assert sorted(NAMES) == sorted(built), f"no golden build for {sorted(set(NAMES) - built)}"


def run(cmd: list[str], **kw) -> None:
    """Runs cmd; on failure the assertion carries its output (pytest shows it)."""
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, **kw)
    assert r.returncode == 0, (
        f"{' '.join(map(str, cmd))} failed ({r.returncode}):\n{r.stdout[-4000:]}\n{r.stderr[-4000:]}"
    )


def cmake_build_and_test(lang: str) -> None:
    src, out = TREE / lang / PACKAGE, BUILD / lang / PACKAGE
    P = PACKAGE.upper()
    cache = out / "CMakeCache.txt"
    if not (out / "build.ninja").is_file() or f"{P}_BUILD_TESTS:BOOL=ON" not in cache.read_text():
        # the packages' own -Werror option (OFF for consumers), as the project's CI builds them, and
        # their tests, tools and examples, which are OFF unless asked for
        asked = [f"-D{P}_BUILD_{what}=ON" for what in ("TESTS", "TOOLS", "EXAMPLES")]
        run(["cmake", "-G", "Ninja", "-S", src, "-B", out, "-DCMAKE_BUILD_TYPE=Debug", f"-D{P}_WERROR=ON", *asked])
    run(["cmake", "--build", out])
    run([out / f"{PACKAGE}-tests", "--gtest_brief=1"])


def test_c_package_builds_and_passes_its_tests() -> None:
    cmake_build_and_test("c")


def test_cpp_package_builds_and_passes_its_tests() -> None:
    cmake_build_and_test("cpp")


def copy_of(lang: str) -> Path:
    """A fresh copy of the rendered package under build/golden/<lang>/src/ (timestamps kept, so
    incremental builds stay incremental), for the tools that write beside their sources."""
    out = BUILD / lang / "src" / PACKAGE
    if out.exists():
        shutil.rmtree(out)
    shutil.copytree(TREE / lang / PACKAGE, out)
    return out


def test_rust_crate_builds_and_passes_its_tests() -> None:
    # from a copy: cargo writes Cargo.lock beside Cargo.toml
    env = dict(os.environ, CARGO_TARGET_DIR=str(BUILD / "rust" / "target"))
    run(["cargo", "test", "--quiet", "--manifest-path", copy_of("rust") / "Cargo.toml"], env=env)


def _pytest(package_dir: Path, **extra: str) -> None:
    """The package's tests run inside the package (bytecode cached under build/)."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("DEMOCODEC_")}
    env.update(PYTHONPATH=str(package_dir), PYTHONPYCACHEPREFIX=str(BUILD / "python" / "pycache"), **extra)
    run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "tests"], cwd=package_dir, env=env)


def test_python_package_passes_its_tests_pure() -> None:
    _pytest(TREE / "python" / PACKAGE, DEMOCODEC_PURE="1")


def test_python_package_passes_its_tests_with_the_c_accelerator() -> None:
    # the extension is built in place in a copy (unchanged codec/_speedups*.c are not recompiled:
    # its object file stays in build/golden/python/ext-tmp/), never in the golden tree
    out = copy_of("python")
    run(
        [sys.executable, "setup.py", "-q", "build_ext", "--inplace", "--build-temp", BUILD / "python" / "ext-tmp"],
        cwd=out,
        env=dict(os.environ, PYTHONPYCACHEPREFIX=""),
    )
    assert list((out / PACKAGE).glob("codec/_speedups*.so")), "the C accelerator did not build"
    _pytest(out, DEMOCODEC_EXPECT_ACCELERATED="1")


def test_python_package_passes_mypy_strict() -> None:
    # as tests/lang/python.sh checks the project's packages: typed (py.typed), strict
    package = TREE / "python" / PACKAGE
    run(
        [
            sys.executable,
            "-m",
            "mypy",
            "--strict",
            "--explicit-package-bases",
            "--no-error-summary",
            "--cache-dir",
            BUILD / "python" / "mypy-cache",
            PACKAGE,
            *sorted(p.relative_to(package) for p in (package / "examples").glob("*.py")),
        ],
        cwd=package,
    )
