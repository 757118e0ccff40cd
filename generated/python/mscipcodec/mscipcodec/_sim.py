"""What the Memsense MS-CIP spec says, for the simulated device (sim.py, docs/conformance.md
section 9): per command layout the parameters each function sends (the key of a setting) and its
enum parameters; per data layout the units of its values; the commands that configure streaming
(generator/targets/python/backend.py STREAMING), base rates in Hz and the NACK code of each refusal.
"""

from __future__ import annotations

from typing import Any, Dict, Tuple

from . import base, imu_config, imu_data, types
from ._identity import IDENTITY as IDENTITY  # re-exported (sim, session)
from ._identity import IDENTITY_REPORTS as IDENTITY_REPORTS

# NACK code per refusal: an unknown descriptor, an unknown descriptor set, a bad parameter value,
# a command the simulator failed to carry out.
NACK: Dict[str, int] = {
    "unknown_descriptor": 3,
    "unknown_set": 2,
    "invalid_parameter": 4,
    "failed": 4,
}

# class -> ({function value: parameters it sends, without the selector}, enum parameters)
COMMANDS: Dict[Any, Tuple[Dict[int, Tuple[str, ...]], Tuple[str, ...]]] = {
    base.Ping: ({}, ()),
    base.GetDeviceMessages: ({}, ()),
    base.DeviceReset: ({}, ()),
    base.GetDeviceModel: ({}, ()),
    base.GetDeviceSn: ({}, ()),
    base.GetDeviceFw: ({}, ()),
    base.GetDeviceCal: ({}, ()),
    base.CorrelateGpsTime: ({}, ()),
    imu_config.UartBaudRate: ({1: (), 2: (), 3: (), 4: (), 5: ()}, ("baud_rate",)),
    imu_config.Filter: ({1: (), 2: (), 3: (), 4: (), 5: ()}, ("bandwidth",)),
    imu_config.SampleRate: ({1: (), 2: (), 3: (), 4: (), 5: ()}, ()),
    imu_config.SelectSensors: ({1: (), 2: (), 3: (), 4: (), 5: ()}, ()),
    imu_config.GetInternalSampleRate: ({}, ()),
    imu_config.AccelRange: ({1: (), 2: (), 3: (), 4: (), 5: ()}, ("range",)),
    imu_config.GyroRange: ({1: (), 2: (), 3: (), 4: (), 5: ()}, ("range",)),
    imu_config.ConfigAll: ({3: (), 4: (), 5: ()}, ()),
    imu_config.DataOnOff: ({1: (), 2: (), 3: (), 4: (), 5: ()}, ("control",)),
    imu_config.XtrigOnOff: ({1: (), 2: (), 3: (), 4: (), 5: ()}, ("control",)),
    imu_config.SelectSensorsRevB: ({1: (), 2: (), 3: (), 4: (), 5: ()}, ()),
    imu_config.AuxAccelRange: ({1: (), 2: (), 3: (), 4: (), 5: ()}, ("range",)),
}

# class -> {function value: parameters the device ignores for it}: not sent for that function, or
# stated ignored by the manual (the spec's `ignored`); neither checked nor taken into a reply
IGNORED: Dict[Any, Dict[int, Tuple[str, ...]]] = {
    imu_config.UartBaudRate: {2: ("baud_rate",), 3: ("baud_rate",), 4: ("baud_rate",), 5: ("baud_rate",)},
    imu_config.Filter: {2: ("bandwidth",), 3: ("bandwidth",), 4: ("bandwidth",), 5: ("bandwidth",)},
    imu_config.SampleRate: {2: ("decimation",), 3: ("decimation",), 4: ("decimation",), 5: ("decimation",)},
    imu_config.SelectSensors: {
        2: ("reserved", "sensors"),
        3: ("reserved", "sensors"),
        4: ("reserved", "sensors"),
        5: ("reserved", "sensors"),
    },
    imu_config.AccelRange: {2: ("range",), 3: ("range",), 4: ("range",), 5: ("range",)},
    imu_config.GyroRange: {2: ("range",), 3: ("range",), 4: ("range",), 5: ("range",)},
    imu_config.DataOnOff: {2: ("control",), 3: ("control",), 4: ("control",), 5: ("control",)},
    imu_config.XtrigOnOff: {2: ("control",), 3: ("control",), 4: ("control",), 5: ("control",)},
    imu_config.SelectSensorsRevB: {2: ("sensors",), 3: ("sensors",), 4: ("sensors",), 5: ("sensors",)},
    imu_config.AuxAccelRange: {2: ("range",), 3: ("range",), 4: ("range",), 5: ("range",)},
}

# class -> ((parameter, units, fixed count or None), ...) of its plain values
DATA: Dict[Any, Tuple[Tuple[str, Any, Any], ...]] = {
    imu_data.ScaledAccel: (("accel", "g", 3),),
    imu_data.ScaledGyro: (("gyro", "deg/s", 3),),
    imu_data.ScaledMag: (("mag", "gauss", 3),),
    imu_data.DeltaTheta: (("delta_theta", "rad", 3),),
    imu_data.DeltaVelocity: (("delta_velocity", "m/s", 3),),
    imu_data.ScaledPressure: (("pressure", "mbar", None),),
    imu_data.ScaledTemperature: (("temperature", "degC", None),),
    imu_data.GpsCorrelatedTime: (("seconds", "s", None), ("week", "weeks", None)),
    imu_data.ScaledAuxAccel: (("accel", "g", 3),),
}

# The simulated world (sim/world.py; the spec's simulation.world): class -> ((parameter, world quantity), ...)
WORLD: Dict[Any, Tuple[Tuple[str, str], ...]] = {}

# The navigation filter of each device (backend.py FILTER): states, aiding, fix type members
FILTER: Dict[str, Dict[str, Any]] = {}

# What commands do to the world (the spec's simulation.actions): class -> (action, arguments...)
ACTIONS: Dict[Any, Tuple[Any, ...]] = {}

# Message format commands: class -> (set, list parameter, descriptor member or None, decimation member or None)
FORMATS: Dict[Any, Any] = {
    imu_config.SelectSensors: (162, "sensors", None, None),
    imu_config.SelectSensorsRevB: (162, "sensors", None, None),
}

# Stream control: class -> (set, enable parameter)
ENABLES: Dict[Any, Any] = {
    imu_config.DataOnOff: (162, "control"),
}

# Base rate queries: class -> set
RATES: Dict[Any, Any] = {
    imu_config.GetInternalSampleRate: 162,
}

# Poll commands: class -> (set, descriptor list parameter)
POLLS: Dict[Any, Any] = {}

# One decimation for every streamed field (when the format list has none): class -> parameter
DECIMATION: Dict[Any, str] = {
    imu_config.SampleRate: "decimation",
}

BASE_RATES: Dict[str, Dict[int, int]] = {"ms_imu3020": {162: 1000}}

# Commands that change the port's baud rate (write): class -> rate parameter
BAUD: Dict[Any, str] = {
    imu_config.UartBaudRate: "baud_rate",
}

# Data sets the stream control of a model cannot address: they stream whenever their format is set
UNADDRESSED: Dict[str, Any] = {}

# Commands whose save, load and default apply to every setting at once
ALL_SETTINGS: Tuple[Any, ...] = (imu_config.ConfigAll,)

DEVICE_TITLES: Dict[str, str] = {"ms_imu3020": "MS-IMU3020"}

# How each device's external (GPS) time is synchronized (spec time.sync; sim/clocks.py,
# device/timesync.py): the update command and window, the PPS kinds, the PPS source setting, the
# sync status field, the external time fields with their flag masks, the correlation flags
TIME_SYNC: Dict[str, Dict[str, Any]] = {}

# The replies that list what the device supports (spec simulation descriptor_lists): reply class ->
# (which reply: 0 the first, 1 the extended; its capacity; the list attribute), and the item class
# (None: a u16, (set << 8) | descriptor); which capabilities lists they hold, in that order
DESCRIPTOR_LISTS: Dict[Any, Tuple[int, int, str]] = {
    base.DeviceMessages: (0, 124, "messages"),
}
DESCRIPTOR_ITEMS: Dict[Any, Any] = {
    base.DeviceMessages: types.MessageId,
}
DESCRIPTOR_CONTENTS: Tuple[str, ...] = ("command",)

# Identity (spec simulation identity): the reports of each reply class and per device the value of
# every item (`_identity`, a module of its own for the log tools); per item its kind and limit (the
# largest integer, or the most characters)
IDENTITY_ITEMS: Dict[str, Tuple[str, int]] = {
    "model_name": ("string", 16),
    "serial_number": ("string", 16),
    "firmware": ("string", 16),
    "calibration_date": ("string", 16),
}

# Device status replies kept live (spec simulation status; sim/status.py): reply class -> the
# attributes of each role (timer, power, streams {attribute: set}, bytes, pps, messages (set, count, last, only while
# the receiver has a fix))
STATUS: Dict[Any, Dict[str, Any]] = {}

# NMEA-0183 output and input (spec simulation nmea; sim/nmea.py): entry attributes by role, the
# NACK code of a refused entry, origins {kind: (sets, highest Hz)}, talker IDs and sentences
# {code: (name, talker configurable, source kinds)} by code, the input (set, sentences, updates);
# the commands: class -> ("format" or "poll", list attribute)
NMEA: Dict[str, Any] = {}
NMEA_COMMANDS: Dict[Any, Tuple[str, str]] = {}

# Factory values the manuals state (the spec's `default`, with its source line), else the spec's
# `plausible` value (with its reason); every other parameter's factory value is zero:
# device -> class -> {parameter: value}
FACTORY: Dict[str, Dict[Any, Dict[str, Any]]] = {
    "ms_imu3020": {
        imu_config.UartBaudRate: {"baud_rate": 115200},
        imu_config.Filter: {"bandwidth": 0},
        imu_config.SampleRate: {"decimation": 1},
        imu_config.SelectSensors: {"reserved": 0, "sensors": [129, 130]},
        imu_config.AccelRange: {"range": 0},
        imu_config.GyroRange: {"range": 1},
        imu_config.DataOnOff: {"control": 0},
        imu_config.XtrigOnOff: {"control": 0},
        imu_config.SelectSensorsRevB: {"sensors": [129, 130]},
        imu_config.AuxAccelRange: {"range": 0},
    },
}
