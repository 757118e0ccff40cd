"""`mipcodec export`: the per-packet exporter (`Exporter`, `--join`: `JoinTable`) and the columnar
fast path (`FastExporter`, shared by the dataset export).
"""

from __future__ import annotations

import argparse
import importlib
import os
import pickle
from typing import Any, Dict, List, Optional, Tuple, Type

from .. import _columns, registry
from .._protocol import FIRST_SHARED, SET_OFFSET, TIMESTAMPS
from .._protocol import PACKAGE as PROG
from ..codec.packets import DecodedField, Packet
from .arrow import ArrowCsvText, as_arrow, float_texts, needs_quotes, to_arrow, unify
from .pipeline import PacketClock, t_ns_array, time_array, time_cells
from .writers import (
    COLUMN_SETS,
    TIME_HEADERS,
    WRITERS,
    F32Cell,
    Layout,
    Outputs,
    Rows,
    Writer,
    bool_values,
    iso_texts,
    select,
    table_name,
    taken_texts,
    text_array,
    valid_values,
    values_view,
)


# ------------------------------------------------------------------------------------- export
def _typed(layout: Layout, value: Any) -> List[Any]:
    """Cells of one value, float32 values marked so that they print as the device sent them."""
    cells = layout.cells(value)
    for i in layout.f32:
        if cells[i] is not None:
            cells[i] = F32Cell(cells[i])
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
        if p.set not in COLUMN_SETS:
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
BLOCK = 4 << 20  # bytes decoded by one decode_columns call on the fast path (peak memory grows with it)


def fast_path(args: argparse.Namespace) -> bool:
    """The columnar path (decode_columns in C, numpy, pyarrow) applies: a whole file to CSV or
    Parquet, one table per field, the accelerator built and numpy and pyarrow installed."""
    from ..codec.framing import ACCELERATED

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
            if packet_set not in COLUMN_SETS:
                continue
            cls = type(entry.value)
            chosen = self._layout(cls)
            if chosen is not None:
                other_rows.setdefault((packet_set, cls), []).append((off, k, _typed(chosen[0], entry.value)))
        for (set_id, _d), t in cols.tables.items():
            if set_id not in COLUMN_SETS or t.rows == 0:
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
            return to_arrow(np, pa, a.astype(np.float32))
        if kind == "enum" and not self.enum_numbers:
            names = _columns.ENUMS.get(enum or "", {})
            values, where = np.unique(a, return_inverse=True)  # each value's name once
            return taken_texts(np, pa, [names.get(int(v), str(int(v))) for v in values.tolist()], where.reshape(-1))
        if kind == "bool":
            return to_arrow(np, pa, a.astype(bool))
        if kind in ("int", "bits", "enum") and a.dtype == np.uint64 and (a.size == 0 or a.max() < (1 << 63)):
            return to_arrow(np, pa, a.astype(np.int64))
        return to_arrow(np, pa, a)

    def _py_column(self, vals: List[Any], kind: str) -> Any:
        """An arrow column of Python cells (None: null), built from numpy buffers (pa.array would
        import pandas, a quarter of a second, on its first call)."""
        np, pa = self.np, self.pa
        valid = np.fromiter((v is not None for v in vals), dtype=bool, count=len(vals))
        mask = None if valid.all() else valid
        if kind in ("float32", "float64", "bool", "int", "bits") or (kind == "enum" and self.enum_numbers):
            fill = vals if mask is None else [0 if v is None else v for v in vals]
            if kind in ("float32", "float64", "bool"):
                dtype = {"float32": np.float32, "float64": np.float64, "bool": np.bool_}[kind]
            else:
                big = any(v >= 1 << 63 for v in fill)
                dtype = np.uint64 if big else np.int64
            return to_arrow(np, pa, np.array(fill, dtype=dtype), mask)
        return text_array(np, pa, ["" if v is None else str(v) for v in vals], mask)

    def _write(self, key: Any, parts: List[Any]) -> None:
        np, pa = self.np, self.pa
        set_id, cls = key
        lay, keep = self._kept(cls)
        headers = TIME_HEADERS + ["offset"] + [lay.headers[i] for i in keep]
        offs = np.concatenate([p[0] for p in parts])
        idx = np.concatenate([p[1] for p in parts])
        order = np.lexsort((idx, offs))
        columns = []
        for j in range(len(headers) - 1):  # t_ns, offset, the values (time: from t_ns)
            chunk = [p[2][j] for p in parts]
            col = chunk[0] if len(chunk) == 1 else pa.concat_arrays([as_arrow(pa, c) for c in unify(pa, chunk)])
            col = as_arrow(pa, col)
            if len(parts) > 1:
                col = col.take(to_arrow(np, pa, order))
            columns.append(col)
        text = iso_texts(np, pa, columns[0]) if self.fmt == "csv" else None
        columns.insert(1, text if text is not None else time_array(pa, columns[0], self.fmt == "csv"))
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
                w = CsvRows(self.np, self.pa, path, table.column_names)
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


class CsvRows(ArrowCsvText):
    """`ArrowCsvText` whose rows the C accelerator writes (`csv_rows`: the integers' digits, the
    texts of the float, time and string columns as they are, true/false) in one pass, the same
    bytes as pyarrow's CSV writer writes for them (about a tenth of the CPU time of an export
    went into pyarrow's casts, row population and copies); a table with a column of another
    type, or a string that needs quotes, is written by `ArrowCsvText`."""

    def write_table(self, table: Any) -> None:
        from ..codec.framing import speedups

        if table.num_rows == 0:
            return
        if speedups is None or not hasattr(speedups, "csv_rows"):
            super().write_table(table)
            return
        columns = []
        for j in range(table.num_columns):
            col = table.column(j)
            col = col.chunk(0) if col.num_chunks == 1 else col.combine_chunks()
            spec = self._spec(col)
            if spec is None:
                super().write_table(table)
                return
            columns.append(spec)
        self.file.write(speedups.csv_rows(columns, table.num_rows))

    def _spec(self, col: Any) -> Any:
        """The (kind, values, body, offset, valid) of a column for `csv_rows`, or None."""
        np, pa = self.np, self.pa
        types = pa.types
        if types.is_floating(col.type):
            col = float_texts(np, pa, col)
        valid = valid_values(np, col).tobytes() if col.null_count else None
        t = col.type
        if types.is_string(t) or types.is_large_string(t):
            if needs_quotes(np, pa, col):
                return None
            return (3 if types.is_large_string(t) else 2, col.buffers()[1], col.buffers()[2] or b"", col.offset, valid)
        if types.is_boolean(t):
            return (4, bool_values(np, col).view(np.uint8), None, 0, valid)
        if types.is_integer(t):
            if t == pa.int64() or t == pa.uint64():
                return (1 if t == pa.uint64() else 0, values_view(np, col, np.dtype(str(t))), None, 0, valid)
            return (0, values_view(np, col, np.dtype(str(t))).astype(np.int64), None, 0, valid)
        return None
