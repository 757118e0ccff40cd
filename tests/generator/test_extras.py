"""The Python packages' extras (issue 50 item 5): each extra holds what its commands import, `all`
is every extra, the lower bounds are the versions the tests run, and a missing library is one line
naming the library and the extra that installs it.

The extras come from one table (generator/targets/python/facts.py EXTRAS), rendered into the
packages' pyproject.toml and into their `_extras.py` (the runtime's `need`). This reads the
generated pyproject.toml and the runtime's source (ast: every import of a library that is not in
the standard library, and every `need(...)` call), and blocks libraries through sys.modules to see
the error lines. No network, no virtualenv: installing each extra alone into a fresh virtualenv
and running its documentation's example is tests/consumer/test_extras_alone.py (`make test-extras`).
"""

from __future__ import annotations

import ast
import re
import subprocess
import sys
from pathlib import Path

import pytest
import tomllib

from generator.targets.python import facts
from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
RUNTIME = ROOT / "generator" / "targets" / "python" / "runtime"
PKG_DIR = ROOT / "generated" / "python" / "mipcodec"
PYPROJECT = PKG_DIR / "pyproject.toml"

# The command (documented with its extra) each runtime module with optional imports serves: the
# extras whose libraries the module may import. The log pipeline's modules are the `export` and
# `info` commands' (docs/log-to-csv.md, docs/dataset.md: `[export]`); `plot` (`[plot]`); `query`
# (`[query]`, docs/dataset.md "Queries"); the Spark job (`[spark]`); the device command line
# (`[device]`, docs/configure-a-device.md, docs/record.md); the session's serial transport
# (`[serial]`, README); Table.arrays (`[export]`) and Table.dataframe (`[pandas]`, the package README).
LOGS = ("export",)
COMMAND_EXTRAS = {
    "logs/commands.py": LOGS,
    "logs/export.py": LOGS,
    "logs/writers.py": LOGS,
    "logs/dataset.py": LOGS,
    "logs/arrow.py": LOGS,
    "logs/pipeline.py": LOGS,
    "logs/timebase.py": LOGS,
    "logs/plot.py": ("plot",),
    "logs/query.py": ("query",),
    "logs/mcap.py": ("mcap",),
    "device/record_mcap.py": ("mcap",),
    # the fleet's batch path and the world's batch functions it calls (fleet.py falls back without numpy)
    "protocols/mip/fleet_batch.py": ("export",),
    "sim/world.py": ("export",),
    "spark.py": ("spark",),
    "device/cli.py": ("device",),
    "device/settings.py": ("device",),
    "session/transport.py": ("serial",),
    "codec/packets.py": ("export", "pandas"),
}


def _extras() -> dict[str, list[str]]:
    return tomllib.loads(PYPROJECT.read_text())["project"]["optional-dependencies"]


def _names(requirements: list[str]) -> set[str]:
    return {re.split(r"[<>=!~ ;\[]", r, maxsplit=1)[0].lower() for r in requirements}


def _pins() -> dict[str, str]:
    pins = {}
    for name in ("requirements.txt", "requirements-spark.txt"):
        for line in (ROOT / name).read_text().splitlines():
            m = re.match(r"^([A-Za-z0-9_.-]+)==(\S+)", line)
            if m:
                pins[m.group(1).lower()] = m.group(2)
    return pins


def _imports(path: Path) -> dict[str, list[str | None]]:
    """The libraries a runtime module imports outside the standard library and the package:
    import name (top level) -> the extra named by each `need(NAME, EXTRA)` call (None: an import
    statement, `importlib.import_module` or a `need` without an extra)."""
    found: dict[str, list[str | None]] = {}
    for node in ast.walk(ast.parse(path.read_text())):
        names: list[tuple[str, str | None]] = []
        if isinstance(node, ast.Import):
            names = [(a.name, None) for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names = [(node.module, None)]
        elif isinstance(node, ast.Call) and node.args and isinstance(node.args[0], ast.Constant):
            func = node.func
            called = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
            if called in ("need", "import_module", "_need") and isinstance(node.args[0].value, str):
                extra = node.args[1] if len(node.args) > 1 else None
                names = [(node.args[0].value, extra.value if isinstance(extra, ast.Constant) else None)]
        for name, extra in names:
            top = name.split(".")[0]
            if top and top not in sys.stdlib_module_names and top != "__future__":
                found.setdefault(top, []).append(extra)
    return found


def test_each_extra_is_the_table_and_all_is_the_union() -> None:
    extras = _extras()
    assert set(extras) == set(facts.EXTRAS) | {"all"}
    for name, (_note, modules) in facts.EXTRAS.items():
        assert _names(extras[name]) == {facts.LIBRARIES[m].distribution for m in modules}, name
    union = set().union(*(set(v) for k, v in extras.items() if k != "all"))
    assert set(extras["all"]) == union and len(extras["all"]) == len(union)
    # the reported gaps: Spark's pandas, the query's pytz, and device/query/spark in `all`
    assert {"pandas", "pyspark", "pyarrow"} <= _names(extras["spark"])
    assert {"duckdb", "pytz"} <= _names(extras["query"])
    assert {"pyyaml", "pyserial", "duckdb", "pytz", "pyspark", "pandas", "matplotlib"} <= _names(extras["all"])


def test_lower_bounds_are_the_tested_versions() -> None:
    """Every requirement is `NAME>=V` with V the version requirements*.txt pins (what the tests run)."""
    pins = _pins()
    for name, requirements in _extras().items():
        for r in requirements:
            m = re.fullmatch(r"([a-z0-9_.-]+)>=([0-9][0-9A-Za-z.]*)", r)
            assert m, (name, r)
            assert pins.get(m.group(1)) == m.group(2), f"[{name}] {r}: requirements*.txt pins {pins.get(m.group(1))}"


def test_every_optional_import_is_in_its_commands_extra() -> None:
    """Each runtime module's libraries (import statements, import_module, need) are in the extras of
    the command it serves; a `need(NAME, EXTRA)` names an extra that installs NAME; a module with
    an optional import that no command claims fails here (place it in COMMAND_EXTRAS)."""
    seen = set()
    for path in sorted(RUNTIME.rglob("*.py")):
        rel = path.relative_to(RUNTIME).as_posix()
        if rel.split("/")[0] in ("tests", "package_tests"):
            continue
        libs = _imports(path)
        if not libs:
            continue
        assert rel in COMMAND_EXTRAS, f"{rel} imports {sorted(libs)}: which command's extra?"
        seen.add(rel)
        allowed = {m for e in COMMAND_EXTRAS[rel] for m in facts.EXTRAS[e][1]}
        for lib, named in libs.items():
            assert lib in facts.LIBRARIES, f"{rel}: {lib} is not an optional library of the extras"
            assert lib in allowed, f"{rel}: {lib} is not in {COMMAND_EXTRAS[rel]}"
            for extra in named:
                if extra is not None:
                    assert lib in facts.EXTRAS[extra][1], f"{rel}: need({lib!r}, {extra!r})"
    assert seen == set(COMMAND_EXTRAS)  # no stale entry


def test_docs_name_the_libraries_their_extra_installs() -> None:
    """`pip install '...mipcodec[EXTRA]'  # + lib, lib` lines of the docs: each library named is in EXTRA."""
    known = {lib.distribution for lib in facts.LIBRARIES.values()}
    extras = _extras()
    checked = 0
    for doc in sorted((ROOT / "docs").glob("*.md")):
        for line in doc.read_text().splitlines():
            m = re.search(r"pip install '\S*mipcodec\[(\w+)\]'\s+#(.*)", line)
            if not m or m.group(1) == "all":
                continue
            named = {w.lower() for w in re.findall(r"[A-Za-z]+", m.group(2))} & known
            assert named <= _names(extras[m.group(1)]), (doc.name, line)
            checked += len(named)
    assert checked >= 5


@pytest.fixture
def pkg():
    return python_package("mipcodec")


def _block(monkeypatch, top: str) -> None:
    """Make `import top` (and its submodules) fail as when the library is not installed."""
    for name in [n for n in sys.modules if n == top or n.startswith(top + ".")]:
        monkeypatch.setitem(sys.modules, name, None)
    monkeypatch.setitem(sys.modules, top, None)


def _line(lib: str, extra: str) -> str:
    return (
        f"{lib} is not installed: pip install 'mipcodec[{extra}]' (or pip install {facts.LIBRARIES[lib].distribution})"
    )


@pytest.mark.parametrize("extra", sorted(facts.EXTRAS))
def test_need_names_library_and_extra(pkg, monkeypatch, extra: str) -> None:
    from mipcodec import _extras
    from mipcodec.logs.writers import ToolError, need

    for lib in facts.EXTRAS[extra][1]:
        _block(monkeypatch, lib)
        with pytest.raises(ToolError) as e:
            need(f"{lib}.sub", extra)
        assert str(e.value) == _line(lib, extra) and e.value.__cause__ is None and e.value.__suppress_context__
        assert _extras.missing(lib) == _line(lib, _extras.EXTRA[lib])


def test_library_errors_of_the_runtime(pkg, monkeypatch, tmp_path) -> None:
    """The error lines of the places that import a library themselves, each blocked."""
    from mipcodec.codec.packets import Table
    from mipcodec.device import settings
    from mipcodec.session.transport import SerialTransport, TransportError

    _block(monkeypatch, "yaml")
    with pytest.raises(settings.FileError) as e:
        settings.load_text("a: 1\n", "s.yaml")
    assert e.value.lines == [f"s.yaml: reading settings files: {_line('yaml', 'device')}"]
    _block(monkeypatch, "serial")
    with pytest.raises(TransportError, match=re.escape(f"serial ports: {_line('serial', 'serial')}")):
        SerialTransport(str(tmp_path / "tty"))
    # Table.dataframe and Table.arrays ask for their libraries first (a Table comes from the C
    # accelerator, which the source tree here does not have built)
    _block(monkeypatch, "pandas")
    with pytest.raises(ImportError, match=re.escape(_line("pandas", "pandas"))):
        Table.dataframe(None)  # type: ignore[arg-type]
    _block(monkeypatch, "numpy")
    with pytest.raises(ImportError, match=re.escape(_line("numpy", "export"))):
        Table.arrays(None)  # type: ignore[arg-type]


def _run(tmp_path: Path, block: str, argv: list[str], module: str) -> subprocess.CompletedProcess:
    code = (
        f"import runpy, sys; sys.modules[{block!r}] = None; sys.argv = {argv!r}; "
        f"runpy.run_module({module!r}, run_name='__main__')"
    )
    env = {"PYTHONPATH": str(PKG_DIR), "PATH": "/usr/bin:/bin"}
    return subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120, cwd=tmp_path
    )


def test_query_without_pytz_names_it(tmp_path) -> None:
    """A query returning a timestamp with a time zone needs pytz (DuckDB imports it): the line names
    pytz and the `query` extra (DuckDB's own message stops before its cause)."""
    import duckdb

    (tmp_path / "ds" / "t").mkdir(parents=True)
    duckdb.connect().execute(f"COPY (SELECT 1 AS x) TO '{tmp_path / 'ds' / 't' / 'p.parquet'}' (FORMAT parquet)")
    sql = "SELECT TIMESTAMPTZ '2026-03-14 09:14:00+00' AS t FROM t"
    r = _run(tmp_path, "pytz", ["mipcodec", "query", "ds", sql], "mipcodec")
    assert (r.returncode, r.stdout) == (2, ""), r.stderr
    assert r.stderr == f"mipcodec query: {_line('pytz', 'query')}\n"


def test_spark_without_pandas_names_it(tmp_path) -> None:
    """The Spark job needs pandas (pyspark's mapInArrow imports it): one line before Spark starts."""
    r = _run(tmp_path, "pandas", ["spark", "x.bin", "--out", "d"], "mipcodec.spark")
    assert r.returncode == 2, r.stderr
    assert r.stderr.strip().splitlines() == [f"mipcodec.spark: {_line('pandas', 'spark')}"]
