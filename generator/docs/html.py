"""Pages (generator/docs/model.py) written as a static HTML site that works offline.

The inline subset of the model (`code`, [text](link), **bold**, <br>, escaped \\| \\[ \\]) is
converted here; links to .md pages become .html (README.md becomes index.html).
"""

from __future__ import annotations

import functools
import html
import posixpath
import re

from ..render import environment
from .model import Page

INLINE = re.compile(r"`([^`]*)`|\[((?:\\.|[^\]\\])*)\]\(([^)\s]+)\)|\*\*(.+?)\*\*")


@functools.cache
def _template(name: str):
    return environment().get_template(name)


def html_path(md_path: str) -> str:
    """Where the HTML page for a .md page path lives in the site."""
    head, tail = posixpath.split(md_path)
    name = "index.html" if tail == "README.md" else tail[:-3] + ".html"
    return posixpath.join(head, name) if head else name


def _href(url: str) -> str:
    if re.match(r"^[a-z]+:", url):
        return url
    target, _, anchor = url.partition("#")
    if target.endswith(".md"):
        target = html_path(target)
    return target + (f"#{anchor}" if anchor else "")


def _plain(text: str) -> str:
    text = re.sub(r"\\([|\[\]])", r"\1", text)
    return html.escape(text, quote=False).replace("&lt;br&gt;", "<br>")


def inline(text: str) -> str:
    out, pos = [], 0
    for m in INLINE.finditer(text):
        out.append(_plain(text[pos : m.start()]))
        if m.group(1) is not None:
            out.append(f"<code>{html.escape(m.group(1), quote=False)}</code>")
        elif m.group(2) is not None:
            out.append(f'<a href="{html.escape(_href(m.group(3)))}">{inline(m.group(2))}</a>')
        else:
            out.append(f"<strong>{inline(m.group(4))}</strong>")
        pos = m.end()
    out.append(_plain(text[pos:]))
    return "".join(out)


def write_html(page: Page, nav: list[tuple[str, str]], start: list[tuple[str, str]]) -> str:
    root = posixpath.relpath(".", posixpath.dirname(page.path) or ".")
    root = "" if root == "." else root + "/"
    blocks = []
    for b in page.blocks:
        b = dict(b)
        k = b["kind"]
        if k in ("heading", "para"):
            b["html"] = inline(b["text"])
        elif k == "list":
            b["html_items"] = [inline(i) for i in b["items"]]
        elif k == "table":
            b["html_head"] = [inline(h) for h in b["head"]]
            b["html_rows"] = [[inline(c) for c in row] for row in b["rows"]]
        elif k == "code":
            b["html"] = html.escape(b["text"], quote=False)
        elif k == "image":
            b["alt"] = html.escape(b["alt"])
        blocks.append(b)
    crumbs = [(html.escape(t), _href(page.link_to(target))) for t, target in page.crumbs]
    nav_links = [(html.escape(t), _href(page.link_to(target))) for t, target in nav]
    start_links = [(html.escape(t), _href(page.link_to(target))) for t, target in start]
    return _template("docs/page.html.j2").render(
        title=html.escape(page.title),
        crumbs=crumbs,
        nav=nav_links,
        start=start_links,
        blocks=blocks,
        root=root,
        kind=page.kind,
    )
