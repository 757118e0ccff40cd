"""Bad spec files produce located, readable errors (file:line:column: error: ... (expected ...)).

Each case copies the fixture protocol (fixtures/everything), breaks one thing, and asserts the
message and the line it points at. A few run the command line to check the exit status and that
no traceback is printed.
"""

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from generator.diagnostics import SpecErrors
from generator.spec import load_spec

FIXTURE = Path(__file__).parent / "fixtures" / "everything"
ROOT = Path(__file__).resolve().parents[2]


def _copy(tmp_path: Path) -> Path:
    dst = tmp_path / "spec"
    shutil.copytree(FIXTURE, dst)
    return dst


def _edit(spec: Path, file: str, old: str, new: str) -> None:
    p = spec / "demo" / file
    text = p.read_text()
    assert old in text, f"fixture text not found: {old!r}"
    p.write_text(text.replace(old, new, 1))


def _line_of(spec: Path, file: str, needle: str) -> int:
    for i, line in enumerate((spec / "demo" / file).read_text().splitlines(), 1):
        if needle in line:
            return i
    raise AssertionError(needle)


def _errors(spec: Path) -> list[str]:
    with pytest.raises(SpecErrors) as exc:
        load_spec(spec, root=spec.parent)
    return [str(e) for e in exc.value.errors]


CASES = [
    (
        "ack suppression value not in the enum",
        "commands.yaml",
        "ack_suppressed_by: {param: suppress_ack}",
        "ack_suppressed_by: {param: mode, value: loud}",
        "ack suppression value 'loud' is not a value of parameter mode",
        "ack_suppressed_by",
    ),
    # (id, file, old, new, expected message part, line needle in the edited file)
    (
        "duplicate descriptor",
        "commands.yaml",
        "  - id: 0x03\n    name: per_device",
        "  - id: 0x02\n    name: per_device",
        "descriptor 0x02 is used by both 'configure' and 'per_device'",
        "name: per_device",
    ),
    (
        "enum value too big",
        "commands.yaml",
        "{name: gpio, value: 1}",
        "{name: gpio, value: 256}",
        "enum Mode value gpio = 256 does not fit in u8 (expected 0..255)",
        "value: 256",
    ),
    (
        "enum value clash per device",
        "commands.yaml",
        "{name: quiet, value: 3, devices: [dev_b]}",
        "{name: quiet, value: 3, devices: [dev_a]}",
        "enum Mode value 3 is used by both 'fast' and 'quiet' for the same device",
        "name: quiet",
    ),
    (
        "overlapping bits",
        "commands.yaml",
        "{name: ok, bits: 0}",
        "{name: ok, bits: 0}\n      - {name: low, bits: [0, 3]}",
        "bitfield Flags member low overlaps 'ok' at bit 0",
        "name: low",
    ),
    (
        "bit out of range",
        "commands.yaml",
        "{name: level, bits: [12, 15]}",
        "{name: level, bits: [12, 16]}",
        "bitfield Flags member level: bit 16 is out of range for u16 (expected bits 0..15)",
        "name: level",
    ),
    (
        "count refers to later param",
        "commands.yaml",
        "{name: rates, type: u16, count: count, max_count: 10}",
        "{name: rates, type: u16, count: later, max_count: 10}\n      - {name: later, type: u8}",
        "count of rates refers to 'later', which is a later parameter",
        "count: later",
    ),
    (
        "count refers to missing param",
        "commands.yaml",
        "count: count, max_count: 10",
        "count: nope, max_count: 10",
        "count of rates refers to 'nope', which is not a parameter",
        "count: nope",
    ),
    (
        "count refers to non-integer",
        "commands.yaml",
        "{name: count, type: u8}",
        "{name: count, type: float}",
        "count of rates refers to 'count', which is not a single integer",
        "count: count",
    ),
    (
        "union selector not an enum",
        "commands.yaml",
        "selector: mode, functions: [write]}",
        "selector: instance, functions: [write]}",
        "selector 'instance' of union params is not an enum (it is primitive)",
        "selector: instance",
    ),
    (
        "union selector enum is a bitfield",
        "commands.yaml",
        "selector_enum: Mode",
        "selector_enum: Flags",
        "union TriggerParams: selector type 'Flags' is a bitfield, not an enum (expected the name of an enum)",
        "selector_enum: Flags",
    ),
    (
        "union member not an enum value",
        "commands.yaml",
        "{when: gpio, type: GpioParams}",
        "{when: gpoi, type: GpioParams}",
        "union TriggerParams: 'gpoi' is not a value of enum Mode",
        "when: gpoi",
    ),
    (
        "response does not exist",
        "commands.yaml",
        "{id: 0x82, when: {function: read}}",
        "{id: 0x99, when: {function: read}}",
        "commands.configure: response 0x99 does not exist in set 0x01",
        "id: 0x99",
    ),
    (
        "response is not a response",
        "commands.yaml",
        "{id: 0x82, when: {function: read}}",
        "{id: 0x03, when: {function: read}}",
        "response 0x03 is 'per_device', a command field",
        "id: 0x03, when",
    ),
    (
        "unknown type",
        "commands.yaml",
        "{name: b, type: u64}",
        "{name: b, type: u46}",
        "parameter b: unknown type 'u46'",
        "type: u46",
    ),
    (
        "param for unsupported function",
        "commands.yaml",
        "{name: instance, type: u8, functions: [write, read, save]}",
        "{name: instance, type: u8, functions: [write, read, load]}",
        "parameter instance is marked for function 'load', which the command does not support",
        "functions: [write, read, load]",
    ),
    (
        "required after optional",
        "commands.yaml",
        "{name: suppress_ack, type: bool, functions: [write]}",
        "{name: suppress_ack, type: bool, functions: [write]}\n      - {name: late, type: u8, functions: [write, read, save]}",
        "required parameter late follows optional parameter mode",
        "name: late",
    ),
    (
        "remaining array not last",
        "commands.yaml",
        "{name: tail, type: char, count: remaining}",
        "{name: tail, type: char, count: remaining}\n      - {name: after, type: u8}",
        "parameter tail runs to the end of the field but is not the last parameter",
        "name: tail",
    ),
    (
        "unknown manual",
        "data.yaml",
        "sources: [{manual: demo.txt, line: 51}]",
        "sources: [{manual: dmeo.txt, line: 51}]",
        "unknown manual 'dmeo.txt'",
        "dmeo.txt",
    ),
    (
        "reserved descriptor",
        "commands.yaml",
        "  - id: 0x03\n    name: per_device",
        "  - id: 0x80\n    name: per_device",
        "descriptor 0x80 is reserved for ack",
        "id: 0x80\n",
    ),
    (
        "set outside its kind range",
        "data.yaml",
        "set: 0x90",
        "set: 0x10",
        "data set 0x10 is outside the data range (expected 0x80..0xFF)",
        "set: 0x10",
    ),
    ("schema: missing key", "data.yaml", "    role: data\n", "", "missing required key 'role'", "- id: 0x01"),
    (
        "schema: unknown key",
        "data.yaml",
        "    repeats: true",
        "    repeat: true",
        "Additional properties are not allowed ('repeat' was unexpected)",
        "repeat: true",
    ),
    (
        "schema: bad name",
        "data.yaml",
        "name: sample",
        "name: Sample-1",
        "'Sample-1' is not a valid name",
        "name: Sample-1",
    ),
    (
        "duplicate yaml key",
        "data.yaml",
        "    title: Sample\n",
        "    title: Sample\n    title: Again\n",
        "duplicate key 'title'",
        "title: Again",
    ),
    (
        "unknown field layout",
        "gnss2.yaml",
        "layout: LlhPosition",
        "layout: LlhPositon",
        "receiver_2.llh_position: unknown field layout 'LlhPositon'",
        "layout: LlhPositon",
    ),
    (
        "field with params and layout",
        "gnss2.yaml",
        "    layout: LlhPosition\n",
        "    layout: LlhPosition\n    params: []\n",
        "receiver_2.llh_position: has params and layout (expected exactly one of params",
        "params: []",
    ),
    ("yaml syntax", "data.yaml", "    title: Sample\n", "    title: [Sample\n", "invalid YAML", None),
]


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_bad_spec_is_located(tmp_path, case):
    _id, file, old, new, expected, needle = case
    spec = _copy(tmp_path)
    _edit(spec, file, old, new)
    errors = _errors(spec)
    matching = [e for e in errors if expected in e]
    assert matching, f"no error contains {expected!r}; got:\n" + "\n".join(errors)
    msg = matching[0]
    assert msg.startswith(f"spec/demo/{file}:"), msg
    assert ": error: " in msg
    if needle is not None:
        want = (
            _line_of(spec, file, needle.split("\n")[0])
            if "\n" not in needle
            else _line_of(spec, file, needle.split("\n")[0]) + 0
        )
        line = int(msg.split(":")[1])
        assert abs(line - want) <= 1, f"error points at line {line}, expected about {want}: {msg}"


def test_fixture_itself_is_valid():
    load_spec(FIXTURE, root=FIXTURE)


def _run_cli(spec: Path) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "generator", "--spec", str(spec), "--validate-only"],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )


def test_cli_reports_several_errors_without_traceback(tmp_path):
    spec = _copy(tmp_path)
    _edit(spec, "commands.yaml", "{name: gpio, value: 1}", "{name: gpio, value: 256}")
    _edit(spec, "commands.yaml", "{name: b, type: u64}", "{name: b, type: u46}")
    proc = _run_cli(spec)
    assert proc.returncode == 1
    assert "Traceback" not in proc.stderr
    assert "does not fit in u8" in proc.stderr and "unknown type 'u46'" in proc.stderr
    assert "2 error(s) in the spec; nothing was generated." in proc.stderr


def test_cli_accepts_good_spec(tmp_path):
    proc = _run_cli(_copy(tmp_path))
    assert proc.returncode == 0, proc.stderr


def test_project_spec_is_valid():
    ir = load_spec()
    assert [p["name"] for p in ir["protocols"]] == ["mip", "mscip"]


def _add_part(spec: Path, name: str, set_name: str = "commands", descriptor: int = 0x70) -> None:
    (spec / "demo" / "commands_part.yaml").write_text(
        f"set: 0x01\nname: {set_name}\ntitle: More commands\nkind: command\n"
        "sources: [{manual: demo.txt, line: 99}]\n"
        "fields:\n"
        f"  - id: 0x{descriptor:02X}\n    name: {name}\n    role: command\n    title: Extra\n"
        "    sources: [{manual: demo.txt, line: 100}]\n    params: [{name: x, type: u8}]\n"
    )


def test_set_split_over_files_is_merged(tmp_path):
    spec = _copy(tmp_path)
    _add_part(spec, "extra")
    ir = load_spec(spec, root=spec.parent)
    (s,) = [s for s in ir["protocols"][0]["sets"] if s["id"] == 0x01]
    names = [f["name"] for f in s["fields"]]
    assert names[-1] == "extra" and names.count("extra") == 1 and len(names) > 1
    assert [src["line"] for src in s["sources"]] == [10, 99]


def test_set_parts_must_agree_on_name(tmp_path):
    spec = _copy(tmp_path)
    _add_part(spec, "extra", set_name="commandz")
    errs = _errors(spec)
    assert any("commands_part.yaml:2:" in e and "has name 'commandz' here but 'commands'" in e for e in errs), errs


def test_descriptor_clash_across_parts_is_located(tmp_path):
    spec = _copy(tmp_path)
    _add_part(spec, "extra", descriptor=0x02)
    errs = _errors(spec)
    assert any("commands_part.yaml:7:" in e and "descriptor 0x02 is used by both" in e for e in errs), errs
