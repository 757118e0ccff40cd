"""The optional libraries of mscipcodec and the extras that install them (generated from the
generator's table of extras, as pyproject.toml's optional-dependencies are): every optional import
of the runtime goes through `need`, so that a missing library is one line naming the library and
the extra to install, never a traceback.
"""

from __future__ import annotations

import importlib
from typing import Any, Callable, Dict, Optional, Tuple

from ._protocol import PACKAGE

# extra -> the libraries it installs (pyproject.toml's optional-dependencies)
REQUIRES: Dict[str, Tuple[str, ...]] = {
    "serial": ("pyserial>=3.5",),
    "device": (
        "pyyaml>=6.0.3",
        "pyserial>=3.5",
    ),
    "export": (
        "numpy>=2.3.5",
        "pyarrow>=22.0.0",
        "tqdm>=4.67.1",
    ),
    "plot": (
        "numpy>=2.3.5",
        "matplotlib>=3.10.7",
    ),
    "pandas": (
        "numpy>=2.3.5",
        "pandas>=2.3.3",
    ),
    "query": (
        "duckdb>=1.4.4",
        "pytz>=2026.6",
    ),
    "mcap": ("mcap>=1.6.0",),
    "spark": (
        "pyspark>=4.0.1",
        "pandas>=2.3.3",
        "numpy>=2.3.5",
        "pyarrow>=22.0.0",
    ),
    "all": (
        "pyserial>=3.5",
        "pyyaml>=6.0.3",
        "numpy>=2.3.5",
        "pyarrow>=22.0.0",
        "tqdm>=4.67.1",
        "matplotlib>=3.10.7",
        "pandas>=2.3.3",
        "duckdb>=1.4.4",
        "pytz>=2026.6",
        "mcap>=1.6.0",
        "pyspark>=4.0.1",
    ),
}
# import name -> the extra a missing-library error names when the command names none
EXTRA: Dict[str, str] = {
    "serial": "serial",
    "yaml": "device",
    "numpy": "export",
    "pyarrow": "export",
    "tqdm": "export",
    "matplotlib": "plot",
    "pandas": "pandas",
    "duckdb": "query",
    "pytz": "query",
    "mcap": "mcap",
    "pyspark": "spark",
}
# import name -> the distribution pip installs
DISTRIBUTION: Dict[str, str] = {
    "numpy": "numpy",
    "pyarrow": "pyarrow",
    "tqdm": "tqdm",
    "matplotlib": "matplotlib",
    "pandas": "pandas",
    "duckdb": "duckdb",
    "pytz": "pytz",
    "pyspark": "pyspark",
    "serial": "pyserial",
    "yaml": "pyyaml",
    "mcap": "mcap",
}


def missing(module: str, extra: Optional[str] = None) -> str:
    """The line for a missing optional library: `module` (an import name) is not installed, and the
    extra that installs it (`extra`: the command's own, else the library's)."""
    top = module.split(".")[0]
    extra = extra or EXTRA.get(top, "all")
    return f"{module} is not installed: pip install '{PACKAGE}[{extra}]' (or pip install {DISTRIBUTION.get(top, top)})"


def need(module: str, extra: Optional[str] = None, error: Callable[[str], Exception] = ImportError) -> Any:
    """Import an optional library (`pyarrow.parquet` too), or raise `error(missing(...))` without a
    chained traceback, naming the top-level library that is missing (one that fails on import for
    want of another library the extras know is reported as that other)."""
    try:
        return importlib.import_module(module)
    except ImportError as e:
        name = (getattr(e, "name", None) or module).split(".")[0]
        raise error(missing(name if name in DISTRIBUTION else module.split(".")[0], extra)) from None
