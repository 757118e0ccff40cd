"""generator/device_tables.py and settings_rows.settings_schema: the language-neutral tables of the
device command lines (docs/configure-a-device.md), checked against the manuals."""

from __future__ import annotations

import json

import jsonschema

from generator.device_tables import device_tables
from generator.settings_rows import setting_rows, settings_schema
from generator.spec import load_spec


def _mip() -> dict:
    return next(p for p in load_spec()["protocols"] if p["name"] == "mip")


def test_settings_per_model():
    t = device_tables(_mip())
    gx5 = {s["name"] for s in t["dev_settings"]["gx5_45"]}
    cv7 = {s["name"] for s in t["dev_settings"]["cv7_ins"]}
    # Coning and sculling (0x0C,0x3E) is a GX5-45 setting (3dm-gx5-45-dcp.txt, 4.2.18); the sensor
    # to vehicle Euler angles (0x0C,0x31) a CV7 one (3dm-cv7-ins-docs.txt); both have a read.
    assert "coning_sculling_enable" in gx5 and "coning_sculling_enable" not in cv7
    assert "sensor_to_vehicle_euler" in cv7 and "sensor_to_vehicle_euler" not in gx5
    # The GPS time update is readable but not a setting (the spec's settings: not_settings).
    assert "gps_time_update" not in gx5 | cv7


def test_link_and_identity_facts():
    t = device_tables(_mip())
    # The UART bandwidth calculation: GX5-45 dcp line 536, CV7 line 4099.
    assert "3dm-gx5-45-dcp.txt line 536" in t["dev_bandwidth_sources"]
    assert "3dm-cv7-ins-docs.txt line 4099" in t["dev_bandwidth_sources"]
    # Device information (0x01,0x03) reports the identity (3dm-gx5-45-dcp.txt line 771).
    assert t["dev_identity"] == (0x01, 0x03)
    # The GX5-45 IMU base rate, 500 Hz (3dm-gx5-45-dcp.txt line 375; Get IMU Data Base Rate, line 946).
    assert (0x80, 500) in t["dev_base_rates"]["gx5_45"]


def test_the_schema_accepts_a_dump_and_refuses_a_wrong_value():
    proto = _mip()
    rows, _ = setting_rows(proto, proto["sets"])
    schema = json.loads(settings_schema(proto, "mipcodec", rows))
    jsonschema.Draft202012Validator.check_schema(schema)
    good = {"device": "gx5_45", "coning_sculling_enable": {"enable": True}}
    jsonschema.validate(good, schema)
    bad = {"coning_sculling_enable": {"enable": 3}}
    assert list(jsonschema.Draft202012Validator(schema).iter_errors(bad))
    assert list(jsonschema.Draft202012Validator(schema).iter_errors({"no_such_setting": {}}))
