"""Export table of the Demo protocol with every spec feature, generated from the IR (generator/columns.py).

What the `export`, `info` and `plot` commands (`democodec.logs`) and `Table.arrays` need to
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
- the time model's facts (the spec's `time` section; `democodec.logs.timebase`): `GPS_TIMES`
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
    (0x90, 0x01, None): (
        ("sample.quat.w", ("quat", 0), None, "float32", None),
        ("sample.quat.x", ("quat", 1), None, "float32", None),
        ("sample.quat.y", ("quat", 2), None, "float32", None),
        ("sample.quat.z", ("quat", 3), None, "float32", None),
        ("sample.big", ("big",), None, "int", None),
        ("sample.small", ("small",), None, "int", None),
        ("sample.f", ("f",), None, "float32", None),
    ),
    (0x91, 0x03, None): (
        ("llh_position.latitude", ("latitude",), "deg", "float64", None),
        ("llh_position.longitude", ("longitude",), "deg", "float64", None),
        ("llh_position.valid_flags", ("valid_flags",), None, "int", None),
    ),
    (0x92, 0x03, None): (
        ("llh_position.latitude", ("latitude",), "deg", "float64", None),
        ("llh_position.longitude", ("longitude",), "deg", "float64", None),
        ("llh_position.valid_flags", ("valid_flags",), None, "int", None),
    ),
    (0xFF, 0xD3, None): (("timestamp.nanoseconds", ("nanoseconds",), None, "int", None),),
}

SHAPES: Dict[Key, Dict[str, Tuple[int, ...]]] = {
    (0x90, 0x01, None): {"quat": (4,)},
}

TITLES: Dict[Key, str] = {
    (0x90, 0x01, None): "Sample",
    (0x91, 0x03, None): "LLH position",
    (0x92, 0x03, None): "LLH position",
    (0xFF, 0xD3, None): "Timestamp",
}

DESCRIPTIONS: Dict[Key, Tuple[str, ...]] = {
    (0x90, 0x01, None): ("", "", "", "", "", "", ""),
    (0x91, 0x03, None): ("", "", ""),
    (0x92, 0x03, None): ("", "", ""),
    (0xFF, 0xD3, None): ("",),
}

FRAMES: Dict[Key, Tuple[Optional[str], ...]] = {}

ENUMS: Dict[str, Dict[int, str]] = {}

TIMES: Tuple[Tuple[int, int, str, int], ...] = ()

GPS_TIMES: Tuple[Tuple[int, int, str, str, str, int, int], ...] = ()

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
