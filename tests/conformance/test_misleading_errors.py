"""Errors that used to mislead (issue 39, item 5), each one line that says what to do:

1. HOST:PORT without `tcp:` (`127.0.0.1:5000`, `localhost:5000`, `[::1]:5000`) is not taken as
   a serial port path: the session tool of every language exits 2 with `did you mean
   tcp:HOST:PORT?`, and so does Python's `connect()`; an existing file of that name is a path.
   The Python address parser takes `COM3` and `\\\\.\\COM10` as serial ports without opening
   them (pyserial opens them on Windows); the Rust parser's cases are in
   generator/targets/rust/runtime/tests/addresses.rs.
2. A session told one model but connected to another: the first NACK for an unknown command asks
   the device what it is and says `connected device is 3DM-GX5-45, this session was told
   cv7_ins` (the Python Device API and the session tool of every language, against the simulated
   GX5-45, and the other way round; the Python and C device command lines, which read the
   identity at connect, say it then).
3. `connect()` with a mistyped device name refuses it before opening anything: no connection
   reaches the listener, no descriptor is left open.
"""

from __future__ import annotations

import importlib
import os
import socket
import subprocess
import threading

import pytest

from tests.conformance.test_device_c import ctool, tool  # noqa: F401 (tool: the C device tool fixture)
from tests.conformance.test_simulator import SESSION, SESSION_LANGUAGES, Sim
from tests.helpers.generated import python_package

TCP_LOOKING = ["127.0.0.1:5000", "localhost:5000", "[::1]:5000"]


def _modules(package: str = "mipcodec"):
    python_package(package)
    session = importlib.import_module(f"{package}.session")
    transport = importlib.import_module(f"{package}.session.transport")
    return session, transport


# ------------------------------------------------------------------------------ HOST:PORT
@pytest.mark.parametrize("lang", SESSION_LANGUAGES)
def test_session_tools_suggest_tcp_for_host_and_port(lang: str) -> None:
    for address in TCP_LOOKING:
        run = subprocess.run(
            [str(SESSION), lang, "--connect", address],
            input="",
            capture_output=True,
            text=True,
            timeout=1800,  # the first call builds the tool (C++: minutes on a loaded machine)
        )
        lines = [line for line in run.stderr.splitlines() if line.strip()]
        assert run.returncode == 2, (lang, address, run.stderr)
        # The build's own output (cargo, cmake) may come first; the tool says one line.
        assert lines and lines[-1].endswith(f"'{address}' is not a serial port: did you mean tcp:{address}?"), (
            lang,
            address,
            run.stderr,
        )
        assert "pyserial" not in run.stderr and "Traceback" not in run.stderr, run.stderr


@pytest.mark.parametrize("package", ["mipcodec", "mscipcodec"])
def test_python_connect_suggests_tcp(package: str) -> None:
    session, transport = _modules(package)
    for address in TCP_LOOKING:
        with pytest.raises(ValueError) as e:
            session.connect(address)
        assert str(e.value) == f"'{address}' is not a serial port: did you mean tcp:{address}?"
        assert transport.parse_address(f"tcp:{address}")[0] == "tcp"


def test_python_addresses_of_every_platform(tmp_path, monkeypatch) -> None:
    _, transport = _modules()
    # Serial ports as pyserial names them on Windows and POSIX: parsed, not opened.
    for path in ["COM3", "\\\\.\\COM10", "/dev/ttyUSB0", "/dev/serial/by-id/usb-x:1.0-port0"]:
        assert transport.parse_address(path) == ("serial", path)
    assert transport.parse_address("tcp:[::1]:5000") == ("tcp", ("::1", 5000))
    # Not HOST:PORT: a port that is not a number, an IPv6 host without brackets, a path.
    for path in ["COM3:", "dev:tty", "fe80::1:5000", "./127.0.0.1:5000"]:
        assert transport.parse_address(path) == ("serial", path)
    # An existing file named like HOST:PORT is a path.
    monkeypatch.chdir(tmp_path)
    (tmp_path / "port:5000").write_bytes(b"")
    assert transport.parse_address("port:5000") == ("serial", "port:5000")
    with pytest.raises(ValueError, match="did you mean tcp:other:5000"):
        transport.parse_address("other:5000")


# ------------------------------------------------------------------------- the wrong model
# continuous_bit (0x01, 0x08): a command of the CV7-INS manual that the GX5-45 does not know.
CV7_ONLY = '{"offset":0,"set":1,"fields":[{"descriptor":8,"name":"continuous_bit","values":{}}]}'
PING = '{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}'
MISMATCH = "connected device is 3DM-GX5-45, this session was told cv7_ins"


def test_python_device_names_the_connected_model() -> None:
    session, _ = _modules()
    with Sim("mip", "gx5_45", "tcp:127.0.0.1:0") as sim:
        dev = session.connect(sim.address, "cv7_ins", timeout_ms=500)
        try:
            with pytest.raises(session.Nack) as e:
                dev.base.continuous_bit()
            assert str(e.value) == f"continuous_bit: NACK, code 1 (unknown_command): {MISMATCH}"
            assert e.value.result.note == MISMATCH
            # Asked once: the next NACK is the plain one, and the session goes on.
            with pytest.raises(session.Nack) as again:
                dev.base.continuous_bit()
            assert str(again.value) == "continuous_bit: NACK, code 1 (unknown_command)"
            dev.base.ping()  # raises unless acknowledged
        finally:
            dev.close()
    # The right model: the NACK says nothing more (the CV7-INS does not know a GX5-45 command).
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0") as sim:
        dev = session.connect(sim.address, "cv7_ins", timeout_ms=500)
        try:
            result = dev.run(dev_command(session, "continuous_bit"), check_device=False)
            assert result.status == "ack" and result.note is None
            result = dev.run(dev_command(session, "get_imu_base_rate"), check_device=False)
            assert result.status == "nack" and int(result.code) == 1 and result.note is None
        finally:
            dev.close()


def dev_command(session, name: str):
    registry = importlib.import_module("mipcodec.registry")
    for classes in registry.FIELDS.values():
        for cls in classes or ():
            if cls.NAME == name and cls.ROLE == "command":
                return cls()
    raise AssertionError(name)


# The session tool of every language, told one model and connected to the other (either way):
# (simulated model, --device, the command lines, the stderr line after the tool's name).
GX5_ONLY = '{"offset":0,"set":12,"fields":[{"descriptor":6,"name":"get_imu_base_rate","values":{}}]}'
WRONG_MODEL = [
    ("gx5_45", "cv7_ins", [PING, CV7_ONLY, CV7_ONLY], MISMATCH),
    (
        "cv7_ins",
        "gx5_45",
        [PING, GX5_ONLY, GX5_ONLY],
        "connected device is 3DM-CV7-GNSS/INS, this session was told gx5_45",
    ),
]


@pytest.mark.parametrize("lang", SESSION_LANGUAGES)
@pytest.mark.parametrize("case", WRONG_MODEL, ids=[f"{m}-told-{d}" for m, d, _, _ in WRONG_MODEL])
def test_session_tools_name_the_connected_model(lang: str, case) -> None:
    model, told, lines, said = case
    with Sim("mip", model, "tcp:127.0.0.1:0") as sim:
        run = subprocess.run(
            [str(SESSION), lang, "--connect", sim.address, "--device", told, "--timeout-ms", "500"],
            input="\n".join(lines) + "\n",
            capture_output=True,
            text=True,
            timeout=1800,  # the first call builds the tool (C++: minutes on a loaded machine)
        )
    assert run.returncode == 0, (lang, run.stderr)
    out = run.stdout.splitlines()
    assert [line.split(',"reply"')[0] for line in out] == [
        '{"line":1,"result":"ack","code":0',
        '{"line":2,"result":"nack","code":1',
        '{"line":3,"result":"nack","code":1',
    ], (lang, run.stdout)  # the identity query is not a line of its own
    # Said once, at the first NACK, as one line: the tool's name, then the note. (The build's own
    # output, cargo's or cmake's, may come before it.)
    notes = [line for line in run.stderr.splitlines() if "connected device" in line or "session was told" in line]
    assert len(notes) == 1 and notes[0].endswith(f": {said}"), (lang, run.stderr)
    if lang == "python":
        assert run.stderr.splitlines() == [f"mipcodec.session_tool: {said}"], run.stderr


# A device whose Device Information reply names its model with bytes a terminal would act on: the
# name is at most its 16 bytes, spaces and NULs at either end go, and every byte outside printable
# ASCII is printed as \\xNN (the same text in every language).
HOSTILE_NAME = b" \x1b[31mGX5\xff\x07" + b"\x00" * 5
HOSTILE_SAID = "connected device is \\x1b[31mGX5\\xff\\x07, this session was told cv7_ins"


class HostileDevice:
    """One TCP connection on 127.0.0.1: answers the device information command (0x01, 0x03) with
    HOSTILE_NAME as the model name and NACKs every other command with code 1 (unknown command)."""

    def __init__(self) -> None:
        framing = importlib.import_module("mipcodec.codec.framing")
        self.builder = framing.PacketBuilder
        self.srv = socket.socket()
        self.srv.bind(("127.0.0.1", 0))
        self.srv.listen(1)
        self.srv.settimeout(60)
        self.address = f"tcp:127.0.0.1:{self.srv.getsockname()[1]}"
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self) -> None:
        try:
            conn, _ = self.srv.accept()
        except OSError:
            return
        buf = b""
        with conn:
            while True:
                try:
                    data = conn.recv(4096)
                except OSError:
                    return
                if not data:
                    return
                buf += data
                while len(buf) >= 4 and len(buf) >= 6 + buf[3]:
                    start = buf.find(b"\x75\x65")
                    if start != 0:
                        buf = buf[max(start, 1) :]
                        continue
                    set_id, payload = buf[2], buf[4 : 4 + buf[3]]
                    buf = buf[6 + buf[3] :]
                    descriptor = payload[1]
                    reply = self.builder(set_id)
                    if (set_id, descriptor) == (0x01, 0x03):
                        reply.add_field(0xF1, bytes([descriptor, 0]))
                        reply.add_field(0x81, b"\x05\xfe" + HOSTILE_NAME + b" " * 64)
                    else:
                        reply.add_field(0xF1, bytes([descriptor, 1]))
                    conn.sendall(reply.build())

    def close(self) -> None:
        self.srv.close()


@pytest.mark.parametrize("lang", SESSION_LANGUAGES)
def test_session_tools_show_the_device_name_safely(lang: str) -> None:
    python_package("mipcodec")
    device = HostileDevice()
    try:
        run = subprocess.run(
            [str(SESSION), lang, "--connect", device.address, "--device", "cv7_ins", "--timeout-ms", "500"],
            input=("\n".join([CV7_ONLY, CV7_ONLY]) + "\n").encode(),
            capture_output=True,
            timeout=1800,
        )
    finally:
        device.close()
    stderr = run.stderr.decode("latin-1")
    assert run.returncode == 0, (lang, stderr)
    assert [line.split(b',"reply"')[0] for line in run.stdout.splitlines()] == [
        b'{"line":1,"result":"nack","code":1',
        b'{"line":2,"result":"nack","code":1',
    ], (lang, run.stdout)
    notes = [line for line in stderr.splitlines() if "session was told" in line]
    assert len(notes) == 1 and notes[0].endswith(f": {HOSTILE_SAID}"), (lang, stderr)
    assert all(32 <= b < 127 for b in notes[0].encode("latin-1")), notes  # nothing a terminal acts on


@pytest.mark.parametrize("lang", SESSION_LANGUAGES)
def test_session_tools_say_nothing_more_for_the_right_model(lang: str) -> None:
    # Told the model it is: the CV7-only command is refused before sending (no NACK, no question).
    with Sim("mip", "gx5_45", "tcp:127.0.0.1:0") as sim:
        run = subprocess.run(
            [str(SESSION), lang, "--connect", sim.address, "--device", "gx5_45", "--timeout-ms", "500"],
            input="\n".join([PING, CV7_ONLY]) + "\n",
            capture_output=True,
            text=True,
            timeout=1800,
        )
    assert run.returncode == 0, (lang, run.stderr)
    assert [line.split(',"reply"')[0] for line in run.stdout.splitlines()] == [
        '{"line":1,"result":"ack","code":0',
        '{"line":2,"result":"refused","code":null',
    ], (lang, run.stdout)
    assert "connected device" not in run.stderr, (lang, run.stderr)


# ------------------------------------------------------------------ a mistyped device name
def _open_fds() -> set[str]:
    return set(os.listdir("/proc/self/fd"))


@pytest.mark.parametrize("package", ["mipcodec", "mscipcodec"])
def test_python_connect_checks_the_device_name_before_opening(package: str) -> None:
    session, _ = _modules(package)
    with socket.socket() as listener:
        listener.bind(("127.0.0.1", 0))
        listener.listen(1)
        listener.settimeout(0.3)
        host, port = listener.getsockname()
        before = _open_fds()
        with pytest.raises(ValueError) as e:
            session.connect(f"tcp:{host}:{port}", "cv7_inss")
        assert str(e.value).startswith("unknown device 'cv7_inss' (one of: ")
        assert _open_fds() == before  # no socket left open
        with pytest.raises(socket.timeout):
            listener.accept()  # and none was ever connected


def test_python_device_command_line_names_the_connected_model() -> None:
    # The device command line reads the identity at connect: told another model, it says so.
    from tests.conformance.test_device_cli import cli

    with Sim("mip", "gx5_45", "tcp:127.0.0.1:0") as sim:
        run = cli(sim.address, "ping", "--device", "cv7_ins")
        right = cli(sim.address, "ping", "--device", "gx5_45")
    assert run.returncode == 0, run.stderr
    assert f"mipcodec-device: {MISMATCH}" in run.stderr.splitlines(), run.stderr
    assert right.returncode == 0 and "connected device is" not in right.stderr, right.stderr


def test_c_device_tool_names_the_connected_model(tool) -> None:  # noqa: F811 (the fixture)
    # The C device tool reads the identity at connect, as the Python device command line does.
    with Sim("mip", "gx5_45", "tcp:127.0.0.1:0") as sim:
        run = ctool(tool, sim.address, "ping", "--device", "cv7_ins")
        right = ctool(tool, sim.address, "ping", "--device", "gx5_45")
    assert run.returncode == 0, run.stderr
    assert f"mipcodec-device: {MISMATCH}" in run.stderr.splitlines(), run.stderr
    assert right.returncode == 0 and "connected device is" not in right.stderr, right.stderr
