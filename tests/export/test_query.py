"""`python -m mipcodec query DATASET "SQL"` (runtime query.py, docs/queries.md): every table of a
dataset (the layout of issue 41: TABLE/model=/serial=/date=/part-*.parquet, _files/part-*.parquet)
is a DuckDB view named after its directory; partition columns are text, `date` a DATE and NULL for
Hive's default partition; output as a plain table, CSV or JSON lines; one-line errors, exit 2.

The dataset here is written by hand with pyarrow (the values are chosen, so the answers are
known); the queries on a real exported fleet are in tests/docs/test_queries_page.py."""

from __future__ import annotations

import csv
import io
import json
import sys
from pathlib import Path

import pytest

from tests.helpers.generated import python_package

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")
pytest.importorskip("duckdb")
pkg = python_package("mipcodec")

import mipcodec.cli  # noqa: E402
import mipcodec.logs.query as query  # noqa: E402


def _part(root: Path, table: str, parts: str, name: str, columns: dict) -> None:
    d = root / table / parts if parts else root / table
    d.mkdir(parents=True, exist_ok=True)
    pq.write_table(pa.table(columns), d / name)


@pytest.fixture
def dataset(tmp_path: Path) -> Path:
    root = tmp_path / "ds"
    acc = "sensor.scaled_accel"
    _part(root, acc, "model=cv7_ins/serial=6284.170401/date=2026-03-14", "part-aa-000000000000.parquet",
          {"t_ns": [1, 2], "scaled_accel_x": [0.5, -2.0]})  # fmt: skip
    _part(root, acc, "model=cv7_ins/serial=6284.170401/date=2026-03-15", "part-aa-000000000000.parquet",
          {"t_ns": [3], "scaled_accel_x": [1.5]})  # fmt: skip
    _part(root, acc, "model=gx5_45/serial=6232-10100/date=__HIVE_DEFAULT_PARTITION__", "part-bb-000000000000.parquet",
          {"t_ns": pa.array([None], pa.int64()), "scaled_accel_x": [3.0]})  # fmt: skip
    _part(root, "_files", "", "part-aa.parquet", {"log": ["aa"], "status": ["ok"], "bytes": [100]})
    _part(root, "_files", "", "part-bb.parquet", {"log": ["bb"], "status": ["truncated"], "bytes": [50]})
    # a writer's temporary (a dot file) is not part of the table
    (root / acc / "model=cv7_ins" / ".part-cc.parquet.tmp-1").write_bytes(b"partial")
    return root


def _query(capsys, *args: str) -> tuple:
    status = mipcodec.cli.main(["query", *args])
    out = capsys.readouterr()
    return status, out.out, out.err


def test_views_partitions_and_default_partition(dataset: Path, capsys) -> None:
    status, out, err = _query(
        capsys,
        str(dataset),
        'SELECT model, serial, date, count(*) AS n, max(scaled_accel_x) AS top FROM "sensor.scaled_accel" '
        "GROUP BY ALL ORDER BY model, date NULLS LAST",
        "--format",
        "csv",
    )
    assert status == 0, err
    rows = list(csv.reader(io.StringIO(out)))
    assert rows == [
        ["model", "serial", "date", "n", "top"],
        ["cv7_ins", "6284.170401", "2026-03-14", "2", "0.5"],  # the serial stays text (not 6284.170401 as a number)
        ["cv7_ins", "6284.170401", "2026-03-15", "1", "1.5"],
        ["gx5_45", "6232-10100", "", "1", "3.0"],  # the default partition: NULL (empty in CSV)
    ]
    status, out, err = _query(
        capsys,
        str(dataset),
        'SELECT typeof(date) AS t, typeof(serial) AS s FROM "sensor.scaled_accel" LIMIT 1',
        "--format",
        "json",
    )
    assert json.loads(out) == {"t": "DATE", "s": "VARCHAR"}


def test_files_table_and_formats(dataset: Path, capsys) -> None:
    sql = "SELECT status, sum(bytes) AS bytes FROM _files GROUP BY status ORDER BY status"
    status, out, _ = _query(capsys, str(dataset), sql)
    assert status == 0
    assert out.splitlines() == [
        "status     bytes",
        "---------  -----",
        "ok           100",
        "truncated     50",
        "(2 rows)",
    ]
    status, out, _ = _query(capsys, str(dataset), sql, "--format", "json")
    assert [json.loads(x) for x in out.splitlines()] == [
        {"status": "ok", "bytes": 100},
        {"status": "truncated", "bytes": 50},
    ]


@pytest.mark.parametrize(
    "where, sql, message",
    [
        ("missing", "SELECT 1", "no such dataset directory"),
        ("empty", "SELECT 1", "no tables"),
        ("ds", "SELEC 1", "Parser Error"),
        ("ds", 'SELECT * FROM "no.such_table"', "no.such_table"),
    ],
)
def test_one_line_errors(dataset: Path, capsys, where: str, sql: str, message: str) -> None:
    (dataset.parent / "empty").mkdir()
    status, out, err = _query(capsys, str(dataset.parent / where), sql)
    assert status == 2 and out == ""
    assert err.startswith("mipcodec query: ") and message in err, err
    assert err.count("\n") == 1 and "Traceback" not in err


def test_missing_duckdb_names_the_extra(dataset: Path, capsys, monkeypatch) -> None:
    monkeypatch.setitem(sys.modules, "duckdb", None)  # import duckdb: ImportError
    status, out, err = _query(capsys, str(dataset), "SELECT 1")
    assert status == 2
    assert err == "mipcodec query: duckdb is not installed: pip install 'mipcodec[query]' (or pip install duckdb)\n"


def test_connect_gives_the_views_to_a_program(dataset: Path) -> None:
    con = query.connect(str(dataset))
    assert con.execute('SELECT count(*) FROM "sensor.scaled_accel"').fetchone() == (4,)
    names = {r[0] for r in con.execute("SELECT table_name FROM information_schema.tables").fetchall()}
    assert names == {"sensor.scaled_accel", "_files"}
