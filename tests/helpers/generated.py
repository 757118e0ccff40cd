"""Imports a generated Python package straight from generated/python/<package>/ (the source tree,
nothing installed) without putting its directory on sys.path for every later import."""

from __future__ import annotations

import importlib.machinery
import importlib.util
import sys
from pathlib import Path
from types import ModuleType

ROOT = Path(__file__).resolve().parents[2]
GENERATED_PYTHON = ROOT / "generated" / "python"


def python_package(package: str, base: Path = GENERATED_PYTHON) -> ModuleType:
    """The package <base>/<package>/<package>/, imported under its own name (once per process).
    Its submodules import as usual: they are found through the package's __path__."""
    if package in sys.modules:
        return sys.modules[package]
    spec = importlib.machinery.PathFinder.find_spec(package, [str(base / package)])
    if spec is None or spec.loader is None:
        raise ImportError(f"no generated Python package {package} under {base} (run make)")
    module = importlib.util.module_from_spec(spec)
    sys.modules[package] = module
    try:
        spec.loader.exec_module(module)
    except BaseException:
        del sys.modules[package]
        raise
    return module
