"""`make html`: the reference documentation as a static HTML site (offline: no CDN, no scripts).

    python -m generator.docs.site [--out DIR]     (default build/html)

Built from the same pages as the Markdown in generated/docs/ (generator/docs/model.py), from the
spec, the golden vectors and the generated example programs. Open DIR/index.html.
"""

from __future__ import annotations

import argparse
import shutil
import sys
from pathlib import Path

from ..diagnostics import SpecError, SpecErrors
from ..render import TEMPLATES
from ..spec import ROOT, load_spec
from ..vectors import load_corpus
from .html import html_path, write_html
from .model import LANG_TITLES


def _generated_examples() -> dict[str, str]:
    from .getting_started import EXAMPLE_FILES, SESSION_EXAMPLE_FILES

    out = {}
    for p in (ROOT / "generated").glob("*/*/CMakeLists.txt"):
        out[str(p.relative_to(ROOT / "generated"))] = p.read_text(encoding="utf-8")
    for pattern in [*EXAMPLE_FILES.values(), *SESSION_EXAMPLE_FILES.values()]:
        for p in (ROOT / "generated").glob(pattern.format(pkg="*")):
            out[str(p.relative_to(ROOT / "generated"))] = p.read_text(encoding="utf-8")
    return out


def build_site(out: Path) -> int:
    from .backend import build

    ir = load_spec(None, root=ROOT)
    vectors = load_corpus(ir, ROOT)
    docs = build(ir, vectors, _generated_examples())
    nav = [(p["title"], p["name"] + "/README.md") for p in ir["protocols"]] + [("Errata", "errata.md")]
    start = [(LANG_TITLES[lang], f"getting-started/{lang}.md") for lang in LANG_TITLES]
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    for path, page in docs.pages.items():
        target = out / html_path(path)
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(write_html(page, nav, start), encoding="utf-8")
    for path, text in docs.svgs.items():
        target = out / path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text, encoding="utf-8")
    shutil.copyfile(TEMPLATES / "docs" / "style.css", out / "style.css")
    print(f"make html: {len(docs.pages)} pages and {len(docs.svgs)} diagrams in {out}/ (open {out}/index.html)")
    return 0


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m generator.docs.site", description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(ROOT / "build" / "html"), help="output directory (default: build/html)")
    args = ap.parse_args(argv)
    try:
        return build_site(Path(args.out))
    except SpecErrors as e:
        print("\n".join(str(x) for x in e.errors), file=sys.stderr)
        return 1
    except SpecError as e:
        print(e, file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
