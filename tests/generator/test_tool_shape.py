"""The shape of the runtimes' command-line tools (issue 49; the developers' guide: no function over
150 lines in the tools): every function of the C, C++ and Rust tools' sources is at most 150 lines,
and the C runtime has one hex-digit helper (src/hex.h: the digit of a value and the value of a
digit), not a private copy per file.

Functions are found in the formatted sources (clang-format, rustfmt: `make` formats the runtimes
the same way): a C/C++ function starts at column 0 with a line ending in `{` after a `)` and ends
at the next line that is `}` alone at column 0; a Rust `fn` ends at the first `}` at its own
indentation."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
RUNTIMES = ROOT / "generator" / "targets"
LIMIT = 150

C_TOOLS = sorted((RUNTIMES / "c" / "runtime" / "tools").rglob("*.c"))
CPP_TOOLS = sorted((RUNTIMES / "cpp" / "runtime" / "tools").rglob("*.cpp"))
RUST_TOOLS = sorted((RUNTIMES / "rust" / "runtime" / "src" / "bin").rglob("*.rs"))

_C_HEAD = re.compile(r"^[A-Za-z_][^;{}]*\)\s*(const\s*)?\{\s*$")
_RUST_FN = re.compile(r"^(\s*)(pub(\([a-z]+\))?\s+)?(const\s+|unsafe\s+|async\s+)*fn\s+(\w+)")


def c_functions(text: str) -> list[tuple[str, int, int]]:
    """(name, first line, line count) of each function defined at column 0."""
    lines = text.split("\n")
    out = []
    i = 0
    while i < len(lines):
        line = lines[i]
        start = i
        # a head split over several lines: gather until the line ending in "{" or ";"
        if re.match(r"^[A-Za-z_]", line) and "(" in line and not line.startswith(("typedef", "struct", "#")):
            head = line
            j = i
            while not head.rstrip().endswith(("{", ";", "}")) and j + 1 < len(lines) and j - i < 8:
                j += 1
                head += " " + lines[j].strip()
            if _C_HEAD.match(head.replace("\n", " ")) and "=" not in head.split("(")[0]:
                k = j + 1
                while k < len(lines) and lines[k] != "}":
                    k += 1
                name = re.findall(r"([A-Za-z_][\w:~]*)\s*\(", head)
                out.append((name[0] if name else "?", start + 1, k - start + 1))
                i = k + 1
                continue
        i += 1
    return out


def rust_functions(text: str) -> list[tuple[str, int, int]]:
    lines = text.split("\n")
    out = []
    for i, line in enumerate(lines):
        m = _RUST_FN.match(line)
        if not m:
            continue
        indent = m.group(1)
        k = i
        while k < len(lines) and not lines[k].rstrip().endswith("{") and not lines[k].rstrip().endswith(";"):
            k += 1
        if k >= len(lines) or lines[k].rstrip().endswith(";"):
            continue  # a declaration without a body
        end = k + 1
        while end < len(lines) and lines[end] != indent + "}":
            end += 1
        out.append((m.group(5), i + 1, end - i + 1))
    return out


def _long(paths, finder) -> list[str]:
    found = []
    for path in paths:
        for name, first, count in finder(path.read_text(encoding="utf-8")):
            if count > LIMIT:
                found.append(f"{path.relative_to(ROOT)}:{first}: {name} is {count} lines")
    return found


def test_the_finders_see_the_tools_functions():
    """The check is not vacuous: each finder finds the tools' entry points and a known long body."""
    c = {name for p in C_TOOLS for name, _, _ in c_functions(p.read_text(encoding="utf-8"))}
    cpp = {name for p in CPP_TOOLS for name, _, _ in c_functions(p.read_text(encoding="utf-8"))}
    rust = {name for p in RUST_TOOLS for name, _, _ in rust_functions(p.read_text(encoding="utf-8"))}
    assert "main" in c and "cmd_apply" in c and "cmd_stream" in c
    assert "main" in cpp and "main" in rust
    body = "\n".join(["static int f(int a,", "                int b) {"] + ["    a++;"] * 151 + ["}", ""])
    assert c_functions(body) == [("f", 1, 154)]
    assert rust_functions("fn f() {\n" + "    x();\n" * 151 + "}\n") == [("f", 1, 153)]


def test_no_tool_function_over_150_lines():
    found = _long(C_TOOLS + CPP_TOOLS, c_functions) + _long(RUST_TOOLS, rust_functions)
    assert not found, "functions over 150 lines in the tools:\n" + "\n".join(found)


# A hex digit's value ('a' - 10 arithmetic) or the digits' table, written out again.
_HEX_HELPER = re.compile(r"'[aA]'\s*\+\s*10|-\s*'[aA]'\s*\+\s*10|\"0123456789abcdef\"|\"0123456789ABCDEF\"")


def test_one_hex_helper_in_the_c_runtime():
    runtime = RUNTIMES / "c" / "runtime"
    holders = sorted(
        str(p.relative_to(runtime))
        for p in runtime.rglob("*")
        if p.suffix in (".c", ".h") and p.is_file() and _HEX_HELPER.search(p.read_text(encoding="utf-8"))
    )
    assert holders == ["src/hex.h"], f"hex-digit helpers outside src/hex.h: {holders}"
