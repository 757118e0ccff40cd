"""Every generated package carries the one version of VERSION, the spec hash of its protocol and
the license (docs/versioning.md). The spec hash is computed here from the tree's ir.json, without
the generator's code: SHA-256 of the protocol's entry written as canonical JSON (sorted keys, no
whitespace, ASCII) without its derived `commands`, first 16 hex digits. Checked for generated/ (the project's VERSION) and for
the golden tree (the every-feature fixture, which has its own VERSION)."""

from __future__ import annotations

import ast
import hashlib
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from generator.diagnostics import SpecError
from generator.release import parse_version, spec_hash
from generator.targets import NAMES
from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
LICENSE = (ROOT / "LICENSE").read_bytes()
FIXTURE = ROOT / "tests" / "generator" / "fixtures" / "everything"
TREES = {
    "generated": (ROOT / "generated", ROOT / "VERSION"),
    "golden": (ROOT / "tests" / "golden" / "everything", FIXTURE / "VERSION"),
}


def _independent_hash(protocol: dict) -> str:
    # Without `commands`, the command model derived from the rest of the entry (docs/versioning.md).
    protocol = {k: v for k, v in protocol.items() if k != "commands"}
    text = json.dumps(protocol, sort_keys=True, separators=(",", ":"), ensure_ascii=True)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


def _version(path: Path) -> tuple[str, tuple[int, int, int]]:
    text = path.read_text(encoding="utf-8").strip()
    m = re.fullmatch(r"(0|[1-9]\d*)\.(0|[1-9]\d*)\.(0|[1-9]\d*)", text)
    assert m, f"{path}: {text!r} is not MAJOR.MINOR.PATCH"
    return text, (int(m[1]), int(m[2]), int(m[3]))


def _defines(path: Path) -> dict[str, str]:
    return dict(re.findall(r"^#define (\w+) (.+)$", path.read_text(encoding="utf-8"), re.M))


def _cmake_version(path: Path) -> str:
    """The project VERSION of a CMakeLists.txt, which must also install LICENSE."""
    text = path.read_text(encoding="utf-8")
    m = re.search(r"^project\(\S+ VERSION (\S+) LANGUAGES ", text, re.M)
    assert m, f"{path}: no project(NAME VERSION ... LANGUAGES ...)"
    assert re.search(r"^\s*install\(FILES LICENSE ", text, re.M), f"{path}: LICENSE not installed"
    return m[1]


def _toml(path: Path) -> dict[str, dict[str, object]]:
    """The key = value lines of a generated TOML file by table; the values used here (strings,
    arrays of strings) are written the same in JSON."""
    tables: dict[str, dict[str, object]] = {}
    table = ""
    for line in path.read_text(encoding="utf-8").splitlines():
        if m := re.fullmatch(r"\[\[?([^\]]+)\]\]?", line.strip()):
            table = m[1]
        elif m := re.fullmatch(r'([A-Za-z0-9_-]+) = ("[^"]*"|\[[^\]]*\])', line.strip()):
            tables.setdefault(table, {})[m[1]] = json.loads(m[2])
    return tables


def _py_constants(path: Path) -> dict[str, object]:
    """Top-level NAME = literal assignments of a module."""
    out = {}
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
            if isinstance(node.value, ast.Constant):
                out[node.targets[0].id] = node.value.value
    return out


def _rust_consts(path: Path) -> dict[str, str]:
    return dict(re.findall(r"^pub const (\w+): \S+ = (.+);$", path.read_text(encoding="utf-8"), re.M))


@pytest.mark.parametrize("tree_name", sorted(TREES))
def test_every_package_carries_the_version_and_its_spec_hash(tree_name: str) -> None:
    tree, version_file = TREES[tree_name]
    version, (major, minor, patch) = _version(version_file)
    protocols = json.loads((tree / "ir.json").read_text(encoding="utf-8"))["protocols"]
    assert protocols
    hashes = set()
    checked = []
    for proto in protocols:
        pkg, want_hash = proto["package"], _independent_hash(proto)
        assert re.fullmatch(r"[0-9a-f]{16}", want_hash)
        hashes.add(want_hash)
        # C macros carry the C symbol prefix (package name without "codec", plus "c": MIPC_,
        # docs/packaging.md); C++ macros the package name (MIPCODEC_).
        c_prefix = (pkg[: -len("codec")] if pkg.endswith("codec") else pkg) + "c"

        def want_macros(P: str, want_hash: str = want_hash) -> dict[str, str]:
            return {
                f"{P}_VERSION_MAJOR": str(major),
                f"{P}_VERSION_MINOR": str(minor),
                f"{P}_VERSION_PATCH": str(patch),
                f"{P}_VERSION": f'"{version}"',
                f"{P}_SPEC_HASH": f'"{want_hash}"',
            }

        # C and C++: the macros, the C++ constants, the CMake project version.
        for lang, header, P in (("c", "version.h", c_prefix.upper()), ("cpp", "version.hpp", pkg.upper())):
            root = tree / lang / pkg
            defines = _defines(root / "include" / pkg / header)
            want = want_macros(P)
            assert {k: defines.get(k) for k in want} == want, f"{lang}/{pkg}"
            assert _cmake_version(root / "CMakeLists.txt") == version, f"{lang}/{pkg}"
            umbrella = (root / "include" / pkg / (f"{pkg}.h" if lang == "c" else f"{pkg}.hpp")).read_text()
            assert f'#include "{pkg}/{header}"' in umbrella, f"{lang}/{pkg}: the umbrella header includes {header}"
            checked.append(f"{lang}/{pkg}")
        hpp = (tree / "cpp" / pkg / "include" / pkg / "version.hpp").read_text(encoding="utf-8")
        for line in (
            f"inline constexpr int kVersionMajor = {major};",
            f"inline constexpr int kVersionMinor = {minor};",
            f"inline constexpr int kVersionPatch = {patch};",
            f'inline constexpr std::string_view kVersion = "{version}";',
            f'inline constexpr std::string_view kSpecHash = "{want_hash}";',
        ):
            assert line in hpp, f"cpp/{pkg}: {line}"
        # Python: the module's constants and the distribution's metadata.
        root = tree / "python" / pkg
        constants = _py_constants(root / pkg / "__init__.py")
        assert (constants.get("__version__"), constants.get("SPEC_HASH")) == (version, want_hash), f"python/{pkg}"
        project = _toml(root / "pyproject.toml")["project"]
        assert (project["version"], project["license"], project["license-files"]) == (version, "MIT", ["LICENSE"])
        checked.append(f"python/{pkg}")
        # Rust: the crate's constants and its Cargo version and license.
        root = tree / "rust" / pkg
        consts = _rust_consts(root / "src" / "lib.rs")
        want_consts = {
            "VERSION": f'"{version}"',
            "VERSION_MAJOR": str(major),
            "VERSION_MINOR": str(minor),
            "VERSION_PATCH": str(patch),
            "SPEC_HASH": f'"{want_hash}"',
        }
        assert {k: consts.get(k) for k in want_consts} == want_consts, f"rust/{pkg}"
        package = _toml(root / "Cargo.toml")["package"]
        assert (package["version"], package["license"]) == (version, "MIT"), f"rust/{pkg}"
        checked.append(f"rust/{pkg}")
        # The generator's own function agrees with the independent computation.
        assert spec_hash(proto) == want_hash
    assert len(hashes) == len(protocols), "two protocols with one hash"
    assert len(checked) == 4 * len(protocols)


@pytest.mark.parametrize("tree_name", sorted(TREES))
def test_every_package_has_the_license(tree_name: str) -> None:
    tree, _ = TREES[tree_name]
    assert LICENSE.startswith(b"MIT License\n") and b"Permission is hereby granted" in LICENSE
    packages = [p for lang in NAMES for p in sorted((tree / lang).iterdir()) if p.is_dir()]
    assert len(packages) >= 4
    for package in packages:
        assert (package / "LICENSE").read_bytes() == LICENSE, f"{package.relative_to(ROOT)}/LICENSE"


def test_python_packages_report_their_version_at_run_time() -> None:
    version, _ = _version(ROOT / "VERSION")
    for proto in json.loads((ROOT / "generated" / "ir.json").read_text(encoding="utf-8"))["protocols"]:
        module = python_package(proto["package"])
        assert (module.__version__, module.SPEC_HASH) == (version, _independent_hash(proto))
        assert {"__version__", "SPEC_HASH"} <= set(module.__all__)


def test_spec_hash_follows_the_ir_not_its_key_order() -> None:
    proto = json.loads((ROOT / "generated" / "ir.json").read_text(encoding="utf-8"))["protocols"][0]
    reordered = json.loads(json.dumps(dict(reversed(list(proto.items())))))
    assert spec_hash(reordered) == spec_hash(proto)
    changed = json.loads(json.dumps(proto))
    changed["sets"][0]["fields"][0]["name"] += "_renamed"
    assert spec_hash(changed) != spec_hash(proto)
    changed = json.loads(json.dumps(proto))
    changed["framing"]["max_payload"] -= 1
    assert spec_hash(changed) != spec_hash(proto)


@pytest.mark.parametrize(
    "text, message",
    [
        ("1.0\n", "version '1.0' is not a semantic version MAJOR.MINOR.PATCH"),
        ("v1.2.3\n", "version 'v1.2.3' is not a semantic version"),
        ("01.2.3\n", "version '01.2.3' is not a semantic version"),
        ("1.2.3-rc.1\n", "version '1.2.3-rc.1' is not a semantic version"),
        ("", "version '' is not a semantic version"),
        ("1.2.3\n1.2.4\n", "VERSION holds more than one line"),
    ],
)
def test_bad_versions_are_located_errors(text: str, message: str) -> None:
    with pytest.raises(SpecError) as e:
        parse_version(text, "VERSION")
    assert message in str(e.value)
    assert str(e.value).startswith("VERSION:")


def test_good_versions() -> None:
    assert parse_version("0.1.0\n", "VERSION") == (0, 1, 0)
    assert parse_version(" 12.0.345 \n\n", "VERSION") == (12, 0, 345)


def test_generator_reports_a_bad_version_file(tmp_path: Path) -> None:
    """python -m generator with a --spec whose VERSION is not semver: exit 1, the located error,
    no traceback, nothing written."""
    spec = tmp_path / "spec"
    for src in FIXTURE.rglob("*"):
        if src.is_file():
            dest = spec / src.relative_to(FIXTURE)
            dest.parent.mkdir(parents=True, exist_ok=True)
            dest.write_bytes(src.read_bytes())
    (spec / "VERSION").write_text("2.1\n", encoding="utf-8")
    out = tmp_path / "out"
    proc = subprocess.run(
        [sys.executable, "-m", "generator", "--spec", str(spec), "--out", str(out), "--only", "c"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 1, proc.stderr
    assert f"{spec / 'VERSION'}:1:1: error: version '2.1' is not a semantic version MAJOR.MINOR.PATCH" in proc.stderr
    assert "Traceback" not in proc.stderr
    assert not out.exists()


def test_a_missing_version_file_is_a_located_error(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from generator import release

    monkeypatch.setattr(release, "VERSION_FILE", tmp_path / "VERSION")
    with pytest.raises(SpecError) as e:
        release.load_release()
    assert str(e.value) == (
        f"{tmp_path / 'VERSION'}:1:1: error: VERSION is missing (expected a file holding the version, MAJOR.MINOR.PATCH)"
    )
    (tmp_path / "VERSION").write_text("3.0.7\n", encoding="utf-8")
    assert release.load_release().version == "3.0.7"
    # A --spec directory's own VERSION wins over the project's.
    spec = tmp_path / "spec"
    spec.mkdir()
    (spec / "VERSION").write_text("4.5.6\n", encoding="utf-8")
    assert (release.load_release(spec).major, release.load_release(spec).version) == (4, "4.5.6")
