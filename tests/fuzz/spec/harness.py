"""Fuzz target of the generator's front end (issue 28): spec files from outside through the YAML
loader (generator/yamlpos.py), the JSON Schema check and the IR passes (generator/spec.py,
generator/ir.py), as `python -m generator --spec DIR` reads them.

Input format: byte 0 picks the file (its value modulo 5: 0-3 replace protocol.yaml, base.yaml,
imu_config.yaml or imu_data.yaml of spec/mscip/, 4 adds zz_fuzz.yaml beside them), the rest is
that file's bytes. The other files are the real ones, loaded once.

The property: the spec builds, or the front end raises SpecErrors whose every error is one line
located as `file:line:column` (only "has no protocol file" names the directory instead), of
bounded length. Any other exception (a traceback for the user) is a finding.
"""

from __future__ import annotations

import copy
import functools
import tempfile
from pathlib import Path

from generator import spec
from generator.diagnostics import SpecError, SpecErrors

ROOT = Path(__file__).resolve().parents[3]
SPEC = ROOT / "spec" / "mscip"
FILES = ("protocol.yaml", "base.yaml", "imu_config.yaml", "imu_data.yaml", "zz_fuzz.yaml")
MAX_MESSAGE = 1000


class FuzzCheckFailed(AssertionError):
    """A harness property does not hold."""


@functools.cache
def _setup():
    validator = spec._schema_validator()
    real = {name: spec.read_spec_file(SPEC / name, f"spec/mscip/{name}", validator) for name in FILES[:4]}
    work = Path(tempfile.mkdtemp(prefix="fuzz-spec-"))
    return validator, real, work


def check_error(e: SpecError) -> None:
    text = str(e)
    if "\n" in text or len(text) > MAX_MESSAGE:
        raise FuzzCheckFailed(f"not one short line: {text[:2000]!r}")
    if e.loc is None:
        if not text.startswith("error: spec/mscip/ has no protocol file"):
            raise FuzzCheckFailed(f"error without a location: {text}")
    elif not (e.loc.file.startswith("spec/mscip/") and e.loc.line >= 1 and e.loc.column >= 1):
        raise FuzzCheckFailed(f"bad location: {text}")


def spec_loader(data: bytes) -> dict | None:
    """One input through the front end; returns the IR when the spec builds, None when refused."""
    if not data:
        return None
    validator, real, work = _setup()
    name = FILES[data[0] % len(FILES)]
    path = work / name
    path.write_bytes(data[1:])
    files = {n: copy.deepcopy(sf) for n, sf in real.items() if n != name}
    try:
        files[name] = spec.read_spec_file(path, f"spec/mscip/{name}", validator)
        return spec.build_from_files("spec/mscip", [files[n] for n in sorted(files)])
    except SpecErrors as e:
        if not e.errors:
            raise FuzzCheckFailed("SpecErrors without errors") from None
        for err in e.errors:
            check_error(err)
        return None


def seeds() -> dict[str, bytes]:
    """The real files and the hostile corpus (tests/generator/hostile_specs.py), in the input format."""
    from tests.generator.hostile_specs import corpus

    out = {f"real-{n}": bytes([i]) + (SPEC / n).read_bytes() for i, n in enumerate(FILES[:4])}
    for case, (file, content) in corpus().items():
        if len(content) <= 64 << 10:  # the size-limit cases stay in the pytest corpus
            out[f"hostile-{case}"] = bytes([FILES.index(file) if file in FILES else 4]) + content
    return out
