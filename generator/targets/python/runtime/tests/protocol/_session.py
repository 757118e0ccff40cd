"""Session facts of the test protocol (cf. templates/python/package/_session.py.j2): ping on every
device; set_mode on alpha only, its ack suppressed when mode is AUTO, with 500 ms extra time."""

from __future__ import annotations

from typing import Any, Dict, Tuple

from . import command

ACK_DESCRIPTOR = 0xF1
ACK_ECHO = "command_descriptor"
ACK_CODE = "ack_code"
ACK_OK = 0

FUNCTION_NAMES: Dict[int, str] = {}

FUNCTION_DEVICES: Dict[int, Tuple[str, ...]] = {}

COMMANDS: Dict[Tuple[int, int], Tuple[Tuple[Any, ...], ...]] = {
    (0x01, 0x01): ((command.Ping, None, ("alpha", "beta"), None, (), None, None),),
    (0x01, 0x02): ((command.SetMode, None, ("alpha",), None, (), ("param", "mode", 2), (500, None, None)),),
}


def function_name(value: int) -> str:
    return FUNCTION_NAMES.get(value, str(value))
