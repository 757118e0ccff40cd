"""The cpp target: back end (names and type mapping) in backend.py; see docs/design.md."""

from .backend import OUTPUT_DIRS, api_names, public_name, render
from .facts import GETTING_STARTED
from .identifiers import names, reserved

TITLE = "C++"  # the language's name in the documentation
EXTENSION = "cpp"  # of its source files (the getting-started programs)

__all__ = [
    "EXTENSION",
    "GETTING_STARTED",
    "OUTPUT_DIRS",
    "TITLE",
    "api_names",
    "names",
    "public_name",
    "render",
    "reserved",
]
