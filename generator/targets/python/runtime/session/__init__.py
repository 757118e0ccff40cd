"""Command sessions (docs/conformance.md section 8): send commands, match their replies, route data.

`Session` is the sans-I/O core: it never reads a clock or a socket. The caller gives it the
current time in milliseconds with every call and sends the bytes it returns:

    session = Session(device="cv7_ins")
    pending = session.start(threedm.SensorToVehicleEuler(function=FunctionSelector.READ), now_ms)
    transport.write(pending.packet)
    for event in session.feed(received_bytes, now_ms):   # Result | Packet | Skip
        ...
    pending.result            # Result: ack / nack / timeout / invalid / sent / refused

`Device` is the blocking API over a transport (transport.py): `device.run(command)` returns the
Result, `device.call(command)` raises on anything but success, and the typed command API
(`device.threedm.sensor_to_vehicle_euler.read()`, generated into command_api.py) calls it.
Every packet that is not a reply goes to the handlers registered with `on_packet`, `on_field`
and `on_sample`, also while a command is pending.

Getting through (docs/conformance.md section 8, "Getting through"; the facts from `_link`, the
IR's `link`): `device.to_idle()` gets a streaming device to idle (data dropped and counted,
flush and retry), `device.find_baud()` finds the rate a serial device answers at, and a Device
made with `reconnect_ms` reopens a lost port, gets to idle, re-applies the settings written
since connect and resumes. Each step is reported as one `link: ...` line to `log` (default: the
logger "<package>.link" at INFO).
"""

from __future__ import annotations

import logging
import time
from collections import OrderedDict, deque
from typing import TYPE_CHECKING, Any, Callable, Dict, FrozenSet, List, Optional, Tuple, Union

from .. import _link, _sim, capabilities, registry
from .. import _session as _meta
from ..codec.canonical import error_text, loads
from ..codec.framing import (
    CHECKSUM_SIZE,
    HEADER_SIZE,
    LENGTH_OFFSET,
    MAX_PAYLOAD,
    SYNC,
    Nmea,
    PacketBuilder,
    Parser,
    RawPacket,
    Rtcm,
    Skip,
)
from ..codec.framing import (
    checksum_ok as _checksum_ok,
)
from ..codec.framing import (
    speedups as _speedups,
)
from ..codec.layout import Field
from ..codec.packets import DecodedField, Decoder, Entry, Packet, RawField, Trailing, decode_packet
from ..codec.samples import Sample, SampleGrouper
from ..logs.identity import model_matches as model_matches  # (re-exported: the device CLI)
from ..logs.timebase import SplitClock, Times
from .clock import ClockModel, reference_ns
from .transport import TransportError

DEFAULT_TIMEOUT_MS = 1000  # the reply timeout of a command (plus the spec's allowance)
DEFAULT_INTER_PACKET_TIMEOUT_MS = 100  # a wait longer than this looks ahead for a complete packet (section 8)
MAX_PENDING = 8  # commands waiting for their reply at once (the C core's fixed queue)
SKIP_PIECE = 65536  # a pending skip run is reported when it reaches this many bytes (section 8)
READ_MAX = 65536  # every read from the transport asks for at most this many bytes (section 8)
FEED_SLICE = 4096  # Device feeds a read in slices of this many bytes, each at the current time

ACK = "ack"
NACK = "nack"
TIMEOUT = "timeout"
INVALID = "invalid"
SENT = "sent"
REFUSED = "refused"
LOST = "lost"  # the port went away while the command waited for its reply

IDLE_QUIET_MS = 50  # after a flush, received bytes are read and dropped this long before a retry
RECONNECT_EVERY_MS = 500  # a lost port is reopened this often
DEFAULT_RECONNECT_MS = 10000  # ... until this long after the loss
MAX_SETTINGS = 64  # settings recorded for re-applying after a reconnect (the oldest forgotten)


class SessionError(Exception):
    """Base of the errors the blocking API raises."""


class CommandRefused(SessionError, ValueError):
    """The command (or its function) is not supported by the selected device model; nothing was sent."""

    def __init__(self, result: Result) -> None:
        super().__init__(result.error)
        self.result = result


class CommandFailed(SessionError):
    """A command did not succeed; `result` holds what happened."""

    def __init__(self, result: Result) -> None:
        super().__init__(result.describe())
        self.result = result


class Nack(CommandFailed):
    """The device answered with a NACK; `code` is the typed error code."""

    @property
    def code(self) -> Any:
        return self.result.code


class CommandTimeout(CommandFailed):
    """No reply came before the command's deadline."""


class InvalidReply(CommandFailed):
    """The device acknowledged, but the reply fields do not decode (or the expected one is missing)."""


class LinkLost(CommandFailed):
    """The port went away while the command waited for its reply; it is not retried."""


class LinkError(SessionError):
    """Getting through failed: no ACK to the idle command, no baud rate answers, or the lost port
    did not come back in time."""


class Result:
    """The one result of a command.

    `status`: "ack", "nack", "timeout", "invalid" (acknowledged, but a reply field does not decode
    or the expected reply field is missing; `error` says which), "sent" (the command suppresses its
    ack: it completes when sent) or "refused" (not sent: the selected device does not support it;
    `error` says why). `code` is the ack/nack code (an IntEnum member when the spec names it) or
    None; `reply` the field entries of the reply packet that follow the ack (DecodedField,
    RawField, Trailing).
    """

    __slots__ = ("command", "status", "code", "reply", "error", "expect", "tag", "note")

    def __init__(
        self,
        command: Field,
        status: str,
        code: Any = None,
        reply: Optional[List[Entry]] = None,
        error: Optional[str] = None,
        expect: Tuple[int, ...] = (),
    ) -> None:
        self.command = command
        self.status = status
        self.code = code
        self.reply: List[Entry] = reply if reply is not None else []
        self.error = error
        self.expect = expect
        self.tag: Any = None  # the tag given to Session.start
        # Why a NACK may have come (Device: the connected model is not the one the session was told)
        self.note: Optional[str] = None

    @property
    def ok(self) -> bool:
        """True for "ack" and "sent"."""
        return self.status in (ACK, SENT)

    @property
    def response(self) -> Any:
        """The typed value of the command's reply field (the first decoded field of the reply whose
        descriptor the command expects, else the first decoded field), or None."""
        decoded = [e for e in self.reply if isinstance(e, DecodedField)]
        for e in decoded:
            if e.descriptor in self.expect:
                return e.value
        return decoded[0].value if decoded else None

    def describe(self) -> str:
        name = self.command.NAME
        if self.status == NACK:
            code = getattr(self.code, "name", None)
            text = f" ({code.lower()})" if code else ""
            note = f": {self.note}" if self.note else ""
            return f"{name}: NACK, code {int(self.code)}{text}{note}"
        if self.status == TIMEOUT:
            return f"{name}: no reply before the timeout"
        if self.status in (INVALID, REFUSED, LOST):
            return f"{name}: {self.error}"
        return f"{name}: {self.status}"

    def raise_for_status(self) -> Result:
        """Returns self when ok; raises CommandRefused, Nack, CommandTimeout or InvalidReply."""
        if self.status == REFUSED:
            raise CommandRefused(self)
        if self.status == NACK:
            raise Nack(self)
        if self.status == TIMEOUT:
            raise CommandTimeout(self)
        if self.status == INVALID:
            raise InvalidReply(self)
        if self.status == LOST:
            raise LinkLost(self)
        return self

    def line(self, number: int) -> str:
        """The conformance tool's line for input line `number` (docs/conformance.md section 8)."""
        code = "null" if self.code is None else str(int(self.code))
        text = (
            '{"line":'
            + str(number)
            + ',"result":"'
            + self.status
            + '","code":'
            + code
            + ',"reply":['
            + ",".join(e.line() for e in self.reply)
            + "]"
        )
        if self.error is not None:
            text += ',"error":' + error_text(self.error)
        return text + "}"

    def __repr__(self) -> str:
        return f"Result({self.command.NAME}, {self.status}, code={self.code!r}, reply={self.reply!r})"


class Pending:
    """A started command: the bytes to send (`packet`, empty when nothing is to be sent), its
    deadline and, once complete, its `result`."""

    __slots__ = ("command", "set", "descriptor", "packet", "deadline", "expect", "result", "tag")

    def __init__(self, command: Field, packet: bytes, deadline: int, expect: Tuple[int, ...], tag: Any) -> None:
        self.command = command
        self.set = command.SET
        self.descriptor = command.DESCRIPTOR
        self.packet = packet
        self.deadline = deadline
        self.expect = expect
        self.result: Optional[Result] = None
        self.tag = tag

    @property
    def done(self) -> bool:
        return self.result is not None


# ----------------------------------------------------------------------------- command facts
class CommandInfo:
    """What the spec says about one command layout (generated into _session.py)."""

    __slots__ = ("cls", "device", "devices", "functions", "responses", "ack", "timeout")

    def __init__(self, cls: Any, device: Any, devices: Any, functions: Any, responses: Any, ack: Any, timeout: Any):
        self.cls = cls
        self.device = device
        self.devices = devices
        self.functions = functions
        self.responses = responses
        self.ack = ack
        self.timeout = timeout


_INFO: Dict[Any, CommandInfo] = {}
for _key, _layouts in _meta.COMMANDS.items():
    for _row in _layouts:
        _INFO[_row[0]] = CommandInfo(*_row)


def command_info(command: Field) -> Optional[CommandInfo]:
    """The spec facts of a command value's layout, or None when it is not a command."""
    return _INFO.get(type(command))


def _function(command: Field) -> Optional[int]:
    f = getattr(command, "function", None)
    return None if f is None else int(f)


def support_error(command: Field, device: str) -> Optional[str]:
    """Why `device` does not support the command as given (None when it does)."""
    info = command_info(command)
    name = command.NAME
    if command.SET is None or not capabilities.supports(device, command.SET, command.DESCRIPTOR):
        return f"{name} is not supported by {capabilities.describe(device)}"
    if info is not None and info.device is not None and info.device != device:
        return f"{name}: this layout is for {info.device}, not {device}"
    fn = _function(command)
    if info is not None and info.functions is not None and fn is not None:
        limited = _meta.FUNCTION_DEVICES.get(fn)
        if fn not in info.functions or (limited is not None and device not in limited):
            return f"function {_meta.function_name(fn)} of {name} is not supported by {capabilities.describe(device)}"
    return None


def ack_suppressed(command: Field, info: Optional[CommandInfo] = None) -> bool:
    """True when the command as given asks the device not to reply (spec `ack_suppressed_by`)."""
    info = info or command_info(command)
    if info is None or info.ack is None:
        return False
    if info.ack[0] == "function":
        return bool(_function(command) == info.ack[1])
    value = getattr(command, info.ack[1], None)
    if value is None:
        return False
    return bool(int(value) != 0) if info.ack[2] is None else bool(int(value) == info.ack[2])


def allowance_ms(command: Field, info: Optional[CommandInfo] = None) -> int:
    """The extra reply time the spec gives the command as given (spec `timeout`)."""
    info = info or command_info(command)
    if info is None or info.timeout is None:
        return 0
    ms, param, functions = info.timeout
    if functions is not None and _function(command) not in functions:
        return 0
    if param is not None:
        ms += int(getattr(command, param, 0) or 0)
    return int(ms)


def expected_replies(command: Field, info: Optional[CommandInfo] = None) -> Tuple[int, ...]:
    """The reply field descriptors the command as given expects with its ack (spec `responses`)."""
    info = info or command_info(command)
    if info is None:
        return ()
    out = []
    fn = _function(command)
    for rid, when_fn, when_param, when_value in info.responses:
        if when_fn is not None and fn != when_fn:
            continue
        if when_param is not None:
            v = getattr(command, when_param, None)
            if v is None or (int(v) != when_value if when_value is not None else int(v) == 0):
                continue
        out.append(rid)
    return tuple(out)


def command_from_line(text: str) -> Field:
    """The command of one input line of the conformance tool: a canonical packet line (what
    `encode` accepts) with exactly one decoded command field. Raises ValueError naming the problem."""
    from ..codec.layout import EncodeError
    from ..codec.packets import encode_line

    try:
        encode_line(text)  # every rule of the encoder's input (section 5)
    except EncodeError as e:
        raise ValueError(str(e)) from None
    obj = loads(text)
    if "fields" not in obj:
        raise ValueError("expected a packet line with one command field, not a skip run")
    fields = obj["fields"]
    if len(fields) != 1:
        raise ValueError(f"expected exactly one command field, got {len(fields)}")
    f = fields[0]
    if "values" not in f:
        raise ValueError("expected a decoded command field (descriptor, name, values), not a raw field")
    classes = registry.lookup(obj["set"], f["descriptor"]) or ()
    if "device" in f:
        classes = tuple(c for c in classes if c.DEVICE == f["device"])
    if not classes or classes[0].ROLE != "command":
        raise ValueError(f"{f['name']} (set {obj['set']}, descriptor {f['descriptor']}) is not a command")
    return classes[0].from_json(f["values"], "values.")


# ----------------------------------------------------------------------------- session parser
class TimedParser(Decoder):
    """The stream parser of section 1 with the session rules of section 8.

    The look-ahead rule: while the parser has been waiting at the same position `i` (a partial
    sync, header or packet) since `s`, and `now - s > inter_packet_timeout_ms`, the first position
    `j > i` of the buffered bytes where a sync starts a complete packet with a valid checksum (the
    section 1 check) ends the wait: the bytes `i..j-1` are skipped and parsing resumes at `j`.
    Without such a `j` nothing is dropped (a slow packet is never thrown away by time). The rule
    runs at every `feed_at(data, now)`: on the bytes already buffered *before* it adds `data`, and
    again after, when the parser still waits where it waited since an expired `s` (so the events do
    not depend on whether the caller polled in between). A position the parser starts waiting at
    waits from `now`.

    Skip pieces: a skip run is reported when it ends or as soon as its pending length reaches
    SKIP_PIECE bytes (then a run of exactly SKIP_PIECE bytes; the next begins after it).

    Bounded memory: between calls the parser holds at most framing.MAX_PACKET undecided bytes
    (the candidate it waits at: a longer candidate is decided by section 1) plus the pending skip
    run (< SKIP_PIECE bytes), whatever arrives; within a call, one feed's bytes on top."""

    def __init__(
        self, inter_packet_timeout_ms: int = DEFAULT_INTER_PACKET_TIMEOUT_MS, device: Optional[str] = None
    ) -> None:
        super().__init__(device)
        self.raw = False  # True: RawPacket events (as Parser), else decoded Packets (as Decoder)
        self.inter_packet_timeout_ms = inter_packet_timeout_ms
        self._wait_at = -1
        self._wait_since = 0
        self._last_now: Optional[int] = None
        self._mask_sets: FrozenSet[int] = frozenset()
        self._mask = bytes(256)
        self._hits: List[int] = []
        self._packets = 0
        self._watching: Optional[bytes] = None

    def feed_at(self, data: Any, now_ms: int) -> List[Any]:
        """Consume bytes received at `now_ms` (may be empty: only the look-ahead rule runs)."""
        return self.feed_watch(data, now_ms, frozenset())[0]

    def feed_watch(self, data: Any, now_ms: int, sets: FrozenSet[int]) -> Tuple[List[Any], List[int], bool]:
        """`feed_at`, and for the session: the indexes in the events of the packets whose set is
        in `sets` (the sets of its pending commands), and True when no Skip is among the events
        (False: there may be). With the C accelerator the parser reports both while it decodes;
        no Python code looks at each packet."""
        buf = self._buf
        self._hits = []
        self._packets = 0
        self._watching = self._watch_mask(sets) if _speedups is not None and self.device is None else None
        self._last_now = now_ms
        events: List[Any] = []
        events += self._look_ahead(now_ms, 0)  # (a): on the old buffer
        if data:
            buf += data
            events += self._scan_at(len(events))
            self._waiting(now_ms)
            events += self._look_ahead(now_ms, len(events))  # (b): after the new bytes
        self._waiting(now_ms)
        events = self._pieces(events)
        if self._watching is None:
            if sets:
                self._hits = [i for i, e in enumerate(events) if not isinstance(e, _NOT_PACKETS) and e.set in sets]
            return events, self._hits, False
        return events, self._hits, self._packets == len(events)

    def _waiting(self, now_ms: int) -> None:
        """The position the parser waits at (the start of the buffer), from `now` when new."""
        if not self._buf:
            self._wait_at = -1
        elif self._wait_at != self._base:
            self._wait_at, self._wait_since = self._base, now_ms

    def _look_ahead(self, now_ms: int, first: int) -> List[Any]:
        """The look-ahead rule at `now_ms`, repeated while it finds a packet (after a jump the
        parser waits at a new position, from now: not expired in the same call)."""
        events: List[Any] = []
        while self._buf and self._wait_at == self._base and now_ms - self._wait_since > self.inter_packet_timeout_ms:
            j = self._complete_packet_after_start()
            if j is None:
                break
            self._skipped(0, j)
            del self._buf[:j]
            self._base += j
            events += self._scan_at(first + len(events))
            self._waiting(now_ms)
        return events

    def _complete_packet_after_start(self) -> Optional[int]:
        """The first position j > 0 of the buffer where a complete packet with a valid checksum
        starts (the section 1 check), or None. The buffer then holds less than one packet after
        its start (a longer candidate is decided by the parser), so this looks at < MAX_PACKET bytes."""
        buf = self._buf
        n = len(buf)
        j = buf.find(SYNC, 1)
        while 0 < j <= n - HEADER_SIZE:
            length = buf[j + LENGTH_OFFSET]
            if length <= MAX_PAYLOAD:
                body = HEADER_SIZE + length
                if n - j >= body + CHECKSUM_SIZE and _checksum_ok(buf, j, body):
                    return j
            j = buf.find(SYNC, j + 1)
        return None

    def _pieces(self, events: List[Any]) -> List[Any]:
        """The skip-piece rule: every Skip event longer than SKIP_PIECE bytes is reported as its
        pieces, and a pending run that reached SKIP_PIECE bytes is reported in pieces now (the
        rest stays pending). The indexes of the watched packets follow."""
        if any(type(e) is Skip and len(e.data) > SKIP_PIECE for e in events):
            out: List[Any] = []
            moved: Dict[int, int] = {}
            for i, e in enumerate(events):
                if type(e) is Skip and len(e.data) > SKIP_PIECE:
                    out += _split_skip(e.offset, e.data)
                else:
                    moved[i] = len(out)
                    out.append(e)
            self._hits = [moved[i] for i in self._hits]
            events = out
        skip = self._skip
        if len(skip) >= SKIP_PIECE:
            whole = len(skip) - len(skip) % SKIP_PIECE
            events += _split_skip(self._skip_at, skip[:whole])
            del skip[:whole]
            self._skip_at += whole
        return events

    def flush(self) -> List[Any]:
        """End of input (section 1), the skip run in pieces."""
        return [p for e in super().flush() for p in (_split_skip(e.offset, e.data) if type(e) is Skip else (e,))]

    def _watch_mask(self, sets: FrozenSet[int]) -> bytes:
        if sets != self._mask_sets:
            self._mask_sets = sets
            self._mask = bytes(1 if b in sets else 0 for b in range(256))
        return self._mask

    def _scan_at(self, first: int) -> List[Any]:
        """_scan; with the accelerator watching, the hits (indexes from `first`) and packets counted."""
        if self._watching is None:
            return self._scan(final=False)
        events: List[Any]
        events, pos, self._skip_at, hits, packets = _speedups.scan(
            self._buf, self._base, self._skip, self._skip_at, False, not self.raw, self._watching
        )
        del self._buf[:pos]
        self._base += pos
        self._hits += [first + i for i in hits] if first else hits
        self._packets += packets
        return events

    def _scan(self, final: bool) -> List[Any]:
        return Parser._scan(self, final) if self.raw else Decoder._scan(self, final)

    @property
    def wait_deadline(self) -> Optional[int]:
        """When the look-ahead rule next has something to check (`s + P + 1`, while the parser
        waits and the wait had not expired at the last call), or None."""
        if not self._buf or self._wait_at != self._base:
            return None
        due = self._wait_since + self.inter_packet_timeout_ms + 1
        if self._last_now is not None and self._last_now >= due:
            return None  # expired: only new bytes can change anything (the next feed checks)
        return due


def _split_skip(offset: int, data: Any) -> List[Skip]:
    """A skip run as its pieces of SKIP_PIECE bytes (the last one shorter)."""
    return [Skip(offset + k, bytes(data[k : k + SKIP_PIECE])) for k in range(0, len(data), SKIP_PIECE)]


# ----------------------------------------------------------------------------- the core
Event = Union[Result, Packet, Skip, Nmea, Rtcm]
# Events that are not packets: skip runs, and the NMEA sentences and RTCM3 frames between packets
# (section 1), which go to the on_foreign handlers.
_NOT_PACKETS = (Skip, Nmea, Rtcm)
_FOREIGN = (Nmea, Rtcm)


def check_device_name(device: Optional[str]) -> None:
    """Raises ValueError unless `device` is None or one of registry.DEVICES."""
    if device is not None and device not in registry.DEVICES:
        raise ValueError(f"unknown device {device!r} (one of: {', '.join(registry.DEVICES)})")


class Session:
    """The sans-I/O session core (docs/conformance.md section 8).

    `device`: the device model (one of registry.DEVICES) whose layouts decode replies and data and
    whose support `start` checks (unless `check_device=False`). `timeout_ms`: the reply timeout
    of every command (plus the spec's allowance for long commands). At most `max_pending`
    commands wait for their replies at once.

    Replies are recognised by content (the look-ahead rule of TimedParser), never dropped for
    arriving slowly. Bounded memory, whatever the device sends: between calls the session holds
    at most framing.MAX_PACKET bytes of undecided input plus the pending skip run (< SKIP_PIECE
    bytes; longer runs are reported in pieces of SKIP_PIECE bytes as they arrive), and each call
    returns the events of its own bytes only. A command's `timeout` comes from the first
    `feed`/`poll` at or after its deadline.
    """

    def __init__(
        self,
        device: Optional[str] = None,
        timeout_ms: int = DEFAULT_TIMEOUT_MS,
        inter_packet_timeout_ms: int = DEFAULT_INTER_PACKET_TIMEOUT_MS,
        max_pending: int = MAX_PENDING,
        check_device: bool = True,
    ) -> None:
        check_device_name(device)
        if timeout_ms < 0 or inter_packet_timeout_ms < 0 or max_pending < 1:
            raise ValueError("timeouts must be >= 0 and max_pending >= 1")
        self.device = device
        self.timeout_ms = timeout_ms
        self.max_pending = max_pending
        self.check_device = check_device
        self._parser = TimedParser(inter_packet_timeout_ms, device)
        self._pending: List[Pending] = []
        self._sets: FrozenSet[int] = frozenset()  # the sets of the pending commands (replies come in them)
        self._packet_handlers: List[Callable[[Packet], Any]] = []
        self._field_handlers: Dict[Tuple[int, int], List[Callable[[Any, Packet], Any]]] = {}
        self._sample_handlers: List[Callable[[Sample], Any]] = []
        self._foreign_handlers: List[Callable[[Union[Nmea, Rtcm]], Any]] = []
        self._grouper: Optional[SampleGrouper] = None
        # The time model (timebase; docs/log-to-csv.md "Time"), from its first use on fed every
        # packet that is not a reply: the live clock map (anchors so far, resets, leap seconds).
        self._clock: Optional[SplitClock] = None
        self._timed: Dict[int, Times] = {}  # offset -> times of the packets of the last feed
        self._timed_to = -1  # the offset of the last packet fed to the time model
        # The host clock model (clock.py, docs/time.md), from its first use on fed every packet
        # that is not a reply and carries the device's reference time, at the feed's host time.
        self._host: Optional[ClockModel] = None
        self._host_times: Dict[int, Optional[int]] = {}  # offset -> host ns, packets of the last feed
        self._now_ns = 0

    # -------------------------------------------------------------- handlers
    def on_packet(self, handler: Callable[[Packet], Any]) -> None:
        """Call handler(packet) for every decoded packet that is not a reply."""
        self._packet_handlers.append(handler)

    def on_field(self, set_id: int, descriptor: int, handler: Callable[[Any, Packet], Any]) -> None:
        """Call handler(value, packet) for every decoded field (set, descriptor) of a packet that is not a reply."""
        self._field_handlers.setdefault((set_id, descriptor), []).append(handler)

    def on_foreign(self, handler: Callable[[Union[Nmea, Rtcm]], Any]) -> None:
        """Call handler(frame) for every NMEA sentence (Nmea) and RTCM3 frame (Rtcm) between the
        packets, in stream order with the packet handlers (section 1; none: they are only events)."""
        self._foreign_handlers.append(handler)

    def on_sample(self, handler: Callable[[Sample], Any]) -> None:
        """Call handler(sample) for every complete sample of data packets (section 6 grouping)."""
        if self._grouper is None:
            self._grouper = SampleGrouper(self.device)
            self._parser.raw = True  # the grouper reads the packets' bytes
        self._sample_handlers.append(handler)

    # -------------------------------------------------------------- time
    @property
    def time(self) -> SplitClock:
        """The live time model (`timebase.SplitClock`: the latest anchor, the device clock's epoch,
        the device's leap seconds). Its first use starts it: from then on every packet that is not
        a reply feeds it."""
        if self._clock is None:
            self._clock = SplitClock()
        return self._clock

    def _step(self, packet: Packet) -> Times:
        t = self.time.times(packet)
        self._timed[packet.offset] = t
        self._timed_to = packet.offset
        return t

    def times(self, packet: Packet) -> Times:
        """The times of a data packet (`timebase.Times`: UTC `t_ns`, and the device's own
        `device_ns`, `gps_week`, `gps_tow`) by the log's rule with what the session has seen so
        far: a packet after the last one fed to the time model feeds it (as every packet does once
        the model has started, `time`); a packet of the last `feed`/`poll`/`close` gets the times
        it got then; an earlier one is timed against the current state without changing it. Live, nothing comes from later packets: until the device has sent a packet
        with both a valid GPS time and the reference timestamp (an anchor), and after a reset
        until the next anchor, packets with only the device clock have no UTC time."""
        t = self._timed.get(packet.offset)
        if t is not None:
            return t
        if packet.offset > self._timed_to:
            return self._step(packet)
        return self.time.peek(packet)

    def utc_ns(self, packet: Packet) -> Optional[int]:
        """UTC ns since the Unix epoch of a data packet (None when unknown); see `times`."""
        return self.times(packet).t_ns

    # -------------------------------------------------------------- host clock
    @property
    def host_clock(self) -> ClockModel:
        """The host clock model (`clock.ClockModel`: offset, drift_ppm, bound_ns, restarts of the
        device's reference clock against the host clock of `feed`'s now_ns). Its first use starts
        it: from then on every packet that is not a reply and carries the device's reference time
        (the spec's `time.reference_time`) feeds it."""
        if self._host is None:
            self._host = ClockModel()
        return self._host

    def host_ns(self, packet: Packet) -> Optional[int]:
        """The host time (ns, the clock of `feed`'s now_ns) of a data packet: by the model's
        estimate when it was fed (a packet of the last feed), else by the current one; None
        before an estimate or without the reference time."""
        if packet.offset in self._host_times:
            return self._host_times[packet.offset]
        d = reference_ns(packet, self.device)
        return None if d is None else self.host_clock.host_time(d)

    # -------------------------------------------------------------- commands
    @property
    def pending(self) -> List[Pending]:
        """The commands waiting for their replies, oldest first."""
        return list(self._pending)

    def next_deadline(self) -> Optional[int]:
        """The earliest time at which `poll` has something to do (a timeout or the look-ahead rule)."""
        times = [p.deadline for p in self._pending]
        w = self._parser.wait_deadline
        if w is not None:
            times.append(w)
        return min(times) if times else None

    def start(
        self,
        command: Field,
        now_ms: int,
        timeout_ms: Optional[int] = None,
        check_device: Optional[bool] = None,
        tag: Any = None,
    ) -> Pending:
        """Start a command at `now_ms`: returns the Pending whose `packet` the caller sends. A
        refused command (`packet` empty) and one whose ack it suppresses complete at once."""
        info = command_info(command)
        if info is None or getattr(command, "ROLE", None) != "command":
            raise TypeError(f"not a command: {command!r}")
        check = self.check_device if check_device is None else check_device
        base = self.timeout_ms if timeout_ms is None else timeout_ms
        expect = expected_replies(command, info)
        if check and self.device is not None:
            why = support_error(command, self.device)
            if why is not None:
                p = Pending(command, b"", now_ms, expect, tag)
                p.result = _tagged(Result(command, REFUSED, error=why, expect=expect), tag)
                return p
        if command.SET is None:
            raise TypeError(f"{command.NAME} is not a command of a descriptor set")
        packet = PacketBuilder(command.SET).add(command).build()
        p = Pending(command, packet, now_ms + base + allowance_ms(command, info), expect, tag)
        if ack_suppressed(command, info):
            p.result = _tagged(Result(command, SENT, expect=expect), tag)
            return p
        if len(self._pending) >= self.max_pending:
            p.packet = b""
            p.result = _tagged(
                Result(command, REFUSED, error=f"{self.max_pending} commands already pending", expect=expect), tag
            )
            return p
        self._pending.append(p)
        self._pending_changed()
        return p

    def _pending_changed(self) -> None:
        self._sets = frozenset(p.set for p in self._pending if p.set is not None)

    # -------------------------------------------------------------- input
    def feed(self, data: Any, now_ms: int, now_ns: Optional[int] = None) -> List[Event]:
        """Bytes received at `now_ms`: returns the events in order (Results of commands that
        completed, Packets that are not replies, Skip runs) after calling the handlers. `now_ns`:
        the host time the bytes were read (ns, a monotonic clock; default now_ms), for the host
        clock model."""
        events: List[Event] = self._expire(now_ms) if self._pending else []
        if self._timed:
            self._timed = {}  # (the times of the last call's packets only: bounded memory)
        if self._host_times:
            self._host_times = {}
        self._now_ns = now_ms * 1_000_000 if now_ns is None else now_ns
        parsed, hits, clean = self._parser.feed_watch(data, now_ms, self._sets)
        if not parsed:
            return events
        if self._parser.raw:
            self._route(parsed, events)
            return events
        # Only a packet of a set with a pending command can be a reply (the parser lists them):
        # the runs of events between those are not replies and are handled without a look.
        if not hits:
            if events:
                events += parsed
            else:
                events = parsed
            if (
                self._packet_handlers
                or self._field_handlers
                or self._clock is not None
                or self._host is not None
                or self._foreign_handlers
            ):
                self._deliver(parsed, clean)
            return events
        at = 0
        for i in hits:
            self._plain(parsed, at, i, events)
            self._event(parsed[i], events)
            at = i + 1
        self._plain(parsed, at, len(parsed), events)
        return events

    def _plain(self, parsed: List[Any], a: int, b: int, events: List[Event]) -> None:
        """Events parsed[a:b], none of which is a reply: added to `events`, handlers called."""
        if a < b:
            run = parsed[a:b]
            events += run
            if (
                self._packet_handlers
                or self._field_handlers
                or self._grouper is not None
                or self._clock is not None
                or self._host is not None
                or self._foreign_handlers
            ):
                self._deliver(run, False)

    def poll(self, now_ms: int) -> List[Event]:
        """Nothing received: runs the timeouts and the look-ahead rule at `now_ms`."""
        return self.feed(b"", now_ms)

    def close(self, now_ms: int) -> List[Event]:
        """End of input: what `poll` does, then every buffered byte that is not a complete packet
        is skipped (as at the end of a stream, section 1); pending commands stay pending."""
        events = self.poll(now_ms)
        self._route(self._parser.flush(), events)
        if self._grouper is not None:
            for s in self._grouper.flush():
                for h in self._sample_handlers:
                    h(s)
        return events

    def reset_input(self) -> int:
        """Drop every buffered byte that is not a complete packet (a flush: nothing is reported,
        the stream offsets go on); returns how many."""
        return sum(len(e.data) for e in self._parser.flush() if isinstance(e, Skip))

    def lose_pending(self, reason: str) -> List[Event]:
        """The port went away: every pending command completes with "lost"."""
        out: List[Event] = []
        for p in self._pending:
            p.result = _tagged(Result(p.command, LOST, error=f"link lost: {reason}", expect=p.expect), p.tag)
            out.append(p.result)
        self._pending = []
        self._pending_changed()
        return out

    def _expire(self, now_ms: int) -> List[Event]:
        out: List[Event] = []
        keep = []
        for p in self._pending:
            if now_ms >= p.deadline:
                p.result = _tagged(Result(p.command, TIMEOUT, expect=p.expect), p.tag)
                out.append(p.result)
            else:
                keep.append(p)
        if out:
            self._pending = keep
            self._pending_changed()
        return out

    def _deliver(self, parsed: List[Any], clean: bool) -> None:
        """Calls the handlers for events none of which is a reply (packet by packet, each packet's
        handlers in the order of section 8; one packet handler alone: a loop in C). `clean`: no
        Skip is among them."""
        if (
            len(self._packet_handlers) == 1
            and not self._field_handlers
            and self._grouper is None
            and self._clock is None
            and self._host is None
            and not self._foreign_handlers
        ):
            if not clean:
                packet_type = Packet
                parsed = [e for e in parsed if type(e) is packet_type]
            deque(map(self._packet_handlers[0], parsed), 0)
            return
        if (
            self._grouper is None
            and not self._packet_handlers
            and self._clock is None
            and self._host is None
            and not self._foreign_handlers
        ):
            # Field handlers only: a look at the packets of the sets they are for.
            handlers = self._field_handlers
            sets = {k[0] for k in handlers}
            for e in parsed:
                if isinstance(e, _NOT_PACKETS) or e.set not in sets:
                    continue
                for f in e.fields:
                    if isinstance(f, DecodedField):
                        for on_field in handlers.get((e.set, f.descriptor), ()):
                            on_field(f.value, e)
            return
        for e in parsed:
            if isinstance(e, _FOREIGN):
                for on_foreign in self._foreign_handlers:
                    on_foreign(e)
            elif not isinstance(e, Skip):
                self._data(e)

    def _route(self, parsed: List[Any], events: List[Event]) -> None:
        if (
            self._packet_handlers
            or self._field_handlers
            or self._grouper is not None
            or self._clock is not None
            or self._host is not None
            or self._foreign_handlers
        ):
            for e in parsed:
                self._event(e, events)
            return
        # No handlers (the common case of a caller reading the events): only packets of a set
        # with a pending command need a look.
        sets = self._sets
        for e in parsed:
            if isinstance(e, _NOT_PACKETS) or e.set not in sets:
                events.append(e)
            else:
                self._event(e, events)

    def _event(self, e: Any, events: List[Event]) -> None:
        if isinstance(e, _NOT_PACKETS):
            events.append(e)
            if isinstance(e, _FOREIGN):
                for on_foreign in self._foreign_handlers:
                    on_foreign(e)
            return
        raw: Optional[RawPacket] = None
        if isinstance(e, RawPacket):
            raw = e
            packet = decode_packet(raw.data, raw.offset, self.device)
        else:
            packet = e
        if packet.set in self._sets:
            results = self._match(packet)
            if results:
                events.extend(results)
                return
        events.append(packet)
        self._data(packet, raw)

    def _data(self, packet: Any, raw: Optional[RawPacket] = None) -> None:
        """The handlers of one packet that is not a reply (raw: its RawPacket event, when parsed raw)."""
        if type(packet) is RawPacket:
            raw = packet
            packet = decode_packet(raw.data, raw.offset, self.device)
        if self._clock is not None:
            self._step(packet)
        if self._host is not None:
            d = reference_ns(packet, self.device)
            if d is not None:
                self._host_times[packet.offset] = self._host.add(d, self._now_ns)
        for on_packet in self._packet_handlers:
            on_packet(packet)
        if self._field_handlers:
            for f in packet.fields:
                if isinstance(f, DecodedField):
                    for on_field in self._field_handlers.get((packet.set, f.descriptor), ()):
                        on_field(f.value, packet)
        if self._grouper is not None and raw is not None:
            for s in self._grouper.feed(raw.data, raw.offset):
                for on_sample in self._sample_handlers:
                    on_sample(s)

    def _match(self, packet: Packet) -> List[Result]:
        """Results of the pending commands this packet answers (none: it is not a reply)."""
        fields = packet.fields
        acks = [
            i
            for i, f in enumerate(fields)
            if isinstance(f, DecodedField) and f.descriptor == _meta.ACK_DESCRIPTOR and f.value.ROLE == "ack"
        ]
        results: List[Result] = []
        for n, i in enumerate(acks):
            first = fields[i]
            assert isinstance(first, DecodedField)  # acks holds the indexes of decoded ack fields
            ack = first.value
            echo = int(getattr(ack, _meta.ACK_ECHO))
            p = next((q for q in self._pending if q.set == packet.set and q.descriptor == echo), None)
            if p is None:
                continue
            end = acks[n + 1] if n + 1 < len(acks) else len(fields)
            # A raw ack-descriptor field also ends the reply of the ack before it.
            for j in range(i + 1, end):
                later = fields[j]
                if isinstance(later, RawField) and later.descriptor == _meta.ACK_DESCRIPTOR:
                    end = j
                    break
            self._pending.remove(p)
            self._pending_changed()
            p.result = _tagged(_complete(p, getattr(ack, _meta.ACK_CODE), list(fields[i + 1 : end])), p.tag)
            results.append(p.result)
        return results


def _tagged(result: Result, tag: Any) -> Result:
    result.tag = tag
    return result


def _complete(p: Pending, code: Any, reply: List[Entry]) -> Result:
    if int(code) != _meta.ACK_OK:
        return Result(p.command, NACK, code, reply, expect=p.expect)
    for e in reply:
        if isinstance(e, (RawField, Trailing)):
            return Result(p.command, INVALID, code, reply, error=e.error, expect=p.expect)
    if p.expect and not any(isinstance(e, DecodedField) and e.descriptor in p.expect for e in reply):
        return Result(p.command, INVALID, code, reply, error=f"missing reply field {p.expect[0]}", expect=p.expect)
    return Result(p.command, ACK, code, reply, expect=p.expect)


# ----------------------------------------------------------------------------- blocking API
if TYPE_CHECKING:
    # The typed command API's attributes (device.base, ...), which command_api.bind sets at run time.
    from ..command_api import DeviceCommands as _CommandSets
else:
    _CommandSets = object


class Device(_CommandSets):
    """A session over a transport (transport.py), blocking: `run` sends a command and waits for
    its result, feeding every received byte to the session, so data packets reach the handlers
    meanwhile. The typed command API is bound as attributes (`device.base.ping()`)."""

    def __init__(
        self,
        transport: Any,
        device: Optional[str] = None,
        timeout_ms: int = DEFAULT_TIMEOUT_MS,
        inter_packet_timeout_ms: int = DEFAULT_INTER_PACKET_TIMEOUT_MS,
        check_device: bool = True,
        clock: Callable[[], float] = time.monotonic,
        on_event: Optional[Callable[[Event], Any]] = None,
        log: Optional[Callable[[str], Any]] = None,
        reopen: Optional[Callable[[], Any]] = None,
        address: Optional[str] = None,
        reconnect_ms: Optional[int] = None,
    ) -> None:
        """`log`: called with each `link: ...` line (default: the logger "<package>.link", INFO).
        `reconnect_ms`: reopen a lost port with `reopen()` (a new transport for `address`) for up
        to that long, then get to idle, re-apply the settings and resume (None: a lost port
        raises TransportError, as before)."""
        self.transport = transport
        self.session = Session(device, timeout_ms, inter_packet_timeout_ms, 1, check_device)
        self._clock = clock
        self._t0 = clock()
        self.on_event = on_event
        self.log: Callable[[str], Any] = log or logging.getLogger(f"{__name__.rsplit('.', 1)[0]}.link").info
        self.reopen = reopen
        self.address = address or "the port"
        self.reconnect_ms = reconnect_ms
        # the settings written since connect, in order, the latest per key (re-applied after a reconnect)
        self.settings: OrderedDict[Tuple[Any, ...], Field] = OrderedDict()
        self._app_idle = False  # the application's last idle/resume command was an idle
        self._quiet = False  # inside to_idle: data is counted and dropped, not delivered
        self._muted: Optional[Tuple[Any, Any, Any]] = None  # the handlers while muted
        self._mute_depth = 0
        self._dropped = 0
        self._linking = False  # inside a reconnect: no nested one
        self._identified = device is None  # the model check after the first unknown-command NACK
        self._identifying = False  # inside that check: its own result is no event
        from .. import command_api  # the generated typed API (imports this module)

        command_api.bind(self)

    @property
    def device(self) -> Optional[str]:
        return self.session.device

    def now_ms(self) -> int:
        return int((self._clock() - self._t0) * 1000)

    def on_packet(self, handler: Callable[[Packet], Any]) -> None:
        self.session.on_packet(handler)

    def on_field(self, set_id: int, descriptor: int, handler: Callable[[Any, Packet], Any]) -> None:
        self.session.on_field(set_id, descriptor, handler)

    def on_sample(self, handler: Callable[[Sample], Any]) -> None:
        self.session.on_sample(handler)

    def on_foreign(self, handler: Callable[[Union[Nmea, Rtcm]], Any]) -> None:
        self.session.on_foreign(handler)

    @property
    def time(self) -> SplitClock:
        """The session's live time model (`Session.time`)."""
        return self.session.time

    def times(self, packet: Packet) -> Times:
        """`Session.times`: the times of a data packet."""
        return self.session.times(packet)

    def utc_ns(self, packet: Packet) -> Optional[int]:
        """`Session.utc_ns`: UTC ns since the Unix epoch of a data packet, or None."""
        return self.session.utc_ns(packet)

    @property
    def host_clock(self) -> ClockModel:
        """The session's host clock model (`Session.host_clock`; host times from the device's clock)."""
        return self.session.host_clock

    def host_ns(self, packet: Packet) -> Optional[int]:
        """`Session.host_ns`: the host time of a data packet (the device's clock), or None."""
        return self.session.host_ns(packet)

    def _deliver(self, events: List[Event]) -> None:
        if self.on_event is not None:
            if self._quiet:
                return  # inside to_idle or the baud search: counted and dropped
            for e in events:
                if (self._linking or self._identifying) and isinstance(e, Result):
                    continue  # the results of a reconnect's own commands
                self.on_event(e)

    def run(self, command: Field, timeout_ms: Optional[int] = None, check_device: Optional[bool] = None) -> Result:
        """Send the command and wait for its Result (never raises for nack, timeout or refusal;
        with reconnecting, a command in flight when the port goes away gets "lost")."""
        p = self.start(command, timeout_ms, check_device)
        while p.result is None:
            self.pump(max(0, (self.session.next_deadline() or p.deadline) - self.now_ms()))
        self.record(p.command, p.result)
        return p.result

    def start(
        self, command: Field, timeout_ms: Optional[int] = None, check_device: Optional[bool] = None, tag: Any = None
    ) -> Pending:
        """Start the command and send its packet (the result comes with later pumps)."""
        p = self.session.start(command, self.now_ms(), timeout_ms, check_device, tag)
        if p.packet:
            try:
                self.transport.write(p.packet)
            except TransportError as e:
                self._lost(e)
        return p

    def record(self, command: Field, result: Result) -> None:
        """Notes a completed command: a setting the application wrote (re-applied after a
        reconnect) or its idle/resume (`run` calls it; a caller of `start` calls it itself). The
        first NACK for an unknown command asks the device what it is (once): when it is not the
        model the session was told, `result.note` says so (and the NACK's message)."""
        if result.status == NACK and not self._identified and int(result.code) in _UNKNOWN_CODES:
            self._identified = True
            result.note = self.model_mismatch()
        if not result.ok or self._linking:
            return
        key = (command.SET, command.DESCRIPTOR)
        if _link.IDLE == key:
            self._app_idle = True
        elif _link.RESUME == key:
            self._app_idle = False
        function = getattr(command, "function", None)
        if function is None or _meta.FUNCTION_NAMES.get(int(function)) not in ("write", "write_no_ack"):
            return
        attrs = _sim.COMMANDS.get(type(command), ({}, ()))[0]
        read = next((v for v, n in _meta.FUNCTION_NAMES.items() if n == "read"), None)
        names = attrs.get(read, ()) if read is not None else ()
        key = key + tuple(_plain_value(getattr(command, a, None)) for a in names)
        self.settings.pop(key, None)
        self.settings[key] = command
        while len(self.settings) > MAX_SETTINGS:
            self.settings.popitem(last=False)

    def model_mismatch(self) -> Optional[str]:
        """Asks the device for its identity (the spec's identity command): "connected device is
        NAME, this session was told ID" when the model name it reports is not the session's model;
        None when it is, or when the device does not say."""
        if self.device is None:
            return None
        self._identifying = True
        try:
            name = read_identity(self, quiet=True).get("model_name")
        except SessionError:
            name = None
        finally:
            self._identifying = False
        if not name or model_matches(str(name), self.device):
            return None
        return f"connected device is {shown_name(str(name))}, this session was told {self.device}"

    def call(self, command: Field, timeout_ms: Optional[int] = None, check_device: Optional[bool] = None) -> Result:
        """As `run`, but raises CommandRefused, Nack, CommandTimeout or InvalidReply unless it succeeded."""
        return self.run(command, timeout_ms, check_device).raise_for_status()

    def pump(self, wait_ms: int) -> List[Event]:
        """Wait up to `wait_ms` for bytes (one read of at most READ_MAX bytes: the transports
        read no more), feed them with the current time (or run the timeouts) and deliver the
        events. Callers pass a wait that ends at the session's next deadline at the latest, so a
        flood cannot hold a command past its deadline by more than the handling of one read."""
        try:
            data = self.transport.read(wait_ms / 1000.0)
        except TransportError as e:
            return self._lost(e)
        if self._quiet:
            self._dropped += len(data)
        read_ns = int((self._clock() - self._t0) * 1e9)  # the host time of the read (host clock model)
        if len(data) <= FEED_SLICE:
            events = self.session.feed(data, self.now_ms(), read_ns)
            self._deliver(events)
            return events
        # A long read is fed in slices, each at the current time: a deadline that passes while
        # the read is handled gives its result after one slice (the pure-Python parser takes
        # about 7 us a byte on a flood of false syncs), not after the whole read.
        events = []
        for k in range(0, len(data), FEED_SLICE):
            part = self.session.feed(data[k : k + FEED_SLICE], self.now_ms(), read_ns)
            self._deliver(part)
            events += part
        return events

    # -------------------------------------------------------------- getting through
    def _lost(self, error: TransportError) -> List[Event]:
        """The port went away: the pending commands are lost; reconnect (or raise without it)."""
        if self.reconnect_ms is None or self.reopen is None or self._linking:
            raise error
        reason = getattr(error, "reason", None) or str(error)
        events = self.session.lose_pending(reason)
        self._deliver(events)
        self._reconnect(reason)
        return events

    def _reconnect(self, reason: str) -> None:
        lost_at = self._clock()
        assert self.reconnect_ms is not None and self.reopen is not None
        self.log(f"link: port lost ({reason}), reopening {self.address} every {RECONNECT_EVERY_MS} ms")
        try:
            self.transport.close()
        except OSError:
            pass
        deadline = lost_at + self.reconnect_ms / 1000.0
        baud = getattr(self.transport, "baudrate", None)
        while True:
            try:
                transport = self.reopen()
                break
            except (TransportError, OSError):
                if self._clock() + RECONNECT_EVERY_MS / 1000.0 > deadline:
                    self.log(f"link: gave up reopening {self.address} after {self.reconnect_ms} ms")
                    raise LinkError(f"{self.address} did not come back within {self.reconnect_ms} ms") from None
                time.sleep(RECONNECT_EVERY_MS / 1000.0)
        if baud is not None and getattr(transport, "baudrate", None) not in (None, baud):
            transport.baudrate = baud
        self.transport = transport
        self.session.reset_input()
        self._linking = True
        try:
            if _link.IDLE is not None:
                self.to_idle()
            for command in list(self.settings.values()):
                self.run(command)
            if _link.RESUME is not None and not self._app_idle:
                self.run(_command_of(_link.RESUME))
        finally:
            self._linking = False
        elapsed = self._clock() - lost_at
        self.log(f"link: reconnected after {elapsed:.1f} s, re-applied {len(self.settings)} settings")

    def _mute(self, on: bool) -> None:
        """Inside to_idle and the baud search: no handler and no event consumer sees what arrives
        (it is counted and dropped); the handlers come back after."""
        s = self.session
        if on:
            self._dropped = 0
            self._mute_depth += 1
            if self._mute_depth == 1:  # (a reconnect inside to_idle mutes again: nested)
                self._quiet = True
                self._muted = (s._packet_handlers, s._field_handlers, s._grouper)
                s._packet_handlers, s._field_handlers, s._grouper = [], {}, None
            return
        self._mute_depth -= 1
        if self._mute_depth == 0 and self._muted is not None:
            self._quiet = False
            s._packet_handlers, s._field_handlers, s._grouper = self._muted
            self._muted = None

    def _flush(self) -> None:
        flush = getattr(self.transport, "flush_input", None)
        if flush is not None:
            flush()
        self.session.reset_input()

    def to_idle(self, timeout_ms: Optional[int] = None) -> Result:
        """Get the device to idle while it may stream at full rate (docs/conformance.md section 8):
        the idle command, data counted and dropped meanwhile, on a timeout a flush, a quiet time and
        a retry, up to the spec's attempts. Returns the ACK's Result; raises LinkError after the
        last attempt (its result in `.result`) or CommandFailed for a NACK."""
        if _link.IDLE is None:
            self.log("link: idle: the protocol has no idle command")
            raise LinkError("the protocol has no idle command")
        wait = self.session.timeout_ms if timeout_ms is None else timeout_ms
        attempts = _link.IDLE_ATTEMPTS
        command = _command_of(_link.IDLE)
        result: Optional[Result] = None
        for attempt in range(1, attempts + 1):
            self._mute(True)
            try:
                p = self.start(command, wait)
                while p.result is None:
                    self.pump(max(0, (self.session.next_deadline() or p.deadline) - self.now_ms()))
                result = p.result
                dropped = self._dropped
                if result.status == TIMEOUT and attempt < attempts:
                    self._flush()
                    end = self.now_ms() + IDLE_QUIET_MS
                    while self.now_ms() < end:
                        self.pump(max(0, end - self.now_ms()))
                    self._flush()
            finally:
                self._mute(False)
            if result.status == TIMEOUT:
                if attempt < attempts:
                    streaming = f" while streaming ({dropped} bytes dropped)" if dropped else ""
                    self.log(
                        f"link: idle: no ACK in {wait} ms{streaming}, flushing, attempt {attempt + 1} of {attempts}"
                    )
                    continue
                self.log(f"link: idle: no ACK after {attempts} attempts, giving up")
                error = LinkError(f"no ACK to {command.NAME} after {attempts} attempts")
                error.result = result  # type: ignore[attr-defined]
                raise error
            if result.ok:
                self.log(f"link: idle: ACK on attempt {attempt} of {attempts} ({dropped} bytes dropped)")
                if not self._linking:
                    self._app_idle = True
                return result
            return result.raise_for_status()
        raise AssertionError("unreachable")  # pragma: no cover

    def find_baud(self, timeout_ms: Optional[int] = None) -> Optional[int]:
        """On a serial port (a transport with `baudrate`): ping at the configured rate, and without
        an answer at the spec's rates of the model, most likely first; stays at the first that
        answers and returns it. None over a transport without a baud rate (TCP). Raises LinkError
        when no rate answers."""
        if getattr(self.transport, "baudrate", None) is None:
            return None
        probe = _link.PING or _link.IDLE
        if probe is None:
            raise LinkError("the protocol has no ping command")
        configured = int(self.transport.baudrate)
        order = baud_search_order(self.device, configured)
        command = _command_of(probe)
        for i, rate in enumerate(order):
            if rate != int(self.transport.baudrate):
                self.transport.baudrate = rate
            self._flush()
            self._mute(True)
            try:
                result = self.run(command, timeout_ms)
            finally:
                self._mute(False)
            if result.status != TIMEOUT:
                if rate != configured:
                    self.log(f"link: baud: device answers at {rate}")
                return rate
            if i + 1 < len(order):
                self.log(f"link: baud: no answer at {rate}, trying {order[i + 1]}")
        self.log("link: baud: no answer at any rate")
        self.transport.baudrate = configured
        raise LinkError(f"no answer at any baud rate ({', '.join(map(str, order))})")

    def listen(self, duration_ms: int) -> None:
        """Receive for `duration_ms`, routing every packet to the handlers."""
        end = self.now_ms() + duration_ms
        while True:
            left = end - self.now_ms()
            if left <= 0:
                break
            self.pump(left)

    def close(self) -> None:
        self._deliver(self.session.close(self.now_ms()))
        self.transport.close()

    def __enter__(self) -> Device:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


def connect(
    address: str, device: Optional[str] = None, baudrate: int = 115200, auto_baud: bool = False, **options: Any
) -> Device:
    """A Device on `address`: "tcp:HOST:PORT" or a serial port path ("/dev/ttyUSB0", "COM3").
    Options of Device (`reconnect_ms`: a lost port is reopened at the same address, `log`);
    `auto_baud`: find the rate the device answers at when `baudrate` gets no answer (a serial port)."""
    from .transport import open_transport

    check_device_name(device)  # before anything is opened
    options.setdefault("reopen", lambda: open_transport(address, baudrate))
    options.setdefault("address", address)
    result = Device(open_transport(address, baudrate), device, **options)
    if auto_baud:
        result.find_baud()  # a reopened port is set to the rate found (Device._reconnect)
    return result


# The NACK codes of a command the device does not know (spec simulation.nack: unknown_descriptor,
# unknown_set): the first one makes a Device ask what the device is (Device.model_mismatch).
_UNKNOWN_CODES = frozenset(_sim.NACK[k] for k in ("unknown_descriptor", "unknown_set") if k in _sim.NACK)


def identity_command() -> Optional[Tuple[Any, Any]]:
    """(command class, reply class) of the command whose reply reports the device's identity."""
    for reply in _sim.IDENTITY_REPORTS:
        for (set_id, _), rows in _meta.COMMANDS.items():
            for row in rows:
                if set_id == reply.SET and any(r[0] == reply.DESCRIPTOR for r in row[4]):
                    return row[0], reply
    return None


def read_identity(device: Device, quiet: bool = False) -> Dict[str, Any]:
    """The identity items the device reports (model_name, serial_number, firmware, ...); raises
    CommandFailed when it does not answer (`quiet`: the command is sent whatever the model)."""
    found = identity_command()
    if found is None:
        return {}
    cls, reply_cls = found
    result = device.call(cls(), check_device=False if quiet else None)
    reply = result.response
    out: Dict[str, Any] = {}
    if not isinstance(reply, reply_cls):
        return out
    for path, item, _fmt in _sim.IDENTITY_REPORTS[reply_cls]:
        v: Any = reply
        for name in path:
            v = getattr(v, name)
        if isinstance(v, (bytes, bytearray)):
            v = bytes(v).decode("latin-1")
        if isinstance(v, str):
            v = v.strip(" \x00")
        out[item] = v
    return out


def shown_name(text: str) -> str:
    """A name the device reported, as printed: a character outside printable ASCII is written
    `\\xNN` (the device's bytes reach no terminal as they are). The rule of every language."""
    return "".join(c if " " <= c <= "~" else f"\\x{ord(c) & 0xFF:02x}" for c in text)


def model_of(identity: Dict[str, Any]) -> Optional[str]:
    """The device id whose model name (the spec's identity, or its title) the device reports."""
    name = str(identity.get("model_name", "")).strip()
    for d in registry.DEVICES:
        if name and model_matches(name, d):
            return d
    return registry.DEVICES[0] if len(registry.DEVICES) == 1 else None


def baud_search_order(device: Optional[str], configured: int) -> Tuple[int, ...]:
    """The baud rates to try when `configured` gets no answer, most likely first: the configured
    rate, the model's default, then the model's rates from the highest down (without a model: the
    defaults of every model that states one, then every model's rates), each once."""
    devices = [device] if device is not None else list(registry.DEVICES)
    order = [configured]
    for d in devices:
        default = _link.DEFAULT_BAUD.get(d)
        if default is not None and default not in order:
            order.append(default)
    rates = sorted({r for d in devices for r in _link.BAUD_RATES.get(d, ())}, reverse=True)
    order.extend(r for r in rates if r not in order)
    return tuple(order)


def _command_of(key: Tuple[int, int]) -> Field:
    """The command (set, descriptor) of the link facts, as sent: no parameters."""
    cls: Any = _meta.COMMANDS[key][0][0]
    value: Field = cls()
    return value


def _plain_value(value: Any) -> Any:
    """A parameter's value as a key (lists and structs as tuples)."""
    if isinstance(value, list):
        return tuple(_plain_value(v) for v in value)
    if hasattr(value, "__slots__") and not isinstance(value, int):
        return tuple(_plain_value(getattr(value, s, None)) for s in value.__slots__)
    return value


__all__ = [
    "Session",
    "Device",
    "Pending",
    "Result",
    "TimedParser",
    "CommandInfo",
    "SessionError",
    "CommandRefused",
    "CommandFailed",
    "Nack",
    "CommandTimeout",
    "InvalidReply",
    "connect",
    "baud_search_order",
    "LinkLost",
    "LinkError",
    "command_from_line",
    "command_info",
    "support_error",
    "ack_suppressed",
    "allowance_ms",
    "expected_replies",
    "DEFAULT_TIMEOUT_MS",
    "DEFAULT_INTER_PACKET_TIMEOUT_MS",
    "MAX_PENDING",
    "SKIP_PIECE",
    "READ_MAX",
]
