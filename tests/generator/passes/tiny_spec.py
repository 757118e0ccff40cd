"""Tiny specs for the IR pass tests: YAML written here, loaded with positions and checked against
the JSON Schema like a real spec, then run through generator.ir.PASSES up to the pass under test.

`build(tmp_path, files, until="sets")` takes {file name: YAML text} (PROTOCOL is used when no file has
`protocol:`) and returns the Context after that pass; `errors(ctx)` gives the error texts.
"""

from __future__ import annotations

from pathlib import Path

from generator import spec
from generator.ir import PASSES
from generator.passes.context import Context, SpecFile
from generator.yamlpos import load

PROTOCOL = """\
protocol: tiny
title: Tiny protocol
package: tinycodec
byte_order: big
sources: [{manual: a.txt, line: 1}]
devices:
  - {id: dev_a, title: Device A, manual: a.txt}
  - {id: dev_b, title: Device B, manual: b.txt}
framing:
  sync: [0x75, 0x65]
  header: [set, payload_length]
  field_header: [length, descriptor]
  field_length_counts_header: true
  max_payload: 255
  checksum: {algorithm: fletcher16, covers: header_and_payload, order: [sum1, sum2]}
set_kinds:
  command: {first: 0x01, last: 0x7F}
  data: {first: 0x80, last: 0xFF}
"""

PASS_NAMES = [p.__name__.rsplit(".", 1)[1] for p in PASSES]


def build(tmp_path: Path, files: dict[str, str], until: str) -> Context:
    assert until in PASS_NAMES, until
    if not any(text.startswith("protocol:") for text in files.values()):
        files = {"protocol.yaml": PROTOCOL, **files}
    validators = spec._schema_validator()
    pf, set_files, type_files = None, [], []
    for name, text in sorted(files.items()):
        (tmp_path / name).write_text(text)
        data, locate = load(str(tmp_path / name), name)
        sf = SpecFile(name, data, locate)
        shape = spec._validate_shape(validators, sf)
        assert not shape, "the tiny spec itself is malformed: " + "; ".join(map(str, shape))
        if "protocol" in data:
            pf = sf
        elif "set" in data:
            set_files.append(sf)
        else:
            type_files.append(sf)
    ctx = Context(pf, set_files, type_files)
    for step in PASSES[: PASS_NAMES.index(until) + 1]:
        step.run(ctx)
    return ctx


def errors(ctx: Context) -> list[str]:
    return [str(e) for e in ctx.errors]


def command_set(fields: str, extra: str = "", set_id: int = 0x01, name: str = "base") -> str:
    """A command set file holding the given `fields:` items (YAML, indented two spaces)."""
    return (
        f"set: 0x{set_id:02X}\nname: {name}\ntitle: Base\nkind: command\nsources: [{{manual: a.txt, line: 2}}]\n"
        + extra
        + "fields:\n"
        + fields
    )


def data_set(fields: str, extra: str = "", set_id: int = 0x80, name: str = "sensor") -> str:
    return (
        f"set: 0x{set_id:02X}\nname: {name}\ntitle: Sensor\nkind: data\nsources: [{{manual: a.txt, line: 3}}]\n"
        + extra
        + "fields:\n"
        + fields
    )
