"""GNSS Corrections Data Set (descriptor set 0x93, data).

Information about the RTK correction stream: the base station reported in the RTCM messages and the
status and latency of the corrections received. Sent as the data is received (base rate 0).
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class BaseStationInfo(_c.Field):
    """Base station information (set 0x93, descriptor 0x30, data).

    Base station reported by the RTCM corrections (message 1005 or 1006): its ECEF position, antenna
    height, station id and indicators, with the GPS time the message was received.

    Sources: 3dm-cv7-ins-docs.txt line 4741. Field data: 44 bytes.
    """

    tow: float = 0.0  # GPS time of week the message was received. [s]
    week_number: int = 0  # GPS week number (since 1980). [weeks]
    # (x, y, z) ECEF position of the base station. [m]
    ecef_position: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    height: float = 0.0  # Antenna height above the survey marker. [m]
    station_id: int = 0  # Reference station id (0-4095).
    indicators: _t.GnssBaseStationIndicators = _t.GnssBaseStationIndicators(0)  # Base station indicator bits.
    valid_flags: _t.GnssBaseStationInfoValidFlags = _t.GnssBaseStationInfoValidFlags(0)  # Which values are valid.

    SET = 0x93
    DESCRIPTOR = 0x30
    NAME = "base_station_info"
    ROLE = "data"
    _ATTRS = ("tow", "week_number", "ecef_position", "height", "station_id", "indicators", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("tow", _c.F64),
            _c.P("week_number", _c.U16),
            _c.P("ecef_position", _c.F64, 3),
            _c.P("height", _c.F32),
            _c.P("station_id", _c.U16),
            _c.P("indicators", _c.flags(_t.GnssBaseStationIndicators)),
            _c.P("valid_flags", _c.flags(_t.GnssBaseStationInfoValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class RtkCorrectionsStatus(_c.Field):
    """RTK corrections status (set 0x93, descriptor 0x31, data).

    Status of the RTK corrections received in the current epoch, the RTK dongle status and the
    latency of the last correction per constellation, with the GPS time.

    Sources: 3dm-cv7-ins-docs.txt line 4776. Field data: 50 bytes.
    """

    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number (since 1980). [weeks]
    # Status of the corrections received during this epoch.
    epoch_status: _t.RtkCorrectionsEpochStatus = _t.RtkCorrectionsEpochStatus(0)
    dongle_status: int = 0  # RTK dongle status flags (only valid when an RTK dongle is used).
    gps_correction_latency: float = 0.0  # Latency of the last GPS correction. [s]
    glonass_correction_latency: float = 0.0  # Latency of the last GLONASS correction. [s]
    galileo_correction_latency: float = 0.0  # Latency of the last Galileo correction. [s]
    beidou_correction_latency: float = 0.0  # Latency of the last BeiDou correction. [s]
    reserved: _ty.List[int] = _dc.field(default_factory=lambda: [0] * 4)  # Reserved for future use.
    valid_flags: _t.RtkCorrectionsStatusValidFlags = _t.RtkCorrectionsStatusValidFlags(0)  # Which values are valid.

    SET = 0x93
    DESCRIPTOR = 0x31
    NAME = "rtk_corrections_status"
    ROLE = "data"
    _ATTRS = (
        "tow",
        "week_number",
        "epoch_status",
        "dongle_status",
        "gps_correction_latency",
        "glonass_correction_latency",
        "galileo_correction_latency",
        "beidou_correction_latency",
        "reserved",
        "valid_flags",
    )
    _OPS = (
        _c.Run(
            _c.P("tow", _c.F64),
            _c.P("week_number", _c.U16),
            _c.P("epoch_status", _c.flags(_t.RtkCorrectionsEpochStatus)),
            _c.P("dongle_status", _c.U32),
            _c.P("gps_correction_latency", _c.F32),
            _c.P("glonass_correction_latency", _c.F32),
            _c.P("galileo_correction_latency", _c.F32),
            _c.P("beidou_correction_latency", _c.F32),
            _c.P("reserved", _c.U32, 4),
            _c.P("valid_flags", _c.flags(_t.RtkCorrectionsStatusValidFlags)),
        ),
    )


FIELDS: tuple[type[_c.Field], ...] = (BaseStationInfo, RtkCorrectionsStatus)
