"""Reserved fields: descriptors reserved in every set of a kind (e.g. ack/nack in command sets)."""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class Ack(_c.Field):
    """Ack (descriptor 0x80 in every command set, ack).

    First field of every reply: the echoed message code of the command and an error code (0 when the
    command was received without error).

    Sources: ms-cip-doc00419-revM.txt line 182; ms-cip-doc00419-revM.txt line 141. Field data: 2
    bytes.
    """

    command_code: int = 0  # Message code of the command being answered ("Message echo").
    error_code: _ty.Union[_t.ErrorCode, int] = _t.ErrorCode.OK  # 0 when the command was received without error.

    SET = None
    DESCRIPTOR = 0x80
    NAME = "ack"
    ROLE = "ack"
    APPLIES_TO = "command"
    _ATTRS = ("command_code", "error_code")
    _OPS = (_c.Run(_c.P("command_code", _c.U8), _c.P("error_code", _c.enum(_t.ErrorCode, "u8"))),)


FIELDS: tuple[type[_c.Field], ...] = (Ack,)
