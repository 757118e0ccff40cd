"""The c target: back end (names and type mapping) in backend.py; see docs/design.md."""

from .backend import OUTPUT_DIRS, api_names, public_name, render

__all__ = ["OUTPUT_DIRS", "api_names", "public_name", "render"]
