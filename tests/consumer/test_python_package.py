"""The generated Python packages consumed the documented way, out of the tree: built into an sdist
and a wheel (`python -m build`), installed with `pip install --no-index` from those artifacts into
clean virtualenvs (no network: the packages have no dependencies), then used from outside the
repository. Run by `tests/lang/python.sh test` (make test); alone: `tests/lang/python.sh consumer`.

Per package, under build/python/consumer/<package>/ (recreated each run):
- `python -m build --no-isolation`: the sdist, then the wheel built from the unpacked sdist (so the
  sdist must carry everything, _protocol.h included, for the C accelerator to compile); the build
  uses the pinned setuptools of requirements.txt (no isolated environment, so no download);
- the sdist built again into a wheel with CC naming a compiler that does not exist (what
  `pip install <sdist>` does on a machine without a compiler): the build must succeed without the
  accelerator;
- each wheel installed into its own virtualenv (`--without-pip`, pip driven from outside with
  `--python`), where tests/consumer/python/smoke.py decodes every golden vector of the package and
  encodes it back, accelerated or pure as expected, and the console script decodes a packet;
- mipcodec only: tests/consumer/python/typed_mipcodec.py and the package's getting-started
  example pass `mypy --strict` against the installed wheel, and wrong_types_mipcodec.py is
  rejected with exactly its marked errors (so the package's types are read and precise).
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tarfile
import time
import zipfile
from pathlib import Path

import pytest

from generator.vectors import load_vectors

ROOT = Path(__file__).resolve().parents[2]
GENERATED = ROOT / "generated" / "python"
HERE = Path(__file__).resolve().parent / "python"
OUT = ROOT / "build" / "python" / "consumer"
PACKAGES = sorted(p.name for p in GENERATED.iterdir() if (p / "pyproject.toml").is_file())
# Files of the source tree a build may leave behind, never part of what is shipped.
LEFTOVERS = shutil.ignore_patterns("build", "*.egg-info", "__pycache__", "*.pyc", "*.so", ".mypy_cache")
TIMINGS: dict[str, float] = {}


def run(cmd: list[str], what: str, env: dict[str, str] | None = None, cwd: Path | None = None) -> str:
    """Runs cmd; fails the test with its output when it exits non-zero; returns stdout and stderr."""
    start = time.monotonic()
    proc = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=cwd)
    TIMINGS[what] = time.monotonic() - start
    if proc.returncode != 0:
        pytest.fail(f"{what} failed (exit {proc.returncode}): {' '.join(map(str, cmd))}\n{proc.stdout}\n{proc.stderr}")
    return proc.stdout + proc.stderr


def shipped_files(src: Path) -> list[str]:
    """Every file of the package's source tree (generated/python/<package>), relative paths."""
    return sorted(str(p.relative_to(src)) for p in src.rglob("*") if p.is_file() and "__pycache__" not in p.parts)


class Built:
    """The artifacts of one package: sdist, wheels, and the two virtualenvs they are installed in."""

    def __init__(self, package: str) -> None:
        self.package = package
        self.dir = OUT / package
        shutil.rmtree(self.dir, ignore_errors=True)
        self.src = self.dir / "src"
        shutil.copytree(GENERATED / package, self.src, ignore=LEFTOVERS)
        self.dist = self.dir / "dist"
        run(
            [sys.executable, "-m", "build", "--no-isolation", "--outdir", str(self.dist), str(self.src)],
            f"{package}: python -m build (sdist, then wheel from it)",
        )
        (self.sdist,) = self.dist.glob("*.tar.gz")
        (self.wheel,) = self.dist.glob("*.whl")
        # The sdist without a compiler: setup.py's optional extension must be skipped, not fail.
        self.nocc = self.dir / "dist-nocc"
        env = dict(os.environ, CC=str(self.dir / "no-such-compiler"), LDSHARED=str(self.dir / "no-such-linker"))
        self.nocc_log = run(
            [
                sys.executable,
                "-m",
                "pip",
                "wheel",
                "-v",
                "--isolated",
                "--no-cache-dir",
                "--disable-pip-version-check",
                "--no-index",
                "--no-build-isolation",
                "--no-deps",
                "-w",
                str(self.nocc),
                str(self.sdist),
            ],
            f"{package}: wheel from the sdist without a C compiler",
            env=env,
        )
        (self.nocc_wheel,) = self.nocc.glob("*.whl")
        self.venv = self.install("venv", self.dist)
        self.venv_nocc = self.install("venv-nocc", self.nocc)

    def install(self, name: str, links: Path) -> Path:
        """A clean virtualenv with the package installed from `links` only (no index)."""
        venv = self.dir / name
        run([sys.executable, "-m", "venv", "--without-pip", str(venv)], f"{self.package}: {name}: python -m venv")
        python = venv / "bin" / "python"
        run(
            [
                sys.executable,
                "-m",
                "pip",
                "--python",
                str(python),
                "install",
                "--isolated",
                "--no-cache-dir",
                "--quiet",
                "--disable-pip-version-check",
                "--no-index",
                "--find-links",
                str(links),
                self.package,
            ],
            f"{self.package}: {name}: pip install --no-index",
        )
        return venv


_BUILT: dict[str, Built] = {}


def get_built(package: str) -> Built:
    """The package built and installed (once per session)."""
    if package not in _BUILT:
        _BUILT[package] = Built(package)
    return _BUILT[package]


@pytest.fixture(params=PACKAGES)
def built(request: pytest.FixtureRequest) -> Built:
    return get_built(request.param)


@pytest.fixture(scope="module")
def cases() -> dict[str, list[dict]]:
    """The golden vectors per package: name, hex, expected canonical JSON lines."""
    ir = json.loads((ROOT / "generated" / "ir.json").read_text(encoding="utf-8"))
    packages = {p["name"]: p["package"] for p in ir["protocols"]}
    out: dict[str, list[dict]] = {}
    for case in load_vectors(ir, ROOT / "tests" / "vectors"):
        out.setdefault(packages[case["protocol"]], []).append(
            {"name": case["name"], "hex": case["hex"], "device": case["device"], "expect": case["expect"]}
        )
    return out


def test_sdist_carries_the_whole_package(built: Built) -> None:
    with tarfile.open(built.sdist) as tar:
        top = f"{built.sdist.name[: -len('.tar.gz')]}/"
        names = {n[len(top) :] for n in tar.getnames() if n.startswith(top)}
    missing = [f for f in shipped_files(GENERATED / built.package) if f not in names]
    assert not missing, f"{built.sdist.name} lacks {missing}"
    for needed in ("py.typed", "codec/_protocol.h", "codec/_speedups.c"):
        assert f"{built.package}/{needed}" in names
    assert not [n for n in names if n.endswith((".so", ".pyc"))], f"build leftovers in {built.sdist.name}"


def test_wheels_carry_the_marker_and_the_accelerator_when_compiled(built: Built) -> None:
    for wheel, compiled in ((built.wheel, True), (built.nocc_wheel, False)):
        with zipfile.ZipFile(wheel) as z:
            names = z.namelist()
        assert f"{built.package}/py.typed" in names, wheel.name
        assert f"{built.package}/__init__.py" in names, wheel.name
        so = [n for n in names if n.startswith(f"{built.package}/codec/_speedups") and n.endswith(".so")]
        assert bool(so) == compiled, f"{wheel.name}: accelerator {so}, expected compiled={compiled}"
        if (GENERATED / built.package / "LICENSE").is_file():
            assert any(n.endswith("/LICENSE") and ".dist-info/" in n for n in names), f"{wheel.name} lacks LICENSE"
    # The build log shows the compiler was tried and the optional extension skipped.
    assert f'building extension "{built.package}.codec._speedups" failed' in built.nocc_log, built.nocc_log


@pytest.mark.parametrize("mode", ["accelerated", "pure"])
def test_installed_package_decodes_and_encodes_every_vector(
    built: Built, cases: dict[str, list[dict]], mode: str, tmp_path: Path
) -> None:
    path = tmp_path / "cases.json"
    path.write_text(json.dumps(cases[built.package]), encoding="utf-8")
    venv = built.venv if mode == "accelerated" else built.venv_nocc
    # Run from a directory outside the repository, with a clean environment for Python.
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON") and not k.endswith("_PURE")}
    out = run(
        [str(venv / "bin" / "python"), str(HERE / "smoke.py"), built.package, str(path), mode],
        f"{built.package}: smoke ({mode})",
        env=env,
        cwd=tmp_path,
    )
    assert f"{len(cases[built.package])} vectors" in out


def test_console_script_decodes(built: Built, cases: dict[str, list[dict]], tmp_path: Path) -> None:
    case = next(c for c in cases[built.package] if c["expect"] and '"fields"' in c["expect"][0])
    stream = tmp_path / "stream.bin"
    stream.write_bytes(bytes.fromhex(case["hex"]))
    out = run(
        [str(built.venv / "bin" / built.package), "decode", str(stream)],
        f"{built.package}: console script",
        cwd=tmp_path,
    )
    assert out.splitlines() == case["expect"]


def mypy(built: Built, *files: Path) -> subprocess.CompletedProcess[str]:
    cache = OUT / "mypy-cache"
    cmd = [
        sys.executable,
        "-m",
        "mypy",
        "--strict",
        "--no-error-summary",
        "--cache-dir",
        str(cache),
        "--python-executable",
        str(built.venv / "bin" / "python"),
        *map(str, files),
    ]
    start = time.monotonic()
    proc = subprocess.run(cmd, capture_output=True, text=True, cwd=built.dir)
    TIMINGS[f"mypy {' '.join(f.name for f in files)}"] = time.monotonic() - start
    return proc


# The typed consumer is written against mipcodec: one package is enough, the runtime is the same.
def test_mypy_strict_accepts_a_typed_consumer(cases: dict[str, list[dict]]) -> None:
    built = get_built("mipcodec")
    example = built.src / "examples" / "getting_started.py"
    proc = mypy(built, HERE / "typed_mipcodec.py", example)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    case = next(c for c in cases["mipcodec"] if c["name"] == "scaled_accel_example")
    for venv, accelerated in ((built.venv, True), (built.venv_nocc, False)):
        out = run(
            [str(venv / "bin" / "python"), str(HERE / "typed_mipcodec.py"), case["hex"]],
            f"typed consumer ({venv.name})",
            cwd=built.dir,
        )
        assert f"typed_mipcodec: ok (accelerated={accelerated}" in out


def test_mypy_strict_rejects_wrong_types() -> None:
    built = get_built("mipcodec")
    source = HERE / "wrong_types_mipcodec.py"
    expected = [n for n, line in enumerate(source.read_text().splitlines(), 1) if line.endswith("# expected error")]
    proc = mypy(built, source)
    reported = sorted({int(line.split(":")[1]) for line in proc.stdout.splitlines() if ": error:" in line})
    assert proc.returncode == 1 and reported == expected, proc.stdout + proc.stderr


# The getting-started pages' "Run it against the simulator" commands (every language, both packages)
# run from the installed wheels in tests/consumer/test_outside_user.py.
