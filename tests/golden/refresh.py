"""The golden tree: the every-feature fixture (tests/generator/fixtures/everything/, protocol demo)
and its hand-derived vectors (tests/golden/vectors/demo/) rendered by the C, C++, Python and Rust
back ends into tests/golden/everything/ (with the fixture's ir.json), as Emboss keeps
testdata/golden_cpp. A back-end change then shows as a small, reviewable diff of this tree.

    python -m tests.golden.refresh        (or `make golden`; from the project root)

rewrites the tree after a wanted change; tests/golden/test_golden.py fails while it is stale.
"""

from __future__ import annotations

import sys
from pathlib import Path

from generator import pipeline
from generator.targets import NAMES

ROOT = Path(__file__).resolve().parents[2]
FIXTURE = ROOT / "tests" / "generator" / "fixtures" / "everything"
VECTORS = ROOT / "tests" / "golden" / "vectors"
GOLDEN = ROOT / "tests" / "golden" / "everything"
LANGS = list(NAMES)  # every target of the registry


def render(out: Path) -> None:
    """The fixture's four packages and ir.json into out (only changed files are written; files
    the back ends no longer produce are removed)."""
    pipeline.run(spec_dir=FIXTURE, out_dir=out, only=LANGS, validate_only=False, lint=False, vectors_dir=VECTORS)


def files(tree: Path) -> dict[str, bytes]:
    """Every file under tree by its relative path (build droppings such as __pycache__ excluded)."""
    return {
        p.relative_to(tree).as_posix(): p.read_bytes()
        for p in sorted(tree.rglob("*"))
        if p.is_file() and "__pycache__" not in p.parts
    }


def main() -> int:
    render(GOLDEN)
    tree = files(GOLDEN)
    size = sum(len(b) for b in tree.values())
    print(f"golden: {GOLDEN.relative_to(ROOT)}/: {len(tree)} files, {size} bytes (review with git diff)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
