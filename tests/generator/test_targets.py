"""The language list once (issue 36): the target registry generator/targets/__init__.py is the one
list of languages. Everything that runs per language reads it: the CLI, setup.py, the Makefile,
the conformance tools and the cross-language tests. A target registered without its runner
fails those tests by name instead of dropping out of them."""

from __future__ import annotations

import inspect
import re
import subprocess
import sys
from pathlib import Path

from generator import cli
from generator.resources import runtime_dir
from generator.targets import NAMES, TARGETS
from tests.helpers.langs import LANGS, missing_runner

ROOT = Path(__file__).resolve().parents[2]


def test_the_registry_is_one_ordered_list_and_every_target_has_its_wing():
    assert list(TARGETS) == list(NAMES) and len(set(NAMES)) == len(NAMES)
    for name in NAMES:
        mod = TARGETS[name]
        assert mod.OUTPUT_DIRS and all(isinstance(d, str) for d in mod.OUTPUT_DIRS), name
        # every back end takes the same arguments: the pipeline passes them positionally
        params = list(inspect.signature(mod.render).parameters)
        assert params == ["ir", "vectors", "release", "sessions"], (name, params)
        assert callable(mod.api_names) and callable(mod.public_name), name
        assert callable(mod.names) and callable(mod.reserved), name  # the name check (issue 37)
        assert mod.TITLE and mod.EXTENSION, name  # the docs and the getting-started programs
        assert runtime_dir(name).is_dir(), name
        assert (ROOT / "templates" / name).is_dir(), name


def test_every_target_has_a_runner():
    assert [n for n in NAMES if missing_runner(n)] == []


def test_the_cli_the_makefile_and_the_tests_read_the_registry():
    assert cli.LANGS == (*NAMES, "docs")
    assert LANGS == list(NAMES)
    listed = subprocess.run([sys.executable, "-m", "generator", "targets"], cwd=ROOT, capture_output=True, text=True)
    assert listed.returncode == 0 and listed.stdout.split() == list(NAMES), listed
    # the Makefile's LANGS is what `python -m generator.targets` prints (a bare interpreter reads it)
    bare = subprocess.run(["python3", "-m", "generator.targets"], cwd=ROOT, capture_output=True, text=True)
    assert bare.returncode == 0 and bare.stdout.split() == list(NAMES), bare
    make = subprocess.run(["make", "-pn", "-f", "Makefile"], cwd=ROOT, capture_output=True, text=True)
    langs = re.search(r"^LANGS := (.*)$", make.stdout, re.M)
    assert langs and langs[1].split() == list(NAMES), langs
    assert "LANGS := $(shell $(PYTHON) -m generator.targets)" in (ROOT / "Makefile").read_text()
    # setup.py ships every registered target's runtime
    assert "from generator.targets import NAMES as LANGS" in (ROOT / "setup.py").read_text()


def test_no_test_module_keeps_a_language_list_of_its_own():
    # The old spellings of the list; a module that needs a language subset names it by the reason
    # (a C-family build, a benchmark implementation) and is checked against the registry below.
    literal = re.compile(
        r"""[\[(]\s*["'](c|python)["'],\s*["'](cpp|c)["'],\s*["'](cpp|python|rust)["'],\s*["']\w+["']\s*[\])]"""
    )
    offenders = []
    for path in [*(ROOT / "tests").rglob("*.py"), *(ROOT / "generator").rglob("*.py"), ROOT / "setup.py"]:
        if "fixtures" in path.parts or path == Path(__file__) or path.name == "__init__.py" and "targets" in path.parts:
            continue
        for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if literal.search(line):
                offenders.append(f"{path.relative_to(ROOT)}:{i}: {line.strip()}")
    assert offenders == [], "\n".join(offenders)


def test_per_language_tables_of_the_fuzz_and_bench_runners_cover_the_registry():
    # Their per-language build steps are code; a new target without them is named here.
    from tests.bench import run as bench
    from tests.fuzz import fuzz

    assert sorted(bench.LANG_ROWS) == sorted(NAMES)
    assert sorted(fuzz.LANGS) == sorted(NAMES)


def test_a_fifth_target_without_a_runner_fails_the_shared_suites_by_name():
    """A toy target registered before collection (tests/helpers/toy_target.py) is a parameter of
    every cross-language test; with no runner each of its tests fails, naming it; none is skipped."""
    proc = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "-p",
            "tests.helpers.toy_target",
            "-p",
            "no:cacheprovider",
            "-q",
            "-rfEs",
            "-k",
            "toy",
            "tests/conformance/test_cross_language.py",
            "tests/conformance/test_sessions.py",
            "tests/conformance/test_cli_streaming.py",
        ],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=600,
    )
    out = proc.stdout
    assert proc.returncode == 1, out[-3000:]
    summary = out.strip().splitlines()[-1]
    assert "skipped" not in summary and "passed" not in summary, summary
    failed = re.findall(r"^(?:FAILED|ERROR) (\S+\[toy\])", out, re.M)
    assert len(failed) >= 8, out[-3000:]  # each per-language test of the three modules
    assert {f.split("::")[0] for f in failed} == {
        "tests/conformance/test_cross_language.py",
        "tests/conformance/test_sessions.py",
        "tests/conformance/test_cli_streaming.py",
    }
    assert "target 'toy' is registered (generator/targets/__init__.py) but has no runner tests/lang/toy.sh" in out
    # and the conformance tools refuse it by name
    tool = subprocess.run(
        [str(ROOT / "tests/conformance/decode"), "toy", "/dev/null"], cwd=ROOT, capture_output=True, text=True
    )
    assert tool.returncode == 2 and "unknown LANG 'toy': no runner tests/lang/toy.sh" in tool.stderr


def test_mipgen_diff_asks_each_target_for_its_names_of_a_field_with_per_device_variants():
    """Renaming a field with per-device layouts: the report's old names are the types each target
    generated for it (one per device in C, C++, Python), found in generated/; a name list kept
    by the diff tool itself once gave C types that do not exist."""
    import copy

    from generator import wirediff
    from generator.spec import load_spec

    old = load_spec()
    mip = next(p for p in old["protocols"] if p["name"] == "mip")
    s, f = next((s, f) for s in mip["sets"] for f in s["fields"] if len(f["variants"]) > 1 and s["kind"] == "data")
    new = copy.deepcopy(old)
    g = next(
        x for x in next(t for t in new["protocols"][0]["sets"] if t["id"] == s["id"])["fields"] if x["id"] == f["id"]
    )
    g["name"] = f["name"] + "_renamed"
    changes = [c for c in wirediff.diff(old, new) if "renamed" in c.what]
    assert len(changes) == 1, changes
    names = changes[0].names
    assert sorted(names) == sorted(NAMES)
    sources = {
        "c": (ROOT / "generated/c/mipcodec/include/mipcodec/sets" / f"{s['name']}.h").read_text(),
        "cpp": "".join(p.read_text() for p in (ROOT / "generated/cpp/mipcodec/include").rglob("*.hpp")),
        "python": "".join(p.read_text() for p in (ROOT / "generated/python/mipcodec/mipcodec").rglob("*.py")),
        "rust": "".join(p.read_text() for p in (ROOT / "generated/rust/mipcodec/src").rglob("*.rs")),
    }
    for lang in ("c", "cpp", "python"):
        (line,) = names[lang]
        before = line.split(" -> ")[0]
        types = [t.strip().split(": ")[-1].rsplit("::", 1)[-1].rsplit(".", 1)[-1] for t in before.split(",")]
        assert len(types) == len(f["variants"]), (lang, line)
        for t in types:
            assert re.search(rf"\b{re.escape(t)}\b", sources[lang]), (lang, t)


def test_runtime_sources_carry_no_generated_banner_and_their_copies_do():
    """The runtimes are hand-written: no source under generator/targets/<lang>/runtime/ says it is
    generated. The copy step closes the first comment of each C copy with the banner
    (generator/render.py add_banner), the vendored grisu3.h excepted."""
    from generator.render import GENERATED_BANNER, add_banner
    from generator.targets.c import backend as c

    banners = [
        p.relative_to(ROOT).as_posix()
        for name in NAMES
        for p in runtime_dir(name).rglob("*")
        if p.is_file()
        and "target" not in p.parts
        and p.suffix != ".md"  # the runtime's README describes the banner
        and "do not edit" in p.read_text(encoding="utf-8", errors="replace")
    ]
    assert banners == []
    package = ROOT / "generated" / "c" / "mipcodec"
    for src, dest in c._RUNTIME_FILES.items():
        text = (package / dest.replace("codec/", "mipcodec/")).read_text(encoding="utf-8")
        first_comment = text[: text.index("*/") + 2] if text.startswith("/*") else text.split("\n#")[0]
        want = 0 if src in c._RUNTIME_VENDORED else 1
        assert first_comment.count(GENERATED_BANNER) == want and text.count(GENERATED_BANNER) == want, dest
    # the banner's two places: the comment's last line when it fits in 100 columns, else its own line
    assert add_banner("/* Short. */\nx") == "/* Short. Generated: do not edit. */\nx"
    long = "/* " + "w" * 80 + " */\nx"
    assert add_banner(long) == "/* " + "w" * 80 + "\n * Generated: do not edit. */\nx"
    assert add_banner("// a\n// b\n#include <x>") == "// a\n// b Generated: do not edit.\n#include <x>"


# ------------------------------------------------------------------ a fifth target's getting-started page
def _fake_target(monkeypatch, with_facts: bool):
    """Registers a fifth target `fake` (issue 49): its wing is a module put where the registry
    imports it from, with its own getting-started record unless with_facts is False."""
    from types import ModuleType

    import generator.targets as registry
    from generator.targets import GettingStarted

    mod = ModuleType("generator.targets.fake")
    mod.TITLE, mod.EXTENSION = "Fake", "fk"
    if with_facts:
        mod.GETTING_STARTED = GettingStarted(
            install="Fetch `{pkg}` with fakepkg ({fake_version}).",
            setup="fakepkg add {pkg}",
            setup_lang="fakesh",
            setup_outside="project",
            include_intro="and summon it:",
            run_package_var="FAKE_PACKAGE",
            outside_run="fakerun {PKG} ADDRESS 5",
            simulator_note=" (fakepkg's serial extra)",
            variables={"fake_version": "fake 9"},
        )
    monkeypatch.setitem(sys.modules, "generator.targets.fake", mod)
    monkeypatch.setattr(registry, "NAMES", (*NAMES, "fake"))
    return mod


def _fake_docs(ir: dict):
    """The part of the documentation model add_pages reads: the fake language's API, the IR, and
    the configure-and-stream example of each package (marker lines only) in the fake language."""
    from generator.examples import SESSION_PARTS

    source = "\n".join(f"# [{part}]\nstep {part}\n# [end]" for part in SESSION_PARTS)

    class FakeDocs:
        def __init__(self):
            self.api, self.ir, self.vectors, self.pages = {"fake": {}}, ir, [], {}
            self.examples = {f"fake/{p['package']}/examples/configure_and_stream.fk": source for p in ir["protocols"]}

        def add(self, page):
            self.pages[page.path] = page
            return page

    return FakeDocs()


def _page_text(page) -> str:
    return "\n".join(str(b.get("text", "")) for b in page.blocks)


def test_a_fifth_target_gets_its_own_getting_started_text(monkeypatch):
    import json

    from generator.docs import getting_started

    _fake_target(monkeypatch, with_facts=True)
    ir = json.loads((ROOT / "generated" / "ir.json").read_text())
    docs = _fake_docs(ir)
    getting_started.add_pages(docs)
    page = docs.pages["getting-started/fake.md"]
    text = _page_text(page)
    assert page.title == "Getting started in Fake"
    assert "Fetch `mipcodec` with fakepkg (fake 9)." in text and "fakepkg add mscipcodec" in text
    assert "fakerun MIPCODEC tcp:127.0.0.1:PORT 5" in text  # the outside user's run, {PKG} upper case
    assert "FAKE_PACKAGE=mscipcodec tests/lang/fake.sh configure" in text
    assert "with the Python package installed (fakepkg's serial extra):" in text
    code = [b for b in page.blocks if b["kind"] == "code" and b["text"].startswith("fakepkg add")]
    assert [(b["lang"], b["outside"]) for b in code] == [("fakesh", "project")] * 2
    # nothing of another language's record
    for other in NAMES:
        facts = TARGETS[other].GETTING_STARTED
        assert facts.run_package_var not in text and facts.install.split("`")[0] not in text, other
    assert "cargo" not in text and "Rust" not in text


def test_a_target_without_its_getting_started_record_is_a_clear_error(monkeypatch):
    import json

    import pytest

    from generator.docs import getting_started
    from generator.render import ToolError

    _fake_target(monkeypatch, with_facts=False)
    ir = json.loads((ROOT / "generated" / "ir.json").read_text())
    with pytest.raises(ToolError, match=r"^target fake has no GETTING_STARTED .*generator/targets/fake/facts\.py"):
        getting_started.add_pages(_fake_docs(ir))
