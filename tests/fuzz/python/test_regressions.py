"""Replays tests/fuzz/regressions/<package>/<target>/* (inputs that once failed a harness in some
language) through the Python harnesses, as plain pytest tests (atheris is not needed), and, when
FUZZ_SEED_CORPUS names a seed directory (tests/fuzz/seeds.py output), the seeds too."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tests.fuzz.python import harness

HERE = Path(__file__).resolve().parent
REGRESSIONS = HERE.parent / "regressions"
CASES = [(p, t) for p in ("mipcodec", "mscipcodec") for t in ("parser", "decode", "json")]


def _files(d: Path) -> list[Path]:
    return sorted(f for f in d.iterdir() if f.is_file() and not f.name.startswith(".")) if d.is_dir() else []


@pytest.mark.parametrize(("package", "target"), CASES)
def test_regressions(package: str, target: str) -> None:
    for f in _files(REGRESSIONS / package / target):
        harness.TARGETS[target](package, f.read_bytes())


@pytest.mark.parametrize(("package", "target"), CASES)
def test_seeds(package: str, target: str) -> None:
    corpus = os.environ.get("FUZZ_SEED_CORPUS")
    if not corpus:
        pytest.skip("FUZZ_SEED_CORPUS not set")
    files = _files(Path(corpus) / package / target)
    assert files, f"no seeds in {corpus}/{package}/{target}"
    for f in files:
        harness.TARGETS[target](package, f.read_bytes())


def test_a_broken_property_is_reported() -> None:
    """The harness does fail: a stream whose wrapped packet is fine but whose check is fed a
    corrupted expectation raises FuzzCheckFailed."""
    m = harness.load("mipcodec")
    with pytest.raises(harness.FuzzCheckFailed):
        harness._check_line(m, '{"offset":0,"skipped":"00"}', b"\x01")
