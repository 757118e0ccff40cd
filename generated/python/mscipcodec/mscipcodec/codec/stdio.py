"""Standard output closed by its reader (`python -m mscipcodec info LOG | head`), for every command
line of the package: the process ends quietly by SIGPIPE, as the C tools, `cat` and the decode tool
do (docs/conformance.md section 5, "I/O faults"): no message, no traceback, and the shell sees
that the writer did not finish (status 141).

Python ignores SIGPIPE at start-up, so a write to a closed pipe raises BrokenPipeError instead; a
command line catches it at its top and calls `closed_stdout()`. A pipe's output is block-buffered:
a command line flushes it (`flushed`) inside its handlers, else the write would fail only at the
interpreter's exit, where nothing catches it.
"""

from __future__ import annotations

import os
import signal
import sys


def silence_stdout() -> None:
    """Further output goes to the null device: after a failed write, the interpreter's last flush
    of stdout must not fail again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, AttributeError, ValueError):
        pass


def flushed(status: int) -> int:
    """status, after stdout is flushed (a closed pipe raises BrokenPipeError here)."""
    sys.stdout.flush()
    return status


def closed_stdout() -> int:
    """A write to stdout failed with EPIPE: ends the process by SIGPIPE (its default action
    restored, the signal raised). Where the system has no SIGPIPE, stdout goes to the null device
    and the status to exit with is returned (1: the output was cut short)."""
    silence_stdout()
    if hasattr(signal, "SIGPIPE"):
        signal.signal(signal.SIGPIPE, signal.SIG_DFL)
        os.kill(os.getpid(), signal.SIGPIPE)
    return 1


__all__ = ["closed_stdout", "flushed", "silence_stdout"]
