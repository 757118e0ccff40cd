"""Command-line tools (docs/conformance.md section 5).

    python -m mipcodec decode [--device ID] [--samples] [FILE|-]   binary stream -> canonical JSON lines
    python -m mipcodec encode                         JSON lines on stdin -> bytes on stdout

decode: exit 0; usage or I/O errors: one line on stderr, exit 2.
encode: bad lines are reported on stderr with their line number and not written; exit 1 if any.
"""

from __future__ import annotations

import os
import sys
from typing import BinaryIO, List, Optional, Tuple, Union

from . import registry
from ._protocol import PACKAGE as PROG
from .codec import EncodeError
from .framing import Parser, RawPacket, Skip
from .packets import encode_line, event_line
from .samples import SampleTracker

USAGE = f"usage: python -m {PROG} decode [--device ID] [--samples] [FILE|-] | python -m {PROG} encode"
CHUNK = 1 << 16


class UsageError(Exception):
    pass


def _decode_args(args: List[str]) -> Tuple[Optional[str], Optional[str], bool]:
    device: Optional[str] = None
    path: Optional[str] = None
    samples = False
    i = 0
    while i < len(args):
        a = args[i]
        if a == "--samples":
            samples = True
        elif a == "--device":
            if i + 1 >= len(args):
                raise UsageError("--device needs a device id")
            device = args[i + 1]
            i += 2
            continue
        elif a.startswith("--device="):
            device = a[len("--device=") :]
        elif a == "-" or not a.startswith("-"):
            if path is not None:
                raise UsageError(f"unexpected argument {a!r}")
            path = a
        else:
            raise UsageError(f"unknown option {a!r}")
        i += 1
    if device is not None and device not in registry.DEVICES:
        raise UsageError(f"unknown device {device!r} (expected one of: {', '.join(registry.DEVICES)})")
    return device, path, samples


def _decode(args: List[str]) -> int:
    device, path, samples = _decode_args(args)
    if path is None or path == "-":
        source: BinaryIO = sys.stdin.buffer
        close = False
    else:
        try:
            source = open(path, "rb")
        except OSError as e:
            print(f"{PROG} decode: cannot open {path!r}: {e.strerror or e}", file=sys.stderr)
            return 2
        close = True
    out = sys.stdout
    parser = Parser()
    tracker = SampleTracker() if samples else None

    def line(event: Union[RawPacket, Skip]) -> str:
        text = event_line(event, device)
        placed = tracker.feed(event.data) if tracker is not None and isinstance(event, RawPacket) else None
        if placed is not None:
            at = text.index(',"fields":')
            text = text[:at] + ',"sample":' + str(placed[0]) + text[at:]
        return text

    read = getattr(source, "read1", source.read)  # read1: do not wait for a full chunk from a live stream
    try:
        while True:
            try:
                chunk = read(CHUNK)
            except OSError as e:
                print(f"{PROG} decode: cannot read {path or 'stdin'}: {e.strerror or e}", file=sys.stderr)
                return 2
            if not chunk:
                break
            for event in parser.feed(chunk):
                out.write(line(event) + "\n")
            out.flush()
        for event in parser.flush():
            out.write(line(event) + "\n")
        out.flush()
    finally:
        if close:
            source.close()
    return 0


def _encode(args: List[str]) -> int:
    if args:
        raise UsageError(f"encode takes no arguments (got {args[0]!r}); it reads JSON lines on stdin")
    out = sys.stdout.buffer
    status = 0
    for number, raw in enumerate(sys.stdin.buffer, start=1):
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError:
            print(f"line {number}: not UTF-8 text", file=sys.stderr)
            status = 1
            continue
        if not text.strip():
            continue  # blank lines carry nothing (as in the C, C++ and Rust encoders)
        try:
            data = encode_line(text)
        except EncodeError as e:
            print(f"line {number}: {e}", file=sys.stderr)
            status = 1
            continue
        out.write(data)
    out.flush()
    return status


def main(argv: Optional[List[str]] = None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    try:
        if not args:
            raise UsageError("missing command")
        command, rest = args[0], args[1:]
        if command in ("-h", "--help", "help"):
            print(USAGE)
            print(f"python -m {PROG} export|info|plot --help: recorded logs to tables, summaries and plots")
            return 0
        if command in ("export", "info", "plot"):
            from .tools import main as tools_main  # the user commands (optional libraries, see tools)

            return tools_main(args)
        if command == "decode":
            if "-h" in rest or "--help" in rest:
                print(USAGE)
                return 0
            return _decode(rest)
        if command == "encode":
            return _encode(rest)
        raise UsageError(f"unknown command {command!r}")
    except UsageError as e:
        print(f"{PROG}: {e} ({USAGE})", file=sys.stderr)
        return 2
    except BrokenPipeError:
        # The reader went away (e.g. `| head`): stop quietly.
        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
        except OSError:
            pass
        return 0
    except KeyboardInterrupt:
        return 130
