"""The simulator's link features (docs/conformance.md section 9, issue 40): `--listen pty:PATH`
(a symbolic link to the pty), `--replug START:END` (the port goes away and comes back, the device
keeping its settings), `--stream-full` (every data quantity at the base rate from power-up) and
`--start-baud` (the device's port at another rate than the host's). The sessions' behaviour over
them is tests/conformance/test_link.py."""

from __future__ import annotations

import errno
import importlib
import os
import socket
import time
from pathlib import Path

import pytest

from tests.conformance.test_simulator import Sim
from tests.helpers.generated import python_package

pkg = python_package("mipcodec")
sim_mod = importlib.import_module("mipcodec.sim")
session = importlib.import_module("mipcodec.session")
transport = importlib.import_module("mipcodec.session.transport")
capabilities = importlib.import_module("mipcodec.capabilities")
framing = importlib.import_module("mipcodec.codec.framing")

# GX5-45 base rates (3dm-gx5-45-dcp.txt lines 375, 387, 973): IMU and filter 500 Hz, GNSS 4 Hz.
GX5_RATES = {0x80: 500, 0x81: 4, 0x82: 500}


def _packets(chunks) -> list[bytes]:
    parser = framing.Parser()
    out = []
    for _, data in chunks:
        out += [e.data for e in parser.feed(data) if isinstance(e, framing.RawPacket)]
    return out


def _descriptors(packet: bytes) -> list[int]:
    """The field descriptors of a MIP packet (length byte first, counting its header)."""
    out, i = [], 4
    while i < 4 + packet[3]:
        out.append(packet[i + 1])
        i += packet[i]
    return out


def test_stream_full_streams_every_documented_quantity_at_the_base_rate() -> None:
    sim = sim_mod.Simulator("gx5_45", stream_full=True)
    sim.poll(0.0)
    # ticks 1 .. 100 of the 500 Hz sets: 0.2 s of samples, polled every 10 ms as the serving loop
    # does (a poll late by more than 20 ms drops the older ticks, as an overrun output buffer)
    chunks = [c for k in range(1, 21) for c in sim.poll(k / 100)]
    seen: dict[int, list[int]] = {}
    for p in _packets(chunks):
        seen.setdefault(p[2], []).extend(_descriptors(p))
    documented = {s: {d for ss, d in capabilities.MODELS["gx5_45"].data if ss == s} for s in GX5_RATES}
    for set_id in (0x80, 0x82):
        assert set(seen[set_id]) == documented[set_id], set_id
        # every quantity once per tick of 500 Hz in 0.2 s: decimation 1
        assert all(seen[set_id].count(d) == 100 for d in documented[set_id]), set_id
    # idle stops every stream, resume restarts it (GX5-45 lines 363, 834)
    chunks = sim.feed(_command(pkg.base.SetToIdle()), 0.2) + sim.poll(0.4)
    assert [p for p in _packets(chunks) if p[2] >= 0x80] == []
    chunks = sim.feed(_command(pkg.base.Resume()), 0.4) + [c for k in range(41, 51) for c in sim.poll(k / 100)]
    assert len([p for p in _packets(chunks) if p[2] == 0x80]) >= 40
    assert sum(len(d) for _, d in sim.poll(1.5)) < 20 * 1024  # 1 s late: only the last 20 ms


def _command(field) -> bytes:
    b = framing.PacketBuilder(field.SET)
    b.add(field)
    return b.build()


def test_without_stream_full_the_factory_formats_stream() -> None:
    sim = sim_mod.Simulator("gx5_45")
    sim.poll(0.0)
    assert sum(len(_descriptors(p)) for p in _packets(sim.poll(0.2))) < 50  # not the full rate


def test_pty_path_is_a_link_replaced_when_the_port_is_replugged(tmp_path: Path) -> None:
    path = tmp_path / "dev"
    with Sim("mip", "gx5_45", f"pty:{path}", "--replug", "0.6:1.2") as sim:
        assert sim.address == str(path)
        first = os.readlink(path)
        assert first.startswith("/dev/pts/")
        dev = session.Device(transport.open_transport(str(path)), device="gx5_45", timeout_ms=300)
        try:
            dev.base.ping()  # the replug clock starts at these first bytes
            dev.threedm.uart_baudrate.write(baud=230400)  # kept across the replug (no --baud: the pty ignores it)
            deadline = time.monotonic() + 5
            with pytest.raises(transport.TransportError):
                while time.monotonic() < deadline:
                    dev.pump(50)
            assert not os.path.lexists(path)  # gone while unplugged
        finally:
            dev.transport.close()
        deadline = time.monotonic() + 5
        while not os.path.lexists(path) and time.monotonic() < deadline:
            time.sleep(0.02)
        assert os.path.islink(path) and os.readlink(path).startswith("/dev/pts/")
        dev = session.Device(transport.open_transport(str(path)), device="gx5_45", timeout_ms=1000)
        try:
            dev.base.ping()
            assert dev.threedm.uart_baudrate.read().baud == 230400
        finally:
            dev.transport.close()


def test_tcp_replug_closes_the_connection_and_listens_again() -> None:
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", "--replug", "0.5:1.0") as sim:
        kind, (host, port) = transport.parse_address(sim.address)
        dev = session.Device(transport.open_transport(sim.address), device="cv7_ins", timeout_ms=300)
        try:
            dev.base.ping()
            deadline = time.monotonic() + 5
            with pytest.raises(transport.TransportError):
                while time.monotonic() < deadline:
                    dev.pump(50)
        finally:
            dev.transport.close()
        with pytest.raises(OSError) as refused:
            socket.create_connection((host, port), timeout=1).close()
        assert refused.value.errno == errno.ECONNREFUSED
        time.sleep(0.6)
        dev = session.Device(transport.open_transport(sim.address), device="cv7_ins", timeout_ms=300)
        try:
            dev.base.ping()
        finally:
            dev.transport.close()


def test_start_baud_serves_only_a_host_at_that_rate() -> None:
    with Sim("mip", "gx5_45", "pty", "--start-baud", "921600") as sim:
        dev = session.Device(transport.open_transport(sim.address, 115200), device="gx5_45", timeout_ms=300)
        try:
            with pytest.raises(session.CommandTimeout):
                dev.base.ping()
        finally:
            dev.transport.close()
        dev = session.Device(transport.open_transport(sim.address, 921600), device="gx5_45", timeout_ms=300)
        try:
            dev.base.ping()
        finally:
            dev.transport.close()


def test_bad_link_options_are_usage_errors(tmp_path: Path) -> None:
    import subprocess

    from tests.conformance.test_simulator import SIMULATE

    regular = tmp_path / "file"
    regular.write_text("")
    for args, words in (
        (["--listen", f"pty:{regular}"], "is not a symbolic link"),
        (["--listen", "tcp:127.0.0.1:0", "--start-baud", "921600"], "--start-baud needs --listen pty"),
        (["--listen", "pty", "--start-baud", "12345"], "not a baud rate"),
        (["--listen", "pty", "--replug", "2:1"], "--replug 2:1: expected 0 <= START < END"),
    ):
        run = subprocess.run([str(SIMULATE), *args], capture_output=True, text=True, timeout=60)
        assert run.returncode == 2 and words in run.stderr and "Traceback" not in run.stderr, (args, run.stderr)
