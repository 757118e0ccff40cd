"""The case module that package_tests/test_canonical.py imports, for the test package: the table of
generator/testcases.py, as the generated tests/canonical_cases.py of every package holds it."""

from testproto import canonical

from generator.testcases import canonical_cases

__all__ = ["ALL_BYTES", "DOUBLES", "FLOATS", "canonical"]

_CASES = canonical_cases()
DOUBLES = [(c.bits, c.text) for c in _CASES.doubles]
FLOATS = [(c.bits, c.text) for c in _CASES.floats]
ALL_BYTES = _CASES.all_bytes
