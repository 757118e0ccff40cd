"""`python -m generator.targets`: the registered language targets, one line, space-separated (the
Makefile's LANGS; `mipgen targets` prints the same). Needs nothing beyond the standard library."""

from . import NAMES

print(" ".join(NAMES))
