"""docs/packaging.md names every C library function the freestanding C core calls (issue 39 item 8).

The core's sources (the `<pkg>_c` library of each generated C package's CMakeLists.txt) are
compiled with the host compiler at -O0 with -fno-builtin (so that no call is folded away) and
-DNDEBUG (the doc names `assert` separately); the symbols they leave undefined, minus what the core
defines itself, the x86 CPU check and the linker's own, must be exactly the list the doc states.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOC = ROOT / "docs" / "packaging.md"
CC = shutil.which("cc") or shutil.which("gcc") or "cc"
NOT_LIBC = {"_GLOBAL_OFFSET_TABLE_", "__cpu_model", "__cpu_indicator_init"}


def _documented() -> set[str]:
    text = DOC.read_text(encoding="utf-8")
    m = re.search(r"The C core needs only (.*?) from the C library", text, re.S)
    assert m, "docs/packaging.md: the sentence 'The C core needs only ... from the C library' is gone"
    return set(re.findall(r"`(\w+)`", m.group(1)))


def _core_sources(package: Path) -> list[str]:
    text = (package / "CMakeLists.txt").read_text()
    m = re.search(r"add_library\(\w+_c STATIC[^\n]*\n(.*?)\)", text, re.S)
    assert m, f"{package}: no core library in CMakeLists.txt"
    return m.group(1).split()


def _undefined(package: Path, tmp: Path) -> set[str]:
    objects = []
    for i, source in enumerate(_core_sources(package)):
        obj = tmp / f"{i}.o"
        cmd = [CC, "-c", "-O0", "-fno-builtin", "-fno-stack-protector", "-DNDEBUG", "-std=c99"]
        subprocess.run([*cmd, "-Iinclude", "-Isrc", source, "-o", str(obj)], cwd=package, check=True)
        objects.append(str(obj))
    undefined = subprocess.run(["nm", "-u", *objects], capture_output=True, text=True, check=True).stdout
    defined = subprocess.run(["nm", "--defined-only", *objects], capture_output=True, text=True, check=True).stdout
    needed = {line.split()[-1] for line in undefined.splitlines() if line.strip() and not line.endswith(":")}
    own = {line.split()[-1] for line in defined.splitlines() if len(line.split()) == 3}
    return needed - own - NOT_LIBC


@pytest.mark.parametrize("package", sorted(p.name for p in (ROOT / "generated" / "c").iterdir() if p.is_dir()))
def test_the_doc_lists_exactly_the_c_library_functions_the_core_calls(package, tmp_path):
    assert _undefined(ROOT / "generated" / "c" / package, tmp_path) == _documented()
