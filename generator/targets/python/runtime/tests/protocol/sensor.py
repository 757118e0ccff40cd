"""Data set 0x80 of the test protocol: a layout of each kind the runtime reads."""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import codec as _c
from . import types as _t


@_dc.dataclass
class Reading(_c.Field):
    """Reading (set 0x80, descriptor 0x01, data): fixed-size scalars."""

    count: int = 0
    offset: int = 0
    valid: bool = False

    SET = 0x80
    DESCRIPTOR = 0x01
    NAME = "reading"
    ROLE = "data"
    _ATTRS = ("count", "offset", "valid")
    _OPS = (_c.Run(_c.P("count", _c.U16), _c.P("offset", _c.S8), _c.P("valid", _c.BOOL)),)


@_c.slotted  # as generated fields are (Reading keeps a __dict__: both ways tested)
@_dc.dataclass
class Vector(_c.Field):
    """Vector (set 0x80, descriptor 0x02, data): float arrays and wide integers."""

    xyz: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    time: float = 0.0
    ticks: int = 0
    delta: int = 0

    SET = 0x80
    DESCRIPTOR = 0x02
    NAME = "vector"
    ROLE = "data"
    _ATTRS = ("xyz", "time", "ticks", "delta")
    _OPS = (_c.Run(_c.P("xyz", _c.F32, 3), _c.P("time", _c.F64), _c.P("ticks", _c.U64), _c.P("delta", _c.S32)),)


@_c.slotted  # as generated fields are (Reading keeps a __dict__: both ways tested)
@_dc.dataclass
class State(_c.Field):
    """State (set 0x80, descriptor 0x03, data): enum, bitfield, string and char."""

    mode: _t.Mode = _t.Mode.OFF
    status: _t.Status = _t.Status(0)
    name: bytes = b"\x00" * 4
    tag: bytes = b"\x00"

    SET = 0x80
    DESCRIPTOR = 0x03
    NAME = "state"
    ROLE = "data"
    _ATTRS = ("mode", "status", "name", "tag")
    _OPS = (
        _c.Run(
            _c.P("mode", _c.enum(_t.Mode, "u8")),
            _c.P("status", _c.flags(_t.Status)),
            _c.P("name", _c.string(4)),
            _c.P("tag", _c.CHAR),
        ),
    )


@_dc.dataclass
class Samples(_c.Field):
    """Samples (set 0x80, descriptor 0x04, data): a counted array and a signed enum (pure path)."""

    level: _t.Level = _t.Level.LOW
    n: int = 0
    values: _ty.List[int] = _dc.field(default_factory=list)

    SET = 0x80
    DESCRIPTOR = 0x04
    NAME = "samples"
    ROLE = "data"
    _ATTRS = ("level", "n", "values")
    _OPS = (
        _c.Run(_c.P("level", _c.enum(_t.Level, "s8")), _c.P("n", _c.U8)),
        _c.Counted("values", _c.U16, count="n", maximum=4),
    )


@_dc.dataclass
class Temperature_alpha(_c.Field):
    """Temperature (set 0x80, descriptor 0x05, data), device alpha."""

    celsius: int = 0

    SET = 0x80
    DESCRIPTOR = 0x05
    NAME = "temperature"
    ROLE = "data"
    DEVICE = "alpha"
    _ATTRS = ("celsius",)
    _OPS = (_c.Run(_c.P("celsius", _c.S16)),)


@_dc.dataclass
class Temperature_beta(_c.Field):
    """Temperature (set 0x80, descriptor 0x05, data), device beta."""

    celsius: float = 0.0

    SET = 0x80
    DESCRIPTOR = 0x05
    NAME = "temperature"
    ROLE = "data"
    DEVICE = "beta"
    _ATTRS = ("celsius",)
    _OPS = (_c.Run(_c.P("celsius", _c.F32)),)


@_dc.dataclass
class Odd(_c.Field):
    """Odd (set 0x80, descriptor 0x06, data): its length byte is one less than the rule's."""

    value: int = 0

    SET = 0x80
    DESCRIPTOR = 0x06
    NAME = "odd"
    ROLE = "data"
    _ATTRS = ("value",)
    _OPS = (_c.Run(_c.P("value", _c.U32)),)


FIELDS: tuple = (Reading, Vector, State, Samples, Temperature_alpha, Temperature_beta, Odd)
