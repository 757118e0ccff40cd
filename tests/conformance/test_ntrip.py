"""RTCM3 corrections into the simulated CV7 and the device command line's NTRIP client (issue 53;
docs/rtk-and-nmea.md).

Golden values come from the specifications and the manual, not from the code under test:

- RTCM3 framing (RTCM 10403.x): 0xD3, 6 reserved zero bits and a 10-bit payload length, the
  payload whose first 12 bits are the message number, CRC-24Q (polynomial 0x1864CFB, initial 0)
  over header and payload; written here independently of the runtime's parser.
- NTRIP 1.0: a request answered `ICY 200 OK` then the data, `SOURCETABLE 200 OK` and the table
  (STR/CAS/NET lines) up to `ENDSOURCETABLE`, `401 Unauthorized` for bad Basic credentials.
  NTRIP 2.0: `HTTP/1.1 200 OK` with `Ntrip-Version: Ntrip/2.0`, the data `Transfer-Encoding:
  chunked` (hex size line, data, CR LF; a 0 chunk ends it), `Content-Type: gnss/sourcetable`,
  404 for an unknown mountpoint. The caster below is written from these rules.
- NMEA-0183 GGA: `$GPGGA,hhmmss.ss,ddmm.mmmm,N,dddmm.mmmm,E,quality,sats,hdop,alt,M,sep,M,,*hh`,
  the checksum the XOR of the characters between `$` and `*`.
- The CV7: supported RTCM3 messages (3dm-cv7-ins-docs.txt line 883), SPARTN blocks RTCM (line
  877), Fix Info 0x91,0x0B fix types FIX_3D 0, FIX_RTK_FLOAT 5, FIX_RTK_FIXED 6 (line 5163). The
  times are the simulator's stated choices (docs/simulator-world.md "RTK", spec decision): RTK
  float 3 s and fixed 10 s after corrections and a fix, corrections aged out 10 s after the
  newest observation.

The simulator serves several TCP hosts at once, every host receiving what the device sends
(docs/conformance.md section 9, "Several hosts"): the fix is read both from the ntrip command's
status lines and over a second connection that only reads, as an application beside the client
would. Fix Info's layout (field length 8, descriptor 0x0B, the fix type its first byte) is the
manual's, line 5163.
"""

from __future__ import annotations

import base64
import os
import random
import re
import signal
import socket
import subprocess
import sys
import threading
import time
from typing import Dict, Iterator, List

import pytest

from tests.conformance.test_device_cli import PACKAGE_DIR, Sim
from tests.conformance.test_simulator_world import command, pkg, sample, sim_mod, world_mod
from tests.helpers.procs import as_in_a_terminal

ntrip_mod = __import__("mipcodec.device.ntrip", fromlist=["ntrip"])
FIX = pkg.types.GnssFixTypeCv7
USER, PASSWORD, MOUNT = "rover", "s3cret:pw", "RTCM3_MSM7"
SOURCETABLE = [
    "CAS;127.0.0.1;2101;Test;none;0;DEU;50.0;8.0;0.0.0.0;0;http://caster.invalid",
    "NET;TEST;none;B;N;none;none;none;none",
    f"STR;{MOUNT};Test;RTCM 3.3;1005(10),1077(1),1087(1);2;GPS+GLO;TEST;DEU;50.00;8.00;1;0;none;none;B;N;9600;",
]


# ------------------------------------------------------------------------ RTCM3 (RTCM 10403)
def crc24q(data: bytes) -> int:
    crc = 0
    for byte in data:
        crc ^= byte << 16
        for _ in range(8):
            crc <<= 1
            if crc & 0x1000000:
                crc ^= 0x1864CFB
    return crc & 0xFFFFFF


def frame(message_type: int, length: int = 20, seed: int = 0) -> bytes:
    """An RTCM3 frame: the message number in the payload's first 12 bits, the rest arbitrary."""
    rng = random.Random(message_type * 1000 + seed)
    body = bytearray(rng.getrandbits(8) for _ in range(length))
    body[0] = message_type >> 4
    body[1] = ((message_type & 0xF) << 4) | (body[1] & 0x0F)
    head = bytes([0xD3, length >> 8, length & 0xFF]) + bytes(body)
    return head + crc24q(head).to_bytes(3, "big")


def nmea_ok(sentence: str) -> bool:
    m = re.fullmatch(r"\$([^*$]+)\*([0-9A-F]{2})\r\n", sentence)
    if not m:
        return False
    x = 0
    for c in m.group(1).encode():
        x ^= c
    return x == int(m.group(2), 16)


# --------------------------------------------------------------------------- the caster
class Caster:
    """An NTRIP caster on 127.0.0.1 (port 0), one thread per client. `version` "1.0" or "2.0";
    `mode`: "stream" (corrections for `stream_for` seconds, then silence with the connection
    open), "garbage" (after the 200 OK: random bytes forever) or "endless" (a header that never
    ends). The requests and the GGA sentences received are kept."""

    def __init__(
        self, version: str = "2.0", mode: str = "stream", stream_for: float = 60.0, bare_lf: bool = False,
        drop_first_after: float = 0.0,
    ) -> None:  # fmt: skip
        self.version, self.mode, self.stream_for, self.bare_lf = version, mode, stream_for, bare_lf
        self.drop_first_after = drop_first_after  # the first stream's connection closed after this long
        self.requests: List[Dict[str, str]] = []
        self.gga: List[str] = []
        self.sent: Dict[int, int] = {}
        self.last_sent = 0.0  # time.monotonic() after the newest corrections were sent
        self.stop = threading.Event()
        self.server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self.server.bind(("127.0.0.1", 0))
        self.server.listen(4)
        self.port = self.server.getsockname()[1]
        threading.Thread(target=self._accept, daemon=True).start()

    def url(self, mount: str = MOUNT, user: str = USER, password: str = PASSWORD, scheme: str = "ntrip") -> str:
        cred = f"{user}:{password.replace(':', '%3A')}@" if user else ""
        return f"{scheme}://{cred}127.0.0.1:{self.port}/{mount}"

    def close(self) -> None:
        self.stop.set()
        self.server.close()

    def _accept(self) -> None:
        while not self.stop.is_set():
            try:
                conn, _ = self.server.accept()
            except OSError:
                return
            threading.Thread(target=self._serve, args=(conn,), daemon=True).start()

    def _line(self, text: str) -> bytes:
        return (text + ("\n" if self.bare_lf else "\r\n")).encode()

    def _serve(self, conn: socket.socket) -> None:
        try:
            with conn:
                head = b""
                while b"\r\n\r\n" not in head and len(head) < 8192:
                    data = conn.recv(4096)
                    if not data:
                        return
                    head += data
                lines = head.split(b"\r\n\r\n", 1)[0].decode().split("\r\n")
                request = {"line": lines[0]}
                for line in lines[1:]:
                    name, _, value = line.partition(":")
                    request[name.strip().lower()] = value.strip()
                self.requests.append(request)
                self._answer(conn, request)
        except OSError:
            pass

    def _answer(self, conn: socket.socket, request: Dict[str, str]) -> None:
        path = request["line"].split()[1]
        v2 = self.version == "2.0"
        if path == "/" or (not v2 and path != f"/{MOUNT}"):  # NTRIP 1.0: an unknown mountpoint gets the table
            table = "".join(line + "\r\n" for line in SOURCETABLE) + "ENDSOURCETABLE\r\n"
            if v2:
                head = ["HTTP/1.1 200 OK", "Ntrip-Version: Ntrip/2.0", "Content-Type: gnss/sourcetable"]
            else:
                head = ["SOURCETABLE 200 OK", "Server: TestCaster/1.0", "Content-Type: text/plain"]
            head.append(f"Content-Length: {len(table)}")
            conn.sendall(b"".join(self._line(h) for h in head) + self._line("") + table.encode())
            return
        token = base64.b64encode(f"{USER}:{PASSWORD}".encode()).decode()
        if request.get("authorization") != f"Basic {token}":
            status = "HTTP/1.1 401 Unauthorized" if v2 else "HTTP/1.0 401 Unauthorized"
            conn.sendall(self._line(status) + self._line('WWW-Authenticate: Basic realm="/"') + self._line(""))
            return
        if path != f"/{MOUNT}":
            conn.sendall(self._line("HTTP/1.1 404 Not Found") + self._line(""))
            return
        if self.mode == "endless":
            conn.sendall(self._line("HTTP/1.1 200 OK"))
            while not self.stop.is_set():
                conn.sendall(b"X-Padding: " + b"a" * 1000 + b"\r\n")
            return
        if v2:
            head = ["HTTP/1.1 200 OK", "Ntrip-Version: Ntrip/2.0", "Content-Type: gnss/data"]
            conn.sendall(b"".join(self._line(h) for h in head + ["Transfer-Encoding: chunked"]) + self._line(""))
        else:
            conn.sendall(self._line("ICY 200 OK") + self._line(""))
        threading.Thread(target=self._read_gga, args=(conn,), daemon=True).start()
        rng = random.Random(7)
        start = time.monotonic()
        tick = 0
        first = len(self.requests) == 1
        while not self.stop.is_set():
            if first and self.drop_first_after and time.monotonic() - start > self.drop_first_after:
                conn.shutdown(socket.SHUT_RDWR)  # the connection closes (the GGA reader too): the client reconnects
                return
            if self.mode == "garbage":
                data = bytes(rng.getrandbits(8) for _ in range(4096))
            elif time.monotonic() - start < self.stream_for:
                types = [1077, 1087] + ([1005, 1019, 1033] if tick % 10 == 0 else [])
                data = b"".join(frame(m, 40 if m > 1070 else 19, tick) for m in types)
                data = b"\x00junk\xd3" + data  # bytes between frames: dropped, not forwarded
                for m in types:
                    self.sent[m] = self.sent.get(m, 0) + 1
            else:
                data = b""
            if data and v2:  # chunks cut anywhere, across frames
                cut = rng.randrange(1, len(data))
                data = b"".join(b"%x\r\n%s\r\n" % (len(p), p) for p in (data[:cut], data[cut:]))
            if data:
                conn.sendall(data)
                self.last_sent = time.monotonic()
            tick += 1
            time.sleep(0.001 if self.mode == "garbage" else 0.1)

    def _read_gga(self, conn: socket.socket) -> None:
        buf = b""
        try:
            while not self.stop.is_set():
                data = conn.recv(4096)
                if not data:
                    return
                buf += data
                while b"\n" in buf:
                    line, _, buf = buf.partition(b"\n")
                    self.gga.append(line.decode("ascii", "replace") + "\n")
        except OSError:
            pass


@pytest.fixture
def caster() -> Iterator[Caster]:
    c = Caster()
    yield c
    c.close()


def device(address: str, *args: str, timeout: float = 60) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(PACKAGE_DIR)}
    cmd = [sys.executable, "-m", "mipcodec", "device", address, "ntrip", *args]
    done = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout)
    assert "Traceback" not in done.stderr, done.stderr
    return done


CLOSED = "tcp:127.0.0.1:1"  # no device there: the sourcetable and usage errors need none


# ------------------------------------------------------------------ the simulator's intake
def _rtcm_then_fix(sim, types: List[int], at: float) -> None:
    sim.sim_time(0.0)
    for m in types:
        sim.feed(frame(m), at / sim.speed)


def test_simulator_takes_supported_rtcm_and_counts_the_rest() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    ping = pkg.codec.framing.PacketBuilder(0x01).add(pkg.base.Ping()).build()
    # a command packet between RTCM3 frames, cut into pieces: frames and the packet all taken
    stream = frame(1005, 19) + frame(4094) + ping + frame(1077, 40) + frame(1125) + frame(1019) + frame(1033)
    acks = []
    sim.sim_time(0.0)
    for k in range(0, len(stream), 7):
        acks += [d for _, d in sim.feed(stream[k : k + 7], 0.0) if d[2] == 0x01]
    assert len(acks) == 1  # the ping answered
    c = sim.corrections
    assert c.taken == {1005: 1, 1077: 1, 1125: 1, 1033: 1}  # 1125: the BeiDou row (line 888 reads 1025)
    assert c.unsupported == {4094: 1, 1019: 1}  # not in the table (line 883): counted, ignored
    bad = bytearray(frame(1077, 40))
    bad[-1] ^= 1  # a bad CRC: not a frame at all
    sim.feed(bytes(bad), 0.0)
    assert c.taken[1077] == 1


def test_simulator_rtk_from_rtcm_and_aged_out() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    assert sim.corrections.spec["max_age"] == 10.0
    _rtcm_then_fix(sim, [1077, 1087], 2.0)  # observations without a station position: nothing
    assert sim.world.rtk_corrections == []
    for k in range(0, 21):  # a station position, then observations every second until 22 s
        _rtcm_then_fix(sim, ([1006] if k == 0 else []) + [1077], 2.0 + k)
    expected = [(4.5, FIX.FIX_3D), (5.5, FIX.FIX_RTK_FLOAT), (11.5, FIX.FIX_RTK_FLOAT), (12.5, FIX.FIX_RTK_FIXED)]
    expected += [(31.5, FIX.FIX_RTK_FIXED), (32.5, FIX.FIX_3D)]  # the last observation at 22 s, aged out at 32 s
    for at, fix in expected:
        assert sample(sim, 0x91, 0x0B, at).fix_type == fix, at
    _rtcm_then_fix(sim, [1077], 40.0)  # after aging out: a station position is needed again
    assert sample(sim, 0x91, 0x0B, 45.0).fix_type == FIX.FIX_3D
    assert sim.corrections.age(41.0) == 19.0


def test_simulator_spartn_blocks_rtcm() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    spartn = pkg.gnss.SpartnConfiguration(
        function=1, enable=1, type=1, current_key_tow=0, current_key_week=0, current_key=b"0" * 32,
        next_key_tow=0, next_key_week=0, next_key=b"0" * 32,
    )  # fmt: skip
    assert command(sim, spartn, 0.0)[0][1] == 0
    for k in range(0, 15):
        _rtcm_then_fix(sim, [1005, 1077], 2.0 + k)
    assert sim.corrections.blocked == 30 and not sim.corrections.taken
    assert sample(sim, 0x91, 0x0B, 16.0).fix_type == FIX.FIX_3D


# ------------------------------------------------------------------------ the NTRIP client
def test_response_decoding_is_tolerant_and_bounded() -> None:
    Response, Broken = ntrip_mod.Response, ntrip_mod.Broken
    body = frame(1077, 40)
    chunked = b"http/1.1 200 ok\ntransfer-ENCODING: Chunked\n\n" + b"%X;ext=1\r\n%s\r\n0\r\n\r\n" % (len(body), body)
    r = Response()
    out = b"".join(r.feed(chunked[k : k + 1]) for k in range(len(chunked)))  # one byte at a time
    assert out == body and r.kind == "stream" and r.ended
    r = Response()
    assert r.feed(b"ICY 200 OK\r\n" + body) == body  # no blank line before the data (NTRIP 1.0 casters)
    r = Response()
    assert r.feed(b"SOURCETABLE 200 OK\r\n\r\nSTR;x\r\n") == b"STR;x\r\n" and r.kind == "sourcetable"
    r = Response()
    with pytest.raises(Broken, match="longer than"):
        for _ in range(100):
            r.feed(b"HTTP/1.1 200 OK\r\n" if not r._head else b"X: " + b"a" * 500 + b"\r\n")
    r = Response()
    r.feed(b"HTTP/1.1 200 OK\r\nTransfer-Encoding: chunked\r\n\r\n")
    with pytest.raises(Broken, match="chunk"):
        r.feed(b"1" * 100)
    with pytest.raises(ntrip_mod.Broken, match="not an NTRIP response"):
        Response().feed(b"SSH-2.0-OpenSSH\r\n\r\n")


def test_gga_sentence() -> None:
    s = ntrip_mod.gga(-33.5, 151.25, 40.0, 62.5, 4, 14, 3723.456)
    assert nmea_ok(s) and s.startswith("$GPGGA,010203.45,3330.00000,S,15115.00000,E,4,14,,40.000,M,22.500,M,,*")


@pytest.mark.parametrize("version", ["1.0", "2.0"])
def test_sourcetable_without_mountpoint(version: str) -> None:
    c = Caster(version)
    try:
        done = device(CLOSED, c.url(mount="", user=""))
    finally:
        c.close()
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == SOURCETABLE + ["ENDSOURCETABLE"]
    assert c.requests[0]["line"] == "GET / HTTP/1.1" and c.requests[0]["ntrip-version"] == "Ntrip/2.0"


def test_usage_errors_exit_2() -> None:
    for url in ("ftp://x/y", "ntrip://127.0.0.1:99999/M", "ntrip:///M", "ntrip://h/a/b"):
        done = device(CLOSED, url)
        assert done.returncode == 2 and len(done.stderr.splitlines()) == 1 and "URL" in done.stderr, (url, done.stderr)
    done = device(CLOSED, "ntrip://127.0.0.1/M", "--gga-interval", "-1")
    assert done.returncode == 2 and "--gga-interval" in done.stderr


@pytest.fixture(scope="module")
def cv7() -> Iterator[Sim]:
    with Sim("cv7_ins", "tcp:127.0.0.1:0", "--speed", "20") as s:  # the later --speed wins
        yield s


def test_refusals_exit_1(cv7: Sim) -> None:
    c, c2 = Caster("1.0", bare_lf=True), Caster("2.0")
    try:
        bad = device(cv7.address, c.url(password="wrong"), "--duration", "10")
        missing = device(cv7.address, c.url(mount="NOPE"), "--duration", "10")  # 1.0: the sourcetable
        missing2 = device(cv7.address, c2.url(mount="NOPE"), "--duration", "10")  # 2.0: 404
    finally:
        c.close()
        c2.close()
    assert bad.returncode == 1 and "credentials" in bad.stderr and len(bad.stderr.splitlines()) == 1, bad.stderr
    assert missing.returncode == 1 and "no mountpoint 'NOPE'" in missing.stderr, missing.stderr
    assert missing2.returncode == 1 and "no such mountpoint (HTTP/1.1 404" in missing2.stderr, missing2.stderr
    unreachable = device(cv7.address, "ntrip://127.0.0.1:1/M", "--retries", "1", "--duration", "10")
    assert unreachable.returncode == 1 and "gave up after 2" in unreachable.stderr.splitlines()[-1]


def test_garbage_and_an_endless_header(cv7: Sim) -> None:
    garbage, endless = Caster("1.0", mode="garbage"), Caster("2.0", mode="endless")
    try:
        g = device(cv7.address, garbage.url(), "--duration", "2.5")
        e = device(cv7.address, endless.url(), "--retries", "0", "--duration", "10")
    finally:
        garbage.close()
        endless.close()
    assert g.returncode == 0, g.stderr
    last = g.stdout.splitlines()[-1]
    assert "frames=-" in last and int(re.search(r"garbage=(\d+)", last).group(1)) > 100_000, last
    assert e.returncode == 1 and "longer than 16384 bytes" in e.stderr, e.stderr


class Reader:
    """A second connection to the simulator that only reads: the fix type of every GNSS receiver 1
    Fix Info (0x91,0x0B) in the stream, with the time it came (time.monotonic())."""

    def __init__(self, address: str) -> None:
        host, _, port = address[4:].rpartition(":")
        self.sock = socket.create_connection((host, int(port)), timeout=5)
        self.sock.settimeout(0.1)
        self.fixes: List[tuple] = []
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._read, daemon=True)
        self.thread.start()

    def _read(self) -> None:
        parser = pkg.codec.framing.Parser()
        while not self.stop.is_set():
            try:
                data = self.sock.recv(65536)
            except socket.timeout:
                continue
            if not data:
                return
            now = time.monotonic()
            for e in parser.feed(data):
                p = getattr(e, "data", b"")
                if isinstance(e, pkg.codec.framing.RawPacket) and p[2] == 0x91:
                    k = 4
                    while k < 4 + p[3]:  # the fields: length, descriptor, data
                        if p[k + 1] == 0x0B and p[k] == 8:
                            self.fixes.append((now, p[k + 2]))
                        k += p[k]

    def close(self) -> List[tuple]:
        self.stop.set()
        self.thread.join(5)
        self.sock.close()
        return self.fixes


def test_cv7_reaches_rtk_fixed_through_ntrip_and_falls_back(cv7: Sim) -> None:
    """NTRIP 2.0 chunked: corrections for 3 s (60 simulated s at --speed 20), then silence. A second
    connection reads receiver 1's Fix Info meanwhile (the issue's "read over a second connection")."""
    c = Caster("2.0", stream_for=3.0)
    reader = Reader(cv7.address)
    try:
        done = device(cv7.address, c.url(scheme="http"), "--gga-interval", "0.5", "--duration", "6.5")
    finally:
        c.close()
        seen = reader.close()
    assert done.returncode == 0, done.stderr
    # Over the second connection: 3D (0), RTK float (5), RTK fixed (6) while corrections flow, then
    # back to 3D once they age out, 10 simulated s (0.5 s real) after the caster's last frames
    types = [t for _, t in seen]
    assert 6 in types and 5 in types[: types.index(6)], types
    fixed_at = seen[types.index(6)][0]
    assert fixed_at < c.last_sent, (fixed_at, c.last_sent)
    last_fixed = len(types) - 1 - types[::-1].index(6)
    after = seen[last_fixed + 1 :]
    assert after and {t for _, t in after} <= {0, 5} and after[-1][1] == 0, types
    assert after[0][0] >= c.last_sent + 0.4, (after[0][0] - c.last_sent, types)
    lines = done.stdout.splitlines()
    fixes = [re.search(r"fix=(\S+)", line).group(1) for line in lines]
    # RTK fixed while corrections flow (a fix at 2 s, fixed 10 s later: 0.6 s real), back to the
    # 3D fix 10 simulated s (0.5 s real) after they stop
    assert "fix_rtk_fixed" in fixes[:3], lines
    assert fixes[-1] == "fix_3d", lines
    frames = dict(re.findall(r"(\d+):(\d+)", re.search(r"frames=(\S+( \d+:\d+)*)", lines[-1]).group(1)))
    assert {int(k) for k in frames} == set(c.sent) and int(frames["1077"]) == c.sent[1077], (frames, c.sent)
    assert c.requests[0]["line"] == f"GET /{MOUNT} HTTP/1.1"
    good = [s for s in c.gga if nmea_ok(s)]
    assert good and len(good) == len(c.gga), c.gga
    fields = good[-1].split(",")
    lat = int(fields[2][:2]) + float(fields[2][2:]) / 60
    lon = int(fields[4][:3]) + float(fields[4][3:]) / 60
    origin = world_mod.ORIGIN
    assert abs(lat * (1 if fields[3] == "N" else -1) - origin[0]) < 1e-4
    assert abs(lon * (1 if fields[5] == "E" else -1) - origin[1]) < 1e-4
    assert {f.split(",")[6] for f in good} <= {"1", "5", "4"} and "4" in {f.split(",")[6] for f in good}


def test_ntrip1_icy_stream_reconnects_and_stops_on_ctrl_c(cv7: Sim) -> None:
    """NTRIP 1.0 with bare LF line ends; the caster drops the first connection after 0.5 s: the
    client retries 1 s later (the first backoff step) and streams on; SIGINT ends it with 0."""
    c = Caster("1.0", bare_lf=True, drop_first_after=0.5)
    env = {**os.environ, "PYTHONPATH": str(PACKAGE_DIR)}
    cmd = [sys.executable, "-m", "mipcodec", "device", cv7.address, "ntrip", c.url(), "--gga-interval", "0"]
    proc = subprocess.Popen(
        cmd,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
        preexec_fn=as_in_a_terminal,
    )
    try:
        lines = [proc.stdout.readline() for _ in range(3)]  # 3 s of status lines
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=30)
    finally:
        c.close()
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 0 and "Traceback" not in err, err
    assert "retrying in 1 s" in err and len(c.requests) == 2, (err, c.requests)
    last = (lines + out.splitlines())[-1]
    assert re.search(r" 1077:\d+ ", last), last
    assert not c.gga  # --gga-interval 0: none sent
