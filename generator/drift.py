"""`make check`: regenerate into a temporary directory and fail if generated/ or docs/errata.md differ."""

from __future__ import annotations

import difflib
import subprocess
import sys
import tempfile
from pathlib import Path

from . import pipeline
from .diagnostics import SpecErrors
from .spec import ROOT


def _tracked_tree(base: Path) -> dict[str, Path]:
    """Files under base that git would track (ignored build products are skipped)."""
    out = {}
    if not base.exists():
        return out
    for p in base.rglob("*"):
        if p.is_file():
            out[str(p.relative_to(base))] = p
    if out:
        rels = list(out)
        proc = subprocess.run(
            ["git", "check-ignore", "--stdin"], cwd=base, input="\n".join(rels), capture_output=True, text=True
        )
        for ignored in proc.stdout.split():
            out.pop(ignored, None)
    return out


def main() -> int:
    with tempfile.TemporaryDirectory(prefix="drift-") as tmp:
        gen, docs = Path(tmp, "generated"), Path(tmp, "docs")
        try:
            pipeline.run(
                spec_dir=None, out_dir=gen, only=None, validate_only=False, lint=False, docs_dir=docs, quiet=True
            )
        except SpecErrors as e:
            print("\n".join(str(x) for x in e.errors), file=sys.stderr)
            return 1
        except pipeline.ToolError as e:
            print(f"error: {e}", file=sys.stderr)
            return 2
        problems = []
        pairs = [(gen, ROOT / "generated"), (docs, ROOT / "docs")]
        for fresh_base, have_base in pairs:
            fresh = {k: v for k, v in _tracked_tree(fresh_base).items()}
            have = (
                _tracked_tree(have_base)
                if fresh_base is gen
                else {k: have_base / k for k in fresh if (have_base / k).exists()}
            )
            label = have_base.relative_to(ROOT)
            for rel in sorted(set(fresh) | set(have)):
                if rel not in have:
                    problems.append(f"{label}/{rel}: missing (the generator would create it)")
                elif rel not in fresh:
                    problems.append(f"{label}/{rel}: stale (the generator no longer produces it)")
                else:
                    a = have[rel].read_text(encoding="utf-8", errors="replace")
                    b = fresh[rel].read_text(encoding="utf-8", errors="replace")
                    if a != b:
                        diff = list(
                            difflib.unified_diff(
                                a.splitlines(),
                                b.splitlines(),
                                f"{label}/{rel} (checked in)",
                                f"{label}/{rel} (regenerated)",
                                lineterm="",
                                n=1,
                            )
                        )
                        problems.append(f"{label}/{rel}: out of date\n" + "\n".join(diff[:20]))
        if problems:
            print("generated output is out of date; run `make` and commit the result:", file=sys.stderr)
            for p in problems:
                print("  " + p.replace("\n", "\n    "), file=sys.stderr)
            return 1
        print("make check: generated/ and docs/errata.md are up to date")
        return 0


if __name__ == "__main__":
    sys.exit(main())
