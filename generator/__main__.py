"""Command line: python -m generator [--spec DIR [--vectors DIR]] [--out DIR] [--only LANG,...] [--lint]

`python -m generator generate|diff|lint|targets ...` is the `mipgen` command (generator/cli.py).

Loads and validates spec/, builds the IR, and renders every back end into generated/.
Exit status: 0 ok, 1 spec errors (printed as file:line:column: error: ...), 2 usage/tool errors.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .diagnostics import SpecError, SpecErrors


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] in ("generate", "diff", "lint", "targets"):
        from .cli import main as cli_main

        return cli_main(argv, prog="python -m generator")
    ap = argparse.ArgumentParser(prog="python -m generator", description=__doc__.splitlines()[0])
    ap.add_argument(
        "--spec",
        default=None,
        help="spec directory (default: spec/); its VERSION file, if any, replaces the project's (docs/versioning.md)",
    )
    ap.add_argument(
        "--vectors",
        default=None,
        help="golden vectors of a --spec spec: DIR/<protocol>/*.yaml (default: none; spec/ has tests/vectors and tests/streams)",
    )
    ap.add_argument("--out", default=None, help="output directory (default: generated/)")
    ap.add_argument("--only", default=None, help="comma-separated back ends to render (default: all)")
    ap.add_argument("--validate-only", action="store_true", help="load and validate the spec, write nothing")
    ap.add_argument("--lint", action="store_true", help="list stated lengths that disagree with the computed ones")
    args = ap.parse_args(argv)
    if args.vectors and not args.spec:
        ap.error("--vectors goes with --spec (spec/ always uses tests/vectors and tests/streams)")

    from . import pipeline  # imported late so that --help works without dependencies

    try:
        return pipeline.run(
            spec_dir=Path(args.spec) if args.spec else None,
            out_dir=Path(args.out) if args.out else None,
            only=args.only.split(",") if args.only else None,
            validate_only=args.validate_only,
            lint=args.lint,
            vectors_dir=Path(args.vectors) if args.vectors else None,
        )
    except SpecErrors as e:
        for err in e.errors:
            print(err, file=sys.stderr)
        print(f"{len(e.errors)} error(s) in the spec; nothing was generated.", file=sys.stderr)
        return 1
    except SpecError as e:
        print(e, file=sys.stderr)
        return 1
    except pipeline.ToolError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
