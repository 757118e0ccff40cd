"""Child processes a test stops as a user does."""

from __future__ import annotations

import signal


def as_in_a_terminal() -> None:
    """`preexec_fn` of a child the test stops with SIGINT, as Ctrl-C in a terminal does: SIGINT at
    its default in the child. A test run started in the background of a non-interactive shell
    (`.ci/run &`, nohup) has SIGINT ignored, and so have pytest-xdist's workers; a child inherits
    that, and Python then keeps it ignored (no KeyboardInterrupt: the command would run on, as a
    background job should)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
