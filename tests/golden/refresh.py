"""The golden tree: the every-feature fixture (tests/generator/fixtures/everything/, protocol demo)
and its hand-derived vectors (tests/golden/vectors/demo/) rendered by every back end of the
target registry (generator/targets/__init__.py), as Emboss keeps testdata/golden_cpp. A back-end
change then shows as a small, reviewable diff of tests/golden/everything/.

The tree holds what the back ends generate (and the fixture's ir.json), not the runtime files
they copy into each package: those are checked against their sources instead (a copy is its
runtime source with the back end's name replacements and banner, generator/render.py
copy_runtime), and listed with their sources in RUNTIME_COPIES, so a runtime edit shows once, in
generator/targets/<lang>/runtime/. The complete packages are rendered into build/golden/tree/,
where tests/golden/test_builds.py builds them.

    python -m tests.golden.refresh        (or `make golden`; from the project root)

rewrites the tree after a wanted change; tests/golden/test_golden.py fails while it is stale.
"""

from __future__ import annotations

import sys
from pathlib import Path

from generator import pipeline
from generator.render import RuntimeCopy, recording_copies
from generator.targets import NAMES

ROOT = Path(__file__).resolve().parents[2]
FIXTURE = ROOT / "tests" / "generator" / "fixtures" / "everything"
VECTORS = ROOT / "tests" / "golden" / "vectors"
GOLDEN = ROOT / "tests" / "golden" / "everything"
TREE = ROOT / "build" / "golden" / "tree"  # the complete rendering (golden tree + runtime copies)
MANIFEST = "RUNTIME_COPIES"  # in GOLDEN: one line per runtime copy, "path <lang>/runtime/<source>"
LANGS = list(NAMES)  # every target of the registry


def render(out: Path) -> dict[str, RuntimeCopy]:
    """The fixture's packages and ir.json into out (only changed files are written; files the back
    ends no longer produce are removed). Returns the files of out that are runtime copies, each
    with the copy it is (its text is exactly the copy's)."""
    with recording_copies() as copies:
        pipeline.run(
            spec_dir=FIXTURE, out_dir=out, only=LANGS, validate_only=False, lint=False, vectors_dir=VECTORS, quiet=True
        )
    by_text: dict[str, list[RuntimeCopy]] = {}
    for c in copies:
        by_text.setdefault(c.text, []).append(c)
    found = {}
    for rel, data in files(out).items():
        # a copy: the file whose path ends in the copy's destination and whose bytes are the copy's
        same = [
            c for c in by_text.get(data.decode("utf-8", "replace"), []) if rel == c.dest or rel.endswith("/" + c.dest)
        ]
        if same:
            found[rel] = same[0]
    return found


_FRESH: dict[str, RuntimeCopy] | None = None


def fresh() -> dict[str, RuntimeCopy]:
    """render(TREE), once per process (the golden test and the builds share it)."""
    global _FRESH
    if _FRESH is None:
        _FRESH = render(TREE)
    return _FRESH


def files(tree: Path) -> dict[str, bytes]:
    """Every file under tree by its relative path (build droppings such as __pycache__ excluded)."""
    return {
        p.relative_to(tree).as_posix(): p.read_bytes()
        for p in sorted(tree.rglob("*"))
        if p.is_file() and "__pycache__" not in p.parts
    }


def golden_view(tree: Path, copies: dict[str, RuntimeCopy]) -> dict[str, bytes]:
    """What tests/golden/everything/ holds for a rendering: every file but the runtime copies, and
    the list of those copies with their sources."""
    out = {rel: data for rel, data in files(tree).items() if rel not in copies}
    out[MANIFEST] = "".join(f"{rel} {c.lang}/runtime/{c.src}\n" for rel, c in sorted(copies.items())).encode()
    return out


def main() -> int:
    want = golden_view(TREE, render(TREE))
    have = files(GOLDEN)
    for rel in sorted(set(have) - set(want)):
        (GOLDEN / rel).unlink()
    for rel, data in want.items():
        if have.get(rel) != data:
            (GOLDEN / rel).parent.mkdir(parents=True, exist_ok=True)
            (GOLDEN / rel).write_bytes(data)
    for d in sorted((p for p in GOLDEN.rglob("*") if p.is_dir()), key=lambda p: len(p.parts), reverse=True):
        if not any(d.iterdir()):
            d.rmdir()
    size = sum(len(b) for b in want.values())
    print(
        f"golden: {GOLDEN.relative_to(ROOT)}/: {len(want)} files, {size} bytes; "
        f"complete packages in {TREE.relative_to(ROOT)}/ (review with git diff)"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
