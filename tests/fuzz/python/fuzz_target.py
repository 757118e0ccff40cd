"""Runs one Python fuzz target under atheris (libFuzzer flags and corpus directories follow):

    python -m tests.fuzz.python.fuzz_target PACKAGE TARGET [libFuzzer args...] [CORPUS_DIR...]

(from the project root, or with it on PYTHONPATH as tests/fuzz/fuzz.py runs it).

PACKAGE is mipcodec or mscipcodec, TARGET parser, decode or json (tests/fuzz/python/harness.py).
`make fuzz` / `make fuzz-long` call this through tests/fuzz/fuzz.py.
"""

from __future__ import annotations

import sys


def main() -> None:
    import atheris

    package, target = sys.argv[1], sys.argv[2]
    from tests.fuzz.python import harness

    with atheris.instrument_imports():
        harness.load(package)
    run = harness.TARGETS[target]

    def one_input(data: bytes) -> None:
        run(package, data)

    atheris.Setup([sys.argv[0], *sys.argv[3:]], one_input)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
