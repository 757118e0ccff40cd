"""The Rust session layer end to end: each crate's `configure_and_stream` example (the typed
command API over the blocking `Device`, over loopback TCP) against the scripted fake device
(tests/conformance/fake_device.py). The script answers the example's commands (ping, the device
information, a setting written and read back, the stream command) and then sends data packets;
the example must print the typed replies and every data packet as its canonical JSON line (the
Python package's line for the same bytes at the same offset) and exit 0. It also checks that the
example's commands went out (the fake device reads each one as a complete packet)."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pytest

from generator.spec import load_spec
from tests.conformance.fake_device import FakeDevice
from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
IR = load_spec()
PROTOCOLS = {p["name"]: p for p in IR["protocols"]}

# Per protocol: the device model, the replies to the example's commands in order (fields after
# the ack, as canonical JSON objects), what the example prints for them, and the data packets.
SCRIPTS = {
    "mip": {
        "device": "cv7_ins",
        "replies": [
            (0x01, 0x01, []),
            (
                0x01,
                0x03,
                [
                    {
                        "descriptor": 0x81,
                        "name": "device_info",
                        "values": {
                            "info": {
                                "firmware_version": 1534,
                                "model_name": "3DM-CV7-INS     ",
                                "model_number": "6232-4270       ",
                                "serial_number": "6232-00122      ",
                                "lot_number": "                ",
                                "device_options": "8g, 300d/s      ",
                            }
                        },
                    }
                ],
            ),
            (0x0C, 0x31, []),
            (
                0x0C,
                0x31,
                [
                    {
                        "descriptor": 0xB1,
                        "name": "sensor_to_vehicle_euler_response",
                        "values": {"roll": 0.0, "pitch": 1.5708, "yaw": 1.5708},
                    }
                ],
            ),
            (0x0C, 0x11, []),
        ],
        "prints": ["ping: ack", "device info: DeviceInfo", "sensor_to_vehicle_euler: SensorToVehicleEulerResponse"],
        "data": "7565800e0e040000000000000000bf800000b935",
    },
    "mscip": {
        "device": "ms_imu3020",
        "replies": [
            (0x01, 0x02, []),
            (0x01, 0x05, [{"descriptor": 0x85, "name": "device_model", "values": {"model": "      MS_IMU3020"}}]),
            (0x02, 0x04, []),
            (0x02, 0x04, [{"descriptor": 0x84, "name": "sample_rate_response", "values": {"decimation": 10}}]),
            (0x02, 0x05, []),
        ],
        "prints": ["ping: ack", "device model: DeviceModel", "sample_rate: SampleRateResponse { decimation: 10 }"],
        "data": "a5a5a20e810c37a7c5ac377ba8823f800065d61a",
    },
}

DATA_PACKETS = 3


def _ack(proto: dict, set_id: int, descriptor: int, extra: list) -> bytes:
    """The reply packet: the ack of (set, descriptor) with success, then `extra` fields."""
    pkg = python_package(proto["package"])
    rule = proto["session"]
    ack = {"descriptor": rule["ack"], "name": rule["ack_name"], "values": {rule["echo"]: descriptor, rule["code"]: 0}}
    line = json.dumps({"offset": 0, "set": set_id, "fields": [ack, *extra]}, separators=(",", ":"))
    return pkg.packets.encode_line(line)


@pytest.mark.parametrize("protocol", sorted(SCRIPTS))
def test_configure_and_stream_example(protocol):
    proto = PROTOCOLS[protocol]
    script = SCRIPTS[protocol]
    pkg = python_package(proto["package"])
    steps, received, at = [], b"", 0
    for set_id, descriptor, extra in script["replies"]:
        reply = _ack(proto, set_id, descriptor, extra)
        steps += [{"at": at, "send": "command"}, {"at": at + 3, "receive": reply.hex()}]
        received += reply
        at += 10
    expect_data = []
    for k in range(DATA_PACKETS):
        data = bytes.fromhex(script["data"])
        expect_data.append("data " + pkg.packets.decode_packet(data, len(received), script["device"]).line())
        steps.append({"at": at + 5 * k, "receive": data.hex()})
        received += data
    manifest = ROOT / "generated" / "rust" / proto["package"] / "Cargo.toml"
    cargo = ["cargo", "--quiet", "--manifest-path", str(manifest), "--example", "configure_and_stream"]
    env = {**os.environ, "CARGO_TARGET_DIR": str(ROOT / "build" / "rust" / "target")}
    # Built first: the fake device waits 30 s for its connection.
    build = subprocess.run([cargo[0], "build", *cargo[1:]], capture_output=True, text=True, timeout=900, env=env)
    assert build.returncode == 0, build.stderr
    dev = FakeDevice({"steps": steps, "expect": []}, proto["framing"]).start()
    proc = subprocess.run(
        [cargo[0], "run", *cargo[1:], "--", f"tcp:127.0.0.1:{dev.port}", str(DATA_PACKETS)],
        capture_output=True,
        text=True,
        timeout=900,
        env=env,
    )
    dev.join(10)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert len(lines) == len(script["prints"]) + DATA_PACKETS, lines
    for got, want in zip(lines, script["prints"]):
        assert got.startswith(want), (got, want)
    assert lines[len(script["prints"]) :] == expect_data
    assert dev.errors == [] and len(dev.received) == len(script["replies"])


def test_tool_over_ipv6():
    """The Rust session tool connects to a bracketed IPv6 host (`tcp:[::1]:PORT`): a responder on
    the IPv6 loopback answers one ping with its ack."""
    import socket
    import threading

    srv = socket.socket(socket.AF_INET6, socket.SOCK_STREAM)
    srv.bind(("::1", 0))
    srv.listen(1)
    srv.settimeout(900)  # the tool may be built first (tests/lang/rust.sh)
    port = srv.getsockname()[1]
    got: list[bytes] = []

    def serve() -> None:
        conn, _ = srv.accept()
        with conn:
            data = b""
            while len(data) < 8:
                data += conn.recv(64)
            got.append(data)
            conn.sendall(bytes.fromhex("75650104 04f10100 d56a".replace(" ", "")))
            while conn.recv(64):
                pass

    t = threading.Thread(target=serve, daemon=True)
    t.start()
    line = '{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}\n'
    proc = subprocess.run(
        [str(ROOT / "tests/conformance/session"), "rust", "--connect", f"tcp:[::1]:{port}"],
        input=line,
        capture_output=True,
        text=True,
        timeout=900,
    )
    t.join(10)
    srv.close()
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == ['{"line":1,"result":"ack","code":0,"reply":[]}']
    assert got == [bytes.fromhex("7565010202 01e0c6".replace(" ", ""))]
