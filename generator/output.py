"""Writing the generated tree: all or nothing.

A regeneration renders every file in memory, then `write_tree` builds the complete new tree in a
temporary directory beside the old one and swaps the two, so an interrupted run (a full disk, a
kill, a formatter failing half-way) leaves either the old tree or the new one, never a mix.

Files whose bytes did not change are hard-linked from the old tree into the new one, so they keep
their inode and modification time and incremental builds (CMake, cargo) rebuild only what changed;
a regeneration that changes nothing touches nothing.

Within the directories a back end owns, files it no longer renders are dropped (they are stale);
anything else already in the tree (e.g. ir.json's neighbours that no back end owns) is kept.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from .render import ToolError

_NEW = ".new-"
_OLD = ".old-"


def _owned(rel: str, owned: list[str]) -> bool:
    return any(rel == d or rel.startswith(d.rstrip("/") + "/") for d in owned)


def _existing(out_dir: Path) -> dict[str, Path]:
    found: dict[str, Path] = {}
    if not out_dir.is_dir():
        return found
    for root, _dirs, names in os.walk(out_dir):
        for n in names:
            p = Path(root, n)
            found[str(p.relative_to(out_dir))] = p
    return found


def _same(path: Path, data: bytes) -> bool:
    try:
        return path.stat().st_size == len(data) and path.read_bytes() == data
    except OSError:
        return False


def _exchange(a: Path, b: Path) -> bool:
    """Atomically swaps two directories (Linux renameat2 RENAME_EXCHANGE); False where the system
    cannot, and the caller falls back to two renames."""
    libc_name = ctypes.util.find_library("c")
    if not libc_name:
        return False
    try:
        libc = ctypes.CDLL(libc_name, use_errno=True)
        renameat2 = libc.renameat2
    except (OSError, AttributeError):
        return False
    at_fdcwd, rename_exchange = -100, 2
    rc = renameat2(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange)
    return rc == 0


def _clean_leftovers(out_dir: Path) -> None:
    """Removes what an interrupted earlier run left beside the tree; restores the old tree if the
    run died between the two renames of the fallback swap."""
    parent = out_dir.parent
    if not parent.is_dir():
        return
    prefix = f".{out_dir.name}"
    for p in sorted(parent.iterdir()):
        if not p.name.startswith(prefix) or not p.is_dir():
            continue
        if p.name.startswith(prefix + _OLD) and not out_dir.exists():
            os.rename(p, out_dir)
        elif p.name.startswith((prefix + _NEW, prefix + _OLD)):
            shutil.rmtree(p, ignore_errors=True)


@dataclass(frozen=True)
class TreeChanges:
    """What a `write_tree` changed, paths relative to the tree (sorted)."""

    added: list[str] = field(default_factory=list)
    modified: list[str] = field(default_factory=list)
    removed: list[str] = field(default_factory=list)
    total: int = 0

    def summary(self, name: str, limit: int = 20) -> list[str]:
        """One line for the tree, then one per changed path (A, M, D as git prints them), at most limit."""
        if not (self.added or self.modified or self.removed):
            return [f"{name}: up to date ({self.total} files)"]
        lines = [
            f"{name}: {len(self.modified)} changed, {len(self.added)} added, {len(self.removed)} removed "
            f"({self.total} files)"
        ]
        marked = sorted(
            [("A", r) for r in self.added] + [("M", r) for r in self.modified] + [("D", r) for r in self.removed],
            key=lambda x: x[1],
        )
        lines += [f"  {mark} {rel}" for mark, rel in marked[:limit]]
        if len(marked) > limit:
            lines.append(f"  ... and {len(marked) - limit} more")
        return lines


def write_tree(out_dir: Path, files: dict[str, str], owned: list[str]) -> TreeChanges:
    """Makes out_dir hold `files` (paths relative to it); stale files in the `owned` directories go.
    Returns what changed."""
    out_dir = Path(out_dir).resolve()
    try:
        _clean_leftovers(out_dir)
        data = {rel: text.encode("utf-8") for rel, text in files.items()}
        existing = _existing(out_dir)
        kept = {rel: p for rel, p in existing.items() if rel not in data and not _owned(rel, owned)}
        stale = [rel for rel in existing if rel not in data and rel not in kept]
        changed = [rel for rel, b in data.items() if rel not in existing or not _same(existing[rel], b)]
        changes = TreeChanges(
            added=sorted(rel for rel in changed if rel not in existing),
            modified=sorted(rel for rel in changed if rel in existing),
            removed=sorted(stale),
            total=len(data) + len(kept),
        )
        if not changed and not stale and out_dir.is_dir():
            return changes
        out_dir.parent.mkdir(parents=True, exist_ok=True)
        new = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}{_NEW}", dir=out_dir.parent))
        os.chmod(new, 0o777 & ~_umask())  # mkdtemp makes it private; the tree is not
    except OSError as e:
        raise ToolError(f"cannot write {out_dir}: {e.strerror or e}") from None
    try:
        changed_set = set(changed)
        for rel in sorted(set(data) | set(kept)):
            dest = new / rel
            dest.parent.mkdir(parents=True, exist_ok=True)
            if rel in data and rel in changed_set:
                dest.write_bytes(data[rel])
                continue
            src = existing[rel]
            try:
                os.link(src, dest)  # same bytes: keep the inode and modification time
            except OSError:
                shutil.copy2(src, dest)
        if out_dir.exists():
            if not _exchange(new, out_dir):
                old = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}{_OLD}", dir=out_dir.parent))
                os.rmdir(old)
                os.rename(out_dir, old)
                os.rename(new, out_dir)
                new = old
            shutil.rmtree(new, ignore_errors=True)  # the old tree, after the swap
        else:
            os.rename(new, out_dir)
    except OSError as e:
        shutil.rmtree(new, ignore_errors=True)
        raise ToolError(f"cannot write {out_dir} (left unchanged): {e.strerror or e}") from None
    except BaseException:
        shutil.rmtree(new, ignore_errors=True)
        raise
    return changes


def write_file(path: Path, text: str) -> None:
    """Replaces one file atomically (a temporary file beside it, then a rename); unchanged bytes
    are not rewritten."""
    path = Path(path)
    data = text.encode("utf-8")
    if _same(path, data):
        return
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except OSError as e:
        if tmp:
            Path(tmp).unlink(missing_ok=True)
        raise ToolError(f"cannot write {path} (left unchanged): {e.strerror or e}") from None


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
