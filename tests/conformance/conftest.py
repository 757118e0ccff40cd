"""pytest hooks of the cross-language suite: a test of one language (parametrized by `lang`) first
asks for that target's runner, so a registered target without one fails by name (never skips);
print the seed of the differential test.

The seed is DIFF_SEED when set, otherwise fresh for every session (differential.SEED); it is
printed in the report header, again at the end of the run (also under -q, where the header is
not shown), and in every failure message, with the command that replays it. A fresh seed is put
into DIFF_SEED before any pytest worker starts (`make test-conformance` runs the suite on `-n`
workers, pytest-xdist), so that every worker draws the seed the report prints.
"""

import os

import pytest

from tests.conformance.differential import SEED, replay_command
from tests.helpers.langs import runner

os.environ["DIFF_SEED"] = str(SEED)


def _line() -> str:
    return f"differential seed: {SEED} (replay: {replay_command(SEED)})"


def pytest_report_header(config):
    return _line()


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    """The seed again when a differential test ran (its reports reach the controller also when the
    tests ran on workers)."""
    reports = (r for rs in terminalreporter.stats.values() for r in rs)
    if any("test_differential.py" in str(getattr(r, "nodeid", "")) for r in reports):
        terminalreporter.write_line(_line())


@pytest.fixture(autouse=True)
def _target_has_a_runner(request):
    """Fails a test of a registered language that has no runner, naming it (tests/helpers/langs.py)."""
    callspec = getattr(request.node, "callspec", None)
    lang = callspec.params.get("lang") if callspec else None
    if isinstance(lang, str):
        runner(lang)
