"""The log pages' first steps are a real run: the ```console blocks of docs/log-to-csv.md section
"Your first log" (the simulator, the recorder, `info`, `export`, `plot`, `export --dataset` on the
recorded log) and of docs/dataset.md section "Your first dataset" (the fleet generator and
`export --dataset` on its logs) run in order, each section in one empty directory, with bash
(`python` the test's interpreter, the generated mipcodec package on PYTHONPATH, the C locale),
and print what the page shows (standard output, then standard error).

A command `python -m mipcodec.sim ... &` starts the simulator on a free port (`--listen
tcp:127.0.0.1:0`); the address it prints replaces the page's tcp:127.0.0.1:5000 in the commands
after it. The simulator runs in real time, so in the recorded log's section the numbers (packet
counts, times, values) and the log's id are compared as N, except in the link budget and the
plot's line, and the facts that must hold whatever the timing are checked on their own: the log
names the simulator's device and serial, its byte count is the recorder's, no byte is skipped,
every data packet has a UTC time, the tables' rows carry it. The fleet is deterministic (same
arguments, same bytes): its section is compared exactly.

`python -m tests.docs.test_log_pages` rewrites both sections' console blocks from a run (then put
back ` (columnar path)` after export's last line: the page shows an installed package's output).
"""

from __future__ import annotations

import os
import re
import select
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGE_DIR = ROOT / "generated" / "python" / "mipcodec"
PAGE_ADDRESS = "tcp:127.0.0.1:5000"
# (page, section heading, numbers compared as N)
SECTIONS = [
    (ROOT / "docs" / "log-to-csv.md", "## Your first log", True),
    (ROOT / "docs" / "dataset.md", "## Your first dataset", False),
]
BLOCK = re.compile(r"```console\n(.*?)```", re.S)
NUMBER = re.compile(r"-?\d+(\.\d+)?(e-?\d+)?")
# lines that do not depend on the timing: the streams' link budget, the plot's series
EXACT = re.compile(r"mipcodec-device: link budget: |imu\.png: ")
SIM = re.compile(r"^python -m mipcodec\.sim .*&$")


def _section(text: str, heading: str) -> str:
    start = text.index(heading + "\n")
    nxt = text.find("\n## ", start + len(heading))
    return text[start : nxt if nxt >= 0 else len(text)]


def _commands(block: str) -> list:
    """The commands of a console block: (command text, the output the page shows)."""
    out: list = []
    for line in block.splitlines(keepends=True):
        if line.startswith("$ "):
            out.append([line[2:], ""])
        elif out:
            out[-1][1] += line
    return [(c.rstrip("\n"), o) for c, o in out]


class Replay:
    """Runs a section's commands in order in one directory."""

    def __init__(self, cwd: Path) -> None:
        self.cwd = cwd
        self.env = {
            **os.environ,
            "PYTHONPATH": str(PACKAGE_DIR),
            "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
        }
        self.env["LC_ALL"] = "C"  # `ls` and `sort` in byte order, as the page shows them
        self.address = ""
        self.sims: list = []

    def close(self) -> None:
        for sim in self.sims:
            sim.terminate()
            sim.wait(10)
            for stream in (sim.stdout, sim.stderr):
                stream.close()

    def simulator(self, command: str) -> str:
        command = command.rstrip(" &").replace(PAGE_ADDRESS, "tcp:127.0.0.1:0")
        sim = subprocess.Popen(
            ["bash", "-c", "exec " + command.replace("python ", f"{sys.executable} ", 1)],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            cwd=self.cwd,
            env=self.env,
        )
        self.sims.append(sim)
        ready, _, _ = select.select([sim.stdout], [], [], 60)
        self.address = sim.stdout.readline().strip() if ready else ""
        assert self.address.startswith("tcp:127.0.0.1:"), f"`{command}` printed no address"
        return PAGE_ADDRESS + "\n"

    def run(self, command: str) -> str:
        if SIM.match(command):
            return self.simulator(command)
        if self.address:
            command = command.replace(PAGE_ADDRESS, self.address)
        run = subprocess.run(
            ["bash", "-c", command.replace("python ", f"{sys.executable} ", 1)],
            capture_output=True,
            text=True,
            cwd=self.cwd,
            env=self.env,
            timeout=300,
        )
        out = run.stdout + run.stderr
        return out.replace(self.address, PAGE_ADDRESS) if self.address else out


def replay(page: Path, heading: str, cwd: Path) -> list:
    """(block, [(command, page output, real output)]) for each console block of the section."""
    runner = Replay(cwd)
    try:
        section = _section(page.read_text(encoding="utf-8"), heading)
        return [
            (m.group(1), [(c, shown, runner.run(c)) for c, shown in _commands(m.group(1))])
            for m in BLOCK.finditer(section)
        ]
    finally:
        runner.close()


def _normal(text: str) -> str:
    # `export` names its columnar path (the C accelerator of an installed package, as the page
    # shows) and not the packet-by-packet one this test's source tree takes: the same tables
    # and the log's id (a hash of its bytes) as H
    text = re.sub(r"\blog [0-9a-f]{16}\b", "log H", text.replace(" (columnar path)\n", "\n"))
    # `info`'s synchronization stretches: whether the recording starts before the simulated
    # receiver's first fix (a stretch of invalid GPS time) depends on the timing
    text = re.sub(r"^    offsets? \d.*\n", "", text, flags=re.M)
    return "".join(line if EXACT.match(line) else NUMBER.sub("N", line) for line in text.splitlines(True))


@pytest.fixture(scope="module")
def recorded(tmp_path_factory) -> tuple:
    pytest.importorskip("numpy")
    pytest.importorskip("pyarrow")
    pytest.importorskip("matplotlib")
    cwd = tmp_path_factory.mktemp("first-log")
    page, heading, _ = SECTIONS[0]
    return cwd, replay(page, heading, cwd)


def _outputs(blocks: list) -> dict:
    return {c: real for _, runs in blocks for c, _, real in runs}


def test_first_log_page_shows_the_real_output(recorded: tuple) -> None:
    blocks = recorded[1]
    assert len(blocks) >= 3
    for _, runs in blocks:
        for command, shown, real in runs:
            assert _normal(real) == _normal(shown), f"docs/log-to-csv.md: `{command}` prints\n{real}\nnot\n{shown}"


def _one(blocks: list, prefix: str) -> str:
    hits = [real for c, real in _outputs(blocks).items() if c.startswith(prefix)]
    assert len(hits) == 1, f"no single command {prefix!r} on the page"
    return hits[0]


def test_first_log_names_the_device_and_its_time(recorded: tuple) -> None:
    cwd, blocks = recorded
    info = _one(blocks, "python -m mipcodec info ")
    # the simulator's identity (its Device Information reply, the spec's default serial)
    assert re.search(r"^device: cv7_ins \(model 3dm-cv7-gnss-ins, serial \S+ ", info, re.M), info
    head = re.match(r"bytes: (\d+)  packets: (\d+)  skipped bytes: 0 in 0 runs  bad checksums: 0\n", info)
    assert head, info
    recorded_bytes = re.search(
        r"mipcodec-device: (\d+) bytes in 1 file\(s\) \(cv7\.bin\); stopped: --duration",
        _one(blocks, "python -m mipcodec device tcp:127.0.0.1:5000 record"),
    )
    assert recorded_bytes and int(recorded_bytes[1]) == int(head[1]) == (cwd / "cv7.bin").stat().st_size
    # every data packet carries its GPS time (the streams asked for the shared 0xD3), valid after
    # the simulated receiver's first fix (GNSS_FIX_AFTER = 2 s, docs/simulator-world.md)
    utc = re.search(r"^UTC: first (\S+)  last (\S+)  span \S+ s  \((\d+) of (\d+) data packets", info, re.M)
    assert utc and int(utc[3]) == int(utc[4]) > 0, info
    assert int(head[2]) == int(utc[4]) + 1  # the data packets and the Device Information reply


def test_first_log_tables_carry_utc_time(recorded: tuple) -> None:
    cwd = recorded[0]
    lines = (cwd / "tables" / "sensor.scaled_accel.csv").read_text().splitlines()
    assert lines[0].startswith('"t_ns","time","offset","scaled_accel.x [g]"')
    assert len(lines) > 100  # 100 Hz for the recording's seconds
    for line in lines[1:]:
        t_ns, time = line.split(",")[:2]
        assert t_ns and time.strip('"').startswith("2026-"), line
    assert (cwd / "imu.png").stat().st_size > 10000
    assert list((cwd / "fleet" / "_files").glob("part-*.parquet"))


def test_first_dataset_page_shows_the_real_output(tmp_path: Path) -> None:
    pytest.importorskip("pyarrow")
    page, heading, _ = SECTIONS[1]
    blocks = replay(page, heading, tmp_path)
    assert blocks
    for _, runs in blocks:
        for command, shown, real in runs:
            assert real == shown, f"docs/dataset.md: `{command}` prints\n{real}\nnot\n{shown}"
    assert (tmp_path / "logs" / "fleet.json").exists()


def main() -> int:
    """Rewrite the sections' console blocks from a real run."""
    for page, heading, _ in SECTIONS:
        with tempfile.TemporaryDirectory() as tmp:
            blocks = replay(page, heading, Path(tmp))
        text = page.read_text(encoding="utf-8")
        section = _section(text, heading)
        new = section
        for block, runs in blocks:
            body = "".join("$ " + command + "\n" + real for command, _, real in runs)
            new = new.replace(f"```console\n{block}```", f"```console\n{body}```", 1)
        page.write_text(text.replace(section, new), encoding="utf-8")
        print(f"{page.relative_to(ROOT)}: {len(blocks)} console blocks rewritten")
    return 0


if __name__ == "__main__":
    sys.exit(main())
