"""User commands for recorded logs: export to tables, summarise, plot (`python -m <package> export|info|plot`).

    python -m <package> export LOG --format csv|jsonl|parquet --out DIR [--join] [--fields F,..]
                                  [--enum-numbers] [--device ID] [--follow [--idle S]] [--force]
    python -m <package> export --dataset DIR LOG... [--split-bytes N] [--model NAME] [--serial SN]
    python -m <package> info LOG [--device ID]
    python -m <package> plot LOG --fields F,.. --out FILE.png|svg|html [--device ID] [--force]

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
import csv
import importlib
import io
import json
import math
import os
import pickle
import signal
import struct
import sys
import tempfile
import time
from typing import Any, Callable, Dict, Iterator, List, Optional, Tuple, Type

from . import _columns, registry
from ._protocol import FIRST_SHARED, MAX_PACKET, SET_OFFSET, SYNC, TIMESTAMPS
from ._protocol import PACKAGE as PROG
from .framing import Skip, fletcher16
from .logpipe import LogDevice, PacketClock, UtcText, plot_times, t_ns_array, time_array, time_cells
from .packets import DecodedField, Decoder, Packet

CHUNK = 1 << 16
_F32 = struct.Struct(">f")
EXTRAS = {"pyarrow": "export", "numpy": "export", "matplotlib": "plot", "tqdm": "export"}


class ToolError(Exception):
    """A problem the user can fix: printed as one line, exit status `status`."""

    def __init__(self, message: str, status: int = 2) -> None:
        super().__init__(message)
        self.status = status


def need(module: str) -> Any:
    """Import an optional library or say which extra installs it."""
    try:
        return importlib.import_module(module)
    except ImportError:
        extra = EXTRAS.get(module.split(".")[0], "export")
        raise ToolError(
            f"{module} is not installed: pip install '{PROG}[{extra}]' (or pip install {module.split('.')[0]})"
        ) from None


# ------------------------------------------------------------------------------ values to cells
def f32_text(v: float) -> str:
    """The text of a float32 value in every output: the fewest significant digits that read back
    as the same float32 (the value as the device sent it), correctly rounded, laid out as Python's
    repr(float) (docs/conformance.md section 4): positional from 1e-4 to below 1e16, else
    `d.ddde-XX`. The columnar path gets the same text from numpy (`_f32_texts`)."""
    if v != v or v in (math.inf, -math.inf):
        return repr(float(v))

    def exact(digits: int) -> Optional[float]:
        x = float(f"{v:.{digits}g}")
        return x if _F32.unpack(_F32.pack(x))[0] == v else None

    # Reading back is monotonic in the digits (more digits are closer): the first of 6..9 that
    # works, or fewer when 6 already do.
    for digits in range(6, 10):
        x = exact(digits)
        if x is not None:
            while digits > 1:
                y = exact(digits - 1)
                if y is None:
                    break
                x, digits = y, digits - 1
            return repr(x)
    return repr(float(v))


def plain(v: Any) -> Any:
    """A decoded value as plain JSON data (dataclasses as objects, bytes as latin-1 text)."""
    if isinstance(v, (bytes, bytearray)):
        return bytes(v).decode("latin-1")
    if isinstance(v, (list, tuple)):
        return [plain(x) for x in v]
    if isinstance(v, bool) or v is None:
        return v
    if isinstance(v, int):
        return int(v)
    if isinstance(v, float):
        return float(v) if v == v and abs(v) != math.inf else repr(float(v))
    names = getattr(v, "_ATTRS", None)
    if names is not None:
        return {a: plain(getattr(v, a)) for a in names}
    return str(v)


def _get(value: Any, path: _columns.Path) -> Any:
    for step in path:
        if value is None:
            return None
        value = value[step] if isinstance(step, int) else getattr(value, step, None)
    return value


class Layout:
    """The columns of one field layout class: names with units, and how to read each value."""

    def __init__(self, cls: Any, enum_numbers: bool) -> None:
        self.cls = cls
        key = (cls.SET, cls.DESCRIPTOR, cls.DEVICE)
        self.specs = _columns.COLUMNS.get(key, ())
        self.enum_numbers = enum_numbers
        self.headers = [header(name, units) for name, _p, units, _k, _e in self.specs]
        self.f32 = [i for i, spec in enumerate(self.specs) if spec[3] == "float32"]

    def cells(self, value: Any) -> List[Any]:
        """Typed cells of one decoded value: float, int, bool, str or None (absent)."""
        out: List[Any] = []
        for _name, path, _units, kind, enum in self.specs:
            v = _get(value, path)
            if v is None:
                out.append(None)
            elif kind == "json":
                out.append(json.dumps(plain(v), separators=(",", ":")))
            elif kind == "enum":
                n = int(v)
                out.append(n if self.enum_numbers else _columns.ENUMS.get(enum or "", {}).get(n, n))
            elif kind == "bool":
                out.append(bool(v))
            elif kind in ("int", "bits"):
                out.append(int(v))
            else:
                out.append(float(v))
        return out


def header(name: str, units: Optional[str]) -> str:
    return f"{name} [{units}]" if units else name


# Every table starts with the row's UTC time (logpipe: the dataset's time model) and its offset.
TIME_HEADERS = ["t_ns", "time"]


def packet_time(packet: Packet) -> Optional[float]:
    """Seconds from the packet's shared timestamp (the generated TIMES order), or None."""
    found: Dict[Tuple[int, int], float] = {}
    for f in packet.fields:
        if isinstance(f, DecodedField):
            cls = type(f.value)
            for s, d, attr, per_second in _columns.TIMES:
                if cls.SET == s and cls.DESCRIPTOR == d:  # the first occurrence (as section 6's key)
                    found.setdefault((s, d), getattr(f.value, attr) / per_second)
    for s, d, _attr, _per_second in _columns.TIMES:
        if (s, d) in found:
            return found[(s, d)]
    return None


def table_name(set_id: int, cls: Any) -> str:
    """File stem of a (set, field layout) table: <set name>.[shared.]<field name>[.<device>]
    (`shared.` for the shared data fields a packet of the set carries)."""
    shared = "shared." if cls.SET != set_id else ""
    base = f"{registry.SET_NAMES.get(set_id, f'set_{set_id:02x}')}.{shared}{cls.NAME}"
    return f"{base}.{cls.DEVICE}" if cls.DEVICE else base


def select(headers: List[str], fields: Optional[List[str]]) -> List[int]:
    """Indices of the headers that `--fields` selects (a column name, or any prefix ending at . or [)."""
    if not fields:
        return list(range(len(headers)))
    out = []
    for i, h in enumerate(headers):
        name = h.split(" [")[0]
        if any(name == f or name.startswith(f + ".") or name.startswith(f + "[") for f in fields):
            out.append(i)
    return out


# ------------------------------------------------------------------------------------ sources
class _Stop(Exception):
    """Ctrl-C while `export --follow` waits in a read: stop reading (raised by the SIGINT handler)."""


class Source:
    """The bytes of a log: a file (optionally followed as it grows) or stdin, in chunks.

    `stop()` (the SIGINT handler of `export --follow`) ends `chunks()` after the chunk in hand."""

    def __init__(self, path: str, follow: bool = False, idle: Optional[float] = None, progress: bool = True) -> None:
        self.path = path
        self.follow = follow
        self.idle = idle
        self.stopped = False
        self.reading = False
        if path == "-":
            self.file = sys.stdin.buffer
            self.size = None
        else:
            try:
                self.file = open(path, "rb")
            except OSError as e:
                raise ToolError(f"cannot open {path!r}: {e.strerror or e}") from None
            self.size = None if follow else os.fstat(self.file.fileno()).st_size
        self.bar = _progress(self.size) if progress and sys.stderr.isatty() and self.size else None

    def stop(self) -> None:
        self.stopped = True
        if self.reading:  # a read that waits for data (stdin): interrupt it
            raise _Stop()

    def chunks(self) -> Iterator[bytes]:
        read = getattr(self.file, "read1", self.file.read)
        quiet_since = time.monotonic()
        try:
            while not self.stopped:
                try:
                    self.reading = True
                    try:
                        chunk = read(CHUNK)
                    finally:
                        self.reading = False
                except _Stop:
                    return
                except OSError as e:
                    raise ToolError(f"cannot read {self.path}: {e.strerror or e}") from None
                if chunk:
                    quiet_since = time.monotonic()
                    if self.bar is not None:
                        self.bar.update(len(chunk))
                    yield chunk
                    continue
                if not self.follow:
                    return
                if self.idle is not None and time.monotonic() - quiet_since >= self.idle:
                    return
                time.sleep(0.05)
        finally:
            if self.bar is not None:
                self.bar.close()
            if self.file is not sys.stdin.buffer:
                self.file.close()

    def read_all(self) -> bytes:
        return b"".join(self.chunks())


def _progress(total: int) -> Any:
    """A tqdm bar in bytes (with bytes/s) on stderr, or None when tqdm is not installed."""
    try:
        tqdm = importlib.import_module("tqdm").tqdm  # no type stubs
    except ImportError:
        return None
    return tqdm(total=total, unit="B", unit_scale=True, unit_divisor=1024, file=sys.stderr, leave=False)


SKIP_WINDOW = 1 << 20  # skipped bytes the tools let the parser hold before counting them


class SkipPart(Skip):
    """The first bytes of a skip run that is still going on (the run's `Skip` follows with the
    rest): the tools hand long runs on in pieces so that noise without a packet start (/dev/zero)
    is skipped in bounded memory. `after` is what follows in the run (up to MAX_PACKET bytes),
    to check the packets that start in this piece (`bad_checksums`)."""

    __slots__ = ("after",)

    def __init__(self, offset: int, data: bytes, after: bytes) -> None:
        super().__init__(offset, data)
        self.after = after


class Events:
    """Decoded events of a stream, fed chunk by chunk, in bounded memory: a skip run beyond
    SKIP_WINDOW bytes is handed on as `SkipPart`s (all but its last MAX_PACKET bytes, so the
    parser's events are otherwise those of `Decoder`)."""

    def __init__(self, device: Optional[str]) -> None:
        self.decoder = Decoder(device)

    def feed(self, chunk: bytes) -> List[Any]:
        out: List[Any] = self.decoder.feed(chunk)
        held = getattr(self.decoder, "_skip", None)  # the run the parser holds (framing.Parser)
        if isinstance(held, bytearray) and len(held) > SKIP_WINDOW:
            n = len(held) - MAX_PACKET
            part = SkipPart(self.decoder._skip_at, bytes(held[:n]), bytes(held[n:]))
            del held[:n]
            self.decoder._skip_at += n
            out.append(part)
        return out

    def flush(self) -> List[Any]:
        return list(self.decoder.flush())


def events(source: Source, device: Optional[str]) -> Iterator[Any]:
    """Decoded events (Packet, Skip, SkipPart) of the source, chunk by chunk."""
    return _stream_events(source, Events(device))


def _stream_events(source: Source, ev: Events) -> Iterator[Any]:
    for chunk in source.chunks():
        yield from ev.feed(chunk)
    yield from ev.flush()


# ------------------------------------------------------------------------------------ outputs
class Outputs:
    """The files one command writes, whole or not at all: each is written under a temporary name
    in its directory (`.NAME.part-PID`) and renamed when every one is complete (`commit`);
    `abort` removes them. So a failed write (a full disk), a crash or Ctrl-C leaves the previous
    files or complete new ones, never a partial one. An existing output is refused unless
    `force`."""

    def __init__(self, force: bool) -> None:
        self.force = force
        self.files: List[Tuple[str, str]] = []  # (temporary, final)
        self.extra: List[Any] = []  # temporary files of their own (join spools), closed on abort

    def refuse_existing(self, path: str) -> None:
        if not self.force and os.path.lexists(path):
            raise ToolError(f"{path} exists: not overwritten (--force overwrites it)")

    def claim(self, path: str) -> str:
        """The temporary name to write `path` under."""
        self.refuse_existing(path)
        tmp = os.path.join(os.path.dirname(path) or ".", f".{os.path.basename(path)}.part-{os.getpid()}")
        self.files.append((tmp, path))
        return tmp

    def spool(self, directory: str) -> Any:
        """An anonymous temporary file (in `directory`, removed when closed)."""
        f = tempfile.TemporaryFile(dir=directory, prefix=".spool-")
        self.extra.append(f)
        return f

    def commit(self) -> None:
        for _tmp, path in self.files:
            self.refuse_existing(path)  # created meanwhile by someone else
        for tmp, path in self.files:
            os.replace(tmp, path)
        self.files = []
        self._close_extra()

    def abort(self) -> None:
        for tmp, _path in self.files:
            try:
                os.unlink(tmp)
            except OSError:
                pass
        self.files = []
        self._close_extra()

    def _close_extra(self) -> None:
        for f in self.extra:
            try:
                f.close()
            except OSError:
                pass
        self.extra = []


def _write_error(where: str, e: OSError) -> ToolError:
    return ToolError(f"cannot write {where!r}: {e.strerror or e}")


# --------------------------------------------------------------------------------- table model
class Rows:
    """One output table: headers, then rows of typed cells; written by a Writer."""

    def __init__(self, name: str, headers: List[str], keep: List[int]) -> None:
        self.name = name
        self.keep = keep
        self.headers = TIME_HEADERS + ["offset"] + [headers[i] for i in keep]
        self.count = 0


class Writer:
    """A table file being written: headers first, then rows of typed cells."""

    suffix = ""

    def __init__(self, path: str, headers: List[str]) -> None:
        raise NotImplementedError

    def write(self, rows: List[List[Any]]) -> None:
        raise NotImplementedError

    def flush(self) -> None:
        raise NotImplementedError

    def close(self) -> None:
        raise NotImplementedError


class CsvWriter(Writer):
    suffix = ".csv"

    def __init__(self, path: str, headers: List[str]) -> None:
        self.file = open(path, "w", newline="", encoding="utf-8")
        self.csv = csv.writer(self.file, lineterminator="\n")
        # Headers quoted, as pyarrow writes them on the fast path: the files are the same bytes.
        csv.writer(self.file, lineterminator="\n", quoting=csv.QUOTE_ALL).writerow(headers)

    def write(self, rows: List[List[Any]]) -> None:
        self.csv.writerows([[_cell_text(c) for c in row] for row in rows])

    def flush(self) -> None:
        self.file.flush()

    def close(self) -> None:
        self.file.close()


def _cell_text(c: Any) -> str:
    if c is None:
        return ""
    if c is True:
        return "true"
    if c is False:
        return "false"
    if isinstance(c, _F32Cell):
        return c.text
    if isinstance(c, float):
        return repr(c) if c == c else "nan"
    return str(c)


class _F32Cell(float):
    """A float32 value: prints as its shortest float32 text in CSV."""

    @property
    def text(self) -> str:
        return f32_text(self)


class JsonlWriter(Writer):
    suffix = ".jsonl"

    def __init__(self, path: str, headers: List[str]) -> None:
        self.file = open(path, "w", encoding="utf-8")
        self.headers = headers

    def write(self, rows: List[List[Any]]) -> None:
        out = []
        for row in rows:
            obj = {h: (_json_float(c) if isinstance(c, float) else c) for h, c in zip(self.headers, row)}
            out.append(json.dumps(obj, separators=(",", ":"), allow_nan=False))
        self.file.write("\n".join(out) + "\n" if out else "")

    def flush(self) -> None:
        self.file.flush()

    def close(self) -> None:
        self.file.close()


def _json_float(c: float) -> Any:
    if c != c or abs(c) == math.inf:
        return repr(float(c))  # "nan", "inf", "-inf" as strings (JSON has no such numbers)
    if isinstance(c, _F32Cell):
        return float(c.text)
    return c


class ParquetWriter(Writer):
    """Parquet by pyarrow, in row groups of up to 65536 rows (bounded memory)."""

    suffix = ".parquet"
    GROUP = 65536

    def __init__(self, path: str, headers: List[str]) -> None:
        self.pa = need("pyarrow")
        self.pq = need("pyarrow.parquet")
        self.path = path
        self.headers = headers
        self.pending: List[List[Any]] = []
        self.writer: Any = None
        self.types: Optional[List[Any]] = None

    def _type(self, cells: List[Any]) -> Any:
        pa = self.pa
        sample = next((c for c in cells if c is not None), None)
        if isinstance(sample, UtcText):
            return pa.timestamp("us", tz="UTC")
        if isinstance(sample, _F32Cell):
            return pa.float32()
        if isinstance(sample, bool):
            return pa.bool_()
        if isinstance(sample, int):
            return pa.uint64() if any(c is not None and c >= 1 << 63 for c in cells) else pa.int64()
        if isinstance(sample, float):
            return pa.float64()
        return pa.string()

    def write(self, rows: List[List[Any]]) -> None:
        self.pending.extend(rows)
        if len(self.pending) >= self.GROUP:
            self._emit()

    def _emit(self) -> None:
        if not self.pending:
            return
        cols = list(zip(*self.pending))
        self.pending = []
        if self.types is None:
            self.types = [self._type(list(c)) for c in cols]
            self.types[:3] = [self.pa.int64(), self.pa.timestamp("us", tz="UTC"), self.pa.int64()]  # t_ns, time, offset
        arrays = []
        for c, t in zip(cols, self.types):
            values: List[Any] = list(c)
            if t == self.pa.string():
                values = [None if x is None else str(x) for x in values]
            elif t == self.types[1]:  # the time: UtcText cells
                values = [None if x is None else x.t_ns // 1000 for x in values]
            arrays.append(self.pa.array(values, type=t))
        table = self.pa.Table.from_arrays(arrays, names=self.headers)
        if self.writer is None:
            self.writer = self.pq.ParquetWriter(self.path, table.schema)
        self.writer.write_table(table)

    def flush(self) -> None:
        pass

    def close(self) -> None:
        self._emit()
        if self.writer is None:  # no rows: an empty table with string columns
            schema = self.pa.schema([(h, self.pa.string()) for h in self.headers])
            self.pq.write_table(schema.empty_table(), self.path)
        else:
            self.writer.close()


WRITERS: Dict[str, Type[Writer]] = {"csv": CsvWriter, "jsonl": JsonlWriter, "parquet": ParquetWriter}


# ------------------------------------------------------------------------------------- export
def _typed(layout: Layout, value: Any) -> List[Any]:
    """Cells of one value, float32 values marked so that they print as the device sent them."""
    cells = layout.cells(value)
    for i in layout.f32:
        if cells[i] is not None:
            cells[i] = _F32Cell(cells[i])
    return cells


class Exporter:
    """Writes the tables of a stream of decoded packets (one per (set, layout), or per set with join)."""

    def __init__(
        self,
        out: str,
        fmt: str,
        fields: Optional[List[str]],
        enum_numbers: bool,
        join: bool,
        outputs: Optional[Outputs] = None,
        clock: Optional[PacketClock] = None,
    ) -> None:
        self.clock = clock  # the rows' UTC time (None: none)
        self.out = out
        self.writer = WRITERS[fmt]
        self.fields = fields
        self.enum_numbers = enum_numbers
        self.join = join
        self.outputs = outputs if outputs is not None else Outputs(force=True)
        # (set, layout class) -> its table, or None when --fields keeps none of its columns
        self.tables: Dict[Any, Optional[Tuple[Rows, Writer, Layout]]] = {}
        self.pending: Dict[Any, List[List[Any]]] = {}
        self.layouts: Dict[Any, Layout] = {}
        self.joined: Dict[int, JoinTable] = {}  # join: set -> its table (rows spooled)

    def layout(self, cls: Any) -> Layout:
        lay = self.layouts.get(cls)
        if lay is None:
            lay = self.layouts[cls] = Layout(cls, self.enum_numbers)
        return lay

    def packet(self, p: Packet) -> None:
        t = self.clock.t_ns(p) if self.clock is not None else None  # every packet, in log order
        if p.set not in _DATA_SETS:
            return
        if self.join:
            self._join(p, t)
            return
        for f in p.fields:
            if not isinstance(f, DecodedField):
                continue
            cls = type(f.value)
            key = (p.set, cls)
            if key in self.tables:
                entry = self.tables[key]
            else:
                lay = self.layout(cls)
                keep = select(lay.headers, self.fields)
                if self.fields and not keep:
                    self.tables[key] = entry = None
                else:
                    rows = Rows(table_name(p.set, cls), lay.headers, keep)
                    path = self.outputs.claim(os.path.join(self.out, rows.name + self.writer.suffix))
                    self.tables[key] = entry = (rows, self.writer(path, rows.headers), lay)
                    self.pending[key] = []
            if entry is None:
                continue
            rows, _w, lay = entry
            cells = _typed(lay, f.value)
            self.pending[key].append(time_cells(t) + [p.offset] + [cells[i] for i in rows.keep])
            rows.count += 1
            if len(self.pending[key]) >= 4096:
                self._drain(key)

    def _writer(self, key: Any) -> Writer:
        """The writer of a table that has pending rows (so one with columns)."""
        entry = self.tables[key]
        assert entry is not None
        return entry[1]

    def _drain(self, key: Any) -> None:
        rows = self.pending[key]
        if rows:
            self._writer(key).write(rows)
            self.pending[key] = []

    def _join(self, p: Packet, t: Optional[int]) -> None:
        table = self.joined.get(p.set)
        if table is None:
            name = registry.SET_NAMES.get(p.set, f"set_{p.set:02x}") + self.writer.suffix
            path = os.path.join(self.out, name)
            self.outputs.refuse_existing(path)  # before an hour of --follow, not after
            table = self.joined[p.set] = JoinTable(name, path, self.outputs.spool(self.out))
        cells: List[Tuple[str, Any]] = []
        for f in p.fields:
            if not isinstance(f, DecodedField):
                continue
            lay = self.layout(type(f.value))
            keep = select(lay.headers, self.fields)
            if keep:
                typed = _typed(lay, f.value)
                cells.extend((lay.headers[i], typed[i]) for i in keep)
        table.packet(sample_key(p), t, p.offset, cells)

    def flush(self) -> None:
        for key in list(self.pending):
            self._drain(key)
            self._writer(key).flush()
        for table in self.joined.values():
            table.spill()

    def close(self) -> List[Tuple[str, int]]:
        written: List[Tuple[str, int]] = []
        if self.join:
            for _set_id, table in sorted(self.joined.items()):
                if not table.columns and self.fields:
                    continue
                table.write(self.writer, self.outputs.claim(table.path))
                written.append((table.name, table.rows))
            return written
        for key, entry in self.tables.items():
            if entry is None:
                continue
            rows, w, _lay = entry
            self._drain(key)
            w.close()
            written.append((rows.name + self.writer.suffix, rows.count))
        return sorted(written)


class JoinTable:
    """The `--join` table of one data set: one row per sample (docs/conformance.md section 6: the
    packets of a set that share a key, i.e. continuation packets, make one row, the first value
    of a column wins, so the shared copies of a continuation add nothing). Rows go to a spool
    file as they complete (memory bounded by the table's width); the table is written at the
    end, when its columns (the union of those seen, in order of appearance) are known."""

    BATCH = 4096

    def __init__(self, name: str, path: str, spool: Any) -> None:
        self.name, self.path, self.spool = name, path, spool
        self.columns: Dict[str, int] = {}  # header -> index among the value columns
        self.batch: List[Tuple[Optional[int], int, Dict[int, Any]]] = []
        self.rows = 0
        self.key: Any = None
        self.row: Optional[Tuple[Optional[int], int, Dict[int, Any]]] = None

    def packet(self, key: Any, t: Optional[int], offset: int, cells: List[Tuple[str, Any]]) -> None:
        if self.row is None or key is None or key != self.key:
            self._end_row()
            self.row = (t, offset, {})
            self.key = key
        elif self.row[0] is None and t is not None:
            self.row = (t, self.row[1], self.row[2])
        values = self.row[2]
        for h, c in cells:
            i = self.columns.setdefault(h, len(self.columns))
            values.setdefault(i, c)

    def _end_row(self) -> None:
        if self.row is not None:
            self.batch.append(self.row)
            self.rows += 1
            self.row = None
            if len(self.batch) >= self.BATCH:
                self.spill()

    def spill(self) -> None:
        if self.batch:
            pickle.dump(self.batch, self.spool, protocol=pickle.HIGHEST_PROTOCOL)
            self.batch = []

    def write(self, writer: Type[Writer], path: str) -> None:
        self._end_row()
        self.spill()
        width = len(self.columns)
        w = writer(path, TIME_HEADERS + ["offset"] + list(self.columns))
        self.spool.seek(0)
        while True:
            try:
                batch = pickle.load(self.spool)
            except EOFError:
                break
            out = []
            for t, offset, values in batch:
                row: List[Any] = time_cells(t) + [offset] + [None] * width
                for i, c in values.items():
                    row[3 + i] = c
                out.append(row)
            w.write(out)
        w.close()


_DATA_SETS = frozenset(s for s, _d, _dev in _columns.COLUMNS)


def sample_key(p: Packet) -> Optional[Tuple[Tuple[int, bytes], ...]]:
    """The sample key of a decoded packet (docs/conformance.md section 6): the leading shared
    timestamp fields of the sample rule, as sent; None when it has none."""
    key: List[Tuple[int, bytes]] = []
    for f in p.fields:
        d = getattr(f, "descriptor", None)
        if d is None or d < FIRST_SHARED:
            break
        if isinstance(f, DecodedField) and d in TIMESTAMPS and all(k[0] != d for k in key):
            key.append((d, f.value.encode()))
    return tuple(key) if key else None


# ------------------------------------------------------------------------- columnar fast path
BLOCK = 16 << 20  # bytes decoded by one decode_columns call on the fast path


def _fast_path(args: argparse.Namespace) -> bool:
    """The columnar path (decode_columns in C, numpy, pyarrow) applies: a whole file to CSV or
    Parquet, one table per field, the accelerator built and numpy and pyarrow installed."""
    from .framing import ACCELERATED

    if args.log == "-" or args.follow or args.join or args.format not in ("csv", "parquet") or not ACCELERATED:
        return False
    try:
        importlib.import_module("numpy")
        importlib.import_module("pyarrow")
    except ImportError:
        return False
    return os.environ.get(PROG.upper() + "_EXPORT_SLOW") is None


class FastExporter:
    """Exports per-field tables from decode_columns blocks: the numbers the C accelerator read as
    numpy columns, every other entry (NaN, optional, nested, ...) through `Layout`, merged in
    stream order; written by pyarrow (CSV or Parquet) block by block."""

    def __init__(
        self, out: str, fmt: str, fields: Optional[List[str]], enum_numbers: bool, outputs: Optional[Outputs] = None
    ) -> None:
        # numpy and pyarrow are optional (pyarrow has no type stubs): both used untyped here.
        self.np: Any = importlib.import_module("numpy")
        self.pa: Any = importlib.import_module("pyarrow")
        self.out, self.fmt, self.fields, self.enum_numbers = out, fmt, fields, enum_numbers
        self.outputs = outputs if outputs is not None else Outputs(force=True)
        self.writers: Dict[Any, Any] = {}
        self.counts: Dict[Any, int] = {}
        self.schemas: Dict[Any, Any] = {}
        import threading

        self.lock = threading.Lock()
        self.layouts: Dict[Any, Optional[Tuple[Layout, List[int]]]] = {}
        self.pool: Any = None  # the writer threads (concurrent.futures), made on first use
        self.pending: List[Any] = []  # the writes of the last block

    def _layout(self, cls: Any) -> Optional[Tuple[Layout, List[int]]]:
        if cls not in self.layouts:
            lay = Layout(cls, self.enum_numbers)
            keep = select(lay.headers, self.fields)
            self.layouts[cls] = None if (self.fields and not keep) else (lay, keep)
        return self.layouts[cls]

    def _kept(self, cls: Any) -> Tuple[Layout, List[int]]:
        """The layout and kept columns of a class that has rows (so columns to write)."""
        chosen = self._layout(cls)
        assert chosen is not None
        return chosen

    def block(self, cols: Any, data: Any, base: int, times: Any = None) -> None:
        """Write the tables of one decode_columns block (`data`, at stream offset `base`; `times`
        its `timebase.BlockTimes`)."""
        pieces = self.pieces(cols, data, base, times)
        # pyarrow formats and writes without the GIL: one table per thread, while the caller
        # decodes the next block; a block's writes start when the previous block's are done.
        self.wait()
        if (os.cpu_count() or 1) > 1:
            if self.pool is None:
                from concurrent.futures import ThreadPoolExecutor

                self.pool = ThreadPoolExecutor(max_workers=os.cpu_count() or 1)
            self.pending = [self.pool.submit(self._write, key, parts) for key, parts in pieces.items()]
        else:
            for key, parts in pieces.items():
                self._write(key, parts)

    def pieces(self, cols: Any, data: Any, base: int, times: Any = None) -> Dict[Any, List[Any]]:
        """The rows of one decode_columns block (`data`, at stream offset `base`) per (set,
        layout class): a list of (packet offsets in the block, field index, columns), the columns
        being the UTC `t_ns` (from `times`, the block's `timebase.BlockTimes`; None without),
        the stream offset and the kept value columns (numpy or arrow arrays, or lists); rows of
        one piece in stream order, pieces to be merged by (offset, index). Shared by the dataset
        export (dataset.py), which times its rows itself."""
        np, pa = self.np, self.pa

        def t_ns(offs: Any) -> Any:
            return None if times is None else t_ns_array(np, pa, times, offs + base)

        pieces: Dict[Any, List[Any]] = {}
        other_rows: Dict[Any, List[Tuple[int, int, List[Any]]]] = {}
        for off, k, entry in cols.others:
            if k < 0 or not isinstance(entry, DecodedField):
                continue
            packet_set = data[off + SET_OFFSET]
            if packet_set not in _DATA_SETS:
                continue
            cls = type(entry.value)
            chosen = self._layout(cls)
            if chosen is not None:
                other_rows.setdefault((packet_set, cls), []).append((off, k, _typed(chosen[0], entry.value)))
        for (set_id, _d), t in cols.tables.items():
            if set_id not in _DATA_SETS or t.rows == 0:
                continue
            chosen = self._layout(t.cls)
            if chosen is None:
                continue
            lay, keep = chosen
            arrays = t.arrays()
            offs = np.frombuffer(t.offsets, dtype=np.int64)
            cols_out: List[Any] = [t_ns(offs), offs + base]
            for i in keep:
                _name, path, _units, kind, enum = lay.specs[i]
                a = arrays[path[0]]
                if len(path) > 1:
                    a = a.reshape(t.rows, -1)[:, path[1]]
                cols_out.append(self._column(a, kind, enum))
            pieces.setdefault((set_id, t.cls), []).append((offs, np.frombuffer(t.index, dtype=np.int64), cols_out))
        for (set_id, cls), rows in other_rows.items():
            lay, keep = self._kept(cls)
            offs = np.array([r[0] for r in rows], dtype=np.int64)
            idx = np.array([r[1] for r in rows], dtype=np.int64)
            cells = [t_ns(offs), offs + base]
            for i in keep:
                cells.append(self._py_column([r[2][i] for r in rows], lay.specs[i][3]))
            pieces.setdefault((set_id, cls), []).append((offs, idx, cells))
        return pieces

    def wait(self) -> None:
        """Until the writes of the last block are done (their first error raised here)."""
        pending, self.pending = self.pending, []
        for done in pending:
            done.result()

    def _column(self, a: Any, kind: str, enum: Optional[str]) -> Any:
        np, pa = self.np, self.pa
        if kind == "float32":
            return _arrow(np, pa, a.astype(np.float32))
        if kind == "enum" and not self.enum_numbers:
            names = _columns.ENUMS.get(enum or "", {})
            return pa.array([names.get(int(v), str(int(v))) for v in a], type=pa.string())
        if kind == "bool":
            return _arrow(np, pa, a.astype(bool))
        if kind in ("int", "bits", "enum") and a.dtype == np.uint64 and (a.size == 0 or a.max() < (1 << 63)):
            return _arrow(np, pa, a.astype(np.int64))
        return _arrow(np, pa, a)

    def _py_column(self, vals: List[Any], kind: str) -> Any:
        pa = self.pa
        if kind == "float32":
            return pa.array([None if v is None else float(v) for v in vals], type=pa.float32())
        if kind == "float64":
            return pa.array(vals, type=pa.float64())
        if kind == "bool":
            return pa.array(vals, type=pa.bool_())
        if kind in ("int", "bits") or (kind == "enum" and self.enum_numbers):
            big = any(v is not None and v >= 1 << 63 for v in vals)
            return pa.array(vals, type=pa.uint64() if big else pa.int64())
        return pa.array([None if v is None else str(v) for v in vals], type=pa.string())

    def _write(self, key: Any, parts: List[Any]) -> None:
        np, pa = self.np, self.pa
        set_id, cls = key
        lay, keep = self._kept(cls)
        headers = TIME_HEADERS + ["offset"] + [lay.headers[i] for i in keep]
        offs = np.concatenate([p[0] for p in parts])
        idx = np.concatenate([p[1] for p in parts])
        order = np.lexsort((idx, offs))
        columns = []
        for j in range(len(headers) - 1):
            chunk = [p[2][j] for p in parts]
            col = chunk[0] if len(chunk) == 1 else pa.concat_arrays([_as_arrow(pa, c) for c in _unify(pa, chunk)])
            col = _as_arrow(pa, col)
            if len(parts) > 1:
                col = col.take(_arrow(np, pa, order))
            columns.append(col)
        columns.insert(1, time_array(pa, columns[0], self.fmt == "csv"))
        table = pa.Table.from_arrays(columns, names=headers)
        with self.lock:
            w = self._writer(key, table)
        schema = self.schemas[key]
        w.write_table(table if table.schema == schema else table.cast(schema))
        with self.lock:
            self.counts[key] += table.num_rows

    def _writer(self, key: Any, table: Any) -> Any:
        set_id, cls = key
        w = self.writers.get(key)
        if w is None:
            path = self.outputs.claim(os.path.join(self.out, table_name(set_id, cls) + "." + self.fmt))
            if self.fmt == "csv":
                w = ArrowCsvText(self.np, self.pa, path, table.column_names)
            else:
                w = importlib.import_module("pyarrow.parquet").ParquetWriter(path, table.schema)
            self.writers[key] = w
            self.schemas[key] = table.schema
            self.counts[key] = 0
        return w

    def shutdown(self) -> None:
        if self.pool is not None:
            self.pool.shutdown()
            self.pool = None

    def close(self) -> List[Tuple[str, int]]:
        self.wait()
        out = []
        for (set_id, cls), w in self.writers.items():
            w.close()
            out.append((table_name(set_id, cls) + "." + self.fmt, self.counts[(set_id, cls)]))
        return sorted(out)


class ArrowCsvText:
    """CSV of arrow tables with the cell text of `CsvWriter` (so both paths write the same bytes):
    floats as `_cell_text` prints them (float32 as `f32_text`: `_float_texts`), bools true/false,
    null empty, strings quoted only when they need it, headers quoted. pyarrow writes the rows."""

    def __init__(self, np: Any, pa: Any, path: str, headers: List[str]) -> None:
        self.np, self.pa = np, pa
        self.pacsv = importlib.import_module("pyarrow.csv")
        self.headers = headers
        self.file = open(path, "wb")
        head = io.StringIO()
        csv.writer(head, lineterminator="\n", quoting=csv.QUOTE_ALL).writerow(headers)
        self.file.write(head.getvalue().encode("utf-8"))

    def write_table(self, table: Any) -> None:
        np, pa = self.np, self.pa
        if table.num_rows == 0:
            return
        columns, plain = [], True
        for j in range(table.num_columns):
            col = table.column(j)
            col = col.combine_chunks() if isinstance(col, pa.ChunkedArray) else col
            t = col.type
            if pa.types.is_floating(t):
                col = _float_texts(np, pa, col)
            elif pa.types.is_string(t) or pa.types.is_large_string(t):
                texts = col.to_pylist()
                if any(v is not None and any(c in v for c in ',"\n\r') for v in texts):
                    plain = False
                    col = pa.array([None if v is None else _csv_quote(v) for v in texts], type=pa.string())
            columns.append(col)
        if plain:  # nothing to quote: pyarrow writes the cells as they are
            names = [f"c{j}" for j in range(len(columns))]
            options = self.pacsv.WriteOptions(include_header=False, quoting_style="none")
            self.pacsv.write_csv(pa.Table.from_arrays(columns, names=names), self.file, write_options=options)
            return
        texts = [["" if v is None else str(v) for v in _text_cells(pa, c)] for c in columns]
        self.file.write(("\n".join(map(",".join, zip(*texts))) + "\n").encode("utf-8"))

    def close(self) -> None:
        self.file.close()


def _text_cells(pa: Any, col: Any) -> List[Any]:
    """Cells of an arrow column as CsvWriter prints them (strings already final)."""
    if pa.types.is_boolean(col.type):
        return [None if v is None else ("true" if v else "false") for v in col.to_pylist()]
    out: List[Any] = col.to_pylist()
    return out


def _float_texts(np: Any, pa: Any, col: Any) -> Any:
    """The text of each value of a float32 / float64 arrow array as the packet path prints it
    (`f32_text`, repr(float)), as an arrow string array. pyarrow prints the same shortest digits,
    positional without a trailing `.0` over a range that covers 2e-4 to 1e15 but for some large
    float32 values (where repr is positional too): there, its text plus `.0` when integral is
    repr's; the values outside that range or in pyarrow's exponent form are printed one by one."""
    pc = importlib.import_module("pyarrow.compute")
    single = col.type == pa.float32()
    text = pc.cast(col, pa.string())
    integral = pc.match_substring_regex(text, "^-?[0-9]+$")
    text = pc.if_else(integral, pc.binary_join_element_wise(text, pa.scalar(".0"), ""), text)
    values = col.fill_null(0).to_numpy(zero_copy_only=False)
    size = np.abs(values.astype(np.float64))
    with np.errstate(invalid="ignore"):
        odd = np.isfinite(size) & ((size < 2e-4) | (size >= 1e15))
    odd |= pc.match_substring(text, "e").fill_null(False).to_numpy(zero_copy_only=False)  # pyarrow's exponent form
    if col.null_count:
        odd &= col.is_valid().to_numpy(zero_copy_only=False)
    where = np.flatnonzero(odd)
    if len(where) == 0:
        return text
    fmt = f32_text if single else (lambda v: repr(float(v)))
    fixed = pa.array([fmt(float(v)) for v in values[where]], type=pa.string())
    mask = np.zeros(len(values), dtype=bool)
    mask[where] = True
    return pc.replace_with_mask(text, pa.array(mask), fixed)


def _f32_texts(np: Any, a: Any) -> Any:
    """`f32_text` of each value of a float32 numpy array, as the columnar path prints them."""
    pa = importlib.import_module("pyarrow")
    texts: List[str] = _float_texts(np, pa, pa.array(a.astype(np.float32), type=pa.float32())).to_pylist()
    return np.array(texts, dtype=object)


def _csv_quote(text: str) -> str:
    """A string cell as the csv module writes it (QUOTE_MINIMAL, lineterminator \\n)."""
    if any(c in text for c in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text


def _as_arrow(pa: Any, c: Any) -> Any:
    if isinstance(c, (pa.Array, pa.ChunkedArray)):
        return c
    np = importlib.import_module("numpy")
    return _arrow(np, pa, c) if isinstance(c, np.ndarray) else pa.array(c)


def _arrow(np: Any, pa: Any, a: Any, valid: Any = None) -> Any:
    """A one-dimensional numpy array of numbers or bools as an arrow array, sharing its memory;
    `valid` (bools) marks the non-null entries. (pa.array would do the same but imports pandas,
    about a second of start-up, on its first call.)"""
    a = np.ascontiguousarray(a)
    mask = None if valid is None else pa.py_buffer(np.packbits(valid, bitorder="little"))
    nulls = 0 if valid is None else int(len(a) - np.count_nonzero(valid))
    if a.dtype == np.bool_:
        return pa.Array.from_buffers(pa.bool_(), len(a), [mask, pa.py_buffer(np.packbits(a, bitorder="little"))], nulls)
    return pa.Array.from_buffers(pa.from_numpy_dtype(a.dtype), len(a), [mask, pa.py_buffer(a)], nulls)


def _unify(pa: Any, chunks: List[Any]) -> List[Any]:
    """Chunks of one column as one arrow type (the first non-null type wins; ints widen to float)."""
    arrs = [_as_arrow(pa, c) for c in chunks]
    types = [a.type for a in arrs if a.type != pa.null()]
    target = types[0] if types else pa.null()
    if any(pa.types.is_floating(t) for t in types) and pa.types.is_integer(target):
        target = next(t for t in types if pa.types.is_floating(t))
    return [a if a.type == target else a.cast(target) for a in arrs]


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
    if args.format == "parquet":
        need("pyarrow")
    fields = _field_list(args.fields)
    try:
        os.makedirs(args.out, exist_ok=True)
    except OSError as e:
        raise ToolError(f"cannot create {args.out!r}: {e.strerror or e}") from None
    outputs = Outputs(args.force)
    try:
        if _fast_path(args):
            written, tally = _export_fast(args, fields, outputs)
        else:
            written, tally = _export_packets(args, fields, outputs)
        outputs.commit()
    except OSError as e:
        outputs.abort()
        raise _write_error(args.out, e) from None
    except BaseException:
        outputs.abort()
        raise
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
            args.logs, args.dataset, args.split_bytes or dataset.SPLIT_BYTES, args.model, args.serial
        )
    except OSError as e:
        raise _write_error(args.dataset, e) from None
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
    from .packets import Columns, decode_columns

    dev = LogDevice.of(args.log, args.device)
    clock = PacketClock(args.log)
    source = Source(args.log)
    ex = FastExporter(args.out, args.format, fields, args.enum_numbers, outputs)
    packets = skipped = 0
    carry = b""
    base = 0
    pending = bytearray()
    try:
        for chunk in source.chunks():
            pending += chunk
            if len(pending) < BLOCK:
                continue
            data = carry + bytes(pending)
            pending = bytearray()
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


def _field_list(text: Optional[str]) -> Optional[List[str]]:
    if text is None:
        return None
    fields = [f.strip() for f in text.split(",") if f.strip()]
    if not fields:
        raise ToolError("--fields needs at least one column name")
    known = {h.split(" [")[0] for specs in _columns.COLUMNS.values() for h in (s[0] for s in specs)}
    for f in fields:
        if not any(k == f or k.startswith(f + ".") or k.startswith(f + "[") for k in known):
            raise ToolError(f"--fields: no column named {f!r} (column names look like 'scaled_accel.x')")
    return fields


# --------------------------------------------------------------------------------------- info
class Intervals:
    """The intervals between one field's timestamps, as a histogram of at most MAX_BINS bins:
    exact (one bin per distinct interval) while there are that few, then geometric bins of
    relative width `scale` (doubled whenever the bins would exceed MAX_BINS), each counted at its
    centre. So `info` holds the same small state per (set, field) whatever the log's length."""

    MAX_BINS = 2048

    def __init__(self) -> None:
        self.bins: Dict[float, int] = {}
        self.scale = 0.0  # 0: exact

    def _key(self, dt: float) -> float:
        if self.scale == 0.0:
            return dt
        return math.exp((math.floor(math.log(dt) / self.scale) + 0.5) * self.scale)

    def add(self, dt: float, n: int = 1) -> None:
        key = self._key(dt)
        self.bins[key] = self.bins.get(key, 0) + n
        while len(self.bins) > self.MAX_BINS:
            old, self.bins = self.bins, {}
            self.scale = 1e-4 if self.scale == 0.0 else 2 * self.scale
            for k, m in old.items():
                k2 = self._key(k)
                self.bins[k2] = self.bins.get(k2, 0) + m

    def rate(self) -> Tuple[Optional[float], int, int]:
        """(rate in Hz from the median interval, gaps over 1.5 times it, samples they dropped)."""
        total = sum(self.bins.values())
        if not total:
            return None, 0, 0
        ordered = sorted(self.bins.items())
        seen, step = 0, ordered[-1][0]
        for dt, n in ordered:  # the interval at index total // 2 of the sorted intervals
            seen += n
            if seen > total // 2:
                step = dt
                break
        gaps = dropped = 0
        for dt, n in ordered:
            if dt > 1.5 * step:
                gaps += n
                dropped += n * (round(dt / step) - 1)
        return 1.0 / step, gaps, dropped


class FieldSummary:
    """What `info` keeps of one (set, descriptor, name): counts, the last time, its intervals."""

    __slots__ = ("count", "untimed", "last", "intervals")

    def __init__(self) -> None:
        self.count = 0
        self.untimed = 0
        self.last: Optional[float] = None
        self.intervals = Intervals()

    def add(self, t: Optional[float]) -> None:
        self.count += 1
        if t is None:
            self.untimed += 1
            return
        if self.last is not None and t > self.last:
            self.intervals.add(t - self.last)
        self.last = t


class Summary:
    """What `info` prints, computed from a stream of events in bounded memory (a `FieldSummary`
    per (set, field), not a list per entry)."""

    def __init__(self) -> None:
        self.packets: Dict[int, int] = {}
        self.fields: Dict[Tuple[int, int, str], FieldSummary] = {}
        self.skipped = 0
        self.skip_runs = 0
        self.bad_checksums = 0
        self.first: Optional[float] = None
        self.last: Optional[float] = None
        self.bytes = 0

    def add(self, e: Any) -> None:
        if isinstance(e, Packet):
            self.packets[e.set] = self.packets.get(e.set, 0) + 1
            t = packet_time(e)
            if t is not None:
                self.first = t if self.first is None else min(self.first, t)
                self.last = t if self.last is None else max(self.last, t)
            for f in e.fields:
                d = getattr(f, "descriptor", None)
                if d is None:
                    continue
                name = f.name if isinstance(f, DecodedField) else "(undecoded)"
                key = (e.set, d, name)
                summary = self.fields.get(key)
                if summary is None:
                    summary = self.fields[key] = FieldSummary()
                summary.add(t)
        elif isinstance(e, SkipPart):  # the start of a run still going on
            self.skipped += len(e.data)
            self.bad_checksums += bad_checksums(bytes(e.data) + bytes(e.after), len(e.data))
        else:
            self.skipped += len(e.data)
            self.skip_runs += 1
            self.bad_checksums += bad_checksums(bytes(e.data))

    def lines(self) -> List[str]:
        out = []
        total = sum(self.packets.values())
        out.append(
            f"bytes: {self.bytes}  packets: {total}  skipped bytes: {self.skipped} in {self.skip_runs} runs  bad checksums: {self.bad_checksums}"
        )
        for s in sorted(self.packets):
            out.append(f"set 0x{s:02X} {registry.SET_NAMES.get(s, '?')}: {self.packets[s]} packets")
            for (fs, d, name), summary in sorted(self.fields.items()):
                if fs != s:
                    continue
                hz, gaps, dropped = summary.intervals.rate()
                rate = f"{hz:10.3f} Hz" if hz is not None else "         - Hz"
                # Rates, gaps and drops come from the entries whose packet carries a timestamp.
                note = f"  ({summary.untimed} without timestamp)" if summary.untimed else ""
                out.append(f"  0x{d:02X} {name:32} {summary.count:8} {rate}  gaps {gaps}  dropped {dropped}{note}")
        return out


def bad_checksums(data: bytes, starts: Optional[int] = None) -> int:
    """Complete packets with a wrong checksum inside a skipped run (same header, wrong sum),
    among those that start before `starts` (default: anywhere)."""
    from ._protocol import CHECKSUM_SIZE, HEADER_SIZE, LENGTH_OFFSET
    from .framing import checksum_bytes

    limit = len(data) if starts is None else starts
    n = 0
    i = data.find(SYNC, 0, limit + len(SYNC) - 1)
    while 0 <= i < limit:
        if i + HEADER_SIZE <= len(data):
            end = i + HEADER_SIZE + data[i + LENGTH_OFFSET] + CHECKSUM_SIZE
            if end <= len(data):
                if checksum_bytes(data[i : end - CHECKSUM_SIZE]) != data[end - CHECKSUM_SIZE : end]:
                    n += 1
        i = data.find(SYNC, i + 1, limit + len(SYNC) - 1)
    return n


def info(args: argparse.Namespace) -> int:
    """The log's counts, its device, a line per clock (device clock, GPS time, UTC: logpipe's
    ClockLines and timebase's TimeReport, the time model of export) and its fields' rates."""
    from . import timebase
    from .logpipe import ClockLines

    dev = LogDevice.of(args.log, args.device)
    clock = PacketClock(args.log)
    report = timebase.TimeReport(_DATA_SETS)
    clocks = ClockLines(_DATA_SETS)
    source = Source(args.log)
    summary = Summary()
    stream = Events(dev.device)

    def add(e: Any) -> None:
        summary.add(e)
        if isinstance(e, Packet):
            dev.packet(e, stream.decoder, strict=False)  # info reports an unknown device, decodes on
            pt = timebase.packet_time(e)
            clocks.add(e, pt)
            report.add(e, pt, clock.clock.step(pt))

    for chunk in source.chunks():
        summary.bytes += len(chunk)
        for e in stream.feed(chunk):
            add(e)
    for e in stream.flush():
        add(e)
    lines = summary.lines()
    print("\n".join(lines[:1] + [dev.line()] + clocks.lines() + report.lines() + lines[1:]))
    return 0


# --------------------------------------------------------------------------------------- plot
def figure(log: str, fields: Optional[List[str]], device: Optional[str] = None) -> Any:
    """The matplotlib figure of `plot`: the selected columns against time, one panel per unit."""
    need("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # x: (UTC t_ns or None, offset); plotted against UTC when the log has it (logpipe.plot_times)
    series: Dict[str, Tuple[List[Any], List[float], str]] = {}
    dev = LogDevice.of(log, device)
    clock = PacketClock(log)
    source = Source(log)
    stream = Events(dev.device)
    have_time = False
    for e in _stream_events(source, stream):
        if not isinstance(e, Packet):
            continue
        dev.packet(e, stream.decoder)
        t = clock.t_ns(e)
        if e.set not in _DATA_SETS:
            continue
        x = (t, e.offset)
        have_time = have_time or t is not None
        for f in e.fields:
            if not isinstance(f, DecodedField):
                continue
            lay = Layout(type(f.value), True)
            keep = select(lay.headers, fields)
            if not keep:
                continue
            cells = lay.cells(f.value)
            for i in keep:
                if lay.specs[i][3] == "json" or cells[i] is None:
                    continue
                s = series.setdefault(lay.headers[i], ([], [], lay.specs[i][2] or ""))
                s[0].append(x)
                s[1].append(float(cells[i]))
    if not series:
        raise ToolError("no values of the selected fields in the log", 1)
    series = plot_times(series, have_time)
    by_units: Dict[str, List[str]] = {}
    for name, (_x, _y, units) in series.items():
        by_units.setdefault(units, []).append(name)
    fig, axes = plt.subplots(len(by_units), 1, sharex=True, figsize=(10, 2.8 * len(by_units)), squeeze=False)
    for ax, (units, names) in zip(axes[:, 0], by_units.items()):
        for name in names:
            xs, ys, _u = series[name]
            ax.plot(xs, ys, label=name.split(" [")[0], linewidth=0.8)
        ax.set_ylabel(units or "value")
        ax.legend(loc="upper right", fontsize="small")
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time (UTC)" if have_time else "packet offset [bytes]")
    fig.suptitle(os.path.basename(log))
    fig.tight_layout()
    return fig


def plot(args: argparse.Namespace) -> int:
    fields = _field_list(args.fields)
    ext = os.path.splitext(args.out)[1].lower()
    if ext not in (".png", ".svg", ".html"):
        raise ToolError(f"--out must end in .png, .svg or .html (got {args.out!r})")
    need("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    outputs = Outputs(args.force)
    outputs.refuse_existing(args.out)  # before reading the log
    fig = figure(args.log, fields, args.device)
    try:
        tmp = outputs.claim(args.out)
        if ext == ".html":
            buf = io.StringIO()
            fig.savefig(buf, format="svg")
            title = os.path.basename(args.log)
            with open(tmp, "w", encoding="utf-8") as fh:
                fh.write(f"<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>{title}</title></head><body>\n")
                fh.write(buf.getvalue()[buf.getvalue().find("<svg") :])
                fh.write("</body></html>\n")
        else:
            with open(tmp, "wb") as fh:
                fig.savefig(fh, dpi=110, format=ext[1:])
        outputs.commit()
    except OSError as e:
        outputs.abort()
        raise _write_error(args.out, e) from None
    except BaseException:
        outputs.abort()
        raise
    plt.close(fig)
    print(f"{args.out}: {sum(len(ax.lines) for ax in fig.axes)} series")
    return 0


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
        "--format", choices=sorted(WRITERS), default="csv", help="table format (default csv; parquet needs pyarrow)"
    )
    e.add_argument("--out", metavar="DIR", help="directory for the tables (created if missing)")
    e.add_argument(
        "--dataset",
        metavar="DIR",
        help="write the logs into a partitioned Parquet dataset instead (docs/dataset.md; needs pyarrow)",
    )
    e.add_argument("--split-bytes", type=_positive, metavar="N", help="--dataset: bytes per split (default 64 MiB)")
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


def _positive(text: str) -> int:
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
    try:
        return run(args)
    except ToolError as e:
        print(f"{PROG} {args.command}: {e}", file=sys.stderr)
        return e.status
    except KeyboardInterrupt:
        return 130


__all__ = ["main", "Layout", "Exporter", "Summary", "packet_time", "f32_text", "fletcher16"]
