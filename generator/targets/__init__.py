"""The language targets, one wing each (generator/targets/<lang>/), in render order.

Each target module exposes:
  OUTPUT_DIRS: directories under generated/ that it owns entirely
  render(ir: dict, vectors: list[dict], release: generator.release.Release | None)
      -> dict[path relative to generated/, file text]; release (the version, the license; the
      project's when None) is stamped into every package with its protocol's spec hash
  api_names(protocol, set, field) -> the names a field has in that language (for the docs)

The registry is explicit (no import by name), so readers and tools can follow the calls.
"""

from __future__ import annotations

from types import ModuleType

from . import c, cpp, python, rust

TARGETS: dict[str, ModuleType] = {"c": c, "cpp": cpp, "python": python, "rust": rust}

__all__ = ["TARGETS"]
