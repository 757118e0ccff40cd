"""What the Demo protocol with every spec feature spec says, for the device command line's settings files and link
budget (device/settings.py, device/budget.py; docs/configure-a-device.md): per device every setting -- a command
with the write and read functions that the spec's `settings` section does not exclude -- and per
device the largest data size of every data field (without its header). Generated from the spec: do not edit.

A setting row: (command class, read reply class, (command name, (set, descriptor), key attributes
sent with read, ((attribute, reply attribute, units or None), ...) the attributes a file entry
holds, ((count attribute, list attribute), ...) set from the lists, the key combinations read:
((attribute, value), ...) each, ((attribute, value), ...) written but not read back: sent as zero)).
"""

from __future__ import annotations

from typing import Any, Dict, Tuple

from . import commands

SETTINGS: Dict[str, Tuple[Tuple[Any, Any, Tuple[Any, ...]], ...]] = {
    "dev_a": (
        (
            commands.Configure,
            commands.Configuration,
            (
                "configure",
                (1, 2),
                ("instance",),
                (("instance", "instance", None),),
                (),
                (),
                (("mode", 0), ("params", 0), ("suppress_ack", 0)),
            ),
        ),
    ),
    "dev_b": (),
}

# device -> (set, descriptor) -> the largest data size of the field in bytes (its header not included)
DATA_SIZES: Dict[str, Dict[Tuple[int, int], int]] = {
    "dev_a": {(144, 1): 29, (145, 3): 18, (146, 3): 18, (255, 211): 8},
    "dev_b": {},
}

# The manual lines of the UART bandwidth calculation (spec `link: bandwidth`; its numbers: _link.py)
BANDWIDTH_SOURCES = ""
