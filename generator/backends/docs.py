"""Documentation back end: Markdown pages and SVG diagrams in generated/docs/.

Unlike the language back ends it runs after them (pipeline.py), because the getting-started pages
quote the example programs as the language back ends generated and formatted them.
"""

from __future__ import annotations

import importlib

from ..docs.markdown import write_markdown
from ..docs.model import Docs

OUTPUT_DIRS = ["docs"]


def build(ir: dict, vectors: list[dict], generated: dict[str, str]) -> Docs:
    from ..pipeline import BACKENDS  # the language back ends, in their order

    api = {lang: importlib.import_module(f"generator.backends.{lang}") for lang in BACKENDS}
    docs = Docs(ir, vectors, api, generated)
    docs.build()
    return docs


def render(ir: dict, vectors: list[dict], generated: dict[str, str]) -> dict[str, str]:
    docs = build(ir, vectors, generated)
    out = {f"docs/{path}": write_markdown(page) for path, page in docs.pages.items()}
    out.update({f"docs/{path}": text for path, text in docs.svgs.items()})
    return out
