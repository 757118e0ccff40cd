"""configure_and_stream ADDRESS [COUNT]: configures a cv7_ins with mipcodec's command session and
prints COUNT data packets (default 5).

ADDRESS is tcp:HOST:PORT or a serial device path (/dev/ttyUSB0, COM3; needs pyserial). The
program pings the device, reads its get device information, writes then reads one setting
(Sensor-to-vehicle frame transformation (Euler)), sets the data message (Message format), enables the stream
(Data stream control) and prints the fields of Sensor (IMU) Data Set (0x80)
through one handler per data descriptor. A NACK, a timeout or a refused command ends it with a
message and exit status 1.

Run it with the package importable (installed, or PYTHONPATH=generated/python/mipcodec).
The documentation quotes the parts between the [...] and [end] comments. Generated: do not edit.
"""

import sys
from typing import Any, List

from mipcodec import Device, Packet, connect, types
from mipcodec.session import SessionError

WAIT_MS = 5000  # how long to wait for the data packets


def run(address: str, count: int) -> int:
    # [connect]
    device = connect(address, device="cv7_ins")  # tcp:HOST:PORT or a serial port path
    with device:
        device.base.ping()
        info = device.base.get_device_info()
        print("device", info)
        # [end]
        configure(device)
        return stream(device, count)


def configure(device: Device) -> None:
    # [configure]
    device.threedm.sensor_to_vehicle_euler.write(roll=0.0, pitch=0.0, yaw=1.5)
    setting = device.threedm.sensor_to_vehicle_euler.read()
    print("setting", setting)
    # [end]


def stream(device: Device, count: int) -> int:
    # [stream]
    packets = 0

    def on_packet(packet: Packet) -> None:
        nonlocal packets
        if packet.set == 0x80:
            packets += 1

    def on_scaled_accel(value: Any, packet: Packet) -> None:
        if packets <= count:  # on_packet has counted this packet
            print("scaled_accel", value)

    def on_scaled_gyro(value: Any, packet: Packet) -> None:
        if packets <= count:  # on_packet has counted this packet
            print("scaled_gyro", value)

    device.on_packet(on_packet)
    device.on_field(0x80, 0x04, on_scaled_accel)
    device.on_field(0x80, 0x05, on_scaled_gyro)
    device.threedm.message_format.write(
        desc_set=0x80,
        descriptors=[
            types.DescriptorRate(descriptor=4, decimation=100),
            types.DescriptorRate(descriptor=5, decimation=100),
        ],
    )
    device.threedm.data_stream_control.write_cv7_ins(desc_set=0x80, enable=True)
    deadline = device.now_ms() + WAIT_MS
    while packets < count and device.now_ms() < deadline:
        device.pump(deadline - device.now_ms())  # data packets reach the handlers
    # [end]
    if packets < count:
        print(f"configure_and_stream: {packets} of {count} data packets in {WAIT_MS} ms", file=sys.stderr)
        return 1
    return 0


def main(argv: List[str]) -> int:
    if len(argv) not in (2, 3) or (len(argv) == 3 and not argv[2].isdigit()):
        print("usage: configure_and_stream ADDRESS [COUNT]", file=sys.stderr)
        return 2
    count = int(argv[2]) if len(argv) == 3 else 5
    try:
        return run(argv[1], count)
    except SessionError as error:  # a NACK, a timeout, a refused command
        print(f"configure_and_stream: {error}", file=sys.stderr)
    except OSError as error:  # cannot connect, connection lost, serial port errors
        print(f"configure_and_stream: {error}", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
