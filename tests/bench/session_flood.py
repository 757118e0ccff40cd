"""The session tools under a noise flood (issue 37): per language and flood kind, the peak memory
and the time past the command's deadline.

    python -m tests.bench.session_flood [--langs c,cpp,rust,python] [--timeout-ms 500]

For each language (the target registry) and each kind of noise of tests/conformance/noise_device.py
(zeros, random bytes, repeated false syncs), the tool runs one ping with `--timeout-ms` against a
loopback device that floods it as fast as the connection takes it (tests/conformance/noise_device.py).
Printed: the bytes the device sent, the tool's peak resident memory (VmHWM of its process tree when
the result came), the time from the deadline (the command's arrival at the device plus the timeout)
to the result line (negative: before; the tool started its clock earlier), the longest skip line
and the result. `make bench` runs it after the throughput benchmarks (tests/bench/run.py; its
--no-flood leaves it out). Exit status 1 when a tool printed no result or a line that is not JSON.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from tests.conformance.noise_device import NOISE_KINDS, FloodRun, run_flood
from tests.helpers.langs import langs as registry_langs

ROOT = Path(__file__).resolve().parents[2]
TOOL = ROOT / "tests" / "conformance" / "session"


def row(lang: str, run: FloodRun) -> dict:
    """One row of the table (also the JSON shape)."""
    return {
        "lang": lang,
        "flood": run.kind,
        "timeout_ms": run.timeout_ms,
        "sent_mib": round(run.sent / 2**20, 1),
        "peak_rss_mib": round(run.peak_rss_kib / 1024, 1),
        "ms_past_deadline": None if run.late_ms is None else round(run.late_ms),
        "longest_skip_line_bytes": max((n for _, n in run.skips), default=0),
        "result": (run.result or {}).get("result", "none"),
        "exit": run.exit_status,
        "ok": run.result is not None and not run.bad_lines,
    }


def table(rows: list[dict]) -> str:
    """A markdown table of the rows."""
    head = ("language", "flood", "MiB sent", "peak RSS MiB", "ms past deadline", "longest skip line", "result")
    lines = [head] + [
        (
            r["lang"],
            r["flood"],
            f"{r['sent_mib']:.1f}",
            f"{r['peak_rss_mib']:.1f}",
            "-" if r["ms_past_deadline"] is None else str(r["ms_past_deadline"]),
            str(r["longest_skip_line_bytes"]),
            r["result"],
        )
        for r in rows
    ]
    widths = [max(len(line[i]) for line in lines) for i in range(len(head))]
    out = []
    for k, line in enumerate(lines):
        cells = [c.ljust(w) if i in (0, 1, 6) else c.rjust(w) for i, (c, w) in enumerate(zip(line, widths))]
        out.append("| " + " | ".join(cells) + " |")
        if k == 0:
            out.append("|" + "|".join("-" * (w + 2) for w in widths) + "|")
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    import subprocess

    from generator.spec import load_spec

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--langs", default=",".join(registry_langs()), help="comma-separated languages")
    ap.add_argument("--timeout-ms", type=int, default=500, help="the ping's --timeout-ms")
    ap.add_argument("--json", help="also write the rows there")
    args = ap.parse_args(argv)
    chosen = [x for x in args.langs.split(",") if x]
    unknown = [x for x in chosen if x not in registry_langs()]
    if unknown:
        ap.error(f"unknown language(s) {','.join(unknown)}")
    framing = next(p for p in load_spec()["protocols"] if p["name"] == "mip")["framing"]
    rows = []
    for lang in chosen:
        # build first (a build would hold the connection back)
        subprocess.run([str(TOOL), lang, "--help"], capture_output=True, timeout=900)
        for kind in NOISE_KINDS:
            rows.append(row(lang, run_flood(lang, kind, args.timeout_ms, framing)))
            print(f"session-flood: {lang} {kind}: done", file=sys.stderr, flush=True)
    print(f"Session tools under a noise flood (issue 37): one ping, --timeout-ms {args.timeout_ms}\n")
    print(table(rows))
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1) + "\n")
    return 0 if all(r["ok"] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
