"""python -m <package>.session_tool --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N]

The session conformance tool (docs/conformance.md section 8): reads command packets as canonical
JSON lines on stdin, runs them in order over the connection and prints one result line per
command; every other packet received (and every skip run) is printed as its canonical line, in
arrival order. Exit 0 when every line ran, 1 when a line was bad (reported on stderr with its
number and skipped), 2 for usage or connection errors.
"""

from __future__ import annotations

import os
import sys
from typing import Any, Dict, List, Optional

from . import registry
from .framing import Skip
from .packets import Packet
from .session import DEFAULT_TIMEOUT_MS, Device, Result, command_from_line
from .transport import TransportError, open_transport

PROG = f"{__package__}.session_tool"
USAGE = "usage: session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N]"


class UsageError(Exception):
    pass


def _int_option(name: str, text: str, low: int) -> int:
    if not text.isdigit() or int(text) < low:
        raise UsageError(f"{name} needs an integer >= {low}, not {text!r}")
    return int(text)


def _options(argv: List[str]) -> Dict[str, Any]:
    opts: Dict[str, Any] = {"connect": None, "timeout_ms": DEFAULT_TIMEOUT_MS, "device": None, "baud": 115200}
    i = 0
    while i < len(argv):
        a = argv[i]
        name, eq, value = a.partition("=")
        if name not in ("--connect", "--timeout-ms", "--device", "--baud"):
            raise UsageError(f"unknown argument {a!r}")
        if not eq:
            if i + 1 >= len(argv):
                raise UsageError(f"{name} needs a value")
            value = argv[i + 1]
            i += 1
        i += 1
        if name == "--connect":
            opts["connect"] = value
        elif name == "--timeout-ms":
            opts["timeout_ms"] = _int_option(name, value, 0)
        elif name == "--baud":
            opts["baud"] = _int_option(name, value, 1)
        else:
            if value not in registry.DEVICES:
                raise UsageError(f"unknown device {value!r} (one of: {', '.join(registry.DEVICES)})")
            opts["device"] = value
    if opts["connect"] is None:
        raise UsageError("--connect ADDRESS is required")
    return opts


def _print_event(e: Any) -> None:
    if isinstance(e, Result):
        print(e.line(e.tag), flush=True)
    elif isinstance(e, Skip):
        print('{"offset":' + str(e.offset) + ',"skipped":"' + e.data.hex() + '"}', flush=True)
    elif isinstance(e, Packet):
        print(e.line(), flush=True)


def run(argv: List[str]) -> int:
    opts = _options(argv)
    try:
        transport = open_transport(opts["connect"], opts["baud"])
    except (TransportError, ValueError) as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    device = Device(transport, opts["device"], opts["timeout_ms"], on_event=_print_event)
    status = 0
    try:
        for number, raw in enumerate(sys.stdin.buffer, 1):
            try:
                text = raw.decode("utf-8")
            except UnicodeDecodeError:
                print(f"{PROG}: line {number}: not UTF-8", file=sys.stderr)
                status = 1
                continue
            if not text.strip():
                continue
            try:
                command = command_from_line(text)
            except ValueError as e:
                print(f"{PROG}: line {number}: {e}", file=sys.stderr)
                status = 1
                continue
            p = device.session.start(command, device.now_ms(), tag=number)
            if p.packet:
                transport.write(p.packet)
            if p.result is not None:
                _print_event(p.result)
            while p.result is None:
                device.pump(max(0, (device.session.next_deadline() or p.deadline) - device.now_ms()))
        device.close()
    except TransportError as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    return status


def main(argv: Optional[List[str]] = None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    if "-h" in args or "--help" in args:
        print(USAGE)
        return 0
    try:
        return run(args)
    except UsageError as e:
        print(f"{PROG}: {e} ({USAGE})", file=sys.stderr)
        return 2
    except BrokenPipeError:
        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
        except OSError:
            pass
        return 0
    except KeyboardInterrupt:
        return 130


if __name__ == "__main__":
    sys.exit(main())
