"""The C++ configure-and-stream example (generated/cpp/mipcodec/examples/configure_and_stream.cpp)
built and run over loopback TCP against the scripted fake device: ping, device information, write
and read of the sensor-to-vehicle rotation, the data stream switched on, then data packets."""

from __future__ import annotations

import subprocess
from pathlib import Path

from generator.spec import load_spec
from tests.conformance.fake_device import FakeDevice
from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
CPP = ROOT / "tests" / "lang" / "cpp.sh"


def _script(pkg) -> dict:
    """A fake-device case: the example's five commands, each answered, then four data packets."""

    def ack(set_id: int, descriptor: int, *reply) -> str:
        b = pkg.PacketBuilder(set_id).add(pkg.reserved.AckNack(command_descriptor=descriptor, ack_code=0))
        for r in reply:
            b.add(r)
        return b.build().hex()

    def _one(set_id: int, value) -> str:
        return pkg.PacketBuilder(set_id).add(value).build().hex()

    info = pkg.types.DeviceInfo(firmware_version=1234, model_name=b"3DM-CV7-INS     ")
    rotation = pkg.threedm.SensorToVehicleEulerResponse(roll=0.0, pitch=1.5708, yaw=1.5708)
    data = _one(0x80, pkg.sensor.ScaledAccel(scaled_accel=(0.0, 0.0, -1.0)))
    steps = []
    replies = [
        ack(0x01, 0x01),
        ack(0x01, 0x03, pkg.base.DeviceInfo(info=info)),
        ack(0x0C, 0x31),
        ack(0x0C, 0x31, rotation),
        ack(0x0C, 0x11),
    ]
    for i, reply in enumerate(replies):
        steps.append({"at": i * 10, "send": "", "bytes": None})
        steps.append({"at": i * 10 + 1, "receive": reply + (data * 4 if i == len(replies) - 1 else "")})
    return {"steps": steps, "expect": []}


def test_configure_and_stream_example():
    pkg = python_package("mipcodec")
    framing = next(p for p in load_spec()["protocols"] if p["name"] == "mip")["framing"]
    build = subprocess.run([str(CPP), "configure-and-stream-build"], capture_output=True, text=True, timeout=900)
    assert build.returncode == 0, build.stderr
    exe = build.stdout.strip()
    dev = FakeDevice(_script(pkg), framing).start()
    proc = subprocess.run([exe, f"tcp:127.0.0.1:{dev.port}", "4"], capture_output=True, text=True, timeout=60)
    dev.join(10)
    assert dev.errors == []
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert lines[0] == "model 3DM-CV7-INS     , firmware 1234"
    assert lines[1] == "rotation roll=0 pitch=1.5708 yaw=1.5708"
    assert lines[2:] == ["data packet: set 0x80, 20 bytes"] * 4
    # What the device received: (set, descriptor) of the five commands, then the functions sent.
    assert [(p[2], p[5]) for p in dev.received] == [
        (0x01, 0x01),
        (0x01, 0x03),
        (0x0C, 0x31),
        (0x0C, 0x31),
        (0x0C, 0x11),
    ]
    assert [p[6] for p in dev.received[2:]] == [1, 2, 1]  # write, read, write
