"""Load and validate the spec tree: JSON Schema for shape, then the IR builder for meaning."""

from __future__ import annotations

import json
import os
from pathlib import Path

import jsonschema

from .diagnostics import Location, SpecError, SpecErrors
from .gps_scale import COMMON, load_gps_scale
from .ir import IR_VERSION, build_protocol
from .overlay import apply_extensions
from .passes.context import SpecFile
from .resources import ROOT, SCHEMA_DIR
from .schema_check import schema_errors
from .yamlpos import load

SCHEMA_PATH = SCHEMA_DIR / "spec.schema.json"
FILE_KINDS = ("protocol", "set", "types", "extends")  # the key that tells a file's kind


def _schema_validator():
    """One validator per file kind; the kind is chosen by the file's discriminating key."""
    with open(SCHEMA_PATH, encoding="utf-8") as fh:
        schema = json.load(fh)
    validators = {}
    for key, ref in (
        ("protocol", "protocolFile"),
        ("set", "setFile"),
        ("types", "typesFile"),
        ("extends", "extensionFile"),
    ):
        sub = {"$schema": schema["$schema"], "$defs": schema["$defs"], "$ref": f"#/$defs/{ref}"}
        validators[key] = jsonschema.Draft202012Validator(sub)
    validators[None] = jsonschema.Draft202012Validator(schema)
    return validators


def _validate_shape(validators, sf: SpecFile) -> list[SpecError]:
    kind = next((k for k in FILE_KINDS if k in sf.data), None)
    if kind is None:
        return [
            SpecError(
                sf.locate(()),
                "cannot tell what kind of spec file this is",
                "a top-level 'protocol:' (protocol file), 'set:' (descriptor set), 'types:' (shared types)"
                " or 'extends:' (an overlay's additions) key",
            )
        ]
    return schema_errors(validators[kind], sf.data, sf.locate)


def read_spec_file(path: Path, display_name: str, validator) -> SpecFile:
    """One spec file loaded (with positions) and its shape checked against the JSON Schema; raises
    SpecErrors for a file that cannot be read or has the wrong shape."""
    try:
        data, locate = load(str(path), display_name)
    except SpecError as e:
        raise SpecErrors([e]) from None
    sf = SpecFile(display_name, data, locate)
    if not isinstance(data, dict):
        raise SpecErrors(
            [
                SpecError(
                    locate(()),
                    "the file must be a YAML mapping",
                    "a protocol file (protocol: ...) or a set file (set: ...)",
                )
            ]
        )
    shape = _validate_shape(validator, sf)
    if shape:
        raise SpecErrors(shape)
    return sf


def build_from_files(dir_name: str, spec_files: list[SpecFile]) -> dict:
    """A protocol's IR from its loaded, shape-checked files (one protocol file, set files, type
    files); raises SpecErrors with every problem found."""
    errors: list[SpecError] = []
    protocol_file = None
    set_files: list[SpecFile] = []
    type_files: list[SpecFile] = []
    extensions: list[SpecFile] = []
    for sf in spec_files:
        if "protocol" in sf.data:
            if protocol_file is not None:
                errors.append(
                    SpecError(
                        sf.locate(("protocol",)),
                        f"a second protocol file in {dir_name}/ (first: {protocol_file.path})",
                        "one protocol file per protocol directory",
                    )
                )
            protocol_file = sf
        elif "set" in sf.data:
            set_files.append(sf)
        elif "extends" in sf.data:
            extensions.append(sf)
        else:
            type_files.append(sf)
    if errors:
        raise SpecErrors(errors)
    if protocol_file is None:
        raise SpecErrors(
            [SpecError(None, f"{dir_name}/ has no protocol file", "a file with 'protocol:' describing the framing")]
        )
    if extensions:
        errors = apply_extensions(protocol_file, set_files + type_files, extensions)
        if errors:
            raise SpecErrors(errors)
    protocol, build_errors = build_protocol(protocol_file, set_files, type_files)
    if build_errors:
        raise SpecErrors(build_errors)
    return protocol


def _read_dir(directory: Path, root: Path, validator, errors: list[SpecError]) -> list[SpecFile]:
    files = sorted(p for p in directory.iterdir() if p.suffix in (".yaml", ".yml"))
    spec_files: list[SpecFile] = []
    for path in files:
        try:
            spec_files.append(read_spec_file(path, os.path.relpath(path, root), validator))
        except SpecErrors as e:
            errors.extend(e.errors)
    return spec_files


def load_protocol_dir(directory: Path, root: Path = ROOT, overlays: list[tuple[Path, Path]] = ()) -> dict:
    """Load spec/<protocol>/ (and the same protocol's directories of overlays, each given as
    (directory, the root its file names are relative to)) and return the protocol's IR entry."""
    validator = _schema_validator()
    errors: list[SpecError] = []
    spec_files = _read_dir(directory, root, validator, errors)
    for odir, oroot in overlays:
        spec_files += _read_dir(odir, oroot, validator, errors)
    if errors:
        raise SpecErrors(errors)
    return build_from_files(os.path.relpath(directory, root), spec_files)


def _protocol_dirs(spec_dir: Path) -> list[Path]:
    return sorted(p for p in spec_dir.iterdir() if p.is_dir() and p.name not in ("schema", COMMON))


def load_spec(spec_dir: Path | None = None, root: Path = ROOT, overlays: list[Path] = ()) -> dict:
    """The IR of a spec directory (one subdirectory per protocol) with the overlay directories
    laid over it in order (generator/overlay.py): an overlay's <protocol>/ adds files to that
    protocol; a directory naming no protocol of the spec is a protocol of its own."""
    spec_dir = spec_dir or root / "spec"
    protocols = []
    errors: list[SpecError] = []
    for d in [spec_dir, *overlays]:
        if not Path(d).is_dir():
            raise SpecErrors(
                [SpecError(None, f"spec directory {d} does not exist", "a directory of protocol directories")]
            )
    base = {d.name: d for d in _protocol_dirs(spec_dir)}
    extra: dict[str, list[tuple[Path, Path]]] = {name: [] for name in base}
    for o in overlays:
        o = Path(o)
        subdirs = _protocol_dirs(o)
        if not subdirs:
            raise SpecErrors(
                [
                    SpecError(
                        None,
                        f"overlay {o} has no protocol directory",
                        "one directory per protocol it adds to, named as in the spec: "
                        + ", ".join(f"{o}/{n}/" for n in sorted(base)),
                    )
                ]
            )
        for sub in subdirs:
            if sub.name in base:
                extra[sub.name].append((sub, o.resolve().parent))
            else:
                base[sub.name] = sub  # a protocol of the overlay's own
                extra[sub.name] = []
    for name in sorted(base):
        d = base[name]
        try:
            own_root = root if d.resolve().is_relative_to(Path(root).resolve()) else d.resolve().parent.parent
            protocols.append(load_protocol_dir(d, own_root, extra[name]))
        except SpecErrors as e:
            errors.extend(e.errors)
    try:
        gps_scale = load_gps_scale(Path(spec_dir), root)
    except SpecErrors as e:
        errors.extend(e.errors)
    if errors:
        raise SpecErrors(errors)
    if not protocols:
        raise SpecError(None, _no_protocol(Path(spec_dir)), "a spec root: one directory per protocol, e.g. spec/")
    for p in protocols:  # the GPS time scale, the same for every protocol (generator/gps_scale.py)
        p["time"]["gps_scale"] = gps_scale
    return {"ir_version": IR_VERSION, "protocols": protocols}


def _no_protocol(spec_dir: Path) -> str:
    """Why spec_dir yields no protocol: a protocol's own directory given for the spec root, or
    a directory with no protocol directory at all (either would make an IR of nothing)."""
    if any(p.suffix in (".yaml", ".yml") for p in spec_dir.iterdir()):
        return (
            f"spec directory {spec_dir} has no protocol directory: it holds spec files, so it looks like one"
            f" protocol's directory; give its parent ({os.path.relpath(spec_dir.resolve().parent)})"
        )
    return f"spec directory {spec_dir} has no protocol directory"


def locate_names(
    protocol: str, names: tuple[str, ...], spec_dir: Path | None = None, root: Path = ROOT, overlays: list[Path] = ()
) -> Location | None:
    """Where the spec element reached by `names` is defined: the `name:` of the mapping named
    names[-1] inside the mappings named by the names before it (("GpsMode", "a") is value a of
    enum GpsMode; ("commands", "ping") field ping of set commands), searched in the protocol's
    files of the spec and its overlays. None when no file has it (for a back end's error)."""
    spec_dir = spec_dir or root / "spec"
    dirs = [(Path(spec_dir) / protocol, root)]
    dirs += [(Path(o) / protocol, Path(o).resolve().parent) for o in overlays]

    def find(node, path: tuple, want: tuple[str, ...]):
        if isinstance(node, dict):
            if node.get("name") == want[0]:
                if len(want) == 1:
                    return path + ("name",)
                want = want[1:]
            items = node.items()
        elif isinstance(node, list):
            items = enumerate(node)
        else:
            return None
        for key, child in items:
            hit = find(child, path + (key,), want)
            if hit:
                return hit
        return None

    if not names:
        return None
    for directory, base in dirs:
        if not directory.is_dir():
            continue
        for path in sorted(p for p in directory.iterdir() if p.suffix in (".yaml", ".yml")):
            try:
                data, locate = load(str(path), os.path.relpath(path, base))
            except SpecError:
                continue
            hit = find(data, (), tuple(names))
            if hit:
                return locate(hit)
    return None
