"""The checked-in golden tree (tests/golden/everything/) is exactly what the back ends render now
from the every-feature fixture and its vectors, rendered afresh (into build/golden/tree/) and
compared byte for byte, but for the runtime files the back ends copy into the packages: those
are listed in its RUNTIME_COPIES with their sources, and each must be its runtime source with the
back end's replacements (tests/golden/refresh.py). After a wanted back-end change, `make golden`
refreshes the tree and the change is reviewed as its diff."""

from __future__ import annotations

import difflib

from generator.targets import NAMES
from tests.golden.refresh import GOLDEN, MANIFEST, TREE, files, fresh, golden_view


def _diff(rel: str, want: bytes, got: bytes) -> str:
    lines = difflib.unified_diff(
        want.decode("utf-8", "replace").splitlines(),
        got.decode("utf-8", "replace").splitlines(),
        f"golden/{rel}",
        f"rendered/{rel}",
        lineterm="",
    )
    return "\n".join(list(lines)[:40])


def test_golden_tree_is_what_the_back_ends_render() -> None:
    want, got = files(GOLDEN), golden_view(TREE, fresh())
    assert len(want) > 60  # the packages' generated files and ir.json, not an empty directory
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


def test_runtime_copies_are_their_sources_with_the_back_ends_replacements() -> None:
    """The files left out of the tree are runtime copies: made again from their runtime source with
    the replacements and banner the back end asked for, they are the rendered bytes (a back end
    that edits a copy afterwards makes it a generated file, stored and diffed in the tree)."""
    copies = fresh()
    # every target copies runtime files into its package, and they are not stored in the tree
    assert {rel.split("/")[0] for rel in copies} == set(NAMES)
    assert not set(copies) & set(files(GOLDEN))
    wrong = [rel for rel, c in copies.items() if (TREE / rel).read_text(encoding="utf-8") != c.expected()]
    assert wrong == [], wrong
    listed = (GOLDEN / MANIFEST).read_text(encoding="utf-8").splitlines()
    assert len(listed) == len(copies)
    for line in listed:
        rel, source = line.split(" ")
        lang, _, src = source.partition("/runtime/")
        assert copies[rel].src == src and copies[rel].lang == lang, line
