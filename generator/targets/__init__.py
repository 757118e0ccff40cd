"""The language targets, one wing each (generator/targets/<lang>/), in render order: the one list
of languages of the project. The CLI (`mipgen generate --langs`, `mipgen targets`), setup.py, the
Makefile (LANGS), `mipgen diff`, the docs, the golden tree and every cross-language test read it
from here; docs/design.md "One wing per language" says how to add one.

Importing this module imports no back end (setup.py and the Makefile read NAMES with a bare
Python); TARGETS["c"] imports generator/targets/c/ when first asked for.

Each target module exposes:
  OUTPUT_DIRS: directories under generated/ that it owns entirely
  render(ir: dict, vectors: list[dict], release: generator.release.Release | None,
         sessions: list[dict]) -> dict[path relative to generated/, file text]
      release (the version, the license; the project's when None) is stamped into every package
      with its protocol's spec hash; sessions is the session corpus (generator/sessions.py: the
      project's tests/sessions/, none for another spec), the same for every target
  api_names(protocol, set, field) -> the names a field has in that language (for the docs)
  public_names(protocol, kind, *names) -> the public name(s) of a spec element (for `mipgen diff`)
  names(protocol) -> [generator.name_check.Name]: every identifier its code gives a spec element,
      and reserved(identifier) -> why it is still reserved in the language, or None (the name
      check the pipeline runs before rendering; targets/<lang>/identifiers.py)
  TITLE, EXTENSION: the language's name in the documentation, its source files' extension
  GETTING_STARTED: a GettingStarted (below; targets/<lang>/facts.py), the language's own text on
      its getting-started page (generator/docs/getting_started.py reads nothing else per language)

Each target also has a runner, tests/lang/<lang>.sh (build, test, decode, encode, session), which
the conformance tools (tests/conformance/decode, encode, session) and the cross-language tests
call; a registered target without one fails those tests by name (tests/helpers/langs.py).
"""

from __future__ import annotations

import importlib
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from types import ModuleType

NAMES: tuple[str, ...] = ("c", "cpp", "python", "rust")


class _Registry(Mapping):
    """NAMES -> the target modules, imported on first use (explicitly: generator/targets/<name>/)."""

    def __getitem__(self, name: str) -> ModuleType:
        if name not in NAMES:
            raise KeyError(name)
        return importlib.import_module(f"{__name__}.{name}")

    def __iter__(self) -> Iterator[str]:
        return iter(NAMES)

    def __len__(self) -> int:
        return len(NAMES)


TARGETS: Mapping[str, ModuleType] = _Registry()


@dataclass(frozen=True)
class GettingStarted:
    """What a language's getting-started page says in its own words (generated/docs/getting-started/
    <lang>.md; generator/docs/getting_started.py). Every text is a `str.format` template of `{pkg}`
    (the package), `{PKG}` (upper case) and the record's `variables`."""

    install: str  # how to vendor and build the package: the paragraph before `setup`
    setup: str  # the build-file lines or shell commands that go with it
    setup_lang: str  # the code block's language (cmake, toml, sh)
    # the outside-user test's marker for `setup` (docs/conformance.md section 11): "project" (built
    # as a project around the package's example) or "files capture.bin" (run as commands)
    setup_outside: str
    include_intro: str  # the sentence before the example's lines that include or import the package
    run_package_var: str  # the variable of tests/lang/<lang>.sh that picks the package
    outside_run: str  # build and run the configure-and-stream example from the package's directory (ADDRESS)
    simulator_note: str = ""  # said of the simulator run's prerequisites, before its commands
    variables: Mapping[str, str] = field(default_factory=dict)


__all__ = ["NAMES", "TARGETS", "GettingStarted"]
