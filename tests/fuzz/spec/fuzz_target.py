"""Runs the spec loader fuzz target under atheris (libFuzzer flags and corpus directories follow):

    python -m tests.fuzz.spec.fuzz_target [libFuzzer args...] [CORPUS_DIR...]

from the project root; `make fuzz` runs it through tests/fuzz/fuzz.py as spec/generator/loader.
Only the front end is instrumented (the generator, PyYAML, jsonschema): instrumenting everything
takes minutes on a shared machine.
"""

from __future__ import annotations

import sys


def main() -> None:
    import atheris

    with atheris.instrument_imports(include=["generator", "yaml", "jsonschema"]):
        from tests.fuzz.spec import harness

        harness.spec_loader(b"")  # load the real files once, outside the timed inputs
        harness._setup()

    atheris.Setup([sys.argv[0], *sys.argv[1:]], harness.spec_loader)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
