"""Named types of the Demo protocol with every spec feature: enums, bitfields, structs and unions.

Enums are IntEnums; decoding keeps values that are not members as plain ints. Bitfields are ints
whose members are properties (bool for one bit, int for several) with UPPER_CASE mask constants.
Structs are dataclasses; a union value is the selected member's struct (None: member without data).
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from .codec import layout as _c


@_c.bitfield("u16")
class Flags(_c.Bitfield):
    """Flags (u16 bitfield)."""

    _MEMBERS = (
        ("ok", "ok", "OK", 0, 1),
        ("level", "level", "LEVEL", 12, 4),
        ("all", "all", "ALL", 0, 16),
    )
    OK = 0x0001  # bit 0
    LEVEL = 0xF000  # bits 12-15
    ALL = 0xFFFF  # bits 0-15: (alias mask)

    ok = _c.bit(0)
    level = _c.bits(12, 4)
    all = _c.bits(0, 16)


class Function(_c.Enum):
    """Function (u8)."""

    WRITE = 0x01
    READ = 0x02
    SAVE = 0x03


class Mode(_c.Enum):
    """Mode (u8)."""

    NONE = 0x00
    GPIO = 0x01
    THRESHOLD = 0x02
    FAST = 0x03  # (devices: dev_a)
    QUIET = 0x03  # (devices: dev_b)


class Signed(_c.Enum):
    """Signed (s16)."""

    MINUS_ONE = -1
    PLUS_ONE = 0x01


@_dc.dataclass
class GpioParams(_c.Struct):
    """GpioParams (struct, 2 bytes)."""

    pin: int = 0
    polarity: bool = False

    _ATTRS = ("pin", "polarity")
    _OPS = (_c.Run(_c.P("pin", _c.U8), _c.P("polarity", _c.BOOL)),)
    _SIZE = 2


@_dc.dataclass
class ThresholdParams(_c.Struct):
    """ThresholdParams (struct, 28 bytes)."""

    low: float = 0.0
    high: float = 0.0
    axes: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    _ATTRS = ("low", "high", "axes")
    _OPS = (_c.Run(_c.P("low", _c.F64), _c.P("high", _c.F64), _c.P("axes", _c.F32, 3)),)
    _SIZE = 28


class TriggerParams(_c.Union):
    """TriggerParams (union selected by Mode).

    The value of a union parameter is the selected member's struct, or None for a member without
    data.
    """

    _SELECTOR = Mode
    _MEMBERS = {
        0x00: None,  # none
        0x01: GpioParams,  # gpio
        0x02: ThresholdParams,  # threshold
    }
