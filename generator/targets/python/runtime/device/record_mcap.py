"""The recorder into an MCAP file (docs/mcap.md, "Recording"): `<package>-device ADDRESS record
FILE.mcap [--duration S]`.

The device's bytes are recorded as by `record FILE` (record.py: the Device Information reply
first, whole packets, the same stop rules) into a log beside FILE (`.FILE.part-PID.bin`); when the
recording ends, that log goes through the MCAP export (logs/mcap.py: the log's device, the time
model over the whole log, so that packets before the first GPS time are timed as `export` times
them), written under a temporary name and renamed to FILE when finished; the log is then removed.
So Ctrl-C, SIGTERM, a vanished device or a full disk during the recording leave a whole, readable
FILE.mcap of what was recorded; if the MCAP cannot be written (a full disk, Ctrl-C while it is
written), no FILE.mcap is left and the recording is kept as FILE-stem.bin (named on stderr),
nothing lost. `--split-size`/`--split-time` are for raw logs only.

Exit status: the recorder's (0 stopped, 1 no answer / device gone, 2 trouble), and 2 when the
MCAP cannot be written.
"""

from __future__ import annotations

import os
import sys
from typing import Callable, Optional

from .._protocol import PACKAGE

PROG = f"{PACKAGE}-device"


def _note(text: str) -> None:
    print(f"{PROG}: {text}", file=sys.stderr, flush=True)


def _keep(raw: str, path: str) -> str:
    """Moves the recorded log to FILE-stem.bin (or .NNN.bin if taken); returns its name."""
    stem = os.path.splitext(path)[0]
    for i in range(1000):
        name = f"{stem}.bin" if i == 0 else f"{stem}.{i:03d}.bin"
        if not os.path.lexists(name):
            os.replace(raw, name)
            return name
    return raw


TROUBLE = 2  # record.py's status of a usage error or a failed write (docs/record.md)


def record_mcap(
    raw_recorder: Callable[..., int],
    address: str,
    path: str,
    baud: int,
    timeout_ms: int,
    duration: Optional[float] = None,
    split_size: float = 0,
    split_time: float = 0.0,
) -> int:
    """Records into FILE.mcap through `raw_recorder` (record.py's `record`, which calls this for a
    FILE ending in .mcap: passed in, not imported, so the two modules import no circle)."""
    from .._extras import need
    from ..logs import mcap, ros
    from ..logs.writers import Outputs, ToolError

    if split_size or split_time:
        _note("record: --split-size and --split-time write raw logs, not FILE.mcap")
        return TROUBLE
    try:
        need("mcap.writer", "mcap")
    except ImportError as e:  # one line naming the library and the extra
        _note(f"record: {e}")
        return TROUBLE
    if os.path.lexists(path):
        _note(f"cannot create {path}: exists")
        return TROUBLE
    head, tail = os.path.split(path)
    raw = os.path.join(head, f".{tail}.part-{os.getpid()}.bin")
    status = raw_recorder(address, raw, baud, timeout_ms, duration)
    if not os.path.exists(raw):
        return status
    outputs = Outputs(force=False)
    try:
        counts, tally = mcap.write_mcap(raw, path, None, ros.Topics(), outputs, progress=False)
        outputs.commit()
    except BaseException as e:  # a full disk, Ctrl-C, anything: no partial FILE.mcap, the log kept
        outputs.abort()
        kept = _keep(raw, path)
        why = "interrupted" if isinstance(e, KeyboardInterrupt) else (getattr(e, "strerror", None) or str(e))
        _note(f"cannot write {path}: {why}; the recording is kept in {kept}")
        if not isinstance(e, (OSError, ToolError, KeyboardInterrupt)):
            raise
        return TROUBLE
    os.unlink(raw)
    _note(f"{path}: {sum(counts.values())} messages on {len(counts)} topics ({tally})")
    return status


__all__ = ["record_mcap"]
