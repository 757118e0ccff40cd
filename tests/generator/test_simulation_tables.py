"""The simulated device's tables with the spec's names resolved (generator/simulation.py): IR
snippets and the real IR. Expected values come from the rule each test states or from the
manuals (cited by file and line), never from the module itself."""

from __future__ import annotations

import json
from pathlib import Path

from generator import simulation

ROOT = Path(__file__).resolve().parents[2]
IR = json.loads((ROOT / "generated" / "ir.json").read_text(encoding="utf-8"))
MIP = next(p for p in IR["protocols"] if p["name"] == "mip")

CODES = {"kind": "enum", "name": "Code", "values": [{"name": "ok", "value": 0}, {"name": "bad", "value": 9}]}
FLAGS = {"kind": "bitfield", "name": "Flags", "members": [{"name": "low", "mask": 1}, {"name": "high", "mask": 0x40}]}
SOURCES = {"kind": "enum", "name": "Source", "values": [{"name": "none", "value": 0}, {"name": "gnss", "value": 2}]}


def _proto(simulation_=None, session=None, types=(), selector=None):
    return {
        "types": [CODES, FLAGS, SOURCES, *types],
        "session": session,
        "simulation": simulation_,
        "function_selector": {"enum": selector} if selector else None,
    }


def _q(name, kind="primitive", tname="u8", optional=False, functions=None, default=None, count=None):
    return {
        "name": name,
        "type": {"kind": kind, "name": tname},
        "optional": optional,
        "functions": functions,
        "default": default,
        "count": count,
    }


def test_nack_codes_resolve_the_named_members_and_fall_back_to_the_first_refusal():
    # Rule: a role the section names gets that member's value; any other role the first code
    # that is not OK; without a session rule every role gets 1.
    session = {"code_enum": "Code", "ok": 0}
    got = simulation.nack_codes(_proto({"nack": {"failed": "ok"}}, session))
    assert got == {"unknown_descriptor": 9, "unknown_set": 9, "invalid_parameter": 9, "failed": 0}
    assert set(simulation.nack_codes(_proto()).values()) == {1}


def test_nack_codes_of_mip_are_the_manuals_codes():
    # 3dm-cv7-ins-docs.txt:8876-8881: 0x01 unknown command, 0x03 invalid parameter, 0x04 command
    # failed, 0x06 unknown descriptor set.
    assert simulation.nack_codes(MIP) == {
        "unknown_descriptor": 0x01,
        "unknown_set": 0x06,
        "invalid_parameter": 0x03,
        "failed": 0x04,
    }


def test_filters_resolve_members_to_values_and_flag_roles_to_masks():
    entry = {
        "device": "dev",
        "aiding": ["gnss"],
        "states": {"members": ["init", "run"]},
        "fix": {"fix": "fix_3d", "none": "no_fix"},
        "flags": {"type": "Flags", "members": {"warning": "high"}},
        "internal": {
            "command": "aid",
            "param": "source",
            "enable": "class",
            "enum": "Source",
            "members": {"gnss": "g"},
        },
    }
    got = simulation.filters(_proto({"filters": [entry]}), lambda n: n + "_")
    assert got["dev"]["flags"] == {"warning": 0x40}
    assert got["dev"]["internal"] == {
        "command": "aid",
        "param": "source_",
        "enable": "class_",
        "all": None,
        "sources": {2: "g"},
    }
    assert got["dev"]["states"] == ["init", "run"] and got["dev"]["fix"] == ["fix_3d", "no_fix"]


def test_command_facts_per_function_enums_and_factory_defaults():
    # Rule: a function's request carries the parameters sent for it that are not optional (the
    # selector left out); a default holds on the devices it names, each device its own table.
    selector = {
        "kind": "enum",
        "name": "Function",
        "values": [{"name": "write", "value": 1}, {"name": "read", "value": 2}],
    }
    v = {
        "functions": ["write", "read"],
        "devices": ["a", "b"],
        "params": [
            _q("function", "enum", "Function"),
            _q("mode", "enum", "Source", functions=["write"], default={"value": 2, "devices": ["b"]}),
            _q("extra", optional=True, functions=["write"]),
            _q("index"),
        ],
    }
    got = simulation.command_facts(_proto(types=[selector], selector="Function"), v, str.upper)
    assert got["sends"] == {1: ("MODE", "INDEX"), 2: ("INDEX",)}
    assert got["enums"] == ("MODE",)
    assert got["factory"] == {"b": {"MODE": 2}}


def test_nmea_of_mip_is_the_manuals_rate_limits_and_sources():
    # 3dm-cv7-ins-docs.txt:1062: at most 10 Hz per sentence from the IMU and filter sources, 2 Hz
    # from a GNSS source, else NACK'd (the simulator's code: 0x03 Invalid Parameter, line 8878);
    # line 1056: IMU, Filter, GNSS 1 or GNSS 2 (0x80, 0x82, 0x91, 0x92); line 1013: PMSRA from the
    # filter, PMSRR from the IMU, GSV and the proprietary sentences without a talker ID to choose.
    got = simulation.nmea(MIP, str)
    assert got["origins"] == {"imu": ((0x80,), 10), "filter": ((0x82,), 10), "gnss": ((0x91, 0x92), 2)}
    assert got["nack"] == 0x03
    by_name = {name: (talker, sources) for name, talker, sources in got["sentences"].values()}
    assert set(by_name) == {"GGA", "GLL", "GSV", "RMC", "VTG", "HDT", "ZDA", "GST", "PMSRA", "PMSRR"}
    assert by_name["PMSRA"] == (False, ("filter",)) and by_name["PMSRR"] == (False, ("imu",))
    assert by_name["GSV"] == (False, ("gnss",)) and by_name["ZDA"] == (True, ("gnss",))
    assert sorted(got["talkers"].values()) == ["GA", "GL", "GN", "GP"]
    # lines 1084-1092 and 1102: the input sentences, into GNSS External (0x94), two updates
    assert got["input"] == {"set": 0x94, "sentences": ("RMC", "ZDA", "HDT", "GGA", "VTG", "GLL", "GSV"), "updates": 2}
    assert simulation.nmea({"simulation": None}, str) == {}
