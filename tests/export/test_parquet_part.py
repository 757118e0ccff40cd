"""The dataset's part files (the package's logs/parquet_part.py, docs/dataset.md "Sizes"): the
all-null column chunks written by the package, the rest by pyarrow.

The expectation is pyarrow's own writer: the file written for a table must be, byte for byte, the
one `pq.write_table` writes for it with the same encodings and the all-null columns uncompressed
(one row group); with several row groups, whose null columns differ, the table read back equal by
pyarrow, Polars and DuckDB, each chunk compressed as the rule says. The Thrift decoder and encoder
give back pyarrow's footers byte for byte.
"""

from __future__ import annotations

import importlib
import struct

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest

from tests.export.test_export import pkg

ROWS = 5000


def part_module():
    pkg()
    return importlib.import_module("mipcodec.logs.parquet_part")


def thrift_module():
    pkg()
    return importlib.import_module("mipcodec.logs.thrift")


def dataset_module():
    pkg()
    return importlib.import_module("mipcodec.logs.dataset")


def table(rows: int = ROWS, valued=lambda name: not name.startswith("n"), seed: int = 1) -> pa.Table:
    """Columns of every type the dataset writes (docs/dataset.md "Columns"): the base columns
    (`offset` and `log` not nullable, as in the dataset), then values; the columns `valued` refuses all null."""
    rng = np.random.default_rng(seed)
    types = {
        "f32": pa.float32(),
        "f64": pa.float64(),
        "i64": pa.int64(),
        "i32": pa.int32(),
        "u8": pa.uint8(),
        "flag": pa.bool_(),
        "state": pa.string(),
        "json": pa.string(),
        "stamp": pa.timestamp("us", tz="UTC"),
    }
    cols = {
        "t_ns": pa.array(np.arange(rows, dtype=np.int64) * 1_000_000 + 1_700_000_000_000_000_000),
        "time": pa.array(np.arange(rows, dtype=np.int64) * 1000, pa.timestamp("us", tz="UTC")),
        "offset": pa.array(np.arange(rows, dtype=np.int64) * 40),
        "log": pa.array(["0123456789abcdef"] * rows),
    }
    for prefix in ("v", "n"):
        for name, t in types.items():
            col = f"{prefix}_{name}"
            if not valued(col):
                cols[col] = pa.nulls(rows, t)
            elif t == pa.string():
                cols[col] = pa.array([None if k % 7 == 0 else ("ahrs", "full_nav")[k % 2] for k in range(rows)], t)
            elif t == pa.bool_():
                cols[col] = pa.array([None if k % 5 == 0 else bool(k % 3) for k in range(rows)], t)
            elif pa.types.is_floating(t):
                cols[col] = pa.array(rng.normal(size=rows).astype(t.to_pandas_dtype()))
            else:
                cols[col] = pa.array(rng.integers(0, 100, size=rows), pa.int64()).cast(t)
    schema = pa.schema(
        [
            pa.field(
                n, c.type, nullable=n not in ("offset", "log"), metadata={"units": "m/s"} if n == "v_f32" else None
            )
            for n, c in cols.items()
        ],
        metadata={"mipcodec.log": "0123456789abcdef", "mipcodec.split": "000000000000"},
    )
    return pa.table(list(cols.values()), schema=schema)


def write_ours(path, t: pa.Table, row_group_rows: int = 1 << 20, templates=None, constant=()):
    d = dataset_module()
    templates = {} if templates is None else templates
    options = d._options(pa, t.schema)
    part_module().write_table(pq, pa, str(path), t, options, d.COMPRESSION, row_group_rows, templates, constant)


def write_pyarrows(path, t: pa.Table):
    """pyarrow's file: the dataset's options, no compression for the all-null columns."""
    d = dataset_module()
    compression = {f.name: "NONE" if c.null_count == len(c) else d.COMPRESSION for f, c in zip(t.schema, t.columns)}
    pq.write_table(t, str(path), row_group_size=1 << 20, compression=compression, **d._options(pa, t.schema))


def test_one_row_group_is_pyarrows_file_byte_for_byte(tmp_path):
    t = table()
    assert sum(c.null_count == len(c) for c in t.columns) == 9  # the n_ columns
    write_ours(tmp_path / "ours.parquet", t)
    write_pyarrows(tmp_path / "pyarrow.parquet", t)
    assert (tmp_path / "ours.parquet").read_bytes() == (tmp_path / "pyarrow.parquet").read_bytes()


@pytest.mark.parametrize("rows", [1, 2, 127, 128, 129, 70_000])
def test_row_counts_around_varint_and_bit_packing_edges(tmp_path, rows):
    # the definition levels' run header is a varint of rows << 1 (one byte up to 63 rows, two up to
    # 8191, three above); DELTA_BINARY_PACKED's empty header is the same at every count
    t = table(rows)
    write_ours(tmp_path / "ours.parquet", t)
    write_pyarrows(tmp_path / "pyarrow.parquet", t)
    assert (tmp_path / "ours.parquet").read_bytes() == (tmp_path / "pyarrow.parquet").read_bytes()


def test_no_null_column_and_every_column_null_but_offset(tmp_path):
    for t in (table(valued=lambda name: True), table(valued=lambda name: False)):
        write_ours(tmp_path / "ours.parquet", t)
        write_pyarrows(tmp_path / "pyarrow.parquet", t)
        assert (tmp_path / "ours.parquet").read_bytes() == (tmp_path / "pyarrow.parquet").read_bytes()


def test_row_groups_with_other_null_columns_read_back_in_every_reader(tmp_path):
    duckdb = pytest.importorskip("duckdb")
    polars = pytest.importorskip("polars")
    # rows 0-2999 without the v_ values, 3000-5999 with them: the row groups of 1000 rows differ
    head = table(3000, valued=lambda name: False)
    tail = table(3000, valued=lambda name: not name.startswith("n"), seed=2)
    tail = tail.set_column(2, "offset", pa.array(np.arange(3000, 6000, dtype=np.int64) * 40))
    t = pa.concat_tables([head, tail.cast(head.schema)])
    path = tmp_path / "part.parquet"
    write_ours(path, t, row_group_rows=1000)
    back = pq.read_table(path)
    assert back.equals(t)
    assert back.schema.equals(t.schema, check_metadata=True)
    assert [f.metadata for f in back.schema] == [f.metadata for f in t.schema]
    md = pq.read_metadata(path)
    assert md.num_row_groups == 6 and md.num_rows == 6000
    for g in range(md.num_row_groups):
        rg = md.row_group(g)
        for c in range(rg.num_columns):
            chunk = rg.column(c)
            column = t.column(c).slice(g * 1000, 1000)
            assert chunk.num_values == 1000
            assert chunk.statistics.null_count == column.null_count
            expected = "UNCOMPRESSED" if column.null_count == 1000 else "ZSTD"
            assert chunk.compression == expected, (g, chunk.path_in_schema)
    # the row groups' byte ranges tile the file after its magic, in column order
    pos = 4
    for g in range(md.num_row_groups):
        for c in range(md.num_columns):
            chunk = md.row_group(g).column(c)
            start = chunk.dictionary_page_offset if chunk.has_dictionary_page else chunk.data_page_offset
            assert start == pos
            pos += chunk.total_compressed_size
    assert pos == path.stat().st_size - 8 - struct.unpack("<I", path.read_bytes()[-8:-4])[0]
    # Polars and DuckDB: the same values, column by column
    pl = polars.read_parquet(str(path))
    assert pl.height == 6000
    assert pl["v_f64"].to_list() == t.column("v_f64").to_pylist()
    assert pl["n_state"].null_count() == 3000 + t.column("n_state").slice(3000).null_count
    con = duckdb.connect()
    got = con.execute(f"SELECT count(*), count(v_state), count(n_i64), sum(v_i64), max(time) FROM '{path}'").fetchone()
    assert got[0] == 6000
    assert got[1] == 6000 - t.column("v_state").null_count
    assert got[2] == 6000 - t.column("n_i64").null_count
    assert got[3] == pa.compute.sum(t.column("v_i64")).as_py()
    assert got[4] == t.column("time")[-1].as_py()


def test_footer_decodes_and_encodes_to_pyarrows_bytes(tmp_path):
    m = part_module()
    write_pyarrows(tmp_path / "a.parquet", table())
    pq.write_table(table(valued=lambda name: True), tmp_path / "b.parquet", row_group_size=700, compression="snappy")
    for name in ("a.parquet", "b.parquet"):
        data = (tmp_path / name).read_bytes()
        size = struct.unpack("<I", data[-8:-4])[0]
        assert thrift_module().encode(m.footer(data)) == data[-8 - size : -8]


def test_an_unexpected_template_leaves_the_file_to_pyarrow(tmp_path, monkeypatch):
    m = part_module()

    def refuse(data, meta):
        raise ValueError("unexpected page")

    monkeypatch.setattr(m._Template, "_shape", staticmethod(refuse))
    t = table()
    write_ours(tmp_path / "part.parquet", t)
    assert pq.read_table(tmp_path / "part.parquet").equals(t)
    # pyarrow wrote every column: the null ones compressed too
    md = pq.read_metadata(tmp_path / "part.parquet")
    assert {md.row_group(0).column(c).compression for c in range(md.num_columns)} == {"ZSTD"}


def test_empty_table_and_templates_made_once(tmp_path):
    t = table()
    templates: dict = {}
    write_ours(tmp_path / "a.parquet", t, templates=templates)
    write_ours(tmp_path / "b.parquet", t.slice(0, 10), templates=templates)
    write_ours(tmp_path / "c.parquet", t.slice(0, 0), templates=templates)
    assert len(templates) == 1
    assert pq.read_table(tmp_path / "b.parquet").equals(t.slice(0, 10))
    assert pq.read_table(tmp_path / "c.parquet").num_rows == 0
    assert pq.read_table(tmp_path / "c.parquet").schema.equals(t.schema, check_metadata=True)


def test_a_failed_write_leaves_no_footer_and_raises(tmp_path):
    m = part_module()
    d = dataset_module()
    t = table()
    path = tmp_path / "part.parquet"
    part = m.PartFile(pq, pa, str(path), t.schema, d._options(pa, t.schema), d.COMPRESSION, 1 << 20, {})
    part.write(t)
    bad = t.set_column(2, "offset", pa.array([None] * t.num_rows, pa.int64()))
    with pytest.raises(ValueError, match="offset"):
        part.write(bad)
    part.abort()
    with pytest.raises(pa.ArrowInvalid):
        pq.read_table(path)


def test_a_constant_text_column_goes_as_a_dictionary_of_its_value(tmp_path):
    t = table()
    write_ours(tmp_path / "part.parquet", t, row_group_rows=2000, constant=("log",))
    back = pq.read_table(tmp_path / "part.parquet")
    assert back.equals(t) and back.schema.field("log").type == pa.string()
    md = pq.read_metadata(tmp_path / "part.parquet")
    at = t.schema.get_field_index("log")
    for g in range(md.num_row_groups):
        chunk = md.row_group(g).column(at)
        assert chunk.has_dictionary_page and "RLE_DICTIONARY" in chunk.encodings
        assert chunk.statistics.min == chunk.statistics.max == "0123456789abcdef"
    # not one value (first and last rows differ): written as given, PLAIN
    logs = pa.array(["0123456789abcdef"] * (t.num_rows - 1) + ["fedcba9876543210"])
    other = t.set_column(at, t.schema.field("log"), logs)
    write_ours(tmp_path / "other.parquet", other, constant=("log",))
    assert pq.read_table(tmp_path / "other.parquet").equals(other)
    chunk = pq.read_metadata(tmp_path / "other.parquet").row_group(0).column(at)
    assert not chunk.has_dictionary_page
    # a column that can be null is never taken as constant
    write_ours(tmp_path / "state.parquet", t, constant=("v_json",))
    write_pyarrows(tmp_path / "pyarrow.parquet", t)
    assert (tmp_path / "state.parquet").read_bytes() == (tmp_path / "pyarrow.parquet").read_bytes()


def test_a_moved_chunk_is_the_chunk_encoded_with_new_offsets():
    # pyarrow's chunks move by re-encoding their page offsets only; a chunk with a file offset
    # (older writers) or a bloom filter is decoded and encoded whole: both give the same bytes
    m, t = part_module(), thrift_module()
    stats = {1: (t.BINARY, b"\xff" * 8), 3: (t.I64, 0), 7: (t.TRUE, True)}
    meta = {
        1: (t.I32, 5),
        2: (t.LIST, (t.I32, [3, 9])),
        3: (t.LIST, (t.BINARY, [b"x"])),
        4: (t.I32, 6),
        5: (t.I64, 1000),
        6: (t.I64, 8040),
        7: (t.I64, 300),
        9: (t.I64, 70),
        11: (t.I64, 50),
        12: (t.STRUCT, stats),
        13: (t.LIST, (t.STRUCT, [{1: (t.I32, 0), 2: (t.I32, 9), 3: (t.I32, 1)}])),
        16: (t.STRUCT, {3: (t.LIST, (t.I64, [0, 1000]))}),
    }
    for extra, offset in (({}, 0), ({14: (t.I64, 400)}, 0), ({}, 350)):
        chunk = {2: (t.I64, offset), 3: (t.STRUCT, {**meta, **extra})}
        data = t.encode(chunk)
        copied = m._Copied(t.Reader(data))
        assert (copied.before is None) == bool(extra or offset)
        moved = {9: (t.I64, 70 - 50 + 1_000_000), 11: (t.I64, 1_000_000)}
        if extra:
            moved[14] = (t.I64, 400 - 50 + 1_000_000)
        want = {2: (t.I64, offset - 50 + 1_000_000 if offset else 0), 3: (t.STRUCT, {**meta, **extra, **moved})}
        assert copied.at(1_000_000) == t.encode(want)
        assert copied.meta[7][1] == 300 and copied.start == 50


def test_a_schema_without_a_template_is_written_by_pyarrow(tmp_path):
    # a column that cannot be null and has no one-value form here (a list): no template, so
    # pyarrow writes the whole file, the same rows
    t = table(100)
    t = t.append_column(
        pa.field("items", pa.list_(pa.int32()), nullable=False), pa.array([[1, 2]] * 100, pa.list_(pa.int32()))
    )
    templates: dict = {}
    write_ours(tmp_path / "part.parquet", t, templates=templates)
    assert list(templates.values()) == [None]
    assert pq.read_table(tmp_path / "part.parquet").equals(t)
