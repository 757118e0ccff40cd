"""What the Demo protocol with every spec feature spec says, for the simulated device (sim.py, docs/conformance.md
section 9): per command layout the parameters each function sends (the key of a setting) and its
enum parameters; per data layout the units of its values; the commands that configure streaming
(generator/targets/python/backend.py STREAMING), base rates in Hz and the NACK code of each refusal.
"""

from __future__ import annotations

from typing import Any, Dict, Tuple

from . import commands, data, receiver_1, receiver_2, shared
from ._identity import IDENTITY as IDENTITY  # re-exported (sim, session)
from ._identity import IDENTITY_REPORTS as IDENTITY_REPORTS

# NACK code per refusal: an unknown descriptor, an unknown descriptor set, a bad parameter value,
# a command the simulator failed to carry out.
NACK: Dict[str, int] = {
    "unknown_descriptor": 1,
    "unknown_set": 1,
    "invalid_parameter": 1,
    "failed": 1,
}

# class -> ({function value: parameters it sends, without the selector}, enum parameters)
COMMANDS: Dict[Any, Tuple[Dict[int, Tuple[str, ...]], Tuple[str, ...]]] = {
    commands.Ping: ({}, ()),
    commands.Configure: ({1: ("instance",), 2: ("instance",), 3: ("instance",)}, ("mode",)),
    commands.PerDevice_dev_a: ({}, ()),
    commands.PerDevice_dev_b: ({}, ()),
}

# class -> {function value: parameters the device ignores for it}: not sent for that function, or
# stated ignored by the manual (the spec's `ignored`); neither checked nor taken into a reply
IGNORED: Dict[Any, Dict[int, Tuple[str, ...]]] = {
    commands.Configure: {2: ("mode", "params", "suppress_ack"), 3: ("mode", "params", "suppress_ack")},
}

# class -> ((parameter, units, fixed count or None), ...) of its plain values
DATA: Dict[Any, Tuple[Tuple[str, Any, Any], ...]] = {
    data.Sample: (("quat", None, 4), ("big", None, None), ("small", None, None), ("f", None, None)),
    receiver_1.LlhPosition: (("latitude", "deg", None), ("longitude", "deg", None), ("valid_flags", None, None)),
    receiver_2.LlhPosition: (("latitude", "deg", None), ("longitude", "deg", None), ("valid_flags", None, None)),
    shared.Timestamp: (("nanoseconds", None, None),),
}

# The simulated world (sim/world.py; the spec's simulation.world): class -> ((parameter, world quantity), ...)
WORLD: Dict[Any, Tuple[Tuple[str, str], ...]] = {}

# The navigation filter of each device (backend.py FILTER): states, aiding, fix type members
FILTER: Dict[str, Dict[str, Any]] = {}

# What commands do to the world (the spec's simulation.actions): class -> (action, arguments...)
ACTIONS: Dict[Any, Tuple[Any, ...]] = {}

# Message format commands: class -> (set, list parameter, descriptor member or None, decimation member or None)
FORMATS: Dict[Any, Any] = {}

# Stream control: class -> (set, enable parameter)
ENABLES: Dict[Any, Any] = {}

# Base rate queries: class -> set
RATES: Dict[Any, Any] = {}

# Poll commands: class -> (set, descriptor list parameter)
POLLS: Dict[Any, Any] = {}

# One decimation for every streamed field (when the format list has none): class -> parameter
DECIMATION: Dict[Any, str] = {}

BASE_RATES: Dict[str, Dict[int, int]] = {}

# Commands that change the port's baud rate (write): class -> rate parameter
BAUD: Dict[Any, str] = {}

# Data sets the stream control of a model cannot address: they stream whenever their format is set
UNADDRESSED: Dict[str, Any] = {}

# Commands whose save, load and default apply to every setting at once
ALL_SETTINGS: Tuple[Any, ...] = ()

DEVICE_TITLES: Dict[str, str] = {"dev_a": "Device A", "dev_b": "Device B"}

# How each device's external (GPS) time is synchronized (spec time.sync; sim/clocks.py,
# device/timesync.py): the update command and window, the PPS kinds, the PPS source setting, the
# sync status field, the external time fields with their flag masks, the correlation flags
TIME_SYNC: Dict[str, Dict[str, Any]] = {}

# The replies that list what the device supports (spec simulation descriptor_lists): reply class ->
# (which reply: 0 the first, 1 the extended; its capacity; the list attribute), and the item class
# (None: a u16, (set << 8) | descriptor); which capabilities lists they hold, in that order
DESCRIPTOR_LISTS: Dict[Any, Tuple[int, int, str]] = {}
DESCRIPTOR_ITEMS: Dict[Any, Any] = {}
DESCRIPTOR_CONTENTS: Tuple[str, ...] = ()

# Identity (spec simulation identity): the reports of each reply class and per device the value of
# every item (`_identity`, a module of its own for the log tools); per item its kind and limit (the
# largest integer, or the most characters)
IDENTITY_ITEMS: Dict[str, Tuple[str, int]] = {}

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
FACTORY: Dict[str, Dict[Any, Dict[str, Any]]] = {}
