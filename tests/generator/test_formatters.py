"""Which formatter the generator runs (issue 27): the pinned one in the virtualenv, never another
on PATH; an explicit CLANG_FORMAT/RUSTFMT wins; a missing or broken one is one clear line."""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

from generator import render


def _broken(tmp_path: Path, name: str) -> Path:
    exe = tmp_path / name
    exe.write_text("#!/bin/sh\necho broken >&2\nexit 3\n")
    exe.chmod(0o755)
    return exe


def test_pinned_clang_format_wins_over_path(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _broken(tmp_path, "clang-format")
    monkeypatch.setenv("PATH", f"{tmp_path}{os.pathsep}{os.environ['PATH']}")
    monkeypatch.delenv("CLANG_FORMAT", raising=False)
    exe = render._which("clang-format", "CLANG_FORMAT")
    assert Path(exe) == Path(sys.executable).parent / "clang-format"


def test_explicit_broken_formatter_is_one_clear_error(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("CLANG_FORMAT", str(_broken(tmp_path, "cf")))
    with pytest.raises(render.ToolError) as e:
        render._which("clang-format", "CLANG_FORMAT")
    assert "failed (exit 3)" in str(e.value) and "unset CLANG_FORMAT" in str(e.value)


def test_missing_rustfmt_names_the_command_that_fixes_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("RUSTFMT", raising=False)
    monkeypatch.setenv("CARGO_HOME", str(tmp_path))  # no rustfmt there
    monkeypatch.setenv("PATH", str(tmp_path))  # nor on PATH
    with pytest.raises(render.ToolError) as e:
        render._which("rustfmt", "RUSTFMT")
    assert "run: rustup component add rustfmt" in str(e.value)
