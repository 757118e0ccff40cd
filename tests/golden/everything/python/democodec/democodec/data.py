"""Data (descriptor set 0x90, data)."""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class Sample(_c.Field):
    """Sample (set 0x90, descriptor 0x01, data).

    Sources: demo.txt line 51. Field data: 29 bytes.
    """

    quat: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 4)
    big: int = 0
    small: int = 0
    f: float = 0.0

    SET = 0x90
    DESCRIPTOR = 0x01
    NAME = "sample"
    ROLE = "data"
    _ATTRS = ("quat", "big", "small", "f")
    _OPS = (_c.Run(_c.P("quat", _c.F32, 4), _c.P("big", _c.U64), _c.P("small", _c.S8), _c.P("f", _c.F32)),)


FIELDS: tuple[type[_c.Field], ...] = (Sample,)
