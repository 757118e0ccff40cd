"""Replays tests/fuzz/regressions/generator/loader/* and, when FUZZ_SEED_CORPUS names a seed
directory (tests/fuzz/seeds.py output), the seeds through the spec loader harness, as plain pytest
tests (atheris is not needed); `make test-fuzz-regressions` runs it."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tests.fuzz.spec import harness

REGRESSIONS = Path(__file__).resolve().parents[1] / "regressions" / "generator" / "loader"


def _files(d: Path) -> list[Path]:
    return sorted(f for f in d.iterdir() if f.is_file() and not f.name.startswith(".")) if d.is_dir() else []


def test_regressions() -> None:
    files = _files(REGRESSIONS)
    assert files, f"no regression inputs in {REGRESSIONS}"
    for f in files:
        harness.spec_loader(f.read_bytes())


def test_seeds() -> None:
    corpus = os.environ.get("FUZZ_SEED_CORPUS")
    if not corpus:
        pytest.skip("FUZZ_SEED_CORPUS not set")
    files = _files(Path(corpus) / "generator" / "loader")
    assert len(files) > 50, f"too few seeds in {corpus}/generator/loader"
    built = [f.name for f in files if harness.spec_loader(f.read_bytes()) is not None]
    assert sorted(built) == [f"real-{n}" for n in sorted(harness.FILES[:4])]  # the hostile ones are refused


def test_a_broken_property_is_reported() -> None:
    from generator.diagnostics import Location, SpecError

    with pytest.raises(harness.FuzzCheckFailed):
        harness.check_error(SpecError(None, "a message with no place"))
    with pytest.raises(harness.FuzzCheckFailed):
        harness.check_error(SpecError(Location("spec/mscip/base.yaml", 1, 1), "two\nlines"))
