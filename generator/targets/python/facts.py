"""Facts of the Python language and of the Python runtime that the back end maps names and types with.

Written out as data (not read from the running interpreter's `keyword` module or `dir(int)`), so that
the generated code does not depend on which Python runs the generator.
"""

from __future__ import annotations

from typing import NamedTuple

from generator.targets import GettingStarted

# Python's reserved words (keyword.kwlist, unchanged from 3.9 to 3.13): a parameter, member or
# module name that is one of them gets a "_" suffix.
KEYWORDS = frozenset(
    {
        "False",
        "None",
        "True",
        "and",
        "as",
        "assert",
        "async",
        "await",
        "break",
        "class",
        "continue",
        "def",
        "del",
        "elif",
        "else",
        "except",
        "finally",
        "for",
        "from",
        "global",
        "if",
        "import",
        "in",
        "is",
        "lambda",
        "nonlocal",
        "not",
        "or",
        "pass",
        "raise",
        "return",
        "try",
        "while",
        "with",
        "yield",
    }
)

# Names pycodestyle (ruff E741) rejects as ambiguous: they get a "_" suffix too.
AMBIGUOUS_NAMES = frozenset({"l", "O", "I"})

# The attributes of the builtin `int` (dir(int) of Python 3.11): a bitfield is an int subclass,
# so a member with one of these names would hide them.
INT_ATTRIBUTES = frozenset(
    {
        "__abs__",
        "__add__",
        "__and__",
        "__bool__",
        "__ceil__",
        "__class__",
        "__delattr__",
        "__dir__",
        "__divmod__",
        "__doc__",
        "__eq__",
        "__float__",
        "__floor__",
        "__floordiv__",
        "__format__",
        "__ge__",
        "__getattribute__",
        "__getnewargs__",
        "__getstate__",
        "__gt__",
        "__hash__",
        "__index__",
        "__init__",
        "__init_subclass__",
        "__int__",
        "__invert__",
        "__le__",
        "__lshift__",
        "__lt__",
        "__mod__",
        "__mul__",
        "__ne__",
        "__neg__",
        "__new__",
        "__or__",
        "__pos__",
        "__pow__",
        "__radd__",
        "__rand__",
        "__rdivmod__",
        "__reduce__",
        "__reduce_ex__",
        "__repr__",
        "__rfloordiv__",
        "__rlshift__",
        "__rmod__",
        "__rmul__",
        "__ror__",
        "__round__",
        "__rpow__",
        "__rrshift__",
        "__rshift__",
        "__rsub__",
        "__rtruediv__",
        "__rxor__",
        "__setattr__",
        "__sizeof__",
        "__str__",
        "__sub__",
        "__subclasshook__",
        "__truediv__",
        "__trunc__",
        "__xor__",
        "as_integer_ratio",
        "bit_count",
        "bit_length",
        "conjugate",
        "denominator",
        "from_bytes",
        "imag",
        "numerator",
        "real",
        "to_bytes",
    }
)

# Attributes of the runtime's base classes (runtime/codec.py): Layout (every struct and field) and
# Bitfield (an int subclass besides).
LAYOUT_ATTRIBUTES = frozenset({"decode", "encode", "to_json", "from_json"})
BITFIELD_ATTRIBUTES = frozenset({"replace", "members"})


class Primitive(NamedTuple):
    """How one wire primitive looks in Python."""

    scalar: str  # the runtime's codec.Scalar object that packs it (runtime/codec.py)
    struct: str  # its `struct` format character (without the byte order), as that Scalar uses
    annotation: str  # the Python type of a decoded value
    default: str  # source of the default value of a dataclass attribute


PRIMITIVES: dict[str, Primitive] = {
    "u8": Primitive("U8", "B", "int", "0"),
    "u16": Primitive("U16", "H", "int", "0"),
    "u32": Primitive("U32", "I", "int", "0"),
    "u64": Primitive("U64", "Q", "int", "0"),
    "s8": Primitive("S8", "b", "int", "0"),
    "s16": Primitive("S16", "h", "int", "0"),
    "s32": Primitive("S32", "i", "int", "0"),
    "s64": Primitive("S64", "q", "int", "0"),
    "float": Primitive("F32", "f", "float", "0.0"),
    "double": Primitive("F64", "d", "float", "0.0"),
    "bool": Primitive("BOOL", "B", "bool", "False"),
    "char": Primitive("CHAR", "c", "bytes", 'b"\\x00"'),
}

# The runtime's public names that a package's __init__ re-exports, by runtime module, in the order
# it imports them (templates/python/package/__init__.py.j2), sorted as the import sorter wants them.
EXPORTS = {
    "codec.canonical": ["NaN"],
    "codec.framing": [
        "ACCELERATED",
        "FramingError",
        "Nmea",
        "PacketBuilder",
        "Parser",
        "RawPacket",
        "Rtcm",
        "Skip",
        "build_packet",
        "checksum_bytes",
        "fletcher16",
        "iter_fields",
        "parse",
    ],
    "codec.layout": ["DecodeError", "EncodeError", "Field", "Layout", "Struct"],
    "codec.packets": [
        "Columns",
        "DecodedField",
        "Decoder",
        "Packet",
        "RawField",
        "Trailing",
        "decode_all",
        "decode_bytes",
        "decode_columns",
        "decode_field",
        "decode_packet",
        "decode_stream",
        "encode_line",
        "encode_lines",
    ],
    "codec.samples": ["Sample", "SampleGrouper", "SampleTracker", "sample_key"],
    "registry": ["DEVICES", "lookup"],
    "session": ["Device", "Result", "Session", "connect"],
}

# Modules of EXPORTS whose names the package's __init__ imports on first use (they import the
# command sets' modules): `import <package>` stays cheap for the decode tools.
LAZY_EXPORTS = ("session",)


# The getting-started page (generated/docs/getting-started/python.md).
GETTING_STARTED = GettingStarted(
    install="Install `generated/python/{pkg}/` (Python 3.9+, no dependencies, typed for mypy; its optional C "
    "accelerator is compiled when a C compiler is there), or build a wheel and an sdist once and install "
    "from them anywhere, offline too (`generated/python/{pkg}/README.md` has the details):",
    setup="pip install ./generated/python/{pkg}\n"
    "# or: python -m build --outdir dist generated/python/{pkg}\n"
    "#     pip install --no-index --find-links dist {pkg}\n"
    "python -m {pkg} decode capture.bin   # canonical JSON lines",
    setup_lang="sh",
    setup_outside="files capture.bin",  # capture.bin: the page's placeholder for a device log
    include_intro="and import it:",
    run_package_var="PY_PACKAGE",
    outside_run="python examples/configure_and_stream.py ADDRESS 5",
)


# ------------------------------------------------------------------------------ optional extras
class Library(NamedTuple):
    """An optional library of the packages: its distribution (what pip installs), the lower bound
    of its version (the version requirements.txt / requirements-spark.txt pin, which the tests
    run: tests/generator/test_extras.py checks they agree) and its import name."""

    distribution: str
    minimum: str
    module: str


LIBRARIES = {
    lib.module: lib
    for lib in (
        Library("numpy", "2.3.5", "numpy"),
        Library("pyarrow", "22.0.0", "pyarrow"),
        Library("tqdm", "4.67.1", "tqdm"),
        Library("matplotlib", "3.10.7", "matplotlib"),
        Library("pandas", "2.3.3", "pandas"),
        Library("duckdb", "1.4.4", "duckdb"),
        Library("pytz", "2026.6", "pytz"),
        Library("pyspark", "4.0.1", "pyspark"),
        Library("pyserial", "3.5", "serial"),
        Library("pyyaml", "6.0.3", "yaml"),
        Library("mcap", "1.6.0", "mcap"),
    )
}

# The extras of every Python package (pyproject.toml's optional-dependencies, and the runtime's
# `_extras.py`, which names the extra to install when a library is missing): extra -> (what it is
# for, the import names of its libraries). Each extra holds what its documented commands import;
# `all` (the union of every extra) is added by the back end. The first extra that lists a library
# is the one a missing-library error names unless the command names its own.
EXTRAS = {
    "serial": ("serial ports of the session layer (transport.SerialTransport; TCP needs nothing)", ("serial",)),
    "device": ("the device command line (`{package}-device`): YAML settings files, serial ports", ("yaml", "serial")),
    "export": (
        "`{package} export|info` (CSV, JSON lines, Parquet, --dataset; the progress bar) and Table.arrays",
        ("numpy", "pyarrow", "tqdm"),
    ),
    "plot": ("`{package} plot` (png, svg, html)", ("numpy", "matplotlib")),
    "pandas": ("Table.dataframe", ("numpy", "pandas")),
    "query": (
        '`{package} query DATASET "SQL"` with DuckDB (pytz: its timestamps with a time zone)',
        ("duckdb", "pytz"),
    ),
    "mcap": (
        "`{package} export --format mcap` and `{package}-device ADDRESS record FILE.mcap` (MCAP, ROS 2 messages)",
        ("mcap",),
    ),
    "spark": (
        "the Spark job (`python -m {package}.spark`; Java 17 or 21): pyspark, pandas (its mapInArrow needs it)"
        " and the libraries of the dataset functions it drives",
        ("pyspark", "pandas", "numpy", "pyarrow"),
    ),
}
