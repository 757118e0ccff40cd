"""Export table of the Memsense MS-CIP, generated from the IR (generator/columns.py).

What the `export`, `info` and `plot` commands (`mscipcodec.logs`) and `Table.arrays` need to
know about the data fields, taken from the spec rather than written by hand:

- `COLUMNS[(set, descriptor, device)]`: one entry per value a row of that field layout holds:
  (column name, path to the value in the decoded dataclass (attributes and indices), units or
  None, kind ("float32", "float64", "int", "bool", "enum", "bits", "json"), enum type name or None);
- `SHAPES[(set, descriptor, device)]`: fixed-array parameters with a spec shape (vector 3,
  quaternion 4, matrix 3x3), by attribute;
- `ENUMS[type name]`: value -> name of every enum a column uses;
- `TIMES`: (set, descriptor, attribute, counts per second) of the shared fields giving a
  packet its time (value / counts seconds), in order of preference;
- `TITLES[(set, descriptor, device)]`: the field's title;
- `FRAMES[(set, descriptor, device)]`: per column, the coordinate frame the spec states for its
  parameter (`sensor`, `vehicle`, `sensor_or_vehicle`, `ned`, `ecef`, `wgs84`, or `device: frame`
  per device joined by `; `), None where it states none; layouts without any frame are left out;
- the time model's facts (the spec's `time` section; `mscipcodec.logs.timebase`): `GPS_TIMES`
  (set, descriptor, time-of-week attribute, week attribute, valid-flags attribute, bits that must
  be set, bits that must be clear) of the fields carrying a GPS time, in order of preference (set
  of the protocol's shared data placeholder: that field in any data set); `DEVICE_CLOCKS` (set, descriptor,
  attribute, counts per second) of the device clock; `LEAP_SECONDS` (set, descriptor, attribute,
  valid-flags attribute, bits that must be set) of the GPS - UTC leap second reports;
  `GPS_EPOCH_UNIX_S` and `LEAP_TABLE`, the GPS time scale (spec/common/gps_time.yaml).
"""

from __future__ import annotations

from typing import Dict, Optional, Tuple, Union

Key = Tuple[int, int, Optional[str]]
Path = Tuple[Union[str, int], ...]
ColumnSpec = Tuple[str, Path, Optional[str], str, Optional[str]]

COLUMNS: Dict[Key, Tuple[ColumnSpec, ...]] = {
    (0xA2, 0x81, None): (
        ("scaled_accel.accel.x", ("accel", 0), "g", "float32", None),
        ("scaled_accel.accel.y", ("accel", 1), "g", "float32", None),
        ("scaled_accel.accel.z", ("accel", 2), "g", "float32", None),
    ),
    (0xA2, 0x82, None): (
        ("scaled_gyro.gyro.x", ("gyro", 0), "deg/s", "float32", None),
        ("scaled_gyro.gyro.y", ("gyro", 1), "deg/s", "float32", None),
        ("scaled_gyro.gyro.z", ("gyro", 2), "deg/s", "float32", None),
    ),
    (0xA2, 0x83, None): (
        ("scaled_mag.mag.x", ("mag", 0), "gauss", "float32", None),
        ("scaled_mag.mag.y", ("mag", 1), "gauss", "float32", None),
        ("scaled_mag.mag.z", ("mag", 2), "gauss", "float32", None),
    ),
    (0xA2, 0x84, None): (
        ("delta_theta.x", ("delta_theta", 0), "rad", "float32", None),
        ("delta_theta.y", ("delta_theta", 1), "rad", "float32", None),
        ("delta_theta.z", ("delta_theta", 2), "rad", "float32", None),
    ),
    (0xA2, 0x85, None): (
        ("delta_velocity.x", ("delta_velocity", 0), "m/s", "float32", None),
        ("delta_velocity.y", ("delta_velocity", 1), "m/s", "float32", None),
        ("delta_velocity.z", ("delta_velocity", 2), "m/s", "float32", None),
    ),
    (0xA2, 0x86, None): (("scaled_pressure.pressure", ("pressure",), "mbar", "float32", None),),
    (0xA2, 0x87, None): (("scaled_temperature.temperature", ("temperature",), "degC", "float32", None),),
    (0xA2, 0x88, None): (
        ("gps_correlated_time.seconds", ("seconds",), "s", "float64", None),
        ("gps_correlated_time.week", ("week",), "weeks", "int", None),
        ("gps_correlated_time.flags", ("flags",), None, "bits", None),
    ),
    (0xA2, 0x89, None): (
        ("scaled_aux_accel.accel.x", ("accel", 0), "g", "float32", None),
        ("scaled_aux_accel.accel.y", ("accel", 1), "g", "float32", None),
        ("scaled_aux_accel.accel.z", ("accel", 2), "g", "float32", None),
    ),
}

SHAPES: Dict[Key, Dict[str, Tuple[int, ...]]] = {
    (0xA2, 0x81, None): {"accel": (3,)},
    (0xA2, 0x82, None): {"gyro": (3,)},
    (0xA2, 0x83, None): {"mag": (3,)},
    (0xA2, 0x84, None): {"delta_theta": (3,)},
    (0xA2, 0x85, None): {"delta_velocity": (3,)},
    (0xA2, 0x89, None): {"accel": (3,)},
}

TITLES: Dict[Key, str] = {
    (0xA2, 0x81, None): "Scaled acceleration vector",
    (0xA2, 0x82, None): "Scaled angular rate vector",
    (0xA2, 0x83, None): "Scaled magnetic field vector",
    (0xA2, 0x84, None): "Scaled delta theta vector",
    (0xA2, 0x85, None): "Scaled delta velocity vector",
    (0xA2, 0x86, None): "Scaled pressure",
    (0xA2, 0x87, None): "Scaled temperature",
    (0xA2, 0x88, None): "GPS correlated time",
    (0xA2, 0x89, None): "Scaled aux accel vector",
}

DESCRIPTIONS: Dict[Key, Tuple[str, ...]] = {
    (0xA2, 0x81, None): ("Acceleration [x, y, z].", "Acceleration [x, y, z].", "Acceleration [x, y, z]."),
    (0xA2, 0x82, None): ("Angular rate [x, y, z].", "Angular rate [x, y, z].", "Angular rate [x, y, z]."),
    (0xA2, 0x83, None): ("Magnetic field [x, y, z].", "Magnetic field [x, y, z].", "Magnetic field [x, y, z]."),
    (0xA2, 0x84, None): ("Change in angle [x, y, z].", "Change in angle [x, y, z].", "Change in angle [x, y, z]."),
    (0xA2, 0x85, None): (
        "Change in velocity [x, y, z].",
        "Change in velocity [x, y, z].",
        "Change in velocity [x, y, z].",
    ),
    (0xA2, 0x86, None): ("Pressure.",),
    (0xA2, 0x87, None): ("Temperature.",),
    (0xA2, 0x88, None): ("GPS seconds of the week.", "GPS week number.", "GPS correlated time flags."),
    (0xA2, 0x89, None): (
        "Auxiliary acceleration [x, y, z].",
        "Auxiliary acceleration [x, y, z].",
        "Auxiliary acceleration [x, y, z].",
    ),
}

FRAMES: Dict[Key, Tuple[Optional[str], ...]] = {}

ENUMS: Dict[str, Dict[int, str]] = {}

TIMES: Tuple[Tuple[int, int, str, int], ...] = ()

GPS_TIMES: Tuple[Tuple[int, int, str, str, str, int, int], ...] = (
    (0xA2, 0x88, "seconds", "week", "flags", 0x0000, 0x0004),
)

DEVICE_CLOCKS: Tuple[Tuple[int, int, str, int], ...] = ()

LEAP_SECONDS: Tuple[Tuple[int, int, str, str, int], ...] = ()

# The fields carrying the device's external time on the GPS time scale (the time model's second
# choice, after a valid GPS time): (set, descriptor, count attribute, counts per second,
# valid-flags attribute, bits that must be set).
EXTERNAL_TIMES: Tuple[Tuple[int, int, str, int, str, int], ...] = ()

# The fields saying whether a PPS is present (`info`'s synchronization section): (set,
# descriptor, attribute, mask): mask 0: a bool attribute, true while PPS sync is valid; else the
# flag bits set while a PPS is present.
SYNC_PPS: Tuple[Tuple[int, int, str, int], ...] = ()

# The host clock model's parameters (session/clock.py, docs/time.md; the spec's time.clock_model):
# device time per bucket (ns), closed buckets kept, closed buckets before an estimate, and the
# step disagreement (ns) above which consecutive packets restart the model.
CLOCK_BUCKET_NS = 1000000000
CLOCK_BUCKETS = 2
CLOCK_MIN_BUCKETS = 3
CLOCK_RESTART_NS = 1000000000

# The GPS time scale (spec/common/gps_time.yaml, the same for every protocol; logs/timebase.py,
# sim/world.py and device/timesync.py read it): the GPS epoch 1980-01-06T00:00:00Z in Unix seconds,
# and GPS - UTC in seconds from each UTC instant on (the Unix time of the first UTC second with the
# new offset; IERS Bulletin C), 0 before the first.
GPS_EPOCH_UNIX_S = 315964800
LEAP_TABLE: Tuple[Tuple[int, int], ...] = (
    (362793600, 1),
    (394329600, 2),
    (425865600, 3),
    (489024000, 4),
    (567993600, 5),
    (631152000, 6),
    (662688000, 7),
    (709948800, 8),
    (741484800, 9),
    (773020800, 10),
    (820454400, 11),
    (867715200, 12),
    (915148800, 13),
    (1136073600, 14),
    (1230768000, 15),
    (1341100800, 16),
    (1435708800, 17),
    (1483228800, 18),
)

# Per device, the field carrying its own reference time (the host clock model, clock.py;
# docs/time.md): (device, set, descriptor, kind "count" or "gps", count parameter, its units per
# second, tow parameter, week parameter, monotonic).
REFERENCE_TIMES: Tuple[Tuple[str, int, int, str, str, int, str, str, bool], ...] = ()
