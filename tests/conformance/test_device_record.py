"""The device command line's recorder (`record FILE`, docs/record.md) and its option placement,
partial writes and exit statuses (docs/configure-a-device.md), each test run with both command
lines: the Python package's (`python -m mipcodec device`) and the C tool (`mipcodec-device` of
generated/c/mipcodec, built as tests/conformance/test_device_c.py builds it).

- a recording of the simulated CV7 (streaming every data set from the start) begins with its
  Device Information reply, names the simulator's serial to the dataset's identity, and has no
  byte outside a packet, also when stopped by SIGINT; --split-size writes FILE.NNN.bin files that
  each begin with the reply;
- a device that goes away mid-stream (a scripted loopback server: packets cut across writes, bytes
  that are not part of a packet, then half a packet and the end of the connection): the log is the
  reply, then exactly the bytes sent but the unfinished packet; exit 1;
- a full disk (a file size limit, RLIMIT_FSIZE: the write fails with EFBIG, the path ENOSPC takes):
  the log is cut back to its last whole packet; exit 2;
- options before the subcommand are honoured (--device, --baud, --timeout-ms);
- `send NAME write P=V` with parameters left out reads, modifies and writes a setting, and needs
  every parameter of a command without a read;
- a silent device (a loopback listener that never answers): exit 1, as the docs say.
"""

from __future__ import annotations

import importlib
import os
import resource
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Callable, Iterator, List

import pytest

from tests.conformance.test_device_c import tool  # noqa: F401 - the C tool's fixture
from tests.conformance.test_device_cli import PACKAGE_DIR, Sim, mip
from tests.helpers.procs import as_in_a_terminal

SERIAL = "6284.424242"
MODEL = "cv7_ins"
TOOLS = ["python", "c"]
Run = Callable[..., List[str]]


@pytest.fixture(scope="module")
def sim() -> Iterator[Sim]:
    """One simulated CV7 for the module: streaming every data set at its base rate from the start
    (about 200 kB/s), with its own serial number."""
    with Sim(MODEL, "tcp:127.0.0.1:0", "--stream-full", "--speed", "1", "--serial", SERIAL) as s:
        yield s


@pytest.fixture(scope="module")
def quiet() -> Iterator[Sim]:
    """A simulated CV7 that streams nothing (the command line's tests: the Python session decodes
    every data packet that comes while it waits for a reply)."""
    with Sim(MODEL, "tcp:127.0.0.1:0") as s:
        yield s


@pytest.fixture(params=TOOLS)
def command(request: pytest.FixtureRequest) -> List[str]:
    """The command line of the device tool: Python's or C's."""
    if request.param == "python":
        return [sys.executable, "-m", "mipcodec", "device"]
    return [str(request.getfixturevalue("tool"))]


def run(command: List[str], *args: str, timeout: float = 60, **kw: object) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(PACKAGE_DIR)}
    done = subprocess.run([*command, *args], capture_output=True, text=True, env=env, timeout=timeout, **kw)  # type: ignore[call-overload]
    assert "Traceback" not in done.stderr and done.returncode >= 0, done.stderr
    return done  # type: ignore[no-any-return]


def packets(data: bytes) -> List[bytes]:
    """The packets of a log; asserts that every byte is part of one (no skipped bytes)."""
    events = mip.codec.framing.parse(data)
    skipped = [e for e in events if not isinstance(e, mip.codec.framing.RawPacket)]
    assert not skipped, f"{sum(len(e.data) for e in skipped)} bytes outside packets"
    return [bytes(e.data) for e in events]


def device_info(packet: bytes) -> object:
    """The Device Information reply's value in a packet (None: not such a reply)."""
    decoded = mip.codec.packets.decode_packet(packet, 0, MODEL)
    for f in decoded.fields:
        value = getattr(f, "value", None)
        if value is not None and type(value).NAME == "device_info":
            return value
    return None


def serial_of(packet: bytes) -> str:
    info = device_info(packet)
    assert info is not None, packet.hex()
    serial = info.info.serial_number  # type: ignore[attr-defined]
    return (serial.decode("latin-1") if isinstance(serial, bytes) else str(serial)).strip(" \x00")


# ------------------------------------------------------------------------------ recording
@pytest.mark.parametrize("split", ["", "size", "time"], ids=["one-file", "split-size", "split-time"])
def test_a_recording_begins_with_the_device_and_skips_nothing(
    sim: Sim, command: List[str], split: str, tmp_path: Path
) -> None:
    log = tmp_path / "cv7.bin"
    extra = {"": [], "size": ["--split-size", "40000"], "time": ["--split-time", "0.3"]}[split]
    done = run(command, sim.address, "record", str(log), "--duration", "1", *extra)
    assert done.returncode == 0, done.stderr
    assert done.stderr.rstrip().endswith("stopped: --duration"), done.stderr
    files = sorted(tmp_path.iterdir())
    if split:  # FILE's stem, .NNN, its extension; each starts with the reply, each but the last full
        assert [f.name for f in files] == [f"cv7.{i:03d}.bin" for i in range(len(files))]
        assert len(files) >= 3, files  # 1 s at ~300 kB/s: new files every 40 kB or every 0.3 s
        if split == "size":
            assert all(f.stat().st_size >= 40000 for f in files[:-1])
    else:
        assert files == [log]
    first = None
    for n, f in enumerate(files):
        data = f.read_bytes()
        found = packets(data)
        assert serial_of(found[0]) == SERIAL
        first = first or found[0]
        assert found[0] == first  # the same reply first in every file
        assert sum(device_info(p) is not None for p in found) == 1
        assert len(found) > 100 or n == len(files) - 1  # the stream: 200 kB/s, ~1100 packets a second
    # the dataset's identity of the log (Hive partitions model=/serial=), and `info`'s count (once)
    data = files[0].read_bytes()
    identity = importlib.import_module("mipcodec.logs.dataset").log_identity(lambda at, n: data[at : at + n], len(data))
    # the reported model name "3DM-CV7-GNSS/INS" as the model partition value: lower case, runs of
    # characters other than letters and digits as "-" (dataset.model_slug's rule)
    assert (identity.serial, identity.model) == (SERIAL, "3dm-cv7-gnss-ins"), identity
    if split:
        return
    env = {**os.environ, "PYTHONPATH": str(PACKAGE_DIR)}
    info = subprocess.run(
        [sys.executable, "-m", "mipcodec", "info", str(files[0])], capture_output=True, text=True, env=env
    )
    assert info.returncode == 0 and "skipped bytes: 0 in 0 runs" in info.stdout, info.stdout + info.stderr
    # `info` names the recorded device by its model and serial (issue 50: "names its serial")
    assert f"serial {SERIAL}" in info.stdout and "device: cv7_ins" in info.stdout, info.stdout


def test_sigint_leaves_a_whole_log(sim: Sim, command: List[str], tmp_path: Path) -> None:
    log = tmp_path / "cv7.bin"
    env = {**os.environ, "PYTHONPATH": str(PACKAGE_DIR)}
    proc = subprocess.Popen(
        [*command, sim.address, "record", str(log)],
        stderr=subprocess.PIPE,
        text=True,
        env=env,
        preexec_fn=as_in_a_terminal,
    )
    deadline = time.monotonic() + 30
    while (not log.exists() or log.stat().st_size < 50000) and time.monotonic() < deadline:
        time.sleep(0.05)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=30)
    assert proc.returncode == 0, err
    assert "stopped: interrupted" in err, err
    found = packets(log.read_bytes())
    assert serial_of(found[0]) == SERIAL and len(found) > 200


def test_a_full_disk_leaves_a_whole_log(sim: Sim, command: List[str], tmp_path: Path) -> None:
    """The file size limit (RLIMIT_FSIZE) makes a write fail part way with EFBIG, as a full disk
    does with ENOSPC: the file is cut back to its last whole packet; exit 2, one line."""
    log = tmp_path / "cv7.bin"
    limit = 30001  # odd: a write ends inside a packet when the limit is reached

    def small_files() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    done = run(command, sim.address, "record", str(log), "--duration", "10", preexec_fn=small_files)
    assert done.returncode == 2, done.stderr
    assert f"cannot write {log}: File too large" in done.stderr, done.stderr
    assert done.stderr.endswith("; stopped: the write failed\n"), done.stderr
    data = log.read_bytes()
    assert limit - 300 < len(data) <= limit  # cut back by less than a packet and a read
    found = packets(data)
    assert serial_of(found[0]) == SERIAL


def test_an_existing_file_is_not_overwritten(sim: Sim, command: List[str], tmp_path: Path) -> None:
    log = tmp_path / "kept.bin"
    log.write_bytes(b"mine")
    done = run(command, sim.address, "record", str(log), "--duration", "1")
    assert done.returncode == 2 and done.stderr == f"mipcodec-device: cannot create {log}: exists\n"
    assert log.read_bytes() == b"mine"


class Script:
    """A device on a loopback port that answers the first command with `reply` between `before`
    and `after` (each a list of writes, 50 ms apart), then sends `tail` and closes."""

    def __init__(self, before: List[bytes], reply: bytes, after: List[bytes], tail: bytes) -> None:
        self.server = socket.socket()
        self.server.bind(("127.0.0.1", 0))
        self.server.listen(1)
        self.address = f"tcp:127.0.0.1:{self.server.getsockname()[1]}"
        self.writes = [*before, reply, *after, tail]
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self) -> None:
        client, _ = self.server.accept()
        with client:
            client.recv(1024)  # the Device Information command
            for chunk in self.writes:
                client.sendall(chunk)
                time.sleep(0.05)


def test_a_vanished_device_leaves_the_stream_but_its_unfinished_packet(
    sim: Sim, command: List[str], tmp_path: Path
) -> None:
    # real packets of the simulator: its reply and its stream, recorded by the Python recorder
    source = tmp_path / "source.bin"
    done = run([sys.executable, "-m", "mipcodec", "device"], sim.address, "record", str(source), "--duration", "0.3")
    assert done.returncode == 0, done.stderr
    reply, *stream = packets(source.read_bytes())
    a, b, c = stream[0], stream[1], stream[2]
    garbage = b"\x00\x01\x02junk"  # no sync byte: not part of any packet, kept
    before = [a[:5], a[5:] + b[:3]]  # a packet cut by a write waits for its end
    after = [b[3:] + garbage, c]
    tail = stream[3][: len(stream[3]) // 2]  # the device goes away inside a packet
    script = Script(before, reply, after, tail)
    log = tmp_path / "gone.bin"
    done = run(command, script.address, "record", str(log))
    assert done.returncode == 1, done.stderr
    assert (
        f"stopped: the device went away (end of file); {len(tail)} bytes of an unfinished packet left out"
        in done.stderr
    ), done.stderr
    assert log.read_bytes() == reply + a + b + garbage + c


# --------------------------------------------------------------------- the command line
@pytest.fixture(scope="module")
def silent() -> Iterator[str]:
    """A loopback listener that accepts and never answers."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(8)
    yield f"tcp:127.0.0.1:{server.getsockname()[1]}"
    server.close()


def test_a_silent_device_exits_1(silent: str, command: List[str], tmp_path: Path) -> None:
    for args in (["ping"], ["info"], ["record", str(tmp_path / "none.bin")]):
        done = run(command, "--timeout-ms", "200", silent, *args)
        assert done.returncode == 1, (args, done.stderr)
        assert "no answer to the device information command" in done.stderr, done.stderr
        assert len(done.stderr.splitlines()) == 1, done.stderr
    assert not (tmp_path / "none.bin").exists()


def test_options_before_the_subcommand_are_honoured(quiet: Sim, command: List[str]) -> None:
    sim = quiet
    done = run(command, "--baud", "9600", "--device", "gx5_45", sim.address, "ping")
    assert "connected device is 3DM-CV7-GNSS/INS, this session was told gx5_45" in done.stderr, done.stderr
    done = run(command, "--baud", "921600", sim.address, "info")
    assert done.returncode == 0, done.stderr
    assert "  total " in done.stdout and "921600 baud (--baud)" in done.stdout, done.stdout
    # after the subcommand still, and the later one wins
    done = run(command, "--baud", "9600", sim.address, "info", "--baud", "460800")
    assert "460800 baud (--baud)" in done.stdout, done.stdout


def test_send_write_with_parameters_left_out(quiet: Sim, command: List[str]) -> None:
    sim = quiet
    done = run(command, sim.address, "send", "sensor_to_vehicle_euler", "write", "roll=0.5", "pitch=0.25", "yaw=-1")
    assert (done.returncode, done.stdout) == (0, "sensor_to_vehicle_euler: ack\n"), done.stderr
    # one angle tuned: the other two are read first and written back as they were
    done = run(command, sim.address, "send", "sensor_to_vehicle_euler", "write", "pitch=0.125")
    assert (done.returncode, done.stdout) == (0, "sensor_to_vehicle_euler: ack\n"), done.stderr
    assert done.stderr == (
        "mipcodec-device: sensor_to_vehicle_euler: roll, yaw as read from the device (read, modify, write)\n"
    )
    done = run(command, sim.address, "send", "sensor_to_vehicle_euler", "read")
    assert done.stdout.splitlines()[1] == 'sensor_to_vehicle_euler_response {"roll":0.5,"pitch":0.125,"yaw":-1.0}'
    # a keyed setting needs its key; a command without a read needs every parameter
    done = run(command, sim.address, "send", "message_format", "write", "descriptors=[]")
    assert done.returncode == 2
    assert done.stderr == (
        "mipcodec-device: message_format write: give desc_set (the key of the read that fills the parameters left out)\n"
    )
    done = run(command, sim.address, "send", "gps_time_update", "write", "value=5")
    assert done.returncode == 2
    assert done.stderr == (
        "mipcodec-device: gps_time_update write: give every parameter "
        "(field_id left out; the command has no read to fill them from)\n"
    )
