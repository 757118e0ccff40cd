"""The simulated devices against facts the manuals state in prose (issue 51), in process.

1. Ignored parameters: every parameter the spec records as `ignored` for some functions (the
   manual: "For all functions except 0x01 ..., the new ... value is ignored") is neither required
   nor checked nor echoed for those functions: each read, save, load and default is answered the
   same without the ignored bytes, with zeros in them and with 0xFF in them (an enum value, a
   bool and a baud rate no device has), and a read after it reports the same setting.
2. Plausible values: no read of a simulated setting reports a placeholder the device cannot hold
   (an enum value outside its enum, a baud rate outside the port's rates, a noise 1-sigma that is
   not greater than 0, a soft iron matrix of zeros, a sensor range selector the range table does
   not list).
3. Identity: the model number the simulated Device Information reports selects the device's own
   Device Status structure.
"""

from __future__ import annotations

import importlib
from enum import Enum

import pytest

from generator.spec import load_spec
from tests.helpers.generated import python_package

IR = load_spec()
MIP = next(p for p in IR["protocols"] if p["name"] == "mip")
pkg = python_package("mipcodec")
sim_mod = importlib.import_module("mipcodec.sim")
importlib.import_module("mipcodec.codec.packets")
FUNCTIONS = {v["name"]: v["value"] for t in MIP["types"] if t["name"] == "FunctionSelector" for v in t["values"]}


def raw_packet(set_id: int, descriptor: int, payload: bytes) -> bytes:
    """A MIP packet of one field (framing from the manual: 0x75 0x65, set, length, field, Fletcher)."""
    field = bytes([len(payload) + 2, descriptor]) + payload
    packet = bytes([0x75, 0x65, set_id, len(field)]) + field
    a = b = 0
    for x in packet:
        a = (a + x) & 0xFF
        b = (b + a) & 0xFF
    return packet + bytes([a, b])


def exchange(sim, set_id: int, descriptor: int, payload: bytes) -> list:
    """(ack code, reply values) of one command fed to the simulator."""
    out = []
    for _when, data in sim.feed(raw_packet(set_id, descriptor, payload), 0.0):
        packet = pkg.codec.packets.decode_packet(data, device=sim.device)
        if packet.set == set_id:
            fields = [f.value for f in packet.fields]
            out.append((int(getattr(fields[0], sim_mod._meta.ACK_CODE)), [repr(f) for f in fields[1:]]))
    return out


def ignored_cases() -> list[tuple]:
    """(set id, field, variant, device, parameter) of every parameter stated ignored."""
    cases = []
    for s in MIP["sets"]:
        for f in s["fields"]:
            for v in f["variants"]:
                for q in v["params"]:
                    if q.get("ignored"):
                        for dev in v["devices"]:
                            cases.append((s["id"], f, v, dev, q))
    return cases


CASES = ignored_cases()


def _class_of(set_id: int, descriptor: int, device: str):
    classes = pkg.registry.FIELDS[(set_id, descriptor)]
    return next(c for c in classes if c.DEVICE in (None, device))


def _key_values(v: dict, fn: str) -> dict:
    """Valid values of the parameters a function sends (the setting's key): an enum's first member,
    an integer 1."""
    types = {t["name"]: t for t in MIP["types"]}
    out = {}
    for q in v["params"]:
        if q["type"].get("name") == "FunctionSelector" or q.get("optional") or fn not in (q["functions"] or []):
            continue
        t = types.get(q["type"].get("name", ""))
        out[q["name"]] = t["values"][0]["value"] if t and t["kind"] == "enum" else 1
    return out


def test_the_spec_records_the_ignored_parameters_the_manuals_state() -> None:
    """The commands whose manual says a value is ignored for all functions but write (issue 51):
    the GX5-45's Communication Mode among them (3dm-gx5-45-dcp.txt:2005)."""
    named = {(f["name"], q["name"]) for _s, f, _v, _d, q in CASES}
    assert ("communication_mode", "mode") in named
    assert ("data_stream_control", "enable") in named
    assert ("uart_baudrate", "baud") in named
    for _s, _f, _v, _d, q in CASES:
        assert set(q["ignored"]["functions"]) == {"read", "save", "load", "default"}, q["name"]


@pytest.mark.parametrize(
    "set_id,field,variant,device,param",
    CASES,
    ids=[f"{c[1]['name']}-{c[3]}-{c[4]['name']}" for c in CASES],
)
def test_ignored_parameters_are_neither_required_nor_checked(set_id, field, variant, device, param) -> None:
    cls = _class_of(set_id, field["id"], device)
    read = FUNCTIONS["read"]
    for fn in param["ignored"]["functions"]:
        keys = _key_values(variant, fn)
        bare = cls(function=FUNCTIONS[fn], **keys).encode()
        filled = dict(keys)
        for q in variant["params"]:  # every parameter the write sends, ignored ones included
            if q["name"] not in filled and "write" in (q["functions"] or []):
                filled[q["name"]] = _sample(q)
        full = cls(function=FUNCTIONS[fn], **filled).encode()
        assert full.startswith(bare) and len(full) > len(bare), (fn, bare.hex(), full.hex())
        extra = len(full) - len(bare)
        answers = []
        for payload in (bare, bare + bytes(extra), bare + b"\xff" * extra):
            sim = sim_mod.Simulator(device, scenario="static")
            first = exchange(sim, set_id, field["id"], payload)
            after = exchange(sim, set_id, field["id"], cls(function=read, **_key_values(variant, "read")).encode())
            assert first and first[0][0] == sim_mod._meta.ACK_OK, (fn, payload.hex(), first)
            answers.append((first, after))
        assert answers[1] == answers[0], (fn, "zeros in the ignored bytes changed the answer")
        assert answers[2] == answers[0], (fn, "0xFF in the ignored bytes changed the answer")


def _sample(q: dict):
    """A value of the parameter's type for the encoder (only its size matters here)."""
    t = next((t for t in MIP["types"] if t["name"] == q["type"].get("name")), None)
    if t is not None and t["kind"] == "enum":
        return t["values"][0]["value"]
    if q["count"] is not None:
        return [0.5] * q["count"]["value"]
    if q["type"].get("name") == "bool":
        return True
    return 0.5 if q["type"].get("name") in ("float", "double") else 1


def test_a_read_does_not_echo_an_ignored_value() -> None:
    """GX5-45 Communication Mode read with the mode byte 0, as vendor clients send it: ACK and the
    mode the device holds (Standard, its factory value, 3dm-gx5-45-dcp.txt:2005), not the byte."""
    sim = sim_mod.Simulator("gx5_45", scenario="static")
    answer = exchange(sim, 0x7F, 0x10, bytes([FUNCTIONS["read"], 0x00]))
    assert answer[0][0] == sim_mod._meta.ACK_OK
    assert "STANDARD" in answer[0][1][0], answer


def _holdable(value, q: dict, types: dict, rates: set) -> bool:
    """Whether a reported value is one the device can hold: an enum value is a member of its enum,
    a baud rate (bit/s) one of the port's rates."""
    t = types.get(q["type"].get("name", ""))
    items = value if isinstance(value, list) else [value]
    if t is not None and t["kind"] == "enum":
        return all(isinstance(x, Enum) for x in items)
    if q.get("units") == "bit/s" and rates:
        return all(int(x) in rates for x in items)
    if q["description"].startswith("Soft iron matrix"):  # multiplies the reading (3dm-cv7-ins-docs.txt:7397)
        return any(float(x) != 0.0 for x in items)  # all zeros would erase the magnetic field
    if "noise 1-sigma" in q["description"]:  # "must be greater than 0.0" (3dm-gx5-45-dcp.txt:1792, cv7:8339)
        return all(float(x) > 0.0 for x in items)
    return True


@pytest.mark.parametrize("device", [d["id"] for d in MIP["devices"]])
def test_no_read_reports_a_value_the_device_cannot_hold(device: str) -> None:
    """Every setting read on a fresh simulated device (its key: an enum's first member, else 1):
    no placeholder the device cannot hold; the CV7's Comm Port Speed read of port 1 reported 0 baud
    (issue 51)."""
    types = {t["name"]: t for t in MIP["types"]}
    rates = {e["device"]: set(e["rates"]) for e in MIP["link"]["baud_rates"]}.get(device, set())
    read = FUNCTIONS["read"]
    checked = 0
    for s in MIP["sets"]:
        replies = {f["id"]: f for f in s["fields"]}
        for f in s["fields"]:
            for v in f["variants"]:
                if f["role"] != "command" or device not in v["devices"] or "read" not in (v["functions"] or []):
                    continue
                cls = _class_of(s["id"], f["id"], device)
                sim = sim_mod.Simulator(device, scenario="static")
                payload = cls(function=read, **_key_values(v, "read")).encode()
                for _when, data in sim.feed(raw_packet(s["id"], f["id"], payload), 0.0):
                    for entry in pkg.codec.packets.decode_packet(data, device=device).fields[1:]:
                        value = entry.value
                        rf = replies[entry.descriptor]
                        rv = next(x for x in rf["variants"] if x["device"] in (None, device))
                        for q in rv["params"]:
                            got = getattr(value, q["name"], None)
                            assert _holdable(got, q, types, rates), (f["name"], q["name"], got)
                        checked += 1
    assert checked > 10


def test_the_model_number_read_selects_the_device_status_structure() -> None:
    """The GX5-45's Device Status section: its model number "is always = 6251 (0x186B)"
    (3dm-gx5-45-dcp.txt:1341, 1349, 1386). The model number the simulated Device Information
    reports, passed to Device Status as a client does, is that number, and Device Status answers
    with the GX5-45's structure (docs/errata.md: the example reply at line 786 says 6232)."""
    sim = sim_mod.Simulator("gx5_45", scenario="static")
    info = [v for v in _values(sim, pkg.base.GetDeviceInfo()) if isinstance(v, pkg.base.DeviceInfo)]
    number = int(info[0].info.model_number.strip().split(b"-")[0])
    assert number == 6251
    selector = pkg.types.DeviceStatusSelector.BASIC
    status = _values(sim, pkg.threedm.DeviceStatus(model_number=number, status_selector=selector))
    reply = next(v for v in status if isinstance(v, pkg.threedm.DeviceStatusResponse))
    assert reply.model_number == 6251 and reply.status_selector == selector


def _values(sim, command) -> list:
    """The reply values (after the ack) of one command fed to the simulator, the ack checked OK."""
    out = []
    for _when, data in sim.feed(raw_packet(command.SET, command.DESCRIPTOR, command.encode()), 0.0):
        fields = [f.value for f in pkg.codec.packets.decode_packet(data, device=sim.device).fields]
        assert int(getattr(fields[0], sim_mod._meta.ACK_CODE)) == sim_mod._meta.ACK_OK, fields
        out.extend(fields[1:])
    return out


def test_the_initial_state_follows_the_defaults_stated_in_sentences() -> None:
    """Defaults the manuals state in sentences, read from fresh simulated devices: the GX5-45's
    "Factory default setting is GPS and GLONASS enabled with min/max of GPS 8/16, GLONASS 8/14,
    SBAS 1/3, QZSS 0/3" (3dm-gx5-45-dcp.txt:1106), the CV7's complementary filter "The default
    time constant is 10 seconds" (3dm-cv7-ins-docs.txt:7594) and its axes "In its default state
    ... aligned with the vehicle frame" (3dm-cv7-ins-docs.txt:154): a unit quaternion."""
    read = FUNCTIONS["read"]
    gx5 = sim_mod.Simulator("gx5_45", scenario="static")
    (reply,) = _values(gx5, pkg.threedm.GnssConstellationSettings(function=read))
    records = {r.constellation_id.name: (r.enable, r.reserved_channels, r.max_channels) for r in reply.settings}
    assert records == {"GPS": (1, 8, 16), "GLONASS": (1, 8, 14), "SBAS": (0, 1, 3), "QZSS": (0, 0, 3)}
    cv7 = sim_mod.Simulator("cv7_ins", scenario="static")
    (reply,) = _values(cv7, pkg.threedm.ComplementaryFilter(function=read))
    assert (reply.pitch_roll_time_constant, reply.heading_time_constant) == (10.0, 10.0)
    (reply,) = _values(cv7, pkg.threedm.SensorToVehicleQuaternion(function=read))
    assert list(reply.q) == [1.0, 0.0, 0.0, 0.0]
    (reply,) = _values(cv7, pkg.threedm.SensorToVehicleDcm(function=read))
    assert list(reply.dcm) == [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]


def test_the_ms_imu3020_reads_a_decimation_and_a_baud_rate_it_can_hold() -> None:
    """MS-IMU3020: the decimation divides the internal rate (ms-cip-doc00419-revM.txt:664), so 0 is
    no value it can hold; the baud rate is one of Table 20 (line 539)."""
    mscip = python_package("mscipcodec")
    importlib.import_module("mscipcodec.codec.packets")
    importlib.import_module("mscipcodec.codec.framing")
    msim = importlib.import_module("mscipcodec.sim")
    cfg = mscip.imu_config
    read = mscip.types.FunctionCode.READ
    sim = msim.Simulator("ms_imu3020", scenario="static")
    got = {}
    for command in (cfg.SampleRate(function=read), cfg.UartBaudRate(function=read)):
        raw = mscip.codec.framing.PacketBuilder(command.SET).add(command).build()
        for _when, data in sim.feed(raw, 0.0):
            for entry in mscip.codec.packets.decode_packet(data, device="ms_imu3020").fields:
                got[type(entry.value).__name__] = entry.value
    assert got["SampleRateResponse"].decimation >= 1
    assert int(got["UartBaudRateResponse"].baud_rate) in (9600, 19200, 115200, 230400, 460800, 921600)


def test_the_cv7_reads_a_sensor_range_selector_its_range_table_lists() -> None:
    """The CV7-INS range table (3dm-cv7-ins-docs.txt:1502) lists the accelerometer selectors
    2 = 4g, 3 = 8g, 4 = 16g and the gyro selector 2; "Using values other than those specified may
    result in a NACK" (line 7619), so a fresh device's selector is one of them, never 0."""
    read = FUNCTIONS["read"]
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    listed = {"ACCEL": {2, 3, 4}, "GYRO": {2}}
    for sensor, selectors in listed.items():
        kind = pkg.types.SensorRangeType[sensor]
        (reply,) = _values(sim, pkg.threedm.SensorRange(function=read, sensor=kind))
        assert reply.setting in selectors, (sensor, reply.setting)
