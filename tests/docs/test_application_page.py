"""docs/application-against-the-simulator.md quotes the Python application program: every Python
listing on the page is a verbatim part of tests/apps/python/cv7_external_aiding.py, and every
application program the page names exists."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs/application-against-the-simulator.md"
APP = ROOT / "tests/apps/python/cv7_external_aiding.py"


def listings(text: str, language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", text, flags=re.S)


def test_every_python_listing_is_part_of_the_program() -> None:
    source = APP.read_text(encoding="utf-8")
    quoted = listings(PAGE.read_text(encoding="utf-8"), "python")
    assert len(quoted) >= 3
    for block in quoted:
        assert block in source, block


def test_the_page_names_programs_that_exist() -> None:
    text = PAGE.read_text(encoding="utf-8")
    for lang in re.findall(r"tests/lang/(\w+)\.sh app", text):
        assert (ROOT / "tests/lang" / f"{lang}.sh").is_file()
    for lang, ext in (("python", "py"), ("c", "c"), ("cpp", "cpp")):
        assert (ROOT / "tests/apps" / lang / f"cv7_external_aiding.{ext}").is_file(), lang
    assert (ROOT / "tests/apps/rust/Cargo.toml").is_file()
    ext = {"python": "py", "c": "c", "cpp": "cpp", "rust": "rs"}
    for lang, name in re.findall(r"tests/lang/(\w+)\.sh app (\w+)", text):
        assert (ROOT / "tests/apps" / lang / f"{name}.{ext[lang]}").is_file(), (lang, name)
