"""Reserved fields: descriptors reserved in every set of a kind (e.g. ack/nack in command sets)."""

from __future__ import annotations

import dataclasses as _dc

from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class Ack(_c.Field):
    """Ack (descriptor 0x80 in every command set, ack).

    Sources: demo.txt line 2. Field data: 2 bytes.
    """

    echo: int = 0
    code: int = 0

    SET = None
    DESCRIPTOR = 0x80
    NAME = "ack"
    ROLE = "ack"
    APPLIES_TO = "command"
    _ATTRS = ("echo", "code")
    _OPS = (_c.Run(_c.P("echo", _c.U8), _c.P("code", _c.U8)),)


FIELDS: tuple[type[_c.Field], ...] = (Ack,)
