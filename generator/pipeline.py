"""spec/ -> IR -> every back end -> formatted files in generated/ (only changed files are written)."""

from __future__ import annotations

import os
from pathlib import Path

from .errata import render_errata
from .export import ir_to_json
from .render import ToolError, format_files  # noqa: F401  (ToolError re-exported for __main__)
from .spec import ROOT, load_spec
from .stated_lengths import lint_stated_lengths
from .targets import TARGETS
from .vectors import load_corpus


def run(
    spec_dir: Path | None,
    out_dir: Path | None,
    only: list[str] | None,
    validate_only: bool,
    lint: bool,
    docs_dir: Path | None = None,
) -> int:
    ir = load_spec(spec_dir, root=spec_dir.parent if spec_dir else ROOT)
    if lint:
        for item in lint_stated_lengths(ir):
            print(
                f"{item['manual']}:{item.get('line')}: {item['name']} (0x{item['set']:02X},0x{item['descriptor']:02X}): "
                f"manual states {item['stated']!r}, computed {item['computed']}"
            )
        return 0
    # Golden vectors and the stream corpus belong to the project's own spec; a spec given with
    # --spec is validated alone.
    vectors = load_corpus(ir, ROOT) if spec_dir is None else []
    if validate_only:
        return 0
    out_dir = out_dir or ROOT / "generated"
    files: dict[str, str] = {"ir.json": ir_to_json(ir)}
    owned: list[str] = []
    for name, mod in TARGETS.items():
        if only and name not in only:
            continue
        owned.extend(mod.OUTPUT_DIRS)
        rendered = mod.render(ir, vectors)
        for rel in rendered:
            if not any(rel == d or rel.startswith(d.rstrip("/") + "/") for d in mod.OUTPUT_DIRS):
                raise ToolError(f"back end {name} wrote {rel}, outside its directories {mod.OUTPUT_DIRS}")
        files.update(rendered)
    files = format_files(files)
    if not only or "docs" in only:
        # The documentation quotes the formatted example programs, so it renders last.
        from .docs import backend as docs

        owned.extend(docs.OUTPUT_DIRS)
        files.update(docs.render(ir, vectors, files))
    _write_tree(out_dir, files, owned)
    docs_dir = docs_dir or ROOT / "docs"
    _write_tree(docs_dir, {"errata.md": render_errata(ir, vectors)}, [])
    return 0


def _write_tree(out_dir: Path, files: dict[str, str], owned: list[str]) -> None:
    out_dir.mkdir(parents=True, exist_ok=True)
    for rel, text in sorted(files.items()):
        p = out_dir / rel
        p.parent.mkdir(parents=True, exist_ok=True)
        if not p.exists() or p.read_text(encoding="utf-8") != text:
            p.write_text(text, encoding="utf-8")
    # Remove stale files in directories a back end owns.
    keep = set(files)
    for d in owned:
        base = out_dir / d
        if not base.exists():
            continue
        for root, _dirs, names in os.walk(base, topdown=False):
            for n in names:
                rel = os.path.relpath(os.path.join(root, n), out_dir)
                if rel not in keep:
                    os.remove(os.path.join(root, n))
            if not os.listdir(root):
                os.rmdir(root)
