"""The host clock model's parameters (docs/time.md) come from one place, the spec's
`time.clock_model` (spec/mip/protocol.yaml): the project's own choice, so no manual line; this
checks that the places that must agree with it do.

- tests/clock/make_cases.py writes the corpus tests/clock/cases.txt from the spec's values: written
  again (to a temporary file), it is the checked-in corpus byte for byte.
- The runtimes' own tests run that corpus against the test protocol tests/runtime_specs/ (both
  framings), whose `time.clock_model` must hold the same four numbers.
- The generated packages of the protocol carry them (Python `_columns`, C `protocol.h`, C++
  `framing.hpp`, Rust `framing.rs`).
- The JSON Schema refuses an entry without its `basis` (the reason for values no manual states).
"""

from __future__ import annotations

import importlib.util
import json
import re
from pathlib import Path

import jsonschema
import yaml

ROOT = Path(__file__).resolve().parents[2]
KEYS = ("bucket_ns", "buckets", "min_buckets", "restart_ns")


def _model(path: Path) -> dict:
    return yaml.safe_load(path.read_text(encoding="utf-8"))["time"]["clock_model"]


SPEC = _model(ROOT / "spec" / "mip" / "protocol.yaml")


def test_the_corpus_is_written_with_the_spec_values(tmp_path, monkeypatch):
    spec = importlib.util.spec_from_file_location("make_cases", ROOT / "tests" / "clock" / "make_cases.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    assert (mod.BUCKET_NS, mod.BUCKETS, mod.MIN_BUCKETS, mod.RESTART_NS) == tuple(SPEC[k] for k in KEYS)
    monkeypatch.setattr(mod, "OUT", tmp_path / "cases.txt")
    mod.main()
    assert (tmp_path / "cases.txt").read_bytes() == (ROOT / "tests" / "clock" / "cases.txt").read_bytes()


def test_the_runtime_test_protocol_has_the_same_values():
    for framing in ("framing_a", "framing_b"):
        m = _model(ROOT / "tests" / "runtime_specs" / framing / "testproto" / "protocol.yaml")
        assert {k: m[k] for k in KEYS} == {k: SPEC[k] for k in KEYS}, framing


def test_the_generated_packages_carry_them():
    gen = ROOT / "generated"
    texts = {
        "python": (gen / "python/mipcodec/mipcodec/_columns.py", "CLOCK_{} = {}"),
        "c": (gen / "c/mipcodec/include/mipcodec/protocol.h", "#define MIPC_CLOCK_{} {}"),
        "rust": (gen / "rust/mipcodec/src/framing.rs", "pub const CLOCK_{}: [a-z0-9]+ = {};"),
    }
    for lang, (path, pattern) in texts.items():
        text = path.read_text(encoding="utf-8")
        for k in KEYS:
            assert re.search(pattern.format(k.upper(), SPEC[k]), text), (lang, k)
    cpp = (gen / "cpp/mipcodec/include/mipcodec/framing.hpp").read_text(encoding="utf-8")
    for k in KEYS:
        name = "kClock" + "".join(w.capitalize() for w in k.split("_"))
        assert re.search(rf"{name} = {SPEC[k]};", cpp), k


def test_the_schema_wants_a_basis():
    schema = json.loads((ROOT / "spec" / "schema" / "spec.schema.json").read_text(encoding="utf-8"))
    doc = yaml.safe_load((ROOT / "spec" / "mip" / "protocol.yaml").read_text(encoding="utf-8"))
    validator = jsonschema.Draft202012Validator(schema)
    assert not list(validator.iter_errors(doc))
    del doc["time"]["clock_model"]["basis"]
    # (the top level is a choice of file kinds: the protocol file's error is in the error's context)
    found = [c for e in validator.iter_errors(doc) for c in [e, *(e.context or [])]]
    assert any(c.message == "'basis' is a required property" and "clock_model" in c.absolute_path for c in found)
