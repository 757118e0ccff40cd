"""The identity reports of the MicroStrain MIP (spec simulation identity), generated: what a
Device Information reply holds, for the log tools (`logs/identity.py`: the log's model and serial),
the sessions and the simulator (`_sim` re-exports it). A module of its own so that a log command
imports only the reply's set module, not every command module `_sim` needs.

`IDENTITY_REPORTS`: reply class -> ((attribute path, item, string format: (length, pad, justify)
or None for an integer), ...). `IDENTITY`: per device the value of every item (the model name a log's
reply is compared with: `logs/identity.py` `model_matches`).
"""

from __future__ import annotations

from typing import Any, Dict, Tuple

from . import base

IDENTITY_REPORTS: Dict[Any, Tuple[Tuple[Any, ...], ...]] = {
    base.DeviceInfo: (
        (("info", "firmware_version"), "firmware", None),
        (("info", "model_name"), "model_name", (16, " ", "left")),
        (("info", "model_number"), "model_number", (16, " ", "left")),
        (("info", "serial_number"), "serial_number", (16, " ", "left")),
        (("info", "lot_number"), "lot_number", (16, " ", "left")),
        (("info", "device_options"), "options", (16, " ", "left")),
    ),
}
IDENTITY: Dict[str, Dict[str, Any]] = {
    "gx5_45": {
        "firmware": 1534,
        "model_name": "3DM-GX5-45",
        "model_number": "6251-4270",
        "serial_number": "6232-00122",
        "lot_number": "",
        "options": "5g, 150d/s",
    },
    "cv7_ins": {
        "firmware": 1202,
        "model_name": "3DM-CV7-GNSS/INS",
        "model_number": "6284-4220",
        "serial_number": "6284.170342",
        "lot_number": "2407-118",
        "options": "8g, 300d/s",
    },
}
