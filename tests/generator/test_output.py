"""generator/output.py: a regeneration leaves the old tree or the new one, never a mix (issue 28)."""

from __future__ import annotations

import errno
from pathlib import Path

import pytest

from generator import output
from generator.render import ToolError

OLD = {"ir.json": "{}\n", "c/a.h": "a\n", "c/b.h": "b\n", "c/stale.h": "old\n"}
NEW = {"ir.json": "{}\n", "c/a.h": "a\n", "c/b.h": "B!\n", "c/new.h": "n\n"}


def _tree(base: Path) -> dict[str, str]:
    return {str(p.relative_to(base)): p.read_text() for p in sorted(base.rglob("*")) if p.is_file()}


def _made(tmp_path: Path) -> Path:
    out = tmp_path / "gen"
    output.write_tree(out, OLD, ["c"])
    (out / "keep.txt").write_text("not owned\n")
    return out


def test_new_tree_replaces_the_old(tmp_path: Path) -> None:
    out = _made(tmp_path)
    inode_a = (out / "c/a.h").stat().st_ino
    output.write_tree(out, NEW, ["c"])
    assert _tree(out) == {**NEW, "keep.txt": "not owned\n"}  # stale c/stale.h gone, keep.txt kept
    assert (out / "c/a.h").stat().st_ino == inode_a  # unchanged bytes: same file, same mtime
    assert [p.name for p in tmp_path.iterdir()] == ["gen"]  # nothing left beside it
    assert out.stat().st_mode & 0o777 == 0o777 & ~output._umask()  # not mkdtemp's private 0700


def test_unchanged_run_touches_nothing(tmp_path: Path) -> None:
    out = _made(tmp_path)
    before = {p: p.stat().st_mtime_ns for p in out.rglob("*")}
    ino = out.stat().st_ino
    output.write_tree(out, OLD, ["c"])
    assert out.stat().st_ino == ino
    assert {p: p.stat().st_mtime_ns for p in out.rglob("*")} == before


@pytest.mark.parametrize("failure", [OSError(errno.ENOSPC, "No space left on device"), KeyboardInterrupt()])
def test_interrupted_run_leaves_the_old_tree(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, failure) -> None:
    out = _made(tmp_path)
    before = _tree(out)
    real = Path.write_bytes
    calls = []

    def failing(self: Path, data: bytes) -> int:
        calls.append(self)
        if len(calls) == 2:  # the first changed file is written, the second fails
            raise failure
        return real(self, data)

    monkeypatch.setattr(Path, "write_bytes", failing)
    with pytest.raises(ToolError if isinstance(failure, OSError) else KeyboardInterrupt) as e:
        output.write_tree(out, NEW, ["c"])
    if isinstance(failure, OSError):
        assert "left unchanged" in str(e.value) and "No space left on device" in str(e.value)
    assert _tree(out) == before
    assert [p.name for p in tmp_path.iterdir()] == ["gen"]


def test_a_run_killed_between_the_renames_is_recovered(tmp_path: Path) -> None:
    out = _made(tmp_path)
    before = _tree(out)
    out.rename(tmp_path / ".gen.old-xyz")  # the fallback swap died after its first rename
    (tmp_path / ".gen.new-abc").mkdir()
    output.write_tree(out, OLD, ["c"])
    assert _tree(out) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["gen"]


def test_fallback_swap_without_renameat2(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    out = _made(tmp_path)
    monkeypatch.setattr(output, "_exchange", lambda a, b: False)
    output.write_tree(out, NEW, ["c"])
    assert _tree(out) == {**NEW, "keep.txt": "not owned\n"}
    assert [p.name for p in tmp_path.iterdir()] == ["gen"]


def test_write_file_failure_keeps_the_old_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    f = tmp_path / "errata.md"
    output.write_file(f, "old\n")

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(output.os, "replace", full)
    with pytest.raises(ToolError, match="left unchanged"):
        output.write_file(f, "new\n")
    assert f.read_text() == "old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["errata.md"]
