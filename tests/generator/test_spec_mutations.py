"""Randomly damaged spec files produce located errors (or load), never a Python traceback.

Each run mutates the every-feature fixture line by line (delete, duplicate, swap, or edit a
token) with a seeded generator; the seed is in the test id so a failure can be replayed.
"""

import random
import shutil
from pathlib import Path

import pytest

from generator.diagnostics import SpecError, SpecErrors
from generator.spec import load_spec

FIXTURE = Path(__file__).parent / "fixtures" / "everything"
TOKENS = ["u8", "0x", "name", "type", "[", "]", "{", "}", "1", "e", ":", "-", "count", "selector"]
REPLACEMENTS = ["", "u16", "x", "Foo", "2", "[", "!!binary", "&a", "*a", "? "]


def _mutate(rng: random.Random, lines: list[str]) -> list[str]:
    i = rng.randrange(len(lines))
    op = rng.randrange(4)
    if op == 0:
        del lines[i]
    elif op == 1:
        lines[i] = lines[i].replace(rng.choice(TOKENS), rng.choice(REPLACEMENTS), 1)
    elif op == 2:
        lines.insert(i, lines[rng.randrange(len(lines))])
    else:
        j = rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    return lines


@pytest.mark.parametrize("seed", range(60))
def test_mutated_specs_never_traceback(tmp_path, seed):
    rng = random.Random(seed)
    for attempt in range(40):
        dst = tmp_path / f"spec{attempt}"
        shutil.copytree(FIXTURE, dst)
        f = rng.choice(sorted((dst / "demo").glob("*.yaml")))
        lines = f.read_text().splitlines()
        for _ in range(rng.randrange(1, 4)):
            lines = _mutate(rng, lines) or ["x"]
        f.write_text("\n".join(lines) + "\n")
        try:
            load_spec(dst, root=dst.parent)
        except SpecErrors as e:
            assert all(str(err).count(": error: ") == 1 for err in e.errors)
        except SpecError as e:
            assert ": error: " in str(e)
