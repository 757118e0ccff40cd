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


class BackendError(SpecError):
    """A spec that one back end cannot express (two spec names that become one identifier in its
    language, a framing it does not implement). It is a spec error (exit 1, one line): the
    pipeline locates it at the spec element it names, `where` being the names leading to it
    (("GPSMode",), ("GpsMode", "a"), ("commands", "ping")) in the protocol `protocol`."""

    def __init__(self, message: str, protocol: str | None = None, where: tuple[str, ...] = ()):
        self.protocol = protocol
        self.where = tuple(where)
        super().__init__(None, message)
