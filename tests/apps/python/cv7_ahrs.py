"""cv7_ahrs ADDRESS [--samples N] [--deadline-s N]

A 3DM-CV7-GNSS/INS used as an AHRS on its own magnetometer, the manual's getting-started flow
(3dm-cv7-ins-docs.txt "Getting Started", "Filter Initialization", "Filter Aiding Measurements"),
written against the generated `mipcodec` package (contract: tests/apps/README.md): idle, device
information, the filter data message (GPS time, status, Euler angles at 10 Hz), the magnetometer as
the only aiding measurement, heading initialized from the magnetometer, filter reset, resume. It
prints the filter mode on each change and, once in AHRS mode or better, the attitude samples. Run
it with the package importable (PYTHONPATH=generated/python/mipcodec).
"""

from __future__ import annotations

import argparse
import json
import sys
from typing import Dict, List, Optional

from mipcodec import Device, Packet, connect, types
from mipcodec.session import SessionError

PROG = "cv7_ahrs"
USAGE = f"usage: {PROG} ADDRESS [--samples N>0] [--deadline-s N>0]"
FILTER_SET = 0x82
GPS_TIMESTAMP, FILTER_STATUS, EULER = 0x11, 0x10, 0x05
RATE_HZ = 10
AHRS = types.FilterModeCv7.AHRS
SOURCES = types.AidingMeasurementSource


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
    base = device.threedm.get_base_rate(desc_set=FILTER_SET).rate
    if base < RATE_HZ:
        raise ValueError(f"the filter data base rate is {base} Hz, below {RATE_HZ} Hz")
    fields = (GPS_TIMESTAMP, FILTER_STATUS, EULER)
    device.threedm.message_format.write(
        desc_set=FILTER_SET,
        descriptors=[types.DescriptorRate(descriptor=d, decimation=base // RATE_HZ) for d in fields],
    )
    device.filter.aiding_measurement_control.write(source=SOURCES.MAGNETOMETER, enable=True)
    device.filter.aiding_measurement_control.write(source=SOURCES.GNSS_POS_VEL, enable=False)
    device.filter.aiding_measurement_control.write(source=SOURCES.GNSS_HEADING, enable=False)
    device.filter.initialization_configuration.write(
        wait_for_run_command=0,
        initial_cond_src=types.FilterInitialConditionSource.AUTO_POS_VEL_ATT,
        auto_heading_alignment_selector=types.HeadingAlignmentMethods(types.HeadingAlignmentMethods.MAGNETOMETER),
        initial_heading=0.0,
        initial_pitch=0.0,
        initial_roll=0.0,
        initial_position=[0.0] * 3,
        initial_velocity=[0.0] * 3,
        reference_frame_selector=types.FilterReferenceFrame.LLH,
    )
    device.filter.reset_filter()
    device.base.resume()


def read_attitude(device: Device, samples: int, deadline_ms: int) -> int:
    state: Dict[str, Optional[int]] = {"mode": None}
    printed = 0

    def on_packet(packet: Packet) -> None:
        nonlocal printed
        if packet.set != FILTER_SET:
            return
        values = {f.descriptor: f.value for f in packet.fields}
        status = values.get(FILTER_STATUS)
        if status is None:
            return
        mode = int(status.filter_state)
        if mode != state["mode"]:
            state["mode"] = mode
            print(f"mode {mode}", flush=True)
        if mode >= AHRS and printed < samples and GPS_TIMESTAMP in values and EULER in values:
            euler = values[EULER]
            sample = {
                "tow": values[GPS_TIMESTAMP].tow,
                "euler": [euler.roll, euler.pitch, euler.yaw],
                "euler_valid": int(euler.valid_flags),
            }
            print(json.dumps(sample, separators=(",", ":")), flush=True)
            printed += 1

    device.on_packet(on_packet)
    while printed < samples:
        left = deadline_ms - device.now_ms()
        if left <= 0:
            print(
                f"error: {printed} of {samples} AHRS samples before the deadline (filter mode {state['mode']})",
                file=sys.stderr,
            )
            return 1
        device.pump(min(left, 50))
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
        with connect(args.address, device="cv7_ins") as device:
            deadline_ms = device.now_ms() + int(args.deadline_s * 1000)
            configure(device)
            return read_attitude(device, args.samples, deadline_ms)
    except (SessionError, OSError, ValueError) as error:  # nack, timeout, refusal; connection
        print(f"error: {error}", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
