"""Every upper-case identifier the hand-written docs name after a protocol exists in generated/.

An identifier in backticks that starts with a protocol's name (`MIPC_FIELD_BASE_PING`,
`MIPCODEC_BUILD_TESTS`) is a C/C++ constant, macro or CMake option of a generated package; a
misspelled prefix (`MIP_FIELD_BASE_PING` for `MIPC_FIELD_BASE_PING`, issue 39) names nothing and a
reader who copies it gets a compile error. Placeholders written with `<pkg>` are not checked.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
IR = json.loads((ROOT / "generated" / "ir.json").read_text())
PREFIXES = tuple(sorted({p["name"].upper() for p in IR["protocols"]}))
IDENT = re.compile(r"`(" + "|".join(PREFIXES) + r")([A-Z0-9]*_[A-Z0-9_]+)`")
SOURCES = (".h", ".hpp", ".c", ".cpp", ".txt", ".cmake", ".in", ".rs", ".py")


def _generated_text() -> str:
    parts = []
    for path in sorted((ROOT / "generated").rglob("*")):
        if path.is_file() and (path.suffix in SOURCES or path.name == "CMakeLists.txt"):
            parts.append(path.read_text(encoding="utf-8", errors="replace"))
    return "\n".join(parts)


def _pages() -> list[Path]:
    return [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]


def test_prefixes_come_from_the_ir():
    assert "MIP" in PREFIXES and "MSCIP" in PREFIXES


def test_every_protocol_prefixed_identifier_in_the_docs_exists():
    text = _generated_text()
    missing = []
    for page in _pages():
        for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
            for m in IDENT.finditer(line):
                name = m.group(1) + m.group(2)
                if not re.search(r"\b" + re.escape(name) + r"\b", text):
                    missing.append(f"{page.relative_to(ROOT)}:{number}: `{name}` is not in generated/")
    assert not missing, "\n".join(missing)


def test_the_check_catches_a_wrong_prefix():
    assert IDENT.search("`MIP_FIELD_BASE_PING`")
    assert not re.search(r"\bMIP_FIELD_BASE_PING\b", _generated_text())
