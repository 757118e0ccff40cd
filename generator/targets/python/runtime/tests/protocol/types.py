"""Named types of the test protocol (what the generator renders into types.py)."""

from __future__ import annotations

from . import codec as _c


class Mode(_c.Enum):
    """Mode (u8)."""

    OFF = 0x00
    ON = 0x01
    AUTO = 0x02


class Level(_c.Enum):
    """Level (s8): a signed enum, read by the pure-Python decoder only."""

    LOW = -1
    HIGH = 0x01


class AckCode(_c.Enum):
    """Ack/Nack code (u8)."""

    OK = 0x00
    UNKNOWN_COMMAND = 0x01


@_c.bitfield("u16")
class Status(_c.Bitfield):
    """Status (u16 bitfield)."""

    _MEMBERS = (
        ("ready", "ready", "READY", 0, 1),
        ("level", "level", "LEVEL", 4, 3),
    )
    READY = 0x0001  # bit 0
    LEVEL = 0x0070  # bits 4-6

    ready = _c.bit(0)
    level = _c.bits(4, 3)
