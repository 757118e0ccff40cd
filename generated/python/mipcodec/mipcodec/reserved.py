"""Reserved fields: descriptors reserved in every set of a kind (e.g. ack/nack in command sets)."""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class AckNack(_c.Field):
    """Ack/Nack (descriptor 0xF1 in every command set, ack).

    Reply to every command field: echoes the command descriptor and gives an ack code. Reserved in
    every command descriptor set.

    Sources: 3dm-gx5-45-dcp.txt line 315; 3dm-cv7-ins-docs.txt line 8862. Field data: 2 bytes.
    """

    command_descriptor: int = 0  # Descriptor of the command being answered.
    ack_code: _ty.Union[_t.AckCode, int] = _t.AckCode.OK  # 0 is an ACK; any other value is a NACK.

    SET = None
    DESCRIPTOR = 0xF1
    NAME = "ack_nack"
    ROLE = "ack"
    APPLIES_TO = "command"
    _ATTRS = ("command_descriptor", "ack_code")
    _OPS = (_c.Run(_c.P("command_descriptor", _c.U8), _c.P("ack_code", _c.enum(_t.AckCode, "u8"))),)


FIELDS: tuple[type[_c.Field], ...] = (AckNack,)
