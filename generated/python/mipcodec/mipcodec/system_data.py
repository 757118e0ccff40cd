"""System Data Set (descriptor set 0xA0, data).

Device-level status data (CV7 only); sampled at the system data base rate.
"""

from __future__ import annotations

import dataclasses as _dc

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class BuiltInTest(_c.Field):
    """Built-in test (streaming continuous BIT) (set 0xA0, descriptor 0x01, data).

    The continuous built-in test result, streamed or polled (the same bits as the Continuous BIT
    command 0x01,0x08). The bits latch until the next output of this message; some may be set in
    normal situations (e.g. no GNSS fix yet). Large: stream at a low rate.

    Sources: 3dm-cv7-ins-docs.txt line 6689; 3dm-cv7-ins-docs.txt line 1413. Field data: 16 bytes.
    """

    # Continuous BIT bit map, 16 bytes, least-significant byte first.
    result: _t.Cv7ContinuousBit = _dc.field(default_factory=_t.Cv7ContinuousBit)

    SET = 0xA0
    DESCRIPTOR = 0x01
    NAME = "built_in_test"
    ROLE = "data"
    _ATTRS = ("result",)
    _OPS = (_c.Nested("result", _t.Cv7ContinuousBit),)


@_c.slotted
@_dc.dataclass
class TimeSyncStatus(_c.Field):
    """Time sync status (set 0xA0, descriptor 0x02, data).

    Whether the device is synchronised to the PPS signal, and how long ago the last pulse came.

    Sources: 3dm-cv7-ins-docs.txt line 6700. Field data: 2 bytes.
    """

    time_sync: bool = False  # True while PPS sync is valid; false if PPS is disabled or not detected.
    last_pps_rcvd: int = 0  # Seconds since the last PPS pulse, saturating at 255. [s]

    SET = 0xA0
    DESCRIPTOR = 0x02
    NAME = "time_sync_status"
    ROLE = "data"
    _ATTRS = ("time_sync", "last_pps_rcvd")
    _OPS = (_c.Run(_c.P("time_sync", _c.BOOL), _c.P("last_pps_rcvd", _c.U8)),)


@_c.slotted
@_dc.dataclass
class GpioState(_c.Field):
    """GPIO state (set 0xA0, descriptor 0x03, data).

    States of the user GPIO pins, sampled within one base period of the system data set. For slow
    signals; pins must be configured with the GPIO feature (0x0C,0x41) to read validly.

    Sources: 3dm-cv7-ins-docs.txt line 6712. Field data: 1 bytes.
    """

    states: _t.GpioPinStates = _t.GpioPinStates(0)  # One bit per pin; pins that do not exist read 0.

    SET = 0xA0
    DESCRIPTOR = 0x03
    NAME = "gpio_state"
    ROLE = "data"
    _ATTRS = ("states",)
    _OPS = (_c.Run(_c.P("states", _c.flags(_t.GpioPinStates))),)


FIELDS: tuple[type[_c.Field], ...] = (BuiltInTest, TimeSyncStatus, GpioState)
