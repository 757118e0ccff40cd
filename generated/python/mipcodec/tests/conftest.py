"""Make the package importable when the tests run from a source checkout, and the generated case
modules of this folder (vector_cases.py, canonical_cases.py) importable by the plain test files."""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
for path in (HERE, ROOT):
    if path not in sys.path:
        sys.path.insert(0, path)
