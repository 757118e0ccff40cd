"""Shared Data Descriptors (descriptor set 0xFF, data, shared data descriptors).

Timestamps, time deltas and the event source, usable in any data descriptor set. Placed at the front
of a message format, they are repeated in every continuation packet of a message that does not fit
in one packet, so that a parser can group the packets of one sample by their timestamp (CV7 lines
4002-4024). The GX5-45 has no shared descriptors.
"""

from __future__ import annotations

import dataclasses as _dc

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class EventSource(_c.Field):
    """Event source (set 0xFF, descriptor 0xD0, data).

    Which event trigger caused this packet to be sent; 0 for packets sent by the scheduled streaming
    of the message format (0x0C,0x0F). Recommended as the first field of every event packet; as a
    shared descriptor it is repeated in continuation packets.

    Sources: 3dm-cv7-ins-docs.txt line 6583; 3dm-cv7-ins-docs.txt line 1834. Field data: 1 bytes.
    """

    trigger_id: int = 0  # Trigger (or, per line 1836, action) instance ID; 0 for scheduled streaming.

    SET = 0xFF
    DESCRIPTOR = 0xD0
    NAME = "event_source"
    ROLE = "data"
    _ATTRS = ("trigger_id",)
    _OPS = (_c.Run(_c.P("trigger_id", _c.U8)),)


@_c.slotted
@_dc.dataclass
class GpsTimestamp(_c.Field):
    """GPS timestamp (set 0xFF, descriptor 0xD3, data).

    GPS time of the sample (for event packets, of the event trigger) as time of week and week
    number. Valid after PPS synchronisation and after both the time of week and the week number have
    been sent with the GPS Time Update command (0x01,0x72).

    Sources: 3dm-cv7-ins-docs.txt line 6594; 3dm-cv7-ins-docs.txt line 1576. Field data: 12 bytes.
    """

    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number since 1980. [weeks]
    # Which parts of the time have been set.
    valid_flags: _t.SharedGpsTimestampValidFlags = _t.SharedGpsTimestampValidFlags(0)

    SET = 0xFF
    DESCRIPTOR = 0xD3
    NAME = "gps_timestamp"
    ROLE = "data"
    _ATTRS = ("tow", "week_number", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("tow", _c.F64),
            _c.P("week_number", _c.U16),
            _c.P("valid_flags", _c.flags(_t.SharedGpsTimestampValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class DeltaTime(_c.Field):
    """Delta time (set 0xFF, descriptor 0xD4, data).

    Seconds in the synchronised (external/GPS) clock domain since the last output of this field in
    the same descriptor set and event instance. The same value as external time delta 0xD8 in
    seconds; both restart one shared counter, so stream only one of them.

    Sources: 3dm-cv7-ins-docs.txt line 6613. Field data: 8 bytes.
    """

    seconds: float = 0.0  # Seconds since the last output. [s]

    SET = 0xFF
    DESCRIPTOR = 0xD4
    NAME = "delta_time"
    ROLE = "data"
    _ATTRS = ("seconds",)
    _OPS = (_c.Run(_c.P("seconds", _c.F64)),)


@_c.slotted
@_dc.dataclass
class ReferenceTimestamp(_c.Field):
    """Reference timestamp (set 0xFF, descriptor 0xD5, data).

    Time at which the data was sampled (for events, of the trigger) on the internal monotonic
    reference clock, in nanoseconds since power-on. Never jumps; always valid.

    Sources: 3dm-cv7-ins-docs.txt line 6624; 3dm-cv7-ins-docs.txt line 1560. Field data: 8 bytes.
    """

    nanoseconds: int = 0  # Nanoseconds since initialization. [ns]

    SET = 0xFF
    DESCRIPTOR = 0xD5
    NAME = "reference_timestamp"
    ROLE = "data"
    _ATTRS = ("nanoseconds",)
    _OPS = (_c.Run(_c.P("nanoseconds", _c.U64)),)


@_c.slotted
@_dc.dataclass
class ReferenceTimeDelta(_c.Field):
    """Reference time delta (set 0xFF, descriptor 0xD6, data).

    Difference between the reference timestamp (0xD5) now and at the previous output of this field
    in the same descriptor set and event instance. Always valid.

    Sources: 3dm-cv7-ins-docs.txt line 6636. Field data: 8 bytes.
    """

    dt_nanos: int = 0  # Nanoseconds since the last occurrence of this field. [ns]

    SET = 0xFF
    DESCRIPTOR = 0xD6
    NAME = "reference_time_delta"
    ROLE = "data"
    _ATTRS = ("dt_nanos",)
    _OPS = (_c.Run(_c.P("dt_nanos", _c.U64)),)


@_c.slotted
@_dc.dataclass
class ExternalTimestamp(_c.Field):
    """External timestamp (set 0xFF, descriptor 0xD7, data).

    Time at which the data was sampled (for events, of the trigger) in the external clock domain, in
    nanoseconds: the GPS timestamp in nanoseconds. Valid once the external clock is synchronised
    with the PPS input.

    Sources: 3dm-cv7-ins-docs.txt line 6647; 3dm-cv7-ins-docs.txt line 1566. Field data: 10 bytes.
    """

    nanoseconds: int = 0  # External time in nanoseconds. [ns]
    valid_flags: _t.ExternalTimestampValidFlags = _t.ExternalTimestampValidFlags(0)  # Bit 0: nanoseconds valid.

    SET = 0xFF
    DESCRIPTOR = 0xD7
    NAME = "external_timestamp"
    ROLE = "data"
    _ATTRS = ("nanoseconds", "valid_flags")
    _OPS = (_c.Run(_c.P("nanoseconds", _c.U64), _c.P("valid_flags", _c.flags(_t.ExternalTimestampValidFlags))),)


@_c.slotted
@_dc.dataclass
class ExternalTimeDelta(_c.Field):
    """External time delta (set 0xFF, descriptor 0xD8, data).

    Difference between the external timestamp (0xD7) now and at the previous output of this field in
    the same descriptor set and event instance. The same value as delta time 0xD4 in nanoseconds;
    both restart one shared counter.

    Sources: 3dm-cv7-ins-docs.txt line 6663. Field data: 10 bytes.
    """

    dt_nanos: int = 0  # Nanoseconds since the last occurrence of this field. [ns]
    valid_flags: _t.ExternalTimeDeltaValidFlags = _t.ExternalTimeDeltaValidFlags(0)  # Bit 0: delta valid.

    SET = 0xFF
    DESCRIPTOR = 0xD8
    NAME = "external_time_delta"
    ROLE = "data"
    _ATTRS = ("dt_nanos", "valid_flags")
    _OPS = (_c.Run(_c.P("dt_nanos", _c.U64), _c.P("valid_flags", _c.flags(_t.ExternalTimeDeltaValidFlags))),)


FIELDS: tuple[type[_c.Field], ...] = (
    EventSource,
    GpsTimestamp,
    DeltaTime,
    ReferenceTimestamp,
    ReferenceTimeDelta,
    ExternalTimestamp,
    ExternalTimeDelta,
)
