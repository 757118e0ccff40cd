"""3DM Command Set (descriptor set 0x0C, command).

Device configuration common to MicroStrain inertial sensors.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import codec as _c
from . import types as _t


@_dc.dataclass
class EventControl(_c.Field):
    """Event control (set 0x0C, descriptor 0x2B, command).

    Enable, disable or test an event trigger.

    Functions: write, read, save, load, default. Responses: 0xB5 event_control_response. Sources:
    3dm-cv7-ins-docs.txt line 7018. Field data: 2..3 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
    instance: int = 0  # Trigger instance; 0 applies to all configured triggers (not for read).
    mode: _ty.Optional[_t.EventControlMode] = None  # How to change the trigger state. (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x2B
    NAME = "event_control"
    ROLE = "command"
    _ATTRS = ("function", "instance", "mode")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("instance", _c.U8)),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.EventControlMode, "u8")))),
    )


@_dc.dataclass
class EventControlResponse(_c.Field):
    """Event control (response) (set 0x0C, descriptor 0xB5, response).

    Current mode of a trigger.

    Sources: 3dm-cv7-ins-docs.txt line 7032. Field data: 2 bytes.
    """

    instance: int = 0  # Trigger instance.
    mode: _t.EventControlMode = _t.EventControlMode.DISABLED  # Trigger mode.

    SET = 0x0C
    DESCRIPTOR = 0xB5
    NAME = "event_control_response"
    ROLE = "response"
    _ATTRS = ("instance", "mode")
    _OPS = (_c.Run(_c.P("instance", _c.U8), _c.P("mode", _c.enum(_t.EventControlMode, "u8"))),)


@_dc.dataclass
class GetEventTriggerStatus(_c.Field):
    """Get event trigger status (set 0x0C, descriptor 0x2C, command).

    Report the type and status of event triggers.

    Responses: 0xB6 event_trigger_status. Sources: 3dm-cv7-ins-docs.txt line 7047. Field data:
    1..253 bytes.
    """

    requested_count: int = 0  # Number of entries requested; 0 requests all trigger slots.
    # Trigger instances to query. (count: requested_count)
    requested_instances: _ty.List[int] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x2C
    NAME = "get_event_trigger_status"
    ROLE = "command"
    _ATTRS = ("requested_count", "requested_instances")
    _OPS = (
        _c.Run(_c.P("requested_count", _c.U8)),
        _c.Counted("requested_instances", _c.U8, count="requested_count", maximum=252),
    )


@_dc.dataclass
class EventTriggerStatus(_c.Field):
    """Event trigger status (set 0x0C, descriptor 0xB6, response).

    Status of the requested triggers, in the order requested (increasing if all).

    Sources: 3dm-cv7-ins-docs.txt line 7057. Field data: 1..253 bytes.
    """

    count: int = 0  # Number of entries.
    # The configured triggers. (count: count)
    triggers: _ty.List[_t.TriggerStatusEntry] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0xB6
    NAME = "event_trigger_status"
    ROLE = "response"
    _ATTRS = ("count", "triggers")
    _OPS = (
        _c.Run(_c.P("count", _c.U8)),
        _c.Counted("triggers", _t.TriggerStatusEntry, count="count", maximum=126),
    )


@_dc.dataclass
class GetEventActionStatus(_c.Field):
    """Get event action status (set 0x0C, descriptor 0x2D, command).

    Report the type and trigger of event actions.

    Responses: 0xB7 event_action_status. Sources: 3dm-cv7-ins-docs.txt line 7080. Field data: 1..253
    bytes.
    """

    requested_count: int = 0  # Number of entries requested; 0 requests all action slots.
    # Action instances to query. (count: requested_count)
    requested_instances: _ty.List[int] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x2D
    NAME = "get_event_action_status"
    ROLE = "command"
    _ATTRS = ("requested_count", "requested_instances")
    _OPS = (
        _c.Run(_c.P("requested_count", _c.U8)),
        _c.Counted("requested_instances", _c.U8, count="requested_count", maximum=252),
    )


@_dc.dataclass
class EventActionStatus(_c.Field):
    """Event action status (set 0x0C, descriptor 0xB7, response).

    Status of the requested actions.

    Sources: 3dm-cv7-ins-docs.txt line 7090. Field data: 1..253 bytes.
    """

    count: int = 0  # Number of entries.
    actions: _ty.List[_t.ActionStatusEntry] = _dc.field(default_factory=list)  # The configured actions. (count: count)

    SET = 0x0C
    DESCRIPTOR = 0xB7
    NAME = "event_action_status"
    ROLE = "response"
    _ATTRS = ("count", "actions")
    _OPS = (
        _c.Run(_c.P("count", _c.U8)),
        _c.Counted("actions", _t.ActionStatusEntry, count="count", maximum=126),
    )


@_dc.dataclass
class EventTriggerConfig(_c.Field):
    """Event trigger configuration (set 0x0C, descriptor 0x2E, command).

    Configure an event trigger (GPIO, threshold or combination).

    Functions: write, read, save, load, default. Responses: 0xB8 event_trigger_config_response.
    Sources: 3dm-cv7-ins-docs.txt line 7107. Field data: 2..23 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
    instance: int = 0  # Trigger number; 0 applies to all instances for save, load and default.
    type: _ty.Optional[_t.TriggerType] = None  # Type of trigger. (sent for: write)
    # Parameters of the trigger type. (sent for: write)
    parameters: _ty.Optional[_ty.Union[_t.TriggerGpioParams, _t.ThresholdParams, _t.CombinationParams]] = None

    SET = 0x0C
    DESCRIPTOR = 0x2E
    NAME = "event_trigger_config"
    ROLE = "command"
    _ATTRS = ("function", "instance", "type", "parameters")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("instance", _c.U8)),
        _c.Opt(_c.Run(_c.P("type", _c.enum(_t.TriggerType, "u8")))),
        _c.Opt(_c.Choice("parameters", _t.TriggerParams, selector="type")),
    )


@_dc.dataclass
class EventTriggerConfigResponse(_c.Field):
    """Event trigger configuration (response) (set 0x0C, descriptor 0xB8, response).

    Current configuration of a trigger.

    Sources: 3dm-cv7-ins-docs.txt line 7124. Field data: 2..22 bytes.
    """

    instance: int = 0  # Trigger number.
    type: _t.TriggerType = _t.TriggerType.NONE  # Type of trigger.
    # Parameters of the trigger type.
    parameters: _ty.Optional[_ty.Union[_t.TriggerGpioParams, _t.ThresholdParams, _t.CombinationParams]] = None

    SET = 0x0C
    DESCRIPTOR = 0xB8
    NAME = "event_trigger_config_response"
    ROLE = "response"
    _ATTRS = ("instance", "type", "parameters")
    _OPS = (
        _c.Run(_c.P("instance", _c.U8), _c.P("type", _c.enum(_t.TriggerType, "u8"))),
        _c.Choice("parameters", _t.TriggerParams, selector="type"),
    )


@_dc.dataclass
class EventActionConfig(_c.Field):
    """Event action configuration (set 0x0C, descriptor 0x2F, command).

    Configure an event action (GPIO or message) and the trigger that fires it.

    Functions: write, read, save, load, default. Responses: 0xB9 event_action_config_response.
    Sources: 3dm-cv7-ins-docs.txt line 7186. Field data: 2..20 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
    instance: int = 0  # Action number; 0 applies to all instances for save, load and default.
    trigger: _ty.Optional[int] = None  # Trigger ID number. (sent for: write)
    type: _ty.Optional[_t.ActionType] = None  # Type of action. (sent for: write)
    # Parameters of the action type. (sent for: write)
    parameters: _ty.Optional[_ty.Union[_t.ActionGpioParams, _t.MessageParams]] = None

    SET = 0x0C
    DESCRIPTOR = 0x2F
    NAME = "event_action_config"
    ROLE = "command"
    _ATTRS = ("function", "instance", "trigger", "type", "parameters")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("instance", _c.U8)),
        _c.Opt(_c.Run(_c.P("trigger", _c.U8))),
        _c.Opt(_c.Run(_c.P("type", _c.enum(_t.ActionType, "u8")))),
        _c.Opt(_c.Choice("parameters", _t.ActionParams, selector="type")),
    )


@_dc.dataclass
class EventActionConfigResponse(_c.Field):
    """Event action configuration (response) (set 0x0C, descriptor 0xB9, response).

    Current configuration of an action.

    Sources: 3dm-cv7-ins-docs.txt line 7203. Field data: 3..19 bytes.
    """

    instance: int = 0  # Action number.
    trigger: int = 0  # Trigger ID number.
    type: _t.ActionType = _t.ActionType.NONE  # Type of action.
    parameters: _ty.Optional[_ty.Union[_t.ActionGpioParams, _t.MessageParams]] = None  # Parameters of the action type.

    SET = 0x0C
    DESCRIPTOR = 0xB9
    NAME = "event_action_config_response"
    ROLE = "response"
    _ATTRS = ("instance", "trigger", "type", "parameters")
    _OPS = (
        _c.Run(_c.P("instance", _c.U8), _c.P("trigger", _c.U8), _c.P("type", _c.enum(_t.ActionType, "u8"))),
        _c.Choice("parameters", _t.ActionParams, selector="type"),
    )


FIELDS: tuple = (
    EventControl,
    EventControlResponse,
    GetEventTriggerStatus,
    EventTriggerStatus,
    GetEventActionStatus,
    EventActionStatus,
    EventTriggerConfig,
    EventTriggerConfigResponse,
    EventActionConfig,
    EventActionConfigResponse,
)
