"""What the Demo protocol with every spec feature spec says about every command, for the session layer (session/):
how a reply is matched, and per command layout (set, descriptor) -> rows of
(class, device, devices, functions, replies, ack suppression, timeout allowance).

functions: the function selector values the layout accepts (None: no selector). replies:
(descriptor, function or None, parameter or None, value or None) -- the reply field sent with
the ack when the function is that one and the parameter has that value (None: any non-zero).
ack suppression: ("function", value) or ("param", attribute, value or None: any non-zero).
timeout allowance: (ms, parameter whose value adds milliseconds or None, functions or None).
"""

from __future__ import annotations

from typing import Any, Dict, Tuple

from . import commands

ACK_DESCRIPTOR = 0x80
ACK_ECHO = "echo"
ACK_CODE = "code"
ACK_OK = 0

FUNCTION_NAMES: Dict[int, str] = {
    1: "write",
    2: "read",
    3: "save",
}

# Function selector values that only some devices accept.
FUNCTION_DEVICES: Dict[int, Tuple[str, ...]] = {}

COMMANDS: Dict[Tuple[int, int], Tuple[Tuple[Any, ...], ...]] = {
    (0x01, 0x01): ((commands.Ping, None, ("dev_a",), None, (), None, None),),
    (0x01, 0x02): (
        (
            commands.Configure,
            None,
            ("dev_a",),
            (1, 2, 3),
            ((0x82, 2, None, None),),
            ("param", "suppress_ack", None),
            None,
        ),
    ),
    (0x01, 0x03): (
        (commands.PerDevice_dev_a, "dev_a", ("dev_a",), None, (), None, None),
        (commands.PerDevice_dev_b, "dev_b", ("dev_b",), None, (), None, None),
    ),
}


def function_name(value: int) -> str:
    return FUNCTION_NAMES.get(value, str(value))
