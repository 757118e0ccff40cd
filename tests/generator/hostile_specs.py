"""The hostile spec corpus (issue 28): spec files a user, an overlay or a vendor update could hand
the generator, each placed into a copy of spec/mscip/ (the smaller protocol). Every one must be
refused with exit status 1 and `file:line:column: error:` lines only, quickly and in bounded memory
(tests/generator/test_hostile_specs.py); tests/fuzz/spec_loader.py starts from the same files.

`corpus()` maps a case name to (file name in the protocol directory, the file's bytes). A file
named like a real one replaces it; any other is added beside them.
"""

from __future__ import annotations

import random
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SPEC = ROOT / "spec" / "mscip"

# A set file beside the real ones: message type 0xA3, one data field whose params are given.
_SET = """\
set: 0xA3
name: hostile
title: Hostile
kind: data
sources: [{{manual: ms-cip-doc00419-revM.txt, line: 1}}]
{extra}fields:
  - id: 0x01
    name: f
    role: data
    title: F
    sources: [{{manual: ms-cip-doc00419-revM.txt, line: 2}}]
    params: {params}
"""


def _set(params: str, extra: str = "") -> bytes:
    return _SET.format(params=params, extra=extra).encode()


def _real(name: str) -> str:
    return (SPEC / name).read_text(encoding="utf-8")


def _replace(name: str, old: str, new: str) -> tuple[str, bytes]:
    text = _real(name)
    assert old in text, (name, old)
    return name, text.replace(old, new, 1).encode()


def _bomb(levels: int = 9, fan: int = 9) -> str:
    lines = ['l0: &l0 ["x", "x", "x", "x", "x", "x", "x", "x", "x"]']
    for i in range(1, levels):
        lines.append(f"l{i}: &l{i} [" + ", ".join([f"*l{i - 1}"] * fan) + "]")
    return "\n".join(lines) + "\n"


def _struct_chain(n: int) -> str:
    """n structs, each holding the next: type references n deep."""
    out = ["structs:"]
    for i in range(n):
        inner = f"S{i + 1}" if i + 1 < n else "u8"
        out.append(f"  - {{name: S{i}, title: S, params: [{{name: x, type: {inner}}}]}}")
    return "\n".join(out) + "\n"


def corpus() -> dict[str, tuple[str, bytes]]:
    rnd = random.Random(28)
    junk = bytes(rnd.randrange(256) for _ in range(4096))
    return {
        # The reader: bytes that are not a YAML document of a spec file.
        "empty": ("protocol.yaml", b""),
        "only_comments": ("protocol.yaml", b"# nothing here\n# at all\n"),
        "only_document_marker": ("protocol.yaml", b"---\n...\n"),
        "null_document": ("protocol.yaml", b"null\n"),
        "scalar_document": ("protocol.yaml", b"42\n"),
        "list_document": ("protocol.yaml", b"- protocol: mscip\n"),
        "binary_junk": ("protocol.yaml", junk),
        "nul_bytes": ("protocol.yaml", b"protocol: ms\x00cip\n"),
        "not_utf8": ("protocol.yaml", b'protocol: mscip\ntitle: "\xff\xfe"\n'),
        "utf16_bom": ("protocol.yaml", "protocol: mscip\n".encode("utf-16")),
        "unclosed_flow": ("protocol.yaml", b"protocol: [mscip\n"),
        "tab_indent": ("protocol.yaml", b"protocol: mscip\nframing:\n\tsync: [1]\n"),
        "python_tag": ("protocol.yaml", b"protocol: !!python/object/apply:os.system [echo hi]\n"),
        "unknown_tag": ("protocol.yaml", b"protocol: !mytag mscip\n"),
        "complex_key": ("protocol.yaml", b"? [a, b]\n: 1\nprotocol: mscip\n"),
        "duplicate_key": (
            "protocol.yaml",
            _real("protocol.yaml").replace("title:", "protocol: again\ntitle:", 1).encode(),
        ),
        "undefined_alias": ("protocol.yaml", b"protocol: *nowhere\n"),
        # The limits: size, nesting, values, aliases.
        "huge_file": ("protocol.yaml", b"protocol: mscip\n" + b"# padding padding padding padding\n" * 200_000),
        "huge_scalar": ("protocol.yaml", b"protocol: mscip\ntitle: " + b"x" * 6_000_000 + b"\n"),
        "deep_flow": ("protocol.yaml", b"x: " + b"[" * 5000 + b"]" * 5000 + b"\n"),
        "deep_block": ("protocol.yaml", "".join("  " * i + f"k{i}:\n" for i in range(300)).encode()),
        "many_values": ("protocol.yaml", b"protocol: mscip\nxs: [" + b"1," * 250_000 + b"1]\n"),
        "alias_bomb": ("protocol.yaml", _bomb().encode()),
        "alias_wide": ("protocol.yaml", (b"a: &a [" + b"x," * 5000 + b"x]\nb: [" + b"*a," * 100 + b"*a]\n")),
        # The schema: right YAML, wrong types and values.
        "set_id_string": _replace("imu_data.yaml", "set: 0xA2", 'set: "0xA2"'),
        "set_id_huge": _replace("imu_data.yaml", "set: 0xA2", "set: 0x" + "F" * 40),
        "set_id_nan": _replace("imu_data.yaml", "set: 0xA2", "set: .nan"),
        "set_id_inf": _replace("imu_data.yaml", "set: 0xA2", "set: -.inf"),
        "set_id_float": _replace("imu_data.yaml", "set: 0xA2", "set: 162.5"),
        "set_id_bool": _replace("imu_data.yaml", "set: 0xA2", "set: true"),
        "set_id_date": _replace("imu_data.yaml", "set: 0xA2", "set: 2026-11-25"),
        "field_id_huge": _replace("imu_data.yaml", "- id: 0x81", "- id: " + "9" * 400),
        "fields_a_string": _replace("imu_data.yaml", "fields:\n", "fields: nope\nx_fields:\n"),
        "params_a_mapping": _replace(
            "imu_data.yaml",
            "    params:\n      - {name: accel",
            "    params: {a: 1}\n    x_params:\n      - {name: accel",
        ),
        "name_a_list": _replace("imu_data.yaml", "name: imu_data", "name: [imu, data]"),
        "framing_null": _replace("protocol.yaml", "  sync: [0xA5, 0xA5]", "  sync: ~"),
        "max_payload_huge": _replace("protocol.yaml", "max_payload: 255", "max_payload: 1e400"),
        "max_payload_nan": _replace("protocol.yaml", "max_payload: 255", "max_payload: .nan"),
        "sources_line_negative": _replace("imu_data.yaml", "line: 1227", "line: -99999999999999999999999"),
        "int_keys": _replace("imu_data.yaml", "name: imu_data", "name: imu_data\n12: twelve\n.nan: x\nnull: y"),
        "enum_value_huge": (
            "zz_hostile.yaml",
            _set(
                "[{name: e, type: E}]",
                "enums:\n  - {name: E, type: u8, title: E, values: [{name: a, value: 99999999999999999999999999999999}]}\n",
            ),
        ),
        "bits_huge": (
            "zz_hostile.yaml",
            _set(
                "[{name: b, type: B}]",
                "bitfields:\n  - {name: B, type: u8, title: B, members: [{name: a, bits: [0, 99999999999999999999]}]}\n",
            ),
        ),
        # The meaning: types that refer in circles or very deep, counts no field can hold.
        "struct_self_cycle": (
            "zz_hostile.yaml",
            _set("[{name: a, type: A}]", "structs:\n  - {name: A, title: A, params: [{name: a, type: A}]}\n"),
        ),
        "struct_cycle": (
            "zz_hostile.yaml",
            _set(
                "[{name: a, type: A}]",
                "structs:\n  - {name: A, title: A, params: [{name: b, type: B}]}\n"
                "  - {name: B, title: B, params: [{name: c, type: C}]}\n"
                "  - {name: C, title: C, params: [{name: a, type: A, count: 2}]}\n",
            ),
        ),
        "struct_chain_deep": ("zz_hostile.yaml", _set("[{name: a, type: S0}]", _struct_chain(1000))),
        "count_huge": ("zz_hostile.yaml", _set("[{name: a, type: u8, count: 99999999999999999999999999}]")),
        "count_negative": ("zz_hostile.yaml", _set("[{name: a, type: u8, count: -5}]")),
        "count_nan": ("zz_hostile.yaml", _set("[{name: a, type: u8, count: .nan}]")),
        "count_self": ("zz_hostile.yaml", _set("[{name: a, type: u8, count: a}]")),
        "max_count_huge": (
            "zz_hostile.yaml",
            _set("[{name: n, type: u32}, {name: a, type: double, count: n, max_count: 4294967296}]"),
        ),
        "nested_counts": (
            "zz_hostile.yaml",
            _set(
                "[{name: a, type: S0, count: 1000000}]",
                "structs:\n"
                + "".join(
                    f"  - {{name: S{i}, title: S, params: [{{name: x, type: {f'S{i + 1}' if i < 29 else 'double'}, count: 1000000}}]}}\n"
                    for i in range(30)
                ),
            ),
        ),
        "string_huge": ("zz_hostile.yaml", _set("[{name: s, type: string, length: 100000000000}]")),
        "u8_300": ("zz_hostile.yaml", _set("[{name: a, type: u8, count: 300}]")),
        "char_300": ("zz_hostile.yaml", _set("[{name: s, type: string, length: 300}]")),
        "four_matrices": (
            "zz_hostile.yaml",
            _set("[" + ", ".join(f"{{name: m{i}, type: matrix3d}}" for i in range(4)) + "]"),
        ),
        "unknown_type_everywhere": ("zz_hostile.yaml", _set("[{name: a, type: nope}, {name: b, type: [u8]}]")),
    }


def run_all(work: Path, names: list[str] | None = None) -> dict[str, dict]:
    """Each case through the generator's command line (`main`, in this process), in its own copy
    of spec/mscip/ under work: exit status, stderr lines and seconds per case."""
    import contextlib
    import io
    import shutil
    import time

    from generator.__main__ import main

    results = {}
    for name, (file, data) in corpus().items():
        if names and name not in names:
            continue
        spec = work / name / "spec"
        shutil.copytree(SPEC, spec / "mscip")
        (spec / "mscip" / file).write_bytes(data)
        err = io.StringIO()
        start = time.monotonic()
        with contextlib.redirect_stderr(err):
            try:
                status = main(["--spec", str(spec), "--validate-only"])
            except BaseException as exc:  # noqa: BLE001 - a crash is what the corpus looks for
                status = f"{type(exc).__name__}: {exc}"[:300]
        results[name] = {"status": status, "stderr": err.getvalue().splitlines(), "seconds": time.monotonic() - start}
    return results


if __name__ == "__main__":  # python -m tests.generator.hostile_specs WORKDIR: the results as JSON
    import json
    import resource
    import sys

    out = run_all(Path(sys.argv[1]), sys.argv[2:] or None)
    peak_kb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    json.dump({"cases": out, "peak_rss_kb": peak_kb}, sys.stdout)
