"""The structure of the Python runtime (generator/targets/python/runtime/, docs/design.md "The
Python runtime's rooms"): read from its sources, nothing imported or run.

- no runtime module imports another runtime module's private (`_name`) names, nor reads them as
  attributes of a runtime module it imported (the generated modules, `_protocol`, `_sim`, ...,
  are the package's facts, not another module's helpers);
- the runtime modules' imports, at module level or inside functions, make no circle;
- no runtime source (Python or C) is over 1,500 lines, no runtime function over 150;
- at most six modules at the runtime's top, at least four rooms;
- a protocol's package carries no other protocol's knowledge in its code: no other protocol's
  name, package name or device ids in the names and strings of the runtime's copies in it
  (comments and docstrings may cite any manual).
"""

from __future__ import annotations

import ast
import io
import json
import re
import tokenize

from generator.render import ROOT, runtime_dir
from generator.targets.python.backend import RUNTIME_FILES, RUNTIME_ROOMS, runtime_files

RUNTIME = runtime_dir("python")
MAX_LINES = 1500
MAX_FUNCTION = 150
# Every runtime source: the files copied into every package and the modules of one protocol.
SOURCES = RUNTIME_FILES + runtime_files("protocols", excluded=())


def _module(path: str) -> str:
    """The dotted name of a runtime source inside its package ("" for the package itself);
    protocols/<name>/x.py lands at the package's top."""
    parts = path[: -len(".py")].split("/")
    if parts[0] == "protocols":
        parts = parts[2:]
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


MODULES = {_module(p): p for p in SOURCES if p.endswith(".py")}


def _package_of(module: str, path: str) -> list[str]:
    parts = module.split(".") if module else []
    return parts if path.endswith("__init__.py") else parts[:-1]


def _resolve(module: str, path: str, node: ast.ImportFrom) -> str | None:
    """The dotted module a relative `from ... import` names (None: not a relative import)."""
    if not node.level:
        return None
    base = _package_of(module, path)
    base = base[: len(base) - (node.level - 1)] if node.level > 1 else base
    return ".".join(base + (node.module.split(".") if node.module else []))


def _imports(path: str) -> list[tuple[str, str, ast.ImportFrom, ast.alias]]:
    """(imported runtime-or-generated module, name or "", node, alias) of every name a relative
    import of a source imports."""
    module = _module(path)
    out = []
    for node in ast.walk(ast.parse((RUNTIME / path).read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.level:
            target = _resolve(module, path, node)
            for alias in node.names:
                sub = f"{target}.{alias.name}" if target else alias.name
                if sub in MODULES or sub.split(".")[0] not in MODULES:
                    out.append((sub, "", node, alias))  # a module (runtime or generated) imported by name
                else:
                    out.append((target, alias.name, node, alias))
    return out


def test_no_module_reaches_into_another_modules_private_names():
    reach = []
    for path in MODULES.values():
        bound = {}
        for target, name, node, alias in _imports(path):
            if name and name.startswith("_") and target in MODULES:
                reach.append(f"{path}:{node.lineno}: imports {name} from {target}")
            if not name and target in MODULES:
                bound[alias.asname or alias.name] = target
        tree = ast.parse((RUNTIME / path).read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if (
                isinstance(node, ast.Attribute)
                and isinstance(node.value, ast.Name)
                and node.value.id in bound
                and node.attr.startswith("_")
                and not node.attr.startswith("__")
            ):
                reach.append(f"{path}:{node.lineno}: reads {node.value.id}.{node.attr} ({bound[node.value.id]})")
    assert not reach, "private names reached across runtime modules:\n" + "\n".join(reach)


def test_the_runtime_imports_make_no_circle():
    graph = {m: set() for m in MODULES}
    for module, path in MODULES.items():
        for target, _name, _node, _alias in _imports(path):
            if target in MODULES and target != module:
                graph[module].add(target)
    # a circle: a module reachable from one of the modules it imports
    circles = []
    for start in graph:
        seen, todo = set(), list(graph[start])
        while todo:
            m = todo.pop()
            if m == start:
                circles.append(start)
                break
            if m not in seen:
                seen.add(m)
                todo.extend(graph[m])
    assert not circles, f"modules on an import circle: {sorted(circles)}"
    assert graph["logs.dataset"] >= {"logs.arrow", "logs.export"}  # the check saw the imports


def test_no_source_or_function_is_too_long():
    long_files = []
    for path in SOURCES:
        if path.endswith((".py", ".c", ".h")):
            n = len((RUNTIME / path).read_text(encoding="utf-8").splitlines())
            if n > MAX_LINES:
                long_files.append(f"{path}: {n} lines")
    assert not long_files, f"runtime sources over {MAX_LINES} lines: {long_files}"
    long_functions = []
    for path in MODULES.values():
        for node in ast.walk(ast.parse((RUNTIME / path).read_text(encoding="utf-8"))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                n = node.end_lineno - node.lineno + 1
                if n > MAX_FUNCTION:
                    long_functions.append(f"{path}:{node.lineno}: {node.name} ({n} lines)")
    assert not long_functions, f"runtime functions over {MAX_FUNCTION} lines: {long_functions}"


def test_the_runtime_top_is_small_and_the_rooms_are_there():
    top = [p for p in RUNTIME_FILES if "/" not in p and p.endswith(".py")]
    top += [p.split("/")[-1] for p in runtime_files("protocols", excluded=()) if p.endswith(".py")]
    assert len(top) <= 6, f"modules at the runtime's top: {top}"
    assert len(RUNTIME_ROOMS) >= 4, RUNTIME_ROOMS
    for room in RUNTIME_ROOMS:
        assert (RUNTIME / room / "__init__.py").is_file()


def _code_words(text: str) -> str:
    """The names and strings of a Python module, without comments and docstrings."""
    tree = ast.parse(text)
    docs = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                docs.add(first.lineno)
    out = []
    for tok in tokenize.generate_tokens(io.StringIO(text).readline):
        if tok.type == tokenize.NAME or (tok.type == tokenize.STRING and tok.start[0] not in docs):
            out.append(tok.string)
    return "\n".join(out)


def test_a_protocols_package_holds_no_other_protocols_knowledge():
    ir = json.loads((ROOT / "generated" / "ir.json").read_text(encoding="utf-8"))
    protocols = ir["protocols"]
    assert len(protocols) >= 2  # (the project's MIP and MS-CIP)
    found = []
    for p in protocols:
        package = ROOT / "generated" / "python" / p["package"] / p["package"]
        # the runtime's copies (the generated modules come from the protocol's own spec)
        files = [package / name for name in RUNTIME_FILES if name.endswith(".py")]
        assert all(f.is_file() for f in files), package
        for q in protocols:
            if q is p:
                continue
            for name in runtime_files(f"protocols/{q['name']}", excluded=()):  # its own modules
                if (package / name.split("/")[-1]).exists():
                    found.append(f"{p['package']}: {name} copied")
            words = [q["package"], *(d["id"] for d in q["devices"])]
            pattern = re.compile(r"\b(" + "|".join(map(re.escape, [q["name"], *words])) + r")\b", re.IGNORECASE)
            for f in files:
                for m in pattern.finditer(_code_words(f.read_text(encoding="utf-8"))):
                    found.append(f"{f.relative_to(ROOT)}: {m.group(0)!r} ({q['name']})")
    assert not found, "another protocol's knowledge in a package's code:\n" + "\n".join(found[:20])
