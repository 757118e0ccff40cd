"""Pages (generator/docs/model.py) written as Markdown for a repository browser."""

from __future__ import annotations

import functools

from ..render import environment
from .model import Page


@functools.cache
def _template(name: str):
    return environment().get_template(name)


def write_markdown(page: Page) -> str:
    blocks = []
    for b in page.blocks:
        if b["kind"] == "code":
            fence = "```"
            while fence in b["text"]:
                fence += "`"
            b = {**b, "fence": fence}
        blocks.append(b)
    crumbs = [(text, page.link_to(target)) for text, target in page.crumbs]
    text = _template("docs/page.md.j2").render(title=page.title, crumbs=crumbs, blocks=blocks)
    return text.rstrip("\n") + "\n"
