"""Simulator facts of the test protocol (cf. templates/python/package/_sim.py.j2): no setting
commands; set_mode's mode is an enum; the sensor set streams at 100 Hz on alpha."""

from __future__ import annotations

from typing import Any, Dict, Tuple

from . import command, sensor, shared

NACK: Dict[str, int] = {"unknown_descriptor": 1, "unknown_set": 1, "invalid_parameter": 1, "failed": 1}

COMMANDS: Dict[Any, Tuple[Dict[int, Tuple[str, ...]], Tuple[str, ...]]] = {
    command.Ping: ({}, ()),
    command.SetMode: ({}, ("mode",)),
}

DATA: Dict[Any, Tuple[Tuple[str, Any, Any], ...]] = {
    sensor.Vector: (("xyz", "g", 3), ("time", "s", None), ("ticks", "ns", None)),
    shared.Timestamp: (("ticks", "ns", None),),
}

FORMATS: Dict[Any, Any] = {}
ENABLES: Dict[Any, Any] = {}
RATES: Dict[Any, Any] = {}
POLLS: Dict[Any, Any] = {}
DECIMATION: Dict[Any, str] = {}
BASE_RATES: Dict[str, Dict[int, int]] = {"alpha": {0x80: 100}}
ALL_SETTINGS: Tuple[Any, ...] = ()
DEVICE_TITLES: Dict[str, str] = {"alpha": "Alpha", "beta": "Beta"}
FACTORY: Dict[str, Dict[Any, Dict[str, Any]]] = {}
# The world (sim_world.py): the vector shows the specific force, its time the GPS time of week
WORLD: Dict[Any, Tuple[Tuple[str, str], ...]] = {sensor.Vector: (("xyz", "specific_force"), ("time", "gps_tow"))}
FILTER: Dict[str, Dict[str, Any]] = {}
ACTIONS: Dict[Any, Tuple[Any, ...]] = {}
UNADDRESSED: Dict[str, Any] = {}
BAUD: Dict[Any, str] = {}
# Descriptor lists and identity (cf. the spec's simulation descriptor_lists and identity): none
DESCRIPTOR_LISTS: Dict[Any, Tuple[int, int, str]] = {}
DESCRIPTOR_ITEMS: Dict[Any, Any] = {}
DESCRIPTOR_CONTENTS: Tuple[str, ...] = ()
IDENTITY_REPORTS: Dict[Any, Tuple[Tuple[Any, ...], ...]] = {}
IDENTITY: Dict[str, Dict[str, Any]] = {}
IDENTITY_ITEMS: Dict[str, Tuple[str, int]] = {}
