"""System Command Set (descriptor set 0x7F, command).

Advanced commands for devices with several intelligent internal sensor blocks, such as switching the
communication port to the native protocol of an embedded sensor.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class CommunicationMode(_c.Field):
    """Communication mode (set 0x7F, descriptor 0x10, command).

    Switch the communication protocol between standard MIP and the native protocols of an internal
    sensor block (IMU direct, or u-blox GNSS direct). Always active, even in the direct modes; the
    device acks just before switching. GNSS message settings are reloaded when returning to standard
    mode, and switching to or from GNSS direct takes longer than most commands.

    Functions: write, read, save, load, default. Responses: 0x90 communication_mode_response.
    Sources: 3dm-gx5-45-dcp.txt line 2001. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # New communication mode (ignored for functions other than write). (sent for: write)
    mode: _ty.Optional[_ty.Union[_t.SystemCommMode, int]] = None

    SET = 0x7F
    DESCRIPTOR = 0x10
    NAME = "communication_mode"
    ROLE = "command"
    _ATTRS = ("function", "mode")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.SystemCommMode, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class CommunicationModeResponse(_c.Field):
    """Communication mode (response) (set 0x7F, descriptor 0x90, response).

    Current communication mode (reply to a read).

    Sources: 3dm-gx5-45-dcp.txt line 2014. Field data: 1 bytes.
    """

    mode: _ty.Union[_t.SystemCommMode, int] = _t.SystemCommMode.STANDARD  # Current communication mode.

    SET = 0x7F
    DESCRIPTOR = 0x90
    NAME = "communication_mode_response"
    ROLE = "response"
    _ATTRS = ("mode",)
    _OPS = (_c.Run(_c.P("mode", _c.enum(_t.SystemCommMode, "u8"))),)


FIELDS: tuple[type[_c.Field], ...] = (CommunicationMode, CommunicationModeResponse)
