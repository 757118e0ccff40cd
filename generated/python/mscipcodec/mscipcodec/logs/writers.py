"""The table writers of the user commands and what they share: the optional libraries (`need`),
values as cells, the layouts' columns, the log sources, outputs written whole (`Outputs`) and the
CSV, JSON-lines and Parquet writers.
"""

from __future__ import annotations

import contextlib
import csv
import importlib
import json
import math
import os
import struct
import sys
import tempfile
import time
from typing import Any, Dict, Iterator, List, Optional, Tuple, Type

from .. import _columns, _extras, registry
from .._protocol import MAX_PACKET
from ..codec.framing import Skip
from ..codec.packets import DecodedField, Decoder, Packet

CHUNK = 1 << 16
_F32 = struct.Struct(">f")


class ToolError(Exception):
    """A problem the user can fix: printed as one line, exit status `status`."""

    def __init__(self, message: str, status: int = 2) -> None:
        super().__init__(message)
        self.status = status


def need(module: str, extra: Optional[str] = None) -> Any:
    """Import an optional library, or a ToolError line naming it and the extra that installs it
    (`extra`: the command's own, else the library's; the package's `_extras`)."""
    return _extras.need(module, extra, ToolError)


# ------------------------------------------------------------------------------ values to cells
def f32_text(v: float) -> str:
    """The text of a float32 value in every output: the fewest significant digits that read back
    as the same float32 (the value as the device sent it), correctly rounded, laid out as Python's
    repr(float) (docs/conformance.md section 4): positional from 1e-4 to below 1e16, else
    `d.ddde-XX`. The columnar path gets the same text from numpy (`f32_texts`)."""
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


def values_view(np: Any, col: Any, dtype: Any) -> Any:
    """The values of a primitive arrow array (of numpy type `dtype`) as a numpy view, whatever
    its null slots hold."""
    if col.buffers()[1] is None:  # (an array of nulls only)
        return np.zeros(len(col), dtype=dtype)
    return np.frombuffer(col.buffers()[1], dtype=dtype, count=len(col) + col.offset)[col.offset :]


def bool_values(np: Any, col: Any) -> Any:
    """A boolean arrow array as numpy bools, null as False (to_numpy would import pandas)."""
    n, at = len(col), col.offset
    validity, data = col.buffers()[:2]
    if data is None:  # (an array of nulls only)
        return np.zeros(n, dtype=bool)
    out = np.unpackbits(np.frombuffer(data, dtype=np.uint8), bitorder="little")[at : at + n].astype(bool)
    if col.null_count:
        out &= np.unpackbits(np.frombuffer(validity, dtype=np.uint8), bitorder="little")[at : at + n].astype(bool)
    return out


def valid_values(np: Any, col: Any) -> Any:
    """The non-null entries of an arrow array as numpy bools, from its validity bitmap (what
    `bool_values(col.is_valid())` gives, without importing pyarrow.compute)."""
    n, at = len(col), col.offset
    validity = col.buffers()[0]
    if validity is None:
        return np.full(n, col.null_count == 0, dtype=bool)  # (no bitmap: none null, or all null)
    return np.unpackbits(np.frombuffer(validity, dtype=np.uint8), bitorder="little")[at : at + n].astype(bool)


def text_array(np: Any, pa: Any, texts: List[str], valid: Any = None) -> Any:
    """An arrow string array of Python strings, built from its buffers (pa.array would import
    pandas, about a quarter of a second, on its first call); `valid` (numpy bools) marks the
    non-null entries (a null's text is empty)."""
    n = len(texts)
    offsets = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.fromiter(map(len, texts), dtype=np.int64, count=n), out=offsets[1:])
    body = "".join(texts).encode("utf-8")
    if len(body) != offsets[-1]:  # not all ASCII: the lengths in bytes
        data = [t.encode("utf-8") for t in texts]
        np.cumsum(np.fromiter(map(len, data), dtype=np.int64, count=n), out=offsets[1:])
    kind, width = (pa.string(), np.int32) if offsets[-1] < 1 << 31 else (pa.large_string(), np.int64)
    mask = None if valid is None else pa.py_buffer(np.packbits(valid, bitorder="little"))
    nulls = 0 if valid is None else int(n - np.count_nonzero(valid))
    return pa.Array.from_buffers(kind, n, [mask, pa.py_buffer(offsets.astype(width)), pa.py_buffer(body)], nulls)


def taken_texts(np: Any, pa: Any, texts: List[str], where: Any) -> Any:
    """The arrow string array of `texts[i]` for each i of the int numpy array `where`, its bytes
    gathered by numpy (what `text_array(texts).take(where)` gives, without pyarrow.compute: its
    import is a twentieth of a second of every CSV export)."""
    data = [t.encode("utf-8") for t in texts]
    lens = np.fromiter(map(len, data), dtype=np.int64, count=len(data))
    starts = np.zeros(len(data) + 1, dtype=np.int64)
    np.cumsum(lens, out=starts[1:])
    table = np.frombuffer(b"".join(data), dtype=np.uint8)
    sizes = lens[where]
    offsets = np.zeros(len(where) + 1, dtype=np.int64)
    np.cumsum(sizes, out=offsets[1:])
    total = int(offsets[-1])
    body = table[np.repeat(starts[where] - offsets[:-1], sizes) + np.arange(total, dtype=np.int64)]
    kind, width = (pa.string(), np.int32) if total < 1 << 31 else (pa.large_string(), np.int64)
    return pa.Array.from_buffers(kind, len(where), [None, pa.py_buffer(offsets.astype(width)), pa.py_buffer(body)])


def iso_texts(np: Any, pa: Any, t_ns: Any) -> Any:
    """The `time` text of an arrow int64 `t_ns` column (UTC ns, null where unknown) as
    `timebase.iso` writes it (2026-03-14T09:14:02.010000Z: microseconds, truncated toward zero as
    pipeline.time_array's timestamps are), as an arrow string array: each distinct second's
    `YYYY-MM-DDTHH:MM:SS` from datetime once, the microseconds as digits, 27 bytes a row.
    None where a second's text is not 19 characters (a year before 1000 or after 9999)."""
    if isinstance(t_ns, pa.ChunkedArray):
        t_ns = t_ns.combine_chunks()
    n = len(t_ns)
    from ..codec.framing import speedups

    if speedups is not None and hasattr(speedups, "iso_texts"):  # the same bytes in one C pass
        valid = valid_values(np, t_ns).tobytes() if t_ns.null_count else None
        values = t_ns.buffers()[1] if t_ns.buffers()[1] is not None else bytes(8 * (n + t_ns.offset))
        text = speedups.iso_texts(values, t_ns.offset, n, valid)
        if text is None:
            return None
        cells = np.frombuffer(text, dtype=np.uint8)
    else:
        cells = _iso_cells(np, t_ns, n)
        if cells is None:
            return None
    offsets = np.arange(0, 27 * (n + 1), 27, dtype=np.int32)
    nulls = t_ns.null_count
    valid_bits = None
    if nulls:  # the validity bits from offset 0 (is_valid().to_numpy would import pandas)
        valid_bits = t_ns.buffers()[0]
        if t_ns.offset:
            bits = np.unpackbits(np.frombuffer(valid_bits, dtype=np.uint8), bitorder="little")
            valid_bits = pa.py_buffer(np.packbits(bits[t_ns.offset : t_ns.offset + n], bitorder="little"))
    return pa.Array.from_buffers(pa.string(), n, [valid_bits, pa.py_buffer(offsets), pa.py_buffer(cells)], nulls)


def _iso_cells(np: Any, t_ns: Any, n: int) -> Any:
    """`iso_texts`' bytes by numpy (n x 27 uint8, flat), None for a year out of 1000-9999."""
    import datetime

    ns = values_view(np, t_ns, np.int64)  # (not fill_null: pa.scalar imports pandas)
    if t_ns.null_count:
        ns = np.where(valid_values(np, t_ns), ns, 0)  # (a null slot holds anything)
    us = np.where(ns < 0, -(-ns // 1000), ns // 1000)
    sec, frac = np.divmod(us, 1_000_000)
    # The seconds of the runs of equal seconds (a log's times mostly rise: few runs), else sorted.
    starts = np.flatnonzero(sec[1:] != sec[:-1]) + 1 if n else np.zeros(0, dtype=np.int64)
    if len(starts) < n // 4:
        seconds = sec[np.concatenate(([0], starts))] if n else sec
        where = np.zeros(n, dtype=np.int64)
        where[starts] = 1
        where = np.cumsum(where)
    else:
        seconds, where = np.unique(sec, return_inverse=True)
    epoch = datetime.datetime(1970, 1, 1)
    try:
        heads = [(epoch + datetime.timedelta(seconds=int(s))).strftime("%Y-%m-%dT%H:%M:%S") for s in seconds]
    except OverflowError:
        return None
    if any(len(h) != 19 for h in heads):
        return None
    table = np.frombuffer("".join(heads).encode("ascii"), dtype=np.uint8).reshape(-1, 19)
    cells = np.empty((n, 27), dtype=np.uint8)
    cells[:, :19] = table[where.reshape(-1)]
    cells[:, 19] = ord(".")
    for k in range(6):
        cells[:, 25 - k] = frac % 10 + ord("0")
        frac = frac // 10
    cells[:, 26] = ord("Z")
    return cells.reshape(-1)


def header(name: str, units: Optional[str]) -> str:
    return f"{name} [{units}]" if units else name


# Every table starts with the row's UTC time (pipeline.py: the dataset's time model) and its offset.
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
        self.bar = progress_bar(self.size) if progress and sys.stderr.isatty() and self.size else None

    def stop(self) -> None:
        self.stopped = True
        if self.reading:  # a read that waits for data (stdin): interrupt it
            raise _Stop()

    def chunks(self, size: int = 0) -> Iterator[bytes]:
        """The bytes as they come, in pieces of at most `size` bytes (default CHUNK)."""
        size = size or CHUNK
        read = getattr(self.file, "read1", self.file.read)
        quiet_since = time.monotonic()
        try:
            while not self.stopped:
                try:
                    self.reading = True
                    try:
                        chunk = read(size)
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


def progress_bar(total: int) -> Any:
    """A tqdm bar in bytes (with bytes/s) on stderr, or None when tqdm is not installed. Its last
    state is drawn when it closes, before it is cleared (tqdm redraws at most every 0.1 s: a run
    quicker than that would otherwise never show its end)."""
    try:
        tqdm = importlib.import_module("tqdm").tqdm  # no type stubs
    except ImportError:
        return None

    class Bar(tqdm):  # type: ignore[misc,valid-type]
        def close(self) -> None:
            if not self.disable and self.n:
                self.refresh()
            super().close()

    return Bar(total=total, unit="B", unit_scale=True, unit_divisor=1024, file=sys.stderr, leave=False)


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
    return stream_events(source, Events(device))


def stream_events(source: Source, ev: Events) -> Iterator[Any]:
    """The events of the source through the given Events (whose decoder the caller can steer)."""
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

    @contextlib.contextmanager
    def writing(self, where: str) -> Iterator[Outputs]:
        """The block that writes the outputs: they are committed when it ends and aborted when it
        raises; an OSError (a full disk) becomes one `cannot write WHERE` ToolError."""
        try:
            yield self
            self.commit()
        except OSError as e:
            self.abort()
            raise write_error(where, e) from None
        except BaseException:
            self.abort()
            raise

    def _close_extra(self) -> None:
        for f in self.extra:
            try:
                f.close()
            except OSError:
                pass
        self.extra = []


def write_error(where: str, e: OSError) -> ToolError:
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
    if isinstance(c, F32Cell):
        return c.text
    if isinstance(c, float):
        return repr(c) if c == c else "nan"
    return str(c)


class F32Cell(float):
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
    if isinstance(c, F32Cell):
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
        if isinstance(sample, F32Cell):
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
            # t_ns, time (pipeline.UtcText cells, carrying their t_ns), offset
            self.types[:3] = [self.pa.int64(), self.pa.timestamp("us", tz="UTC"), self.pa.int64()]
        arrays = []
        for j, (c, t) in enumerate(zip(cols, self.types)):
            values: List[Any] = list(c)
            if j == 1:
                values = [None if x is None else x.t_ns // 1000 for x in values]
            elif t == self.pa.string():
                values = [None if x is None else str(x) for x in values]
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


# Data sets with columns (the export table of _columns).
COLUMN_SETS = frozenset(s for s, _d, _dev in _columns.COLUMNS)


def field_list(text: Optional[str]) -> Optional[List[str]]:
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
