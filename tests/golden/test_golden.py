"""The checked-in golden tree (tests/golden/everything/) is exactly what the back ends render now
from the every-feature fixture and its vectors: rendered afresh into a temporary directory and
compared byte for byte. After a wanted back-end change, `make golden` refreshes the tree and the
change is reviewed as its diff."""

from __future__ import annotations

import difflib
from pathlib import Path

from tests.golden.refresh import GOLDEN, files, render


def _diff(rel: str, want: bytes, got: bytes) -> str:
    lines = difflib.unified_diff(
        want.decode("utf-8", "replace").splitlines(),
        got.decode("utf-8", "replace").splitlines(),
        f"golden/{rel}",
        f"rendered/{rel}",
        lineterm="",
    )
    return "\n".join(list(lines)[:40])


def test_golden_tree_is_what_the_back_ends_render(tmp_path: Path) -> None:
    render(tmp_path)
    want, got = files(GOLDEN), files(tmp_path)
    assert len(want) > 100  # four packages and ir.json, not an empty directory
    missing = sorted(set(want) - set(got))
    extra = sorted(set(got) - set(want))
    changed = sorted(rel for rel in set(want) & set(got) if want[rel] != got[rel])
    report = [f"no longer rendered: {rel}" for rel in missing] + [f"new: {rel}" for rel in extra]
    report += [_diff(rel, want[rel], got[rel]) for rel in changed[:5]]
    if len(changed) > 5:
        report.append(f"... and {len(changed) - 5} more changed files: {', '.join(changed[5:])}")
    assert not (missing or extra or changed), (
        "tests/golden/everything/ differs from what the back ends render now; review the diff and, "
        "if the change is wanted, run `make golden`:\n" + "\n".join(report)
    )
