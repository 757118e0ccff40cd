"""pytest hooks of the cross-language suite: a test of one language (parametrized by `lang`) first
asks for that target's runner, so a registered target without one fails by name (never skips);
print the seed of the differential test.

The seed is DIFF_SEED when set, otherwise fresh for every session (differential.SEED); it is
printed in the report header, again at the end of the run (also under -q, where the header is
not shown), and in every failure message, with the command that replays it.
"""

import pytest

from tests.conformance.differential import SEED, replay_command
from tests.helpers.langs import runner

_RAN = []


def _line() -> str:
    return f"differential seed: {SEED} (replay: {replay_command(SEED)})"


def pytest_report_header(config):
    return _line()


def pytest_collection_modifyitems(session, config, items):
    _RAN.extend(i for i in items if i.nodeid.split("::")[0].endswith("test_differential.py"))


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    if _RAN:
        terminalreporter.write_line(_line())


@pytest.fixture(autouse=True)
def _target_has_a_runner(request):
    """Fails a test of a registered language that has no runner, naming it (tests/helpers/langs.py)."""
    callspec = getattr(request.node, "callspec", None)
    lang = callspec.params.get("lang") if callspec else None
    if isinstance(lang, str):
        runner(lang)
