"""What the Memsense MS-CIP spec says, for the device command line's settings files and link
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

from . import imu_config

SETTINGS: Dict[str, Tuple[Tuple[Any, Any, Tuple[Any, ...]], ...]] = {
    "ms_imu3020": (
        (
            imu_config.UartBaudRate,
            imu_config.UartBaudRateResponse,
            ("uart_baud_rate", (2, 1), (), (("baud_rate", "baud_rate", "baud"),), (), ((),), ()),
        ),
        (
            imu_config.Filter,
            imu_config.FilterResponse,
            ("filter", (2, 3), (), (("bandwidth", "bandwidth", None),), (), ((),), ()),
        ),
        (
            imu_config.SampleRate,
            imu_config.SampleRateResponse,
            ("sample_rate", (2, 4), (), (("decimation", "decimation", None),), (), ((),), ()),
        ),
        (
            imu_config.SelectSensors,
            imu_config.SelectSensorsResponse,
            ("select_sensors", (2, 5), (), (("sensors", "sensors", None),), (), ((),), (("reserved", 0),)),
        ),
        (
            imu_config.AccelRange,
            imu_config.AccelRangeResponse,
            ("accel_range", (2, 7), (), (("range", "range", None),), (), ((),), ()),
        ),
        (
            imu_config.GyroRange,
            imu_config.GyroRangeResponse,
            ("gyro_range", (2, 8), (), (("range", "range", None),), (), ((),), ()),
        ),
        (
            imu_config.DataOnOff,
            imu_config.DataOnOffResponse,
            ("data_on_off", (2, 10), (), (("control", "control", None),), (), ((),), ()),
        ),
        (
            imu_config.XtrigOnOff,
            imu_config.XtrigOnOffResponse,
            ("xtrig_on_off", (2, 11), (), (("control", "control", None),), (), ((),), ()),
        ),
        (
            imu_config.SelectSensorsRevB,
            imu_config.SelectSensorsRevBResponse,
            ("select_sensors_rev_b", (2, 12), (), (("sensors", "sensors", None),), (), ((),), ()),
        ),
        (
            imu_config.AuxAccelRange,
            imu_config.AuxAccelRangeResponse,
            ("aux_accel_range", (2, 13), (), (("range", "range", None),), (), ((),), ()),
        ),
    ),
}

# device -> (set, descriptor) -> the largest data size of the field in bytes (its header not included)
DATA_SIZES: Dict[str, Dict[Tuple[int, int], int]] = {
    "ms_imu3020": {
        (162, 129): 12,
        (162, 130): 12,
        (162, 131): 12,
        (162, 132): 12,
        (162, 133): 12,
        (162, 134): 4,
        (162, 135): 4,
        (162, 136): 12,
        (162, 137): 12,
    },
}

# The manual lines of the UART bandwidth calculation (spec `link: bandwidth`; its numbers: _link.py)
BANDWIDTH_SOURCES = ""
