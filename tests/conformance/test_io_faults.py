"""The command-line tools under I/O faults (docs/conformance.md §5, "I/O faults"): the same status
and the same number of lines on stderr in all four languages, never a traceback or a panic.

| case | decode | encode |
|---|---|---|
| stdout on a full disk (/dev/full) | exit 2, one line | exit 2, one line |
| stdout closed early (a pipe whose reader stops after 100 bytes) | killed by SIGPIPE, quiet | the same |
| input file that cannot be read (/proc/self/mem: open succeeds, read fails with EIO) | exit 2, one line | (no FILE) |
| a directory as input FILE | exit 2, one line | (no FILE) |
| a missing input FILE | exit 2, one line | (no FILE) |
| stdin closed (descriptor 0 not open) | exit 2, one line | exit 2, one line |

Every other Python command line of the package (the log tools, the device command line, the
simulator, the fleet generator) ends the same way on a closed stdout: killed by SIGPIPE, quiet.
"""

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from tests.helpers.langs import langs

ROOT = Path(__file__).resolve().parents[2]
LANGS = langs()  # the target registry (generator/targets/__init__.py)
TOOL = {"decode": ROOT / "tests/conformance/decode", "encode": ROOT / "tests/conformance/encode"}

# Ping (0x01,0x01), the Ping of docs/conformance.md's examples, and a skip run: many times over,
# so that the output is far larger than a pipe's buffer.
PING = bytes.fromhex("756501020201e0c6")
BIG_STREAM = (PING + b"\x00") * 40000


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("faults")
    stream = d / "stream.bin"
    stream.write_bytes(BIG_STREAM)
    lines = d / "lines.jsonl"
    for lang in LANGS:  # the tools are built (their build output goes to stderr) before any case runs
        proc = subprocess.run([str(TOOL["decode"]), lang, str(stream)], capture_output=True)
        assert proc.returncode == 0, proc.stderr.decode(errors="replace")
        if lang == "python":
            lines.write_bytes(proc.stdout)
        proc = subprocess.run([str(TOOL["encode"]), lang], input=b"", capture_output=True)
        assert proc.returncode == 0, proc.stderr.decode(errors="replace")
    (d / "a-directory").mkdir()
    return {"stream": stream, "lines": lines, "dir": d / "a-directory", "missing": d / "missing.bin"}


def _check_one_line(proc_stderr: bytes, lang: str, case: str) -> str:
    err = proc_stderr.decode(errors="replace")
    assert "Traceback" not in err and "panicked" not in err, f"{lang} {case}: {err}"
    lines = err.splitlines()
    assert len(lines) == 1, f"{lang} {case}: want one line on stderr, got {len(lines)}: {err!r}"
    return lines[0]


def _run(argv, stdin_path=None, stdout=None, close_stdin=False):
    stdin = open(stdin_path, "rb") if stdin_path else subprocess.DEVNULL
    try:
        return subprocess.run(
            [str(a) for a in argv],
            stdin=None if close_stdin else stdin,
            stdout=stdout if stdout is not None else subprocess.PIPE,
            stderr=subprocess.PIPE,
            preexec_fn=(lambda: os.close(0)) if close_stdin else None,
            timeout=300,
        )
    finally:
        if stdin_path:
            stdin.close()


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("tool", ["decode", "encode"])
def test_full_disk(lang, tool, files):
    with open("/dev/full", "wb") as full:
        if tool == "decode":
            proc = _run([TOOL[tool], lang, files["stream"]], stdout=full)
        else:
            proc = _run([TOOL[tool], lang], stdin_path=files["lines"], stdout=full)
    assert proc.returncode == 2, f"{lang} {tool} > /dev/full: exit {proc.returncode}"
    line = _check_one_line(proc.stderr, lang, f"{tool} > /dev/full")
    assert "No space left on device" in line


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("tool", ["decode", "encode"])
def test_closed_pipe_ends_quietly_by_sigpipe(lang, tool, files):
    if tool == "decode":
        argv, stdin = [TOOL[tool], lang, files["stream"]], subprocess.DEVNULL
    else:
        argv, stdin = [TOOL[tool], lang], open(files["lines"], "rb")
    try:
        proc = subprocess.Popen([str(a) for a in argv], stdin=stdin, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    finally:
        if stdin is not subprocess.DEVNULL:
            stdin.close()
    head = proc.stdout.read(100)  # like `| head -c 100`
    proc.stdout.close()
    err = proc.stderr.read()
    proc.wait(timeout=300)
    assert len(head) == 100
    assert proc.returncode == -signal.SIGPIPE, f"{lang} {tool} | head: exit {proc.returncode}, stderr {err!r}"
    assert err == b"", f"{lang} {tool} | head: not quiet: {err!r}"


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("case", ["unreadable", "directory", "missing"])
def test_decode_input_file_faults(lang, case, files):
    path = {"unreadable": "/proc/self/mem", "directory": files["dir"], "missing": files["missing"]}[case]
    proc = _run([TOOL["decode"], lang, path])
    assert proc.returncode == 2, f"{lang} decode {case}: exit {proc.returncode}"
    assert proc.stdout == b""
    line = _check_one_line(proc.stderr, lang, f"decode {case}")
    assert Path(path).name in line


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("tool", ["decode", "encode"])
def test_closed_stdin(lang, tool, files):
    proc = _run([TOOL[tool], lang, *(["-"] if tool == "decode" else [])], close_stdin=True)
    assert proc.returncode == 2, f"{lang} {tool} <&-: exit {proc.returncode}"
    assert proc.stdout == b""
    line = _check_one_line(proc.stderr, lang, f"{tool} <&-")
    assert "standard input" in line


# Each writes to stdout at once and little (block-buffered: the failed write comes at a flush).
PYTHON_COMMAND_LINES = {
    "info": ["-m", "mipcodec", "info", "LOG"],
    "help": ["-m", "mipcodec", "--help"],
    "device": ["-m", "mipcodec", "device", "x", "settings", "schema"],
    "device-script": ["-m", "mipcodec.device.cli", "x", "settings", "schema"],  # mipcodec-device
    "sim": ["-m", "mipcodec.sim", "--listen", "tcp:127.0.0.1:0"],  # its address line, then it serves
    "fleet": ["-m", "mipcodec.fleet", "--out", "DIR", "--devices", "1", "--size", "20K"],
}


@pytest.mark.parametrize("name", sorted(PYTHON_COMMAND_LINES))
def test_every_python_command_line_ends_quietly_on_a_closed_pipe(name, tmp_path):
    """stdout a pipe whose reader has gone before the first write (`python -m mipcodec info LOG |
    head` when head has what it wants): killed by SIGPIPE, nothing on stderr (a BrokenPipeError
    traceback before, or `Broken pipe` and exit 2)."""
    log = tmp_path / "ping.bin"
    log.write_bytes(PING * 10)
    argv = [{"LOG": str(log), "DIR": str(tmp_path / "fleet")}.get(a, a) for a in PYTHON_COMMAND_LINES[name]]
    env = dict(os.environ, PYTHONPATH=str(ROOT / "generated" / "python" / "mipcodec"))
    read_end, write_end = os.pipe()
    os.close(read_end)
    try:
        proc = subprocess.run([sys.executable, *argv], stdout=write_end, stderr=subprocess.PIPE, env=env, timeout=60)
    finally:
        os.close(write_end)
    assert (proc.returncode, proc.stderr.decode(errors="replace")) == (-signal.SIGPIPE, "")
