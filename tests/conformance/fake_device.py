"""A tiny scripted fake device for the session corpus (tests/sessions/): serves one case over TCP.

It accepts one connection and plays the case's steps: the `receive` steps before the first
command at their times from the connection; then, for every `send` step whose expected result
is not "refused" (a refused command is never sent), it reads one complete packet from the
session (checking it against the step's `bytes` when given) and plays the `receive` steps up to
the next send at their times relative to that command's arrival. Then it waits until the
session closes the connection. It knows nothing of the protocol beyond the framing (sync bytes,
header, length byte, checksum size) of the IR; the simulator of issue 21 replaces it.

    python -m tests.conformance.fake_device --protocol mip --case ping_ack   # prints the port
"""

from __future__ import annotations

import argparse
import json
import socket
import sys
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


class FakeDevice:
    """Serves `case` (a loaded session case, generator/sessions.py) with `framing` (IR framing)."""

    def __init__(self, case: dict, framing: dict) -> None:
        self.case = case
        self.framing = framing
        self.errors: list[str] = []
        self.received: list[bytes] = []
        self._srv = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self._srv.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self._srv.bind(("127.0.0.1", 0))
        self._srv.listen(1)
        self._srv.settimeout(30)
        self.port = self._srv.getsockname()[1]
        self._thread = threading.Thread(target=self._serve, daemon=True)

    def start(self) -> FakeDevice:
        self._thread.start()
        return self

    def join(self, timeout: float = 30) -> None:
        self._thread.join(timeout)

    def _refused(self) -> set[int]:
        out = set()
        for line in self.case["expect"]:
            obj = json.loads(line)
            if obj.get("result") == "refused":
                out.add(obj["line"])
        return out

    def _read_packet(self, conn: socket.socket, buf: bytearray) -> bytes:
        fr = self.framing
        sync = bytes(fr["sync"])
        while True:
            i = buf.find(sync)
            if i >= 0 and len(buf) - i >= fr["header_size"]:
                total = fr["header_size"] + buf[i + fr["length_offset"]] + fr["checksum_size"]
                if len(buf) - i >= total:
                    packet = bytes(buf[i : i + total])
                    del buf[: i + total]
                    return packet
            data = conn.recv(4096)
            if not data:
                raise ConnectionError("the session closed the connection before sending a command")
            buf += data

    def _serve(self) -> None:
        try:
            conn, _ = self._srv.accept()
        except OSError as e:
            self.errors.append(f"no connection: {e}")
            return
        conn.settimeout(30)
        refused = self._refused()
        buf = bytearray()
        anchor_time, anchor_at = time.monotonic(), 0
        number = 0
        try:
            for step in self.case["steps"]:
                if "send" in step:
                    number += 1
                    if number in refused:
                        continue
                    packet = self._read_packet(conn, buf)
                    self.received.append(packet)
                    if step.get("bytes") and packet.hex() != step["bytes"]:
                        self.errors.append(f"command {number}: got {packet.hex()}, expected {step['bytes']}")
                    anchor_time, anchor_at = time.monotonic(), step["at"]
                    continue
                delay = anchor_time + (step["at"] - anchor_at) / 1000.0 - time.monotonic()
                if delay > 0:
                    time.sleep(delay)
                conn.sendall(bytes.fromhex(step["receive"]))
            while conn.recv(4096):
                pass
        except OSError as e:
            self.errors.append(f"connection: {e}")
        except ConnectionError as e:
            self.errors.append(str(e))
        finally:
            conn.close()
            self._srv.close()


def main() -> int:
    from generator.sessions import load_sessions
    from generator.spec import load_spec

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--protocol", default="mip")
    ap.add_argument("--case", required=True)
    args = ap.parse_args()
    ir = load_spec()
    cases = [c for c in load_sessions(ir, ROOT / "tests" / "sessions") if c["protocol"] == args.protocol]
    case = next((c for c in cases if c["name"] == args.case), None)
    if case is None:
        print(f"no case {args.case!r} for {args.protocol}", file=sys.stderr)
        return 2
    framing = next(p for p in ir["protocols"] if p["name"] == args.protocol)["framing"]
    dev = FakeDevice(case, framing).start()
    print(dev.port, flush=True)
    dev.join(3600)
    for e in dev.errors:
        print(e, file=sys.stderr)
    return 1 if dev.errors else 0


if __name__ == "__main__":
    sys.exit(main())
