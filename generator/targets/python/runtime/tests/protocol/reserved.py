"""Reserved fields of the test protocol: ack/nack in every command set."""

from __future__ import annotations

import dataclasses as _dc

from . import codec as _c
from . import types as _t


@_dc.dataclass
class AckNack(_c.Field):
    """Ack/Nack (descriptor 0xF1 in every command set, ack)."""

    command_descriptor: int = 0
    ack_code: _t.AckCode = _t.AckCode.OK

    SET = None
    DESCRIPTOR = 0xF1
    NAME = "ack_nack"
    ROLE = "ack"
    APPLIES_TO = "command"
    _ATTRS = ("command_descriptor", "ack_code")
    _OPS = (_c.Run(_c.P("command_descriptor", _c.U8), _c.P("ack_code", _c.enum(_t.AckCode, "u8"))),)


FIELDS: tuple = (AckNack,)
