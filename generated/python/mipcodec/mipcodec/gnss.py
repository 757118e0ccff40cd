"""GNSS Command Set (descriptor set 0x0E, command).

Configuration of the device's GNSS receivers and correction services.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class ReceiverInfo(_c.Field):
    """Receiver info (set 0x0E, descriptor 0x01, command).

    Get information about the GNSS receivers in the device.

    Responses: 0x81 receiver_info_response. Sources: 3dm-cv7-ins-docs.txt line 8753. Field data: 0
    bytes.
    """

    SET = 0x0E
    DESCRIPTOR = 0x01
    NAME = "receiver_info"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class ReceiverInfoResponse(_c.Field):
    """Receiver info (response) (set 0x0E, descriptor 0x81, response).

    One entry per physical GNSS receiver.

    Sources: 3dm-cv7-ins-docs.txt line 8761. Field data: 1..239 bytes.
    """

    num_receivers: int = 0  # Number of physical receivers in the device.
    # Information on each receiver. (count: num_receivers)
    receiver_info: _ty.List[_t.GnssReceiverInfoEntry] = _dc.field(default_factory=list)

    SET = 0x0E
    DESCRIPTOR = 0x81
    NAME = "receiver_info_response"
    ROLE = "response"
    _ATTRS = ("num_receivers", "receiver_info")
    _OPS = (
        _c.Run(_c.P("num_receivers", _c.U8)),
        _c.Counted("receiver_info", _t.GnssReceiverInfoEntry, count="num_receivers", maximum=7),
    )


@_c.slotted
@_dc.dataclass
class SignalConfiguration(_c.Field):
    """Signal configuration (set 0x0E, descriptor 0x02, command).

    Choose the GNSS constellations and frequency bands the receivers use. Only some combinations are
    valid: GPS or Galileo must be enabled, GPS L1 with BeiDou L1 alone is not allowed, and per
    constellation GPS none / L1 / L1+L5, GLONASS none / L1, Galileo none / L1+L5, BeiDou none / L1 /
    L1+L5.

    Functions: write, read, save, load, default. Responses: 0x82 signal_configuration_response.
    Sources: 3dm-cv7-ins-docs.txt line 8779; 3dm-cv7-ins-docs.txt line 859. Field data: 1..9 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    gps_enable: _ty.Optional[_t.GnssGpsSignals] = None  # GPS signals to use. (sent for: write)
    glonass_enable: _ty.Optional[_t.GnssGlonassSignals] = None  # GLONASS signals to use. (sent for: write)
    galileo_enable: _ty.Optional[_t.GnssGalileoSignals] = None  # Galileo signals to use. (sent for: write)
    beidou_enable: _ty.Optional[_t.GnssBeidouSignals] = None  # BeiDou signals to use. (sent for: write)
    reserved: _ty.Optional[_ty.List[int]] = None  # Reserved. (sent for: write)

    SET = 0x0E
    DESCRIPTOR = 0x02
    NAME = "signal_configuration"
    ROLE = "command"
    _ATTRS = ("function", "gps_enable", "glonass_enable", "galileo_enable", "beidou_enable", "reserved")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("gps_enable", _c.flags(_t.GnssGpsSignals)))),
        _c.Opt(_c.Run(_c.P("glonass_enable", _c.flags(_t.GnssGlonassSignals)))),
        _c.Opt(_c.Run(_c.P("galileo_enable", _c.flags(_t.GnssGalileoSignals)))),
        _c.Opt(_c.Run(_c.P("beidou_enable", _c.flags(_t.GnssBeidouSignals)))),
        _c.Opt(_c.Run(_c.P("reserved", _c.U8, 4))),
    )


@_c.slotted
@_dc.dataclass
class SignalConfigurationResponse(_c.Field):
    """Signal configuration (response) (set 0x0E, descriptor 0x82, response).

    GNSS signals currently enabled.

    Sources: 3dm-cv7-ins-docs.txt line 8793. Field data: 8 bytes.
    """

    gps_enable: _t.GnssGpsSignals = _t.GnssGpsSignals(0)  # GPS signals in use.
    glonass_enable: _t.GnssGlonassSignals = _t.GnssGlonassSignals(0)  # GLONASS signals in use.
    galileo_enable: _t.GnssGalileoSignals = _t.GnssGalileoSignals(0)  # Galileo signals in use.
    beidou_enable: _t.GnssBeidouSignals = _t.GnssBeidouSignals(0)  # BeiDou signals in use.
    reserved: _ty.List[int] = _dc.field(default_factory=lambda: [0] * 4)  # Reserved.

    SET = 0x0E
    DESCRIPTOR = 0x82
    NAME = "signal_configuration_response"
    ROLE = "response"
    _ATTRS = ("gps_enable", "glonass_enable", "galileo_enable", "beidou_enable", "reserved")
    _OPS = (
        _c.Run(
            _c.P("gps_enable", _c.flags(_t.GnssGpsSignals)),
            _c.P("glonass_enable", _c.flags(_t.GnssGlonassSignals)),
            _c.P("galileo_enable", _c.flags(_t.GnssGalileoSignals)),
            _c.P("beidou_enable", _c.flags(_t.GnssBeidouSignals)),
            _c.P("reserved", _c.U8, 4),
        ),
    )


@_c.slotted
@_dc.dataclass
class SpartnConfiguration(_c.Field):
    """SPARTN configuration (set 0x0E, descriptor 0x20, command).

    Configure the SPARTN corrections service: enable, connection type, and the current and next
    decryption keys with the GPS week and time of week until which each is valid. Enable and type
    take effect after a power cycle; keys can be updated while running. Enabling SPARTN blocks RTCM
    corrections.

    Functions: write, read, save, load, default. Responses: 0xA0 spartn_configuration_response.
    Sources: 3dm-cv7-ins-docs.txt line 8804; 3dm-cv7-ins-docs.txt line 869; 3dm-cv7-ins-docs.txt
    line 2305. Field data: 1..79 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    enable: _ty.Optional[int] = None  # SPARTN subsystem: 0 disabled, 1 enabled. (sent for: write)
    type: _ty.Optional[_ty.Union[_t.SpartnConnectionType, int]] = None  # Connection type. (sent for: write)
    # GPS time of week until which the current key is valid. [s] (sent for: write)
    current_key_tow: _ty.Optional[int] = None
    # GPS week until which the current key is valid. [weeks] (sent for: write)
    current_key_week: _ty.Optional[int] = None
    # Current key: 32 ASCII hex characters (e.g. "bc" for 0xBC). (sent for: write)
    current_key: _ty.Optional[bytes] = None
    next_key_tow: _ty.Optional[int] = None  # GPS time of week until which the next key is valid. [s] (sent for: write)
    next_key_week: _ty.Optional[int] = None  # GPS week until which the next key is valid. [weeks] (sent for: write)
    next_key: _ty.Optional[bytes] = None  # Next key: 32 ASCII hex characters. (sent for: write)

    SET = 0x0E
    DESCRIPTOR = 0x20
    NAME = "spartn_configuration"
    ROLE = "command"
    _ATTRS = (
        "function",
        "enable",
        "type",
        "current_key_tow",
        "current_key_week",
        "current_key",
        "next_key_tow",
        "next_key_week",
        "next_key",
    )
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("enable", _c.U8))),
        _c.Opt(_c.Run(_c.P("type", _c.enum(_t.SpartnConnectionType, "u8")))),
        _c.Opt(_c.Run(_c.P("current_key_tow", _c.U32))),
        _c.Opt(_c.Run(_c.P("current_key_week", _c.U16))),
        _c.Opt(_c.Run(_c.P("current_key", _c.string(32)))),
        _c.Opt(_c.Run(_c.P("next_key_tow", _c.U32))),
        _c.Opt(_c.Run(_c.P("next_key_week", _c.U16))),
        _c.Opt(_c.Run(_c.P("next_key", _c.string(32)))),
    )


@_c.slotted
@_dc.dataclass
class SpartnConfigurationResponse(_c.Field):
    """SPARTN configuration (response) (set 0x0E, descriptor 0xA0, response).

    Current SPARTN configuration.

    Sources: 3dm-cv7-ins-docs.txt line 8821. Field data: 78 bytes.
    """

    enable: int = 0  # SPARTN subsystem: 0 disabled, 1 enabled.
    type: _ty.Union[_t.SpartnConnectionType, int] = _t.SpartnConnectionType.NONE  # Connection type.
    current_key_tow: int = 0  # GPS time of week until which the current key is valid. [s]
    current_key_week: int = 0  # GPS week until which the current key is valid. [weeks]
    current_key: bytes = b"\x00" * 32  # Current key: 32 ASCII hex characters.
    next_key_tow: int = 0  # GPS time of week until which the next key is valid. [s]
    next_key_week: int = 0  # GPS week until which the next key is valid. [weeks]
    next_key: bytes = b"\x00" * 32  # Next key: 32 ASCII hex characters.

    SET = 0x0E
    DESCRIPTOR = 0xA0
    NAME = "spartn_configuration_response"
    ROLE = "response"
    _ATTRS = (
        "enable",
        "type",
        "current_key_tow",
        "current_key_week",
        "current_key",
        "next_key_tow",
        "next_key_week",
        "next_key",
    )
    _OPS = (
        _c.Run(
            _c.P("enable", _c.U8),
            _c.P("type", _c.enum(_t.SpartnConnectionType, "u8")),
            _c.P("current_key_tow", _c.U32),
            _c.P("current_key_week", _c.U16),
            _c.P("current_key", _c.string(32)),
            _c.P("next_key_tow", _c.U32),
            _c.P("next_key_week", _c.U16),
            _c.P("next_key", _c.string(32)),
        ),
    )


FIELDS: tuple[type[_c.Field], ...] = (
    ReceiverInfo,
    ReceiverInfoResponse,
    SignalConfiguration,
    SignalConfigurationResponse,
    SpartnConfiguration,
    SpartnConfigurationResponse,
)
