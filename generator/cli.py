"""mipgen: the generator as a command (`pip install .` or a wheel installs it, docs/packaging.md;
`python -m generator` in the checkout is the same program).

    mipgen generate [--spec DIR [OVERLAY ...]] [--vectors DIR] [--out DIR] [--langs c,cpp,python,rust,docs]
    mipgen diff OLD NEW [--json] [--changelog]
    mipgen lint [--spec DIR [OVERLAY ...]]
    mipgen targets          (the registered language targets, generator/targets/__init__.py)

Exit status: 0 ok (diff: nothing breaks the wire), 1 spec errors (diff: wire-breaking changes),
2 usage or tool errors.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .diagnostics import SpecError, SpecErrors
from .targets import NAMES

LANGS = (*NAMES, "docs")  # the language targets of the registry, then the reference documentation


class _Parser(argparse.ArgumentParser):
    def error(self, message: str):  # usage errors exit 2 with one line, as argparse does
        self.print_usage(sys.stderr)
        print(f"{self.prog}: error: {message}", file=sys.stderr)
        sys.exit(2)


def _spec_args(ap: argparse.ArgumentParser) -> None:
    ap.add_argument(
        "--spec",
        nargs="+",
        action="extend",
        metavar="DIR",
        default=None,
        help="the spec directory (default: this project's spec/), then overlay directories laid over it in order",
    )


def _split_spec(ap, spec: list[str] | None):
    """(spec_dir or None for the project's spec/, overlays)."""
    from .resources import CHECKOUT

    if not spec:
        if CHECKOUT is None:
            ap.error("--spec DIR is needed: an installed mipgen has no project spec of its own")
        return None, []
    dirs = [Path(s) for s in spec]
    for d in dirs:
        if not d.is_dir():
            ap.error(f"--spec {d}: no such directory")
    base = dirs[0]
    return (None if CHECKOUT and base.resolve() == (CHECKOUT / "spec").resolve() else base), dirs[1:]


def _run_spec_errors(fn) -> int:
    from .render import ToolError

    try:
        return fn()
    except SpecErrors as e:
        for err in e.errors:
            print(err, file=sys.stderr)
        print(f"{len(e.errors)} error(s) in the spec; nothing was generated.", file=sys.stderr)
        return 1
    except SpecError as e:
        print(e, file=sys.stderr)
        return 1
    except ToolError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2


def cmd_generate(ap, args) -> int:
    from . import pipeline

    spec_dir, overlays = _split_spec(ap, args.spec)
    langs = None
    if args.langs:
        langs = [x.strip() for x in args.langs.split(",") if x.strip()]
        bad = [x for x in langs if x not in LANGS]
        if bad:
            ap.error(f"--langs: unknown {', '.join(bad)} (known: {', '.join(LANGS)})")
    if (spec_dir is not None or overlays) and args.out is None:
        ap.error("--out DIR is needed with a spec other than this project's (generated/ holds the project's own)")
    if args.vectors and spec_dir is None:
        ap.error("--vectors goes with a --spec of your own (the project's spec uses tests/vectors and tests/streams)")
    return _run_spec_errors(
        lambda: pipeline.run(
            spec_dir=spec_dir,
            out_dir=Path(args.out) if args.out else None,
            only=langs,
            validate_only=args.validate_only,
            lint=False,
            vectors_dir=Path(args.vectors) if args.vectors else None,
            overlays=overlays,
        )
    )


def cmd_diff(ap, args) -> int:
    from . import wirediff
    from .release import VERSION_FILE

    try:
        old, old_label = wirediff.load_side(args.old, overlays=[Path(d) for d in args.old_overlay])
        new, new_label = wirediff.load_side(args.new, overlays=[Path(d) for d in args.new_overlay])
    except wirediff.DiffError as e:
        print(f"mipgen diff: error: {e}", file=sys.stderr)
        return 2
    version = args.version or VERSION_FILE.read_text(encoding="utf-8").strip()
    changes = wirediff.diff(old, new)
    if args.json:
        sys.stdout.write(wirediff.json_report(changes, old_label, new_label, version))
    elif args.changelog:
        sys.stdout.write(wirediff.changelog(changes, version))
    else:
        sys.stdout.write(wirediff.text_report(changes, old_label, new_label, version))
    return 1 if wirediff.verdict(changes) == wirediff.BREAKING else 0


def cmd_lint(ap, args) -> int:
    from . import lint

    spec_dir, overlays = _split_spec(ap, args.spec)
    if args.vectors and spec_dir is None:
        ap.error("--vectors goes with a --spec of your own (the project's spec uses tests/vectors and tests/streams)")
    vectors = Path(args.vectors) if args.vectors else None
    if vectors is not None and not vectors.is_dir():
        ap.error(f"--vectors {vectors}: no such directory")
    return _run_spec_errors(lambda: lint.run(spec_dir, overlays, vectors))


def cmd_targets(ap, args) -> int:
    print(" ".join(NAMES))
    return 0


def main(argv: list[str] | None = None, prog: str = "mipgen") -> int:
    ap = _Parser(prog=prog, description="The protocol code generator: generate, diff and lint specs.")
    sub = ap.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    g = sub.add_parser("generate", help="render the packages of a spec (and overlays) into a directory")
    _spec_args(g)
    g.add_argument("--vectors", default=None, help="golden vectors of your spec: DIR/<protocol>/*.yaml")
    g.add_argument("--out", default=None, help="output directory (default: this project's generated/)")
    g.add_argument("--langs", default=None, help="comma-separated: " + ",".join(LANGS) + " (default: all)")
    g.add_argument("--validate-only", action="store_true", help="load and check the spec, write nothing")
    d = sub.add_parser("diff", help="wire-compatibility report between two specs (directories or git revisions)")
    d.add_argument("old", help="spec directory or git revision (its spec/)")
    d.add_argument("new", help="spec directory or git revision (its spec/)")
    out = d.add_mutually_exclusive_group()
    out.add_argument("--json", action="store_true", help="the report as JSON")
    out.add_argument("--changelog", action="store_true", help="a Markdown changelog section")
    d.add_argument("--version", default=None, help="the version being released (default: VERSION)")
    for side in ("old", "new"):
        d.add_argument(
            f"--{side}-overlay",
            action="append",
            default=[],
            metavar="DIR",
            help=f"an overlay directory laid over the {side} spec (repeatable, in order), as generate --spec DIR DIR...",
        )
    li = sub.add_parser("lint", help="descriptors without golden vectors, YAML traps, stated lengths")
    _spec_args(li)
    li.add_argument("--vectors", default=None, help="golden vectors of your spec: DIR/<protocol>/*.yaml")
    sub.add_parser("targets", help="the registered language targets, in render order, one line")
    args = ap.parse_args(argv)
    if args.command is None:
        ap.print_help(sys.stderr)
        return 2
    handler = {"generate": cmd_generate, "diff": cmd_diff, "lint": cmd_lint, "targets": cmd_targets}[args.command]
    return handler(sub.choices[args.command], args)


def entry() -> None:
    sys.exit(main())
