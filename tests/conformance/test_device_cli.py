"""The device command line of the Python package (`python -m mipcodec device`, the console script
`mipcodec-device`; docs/configure-a-device.md) against the simulated devices over a pty and TCP.

- settings as data: dump -> edit -> apply -> diff is empty, and a second apply writes nothing
  (proved over TCP by a recording proxy between the command line and the simulator: no write
  command reaches the device), for both MIP models;
- refused before any write is sent: a setting the connected model does not support, a message
  format over the link budget (the manuals' UART bandwidth calculation); --force writes anyway;
- bad files: one located `FILE:LINE: ...` line per problem, exit status 2, no traceback;
- every subcommand: ping, info, stream, send, settings dump/apply/diff/schema, save-startup,
  factory-reset, and `auto` over a pty (`--ports`);
- the link budget against the manuals' worked example (GX5-45 dcp lines 556-562, CV7 lines
  4121-4127: 14-byte and 6-byte fields at 100 Hz need 26000 baud);
- the dump validates against the generated JSON Schema (settings.schema.json).
"""

from __future__ import annotations

import importlib
import json
import os
import re
import select
import socket
import subprocess
import sys
import threading
from pathlib import Path

import jsonschema
import pytest
import yaml

from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
PACKAGE_DIR = ROOT / "generated" / "python" / "mipcodec"
SIMULATE = ROOT / "tests" / "conformance" / "simulate"
MODELS = ["gx5_45", "cv7_ins"]
TRANSPORTS = ["pty", "tcp"]

mip = python_package("mipcodec")


class Sim:
    """A running simulator (`tests/conformance/simulate`); `address` is its first line."""

    def __init__(self, device: str, listen: str, *extra: str) -> None:
        cmd = [str(SIMULATE), "--listen", listen, "--device", device, "--speed", "10", *extra]
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        ready, _, _ = select.select([self.proc.stdout], [], [], 30)
        self.address = self.proc.stdout.readline().strip() if ready else ""
        if not self.address:
            self.close()
            raise AssertionError(f"the simulator printed no address: {self.proc.stderr.read()}")

    def close(self) -> None:
        if self.proc.poll() is None:
            self.proc.terminate()
            self.proc.wait(10)

    def __enter__(self) -> Sim:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class Recorder:
    """A TCP proxy on 127.0.0.1 between the command line and the simulator that records every
    byte the command line sends (the device's received-command log)."""

    def __init__(self, target: str, device: str) -> None:
        self.device = device
        host, _, port = target[len("tcp:") :].rpartition(":")
        self.target = (host, int(port))
        self.sent = bytearray()
        self.server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self.server.bind(("127.0.0.1", 0))
        self.server.listen(4)
        self.address = f"tcp:127.0.0.1:{self.server.getsockname()[1]}"
        threading.Thread(target=self._accept, daemon=True).start()

    def _accept(self) -> None:
        while True:
            try:
                client, _ = self.server.accept()
            except OSError:
                return
            upstream = socket.create_connection(self.target)
            threading.Thread(target=self._pipe, args=(client, upstream, True), daemon=True).start()
            threading.Thread(target=self._pipe, args=(upstream, client, False), daemon=True).start()

    def _pipe(self, a: socket.socket, b: socket.socket, record: bool) -> None:
        try:
            while True:
                data = a.recv(65536)
                if not data:
                    break
                if record:
                    self.sent += data
                b.sendall(data)
        except OSError:
            pass
        finally:
            for s in (a, b):
                try:
                    s.shutdown(socket.SHUT_RDWR)
                except OSError:
                    pass

    def commands(self) -> list[tuple[str, int | None]]:
        """(command name, function value or None) of every command received so far."""
        out = []
        decoder = mip.codec.packets.Decoder(self.device)
        for event in decoder.feed(bytes(self.sent)) + decoder.flush():
            for f in getattr(event, "fields", []):
                value = getattr(f, "value", None)
                if value is not None:
                    fn = getattr(value, "function", None)
                    out.append((value.NAME, None if fn is None else int(fn)))
        return out

    def writes(self) -> list[str]:
        return [name for name, fn in self.commands() if fn == 1]

    def close(self) -> None:
        self.server.close()


def cli(*args: str, stdin: str | None = None, timeout: float = 120) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(PACKAGE_DIR)}
    run = subprocess.run(
        [sys.executable, "-m", "mipcodec", "device", *args],
        capture_output=True,
        text=True,
        env=env,
        input=stdin,
        timeout=timeout,
    )
    assert "Traceback" not in run.stderr, run.stderr
    return run


def listen_for(transport: str) -> str:
    return "pty" if transport == "pty" else "tcp:127.0.0.1:0"


# ----------------------------------------------------------------------------- settings files
# An edit per model: a float setting and a message format within the link budget at 115200 baud
# (GX5-45: scaled accel and gyro at 500 / 50 = 10 Hz: 10 x (6 x 10 + 2 x 14 x 10) = 3400 bit/s;
# CV7: the same two fields at 1000 / 100 = 10 Hz in set 0x80).
def _edit(model: str, doc: dict) -> dict:
    doc = dict(doc)
    doc["accel_bias"] = {"bias": [0.25, 0.0, -0.5]}
    fmt = [{"descriptor": 4, "decimation": 50}, {"descriptor": 5, "decimation": 50}]
    if model == "gx5_45":
        doc["imu_message_format"] = {"descriptors": fmt}
    else:
        fmt = [{"descriptor": 4, "decimation": 100}, {"descriptor": 5, "decimation": 100}]
        doc["message_format"] = [
            {**e, "descriptors": fmt} if e["desc_set"] == 0x80 else e for e in doc["message_format"]
        ]
    return doc


@pytest.mark.parametrize("transport", TRANSPORTS)
@pytest.mark.parametrize("model", MODELS)
def test_dump_edit_apply_diff_round_trip(model: str, transport: str, tmp_path: Path) -> None:
    with Sim(model, listen_for(transport)) as sim:
        recorder = Recorder(sim.address, model) if transport == "tcp" else None
        address = recorder.address if recorder else sim.address
        dumped = tmp_path / "device.yaml"
        run = cli(address, "settings", "dump", str(dumped))
        assert run.returncode == 0, run.stderr
        text = dumped.read_text()
        assert text.startswith("# mipcodec settings of a ")
        assert f"device: {model}\n" in text
        assert "  bias: [0.0, 0.0, 0.0]  # g\n" in text  # units as comments
        doc = yaml.safe_load(text)
        jsonschema.validate(doc, json.loads((PACKAGE_DIR / "mipcodec/settings.schema.json").read_text()))
        # the same file applied: nothing to write
        run = cli(address, "settings", "apply", str(dumped))
        assert run.returncode == 0, run.stderr
        assert "nothing to write: the device matches the file" in run.stdout
        edited = tmp_path / "edited.yaml"
        edited.write_text(yaml.safe_dump(_edit(model, doc), sort_keys=False))
        run = cli(address, "settings", "diff", str(edited))
        assert run.returncode == 1, run.stderr
        assert "accel_bias.bias: device [0.0, 0.0, 0.0], file [0.25, 0.0, -0.5]" in run.stdout
        run = cli(address, "settings", "apply", str(edited))
        assert run.returncode == 0, run.stderr
        assert "accel_bias: bias: [0.0, 0.0, 0.0] -> [0.25, 0.0, -0.5]" in run.stdout
        assert "2 settings written and read back" in run.stdout
        run = cli(address, "settings", "diff", str(edited))
        assert (run.returncode, run.stdout) == (0, ""), run.stderr
        before = len(recorder.writes()) if recorder else 0
        run = cli(address, "settings", "apply", str(edited))
        assert run.returncode == 0, run.stderr
        assert "nothing to write" in run.stdout
        if recorder is not None:
            assert recorder.writes()[before:] == []  # the second apply wrote nothing
            assert {"accel_bias", "imu_message_format" if model == "gx5_45" else "message_format"} <= set(
                recorder.writes()
            )
            recorder.close()


# --------------------------------------------------------------------- refused before writing
def test_unsupported_setting_refused_before_any_write(tmp_path: Path) -> None:
    path = tmp_path / "cv7.yaml"
    path.write_text("device: cv7_ins\naccel_bias:\n  bias: [0.5, 0.0, 0.0]\nconing_sculling_enable:\n  enable: false\n")
    with Sim("cv7_ins", "tcp:127.0.0.1:0") as sim:
        recorder = Recorder(sim.address, "cv7_ins")
        run = cli(recorder.address, "settings", "apply", str(path))
        assert run.returncode == 2
        assert (
            f"{path}:4: coning_sculling_enable is not supported by 3DM-CV7-GNSS/INS (3dm-cv7-ins-docs.txt) "
            "(a setting of gx5_45)"
        ) in run.stderr
        assert "nothing was written" in run.stderr
        assert recorder.writes() == []
        assert recorder.commands()  # it did talk to the device (the model's identity)
        recorder.close()


def _over_budget(tmp_path: Path) -> Path:
    # GX5-45 IMU set at 500 Hz: accel, gyro and mag (12 + 2 bytes each) at decimation 1:
    # 10 x (6 x 500 + 3 x 14 x 500) = 240000 bit/s > 115200 baud.
    path = tmp_path / "fast.yaml"
    path.write_text(
        "device: gx5_45\naccel_bias:\n  bias: [0.5, 0.0, 0.0]\nimu_message_format:\n"
        "  descriptors:\n    - {descriptor: 4, decimation: 1}\n    - {descriptor: 5, decimation: 1}\n"
        "    - {descriptor: 6, decimation: 1}\n"
    )
    return path


def test_over_budget_refused_before_any_write(tmp_path: Path) -> None:
    path = _over_budget(tmp_path)
    with Sim("gx5_45", "tcp:127.0.0.1:0") as sim:
        recorder = Recorder(sim.address, "gx5_45")
        run = cli(recorder.address, "settings", "apply", str(path))
        assert run.returncode == 2
        assert "set 0x80: 240000 bit/s (24000 bytes/s, 500 packets/s)" in run.stderr
        assert "link budget exceeded: the message formats need 240000 bit/s, the port carries 115200 baud" in run.stderr
        assert "nothing was written" in run.stderr
        assert recorder.writes() == []
        # the baud rate given on the command line (TCP has none of its own)
        run = cli(recorder.address, "settings", "apply", str(path), "--baud", "921600")
        assert run.returncode == 0, run.stderr
        assert recorder.writes() == ["accel_bias", "imu_message_format"]
        recorder.close()


def test_over_budget_forced_warns_and_writes(tmp_path: Path) -> None:
    path = _over_budget(tmp_path)
    with Sim("gx5_45", "pty") as sim:
        run = cli(sim.address, "settings", "apply", str(path), "--force")
        assert run.returncode == 0, run.stderr
        assert "warning: link budget exceeded" in run.stderr
        assert "imu_message_format: descriptors: [] -> " in run.stdout


def test_stream_over_budget_refused(tmp_path: Path) -> None:
    with Sim("gx5_45", "tcp:127.0.0.1:0") as sim:
        recorder = Recorder(sim.address, "gx5_45")
        run = cli(recorder.address, "stream", "scaled_accel", "scaled_gyro", "scaled_mag", "--count", "1")
        assert run.returncode == 2
        assert "link budget exceeded" in run.stderr
        assert recorder.writes() == []
        recorder.close()


# ------------------------------------------------------------------------------- bad files
BAD_FILES = [
    ("frobnicate:\n  x: 1\n", 1, "unknown setting 'frobnicate'"),
    ("accel_bias:\n  bias: fast\n", 2, "accel_bias.bias"),
    ("accel_bias:\n  bias: [0.0, 0.0]\n", 2, "accel_bias.bias"),
    ("uart_baudrate:\n  baud: -5\n", 2, "out of range"),
    ("accel_bias:\n  bias: [0.0, 0.0, 0.0]\n  extra: 1\n", 3, "accel_bias: unknown parameter 'extra'"),
    ("complementary_filter:\n  pitch_roll_enable: true\n", 1, "complementary_filter: missing"),
    ("data_stream_control:\n  - device_selector: sideways\n    enable: 1\n", 2, "not a member of Gx5StreamSelector"),
    ("data_stream_control:\n  device_selector: imu\n  enable: 1\n", 1, "expected a list of entries"),
    ("accel_bias: [\n", 2, "not valid YAML"),
    ("accel_bias:\n  bias: [0, 0, 0]\naccel_bias:\n  bias: [1, 1, 1]\n", 3, "'accel_bias' given twice"),
    ("- 1\n- 2\n", 1, "expected a mapping of setting names to values"),
    ("device: cv7_ins\n", 1, "the file is for 'cv7_ins', the connected model is gx5_45"),
]


def test_bad_files_give_located_errors(tmp_path: Path) -> None:
    with Sim("gx5_45", "pty") as sim:
        for i, (text, line, message) in enumerate(BAD_FILES):
            path = tmp_path / f"bad{i}.yaml"
            path.write_text(text)
            for action in ("apply", "diff"):
                run = cli(sim.address, "settings", action, str(path))
                assert run.returncode == 2, (text, run.stdout, run.stderr)
                first = run.stderr.splitlines()[0]
                assert first.startswith(f"{path}:{line}: "), (text, run.stderr)
                assert message in first, (text, run.stderr)
        # every problem of a file at once, before anything is written
        path = tmp_path / "many.yaml"
        path.write_text("frobnicate: 1\naccel_bias:\n  bias: fast\nconing_sculling_enable:\n  enable: 3\n")
        run = cli(sim.address, "settings", "apply", str(path))
        assert run.returncode == 2
        located = [x for x in run.stderr.splitlines() if x.startswith(str(path))]
        assert [x.split(":")[1] for x in located] == ["1", "3", "5"], run.stderr
        assert "3 problem(s) in the settings file; nothing was written" in run.stderr
        missing = cli(sim.address, "settings", "apply", str(tmp_path / "absent.yaml"))
        assert missing.returncode == 2 and "cannot read" in missing.stderr


# ---------------------------------------------------------------------------- subcommands
@pytest.mark.parametrize("transport", TRANSPORTS)
def test_ping_info_send(transport: str) -> None:
    with Sim("cv7_ins", listen_for(transport)) as sim:
        run = cli(sim.address, "ping")
        assert run.returncode == 0, run.stderr
        assert re.fullmatch(r"3DM-CV7-GNSS/INS 6284\.170342 answered in \d+ ms\n", run.stdout), run.stdout
        run = cli(sim.address, "info")
        assert run.returncode == 0, run.stderr
        lines = run.stdout.splitlines()
        assert lines[0] == "model: 3DM-CV7-GNSS/INS (cv7_ins, manual 3dm-cv7-ins-docs.txt)"
        assert "serial: 6284.170342" in lines and "firmware: 1202" in lines
        assert any(x.startswith("descriptors: ") for x in lines)
        assert "  0x80 sensor: 04 05 06 07 08 09 0A 0C 10 11 12 17" in lines or any(
            x.startswith("  0x80 sensor: 04 05 06") for x in lines
        )
        assert "base rates: 0x80 1000 Hz, 0x82 1000 Hz, 0x91 5 Hz, 0x92 5 Hz, 0xA0 1000 Hz" in lines
        assert "link budget:" in lines
        if transport == "pty":  # the serial port's rate
            assert f"  total 0 bit/s of 115200 baud ({sim.address}) (0%)" in lines, lines
        else:  # TCP has none: the device's own UART rate, 115200 in the simulator (its plausible value,
            # the lowest rate the CV7's main UART serves, 3dm-cv7-ins-docs.txt:2718; the manual states no default)
            assert "  total 0 bit/s of 115200 baud (the device's uart_baudrate) (0%)" in lines, lines
        run = cli(sim.address, "info", "--baud", "921600")
        assert "  total 0 bit/s of 921600 baud (--baud) (0%)" in run.stdout.splitlines(), run.stdout
        run = cli(sim.address, "send", "sensor_to_vehicle_euler", "write", "roll=0.5", "pitch=0", "yaw=-1")
        assert (run.returncode, run.stdout) == (0, "sensor_to_vehicle_euler: ack\n"), run.stderr
        run = cli(sim.address, "send", "sensor_to_vehicle_euler", "read")
        assert run.returncode == 0
        assert run.stdout.splitlines()[1] == 'sensor_to_vehicle_euler_response {"roll":0.5,"pitch":0.0,"yaw":-1.0}'
        run = cli(sim.address, "send", "sensor_to_vehicle_euler", "read", "--json")
        assert json.loads(run.stdout)["result"] == "ack"
        run = cli(sim.address, "send", "coning_sculling_enable", "read")
        assert run.returncode == 2
        assert "coning_sculling_enable is not supported by 3DM-CV7-GNSS/INS (3dm-cv7-ins-docs.txt)" in run.stderr
        assert cli(sim.address, "send", "no_such_command").returncode == 2
        run = cli(sim.address, "send", "sensor_to_vehicle_euler")
        assert run.returncode == 2 and "give the function first (write, read, save, load, default)" in run.stderr
        run = cli(sim.address, "send", "sensor_to_vehicle_euler", "write", "roll=abc", "pitch=0", "yaw=0")
        assert run.returncode == 2 and "roll" in run.stderr


def test_send_nack_exits_1() -> None:
    with Sim("cv7_ins", "pty", "--nack", "sensor_to_vehicle_euler") as sim:
        run = cli(sim.address, "send", "sensor_to_vehicle_euler", "read")
        assert run.returncode == 1
        assert "sensor_to_vehicle_euler: NACK, code 3" in run.stdout


@pytest.mark.parametrize("model,field,base", [("gx5_45", "scaled_accel", 500), ("cv7_ins", "scaled_gyro", 1000)])
def test_stream(model: str, field: str, base: int, tmp_path: Path) -> None:
    with Sim(model, "pty") as sim:
        dumped = tmp_path / "before.yaml"
        assert cli(sim.address, "settings", "dump", str(dumped)).returncode == 0
        run = cli(sim.address, "stream", field, "--rate", "50", "--count", "5", "--json")
        assert run.returncode == 0, run.stderr
        lines = [json.loads(x) for x in run.stdout.splitlines()]
        assert len(lines) == 5
        assert all(x["set"] == 0x80 and x["fields"][0]["name"] == field for x in lines)
        decimation = base // 50
        assert re.search(
            rf"5 packets of set 0x80; observed [0-9.]+ Hz \(configured 50 Hz: base {base} Hz / decimation {decimation}\)",
            run.stderr,
        ), run.stderr
        run = cli(sim.address, "stream", field, "--rate", "100", "--duration", "0.5")
        assert run.returncode == 0, run.stderr
        assert run.stdout.startswith(f"{field} {{")
        # the message format is restored afterwards
        assert cli(sim.address, "settings", "diff", str(dumped)).returncode == 0
        bad = cli(sim.address, "stream", "no_such_field")
        assert bad.returncode == 2 and "'no_such_field' is not a data field of" in bad.stderr


@pytest.mark.parametrize("model", MODELS)
def test_save_startup_and_factory_reset(model: str, tmp_path: Path) -> None:
    with Sim(model, "pty") as sim:
        factory = tmp_path / "factory.yaml"
        assert cli(sim.address, "settings", "dump", str(factory)).returncode == 0
        edited = tmp_path / "edited.yaml"
        edited.write_text(f"device: {model}\naccel_bias:\n  bias: [0.5, 0.5, 0.5]\n")
        run = cli(sim.address, "settings", "apply", str(edited), "--save")
        assert run.returncode == 0, run.stderr
        assert "saved as startup settings" in run.stdout
        run = cli(sim.address, "factory-reset")
        assert run.returncode == 0, run.stderr
        assert cli(sim.address, "settings", "diff", str(factory)).returncode == 0
        assert cli(sim.address, "settings", "diff", str(edited)).returncode == 1
        run = cli(sim.address, "save-startup")
        assert (run.returncode, run.stdout) == (0, "current settings saved as startup settings\n")


def test_dump_to_stdout_and_schema() -> None:
    with Sim("gx5_45", "tcp:127.0.0.1:0") as sim:
        run = cli(sim.address, "settings", "dump")
        assert run.returncode == 0
        assert "device: gx5_45\n" in run.stdout
        assert cli(sim.address, "settings", "dump", "-").stdout == run.stdout
        applied = cli(sim.address, "settings", "apply", "-", stdin=run.stdout)
        assert "nothing to write" in applied.stdout
    run = cli("tcp:127.0.0.1:1", "settings", "schema")
    assert run.returncode == 0 and Path(run.stdout.strip()).name == "settings.schema.json"


def test_auto_scans_the_given_ports(tmp_path: Path) -> None:
    with Sim("gx5_45", "pty") as a, Sim("cv7_ins", "pty") as b:
        absent = str(tmp_path / "no-such-port")
        run = cli("auto", "ping", "--ports", a.address, absent, b.address)
        assert run.returncode == 0, run.stderr
        assert run.stdout.splitlines() == [
            f"{a.address} 115200 3DM-GX5-45 (gx5_45) serial 6232-00122",
            f"{b.address} 115200 3DM-CV7-GNSS/INS (cv7_ins) serial 6284.170342",
        ]
        assert f"{absent}: no answer at " in run.stderr
    run = cli("auto", "ping", "--ports", absent)
    assert run.returncode == 1


def test_usage_and_connection_errors() -> None:
    for args in (
        ["tcp:127.0.0.1:1", "ping"],  # nothing listens
        ["tcp:nohost", "ping"],  # a bad address
        ["tcp:127.0.0.1:1", "bogus"],
        ["tcp:127.0.0.1:1", "ping", "--device", "nope"],
        ["auto", "info"],
    ):
        run = cli(*args)
        assert run.returncode == 2, (args, run.stderr)
        assert run.stderr.strip(), args


# ------------------------------------------------------------------------------ the budget
def test_budget_matches_the_manuals_worked_example() -> None:
    # GX5-45 dcp lines 556-562 and CV7 lines 4121-4127: an IMU message of the accelerometer vector
    # (a 14-byte field) and an internal timestamp (6 bytes), both at 100 Hz: 26000 baud. Neither
    # model's sensor set has a 4-byte timestamp field, so the 6-byte field here is the scaled
    # pressure (0x80,0x17: one f32, 4 + 2 bytes), the same size.
    budget = importlib.import_module("mipcodec.device.budget")
    for model, base, decimation in (("gx5_45", 500.0, 5), ("cv7_ins", 1000.0, 10)):
        s = budget.stream(model, 0x80, [(0x04, decimation), (0x17, decimation)], base)
        assert s.fields == ((0x04, 14, 100.0), (0x17, 6, 100.0)), model
        assert s.bits_per_s == 26000
        assert s.bytes_per_s == 2600


def test_the_console_script_is_declared() -> None:
    text = (PACKAGE_DIR / "pyproject.toml").read_text()
    assert 'mipcodec-device = "mipcodec.device.cli:main"' in text
    assert '"settings.schema.json"' in text


def test_diff_exits_2_when_the_device_does_not_answer(tmp_path: Path) -> None:
    path = tmp_path / "bias.yaml"
    path.write_text("accel_bias:\n  bias: [0.0, 0.0, 0.0]\n")
    with Sim("gx5_45", "pty", "--drop", "accel_bias") as sim:
        run = cli(sim.address, "settings", "diff", str(path), "--timeout-ms", "300")
        assert run.returncode == 2, run.stderr
        assert "cannot read the device: accel_bias: no reply before the timeout" in run.stderr


def test_apply_follows_a_baud_rate_change_on_a_serial_port(tmp_path: Path) -> None:
    # the simulator's --baud: the change is acknowledged at the old rate, then the pty serves the
    # new rate only; apply writes it last, waits the settle time (spec link) and reads it back there
    path = tmp_path / "baud.yaml"
    path.write_text("uart_baudrate:\n  baud: 921600\naccel_bias:\n  bias: [0.5, 0.0, 0.0]\n")
    with Sim("gx5_45", "pty", "--baud") as sim:
        run = cli(sim.address, "settings", "apply", str(path))
        assert run.returncode == 0, run.stderr
        assert run.stdout.splitlines()[-2:] == [
            "uart_baudrate: baud: 115200 -> 921600",
            "2 settings written and read back",
        ]
        assert cli(sim.address, "ping", "--baud", "921600").returncode == 0
        # no answer at 115200 now: a silent device, 1 (docs/configure-a-device.md, exit status)
        assert cli(sim.address, "ping", "--timeout-ms", "300").returncode == 1


def test_with_the_model_given_a_file_is_refused_before_any_byte_is_sent(tmp_path: Path) -> None:
    """`settings apply FILE --device MODEL` checks the file without a connection: an unsupported
    setting, and message formats that alone exceed the link budget, are refused before the
    command line even connects (a listener on 127.0.0.1 counts connections and bytes: none)."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(4)
    server.settimeout(0.2)
    address = f"tcp:127.0.0.1:{server.getsockname()[1]}"
    unsupported = tmp_path / "unsupported.yaml"  # a CV7 setting in a GX5-45 file
    unsupported.write_text("sensor_to_vehicle_euler:\n  roll: 0.0\n  pitch: 0.0\n  yaw: 0.5\n")
    fast = tmp_path / "fast.yaml"  # 3 x 14 B at 500 Hz: 60*500 + 10*(3*14*500) = 240000 bit/s
    fast.write_text(
        "imu_message_format:\n  descriptors:\n"
        + "".join(f"    - {{descriptor: {d}, decimation: 1}}\n" for d in (4, 5, 6))
    )
    try:
        run = cli(address, "settings", "apply", str(unsupported), "--device", "gx5_45")
        assert run.returncode == 2, run.stderr
        assert "unsupported.yaml:1: sensor_to_vehicle_euler is not supported by 3DM-GX5-45" in run.stderr
        run = cli(address, "settings", "apply", str(fast), "--device", "gx5_45", "--baud", "115200")
        assert run.returncode == 2, run.stderr
        assert "the message formats need 240000 bit/s, the port carries 115200 baud (--baud)" in run.stderr
        assert "Traceback" not in run.stderr
        with pytest.raises(socket.timeout):
            server.accept()  # nobody connected
    finally:
        server.close()
