"""The runtime contract (docs/runtime-contract.md): the runtimes' tests use code the back ends
render from tests/runtime_specs/, not hand-written stand-ins of generated modules, and what each
runtime takes from generated code is what the page lists and what the templates render.

- No file under generator/targets/<lang>/runtime/ is named as a file a template renders (a
  stand-in of a generated module).
- Python: every symbol the runtime imports from a generated module is listed on the page, and
  every listed symbol is defined by the module the back end renders for the test protocol.
- C: every symbol the runtime uses that only generated code defines is listed, every listed
  symbol is in the rendered file the page names and is stated in runtime/tests/contract.c (which
  tests/lang/c.sh runtime compiles and links against the rendered package).
- C++: every listed symbol is in the rendered header the page names and is checked in
  runtime/tests/contract.cpp (built by tests/lang/cpp.sh runtime against the rendered package).
- Rust: every listed item is bound in runtime/tests/contract.rs (which tests/lang/rust.sh runtime
  compiles against the rendered crate, so that the crate provides each with its type).
"""

from __future__ import annotations

import ast
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import generator.targets
from generator.render import runtime_dir
from generator.targets.c.backend import c_prefix
from generator.targets.python.backend import RUNTIME_FILES, runtime_files
from tests.runtime_specs import render

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "runtime-contract.md"
TEMPLATES = ROOT / "templates"
LANGS = tuple(generator.targets.NAMES)  # the target registry, never a list of its own
# Names a template renders that a runtime folder legitimately has too (build files, docs).
GENERIC = {"CMakeLists.txt", "README.md", "Cargo.toml", "setup.py", "pyproject.toml", "MANIFEST.in"}
# Template outputs whose file name is not the template's: the package's own header.
EXTRA_OUTPUTS = {"c": {"codec.h"}, "cpp": {"protopkg.hpp"}, "python": set(), "rust": set()}
SECTIONS = {"python": "Python", "rust": "Rust", "c": "C", "cpp": "C++"}


def template_outputs(lang: str) -> set[str]:
    """File names the language's templates render (a template x.j2 renders x)."""
    names = {p.name[: -len(".j2")] for p in (TEMPLATES / lang).rglob("*.j2")}
    return (names | EXTRA_OUTPUTS[lang]) - GENERIC


def contract(lang: str) -> dict[str, set[str]]:
    """The page's table of a language: module/file (first code span of the first column) -> the
    identifiers of the code spans of the last column."""
    text = PAGE.read_text(encoding="utf-8")
    m = re.search(rf"^## {re.escape(SECTIONS[lang])}\n(.*?)(?=^## |\Z)", text, re.M | re.S)
    assert m, f"docs/runtime-contract.md: no section ## {SECTIONS[lang]}"
    table: dict[str, set[str]] = {}
    for line in m.group(1).splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 2 or not cells[0].startswith("`"):
            continue
        module = re.findall(r"`([^`]+)`", cells[0])[0]
        names = {re.match(r"[A-Za-z_][A-Za-z0-9_]*", s).group(0) for s in re.findall(r"`([^`]+)`", cells[-1])}
        table[module] = names
    assert table, f"docs/runtime-contract.md: no table in ## {SECTIONS[lang]}"
    return table


@pytest.mark.parametrize("lang", LANGS)
def test_no_hand_written_stand_ins_of_generated_modules(lang: str) -> None:
    rt = runtime_dir(lang)
    outputs = template_outputs(lang)
    # (a subfolder's __init__.py is a room of the Python runtime, not the package's __init__.py)
    found = {
        p.relative_to(rt).as_posix()
        for p in rt.rglob("*")
        if p.is_file() and p.name in outputs and not (p.name == "__init__.py" and p.parent != rt)
    }
    assert not found, (
        f"{lang} runtime: {sorted(found)} named as generated files (a stand-in?); the runtime tests run "
        f"against the package rendered from tests/runtime_specs/ (docs/runtime-contract.md)"
    )


@pytest.fixture(scope="module")
def python_package() -> Path:
    return render.render("python", "a") / "python" / "testproto" / "testproto"


def _python_runtime_uses(modules: set[str]) -> dict[str, set[str]]:
    """What the Python runtime imports from the generated modules: `from .m import X` and
    `from . import m` followed by `m.X`."""
    uses: dict[str, set[str]] = {}
    rt = runtime_dir("python")
    for name in RUNTIME_FILES + runtime_files("protocols", excluded=()):
        if not name.endswith(".py"):
            continue
        f = rt / name
        # the package's top, seen from the file: one dot at the top, one more per room level
        # (protocols/<name>/ files are copied to the top)
        top = 1 if name.startswith("protocols/") else name.count("/") + 1
        tree = ast.parse(f.read_text(encoding="utf-8"))
        aliases: dict[str, str] = {}
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.level == top:
                if node.module in modules:
                    uses.setdefault(node.module, set()).update(a.name for a in node.names)
                elif node.module is None:
                    aliases.update({a.asname or a.name: a.name for a in node.names if a.name in modules})
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in aliases:
                uses.setdefault(aliases[node.value.id], set()).add(node.attr)
    return uses


def test_python_runtime_uses_only_the_listed_symbols_and_the_package_has_them(python_package: Path) -> None:
    table = contract("python")
    generated = {p.name[: -len(".py.j2")] for p in (TEMPLATES / "python" / "package").glob("*.py.j2")}
    generated.discard("fields")  # one module per set: read through registry, never imported by name
    for module, names in _python_runtime_uses(generated).items():
        assert module in table, f"the Python runtime imports generated module {module}, not on the page"
        assert names <= table[module], f"{module}: not on the page: {sorted(names - table[module])}"
    modules = {m: sorted(n) for m, n in table.items() if not m.endswith(".h")}
    # Imported in a child process (the package is testproto, rendered under build/): what each
    # module provides, module-level __getattr__ (registry.FIELDS) included.
    probe = (
        "import importlib, json, sys\n"
        "want = json.loads(sys.argv[1])\n"
        "print(json.dumps({m: [n for n in names if not hasattr(importlib.import_module('testproto.' + m), n)]"
        " for m, names in want.items()}))\n"
    )
    run = subprocess.run(
        [sys.executable, "-c", probe, json.dumps(modules)],
        cwd=python_package.parent,
        env=dict(os.environ, PYTHONPATH=str(python_package.parent), TESTPROTO_PURE="1"),
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    missing = {m: n for m, n in json.loads(run.stdout).items() if n}
    assert not missing, f"the rendered test package lacks {missing}"
    for module, names in table.items():
        if module.endswith(".h"):
            # (a header lives where the C files that #include it are: _protocol.h in codec/)
            text = next(python_package.rglob(module)).read_text(encoding="utf-8")
            absent = {n for n in names if not re.search(rf"\b{n}\b", text)}
            assert not absent, f"rendered {module} lacks {sorted(absent)}"


def _identifiers(paths: list[Path], pattern: str) -> set[str]:
    out: set[str] = set()
    for p in paths:
        out |= set(re.findall(pattern, p.read_text(encoding="utf-8", errors="replace")))
    return out


def test_c_runtime_uses_only_the_listed_symbols_and_the_package_has_them() -> None:
    table = contract("c")
    listed = set().union(*table.values())
    rt = runtime_dir("c")
    pkg = render.render("c", "a") / "c" / "testproto"
    prefix = c_prefix("testproto")
    word = r"\b(?:codec|CODEC)_[A-Za-z0-9_]+"
    used = _identifiers([*rt.glob("src/*.[ch]"), *rt.glob("include/codec/*.h"), *rt.glob("tools/*.[ch]")], word)
    declared = _identifiers([*rt.glob("include/codec/*.h"), *rt.glob("src/*.h")], word)
    runtime_names = {p.name for p in rt.rglob("*") if p.is_file()}
    rendered = [p for p in pkg.rglob("*.[ch]") if p.name not in runtime_names]
    to_neutral = {prefix + "_": "codec_", prefix.upper() + "_": "CODEC_"}
    generated = {
        re.sub(rf"^({prefix}_|{prefix.upper()}_)", lambda m: to_neutral[m.group(1)], n)
        for n in _identifiers(rendered, rf"\b(?:{prefix}|{prefix.upper()})_[A-Za-z0-9_]+")
    }
    only_generated = (used & generated) - declared
    assert only_generated <= listed, (
        f"used by the C runtime, defined by generated code, not on the page: {sorted(only_generated - listed)}"
    )
    for file, names in table.items():
        path = pkg / file.replace("codec/", "testproto/")
        text = path.read_text(encoding="utf-8")
        missing = {
            n
            for n in names
            if not re.search(rf"\b{n.replace('codec_', prefix + '_').replace('CODEC_', prefix.upper() + '_')}\b", text)
        }
        assert not missing, f"rendered {file} lacks {sorted(missing)}"
    stated = (rt / "tests" / "contract.c").read_text(encoding="utf-8")
    unstated = {n for n in listed if n.startswith(("codec_", "CODEC_")) and not re.search(rf"\b{n}\b", stated)}
    assert not unstated, f"runtime/tests/contract.c does not state {sorted(unstated)}"


def test_cpp_package_has_the_listed_symbols_and_contract_cpp_checks_them() -> None:
    pkg = render.render("cpp", "a") / "cpp" / "testproto" / "include" / "testproto"
    for header, names in contract("cpp").items():
        text = (pkg / header.replace("<pkg>", "testproto")).read_text(encoding="utf-8")
        missing = {n for n in names if not re.search(rf"\b{n}\b", text)}
        assert not missing, f"rendered {header} lacks {sorted(missing)}"
    stated = (runtime_dir("cpp") / "tests" / "contract.cpp").read_text(encoding="utf-8")
    unstated = {n for names in contract("cpp").values() for n in names if not re.search(rf"\b{n}\b", stated)}
    assert not unstated, f"runtime/tests/contract.cpp does not state {sorted(unstated)}"


def test_rust_contract_binds_every_listed_item() -> None:
    source = (runtime_dir("rust") / "tests" / "contract.rs").read_text(encoding="utf-8")
    for module, names in contract("rust").items():
        missing = {n for n in names if not re.search(rf"\b{n}\b", source)}
        assert not missing, f"runtime/tests/contract.rs does not bind {module}: {sorted(missing)}"
