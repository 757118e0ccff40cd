"""The rendered test package's own tests/test_canonical.py (package_tests/test_canonical.py with the
generated tests/canonical_cases.py beside it) run in place on the test package."""

import sys

from conftest import OUT

sys.path.insert(0, str(OUT / "tests"))

from test_canonical import *  # noqa: E402, F403
