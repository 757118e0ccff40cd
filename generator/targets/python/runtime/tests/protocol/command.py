"""Command set 0x01 of the test protocol."""

from __future__ import annotations

import dataclasses as _dc

from . import codec as _c
from . import types as _t


@_dc.dataclass
class Ping(_c.Field):
    """Ping (set 0x01, descriptor 0x01, command): no parameters."""

    SET = 0x01
    DESCRIPTOR = 0x01
    NAME = "ping"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_dc.dataclass
class SetMode(_c.Field):
    """Set mode (set 0x01, descriptor 0x02, command)."""

    mode: _t.Mode = _t.Mode.OFF

    SET = 0x01
    DESCRIPTOR = 0x02
    NAME = "set_mode"
    ROLE = "command"
    _ATTRS = ("mode",)
    _OPS = (_c.Run(_c.P("mode", _c.enum(_t.Mode, "u8"))),)


FIELDS: tuple = (Ping, SetMode)
