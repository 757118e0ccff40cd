"""Load and validate the spec tree: JSON Schema for shape, then the IR builder for meaning."""
from __future__ import annotations

import json
import os
from pathlib import Path

import jsonschema

from .diagnostics import SpecError, SpecErrors
from .ir import Builder, SpecFile
from .yamlpos import load

ROOT = Path(__file__).resolve().parent.parent
SCHEMA_PATH = ROOT / "spec" / "schema" / "spec.schema.json"


def _schema_validator():
    with open(SCHEMA_PATH, encoding="utf-8") as fh:
        schema = json.load(fh)
    return jsonschema.Draft202012Validator(schema)


def _describe(error: jsonschema.ValidationError) -> tuple[str, str | None]:
    """Turn a jsonschema error into (what is wrong, what is expected)."""
    # oneOf at the top: find the most specific sub-error.
    best = jsonschema.exceptions.best_match([error]) if error.context else error
    while best.context:
        best = jsonschema.exceptions.best_match(best.context)
    where = ".".join(str(p) for p in best.absolute_path) or "(top level)"
    v = best.validator
    if v == "required":
        missing = best.message.split("'")[1] if "'" in best.message else best.message
        return f"{where}: missing required key '{missing}'", None
    if v == "additionalProperties":
        return f"{where}: {best.message}", "only the keys documented in docs/spec-format.md"
    if v == "enum":
        return f"{where}: value {best.instance!r} is not allowed", "one of " + ", ".join(repr(x) for x in best.validator_value)
    if v == "pattern":
        return f"{where}: {best.instance!r} is not a valid name", f"a name matching {best.validator_value}"
    if v == "type":
        return f"{where}: {best.instance!r} has the wrong type", f"{best.validator_value}"
    if v in ("minimum", "maximum"):
        return f"{where}: {best.instance!r} is out of range", f"{v} {best.validator_value}"
    return f"{where}: {best.message}", None


def _validate_shape(validator, sf: SpecFile) -> list[SpecError]:
    errors = []
    for e in sorted(validator.iter_errors(sf.data), key=lambda e: list(map(str, e.absolute_path))):
        # Locate the deepest sub-error for oneOf/anyOf failures.
        best = e
        while best.context:
            best = jsonschema.exceptions.best_match(best.context)
        msg, expected = _describe(e)
        errors.append(SpecError(sf.locate(tuple(best.absolute_path)), msg, expected))
    return errors


def load_protocol_dir(directory: Path, root: Path = ROOT) -> dict:
    """Load spec/<protocol>/ and return the protocol's IR (one protocol entry)."""
    validator = _schema_validator()
    files = sorted(p for p in directory.iterdir() if p.suffix in (".yaml", ".yml"))
    errors: list[SpecError] = []
    protocol_file = None
    set_files: list[SpecFile] = []
    type_files: list[SpecFile] = []
    for path in files:
        rel = os.path.relpath(path, root)
        try:
            data, locate = load(str(path), rel)
        except SpecError as e:
            errors.append(e)
            continue
        sf = SpecFile(rel, data, locate)
        if not isinstance(data, dict):
            errors.append(SpecError(locate(()), "the file must be a YAML mapping", "a protocol file (protocol: ...) or a set file (set: ...)"))
            continue
        shape = _validate_shape(validator, sf)
        if shape:
            errors.extend(shape)
            continue
        if "protocol" in data:
            if protocol_file is not None:
                errors.append(SpecError(locate(("protocol",)), f"a second protocol file in {directory.name}/ (first: {protocol_file.path})", "one protocol file per protocol directory"))
            protocol_file = sf
        elif "set" in data:
            set_files.append(sf)
        else:
            type_files.append(sf)
    if errors:
        raise SpecErrors(errors)
    if protocol_file is None:
        raise SpecErrors([SpecError(None, f"{os.path.relpath(directory, root)}/ has no protocol file", "a file with 'protocol:' describing the framing")])
    builder = Builder(protocol_file, set_files, type_files)
    ir = builder.build()
    if builder.errors:
        raise SpecErrors(builder.errors)
    return ir["protocols"][0]


def load_spec(spec_dir: Path | None = None, root: Path = ROOT) -> dict:
    spec_dir = spec_dir or root / "spec"
    protocols = []
    errors: list[SpecError] = []
    for d in sorted(p for p in spec_dir.iterdir() if p.is_dir() and p.name != "schema"):
        try:
            protocols.append(load_protocol_dir(d, root))
        except SpecErrors as e:
            errors.extend(e.errors)
    if errors:
        raise SpecErrors(errors)
    from .ir import IR_VERSION
    return {"ir_version": IR_VERSION, "protocols": protocols}
