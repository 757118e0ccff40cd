"""SQL on a dataset with DuckDB (issue 41, docs/queries.md): `python -m mipcodec query DATASET "SQL"`.

    python -m mipcodec query DATASET "SQL" [--format table|csv|json]

DATASET is a directory `export --dataset` (or the Spark job) wrote: one subdirectory per table
(`sensor.scaled_accel`, `filter_data.samples`, `_files`, ...), each a Hive-partitioned Parquet
dataset (`model=`/`serial=`/`date=` directories). Every table is registered as a DuckDB view named
after its directory (quote the names: they have dots, `"sensor.scaled_accel"`); the partition
columns are text (`model`, `serial`: a serial such as `6284.170401` stays text) and `date` a DATE,
NULL for the `unknown` date (or `__HIVE_DEFAULT_PARTITION__`) of rows without a UTC time. The result prints as a plain
table (default), CSV with a header, or JSON lines (one object per row).

Needs duckdb (the package's `[query]` extra, with pytz for timestamps). Errors are one line on
stderr, exit status 2: a missing or empty dataset, SQL DuckDB refuses (its first line), duckdb not
installed (or pytz, for a timestamp with a time zone: the library and the extra).
`connect(DATASET)` gives the same views to a Python program.
"""

from __future__ import annotations

import argparse
import csv
import datetime
import decimal
import json
import math
import os
import re
import sys
from typing import Any, Dict, List, Sequence, Tuple

from .. import _extras
from .._protocol import PACKAGE as PROG

DEFAULT_PARTITION = "__HIVE_DEFAULT_PARTITION__"  # Hive/Spark's directory name for a null value
TYPED = {"date": "DATE"}  # partition columns that are not text
_MISSING = re.compile(r"Required module '([\w.]+)' failed to import")
UNKNOWN_DATE = "unknown"  # the dataset's `date` of rows without a UTC time (dataset.DEFAULT_PARTITION)


class QueryError(Exception):
    """A problem the user can fix: one line, exit status 2."""


def _duckdb() -> Any:
    return _extras.need("duckdb", "query", QueryError)  # (Any: mypy needs no duckdb stubs)


def tables(dataset: str) -> Dict[str, Tuple[str, List[str]]]:
    """The tables of a dataset: name -> (glob of its Parquet files, partition columns in order).
    A table is a subdirectory holding .parquet files (dot files, the writers' temporaries, are
    not); its partition columns are the `KEY=` directories above its first file."""
    if not os.path.isdir(dataset):
        raise QueryError(f"{dataset}: no such dataset directory")
    found: Dict[str, Tuple[str, List[str]]] = {}
    for name in sorted(os.listdir(dataset)):
        top = os.path.join(dataset, name)
        if name.startswith(".") or not os.path.isdir(top):
            continue
        keys = _first_part(top)
        if keys is not None:
            found[name] = (os.path.join(top, "**", "*.parquet"), keys)
    if not found:
        raise QueryError(f"{dataset}: no tables (no TABLE/**/*.parquet in it)")
    return found


def _first_part(top: str) -> Any:
    """The partition keys of the first Parquet file under `top` (None: no file)."""
    for root, dirs, files in os.walk(top):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        if any(f.endswith(".parquet") and not f.startswith(".") for f in files):
            rel = os.path.relpath(root, top)
            return [] if rel == "." else [p.split("=", 1)[0] for p in rel.split(os.sep) if "=" in p]
    return None


def _literal(text: str) -> str:
    return "'" + text.replace("'", "''") + "'"


def _ident(text: str) -> str:
    return '"' + text.replace('"', '""') + '"'


def connect(dataset: str) -> Any:
    """A DuckDB connection (in memory) with a view per table of the dataset."""
    duckdb = _duckdb()
    found = tables(dataset)
    con = duckdb.connect()
    con.execute("SET TimeZone = 'UTC'")  # timestamps print in UTC whatever the machine's zone
    for name, (pattern, keys) in found.items():
        source = f"read_parquet({_literal(pattern)}, union_by_name = true"
        if keys:
            types = ", ".join(f"{_literal(k)}: 'VARCHAR'" for k in keys)
            source += ", hive_partitioning = true, hive_types = {" + types + "}"
        else:
            source += ", hive_partitioning = false"
        source += ")"
        replace = [f"CAST({_null_value(k)} AS {TYPED.get(k, 'VARCHAR')}) AS {_ident(k)}" for k in keys]
        select = f"SELECT * REPLACE ({', '.join(replace)})" if replace else "SELECT *"
        con.execute(f"CREATE VIEW {_ident(name)} AS {select} FROM {source}")
    return con


def _null_value(key: str) -> str:
    """A partition column with its null spellings as NULL (a date: also `unknown`)."""
    expr = f"NULLIF({_ident(key)}, {_literal(DEFAULT_PARTITION)})"
    return f"NULLIF({expr}, {_literal(UNKNOWN_DATE)})" if key in TYPED else expr


def run(dataset: str, sql: str) -> Tuple[List[str], List[Tuple[Any, ...]]]:
    """The column names and rows of `sql` on the dataset."""
    duckdb = _duckdb()
    con = None
    try:
        con = connect(dataset)
        result = con.execute(sql)
        columns = [d[0] for d in result.description or []]
        rows = result.fetchall() if columns else []
    except duckdb.Error as e:
        raise QueryError(_error_line(e)) from None
    finally:
        if con is not None:
            con.close()
    return columns, rows


def _error_line(e: Exception) -> str:
    """DuckDB's error as one line: its first, or, when DuckDB could not import a library it needs
    for the result (pytz for a timestamp with a time zone, ...), the library and the extra."""
    text = str(e).strip()
    lib = _MISSING.search(text)
    if lib is not None:
        return _extras.missing(lib.group(1), "query")
    return text.splitlines()[0] if text else type(e).__name__


def _cell(v: Any) -> str:
    if v is None:
        return "NULL"
    if isinstance(v, float):
        return repr(v) if math.isfinite(v) else str(v)
    if isinstance(v, datetime.datetime):
        return v.isoformat(sep=" ")
    if isinstance(v, (bytes, bytearray)):
        return bytes(v).hex()
    return str(v)


def _json(v: Any) -> Any:
    if v is None or isinstance(v, (bool, int, str)):
        return v
    if isinstance(v, float):
        return v if math.isfinite(v) else str(v)
    if isinstance(v, decimal.Decimal):
        return float(v)
    if isinstance(v, (datetime.date, datetime.time, datetime.timedelta)):
        return v.isoformat() if not isinstance(v, datetime.timedelta) else v.total_seconds()
    if isinstance(v, (list, tuple)):
        return [_json(x) for x in v]
    if isinstance(v, dict):
        return {str(k): _json(x) for k, x in v.items()}
    return _cell(v)


def render(columns: List[str], rows: Sequence[Tuple[Any, ...]], fmt: str = "table") -> str:
    """The result as text: a plain table (numbers right-aligned), CSV or JSON lines."""
    if fmt == "csv":
        out = _Text()
        w = csv.writer(out, lineterminator="\n")
        w.writerow(columns)
        for row in rows:
            w.writerow(["" if v is None else _cell(v) for v in row])
        return "".join(out.parts)
    if fmt == "json":
        return "".join(json.dumps(dict(zip(columns, map(_json, row)))) + "\n" for row in rows)
    cells = [[_cell(v) for v in row] for row in rows]
    widths = [max([len(c)] + [len(r[i]) for r in cells]) for i, c in enumerate(columns)]
    numeric = [
        all(isinstance(row[i], (int, float, decimal.Decimal)) or row[i] is None for row in rows) and bool(rows)
        for i in range(len(columns))
    ]

    def line(values: List[str]) -> str:
        return "  ".join(v.rjust(w) if n else v.ljust(w) for v, w, n in zip(values, widths, numeric)).rstrip() + "\n"

    text = line(columns) + line(["-" * w for w in widths])
    text += "".join(line(r) for r in cells)
    return text + f"({len(rows)} row{'' if len(rows) == 1 else 's'})\n"


class _Text:
    def __init__(self) -> None:
        self.parts: List[str] = []

    def write(self, s: str) -> int:
        self.parts.append(s)
        return len(s)


def add_parser(sub: Any) -> None:
    """The `query` subcommand in the command table of logs/commands.py."""
    q = sub.add_parser(
        "query",
        help="run SQL on a dataset with DuckDB (needs duckdb)",
        description="Run SQL on a dataset (export --dataset): each table is a view named after its directory "
        '(quote it: "sensor.scaled_accel"), partition columns model, serial (text) and date (DATE).',
    )
    q.add_argument("dataset", metavar="DATASET", help="dataset directory")
    q.add_argument("sql", metavar="SQL", help="the query")
    q.add_argument("--format", choices=("table", "csv", "json"), default="table", help="output (default table)")
    q.set_defaults(run=_command)


def _command(args: argparse.Namespace) -> int:
    try:
        columns, rows = run(args.dataset, args.sql)
    except QueryError as e:
        print(f"{PROG} query: {e}", file=sys.stderr)
        return 2
    sys.stdout.write(render(columns, rows, args.format))
    return 0
