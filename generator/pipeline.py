"""spec/ -> IR -> every back end -> formatted files in generated/ (only changed files are written)."""

from __future__ import annotations

import os
import sys
from pathlib import Path

from .diagnostics import BackendError, Location, SpecError, SpecErrors
from .errata import render_errata
from .export import ir_to_json
from .name_check import check as check_names
from .output import write_file, write_tree
from .release import load_release
from .render import ToolError, format_files  # noqa: F401  (ToolError re-exported for __main__)
from .resources import CHECKOUT
from .sessions import load_sessions
from .spec import ROOT, load_spec, locate_names
from .stated_lengths import lint_stated_lengths
from .targets import TARGETS
from .vectors import load_corpus, load_vectors


def run(
    spec_dir: Path | None,
    out_dir: Path | None,
    only: list[str] | None,
    validate_only: bool,
    lint: bool,
    docs_dir: Path | None = None,
    vectors_dir: Path | None = None,
    overlays: list[Path] = (),
    quiet: bool = False,
) -> int:
    if spec_dir is None and CHECKOUT is None:
        raise ToolError("no spec directory given, and an installed generator has no project spec: pass --spec DIR")
    root = spec_dir.parent if spec_dir else ROOT
    ir = load_spec(spec_dir, root=root, overlays=list(overlays))
    if lint:
        for item in lint_stated_lengths(ir):
            print(
                f"{item['manual']}:{item.get('line')}: {item['name']} (0x{item['set']:02X},0x{item['descriptor']:02X}): "
                f"manual states {item['stated']!r}, computed {item['computed']}"
            )
        return 0
    # Golden vectors and the stream corpus belong to the project's own spec; a spec given with
    # --spec has the vectors of vectors_dir (<dir>/<protocol>/*.yaml), if any.
    if spec_dir is None:
        vectors = load_corpus(ir, ROOT)
        # The session corpus (docs/conformance.md section 7), checked here, reaches every back end.
        sessions = load_sessions(ir, ROOT / "tests" / "sessions")
    else:
        vectors = load_vectors(ir, vectors_dir.resolve(), _project_root(vectors_dir)) if vectors_dir else []
        sessions = []
    release = load_release(spec_dir)  # VERSION and LICENSE: checked by --validate-only too
    # Every identifier of every target to render, before any renders (generator/name_check.py).
    _check_names(ir, [n for n in TARGETS if not only or n in only], spec_dir, root, overlays)
    if validate_only:
        return 0
    out_dir = out_dir or ROOT / "generated"
    files: dict[str, str] = {"ir.json": ir_to_json(ir)}
    owned: list[str] = []
    for name in TARGETS:
        if only and name not in only:
            continue
        mod = TARGETS[name]  # imported here: a run for one language imports one back end
        owned.extend(mod.OUTPUT_DIRS)
        # Every back end takes the same arguments (generator/targets/__init__.py).
        try:
            rendered = mod.render(ir, vectors, release, sessions)
        except BackendError as e:
            raise _located(e, spec_dir, root, overlays) from None
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
    changes = write_tree(out_dir, files, owned)
    if not quiet:
        # What a regeneration changed, in git's letters (issue 39: `make` said nothing).
        # On stderr: scripts read stdout (tests/runtime_specs/render.py prints the tree it wrote).
        print("\n".join(changes.summary(_display(out_dir))), file=sys.stderr)
    # docs/errata.md is the project's page about its own spec: a spec given with --spec (a test
    # fixture, the golden tree) or with overlays never rewrites it, unless a docs directory is named.
    if (spec_dir is None and not overlays) or docs_dir is not None:
        docs_dir = docs_dir or ROOT / "docs"
        write_file(docs_dir / "errata.md", render_errata(ir, vectors))
    return 0


def _display(path: Path) -> str:
    """path as the user would type it: relative to the current directory when inside it."""
    try:
        return os.path.relpath(path)
    except ValueError:
        return str(path)


def _check_names(ir: dict, langs: list[str], spec_dir: Path | None, root: Path, overlays) -> None:
    """Raises every name collision and reserved identifier of the targets langs (SpecErrors, or
    the SpecError when there is one)."""
    errors: list[SpecError] = []
    for proto in ir["protocols"]:
        locate, rank = _locator(proto["name"], spec_dir, root, overlays)
        for lang in langs:
            mod = TARGETS[lang]
            errors += check_names(mod.TITLE, mod.names(proto), mod.reserved, locate, rank)
    if len(errors) == 1:
        raise errors[0]  # one line, as a back end's own error (diagnostics.BackendError)
    if errors:
        raise SpecErrors(errors)


def _locator(protocol: str, spec_dir: Path | None, root: Path, overlays):
    """locate: where -> the Location of that spec element of protocol (locate_names, each asked
    once), or the protocol's protocol.yaml when no file has it; rank: a Location -> 0 in the spec,
    i in its i-th overlay (the order they are read)."""
    cache: dict[tuple, Location] = {}
    # The file names locate_names gives: relative to root for the spec, to an overlay's parent.
    prefixes = [os.path.relpath(Path(o) / protocol, Path(o).resolve().parent) + os.sep for o in overlays]

    def rank(loc: Location) -> int:
        return next((i + 1 for i, p in enumerate(prefixes) if loc.file.startswith(p)), 0)

    def locate(where: tuple[str, ...]) -> Location:
        if where not in cache:
            cache[where] = locate_names(protocol, where, spec_dir, root, list(overlays)) or Location(
                os.path.relpath(Path(spec_dir or root / "spec", protocol, "protocol.yaml"), root), 1, 1
            )
        return cache[where]

    return locate, rank


def _located(e: BackendError, spec_dir: Path | None, root: Path, overlays) -> SpecError:
    """A back end's error at the spec element it names (else at the protocol's protocol.yaml)."""
    loc = e.loc
    if loc is None and e.protocol:
        protocol_file = Path(spec_dir or root / "spec", e.protocol, "protocol.yaml")
        loc = locate_names(e.protocol, e.where, spec_dir, root, list(overlays)) or Location(
            os.path.relpath(protocol_file, root), 1, 1
        )
    return SpecError(loc, e.message, e.expected)


def _project_root(path: Path) -> Path | None:
    """The project root when path is inside it (vector file names then read tests/...), else None."""
    return CHECKOUT if CHECKOUT and path.resolve().is_relative_to(CHECKOUT) else None
