"""The generator's import structure (issue 49): no import circle among the modules of generator/
and no module reaching into another's private names (`from .x import _name`, `x._name`).

The graph is read from the sources with ast, module-level and function-level imports alike (a
function-local import only hides a circle). The runtimes under generator/targets/<lang>/runtime/
are package sources copied into the generated packages, not modules of the generator, and are
left out here.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _modules(root: Path, package: str) -> dict[str, tuple[Path, bool]]:
    """Dotted module name -> (file, is a package's __init__) for every module of the package."""
    out = {}
    for p in sorted((root / package).rglob("*.py")):
        parts = list(p.relative_to(root).with_suffix("").parts)
        if "runtime" in parts:
            continue
        is_pkg = parts[-1] == "__init__"
        out[".".join(parts[:-1] if is_pkg else parts)] = (p, is_pkg)
    return out


def import_graph(root: Path, package: str) -> tuple[dict[str, set[str]], list[str]]:
    """(module -> the modules of the package it imports, the private reaches as readable lines)."""
    mods = _modules(root, package)
    edges: dict[str, set[str]] = {m: set() for m in mods}
    private: list[str] = []
    for m, (path, is_pkg) in mods.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
        here = m.split(".") if is_pkg else m.split(".")[:-1]
        bound: dict[str, str] = {}  # local name -> the module of the package it names
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for a in node.names:
                    if a.name in mods:
                        edges[m].add(a.name)
                        if a.asname:
                            bound[a.asname] = a.name
            elif isinstance(node, ast.ImportFrom):
                base = here[: len(here) - node.level + 1] if node.level else []
                target = ".".join(base + ([node.module] if node.module else []))
                if target not in mods:
                    continue
                for a in node.names:
                    sub = f"{target}.{a.name}"
                    if sub in mods:
                        edges[m].add(sub)
                        bound[a.asname or a.name] = sub
                        continue
                    edges[m].add(target)
                    if a.name.startswith("_") and target != m:
                        private.append(f"{m} imports {target}.{a.name} (line {node.lineno})")
        for node in ast.walk(tree):
            if (
                isinstance(node, ast.Attribute)
                and isinstance(node.value, ast.Name)
                and node.value.id in bound
                and node.attr.startswith("_")
                and not node.attr.startswith("__")
                and bound[node.value.id] != m
            ):
                private.append(f"{m} uses {bound[node.value.id]}.{node.attr} (line {node.lineno})")
    for m in edges:
        edges[m].discard(m)
    return edges, private


def circles(edges: dict[str, set[str]]) -> list[list[str]]:
    """Each import circle once, as the path around it (first module repeated at the end)."""
    found: list[list[str]] = []
    seen: set[frozenset[str]] = set()
    state: dict[str, int] = {}  # 1 on the path, 2 done

    def visit(m: str, path: list[str]) -> None:
        state[m] = 1
        path.append(m)
        for n in sorted(edges[m]):
            if state.get(n) == 1:
                loop = path[path.index(n) :] + [n]
                if frozenset(loop) not in seen:
                    seen.add(frozenset(loop))
                    found.append(loop)
            elif n not in state:
                visit(n, path)
        path.pop()
        state[m] = 2

    for m in sorted(edges):
        if m not in state:
            visit(m, [])
    return found


def test_the_generator_has_no_import_circle_and_no_private_reach():
    edges, private = import_graph(ROOT, "generator")
    assert len(edges) > 80 and "generator.targets.rust.backend" in edges  # the whole generator (runtimes left out)
    assert [" -> ".join(c) for c in circles(edges)] == []
    assert private == []


def test_the_check_finds_a_circle_a_function_level_import_and_a_private_reach(tmp_path):
    pkg = tmp_path / "gen"
    (pkg / "docs").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "docs" / "__init__.py").write_text("")
    (pkg / "a.py").write_text("from . import b\n")
    (pkg / "b.py").write_text("def f():\n    from .docs.c import g\n    return g\n")  # hidden in a function
    (pkg / "docs" / "c.py").write_text("from ..a import _secret\n\ndef g():\n    pass\n")
    (pkg / "d.py").write_text("from . import b as bee\n\nx = bee._hidden\n")
    edges, private = import_graph(tmp_path, "gen")
    assert edges["gen.a"] == {"gen.b"} and edges["gen.b"] == {"gen.docs.c"} and edges["gen.docs.c"] == {"gen.a"}
    assert circles(edges) == [["gen.a", "gen.b", "gen.docs.c", "gen.a"]]
    assert private == ["gen.d uses gen.b._hidden (line 3)", "gen.docs.c imports gen.a._secret (line 1)"]
