"""User commands for recorded logs: export to tables, summarise, plot (`python -m mipcodec export|info|plot`).

    python -m mipcodec export LOG --format csv|jsonl|parquet --out DIR [--join] [--fields F,..]
                                  [--enum-numbers] [--device ID] [--follow [--idle S]] [--force]
    python -m mipcodec export --dataset DIR LOG... [--split-bytes N] [--model NAME] [--serial SN]
    python -m mipcodec info LOG [--device ID]
    python -m mipcodec plot LOG --fields F,.. --out FILE.png|svg|html [--device ID] [--force]

Column names, units and enum names come from the spec through the generated `_columns` table.
The core package needs nothing beyond Python; Parquet needs pyarrow, plots matplotlib, the
progress bar tqdm (the package's `[export]`, `[plot]` extras), and the commands name the extra to
install when one is missing.

Outputs are written whole or not at all: each under a temporary name in its directory, renamed
when every output of the command is complete (`Outputs`); an existing output is refused unless
`--force`. Memory does not grow with the log: skipped bytes are counted in pieces, `info` keeps a
bounded summary per (set, field), `--join` spools its rows to a temporary file.

Exit status: 0; 1 when `plot` finds no values to plot; 2 on a usage error, an unreadable input or
a failed write (as the decode tool, docs/conformance.md section 5); 130 on Ctrl-C (except with
`export --follow`, where Ctrl-C is the way to stop: the tables are written, exit 0). Messages are
one line on stderr.
"""

from __future__ import annotations

import argparse
import math
import os
import signal
import sys
from typing import Any, Callable, List, Optional, Tuple

from .. import registry
from .._protocol import MAX_PACKET
from .._protocol import PACKAGE as PROG
from ..codec.packets import Packet
from ..codec.stdio import closed_stdout, flushed
from .export import BLOCK, Exporter, FastExporter, fast_path
from .info import info
from .pipeline import LogDevice, PacketClock
from .plot import plot
from .writers import WRITERS, Events, Outputs, Source, ToolError, field_list, need, write_error


def export(args: argparse.Namespace) -> int:
    if args.dataset is not None:
        return _export_dataset(args)
    if args.out is None:
        raise ToolError("needs --out DIR (or --dataset DIR)")
    if len(args.logs) != 1:
        raise ToolError("takes one LOG (several only with --dataset)")
    for option in ("split_bytes", "model", "serial"):
        if getattr(args, option) is not None:
            raise ToolError(f"--{option.replace('_', '-')} needs --dataset")
    args.log = args.logs[0]
    if args.format == "mcap":  # MCAP: one file, ROS 2 and JSON messages (mcap.py, docs/mcap.md)
        from .mcap import export_mcap

        return export_mcap(args)
    if args.format == "parquet":
        need("pyarrow")
    fields = field_list(args.fields)
    try:
        os.makedirs(args.out, exist_ok=True)
    except OSError as e:
        raise ToolError(f"cannot create {args.out!r}: {e.strerror or e}") from None
    with Outputs(args.force).writing(args.out) as outputs:
        if fast_path(args):
            written, tally = _export_fast(args, fields, outputs)
        else:
            written, tally = _export_packets(args, fields, outputs)
    for name, n in written:
        print(f"{os.path.join(args.out, name)}: {n} rows")
    print(tally, file=sys.stderr)
    return 0


def _export_dataset(args: argparse.Namespace) -> int:
    """`export --dataset DIR LOGS...` (dataset.py): one line per log on stdout, exit 0 even when a
    log is unreadable (it is a `_files` row); 2 when the dataset cannot be written."""
    need("pyarrow")
    need("numpy")
    if args.out is not None or args.join or args.follow or args.fields or args.enum_numbers or "-" in args.logs:
        raise ToolError("--dataset takes log files only, without --out, --join, --follow, --fields, --enum-numbers")
    from . import dataset

    try:
        summary = dataset.export_dataset(
            args.logs, args.dataset, args.split_bytes or dataset.SPLIT_BYTES, args.model, args.serial, progress=True
        )
    except OSError as e:
        raise write_error(args.dataset, e) from None
    for row in summary.logs:
        error = f" ({row['error']})" if row["error"] else ""
        print(
            f"{row['path']}: {row['status']}{error}, {row['packets']} packets, {row['skipped_bytes']} bytes skipped, "
            f"{row['bad_checksums']} bad checksums -> log {row['log']}"
        )
    print(f"{args.dataset}: {len(summary.parts)} part files, {sum(summary.rows.values())} rows", file=sys.stderr)
    return 0


def _export_packets(
    args: argparse.Namespace, fields: Optional[List[str]], outputs: Outputs
) -> Tuple[List[Tuple[str, int]], str]:
    """The packet-by-packet export; with --follow, Ctrl-C ends the reading and the tables of what
    was read are written (the documented way to stop it)."""
    dev = LogDevice.of(args.log, args.device, args.follow)
    clock = PacketClock(args.log, args.follow)
    source = Source(args.log, follow=args.follow, idle=args.idle)
    ex = Exporter(args.out, args.format, fields, args.enum_numbers, args.join, outputs, clock)
    stream = Events(dev.device)
    tally = [0, 0]  # packets, skipped bytes

    def take(evs: List[Any]) -> None:
        for ev in evs:
            if isinstance(ev, Packet):
                tally[0] += 1
                dev.packet(ev, stream.decoder)
                ex.packet(ev)
            else:
                tally[1] += len(ev.data)

    previous = None
    if args.follow:
        previous = signal.signal(signal.SIGINT, lambda _n, _f: source.stop())
    try:
        for chunk in source.chunks():
            take(stream.feed(chunk))
            if args.follow:
                ex.flush()
    finally:
        if previous is not None:
            signal.signal(signal.SIGINT, previous)
    take(stream.flush())
    written = ex.close()
    stopped = " (stopped by Ctrl-C)" if source.stopped else ""
    return written, f"{tally[0]} packets, {tally[1]} bytes skipped{stopped}"


def _export_fast(
    args: argparse.Namespace, fields: Optional[List[str]], outputs: Outputs
) -> Tuple[List[Tuple[str, int]], str]:
    """The columnar export: blocks of BLOCK bytes through decode_columns; bytes that end a block
    in a skipped run (possibly a packet cut by the block's end) start the next block, at most
    MAX_PACKET - 1 of them (a packet cut by the end starts there; bytes before are skipped)."""
    from ..codec.packets import Columns, decode_columns

    dev = LogDevice.of(args.log, args.device)
    clock = PacketClock(args.log)
    source = Source(args.log)
    ex = FastExporter(args.out, args.format, fields, args.enum_numbers, outputs)
    packets = skipped = 0
    carry = b""
    base = 0
    pending = bytearray()
    try:
        for chunk in source.chunks(BLOCK):  # (whole blocks from a file: one copy each, no gathering)
            if pending or len(chunk) < BLOCK:
                pending += chunk
                if len(pending) < BLOCK:
                    continue
                chunk, pending = bytes(pending), bytearray()
            data = carry + chunk if carry else chunk
            cols = decode_columns(data)
            cut = len(data)
            block: Optional[Columns] = cols
            if cols.skips and cols.skips[-1].offset + len(cols.skips[-1].data) == len(data):
                cut = max(cols.skips[-1].offset, len(data) - (MAX_PACKET - 1))
                block = decode_columns(data[:cut]) if cut else None
            if block is not None:
                dev.columns(block, data)
                ex.block(block, data, base, clock.block(block, base))
                packets += block.packets
                skipped += sum(len(k.data) for k in block.skips)
            carry = data[cut:]
            base += cut
        data = carry + bytes(pending)
        if data:
            cols = decode_columns(data)
            dev.columns(cols, data)
            ex.block(cols, data, base, clock.block(cols, base))
            packets += cols.packets
            skipped += sum(len(k.data) for k in cols.skips)
        written = ex.close()
    finally:
        ex.shutdown()
    return written, f"{packets} packets, {skipped} bytes skipped (columnar path)"


# ---------------------------------------------------------------------------------------- CLI
class _Parser(argparse.ArgumentParser):
    """Usage errors as one line on stderr (`python -m PKG export: argument --idle: ...`), exit 2."""

    def error(self, message: str) -> Any:
        self.exit(2, f"{self.prog}: {message}\n")


def parser() -> argparse.ArgumentParser:
    p = _Parser(
        prog=f"python -m {PROG}",
        description="Recorded logs to tables and plots (export, info, plot); decode/encode are the canonical "
        "JSON-line tools (python -m %s decode --help)." % PROG,
    )
    sub = p.add_subparsers(dest="command", metavar="COMMAND")

    def device(command: argparse.ArgumentParser) -> None:
        command.add_argument("--device", choices=registry.DEVICES, help="decode per-device layouts for this device")

    e = sub.add_parser(
        "export",
        help="decode a log into tables (CSV, JSON lines, Parquet)",
        description="Decode a log into one table per (set, field) (or per sample with --join). Columns are named from the spec with units in the header, e.g. 'scaled_accel.x [g]', after the row's UTC time ('t_ns', 'time'; empty where unknown) and the packet's 'offset' in the log. Per-device layouts are the log's device's (its Device Information reply, else --device).",
    )
    e.add_argument("logs", nargs="+", metavar="LOG", help="binary log file, or - for stdin (--dataset: several logs)")
    e.add_argument(
        "--format",
        choices=sorted(WRITERS) + ["mcap"],
        default="csv",
        help="table format (default csv; parquet needs pyarrow); mcap: one MCAP file (--out FILE.mcap; docs/mcap.md)",
    )
    e.add_argument("--out", metavar="DIR", help="directory for the tables (created if missing)")
    e.add_argument(
        "--dataset",
        metavar="DIR",
        help="write the logs into a partitioned Parquet dataset instead (docs/dataset.md; needs pyarrow)",
    )
    e.add_argument("--split-bytes", type=positive, metavar="N", help="--dataset: bytes per split (default 64 MiB)")
    e.add_argument("--model", metavar="NAME", help="--dataset: the model of logs without a device information reply")
    e.add_argument("--serial", metavar="SN", help="--dataset: the serial of logs without a device information reply")
    e.add_argument(
        "--join", action="store_true", help="one table per data set, one row per sample (packets sharing a timestamp)"
    )
    e.add_argument(
        "--fields", metavar="F,..", help="only these columns (names or prefixes, e.g. scaled_accel,gps_timestamp.tow)"
    )
    e.add_argument("--enum-numbers", action="store_true", help="write enums as numbers (default: names from the spec)")
    e.add_argument("--follow", action="store_true", help="keep reading a growing file (stop with Ctrl-C or --idle)")
    e.add_argument(
        "--idle", type=_seconds, metavar="S", help="with --follow: stop after S seconds without new data (S >= 0)"
    )
    e.add_argument("--force", action="store_true", help="overwrite tables that exist (default: refuse)")
    device(e)
    from .mcap import add_options as mcap_options  # --topic-prefix, --frame (mcap.py)

    mcap_options(e)
    e.set_defaults(run=export)

    i = sub.add_parser(
        "info",
        help="summarise a log: packets, fields, rates, gaps, skipped bytes",
        description="Packets and fields per set and descriptor, rates in Hz from the timestamps, gaps and dropped samples, skipped bytes and bad checksums, first and last time.",
    )
    i.add_argument("log", metavar="LOG", help="binary log file, or - for stdin")
    device(i)
    i.set_defaults(run=info)

    q = sub.add_parser(
        "plot",
        help="plot fields against time (needs matplotlib)",
        description="Plot the selected fields against the time of their packets, one panel per unit.",
    )
    q.add_argument("log", metavar="LOG", help="binary log file, or - for stdin")
    q.add_argument(
        "--fields",
        required=True,
        metavar="F,..",
        help="columns to plot (names or prefixes, e.g. scaled_accel,scaled_gyro.z)",
    )
    q.add_argument("--out", required=True, metavar="FILE", help="image file: .png, .svg or .html")
    q.add_argument("--force", action="store_true", help="overwrite the image if it exists (default: refuse)")
    device(q)
    q.set_defaults(run=plot)
    from . import query  # python -m PKG query DATASET SQL (runtime query.py)

    query.add_parser(sub)
    return p


def positive(text: str) -> int:
    """An integer > 0 (argparse type)."""
    try:
        value = int(text, 0)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not an integer: {text!r}") from None
    if value <= 0:
        raise argparse.ArgumentTypeError(f"needs an integer > 0, not {text!r}")
    return value


def _seconds(text: str) -> float:
    """A finite number of seconds >= 0 (argparse type: a bad value is one usage line, exit 2)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number of seconds: {text!r}") from None
    if not math.isfinite(value) or value < 0:
        raise argparse.ArgumentTypeError(f"needs a finite number of seconds >= 0, not {text!r}")
    return value


def main(argv: List[str]) -> int:
    args = parser().parse_args(argv)
    if not getattr(args, "run", None):
        parser().print_help()
        return 2
    if getattr(args, "idle", None) is not None and not args.follow:
        print(f"{PROG} {args.command}: --idle needs --follow", file=sys.stderr)
        return 2
    run: Callable[[argparse.Namespace], int] = args.run
    if "numpy" not in sys.modules:
        # The log commands do no linear algebra: numpy's OpenBLAS need not start a thread per core,
        # which spins for a while after the import (about 0.05 s of CPU of every export on two
        # cores). A value the user set is kept.
        os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    try:
        return flushed(run(args))
    except ToolError as e:
        print(f"{PROG} {args.command}: {e}", file=sys.stderr)
        return e.status
    except BrokenPipeError:  # stdout closed by its reader (`info LOG | head`): quietly, by SIGPIPE
        return closed_stdout()
    except KeyboardInterrupt:
        return 130


__all__ = ["main", "parser", "positive"]
