"""The Markdown reference in generated/docs/ as a repository browser shows it.

Every relative link leads to a file that exists, and a #fragment to an anchor on that page;
every descriptor of the IR has a page with a layout table and a packet diagram that is a
well-formed SVG; every bitfield of the IR has a bit diagram. Fast: no browser (see test_site.py).
"""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from pathlib import Path

from generator.targets import NAMES

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "generated" / "docs"
LINK = re.compile(r"!?\[(?:\\.|[^\]\\])*\]\(([^)\s]+)\)")
ANCHOR = re.compile(r'<a id="([^"]+)"></a>')
IR = json.loads((ROOT / "generated" / "ir.json").read_text())


def _pages() -> dict[Path, str]:
    return {p: p.read_text(encoding="utf-8") for p in sorted(DOCS.rglob("*.md"))}


def _without_code(text: str) -> str:
    return re.sub(r"^(`{3,}).*?^\1\s*$", "", text, flags=re.S | re.M)


def test_every_relative_link_and_anchor_resolves():
    pages = _pages()
    anchors = {p: set(ANCHOR.findall(t)) for p, t in pages.items()}
    broken = []
    for page, text in pages.items():
        for target in LINK.findall(_without_code(text)):
            assert not target.startswith(("http:", "https:", "//")), f"{page}: external link {target}"
            path, _, frag = target.partition("#")
            dest = (page.parent / path).resolve() if path else page
            if not dest.exists():
                broken.append(f"{page.relative_to(DOCS)}: {target} (no such file)")
            elif frag and frag not in anchors.get(dest, set()):
                broken.append(f"{page.relative_to(DOCS)}: {target} (no anchor {frag!r})")
    assert not broken, f"{len(broken)} broken link(s):\n" + "\n".join(broken[:40])


def test_every_descriptor_has_a_page_with_layout_table_and_diagram():
    problems = []
    for p in IR["protocols"]:
        fields = [("reserved", r) for r in p["reserved_fields"]] + [
            (s["name"], f) for s in p["sets"] for f in s["fields"]
        ]
        for set_name, f in fields:
            page = DOCS / p["name"] / set_name / f"{f['name']}.md"
            if not page.exists():
                problems.append(f"{page.relative_to(DOCS)}: missing")
                continue
            text = page.read_text(encoding="utf-8")
            title = next(ln for ln in text.splitlines() if ln.startswith("# "))
            if f"0x{f['id']:02X}" not in title:
                problems.append(f"{page.relative_to(DOCS)}: title lacks the descriptor 0x{f['id']:02X}")
            if text.count("| offset | bytes | type | name |") < len(f["variants"]):
                problems.append(f"{page.relative_to(DOCS)}: fewer layout tables than layouts")
            images = re.findall(r"!\[packet diagram[^\]]*\]\(([^)]+\.svg)\)", text)
            if len(images) != len(f["variants"]):
                problems.append(
                    f"{page.relative_to(DOCS)}: {len(images)} packet diagrams for {len(f['variants'])} layouts"
                )
            for img in images:
                root = ET.parse(page.parent / img).getroot()
                if not root.tag.endswith("svg") or not list(root.iter("{http://www.w3.org/2000/svg}rect")):
                    problems.append(f"{img}: not an SVG drawing")
    assert not problems, "\n".join(problems[:40])


def test_bitfields_have_bit_diagrams_and_descriptor_pages_show_their_types():
    for p in IR["protocols"]:
        for t in p["types"]:
            if t["kind"] != "bitfield":
                continue
            svg = DOCS / p["name"] / "types" / (re.sub(r"[^a-z0-9]+", "-", t["name"].lower()).strip("-") + ".svg")
            root = ET.parse(svg).getroot()
            titles = [e.text for e in root.iter("{http://www.w3.org/2000/svg}title")]
            for m in t["members"]:
                if not m.get("alias"):
                    assert any(x and x.startswith(m["name"]) for x in titles), f"{svg.name}: no box for {m['name']}"
    # A data field with a bitfield shows the bitfield's table and diagram on its own page.
    page = (DOCS / "mip" / "system_data" / "built_in_test.md").read_text(encoding="utf-8")
    assert "![bit diagram of" in page and "| bits | mask | name | description |" in page


def test_index_device_matrix_errata_and_getting_started_exist():
    home = (DOCS / "README.md").read_text(encoding="utf-8")
    for p in IR["protocols"]:
        assert f"]({p['name']}/README.md)" in home
        matrix = (DOCS / p["name"] / "devices.md").read_text(encoding="utf-8")
        for d in p["devices"]:
            assert d["title"] in matrix.splitlines()[4] or d["title"] in matrix
        total = sum(1 for s in p["sets"] for _ in s["fields"]) + len(p["reserved_fields"])
        support, _, defaults = matrix.partition("\n## Factory defaults\n")
        rows = [ln for ln in support.splitlines() if ln.startswith("| 0x") or ln.startswith("| any")]
        assert len(rows) == total, f"{p['name']} matrix has {len(rows)} rows for {total} descriptors"
        # one row per parameter default, citing the manual lines stating it; then the assumptions
        stated, _, assumed = defaults.partition("\n## Settings without a stated default\n")
        cited = [
            (q["name"], q["default"])
            for s in p["sets"]
            for f in s["fields"]
            for v in f["variants"]
            for q in v["params"]
            if q.get("default")
        ]
        rows = [ln for ln in stated.splitlines() if ln.startswith("| 0x")]
        assert len(rows) == len(cited), (p["name"], len(rows), len(cited))
        for (name, d), row in zip(cited, rows):
            assert f"`{name}`" in row and f"`{d['source']['manual']}:{d['source']['line']}`" in row, row
        for d in p["devices"]:
            assert f"### {d['title']}: " in assumed
    errata = (DOCS / "errata.md").read_text(encoding="utf-8")
    # Every published example recorded as wrong in tests/vectors appears on the errata page.
    for name in re.findall(r"^\| `([a-z0-9_]+)` \|", (ROOT / "docs" / "errata.md").read_text(encoding="utf-8"), re.M):
        assert f"`{name}`" in errata, name
    for lang in NAMES:
        assert (DOCS / "getting-started" / f"{lang}.md").exists()
