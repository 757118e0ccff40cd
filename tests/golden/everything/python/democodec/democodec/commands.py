"""Commands (descriptor set 0x01, command)."""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class Ping(_c.Field):
    """Ping (set 0x01, descriptor 0x01, command).

    Sources: demo.txt line 15. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x01
    NAME = "ping"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class Configure(_c.Field):
    """Configure (set 0x01, descriptor 0x02, command).

    Functions: write, read, save. Responses: 0x82 configuration. Sources: demo.txt line 20. Field
    data: 2..32 bytes.
    """

    function: _ty.Union[_t.Function, int] = _t.Function.WRITE  # Function (one of: write, read, save)
    instance: int = 0
    mode: _ty.Optional[_ty.Union[_t.Mode, int]] = None  # (sent for: write)
    params: _ty.Optional[_ty.Union[_t.GpioParams, _t.ThresholdParams]] = None  # (sent for: write)
    suppress_ack: _ty.Optional[bool] = None  # (sent for: write)

    SET = 0x01
    DESCRIPTOR = 0x02
    NAME = "configure"
    ROLE = "command"
    _ATTRS = ("function", "instance", "mode", "params", "suppress_ack")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.Function, "u8")), _c.P("instance", _c.U8)),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.Mode, "u8")))),
        _c.Opt(_c.Choice("params", _t.TriggerParams, selector="mode")),
        _c.Opt(_c.Run(_c.P("suppress_ack", _c.BOOL))),
    )


@_c.slotted
@_dc.dataclass
class Configuration(_c.Field):
    """Configuration (set 0x01, descriptor 0x82, response).

    Sources: demo.txt line 30. Field data: 118..273 bytes.
    """

    instance: int = 0
    count: int = 0
    rates: _ty.List[int] = _dc.field(default_factory=list)  # (count: count)
    name: bytes = b"\x00" * 8
    label: bytes = b" " * 16
    matrix: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 9)
    fixed: _ty.List[int] = _dc.field(default_factory=lambda: [0] * 4)
    flags: _t.Flags = _t.Flags(0)
    signed: _ty.Union[_t.Signed, int] = _t.Signed.MINUS_ONE
    tail: _ty.List[bytes] = _dc.field(default_factory=list)  # (to the end of the field)

    SET = 0x01
    DESCRIPTOR = 0x82
    NAME = "configuration"
    ROLE = "response"
    _ATTRS = ("instance", "count", "rates", "name", "label", "matrix", "fixed", "flags", "signed", "tail")
    _OPS = (
        _c.Run(_c.P("instance", _c.U8), _c.P("count", _c.U8)),
        _c.Counted("rates", _c.U16, count="count", maximum=10),
        _c.Run(
            _c.P("name", _c.string(8)),
            _c.P("label", _c.string(16)),
            _c.P("matrix", _c.F64, 9),
            _c.P("fixed", _c.S32, 4),
            _c.P("flags", _c.flags(_t.Flags)),
            _c.P("signed", _c.enum(_t.Signed, "s16")),
        ),
        _c.Remaining("tail", _c.CHAR, maximum=135),
    )


@_c.slotted
@_dc.dataclass
class PerDevice_dev_a(_c.Field):
    """Per-device command (set 0x01, descriptor 0x03, command), device dev_a.

    Sources: demo.txt line 40. Field data: 4 bytes.
    """

    a: int = 0

    SET = 0x01
    DESCRIPTOR = 0x03
    NAME = "per_device"
    ROLE = "command"
    DEVICE = "dev_a"
    _ATTRS = ("a",)
    _OPS = (_c.Run(_c.P("a", _c.U32)),)


@_c.slotted
@_dc.dataclass
class PerDevice_dev_b(_c.Field):
    """Per-device command (set 0x01, descriptor 0x03, command), device dev_b.

    Sources: demo-b.txt line 41. Field data: 8..9 bytes.
    """

    b: int = 0
    extra: _ty.Optional[int] = None

    SET = 0x01
    DESCRIPTOR = 0x03
    NAME = "per_device"
    ROLE = "command"
    DEVICE = "dev_b"
    _ATTRS = ("b", "extra")
    _OPS = (
        _c.Run(_c.P("b", _c.U64)),
        _c.Opt(_c.Run(_c.P("extra", _c.U8))),
    )


FIELDS: tuple[type[_c.Field], ...] = (Ping, Configure, Configuration, PerDevice_dev_a, PerDevice_dev_b)
