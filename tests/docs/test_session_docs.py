"""The session parts of the generated reference (issue 20): every command page has a "Session call"
table with one row per language whose back end names the call (api_names "session"; Python for
every command), data pages have none, and each getting-started page has the "Configure the device
and stream data" section: the snippets of the package's examples/configure_and_stream.<ext>, or a
note that the language's session example is not generated yet."""

from __future__ import annotations

import re
from pathlib import Path

from generator.docs.getting_started import EXTENSIONS, snippet
from generator.examples import SESSION_PARTS, SESSION_PROGRAM, session_example
from generator.spec import load_spec
from generator.targets import TARGETS

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "generated" / "docs"
IR = load_spec()


def test_every_command_page_shows_the_session_call_of_each_language_that_has_one():
    checked = 0
    for p in IR["protocols"]:
        for s in p["sets"]:
            for f in s["fields"]:
                text = (DOCS / p["name"] / s["name"] / f"{f['name']}.md").read_text()
                section = text.split("## Session call", 1)
                calls = {lang: mod.api_names(p, s, f).get("session") for lang, mod in TARGETS.items()}
                if f["role"] != "command" or s["kind"] != "command":
                    assert len(section) == 1, (p["name"], s["name"], f["name"])
                    continue
                assert calls["python"], f["name"]
                assert len(section) == 2, (p["name"], s["name"], f["name"])
                table = section[1].split("\n## ", 1)[0]
                rows = re.findall(r"^\| \[(\w[\w+]*)\]\([^)]*#configure-and-stream\) \| `([^`]+)` \|$", table, re.M)
                want = [(lang, call) for lang, call in calls.items() if call]
                titles = {"c": "C", "cpp": "C++", "python": "Python", "rust": "Rust"}
                assert rows == [(titles[lang], call) for lang, call in want], (f["name"], table)
                checked += 1
    assert checked > 100


def test_getting_started_pages_have_the_configure_section():
    for lang, ext in EXTENSIONS.items():
        page = (DOCS / "getting-started" / f"{lang}.md").read_text()
        section = page.split("## Configure the device and stream data", 1)
        assert len(section) == 2, lang
        for p in IR["protocols"]:
            if session_example(p) is None:
                continue
            program = ROOT / "generated" / lang / p["package"] / "examples" / f"{SESSION_PROGRAM}.{ext}"
            if program.is_file():
                source = program.read_text()
                for part in SESSION_PARTS:
                    assert snippet(source, part) in section[1], (lang, p["name"], part)
            else:
                assert f"session example of `{p['package']}` is not generated yet" in section[1], (lang, p["name"])
    python = (ROOT / "generated/python/mipcodec/examples" / f"{SESSION_PROGRAM}.py").read_text()
    assert "sensor_to_vehicle_euler.write(" in snippet(python, "configure")
