"""Every file the generator reads besides the user's spec, in one place.

Run from a checkout (`python -m generator`, `pip install -e .`), the files are the checkout's:
templates/, spec/schema/, spec/common/ (the GPS time scale), VERSION, LICENSE, .clang-format, ruff.toml, rustfmt.toml and the
runtimes under generator/targets/<lang>/runtime/. Installed from a wheel (`pip install .`,
docs/packaging.md), the wheel carries copies of them in generator/_data/ (made by the build step
of setup.py, never kept in git) laid out as in the checkout, and the runtimes as package data.

CHECKOUT is the project root when running from a checkout, else None: the project's own inputs
(spec/, tests/vectors, tests/streams, tests/sessions, generated/, docs/) exist only there.
ROOT is where the resources are: the checkout, or generator/_data/ of an installed package.
"""

from __future__ import annotations

from pathlib import Path

PACKAGE_DIR = Path(__file__).resolve().parent
DATA_DIR = PACKAGE_DIR / "_data"

# The files and directories (relative to the project root) a wheel carries in generator/_data/.
SHIPPED = (
    "templates",
    "spec/schema",
    "spec/common",
    "VERSION",
    "LICENSE",
    ".clang-format",
    "ruff.toml",
    "rustfmt.toml",
)


def _checkout() -> Path | None:
    if DATA_DIR.is_dir():  # an installed package: its _data wins, whatever lies around it
        return None
    root = PACKAGE_DIR.parent
    return root if (root / "templates").is_dir() and (root / "spec" / "schema").is_dir() else None


CHECKOUT: Path | None = _checkout()
ROOT: Path = CHECKOUT or DATA_DIR

TEMPLATES = ROOT / "templates"
SCHEMA_DIR = ROOT / "spec" / "schema"
VERSION_FILE = ROOT / "VERSION"
LICENSE_FILE = ROOT / "LICENSE"
CLANG_FORMAT_CONFIG = ROOT / ".clang-format"
RUFF_CONFIG = ROOT / "ruff.toml"
RUSTFMT_CONFIG = ROOT / "rustfmt.toml"
TARGETS_DIR = PACKAGE_DIR / "targets"


def runtime_dir(lang: str) -> Path:
    """Where a target's hand-written runtime lives (generator/targets/<lang>/runtime/, package
    data in a wheel): plain source files, compiled, linted and unit-tested in place."""
    return TARGETS_DIR / lang / "runtime"


def sessions_dir() -> Path | None:
    """The project's session corpus (tests/sessions/), or None outside a checkout."""
    return CHECKOUT / "tests" / "sessions" if CHECKOUT else None


def missing() -> list[str]:
    """The resources that are not where they should be (a broken install): empty when all are."""
    return [name for name in SHIPPED if not (ROOT / name).exists()]
