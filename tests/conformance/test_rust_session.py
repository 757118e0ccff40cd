"""The Rust session tool over IPv6 (a bracketed host). The crates' `configure_and_stream` example
is run with the other languages' by tests/conformance/test_configure_example.py."""

from __future__ import annotations

import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_tool_over_ipv6():
    """The Rust session tool connects to a bracketed IPv6 host (`tcp:[::1]:PORT`): a responder on
    the IPv6 loopback answers one ping with its ack."""
    import socket
    import threading

    srv = socket.socket(socket.AF_INET6, socket.SOCK_STREAM)
    srv.bind(("::1", 0))
    srv.listen(1)
    srv.settimeout(900)  # the tool may be built first (tests/lang/rust.sh)
    port = srv.getsockname()[1]
    got: list[bytes] = []

    def serve() -> None:
        conn, _ = srv.accept()
        with conn:
            data = b""
            while len(data) < 8:
                data += conn.recv(64)
            got.append(data)
            conn.sendall(bytes.fromhex("75650104 04f10100 d56a".replace(" ", "")))
            while conn.recv(64):
                pass

    t = threading.Thread(target=serve, daemon=True)
    t.start()
    line = '{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}\n'
    proc = subprocess.run(
        [str(ROOT / "tests/conformance/session"), "rust", "--connect", f"tcp:[::1]:{port}"],
        input=line,
        capture_output=True,
        text=True,
        timeout=900,
    )
    t.join(10)
    srv.close()
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == ['{"line":1,"result":"ack","code":0,"reply":[]}']
    assert got == [bytes.fromhex("7565010202 01e0c6".replace(" ", ""))]
