"""The C package's device tool (`mipcodec-device` built from generated/c/mipcodec, tools/device/;
docs/configure-a-device.md "The C tool") against the simulated devices over a pty and TCP, and
against the Python package's device command line (tests/conformance/test_device_cli.py, whose
simulator and recording proxy this reuses):

- the same output and exit status as the Python CLI for ping (but the reply time), info, send
  and settings dump, on both MIP models and both transports (settings diff and apply: the corpus
  tests/settings/, run by test_settings_corpus.py for both command lines);
- dump -> edit -> apply -> diff is empty; a second apply writes nothing (the recording proxy sees
  no write command);
- a stream over the link budget is refused before any write is sent;
- stream: the text and JSON lines of the fields asked for, --count;
- bad settings files (every mutation of a dump tried here): exit 0, 1 or 2, never a crash; exit 2
  with located `FILE:LINE:` lines or one `mipcodec-device:` line; and the YAML subset's refusals.
"""

from __future__ import annotations

import os
import random
import re
import subprocess
from pathlib import Path

import pytest
import yaml

from tests.conformance.test_device_cli import MODELS, TRANSPORTS, Recorder, Sim, _edit, cli, listen_for
from tests.helpers.builds import c_device_tool

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = "mipcodec"
# C_DEVICE_SANITIZE=1: the tool built with AddressSanitizer and UndefinedBehaviorSanitizer (any
# report ends it with a non-zero status the tests see), in its own build directory
SANITIZE = os.environ.get("C_DEVICE_SANITIZE") == "1"


@pytest.fixture(scope="module")
def tool() -> Path:
    """The C device tool, built with the project's strict flags (warnings are errors)."""
    return c_device_tool(PACKAGE, sanitize=SANITIZE)


def ctool(tool: Path, *args: str, timeout: float = 60) -> subprocess.CompletedProcess:
    run = subprocess.run([str(tool), *args], capture_output=True, text=True, timeout=timeout)
    assert run.returncode >= 0, f"killed by signal {-run.returncode}: {run.stderr}"
    return run


def same(a: subprocess.CompletedProcess, b: subprocess.CompletedProcess, what: str) -> None:
    assert (a.returncode, a.stdout, a.stderr) == (b.returncode, b.stdout, b.stderr), what


# ------------------------------------------------------------------------------ the same output
@pytest.mark.parametrize("transport", TRANSPORTS)
@pytest.mark.parametrize("model", MODELS)
def test_same_output_as_the_python_cli(tool: Path, model: str, transport: str, tmp_path: Path) -> None:
    with Sim(model, listen_for(transport)) as sim:
        a = sim.address
        for args in (
            ["info"],
            ["send", "ping"],
            ["send", "sensor_to_vehicle_euler", "read"],
            ["send", "sensor_to_vehicle_euler", "read", "--json"],
            ["send", "coning_sculling_enable", "read"],
            ["send", "no_such_command"],
            ["settings", "dump"],
            ["settings", "dump", "-"],
        ):
            same(ctool(tool, a, *args), cli(a, *args), " ".join(args))
        # ping: the same line but the reply time
        c, p = ctool(tool, a, "ping"), cli(a, "ping")
        assert (c.returncode, p.returncode) == (0, 0)
        ms = re.compile(r"answered in \d+ ms")
        assert ms.sub("answered in N ms", c.stdout) == ms.sub("answered in N ms", p.stdout)
        # dump to a file: the same file and the same note
        cf, pf = tmp_path / "c.yaml", tmp_path / "p.yaml"
        c, p = ctool(tool, a, "settings", "dump", str(cf)), cli(a, "settings", "dump", str(pf))
        assert (c.returncode, p.returncode) == (0, 0)
        assert cf.read_text() == pf.read_text()
        assert c.stderr.replace(str(cf), "F") == p.stderr.replace(str(pf), "F")
        # settings diff and apply: the corpus (tests/settings/, test_settings_corpus.py)


# ------------------------------------------------------------------------------ settings as data
@pytest.mark.parametrize("model", MODELS)
def test_dump_edit_apply_diff_and_nothing_written_twice(tool: Path, model: str, tmp_path: Path) -> None:
    with Sim(model, "tcp:127.0.0.1:0") as sim:
        recorder = Recorder(sim.address, model)
        a = recorder.address
        dumped = tmp_path / "device.yaml"
        run = ctool(tool, a, "settings", "dump", str(dumped))
        assert run.returncode == 0, run.stderr
        run = ctool(tool, a, "settings", "apply", str(dumped))
        assert (run.returncode, run.stdout) == (0, "nothing to write: the device matches the file\n"), run.stderr
        assert recorder.writes() == []
        edited = tmp_path / "edited.yaml"
        edited.write_text(yaml.safe_dump(_edit(model, yaml.safe_load(dumped.read_text())), sort_keys=False))
        run = ctool(tool, a, "settings", "apply", str(edited))
        assert run.returncode == 0, run.stderr
        assert "accel_bias: bias: [0.0, 0.0, 0.0] -> [0.25, 0.0, -0.5]" in run.stdout
        assert run.stdout.endswith("2 settings written and read back\n")
        assert sorted(recorder.writes()) == sorted(
            ["accel_bias", "imu_message_format" if model == "gx5_45" else "message_format"]
        )
        run = ctool(tool, a, "settings", "diff", str(edited))
        assert (run.returncode, run.stdout) == (0, ""), run.stderr
        # the Python CLI agrees
        run = cli(a, "settings", "diff", str(edited))
        assert (run.returncode, run.stdout) == (0, ""), run.stderr
        before = len(recorder.writes())
        run = ctool(tool, a, "settings", "apply", str(edited))
        assert (run.returncode, run.stdout) == (0, "nothing to write: the device matches the file\n"), run.stderr
        assert len(recorder.writes()) == before
        recorder.close()


def test_stream_over_the_budget_is_refused_before_any_write(tool: Path, tmp_path: Path) -> None:
    """The settings files refused before a write (a setting of another model, a message format
    over the link budget) are corpus cases (tests/settings/mip/); a stream over the budget is
    refused the same way, before its format is written (CV7 lines 4099-4127: three 14-byte fields
    at 1000 Hz need 480000 bit/s, over the device's 115200 baud)."""
    with Sim("cv7_ins", "tcp:127.0.0.1:0") as sim:
        recorder = Recorder(sim.address, "cv7_ins")
        a = recorder.address
        baud = tmp_path / "baud.yaml"
        baud.write_text("uart_baudrate:\n  baud: 115200\n")
        assert ctool(tool, a, "settings", "apply", str(baud)).returncode == 0
        writes = len(recorder.writes())
        run = ctool(tool, a, "stream", "scaled_accel", "scaled_gyro", "scaled_mag", "--count", "1")
        assert run.returncode == 2
        assert "mipcodec-device: total 480000 bit/s of 115200 baud (the device's uart_baudrate) (417%)" in run.stderr
        assert len(recorder.writes()) == writes
        recorder.close()


@pytest.mark.parametrize("transport", TRANSPORTS)
def test_stream_text_and_json(tool: Path, transport: str) -> None:
    with Sim("cv7_ins", listen_for(transport)) as sim:
        run = ctool(tool, sim.address, "stream", "scaled_accel", "scaled_gyro", "--rate", "10", "--count", "3")
        assert run.returncode == 0, run.stderr
        lines = run.stdout.splitlines()
        assert len(lines) == 3
        assert all(
            re.fullmatch(r'scaled_accel \{"scaled_accel":\[.*\]\} scaled_gyro \{"scaled_gyro":\[.*\]\}', x)
            for x in lines
        )
        assert "mipcodec-device: 3 packets of set 0x80;" in run.stderr
        assert "(configured 10 Hz: base 1000 Hz / decimation 100)" in run.stderr
        run = ctool(tool, sim.address, "stream", "0x80:0x04", "--rate", "10", "--count", "2", "--json")
        assert run.returncode == 0, run.stderr
        lines = run.stdout.splitlines()
        assert len(lines) == 2
        assert all(
            re.fullmatch(r'\{"offset":\d+,"set":128,"fields":\[\{"descriptor":4,"name":"scaled_accel".*\}\]\}', x)
            for x in lines
        )
        # the previous (empty) message format is back
        run = ctool(tool, sim.address, "send", "message_format", "read", "desc_set=128")
        assert (
            run.stdout.splitlines()[-1]
            == 'message_format_response {"desc_set":128,"num_descriptors":0,"descriptors":[]}'
        )


def test_save_startup_and_factory_reset(tool: Path) -> None:
    with Sim("gx5_45", "tcp:127.0.0.1:0") as sim:
        for args in (["save-startup"], ["factory-reset"]):
            same(ctool(tool, sim.address, *args), cli(sim.address, *args), args[0])


# ------------------------------------------------------------------------------ bad files
SUBSET_REFUSALS = {
    "a: &x 1\n": "anchors (&) are not in the YAML subset",
    "a: *x\n": "aliases (*) are not in the YAML subset",
    "a: !!str 1\n": "tags (!) are not in the YAML subset",
    "a: |\n  text\n": "block scalars (|) are not in the YAML subset",
    "a: [1,\n  2]\n": "a flow collection that does not end on its line",
    "a: 1\n---\nb: 2\n": "several documents",
    "device: cv7_ins\n\tb: 1\n": "a tab in the indentation",
    "- 1\n- 2\n": "expected a mapping of setting names to values",
    "a: 1\na: 2\n": "'a' given twice (first on line 1)",
    "1: 2\n": "a key must be a name, not 1",
}


def test_yaml_subset_refusals_are_located(tool: Path, tmp_path: Path) -> None:
    with Sim("cv7_ins", "tcp:127.0.0.1:0") as sim:
        for i, (text, message) in enumerate(SUBSET_REFUSALS.items()):
            f = tmp_path / f"bad{i}.yaml"
            f.write_text(text)
            run = ctool(tool, sim.address, "settings", "diff", str(f))
            assert run.returncode == 2, (text, run.stdout, run.stderr)
            first = run.stderr.splitlines()[0]
            assert re.match(rf"{re.escape(str(f))}:\d+: ", first), first
            assert message in first, (text, first)


def _mutations(text: str, count: int, seed: int) -> list[str]:
    """Mutated dumps: bytes replaced, inserted or deleted, lines duplicated, dropped, re-indented or
    swapped, YAML indicators sprinkled in."""
    rng = random.Random(seed)
    pieces = list("-:#[]{},'\"&*!|>%@`?\t \n.0123456789xeE+") + ["\\", "\x00", "\xff", "null", "~", ".inf", "---"]
    out = []
    for _ in range(count):
        lines = text.splitlines(keepends=True)
        for _ in range(rng.randint(1, 4)):
            kind = rng.randrange(6)
            i = rng.randrange(len(lines))
            if kind == 0:
                lines.insert(i, lines[rng.randrange(len(lines))])
            elif kind == 1 and len(lines) > 1:
                del lines[i]
            elif kind == 2:
                lines[i] = " " * rng.randint(0, 6) + lines[i].lstrip(" ")
            elif kind == 3:
                j = rng.randrange(len(lines))
                lines[i], lines[j] = lines[j], lines[i]
            else:
                s = lines[i]
                k = rng.randrange(len(s) + 1)
                p = rng.choice(pieces)
                lines[i] = s[:k] + p + s[k + rng.randint(0, 2) :]
        out.append("".join(lines))
    return out


def test_mutated_dumps_never_crash(tool: Path, tmp_path: Path) -> None:
    with Sim("cv7_ins", "tcp:127.0.0.1:0") as sim:
        dumped = tmp_path / "device.yaml"
        assert ctool(tool, sim.address, "settings", "dump", str(dumped)).returncode == 0
        # the part of a dump with keyed settings, flow lists and comments (a whole dump takes a read
        # of every setting per run)
        text = dumped.read_text()
        start = text.index("sensor_to_vehicle_euler:")
        chunk = "".join(text[start:].splitlines(keepends=True)[:20])
        f = tmp_path / "m.yaml"
        for i, mutated in enumerate(_mutations(chunk, 120, seed=40)):
            f.write_bytes(mutated.encode("latin-1"))
            run = subprocess.run([str(tool), sim.address, "settings", "diff", str(f)], capture_output=True, timeout=60)
            err = run.stderr.decode("latin-1")
            assert run.returncode in (0, 1, 2), (i, mutated, run.returncode, err)
            assert "Sanitizer" not in err and "runtime error" not in err, (mutated, err)
            if run.returncode == 2:
                for line in err.splitlines():
                    assert line.startswith((f"{f}:", "mipcodec-device: ")), (mutated, err)


def test_diff_of_a_device_that_does_not_answer_is_trouble(tool: Path, tmp_path: Path) -> None:
    path = tmp_path / "bias.yaml"
    path.write_text("accel_bias:\n  bias: [0.0, 0.0, 0.0]\n")
    with Sim("gx5_45", "pty", "--drop", "accel_bias") as sim:
        run = ctool(tool, sim.address, "settings", "diff", str(path), "--timeout-ms", "300")
        assert run.returncode == 2, run.stderr
        assert "cannot read the device: accel_bias: no reply before the timeout" in run.stderr


def test_apply_follows_a_baud_rate_change_on_a_serial_port(tool: Path, tmp_path: Path) -> None:
    # the simulator's --baud: the change is acknowledged at the old rate, then the pty serves the
    # new rate only; apply writes it last, waits the settle time (spec link) and reads it back there
    path = tmp_path / "baud.yaml"
    path.write_text("uart_baudrate:\n  baud: 921600\naccel_bias:\n  bias: [0.5, 0.0, 0.0]\n")
    with Sim("gx5_45", "pty", "--baud") as sim:
        run = ctool(tool, sim.address, "settings", "apply", str(path))
        assert run.returncode == 0, run.stderr
        assert run.stdout.splitlines()[-2:] == [
            "uart_baudrate: baud: 115200 -> 921600",
            "2 settings written and read back",
        ]
        assert ctool(tool, sim.address, "ping", "--baud", "921600").returncode == 0


# ------------------------------------------------------------------------------ auto
def test_auto_scans_the_given_ports_as_the_python_cli(tool: Path, tmp_path: Path) -> None:
    with Sim("gx5_45", "pty") as a, Sim("cv7_ins", "pty") as b:
        absent = str(tmp_path / "no-such-port")
        args = ["auto", "ping", "--ports", a.address, absent, b.address]
        c, p = ctool(tool, *args), cli(*args)
        same(c, p, "auto ping")
        assert c.returncode == 0 and len(c.stdout.splitlines()) == 2
        assert f"{absent}: no answer at 115200, " in c.stderr
    c, p = ctool(tool, "auto", "ping", "--ports", absent), cli("auto", "ping", "--ports", absent)
    same(c, p, "auto ping, nothing answers")
    assert c.returncode == 1
    for args in (["auto", "info"], ["auto", "ping", "--ports"], ["tcp:127.0.0.1:1", "ping", "--ports", absent]):
        run = ctool(tool, *args)
        assert run.returncode == 2 and run.stdout == "" and len(run.stderr.splitlines()) == 1, (args, run.stderr)
