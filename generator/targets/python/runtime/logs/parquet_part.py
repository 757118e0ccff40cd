"""A Parquet part file whose all-null column chunks are written here, not by pyarrow's writer
(docs/dataset.md, "Sizes").

Most columns of a `<set>.samples` table hold no value in a row group: the fields a device does
not send in that log. The dataset keeps them (its schema is a function of the spec: "A schema
that only grows"), but pyarrow's writer spends about 4 ns per null cell walking and run-length
encoding definition levels, which was a quarter of `export --dataset`'s CPU time on the
simulated fleet. The chunk of a column with no value in N rows is a few bytes whatever N is (one
data page: one run of N zero definition levels), so:

- each row group's columns that hold a value are written by pyarrow (`pq.write_table` into
  memory, with the dataset's encodings and compression);
- the all-null ones are made here from a one-row template that pyarrow wrote with the same
  options (`_Template`), with N in place of 1 in the page header, the definition-level run and the
  column metadata;
- the chunks go out in the schema's order, each row group's contiguous, and the footer (Thrift
  compact protocol, logs/thrift.py) is pyarrow's for the whole schema: the template's
  schema and column orders, the row groups' chunks with their new offsets, and the key-value
  metadata pyarrow writes (the schema's, then `ARROW:schema`).

The file is the one pyarrow writes for the same table with those columns uncompressed, byte for
byte (tests/export/test_parquet_part.py checks that, and that pyarrow, Polars, DuckDB and Spark
read it back). A template whose shape is not the expected one (another pyarrow's layout) turns
the shortcut off: pyarrow then writes every column of the file.
"""

import base64
import struct
from typing import Any, Dict, List, Optional, Sequence, Tuple

from . import thrift
from .thrift import Struct

MAGIC = b"PAR1"
# parquet.thrift's field ids used here.
_CM_NUM_VALUES, _CM_UNCOMPRESSED, _CM_COMPRESSED, _CM_DATA_PAGE, _CM_INDEX_PAGE, _CM_DICT_PAGE = 5, 6, 7, 9, 10, 11
_CM_STATISTICS, _CM_BLOOM_OFFSET, _CM_SIZE_STATISTICS = 12, 14, 16
_CM_CODEC = 4
# The fields of an all-null chunk's metadata that pyarrow writes (type, encodings, path, codec,
# values, sizes, page offsets, statistics, encoding statistics, size statistics).
_CM_EXPECTED = {1, 2, 3, 4, 5, 6, 7, 9, 11, 12, 13, 16}
_CM_OFFSETS = (_CM_DATA_PAGE, _CM_INDEX_PAGE, _CM_DICT_PAGE, _CM_BLOOM_OFFSET)  # file offsets: moved
_CM_MOVING = {_CM_UNCOMPRESSED, _CM_COMPRESSED, *_CM_OFFSETS}  # what moving a chunk reads
_CC_FILE_OFFSET, _CC_META = 2, 3
_CC_INDEXES = (4, 5, 6, 7)  # offset index and column index: not written by the dataset
_PH_TYPE, _PH_UNCOMPRESSED, _PH_COMPRESSED, _PH_DATA_PAGE = 1, 2, 3, 5
_DATA_PAGE, _DICTIONARY_PAGE = 0, 2


class _Copied:
    """A ColumnChunk of a piece that pyarrow wrote: its metadata, and its encoded bytes around the
    page offsets (`before`, the id of the field before them, `after`), so that it moves to another
    file offset by encoding two or three numbers; `before` None where it has other offsets
    (a bloom filter, a file offset), then encoded whole again."""

    __slots__ = ("chunk", "meta", "start", "before", "last", "after")

    def __init__(self, r: "thrift.Reader") -> None:
        begin = r.i
        self.chunk: Struct = {}
        self.meta: Struct = {}
        spans: Dict[int, Tuple[int, int]] = {}
        fid = 0
        while True:
            head = r.b[r.i]
            r.i += 1
            if head == thrift.STOP:
                break
            t, delta = head & 15, head >> 4
            fid = fid + delta if delta else r.zigzag()
            if fid == _CC_META and t == thrift.STRUCT:
                self.meta, spans = r.spans(_CM_MOVING)
                self.chunk[fid] = (t, self.meta)
            else:
                self.chunk[fid] = (t, r.value(t))
        meta = self.meta
        self.start = meta[_CM_DICT_PAGE][1] if _CM_DICT_PAGE in meta else meta[_CM_DATA_PAGE][1]
        self.before: Optional[bytes] = None
        self.last = 0
        self.after = b""
        moved = [f for f in _CM_OFFSETS if f in meta]
        lo = min((spans[f][0] for f in moved), default=0)
        hi = max((spans[f][1] for f in moved), default=0)
        apart = any(lo <= a < hi for f, (a, _) in spans.items() if f not in moved)  # (never from pyarrow)
        if self.chunk.get(_CC_FILE_OFFSET, (0, 0))[1] or _CM_BLOOM_OFFSET in moved or not moved or apart:
            end = r.i  # encoded whole again: the whole metadata decoded
            r.i = begin
            self.chunk = r.struct()
            self.meta = self.chunk[_CC_META][1]
            r.i = end
            return
        self.before = bytes(r.b[begin:lo])
        self.last = max((f for f in spans if f < min(moved)), default=0)
        self.after = bytes(r.b[hi : r.i])

    def at(self, pos: int) -> bytes:
        """The encoded ColumnChunk, its pages now at file offset `pos`."""
        meta = self.meta
        moved = {f: (meta[f][0], meta[f][1] - self.start + pos) for f in _CM_OFFSETS if f in meta}
        if self.before is None:
            chunk = dict(self.chunk)
            chunk[_CC_META] = (thrift.STRUCT, {**meta, **moved})
            if chunk.get(_CC_FILE_OFFSET, (0, 0))[1]:
                chunk[_CC_FILE_OFFSET] = (thrift.I64, chunk[_CC_FILE_OFFSET][1] - self.start + pos)
            return thrift.encode(chunk)
        out = bytearray(self.before)
        thrift.fields(out, moved, self.last)
        out += self.after
        return bytes(out)


def _piece_chunks(data: Any) -> List[_Copied]:
    """The ColumnChunks of the one row group of a piece's bytes (a ValueError otherwise)."""
    n = len(data)
    size = struct.unpack_from("<I", data, n - 8)[0]
    r = thrift.Reader(data, n - 8 - size)
    r.find(4)  # FileMetaData's row groups
    groups, _ = r.list_header()
    if groups != 1:
        raise ValueError(f"a piece of {groups} row groups")
    r.find(1)  # the row group's columns
    count, _ = r.list_header()
    return [_Copied(r) for _ in range(count)]


def footer(data: Any) -> Struct:
    """The FileMetaData of a whole Parquet file's bytes (a ValueError when they are not one)."""
    n = len(data)
    if n < 12 or bytes(data[:4]) != MAGIC or bytes(data[n - 4 :]) != MAGIC:
        raise ValueError("not a Parquet file")
    size = struct.unpack_from("<I", data, n - 8)[0]
    return thrift.Reader(data, n - 8 - size).struct()


class _Shape:
    """The all-null chunk of one column, from the template's one-row chunk: its dictionary page
    (verbatim, empty), its data page's header and what follows the definition levels (an empty
    encoding's header, e.g. DELTA_BINARY_PACKED's), its column metadata, and the start of its
    encoded ColumnChunk (`head`: the file offset 0, the metadata's type, encodings, path, codec).
    Columns with the same `key` have the same chunk bytes for a row count."""

    __slots__ = ("dictionary", "header", "after_levels", "meta", "key", "head")

    def __init__(self, dictionary: bytes, header: Struct, after_levels: bytes, meta: Struct) -> None:
        self.dictionary, self.header, self.after_levels, self.meta = dictionary, header, after_levels, meta
        if set(meta) - _CM_EXPECTED or any(f not in meta for f in range(1, _CM_CODEC + 1)):
            raise ValueError("unexpected column metadata")
        later = thrift.encode({f: v for f, v in meta.items() if f > _CM_DICT_PAGE})
        self.key = (dictionary, thrift.encode(header), after_levels, later)
        head = bytearray()
        thrift.fields(head, {_CC_FILE_OFFSET: (thrift.I64, 0)}, 0)
        head.append(1 << 4 | thrift.STRUCT)  # field 3: the metadata
        thrift.fields(head, {f: v for f, v in meta.items() if f <= _CM_CODEC}, 0)
        self.head = bytes(head)


# A one-row all-null column's definition levels: one RLE run (header 1 << 1) of the value 0, one
# byte wide (bit width 1).
_ONE_NULL_LEVELS = b"\x02\x00"


def _one_value(pa: Any, t: Any) -> Any:
    """One value of type `t` (an array of one): zero bits, or an empty text. Made from buffers:
    `pa.array` of a value imports pandas (0.15 s) when it is installed."""
    if pa.types.is_string(t) or pa.types.is_binary(t):
        return pa.Array.from_buffers(t, 1, [None, pa.py_buffer(bytes(8)), pa.py_buffer(b"")])
    if pa.types.is_large_string(t) or pa.types.is_large_binary(t):
        return pa.Array.from_buffers(t, 1, [None, pa.py_buffer(bytes(16)), pa.py_buffer(b"")])
    try:
        width = t.bit_width
    except ValueError:  # not a fixed-width type
        raise ValueError(f"no value of type {t} for a template") from None
    return pa.Array.from_buffers(t, 1, [None, pa.py_buffer(bytes((width + 7) // 8))])


class _Template:
    """What a schema's files share: the footer's schema, column orders, version and writer name,
    and each column's all-null chunk shape; None where pyarrow's layout is not the expected one."""

    def __init__(self, pq: Any, pa: Any, schema: Any, options: Dict[str, Any]) -> None:
        sink = pa.BufferOutputStream()
        # (a column that cannot be null, such as `offset`, always has a value: its chunk is pyarrow's)
        one = pa.table([pa.nulls(1, f.type) if f.nullable else _one_value(pa, f.type) for f in schema], schema=schema)
        pq.write_table(one, sink, **dict(options, compression="NONE"))
        data = memoryview(sink.getvalue()).cast("B")
        self.meta = footer(data)
        # the footer's fields before the row count (version, schema) and after the key-value
        # metadata (writer, column orders), encoded once
        before = bytearray()
        self.last = thrift.fields(before, {f: v for f, v in self.meta.items() if f < 3}, 0)
        self.before = bytes(before)
        after = bytearray()
        thrift.fields(after, {f: v for f, v in self.meta.items() if f > 5}, 5)
        after.append(thrift.STOP)
        self.after = bytes(after)
        self.shapes: Optional[List[Optional[_Shape]]] = None
        try:
            chunks = self.meta[4][1][1][0][1][1][1]
            self.shapes = [self._shape(data, c[_CC_META][1]) if f.nullable else None for f, c in zip(schema, chunks)]
        except (ValueError, KeyError, IndexError, struct.error, TypeError):
            self.shapes = None

    @staticmethod
    def _shape(data: Any, meta: Struct) -> _Shape:
        if meta[_CM_NUM_VALUES][1] != 1 or any(f in meta for f in (_CM_INDEX_PAGE, _CM_BLOOM_OFFSET)):
            raise ValueError("unexpected chunk")
        start = meta[_CM_DICT_PAGE][1] if _CM_DICT_PAGE in meta else meta[_CM_DATA_PAGE][1]
        dictionary = bytes(data[start : meta[_CM_DATA_PAGE][1]])
        r = thrift.Reader(data, meta[_CM_DATA_PAGE][1])
        header = r.struct()
        size = header[_PH_COMPRESSED][1]
        page = bytes(data[r.i : r.i + size])
        end = r.i + size
        if (
            header[_PH_TYPE][1] != _DATA_PAGE
            or end - start != meta[_CM_COMPRESSED][1]
            or header[_PH_UNCOMPRESSED][1] != size
            or struct.unpack_from("<I", page)[0] != len(_ONE_NULL_LEVELS)
            or page[4:6] != _ONE_NULL_LEVELS
        ):
            raise ValueError("unexpected page")
        return _Shape(dictionary, header, page[6:], meta)


class _NullChunk:
    """The bytes of a column of one shape with no value in `n` rows (`data`), and the encoded
    fields of its column metadata that depend on `n` (`mid`: values and sizes; `tail`: the
    statistics, then the ends of the metadata and of the ColumnChunk)."""

    __slots__ = ("data", "mid", "tail")

    def __init__(self, shape: "_Shape", n: int) -> None:
        levels = bytearray()
        thrift.varint(levels, n << 1)
        levels.append(0)
        page = struct.pack("<I", len(levels)) + bytes(levels) + shape.after_levels
        header = dict(shape.header)
        dp = dict(header[_PH_DATA_PAGE][1])
        dp[1] = (thrift.I32, n)
        if 5 in dp:
            dp[5] = (thrift.STRUCT, {**dp[5][1], 3: (thrift.I64, n)})
        header[_PH_DATA_PAGE] = (thrift.STRUCT, dp)
        header[_PH_UNCOMPRESSED] = header[_PH_COMPRESSED] = (thrift.I32, len(page))
        self.data = shape.dictionary + thrift.encode(header) + page
        meta = shape.meta
        mid = bytearray()
        sizes = {
            _CM_NUM_VALUES: (thrift.I64, n),
            _CM_UNCOMPRESSED: (thrift.I64, len(self.data)),
            _CM_COMPRESSED: (thrift.I64, len(self.data)),
        }
        thrift.fields(mid, sizes, _CM_CODEC)
        self.mid = bytes(mid)
        later = {f: v for f, v in meta.items() if f > _CM_DICT_PAGE}
        if _CM_STATISTICS in later:
            later[_CM_STATISTICS] = (thrift.STRUCT, {**later[_CM_STATISTICS][1], 3: (thrift.I64, n)})
        if _CM_SIZE_STATISTICS in later:
            stats = dict(later[_CM_SIZE_STATISTICS][1])
            if 3 in stats:  # the definition levels' histogram: n nulls, no value
                stats[3] = (thrift.LIST, (thrift.I64, [n, 0]))
            later[_CM_SIZE_STATISTICS] = (thrift.STRUCT, stats)
        tail = bytearray()
        thrift.fields(tail, later, _CM_DICT_PAGE if _CM_DICT_PAGE in meta else _CM_DATA_PAGE)
        tail += bytes((thrift.STOP, thrift.STOP))  # the metadata's end, the ColumnChunk's end
        self.tail = bytes(tail)

    def chunk(self, shape: "_Shape", at: int) -> bytes:
        """The encoded ColumnChunk of `shape`'s column, these bytes written at file offset `at`."""
        out = bytearray(shape.head)
        out += self.mid
        if shape.dictionary:
            thrift.fields(
                out,
                {_CM_DATA_PAGE: (thrift.I64, at + len(shape.dictionary)), _CM_DICT_PAGE: (thrift.I64, at)},
                _CM_COMPRESSED,
            )
        else:
            thrift.fields(out, {_CM_DATA_PAGE: (thrift.I64, at)}, _CM_COMPRESSED)
        out += self.tail
        return bytes(out)


class PartFile:
    """Writes one Parquet file at `path` (a temporary name: the caller renames it whole) with
    `schema`: `write(table)` adds row groups of at most `row_group_rows`, `close()` writes the
    footer. `options` are `pq.write_table`'s (encodings, dictionary columns, statistics); the
    columns with a value in a row group get `compression`, the others none. `templates`, a dict
    the caller keeps, holds each schema's template once. `constant` names text columns that the
    caller knows hold one value in every row (the dataset's `log`): pyarrow gets them as a
    dictionary of that value (a dictionary page and a run of zero indices, where a plain text
    column cost its writer about 13 ns per row); one whose first and last rows differ, or that can
    be null, is written as it is."""

    def __init__(
        self,
        pq: Any,
        pa: Any,
        path: str,
        schema: Any,
        options: Dict[str, Any],
        compression: str,
        row_group_rows: int,
        templates: Dict[Any, Optional[_Template]],
        constant: Sequence[str] = (),
    ) -> None:
        self.pq, self.pa, self.schema, self.options = pq, pa, schema, options
        self.constant = {
            f.name
            for f in schema
            if f.name in constant and not f.nullable and (pa.types.is_string(f.type) or pa.types.is_binary(f.type))
        }
        self.compression, self.row_group_rows = compression, row_group_rows
        bare = schema.remove_metadata()
        key = bare.serialize().to_pybytes()
        if key not in templates:
            try:
                templates[key] = _Template(pq, pa, bare, options)
            except (ValueError, pa.ArrowException):  # no one-row table of this schema: pyarrow's file
                templates[key] = None
        self.template = templates[key]
        self.writer: Any = None
        self.file: Any = None
        if self.template is None or self.template.shapes is None:  # pyarrow writes it all
            self.writer = pq.ParquetWriter(path, schema, compression=compression, **options)
        else:
            self.file = open(path, "wb")
            self.file.write(MAGIC)
        self.pos = len(MAGIC)
        self.row_groups: List[Struct] = []
        self.rows = 0
        self.nulls: Dict[Tuple[Any, int], _NullChunk] = {}

    def write(self, table: Any) -> None:
        if self.writer is not None:
            self.writer.write_table(table, row_group_size=self.row_group_rows)
            return
        for start in range(0, table.num_rows, self.row_group_rows):
            self._row_group(table.slice(start, self.row_group_rows))

    def _row_group(self, rows: Any) -> None:
        n = rows.num_rows
        valued = [i for i, c in enumerate(rows.columns) if c.null_count < n]
        chunks: Dict[int, Tuple[Any, _Copied]] = {}  # column -> (bytes, ColumnChunk)
        piece: Any = None
        if valued:
            names = [rows.schema.field(i).name for i in valued]
            options = dict(self.options)
            if isinstance(options.get("use_dictionary"), list):
                options["use_dictionary"] = [c for c in options["use_dictionary"] if c in names]
            if options.get("column_encoding"):
                options["column_encoding"] = {k: v for k, v in options["column_encoding"].items() if k in names} or None
            piece_rows = rows.select(valued)
            for name in self.constant:
                piece_rows = self._as_dictionary(piece_rows, name, options)
            sink = self.pa.BufferOutputStream()
            self.pq.write_table(piece_rows, sink, row_group_size=n, compression=self.compression, **options)
            piece = sink.getvalue()
            view = memoryview(piece).cast("B")  # (a pyarrow buffer's format is signed bytes)
            for i, copied in zip(valued, _piece_chunks(view)):
                if any(f in copied.chunk for f in _CC_INDEXES):
                    raise ValueError("a page index in a part's piece")
                chunks[i] = (view[copied.start : copied.start + copied.meta[_CM_COMPRESSED][1]], copied)
        out: List[bytes] = []  # the ColumnChunks, encoded
        first = self.pos
        unc = comp = 0
        shapes = self.template.shapes  # type: ignore[union-attr]
        for i in range(len(shapes)):  # type: ignore[arg-type]
            at = self.pos
            if i in chunks:
                data, copied = chunks[i]
                out.append(copied.at(at))
                unc += copied.meta[_CM_UNCOMPRESSED][1]
                comp += copied.meta[_CM_COMPRESSED][1]
            else:
                shape = shapes[i]  # type: ignore[index]
                if shape is None:
                    raise ValueError(f"column {rows.schema.field(i).name!r} cannot be null")
                null = self._null(shape, n)
                data = null.data
                out.append(null.chunk(shape, at))
                unc += len(data)
                comp += len(data)
            self.file.write(data)
            self.pos += len(data)
        del chunks, piece
        self.row_groups.append(
            {
                1: (thrift.LIST, (thrift.STRUCT, out)),
                2: (thrift.I64, unc),
                3: (thrift.I64, n),
                5: (thrift.I64, first),
                6: (thrift.I64, comp),
            }
        )
        self.rows += n

    def _as_dictionary(self, rows: Any, name: str, options: Dict[str, Any]) -> Any:
        """`rows` with column `name` as a dictionary of its one value, `options` changed to match;
        `rows` as they are if its first and last values differ."""
        pa = self.pa
        column = rows.column(name)
        if column.null_count or column[0] != column[-1]:
            return rows
        n = len(column)
        indices = pa.Array.from_buffers(pa.int32(), n, [None, pa.py_buffer(bytes(4 * n))])
        values = pa.DictionaryArray.from_arrays(indices, column.slice(0, 1).combine_chunks(), safe=False)
        if isinstance(options.get("use_dictionary"), list):
            options["use_dictionary"] = options["use_dictionary"] + [name]
        if options.get("column_encoding"):
            options["column_encoding"] = {k: v for k, v in options["column_encoding"].items() if k != name} or None
        at = rows.schema.get_field_index(name)
        return rows.set_column(at, pa.field(name, values.type, nullable=False), values)

    def _null(self, shape: _Shape, n: int) -> "_NullChunk":
        """`shape`'s column with no value in `n` rows; each (shape, n) made once."""
        key = (shape.key, n)  # (the same for the columns of one type and encoding)
        made = self.nulls.get(key)
        if made is None:
            if len(self.nulls) > 4096:  # a row count per row group and shape: a few per part
                self.nulls.clear()
            made = self.nulls[key] = _NullChunk(shape, n)
        return made

    def close(self) -> None:
        """The footer; the file is then whole."""
        if self.writer is not None:
            self.writer.close()
            self.writer = None
            return
        if self.file is None:
            return
        t = self.template
        kv = [{1: (thrift.BINARY, k), 2: (thrift.BINARY, v)} for k, v in (self.schema.metadata or {}).items()]
        kv.append(
            {
                1: (thrift.BINARY, b"ARROW:schema"),
                2: (thrift.BINARY, base64.b64encode(self.schema.serialize().to_pybytes())),
            }
        )
        out = bytearray(t.before)  # type: ignore[union-attr]
        rows = {
            3: (thrift.I64, self.rows),
            4: (thrift.LIST, (thrift.STRUCT, self.row_groups)),
            5: (thrift.LIST, (thrift.STRUCT, kv)),
        }
        thrift.fields(out, rows, t.last)  # type: ignore[union-attr]
        out += t.after  # type: ignore[union-attr]
        data = bytes(out)
        self.file.write(data + struct.pack("<I", len(data)) + MAGIC)
        self.file.close()
        self.file = None

    def abort(self) -> None:
        """Closes without a footer (the caller removes the file)."""
        try:
            if self.writer is not None:
                self.writer.close()
        finally:
            self.writer = None
            if self.file is not None:
                self.file.close()
                self.file = None


def write_table(
    pq: Any,
    pa: Any,
    path: str,
    table: Any,
    options: Dict[str, Any],
    compression: str,
    row_group_rows: int,
    templates: Dict[Any, Optional[_Template]],
    constant: Sequence[str] = (),
) -> None:
    """One whole table as a part file at `path` (`PartFile`, then its footer; a table without
    rows as pyarrow writes it, one empty row group)."""
    if not table.num_rows:
        pq.write_table(table, path, row_group_size=row_group_rows, compression=compression, **options)
        return
    part = PartFile(pq, pa, path, table.schema, options, compression, row_group_rows, templates, constant)
    try:
        part.write(table)
        part.close()
    except BaseException:
        part.abort()
        raise


__all__: Sequence[str] = ("PartFile", "write_table", "footer")
