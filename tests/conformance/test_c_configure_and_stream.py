"""The C "configure the device and stream data" example (examples/configure_and_stream.c of each C
package) against the scripted fake device (fake_device.py) over loopback TCP: it pings, reads the
device information, writes a setting and reads it back, starts the data stream and prints the
first data packets. The replies are written here as canonical JSON lines (encoded by the Python
package); the expected output follows from them alone."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from generator.spec import load_spec
from tests.conformance.fake_device import FakeDevice
from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
PROTOCOLS = {p["name"]: p for p in load_spec()["protocols"]}


def _line(set_id: int, *fields: str) -> str:
    return '{"offset":0,"set":%d,"fields":[%s]}' % (set_id, ",".join(fields))


MIP_ACK = '{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":%d,"ack_code":0}}'
MSCIP_ACK = '{"descriptor":128,"name":"ack","values":{"command_code":%d,"error_code":0}}'

# Per protocol: (reply lines, one per command in the order the example sends them; data lines;
# the lines the example prints before the data packets).
SCRIPTS = {
    "mip": (
        [
            _line(1, MIP_ACK % 1),
            _line(
                1,
                MIP_ACK % 3,
                '{"descriptor":129,"name":"device_info","values":{"info":{"firmware_version":1534,'
                '"model_name":"3DM-CV7-INS     ","model_number":"6284-4220       ",'
                '"serial_number":"6284-00001      ","lot_number":"                ",'
                '"device_options":"8g, 300dps      "}}}',
            ),
            _line(12, MIP_ACK % 0x31),
            _line(
                12,
                MIP_ACK % 0x31,
                '{"descriptor":177,"name":"sensor_to_vehicle_euler_response","values":{"roll":0.0,"pitch":0.0,"yaw":1.5708}}',
            ),
            _line(12, MIP_ACK % 0x11),
        ],
        _line(128, '{"descriptor":4,"name":"scaled_accel","values":{"scaled_accel":[0.0,0.0,-1.0]}}'),
        ["ping: ack", "model: 3DM-CV7-INS     ", "sensor to vehicle: roll 0.0000 pitch 0.0000 yaw 1.5708"],
        "set 0x80, 1 fields",
    ),
    "mscip": (
        [
            _line(1, MSCIP_ACK % 2),
            _line(1, MSCIP_ACK % 5, '{"descriptor":133,"name":"device_model","values":{"model":"      MS_IMU3020"}}'),
            _line(2, MSCIP_ACK % 0x04),
            _line(2, MSCIP_ACK % 0x04, '{"descriptor":132,"name":"sample_rate_response","values":{"decimation":4}}'),
            _line(2, MSCIP_ACK % 0x0A),
        ],
        _line(
            0xA2,
            '{"descriptor":129,"name":"scaled_accel","values":{"accel":[2.0e-05,1.5e-05,1.000012]}}',
            '{"descriptor":130,"name":"scaled_gyro","values":{"gyro":[2.0e-05,1.5e-05,1.2e-05]}}',
        ),
        ["ping: ack", "model:       MS_IMU3020", "sample rate decimation: 4"],
        "set 0xA2, 2 fields",
    ),
}


@pytest.mark.parametrize("protocol", sorted(SCRIPTS))
def test_configure_and_stream(protocol):
    proto = PROTOCOLS[protocol]
    pkg = python_package(proto["package"])
    replies, data, head, data_text = SCRIPTS[protocol]
    steps = []
    for k, reply in enumerate(replies):
        steps.append({"at": 10 * k, "send": "command"})
        steps.append({"at": 10 * k + 1, "receive": pkg.packets.encode_line(reply).hex()})
    # The data stream, with garbage before it: three packets after the last ack.
    packet = pkg.packets.encode_line(data).hex()
    steps += [{"at": 10 * len(replies) + 2 + k, "receive": "00" + packet} for k in range(3)]
    case = {"steps": steps, "expect": []}
    dev = FakeDevice(case, proto["framing"]).start()
    subprocess.run([str(ROOT / "tests/lang/c.sh"), "build"], check=True, capture_output=True, timeout=1800)
    exe = ROOT / "build" / "c" / proto["package"] / f"{proto['package']}-configure-and-stream"
    proc = subprocess.run([str(exe), f"tcp:127.0.0.1:{dev.port}", "3"], capture_output=True, text=True, timeout=60)
    dev.join(10)
    assert proc.returncode == 0, proc.stderr
    assert dev.errors == []
    assert len(dev.received) == len(replies)
    expect = head + [f"data packet {n}: {data_text}" for n in (1, 2, 3)]
    assert proc.stdout.splitlines() == expect


def test_example_marks_its_parts():
    """The parts the documentation cuts (// [connect], [configure], [stream] ... // [end])."""
    for proto in PROTOCOLS.values():
        text = (ROOT / "generated/c" / proto["package"] / "examples/configure_and_stream.c").read_text()
        for part in ("connect", "configure", "stream"):
            assert f"// [{part}]" in text
        assert text.count("// [end]") == text.count("// [") - text.count("// [end]")
