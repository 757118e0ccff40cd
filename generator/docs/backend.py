"""Documentation back end: Markdown pages and SVG diagrams in generated/docs/.

Unlike the language back ends it runs after them (pipeline.py), because the getting-started pages
quote the example programs as the language back ends generated and formatted them.
"""

from __future__ import annotations

from ..targets import TARGETS
from . import getting_started
from .markdown import write_markdown
from .model import Docs

OUTPUT_DIRS = ["docs"]


def build(ir: dict, vectors: list[dict], generated: dict[str, str]) -> Docs:
    api = dict(TARGETS)  # the language targets, in their order
    docs = Docs(ir, vectors, api, generated)
    docs.build()
    getting_started.add_pages(docs)  # last: after every reference page (it imports the model, not the reverse)
    return docs


def render(ir: dict, vectors: list[dict], generated: dict[str, str]) -> dict[str, str]:
    docs = build(ir, vectors, generated)
    out = {f"docs/{path}": write_markdown(page) for path, page in docs.pages.items()}
    out.update({f"docs/{path}": text for path, text in docs.svgs.items()})
    return out
