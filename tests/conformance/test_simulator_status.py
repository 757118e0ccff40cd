"""The simulated GX5-45's Device Status (0x0C,0x64) is live (issue 51 item 4; the spec's
`simulation.status` and its decisions, spec/mip/protocol.yaml).

Over TCP at --speed 20, with the internal receiver losing its fix for good at 6 s: the system
timer counts milliseconds since power-on; the stream-enabled flags follow Enable/Disable Device
Data Stream (all on at power-up, GX5-45 line 1049; the GNSS stream is not addressable); the byte
counters count exactly what this host sent and read (no stream runs: the factory formats are
empty); one 1PPS pulse per whole second while the receiver has a fix (from 2 s, the simulator's
time to a fix, until the outage at 6 s); the IMU's messages at its 500 Hz base rate and the
receiver's at 4 Hz while it has a fix. Each expectation follows from the reply's own timer.
"""

from __future__ import annotations

import importlib
import math
import select
import socket
import time

from tests.conformance.test_simulator import Sim
from tests.helpers.generated import python_package

pkg = python_package("mipcodec")
importlib.import_module("mipcodec.codec.framing")
importlib.import_module("mipcodec.codec.packets")
threedm = pkg.threedm
FIX_AFTER = 2  # seconds of simulated time to a 3D fix (sim_world.GNSS_FIX_AFTER)
OUTAGE = 6  # --gnss-outage 6:END
SPEED = 20.0


class Host:
    """A raw TCP host: counts every byte it sends and receives."""

    def __init__(self, address: str) -> None:
        host, port = address.removeprefix("tcp:").rsplit(":", 1)
        self.sock = socket.create_connection((host, int(port)), timeout=10)
        self.parser = pkg.codec.framing.Parser()
        self.sent = 0
        self.received = 0

    def ask(self, value):
        raw = pkg.codec.framing.PacketBuilder(value.SET).add(value).build()
        received_before = self.received
        self.sock.sendall(raw)
        self.sent += len(raw)
        end = time.monotonic() + 10
        while time.monotonic() < end:
            ready, _, _ = select.select([self.sock], [], [], 1)
            if not ready:
                continue
            data = self.sock.recv(65536)
            assert data, "the simulator closed the connection"
            self.received += len(data)
            for event in self.parser.feed(data):
                if isinstance(event, pkg.codec.framing.RawPacket):
                    packet = pkg.codec.packets.decode_packet(event.data, device="gx5_45")
                    fields = [f.value for f in packet.fields]
                    if packet.set == value.SET and fields[0].command_descriptor == value.DESCRIPTOR:
                        assert int(fields[0].ack_code) == 0, fields
                        return fields[1:], received_before
        raise AssertionError(f"no reply to {value}")

    def status(self, selector: int):
        fields, before = self.ask(threedm.DeviceStatus(model_number=6251, status_selector=selector))
        return fields[0].status, before


def test_device_status_is_live() -> None:
    with Sim("mip", "gx5_45", "tcp:127.0.0.1:0", "--speed", str(SPEED), "--gnss-outage", f"{OUTAGE}:1000000") as sim:
        host = Host(sim.address)
        try:
            basic, _ = host.status(1)
            assert 0 < basic.system_timer < 60_000 * SPEED
            start = time.monotonic()
            first, before = host.status(2)
            assert first.system_timer >= basic.system_timer
            assert (first.imu_stream_enabled, first.gnss_stream_enabled, first.filter_stream_enabled) == (1, 1, 1)
            assert first.gnss_power_state == 1
            assert first.com_bytes_read == host.sent  # this command included
            assert first.com_bytes_written == before  # every reply before this one
            # the IMU stream off: its flag follows; the filter's stays, the GNSS one is not addressable
            host.ask(threedm.DataStreamControl_gx5_45(function=1, device_selector=1, enable=0))
            while time.monotonic() - start < (OUTAGE + 1.5) / SPEED:  # past the outage
                time.sleep(0.05)
            late, before = host.status(2)
            assert (late.imu_stream_enabled, late.gnss_stream_enabled, late.filter_stream_enabled) == (0, 1, 1)
            assert late.com_bytes_read == host.sent and late.com_bytes_written == before
            for s in (first, late):
                seconds = s.system_timer / 1000.0
                fixed = [k for k in range(FIX_AFTER, math.floor(seconds) + 1) if k < OUTAGE]
                assert s.pps_pulse_count == len(fixed), (seconds, s)
                assert s.last_pps_time == (fixed[-1] * 1000 if fixed else 0), (seconds, s)
                assert abs(s.imu_messages_read - math.floor(seconds * 500)) <= 1, (seconds, s)
                assert abs(s.last_imu_message_time - s.system_timer) <= 2, (seconds, s)
                ticks = [k for k in range(FIX_AFTER * 4, math.floor(seconds * 4) + 1) if k < OUTAGE * 4]
                assert abs(s.gnss_messages_read - len(ticks)) <= 1, (seconds, s)
            assert late.system_timer >= 1000 * (OUTAGE + 1)  # simulated time runs at --speed
            assert late.pps_pulse_count == OUTAGE - FIX_AFTER and late.last_pps_time == (OUTAGE - 1) * 1000
            assert late.gnss_messages_read == (OUTAGE - FIX_AFTER) * 4
            assert late.last_gnss_message_time == OUTAGE * 1000 - 250
            assert (late.imu_parse_errors, late.gnss_parse_errors, late.status_flags) == (0, 0, 0)
        finally:
            host.sock.close()
