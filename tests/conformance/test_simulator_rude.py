"""The simulator under rude hosts and bad options (issue 37, docs/conformance.md section 9,
"Hosts that misbehave" and "Validation"): a host may flood commands without reading, stall,
send noise, leave half a packet or vanish at once while data streams, and the other hosts (served
at the same time, docs/conformance.md section 9 "Several hosts") and the next are served cleanly, with the
simulator's memory bounded; a stream turned on again (or a host connecting to a
streaming device) resumes from now, without samples dated in the time nobody received them;
every option and scenario file outside its stated range is one line on stderr and exit 2, files
read no further than their stated limit; a baud rate the model's port does not list is refused
with NACK invalid parameter.

The hosts are raw TCP sockets (what a rude client does is below any session) and the Python
`Device`; the simulator runs as `tests/conformance/simulate` (TCP on 127.0.0.1, or a pty)."""

from __future__ import annotations

import importlib
import os
import random
import resource
import socket
import struct
import subprocess
import time
from pathlib import Path
from typing import List

import pytest

from tests.conformance.test_simulator import SIMULATE, Sim
from tests.helpers.generated import python_package

pkg = python_package("mipcodec")
sim_mod = importlib.import_module("mipcodec.sim")
session = importlib.import_module("mipcodec.session")
transport = importlib.import_module("mipcodec.session.transport")
framing = importlib.import_module("mipcodec.codec.framing")
packets = importlib.import_module("mipcodec.codec.packets")
types = importlib.import_module("mipcodec.types")

# The simulator's stated bounds (docs/conformance.md section 9): a TCP host that reads nothing for
# 5 s while output waits is disconnected; at most 256 KiB (32 KiB with --stream-full) wait for it.
STALL_S = 5.0
# The memory a bounded simulator may gain while a host misbehaves: its output backlog, one read of
# 64 KiB, one partial packet and the interpreter's own slack, far below what the floods send.
SLACK_KB = 12 * 1024


def _command(field) -> bytes:
    b = framing.PacketBuilder(field.SET)
    b.add(field)
    return b.build()


PING = _command(pkg.base.Ping())


def _rss_kb(pid: int, item: str = "VmRSS") -> int:
    """The resident memory of a process in KiB (VmHWM: its peak so far)."""
    with open(f"/proc/{pid}/status") as f:
        return next(int(line.split()[1]) for line in f if line.startswith(item + ":"))


def _closed_by_peer(sock: socket.socket, within: float) -> bool:
    """Whether the other side closes `sock` (end of file or a reset) within `within` seconds,
    reading and discarding what it sent."""
    sock.settimeout(0.2)
    deadline = time.monotonic() + within
    while time.monotonic() < deadline:
        try:
            if not sock.recv(1 << 20):
                return True
        except socket.timeout:
            continue
        except OSError:
            return True
    return False


def _port(sim: Sim) -> int:
    return int(sim.address.rsplit(":", 1)[1])


def _replies(sock: socket.socket, seconds: float, want: int = 1) -> List[bytes]:
    """The command-set packets (set 0x01) read from `sock` within `seconds` (until `want` came)."""
    parser = framing.Parser()
    got: List[bytes] = []
    deadline = time.monotonic() + seconds
    sock.settimeout(0.05)
    while time.monotonic() < deadline and len(got) < want:
        try:
            data = sock.recv(65536)
        except socket.timeout:
            continue
        if not data:
            break
        got += [e.data for e in parser.feed(data) if isinstance(e, framing.RawPacket) and e.data[2] == 0x01]
    return got


def _pinged(sim: Sim, within: float) -> float:
    """Seconds until a new host's ping is answered (AssertionError: not within `within`)."""
    start = time.monotonic()
    while time.monotonic() - start < within:
        try:
            sock = socket.create_connection(("127.0.0.1", _port(sim)), timeout=1)
        except OSError:
            time.sleep(0.1)
            continue
        try:
            sock.sendall(PING)
            if _replies(sock, min(1.5, within - (time.monotonic() - start))):
                return time.monotonic() - start
        except OSError:
            pass
        finally:
            sock.close()
    raise AssertionError(f"no host was answered a ping within {within} s")


def _alive(sim: Sim) -> None:
    assert sim.proc.poll() is None, sim.proc.stderr.read()


def _reset(sock: socket.socket) -> None:
    """Closes with a reset (SO_LINGER 0): the simulator's next write fails with ECONNRESET/EPIPE."""
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
    sock.close()


# ------------------------------------------------------------------------------------ rude hosts
def test_a_host_that_floods_commands_without_reading_is_dropped_and_the_next_served() -> None:
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0") as sim:
        base = _rss_kb(sim.proc.pid)
        rude = socket.create_connection(("127.0.0.1", _port(sim)))
        rude.setblocking(False)
        sent = 0
        flood = PING * 8192  # 64 KiB of pings a write, about 1 MB of replies a write
        end = time.monotonic() + 1.0
        while time.monotonic() < end and sent < 8 << 20:
            try:
                sent += rude.send(flood)
            except BlockingIOError:
                time.sleep(0.01)
        # It keeps its connection and never reads: the next host is served beside it (several
        # hosts at once), before the rude one is dropped at the stall bound.
        waited = _pinged(sim, STALL_S + 20)
        assert waited < STALL_S  # served beside the rude one, not after it was dropped
        said = _stderr_line(sim, "a host read nothing for 5 s: disconnected", STALL_S + 20)
        peak = _rss_kb(sim.proc.pid, "VmHWM")
        assert peak - base < SLACK_KB, (base, peak)
        rude.setblocking(True)
        assert _closed_by_peer(rude, 15)  # the simulator closed the rude host's connection
        rude.close()
        # a host that floods and vanishes at once: the next is served at once
        for _ in range(3):
            gone = socket.create_connection(("127.0.0.1", _port(sim)))
            gone.sendall(PING * 4096)
            _reset(gone)
        assert _pinged(sim, 10) < 10
        _alive(sim)
        assert "Traceback" not in said + _stderr_so_far(sim)


def _stderr_line(sim: Sim, words: str, within: float) -> str:
    """The simulator's stderr until a line with `words` came (AssertionError: not within `within` s)."""
    said = ""
    end = time.monotonic() + within
    while words not in said:
        assert time.monotonic() < end, f"no {words!r} on stderr within {within} s: {said}"
        time.sleep(0.1)
        said += _stderr_so_far(sim)
    return said


def _stderr_so_far(sim: Sim) -> str:
    os.set_blocking(sim.proc.stderr.fileno(), False)
    try:
        return sim.proc.stderr.read() or ""
    except (BlockingIOError, TypeError):
        return ""


def test_a_stalled_host_while_data_streams_holds_no_memory_and_is_dropped() -> None:
    # --stream-full: the CV7 asks about 900 KB/s; a host that reads nothing fills the socket
    # buffers, then the simulator's output bound, then is disconnected; another host is served
    # meanwhile.
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", "--stream-full") as sim:
        time.sleep(0.5)
        base = _rss_kb(sim.proc.pid)
        stalled = socket.create_connection(("127.0.0.1", _port(sim)))
        time.sleep(1.0)
        waited = _pinged(sim, STALL_S + 15)
        assert waited < STALL_S  # served beside the stalled one, not after it was dropped
        _stderr_line(sim, "a host read nothing for 5 s: disconnected", STALL_S + 15)
        peak = _rss_kb(sim.proc.pid, "VmHWM")
        assert peak - base < SLACK_KB, (base, peak)
        assert _closed_by_peer(stalled, 15)
        stalled.close()
        _alive(sim)


def test_hosts_that_vanish_at_once_while_data_streams_do_not_end_the_simulator() -> None:
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", "--stream-full") as sim:
        rng = random.Random(37)
        for k in range(60):
            sock = socket.create_connection(("127.0.0.1", _port(sim)))
            if k % 3 == 1:
                sock.recv(100)  # data is flowing to it when it goes
            if k % 3 == 2:
                sock.sendall(PING * rng.randrange(1, 50))
            if k % 2:
                _reset(sock)  # the simulator's next write: ECONNRESET or EPIPE
            else:
                sock.close()
        assert _pinged(sim, 10) < 10
        _alive(sim)
        assert "Traceback" not in _stderr_so_far(sim)


def test_a_partial_header_left_by_one_host_does_not_make_the_simulator_deaf_to_the_next() -> None:
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0") as sim:
        # sync, set 0x01 and a payload length of 255: a parser waits for 257 more bytes
        for partial in (b"\x75\x65\x01\xff", b"\x75\x65", b"\x75"):
            first = socket.create_connection(("127.0.0.1", _port(sim)))
            first.sendall(partial)
            time.sleep(0.2)
            first.close()
            nxt = socket.create_connection(("127.0.0.1", _port(sim)))
            try:
                nxt.sendall(PING)
                got = _replies(nxt, 2.0)
                assert got, f"a ping after {partial.hex()} from another host was not answered"
                assert got[0][4:8] == bytes([0x04, 0xF1, 0x01, 0x00])  # ack field: echo ping, code 0
            finally:
                nxt.close()
        _alive(sim)


def test_noise_from_a_host_is_not_held_and_its_next_command_is_answered() -> None:
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0") as sim:
        base = _rss_kb(sim.proc.pid)
        rng = random.Random(7)
        # 48 MiB of bytes without a sync byte (0x75): nothing the simulator may keep
        block = bytes(rng.choice([b for b in range(256) if b != 0x75]) for _ in range(1 << 16))
        sock = socket.create_connection(("127.0.0.1", _port(sim)))
        try:
            for _ in range(48 * 16):
                sock.sendall(block)
            sock.sendall(PING)
            assert _replies(sock, 20.0), "the ping after the noise was not answered"
            grown = _rss_kb(sim.proc.pid, "VmHWM") - base  # the peak: noise held until a packet came
            assert grown < SLACK_KB, f"the simulator held {grown} KiB more while 48 MiB of noise came"
            # a ghost header (a sync, a long length) in the noise: the bytes after it are still read
            sock.sendall(b"\x75\x65\x01\xff" + block[:300] + PING)
            assert _replies(sock, 5.0)
        finally:
            sock.close()
        _alive(sim)


def _stamps(sim_data: bytes) -> List[int]:
    """The reference timestamps (ns) of the data packets in a byte stream, in order."""
    stamps = []
    for e in framing.Parser().feed(sim_data):
        if isinstance(e, framing.RawPacket) and e.data[2] == 0x80:
            packet = packets.decode_packet(e.data, device="cv7_ins")
            for f in packet.fields:
                if getattr(f, "descriptor", None) == 0xD5:
                    stamps.append(int(f.value.nanoseconds))
    return stamps


# ------------------------------------------------------------------------- resume from now
def _format_and_enable(decimation: int) -> List[bytes]:
    fmt = pkg.threedm.MessageFormat(
        desc_set=0x80,
        num_descriptors=2,
        descriptors=[types.DescriptorRate(0xD5, decimation), types.DescriptorRate(0x04, decimation)],
    )
    return [_command(fmt), _command(_enable(True))]


def _enable(on: bool):
    return pkg.threedm.DataStreamControl_cv7_ins(desc_set=0x80, enable=on)


def test_a_stream_turned_on_again_resumes_from_now() -> None:
    # CV7 sensor data 1 kHz base rate (3dm-cv7-ins-docs.txt, _sim.BASE_RATES), decimation 100: 10 Hz
    sim = sim_mod.Simulator("cv7_ins")
    out = []
    for data in _format_and_enable(100):
        out += sim.feed(data, 0.0)
    out += [c for k in range(1, 11) for c in sim.poll(k / 10)]
    before = _stamps(b"".join(d for _, d in out))
    assert before and before[-1] == 1_000_000_000 and all(b - a == 100_000_000 for a, b in zip(before, before[1:]))
    sim.feed(_command(_enable(False)), 1.05)
    assert _stamps(b"".join(d for _, d in sim.poll(2.95))) == []
    out = sim.feed(_command(_enable(True)), 3.0) + [c for k in range(31, 36) for c in sim.poll(k / 10)]
    after = _stamps(b"".join(d for _, d in out))
    # from the first tick after the enable (3.0 s) on, every 100 ms: nothing dated in the 2 s it was off
    assert after == [n * 100_000_000 for n in range(31, 36)], after
    # the same with idle and resume (the loop polls while idle: nothing is owed after it)
    sim.feed(_command(pkg.base.SetToIdle()), 3.55)
    sim.poll(4.0)
    out = sim.feed(_command(pkg.base.Resume()), 4.5) + sim.poll(4.6)
    assert _stamps(b"".join(d for _, d in out)) == [4_600_000_000]


def test_a_host_connecting_to_a_streaming_device_gets_data_from_now() -> None:
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0") as sim:
        first = socket.create_connection(("127.0.0.1", _port(sim)))
        for data in _format_and_enable(100):  # 10 Hz
            first.sendall(data)
        got = b""
        end = time.monotonic() + 1.0
        first.settimeout(0.1)
        while time.monotonic() < end:
            try:
                got += first.recv(65536)
            except socket.timeout:
                pass
        first.close()
        last = _stamps(got)[-1]
        gone = time.monotonic()
        time.sleep(2.0)
        second = socket.create_connection(("127.0.0.1", _port(sim)))
        came = time.monotonic()
        got = b""
        second.settimeout(0.05)
        while time.monotonic() < came + 0.5:
            try:
                got += second.recv(65536)
            except socket.timeout:
                pass
        second.close()
        stamps = _stamps(got)
        assert stamps, "no data after the host connected"
        # nothing dated in the 2 s nobody was connected: the first sample is of about now
        off_ns = (came - gone) * 1e9
        assert stamps[0] - last >= 0.9 * off_ns, (last, stamps[:5], off_ns)
        assert len(stamps) <= 8  # 0.5 s at 10 Hz, no burst of backlog
        assert all(b - a == 100_000_000 for a, b in zip(stamps, stamps[1:])), stamps


# ------------------------------------------------------------------------------ baud rates
def _answer(sim, field, package: str = "mipcodec") -> int:
    """The ack code of the simulator's reply to one command."""
    fr = importlib.import_module(f"{package}.codec.framing")
    b = fr.PacketBuilder(field.SET)
    b.add(field)
    chunks = sim.feed(b.build(), 0.0)
    replies = [e.data for _, d in chunks for e in fr.Parser().feed(d) if isinstance(e, fr.RawPacket)]
    packet = importlib.import_module(f"{package}.codec.packets").decode_packet(replies[0], device=sim.device)
    code = importlib.import_module(f"{package}._session").ACK_CODE
    return int(getattr(packet.fields[0].value, code))


def test_a_baud_rate_the_port_does_not_list_is_nacked() -> None:
    # NACK invalid parameter (0x03): "a value that is outside the allowed range for a command"
    # (3dm-gx5-45-dcp.txt:2027; 3dm-cv7-ins-docs.txt:8878). Rates: 3dm-gx5-45-dcp.txt:1296 (9600 ..
    # 921600), 3dm-cv7-ins-docs.txt:2718 (UART1: 115200 .. 3000000).
    invalid = 0x03
    writes = {
        "gx5_45": [lambda r: pkg.threedm.UartBaudrate(baud=r)],  # its only baud rate command
        "cv7_ins": [lambda r: pkg.threedm.UartBaudrate(baud=r), lambda r: pkg.base.CommPortSpeed(port=1, baud=r)],
    }
    for device, bad, good in (("gx5_45", [12345, 4800, 0, 3000000], 230400), ("cv7_ins", [9600, 12345], 3000000)):
        sim = sim_mod.Simulator(device, baud=True)
        for rate in bad:
            for write in writes[device]:
                assert _answer(sim, write(rate)) == invalid, (device, rate)
        assert sim.baud_changes == []  # the port stays where it was
        for write in writes[device]:
            assert _answer(sim, write(good)) == 0
        assert [r for _, r in sim.baud_changes] == [good] * len(writes[device])
    # MS-CIP: the rate is an enum of the listed rates (ms-cip-doc00419-revM.txt:539); another value:
    # invalid parameter, code 4 (ms-cip-doc00419-revM.txt:143, Table 2)
    ms = python_package("mscipcodec")
    ms_sim = importlib.import_module("mscipcodec.sim").Simulator("ms_imu3020", baud=True)
    assert _answer(ms_sim, ms.imu_config.UartBaudRate(baud_rate=12345), "mscipcodec") == 4
    assert ms_sim.baud_changes == []
    assert _answer(ms_sim, ms.imu_config.UartBaudRate(baud_rate=921600), "mscipcodec") == 0
    assert [r for _, r in ms_sim.baud_changes] == [921600]


def test_an_unsupported_baud_rate_leaves_the_device_reachable() -> None:
    with Sim("mip", "gx5_45", "pty", "--baud") as sim:
        dev = session.Device(transport.open_transport(sim.address, 115200), device="gx5_45", timeout_ms=500)
        try:
            with pytest.raises(session.Nack):
                dev.threedm.uart_baudrate.write(baud=12345)
            time.sleep(0.3)  # the settle time of a change (3dm-gx5-45-dcp.txt:1297), had there been one
            dev.base.ping()
        finally:
            dev.transport.close()


# ------------------------------------------------------------------------------- validation
def _limited() -> None:
    # 1 GiB of address space: an unbounded read of /dev/zero fails here instead of taking the machine
    resource.setrlimit(resource.RLIMIT_AS, (1 << 30, 1 << 30))


def _refused(args: List[str], words: str, timeout: float = 60) -> None:
    run = subprocess.run([str(SIMULATE), *args], capture_output=True, text=True, timeout=timeout, preexec_fn=_limited)
    lines = run.stderr.strip().splitlines()
    assert run.returncode == 2, (args, run.returncode, run.stderr[-2000:])
    assert len(lines) == 1 and words in lines[0] and "Traceback" not in run.stderr, (args, run.stderr[-2000:])
    assert run.stdout == "", (args, run.stdout)  # refused before it listens


SPEED = "0.001 to 100000"


@pytest.mark.parametrize(
    "args, words",
    [
        (["--speed", "inf"], SPEED),
        (["--speed", "nan"], SPEED),
        (["--speed", "0"], SPEED),
        (["--speed", "-1"], SPEED),
        (["--speed", "1e300"], SPEED),
        (["--speed", "1e-9"], SPEED),
        (["--gnss-outage", "0:inf"], "--gnss-outage 0:inf: expected 0 <= START < END <= 1000000000"),
        (["--gnss-outage", "nan:5"], "--gnss-outage nan:5: expected 0 <= START < END"),
        (["--gnss-outage", "0:1e300"], "expected 0 <= START < END <= 1000000000"),
        (["--gnss-outage", "5:1"], "expected 0 <= START < END"),
        (["--mag-disturbance=-1:2"], "--mag-disturbance -1:2: expected 0 <= START"),
        (["--rtk-corrections", "0:1e10"], "--rtk-corrections 0:1e10: expected"),
        (["--replug", "1:inf"], "--replug 1:inf: expected 0 <= START < END <= 1000000000"),
        (["--delay", "ping:99999999999"], "--delay ping:99999999999: expected milliseconds 0..3600000"),
        (["--garbage", "ping:99999999999"], "--garbage ping:99999999999: expected bytes 0..65536"),
        (["--nack", "ping:256"], "--nack ping:256: expected a code 0..255"),
        (["--replay", "/dev/zero"], "--replay /dev/zero: larger than 16 MiB"),
        (["--scenario", "file:/dev/zero"], "/dev/zero: larger than 16 MiB"),
        (["--device", "gx5_45", "--start-baud", "4800"], "--start-baud 4800: not a baud rate of gx5_45"),
        (["--device", "cv7_ins", "--start-baud", "9600"], "--start-baud 9600: not a baud rate of cv7_ins"),
    ],
)
def test_options_out_of_range_are_one_line_and_exit_2(args: List[str], words: str) -> None:
    listen = ["--listen", "pty"] if "--start-baud" in args else ["--listen", "tcp:127.0.0.1:0"]
    _refused(listen + args, words)


TRACK = "0 46.5197 6.6323 372 0 0 30\n1 46.5198 6.6323 372 0 0 30\n"


@pytest.mark.parametrize(
    "text, words",
    [
        (TRACK + "2 nan 6.6323 372 0 0 30\n", ":3: expected finite numbers"),
        (TRACK + "2 46.5 6.6323 inf 0 0 30\n", ":3: expected finite numbers"),
        (TRACK + "nan 46.5 6.6323 372 0 0 30\n", ":3: expected finite numbers"),
        (TRACK + "0.5 46.5 6.6323 372 0 0 30\n", ":3: times must increase"),
        (TRACK + "1 46.5 6.6323 372 0 0 30\n", ":3: times must increase"),
        (TRACK + "2 91 6.6323 372 0 0 30\n", ":3: expected latitude -90..90 and longitude -180..180"),
        (TRACK + "2 46 181 372 0 0 30\n", ":3: expected latitude -90..90"),
        (TRACK + "2 46 6 372 0 0\n", ":3: expected 7 numbers"),
        (TRACK + "# caf\xe9\n", ":3: not UTF-8 text"),
    ],
)
def test_trajectory_files_with_bad_values_are_refused_with_their_line(tmp_path: Path, text: str, words: str) -> None:
    path = tmp_path / "track.txt"
    path.write_bytes(text.encode("latin-1"))
    _refused(["--listen", "tcp:127.0.0.1:0", "--scenario", f"file:{path}"], f"{path}{words}")


def test_a_trajectory_file_above_the_limit_is_refused_unread(tmp_path: Path) -> None:
    path = tmp_path / "big.txt"
    line = b"0 46.5197 6.6323 372 0 0 30\n"
    with open(path, "wb") as f:
        f.write(b"# padding " + b"x" * (16 << 20) + b"\n" + line)
    _refused(["--listen", "tcp:127.0.0.1:0", "--scenario", f"file:{path}"], f"{path}: larger than 16 MiB")
    assert sim_mod.MAX_REPLAY_BYTES == 16 << 20


def test_the_accepted_extremes_still_run() -> None:
    # the ends of the stated ranges are accepted
    for extra in (["--speed", "0.001"], ["--speed", "100000"], ["--gnss-outage", "0:1000000000"]):
        with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", *extra) as sim:
            assert _pinged(sim, 10) < 10
