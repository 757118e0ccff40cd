"""tests/bench/session_flood.py's table and rows on synthetic runs (the figures themselves come
from `make bench`; the bounds are tests/conformance/test_session_robust.py)."""

from __future__ import annotations

from tests.bench.session_flood import row, table
from tests.conformance.noise_device import FloodRun


def test_row_and_table():
    run = FloodRun("zeros", 500, exit_status=0, result={"line": 1, "result": "timeout"}, late_ms=3.4)
    run.sent, run.peak_rss_kib, run.skips = 3 * 2**20, 20480, [(0, 65536), (65536, 100)]
    r = row("python", run)
    assert r["sent_mib"] == 3.0 and r["peak_rss_mib"] == 20.0 and r["ms_past_deadline"] == 3
    assert r["longest_skip_line_bytes"] == 65536 and r["result"] == "timeout" and r["ok"]
    none = row("c", FloodRun("random", 500))
    assert none["result"] == "none" and not none["ok"] and none["ms_past_deadline"] is None
    lines = table([r, none]).splitlines()
    assert lines[0].startswith("| language | flood ") and set(lines[1]) <= {"|", "-"}
    assert lines[2].split("|")[1:-1] == [
        " python   ",
        " zeros  ",
        "      3.0 ",
        "         20.0 ",
        "                3 ",
        "             65536 ",
        " timeout ",
    ]
    assert "|                - |" in lines[3] and lines[3].endswith("| none    |")
