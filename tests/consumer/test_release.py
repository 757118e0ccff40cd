"""The generated Python packages are ready for PyPI (docs/versioning.md, "Releasing"): the sdist, the
wheel and the pure-Python wheel (`<PACKAGE>_NO_EXTENSION=1`, tagged py3-none-any: what the release
uploads beside the sdist) of each, built with `python -m build`, pass `twine check --strict` (the
long description renders as PyPI renders it, the metadata is complete), carry the metadata a user
of PyPI reads (the README as Markdown, the license expression and file, the Python versions,
keywords) and only classifiers of PyPI's list (trove-classifiers, pinned in requirements.txt).
Run by `make test-release`, with `tests/lang/rust.sh publish` (`cargo publish --dry-run` of every
crate). Artifacts under build/release/python/<package>/ (recreated each run).
"""

from __future__ import annotations

import email.parser
import os
import shutil
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

import pytest
from trove_classifiers import classifiers as KNOWN_CLASSIFIERS

ROOT = Path(__file__).resolve().parents[2]
GENERATED = ROOT / "generated" / "python"
OUT = ROOT / "build" / "release" / "python"
PACKAGES = sorted(p.name for p in GENERATED.iterdir() if (p / "pyproject.toml").is_file())
LEFTOVERS = shutil.ignore_patterns("build", "*.egg-info", "__pycache__", "*.pyc", "*.so", ".mypy_cache")


def _run(cmd: list[str], what: str, env: dict[str, str] | None = None) -> str:
    proc = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if proc.returncode != 0:
        pytest.fail(f"{what} failed (exit {proc.returncode}): {' '.join(cmd)}\n{proc.stdout}\n{proc.stderr}")
    return proc.stdout + proc.stderr


@pytest.fixture(scope="module", params=PACKAGES)
def dist(request: pytest.FixtureRequest) -> tuple[str, Path, Path, Path]:
    """(package, sdist, wheel, pure wheel), built from a copy of generated/python/<package>."""
    package = request.param
    out = OUT / package
    shutil.rmtree(out, ignore_errors=True)
    src = out / "src"
    shutil.copytree(GENERATED / package, src, ignore=LEFTOVERS)
    _run(
        [sys.executable, "-m", "build", "--no-isolation", "--outdir", str(out / "dist"), str(src)],
        f"{package}: python -m build",
    )
    (sdist,) = (out / "dist").glob("*.tar.gz")
    (wheel,) = (out / "dist").glob("*.whl")
    env = dict(os.environ, **{f"{package.upper()}_NO_EXTENSION": "1"})
    _run(
        [sys.executable, "-m", "build", "--no-isolation", "--wheel", "--outdir", str(out / "pure"), str(src)],
        f"{package}: python -m build --wheel ({package.upper()}_NO_EXTENSION=1)",
        env=env,
    )
    (pure,) = (out / "pure").glob("*.whl")
    return package, sdist, wheel, pure


def _metadata(package: str, sdist: Path, wheel: Path) -> list[email.message.Message]:
    with tarfile.open(sdist) as tar:
        top = sdist.name[: -len(".tar.gz")]
        member = tar.extractfile(f"{top}/PKG-INFO")
        assert member is not None
        sdist_text = member.read().decode("utf-8")
    with zipfile.ZipFile(wheel) as z:
        (name,) = [n for n in z.namelist() if n.endswith(".dist-info/METADATA")]
        wheel_text = z.read(name).decode("utf-8")
    return [email.parser.Parser().parsestr(t) for t in (sdist_text, wheel_text)]


def test_twine_check_strict(dist: tuple[str, Path, Path, Path]) -> None:
    package, sdist, wheel, pure = dist
    assert pure.name.endswith("-py3-none-any.whl"), pure.name  # PyPI takes no linux_x86_64 wheel
    files = [str(sdist), str(wheel), str(pure)]
    out = _run([sys.executable, "-m", "twine", "check", "--strict", *files], f"{package}: twine check")
    assert out.count("PASSED") == 3, out
    assert "WARNING" not in out and "ERROR" not in out, out


def test_metadata_for_pypi(dist: tuple[str, Path, Path, Path]) -> None:
    package, sdist, wheel, _ = dist
    readme = (GENERATED / package / "README.md").read_text(encoding="utf-8")
    for meta in _metadata(package, sdist, wheel):
        assert meta["Name"] == package
        assert meta["Version"] == (ROOT / "VERSION").read_text(encoding="utf-8").strip()
        assert meta["Summary"]
        assert meta["Description-Content-Type"] == "text/markdown"
        assert meta.get_payload().strip() == readme.strip()  # the README is the long description
        assert meta["License-Expression"] == "MIT"
        assert meta.get_all("License-File") == ["LICENSE"]
        assert meta["Requires-Python"] == ">=3.9"
        assert meta["Keywords"]
        classifiers = meta.get_all("Classifier") or []
        assert classifiers, f"{package}: no classifiers"
        unknown = [c for c in classifiers if c not in KNOWN_CLASSIFIERS]
        assert not unknown, f"{package}: not PyPI classifiers: {unknown}"
        # PEP 639: a license expression and a License :: classifier are not given together.
        assert not [c for c in classifiers if c.startswith("License ::")], classifiers
