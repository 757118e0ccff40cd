"""package_tests/test_canonical.py (copied into every package's tests/) run in place on the test
package, with canonical_cases.py of this folder."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "package_tests"))

from test_canonical import *  # noqa: E402, F403
