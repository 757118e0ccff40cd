"""The Arrow helpers of the exporters and the dataset: arrays from numpy columns, CSV text of Arrow
columns with the cell text of the CSV writer, chunks unified to one type.
"""

from __future__ import annotations

import csv
import importlib
import io
from typing import Any, List

from .writers import bool_values, text_array, valid_values, values_view


class ArrowCsvText:
    """CSV of arrow tables with the cell text of `CsvWriter` (so both paths write the same bytes):
    floats as `_cell_text` prints them (float32 as `f32_text`: `float_texts`), bools true/false,
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
                col = float_texts(np, pa, col)
            elif (pa.types.is_string(t) or pa.types.is_large_string(t)) and needs_quotes(np, pa, col):
                plain = False  # (the check in arrow: the cells become Python strings only here)
                texts = col.to_pylist()
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


def needs_quotes(np: Any, pa: Any, col: Any) -> bool:
    """Whether a string column has a cell the csv module would quote (a comma, quote or line end)."""
    if col.null_count == len(col):
        return False
    first, last = col.offset, col.offset + len(col)  # the cells' bytes, from the offsets buffer
    bounds = np.frombuffer(col.buffers()[1], dtype=np.int64 if pa.types.is_large_string(col.type) else np.int32)
    cells = bytes(memoryview(col.buffers()[2] or b"")[int(bounds[first]) : int(bounds[last])])
    if not any(c in cells for c in (b",", b'"', b"\n", b"\r")):  # (memchr: most columns)
        return False
    pc = importlib.import_module("pyarrow.compute")
    return bool(pc.any(pc.match_substring_regex(col, '[,"\n\r]')).as_py())


def _text_cells(pa: Any, col: Any) -> List[Any]:
    """Cells of an arrow column as CsvWriter prints them (strings already final)."""
    if pa.types.is_boolean(col.type):
        return [None if v is None else ("true" if v else "false") for v in col.to_pylist()]
    out: List[Any] = col.to_pylist()
    return out


def float_texts(np: Any, pa: Any, col: Any) -> Any:
    """The text of each value of a float32 / float64 arrow array as the packet path prints it
    (`f32_text`, repr(float)), as an arrow string array. pyarrow prints the same shortest digits,
    positional without a trailing `.0` over a range that covers 2e-4 to 1e15 but for some large
    float32 values (where repr is positional too): there, its text is repr's but for integral
    values; those, the values outside that range and those in pyarrow's exponent form are printed
    by repr (a float32's: its pyarrow digits read as a double, which repr prints as `f32_text`
    does: the same shortest digits, positional from 1e-4 to below 1e16, `.0` when integral)."""
    single = col.type == pa.float32()
    fast = _speedups()
    if fast is not None:
        return _c_float_texts(np, pa, fast, col, single)
    pc = importlib.import_module("pyarrow.compute")
    text = pc.cast(col, pa.string())
    values = values_view(np, col, np.float32 if single else np.float64)  # (pa.scalar would import pandas)
    size = np.abs(values.astype(np.float64))
    with np.errstate(invalid="ignore"):
        odd = np.isfinite(size) & ((size < 2e-4) | (size >= 1e15) | (size == np.floor(size)))  # integral: .0
    odd |= bool_values(np, pc.match_substring(text, "e"))  # pyarrow's exponent form
    if col.null_count:
        odd &= bool_values(np, col.is_valid())
    where = np.flatnonzero(odd)
    if len(where) == 0:
        return text
    if single:  # pyarrow's shortest float32 digits read as a double: repr prints them as f32_text does
        exact = values_view(np, pc.cast(text.take(to_arrow(np, pa, where)), pa.float64()), np.float64)
    else:
        exact = values[where]
    fixed = text_array(np, pa, list(map(repr, exact.tolist())))
    mask = np.zeros(len(values), dtype=bool)
    mask[where] = True
    return pc.replace_with_mask(text, to_arrow(np, pa, mask), fixed)


def _speedups() -> Any:
    """The C accelerator (codec/_speedups*.c), or None: pure Python."""
    from ..codec.framing import speedups

    return speedups if speedups is not None and hasattr(speedups, "repr_texts") else None


def _c_float_texts(np: Any, pa: Any, fast: Any, col: Any, single: bool) -> Any:
    """`float_texts` by the C accelerator in one pass: a float64 as repr prints it (`repr_texts`,
    Grisu3 with Python's own printer where Grisu3 gives up); a float32 as its shortest float32
    digits (pyarrow's), laid out as repr lays out the same digits (what the pure-Python branch
    gets by reading them as a double and printing it with repr): `f32_texts` (Grisu3 with a
    float's boundaries), or where Grisu3 gives up on a value of the column, pyarrow's digits laid
    out by `relayout_texts`."""
    n = len(col)
    valid = valid_values(np, col) if col.null_count else None
    ok = None if valid is None else valid.tobytes()
    size = 4 if single else 8
    values = col.buffers()[1] if col.buffers()[1] is not None else bytes(size * (n + col.offset))
    if single:
        got = fast.f32_texts(values, col.offset, n, ok) if hasattr(fast, "f32_texts") else None
        if got is None:
            text = importlib.import_module("pyarrow.compute").cast(col, pa.string())
            bufs = text.buffers()
            got = fast.relayout_texts(bufs[1], bufs[2] or b"", text.offset, n, False)
        offsets, body = got
    else:
        offsets, body = fast.repr_texts(values, col.offset, n, ok)
    at = np.frombuffer(offsets, dtype=np.int64)
    kind, width = (pa.string(), np.int32) if len(body) < 1 << 31 else (pa.large_string(), np.int64)
    mask = None if valid is None else pa.py_buffer(np.packbits(valid, bitorder="little"))
    nulls = 0 if valid is None else int(n - np.count_nonzero(valid))
    return pa.Array.from_buffers(kind, n, [mask, pa.py_buffer(at.astype(width)), pa.py_buffer(body)], nulls)


def f32_texts(np: Any, a: Any) -> Any:
    """`f32_text` of each value of a float32 numpy array, as the columnar path prints them."""
    pa = importlib.import_module("pyarrow")
    texts: List[str] = float_texts(np, pa, pa.array(a.astype(np.float32), type=pa.float32())).to_pylist()
    return np.array(texts, dtype=object)


def _csv_quote(text: str) -> str:
    """A string cell as the csv module writes it (QUOTE_MINIMAL, lineterminator \\n)."""
    if any(c in text for c in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text


def as_arrow(pa: Any, c: Any) -> Any:
    if isinstance(c, (pa.Array, pa.ChunkedArray)):
        return c
    np = importlib.import_module("numpy")
    return to_arrow(np, pa, c) if isinstance(c, np.ndarray) else pa.array(c)


def to_arrow(np: Any, pa: Any, a: Any, valid: Any = None) -> Any:
    """A one-dimensional numpy array of numbers or bools as an arrow array, sharing its memory;
    `valid` (bools) marks the non-null entries. (pa.array would do the same but imports pandas,
    about a second of start-up, on its first call.)"""
    a = np.ascontiguousarray(a)
    mask = None if valid is None else pa.py_buffer(np.packbits(valid, bitorder="little"))
    nulls = 0 if valid is None else int(len(a) - np.count_nonzero(valid))
    if a.dtype == np.bool_:
        return pa.Array.from_buffers(pa.bool_(), len(a), [mask, pa.py_buffer(np.packbits(a, bitorder="little"))], nulls)
    return pa.Array.from_buffers(pa.from_numpy_dtype(a.dtype), len(a), [mask, pa.py_buffer(a)], nulls)


def unify(pa: Any, chunks: List[Any]) -> List[Any]:
    """Chunks of one column as one arrow type (the first non-null type wins; ints widen to float)."""
    arrs = [as_arrow(pa, c) for c in chunks]
    types = [a.type for a in arrs if a.type != pa.null()]
    target = types[0] if types else pa.null()
    if any(pa.types.is_floating(t) for t in types) and pa.types.is_integer(target):
        target = next(t for t in types if pa.types.is_floating(t))
    return [a if a.type == target else a.cast(target) for a in arrs]
