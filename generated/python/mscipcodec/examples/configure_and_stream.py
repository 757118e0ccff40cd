"""configure_and_stream ADDRESS [COUNT]: configures a ms_imu3020 with mscipcodec's command session and
prints COUNT data packets (default 5).

ADDRESS is tcp:HOST:PORT or a serial device path (/dev/ttyUSB0, COM3; needs pyserial). The
program pings the device, reads its get device model, writes then reads one setting
(IMU sample rate configure), sets the data message (Select sensors (Rev A)), enables the stream
(Data on/off) and prints the fields of IMU Data Message (0xA2)
through one handler per data descriptor. A NACK, a timeout or a refused command ends it with a
message and exit status 1.

Run it with the package importable (installed, or PYTHONPATH=generated/python/mscipcodec).
The documentation quotes the parts between the [...] and [end] comments. Generated: do not edit.
"""

import sys
from typing import Any, List

from mscipcodec import Device, Packet, connect, types
from mscipcodec.session import SessionError

WAIT_MS = 5000  # how long to wait for the data packets


def run(address: str, count: int) -> int:
    # [connect]
    device = connect(address, device="ms_imu3020")  # tcp:HOST:PORT or a serial port path
    with device:
        device.base.ping()
        info = device.base.get_device_model()
        print("device", info)
        # [end]
        configure(device)
        return stream(device, count)


def configure(device: Device) -> None:
    # [configure]
    device.imu_config.sample_rate.write(decimation=10)
    setting = device.imu_config.sample_rate.read()
    print("setting", setting)
    # [end]


def stream(device: Device, count: int) -> int:
    # [stream]
    packets = 0

    def on_packet(packet: Packet) -> None:
        nonlocal packets
        if packet.set == 0xA2:
            packets += 1

    def on_scaled_accel(value: Any, packet: Packet) -> None:
        if packets <= count:  # on_packet has counted this packet
            print("scaled_accel", value)

    def on_scaled_gyro(value: Any, packet: Packet) -> None:
        if packets <= count:  # on_packet has counted this packet
            print("scaled_gyro", value)

    device.on_packet(on_packet)
    device.on_field(0xA2, 0x81, on_scaled_accel)
    device.on_field(0xA2, 0x82, on_scaled_gyro)
    device.imu_config.select_sensors.write(
        reserved=0, sensors=[types.SensorCode.SCALED_ACCEL, types.SensorCode.SCALED_GYRO]
    )
    device.imu_config.data_on_off.write(control=types.OnOff.ON)
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
