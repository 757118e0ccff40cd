"""The Rust runtime (generator/targets/rust/runtime/src/) reaches every crate verbatim, and the
Rust facts cover the spec's primitives."""

import json

from generator.primitives import PRIMITIVES
from generator.render import ROOT, runtime_dir
from generator.targets.rust import backend, facts

SRC = runtime_dir("rust") / "src"


def _crate() -> tuple[str, dict[str, str]]:
    """The files of the first crate, rendered (not formatted) from the committed IR."""
    ir = json.loads((ROOT / "generated" / "ir.json").read_text(encoding="utf-8"))
    ir["protocols"] = ir["protocols"][:1]
    package = ir["protocols"][0]["package"]
    files = backend.render(ir, [])
    root = f"rust/{package}/"
    return package, {k.removeprefix(root): v for k, v in files.items() if k.startswith(root)}


def test_every_runtime_file_is_copied_verbatim() -> None:
    package, crate = _crate()
    checksum = (SRC / "framing_checksum.rs").read_text(encoding="utf-8")
    for path in sorted(SRC.rglob("*.rs")):
        rel = path.relative_to(SRC.parent).as_posix()
        text = path.read_text(encoding="utf-8")
        assert "{{" not in text and "{%" not in text, f"{rel}: runtime files are plain Rust"
        if path.name == "framing_checksum.rs":
            assert crate["src/framing.rs"].endswith("\n\n" + checksum)
        elif rel.startswith("src/bin/"):
            # The tools name the crate they use: the runtime's own crate, renamed.
            dest = rel.replace("protocodec", package)
            assert crate[dest] == text.replace("protocodec", package), rel
        else:
            assert crate[rel] == text, rel


def test_the_runtime_reads_the_protocol_from_framing_only() -> None:
    _, crate = _crate()
    framing = crate["src/framing.rs"]
    for const in ("SYNC", "MAX_PACKET", "BIG_ENDIAN", "PATH_DEPTH", "DATA_SETS", "TIMESTAMPS", "MAX_KEY"):
        assert f"pub const {const}:" in framing, const


def test_every_primitive_has_a_rust_type() -> None:
    assert set(facts.PRIMITIVE_TYPES) == set(PRIMITIVES)


def test_runtime_modules_are_reserved_names() -> None:
    modules = {p.stem for p in SRC.glob("*.rs") if p.stem != "framing_checksum"}
    assert modules <= facts.RESERVED_MODULES
    assert {"framing", "dispatch", "types", "reserved"} <= facts.RESERVED_MODULES


def _manifest_value(text: str, key: str) -> str:
    """The value of `key = ...` in a Cargo.toml (one line)."""
    line = next(line for line in text.splitlines() if line.startswith(f"{key} = "))
    return line.split(" = ", 1)[1]


def test_the_runtime_and_the_crates_share_the_minimum_rust_version() -> None:
    # tools/bootstrap --ci installs the toolchain named in runtime/Cargo.toml; rust.sh msrv tests
    # a generated crate with the version its Cargo.toml states: both must be facts.RUST_VERSION.
    runtime = (runtime_dir("rust") / "Cargo.toml").read_text(encoding="utf-8")
    assert _manifest_value(runtime, "rust-version") == f'"{facts.RUST_VERSION}"'
    _, crate = _crate()
    assert _manifest_value(crate["Cargo.toml"], "rust-version") == f'"{facts.RUST_VERSION}"'


def test_cargo_metadata_is_what_crates_io_accepts() -> None:
    proto = {"name": "mip", "title": 'Micro"Strain\\ MIP'}
    meta = backend.cargo_metadata(proto)
    assert meta["license"] == '"MIT"'
    # The vendor word `micro"strain\` is not a crates.io keyword: left out.
    assert meta["keywords"] == '"mip", "protocol", "codec", "parser"'
    assert meta["description"].startswith('"Micro\\"Strain\\\\ MIP: ')
    # A vendor word crates.io would refuse (a digit first, too long) is left out, and repeats too.
    for title, want in [("3DM thing", ["demo"]), ("Averyveryverylongvendorname X", ["demo"]), ("Demo X", ["demo"])]:
        kw = backend.cargo_metadata({"name": "demo", "title": title})["keywords"]
        assert kw == ", ".join(f'"{w}"' for w in want + facts.KEYWORDS_COMMON)
    cats = backend.cargo_metadata(proto)["categories"]
    assert cats.count('"') == 2 * len(facts.CATEGORIES) <= 10


def test_toml_strings_escape_what_toml_requires() -> None:
    assert backend.toml_str('a"b\\c') == '"a\\"b\\\\c"'
    assert backend.toml_str("tab\there é") == '"tab\\u0009here \\u00E9"'
    assert backend.toml_str("\U0001f600") == '"\\U0001F600"'


def test_the_core_is_no_std_without_alloc() -> None:
    # Without the `std` feature the crate is `#![no_std]` (rust.sh test builds it so, CI for
    # thumbv7em-none-eabihf without an allocator); `alloc` would need `extern crate alloc`.
    _, crate = _crate()
    assert '#![cfg_attr(not(feature = "std"), no_std)]' in crate["src/lib.rs"]
    for path, text in crate.items():
        if path.endswith(".rs"):
            assert "extern crate alloc" not in text, f"{path}: the core must not allocate"
