"""gx5_polling ADDRESS [--samples N] [--deadline-s N]

A 3DM-GX5-45 application polling for data the way the manual's polling example does
(3dm-gx5-45-dcp.txt section 2.4.2), written against the generated `mipcodec` package (contract:
tests/apps/README.md): idle, device information, the IMU and estimation filter message formats
(written, the streams not resumed: the device stays idle), Initialize the Filter as step 7 does
(poll the complementary filter's Euler angles, Set Initial Attitude with them); then every 100 ms a
Poll IMU Data and a Poll Estimation Filter Data command (ACK/NACK not suppressed), each answered by
its ACK and one data packet. It prints the filter state on each change and, once the solution is
valid, the navigation samples. Run it with the package importable
(PYTHONPATH=generated/python/mipcodec).
"""

from __future__ import annotations

import argparse
import json
import sys
from typing import Any, Dict, List, Optional

from mipcodec import Device, Packet, connect, types
from mipcodec.session import SessionError

PROG = "gx5_polling"
USAGE = f"usage: {PROG} ADDRESS [--samples N>0] [--deadline-s N>0]"
IMU_SET, FILTER_SET = 0x80, 0x82
SCALED_ACCEL, SCALED_GYRO, CF_EULER = 0x04, 0x05, 0x0C
GPS_TIMESTAMP, FILTER_STATUS, LLH, EULER = 0x11, 0x10, 0x01, 0x05
IMU_RATE_HZ, FILTER_RATE_HZ = 100, 10
POLL_PERIOD_MS = 100
IMU_FIELDS = (SCALED_ACCEL, SCALED_GYRO)
FILTER_FIELDS = (GPS_TIMESTAMP, FILTER_STATUS, LLH, EULER)
RUN_SOLUTION_VALID = types.FilterStateGx5.RUN_SOLUTION_VALID


def text(raw: bytes) -> str:
    """A device information string without its padding."""
    return raw.decode("ascii", "replace").strip(" \0")


def configure(device: Device) -> None:
    device.base.ping()
    device.base.set_to_idle()
    info = device.base.get_device_info().info
    print(f"model {text(info.model_name)}", flush=True)
    print(f"serial {text(info.serial_number)}", flush=True)
    print(f"firmware {info.firmware_version}", flush=True)
    imu_base = device.threedm.get_imu_base_rate().rate
    filter_base = device.threedm.get_filter_base_rate().rate
    if imu_base < IMU_RATE_HZ or filter_base < FILTER_RATE_HZ:
        raise ValueError(f"base rates {imu_base} Hz (IMU) and {filter_base} Hz (filter) are too low")
    imu = [types.DescriptorRate(descriptor=d, decimation=imu_base // IMU_RATE_HZ) for d in IMU_FIELDS]
    device.threedm.imu_message_format.write(descriptors=imu)
    nav = [types.DescriptorRate(descriptor=d, decimation=filter_base // FILTER_RATE_HZ) for d in FILTER_FIELDS]
    device.threedm.filter_message_format.write(descriptors=nav)
    # no resume: the device stays idle and answers polls only
    initialize_filter(device)


def initialize_filter(device: Device) -> None:
    """The manual's step 7, Initialize the Filter (3dm-gx5-45-dcp.txt line 431): poll the
    complementary filter's Euler angles (0x80,0x0C), then Set Initial Attitude (0x0D,0x02) with
    them. (A device with auto-initialization enabled does not need it; its factory setting is not
    documented, so the program does not rely on it.)"""
    angles: List[Any] = []
    device.on_field(IMU_SET, CF_EULER, lambda value, packet: angles.append(value))
    device.threedm.poll_imu_data(
        option=types.Gx5PollOption.NORMAL, descriptors=[types.Gx5PollDescriptor(descriptor=CF_EULER)]
    )
    end = device.now_ms() + 1000  # the data packet follows the ACK
    while not angles and device.now_ms() < end:
        device.pump(10)
    if not angles:
        raise TimeoutError("no complementary filter Euler angles (0x80,0x0C) after the poll")
    device.filter.set_initial_attitude(roll=angles[0].roll, pitch=angles[0].pitch, heading=angles[0].yaw)


def poll(device: Device) -> None:
    """One Poll IMU Data and one Poll Estimation Filter Data (the ACK, then one data packet each)."""
    normal = types.Gx5PollOption.NORMAL
    device.threedm.poll_imu_data(option=normal, descriptors=[types.Gx5PollDescriptor(descriptor=d) for d in IMU_FIELDS])
    device.threedm.poll_filter_data(
        option=normal, descriptors=[types.Gx5PollDescriptor(descriptor=d) for d in FILTER_FIELDS]
    )


def poll_data(device: Device, samples: int, deadline_ms: int) -> int:
    state: Dict[str, Optional[int]] = {"filter": None}
    imu_seen = False
    printed = 0

    def on_packet(packet: Packet) -> None:
        nonlocal imu_seen, printed
        values = {f.descriptor: f.value for f in packet.fields}
        if packet.set == IMU_SET:
            if not imu_seen and SCALED_ACCEL in values and SCALED_GYRO in values:
                imu_seen = True
                print("imu ok", flush=True)
            return
        if packet.set != FILTER_SET or FILTER_STATUS not in values:
            return
        filter_state = int(values[FILTER_STATUS].filter_state)
        if filter_state != state["filter"]:
            state["filter"] = filter_state
            print(f"state {filter_state}", flush=True)
        if (
            filter_state == RUN_SOLUTION_VALID
            and printed < samples
            and all(d in values for d in (GPS_TIMESTAMP, LLH, EULER))
        ):
            llh, euler = values[LLH], values[EULER]
            sample = {
                "tow": values[GPS_TIMESTAMP].tow,
                "lat": llh.latitude,
                "lon": llh.longitude,
                "height": llh.ellipsoid_height,
                "euler": [euler.roll, euler.pitch, euler.yaw],
                "llh_valid": int(llh.valid_flags),
                "euler_valid": int(euler.valid_flags),
            }
            print(json.dumps(sample, separators=(",", ":")), flush=True)
            printed += 1

    device.on_packet(on_packet)
    next_poll = device.now_ms()
    while printed < samples:
        now = device.now_ms()
        left = deadline_ms - now
        if left <= 0:
            print(
                f"error: {printed} of {samples} valid-solution samples before the deadline (filter state {state['filter']})",
                file=sys.stderr,
            )
            return 1
        if now >= next_poll:
            poll(device)
            next_poll += POLL_PERIOD_MS
            if next_poll < now:  # after a stall: a period from now, not a burst
                next_poll = now + POLL_PERIOD_MS
        device.pump(max(1, min(next_poll, deadline_ms) - device.now_ms()))
    return 0


def main(argv: List[str]) -> int:
    parser = argparse.ArgumentParser(prog=PROG, add_help=True)
    parser.add_argument("address")
    parser.add_argument("--samples", type=int, default=20)
    parser.add_argument("--deadline-s", type=float, default=60.0)
    try:
        args = parser.parse_args(argv[1:])
    except SystemExit as exit_:  # argparse printed `usage: ...` and the error
        return 2 if exit_.code else 0
    if args.samples <= 0 or args.deadline_s <= 0:
        print(USAGE, file=sys.stderr)
        return 2
    try:
        with connect(args.address, device="gx5_45") as device:
            deadline_ms = device.now_ms() + int(args.deadline_s * 1000)
            configure(device)
            return poll_data(device, args.samples, deadline_ms)
    except (SessionError, OSError, ValueError) as error:  # nack, timeout, refusal; connection
        print(f"error: {error}", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
