"""The Python application program (tests/apps/python/, contract: tests/apps/README.md) on bad
input, as test_apps_rust.py / _c.py / _cpp.py check the other three: wrong arguments (exit 2 with
argparse's usage), a feed that cannot be read, an address that cannot be reached, a command that is
not acknowledged (exit 1 with one `error: ...` line, never a traceback)."""

from __future__ import annotations

import socket

import pytest

from tests.conformance.test_simulator import Sim, listen_for
from tests.conformance.test_simulator_world import run_app, write_aiding_feed

APP = "cv7_external_aiding"


@pytest.fixture(scope="module")
def feed(tmp_path_factory):
    path = tmp_path_factory.mktemp("feed") / "aiding.txt"
    write_aiding_feed(path)
    return path


def failed(r, *words: str) -> None:
    assert r.returncode == 1, (r.returncode, r.stderr)
    last = r.stderr.strip().splitlines()[-1]
    assert last.startswith("error: ") and all(w in last for w in words), r.stderr
    assert "Traceback" not in r.stderr and "{" not in r.stdout


@pytest.mark.parametrize(
    "args",
    [
        [],
        ["tcp:127.0.0.1:1"],
        ["tcp:127.0.0.1:1", "FEED", "extra"],
        ["tcp:127.0.0.1:1", "FEED", "--samples", "0"],
        ["tcp:127.0.0.1:1", "FEED", "--period-ms", "fast"],
        ["tcp:127.0.0.1:1", "FEED", "--deadline-s"],
    ],
)
def test_wrong_arguments_print_the_usage(feed, args: list) -> None:
    r = run_app("python", APP, *[str(feed) if a == "FEED" else a for a in args])
    assert r.returncode == 2 and r.stderr.startswith("usage: cv7_external_aiding"), r.stderr
    assert "Traceback" not in r.stderr and r.stdout == ""


def test_a_feed_that_cannot_be_read(feed, tmp_path) -> None:
    failed(run_app("python", APP, "tcp:127.0.0.1:1", str(tmp_path / "missing.txt")), "missing.txt")
    bad = tmp_path / "bad.txt"
    bad.write_text("# tow ns lat lon height vn ve vd heading bx by bz\n345600.0 0 46.5 6.6 372 0 0 0 0 0 0\n")
    failed(run_app("python", APP, "tcp:127.0.0.1:1", str(bad)), "bad.txt:2", "12 numbers")
    bad.write_text("# only comments\n")
    failed(run_app("python", APP, "tcp:127.0.0.1:1", str(bad)), "no rows")


def test_an_address_that_cannot_be_reached(feed, tmp_path) -> None:
    with socket.socket() as s:  # a port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    failed(run_app("python", APP, f"tcp:127.0.0.1:{port}", str(feed)), "cannot connect", str(port))
    failed(run_app("python", APP, "tcp:localhost", str(feed)), "bad TCP address")
    failed(run_app("python", APP, str(tmp_path / "ttyNONE"), str(feed)), "cannot open", "ttyNONE")


def test_a_command_that_is_not_acknowledged(feed) -> None:
    with Sim("mip", "cv7_ins", listen_for("tcp"), "--speed", "10", "--nack", "aiding_measurement_control") as sim:
        r = run_app("python", APP, sim.address, str(feed))
    failed(r, "aiding_measurement_control", "NACK")
