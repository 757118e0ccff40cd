"""python -m <package>.session_tool --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N]
    [--auto-baud] [--reconnect-ms N]

The session conformance tool (docs/conformance.md section 8): reads command packets as canonical
JSON lines on stdin, runs them in order over the connection and prints one result line per
command; every other packet received (and every skip run) is printed as its canonical line, in
arrival order. Exit 0 when every line ran, 1 when a line was bad (reported on stderr with its
number and skipped), 2 for usage or connection errors. Getting through (section 8): `--auto-baud`
finds the baud rate at connect, `--reconnect-ms N` reopens a lost port, the lines
`{"link":"idle"}` and `{"link":"listen","ms":M}` get to idle and receive for a while; every
`link: ...` step goes to stderr.
"""

from __future__ import annotations

import json
import sys
from typing import Any, Dict, Iterator, List, Optional, Tuple

from . import _link, registry
from .codec.canonical import foreign_line
from .codec.framing import Nmea, Rtcm, Skip
from .codec.packets import Packet
from .codec.stdio import silence_stdout
from .session import DEFAULT_TIMEOUT_MS, Device, LinkError, Result, SessionError, command_from_line
from .session.transport import TransportError, open_transport

PROG = f"{__package__}.session_tool"
USAGE = "usage: session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud] [--reconnect-ms N]"


class UsageError(Exception):
    pass


MAX_LINE = 1048576  # an input line longer than this (without its newline) is a bad line
_BLANK = " \t\r\n"  # RFC 8259 whitespace: a line of only these is blank
_DIGITS = frozenset("0123456789")


def _ranged(name: str, text: str, low: int, high: int) -> int:
    """A decimal integer of ASCII digits only (leading zeros accepted) from low to high."""
    digits = text.lstrip("0") or "0"
    if not text or not set(text) <= _DIGITS or len(digits) > len(str(high)) or not low <= int(digits) <= high:
        raise UsageError(f"{name}: expected an integer from {low} to {high}, got {text}")
    return int(digits)


def _baud(text: str) -> int:
    """One of the protocol's baud rates (the IR's link.baud_rates of every model)."""
    rates = sorted({r for rs in _link.BAUD_RATES.values() for r in rs})
    digits = text.lstrip("0") or "0"
    if not text or not set(text) <= _DIGITS or len(digits) > 10 or int(digits) not in rates:
        listed = ", ".join(map(str, rates))
        raise UsageError(f"--baud: {text} is not a baud rate of {_link.PROTOCOL} devices ({listed})")
    return int(digits)


def _options(argv: List[str]) -> Dict[str, Any]:
    opts: Dict[str, Any] = {
        "connect": None,
        "timeout_ms": DEFAULT_TIMEOUT_MS,
        "device": None,
        "baud": 115200,
        "auto_baud": False,
        "reconnect_ms": None,
    }
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == "--auto-baud":
            opts["auto_baud"] = True
            i += 1
            continue
        name, eq, value = a.partition("=")
        if name not in ("--connect", "--timeout-ms", "--device", "--baud", "--reconnect-ms"):
            raise UsageError(f"unknown argument {a!r} ({USAGE})")
        if not eq:
            if i + 1 >= len(argv):
                if name == "--connect":
                    raise UsageError("--connect ADDRESS is required")
                raise UsageError(f"{name} needs a value ({USAGE})")
            value = argv[i + 1]
            i += 1
        i += 1
        if name == "--connect":
            opts["connect"] = value
        elif name == "--timeout-ms":
            opts["timeout_ms"] = _ranged(name, value, 1, 600000)
        elif name == "--baud":
            opts["baud"] = _baud(value)
        elif name == "--reconnect-ms":
            opts["reconnect_ms"] = _ranged(name, value, 1, 3600000)
        else:
            if value not in registry.DEVICES:
                raise UsageError(f"unknown device {value!r} (one of: {', '.join(registry.DEVICES)}) ({USAGE})")
            opts["device"] = value
    if opts["connect"] is None:
        raise UsageError("--connect ADDRESS is required")
    return opts


def _lines(stream: Any) -> Iterator[Tuple[int, Optional[bytes]]]:
    """(number, line without its newline) for each input line, 1-based; None for a line longer
    than MAX_LINE bytes, read past in pieces (never more than MAX_LINE + 1 bytes held)."""
    number = 0
    while True:
        raw = stream.readline(MAX_LINE + 1)
        if not raw:
            return
        number += 1
        if raw.endswith(b"\n"):
            yield number, raw[:-1]
            continue
        if len(raw) <= MAX_LINE:
            yield number, raw  # the last line, without a newline
            continue
        while True:  # too long: read past the rest of it
            rest = stream.readline(MAX_LINE + 1)
            if not rest or rest.endswith(b"\n"):
                break
        yield number, None


def _print_event(e: Any) -> None:
    if isinstance(e, Result):
        print(e.line(e.tag), flush=True)
    elif isinstance(e, Skip):
        print('{"offset":' + str(e.offset) + ',"skipped":"' + e.data.hex() + '"}', flush=True)
    elif isinstance(e, Packet):
        print(e.line(), flush=True)
    elif isinstance(e, (Nmea, Rtcm)):
        print(foreign_line(e.offset, e.data), flush=True)


def run(argv: List[str]) -> int:
    opts = _options(argv)
    try:
        transport = open_transport(opts["connect"], opts["baud"])
    except (TransportError, ValueError) as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    address, baud = opts["connect"], opts["baud"]
    device = Device(
        transport,
        opts["device"],
        opts["timeout_ms"],
        on_event=_print_event,
        log=_log,
        reopen=lambda: open_transport(address, baud),
        address=address,
        reconnect_ms=opts["reconnect_ms"],
    )
    status = 0
    try:
        if opts["auto_baud"]:
            device.find_baud()
        for number, raw in _lines(sys.stdin.buffer):
            if raw is None:
                print(f"{PROG}: line {number}: longer than {MAX_LINE} bytes", file=sys.stderr)
                status = 1
                continue
            try:
                text = raw.decode("utf-8")  # strict: RFC 3629 (no surrogates, no overlong forms)
            except UnicodeDecodeError:
                print(f"{PROG}: line {number}: not UTF-8", file=sys.stderr)
                status = 1
                continue
            if not text.strip(_BLANK):
                continue
            link = _link_line(text)
            if link is not None:
                if link[0] == "idle":
                    try:
                        result = device.to_idle()
                    except LinkError as e:
                        last = getattr(e, "result", None)
                        if last is None:
                            raise
                        result = last
                    except SessionError as e:  # a NACK
                        result = e.result  # type: ignore[attr-defined]
                    print(result.line(number), flush=True)
                elif link[0] == "listen":
                    device.listen(link[1])
                    print('{"line":' + str(number) + ',"listened":' + str(link[1]) + "}", flush=True)
                else:
                    print(f"{PROG}: line {number}: {link[1]}", file=sys.stderr)
                    status = 1
                continue
            try:
                command = command_from_line(text)
            except ValueError as e:
                print(f"{PROG}: line {number}: {e}", file=sys.stderr)
                status = 1
                continue
            p = device.start(command, tag=number)
            if p.result is not None and p.result.status in ("refused", "sent"):
                _print_event(p.result)  # complete at once (a lost one was printed as an event)
            while p.result is None:
                device.pump(max(0, (device.session.next_deadline() or p.deadline) - device.now_ms()))
            device.record(p.command, p.result)
            if p.result.note:  # the first unknown-command NACK: the connected model is another one
                print(f"{PROG}: {p.result.note}", file=sys.stderr, flush=True)
        device.close()
    except (TransportError, LinkError) as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    return status


def _log(line: str) -> None:
    print(line, file=sys.stderr, flush=True)


def _link_line(text: str) -> Optional[Tuple[str, Any]]:
    """("idle", None) or ("listen", ms) for a link line, ("bad", why) for a malformed one, None
    for anything else (a command line)."""
    if '"link"' not in text:
        return None
    try:
        value = json.loads(text)
    except ValueError:
        return None
    if not isinstance(value, dict) or "link" not in value:
        return None
    if value == {"link": "idle"}:
        return ("idle", None)
    ms = value.get("ms")
    if value.get("link") == "listen" and set(value) == {"link", "ms"}:
        if type(ms) is int and 0 <= ms <= 3600000:
            return ("listen", ms)
        return ("bad", '"ms" must be an integer from 0 to 3600000')
    return ("bad", 'expected {"link":"idle"} or {"link":"listen","ms":M}')


def main(argv: Optional[List[str]] = None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    if "-h" in args or "--help" in args:
        print(USAGE)
        return 0
    try:
        return run(args)
    except UsageError as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        silence_stdout()
        return 0
    except KeyboardInterrupt:
        return 130


if __name__ == "__main__":
    sys.exit(main())
