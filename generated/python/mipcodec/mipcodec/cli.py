"""Command-line tools (docs/conformance.md section 5).

    python -m mipcodec decode [--device ID] [--samples] [FILE|-]   binary stream -> canonical JSON lines
    python -m mipcodec encode                         JSON lines on stdin -> bytes on stdout

decode: exit 0; usage or I/O errors: one line on stderr, exit 2.
encode: bad lines are reported on stderr with their line number and not written; exit 1 if any.

I/O faults, the same in the four languages: a closed pipe on stdout (`decode BIG | head`) ends
the process by SIGPIPE, quietly, as the C tools and `cat` do; any other read or write error
(a full disk, an unreadable file, a directory, a closed stdin) is one line on stderr and exit 2,
never a traceback. Input is read in blocks as it arrives; when stdout is not a regular file, the
lines of every block are flushed at once (a live stream shows each packet when it arrives).
Without --device and --samples the lines come from `LineDecoder`, printed in C when the
accelerator is built (the same text as the pure path, which prints them otherwise).
"""

from __future__ import annotations

import errno
import os
import stat
import sys
from typing import BinaryIO, Iterable, List, Optional, Tuple

from . import registry
from ._protocol import PACKAGE as PROG
from .codec.framing import Event, Parser, RawPacket
from .codec.layout import EncodeError
from .codec.packets import LineDecoder, encode_line, event_line
from .codec.samples import SampleTracker
from .codec.stdio import closed_stdout, flushed, silence_stdout

USAGE = f"usage: python -m {PROG} decode [--device ID] [--samples] [FILE|-] | python -m {PROG} encode"
CHUNK = 1 << 16


class UsageError(Exception):
    pass


class IOFailure(Exception):
    """An I/O error already worded for stderr (exit status 2); `write`: stdout failed."""

    def __init__(self, message: str, write: bool = False) -> None:
        super().__init__(message)
        self.write = write


def _reason(e: OSError) -> str:
    return e.strerror or str(e)


def _stdin() -> BinaryIO:
    """The standard input's byte stream; a closed descriptor is an error (not an empty input)."""
    if sys.stdin is None:
        raise IOFailure(f"cannot read standard input: {os.strerror(errno.EBADF)}")
    return sys.stdin.buffer


def _stdout() -> BinaryIO:
    if sys.stdout is None:
        raise IOFailure(f"cannot write standard output: {os.strerror(errno.EBADF)}", write=True)
    return sys.stdout.buffer


def _read_some(stream: BinaryIO, size: int) -> bytes:
    """What the stream has now, up to size bytes, without waiting for more (read1 where the
    stream is buffered, as sys.stdin.buffer is)."""
    read1 = getattr(stream, "read1", None)
    data: bytes = read1(size) if read1 is not None else stream.read(size)
    return data


def _is_regular_file(stream: BinaryIO) -> bool:
    try:
        return stat.S_ISREG(os.fstat(stream.fileno()).st_mode)
    except (OSError, ValueError):
        return False


def _write_failed(e: OSError) -> IOFailure:
    """A write to stdout failed: a closed pipe ends the process by SIGPIPE (codec.stdio); otherwise
    the one line."""
    if e.errno == errno.EPIPE:
        closed_stdout()
    return IOFailure(f"cannot write standard output: {_reason(e)}", write=True)


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
        source: BinaryIO = _stdin()
        name = "standard input"
        close = False
    else:
        try:
            source = open(path, "rb")
        except OSError as e:
            raise IOFailure(f"cannot open {path!r}: {_reason(e)}") from None
        name = repr(path)
        close = True
    out = _stdout()
    flush_blocks = not _is_regular_file(out)
    parser = Parser()
    tracker = SampleTracker() if samples else None

    def line(event: Event) -> str:
        text = event_line(event, device)
        placed = tracker.feed(event.data) if tracker is not None and isinstance(event, RawPacket) else None
        if placed is not None:
            at = text.index(',"fields":')
            text = text[:at] + ',"sample":' + str(placed[0]) + text[at:]
        return text

    def put(data: bytes) -> None:
        try:
            out.write(data)
            if flush_blocks:
                out.flush()
        except OSError as e:
            raise _write_failed(e) from None

    def write(events: Iterable[Event]) -> None:
        put("".join(line(event) + "\n" for event in events).encode("ascii"))

    # The plain decode (no device, no sample numbers) prints its lines in C when it can.
    lines = LineDecoder() if device is None and tracker is None else None

    read = getattr(source, "read1", source.read)  # read1: do not wait for a full chunk from a live stream
    try:
        while True:
            try:
                chunk = read(CHUNK)
            except OSError as e:
                try:
                    out.flush()  # the lines printed before the fault are kept
                except OSError as w:
                    raise _write_failed(w) from None
                raise IOFailure(f"cannot read {name}: {_reason(e)}") from None
            if not chunk:
                break
            if lines is not None:
                put(lines.feed(chunk))
            else:
                write(parser.feed(chunk))
        if lines is not None:
            put(lines.flush())
        else:
            write(parser.flush())
        try:
            out.flush()
        except OSError as e:
            raise _write_failed(e) from None
    finally:
        if close:
            source.close()
    return 0


def _blank(text: str) -> bool:
    """RFC 8259 whitespace only (space, tab, CR, LF), as in the four encoders."""
    return not text.strip(" \t\r\n")


def _encode(args: List[str]) -> int:
    if args:
        raise UsageError(f"encode takes no arguments (got {args[0]!r}); it reads JSON lines on stdin")
    source = _stdin()
    out = _stdout()
    flush_blocks = not _is_regular_file(out)
    status = 0
    number = 0
    pending = b""
    while True:
        try:
            chunk = _read_some(source, CHUNK)
        except OSError as e:
            try:
                out.flush()  # the bytes written before the fault are kept
            except OSError as w:
                raise _write_failed(w) from None
            raise IOFailure(f"cannot read standard input: {_reason(e)}") from None
        lines = (pending + chunk).split(b"\n")
        pending = lines.pop() if chunk else b""
        if not chunk and not lines[-1]:
            lines.pop()  # the input ended with a newline (or was empty)
        data = []
        for raw in lines:
            number += 1
            try:
                text = raw.decode("utf-8")
            except UnicodeDecodeError:
                print(f"line {number}: not UTF-8 text", file=sys.stderr)
                status = 1
                continue
            if _blank(text):
                continue  # blank lines carry nothing (as in the C, C++ and Rust encoders)
            try:
                data.append(encode_line(text))
            except EncodeError as e:
                print(f"line {number}: {e}", file=sys.stderr)
                status = 1
        try:
            out.write(b"".join(data))
            if flush_blocks or not chunk:
                out.flush()
        except OSError as e:
            raise _write_failed(e) from None
        if not chunk:
            return status


def main(argv: Optional[List[str]] = None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    try:
        if not args:
            raise UsageError("missing command")
        command, rest = args[0], args[1:]
        if command in ("-h", "--help", "help"):
            print(USAGE)
            print(
                f"python -m {PROG} export|info|plot|query --help: recorded logs to tables, summaries and plots; SQL on datasets"
            )
            print(f"python -m {PROG} device ADDRESS SUBCOMMAND (--help): look at, stream from and configure a device")
            return flushed(0)
        if command == "device":
            from .device.cli import main as device_main  # the device command line (docs/configure-a-device.md)

            return flushed(device_main(rest))
        if command in ("export", "info", "plot", "query"):
            from .logs.commands import main as tools_main  # the user commands (optional libraries, see logs)

            return flushed(tools_main(args))
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
    except IOFailure as e:
        if e.write:
            silence_stdout()
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # stdout closed by its reader (`info LOG | head`): quietly, by SIGPIPE
        return closed_stdout()
    except KeyboardInterrupt:
        return 130
