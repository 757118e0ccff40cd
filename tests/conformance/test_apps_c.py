"""The C application program tests/apps/c/cv7_external_aiding.c with bad input (tests/apps/README.md):
wrong arguments exit 2 with `usage: ...`; an unreadable or malformed feed, an unreachable address,
a command the device does not acknowledge and a passed deadline exit 1 with `error: ...`, never a
crash. Its run to full navigation is test_simulator_world.py::test_cv7_application_program_*.

The issue-35 programs (gx5_continuous, gx5_polling, cv7_ahrs, cv7_gnss_ins; tests/apps/README.md)
with the same bad input: wrong arguments, an unreachable address, a NACK (of the first command
they share, and of one of their own flow), a passed deadline. Their runs to the manuals' states are
test_apps_flows.py."""

from __future__ import annotations

import socket
import subprocess

import pytest

from tests.conformance.test_simulator import ROOT, TRANSPORTS, Sim, listen_for
from tests.conformance.test_simulator_world import SPEED, run_app, write_aiding_feed

APP = "cv7_external_aiding"
SOURCES = sorted((ROOT / "tests/apps/c").glob("*.c"))


@pytest.fixture(scope="module")
def feed(tmp_path_factory):
    path = tmp_path_factory.mktemp("feed") / "aiding.txt"
    write_aiding_feed(path)
    built = run_app("c", APP, timeout=1800)  # builds the program: no argument is a usage error
    assert built.returncode == 2 and built.stderr.startswith("usage: "), built.stderr
    return path


def closed_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_sources_are_formatted() -> None:
    format_tool = ROOT / ".venv/bin/clang-format"
    cmd = [str(format_tool), f"--style=file:{ROOT / '.clang-format'}", "--dry-run", "-Werror", *map(str, SOURCES)]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert SOURCES and r.returncode == 0, r.stderr


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("tcp:127.0.0.1:1",), "usage: cv7_external_aiding ADDRESS FEED"),
        (("a", "b", "c"), "usage: unexpected argument c"),
        (("a", "b", "--samples", "0"), "usage: --samples 0: not a number"),
        (("a", "b", "--period-ms", "x"), "usage: --period-ms x: not a number"),
        (("a", "b", "--deadline-s"), "usage: --deadline-s needs a value"),
        (("a", "b", "--speed", "2"), "usage: unknown option --speed"),
    ],
)
def test_wrong_arguments_exit_2(feed, args, message) -> None:
    r = run_app("c", APP, *args)
    assert r.returncode == 2 and r.stderr.startswith(message), r.stderr
    assert r.stdout == ""


def test_bad_feed_and_address_exit_1(feed, tmp_path) -> None:
    bad = tmp_path / "bad.txt"
    bad.write_text("# tow ns ...\n1 2 3 4 5 6 7 8 9 10 11 12\n1.0 2 3 4")  # the last row short, no newline
    empty = tmp_path / "empty.txt"
    empty.write_text("# only a comment\n")
    cases = [
        (("tcp:127.0.0.1:9", str(tmp_path / "missing.txt")), "error: cannot read the feed"),
        (("tcp:127.0.0.1:9", str(tmp_path)), "error: cannot read the feed"),  # a directory
        (("tcp:127.0.0.1:9", str(bad)), f"error: {bad}:3: expected 12 numbers"),
        (("tcp:127.0.0.1:9", str(empty)), "error: the feed"),
        ((f"tcp:127.0.0.1:{closed_port()}", str(feed)), "error: cannot connect to 127.0.0.1"),
        ((str(tmp_path / "no-such-tty"), str(feed)), "error: cannot open"),
        (("tcp:localhost", str(feed)), "error: bad TCP address"),
    ]
    for args, message in cases:
        r = run_app("c", APP, *args)
        assert r.returncode == 1 and r.stderr.startswith(message), (args, r.stderr)


def test_command_not_acknowledged_exits_1(feed) -> None:
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", "--speed", str(SPEED), "--nack", "set_to_idle") as sim:
        r = run_app("c", APP, sim.address, str(feed))
    assert r.returncode == 1 and "error: base.set_to_idle: nack (code" in r.stderr, r.stderr


def test_deadline_exits_1(feed) -> None:
    args = ("--scenario", "circle", "--speed", str(SPEED))
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", *args) as sim:
        period = str(round(500 / SPEED))
        r = run_app("c", APP, sim.address, str(feed), "--period-ms", period, "--samples", "100000", "--deadline-s", "2")
    assert r.returncode == 1 and "error: deadline of 2 s passed" in r.stderr, r.stderr
    assert "mode 4" in r.stdout.splitlines() and r.stdout.count("{") > 0  # it navigated, then gave up


@pytest.mark.parametrize("transport", TRANSPORTS)
def test_lost_connection_exits_1(feed, transport: str) -> None:
    args = ("--scenario", "circle", "--speed", str(SPEED))
    with Sim("mip", "cv7_ins", listen_for(transport), *args) as sim:
        cmd = [str(ROOT / "build/c-apps" / APP), sim.address, str(feed), "--period-ms", "50", "--samples", "100000"]
        app = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            while not app.stdout.readline().startswith("{"):  # navigating: then the device goes away
                assert app.poll() is None, app.stderr.read()
            sim.close()
            _, err = app.communicate(timeout=30)
        finally:
            if app.poll() is None:
                app.kill()
    assert app.returncode == 1 and "error: " in err, err


# ------------------------------------------------------------------------------- the issue-35 programs
# program -> (device, a command of its own flow to refuse, the error line's command name)
FLOW_APPS = {
    "gx5_continuous": ("gx5_45", "filter_message_format", "threedm.filter_message_format write"),
    "gx5_polling": ("gx5_45", "poll_filter_data", "threedm.poll_filter_data"),
    "cv7_ahrs": ("cv7_ins", "aiding_measurement_control", "filter.aiding_measurement_control write (magnetometer)"),
    "cv7_gnss_ins": ("cv7_ins", "multi_antenna_offset", "filter.multi_antenna_offset write"),
}


@pytest.fixture(scope="module")
def flow_apps() -> None:
    for name in FLOW_APPS:
        built = run_app("c", name, timeout=1800)  # builds the program: no argument is a usage error
        assert built.returncode == 2 and built.stderr.startswith(f"usage: {name} ADDRESS"), built.stderr
        assert built.stdout == ""


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("a", "b"), "usage: unexpected argument b"),
        (("a", "--samples", "0"), "usage: --samples 0: not a number from 1"),
        (("a", "--samples", "-3"), "usage: --samples -3: not a number from 1"),
        (("a", "--deadline-s", "x"), "usage: --deadline-s x: not a number from 1"),
        (("a", "--deadline-s"), "usage: --deadline-s needs a value"),
        (("a", "--speed", "2"), "usage: unknown option --speed"),
        (("--samples", "5"), "usage: "),  # no address
    ],
)
def test_flow_app_wrong_arguments_exit_2(flow_apps, name, args, message) -> None:
    r = run_app("c", name, *args)
    assert r.returncode == 2 and r.stderr.startswith(message), r.stderr
    assert f"usage: {name} ADDRESS" in r.stderr and r.stdout == ""


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("a", "--antennas", "3"), "usage: --antennas 3: not a number from 1 to 2"),
        (("a", "--antennas", "0"), "usage: --antennas 0: not a number from 1 to 2"),
        (("a", "--antennas"), "usage: --antennas needs a value"),
    ],
)
def test_gnss_ins_antennas_are_1_or_2(flow_apps, args, message) -> None:
    r = run_app("c", "cv7_gnss_ins", *args)
    assert r.returncode == 2 and r.stderr.startswith(message), r.stderr


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
def test_flow_app_help_on_stdout(flow_apps, name) -> None:
    r = run_app("c", name, "--help")
    assert r.returncode == 0 and r.stdout.startswith(f"usage: {name} ADDRESS") and r.stderr == ""


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
def test_flow_app_unreachable_address_exits_1(flow_apps, name, tmp_path) -> None:
    cases = [
        ((f"tcp:127.0.0.1:{closed_port()}",), "error: cannot connect to 127.0.0.1"),
        ((str(tmp_path / "no-such-tty"),), "error: cannot open"),
        (("tcp:localhost",), "error: bad TCP address"),
    ]
    for args, message in cases:
        r = run_app("c", name, *args)
        assert r.returncode == 1 and r.stderr.startswith(message), (args, r.stderr)
        assert r.stdout == ""


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
def test_flow_app_command_not_acknowledged_exits_1(flow_apps, name) -> None:
    device, own, label = FLOW_APPS[name]
    with Sim("mip", device, "tcp:127.0.0.1:0", "--speed", str(SPEED), "--nack", "set_to_idle") as sim:
        r = run_app("c", name, sim.address)
    assert r.returncode == 1 and r.stderr.startswith("error: base.set_to_idle: nack (code"), r.stderr
    with Sim("mip", device, "tcp:127.0.0.1:0", "--speed", str(SPEED), "--nack", own) as sim:
        r = run_app("c", name, sim.address)
    assert r.returncode == 1 and f"error: {label}: nack (code" in r.stderr, r.stderr
    assert r.stdout.startswith("model "), r.stdout  # the device information came first


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
def test_flow_app_deadline_exits_1(flow_apps, name) -> None:
    device = FLOW_APPS[name][0]
    with Sim("mip", device, "tcp:127.0.0.1:0", "--scenario", "circle", "--speed", str(SPEED)) as sim:
        r = run_app("c", name, sim.address, "--samples", "100000", "--deadline-s", "2")
    assert r.returncode == 1 and "error: deadline of 2 s passed" in r.stderr, r.stderr
    assert r.stdout.count("{") > 0  # it printed samples, then gave up
