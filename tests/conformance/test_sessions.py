"""The session corpus (tests/sessions/, docs/conformance.md section 8) in Python.

1. The sans-I/O core of each generated package (`<package>.session.Session`) runs every case the
   way the section's runner rule says: before each step, `poll` at every deadline the session
   reports up to the step's time; at the end, poll while commands are pending, then `close`.
   Each `receive` is also fed split at every position (two feeds at the same time); the lines
   must not change.
2. The conformance tool (`tests/conformance/session LANG`, each of TOOL_LANGS) runs every live case over loopback
   TCP against the scripted fake device (tests/conformance/fake_device.py), with the case's
   commands as its input lines: the same lines must come out.
3. The tool's errors: a bad input line (stderr, exit 1, the other lines still run), a connection
   refused and bad usage (exit 2).
"""

from __future__ import annotations

import json
import socket
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from generator.sessions import load_sessions
from generator.spec import load_spec
from tests.conformance.fake_device import FakeDevice
from tests.helpers.generated import python_package
from tests.helpers.langs import langs

ROOT = Path(__file__).resolve().parents[2]
IR = load_spec()
PROTOCOLS = {p["name"]: p for p in IR["protocols"]}
CASES = load_sessions(IR, ROOT / "tests" / "sessions")
TOOL = ROOT / "tests" / "conformance" / "session"


def _id(case: dict) -> str:
    return f"{case['protocol']}/{case['name']}"


def _event_line(pkg, e) -> str:
    if isinstance(e, pkg.session.Result):
        return e.line(e.tag)
    if isinstance(e, pkg.Skip):
        return '{"offset":%d,"skipped":"%s"}' % (e.offset, e.data.hex())
    return e.line()


def run_case(case: dict, split: tuple[int, int] | None = None) -> list[str]:
    """The lines the core reports for a case; `split` = (receive step index, position) feeds that
    step in two parts at the same time."""
    pkg = python_package(PROTOCOLS[case["protocol"]]["package"])
    s = pkg.session.Session(case["device"], case["timeout_ms"], case["inter_packet_timeout_ms"])
    out: list[str] = []

    def emit(events) -> None:
        out.extend(_event_line(pkg, e) for e in events)

    def advance(t: int) -> None:
        while True:
            d = s.next_deadline()
            if d is None or d > t:
                return
            emit(s.poll(d))

    number = 0
    now = 0
    for k, step in enumerate(case["steps"]):
        now = step["at"]
        advance(now)
        if "send" in step:
            number += 1
            command = pkg.session.command_from_line(step["send"])
            p = s.start(command, now, tag=number)
            if step["bytes"] is not None and p.result is None:
                assert p.packet.hex() == step["bytes"], f"command {number} sent {p.packet.hex()}"
            if p.result is not None:
                emit([p.result])
            continue
        data = bytes.fromhex(step["receive"])
        if split is not None and split[0] == k:
            emit(s.feed(data[: split[1]], now))
            emit(s.feed(data[split[1] :], now))
        else:
            emit(s.feed(data, now))
    while s.pending:
        now = max(now, s.next_deadline())
        emit(s.poll(now))
    emit(s.close(now))
    return out


@pytest.mark.parametrize("case", CASES, ids=_id)
def test_core(case):
    assert run_case(case) == case["expect"]


@pytest.mark.parametrize("case", CASES, ids=_id)
def test_core_split_everywhere(case):
    for k, step in enumerate(case["steps"]):
        if "receive" not in step:
            continue
        for cut in range(1, len(step["receive"]) // 2):
            assert run_case(case, (k, cut)) == case["expect"], f"receive step {k} split at {cut}"


def test_corpus_covers_the_issue():
    """Every kind of exchange the corpus must hold, per protocol (a case removed by mistake fails here)."""
    names = {(c["protocol"], c["name"]) for c in CASES}
    for proto in ("mip", "mscip"):
        for want in ("ping_ack", "late_reply_after_a_timeout", "false_sync_dropped_by_the_timed_rule"):
            assert (proto, want) in names
    # issue 37: replies recognised by content (the look-ahead rule); these fail with the old timed rule
    for want in (
        "slow_reply_kept_waiting",
        "false_sync_then_the_reply_after_the_inter_packet_timeout",
        "false_sync_with_nothing_after_it_waits_for_close",
    ):
        assert ("mip", want) in names
    results = {json.loads(line)["result"] for c in CASES for line in c["expect"] if '"result"' in line}
    assert results == {"ack", "nack", "timeout", "invalid", "sent", "refused"}
    for proto in ("mip", "mscip"):
        enum = PROTOCOLS[proto]["session"]["code_enum"]
        codes = {v["value"] for t in PROTOCOLS[proto]["types"] if t["name"] == enum for v in t["values"]} - {0}
        nacks = {
            json.loads(line)["code"]
            for c in CASES
            if c["protocol"] == proto
            for line in c["expect"]
            if '"result":"nack"' in line
        }
        assert codes <= nacks, f"{proto}: no NACK case for codes {sorted(codes - nacks)}"


# The languages whose session tool has landed (the others print so and exit 2).
TOOL_LANGS = langs()  # the target registry (generator/targets/__init__.py)


def _ready(lang: str) -> None:
    """Builds the tool of each protocol first (`--help`): the fake device waits 30 s for its connection."""
    for proto in PROTOCOLS:
        subprocess.run([str(TOOL), lang, "--help", "--protocol", proto], capture_output=True, timeout=900)


def run_tool(case: dict, lang: str = "python") -> tuple[subprocess.CompletedProcess, FakeDevice]:
    dev = FakeDevice(case, PROTOCOLS[case["protocol"]]["framing"]).start()
    lines = "".join(step["send"] + "\n" for step in case["steps"] if "send" in step)
    args = [str(TOOL), lang, "--connect", f"tcp:127.0.0.1:{dev.port}", "--timeout-ms", str(case["timeout_ms"])]
    args += ["--protocol", case["protocol"]] + (["--device", case["device"]] if case["device"] else [])
    proc = subprocess.run(args, input=lines, capture_output=True, text=True, timeout=60)
    dev.join(10)
    return proc, dev


LIVE = [c for c in CASES if c["live"]]


@pytest.mark.parametrize("lang", TOOL_LANGS)
def test_tool_over_tcp(lang):
    """Every live case through the tool and the fake device (run in parallel: they mostly wait)."""
    _ready(lang)
    with ThreadPoolExecutor(max_workers=4) as pool:
        runs = list(pool.map(lambda c: run_tool(c, lang), LIVE))
    failures = []
    for case, (proc, dev) in zip(LIVE, runs):
        got = proc.stdout.splitlines()
        if proc.returncode != 0 or got != case["expect"] or dev.errors:
            failures.append(
                f"{_id(case)}: exit {proc.returncode}, stderr {proc.stderr!r}, device {dev.errors}\n"
                + "\n".join(f"  got:    {g}" for g in got)
                + "\n"
                + "\n".join(f"  expect: {e}" for e in case["expect"])
            )
    assert not failures, "\n".join(failures)


@pytest.mark.parametrize("lang", TOOL_LANGS)
def test_tool_bad_line_is_reported_and_skipped(lang):
    _ready(lang)
    case = next(c for c in CASES if c["protocol"] == "mip" and c["name"] == "ping_ack")
    dev = FakeDevice(case, PROTOCOLS["mip"]["framing"]).start()
    bad = [
        "not json",
        '{"offset":0,"set":1,"fields":[]}',
        '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":1,"ack_code":0}}]}',
    ]
    lines = "\n".join(bad) + "\n\n" + case["steps"][0]["send"] + "\n"
    proc = subprocess.run(
        [str(TOOL), lang, "--connect", f"tcp:127.0.0.1:{dev.port}"],
        input=lines,
        capture_output=True,
        text=True,
        timeout=60,
    )
    dev.join(10)
    assert proc.returncode == 1
    assert proc.stdout.splitlines() == ['{"line":5,"result":"ack","code":0,"reply":[]}']
    err = proc.stderr.splitlines()
    assert [e.split(":")[1].strip() for e in err] == ["line 1", "line 2", "line 3"], err
    assert "not a command" in err[2]


@pytest.mark.parametrize("lang", TOOL_LANGS)
def test_tool_connection_refused_and_usage(lang):
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    proc = subprocess.run(
        [str(TOOL), lang, "--connect", f"tcp:127.0.0.1:{port}"],
        input="",
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert proc.returncode == 2 and "cannot connect" in proc.stderr
    for args in (
        ["--connect"],
        ["--timeout-ms", "x", "--connect", "tcp:a:1"],
        ["--device", "nope", "--connect", "tcp:a:1"],
        [],
    ):
        proc = subprocess.run([str(TOOL), lang, *args], input="", capture_output=True, text=True, timeout=60)
        assert proc.returncode == 2 and proc.stderr, args
    proc = subprocess.run([str(TOOL), lang, "--connect", "tcp:nohost"], input="", capture_output=True, text=True)
    assert proc.returncode == 2 and "bad TCP address" in proc.stderr


def test_typed_api_over_tcp():
    """The generated command API of mipcodec against the fake device: write and read the
    sensor-to-vehicle rotation (case write_then_read), a refusal and a NACK raised as errors."""
    pkg = python_package("mipcodec")
    case = next(c for c in CASES if c["protocol"] == "mip" and c["name"] == "write_then_read")
    dev = FakeDevice(case, PROTOCOLS["mip"]["framing"]).start()
    with pkg.connect(f"tcp:127.0.0.1:{dev.port}", device="cv7_ins") as device:
        assert device.threedm.sensor_to_vehicle_euler.write(0.0, 1.5708, 1.5708) is None
        reply = device.threedm.sensor_to_vehicle_euler.read()
        assert isinstance(reply, pkg.threedm.SensorToVehicleEulerResponse)
        assert (reply.roll, round(reply.pitch, 4), round(reply.yaw, 4)) == (0.0, 1.5708, 1.5708)
    dev.join(10)
    # The write of vector sensor_to_vehicle_euler_example_3, then the read of vector sensor_to_vehicle_euler_read.
    assert dev.errors == [] and [p.hex() for p in dev.received] == [case["steps"][0]["bytes"], "75650c030331021f46"]
    case = next(c for c in CASES if c["protocol"] == "mip" and c["name"] == "refused_command_for_the_device")
    dev = FakeDevice(case, PROTOCOLS["mip"]["framing"]).start()
    with pkg.connect(f"tcp:127.0.0.1:{dev.port}", device="gx5_45") as device:
        with pytest.raises(pkg.session.CommandRefused, match=r"not supported by 3DM-GX5-45 \(3dm-gx5-45-dcp\.txt\)"):
            device.threedm.sensor_to_vehicle_euler.read()
        device.base.ping()
    dev.join(10)
    assert dev.errors == []
    case = next(c for c in CASES if c["protocol"] == "mip" and c["name"] == "nack_of_a_read")
    dev = FakeDevice(case, PROTOCOLS["mip"]["framing"]).start()
    with pkg.connect(f"tcp:127.0.0.1:{dev.port}", device="cv7_ins") as device:
        with pytest.raises(pkg.session.Nack) as e:
            device.threedm.sensor_to_vehicle_euler.read()
        assert e.value.code == pkg.types.AckCode.INVALID_PARAMETER
    dev.join(10)


@pytest.mark.parametrize("package", ["mipcodec", "mscipcodec"])
def test_the_session_module_is_an_attribute_of_a_fresh_package(package: str) -> None:
    """`import <package>; <package>.session.Session` in a new interpreter: the package imports its
    set modules and the session lazily (first use), and `session` stays reachable as before."""
    from tests.helpers.generated import GENERATED_PYTHON

    code = f"import {package} as p; print(p.session.Session.__name__, p.Device.__module__)"
    run = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        env={"PYTHONPATH": str(GENERATED_PYTHON / package)},
    )
    assert run.returncode == 0, run.stderr
    assert run.stdout.split() == ["Session", f"{package}.session"]
