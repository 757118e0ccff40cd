"""A pytest plugin for tests/generator/test_targets.py: registers a fifth language target 'toy'
(in the registry only: no back end, no runner) before collection, as a new language looks before
its wing and runner exist. `python -m pytest -p tests.helpers.toy_target ...`."""

from __future__ import annotations

import generator.targets

TOY = "toy"


def pytest_configure(config) -> None:
    if TOY not in generator.targets.NAMES:
        generator.targets.NAMES = (*generator.targets.NAMES, TOY)
