"""Located, readable errors for spec problems. Never a traceback for a bad spec."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass
class Location:
    file: str
    line: int  # 1-based
    column: int  # 1-based

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}"


class SpecError(Exception):
    """One problem in a spec file: where, what is wrong, what is expected."""

    def __init__(self, loc: Location | None, message: str, expected: str | None = None):
        self.loc = loc
        self.message = message
        self.expected = expected
        super().__init__(str(self))

    def __str__(self) -> str:
        where = f"{self.loc}: " if self.loc else ""
        tail = f" (expected {self.expected})" if self.expected else ""
        return f"{where}error: {self.message}{tail}"


class SpecErrors(Exception):
    """Several problems found in one pass, reported together."""

    def __init__(self, errors: list[SpecError]):
        self.errors = errors
        super().__init__("\n".join(str(e) for e in errors))
