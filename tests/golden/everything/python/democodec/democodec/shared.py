"""Shared data (descriptor set 0xFF, data, shared data descriptors)."""

from __future__ import annotations

import dataclasses as _dc

from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class Timestamp(_c.Field):
    """Timestamp (set 0xFF, descriptor 0xD3, data).

    Sources: demo.txt line 61. Field data: 8 bytes.
    """

    nanoseconds: int = 0

    SET = 0xFF
    DESCRIPTOR = 0xD3
    NAME = "timestamp"
    ROLE = "data"
    _ATTRS = ("nanoseconds",)
    _OPS = (_c.Run(_c.P("nanoseconds", _c.U64)),)


FIELDS: tuple[type[_c.Field], ...] = (Timestamp,)
