"""Prints what each step of the consumer tests took and the sizes of the built artifacts."""

from __future__ import annotations

from typing import Any

from tests.consumer.test_python_package import OUT, TIMINGS


def pytest_terminal_summary(terminalreporter: Any, exitstatus: int, config: Any) -> None:
    if not TIMINGS:
        return
    terminalreporter.write_line("consumer test timings and artifacts:")
    for what, seconds in TIMINGS.items():
        terminalreporter.write_line(f"  {seconds:6.1f} s  {what}")
    for f in sorted(OUT.glob("*/dist*/*")):
        terminalreporter.write_line(f"  {f.stat().st_size:9,d} B  {f.relative_to(OUT)}")
