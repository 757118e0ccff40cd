"""The python target: back end (names and type mapping) in backend.py, language facts as data in
facts.py, the hand-written runtime (plain files, unit-tested in place) in runtime/; see
docs/design.md."""

from .backend import OUTPUT_DIRS, api_names, public_name, render
from .facts import GETTING_STARTED
from .identifiers import names, reserved

TITLE = "Python"  # the language's name in the documentation
EXTENSION = "py"  # of its source files (the getting-started programs)

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
