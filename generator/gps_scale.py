"""The GPS time scale every protocol's packages read: spec/common/gps_time.yaml (`gps_time_scale`:
`epoch_unix_s`, the GPS epoch in Unix seconds; `leap_seconds`, rows `[unix_s, gps_minus_utc_s]` in
increasing order of both; `sources`). Checked here with located errors, then put into each
protocol's IR as `time.gps_scale` = {"epoch_unix_s": int, "leap_seconds": [[int, int], ...]}.

A spec directory with a `common/` directory of its own reads its `gps_time.yaml`; one without it
(the tiny test specs) reads the project's spec/common/gps_time.yaml, so the facts have one home."""

from __future__ import annotations

import os
from pathlib import Path

from .diagnostics import SpecError, SpecErrors
from .resources import ROOT
from .yamlpos import load

COMMON = "common"  # the spec root's directory of protocol-independent facts (not a protocol)
FILE = "gps_time.yaml"


def common_file(spec_dir: Path, root: Path = ROOT) -> tuple[Path, Path]:
    """The gps_time.yaml a spec directory reads, with the root its displayed name is relative to."""
    own = Path(spec_dir) / COMMON / FILE
    if own.is_file():
        return own, root
    return ROOT / "spec" / COMMON / FILE, ROOT


def load_gps_scale(spec_dir: Path, root: Path = ROOT) -> dict:
    """The checked `time.gps_scale` IR entry; raises SpecErrors naming each problem where it is."""
    path, base = common_file(spec_dir, root)
    shown = os.path.relpath(path, base)
    data, locate = load(str(path), shown)
    errors: list[SpecError] = []

    def bad(where: tuple, message: str, expected: str) -> None:
        errors.append(SpecError(locate(where), message, expected))

    scale = data.get("gps_time_scale") if isinstance(data, dict) else None
    if not isinstance(scale, dict):
        raise SpecErrors(
            [SpecError(locate(()), "no gps_time_scale mapping", "gps_time_scale: {epoch_unix_s, leap_seconds}")]
        )
    unknown = sorted(set(scale) - {"epoch_unix_s", "leap_seconds", "sources"})
    for key in unknown:
        bad(("gps_time_scale", key), f"unknown key {key!r}", "epoch_unix_s, leap_seconds, sources")
    epoch = scale.get("epoch_unix_s")
    if not _is_int(epoch) or epoch <= 0:
        bad(("gps_time_scale", "epoch_unix_s"), f"epoch_unix_s {epoch!r}", "a positive integer (Unix seconds)")
    rows = scale.get("leap_seconds")
    table: list[list[int]] = []
    if not isinstance(rows, list) or not rows:
        bad(("gps_time_scale", "leap_seconds"), "leap_seconds is not a list of rows", "rows [unix_s, gps_minus_utc_s]")
        rows = []
    for i, row in enumerate(rows):
        where = ("gps_time_scale", "leap_seconds", i)
        if not (isinstance(row, list) and len(row) == 2 and all(_is_int(v) for v in row)):
            bad(where, f"row {row!r}", "[unix_s, gps_minus_utc_s], two integers")
            continue
        if table and (row[0] <= table[-1][0] or row[1] <= table[-1][1]):
            bad(where, f"row {row} does not follow {table[-1]}", "rows in increasing order of time and of offset")
        if _is_int(epoch) and row[0] <= epoch:
            bad(where, f"row {row} is not after the GPS epoch {epoch}", "a leap second after the epoch")
        table.append(list(row))
    if errors:
        raise SpecErrors(errors)
    return {"epoch_unix_s": epoch, "leap_seconds": table}


def _is_int(v: object) -> bool:
    return isinstance(v, int) and not isinstance(v, bool)
