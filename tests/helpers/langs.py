"""The languages every cross-language test runs: the target registry (generator/targets/__init__.py
NAMES), never a list of its own, so that a target added there runs through every shared suite.

Each target has a runner, tests/lang/<lang>.sh (build, test, decode, encode, session, ...), which
tests/conformance/decode, encode and session call. A registered target without one fails the
tests that need it, by name (runner(); test_every_target_has_a_runner), rather than being skipped.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import generator.targets

ROOT = Path(__file__).resolve().parents[2]
RUNNERS = ROOT / "tests" / "lang"


def langs() -> list[str]:
    """The registered language targets, in the registry's order."""
    return list(generator.targets.NAMES)


def runner_path(lang: str) -> Path:
    return RUNNERS / f"{lang}.sh"


def missing_runner(lang: str) -> str | None:
    """Why lang cannot run (its runner is missing or not executable), or None."""
    path = runner_path(lang)
    if not path.is_file():
        return (
            f"target '{lang}' is registered (generator/targets/__init__.py) but has no runner "
            f"{path.relative_to(ROOT)} (build/test/decode/encode/session; docs/design.md, adding a language)"
        )
    if not path.stat().st_mode & 0o111:
        return f"target '{lang}': its runner {path.relative_to(ROOT)} is not executable"
    return None


def runner(lang: str) -> Path:
    """The runner of a registered target; fails the calling test (never skips it) when it has none."""
    if lang not in langs():
        pytest.fail(f"'{lang}' is not a registered target (generator/targets/__init__.py: {', '.join(langs())})")
    why = missing_runner(lang)
    if why:
        pytest.fail(why)
    return runner_path(lang)


LANGS = langs()  # for @pytest.mark.parametrize: the registry as the test module is collected
