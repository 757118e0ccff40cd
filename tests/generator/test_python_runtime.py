"""The Python runtime (generator/targets/python/runtime/) is plain source: no template syntax, and the
package name reaches its code only through the generated _protocol.py / _protocol.h. The
placeholders the back end replaces when it copies the files (<package>, ...) are for documentation
only. (The runtime's behaviour is tested in place: generator/targets/python/runtime/tests/.)"""

from __future__ import annotations

import ast
import io
import tokenize

from generator.render import runtime_dir
from generator.targets.python.backend import PACKAGE_TEST_FILES, RUNTIME_FILES

PLACEHOLDERS = ("<package>", "<PACKAGE>", "<protocol title>")


def _docstrings(tree: ast.AST) -> set[int]:
    """Line numbers where a docstring starts."""
    lines = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                lines.add(first.lineno)
    return lines


def test_runtime_files_have_no_template_syntax():
    for name in RUNTIME_FILES + [f"package_tests/{n}" for n in PACKAGE_TEST_FILES]:
        text = (runtime_dir("python") / name).read_text(encoding="utf-8")
        for tag in ("{{", "{%", "{#"):
            assert tag not in text, f"{name}: template syntax {tag!r} in a runtime file"


def test_placeholders_are_only_in_docstrings_and_comments():
    seen = set()
    for name in RUNTIME_FILES:
        text = (runtime_dir("python") / name).read_text(encoding="utf-8")
        if name.endswith(".py"):
            docs = _docstrings(ast.parse(text))
            for tok in tokenize.generate_tokens(io.StringIO(text).readline):
                if any(p in tok.string for p in PLACEHOLDERS):
                    seen.add(name)
                    where = f"{name}:{tok.start[0]}"
                    assert tok.type == tokenize.COMMENT or tok.start[0] in docs, f"{where}: placeholder in code"
        else:
            for number, line in enumerate(text.splitlines(), 1):
                if any(p in line for p in PLACEHOLDERS):
                    seen.add(name)
                    assert line.lstrip().startswith(("/*", "*")), f"{name}:{number}: placeholder outside a comment"
    assert {"cli.py", "codec/_speedups.c"} <= seen  # the check looked at the files that have them
