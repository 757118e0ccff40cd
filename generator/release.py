"""What every generated package carries besides the code: the project's version, the hash of its
protocol's IR, and the license (docs/versioning.md).

- The version is one semantic version, MAJOR.MINOR.PATCH, in the file VERSION at the project
  root: the single source of truth for every package of every language. A spec given with
  `--spec DIR` uses DIR/VERSION when it has one (the every-feature fixture of the golden tree
  does, so that a release does not change that tree), else the project's.
- The spec hash of a protocol is the first 16 hex digits of the SHA-256 of its entry of
  `protocols` in generated/ir.json without `commands` (derived from the rest), written canonically: JSON with sorted keys, no whitespace
  (separators "," and ":"), non-ASCII escaped, UTF-8. It covers everything the IR says about that
  protocol (framing, devices, types, sets, fields, names, documentation strings, manual
  citations) and nothing else: not the version, the other protocol, the generator or the
  templates. Any change of the protocol's IR changes it; a change of the spec's YAML that leaves
  the IR as it was (a comment, the order of keys) does not.
- The license is the file LICENSE at the project root (MIT), copied into every package.
"""

from __future__ import annotations

import hashlib
import json
import re
from dataclasses import dataclass
from pathlib import Path

from .diagnostics import Location, SpecError
from .resources import LICENSE_FILE, ROOT, VERSION_FILE  # the checkout's, or the wheel's copies

SPEC_HASH_DIGITS = 16

# MAJOR.MINOR.PATCH, no leading zeros (semver 2.0.0 section 2). Pre-release and build suffixes
# are not accepted: Python (PEP 440), Cargo and CMake spell them differently.
_SEMVER = re.compile(r"(0|[1-9][0-9]*)\.(0|[1-9][0-9]*)\.(0|[1-9][0-9]*)")


def canonical_json(value: object) -> bytes:
    """The canonical bytes of a JSON value, as the spec hash reads them."""
    return json.dumps(value, sort_keys=True, separators=(",", ":"), ensure_ascii=True).encode("utf-8")


def spec_hash(protocol: dict) -> str:
    """The spec hash of one protocol's IR (its entry of `protocols` as exported to ir.json)."""
    # Through the exported JSON first, so that the hash is that of ir.json's entry whatever Python
    # types the in-memory IR holds (tuples, integer keys).
    exported = json.loads(json.dumps(protocol, ensure_ascii=True))
    exported.pop("commands", None)  # the command model is derived from the rest (generator/commands.py)
    return hashlib.sha256(canonical_json(exported)).hexdigest()[:SPEC_HASH_DIGITS]


@dataclass(frozen=True)
class Release:
    version: str
    major: int
    minor: int
    patch: int
    license: str  # the text of LICENSE

    def stamp(self, protocol: dict) -> dict:
        """What a package's templates print: the version, its parts and the protocol's hash."""
        return {
            "version": self.version,
            "version_major": self.major,
            "version_minor": self.minor,
            "version_patch": self.patch,
            "spec_hash": spec_hash(protocol),
        }


def parse_version(text: str, where: str) -> tuple[int, int, int]:
    """MAJOR, MINOR, PATCH of a VERSION file's text; a located error when it is not one."""
    lines = text.splitlines()
    first = lines[0].strip() if lines else ""
    if any(line.strip() for line in lines[1:]):
        raise SpecError(Location(where, 2, 1), "VERSION holds more than one line", "one line: MAJOR.MINOR.PATCH")
    m = _SEMVER.fullmatch(first)
    if not m:
        raise SpecError(
            Location(where, 1, 1),
            f"version {first!r} is not a semantic version MAJOR.MINOR.PATCH",
            "three numbers without leading zeros, such as 1.4.0 (docs/versioning.md)",
        )
    return int(m.group(1)), int(m.group(2)), int(m.group(3))


def _display(path: Path) -> str:
    try:
        return str(path.resolve().relative_to(ROOT))
    except ValueError:
        return str(path)


def load_release(spec_dir: Path | None = None) -> Release:
    """The release of a spec: VERSION beside a --spec directory when it has one, else the
    project's; the project's LICENSE."""
    version_file = VERSION_FILE
    if spec_dir is not None and (spec_dir / "VERSION").is_file():
        version_file = spec_dir / "VERSION"
    where = _display(version_file)
    for path, what in ((version_file, "the version, MAJOR.MINOR.PATCH"), (LICENSE_FILE, "the license text")):
        if not path.is_file():
            raise SpecError(Location(_display(path), 1, 1), f"{path.name} is missing", f"a file holding {what}")
    try:
        text = version_file.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise SpecError(Location(where, 1, 1), "VERSION is not UTF-8 text", "MAJOR.MINOR.PATCH") from None
    major, minor, patch = parse_version(text, where)
    return Release(
        version=f"{major}.{minor}.{patch}",
        major=major,
        minor=minor,
        patch=patch,
        license=LICENSE_FILE.read_text(encoding="utf-8"),
    )
