"""The HTML site in a real browser: `make html` output served on localhost, opened in headless Chromium.

Every page reachable from index.html is opened; every internal link must lead to a page that
loads (HTTP 200) and, when it has a #fragment, to an element with that id; every image must load;
every descriptor page must render its layout table and its packet diagram with a non-zero size;
every descriptor of the IR must have a page reached by links from the index. Screenshots of a few
pages are written to build/screenshots/ for a person to look at.
"""

from __future__ import annotations

import functools
import http.server
import json
import subprocess
import sys
import threading
from pathlib import Path
from urllib.parse import urldefrag, urlparse

import pytest

from tests.docs.cdp import Browser, find_chromium

ROOT = Path(__file__).resolve().parents[2]
SCREENSHOTS = {
    "index": "index.html",
    "mip_index": "mip/index.html",
    "command_with_union": "mip/threedm/event_trigger_config.html",
    "data_field_with_bitfield": "mip/filter_data/filter_status.html",
    "mscip_select_sensors": "mscip/imu_config/select_sensors.html",
    "getting_started_c": "getting-started/c.html",
}

PAGE_FACTS = """(() => {
  const nav = performance.getEntriesByType('navigation')[0];
  const box = (e) => { const r = e.getBoundingClientRect(); return [r.width, r.height]; };
  return {
    status: nav ? nav.responseStatus : 0,
    kind: document.body.className,
    title: document.title,
    ids: [...document.querySelectorAll('[id]')].map(e => e.id),
    links: [...document.querySelectorAll('a[href]')].map(a => a.href),
    images: [...document.images].map(i => ({src: i.src, ok: i.complete && i.naturalWidth > 0, cls: i.className, box: box(i)})),
    layouts: [...document.querySelectorAll('table.layout')].map(t => ({rows: t.tBodies[0].rows.length, box: box(t)})),
    css: document.querySelector('main') ? getComputedStyle(document.querySelector('main')).maxWidth : null,
  };
})()"""


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    out = tmp_path_factory.mktemp("site") / "html"
    proc = subprocess.run(
        [sys.executable, "-m", "generator.docs.site", "--out", str(out)], cwd=ROOT, capture_output=True, text=True
    )
    assert proc.returncode == 0, proc.stderr
    handler = functools.partial(QuietHandler, directory=str(out))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    yield out, f"http://127.0.0.1:{server.server_address[1]}/"
    server.shutdown()


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@pytest.fixture(scope="module")
def crawl(site):
    """Open every page reachable from index.html; {relative path: facts}."""
    exe = find_chromium()
    if not exe:
        pytest.fail(
            "headless Chromium is needed for the documentation test (Debian package `chromium`; or set CHROMIUM)"
        )
    out, base = site
    browser = Browser(exe)
    pages: dict[str, dict] = {}
    try:
        todo = ["index.html"]
        while todo:
            rel = todo.pop()
            if rel in pages:
                continue
            browser.open(base + rel)
            facts = browser.evaluate(PAGE_FACTS)
            pages[rel] = facts
            if facts["status"] != 200:
                continue
            for link in facts["links"]:
                target, _frag = urldefrag(link)
                if target.startswith(base):
                    t = target[len(base) :] or "index.html"
                    if t.endswith(".html") and t not in pages:
                        todo.append(t)
        shots = ROOT / "build" / "screenshots"
        shots.mkdir(parents=True, exist_ok=True)
        for name, rel in SCREENSHOTS.items():
            browser.open(base + rel)
            browser.screenshot(str(shots / f"{name}.png"))
    finally:
        browser.close()
    return base, pages


def test_every_internal_link_resolves(crawl):
    base, pages = crawl
    broken = []
    for rel, facts in sorted(pages.items()):
        for link in facts["links"]:
            target, frag = urldefrag(link)
            if not target.startswith(base):
                assert urlparse(link).scheme not in ("http", "https"), (
                    f"{rel}: external link {link} (the site must work offline)"
                )
                continue
            t = target[len(base) :] or "index.html"
            if t.endswith(".html"):
                page = pages.get(t)
                if page is None or page["status"] != 200:
                    broken.append(f"{rel}: {link} (page {'missing' if page is None else page['status']})")
                elif frag and frag not in page["ids"]:
                    broken.append(f"{rel}: {link} (no element with id {frag!r})")
            else:
                broken.append(f"{rel}: {link} (not a page)")
    assert not broken, f"{len(broken)} broken link(s):\n" + "\n".join(broken[:40])
    assert all(f["status"] == 200 for f in pages.values())


def test_every_image_loads_and_the_stylesheet_applies(crawl):
    _base, pages = crawl
    bad = [f"{rel}: {i['src']}" for rel, f in pages.items() for i in f["images"] if not i["ok"] or i["box"][0] <= 0]
    assert not bad, "images that did not load or render:\n" + "\n".join(bad[:40])
    assert {f["css"] for f in pages.values()} == {"1180px"}, "style.css did not load on every page"


def _descriptor_pages(ir: dict) -> dict[str, str]:
    out = {}
    for p in ir["protocols"]:
        for r in p["reserved_fields"]:
            out[f"{p['name']}/reserved/{r['name']}.html"] = f"{p['name']} reserved {r['name']}"
        for s in p["sets"]:
            for f in s["fields"]:
                out[f"{p['name']}/{s['name']}/{f['name']}.html"] = (
                    f"{p['name']} 0x{s['id']:02X},0x{f['id']:02X} {f['name']}"
                )
    return out


def test_every_descriptor_has_a_page_with_layout_table_and_diagram(crawl):
    _base, pages = crawl
    ir = json.loads((ROOT / "generated" / "ir.json").read_text())
    expected = _descriptor_pages(ir)
    missing = [f"{label} ({rel})" for rel, label in expected.items() if rel not in pages]
    assert not missing, "descriptors without a page reachable from the index:\n" + "\n".join(missing)
    problems = []
    for rel in expected:
        f = pages[rel]
        if f["kind"] != "descriptor":
            problems.append(f"{rel}: not rendered as a descriptor page")
        layouts = [t for t in f["layouts"] if t["rows"] >= 1 and t["box"][0] > 0 and t["box"][1] > 0]
        diagrams = [i for i in f["images"] if i["cls"] == "diagram" and i["ok"] and i["box"][1] > 0]
        if not layouts:
            problems.append(f"{rel}: no rendered layout table")
        if not diagrams or len(diagrams) < len(f["layouts"]):
            problems.append(f"{rel}: {len(diagrams)} rendered packet diagram(s) for {len(f['layouts'])} layout(s)")
    assert not problems, "\n".join(problems[:40])


def test_index_matrix_errata_and_getting_started_pages_exist(crawl):
    _base, pages = crawl
    ir = json.loads((ROOT / "generated" / "ir.json").read_text())
    for p in ir["protocols"]:
        for page in ("index.html", "devices.html", "types.html"):
            assert pages.get(f"{p['name']}/{page}", {}).get("status") == 200, f"{p['name']}/{page}"
    for page in (
        "errata.html",
        "getting-started/c.html",
        "getting-started/cpp.html",
        "getting-started/python.html",
        "getting-started/rust.html",
    ):
        assert pages.get(page, {}).get("status") == 200, page
    for name in SCREENSHOTS:
        shot = ROOT / "build" / "screenshots" / f"{name}.png"
        assert shot.stat().st_size > 10_000, f"{shot}: screenshot looks empty"
