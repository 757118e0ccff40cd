"""The identity reports of the Memsense MS-CIP (spec simulation identity), generated: what a
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
    base.DeviceModel: ((("model",), "model_name", (16, " ", "right")),),
    base.DeviceSn: ((("serial_number",), "serial_number", (16, " ", "right")),),
    base.DeviceFw: ((("firmware",), "firmware", (16, " ", "right")),),
    base.DeviceCal: ((("date",), "calibration_date", (16, " ", "right")),),
}
IDENTITY: Dict[str, Dict[str, Any]] = {
    "ms_imu3020": {
        "model_name": "MS_IMU3020",
        "serial_number": "20268",
        "firmware": "R_1_2_3",
        "calibration_date": "05-08-2015",
    }
}
