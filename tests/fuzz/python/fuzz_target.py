"""Runs one Python fuzz target under atheris (libFuzzer flags and corpus directories follow):

    python tests/fuzz/python/fuzz_target.py PACKAGE TARGET [libFuzzer args...] [CORPUS_DIR...]

PACKAGE is mipcodec or mscipcodec, TARGET parser, decode or json (tests/fuzz/python/harness.py).
`make fuzz` / `make fuzz-long` call this through tests/fuzz/fuzz.py.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))


def main() -> None:
    import atheris

    package, target = sys.argv[1], sys.argv[2]
    import harness

    with atheris.instrument_imports():
        harness.load(package)
    run = harness.TARGETS[target]

    def one_input(data: bytes) -> None:
        run(package, data)

    atheris.Setup([sys.argv[0], *sys.argv[3:]], one_input)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
