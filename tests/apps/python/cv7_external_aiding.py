"""cv7_external_aiding ADDRESS FEED [--period-ms N] [--samples N] [--deadline-s N]

A CV7-INS navigation application with external aiding, written against the generated `mipcodec`
package the way a user writes one (contract: tests/apps/README.md): it configures the device as the
manual's external-aiding flow does, then sends heading, position and velocity measurements from its
aiding sensors (here a feed file) every period until the filter reports full navigation, and prints
the navigation samples. Run it with the package importable (PYTHONPATH=generated/python/mipcodec).
"""

from __future__ import annotations

import argparse
import bisect
import json
import sys
from typing import Dict, List, Optional

from mipcodec import Device, Packet, connect, types
from mipcodec.session import SessionError

FILTER_SET = 0x82
GPS_TIMESTAMP, FILTER_STATUS, LLH, NED_VELOCITY, EULER = 0x11, 0x10, 0x01, 0x02, 0x05
HEADING_FRAME, GNSS_FRAME, BODY_VELOCITY_FRAME = 1, 2, 3
FULL_NAV = types.FilterModeCv7.FULL_NAV


class Feed:
    """The aiding sensors: rows `tow ns lat lon height vn ve vd heading bx by bz`, sorted by tow."""

    def __init__(self, path: str) -> None:
        self.rows: List[List[float]] = []
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                if line.strip() and not line.lstrip().startswith("#"):
                    words = line.split()
                    if len(words) != 12:
                        raise ValueError(f"{path}:{number}: 12 numbers expected, got {len(words)}")
                    self.rows.append([float(w) for w in words])
        if not self.rows:
            raise ValueError(f"{path}: no rows")
        self.tows = [r[0] for r in self.rows]

    def nearest(self, tow: float) -> List[float]:
        i = bisect.bisect_left(self.tows, tow)
        candidates = self.rows[max(0, i - 1) : i + 1]
        return min(candidates, key=lambda r: abs(r[0] - tow))


def configure(device: Device) -> None:
    device.base.ping()
    device.base.set_to_idle()
    device.base.get_device_info()
    device.threedm.device_startup_settings.default()
    device.threedm.capture_gyro_bias(averaging_time_ms=2000)  # replies after the capture
    rate = device.threedm.get_base_rate(desc_set=FILTER_SET).rate
    decimation = max(1, rate // 10)  # 10 Hz
    fields = (GPS_TIMESTAMP, FILTER_STATUS, LLH, NED_VELOCITY, EULER)
    device.threedm.message_format.write(
        desc_set=FILTER_SET, descriptors=[types.DescriptorRate(descriptor=d, decimation=decimation) for d in fields]
    )
    for frame in (HEADING_FRAME, GNSS_FRAME, BODY_VELOCITY_FRAME):
        device.aiding.frame_config.write(
            frame_id=frame,
            format=types.AidingFrameFormat.EULER,
            tracking_enabled=False,
            translation=[0.0, 0.0, 0.0],
            rotation=types.AidingFrameEuler([0.0, 0.0, 0.0]),
        )
    for source in (types.AidingMeasurementSource.GNSS_POS_VEL, types.AidingMeasurementSource.EXTERNAL_HEADING):
        device.filter.aiding_measurement_control.write(source=source, enable=True)
    device.filter.initialization_configuration.write(
        wait_for_run_command=0,
        initial_cond_src=types.FilterInitialConditionSource.AUTO_POS_VEL_ATT,
        auto_heading_alignment_selector=types.HeadingAlignmentMethods(0x08),  # external heading
        initial_heading=0.0,
        initial_pitch=0.0,
        initial_roll=0.0,
        initial_position=[0.0] * 3,
        initial_velocity=[0.0] * 3,
        reference_frame_selector=types.FilterReferenceFrame.LLH,
    )
    device.filter.reset_filter()
    device.base.resume()


def send_aiding(device: Device, row: List[float]) -> None:
    _, ns, lat, lon, height, vn, ve, vd, heading, bx, by, bz = row
    stamp = types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, nanoseconds=int(ns))
    arrival = types.AidingTime(timebase=types.AidingTimebase.TIME_OF_ARRIVAL)
    device.aiding.true_heading(time=stamp, frame_id=HEADING_FRAME, heading=heading, uncertainty=0.01, valid_flags=1)
    device.aiding.llh_position(
        time=stamp,
        frame_id=GNSS_FRAME,
        latitude=lat,
        longitude=lon,
        height=height,
        uncertainty=[1.0] * 3,
        valid_flags=types.AidingLlhValidFlags(7),
    )
    device.aiding.ned_velocity(
        time=stamp,
        frame_id=GNSS_FRAME,
        velocity=[vn, ve, vd],
        uncertainty=[0.1] * 3,
        valid_flags=types.AidingVectorValidFlags(7),
    )
    device.aiding.body_frame_velocity(
        time=arrival,
        frame_id=BODY_VELOCITY_FRAME,
        velocity=[bx, by, bz],
        uncertainty=[0.1] * 3,
        valid_flags=types.AidingVectorValidFlags(7),
    )


def navigate(device: Device, feed: Feed, period_ms: int, samples: int, deadline_s: float) -> int:
    state: Dict[str, Optional[float]] = {"tow": None, "mode": None}
    printed = 0

    def on_filter_packet(packet: Packet) -> None:
        nonlocal printed
        if packet.set != FILTER_SET:
            return
        values = {f.descriptor: f.value for f in packet.fields}
        if GPS_TIMESTAMP in values:
            state["tow"] = values[GPS_TIMESTAMP].tow
        status = values.get(FILTER_STATUS)
        if status is None:
            return
        mode = int(status.filter_state)
        if mode != state["mode"]:
            state["mode"] = mode
            print(f"mode {mode}", flush=True)
        if (
            mode == FULL_NAV
            and printed < samples
            and all(d in values for d in (GPS_TIMESTAMP, LLH, NED_VELOCITY, EULER))
        ):
            llh, vel, euler = values[LLH], values[NED_VELOCITY], values[EULER]
            sample = {
                "tow": values[GPS_TIMESTAMP].tow,
                "lat": llh.latitude,
                "lon": llh.longitude,
                "height": llh.ellipsoid_height,
                "vel": [vel.north, vel.east, vel.down],
                "euler": [euler.roll, euler.pitch, euler.yaw],
                "llh_valid": int(llh.valid_flags),
                "euler_valid": int(euler.valid_flags),
            }
            print(json.dumps(sample, separators=(",", ":")), flush=True)
            printed += 1

    device.on_packet(on_filter_packet)
    deadline = device.now_ms() + int(deadline_s * 1000)
    next_send = device.now_ms()
    while printed < samples:
        now = device.now_ms()
        if now >= deadline:
            print(f"error: {printed} of {samples} navigation samples before the deadline", file=sys.stderr)
            return 1
        if now >= next_send:
            if state["tow"] is not None:
                send_aiding(device, feed.nearest(state["tow"]))
            next_send = now + period_ms
        device.pump(max(1, min(next_send, deadline) - device.now_ms()))
    return 0


def main(argv: List[str]) -> int:
    parser = argparse.ArgumentParser(prog="cv7_external_aiding", add_help=True)
    parser.add_argument("address")
    parser.add_argument("feed")
    parser.add_argument("--period-ms", type=int, default=500)
    parser.add_argument("--samples", type=int, default=30)
    parser.add_argument("--deadline-s", type=float, default=60.0)
    try:
        args = parser.parse_args(argv[1:])
    except SystemExit as exit_:  # argparse printed `usage: ...` and the error
        return 2 if exit_.code else 0
    if args.period_ms <= 0 or args.samples <= 0 or args.deadline_s <= 0:
        print(
            "usage: cv7_external_aiding ADDRESS FEED [--period-ms N>0] [--samples N>0] [--deadline-s N>0]",
            file=sys.stderr,
        )
        return 2
    try:
        feed = Feed(args.feed)
        with connect(args.address, device="cv7_ins") as device:
            configure(device)
            return navigate(device, feed, args.period_ms, args.samples, args.deadline_s)
    except (SessionError, OSError, ValueError) as error:  # nack, timeout, refusal; connection; feed
        print(f"error: {error}", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
