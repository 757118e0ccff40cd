"""Receiver 2 (descriptor set 0x92, data)."""

from __future__ import annotations

import dataclasses as _dc

from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class LlhPosition(_c.Field):
    """LLH position (set 0x92, descriptor 0x03, data).

    Sources: demo.txt line 81. Field data: 18 bytes.
    """

    latitude: float = 0.0  # [deg]
    longitude: float = 0.0  # [deg]
    valid_flags: int = 0

    SET = 0x92
    DESCRIPTOR = 0x03
    NAME = "llh_position"
    ROLE = "data"
    _ATTRS = ("latitude", "longitude", "valid_flags")
    _OPS = (_c.Run(_c.P("latitude", _c.F64), _c.P("longitude", _c.F64), _c.P("valid_flags", _c.U16)),)


FIELDS: tuple[type[_c.Field], ...] = (LlhPosition,)
