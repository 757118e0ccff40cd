"""The command-line tools through subprocesses: decode | encode is lossless, exit codes, errors."""

import os
import subprocess
import sys
from pathlib import Path

import testproto
from testproto.codec.framing import PacketBuilder
from testproto.registry import SET_KINDS

# The directory holding the assembled package (conftest.py).
ROOT = str(Path(testproto.__file__).resolve().parent.parent)


def run(args, data=b""):
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""), PYTHONDONTWRITEBYTECODE="1")
    return subprocess.run([sys.executable, "-m", "testproto", *args], input=data, capture_output=True, env=env)


def stream():
    set_id = SET_KINDS[0][1]
    pkt = PacketBuilder(set_id).add_field(0x01, b"\x01\x02").add_bytes(b"\x09").build()
    return b"\x00\xff" + pkt + b"junk" + pkt[:3]


def test_decode_encode_round_trip(tmp_path):
    path = tmp_path / "s.bin"
    path.write_bytes(stream())
    dec = run(["decode", str(path)])
    assert dec.returncode == 0, dec.stderr
    assert dec.stdout.decode().count("\n") == 3
    assert run(["decode", "-"], stream()).stdout == dec.stdout
    assert run(["decode"], stream()).stdout == dec.stdout
    enc = run(["encode"], dec.stdout)
    assert enc.returncode == 0, enc.stderr
    assert enc.stdout == stream()


def test_decode_usage_and_io_errors(tmp_path):
    for args in (
        ["decode", str(tmp_path / "missing.bin")],
        ["decode", "--bogus"],
        ["decode", "--device", "nope"],
        [],
        ["frobnicate"],
    ):
        r = run(args)
        assert r.returncode == 2, args
        assert r.stderr.decode().count("\n") == 1, r.stderr
        assert b"Traceback" not in r.stderr
        assert r.stdout == b""


def test_encode_bad_lines():
    good = b'{"offset":0,"skipped":"00ff"}\n'
    bad = [
        b"not json\n",
        b'{"offset":0}\n',
        b'{"offset":0,"set":1,"fields":[{"descriptor":300,"data":"","error":""}]}\n',
        b"[1]\n",
    ]
    r = run(["encode"], good + b"".join(bad) + good)
    assert r.returncode == 1
    lines = r.stderr.decode().splitlines()
    assert [line.split(":")[0] for line in lines] == ["line 2", "line 3", "line 4", "line 5"]
    assert r.stdout == b"\x00\xff\x00\xff"
    assert b"Traceback" not in r.stderr


def test_io_faults_are_one_line_and_exit_2(tmp_path):
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""), PYTHONDONTWRITEBYTECODE="1")
    path = tmp_path / "s.bin"
    path.write_bytes(stream() * 1000)
    with open("/dev/full", "wb") as full:
        for args, data in ((["decode", str(path)], None), (["encode"], run(["decode", str(path)]).stdout)):
            r = subprocess.run(
                [sys.executable, "-m", "testproto", *args], input=data, stdout=full, stderr=subprocess.PIPE, env=env
            )
            assert r.returncode == 2, args
            assert r.stderr.decode().splitlines() == [f"testproto: cannot write standard output: {os.strerror(28)}"]
    for args in (["decode", "-"], ["encode"], ["decode", str(tmp_path)], ["decode", "/proc/self/mem"]):
        r = subprocess.run(
            [sys.executable, "-m", "testproto", *args],
            capture_output=True,
            env=env,
            preexec_fn=lambda: os.close(0),
        )
        assert r.returncode == 2, args
        assert r.stderr.count(b"\n") == 1 and b"Traceback" not in r.stderr, r.stderr
    # A closed pipe: killed by SIGPIPE, nothing on stderr.
    p = subprocess.Popen(
        [sys.executable, "-m", "testproto", "decode", str(path)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        env=env,
    )
    assert len(p.stdout.read(100)) == 100
    p.stdout.close()
    assert p.wait(timeout=60) == -13
    assert p.stderr.read() == b""


def test_blank_lines_are_rfc_8259_whitespace_only():
    good = b'{"offset":0,"skipped":"00ff"}\n'
    r = run(["encode"], good + b" \t\r\n" + "\u00a0\n".encode() + b"\x0c\n" + good)
    assert r.returncode == 1
    assert [line.split(":")[0] for line in r.stderr.decode().splitlines()] == ["line 3", "line 4"]
    assert r.stdout == b"\x00\xff\x00\xff"
