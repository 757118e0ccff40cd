"""docs/configure-a-device.md is a real run against the simulator: every ```console block's
commands (`$ ...`) run against a fresh simulated CV7 (`python -m mipcodec.sim --device cv7_ins`,
the page's address tcp:127.0.0.1:5000 replaced by the simulator's), in order, in one directory,
and print what the page shows (standard output, then standard error; `; echo "exit $?"` appends
the exit status). Every ```yaml block that starts with `# FILE` is written to FILE before the
commands after it run; a ```yaml block that starts with `# excerpt of FILE` must be a part of
FILE as the commands before it left it. Numbers that vary from run to run (reply times, observed
rates, streamed values) are compared as N.

`python -m tests.docs.test_configure_page` rewrites the page's console blocks from a run.
"""

from __future__ import annotations

import os
import re
import select
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "configure-a-device.md"
PACKAGE_DIR = ROOT / "generated" / "python" / "mipcodec"
PAGE_ADDRESS = "tcp:127.0.0.1:5000"
BLOCK = re.compile(r"```(console|yaml)\n(.*?)```", re.S)
VARYING = re.compile(r"(answered in|observed|^scaled_|^\{\"offset)")
NUMBER = re.compile(r"-?\d+(\.\d+)?(e-?\d+)?")


def _run(command: str, address: str, cwd: Path) -> str:
    status = command.endswith('; echo "exit $?"')
    if status:
        command = command[: -len('; echo "exit $?"')]
    args = shlex.split(command.replace(PAGE_ADDRESS, address))
    if args[0] != "mipcodec-device":
        raise AssertionError(f"the page runs {args[0]!r}, not mipcodec-device")
    env = {**os.environ, "PYTHONPATH": str(PACKAGE_DIR)}
    # A longer reply timeout than the default 1000 ms (not shown on the page): on a loaded machine
    # the simulator streaming at 1000 Hz answered the command after the page's fast.yaml late.
    patience = [] if "--timeout-ms" in args else ["--timeout-ms", "5000"]
    run = subprocess.run(
        [sys.executable, "-m", "mipcodec", "device", *args[1:], *patience],
        capture_output=True,
        text=True,
        cwd=cwd,
        env=env,
        timeout=120,
    )
    out = (run.stdout + run.stderr).replace(address, PAGE_ADDRESS).replace(str(cwd) + "/", "")
    if status:
        out += f"exit {run.returncode}\n"
    return out


def _normal(text: str) -> str:
    return "\n".join(NUMBER.sub("N", line) if VARYING.search(line) else line for line in text.splitlines())


def replay(page: str) -> tuple[str, list[tuple[str, str]]]:
    """The page with its console blocks as a run prints them, and (shown, got) of every excerpt."""
    sim = subprocess.Popen(
        [sys.executable, "-m", "mipcodec.sim", "--listen", "tcp:127.0.0.1:0", "--device", "cv7_ins"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "PYTHONPATH": str(PACKAGE_DIR)},
    )
    try:
        ready, _, _ = select.select([sim.stdout], [], [], 30)
        address = sim.stdout.readline().strip() if ready else ""
        assert address, "the simulator printed no address"
        excerpts: list[tuple[str, str]] = []
        with tempfile.TemporaryDirectory() as tmp:
            cwd = Path(tmp)

            def block(m: re.Match) -> str:
                kind, body = m.group(1), m.group(2)
                if kind == "yaml":
                    first = body.splitlines()[0] if body else ""
                    if first.startswith("# excerpt of "):
                        name = first[len("# excerpt of ") :].strip()
                        shown = "\n".join(body.splitlines()[1:]) + "\n"
                        excerpts.append((shown, (cwd / name).read_text()))
                    elif first.startswith("# ") and first.endswith(".yaml"):
                        (cwd / first[2:].strip()).write_text(body)
                    return m.group(0)
                out = []
                for line in body.splitlines():
                    if line.startswith("$ "):
                        out.append(line)
                        out.extend(_run(line[2:], address, cwd).splitlines())
                return "```console\n" + "".join(x + "\n" for x in out) + "```"

            return BLOCK.sub(block, page), excerpts
    finally:
        sim.terminate()
        sim.wait(10)


def test_the_page_is_a_real_run() -> None:
    page = PAGE.read_text(encoding="utf-8")
    got, excerpts = replay(page)
    assert page.count("```console") >= 6
    assert _normal(got) == _normal(page)
    assert excerpts, "the page shows no part of a dumped file"
    for shown, text in excerpts:
        assert shown in text, shown


def test_the_readme_links_the_page() -> None:
    assert "docs/configure-a-device.md" in (ROOT / "README.md").read_text(encoding="utf-8")


if __name__ == "__main__":
    PAGE.write_text(replay(PAGE.read_text(encoding="utf-8"))[0], encoding="utf-8")
