"""The NTRIP client of the device command line (docs/rtk-and-nmea.md):

    mscipcodec-device ADDRESS ntrip URL [--gga-interval S] [--duration S] [--retries N]

URL: ntrip://[USER:PASSWORD@]HOST[:PORT]/MOUNTPOINT (RTKLIB's form) or http://... (port 2101 by
default). Without a mountpoint it prints the caster's sourcetable and ends. With one, it streams
the mountpoint's RTCM3 corrections into the device's port: the caster's bytes (NTRIP 1.0 `ICY 200
OK`, NTRIP 2.0 `HTTP/1.1 200 OK`, chunked or not) go through the runtime's parser, and every whole
RTCM3 frame with a valid CRC-24Q is written to the device with the session's own writer, between
MIP packets (the session writes whole packets in the same thread, so a frame never lands inside
one); other bytes are counted as garbage and dropped. The device's position comes from its own
data stream: the client sets the message format of the GNSS data set holding LLH position and fix
information to 1 Hz (restored at the end) and sends the caster a GGA sentence built from it every
--gga-interval seconds (0: never). A lost or refused connection is retried after 1, 2, 4 ... 30 s;
after --retries failed attempts in a row it gives up. One status line a second on stdout: time,
caster state, bytes, frames by type, correction age, the device's fix type.

Memory stays bounded whatever the caster sends: a response header is read up to HEADER_MAX bytes,
a chunk-size line up to CHUNK_LINE_MAX, a sourcetable line up to LINE_MAX, and the parser keeps at
most one partial frame (the garbage between frames is counted and dropped).

Exit status: 0 stopped by --duration or Ctrl-C, or the sourcetable printed; 1 the caster refused
(401 bad credentials, 404 or a sourcetable for an unknown mountpoint, any other status), could not
be reached --retries times in a row, or the device went away or did not answer; 2 a usage error (a
bad URL or option) or no connection to the device.
"""

from __future__ import annotations

import base64
import json
import math
import socket
import sys
import time
from typing import Any, Callable, Dict, Optional, Tuple
from urllib.parse import unquote, urlsplit

from .._protocol import PACKAGE
from ..codec.framing import Parser, Rtcm
from ..session import SessionError

PROG = f"{PACKAGE}-device"
DEFAULT_PORT = 2101
HEADER_MAX = 16384  # bytes of a response header at most
CHUNK_LINE_MAX = 64  # bytes of a chunk-size line at most
LINE_MAX = 65536  # bytes of a sourcetable line at most
SOURCETABLE_MAX = 16 << 20  # bytes of a sourcetable at most
CONNECT_TIMEOUT_S = 5.0
SILENCE_S = 30.0  # no byte from the caster this long: reconnect
BACKOFF_S = (1.0, 2.0, 4.0, 8.0, 16.0, 30.0)  # waits between attempts (the last repeats)
READ_MAX = 65536
PUMP_MS = 20  # the device is read at least this often
READS_PER_PUMP = 16  # caster reads between two reads of the device


class Usage(Exception):
    """A usage error (exit 2)."""


class Refused(Exception):
    """The caster said no, for good (exit 1): bad credentials, no such mountpoint."""


class Broken(Exception):
    """This connection failed (a retry may do better): unreachable, closed, a bad response."""


def add_parser(sub: Any, common: Any) -> None:
    """The `ntrip` subcommand's parser (device/cli.py)."""
    n = sub.add_parser("ntrip", parents=[common], help="stream an NTRIP caster's RTCM3 corrections into the device")
    n.add_argument(
        "url",
        metavar="URL",
        help="ntrip://USER:PASSWORD@HOST:PORT/MOUNTPOINT or http://...; no mountpoint: the sourcetable",
    )
    n.add_argument(
        "--gga-interval", type=float, default=10.0, metavar="S", help="send the caster GGA every S seconds (0: never)"
    )
    n.add_argument("--duration", type=float, help="seconds (default: until interrupted)")
    n.add_argument(
        "--retries", type=int, default=10, metavar="N", help="failed caster connections in a row before giving up"
    )


# ------------------------------------------------------------------------------------ URL
class Target:
    """A parsed caster URL."""

    def __init__(self, host: str, port: int, mountpoint: str, user: str, password: str) -> None:
        self.host = host
        self.port = port
        self.mountpoint = mountpoint
        self.user = user
        self.password = password

    def request(self, agent: str) -> bytes:
        """The GET request: NTRIP 2.0 headers, which an NTRIP 1.0 caster ignores (it answers ICY)."""
        lines = [
            f"GET /{self.mountpoint} HTTP/1.1",
            f"Host: {self.host}:{self.port}",
            "Ntrip-Version: Ntrip/2.0",
            f"User-Agent: NTRIP {agent}",
            "Connection: close",
        ]
        if self.user or self.password:
            token = base64.b64encode(f"{self.user}:{self.password}".encode()).decode("ascii")
            lines.append(f"Authorization: Basic {token}")
        return ("\r\n".join(lines) + "\r\n\r\n").encode("utf-8")


def parse_url(url: str) -> Target:
    """ntrip://[USER:PASSWORD@]HOST[:PORT][/MOUNTPOINT] or http://... (Usage when malformed)."""
    parts = urlsplit(url)
    if parts.scheme.lower() not in ("ntrip", "http"):
        raise Usage(f"bad caster URL {url!r} (expected ntrip://USER:PASSWORD@HOST:PORT/MOUNTPOINT or http://...)")
    try:
        port = parts.port or DEFAULT_PORT
    except ValueError:
        raise Usage(f"bad caster URL {url!r}: the port is not a number from 0 to 65535") from None
    if not parts.hostname:
        raise Usage(f"bad caster URL {url!r}: no host")
    mountpoint = parts.path.lstrip("/")
    if "/" in mountpoint or any(c in mountpoint for c in " \r\n") or parts.query or parts.fragment:
        raise Usage(f"bad caster URL {url!r}: a mountpoint is one name (letters, digits, - and _)")
    return Target(parts.hostname, port, mountpoint, unquote(parts.username or ""), unquote(parts.password or ""))


# ------------------------------------------------------------------------------ response
class Response:
    """The caster's answer, decoded as its bytes arrive: `feed(data)` -> the payload bytes (RTCM
    after a 200, or sourcetable text); `kind` is None until the header ended, then "stream" or
    "sourcetable". Raises Refused or Broken. Tolerant: bare LF line ends, header names in any
    case, missing headers, an ICY status line with no blank line after it."""

    def __init__(self) -> None:
        self.kind: Optional[str] = None
        self.version = ""
        self.status = ""
        self.headers: Dict[str, str] = {}
        self._head = bytearray()
        self._chunked = False
        self._chunk_left = 0  # payload bytes of the current chunk still due
        self._chunk_state = "size"  # size, data, crlf, done
        self._line = bytearray()

    def feed(self, data: bytes) -> bytes:
        if self.kind is None:
            self._head += data
            body = self._header()
            if self.kind is None:
                if len(self._head) > HEADER_MAX:
                    raise Broken(f"the caster's response header is longer than {HEADER_MAX} bytes")
                return b""
            data = body
        return self._dechunk(data) if self._chunked else data

    def _header(self) -> bytes:
        head = bytes(self._head)
        first = head.find(b"\n")
        if first < 0:
            return b""
        status = head[:first].strip().decode("latin-1")
        upper = status.upper()
        if upper.startswith("ICY 200") and head[first + 1 : first + 2] not in (b"", b"\r", b"\n"):
            if not _header_line(head[first + 1 :]):  # ICY then data at once (some NTRIP 1.0 casters)
                self._start("stream", "1.0", status, {})
                return head[first + 1 :]
        end, rest = _blank_line(head, first)
        if end < 0:
            return b""
        headers: Dict[str, str] = {}
        for raw in head[first + 1 : end].split(b"\n"):
            name, sep, value = raw.decode("latin-1").partition(":")
            if sep:
                headers[name.strip().lower()] = value.strip()
        words = status.split()
        code = words[1] if len(words) > 1 else ""
        if upper.startswith("ICY 200"):
            self._start("stream", "1.0", status, headers)
        elif upper.startswith("SOURCETABLE 200"):
            self._start("sourcetable", "1.0", status, headers)
        elif upper.startswith("HTTP/") and code == "200":
            gnss = headers.get("content-type", "").lower()
            self._start("sourcetable" if "sourcetable" in gnss else "stream", "2.0", status, headers)
            self._chunked = "chunked" in headers.get("transfer-encoding", "").lower()
        elif code == "401":
            raise Refused(f"the caster refused the credentials ({status})")
        elif code == "404":
            raise Refused(f"the caster has no such mountpoint ({status})")
        elif upper.startswith(("HTTP/", "ICY", "RTSP/")) and code.isdigit():
            raise Refused(f"the caster answered {status!r}")
        else:
            raise Broken(f"not an NTRIP response: {status[:80]!r}")
        return head[rest:]

    def _start(self, kind: str, version: str, status: str, headers: Dict[str, str]) -> None:
        self.kind, self.version, self.status, self.headers = kind, version, status, headers
        self._head = bytearray()

    def _dechunk(self, data: bytes) -> bytes:
        out = bytearray()
        i = 0
        n = len(data)
        while i < n and self._chunk_state != "done":
            if self._chunk_state == "data":
                take = min(self._chunk_left, n - i)
                out += data[i : i + take]
                i += take
                self._chunk_left -= take
                if self._chunk_left == 0:
                    self._chunk_state = "crlf"
                continue
            j = data.find(b"\n", i)
            piece = data[i : j if j >= 0 else n]
            self._line += piece
            if len(self._line) > CHUNK_LINE_MAX:
                raise Broken(f"a chunk-size line longer than {CHUNK_LINE_MAX} bytes")
            if j < 0:
                break
            i = j + 1
            line = bytes(self._line).strip()
            self._line = bytearray()
            if self._chunk_state == "crlf":
                if line:
                    raise Broken("a chunk not followed by CR LF")
                self._chunk_state = "size"
                continue
            try:
                size = int(line.split(b";")[0], 16)
            except ValueError:
                raise Broken(f"a bad chunk size {line[:20]!r}") from None
            if size == 0:
                self._chunk_state = "done"  # the last chunk: the stream ends (trailers ignored)
            else:
                self._chunk_left, self._chunk_state = size, "data"
        return bytes(out)

    @property
    def ended(self) -> bool:
        """A chunked body's last chunk arrived."""
        return self._chunk_state == "done"


def _header_line(rest: bytes) -> bool:
    """Whether `rest` (after an ICY status line) starts with a `Name: value` header line."""
    line = rest.split(b"\n", 1)[0]
    name, sep, _ = line.partition(b":")
    return bool(sep) and 0 < len(name) <= 64 and all(0x21 <= b < 0x7F for b in name)


def _blank_line(head: bytes, first: int) -> Tuple[int, int]:
    """(end of the header lines, start of the body) or (-1, -1): the first empty line (LF or CR LF)."""
    i = first + 1
    while True:
        j = head.find(b"\n", i)
        if j < 0:
            return -1, -1
        if head[i:j].strip(b"\r") == b"":
            return i, j + 1
        i = j + 1


# ------------------------------------------------------------------------------------ GGA
GGA_QUALITY = (("rtk_fixed", 4), ("rtk_float", 5), ("differential", 2), ("dgnss", 2), ("sbas", 2), ("3d", 1), ("2d", 1))


def quality(fix_name: str) -> int:
    """The GGA quality indicator of a fix type's name (0: no fix)."""
    for part, q in GGA_QUALITY:
        if part in fix_name:
            return q
    return 0


def gga(lat: float, lon: float, msl: float, ellipsoid: float, q: int, sats: int, utc: float) -> str:
    """A GGA sentence ($GPGGA ... *hh CR LF) at UTC `utc` (Unix seconds)."""
    t = time.gmtime(utc)
    hundredths = int((utc % 1.0) * 100)
    la, lo = abs(lat), abs(lon)
    body = (
        f"GPGGA,{t.tm_hour:02d}{t.tm_min:02d}{t.tm_sec:02d}.{hundredths:02d},"
        f"{int(la):02d}{(la - int(la)) * 60:08.5f},{'N' if lat >= 0 else 'S'},"
        f"{int(lo):03d}{(lo - int(lo)) * 60:08.5f},{'E' if lon >= 0 else 'W'},"
        f"{q},{min(sats, 99):02d},,{msl:.3f},M,{ellipsoid - msl:.3f},M,,"
    )
    x = 0
    for c in body.encode("ascii"):
        x ^= c
    return f"${body}*{x:02X}\r\n"


# ------------------------------------------------------------------------------ the client
class Position:
    """The device's newest position and fix (from its data stream)."""

    def __init__(self) -> None:
        self.llh: Optional[Tuple[float, float, float, float]] = None  # lat, lon, ellipsoid, msl
        self.fix = "-"
        self.sats = 0


class Client:
    """One run of `ntrip`: the caster connection, the parser, the counters."""

    def __init__(self, target: Target, write: Callable[[bytes], None]) -> None:
        self.target = target
        self.write = write
        from .. import __version__

        self.agent = f"{PACKAGE}/{__version__}"
        self.sock: Optional[socket.socket] = None
        self.response: Optional[Response] = None
        self.parser = Parser()
        self.bytes = 0  # payload bytes from the caster
        self.garbage = 0  # of them, not part of a valid RTCM3 frame
        self.frames: Dict[int, int] = {}
        self.last_frame: Optional[float] = None
        self.last_byte = 0.0
        self.state = "connecting"
        self.failures = 0
        self.next_try = 0.0

    def connect(self, now: float) -> None:
        t = self.target
        try:
            sock = socket.create_connection((t.host, t.port), timeout=CONNECT_TIMEOUT_S)
            sock.sendall(t.request(self.agent))
        except OSError as e:
            raise Broken(f"cannot connect to {t.host}:{t.port}: {e.strerror or e}") from None
        sock.setblocking(False)
        self.sock, self.response, self.parser = sock, Response(), Parser()
        self.last_byte = now
        self.state = "waiting"

    def close(self) -> None:
        if self.sock is not None:
            try:
                self.sock.close()
            except OSError:
                pass
        self.sock = None

    def read(self, now: float) -> bytes:
        """What the caster sent (the payload after the header), b"" for nothing yet; Broken when the
        connection ended or fell silent."""
        assert self.sock is not None and self.response is not None
        try:
            data = self.sock.recv(READ_MAX)
        except (BlockingIOError, InterruptedError):
            if now - self.last_byte > SILENCE_S:
                raise Broken(f"nothing from the caster for {SILENCE_S:g} s") from None
            return b""
        except OSError as e:
            raise Broken(f"the caster connection failed: {e.strerror or e}") from None
        if not data:
            raise Broken("the caster closed the connection")
        self.last_byte = now
        payload = self.response.feed(data)
        if self.response.kind == "stream":
            self.state = "streaming"
        return payload

    def forward(self, payload: bytes, now: float) -> None:
        """Whole RTCM3 frames of the payload to the device; everything else counted and dropped."""
        self.bytes += len(payload)
        for event in self.parser.feed(payload):
            if isinstance(event, Rtcm):
                self.write(event.data)
                self.frames[event.message_type] = self.frames.get(event.message_type, 0) + 1
                self.last_frame = now
            else:
                self.garbage += len(getattr(event, "data", b""))
        self.garbage += len(self.parser._skip)  # the noise is not kept (bounded memory)
        del self.parser._skip[:]

    def send_gga(self, sentence: str) -> None:
        if self.sock is not None and self.state == "streaming":
            try:
                self.sock.setblocking(True)
                self.sock.settimeout(1.0)
                self.sock.sendall(sentence.encode("ascii"))
            except OSError as e:
                raise Broken(f"cannot send GGA to the caster: {e.strerror or e}") from None
            finally:
                if self.sock is not None:
                    self.sock.setblocking(False)

    def status(self, elapsed: float, now: float, fix: str) -> str:
        frames = " ".join(f"{k}:{v}" for k, v in sorted(self.frames.items())) or "-"
        age = f"{now - self.last_frame:.1f}s" if self.last_frame is not None else "-"
        return (
            f"t={elapsed:.0f}s caster={self.state} bytes={self.bytes} garbage={self.garbage}"
            f" frames={frames} age={age} fix={fix}"
        )


def _sourcetable(client: Client, out: Any, deadline: float, first: bytes) -> int:
    """Print the sourcetable (the lines up to ENDSOURCETABLE or the end of the response);
    `first`: the body bytes that came with the header."""
    assert client.response is not None
    pending = bytearray()
    total = 0
    chunks = [first]
    while True:
        for data in chunks:
            pending += data
            total += len(data)
            if total > SOURCETABLE_MAX:
                raise Broken(f"a sourcetable longer than {SOURCETABLE_MAX} bytes")
            while b"\n" in pending:
                line, _, rest = bytes(pending).partition(b"\n")
                pending = bytearray(rest)
                text = line.rstrip(b"\r").decode("utf-8", "replace")
                if text.strip().upper() == "ENDSOURCETABLE":
                    print(text, file=out, flush=True)
                    return 0
                print(text, file=out, flush=True)
            if len(pending) > LINE_MAX:
                raise Broken(f"a sourcetable line longer than {LINE_MAX} bytes")
        if client.response.ended or time.monotonic() > deadline:
            break
        assert client.sock is not None
        client.sock.setblocking(True)
        client.sock.settimeout(max(0.01, min(SILENCE_S, deadline - time.monotonic())))
        try:
            data = client.sock.recv(READ_MAX)
        except socket.timeout:
            raise Broken(f"nothing from the caster for {SILENCE_S:g} s") from None
        except OSError as e:
            raise Broken(f"the caster connection failed: {e.strerror or e}") from None
        if not data:
            break
        chunks = [client.response.feed(data)]
    if pending:
        print(pending.decode("utf-8", "replace").rstrip("\r"), file=out, flush=True)
    return 0


def _position_format(conn: Any, tools: Any) -> Optional[Tuple[Any, Dict[str, Any], Any, int]]:
    """(setting, its key, the command setting the format at 1 Hz, set) for the model's first data
    set with LLH position and fix information and a message format (None: none); `tools`: the
    command line's helpers (device/cli.py `subcommand_tools`)."""
    from .. import _sim, capabilities, registry
    from . import settings as st

    model = capabilities.MODELS.get(conn.model)
    if model is None:
        return None
    for set_id in sorted({set_ for set_, _ in model.data}):
        names: Dict[str, int] = {}
        for set_, d in model.data:
            if set_ == set_id:
                for cls in registry.lookup(set_, d) or ():
                    names[cls.NAME] = d
        if "llh_position" not in names or "fix_info" not in names:
            continue
        found = tools.format_setting(conn.model, set_id)
        if found is None:
            continue
        s, key = found
        hz = tools.read_base_rates(conn).get(set_id)
        if not hz:
            continue
        decimation = max(1, round(hz))
        spec = _sim.FORMATS[s.cls]
        item = tools.list_item_class(s)
        wanted = [names["llh_position"], names["fix_info"]]
        items = [item(**{spec[2]: d, spec[3]: decimation}) for d in wanted]
        previous = st.read_entry(conn.device, s, key)
        entry = {**key, spec[1]: [json.loads(i.to_json()) for i in items]}
        return s, {"key": key, "previous": previous}, st.command_of(s, {**previous, **entry}), set_id
    return None


def main(args: Any, connect: Callable[[], Any], tools: Any) -> int:
    """The `ntrip` subcommand (device/cli.py): its options checked, then `connect()` (the device's
    Connection; cli's own errors pass through) unless only the sourcetable is asked for; `tools`:
    the command line's helpers (device/cli.py `subcommand_tools`)."""
    try:
        target = parse_url(args.url)
        if args.gga_interval < 0 or not math.isfinite(args.gga_interval):
            raise Usage(f"--gga-interval {args.gga_interval:g}: expected 0 (never) or more seconds")
        if args.duration is not None and not (args.duration > 0 and math.isfinite(args.duration)):
            raise Usage(f"--duration {args.duration:g}: expected a positive number of seconds")
        if args.retries < 0:
            raise Usage(f"--retries {args.retries}: expected 0 or more")
        start = time.monotonic()
        end = start + args.duration if args.duration else math.inf
        if not target.mountpoint:
            client = Client(target, lambda data: None)
            try:
                return _with_retries(
                    client, args.retries, end, lambda first: _sourcetable(client, sys.stdout, end, first)
                )
            finally:
                client.close()
        conn = connect()
        try:
            return run(conn, target, args.gga_interval, end, start, args.retries, tools)
        except (OSError, SessionError) as e:  # the device went away or said no
            raise Refused(f"{conn.address}: {getattr(e, 'strerror', None) or e}") from None
        finally:
            conn.close()
    except Usage as e:
        print(f"{PROG}: ntrip: {e}", file=sys.stderr)
        return 2
    except Refused as e:
        print(f"{PROG}: ntrip: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 0


def run(conn: Any, target: Target, gga_interval: float, end: float, start: float, retries: int, tools: Any) -> int:
    """Stream the mountpoint into the open device (a device/cli.py Connection) until `end`."""
    from . import settings as st

    device = conn.device
    client = Client(target, device.transport.write)
    pos = Position()
    fmt = _position_format(conn, tools)
    if fmt is None:
        _note(f"{conn.model}: no data set with LLH position and fix information: no GGA, no fix type")

    def on_packet(packet: Any) -> None:
        if fmt is None or packet.set != fmt[3]:
            return
        for e in packet.fields:
            value: Any = getattr(e, "value", None)
            name = getattr(value, "NAME", "")
            if name == "llh_position":
                pos.llh = (value.latitude, value.longitude, value.ellipsoid_height, value.msl_height)
            elif name == "fix_info":
                pos.fix = (getattr(value.fix_type, "name", None) or str(int(value.fix_type))).lower()
                pos.sats = int(value.num_sv)

    device.on_packet(on_packet)
    if fmt is not None:
        device.call(fmt[2])
        tools.enable(conn, fmt[3])
    try:
        return _stream(client, device, pos, gga_interval, end, start, retries)
    except KeyboardInterrupt:
        return 0
    finally:
        client.close()
        if fmt is not None:
            try:
                device.call(st.command_of(fmt[0], {**fmt[1]["key"], **fmt[1]["previous"]}))
            except Exception:  # noqa: BLE001 - the device may be gone: say so, keep the status
                _note("could not restore the previous message format")


def _note(text: str) -> None:
    print(f"{PROG}: ntrip: {text}", file=sys.stderr, flush=True)


def _with_retries(client: Client, retries: int, end: float, body: Callable[[bytes], int]) -> int:
    """Connect (retrying with backoff) and run `body` on the first body bytes once the header
    ended (the sourcetable; once it has begun to print, a failure is not retried: exit 1)."""
    first = b""
    while True:
        try:
            client.connect(time.monotonic())
            assert client.sock is not None and client.response is not None
            client.sock.setblocking(True)
            client.sock.settimeout(SILENCE_S)
            while client.response.kind is None:
                data = client.sock.recv(READ_MAX)
                if not data:
                    raise Broken("the caster closed the connection before its response header ended")
                first = client.response.feed(data)
            break
        except (OSError, Broken) as e:
            client.close()
            client.failures += 1
            if client.failures > retries or time.monotonic() >= end:
                raise Refused(
                    f"{getattr(e, 'strerror', None) or e}; gave up after {client.failures} failed attempt(s)"
                ) from None
            wait = _backoff(client.failures)
            _note(f"{getattr(e, 'strerror', None) or e}; retrying in {wait:g} s")
            time.sleep(min(wait, max(0.0, end - time.monotonic())))
    assert client.response is not None
    if client.response.kind == "stream":
        raise Refused("the caster sent a data stream, not its sourcetable")
    try:
        return body(first)
    except (OSError, Broken) as e:
        raise Refused(f"{getattr(e, 'strerror', None) or e}") from None


def _backoff(failures: int) -> float:
    return BACKOFF_S[min(failures, len(BACKOFF_S)) - 1]


def _stream(
    client: Client, device: Any, pos: Position, gga_interval: float, end: float, start: float, retries: int
) -> int:
    next_status = start + 1.0
    next_gga = start
    while True:
        now = time.monotonic()
        if now >= end:
            return 0
        if client.sock is None and now >= client.next_try:
            try:
                client.connect(now)
            except Broken as e:
                _failed(client, e, now, retries)
        if client.sock is not None:
            try:
                for _ in range(READS_PER_PUMP):  # what the caster sent, then the device's turn
                    payload = client.read(now)
                    if not payload and (client.response is None or client.response.kind is None):
                        break
                    if client.response is not None and client.response.kind == "sourcetable":
                        raise Refused(
                            f"the caster has no mountpoint {client.target.mountpoint!r} (it sent its sourcetable)"
                        )
                    if payload:
                        client.forward(payload, now)
                        client.failures = 0
                    elif client.response is not None and client.response.ended:
                        raise Broken("the caster ended the stream")
                    else:
                        break
                if gga_interval and now >= next_gga and client.state == "streaming":
                    if pos.llh is not None and quality(pos.fix):
                        lat, lon, ellipsoid, msl = pos.llh
                        client.send_gga(gga(lat, lon, msl, ellipsoid, quality(pos.fix), pos.sats, time.time()))
                    next_gga = now + gga_interval
            except Broken as e:
                client.close()
                _failed(client, e, now, retries)
        device.pump(PUMP_MS)
        if now >= next_status:
            print(client.status(now - start, now, pos.fix), flush=True)
            next_status += 1.0
            if next_status <= now:
                next_status = now + 1.0


def _failed(client: Client, e: Exception, now: float, retries: int) -> None:
    client.failures += 1
    client.state = "retrying"
    if client.failures > retries:
        raise Refused(f"{e}; gave up after {client.failures} failed attempt(s) in a row")
    wait = _backoff(client.failures)
    _note(f"{e}; retrying in {wait:g} s")
    client.next_try = now + wait
