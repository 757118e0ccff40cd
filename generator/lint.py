"""`make lint` / `mipgen lint`: what the spec does not get wrong but should be looked at.

- YAML traps: a plain (unquoted) `on`, `off`, `yes`, `no` (any case) is read by the YAML 1.1
  loader as a boolean; each is listed with its place and the quoted spelling to use. This runs on
  the text, so it also explains a spec that does not load.
- Descriptors without a golden vector (the project's spec: tests/vectors and tests/streams; a
  spec of your own: those of --vectors DIR, and without it one line saying they were not checked).
- Stated lengths of the manuals that disagree with the computed ones (generator/stated_lengths.py).

Exit status 0 (the findings are advice), 1 when the spec does not load.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import yaml

from .resources import CHECKOUT
from .spec import ROOT, load_spec
from .stated_lengths import lint_stated_lengths

_BOOL = "tag:yaml.org,2002:bool"  # a plain on/off/yes/no resolves to it (YAML 1.1)
_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def yaml_traps(path: Path, display: str) -> list[str]:
    """One line per plain scalar that YAML 1.1 reads as a boolean although it is a word."""
    try:
        text = path.read_text(encoding="utf-8")
        node = yaml.compose(text, Loader=_LOADER)
    except (OSError, UnicodeDecodeError, yaml.YAMLError):
        return []  # the loader reports files it cannot read, with their place
    out: list[str] = []
    stack = [node] if node is not None else []
    while stack:
        n = stack.pop()
        if isinstance(n, yaml.MappingNode):
            for k, v in n.value:
                stack += [k, v]
        elif isinstance(n, yaml.SequenceNode):
            stack += n.value
        elif isinstance(n, yaml.ScalarNode) and n.tag == _BOOL and n.value.lower() not in ("true", "false"):
            meaning = n.value.lower() in ("on", "yes")
            out.append(
                (
                    n.start_mark.line + 1,
                    n.start_mark.column + 1,
                    f"{display}:{n.start_mark.line + 1}:{n.start_mark.column + 1}: warning: unquoted {n.value!r}"
                    f' is read as the boolean {str(meaning).lower()}; write "{n.value}" if you mean the word',
                )
            )
    return [line for _, _, line in sorted(out)]


def spec_files(spec_dir: Path, overlays: list[Path]) -> list[tuple[Path, str]]:
    out = []
    for d in [spec_dir, *overlays]:
        base = d.resolve().parent
        for p in sorted(d.rglob("*.y*ml")):
            if "schema" not in p.relative_to(d).parts:
                out.append((p, os.path.relpath(p, base)))
    return out


def covered_descriptors(vectors: list[dict]) -> set[tuple[int, int]]:
    """(set, descriptor) of every field that a golden vector or stream case decodes."""
    seen: set[tuple[int, int]] = set()
    for case in vectors:
        for line in case.get("expect", []):
            try:
                pkt = json.loads(line)
            except ValueError:
                continue
            for f in pkt.get("fields", []) if isinstance(pkt, dict) else []:
                if isinstance(f, dict) and "descriptor" in f and "error" not in f:
                    seen.add((pkt.get("set"), f["descriptor"]))
    return seen


def without_vectors(ir: dict, vectors: list[dict]) -> list[str]:
    seen = covered_descriptors(vectors)
    out = []
    for p in ir["protocols"]:
        for s in p["sets"]:
            for f in s["fields"]:
                hit = any(d == f["id"] for _, d in seen) if s["shared"] else (s["id"], f["id"]) in seen
                if not hit:
                    out.append(f"{p['name']} 0x{s['id']:02X},0x{f['id']:02X} {s['name']}.{f['name']} ({f['role']})")
    return out


def _inside_checkout(path: Path) -> bool:
    return CHECKOUT is not None and path.resolve().is_relative_to(CHECKOUT)


def run(spec_dir: Path | None, overlays: list[Path], vectors_dir: Path | None = None) -> int:
    base = spec_dir or ROOT / "spec"
    traps = [t for path, display in spec_files(base, overlays) for t in yaml_traps(path, display)]
    for t in traps:
        print(t)
    ir = load_spec(spec_dir, root=spec_dir.parent if spec_dir else ROOT, overlays=overlays)
    for item in lint_stated_lengths(ir):
        print(
            f"{item['manual']}:{item.get('line')}: {item['name']} (0x{item['set']:02X},0x{item['descriptor']:02X}): "
            f"manual states {item['stated']!r}, computed {item['computed']}"
        )
    total = sum(len(s["fields"]) for p in ir["protocols"] for s in p["sets"])
    if spec_dir is None:
        from .vectors import load_corpus

        vectors = load_corpus(ir, ROOT)
    elif vectors_dir is not None:
        from .vectors import load_vectors

        vectors = load_vectors(ir, vectors_dir.resolve(), CHECKOUT if _inside_checkout(vectors_dir) else None)
    else:
        # An installed mipgen with a user's spec has no vectors to look at: say so once instead of
        # listing every descriptor (issue 39).
        print(f"golden vectors: not checked ({total} descriptors; give --vectors DIR to check them)")
        print(f"lint: {len(traps)} YAML trap(s), golden vectors not checked")
        return 0
    missing = without_vectors(ir, vectors)
    where = "tests/vectors/, docs/conformance.md" if spec_dir is None else str(vectors_dir)
    print(f"descriptors without a golden vector ({len(missing)} of {total}; {where}):")
    for m in missing:
        print(f"  {m}")
    print(f"lint: {len(traps)} YAML trap(s), {len(missing)} descriptor(s) without a golden vector")
    return 0
