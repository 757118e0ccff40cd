"""The C++ application program tests/apps/cpp/cv7_external_aiding.cpp on bad input (its contract:
tests/apps/README.md): wrong arguments exit 2 with `usage: ...`; an unreadable feed, an address that
cannot be opened, a device that does not answer and a passed deadline exit 1 with `error: ...`;
never a crash. Its run to full navigation is test_simulator_world.py's application-program test.

The issue-35 programs (gx5_continuous, gx5_polling, cv7_ahrs, cv7_gnss_ins; tests/apps/README.md)
with the same bad input: wrong arguments, an unreachable address, a device that does not answer, a
NACK (of the first command they share, and of one of their own flow), a passed deadline. Their
runs to the manuals' states are test_apps_flows.py."""

from __future__ import annotations

import socket
import threading

import pytest

from tests.conformance.test_simulator import Sim
from tests.conformance.test_simulator_world import run_app, write_aiding_feed

APP = "cv7_external_aiding"


def app(*args: str, timeout: float = 120):
    return run_app("cpp", APP, *args, timeout=timeout)


@pytest.fixture(scope="module")
def feed(tmp_path_factory):
    path = tmp_path_factory.mktemp("feed") / "aiding.txt"
    write_aiding_feed(path)
    return path


@pytest.fixture(scope="module", autouse=True)
def built():
    r = app(timeout=1800)  # builds the program first
    assert r.returncode == 2 and r.stderr.startswith("usage: "), r.stderr


def closed_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def check_error(r, *words: str) -> None:
    assert r.returncode == 1, (r.returncode, r.stderr)
    assert r.stderr.startswith("error: ") and all(w in r.stderr for w in words), r.stderr
    assert r.stdout == ""


@pytest.mark.parametrize(
    "args",
    [
        ["tcp:127.0.0.1:1"],
        ["tcp:127.0.0.1:1", "FEED", "extra"],
        ["tcp:127.0.0.1:1", "FEED", "--period-ms"],
        ["tcp:127.0.0.1:1", "FEED", "--period-ms", "0"],
        ["tcp:127.0.0.1:1", "FEED", "--samples", "ten"],
        ["tcp:127.0.0.1:1", "FEED", "--deadline-s", "-5"],
        ["tcp:127.0.0.1:1", "FEED", "--speed", "2"],
    ],
)
def test_wrong_arguments_print_usage(args, feed) -> None:
    r = app(*[str(feed) if a == "FEED" else a for a in args])
    assert r.returncode == 2 and "usage: cv7_external_aiding ADDRESS FEED" in r.stderr, r.stderr
    assert r.stdout == ""


def test_help_prints_usage_on_stdout() -> None:
    r = app("--help")
    assert r.returncode == 0 and r.stdout.startswith("usage: ") and r.stderr == ""


@pytest.mark.parametrize(
    ("content", "words"),
    [
        (None, ["missing.txt", "No such file"]),
        ("# only a comment\n\n", ["no rows"]),
        ("345600.0 0 46.5 6.6 372.0 0 0 0 0.1 0 0\n", ["line 1", "12 numbers"]),
        ("# header\n345600.0 -5 46.5 6.6 372.0 0 0 0 0.1 0 0 0\n", ["line 2"]),
        ("345600.0 0 46.5 6.6 372.0 0 0 0 0.1 0 0 zero\n", ["line 1"]),
    ],
)
def test_unreadable_feed(tmp_path, content, words) -> None:
    path = tmp_path / "missing.txt"
    if content is not None:
        path.write_text(content)
    check_error(app(f"tcp:127.0.0.1:{closed_port()}", str(path)), str(path), *words)


def test_unreachable_addresses(tmp_path, feed) -> None:
    check_error(app(f"tcp:127.0.0.1:{closed_port()}", str(feed)), "127.0.0.1")
    check_error(app("tcp:nowhere", str(feed)))
    check_error(app(str(tmp_path / "no-such-tty"), str(feed)), "no-such-tty")


def test_a_device_that_does_not_answer(feed) -> None:
    """Connected, but nothing answers the ping: its reply timeout ends the program."""
    with socket.socket() as server:
        server.bind(("127.0.0.1", 0))
        server.listen(1)
        peers = []
        threading.Thread(target=lambda: peers.append(server.accept()[0]), daemon=True).start()
        r = app(f"tcp:127.0.0.1:{server.getsockname()[1]}", str(feed), timeout=60)
        for p in peers:
            p.close()
    check_error(r, "base.ping", "timeout")


def test_the_deadline_passes(feed) -> None:
    """Full navigation reached, but more samples asked than the deadline allows."""
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", "--scenario", "circle", "--speed", "10") as sim:
        r = run_app("cpp", APP, sim.address, str(feed), "--period-ms", "50", "--samples", "100000", "--deadline-s", "1")
    assert r.returncode == 1 and r.stderr.startswith("error: deadline passed"), r.stderr
    assert "mode 4" in r.stdout.splitlines() and r.stdout.count("{") > 0


# ------------------------------------------------------------------------------- the issue-35 programs
# program -> (device, a command of its own flow to refuse, the error line's command name)
FLOW_APPS = {
    "gx5_continuous": ("gx5_45", "filter_message_format", "threedm.filter_message_format write"),
    "gx5_polling": ("gx5_45", "poll_filter_data", "threedm.poll_filter_data"),
    "cv7_ahrs": ("cv7_ins", "aiding_measurement_control", "filter.aiding_measurement_control write"),
    "cv7_gnss_ins": ("cv7_ins", "multi_antenna_offset", "filter.multi_antenna_offset write"),
}


@pytest.fixture(scope="module")
def flow_apps() -> None:
    for name in FLOW_APPS:
        r = run_app("cpp", name, timeout=1800)  # builds the program first: no argument is a usage error
        assert r.returncode == 2 and r.stderr.startswith(f"usage: {name} ADDRESS"), r.stderr
        assert r.stdout == ""


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("a", "b"), "usage: unexpected argument b"),
        (("a", "--samples", "0"), "usage: --samples 0: not a number from 1"),
        (("a", "--samples", "ten"), "usage: --samples ten: not a number from 1"),
        (("a", "--deadline-s", "-5"), "usage: --deadline-s -5: not a number from 1"),
        (("a", "--deadline-s"), "usage: --deadline-s needs a value"),
        (("a", "--speed", "2"), "usage: unknown option --speed"),
        (("--samples", "5"), "usage: "),  # no address
    ],
)
def test_flow_app_wrong_arguments_print_usage(flow_apps, name, args, message) -> None:
    r = run_app("cpp", name, *args)
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
    r = run_app("cpp", "cv7_gnss_ins", *args)
    assert r.returncode == 2 and r.stderr.startswith(message), r.stderr


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
def test_flow_app_help_prints_usage_on_stdout(flow_apps, name) -> None:
    r = run_app("cpp", name, "--help")
    assert r.returncode == 0 and r.stdout.startswith(f"usage: {name} ADDRESS") and r.stderr == ""


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
def test_flow_app_unreachable_addresses(flow_apps, name, tmp_path) -> None:
    check_error(run_app("cpp", name, f"tcp:127.0.0.1:{closed_port()}"), "127.0.0.1")
    check_error(run_app("cpp", name, "tcp:nowhere"))
    check_error(run_app("cpp", name, str(tmp_path / "no-such-tty")), "no-such-tty")


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
def test_flow_app_a_device_that_does_not_answer(flow_apps, name) -> None:
    """Connected, but nothing answers the ping: its reply timeout ends the program."""
    with socket.socket() as server:
        server.bind(("127.0.0.1", 0))
        server.listen(1)
        peers = []
        threading.Thread(target=lambda: peers.append(server.accept()[0]), daemon=True).start()
        r = run_app("cpp", name, f"tcp:127.0.0.1:{server.getsockname()[1]}", timeout=60)
        for p in peers:
            p.close()
    check_error(r, "base.ping", "timeout")


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
def test_flow_app_command_not_acknowledged(flow_apps, name) -> None:
    device, own, label = FLOW_APPS[name]
    with Sim("mip", device, "tcp:127.0.0.1:0", "--speed", "10", "--nack", "set_to_idle") as sim:
        check_error(run_app("cpp", name, sim.address), "base.set_to_idle", "NACK")
    with Sim("mip", device, "tcp:127.0.0.1:0", "--speed", "10", "--nack", own) as sim:
        r = run_app("cpp", name, sim.address)
    assert r.returncode == 1 and r.stderr.startswith(f"error: {label}: ") and "NACK" in r.stderr, r.stderr
    assert r.stdout.startswith("model "), r.stdout  # the device information came first


@pytest.mark.parametrize("name", sorted(FLOW_APPS))
def test_flow_app_the_deadline_passes(flow_apps, name) -> None:
    """The samples come, but more are asked than the deadline allows."""
    device = FLOW_APPS[name][0]
    with Sim("mip", device, "tcp:127.0.0.1:0", "--scenario", "circle", "--speed", "10") as sim:
        r = run_app("cpp", name, sim.address, "--samples", "100000", "--deadline-s", "2")
    assert r.returncode == 1 and r.stderr.startswith("error: deadline passed"), r.stderr
    assert r.stdout.count("{") > 0
