"""The C++ runtime's copy into a package (generator/targets/cpp/backend.py, runtime/README.md): the
files it names exist and are plain source, and the placeholder package "protopkg" becomes the
package's file names and namespace everywhere, also when the two differ (a C++ keyword)."""

from __future__ import annotations

import re

from generator.render import copy_runtime, runtime_dir
from generator.targets.cpp.backend import ident, runtime_files, runtime_names


def copied(pkg: str) -> dict[str, str]:
    return copy_runtime("cpp", runtime_files(pkg), runtime_names(pkg, ident(pkg)))


def test_runtime_files_exist_and_are_plain_source() -> None:
    for src in runtime_files("mipcodec"):
        text = (runtime_dir("cpp") / src).read_text(encoding="utf-8")
        assert not re.search(r"\{[{%#]", text), f"{src} holds template syntax"
        assert "protopkg" in text, f"{src} does not name its package"


def test_the_placeholder_becomes_the_package() -> None:
    files = copied("mipcodec")
    assert "include/mipcodec/wire.hpp" in files and "tools/decode.cpp" in files
    for dest, text in files.items():
        assert "protopkg" not in text.lower(), dest
    assert "namespace mipcodec {" in files["include/mipcodec/wire.hpp"]
    assert "#define MIPCODEC_INLINE" in files["include/mipcodec/wire.hpp"]
    assert '#include "mipcodec/json_lines.hpp"' in files["tools/decode.cpp"]
    assert '"usage: mipcodec-decode' in files["tools/decode.cpp"]
    assert '#include "mipcodec/mipcodec.hpp"' in files["tests/test_support.hpp"]


def test_a_keyword_package_keeps_its_file_names_and_gets_a_namespace() -> None:
    files = copied("int")
    wire = files["include/int/wire.hpp"]
    assert "namespace int_ {" in wire and "#define INT__INLINE" in wire
    assert '#include "int/framing.hpp"' in wire
    assert '#include "int/int.hpp"' in files["tests/test_support.hpp"]
    assert '"usage: int-decode' in files["tools/decode.cpp"]
    assert "int_::JsonLinesDecoder" in files["tools/decode.cpp"]
    assert "namespace int_::tool_io {" in files["tools/tool_io.hpp"]
