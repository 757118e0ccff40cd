"""End to end: sessions against the simulated device (docs/conformance.md section 9).

1. The conformance tool of every language of SESSION_LANGUAGES (`tests/conformance/session LANG
   --connect ADDRESS`) against `tests/conformance/simulate` over a pseudo-terminal and over TCP,
   driven by command lines only (so any language runs it): ping, device information, and for every
   command that has write and read, with values generated from the spec (tests/conformance/
   samples.py): read (factory) -> write A -> read A -> save -> write B -> read B -> load -> read A
   -> default -> read factory; NACKs for a command or a function the model does not support and
   for an enum value the spec does not define; a NACK, a timeout and a corrupted reply forced by
   the simulator's fault options.
2. The Python blocking API (`Device`) over both transports: streaming at the configured rate with
   commands answered meanwhile, continuation packets grouped into samples, a poll, a dropped
   reply's timeout; raw packets: an unknown descriptor and set, a count above the maximum.
3. The simulator's own errors: bad options (exit 2), replay of a capture.
"""

from __future__ import annotations

import importlib
import json
import select
import socket
import struct
import subprocess
import time
from pathlib import Path

import pytest

from generator.spec import load_spec
from tests.conformance.samples import field_samples
from tests.helpers.generated import python_package
from tests.helpers.langs import langs

ROOT = Path(__file__).resolve().parents[2]
SIMULATE = ROOT / "tests" / "conformance" / "simulate"
SESSION = ROOT / "tests" / "conformance" / "session"
# The session languages the end-to-end tests run (tests/conformance/session LANG): one place.
SESSION_LANGUAGES = langs()  # the target registry (generator/targets/__init__.py)
TRANSPORTS = ["pty", "tcp"]
IR = load_spec()
PROTOCOLS = {p["name"]: p for p in IR["protocols"]}
# (protocol, device) the round trips run on: every device model of the spec.
MODELS = [(p["name"], d["id"]) for p in IR["protocols"] for d in p["devices"]]


class Sim:
    """A running `tests/conformance/simulate`; `address` is its first line."""

    def __init__(self, protocol: str, device: str, listen: str, *extra: str) -> None:
        cmd = [str(SIMULATE), "--listen", listen, "--protocol", protocol, "--device", device, *extra]
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        ready, _, _ = select.select([self.proc.stdout], [], [], 30)
        line = self.proc.stdout.readline().strip() if ready else ""
        if not line:
            self.close()
            raise AssertionError(f"the simulator printed no address: {self.proc.stderr.read()}")
        self.address = line

    def close(self) -> None:
        if self.proc.poll() is None:
            self.proc.terminate()
            self.proc.wait(10)

    def __enter__(self) -> Sim:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def listen_for(transport: str) -> str:
    return "pty" if transport == "pty" else "tcp:127.0.0.1:0"


def session_tool(lang: str, protocol: str, address: str, lines: list[str], *extra: str) -> list[dict]:
    cmd = [str(SESSION), lang, "--connect", address, "--protocol", protocol, "--timeout-ms", "300", *extra]
    run = subprocess.run(cmd, input="\n".join(lines) + "\n", capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    return [json.loads(x) for x in run.stdout.splitlines()]


def results(out: list[dict]) -> list[dict]:
    return [x for x in out if "result" in x]


def command_line(protocol: dict, set_id: int, descriptor: int, name: str, values: dict) -> str:
    field = {"descriptor": descriptor, "name": name, "values": values}
    return json.dumps({"offset": 0, "set": set_id, "fields": [field]}, separators=(",", ":"))


# ------------------------------------------------------------------------------- the round trips
def _function_value(protocol: dict, name: str) -> int:
    enum = protocol["function_selector"]["enum"]
    t = next(t for t in protocol["types"] if t["name"] == enum)
    return next(v["value"] for v in t["values"] if v["name"] == name)


def _command(protocol: dict, set_id: int, field: dict, device: str, values: dict) -> str:
    """A command line for the session tool (the device named when the command has per-device layouts)."""
    entry = {"descriptor": field["id"], "name": field["name"]}
    if len(field["variants"]) > 1:
        entry["device"] = device
    entry["values"] = values
    return json.dumps({"offset": 0, "set": set_id, "fields": [entry]}, separators=(",", ":"))


def _perturbed(value):
    """Another value of the same shape: floats doubled (still exact), bools negated."""
    if isinstance(value, dict):
        return {k: v if k == "function" else _perturbed(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_perturbed(v) for v in value]
    if isinstance(value, bool):
        return not value
    if isinstance(value, float):
        return value * 2 if value else 0.5
    return value


def _factory(protocol: dict, set_: dict, variant: dict, device: str) -> dict:
    """The factory values of the read reply's plain parameters (by name): the spec's default of the
    command parameter of that name where the device's manual states one, else its plausible value,
    else zero (an enum without a zero value: its first value)."""
    types = {t["name"]: t for t in protocol["types"]}
    defaults = {
        q["name"]: q["default"]["value"]
        if q.get("default") and device in q["default"]["devices"]
        else q["plausible"]["value"]
        for q in variant["params"]
        if (q.get("default") and device in q["default"]["devices"]) or q.get("plausible")
    }
    for q in variant["params"]:  # a counted list's count parameter: the number of its records
        if (q["count"] or {}).get("kind") == "param" and isinstance(defaults.get(q["name"]), list):
            defaults.setdefault(q["count"]["param"], len(defaults[q["name"]]))
    rid = next(r["id"] for r in variant["responses"] if (r["when"] or {}).get("function") == "read")
    reply = next(f for f in set_["fields"] if f["id"] == rid)
    params = next(v for v in reply["variants"] if v["device"] in (None, device))["params"]
    if len(params) == len(variant["params"]):  # a reply parameter named otherwise (enable -> enabled)
        names = [q["name"] for q in variant["params"]]
        defaults = {r["name"]: defaults[c] for r, c in zip(params, names) if c in defaults} | defaults
    out = {}
    for q in params:
        kind = q["type"]["kind"]
        if q["count"] is not None or kind not in ("primitive", "enum", "bitfield"):
            continue
        if q["name"] in defaults:
            value = defaults[q["name"]]
            if q["type"].get("name") == "float":  # as a 32-bit float on the wire (0.1 -> 0.10000000149...)
                value = struct.unpack("<f", struct.pack("<f", value))[0]
            out[q["name"]] = value
        elif kind == "enum":
            values = [v["value"] for v in types[q["type"]["name"]]["values"]]
            out[q["name"]] = 0 if 0 in values else values[0]
        elif q["type"].get("name") == "bool":
            out[q["name"]] = False
        else:
            out[q["name"]] = 0
    return out


def keys_of(line: str) -> set:
    return set(json.loads(line)["fields"][0]["values"])


def _baud_param(protocol: dict, command: str) -> str | None:
    """The rate parameter of a baud rate command (the protocol file's `simulation.baud`)."""
    entries = (protocol.get("simulation") or {}).get("baud") or []
    return next((e["param"] for e in entries if e["command"] == command), None)


def _baud_rates(protocol: dict, device: str) -> list[int]:
    """The rates of the model's port (`link.baud_rates`; empty: the manual lists none)."""
    entries = (protocol.get("link") or {}).get("baud_rates") or []
    return next((list(e["rates"]) for e in entries if e["device"] == device), [])


def _nmea_entries(protocol: dict, device: str, name: str, a: dict, b: dict) -> tuple[dict, dict]:
    """An NMEA message format write (spec `simulation.nmea`): entries the simulator takes (a
    sentence, talker and source of the table at most its source's rate; any other is NACKed,
    docs/conformance.md section 9) instead of the random samples: GGA from the filter at 1 Hz (a)
    and at 2 Hz (b)."""
    nmea = (protocol.get("simulation") or {}).get("nmea")
    if not nmea or name != nmea["format"]["command"]:
        return a, b
    gga = next(x for x in nmea["sentences"] if x["name"] == "GGA")
    origin = next(o for o in nmea["origins"] if o["kind"] in gga["sources"] and o["max_hz"] >= 2)
    rates = next(r["rates"] for r in protocol["simulation"]["base_rates"] if r["device"] == device)
    set_id, base = next((r["set"], r["hz"]) for r in rates if r["set"] in origin["sets"])
    e = nmea["entry"]
    entry = {e["sentence"]: gga["code"], e["talker"]: nmea["talkers"][0]["code"], e["source"]: set_id}
    lst = nmea["format"]["list"]
    return (
        {**a, lst: [{**entry, e["decimation"]: base}]},
        {**b, lst: [{**entry, e["decimation"]: base // 2}]},
    )


def roundtrip_plan(protocol: dict, device: str) -> list[tuple[str, list[str], list]]:
    """Per command with write and read on `device`: (name, its lines, what each read must give
    back: "factory", or the values written)."""
    samples = field_samples(protocol)
    plans = []
    for s in protocol["sets"]:
        if s["kind"] != "command":
            continue
        for f in s["fields"]:
            if f["role"] != "command" or device not in f["devices"]:
                continue
            v = next(
                (v for v in f["variants"] if v["device"] in (None, device) and device in v["devices"]),
                None,
            )
            if (
                v is None
                or not v["functions"]
                or not {"write", "read", "save", "load", "default"} <= set(v["functions"])
            ):
                continue
            sel = "function"
            write = _function_value(protocol, "write")
            writes = [
                x
                for x in samples
                if x.set_id == s["id"]
                and x.descriptor == f["id"]
                and x.device in (None, device)
                and x.values.get(sel) == write
            ]
            distinct = list({json.dumps(x.values, sort_keys=True): x for x in writes}.values())
            if not distinct:
                continue
            order = sorted((x.values for x in distinct), key=lambda x: len(json.dumps(x)))
            full = [x for x in order if len(x) == max(map(len, order))]  # every parameter present
            a = full[0]  # not the longest: its read reply must fit beside the ack in one packet
            keys = [q["name"] for q in v["params"] if q["functions"] and "read" in q["functions"] and not q["optional"]]
            other = full[1] if len(full) > 2 else _perturbed(a)
            b = {**other, **{k: a[k] for k in keys}}  # the same setting, other values
            rate = _baud_param(protocol, f["name"])
            rates = _baud_rates(protocol, device)
            if rate is not None and rate in a and len(rates) >= 2 and isinstance(a[rate], int):
                # a baud rate write: rates the model's port lists (another is NACKed, docs/conformance.md §9)
                a, b = {**a, rate: rates[-1]}, {**b, rate: rates[-2]}
            a, b = _nmea_entries(protocol, device, f["name"], a, b)

            def line(function: str, values: dict, set_id: int = s["id"], field: dict = f) -> str:
                return _command(
                    protocol, set_id, field, device, {**values, "function": _function_value(protocol, function)}
                )

            key = {k: a[k] for k in keys}
            lines = [line("read", key), line("write", a), line("read", key), line("save", key), line("write", b)]
            lines += [line("read", key), line("load", key), line("read", key), line("default", key), line("read", key)]
            expect = [None, "ack", a, "ack", "ack", b, "ack", a, "ack", "factory"]
            plans.append((f["name"], lines, expect, sel, _factory(protocol, s, v, device)))
    return plans


def check_roundtrips(protocol: dict, device: str, out: list[dict]) -> int:
    plans = roundtrip_plan(protocol, device)
    res = results(out)
    assert len(res) == sum(len(p[1]) for p in plans)
    at = 0
    for name, lines, expect, sel, defaults in plans:
        got = res[at : at + len(lines)]
        at += len(lines)
        assert all(r["result"] == "ack" for r in got), (name, got)
        factory = got[0]["reply"][0]["values"]
        # the factory value: the spec's default where the manual states one, else zero
        for k, v in defaults.items():
            if k not in keys_of(lines[0]):
                assert factory[k] == v, (name, k, factory[k], v)
        for want, r in zip(expect, got):
            if want in (None, "ack"):
                continue
            reply = r["reply"][0]["values"]
            if want == "factory":
                assert reply == factory, (name, "default", reply, factory)
                continue
            shared = {k: v for k, v in want.items() if k in reply and k != sel}
            assert shared, (name, want, reply)
            assert {k: reply[k] for k in shared} == shared, (name, want, reply)
    return len(plans)


@pytest.mark.parametrize("transport", TRANSPORTS)
@pytest.mark.parametrize("lang", SESSION_LANGUAGES)
@pytest.mark.parametrize("protocol,device", MODELS)
def test_roundtrips_through_the_session_tool(lang: str, protocol: str, device: str, transport: str) -> None:
    proto = PROTOCOLS[protocol]
    ping = next(f for s in proto["sets"] if s["id"] == 1 for f in s["fields"] if f["name"] == "ping")
    lines = [command_line(proto, 1, ping["id"], "ping", {})]
    plans = roundtrip_plan(proto, device)
    assert len(plans) >= (3 if protocol == "mscip" else 40), [p[0] for p in plans]
    for p in plans:
        lines += p[1]
    with Sim(protocol, device, listen_for(transport)) as sim:
        out = session_tool(lang, protocol, sim.address, lines, "--device", device)
    res = results(out)
    assert res[0] == {"line": 1, "result": "ack", "code": 0, "reply": []}
    assert check_roundtrips(proto, device, [*res[1:]]) == len(plans)


MIP = PROTOCOLS["mip"]
INFO = command_line(MIP, 1, 3, "get_device_info", {})
PING = command_line(MIP, 1, 1, "ping", {})
GX5_ONLY = command_line(MIP, 12, 0x06, "get_imu_base_rate", {})
STARTUP = {"descriptor": 0x30, "name": "device_startup_settings", "device": "gx5_45", "values": {"function": 2}}
GX5_READ_ONLY = json.dumps({"offset": 0, "set": 12, "fields": [STARTUP]})
BAD_ENUM = command_line(MIP, 12, 0x28, "pps_source", {"function": 1, "source": 99})


@pytest.mark.parametrize("transport", TRANSPORTS)
@pytest.mark.parametrize("lang", SESSION_LANGUAGES)
def test_nacks_faults_and_device_information(lang: str, transport: str) -> None:
    # No --device for the tool: it sends what the simulated CV7-INS must refuse itself.
    lines = [INFO, GX5_ONLY, GX5_READ_ONLY, BAD_ENUM, *[PING] * 7]
    faults = ["--nack", "ping:4@1", "--drop", "ping@1", "--corrupt", "ping@1"]
    faults += ["--delay", "ping:150@1", "--split", "ping@1", "--garbage", "ping:5@1"]
    with Sim("mip", "cv7_ins", listen_for(transport), *faults) as sim:
        out = session_tool(lang, "mip", sim.address, lines)
    res = results(out)
    info = res[0]["reply"][0]["values"]["info"]
    assert res[0]["result"] == "ack" and info["model_name"].startswith("3DM-CV7-GNSS/INS"), res[0]
    assert [(r["result"], r["code"]) for r in res[1:]] == [
        ("nack", 1),  # get_imu_base_rate: a GX5-45 command, unknown to the CV7-INS
        ("nack", 3),  # device_startup_settings read: the CV7-INS has no read
        ("nack", 3),  # mode 99: the enum does not define it
        # one fault per reply, the first that applies in the order nack, drop, delay, corrupt, split, garbage
        ("nack", 4),  # --nack ping:4@1
        ("timeout", None),  # --drop ping@1
        ("ack", 0),  # --delay ping:150@1, within the 300 ms timeout
        ("timeout", None),  # --corrupt ping@1: the reply is skipped as a bad packet
        ("ack", 0),  # --split ping@1: two writes 20 ms apart
        ("ack", 0),  # --garbage ping:5@1: five bytes skipped before the reply
        ("ack", 0),
    ]
    skipped = [x for x in out if "skipped" in x]
    assert len(skipped) == 2 and len(bytes.fromhex(skipped[1]["skipped"])) == 5, out


# ------------------------------------------------------------------------------- the Python API
def pump_for(dev, seconds: float) -> None:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        dev.pump(max(1, int((end - time.monotonic()) * 1000)))


def open_device(pkg, address: str, device: str):
    session = importlib.import_module(pkg.__name__ + ".session")
    transport = importlib.import_module(pkg.__name__ + ".session.transport")
    return session.Device(transport.open_transport(address), device=device, timeout_ms=500)


@pytest.mark.parametrize("transport", TRANSPORTS)
def test_python_device_streams_at_the_configured_rate(transport: str) -> None:
    pkg = python_package("mipcodec")
    t = pkg.types
    with Sim("mip", "cv7_ins", listen_for(transport), "--seed", "7") as sim:
        dev = open_device(pkg, sim.address, "cv7_ins")
        try:
            assert dev.threedm.get_base_rate(desc_set=0x80).rate == 1000
            fmt = [t.DescriptorRate(descriptor=d, decimation=20) for d in (0xD5, 0x04, 0x05)]
            dev.threedm.message_format.write(desc_set=0x80, descriptors=fmt)
            dev.threedm.data_stream_control.write_cv7_ins(desc_set=0x80, enable=True)
            assert [x.descriptor for x in dev.threedm.message_format.read(desc_set=0x80).descriptors] == [0xD5, 4, 5]
            accel = []
            dev.on_field(0x80, 0x04, lambda value, packet: accel.append(value.scaled_accel))
            start = time.monotonic()
            pings = 0
            while time.monotonic() - start < 1.0:
                dev.base.ping()  # commands are answered while data streams
                pings += 1
                pump_for(dev, 0.02)
            elapsed = time.monotonic() - start
            rate = len(accel) / elapsed
            assert 40 <= rate <= 60, (len(accel), elapsed)  # 1000 Hz / 20
            assert pings > 5
            assert all(abs(a[2] + 1.0) < 0.05 and abs(a[0]) < 0.05 for a in accel)  # gravity on z
            stream = dev.threedm.data_stream_control
            stream.write_cv7_ins(desc_set=0x80, enable=False)
            pump_for(dev, 0.1)
            accel.clear()
            pump_for(dev, 0.3)
            assert accel == []
            stream.save_cv7_ins(desc_set=0x80)  # startup value: disabled
            stream.default_cv7_ins(desc_set=0x80)  # factory value: enabled (the spec's default, CV7 manual)
            assert stream.read_cv7_ins(desc_set=0x80).enabled is True
            pump_for(dev, 0.2)
            assert accel, "default restores the factory value, enabled"
            stream.load_cv7_ins(desc_set=0x80)
            assert stream.read_cv7_ins(desc_set=0x80).enabled is False
            pump_for(dev, 0.1)
            accel.clear()
            pump_for(dev, 0.3)
            assert accel == [], "load restores the saved value, disabled"
        finally:
            dev.transport.close()


def test_python_device_continuation_packets_and_poll() -> None:
    pkg = python_package("mipcodec")
    t = pkg.types
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0") as sim:
        dev = open_device(pkg, sim.address, "cv7_ins")
        try:
            packets, samples = [], []
            dev.on_packet(packets.append)
            dev.on_sample(samples.append)
            # 0xD5 first (shared timestamp) and more data than one packet holds (255 bytes)
            descriptors = [0xD5, *range(0x01, 0x0F)]
            fmt = [t.DescriptorRate(descriptor=d, decimation=100) for d in descriptors]
            dev.threedm.message_format.write(desc_set=0x82, descriptors=fmt)
            dev.threedm.data_stream_control.write_cv7_ins(desc_set=0x82, enable=True)
            pump_for(dev, 0.35)
            dev.threedm.data_stream_control.write_cv7_ins(desc_set=0x82, enable=False)
            pump_for(dev, 0.05)
            data = [p for p in packets if p.set == 0x82]
            assert len(data) >= 4
            assert len(samples) >= 2
            for sample in samples[:-1]:
                assert len(sample.offsets) >= 2  # a packet and its continuation packets
                names = [f.name for f in sample.fields]
                assert names.count("reference_timestamp") == 1
                assert "llh_position" in names and "comp_angular_rate" in names
            for p in data:
                assert p.fields[0].descriptor == 0xD5  # repeated in every continuation packet
            packets.clear()
            dev.threedm.poll_data(desc_set=0x80, suppress_ack=False, descriptors=[0x04])
            pump_for(dev, 0.1)
            polled = [p for p in packets if p.set == 0x80]
            assert len(polled) == 1 and [f.descriptor for f in polled[0].fields] == [0x04]
        finally:
            dev.transport.close()


@pytest.mark.parametrize("transport", TRANSPORTS)
def test_python_device_timeout_from_a_dropped_reply(transport: str) -> None:
    pkg = python_package("mscipcodec")
    with Sim(
        "mscip", "ms_imu3020", listen_for(transport), "--drop", "ping@1", "--delay", "get_device_model:100"
    ) as sim:
        dev = open_device(pkg, sim.address, "ms_imu3020")
        try:
            start = time.monotonic()
            with pytest.raises(importlib.import_module("mscipcodec.session").CommandTimeout):
                dev.base.ping()
            assert 0.45 <= time.monotonic() - start < 2.0
            dev.base.ping()
            start = time.monotonic()
            dev.base.get_device_model()
            assert time.monotonic() - start >= 0.09
        finally:
            dev.transport.close()


def test_mscip_streams_the_selected_sensors() -> None:
    pkg = python_package("mscipcodec")
    t = pkg.types
    with Sim("mscip", "ms_imu3020", "tcp:127.0.0.1:0") as sim:
        dev = open_device(pkg, sim.address, "ms_imu3020")
        try:
            packets = []
            dev.on_packet(packets.append)
            dev.imu_config.sample_rate.write(decimation=50)
            dev.imu_config.select_sensors.write(reserved=0, sensors=[t.SensorCode.SCALED_ACCEL])
            dev.imu_config.data_on_off.write(control=t.OnOff.ON)
            pump_for(dev, 0.5)
            dev.imu_config.data_on_off.write(control=t.OnOff.OFF)
            data = [p for p in packets if p.set == 0xA2]
            assert 7 <= len(data) <= 13, len(data)  # 1000 Hz / 50 for 0.5 s
            assert all(f.descriptor == 0x81 for p in data for f in p.fields)
        finally:
            dev.transport.close()


def test_gx5_streams_are_enabled_from_the_factory() -> None:
    """A GX5-45 program that relies on the factory defaults: "The default for the device is all
    streams enabled" (3dm-gx5-45-dcp.txt:1049; getting started step 5, line 411: "may have already
    been enabled by default"). Ping, set to idle, set the IMU and filter message formats, resume,
    and never send Enable/Disable Continuous Data Stream (0x0C,0x11): IMU and filter data arrive."""
    pkg = python_package("mipcodec")
    t = pkg.types
    with Sim("mip", "gx5_45", "tcp:127.0.0.1:0") as sim:
        dev = open_device(pkg, sim.address, "gx5_45")
        try:
            packets = []
            dev.on_packet(packets.append)
            dev.base.ping()
            dev.base.set_to_idle()
            # the manual's copy-paste example rates (line 1043): decimation 4 of the 500 Hz base rate
            dev.threedm.imu_message_format.write(
                descriptors=[t.DescriptorRate(descriptor=d, decimation=4) for d in (4, 5)]
            )
            dev.threedm.filter_message_format.write(
                descriptors=[t.DescriptorRate(descriptor=d, decimation=4) for d in (3, 5)]
            )
            pump_for(dev, 0.2)
            assert [p for p in packets if p.set in (0x80, 0x82)] == [], "idle: no data"
            dev.base.resume()
            pump_for(dev, 0.5)
            imu = [p for p in packets if p.set == 0x80]
            nav = [p for p in packets if p.set == 0x82]
            assert 40 <= len(imu) <= 80 and 40 <= len(nav) <= 80, (len(imu), len(nav))  # 125 Hz for 0.5 s
            assert [f.descriptor for f in imu[0].fields] == [4, 5]
            assert [f.descriptor for f in nav[0].fields] == [3, 5]
            # reads answer the factory values the manual states
            stream = dev.threedm.data_stream_control
            for selector in (t.Gx5StreamSelector.IMU, t.Gx5StreamSelector.ESTIMATION_FILTER):
                assert stream.read_gx5_45(device_selector=selector).enabled == 1
            assert dev.threedm.uart_baudrate.read().baud == 115200  # line 1296
            assert dev.threedm.coning_sculling_enable.read().enable is True  # line 1282
            sbas = dev.threedm.gnss_sbas_settings.read()
            assert (sbas.enable_sbas, int(sbas.sbas_options)) == (1, 0x0003)  # line 1145
            assert dev.threedm.mag_soft_iron_matrix.read().matrix == [1, 0, 0, 0, 1, 0, 0, 0, 1]  # line 1265
            assert dev.filter.declination_source.read().source == t.MagneticParamSource.WMM  # line 1878
        finally:
            dev.transport.close()


def test_cv7_holds_the_defaults_of_its_own_manual_only() -> None:
    """A default one manual states holds on that manual's device: the GX5-45's baud rate (line
    1296) is no CV7 default, its PPS source is (3dm-cv7-ins-docs.txt:217)."""
    pkg = python_package("mipcodec")
    t = pkg.types
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0") as sim:
        dev = open_device(pkg, sim.address, "cv7_ins")
        try:
            # no stated default: the spec's plausible value, the lowest rate its main UART serves
            # (issue 51; 3dm-cv7-ins-docs.txt:2718), not the GX5-45's stated default
            assert dev.threedm.uart_baudrate.read().baud == 115200
            assert dev.threedm.pps_source.read().source == t.PpsSource.RECEIVER_1
            cal = dev.filter.gnss_antenna_calibration_control.read()
            assert abs(cal.max_offset - 0.1) < 1e-6  # line 271
        finally:
            dev.transport.close()


def test_mscip_streams_its_default_message_without_select_sensors() -> None:
    """ "The IMU Data Message ... is the default output configuration on device startup" (Table 63:
    scaled accelerations and angular rates; ms-cip-doc00419-revM.txt:1229): data on, and nothing
    else, streams them."""
    pkg = python_package("mscipcodec")
    t = pkg.types
    with Sim("mscip", "ms_imu3020", "tcp:127.0.0.1:0") as sim:
        dev = open_device(pkg, sim.address, "ms_imu3020")
        try:
            packets = []
            dev.on_packet(packets.append)
            assert list(dev.imu_config.select_sensors.read().sensors) == [
                t.SensorCode.SCALED_ACCEL,
                t.SensorCode.SCALED_GYRO,
            ]
            dev.imu_config.sample_rate.write(decimation=50)
            dev.imu_config.data_on_off.write(control=t.OnOff.ON)
            pump_for(dev, 0.3)
            dev.imu_config.data_on_off.write(control=t.OnOff.OFF)
            data = [p for p in packets if p.set == 0xA2]
            assert data
            assert all([f.descriptor for f in p.fields] == [0x81, 0x82] for p in data)
        finally:
            dev.transport.close()


# ------------------------------------------------------------------------------- raw packets
def raw_exchange(address: str, packet: bytes) -> bytes:
    host, _, port = address[4:].rpartition(":")
    with socket.create_connection((host, int(port)), timeout=5) as s:
        s.sendall(packet)
        s.settimeout(1.0)
        return s.recv(4096)


def test_raw_nacks_unknown_descriptor_set_and_count_above_maximum() -> None:
    pkg = python_package("mipcodec")
    b = pkg.PacketBuilder
    cases = [
        (b(0x01).add_field(0x55, b"").build(), 0x55, 1),  # unknown command descriptor
        (b(0x0C).add_field(0x0F, bytes([1, 0x80, 84]) + bytes(3 * 84)[:240]).build(), 0x0F, 3),  # count 84 > 83
    ]
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0") as sim:
        for packet, descriptor, code in cases:
            reply = pkg.decode_packet(raw_exchange(sim.address, packet))
            ack = reply.fields[0].value
            assert (ack.command_descriptor, int(ack.ack_code)) == (descriptor, code)
        reply = raw_exchange(sim.address, b(0x7E).add_field(0x01, b"").build())
        assert int(pkg.decode_packet(reply).fields[0].value.ack_code) == 6  # unknown descriptor set


# ------------------------------------------------------------------------------- the tool itself
def test_simulator_usage_errors() -> None:
    for args in (
        ["--listen", "udp:1"],
        ["--listen", "pty", "--device", "nope"],
        ["--listen", "pty", "--delay", "ping"],
    ):
        run = subprocess.run([str(SIMULATE), *args], capture_output=True, text=True, timeout=60)
        assert run.returncode == 2, (args, run.stdout, run.stderr)
        assert "Traceback" not in run.stderr and run.stderr.strip(), run.stderr


def test_replay_of_a_capture(tmp_path: Path) -> None:
    pkg = python_package("mipcodec")
    capture = b"".join(pkg.PacketBuilder(1).add_field(1, b"").build() for _ in range(3))
    path = tmp_path / "capture.bin"
    path.write_bytes(capture)
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", "--replay", str(path), "--fast") as sim:
        host, _, port = sim.address[4:].rpartition(":")
        got = b""
        with socket.create_connection((host, int(port)), timeout=5) as s:
            s.settimeout(2.0)
            while len(got) < len(capture):
                chunk = s.recv(4096)
                if not chunk:
                    break
                got += chunk
    assert got == capture


def test_replay_pace_follows_the_timestamps() -> None:
    pkg = python_package("mipcodec")
    sim = importlib.import_module("mipcodec.sim")
    shared = pkg.shared
    packets = [
        pkg.PacketBuilder(0x80).add(shared.ReferenceTimestamp(nanoseconds=n * 100_000_000)).build() for n in range(4)
    ]
    chunks = sim.replay_chunks(b"".join(packets))
    assert [round(t, 3) for t, _ in chunks] == [0.0, 0.1, 0.2, 0.3]
    assert [t for t, _ in sim.replay_chunks(b"".join(packets), fast=True)] == [0.0] * 4


@pytest.mark.parametrize("transport", TRANSPORTS)
@pytest.mark.parametrize("lang", SESSION_LANGUAGES)
def test_streaming_through_the_session_tool(lang: str, transport: str) -> None:
    """Data at the configured rate reaches any language's tool while it waits for a reply (one
    dropped by the simulator: the tool waits the whole 300 ms timeout), and commands are answered
    while the data streams."""
    fmt = {"function": 1, "desc_set": 0x80, "num_descriptors": 2}
    fmt["descriptors"] = [{"descriptor": 0xD5, "decimation": 10}, {"descriptor": 0x04, "decimation": 10}]
    control = {"descriptor": 0x11, "name": "data_stream_control", "device": "cv7_ins"}
    control["values"] = {"function": 1, "desc_set": 0x80, "enable": True}
    lines = [
        command_line(MIP, 12, 0x0F, "message_format", fmt),
        json.dumps({"offset": 0, "set": 12, "fields": [control]}),
        INFO,
        PING,
    ]
    with Sim("mip", "cv7_ins", listen_for(transport), "--drop", "get_device_info") as sim:
        out = session_tool(lang, "mip", sim.address, lines, "--device", "cv7_ins")
    assert [r["result"] for r in results(out)] == ["ack", "ack", "timeout", "ack"]
    data = [x for x in out if x.get("set") == 0x80]
    assert 20 <= len(data) <= 60, len(data)  # 100 Hz (1 kHz / 10) for a little over 300 ms
    assert all([f["descriptor"] for f in p["fields"]] == [0xD5, 0x04] for p in data)
    stamps = [p["fields"][0]["values"]["nanoseconds"] for p in data]
    assert all(b - a == 10_000_000 for a, b in zip(stamps, stamps[1:]))  # every 10 ms of device time


# ------------------------------------------------------------------------------- capabilities and identity
def supported(protocol: dict, device: str) -> list[int]:
    """Written from the IR here, not from the simulator: every command and every data quantity
    (outside the shared data set) whose manual documents it for `device`, (set << 8) | descriptor,
    ascending (the decision of spec/mip/protocol.yaml simulation descriptor_lists)."""
    out = []
    for s in protocol["sets"]:
        for f in s["fields"]:
            if device in f["devices"] and (f["role"] == "command" or (f["role"] == "data" and not s["shared"])):
                out.append(s["id"] << 8 | f["id"])
    return sorted(out)


# One reply holds the ack field (2 + 2 bytes) and the list field (2 header bytes + 2 per entry) in
# at most 255 payload bytes (max_payload of spec/mip/protocol.yaml): (255 - 4 - 2) // 2 entries.
FIRST_LIST = (255 - 4 - 2) // 2


@pytest.mark.parametrize("device", ["gx5_45", "cv7_ins"])
def test_descriptor_lists_are_the_device_capabilities(device: str) -> None:
    pkg = python_package("mipcodec")
    expected = supported(MIP, device)
    assert len(expected) > FIRST_LIST  # both models need the extended list
    with Sim("mip", device, "tcp:127.0.0.1:0") as sim:
        dev = open_device(pkg, sim.address, device)
        try:
            first = list(dev.base.get_device_descriptors().descriptors)
            extended = list(dev.base.get_extended_descriptors().descriptors)
        finally:
            dev.transport.close()
        # the manual's format: reply field 0x82 of length 2 x <number of descriptors> + 2, u16 MSB set
        raw = raw_exchange(sim.address, pkg.PacketBuilder(0x01).add_field(0x04, b"").build())
    assert first == expected[:FIRST_LIST] and extended == expected[FIRST_LIST:]
    assert 0x0107 in first  # "search for the 0x0107 descriptor in the list" (GX5-45 line 847)
    assert 0x8006 in first + extended  # does this device have a magnetometer? scaled mag 0x80,0x06
    assert raw[:4] == bytes([0x75, 0x65, 0x01, 4 + 2 + 2 * FIRST_LIST])
    assert raw[4:8] == bytes([0x04, 0xF1, 0x04, 0x00])  # the ack echoes 0x04
    assert raw[8:10] == bytes([2 + 2 * FIRST_LIST, 0x82])
    assert raw[10:14] == bytes([0x01, 0x01, 0x01, 0x02])  # ping 0x0101, set to idle 0x0102, big-endian


def test_mscip_device_messages_list_the_commands() -> None:
    pkg = python_package("mscipcodec")
    proto = PROTOCOLS["mscip"]
    commands = sorted(s["id"] << 8 | f["id"] for s in proto["sets"] for f in s["fields"] if f["role"] == "command")
    with Sim("mscip", "ms_imu3020", "tcp:127.0.0.1:0") as sim:
        dev = open_device(pkg, sim.address, "ms_imu3020")
        try:
            got = dev.base.get_device_messages().messages
        finally:
            dev.transport.close()
    assert [m.message_type << 8 | m.message_code for m in got] == commands


def test_identity_defaults_and_flags() -> None:
    mip, mscip = python_package("mipcodec"), python_package("mscipcodec")
    with Sim("mip", "gx5_45", "tcp:127.0.0.1:0") as sim:
        dev = open_device(mip, sim.address, "gx5_45")
        try:
            info = dev.base.get_device_info().info
        finally:
            dev.transport.close()
    # the GX5-45 manual's example reply (3dm-gx5-45-dcp.txt line 785), model number 6251 (line 1349)
    assert info.firmware_version == 0x05FE and info.serial_number.strip() == b"6232-00122"
    assert (info.model_name.strip(), info.model_number.strip(), info.device_options.strip()) == (
        b"3DM-GX5-45",
        b"6251-4270",  # the model number Device Status states (line 1349; docs/errata.md)
        b"5g, 150d/s",
    )
    flags = ["--serial", "SN-42", "--lot", "L7", "--options", "2g, 75d/s", "--firmware", "1209"]
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", *flags) as sim:
        dev = open_device(mip, sim.address, "cv7_ins")
        try:
            info = dev.base.get_device_info().info
        finally:
            dev.transport.close()
    assert info.firmware_version == 1209 and info.model_name == b"3DM-CV7-GNSS/INS"
    assert (info.serial_number, info.lot_number, info.device_options) == (
        b"SN-42".ljust(16),
        b"L7".ljust(16),
        b"2g, 75d/s".ljust(16),
    )
    with Sim("mscip", "ms_imu3020", "tcp:127.0.0.1:0", "--serial", "31337", "--firmware", "R_2_0_1") as sim:
        dev = open_device(mscip, sim.address, "ms_imu3020")
        try:
            sn = dev.base.get_device_sn().serial_number
            fw = dev.base.get_device_fw().firmware
            model = dev.base.get_device_model().model
        finally:
            dev.transport.close()
    # right-justified, space-padded (ms-cip-doc00419-revM.txt lines 330, 382)
    assert (sn, fw, model) == (b"31337".rjust(16), b"R_2_0_1".rjust(16), b"MS_IMU3020".rjust(16))


def test_identity_flag_errors() -> None:
    for args, message in (
        (
            ["--protocol", "mip", "--device", "cv7_ins", "--firmware", "1.2.3"],
            "--firmware 1.2.3: expected an integer 0..65535",
        ),
        (["--protocol", "mip", "--firmware", "65536"], "--firmware 65536: expected an integer 0..65535"),
        (["--protocol", "mip", "--serial", "x" * 17], "expected at most 16 printable ASCII characters"),
        (["--protocol", "mscip", "--lot", "7"], "--lot 7: ms_imu3020 reports no lot number"),
    ):
        run = subprocess.run([str(SIMULATE), "--listen", "pty", *args], capture_output=True, text=True, timeout=60)
        assert run.returncode == 2, (args, run.stdout, run.stderr)
        lines = run.stderr.strip().splitlines()
        assert len(lines) == 1 and message in lines[0] and "Traceback" not in run.stderr, run.stderr


def refusal_lines(protocol: dict, device: str, documented: bool = False) -> tuple[list[str], list[str]]:
    """One command line for every command of the protocol the manual of `device` does not document
    (from the IR's fields, as `supported` derives it), and the refusal each session must give; with
    `documented`, the lines of the commands it documents (in the device's own layout)."""
    model = next(d for d in protocol["devices"] if d["id"] == device)
    first: dict[tuple[int, int], object] = {}
    for x in field_samples(protocol):
        if not documented or x.device in (None, device):
            first.setdefault((x.set_id, x.descriptor), x)
    lines, errors = [], []
    for s in protocol["sets"]:
        for f in s["fields"]:
            if f["role"] != "command" or (device in f["devices"]) != documented:
                continue
            if documented and any(v["timeout"] for v in f["variants"]):
                continue  # the simulator takes the allowance (capture gyro bias: up to a minute)
            x = first[(s["id"], f["id"])]
            entry = {"descriptor": f["id"], "name": f["name"], "values": x.values}
            if x.print_device:
                entry["device"] = x.device
            lines.append(json.dumps({"offset": 0, "set": s["id"], "fields": [entry]}, separators=(",", ":")))
            errors.append(f"{f['name']} is not supported by {model['title']} ({model['manual']})")
    return lines, errors


@pytest.mark.parametrize("lang", SESSION_LANGUAGES)
@pytest.mark.parametrize("device", ["gx5_45", "cv7_ins"])
def test_every_language_refuses_what_the_model_does_not_support(lang: str, device: str) -> None:
    # Each language's capabilities table, asked through its session: every command the model's
    # manual does not document is refused before sending, naming the model and its manual; ping
    # and the descriptor lists (documented for both) go out and are answered.
    lines, errors = refusal_lines(MIP, device)
    assert len(lines) >= 8, lines
    # every documented command goes out (whatever the simulator answers), then the list
    documented = refusal_lines(MIP, device, documented=True)[0]
    asked = [*documented, PING, command_line(MIP, 1, 4, "get_device_descriptors", {})]
    with Sim("mip", device, "tcp:127.0.0.1:0") as sim:
        out = session_tool(lang, "mip", sim.address, [*lines, *asked], "--device", device)
    res = results(out)
    assert [(r["result"], r.get("error")) for r in res[: len(lines)]] == [("refused", e) for e in errors]
    sent = res[len(lines) :]
    assert len(sent) == len(asked) and not [r for r in sent if r["result"] == "refused"], sent
    assert [r["result"] for r in sent[-2:]] == ["ack", "ack"], sent[-2:]
    listed = res[-1]["reply"][0]["values"]["descriptors"]
    assert listed == supported(MIP, device)[:FIRST_LIST]
