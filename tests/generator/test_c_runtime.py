"""The C runtime (generator/targets/c/runtime/): plain files copied into each package with the
package's names in place of the neutral codec_/CODEC_/codec-/codec/ tokens, and the generated
protocol.h that is its only protocol input."""

import json
import re
from pathlib import Path

from generator.render import runtime_dir
from generator.targets.c import backend

RUNTIME = runtime_dir("c")
IR = Path(__file__).resolve().parents[2] / "generated" / "ir.json"


def test_every_runtime_source_is_copied():
    """A source file added to the runtime but not to the copy list would compile in place and be
    missing from every package."""
    sources = {
        p.relative_to(RUNTIME).as_posix()
        for d in ("include", "src", "tools")
        for p in (RUNTIME / d).rglob("*")
        if p.is_file()
    }
    assert sources <= set(backend._RUNTIME_FILES)
    for src in backend._RUNTIME_FILES:
        assert (RUNTIME / src).is_file(), src


def test_tokens_occur_only_as_whole_prefixes():
    """The copy replaces plain text: a token (codec_, CODEC_, codec-, codec/) may only start a word,
    or the replacement would change other text (json_codec_x would become json_mip_x)."""
    for src in backend._RUNTIME_FILES:
        text = (RUNTIME / src).read_text(encoding="utf-8")
        for m in re.finditer(r"codec[_/-]|CODEC_", text):
            before = text[m.start() - 1 : m.start()]
            assert not re.match(r"[A-Za-z0-9_]", before), f"{src}: {text[max(0, m.start() - 20) : m.end() + 5]!r}"


def test_replacements_do_not_touch_their_own_output():
    """A package name that contains the token (mipcodec) comes out once, not twice."""
    text = '#include "codec/json.h"\ncodec_parser_t p; CODEC_OK; "codec-decode: %s"'
    for old, new in backend.runtime_replacements("codec2", "mycodec"):
        text = text.replace(old, new)
    assert text == '#include "mycodec/json.h"\ncodec2_parser_t p; CODEC2_OK; "mycodec-decode: %s"'


def _protocol_h(byte_order: str) -> str:
    ir = json.loads(IR.read_text(encoding="utf-8"))
    proto = next(p for p in ir["protocols"] if p["package"] == "mscipcodec")
    proto["byte_order"] = byte_order
    out = backend.render({**ir, "protocols": [proto]}, [])
    return out["c/mscipcodec/include/mscipcodec/protocol.h"]


def test_protocol_header_carries_the_byte_order():
    """byte_order: little reaches the runtime's readers and writers through one constant."""
    assert "#define MSCIPC_LITTLE_ENDIAN 0\n" in _protocol_h("big")
    assert "#define MSCIPC_LITTLE_ENDIAN 1\n" in _protocol_h("little")


def test_prefix_is_not_the_protocol_name():
    """The C prefix is the package name without "codec", plus "c": the vendor SDKs name their C API
    after the protocol (mip_, MIP_), so every macro of a package's headers starts with the package's
    own prefix (tests/consumer checks the same for the library's linker symbols)."""
    assert backend.c_prefix("mipcodec") == "mipc"
    assert backend.c_prefix("mscipcodec") == "mscipc"
    assert backend.c_prefix("democodec") == "democ"
    assert backend.c_prefix("sbp") == "sbpc"
    ir = json.loads(IR.read_text(encoding="utf-8"))
    out = backend.render(ir, [])
    for proto in ir["protocols"]:
        own = backend.c_prefix(proto["package"]).upper() + "_"
        macros = {
            m
            for path, text in out.items()
            if path.startswith(f"c/{proto['package']}/include/")
            for m in re.findall(r"^#\s*define\s+(\w+)", text, re.M)
        }
        assert macros
        assert sorted(m for m in macros if not m.startswith(own)) == []
        assert own != proto["name"].upper() + "_"
