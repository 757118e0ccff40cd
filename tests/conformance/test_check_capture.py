"""The capture checker (check_capture.py, run by `make test-capture`) passes a clean stream and
fails on each kind of incomplete decoding. Streams are built from published vectors."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CHECK = [sys.executable, str(ROOT / "tests/conformance/check_capture.py")]
# The CV7 example data packet (scaled accel, line 3958).
ACCEL = bytes.fromhex("7565800E0E043E7A63A0BB8E3B297FE5BF7F84EE")
# The GX5/CV7 overview packet with field descriptor 0x03, which no manual defines in set 0x80.
UNKNOWN = bytes.fromhex("7565800E0E033E7A63A0BB8E3B297FE5BF7F83E1")


def check(tmp_path: Path, data: bytes) -> subprocess.CompletedProcess:
    f = tmp_path / "capture.bin"
    f.write_bytes(data)
    return subprocess.run([*CHECK, str(f)], capture_output=True, text=True)


def test_clean_stream_passes(tmp_path):
    proc = check(tmp_path, ACCEL * 3)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "3 packets" in proc.stdout and "(0x80,0x04) scaled_accel: 3" in proc.stdout


def test_skipped_bytes_fail(tmp_path):
    proc = check(tmp_path, ACCEL + b"\x00\x75" + ACCEL)
    assert proc.returncode == 1
    assert "offset 20: 2 skipped bytes" in proc.stdout


def test_unknown_descriptor_fails(tmp_path):
    proc = check(tmp_path, ACCEL + UNKNOWN)
    assert proc.returncode == 1
    assert "offset 20: field (0x80,0x03) left raw: unknown descriptor" in proc.stdout


def test_missing_file_is_a_usage_error(tmp_path):
    proc = subprocess.run([*CHECK, str(tmp_path / "none.bin")], capture_output=True, text=True)
    assert proc.returncode == 2 and "no such file" in proc.stderr
