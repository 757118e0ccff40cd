"""The generator as a wheel (issue 24, docs/packaging.md): one wheel is built from the files the
build needs (copied to a temporary directory, so the checkout gets no build/), installed without
network into a temporary virtualenv that sees this interpreter's dependencies, and its `mipgen`
run from outside the checkout on a copy of the every-feature fixture spec. Its output must equal
`python -m generator generate` of the checkout for the same spec."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

from generator.resources import CHECKOUT, SHIPPED, runtime_dir
from generator.targets import NAMES

FIXTURE = Path(__file__).parent / "fixtures" / "everything"
VECTORS = Path(__file__).parents[1] / "golden" / "vectors"
LANGS = "python,c"
BUILD_FILES = ("pyproject.toml", "setup.py", "MANIFEST.in", *SHIPPED)
_IGNORE = shutil.ignore_patterns("__pycache__", "*.pyc", "target", "Cargo.lock", "build", "*.egg-info")


def _run(cmd: list[str], **kw) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, capture_output=True, text=True, timeout=300, **kw)


@pytest.fixture(scope="module")
def installed(tmp_path_factory) -> dict:
    tmp = tmp_path_factory.mktemp("wheel")
    src = tmp / "src"
    for name in (*BUILD_FILES, "generator"):
        s = CHECKOUT / name
        if s.is_dir():
            shutil.copytree(s, src / name, ignore=_IGNORE)
        else:
            (src / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(s, src / name)
    built = _run([sys.executable, "-m", "build", "--wheel", "--no-isolation", "--outdir", str(tmp / "dist"), str(src)])
    assert built.returncode == 0, built.stdout[-2000:] + built.stderr[-2000:]
    (wheel,) = (tmp / "dist").glob("mipgen-*.whl")
    venv = tmp / "venv"
    made = _run([sys.executable, "-m", "venv", "--without-pip", str(venv)])
    assert made.returncode == 0, made.stderr
    py = venv / "bin" / "python"
    pip = [sys.executable, "-m", "pip", "--python", str(py), "--disable-pip-version-check"]
    inst = _run([*pip, "install", "--quiet", "--no-deps", "--no-index", str(wheel)])
    assert inst.returncode == 0, inst.stderr
    # The wheel's dependencies (jinja2, pyyaml, jsonschema, ruff, clang-format: Requires-Dist) are
    # this interpreter's: appended to the venv's path, after the wheel's own `generator`.
    site = Path(_run([str(py), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"]).stdout.strip())
    deps = {sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]}
    (site / "zz_mipgen_test_deps.pth").write_text("\n".join(sorted(deps)) + "\n")
    work = tmp / "work"  # the user's directory, outside the checkout: spec, vectors, output
    shutil.copytree(FIXTURE, work / "spec")
    shutil.copytree(VECTORS, work / "vectors")
    return {"wheel": wheel, "venv": venv, "py": py, "mipgen": venv / "bin" / "mipgen", "work": work}


def _tree(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def test_wheel_carries_every_resource_and_declares_the_pinned_formatters(installed):
    with zipfile.ZipFile(installed["wheel"]) as z:
        names = set(z.namelist())
        meta = next(z.read(n).decode() for n in names if n.endswith(".dist-info/METADATA"))
    for name in SHIPPED:
        src = CHECKOUT / name
        files = [p for p in src.rglob("*") if p.is_file() and "__pycache__" not in p.parts] if src.is_dir() else [src]
        for f in files:
            assert f"generator/_data/{f.relative_to(CHECKOUT).as_posix()}" in names
    for lang in NAMES:
        root = runtime_dir(lang)
        tracked = _run(["git", "ls-files", "--", "."], cwd=root).stdout.split()
        shipped = {f"generator/targets/{lang}/runtime/{t}" for t in tracked if not t.startswith("target/")}
        assert shipped and shipped <= names, sorted(shipped - names)[:5]
    assert not [n for n in names if "/target/" in n or n.endswith((".pyc", "Cargo.lock"))]
    assert "Requires-Dist: clang-format==23.1.3" in meta and "Requires-Dist: ruff==0.17.6" in meta


def test_installed_mipgen_reads_its_own_copies_not_the_checkout(installed):
    probe = _run(
        [
            str(installed["py"]),
            "-c",
            "import generator.resources as r; print(r.CHECKOUT); print(r.ROOT); print(r.missing())",
        ],
        cwd=installed["work"],
    )
    checkout, root, missing = probe.stdout.splitlines()
    assert checkout == "None" and missing == "[]"
    assert Path(root).is_relative_to(installed["venv"]), root


def test_installed_mipgen_generates_what_the_checkout_generates(installed, tmp_path):
    work = installed["work"]
    args = ["generate", "--spec", str(work / "spec"), "--vectors", str(work / "vectors"), "--langs", LANGS]
    got = _run([str(installed["mipgen"]), *args, "--out", str(work / "out")], cwd=work)
    assert got.returncode == 0, got.stderr
    want = _run([sys.executable, "-m", "generator", *args, "--out", str(tmp_path / "out")], cwd=CHECKOUT)
    assert want.returncode == 0, want.stderr
    mine, theirs = _tree(work / "out"), _tree(tmp_path / "out")
    assert (
        {"ir.json"} < set(mine) and any(k.startswith("c/") for k in mine) and any(k.startswith("python/") for k in mine)
    )
    assert sorted(mine) == sorted(theirs)
    assert [k for k in mine if mine[k] != theirs[k]] == []
    # A spec without vectors (a user's first spec) generates too.
    bare = _run(
        [str(installed["mipgen"]), "generate", "--spec", "spec", "--out", "bare", "--langs", "python"], cwd=work
    )
    assert bare.returncode == 0, bare.stderr
    assert (work / "bare" / "python").is_dir()


def test_installed_mipgen_errors_are_one_line(installed):
    work, mipgen = installed["work"], str(installed["mipgen"])
    nospec = _run([mipgen, "generate", "--out", "x"], cwd=work)
    assert nospec.returncode == 2 and "--spec DIR is needed" in nospec.stderr
    assert "Traceback" not in nospec.stderr
    # No rustfmt anywhere: the one-line error that says how to get it, nothing written.
    env = {k: v for k, v in os.environ.items() if k != "RUSTFMT"}
    env.update(PATH="/usr/bin:/bin", CARGO_HOME=str(work / "no-cargo"))
    norust = _run([mipgen, "generate", "--spec", "spec", "--out", "rs", "--langs", "rust"], cwd=work, env=env)
    assert (norust.returncode, norust.stderr.strip().splitlines()) == (
        2,
        ["error: 'rustfmt' is not installed (it formats the generated code); run: rustup component add rustfmt"],
    )
    assert not (work / "rs").exists()
    diff = _run([mipgen, "diff", "spec", "spec"], cwd=work)
    assert diff.returncode == 0 and "verdict: unchanged" in diff.stdout, diff.stdout + diff.stderr
