"""The generated names of every target (issue 37, generator/name_check.py): two spec entries that
become one identifier in one scope of a target's code, after its case conversion and escaping,
are one located error naming both places; an identifier still reserved after escaping is an
error at its entry; C and C++ escape the library's and compilers' macros (errno, linux, ...).

The spec cases are added to the every-feature fixture's data set (tests/generator/fixtures/
everything/demo/data.yaml): the expected locations are the lines of the text added here (the
fixture's file ends at DATA_LINES lines, each case's first line follows), and the expected
identifiers come from the naming rules of docs/spec-format.md "Names in the generated code", not
from the back ends."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from generator.diagnostics import Location
from generator.name_check import Name, check
from generator.pipeline import _locator
from generator.spec import load_spec
from generator.targets import NAMES, TARGETS

ROOT = Path(__file__).resolve().parents[2]
FIXTURE = ROOT / "tests" / "generator" / "fixtures" / "everything"
DATA = FIXTURE / "demo" / "data.yaml"
DATA_LINES = len(DATA.read_text(encoding="utf-8").splitlines())


def _field(descriptor: int, name: str, *params: str, role: str = "data") -> str:
    """A field's YAML; its `name:` value is on its 2nd line, parameter i's on line 7 + i."""
    lines = [
        f"  - id: 0x{descriptor:02X}",
        f"    name: {name}",
        f"    role: {role}",
        f"    title: {name}",
        "    sources: [{manual: demo.txt, line: 50}]",
        "    params:",
    ]
    lines += [f"      - {{name: {p}, type: u8}}" for p in params]
    return "".join(line + "\n" for line in lines)


def _spec(tmp_path: Path, *fields: str, file: str = "data.yaml") -> Path:
    spec = tmp_path / "spec"
    shutil.copytree(FIXTURE, spec)
    with open(spec / "demo" / file, "a", encoding="utf-8") as fh:
        fh.write("".join(fields))
    return spec


def _errors(spec: Path, lang: str) -> list[str]:
    """The name check's errors for one target, as printed (paths relative to spec's parent)."""
    ir = load_spec(spec, root=spec.parent)
    mod = TARGETS[lang]
    out: list[str] = []
    for proto in ir["protocols"]:
        locate, _rank = _locator(proto["name"], spec, spec.parent, [])
        out += [str(e) for e in check(mod.TITLE, mod.names(proto), mod.reserved, locate)]
    return out


def _names(spec: Path, lang: str) -> list[Name]:
    ir = load_spec(spec, root=spec.parent)
    return [n for p in ir["protocols"] for n in TARGETS[lang].names(p)]


# The fixture's own lines of the added text: field k (0-based, each _field of 2 params is 8 lines)
def _line(field_index: int, param: int | None = None, params_per_field: int = 2) -> int:
    start = DATA_LINES + 1 + field_index * (6 + params_per_field)
    return start + 1 if param is None else start + 6 + param


# ---------------------------------------------------------------------- the pass on its own
def test_check_reports_a_collision_once_at_the_later_entry_naming_the_first():
    locs = {("a",): Location("f.yaml", 3, 5), ("b",): Location("f.yaml", 9, 5), ("c",): Location("g.yaml", 1, 1)}
    names = [
        Name("scope S", "x_", "entry b", ("b",)),
        Name("scope S", "x_", "entry a", ("a",)),
        Name("scope S", "x_", "entry a", ("a",)),  # the same entry again: no collision with itself
        Name("scope T", "x_", "entry c", ("c",)),  # another scope
    ]
    errors = check("L", names, lambda i: None, locs.__getitem__)
    assert [str(e) for e in errors] == [
        "f.yaml:9:5: error: L: entry b and entry a would both be named x_ in scope S (the first at f.yaml:3:5)"
        " (expected names that stay distinct in L after case conversion and escaping)"
    ]


def test_check_compares_members_only_within_their_owner():
    loc = lambda where: Location("f.yaml", len(where), 1)  # noqa: E731
    names = [
        Name("struct S", "x", "parameter x of a", ("a", "x"), owner="a"),
        Name("struct S", "x", "parameter x of b", ("b", "x"), owner="b"),
    ]
    assert check("L", names, lambda i: None, loc) == []


def test_check_reports_names_taken_by_the_generated_code_and_reserved_leftovers():
    loc = lambda where: Location("f.yaml", 7, 2)  # noqa: E731
    names = [
        Name("class K", "raw", "the runtime's member raw"),  # generated: no where
        Name("class K", "raw", "member raw of K", ("K", "raw")),
        Name("module M", "None", "type None", ("None",)),
        Name("module M", "Fine", "type Fine", ("Fine",)),
        Name("module P", "None", "a prefixed name", ("P",), checked=False),
    ]
    errors = [str(e) for e in check("L", names, lambda i: "is a keyword" if i == "None" else None, loc)]
    assert errors[0].startswith(
        "f.yaml:7:2: error: L: type None would be named None in module M, which is a keyword (expected"
    )
    assert errors[1].startswith(
        "f.yaml:7:2: error: L: member raw of K would be named raw in class K, which is the runtime's member raw"
    )
    assert len(errors) == 2


# ---------------------------------------------------------------------- every target, the cases
ESCAPE_COLLISION = {  # a keyword of the language and its escaped spelling, both as parameters
    "c": ("class", "class_", "struct democ_data_klass_t"),
    "cpp": ("class", "class_", "struct democodec::data::Klass"),
    "python": ("class", "class_", "class democodec.data.Klass"),
    "rust": ("self", "self_", "struct democodec::data::Klass"),
}


@pytest.mark.parametrize("lang", NAMES)
def test_a_keyword_and_its_escaped_spelling_are_one_error_naming_both(tmp_path, lang):
    kw, escaped, scope = ESCAPE_COLLISION[lang]
    spec = _spec(tmp_path, _field(0x30, "klass", kw, escaped))
    (err,) = _errors(spec, lang)
    first, second = _line(0, 0), _line(0, 1)
    assert err == (
        f"spec/demo/data.yaml:{second}:16: error: {TARGETS[lang].TITLE}: parameter {escaped} of field data.klass"
        f" and parameter {kw} of field data.klass would both be named {escaped} in {scope}"
        f" (the first at spec/demo/data.yaml:{first}:16)"
        f" (expected names that stay distinct in {TARGETS[lang].TITLE} after case conversion and escaping)"
    )


CASE_SCOPE = {"cpp": "namespace democodec::data", "python": "module democodec.data", "rust": "module democodec::data"}


@pytest.mark.parametrize("lang", NAMES)
def test_two_fields_with_one_camel_case_name(tmp_path, lang):
    spec = _spec(tmp_path, _field(0x32, "abc_def", "x", "y"), _field(0x33, "abc__def", "x", "y"))
    errors = _errors(spec, lang)
    if lang == "c":
        # C names a field's type in snake case with the spec's name: democ_data_abc_def_t and
        # democ_data_abc__def_t stay apart.
        assert errors == []
        idents = {n.ident for n in _names(spec, "c") if n.element == "field data.abc__def"}
        assert "democ_data_abc__def_t" in idents
        return
    # One error (the two structs' members x and y are not compared with each other).
    (err,) = errors
    assert err.startswith(
        f"spec/demo/data.yaml:{_line(1)}:11: error: {TARGETS[lang].TITLE}: field data.abc__def and field"
        f" data.abc_def would both be named AbcDef in {CASE_SCOPE[lang]}"
        f" (the first at spec/demo/data.yaml:{_line(0)}:11)"
    ), err


def test_c_types_that_differ_only_in_case(tmp_path):
    spec = tmp_path / "spec"
    shutil.copytree(FIXTURE, spec)
    commands = spec / "demo" / "commands.yaml"
    text = commands.read_text(encoding="utf-8")
    added = "".join(
        f"  - name: {n}\n    type: u8\n    values: [{{name: v_{i}, value: 0}}]\n"
        for i, n in enumerate(["GpsMode", "GPSMode"])
    )
    commands.write_text(text.replace("\nenums:\n", "\nenums:\n" + added, 1), encoding="utf-8")
    enums_line = text.splitlines().index("enums:") + 1
    errors = _errors(spec, "c")
    assert errors == [
        f"spec/demo/commands.yaml:{enums_line + 4}:11: error: C: type GPSMode and type GpsMode would both be"
        f" named democ_gps_mode_t in the C file scope of democodec (the first at"
        f" spec/demo/commands.yaml:{enums_line + 1}:11)"
        " (expected names that stay distinct in C after case conversion and escaping)"
    ]
    for lang in ("cpp", "python", "rust"):
        assert _errors(spec, lang) == []


# errno is a macro of <errno.h>; linux and unix are predefined by gcc/g++ in their default GNU
# modes (`gcc -dM -E - </dev/null`), so a member with such a name breaks any C or C++ program.
LIBC = {
    "c": "errno_ linux_ unix_",
    "cpp": "errno_ linux_ unix_",
    "python": "errno linux unix",
    "rust": "errno linux unix",
}


@pytest.mark.parametrize("lang", NAMES)
def test_library_and_compiler_macros_are_escaped_in_c_and_cpp(tmp_path, lang):
    spec = _spec(tmp_path, _field(0x31, "libc", "errno", "linux", "unix"))
    assert _errors(spec, lang) == []
    members = [
        n.ident
        for n in _names(spec, lang)
        if n.element.startswith("parameter") and n.element.endswith("of field data.libc")
    ]
    assert members == LIBC[lang].split()


@pytest.mark.parametrize("lang", ["c", "cpp"])
def test_a_macro_and_its_escaped_spelling_collide_in_c_and_cpp(tmp_path, lang):
    spec = _spec(tmp_path, _field(0x31, "libc", "errno", "errno_"))
    (err,) = _errors(spec, lang)
    assert err.startswith(
        f"spec/demo/data.yaml:{_line(0, 1)}:16: error: {TARGETS[lang].TITLE}: parameter errno_ of field data.libc"
        f" and parameter errno of field data.libc would both be named errno_ in"
    ), err
    assert f"(the first at spec/demo/data.yaml:{_line(0, 0)}:16)" in err


LEFTOVERS = {  # a spec name the target does not escape, that stays reserved
    "cpp": ("enums", "EOF", "is a C++ keyword or a name of the standard library"),
    "python": ("enums", "None", "is a Python keyword"),
    "rust": ("field", "self", "is a Rust keyword"),
}


@pytest.mark.parametrize("lang", sorted(LEFTOVERS))
def test_a_name_left_reserved_after_escaping_is_an_error(tmp_path, lang):
    kind, name, why = LEFTOVERS[lang]
    if kind == "field":
        spec = _spec(tmp_path, _field(0x34, name, "x", "y"))
        where, ident, element = f"spec/demo/data.yaml:{_line(0)}:11", "Self", f"field data.{name}"
    else:
        spec = tmp_path / "spec"
        shutil.copytree(FIXTURE, spec)
        commands = spec / "demo" / "commands.yaml"
        text = commands.read_text(encoding="utf-8")
        commands.write_text(
            text.replace(
                "\nenums:\n", f"\nenums:\n  - name: {name}\n    type: u8\n    values: [{{name: a, value: 0}}]\n"
            ),
            encoding="utf-8",
        )
        line = text.splitlines().index("enums:") + 2
        where, ident, element = f"spec/demo/commands.yaml:{line}:11", name, f"type {name}"
    errors = _errors(spec, lang)
    assert any(
        e.startswith(f"{where}: error: {TARGETS[lang].TITLE}: {element} would be named {ident} in ") and why in e
        for e in errors
    ), errors


def test_cpp_refuses_a_double_underscore_member(tmp_path):
    spec = _spec(tmp_path, _field(0x30, "klass", "abc__def", "y"))
    (err,) = _errors(spec, "cpp")
    assert err.startswith(f"spec/demo/data.yaml:{_line(0, 0)}:16: error: C++: parameter abc__def of field data.klass")
    assert "contains a double underscore" in err
    for lang in ("c", "python", "rust"):
        assert _errors(spec, lang) == []


# A typed command function's own parameter names (the link, the connection, the options, the
# device) or an escaped argument beside the same spelling: the command API's generated signatures.
COMMAND_ARGS = {
    "c": (("link", "link_"), "link_", "the parameters of democ_commands_poke", None),
    "cpp": (
        ("options", "x"),
        "options",
        "function democodec::api::commands::poke::call",
        "a parameter or variable of the function, options",
    ),
    "python": (
        ("timeout_ms", "x"),
        "timeout_ms",
        "method Poke.__call__",
        "a parameter or variable of the method, timeout_ms",
    ),
    "rust": (("device", "x"), "device", "fn send_poke_poke", "the function's parameter device"),
}


@pytest.mark.parametrize("lang", NAMES)
def test_command_arguments_that_the_typed_api_cannot_declare(tmp_path, lang):
    params, ident, scope, generated = COMMAND_ARGS[lang]
    spec = _spec(tmp_path, _field(0x10, "poke", *params, role="command"), file="commands.yaml")
    start = len((FIXTURE / "demo" / "commands.yaml").read_text(encoding="utf-8").splitlines()) + 1
    (err,) = _errors(spec, lang)
    title = TARGETS[lang].TITLE
    if generated is None:  # two arguments: one names the other's place
        assert err.startswith(
            f"spec/demo/commands.yaml:{start + 7}:16: error: {title}: parameter link_ of the command function of"
            f" field commands.poke and parameter link of the command function of field commands.poke would both be"
            f" named link_ in {scope} (the first at spec/demo/commands.yaml:{start + 6}:16)"
        ), err
    else:
        assert err.startswith(f"spec/demo/commands.yaml:{start + 6}:16: error: {title}: parameter {params[0]} of"), err
        assert f"would be named {ident} in {scope}, which is {generated} (expected" in err, err


# ---------------------------------------------------------------------- the project's spec, the tool
def test_the_project_spec_has_no_name_problem_in_any_target():
    ir = load_spec()
    for lang in NAMES:
        mod = TARGETS[lang]
        for proto in ir["protocols"]:
            names = mod.names(proto)
            assert len(names) > 200  # the check sees the spec's names, not an empty list
            errors = check(mod.TITLE, names, mod.reserved, lambda w: Location("spec", 1, 1))
            assert errors == [], (lang, [str(e) for e in errors[:5]])


def _generate(spec: Path, out: Path, langs: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "generator", "generate", "--spec", str(spec), "--out", str(out), "--langs", langs],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=300,
    )


@pytest.mark.parametrize("lang", NAMES)
def test_mipgen_generate_exits_1_and_writes_nothing(tmp_path, lang):
    kw, escaped, _scope = ESCAPE_COLLISION[lang]
    spec = _spec(
        tmp_path,
        _field(0x30, "klass", kw, escaped),
        _field(0x32, "abc_def", "x", "y"),
        _field(0x33, "abc__def", "x", "y"),
    )
    out = tmp_path / "out"
    r = _generate(spec, out, lang)
    assert r.returncode == 1, r.stderr
    assert "Traceback" not in r.stderr
    lines = r.stderr.splitlines()
    expected = 1 if lang == "c" else 2  # C keeps abc_def and abc__def apart
    if expected == 1:
        assert len(lines) == 1
    else:
        assert len(lines) == expected + 1 and lines[-1] == f"{expected} error(s) in the spec; nothing was generated."
    assert all(re.match(r"spec/demo/data\.yaml:\d+:\d+: error: ", x) for x in lines[:expected]), lines
    assert not out.exists()


@pytest.mark.skipif(not (shutil.which("gcc") and shutil.which("g++")), reason="needs gcc and g++")
def test_a_program_using_errno_and_linux_members_compiles_in_gnu_modes(tmp_path):
    # A user's program includes <errno.h> and the package's header and is compiled in the
    # compilers' default GNU modes, where `linux` and `unix` are predefined macros: the members
    # must not be spelled errno, linux or unix (on today's main the C struct has `uint8_t errno;`
    # and the C++ one `std::uint8_t linux{};`, and neither compiles).
    spec = _spec(tmp_path, _field(0x31, "libc", "errno", "linux", "unix"))
    out = tmp_path / "out"
    r = _generate(spec, out, "c,cpp")
    assert r.returncode == 0, r.stderr
    c_src = tmp_path / "use.c"
    c_src.write_text(
        "#include <errno.h>\n#include <stdio.h>\n#include <democodec/democodec.h>\n"
        "int main(void) { democ_data_libc_t v = {0}; return v.errno_ + v.linux_ + v.unix_ + errno; }\n"
    )
    cpp_src = tmp_path / "use.cpp"
    cpp_src.write_text(
        "#include <cerrno>\n#include <democodec/democodec.hpp>\n"
        "int main() { democodec::data::Libc v{}; return v.errno_ + v.linux_ + v.unix_ + errno; }\n"
    )
    for cmd in (
        ["gcc", "-std=gnu11", "-fsyntax-only", "-I", str(out / "c" / "democodec" / "include"), str(c_src)],
        ["g++", "-std=gnu++17", "-fsyntax-only", "-I", str(out / "cpp" / "democodec" / "include"), str(cpp_src)],
    ):
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stderr[-3000:]


def test_an_overlay_entry_colliding_with_the_spec_is_the_error_naming_the_spec_entry(tmp_path):
    # An overlay (docs/spec-format.md "Overlays") adds sensor field scaled__accel beside the
    # spec's scaled_accel: C++, Python and Rust name both ScaledAccel. The error is at the
    # overlay's entry, the spec's is "the first" (the spec is read before its overlays).
    overlay = tmp_path / "overlay"
    shutil.copytree(ROOT / "tests" / "generator" / "fixtures" / "overlay", overlay)
    f = overlay / "mip" / "sensor_gq9.yaml"
    text = f.read_text(encoding="utf-8")
    f.write_text(text.replace("    name: board_temperature\n", "    name: scaled__accel\n"), encoding="utf-8")
    line = text.splitlines().index("    name: board_temperature") + 1
    spec_line = (ROOT / "spec" / "mip" / "sensor.yaml").read_text(encoding="utf-8").splitlines().index(
        "    name: scaled_accel"
    ) + 1
    ir = load_spec(overlays=[overlay])
    mip = next(p for p in ir["protocols"] if p["name"] == "mip")
    locate, rank = _locator("mip", None, ROOT, [overlay])
    for lang in NAMES:
        mod = TARGETS[lang]
        errors = [str(e) for e in check(mod.TITLE, mod.names(mip), mod.reserved, locate, rank)]
        if lang == "c":
            assert errors == []  # mipc_sensor_scaled__accel_t
            continue
        assert errors[0].startswith(
            f"overlay/mip/sensor_gq9.yaml:{line}:11: error: {mod.TITLE}: field sensor.scaled__accel and field"
            f" sensor.scaled_accel would both be named ScaledAccel in "
        ), errors
        assert f"(the first at spec/mip/sensor.yaml:{spec_line}:11)" in errors[0]
