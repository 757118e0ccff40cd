"""The settings rules as data (tests/settings/<protocol>/*.yaml, tests/settings/README.md): every
case through both device command lines, the Python package's (`python -m <package> device`) and
the C package's (`<package>-device`, generated/c/<package>/tools/device/), each against its own
simulated device (`tests/conformance/simulate`) put in the case's state, behind a recording proxy
that sees every command the command line sends.

For each case and language: `settings diff FILE` and then `settings apply FILE [ARGS]` must print
the case's lines on stdout and stderr and exit with its status, and apply must send exactly the
case's writes (the names of the commands sent with function write, in order). A rule is stated
once, in a case, and each implementation is checked against it, not against the other.
"""

from __future__ import annotations

import importlib
import json
import os
import shutil
import socket
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
import yaml

from tests.conformance.test_device_cli import Recorder, Sim
from tests.helpers.builds import c_device_tool
from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "settings"
PACKAGES = {"mip": "mipcodec", "mscip": "mscipcodec"}
LANGS = ("python", "c")
CASE_KEYS = {"description", "device", "state", "file", "diff", "apply", "apply_args"}
RUN_KEYS = {"status", "stdout", "stderr", "writes"}


def load_cases() -> list[dict]:
    """Every case, checked for its shape (a misspelt key fails here, not silently)."""
    cases = []
    for proto_dir in sorted(p for p in CORPUS.iterdir() if p.is_dir()):
        assert proto_dir.name in PACKAGES, f"{proto_dir}: no protocol {proto_dir.name}"
        for path in sorted(proto_dir.glob("*.yaml")):
            case = yaml.safe_load(path.read_text(encoding="utf-8"))
            where = path.relative_to(ROOT)
            assert isinstance(case, dict) and set(case) <= CASE_KEYS, f"{where}: keys {sorted(CASE_KEYS)}"
            assert {"description", "device", "file", "diff", "apply"} <= set(case), f"{where}: a key is missing"
            for run in ("diff", "apply"):
                assert set(case[run]) <= RUN_KEYS and "status" in case[run], f"{where}: {run}: keys {RUN_KEYS}"
            assert "writes" not in case["diff"], f"{where}: diff writes nothing"
            case["name"] = f"{proto_dir.name}/{path.stem}"
            case["protocol"] = proto_dir.name
            cases.append(case)
    return cases


CASES = load_cases()


def test_the_corpus_covers_the_rules():
    """At least ten cases; each kind of rule the issue lists is exercised (a case removed by
    mistake fails here)."""
    assert len(CASES) >= 10
    statuses = {(c["diff"]["status"], c["apply"]["status"]) for c in CASES}
    assert (0, 0) in statuses, "an unchanged setting: diff 0, apply writes nothing"
    assert (1, 0) in statuses, "a change: diff 1, apply writes it"
    assert (2, 2) in statuses, "a refused file: nothing written"
    assert any(c["apply"].get("writes") for c in CASES), "a case where apply writes"
    assert any(c.get("state") for c in CASES), "a case with a device state"
    assert {c["protocol"] for c in CASES} == set(PACKAGES)


# ------------------------------------------------------------------------------ the C tool
def c_tool(package: str) -> Path:
    """The package's C device tool, built with warnings as errors (build/c-device/<package>)."""
    return c_device_tool(package)


@pytest.fixture(scope="module")
def tools() -> dict[str, Path]:
    assert shutil.which("cmake"), "cmake is needed to build the C packages"
    return {proto: c_tool(pkg) for proto, pkg in PACKAGES.items() if any(c["protocol"] == proto for c in CASES)}


# ------------------------------------------------------------------------------ one run
class CorpusRecorder(Recorder):
    """The recording proxy, decoding with the case's protocol package."""

    def __init__(self, target: str, device: str, package: str) -> None:
        self.package = python_package(package)
        super().__init__(target, device)

    def commands(self) -> list[tuple[str, int | None]]:
        out = []
        decoder = importlib.import_module(f"{self.package.__name__}.codec.packets").Decoder(self.device)
        for event in decoder.feed(bytes(self.sent)) + decoder.flush():
            for f in getattr(event, "fields", []):
                value = getattr(f, "value", None)
                if value is not None:
                    fn = getattr(value, "function", None)
                    out.append((value.NAME, None if fn is None else int(fn)))
        return out


def put_state(address: str, package: str, device: str, state: list[dict]) -> None:
    """Sends the state's commands to the simulator (the package's encoder) and waits for each ACK."""
    pkg = python_package(package)
    host, _, port = address[len("tcp:") :].rpartition(":")
    with socket.create_connection((host, int(port)), timeout=10) as s:
        for command in state:
            line = {"offset": 0, "set": command["set"], "fields": [{k: v for k, v in command.items() if k != "set"}]}
            s.sendall(pkg.encode_line(json.dumps(line)))
            decoder = importlib.import_module(f"{package}.codec.packets").Decoder(device)
            acked = None
            deadline = time.monotonic() + 10
            while acked is None and time.monotonic() < deadline:
                for event in decoder.feed(s.recv(65536)):
                    for f in getattr(event, "fields", []):
                        code = getattr(getattr(f, "value", None), "ack_code", None)
                        if code is not None and acked is None:
                            acked = int(code)
            assert acked == 0, f"state command {command['name']}: no ACK (code {acked})"


def run_tool(lang: str, case: dict, tool: Path | None, address: str, *args: str) -> subprocess.CompletedProcess:
    package = PACKAGES[case["protocol"]]
    if lang == "c":
        cmd = [str(tool), address, *args]
        env = None
    else:
        cmd = [sys.executable, "-m", package, "device", address, *args]
        env = {**os.environ, "PYTHONPATH": str(ROOT / "generated" / "python" / package)}
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=120, env=env)
    assert run.returncode >= 0 and "Traceback" not in run.stderr, run.stderr
    return run


def run_case(case: dict, lang: str, tool: Path | None, tmp: Path) -> list[str]:
    """The differences between what the case expects and what the language's command line did."""
    package = PACKAGES[case["protocol"]]
    path = tmp / f"{case['name'].replace('/', '_')}_{lang}.yaml"
    path.write_text(case["file"], encoding="utf-8")
    extra = ["--protocol", case["protocol"]]
    problems = []
    with Sim(case["device"], "tcp:127.0.0.1:0", *extra) as sim:
        put_state(sim.address, package, case["device"], case.get("state") or [])
        recorder = CorpusRecorder(sim.address, case["device"], package)
        try:
            for what, args in (("diff", ["diff"]), ("apply", ["apply", *case.get("apply_args", [])])):
                want = case[what]
                before = len(recorder.writes())
                got = run_tool(lang, case, tool, recorder.address, "settings", args[0], str(path), *args[1:])
                subst = {"FILE": str(path), "PROG": f"{package}-device"}
                for stream in ("stdout", "stderr"):
                    expected = want.get(stream, "")
                    for k, v in subst.items():
                        expected = expected.replace("{" + k + "}", v)
                    if getattr(got, stream) != expected:
                        problems.append(f"{what} {stream}:\n  got:    {getattr(got, stream)!r}\n  expect: {expected!r}")
                if got.returncode != want["status"]:
                    problems.append(f"{what}: exit {got.returncode}, expected {want['status']}")
                writes = recorder.writes()[before:]
                if writes != want.get("writes", []):
                    problems.append(f"{what}: wrote {writes}, expected {want.get('writes', [])}")
        finally:
            recorder.close()
    return [f"{case['name']} ({lang}): {p}" for p in problems]


@pytest.fixture(scope="module")
def outcomes(
    request: pytest.FixtureRequest, tools: dict[str, Path], tmp_path_factory: pytest.TempPathFactory
) -> dict[tuple[str, str], list[str]]:
    """The selected cases in their languages, run once in parallel (they mostly wait on the
    simulators); a run that fails to start is that case's problem, not the others'."""
    tmp = tmp_path_factory.mktemp("settings")
    chosen = {
        (item.callspec.params["name"], item.callspec.params["lang"])
        for item in request.session.items
        if getattr(item, "originalname", "") == "test_settings_case"
    }
    jobs = [(c, lang) for c in CASES for lang in LANGS if (c["name"], lang) in chosen]

    def one(job: tuple[dict, str]) -> list[str]:
        case, lang = job
        try:
            return run_case(case, lang, tools.get(case["protocol"]), tmp)
        except (AssertionError, OSError, subprocess.SubprocessError) as e:
            return [f"{case['name']} ({lang}): {e}"]

    with ThreadPoolExecutor(max_workers=4) as pool:
        runs = list(pool.map(one, jobs))
    return {(c["name"], lang): problems for (c, lang), problems in zip(jobs, runs)}


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", [c["name"] for c in CASES])
def test_settings_case(name: str, lang: str, outcomes: dict[tuple[str, str], list[str]]) -> None:
    problems = outcomes[(name, lang)]
    assert not problems, "\n".join(problems)
