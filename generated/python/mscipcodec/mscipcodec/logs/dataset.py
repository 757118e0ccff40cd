"""Raw logs to a Hive-partitioned Parquet dataset (`python -m mscipcodec export --dataset DIR LOGS...`).

The layout (docs/dataset.md), which the single-machine export and the Spark job
(`mscipcodec.spark`) both write through the functions below:

    DIR/_files/part-<LOG>.parquet                                  one row per source log
    DIR/<TABLE>/model=<MODEL>/serial=<SERIAL>/date=<YYYY-MM-DD>/part-<LOG>-<SPLIT>.parquet

`<TABLE>` is a per-(set, field) table named as `export` names its files (`sensor.scaled_accel`)
or a joined-sample table `<set>.samples`; `<LOG>` the first 16 hex digits of the SHA-256 of the
log's content; `<SPLIT>` the split's start offset as 12 hex digits. A log is cut into a fixed grid
of splits of SPLIT_BYTES; split [start, end) holds the packets whose first byte is in it: its
bytes are decoded from LOOKBACK bytes before `start` (the parser resynchronises there) to
MAX_PACKET bytes past `end` (the last packet that starts inside is complete), and only the
packets starting in [start, end) are kept, so that every packet is decoded exactly once across
the splits. Skipped bytes and bad checksums are counted for the bytes in [start, end) only.

Engines drive the same four steps per log: `log_id` and `log_identity` (model, serial and firmware
from the log's device information reply), per split `read_split` and `decode_split`, then
`write_split`; `files_row` / `write_files_row` record the log in `_files`. `export_dataset` is the
single-machine driver: it decodes each split in windows of WINDOW_BYTES (`windows`, each timed by
`range_clocks`) and writes the split's part files as the windows come (`SplitWriter`), so that its
memory is bounded by a window whatever the size of the logs and splits. numpy and pyarrow are imported when used (the `[export]` extra).
"""

from __future__ import annotations

import functools
import hashlib
import importlib
import os
import re
import sys
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, Iterable, List, Optional, Sequence, Tuple

from .. import _columns, registry
from .._protocol import CHECKSUM_SIZE, HEADER_SIZE, LENGTH_OFFSET, MAX_PACKET, SYNC, TIMESTAMPS
from .._protocol import PACKAGE as PROG
from . import parquet_part
from .arrow import as_arrow, to_arrow, unify
from .export import FastExporter
from .identity import UNKNOWN, Identity, ReadAt, ReadError, file_reader, log_identity, partition_value
from .info import bad_checksums
from .pipeline import split_device
from .writers import bool_values, need, progress_bar, table_name, text_array, values_view

SPLIT_BYTES = 64 << 20  # the split grid (bytes of log per task / per part file)
LOOKBACK = 64 << 10  # bytes decoded before a split's start so that the parser is in sync at it
ROW_GROUP_ROWS = 1 << 20  # rows per Parquet row group (docs/dataset.md: sizes for object storage)
# The local driver decodes a split window by window (memory bounded by a window, not by the split)
# and writes each part file of the split as its windows come, a row group per ROW_GROUP_BYTES of
# rows (PENDING_BYTES of rows held in all, the largest written first beyond that).
WINDOW_BYTES = 4 << 20
ROW_GROUP_BYTES = 48 << 20
PENDING_BYTES = 160 << 20
# The time facts of a log's first windows kept from the clock pass for the decode (range_clocks)
HELD_TIME_BYTES = 64 << 20
COMPRESSION = "zstd"
META = f"{PROG}.".encode()  # the namespace of the Parquet metadata keys: the package's name
FILES_TABLE = "_files"
# The `date` partition of rows without a UTC time: a plain value every reader takes as a string
# (pyarrow's hive partitioning fails on a field whose every value is Hive's null spelling
# `__HIVE_DEFAULT_PARTITION__`), spelled as the `unknown` model and serial (docs/dataset.md).
DEFAULT_PARTITION = "unknown"
SAMPLES = "samples"  # joined-sample tables: <set>.samples
BASE_COLUMNS = ("t_ns", "time", "offset", "log", "device_ns", "gps_week", "gps_tow")
PARTITION_COLUMNS = ("model", "serial", "date")


# ---------------------------------------------------------------------------------- the grid
def log_id(path: str) -> str:
    """The log's id: the first 16 hex digits of the SHA-256 of its whole content (read in pieces).
    ReadError when it cannot be read."""
    h = hashlib.sha256()
    buf = bytearray(1 << 20)  # (one buffer read into: a fresh 4 MiB bytes per read cost page faults)
    view = memoryview(buf)
    try:
        with open(path, "rb", buffering=0) as f:
            while True:
                n = f.readinto(buf)
                if not n:
                    break
                h.update(view[:n])
    except OSError as e:
        raise ReadError(e.strerror or str(e)) from None
    return h.hexdigest()[:16]


def splits(size: int, split_bytes: int = SPLIT_BYTES) -> List[Tuple[int, int]]:
    """The split grid of a log of `size` bytes: [(k*S, min((k+1)*S, size))]; one empty split for
    an empty log (so that it is still decoded and recorded)."""
    if split_bytes <= 0:
        raise ValueError("split_bytes must be positive")
    if size <= 0:
        return [(0, 0)]
    return [(s, min(s + split_bytes, size)) for s in range(0, size, split_bytes)]


def split_name(start: int) -> str:
    """<SPLIT> of a part file: the split's start offset as 12 hex digits."""
    return f"{start:012x}"


def read_split(read_at: ReadAt, size: int, start: int, end: int) -> Tuple[bytes, int]:
    """The bytes a split decodes and the log offset of their first byte:
    [max(0, start - LOOKBACK), min(size, end + MAX_PACKET))."""
    lo = max(0, start - LOOKBACK)
    hi = min(size, end + MAX_PACKET)
    return read_at(lo, hi - lo), lo


# --------------------------------------------------------------------------------- the schema
def column_name(export_name: str) -> str:
    """A dataset column name from an export column name: '.', '[' and ']' as '_' (runs as one,
    none at the ends): scaled_accel.x -> scaled_accel_x, satellites[0].prn -> satellites_0_prn."""
    return re.sub(r"[.\[\]]+", "_", export_name).strip("_")


def arrow_type(kind: str) -> Any:
    """The Arrow type of a column kind of `_columns` (the type depends on the spec only)."""
    pa = _need("pyarrow")
    return {
        "float32": pa.float32(),
        "float64": pa.float64(),
        "int": pa.int64(),
        "bits": pa.int64(),
        "bool": pa.bool_(),
        "enum": pa.string(),  # the enum value's name from the spec (its number when the spec has none)
        "json": pa.string(),
    }[kind]


def base_fields() -> List[Any]:
    """The leading columns of every table (t_ns, time, offset, log, device_ns, gps_week, gps_tow)."""
    pa = _need("pyarrow")
    meta = {
        "t_ns": ("ns", "UTC time, nanoseconds since 1970-01-01 00:00:00 UTC (null when unknown)"),
        "time": ("", "UTC time (t_ns to microseconds)"),
        "offset": ("bytes", "offset of the packet's first byte in the log"),
        "log": ("", "the log's id: first 16 hex digits of the SHA-256 of its content"),
        "device_ns": ("ns", "the device's own clock (reference timestamp), as sent"),
        "gps_week": ("weeks", "GPS week number the packet carries, as sent"),
        "gps_tow": ("s", "GPS time of week the packet carries, as sent"),
    }
    types = {
        "t_ns": pa.int64(),
        "time": pa.timestamp("us", tz="UTC"),
        "offset": pa.int64(),
        "log": pa.string(),
        "device_ns": pa.int64(),
        "gps_week": pa.int32(),
        "gps_tow": pa.float64(),
    }
    out = []
    for name in BASE_COLUMNS:
        units, description = meta[name]
        md = {"description": description}
        if units:
            md["units"] = units
        out.append(pa.field(name, types[name], nullable=name not in ("offset", "log"), metadata=md))
    return out


def _value_fields(set_id: int, key: Tuple[int, int, Optional[str]]) -> List[Any]:
    """The value columns of one field layout (key of `_columns.COLUMNS`) with their metadata."""
    pa = _need("pyarrow")
    title = _columns.TITLES.get(key, "")
    descriptions = _columns.DESCRIPTIONS
    frames: Dict[Any, Tuple[Optional[str], ...]] = getattr(_columns, "FRAMES", {})
    out = []
    for j, (name, _path, units, kind, _enum) in enumerate(_columns.COLUMNS.get(key, ())):
        md = {"set": f"0x{set_id:02X}", "descriptor": f"0x{key[1]:02X}", "title": title}
        if key[0] != set_id:
            md["field_set"] = f"0x{key[0]:02X}"  # a shared field: the shared set it belongs to
        if units:
            md["units"] = units
        desc = descriptions.get(key, ())
        md["description"] = desc[j] if j < len(desc) and desc[j] else title
        frame = frames.get(key, ())
        if j < len(frame) and frame[j]:
            md["frame"] = str(frame[j])
        out.append(pa.field(column_name(name), arrow_type(kind), metadata=md))
    return out


@functools.cache
def table_schema(set_id: int, key: Tuple[int, int, Optional[str]]) -> Any:
    """The Arrow schema of the per-field table of layout `key` in packets of set `set_id`
    (partition columns not included; made once: every window of every log asks)."""
    pa = _need("pyarrow")
    return pa.schema(base_fields() + _value_fields(set_id, key))


def set_layouts(set_id: int) -> List[Tuple[int, int, Optional[str]]]:
    """The layouts a packet of data set `set_id` can carry: the shared fields (FIRST_SHARED and up,
    of the protocol's shared set) then the set's own fields, by descriptor (spec order)."""
    shared = getattr(registry, "SHARED_SET", None)
    own = sorted(k for k in _columns.COLUMNS if k[0] == set_id)
    common = sorted(k for k in _columns.COLUMNS if shared is not None and k[0] == shared and shared != set_id)
    return common + own


@functools.cache
def samples_schema(set_id: int) -> Any:
    """The Arrow schema of `<set>.samples`: the base columns, then the columns of every layout of
    `set_layouts` (a name met twice, as per-device variants of a field, once: the first)."""
    pa = _need("pyarrow")
    fields = base_fields()
    seen = {f.name for f in fields}
    for key in set_layouts(set_id):
        for f in _value_fields(set_id, key):
            if f.name not in seen:
                seen.add(f.name)
                fields.append(f)
    return pa.schema(fields)


@functools.cache
def _value_columns(set_id: int) -> Tuple[Tuple[str, Any], ...]:
    """(name, type) of the value columns of `<set>.samples` (after the base columns)."""
    schema = samples_schema(set_id)
    return tuple((schema.field(j).name, schema.field(j).type) for j in range(len(BASE_COLUMNS), len(schema)))


def data_sets() -> List[int]:
    """The data sets with tables (those with field layouts, the shared set excluded)."""
    shared = getattr(registry, "SHARED_SET", None)
    return sorted({k[0] for k in _columns.COLUMNS if k[0] != shared})


def table_names() -> Dict[str, Any]:
    """Every table the spec can give: name -> schema (per field in each data set, shared
    fields in each data set, and `<set>.samples`)."""

    out: Dict[str, Any] = {}
    for set_id in data_sets():
        for key in set_layouts(set_id):
            out[table_name(set_id, _Key(key))] = table_schema(set_id, key)
        out[samples_name(set_id)] = samples_schema(set_id)
    return out


class _Key:
    """A layout key seen as a layout class by `writers.table_name` (SET, NAME, DEVICE)."""

    def __init__(self, key: Tuple[int, int, Optional[str]]) -> None:
        self.SET, self.DESCRIPTOR, self.DEVICE = key
        self.NAME = _field_name(key)


def _field_name(key: Tuple[int, int, Optional[str]]) -> str:
    specs = _columns.COLUMNS.get(key, ())
    if specs:
        return specs[0][0].split(".")[0].split("[")[0]
    return f"field_{key[1]:02x}"


def samples_name(set_id: int) -> str:
    return f"{registry.SET_NAMES.get(set_id, f'set_{set_id:02x}')}.{SAMPLES}"


def file_metadata(identity: Identity, log: str, split_start: int) -> Dict[bytes, bytes]:
    """The Parquet file (schema) metadata of a part (keys in the package's namespace, `mscipcodec.model`)."""
    return {
        META + b"spec_version": _spec_version().encode(),
        META + b"spec_hash": _spec_hash().encode(),
        META + b"package": PROG.encode(),
        META + b"model": identity.model.encode(),
        META + b"serial": identity.serial.encode(),
        META + b"firmware": (identity.firmware or "").encode(),
        META + b"log": log.encode(),
        META + b"split": split_name(split_start).encode(),
    }


def _spec_hash() -> str:
    """The package's SPEC_HASH (16 hex digits of the SHA-256 of the protocol's canonical IR)."""
    return str(getattr(importlib.import_module(PROG), "SPEC_HASH", ""))


def _spec_version() -> str:
    """The package's version (docs/versioning.md: it moves with the spec)."""
    return str(getattr(importlib.import_module(PROG), "__version__", ""))


# ------------------------------------------------------------------------------ decode a split
@dataclass
class SplitResult:
    """One split decoded: `tables[name]` (pyarrow Tables in the dataset's columns, partition
    columns not included, rows in stream order) and the split's counts for `_files`."""

    log: str
    start: int
    end: int
    identity: Identity
    tables: Dict[str, Any] = field(default_factory=dict)
    packets: int = 0
    skipped_bytes: int = 0
    bad_checksums: int = 0
    truncated: bool = False  # the split ends the log inside a packet
    first_t_ns: Optional[int] = None
    last_t_ns: Optional[int] = None
    # per `<set>.samples` table: the sample key of its first and of its last packet (None: no key)
    sample_edges: Dict[str, Tuple[Any, Any]] = field(default_factory=dict)


def decode_split(
    data: bytes,
    base: int,
    start: int,
    end: int,
    clock: Any = None,
    identity: Optional[Identity] = None,
    log: str = "",
    size: Optional[int] = None,
    time_arrays: Any = None,
) -> SplitResult:
    """Decode the packets whose first byte is in [start, end) from `data` (the bytes of the log
    from offset `base`, as `read_split` gives them) into the dataset's tables.

    `clock` is the split's clock (`clock_maps(...)[k]`, a timebase.SplitClock; None: the split
    is taken as a whole log, `whole_clock`) for the UTC time of packets with only the device clock; `identity` the log's (`log_identity`); `log` its id; `size` the log's size (the
    split that ends the log checks whether it ends inside a packet); `time_arrays` the
    window's time facts from `range_clocks` (None: taken from the decode). Counts are for [start, end)."""
    np = _need("numpy")
    pa = _need("pyarrow")
    from ..codec.packets import decode_columns

    ident = identity if identity is not None else Identity()
    result = SplitResult(log, start, end, ident)
    cols = decode_columns(data)
    split_device(cols, data, ident, log)  # the log's device, else DeviceUnknown (a ReadError)
    # skipped bytes and bad checksums inside [start, end)
    for skip in cols.skips:
        a, b = skip.offset + base, skip.offset + base + len(skip.data)
        lo, hi = max(a, start), min(b, end)
        if lo < hi:
            result.skipped_bytes += hi - lo
            result.bad_checksums += _bad_checksums(bytes(skip.data[lo - a :]), hi - lo)
        if size is not None and end == size and b == size == base + len(data) and lo < hi:
            result.truncated = _ends_in_packet(bytes(skip.data))
    maker = _Pieces("", "parquet", None, False)
    pieces = maker.pieces(cols, data, base)
    times = _PacketTimes(
        np, cols, base, start, end, clock if clock is not None else whole_clock(data, base, start, end), time_arrays
    )
    per_set: Dict[int, List[Tuple[Any, Any, Any, Any]]] = {}
    for (set_id, cls), parts in pieces.items():
        if len(parts) == 1:
            offs = np.asarray(parts[0][0], dtype=np.int64) + base
            idx = np.asarray(parts[0][1], dtype=np.int64)
        else:
            offs = np.concatenate([np.asarray(p[0], dtype=np.int64) for p in parts]) + base
            idx = np.concatenate([np.asarray(p[1], dtype=np.int64) for p in parts])
        if len(parts) == 1 and bool((offs[1:] > offs[:-1]).all()):
            # one entry per packet, in stream order (the usual case): the rows in [start, end)
            # are a slice
            lo, hi = (int(i) for i in np.searchsorted(offs, [start, end]))
            if lo == hi:
                continue
            offs, idx = offs[lo:hi], idx[lo:hi]
            sel = None
            contiguous = True
        else:
            order = np.lexsort((idx, offs))
            offs, idx = offs[order], idx[order]
            keep = (offs >= start) & (offs < end)
            if not keep.any():
                continue
            sel = order[keep]
            offs, idx = offs[keep], idx[keep]
            lo = int(sel[0])
            contiguous = bool(sel[-1] - lo == len(sel) - 1 and (len(sel) < 2 or (np.diff(sel) == 1).all()))
        key = (cls.SET, cls.DESCRIPTOR, cls.DEVICE)
        values = []
        for j in range(2, len(parts[0][2])):
            chunk = unify(pa, [p[2][j] for p in parts])
            col = as_arrow(pa, chunk[0] if len(chunk) == 1 else pa.concat_arrays(chunk))
            # rows in stream order already (the usual case): a slice, not a copy
            values.append(col.slice(lo, len(offs)) if contiguous else col.take(_ints(np, pa, sel)))
        schema = table_schema(set_id, key)
        table = _table(np, pa, schema, times, offs, log, values)
        result.tables[table_name(set_id, cls)] = table
        per_set.setdefault(set_id, []).append((key, offs, idx, table))
    for set_id, tables in per_set.items():
        edges: List[Any] = []
        result.tables[samples_name(set_id)] = _join(np, pa, set_id, tables, times, log, edges)
        result.sample_edges[samples_name(set_id)] = (edges[0], edges[1])
    packets = _packet_offsets(np, cols, base)
    packets = packets[(packets >= start) & (packets < end)]
    result.packets = int(len(packets))
    if len(packets):
        t = times.t_ns_known(start, end)
        if len(t):
            result.first_t_ns, result.last_t_ns = int(t.min()), int(t.max())
    return result


def _packet_offsets(np: Any, cols: Any, base: int) -> Any:
    """The sorted log offsets of the packets of a decoded window: those of its field entries (in
    a table or among the others; a packet with an empty payload has none and is not counted)."""
    parts = [np.frombuffer(t.offsets, dtype=np.int64) for t in cols.tables.values() if t.rows]
    if cols.others:
        parts.append(np.fromiter((o for o, _k, _e in cols.others), dtype=np.int64, count=len(cols.others)))
    if not parts:
        return np.zeros(0, dtype=np.int64)
    out: Any = _union(np, parts) + base
    return out


def _union(np: Any, parts: List[Any]) -> Any:
    """The sorted distinct values of int64 arrays (packet offsets): the fields of one packet type
    give equal arrays, each taken once; one strictly rising array is its own union."""
    distinct: List[Any] = []
    for a in parts:
        if not any(len(b) == len(a) and np.array_equal(b, a) for b in distinct):
            distinct.append(a)
    if len(distinct) == 1 and bool((distinct[0][1:] > distinct[0][:-1]).all()):
        return distinct[0]
    return _sorted_unique(np, np.concatenate(distinct))


def _sorted_unique(np: Any, a: Any) -> Any:
    """The distinct values of an int64 array, sorted (np.unique without its hashing path)."""
    a = np.sort(a, kind="stable")
    keep = np.ones(len(a), dtype=bool)
    keep[1:] = a[1:] != a[:-1]
    return a[keep]


def _table(np: Any, pa: Any, schema: Any, times: Any, offs: Any, log: str, values: List[Any]) -> Any:
    """A table of the schema: the base columns of the packets at `offs`, then `values`."""
    arrays = times.base_columns(offs, log) + [
        _cast(pa, v, schema.field(len(BASE_COLUMNS) + j).type) for j, v in enumerate(values)
    ]
    return pa.Table.from_arrays(arrays, schema=schema)


def _cast(pa: Any, a: Any, t: Any) -> Any:
    if a.type == t:
        return a
    if pa.types.is_string(t) and not pa.types.is_string(a.type):
        return pa.array([None if v is None else str(v) for v in a.to_pylist()], type=t)
    try:
        return a.cast(t)
    except (pa.ArrowInvalid, pa.ArrowNotImplementedError):
        return a.cast(t, safe=False)  # uint64 values from 2^63 up wrap (docs/dataset.md)


def _join(
    np: Any, pa: Any, set_id: int, tables: List[Tuple[Any, Any, Any, Any]], times: Any, log: str, edges: Any = None
) -> Any:
    """`<set>.samples`: one row per sample (docs/conformance.md section 6, as `export --join`):
    consecutive packets of the set with the same sample key (the timestamp fields of the sample
    rule, equal values) make one row; no key, one row per packet; a column's first value wins.
    `edges` (a list) gets the sample key of the first and of the last packet (None: no key)."""
    schema = samples_schema(set_id)
    packets = _union(np, [t[1] for t in tables])
    n = len(packets)
    # the sample key per packet: (present, values) of each TIMESTAMPS field
    new = np.ones(n, dtype=bool)
    keyed = np.zeros(n, dtype=bool)
    same = np.ones(max(n - 1, 0), dtype=bool)
    key_values: List[Tuple[Any, Any]] = []  # (present, values) per key field and per column
    for key, offs, _idx, table in tables:
        if key[1] not in TIMESTAMPS or key[0] == set_id:
            continue
        first = np.ones(len(offs), dtype=bool)
        first[1:] = offs[1:] != offs[:-1]
        pos = _positions(np, packets, offs[first])
        present = np.zeros(n, dtype=bool)
        present[pos] = True
        keyed |= present
        same &= present[1:] == present[:-1]
        keep_first = None if bool(first.all()) else to_arrow(np, pa, first)
        for c in range(len(BASE_COLUMNS), table.num_columns):
            col = _chunk(table.column(c))
            col = col if keep_first is None else col.filter(keep_first)
            vals = np.zeros(n, dtype=np.float64)
            vals[pos] = _floats(np, pa, col)
            same &= (vals[1:] == vals[:-1]) | ~present[1:]
            key_values.append((present, vals))
    if n > 1:
        new[1:] = ~(same & keyed[1:] & keyed[:-1])
    if edges is not None:
        edges[:] = [_packet_key(keyed, key_values, i) for i in ((0, n - 1) if n else (None, None))]
    group = np.cumsum(new) - 1
    rows = int(group[-1]) + 1 if n else 0
    row_offs = packets[new]
    arrays: Dict[str, Any] = {}  # name -> (rows filled, values, whether `rows` is rising)
    seen: List[Tuple[Any, Any]] = []  # (offsets, group) of the tables so far: mostly the same packets
    for _key, offs, _idx, table in tables:
        g = next((grp for o, grp in seen if len(o) == len(offs) and (o is offs or np.array_equal(o, offs))), None)
        if g is None:
            g = group[_positions(np, packets, offs)]
            seen.append((offs, g))
        firsts = np.ones(len(g), dtype=bool)
        firsts[1:] = g[1:] != g[:-1]
        target = g[firsts]
        take = None if firsts.all() else _ints(np, pa, np.flatnonzero(firsts))
        for c in range(len(BASE_COLUMNS), table.num_columns):
            name = table.schema.field(c).name
            col = _chunk(table.column(c))
            col = col if take is None else col.take(take)
            prev = arrays.get(name)
            if prev is None:
                arrays[name] = (target, col, True)  # (`target` rises: `g` does, its repeats dropped)
            else:  # first value wins: only the rows this column did not fill yet
                have = np.zeros(rows, dtype=bool)
                have[prev[0]] = True
                extra = ~have[target]
                if extra.any():
                    arrays[name] = (
                        np.concatenate([prev[0], target[extra]]),
                        pa.concat_arrays([prev[1], col.filter(to_arrow(np, pa, extra))]),
                        False,
                    )
    # a row's time: its first packet with one (a row per packet: the packets' own, as made for
    # the set's tables)
    out = times.base_columns(row_offs, log, None if rows == n else times.row_times(packets, group, rows))
    nulls: Dict[Any, Any] = {}  # type -> the all-null column of this table's rows (one per type)
    for name, t in _value_columns(set_id):
        entry = arrays.get(name)
        if entry is None:
            empty = nulls.get(t)
            if empty is None:
                empty = nulls[t] = _nulls(pa, rows, t)
            out.append(empty)
            continue
        where, col, rising = entry
        col = _cast(pa, col, t)
        if len(where) == rows and (rising or rows == 0 or (where[0] == 0 and (np.diff(where) == 1).all())):
            out.append(col)  # every row, in order
            continue
        full_idx = np.full(rows, -1, dtype=np.int64)
        full_idx[where] = np.arange(len(where))
        mask = full_idx < 0
        full_idx[mask] = 0
        taken = col.take(_ints(np, pa, full_idx))
        out.append(_null_where(np, pa, taken, mask))
    return pa.Table.from_arrays(out, schema=schema)


def _positions(np: Any, packets: Any, offs: Any) -> Any:
    """The index in `packets` (sorted) of each of `offs` (members of it): without a search when
    they are all the packets (a field every packet of the set carries)."""
    if len(offs) == len(packets) and np.array_equal(offs, packets):
        return np.arange(len(packets))
    return np.searchsorted(packets, offs)


def _packet_key(keyed: Any, key_values: List[Tuple[Any, Any]], i: Optional[int]) -> Any:
    """The sample key of packet i of a join (None without one): what `_join` compares."""
    if i is None or not keyed[i]:
        return None
    return tuple((bool(p[i]), float(v[i]) if p[i] else None) for p, v in key_values)


def _chunk(col: Any) -> Any:
    """A table column as one array: its chunk when it has one (combine_chunks would copy it)."""
    return col.chunk(0) if col.num_chunks == 1 else col.combine_chunks()


def _ints(np: Any, pa: Any, a: Any) -> Any:
    """An arrow int64 array of a numpy array of indices (pa.array would import pandas, about a
    quarter of a second, on its first call: the helpers here build arrays from buffers)."""
    return to_arrow(np, pa, np.asarray(a, dtype=np.int64))


def _floats(np: Any, pa: Any, col: Any) -> Any:
    """The values of a numeric arrow array as float64 numpy, null as 0."""
    pc = importlib.import_module("pyarrow.compute")
    out = values_view(np, pc.cast(col, pa.float64(), safe=False), np.float64)
    return np.where(bool_values(np, col.is_valid()), out, 0.0) if col.null_count else out


_REPEATED: Dict[str, Any] = {}  # text -> an array of copies of it, sliced by `_repeated`


def _repeated(np: Any, pa: Any, text: str, n: int) -> Any:
    """An arrow string array of `n` copies of `text` (a slice of one array per text, grown as
    needed)."""
    have = _REPEATED.get(text)
    if have is None or len(have) < n:
        size = max(n, 1 << 16, 2 * len(have) if have is not None else 0)
        if size * len(text.encode("utf-8")) >= 1 << 31:  # (a large_string: made for `n` alone)
            return _repeated_array(np, pa, text, n)
        if len(_REPEATED) > 8:
            _REPEATED.clear()
        have = _REPEATED[text] = _repeated_array(np, pa, text, size)
    return have.slice(0, n)


def _repeated_array(np: Any, pa: Any, text: str, n: int) -> Any:
    body = text.encode("utf-8")
    offsets = np.arange(n + 1, dtype=np.int64) * len(body)
    kind, width = (pa.string(), np.int32) if n * len(body) < 1 << 31 else (pa.large_string(), np.int64)
    return pa.Array.from_buffers(kind, n, [None, pa.py_buffer(offsets.astype(width)), pa.py_buffer(body * n)], 0)


_TIMESTAMP: List[Any] = []  # [pa.timestamp("us", tz="UTC")], made on first use


_NULLS: Dict[Any, Any] = {}  # type -> an all-null array, sliced by `_nulls` (grown as needed)


def _nulls(pa: Any, n: int, t: Any) -> Any:
    """An all-null array of `n` rows of type `t`: a slice of one array per type, so that the
    columns a table does not fill (most of a `<set>.samples` table's) take no memory per window."""
    have = _NULLS.get(t)
    if have is None or len(have) < n:
        have = _NULLS[t] = pa.nulls(max(n, 1 << 16, 2 * len(have) if have is not None else 0), type=t)
    return have.slice(0, n)


def _null_where(np: Any, pa: Any, a: Any, mask: Any) -> Any:
    if not mask.any():
        return a
    pc = importlib.import_module("pyarrow.compute")
    return pc.if_else(to_arrow(np, pa, mask), pa.nulls(len(a), type=a.type), a)


class _PacketTimes:
    """The time columns of the packets of a decoded window (timebase: the split's clock map):
    t_ns (UTC), the device clock and the GPS week / time of week the packet carries, as sent."""

    def __init__(self, np: Any, cols: Any, base: int, start: int, end: int, clock: Any, arrays: Any = None) -> None:
        self.np = np
        self.block = clock.block(cols, base, start, end, arrays)
        # the base columns of the last packet offsets asked (the field tables of a data set
        # mostly have the same packets: their arrays are made once and shared)
        self.made: List[Tuple[Any, List[Any]]] = []
        self.looked: List[Tuple[Any, Dict[str, Tuple[Any, Any]]]] = []

    def columns(self, offs: Any) -> Dict[str, Tuple[Any, Any]]:
        """name -> (values, valid) of t_ns, device_ns, gps_week, gps_tow for packet offsets
        (the last few asked kept: the tables of a window mostly ask for the same packets)."""
        offs = self.np.asarray(offs, dtype=self.np.int64)
        for seen, cols in self.looked:
            if len(seen) == len(offs) and (seen is offs or self.np.array_equal(seen, offs)):
                return cols
        got = self.block.lookup(offs)
        out = {
            "t_ns": (got["t_ns"], got["t_valid"]),
            "device_ns": (got["device_ns"], got["device_valid"]),
            "gps_week": (got["gps_week"], got["gps_valid"]),
            "gps_tow": (got["gps_tow"], got["gps_valid"]),
        }
        self.looked = [(offs, out)] + self.looked[:3]
        return out

    def t_ns_of(self, offs: Any) -> Any:
        vals, valid = self.columns(offs)["t_ns"]
        return vals[valid]

    def t_ns_known(self, start: int, end: int) -> Any:
        """The known t_ns of the packets in [start, end) (those of `t_ns_of` of all of them: a
        packet without a time fact has none; the block's packets are sorted by offset)."""
        b = self.block
        lo, hi = (int(i) for i in self.np.searchsorted(b.offset, [start, end]))
        return b.t_ns[lo:hi][b.t_valid[lo:hi]]

    def row_times(self, packets: Any, group: Any, rows: int) -> Dict[str, Tuple[Any, Any]]:
        """Per joined row: each time column from the row's first packet that has it."""
        np = self.np
        cols = self.columns(packets)
        out = {}
        for name, (vals, valid) in cols.items():
            rv = np.zeros(rows, dtype=vals.dtype)
            rk = np.zeros(rows, dtype=bool)
            # the last write wins: written in reverse, the first valid packet of a group stays
            idx = np.flatnonzero(valid)[::-1]
            rv[group[idx]] = vals[idx]
            rk[group[idx]] = True
            out[name] = (rv, rk)
        return out

    def base_columns(self, offs: Any, log: str, given: Optional[Dict[str, Tuple[Any, Any]]] = None) -> List[Any]:
        """Arrow arrays of the base columns (BASE_COLUMNS order) of rows at packet offsets `offs`."""
        np = self.np
        pa = _need("pyarrow")
        if not _TIMESTAMP:
            _TIMESTAMP.append(pa.timestamp("us", tz="UTC"))
        offs = np.asarray(offs, dtype=np.int64)
        if given is None:
            for seen, arrays in self.made:
                if len(seen) == len(offs) and (seen is offs or np.array_equal(seen, offs)):
                    return list(arrays)
        cols = given if given is not None else self.columns(offs)
        t_ns, t_ok = cols["t_ns"]
        t_ns = np.ascontiguousarray(t_ns, dtype=np.int64)
        n = len(t_ns)
        # t_ns and time share one validity bitmap; time made as a timestamp from its buffers (a
        # cast would copy it)
        missing = n - int(np.count_nonzero(t_ok))
        mask = pa.py_buffer(np.packbits(t_ok, bitorder="little")) if missing else None
        out = [
            pa.Array.from_buffers(pa.int64(), n, [mask, pa.py_buffer(t_ns)], missing),
            pa.Array.from_buffers(_TIMESTAMP[0], n, [mask, pa.py_buffer(t_ns // 1000)], missing),
            to_arrow(np, pa, offs),
            _repeated(np, pa, log, len(offs)),
        ]
        for name, dtype in (("device_ns", np.int64), ("gps_week", np.int32), ("gps_tow", np.float64)):
            vals, ok = cols[name]
            out.append(to_arrow(np, pa, np.asarray(vals).astype(dtype), ok))
        if given is None:
            self.made = [(offs, out)] + self.made[:3]
        return list(out)


class _Pieces(FastExporter):
    """The columnar exporter's pieces with enum names taken per distinct value (not per row)."""

    def _column(self, a: Any, kind: str, enum: Optional[str]) -> Any:
        if kind != "enum" or self.enum_numbers:
            return super()._column(a, kind, enum)
        np, pa = self.np, self.pa
        names = _columns.ENUMS.get(enum or "", {})
        a = a.reshape(-1)
        if len(a) and a.dtype.kind in "iu" and int(a.min()) >= 0 and int(a.max()) < 1 << 16:
            # small codes (every enum of the spec): the distinct values by a table, not a sort
            seen = np.zeros(int(a.max()) + 1, dtype=bool)
            seen[a] = True
            values = np.flatnonzero(seen)
            where = (np.cumsum(seen) - 1)[a]
        else:
            values, where = np.unique(a, return_inverse=True)
        texts = text_array(np, pa, [names.get(int(v), str(int(v))) for v in values.tolist()])
        return texts.take(to_arrow(np, pa, where.astype(np.int64).reshape(-1)))


def whole_clock(data: bytes, base: int, start: int, end: int) -> Any:
    """The clock of a split decoded on its own as a whole log (no split before it)."""
    from . import timebase

    return timebase.ClockMap.from_splits([timebase.split_anchors(data, base, start, end)]).split(0)


def _bad_checksums(run: bytes, starts: int) -> int:
    """Complete packets with a wrong checksum inside a skipped run (`info.bad_checksums`), among
    those whose sync starts in the run's first `starts` bytes."""

    return bad_checksums(run, starts)


def _ends_in_packet(run: bytes) -> bool:
    """True when a skipped run that ends the log holds the start of a packet cut by the end: a
    sync whose header is incomplete or whose stated length runs past the end."""
    i = run.find(SYNC)
    while i >= 0:
        if len(run) - i < HEADER_SIZE:
            return True
        if i + HEADER_SIZE + run[i + LENGTH_OFFSET] + CHECKSUM_SIZE > len(run):
            return True
        i = run.find(SYNC, i + 1)
    return False


# ------------------------------------------------------------------------------------- writing
def write_split(out_dir: str, result: SplitResult) -> List[str]:
    """Write the tables of a decoded split as part files (paths relative to `out_dir` returned):
    partitioned by model, serial and UTC date, rows sorted by (t_ns nulls last, offset), each
    written under a dot name in its directory and renamed whole (a crash leaves no visible part)."""
    np = _need("numpy")
    pa = _need("pyarrow")
    written: List[str] = []
    meta = file_metadata(result.identity, result.log, result.start)
    for name in sorted(result.tables):
        table = result.tables[name]
        if table.num_rows == 0:
            continue
        table = _sorted(np, pa, table)
        for date, part in _by_date(np, pa, table):
            part = part.replace_schema_metadata({**(table.schema.metadata or {}), **meta})
            rel = os.path.join(
                name,
                f"model={result.identity.model}",
                f"serial={result.identity.serial}",
                f"date={date or DEFAULT_PARTITION}",
                f"part-{result.log}-{split_name(result.start)}.parquet",
            )
            _write_atomic(pa, os.path.join(out_dir, rel), part)
            written.append(rel)
    return written


def _sorted(np: Any, pa: Any, table: Any, memo: Optional[Dict[Any, Any]] = None) -> Any:
    """The table's rows by (t_ns, nulls last; then offset): taken only when they are not in that
    order already (a log's rows mostly are). `memo` (a dict, for the tables of one window, alive
    together) keeps the order found per set of time and offset columns: the tables of a data set
    mostly share them (`_PacketTimes.base_columns`)."""
    plan = _planned(memo, table, lambda: _order(np, pa, table))
    if plan is True:
        return table
    if isinstance(plan, int):
        return pa.concat_tables([table.slice(plan), table.slice(0, plan)])
    return table.take(plan)


def _planned(memo: Optional[Dict[Any, Any]], table: Any, plan: Callable[[], Any]) -> Any:
    """`plan()`, kept in `memo` (when given) under the table's `_order_key`: found once for the
    tables of a window that share their time and offset columns."""
    key = _order_key(table) if memo is not None else None
    if memo is None or key is None:
        return plan()
    if key not in memo:
        memo[key] = plan()
    return memo[key]


def _order_key(table: Any) -> Optional[Tuple[Any, ...]]:
    """What the rows' order and dates depend on: the buffers of t_ns, time and offset (their
    addresses, offsets and lengths); None when a column has several chunks (a combined copy
    would be freed, and its address reused)."""
    key: List[Any] = [table.num_rows]
    for name in ("t_ns", "time", "offset"):
        col = table.column(name)
        if col.num_chunks != 1:
            return None
        a = col.chunk(0)
        key.append(a.offset)
        key.extend(None if b is None else b.address for b in a.buffers())
    return tuple(key)


def _order(np: Any, pa: Any, table: Any) -> Any:
    """How `_sorted` puts the rows in order: True (they are), k (the last rows first, from k:
    a log's first rows without a time), or the indices to take (an arrow array)."""
    t_ns = _chunk(table.column("t_ns"))
    offs = values_view(np, _chunk(table.column("offset")), np.int64)
    valid = np.ones(len(t_ns), dtype=bool) if t_ns.null_count == 0 else bool_values(np, t_ns.is_valid())
    t = values_view(np, t_ns, np.int64)
    if t_ns.null_count:
        t = np.where(valid, t, 0)
    known = int(valid.sum())
    if known == len(t) and bool((t[1:] > t[:-1]).all()):  # rising times (most tables): in order
        return True
    if bool(valid[:known].all()):  # nulls (if any) last: in order when each part is (a stable sort)
        step = np.diff(t[:known])
        if bool((step >= 0).all() and (np.diff(offs[:known])[step == 0] >= 0).all()):
            if bool((np.diff(offs[known:]) >= 0).all()):
                return True
    if 0 < known < len(t) and not valid[: len(t) - known].any():  # nulls first (a log's start):
        k = len(t) - known  # the known rows then the null rows, when each part is in order
        step = np.diff(t[k:])
        if bool((step >= 0).all() and (np.diff(offs[k:])[step == 0] >= 0).all()):
            if bool((np.diff(offs[:k]) >= 0).all()):
                return k
    order = np.lexsort((offs, t, ~valid))  # stable, as the sort it stands for
    return _ints(np, pa, order)


DAY_US = 86_400_000_000


def _by_date(np: Any, pa: Any, table: Any, memo: Optional[Dict[Any, Any]] = None) -> List[Tuple[Optional[str], Any]]:
    """The table's rows by UTC date of `time` ("YYYY-MM-DD"; None: no time), in date order with
    None last; rows in their order within each date. `memo` as `_sorted`'s (the dates of tables
    that share their time columns found once)."""
    plan = _planned(memo, table, lambda: _dates(np, pa, table))
    if len(plan) == 1:
        return [(plan[0][0], table)]
    out: List[Tuple[Optional[str], Any]] = []
    for text, where in plan:
        out.append((text, table.slice(where[0], where[1]) if isinstance(where, tuple) else table.filter(where)))
    return out


def _dates(np: Any, pa: Any, table: Any) -> List[Tuple[Optional[str], Any]]:
    """`_by_date`'s plan: (date text, rows) per date, rows as (start, count) or a mask (arrow)."""
    import datetime

    time_col = _chunk(table.column("time"))
    us = values_view(np, time_col, np.int64)  # (timestamps in microseconds: int64 values)
    epoch = datetime.date(1970, 1, 1)
    if not time_col.null_count and len(us):  # one date (most tables): from the extremes, no copy
        first = int(us.min()) // DAY_US
        if int(us.max()) // DAY_US == first:
            return [((epoch + datetime.timedelta(days=first)).isoformat(), (0, len(us)))]
    if time_col.null_count:
        us = np.where(bool_values(np, time_col.is_valid()), us, np.iinfo(np.int64).max)
    day = np.where(us == np.iinfo(np.int64).max, np.iinfo(np.int64).max, us // DAY_US)
    lo, hi = (int(day.min()), int(day.max())) if len(day) else (0, 1)
    days = np.unique(day) if lo != hi else [lo]  # (one date: without a sort)
    # Rows in date order (as `_sorted` leaves them: by time, nulls last): each date a slice.
    rising = len(days) > 1 and bool((day[1:] >= day[:-1]).all())
    bounds = np.searchsorted(day, days) if rising else None
    out: List[Tuple[Optional[str], Any]] = []
    for k, d in enumerate(days):
        text = None if d == np.iinfo(np.int64).max else (epoch + datetime.timedelta(days=int(d))).isoformat()
        if len(days) == 1:
            out.append((text, (0, len(day))))
        elif bounds is not None:
            end = int(bounds[k + 1]) if k + 1 < len(days) else len(day)
            out.append((text, (int(bounds[k]), end - int(bounds[k]))))
        else:
            out.append((text, to_arrow(np, pa, day == d)))
    return out


def _encodings(pa: Any, schema: Any) -> Tuple[Dict[str, str], List[str]]:
    """The Parquet encodings of a table's columns (docs/dataset.md, "Storage"): integers and
    timestamps DELTA_BINARY_PACKED (time, offsets and counters step by small amounts), floats
    BYTE_STREAM_SPLIT (their bytes compress apart), strings and bools a dictionary; the columns
    with a dictionary listed."""
    encodings: Dict[str, str] = {}
    dictionary: List[str] = []
    for f in schema:
        t = f.type
        if pa.types.is_integer(t) or pa.types.is_timestamp(t):
            encodings[f.name] = "DELTA_BINARY_PACKED"
        elif pa.types.is_floating(t):
            encodings[f.name] = "BYTE_STREAM_SPLIT"
        elif f.name == "log":  # one value per part: a dictionary of it (CONSTANT), else PLAIN
            encodings[f.name] = "PLAIN"
        else:
            dictionary.append(f.name)
    return encodings, dictionary


def _write_atomic(pa: Any, path: str, table: Any) -> None:
    pq = importlib.import_module("pyarrow.parquet")
    directory, base = os.path.split(path)
    os.makedirs(directory, exist_ok=True)
    tmp = os.path.join(directory, f".{base}.tmp-{os.getpid()}")
    try:
        parquet_part.write_table(
            pq, pa, tmp, table, _options(pa, table.schema), COMPRESSION, ROW_GROUP_ROWS, _TEMPLATES
        )
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def _options(pa: Any, schema: Any) -> Dict[str, Any]:
    """pyarrow's writer options of a part with `schema` (`_encodings`; statistics on)."""
    encodings, dictionary = _encodings(pa, schema)
    return {"use_dictionary": dictionary, "column_encoding": encodings or None, "write_statistics": True}


# The columns a part's writer may take as one value in every row: `log` (parquet_part.PartFile).
CONSTANT = ("log",)
# Each table schema's Parquet template (parquet_part): the footer's schema and every column's
# all-null chunk, made once per schema (a few hundred tables in the spec at most).
_TEMPLATES: Dict[Any, Any] = {}


def remove_parts(out_dir: str, log: str, keep: Iterable[str] = ()) -> int:
    """Delete every `part-<log>-*` file of the dataset (tables and partitions) but those in `keep`
    (paths relative to out_dir); the number removed. A re-run then replaces, never duplicates."""
    keep_set = {os.path.normpath(k) for k in keep}
    prefix = f"part-{log}-"
    removed = 0
    if not os.path.isdir(out_dir):
        return 0
    for root, dirs, files in os.walk(out_dir):
        dirs[:] = [d for d in dirs if not d.startswith(".") and d != FILES_TABLE]
        for f in files:
            if f.startswith(prefix):
                rel = os.path.normpath(os.path.relpath(os.path.join(root, f), out_dir))
                if rel not in keep_set:
                    os.unlink(os.path.join(root, f))
                    removed += 1
    return removed


# --------------------------------------------------------------------------------------- _files
def files_schema() -> Any:
    pa = _need("pyarrow")
    ts = pa.timestamp("us", tz="UTC")
    return pa.schema(
        [
            ("log", pa.string()),
            ("path", pa.string()),
            ("bytes", pa.int64()),
            ("packets", pa.int64()),
            ("skipped_bytes", pa.int64()),
            ("bad_checksums", pa.int64()),
            ("first_t_ns", pa.int64()),
            ("last_t_ns", pa.int64()),
            ("first_time", ts),
            ("last_time", ts),
            ("model", pa.string()),
            ("serial", pa.string()),
            ("firmware", pa.string()),
            ("status", pa.string()),
            ("error", pa.string()),
        ]
    )


def files_row(
    log: str, path: str, size: int, identity: Identity, results: Sequence[SplitResult], error: Optional[str] = None
) -> Dict[str, Any]:
    """The `_files` row of a log from its split results (or an `error` when it could not be read):
    status `unreadable` (error), `truncated` (ends inside a packet), `corrupt` (bad checksums or
    skipped bytes), else `ok`."""
    packets = sum(r.packets for r in results)
    skipped = sum(r.skipped_bytes for r in results)
    bad = sum(r.bad_checksums for r in results)
    firsts = [r.first_t_ns for r in results if r.first_t_ns is not None]
    lasts = [r.last_t_ns for r in results if r.last_t_ns is not None]
    if error is not None:
        status = "unreadable"
    elif any(r.truncated for r in results):
        status = "truncated"
    elif skipped or bad:
        status = "corrupt"
    else:
        status = "ok"
    first = min(firsts) if firsts else None
    last = max(lasts) if lasts else None
    return {
        "log": log,
        "path": path,
        "bytes": size,
        "packets": packets,
        "skipped_bytes": skipped,
        "bad_checksums": bad,
        "first_t_ns": first,
        "last_t_ns": last,
        "first_time": None if first is None else first // 1000,
        "last_time": None if last is None else last // 1000,
        "model": identity.model,
        "serial": identity.serial,
        "firmware": identity.firmware,
        "status": status,
        "error": error,
    }


def write_files_row(out_dir: str, row: Dict[str, Any]) -> str:
    """Write `_files/part-<log>.parquet` (replacing the log's previous row); its relative path."""
    pa = _need("pyarrow")
    schema = files_schema()
    arrays = [_cell(pa, row[f.name], f.type) for f in schema]
    table = pa.Table.from_arrays(arrays, schema=schema)
    table = table.replace_schema_metadata(
        {META + b"spec_version": _spec_version().encode(), META + b"spec_hash": _spec_hash().encode()}
    )
    rel = os.path.join(FILES_TABLE, f"part-{row['log']}.parquet")
    _write_atomic(pa, os.path.join(out_dir, rel), table)
    return rel


def _cell(pa: Any, value: Any, t: Any) -> Any:
    """A one-value arrow array of type `t` (a string, an int, a timestamp in microseconds, or
    None), built without pa.array (which would import pandas)."""
    np = _need("numpy")
    if value is None:
        return pa.nulls(1, type=t)
    if pa.types.is_string(t):
        return text_array(np, pa, [str(value)])
    return to_arrow(np, pa, np.array([value], dtype=np.int64)).cast(t)


def unreadable_id(path: str) -> str:
    """The `_files` id of a log that cannot be read: 16 hex digits of the SHA-256 of its path."""
    return hashlib.sha256(("unreadable:" + path).encode("utf-8", "surrogateescape")).hexdigest()[:16]


# ------------------------------------------------------------------------- the local driver
@dataclass
class Summary:
    """What `export_dataset` did: the `_files` rows and the part files written."""

    logs: List[Dict[str, Any]] = field(default_factory=list)
    parts: List[str] = field(default_factory=list)
    rows: Dict[str, int] = field(default_factory=dict)


def export_log(
    path: str,
    out_dir: str,
    split_bytes: int = SPLIT_BYTES,
    model: Optional[str] = None,
    serial: Optional[str] = None,
    bar: Any = None,
) -> Tuple[Dict[str, Any], List[str], Dict[str, int]]:
    """Export one log (every split in turn, then its `_files` row; the log's stale parts
    removed): (its `_files` row, the parts written, rows per table). A log that cannot be read
    is a `_files` row with status `unreadable` and its error; a failed write raises OSError.
    `bar` (a tqdm bar in bytes, or None) moves by each split's bytes once it is written."""
    fallback = Identity(partition_value(model) if model else UNKNOWN, partition_value(serial) if serial else UNKNOWN)
    try:
        read_at, size = file_reader(path)
        log = log_id(path)
        identity = log_identity(read_at, size, model, serial)
    except ReadError as e:
        row = files_row(unreadable_id(path), path, 0, fallback, [], error=str(e))
        write_files_row(out_dir, row)
        return row, [], {}
    results: List[SplitResult] = []
    parts: List[str] = []
    rows: Dict[str, int] = {}
    try:
        grid = [(start, end, windows(start, end)) for start, end in splits(size, split_bytes)]
        held_times: List[Any] = []
        clock = range_clocks(read_at, size, [w for _s, _e, ws in grid for w in ws], held_times)
        k = 0
        for start, _end, ws in grid:
            n = len(ws)
            got, split_rows = export_split(
                out_dir, read_at, size, identity, log, start, ws, clock[k : k + n], results, held_times, k, bar
            )
            k += n
            parts += got
            for name, count in split_rows.items():
                rows[name] = rows.get(name, 0) + count
    except ReadError as e:  # read before (the parts written stay: a re-run replaces them)
        row = files_row(log, path, size, identity, results, error=str(e))
        write_files_row(out_dir, row)
        return row, parts, rows
    remove_parts(out_dir, log, keep=parts)
    row = files_row(log, path, size, identity, results)
    write_files_row(out_dir, row)
    return row, parts, rows


def export_split(
    out_dir: str,
    read_at: ReadAt,
    size: int,
    identity: Identity,
    log: str,
    start: int,
    ws: Sequence[Tuple[int, int]],
    clocks: Sequence[Any],
    results: List[SplitResult],
    held_times: Optional[List[Any]] = None,
    first: int = 0,
    bar: Any = None,
) -> Tuple[List[str], Dict[str, int]]:
    """Decode and write the split starting at `start` one window at a time (`ws`: its `windows`,
    `clocks`: each window's clock from `range_clocks`): the same part files and rows as
    `decode_split` and `write_split` of the whole split, in the memory of one window. Returns
    (the parts written, rows per table); each window's result, without its tables, is appended
    to `results` as it is decoded (also those before a ReadError). `held_times` (`range_clocks`'
    held time facts, of the log's windows from number `first` on) are used and let go; `bar`
    moves by each window's bytes. On any error the split's unfinished parts are removed."""
    out = SplitWriter(out_dir, identity, log, start)
    held = _HeldSamples()
    rows: Dict[str, int] = {}
    try:
        for j, ((w_start, w_end), clock) in enumerate(zip(ws, clocks)):
            k = first + j
            data, base = read_split(read_at, size, w_start, w_end)
            arrays = held_times[k] if held_times is not None and k < len(held_times) else None
            r = decode_split(data, base, w_start, w_end, clock, identity, log, size, arrays)
            if arrays is not None:
                held_times[k] = None  # type: ignore[index]
            del data
            tables = held.take(r)
            out.add(tables)
            for name, t in tables.items():
                rows[name] = rows.get(name, 0) + t.num_rows
            r.tables = {}
            results.append(r)
            if bar is not None:
                bar.update(w_end - w_start)
        tables = held.rest()
        out.add(tables)
        for name, t in tables.items():
            rows[name] = rows.get(name, 0) + t.num_rows
        return out.close(), rows
    except BaseException:
        out.abort()
        raise


class _HeldSamples:
    """The joined-sample rows of a split decoded in windows as the whole split gives them: each
    window's last `<set>.samples` row is held back, and merged with the next window's first row
    when that row continues its sample (`_join`'s rule: the last packet of the one and the first
    of the other have the same sample key), the first value of each column winning; the held
    rows go out when the split ends (`rest`)."""

    def __init__(self) -> None:
        self.pa = _need("pyarrow")
        self.held: Dict[str, Tuple[Any, Any]] = {}  # name -> (row, sample key of its last packet)

    def take(self, result: SplitResult) -> Dict[str, Any]:
        pa = self.pa
        out = dict(result.tables)
        for name, table in result.tables.items():
            if name not in result.sample_edges or table.num_rows == 0:
                continue
            first_key, last_key = result.sample_edges[name]
            prev, prev_key = self.held.pop(name, (None, None))
            if prev is not None and prev_key is not None and prev_key == first_key:
                prev = _coalesce(pa, prev, table.slice(0, 1))
                table = table.slice(1)
                if table.num_rows == 0:
                    self.held[name] = (prev, last_key)
                    del out[name]
                    continue
            front = table.slice(0, table.num_rows - 1)
            out[name] = front if prev is None else pa.concat_tables([prev, front])
            self.held[name] = (table.slice(table.num_rows - 1), last_key)
        return out

    def rest(self) -> Dict[str, Any]:
        out = {name: row for name, (row, _key) in self.held.items()}
        self.held = {}
        return out


def _coalesce(pa: Any, a: Any, b: Any) -> Any:
    """Row `a` with each null cell taken from row `b` (one row each): the first value wins."""
    pc = importlib.import_module("pyarrow.compute")
    cols = [pc.coalesce(a.column(j), b.column(j)) for j in range(a.num_columns)]
    return pa.Table.from_arrays(cols, schema=a.schema)


def windows(start: int, end: int, window: Optional[int] = None) -> List[Tuple[int, int]]:
    """The windows of split [start, end) the local driver decodes one at a time (WINDOW_BYTES)."""
    window = window or WINDOW_BYTES
    if end <= start:
        return [(start, end)]
    return [(w, min(w + window, end)) for w in range(start, end, window)]


def range_clocks(
    read_at: ReadAt, size: int, ranges: Sequence[Tuple[int, int]], held: Optional[List[Any]] = None
) -> List[Any]:
    """The clock of each of `ranges` (consecutive, covering the log; `clock_maps` for any grid:
    the time model does not depend on where the log is cut). `held` (a list) gets the time facts
    of the first ranges, up to HELD_TIME_BYTES of them, for `decode_split` (`time_arrays`): the
    driver then does not make them twice (not when the log's device changes them,
    `timebase.per_device_times`)."""
    from . import timebase

    anchors = []
    budget = HELD_TIME_BYTES if held is not None and not timebase.per_device_times() else 0
    for start, end in ranges:
        data, base = read_split(read_at, size, start, end)
        got: List[Any] = []
        anchors.append(timebase.split_anchors(data, base, start, end, got if budget > 0 else None))
        if got and held is not None:
            budget -= sum(a.nbytes for a in got[0].values())
            if budget >= 0:
                held.append(got[0])
        del data, got
    cmap = timebase.ClockMap.from_splits(anchors)
    return [cmap.split(k) for k in range(len(anchors))]


class SplitWriter:
    """The part files of one split written as its windows' tables come (`add`, in log order),
    each under a dot name renamed whole by `close` (`abort` removes them). Rows of a part are in
    the order `write_split` gives them (t_ns, then offset): each window's rows are sorted, and a
    part whose rows would go back in time from one window to the next is sorted again whole
    when the split ends (a log whose clock steps back; memory then that part's)."""

    def __init__(self, out_dir: str, identity: Identity, log: str, start: int) -> None:
        self.np, self.pa = _need("numpy"), _need("pyarrow")
        self.pq = importlib.import_module("pyarrow.parquet")
        self.out_dir, self.identity, self.log, self.start = out_dir, identity, log, start
        self.meta = file_metadata(identity, log, start)
        self.parts: Dict[Tuple[str, Optional[str]], _Part] = {}

    def add(self, tables: Dict[str, Any]) -> None:
        order: Dict[Any, Any] = {}
        dates: Dict[Any, Any] = {}
        for name in sorted(tables):
            table = tables[name]
            if table.num_rows == 0:
                continue
            key = _order_key(table)
            table = _sorted(self.np, self.pa, table, order)
            if key is not None and order.get(key) is not True:
                key = None  # (rows taken: new columns, found again)
            for date, rows in _by_date(self.np, self.pa, table, dates if key is not None else None):
                part = self.parts.get((name, date))
                if part is None:
                    part = self.parts[(name, date)] = self._open(name, date, table.schema)
                part.add(self.np, rows)
                if part.pending_bytes >= ROW_GROUP_BYTES:
                    part.flush()
        pending = sorted(self.parts.values(), key=lambda p: p.pending_bytes, reverse=True)
        total = sum(p.pending_bytes for p in pending)
        for part in pending:
            if total <= PENDING_BYTES:
                break
            total -= part.pending_bytes
            part.flush()

    def _open(self, name: str, date: Optional[str], schema: Any) -> _Part:
        rel = os.path.join(
            name,
            f"model={self.identity.model}",
            f"serial={self.identity.serial}",
            f"date={date or DEFAULT_PARTITION}",
            f"part-{self.log}-{split_name(self.start)}.parquet",
        )
        schema = schema.with_metadata({**(schema.metadata or {}), **self.meta})
        return _Part(self.pq, self.pa, rel, os.path.join(self.out_dir, rel), schema)

    def close(self) -> List[str]:
        """Finish every part (rows flushed, sorted again where needed, renamed whole): their
        relative paths, in table then date order as `write_split` lists them."""
        for part in self.parts.values():
            part.finish(self.np)
        keys = sorted(self.parts, key=lambda k: (k[0], k[1] is None, k[1] or ""))
        return [self.parts[k].rel for k in keys]

    def abort(self) -> None:
        for part in self.parts.values():
            part.discard()


class _Part:
    """One part file being written: its pending rows, its writer and whether its rows went back."""

    def __init__(self, pq: Any, pa: Any, rel: str, path: str, schema: Any) -> None:
        self.pq, self.pa, self.rel, self.path, self.schema = pq, pa, rel, path, schema
        directory, base = os.path.split(path)
        os.makedirs(directory, exist_ok=True)
        self.tmp = os.path.join(directory, f".{base}.tmp-{os.getpid()}")
        self.writer: Any = None
        self.pending: List[Any] = []
        self.pending_bytes = 0
        self.last: Optional[Tuple[Any, int]] = None  # (t_ns or None, offset) of the last row added
        self.unsorted = False

    def add(self, np: Any, rows: Any) -> None:
        rows = rows.replace_schema_metadata(self.schema.metadata)
        t = rows.column("t_ns")
        offs = rows.column("offset")
        first = (t[0].as_py(), offs[0].as_py())
        if self.last is not None and _row_key(first) < _row_key(self.last):
            self.unsorted = True
        self.last = (t[-1].as_py(), offs[-1].as_py())
        self.pending.append(rows)
        self.pending_bytes += _held_bytes(rows)

    def flush(self) -> None:
        if not self.pending:
            return
        table = self.pa.concat_tables(self.pending)
        self.pending, self.pending_bytes = [], 0
        if self.writer is None:
            options = _options(self.pa, self.schema)
            self.writer = parquet_part.PartFile(
                self.pq, self.pa, self.tmp, self.schema, options, COMPRESSION, ROW_GROUP_ROWS, _TEMPLATES, CONSTANT
            )
        self.writer.write(table)

    def finish(self, np: Any) -> None:
        self.flush()
        if self.writer is not None:
            self.writer.close()
            self.writer = None
        if self.unsorted:  # a clock that stepped back: the whole part in order again
            table = self.pq.read_table(self.tmp, partitioning=None).replace_schema_metadata(self.schema.metadata)
            os.unlink(self.tmp)
            _write_atomic(self.pa, self.path, _sorted(np, self.pa, table))
            return
        os.replace(self.tmp, self.path)

    def discard(self) -> None:
        try:
            if self.writer is not None:
                self.writer.abort()
        except Exception:  # the write that failed already said why
            pass
        try:
            os.unlink(self.tmp)
        except OSError:
            pass


def _held_bytes(table: Any) -> int:
    """The memory a window's rows hold: the bytes of their columns with a value (an all-null
    column is a slice of one shared array, `_nulls`: counted, it would cut a `<set>.samples`
    part, mostly null columns, into row groups of a few thousand rows, each costing the
    writer per column)."""
    return sum(c.nbytes for c in table.columns if c.null_count < len(c))


def _row_key(key: Tuple[Any, int]) -> Tuple[bool, int, int]:
    """The sort key of a row's (t_ns, offset): known times first, by time, then by offset."""
    t, off = key
    return (t is None, t or 0, off)


def clock_maps(read_at: ReadAt, size: int, split_bytes: int = SPLIT_BYTES) -> List[Any]:
    """Each split's clock (timebase's two phases: the anchors of every split, `split_anchors`,
    then `ClockMap.from_splits` gives each split its starting state): `decode_split`'s `clock`."""
    from . import timebase

    anchors = []
    for start, end in splits(size, split_bytes):
        data, base = read_split(read_at, size, start, end)
        anchors.append(timebase.split_anchors(data, base, start, end))
    cmap = timebase.ClockMap.from_splits(anchors)
    return [cmap.split(k) for k in range(len(anchors))]


def export_dataset(
    paths: Sequence[str],
    out_dir: str,
    split_bytes: int = SPLIT_BYTES,
    model: Optional[str] = None,
    serial: Optional[str] = None,
    progress: bool = False,
) -> Summary:
    """Export logs into the dataset at `out_dir` (created): each log's parts and `_files` row.
    A log that cannot be read or decoded is recorded in `_files`; a failed write raises OSError.
    `progress`: a bar of the bytes of log done on stderr when it is a terminal (tqdm, of the
    `[export]` extra; none without it)."""
    os.makedirs(out_dir, exist_ok=True)
    summary = Summary()
    bar = _bar(paths) if progress else None
    try:
        for path in paths:
            row, parts, rows = export_log(path, out_dir, split_bytes, model, serial, bar)
            summary.logs.append(row)
            summary.parts += parts
            for name, n in rows.items():
                summary.rows[name] = summary.rows.get(name, 0) + n
    finally:
        if bar is not None:
            bar.close()
    return summary


def _bar(paths: Sequence[str]) -> Any:
    """A progress bar of the logs' bytes on stderr when it is a terminal, else None."""
    if not sys.stderr.isatty():
        return None
    total = 0
    for path in paths:
        try:
            total += os.path.getsize(path)
        except OSError:
            pass  # an unreadable log is a `_files` row; the bar counts what can be read
    return progress_bar(total) if total else None


def _need(module: str) -> Any:

    return need(module)


__all__ = [
    "SPLIT_BYTES",
    "LOOKBACK",
    "Identity",
    "ReadError",
    "SplitResult",
    "Summary",
    "log_id",
    "splits",
    "split_name",
    "file_reader",
    "read_split",
    "log_identity",
    "partition_value",
    "UNKNOWN",
    "decode_split",
    "clock_maps",
    "whole_clock",
    "write_split",
    "remove_parts",
    "files_row",
    "write_files_row",
    "export_log",
    "export_dataset",
    "table_schema",
    "samples_schema",
    "table_names",
    "column_name",
]
