"""docs/dataset.md section "Queries" is a real run: its ```console blocks (`$ ` a command, `> `
its continuation lines) run in order in one empty directory with bash (`python` the test's
interpreter, the generated mipcodec package on PYTHONPATH) and print exactly what the page shows:
a simulated fleet (`python -m mipcodec.fleet`), its dataset (`export --dataset`), the example
queries (`python -m mipcodec query`).

Then the answers are checked against what the simulated world implies, from the fleet's manifest
(fleet.json: computed from the simulation's parameters, tests/export/test_fleet.py checks it
against an independent count of the logs): samples per vehicle and UTC date = rate x duration, split
at midnight (rows without a valid GPS time, which the GX5-45 flags invalid before its first fix,
have no date: NULL); seconds in each filter mode = the modes' samples at 50 Hz (the time out of full navigation = the outages configured, less the 2 s the CV7 coasts on its IMU); the
largest acceleration norm = 1 g at rest, sqrt(1 + (v^2 / r / g)^2) g on the 50 m circle at 5 m/s,
within the accelerometer's simulated noise.

`python -m tests.docs.test_queries_page` rewrites the page's console blocks from a run.
"""

from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "dataset.md"
PACKAGE_DIR = ROOT / "generated" / "python" / "mipcodec"
SECTION = "## Queries"
BLOCK = re.compile(r"```console\n(.*?)```", re.S)
GRAVITY = 9.80665
CIRCLE_G = math.hypot(1.0, 5.0**2 / 50.0 / GRAVITY)  # the circle scenario: 5 m/s on a 50 m radius


def _section(text: str) -> str:
    start = text.index(SECTION)
    nxt = text.find("\n## ", start + len(SECTION))
    return text[start : nxt if nxt >= 0 else len(text)]


def _commands(block: str) -> list:
    """The commands of a console block: (command text, the output the page shows)."""
    out: list = []
    for line in block.splitlines(keepends=True):
        if line.startswith("$ "):
            out.append([line[2:], ""])
        elif line.startswith("> ") and out and not out[-1][1]:
            out[-1][0] += line[2:]
        elif out:
            out[-1][1] += line
    return [(c.rstrip("\n"), o) for c, o in out]


def _run(command: str, cwd: Path) -> str:
    env = {
        **os.environ,
        "PYTHONPATH": str(PACKAGE_DIR),
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
    }
    run = subprocess.run(
        ["bash", "-c", command.replace("python ", f"{sys.executable} ", 1)],
        capture_output=True,
        text=True,
        cwd=cwd,
        env=env,
        timeout=900,
    )
    return run.stdout + run.stderr


def _replay(cwd: Path) -> list:
    """(block, [(command, page output, real output)]) for each console block of the section."""
    section = _section(PAGE.read_text(encoding="utf-8"))
    return [
        (m.group(1), [(c, shown, _run(c, cwd)) for c, shown in _commands(m.group(1))]) for m in BLOCK.finditer(section)
    ]


@pytest.fixture(scope="module")
def replay(tmp_path_factory) -> tuple:
    pytest.importorskip("pyarrow")
    pytest.importorskip("duckdb")
    cwd = tmp_path_factory.mktemp("queries")
    return cwd, _replay(cwd)


def _table(text: str) -> list:
    """The rows of a plain table the query command printed, as lists of cells."""
    lines = text.strip().splitlines()
    assert lines[1].startswith("-") and lines[-1].startswith("("), text
    widths = [len(c) for c in lines[1].split("  ")]
    rows = []
    for line in lines[2:-1]:
        cells, at = [], 0
        for w in widths:
            cells.append(line[at : at + w].strip())
            at += w + 2
        rows.append(cells)
    return rows


def _outputs(replay: tuple) -> dict:
    """The real output of each query, by the query's first words (FROM clause's table)."""
    return {c: real for _, runs in replay[1] for c, _, real in runs}


def test_page_shows_the_real_output(replay: tuple) -> None:
    blocks = replay[1]
    assert len(blocks) >= 2
    for _, runs in blocks:
        for command, shown, real in runs:
            assert real == shown, f"docs/dataset.md: `{command[:60]}...` prints\n{real}\nnot\n{shown}"


def _manifest(replay: tuple) -> dict:
    found = list(replay[0].glob("*/fleet.json"))
    assert len(found) == 1, found
    return json.loads(found[0].read_text())


def _query(replay: tuple, words: str) -> list:
    hits = [real for command, real in _outputs(replay).items() if "query" in command and words in command]
    assert len(hits) == 1, f"no single query with {words!r} on the page"
    return _table(hits[0])


def _by_serial(manifest: dict) -> dict:
    return {d["serial"]: d for d in manifest["devices"]}


def test_samples_per_vehicle_per_day(replay: tuple) -> None:
    devices = _by_serial(_manifest(replay))
    got = {(r[1], r[2]): int(r[3]) for r in _query(replay, "AS samples")}
    want = {}
    for serial, d in devices.items():
        stream = d["streams"]["0x80"]
        for day, n in stream["samples_gps_valid_per_date"].items():
            want[(serial, day)] = n
        no_time = stream["samples"] - stream["samples_gps_valid"]
        if d["model"] == "gx5_45" and no_time:  # no device clock: rows without a valid GPS time have no date
            want[(serial, "NULL")] = no_time
        elif d["model"] == "cv7_ins":  # the reference timestamp dates them all (the clock map)
            want.update({(serial, day): n for day, n in stream["samples_per_date"].items()})
    assert got == want


def _modes(replay: tuple) -> dict:
    got: dict = {}
    for r in _query(replay, "AS seconds"):
        got.setdefault(r[1], {})[r[2]] = float(r[3])
    return got


def test_time_in_each_filter_mode_gx5(replay: tuple) -> None:
    devices = _by_serial(_manifest(replay))
    got = _modes(replay)
    for serial, d in devices.items():
        if d["model"] != "gx5_45":
            continue
        assert got[serial] == {s: m["samples"] / 50 for s, m in d["filter_modes"].items()}  # 50 Hz
        out = sum(o["seconds"] for o in d["gnss_outages"])
        assert got[serial].get("run_solution_error", 0.0) == out  # out of full navigation: the outages


def test_time_in_each_filter_mode_cv7_seconds(replay: tuple) -> None:
    """The CV7's seconds per mode (whatever the mode's name, see the next test); out of full
    navigation: the outages less the 2 s coasting each, plus 1 s of AHRS before the first fix."""
    devices = _by_serial(_manifest(replay))
    got = _modes(replay)
    for serial, d in devices.items():
        if d["model"] != "cv7_ins":
            continue
        assert sorted(got[serial].values()) == sorted(m["samples"] / 50 for m in d["filter_modes"].values())
        out = sum(o["seconds"] - 2 for o in d["gnss_outages"]) + 1
        assert d["filter_modes"]["ahrs"]["seconds"] == out


def test_time_in_each_filter_mode_cv7_names(replay: tuple) -> None:
    devices = _by_serial(_manifest(replay))
    got = _modes(replay)
    for serial, d in devices.items():
        if d["model"] == "cv7_ins":
            assert got[serial] == {s: m["samples"] / 50 for s, m in d["filter_modes"].items()}


def test_maximum_acceleration_norm(replay: tuple) -> None:
    devices = _by_serial(_manifest(replay))
    got = {r[1]: float(r[2]) for r in _query(replay, "AS max_g")}
    assert set(got) == set(devices)
    for serial, d in devices.items():
        truth = CIRCLE_G if d["scenario"] == "circle" else 1.0
        # the simulated noise: 0.002 m/s^2 per axis (sim_world: specific_force), the most of
        # thousands of samples stays within 5 sigma
        assert truth - 1e-4 <= got[serial] <= truth + 5 * 0.002 / GRAVITY + 1e-4, (serial, got[serial], truth)


def main() -> int:
    """Rewrite the section's console blocks from a real run."""
    with tempfile.TemporaryDirectory() as tmp:
        blocks = _replay(Path(tmp))
    text = PAGE.read_text(encoding="utf-8")
    section = _section(text)
    new = section
    for block, runs in blocks:
        body = ""
        for command, _, real in runs:
            lines = command.split("\n")
            body += "$ " + lines[0] + "\n" + "".join("> " + x + "\n" for x in lines[1:]) + real
        new = new.replace(f"```console\n{block}```", f"```console\n{body}```", 1)
    PAGE.write_text(text.replace(section, new), encoding="utf-8")
    print(f"{PAGE.relative_to(ROOT)}: {len(blocks)} console blocks rewritten")
    return 0


if __name__ == "__main__":
    sys.exit(main())
