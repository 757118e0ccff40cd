"""A simulated Memsense MS-CIP device (docs/conformance.md section 9): test an application without
the hardware, over a pseudo-terminal or TCP.

    python -m mscipcodec.sim --listen pty[:PATH]|tcp:HOST:PORT [--device ID] [--seed N] [fault options]

prints the address it listens on as its first line and serves until terminated. The behaviour
comes from the spec: `_session.py` (functions, reply fields and their `when`, device support, ack
suppression) and `_sim.py` (the parameters each function sends, enum parameters, units of data
values, the streaming commands, base rates, NACK codes), both generated from the IR.

`Simulator` is the sans-I/O core: `feed(bytes, now)` takes what the host sent, `poll(now)`
produces the data stream due by `now`; both return `(time, bytes)` chunks to write at those
times (faults delay and split them). `hosts.serve()` runs it over a pty or a TCP socket (several
TCP hosts at once, as a device's port behind a network bridge).
"""

from __future__ import annotations

import dataclasses
import math
import random
import sys
from typing import Any, Dict, List, Optional, Sequence, Set, Tuple

from .. import _link, _sim, capabilities, registry
from .. import _session as _meta
from .._protocol import FIELD_HEADER_SIZE, FIRST_SHARED, MAX_PAYLOAD, SET_OFFSET
from ..codec.framing import Nmea, PacketBuilder, Parser, RawPacket, Rtcm
from ..codec.layout import Choice, Enum, Field
from ..codec.packets import DecodedField, RawField, decode_packet
from ..session import support_error
from . import corrections as sim_corrections
from . import status as sim_status
from .clocks import Clocks
from .nmea import NmeaPort
from .status import set_of as _set_of
from .world import GRAVITY, RADIANS, World

Chunk = Tuple[float, bytes]
FAULT_KINDS = ("drop", "delay", "corrupt", "split", "garbage", "nack")

# The accepted ranges of the options (docs/conformance.md section 9, "Validation"): every number
# finite; what lies outside is a usage error (exit 2) naming the range.
SPEED_RANGE = (0.001, 100000.0)  # --speed: simulated seconds per real second
MAX_SECONDS = 1e9  # --gnss-outage, --mag-disturbance, --rtk-corrections, --replug: 0 <= START < END <= this
MAX_DELAY_MS = 3_600_000  # --delay COMMAND:MS: at most an hour
MAX_GARBAGE = 65536  # --garbage COMMAND:BYTES: at most 64 KiB before a reply
MAX_CODE = 255  # --nack COMMAND:CODE: the ack field's code is one byte
MAX_REPLAY_BYTES = 16 << 20  # --replay FILE: at most 16 MiB (read no further)
# A serving loop late by more than this much real time drops the older ticks (with --stream-full:
# STREAM_FULL_WINDOW), and builds at most MAX_BURST samples of a data set at once.
LATE_WINDOW = 1.0
STREAM_FULL_WINDOW = 0.02
MAX_BURST = 4096


class Fault:
    """A fault applied to the replies to one command (its name, or "all"): drop, delay (`arg` ms),
    corrupt (checksum), split (two writes 20 ms apart), garbage (bytes before the reply), nack
    (`arg`: the code, default the invalid-parameter code); for the first `times` replies only
    when given."""

    def __init__(self, kind: str, command: str, arg: Optional[int] = None, times: Optional[int] = None) -> None:
        self.kind = kind
        self.command = command
        self.arg = arg
        self.times = times

    @classmethod
    def parse(cls, kind: str, text: str) -> Fault:
        """From an option value COMMAND[:ARG][@TIMES]."""
        times = None
        if "@" in text:
            text, _, n = text.rpartition("@")
            if not n.isdigit() or int(n) < 1:
                raise ValueError(f"--{kind} {text}@{n}: the count after @ must be a positive integer")
            times = int(n)
        command, _, arg = text.partition(":")
        if not command:
            raise ValueError(f"--{kind}: expected COMMAND[:ARG][@TIMES] (a command name or 'all')")
        value = None
        if arg:
            if not arg.isdigit():
                raise ValueError(f"--{kind} {text}: {arg!r} is not a non-negative integer")
            value = int(arg)
            limit = {"delay": MAX_DELAY_MS, "garbage": MAX_GARBAGE, "nack": MAX_CODE}.get(kind)
            what = {"delay": "milliseconds", "garbage": "bytes", "nack": "a code"}.get(kind)
            if limit is not None and value > limit:
                raise ValueError(f"--{kind} {text}: expected {what} 0..{limit}")
        elif kind == "delay":
            raise ValueError(f"--delay {text}: expected COMMAND:MILLISECONDS")
        return cls(kind, command, value, times)

    def applies(self, name: str) -> bool:
        if self.times is not None and self.times <= 0:
            return False
        if self.command not in ("all", name):
            return False
        if self.times is not None:
            self.times -= 1
        return True


def check_speed(speed: float) -> float:
    """--speed: a finite factor in SPEED_RANGE (ValueError names the range)."""
    low, high = SPEED_RANGE
    if not (isinstance(speed, (int, float)) and math.isfinite(speed) and low <= speed <= high):
        raise ValueError(
            f"--speed {speed}: expected a number of simulated seconds per real second, {low:g} to {high:g}"
        )
    return float(speed)


class Simulator:
    """The simulated device: settings (current, startup, factory), replies, streams, faults."""

    def __init__(
        self,
        device: Optional[str] = None,
        seed: int = 0,
        faults: Sequence[Fault] = (),
        scenario: str = "static",
        speed: float = 1.0,
        baud: bool = False,
        identity: Optional[Dict[str, Any]] = None,
        stream_full: bool = False,
    ) -> None:
        check_speed(speed)
        if device is None:
            device = registry.DEVICES[0]
        if device not in registry.DEVICES:
            raise ValueError(f"unknown device {device!r} (expected one of {', '.join(registry.DEVICES)})")
        self.device = device
        # what the device reports as its identity (spec simulation identity; --serial, ...)
        self.identity: Dict[str, Any] = {**_sim.IDENTITY.get(device, {}), **(identity or {})}
        self.rng = random.Random(seed)
        self.faults = list(faults)
        self.parser = Parser()
        self.current: Dict[Tuple[Any, ...], Field] = {}
        self.startup: Dict[Tuple[Any, ...], Field] = {}
        self.base_rates = dict(_sim.BASE_RATES.get(device, {}))
        self.start_time: Optional[float] = None
        self.ticks: Dict[int, int] = {}  # data set -> last tick sent
        self.plan: Dict[int, List[Tuple[int, int]]] = {}  # data set -> [(descriptor, decimation)]
        self.commands = 0
        self._names: Dict[str, List[Any]] = {}  # command name -> its classes on this device
        self.speed = float(speed)
        self.world = World(scenario, seed, _sim.FILTER.get(device))
        self.corrections = sim_corrections.Corrections(_sim.FILTER.get(device, {}), self.world)  # RTCM3 in
        self.clocks = Clocks(self, seed)  # reference and external time, PPS, link delay (clocks.py)
        self.delay = 0.0  # seconds of simulated time the reply being built comes late
        self.idle = False  # set to idle: no streams until resume
        self._world_at: Optional[Tuple[float, Dict[str, Any]]] = None
        self.follow_baud = baud  # a write of the port's baud rate changes the pty's line rate
        self.baud_changes: List[Tuple[float, int]] = []  # (after the reply sent at, new baud rate)
        # --stream-full: the model's highest data rates from power-up, as if saved as its startup
        # settings: every data set with a base rate streams every data quantity the model documents
        # in it (capabilities), at decimation 1, until the host changes the format or the stream
        self.full: Dict[int, List[Tuple[int, int]]] = {}
        if stream_full:
            model = capabilities.MODELS.get(device)
            for set_id in self.base_rates:
                entries = [(d, 1) for s, d in (model.data if model else ()) if s == set_id]
                if entries:
                    self.full[set_id] = entries
        self.nmea = NmeaPort(self)  # NMEA out and in (sim/nmea.py)
        self._replan()

    def sim_time(self, now: float) -> float:
        """The simulated clock: seconds since the device started, times --speed."""
        if self.start_time is None:
            self.start_time = now
        return (now - self.start_time) * self.speed

    # ------------------------------------------------------------------ commands
    def feed(self, data: bytes, now: float, parser: Optional[Parser] = None) -> List[Chunk]:
        """The replies to the commands in `data` (and the data due by `now`). `parser`: the framing
        of the host that sent `data` (hosts.py: each host its own, so half a packet from one host
        never merges with another's bytes; default the simulator's own)."""
        parser = self.parser if parser is None else parser
        out = self.poll(now)
        sim_status.received(self, data, now)  # what a device status counts
        for event in parser.feed(data):
            if isinstance(event, RawPacket):
                out.extend(self._packet(event.data, now))
            elif isinstance(event, Nmea):
                out.extend(self.nmea.receive(event.data, now))
            elif isinstance(event, Rtcm):
                sim_corrections.feed(self, event, now)
        # The device reports no skip run: the parser holds at most one partial packet (at most
        # the maximum packet size), never the noise between packets.
        del parser._skip[:]
        return out

    def _packet(self, raw: bytes, now: float) -> List[Chunk]:
        set_id = raw[SET_OFFSET]
        if registry.set_kind(set_id) != "command":
            return []
        packet = decode_packet(raw, device=self.device)
        out: List[Chunk] = []
        for entry in packet.fields:
            descriptor = getattr(entry, "descriptor", None)
            if descriptor is None:
                continue
            self.commands += 1
            self._world_at = None  # a command may change the world
            try:
                name, code, replies, extra = self._answer(set_id, entry, now)
            except Exception as e:  # a simulator bug must not end the session: report, NACK
                print(f"{__name__}: {type(e).__name__}: {e}", file=sys.stderr)
                name, code, replies, extra = "", _sim.NACK["failed"], [], []
            if code is None:
                out.extend(extra)
                continue
            try:
                reply = self._reply(set_id, descriptor, code, replies)
            except ValueError:  # the reply does not fit one packet: the device cannot report it
                reply = self._reply(set_id, descriptor, _sim.NACK["invalid_parameter"], [])
            late, self.delay = now + self.delay / self.speed, 0.0
            out.extend(self._faulted(name, reply, late))
            if self.baud_changes and self.baud_changes[-1][0] < 0:  # acked at the old rate first
                self.baud_changes[-1] = (late, self.baud_changes[-1][1])
            out.extend(extra)
        return out

    def _answer(self, set_id: int, entry: Any, now: float) -> Tuple[str, Optional[int], List[Field], List[Chunk]]:
        """(command name, code or None for no reply, reply fields, packets sent after the reply)."""
        nack = _sim.NACK
        if not any(s == set_id for s, _ in registry.FIELDS):
            return "", nack["unknown_set"], [], []
        if isinstance(entry, RawField):
            entry = _without_ignored(set_id, entry, self.device) or entry
        if isinstance(entry, RawField):
            classes = registry.FIELDS.get((set_id, entry.descriptor))
            rows = _meta.COMMANDS.get((set_id, entry.descriptor), ())
            if not classes or classes[0].ROLE != "command" or not any(self.device in r[2] for r in rows):
                return "", nack["unknown_descriptor"], [], []
            return classes[0].NAME, nack["invalid_parameter"], [], []
        if not isinstance(entry, DecodedField):
            return "", None, [], []
        command = entry.value
        name = command.NAME
        if command.ROLE != "command":
            return name, nack["unknown_descriptor"], [], []
        for fault in self.faults:
            if fault.kind == "nack" and fault.applies(name):
                return "", nack["invalid_parameter"] if fault.arg is None else fault.arg, [], []  # "": no other fault
        error = support_error(command, self.device)
        if error is not None:
            unknown = not capabilities.supports(self.device, int(command.SET or 0), command.DESCRIPTOR)
            return name, nack["unknown_descriptor" if unknown else "invalid_parameter"], [], []
        info = _sim.COMMANDS.get(type(command))
        ignored = _ignored(command)  # what the function does not read: never checked
        if info is not None and any(
            not isinstance(getattr(command, a, None), Enum) and getattr(command, a, None) is not None
            for a in info[1]
            if a not in ignored
        ):
            return name, nack["invalid_parameter"], [], []
        if not self._baud_supported(command):
            return name, nack["invalid_parameter"], [], []
        refused = self._act(command, now)
        if refused is not None:
            return name, refused, [], []
        replies, extra = self._execute(command, now)
        if _suppressed(command):
            return name, None, [], extra
        return name, _meta.ACK_OK, replies, extra

    def _baud_supported(self, command: Field) -> bool:
        """Whether a baud rate write (_sim.BAUD) asks a rate the model's port supports (_link.BAUD_RATES,
        from the manuals; a model whose manual lists none takes any). Another rate is refused with
        NACK invalid parameter, "a value outside the allowed range" (3dm-gx5-45-dcp.txt:2027,
        3dm-cv7-ins-docs.txt:8878, ms-cip-doc00419-revM.txt:143): acknowledging it would leave the
        device at a rate no host can reach."""
        attr = _sim.BAUD.get(type(command))
        rates = _link.BAUD_RATES.get(self.device, ())
        if attr is None or not rates:
            return True
        fn = getattr(command, "function", None)
        if fn is not None and _meta.function_name(int(fn)).lower() not in ("write", "write_no_ack"):
            return True
        rate = getattr(command, attr, None)
        return rate is None or int(rate) in rates

    def _key(self, command: Field, function: Optional[int]) -> Tuple[Any, ...]:
        keys = _sim.COMMANDS.get(type(command), ({}, ()))[0]
        read = _function_value("read")
        attrs = keys.get(read, ()) if read in keys else keys.get(function if function is not None else -1, ())
        return (command.SET, command.DESCRIPTOR, tuple(_plain(getattr(command, a, None)) for a in attrs))

    def _execute(self, command: Field, now: float) -> Tuple[List[Field], List[Chunk]]:
        fn = getattr(command, "function", None)
        fn = None if fn is None else int(fn)
        key = self._key(command, fn)
        kind = _meta.function_name(fn).lower() if fn is not None else None
        if type(command) in _sim.ALL_SETTINGS and kind in ("save", "load", "default"):
            self._all(kind)
        elif kind in ("write", "write_no_ack"):
            self.current.pop(key, None)  # in the order of the writes: the latest last
            self.current[key] = command
        elif kind in ("save", "load", "default"):
            for k in self._matching(key):
                if kind == "save":
                    if k in self.current:
                        self.startup[k] = self.current[k]
                elif kind == "load":
                    self._restore(k, self.startup)
                else:
                    self.current.pop(k, None)
        if kind not in (None, "read"):  # the settings changed (a ping, a read: the plan stays)
            self._replan()
        replies = [r for r in (self._response(command, key, fn),) if r is not None]
        baud = _sim.BAUD.get(type(command))
        if baud is not None and kind == "write" and self.follow_baud:
            self.baud_changes.append((-1.0, int(getattr(command, baud, 0) or 0)))
        action = _sim.ACTIONS.get(type(command), ("",))
        if action[0] == "capture":
            self.delay = float(getattr(command, action[1], 0) or 0) / 1000.0
            bias = self.world.capture_gyro_bias()
            for r in replies:
                if hasattr(r, "bias"):
                    r.bias = list(bias)
        extra: List[Chunk] = []
        poll = _sim.POLLS.get(type(command))
        if poll is not None:
            set_id = _set_of(poll[0], command)
            if set_id is not None:
                wanted = [_descriptor_of(d) for d in (getattr(command, poll[1], None) or [])]
                fields = wanted or [d for d, _ in self.plan.get(set_id, [])]
                extra = [(now + 0.001, p) for p in self.sample_packets(set_id, fields, now)]
        extra += self.nmea.poll_command(command, now)
        return replies, extra

    def _factory(self, cls: Any) -> Dict[str, Any]:
        """A command's factory values on this device (the spec's defaults its manual states)."""
        return _sim.FACTORY.get(self.device, {}).get(cls, {})

    def _setting_on(self, cls: Any, attr: str, **match: Any) -> bool:
        """Whether a setting's current value (factory: the spec's default, else off) turns `attr`
        on, for the keys whose parameters take the values in `match` (any of a tuple)."""
        factory = bool(self._factory(cls).get(attr))
        found = None
        for value in self.current.values():
            if type(value) is cls and all(
                int(getattr(value, k, -1) or 0) in (v if isinstance(v, tuple) else (v,)) for k, v in match.items()
            ):
                found = found or bool(getattr(value, attr, False))
        return factory if found is None else found

    def _act(self, command: Field, now: float) -> Optional[int]:
        """What a command does to the world (_sim.ACTIONS): None, or the NACK code refusing it."""
        self.clocks.command(command, self.sim_time(now))  # a GPS Time Update sets the external time
        if type(command) in _sim.NMEA_COMMANDS:  # NMEA entries: rate limits (sim/nmea.py)
            return self.nmea.refuse(command)
        heading = _sim.FILTER.get(self.device, {}).get("heading") or {}
        if command.NAME in heading.get("external", ()):  # an external heading update (0x0D,0x17)
            if "external" not in self.world.filter.heading_sources:
                return int(_sim.NACK["invalid_parameter"])  # only used when enabled, otherwise NACKed
            t = self.sim_time(now)
            self.world.aid("heading", t, [float(getattr(command, "heading", 0.0) or 0.0)])
            self.world.filter.accept("external", t)
            return None
        action = _sim.ACTIONS.get(type(command))
        if action is None:
            return None
        t = self.sim_time(now)
        nav = self.world.filter
        if action[0] == "reset":
            nav.reset(t)
        elif action[0] == "attitude":
            nav.attitude_set = True
        elif action[0] == "run":
            nav.run_command = True
        elif action[0] in ("idle", "resume"):
            self.idle = action[0] == "idle"
        elif action[0] == "aid":
            frame = int(getattr(command, "frame_id", 0) or 0)
            frames = [c for c, a in _sim.ACTIONS.items() if a[0] == "frame"]
            if not any(type(v) in frames and int(getattr(v, "frame_id", -1)) == frame for v in self.current.values()):
                return int(_sim.NACK["invalid_parameter"])
            enables = [(c, a) for c, a in _sim.ACTIONS.items() if a[0] == "enable"]
            internal = _sim.FILTER.get(self.device, {}).get("internal")
            if internal:  # the aiding measurement control, in the order of its writes
                enabled = any(self._aiding_enabled(internal, v) for v in action[2] if v != internal["all"])
            else:
                enabled = any(self._setting_on(c, a[2], **{a[1]: action[2]}) for c, a in enables)
            if enabled and int(getattr(command, "valid_flags", 0) or 0):
                values = [getattr(command, a) for a in action[3]]
                flat = [float(x) for v in values for x in (v if isinstance(v, list) else [v])]
                stamp = getattr(command, "time", None)  # internal reference time: when it was measured
                measured = t
                if stamp is not None and int(getattr(stamp, "timebase", 0) or 0) == 1:
                    measured = min(t, int(getattr(stamp, "nanoseconds", 0) or 0) / 1e9)
                self.world.aid(action[1], t, flat, measured)
        return None

    def _all(self, kind: str) -> None:
        """Save, load or default every setting (_sim.ALL_SETTINGS: device startup settings)."""
        if kind == "save":
            self.startup = dict(self.current)
        elif kind == "load":
            self.current = dict(self.startup)
        else:
            self.current = {}

    def _matching(self, key: Tuple[Any, ...]) -> List[Tuple[Any, ...]]:
        """The settings a save/load/default of `key` applies to: the key itself, or every key of the
        command when the function sends no key parameter (or only zeros: "all")."""
        if key[2] and any(v != 0 for v in key[2]):
            return [key]
        every = {k for k in list(self.current) + list(self.startup) if k[:2] == key[:2]}
        return sorted(every | {key}, key=repr)

    def _restore(self, key: Tuple[Any, ...], table: Dict[Tuple[Any, ...], Field]) -> None:
        if key in table:
            self.current[key] = table[key]
        else:
            self.current.pop(key, None)

    def _response(self, command: Field, key: Tuple[Any, ...], fn: Optional[int]) -> Optional[Field]:
        rows = _meta.COMMANDS.get((int(command.SET or 0), command.DESCRIPTOR), ())
        row = next((r for r in rows if r[0] is type(command)), None)
        if row is None:
            return None
        for descriptor, when_fn, param, value in row[4]:
            if when_fn is not None and fn != when_fn:
                continue
            if param is not None:
                got = getattr(command, param, None)
                if (value is None and not got) or (value is not None and got is not None and int(got) != value):
                    continue
            return self._build_response(command, key, descriptor)
        return None

    def _build_response(self, command: Field, key: Tuple[Any, ...], descriptor: int) -> Optional[Field]:
        classes = registry.FIELDS.get((int(command.SET or 0), descriptor), ())
        cls = next((c for c in classes if c.DEVICE in (None, self.device)), classes[0] if classes else None)
        if cls is None:
            return None
        stored = self.current.get(key)
        values: Dict[str, Any] = {} if stored is not None else dict(self._factory(type(command)))
        for source in (stored, command):
            if source is None:
                continue
            skip = _ignored(source)  # a read's ignored bytes are not the setting's value
            for a in source._ATTRS:
                v = getattr(source, a)
                if a != "function" and v is not None and a not in skip:
                    values[a] = v
        internal = _sim.FILTER.get(self.device, {}).get("internal")
        if internal and command.NAME == internal["command"]:  # a source's effective state (ALL included)
            asked = int(values.get(internal["param"], -1) or 0)
            if asked != internal["all"]:
                values[internal["enable"]] = self._aiding_enabled(internal, asked)
        # A reply parameter named otherwise than the command's (enable -> enabled) takes the value
        # of the command parameter at its position, when both have as many.
        sent = [a for a in type(command)._ATTRS if a != "function"]
        if len(sent) == len(cls._ATTRS):
            for mine, theirs in zip(cls._ATTRS, sent):
                if mine not in values and theirs in values:
                    values[mine] = values[theirs]
        rate_set = _set_of(_sim.RATES[type(command)], command) if type(command) in _sim.RATES else None
        if rate_set is not None:
            values["rate"] = self.base_rates.get(rate_set, 0)
        kwargs = {a: values[a] for a in cls._ATTRS if a in values}
        try:
            value = _complete(cls(**kwargs))
            value.encode()
        except (TypeError, ValueError):
            value = _complete(cls())
        self._report(value)
        sim_status.fill(self, value)
        return value  # type: ignore[no-any-return]

    def descriptor_lists(self) -> List[List[Tuple[int, int]]]:
        """What the descriptor-list replies carry, in order (the first reply, the extended one):
        the model's capabilities lists named by the spec, ascending, cut at each reply's capacity."""
        model = capabilities.MODELS[self.device]
        lists = {"command": model.commands, "data": model.data}
        entries = sorted(e for kind in _sim.DESCRIPTOR_CONTENTS for e in lists[kind])
        out: List[List[Tuple[int, int]]] = []
        for _, capacity, _ in sorted(_sim.DESCRIPTOR_LISTS.values()):
            out.append(entries[:capacity])
            entries = entries[capacity:]
        return out

    def _report(self, value: Any) -> None:
        """Writes the device's identity and its descriptor lists into a reply that carries them."""
        for path, item, fmt in _sim.IDENTITY_REPORTS.get(type(value), ()):
            target = value
            for name in path[:-1]:
                target = getattr(target, name)
            v = self.identity.get(item)
            if fmt is not None:
                length, pad, justify = fmt
                text = str(v or "")
                v = (text.rjust(length, pad) if justify == "right" else text.ljust(length, pad)).encode("ascii")
            setattr(target, path[-1], v if v is not None else 0)
        spec = _sim.DESCRIPTOR_LISTS.get(type(value))
        if spec is not None:
            index, _, attr = spec
            item = _sim.DESCRIPTOR_ITEMS.get(type(value))
            listed = self.descriptor_lists()[index]
            setattr(value, attr, [item(s, d) if item is not None else (s << 8) | d for s, d in listed])

    def _reply(self, set_id: int, descriptor: int, code: int, replies: List[Field]) -> bytes:
        ack_cls = registry.RESERVED["command"][_meta.ACK_DESCRIPTOR][0]
        builder = PacketBuilder(set_id).add(ack_cls(**{_meta.ACK_ECHO: descriptor, _meta.ACK_CODE: code}))
        for r in replies:
            builder.add(r)
        return builder.build()

    def _faulted(self, name: str, packet: bytes, now: float) -> List[Chunk]:
        """The reply as sent: the first fault (in option order) that applies to it, if any."""
        fault = next((f for f in self.faults if f.kind != "nack" and name and f.applies(name)), None)
        if fault is None:
            return [(now, packet)]
        if fault.kind == "drop":
            return []
        if fault.kind == "delay":
            return [(now + (fault.arg or 0) / 1000.0, packet)]
        if fault.kind == "corrupt":
            return [(now, packet[:-1] + bytes([packet[-1] ^ 0xFF]))]
        if fault.kind == "garbage":
            return [(now, bytes(self.rng.randrange(256) for _ in range(fault.arg or 7)) + packet)]
        half = len(packet) // 2  # split
        return [(now, packet[:half]), (now + 0.02, packet[half:])]

    # ------------------------------------------------------------------ streaming
    def _replan(self) -> None:
        """The data streams of the current settings: per data set, [(descriptor, decimation)]."""
        plan: Dict[int, List[Tuple[int, int]]] = {}
        decimation = 1
        for value in self.current.values():
            attr = _sim.DECIMATION.get(type(value))
            if attr is not None:
                decimation = max(1, int(getattr(value, attr, 1) or 1))
        for cls, fmt in _sim.FORMATS.items():  # a format list never written: the spec's default
            items = self._factory(cls).get(fmt[1])
            if items and isinstance(fmt[0], int) and not fmt[2]:
                plan[fmt[0]] = [(int(d), decimation) for d in items]
        plan.update(self.full)  # --stream-full: the power-up format, until the host writes one
        for value in self.current.values():
            fmt = _sim.FORMATS.get(type(value))
            if fmt is None:
                continue
            set_id = _set_of(fmt[0], value)
            if set_id is None:
                continue
            entries = []
            for item in getattr(value, fmt[1], None) or []:
                d = int(getattr(item, fmt[2]) if fmt[2] else item)
                dec = int(getattr(item, fmt[3])) if fmt[3] else decimation
                if dec > 0:
                    entries.append((d, dec))
            plan[set_id] = entries
        # A stream without a stored control has its factory value: the spec's default, else off.
        factory = any(
            bool(self._factory(cls).get(en[1]))
            for cls, en in _sim.ENABLES.items()
            if getattr(cls, "DEVICE", None) in (None, self.device)
        )
        enabled = set(plan) if factory else set()
        enabled |= set(self.full)
        for value in self.current.values():
            en = _sim.ENABLES.get(type(value))
            if en is None:
                continue
            set_id = _set_of(en[0], value)
            if set_id is None:
                continue
            if getattr(value, en[1], None):
                enabled.add(set_id)
            else:
                enabled.discard(set_id)
        enabled |= set(_sim.UNADDRESSED.get(self.device, ()))
        for cls, action in _sim.ACTIONS.items():  # settings the filter follows
            if action[0] == "auto_init" and getattr(cls, "DEVICE", None) in (None, self.device):
                self.world.filter.auto_init = self._setting_on(cls, action[1])
            if action[0] == "wait_run" and getattr(cls, "DEVICE", None) in (None, self.device):
                self.world.filter.wait_for_run = self._setting_on(cls, action[1])
        self._filter_settings()
        plan = {s: e for s, e in plan.items() if s in enabled}
        self.unpaced = {s: e for s, e in plan.items() if e and not self.base_rates.get(s)}  # sent as data arrives
        self.plan = {s: e for s, e in plan.items() if e and self.base_rates.get(s)}
        for set_id in [s for s in self.ticks if s not in self.plan]:
            del self.ticks[set_id]  # a stream turned off: when it is on again it resumes from then

    def _named(self, name: str) -> List[Any]:
        """The command classes of a command name for this device."""
        found = self._names.get(name)
        if found is None:
            found = [c for c in _sim.COMMANDS if c.NAME == name and getattr(c, "DEVICE", None) in (None, self.device)]
            self._names[name] = found
        return found

    def _filter_settings(self) -> None:
        """The internal aiding the settings give the filter (_sim.FILTER, docs/simulator-world.md):
        the aiding measurement control sources enabled, the heading update control's sources (or the
        initialization configuration's heading alignment methods that keep aiding), and whether
        both receivers' antenna offsets are configured and apart."""
        profile = _sim.FILTER.get(self.device, {})
        nav = self.world.filter
        internal = profile.get("internal")
        if internal:
            nav.internal = [
                source for value, source in internal["sources"].items() if self._aiding_enabled(internal, value)
            ]
        heading = profile.get("heading")
        if heading:
            chosen = None
            for c in self._named(heading["command"]):
                for value in self.current.values():
                    if type(value) is c:
                        chosen = int(getattr(value, heading["param"], 0) or 0)
                if chosen is None:
                    chosen = int(self._factory(c).get(heading["param"], 0) or 0)
            nav.heading_sources = list(heading["sources"].get(chosen or 0, []))
        alignment = profile.get("alignment")
        if alignment and "gnss" in nav.internal:
            bits = 0
            for c in self._named(alignment["command"]):
                for value in self.current.values():
                    if type(value) is c:
                        bits = int(getattr(value, alignment["param"], 0) or 0)
            nav.heading_sources = [s for s, mask in alignment["sources"].items() if bits & mask]
        antennas = profile.get("antennas")
        if antennas:
            offsets: Dict[int, Tuple[float, ...]] = {}
            for value in self.current.values():
                if any(type(value) is c for c in self._named(antennas["command"])):
                    receiver = int(getattr(value, antennas["receiver"], 0) or 0)
                    offsets[receiver] = tuple(float(x) for x in getattr(value, antennas["offset"], None) or ())
            a, b = offsets.get(1), offsets.get(2)
            nav.antennas_ok = bool(a and b and len(a) == len(b) and math.dist(a, b) > 0.0)

    def _aiding_enabled(self, internal: Dict[str, Any], value: int) -> bool:
        """Whether the aiding measurement control enables a source: its factory value (the spec's
        default), then every write of that source or of ALL in the order written, the latest
        winning (ALL then one source off: every source but that one)."""
        classes = self._named(internal["command"])
        on = any(bool(self._factory(c).get(internal["enable"])) for c in classes)
        for setting in self.current.values():
            if any(type(setting) is c for c in classes):
                source = int(getattr(setting, internal["param"], -1) or 0)
                if source == value or (internal["all"] is not None and source == internal["all"]):
                    on = bool(getattr(setting, internal["enable"], False))
        return on

    def poll(self, now: float) -> List[Chunk]:
        """The data packets due by `now` (each at its tick's time). A stream resumes from `now`
        when it is turned on again (no samples dated in the time it was off); ticks older than
        LATE_WINDOW seconds of real time (STREAM_FULL_WINDOW with --stream-full) or beyond the
        newest MAX_BURST samples are dropped, as a device's overrun output buffer drops them."""
        sim_now = self.sim_time(now)
        out: List[Chunk] = []
        window = STREAM_FULL_WINDOW if self.full else LATE_WINDOW
        for set_id, entries in self.plan.items():
            rate = self.base_rates[set_id]
            tick_now = int(sim_now * rate)
            last = self.ticks.get(set_id, tick_now - 1)  # turned on: from the tick of now
            self.ticks[set_id] = tick_now
            if self.idle or tick_now <= last:
                continue
            decimations = sorted({dec for _, dec in entries})
            first = max(
                last + 1,
                tick_now - max(1, int(rate * self.speed * window)) + 1,
                tick_now - MAX_BURST * decimations[0] + 1,
            )
            due: Set[int] = set()
            for dec in decimations:
                due.update(range(-(-first // dec) * dec, tick_now + 1, dec))
            for tick in sorted(due)[-MAX_BURST:]:
                fields = [d for d, dec in entries if tick % dec == 0]
                t = self.start_time + tick / rate / self.speed  # type: ignore[operator]
                out.extend((t, p) for p in self.sample_packets(set_id, fields, t, tick / rate))
        return self.clocks.delay(out + self.nmea.poll(now), self.speed)  # --link-jitter

    def skip(self, now: float) -> None:
        """No host is there to read the data due by `now` (between two TCP hosts): the streams go
        on without building it."""
        sim_now = self.sim_time(now)
        for set_id in self.plan:
            self.ticks[set_id] = int(sim_now * self.base_rates[set_id])
        self.nmea.ticks.clear()  # the sentences resume from the next host's arrival

    def next_wakeup(self, now: float) -> Optional[float]:
        """When the next data packet is due (None: no stream)."""
        due = [self.nmea.next_wakeup()]
        if self.plan and self.start_time is not None:
            due.append(
                min(self.start_time + (self.ticks.get(s, 0) + 1) / self.base_rates[s] / self.speed for s in self.plan)
            )
        return min((d for d in due if d is not None), default=None)

    def sample_packets(
        self, set_id: int, descriptors: List[int], t: float, elapsed: Optional[float] = None
    ) -> List[bytes]:
        """One sample of `descriptors` as a packet and continuation packets (docs/conformance.md
        section 6): split at field boundaries, the leading shared fields repeated in each.
        `elapsed`: its simulated time (default: from `t`, the real time it is sent at)."""
        fields: List[Tuple[int, bytes]] = []
        for d in descriptors:
            value = self._data_value(set_id, d, t, elapsed)
            if value is not None:
                fields.append((d, value.encode()))
        if not fields:
            return []
        first_shared = FIRST_SHARED
        lead = 0
        while lead < len(fields) and first_shared is not None and fields[lead][0] >= first_shared:
            lead += 1
        shared, rest = fields[:lead], fields[lead:]
        packets: List[bytes] = []
        overhead = FIELD_HEADER_SIZE
        size_shared = sum(len(b) + overhead for _, b in shared)
        current: List[Tuple[int, bytes]] = []
        size = size_shared
        for d, b in rest:
            if current and size + len(b) + overhead > MAX_PAYLOAD:
                packets.append(_build(set_id, shared + current))
                current, size = [], size_shared
            current.append((d, b))
            size += len(b) + overhead
        if current or not packets:
            packets.append(_build(set_id, shared + current))
        return packets

    def world_at(self, elapsed: float) -> Dict[str, Any]:
        """The world's quantities at simulated time `elapsed`, one world per sample."""
        if self._world_at is None or self._world_at[0] != elapsed:
            self._world_at = (elapsed, self.world.quantities(elapsed))
        return self._world_at[1]

    def _data_value(self, set_id: int, descriptor: int, t: float, elapsed: Optional[float] = None) -> Optional[Field]:
        classes = registry.lookup(set_id, descriptor) or ()
        cls = next((c for c in classes if c.DEVICE in (None, self.device)), None)
        if cls is None:
            return None
        value = cls()
        if elapsed is None:
            elapsed = (t - (t if self.start_time is None else self.start_time)) * self.speed
        for attr, units, count in _sim.DATA.get(cls, ()):
            current = getattr(value, attr, None)
            if isinstance(current, list):
                n = len(current) if current else (count or 0)
                setattr(
                    value,
                    attr,
                    [
                        _plausible(attr, units, i, n, elapsed, self.rng, current[i] if i < len(current) else 0)
                        for i in range(n)
                    ],
                )
            elif current is not None:
                setattr(value, attr, _plausible(attr, units, 0, 1, elapsed, self.rng, current))
        shows = _sim.WORLD.get(cls)
        if shows:
            world = self.world_at(elapsed)
            units = {a: u for a, u, _ in _sim.DATA.get(cls, ())}
            for attr, quantity in shows:
                _show(value, attr, quantity, units.get(attr), world, _sim.FILTER.get(self.device, {}))
        self.clocks.fill(value, elapsed)  # the time fields from the simulated clocks
        return value


# ---------------------------------------------------------------------------------------- helpers
def _complete(value: Any) -> Any:
    """Fills a union left at None with the member its selector chooses (a factory value)."""
    for op in getattr(type(value), "_OPS", ()):
        if isinstance(op, Choice) and getattr(value, op.name, None) is None:
            member = op.union._MEMBERS.get(int(getattr(value, op.selector, 0) or 0))
            if member is not None:
                setattr(value, op.name, member())
    return value


def _build(set_id: int, fields: List[Tuple[int, bytes]]) -> bytes:
    b = PacketBuilder(set_id)
    for d, data in fields:
        b.add_field(d, data)
    return b.build()


def _function_value(name: str) -> Optional[int]:
    return next((v for v, n in _meta.FUNCTION_NAMES.items() if n == name), None)


def _ignored(command: Any) -> Tuple[str, ...]:
    """The parameters the command's function does not read (_sim.IGNORED: not sent for it, or
    stated ignored by the manual): a request may carry any bytes there."""
    fn = getattr(command, "function", None)
    if fn is None:
        return ()
    return _sim.IGNORED.get(type(command), {}).get(int(fn), ())


def _without_ignored(set_id: int, entry: Any, device: str) -> Optional[DecodedField]:
    """A command field that does not decode because of bytes its function ignores (a bool of 0xFF
    in a read: "For all functions except 0x01 ... the new ... value is ignored"), decoded without
    them: the longest prefix that decodes leaving every ignored parameter out; None otherwise."""
    data = bytes(entry.data)
    for cls in registry.FIELDS.get((set_id, entry.descriptor), ()):
        ignored = _sim.IGNORED.get(cls, {}).get(data[0]) if data else None
        if not ignored:
            continue
        for n in range(len(data) - 1, 0, -1):
            fields = decode_packet(_build(set_id, [(entry.descriptor, data[:n])]), device=device).fields
            got = fields[0] if fields else None
            if isinstance(got, DecodedField) and all(getattr(got.value, a, None) is None for a in ignored):
                return got
    return None


def _plain(value: Any) -> Any:
    if isinstance(value, list):
        return tuple(_plain(v) for v in value)
    if dataclasses.is_dataclass(value):
        return repr(value)
    return int(value) if isinstance(value, int) else value


def _suppressed(command: Field) -> bool:
    from ..session import ack_suppressed

    return bool(ack_suppressed(command))


def _descriptor_of(item: Any) -> int:
    return int(getattr(item, "descriptor", item))


IDENTITY_FLAGS = {"serial": "serial_number", "lot": "lot_number", "options": "options", "firmware": "firmware"}


def parse_identity(device: str, flag: str, text: str) -> Tuple[str, Any]:
    """The identity item and value of a --serial/--lot/--options/--firmware flag, checked against
    what the device's replies can carry (spec simulation identity); ValueError says why not."""
    item = IDENTITY_FLAGS[flag]
    if item not in _sim.IDENTITY_ITEMS or item not in _sim.IDENTITY.get(device, {}):
        raise ValueError(f"--{flag} {text}: {device} reports no {item.replace('_', ' ')}")
    kind, limit = _sim.IDENTITY_ITEMS[item]
    if kind == "integer":
        try:
            value = int(text, 0)
        except ValueError:
            value = -1
        if not 0 <= value <= limit:
            raise ValueError(f"--{flag} {text}: expected an integer 0..{limit}")
        return item, value
    if len(text) > limit or not all(" " <= c <= "~" for c in text):
        raise ValueError(f"--{flag} {text}: expected at most {limit} printable ASCII characters")
    return item, text


def _show(
    value: Any, attr: str, quantity: str, units: Optional[str], world: Dict[str, Any], nav: Dict[str, Any]
) -> None:
    """Sets one parameter from the world (_sim.WORLD): a quantity (or its component `q[i]`) in
    the parameter's units, a valid flags parameter, an enum member or a bitfield."""
    current = getattr(value, attr, None)
    kind, _, name = quantity.partition(":")
    if kind == "valid":
        ok = {"always": True, "gnss": world["gnss_fix"]}.get(name, world.get(f"filter_valid_{name}"))
        if current is not None:
            setattr(value, attr, type(current)(all_bits(type(current)) if ok else 0))
        return
    if kind == "enum":
        member = (
            world[name] if isinstance(world.get(name), str) else nav.get("fix", ["", ""])[0 if world["gnss_fix"] else 1]
        )
        if isinstance(current, Enum) and str(member).upper() in type(current).__members__:
            setattr(value, attr, type(current)[str(member).upper()])
        return
    if kind == "flags":
        setattr(value, attr, type(current)(int(world[name])) if current is not None else int(world[name]))
        return
    index = None
    if quantity.endswith("]"):
        quantity, _, rest = quantity.partition("[")
        index = int(rest[:-1])
    q = world[quantity]
    if index is not None:
        q = q[index]
    if isinstance(current, list):
        setattr(value, attr, [_convert(float(x), units, quantity) for x in q])
    elif isinstance(current, int) and not isinstance(current, bool):
        setattr(value, attr, type(current)(int(round(float(q)))))
    elif current is not None:
        setattr(value, attr, _convert(float(q), units, quantity))


def all_bits(cls: Any) -> int:
    """The single-bit, not reserved members of a bitfield type (every bit of a valid flags)."""
    mask = 0
    for name, _attr, _const, first, width in getattr(cls, "_MEMBERS", ()):
        if width == 1 and not name.startswith("reserved"):
            mask |= 1 << first
    return mask or 1


def _convert(x: float, units: Optional[str], quantity: str) -> float:
    """A world value (SI; latitude and longitude in deg) in a parameter's units."""
    if units == "g":
        return x / GRAVITY
    if units == "deg" and quantity in RADIANS:
        return math.degrees(x)
    if units == "ms":
        return x * 1000.0
    return x


def _plausible(attr: str, units: Any, i: int, n: int, elapsed: float, rng: random.Random, default: Any) -> Any:
    """A plausible value of a data parameter from its units and name: gravity on the accelerometer
    (-1 g or -9.81 m/s^2 on the z axis), a fixed position moving slowly, clocks from the elapsed
    time, small seeded noise on other floats; integers and flags stay at their defaults."""
    if isinstance(default, bool) or not isinstance(default, (int, float)) or isinstance(default, Enum):
        return default
    if isinstance(default, int):
        if units == "ns":
            return round(elapsed * 1e9)
        if units == "us":
            return round(elapsed * 1e6)
        if units == "ms":
            return round(elapsed * 1e3)
        if units == "weeks":
            return 2400
        return default
    noise = rng.gauss(0.0, 0.001)
    if units == "s":
        return 345600.0 + elapsed
    if units in ("g", "m/s^2") and n == 3:
        return (-1.0 if units == "g" else -GRAVITY) + noise if i == 2 else noise
    if attr == "gravity_magnitude":
        return GRAVITY + noise
    if attr == "latitude":
        return 46.5197 + elapsed * 1e-6
    if attr == "longitude":
        return 6.6323 + elapsed * 1e-6
    if attr in ("ellipsoid_height", "height", "msl_height"):
        return 372.0 + 0.01 * math.sin(elapsed)
    if units == "degC":
        return 25.0 + noise
    if units == "mbar":
        return 1013.25 + noise
    if attr in ("q",) and n == 4:
        return 1.0 if i == 0 else noise
    return noise


# ---------------------------------------------------------------------------------------- replay
def replay_chunks(data: bytes, fast: bool = False) -> List[Tuple[float, bytes]]:
    """The packets of a capture with their times from its first: from the shared timestamps
    (_columns.TIMES) of the data packets, each packet sent when its time comes (a packet without
    one at the time of the one before); all at 0 when `fast`."""
    from .. import _columns

    times = {(s, d): (a, per) for s, d, a, per in getattr(_columns, "TIMES", ())}
    out: List[Tuple[float, bytes]] = []
    first: Optional[float] = None
    last = 0.0
    for event in Parser().feed(data) + Parser().flush():
        if not isinstance(event, RawPacket):
            continue
        t = last
        if not fast:
            try:
                packet = decode_packet(event.data, check=False)
            except ValueError:
                packet = None
            for entry in packet.fields if packet is not None else []:
                if isinstance(entry, DecodedField):
                    src = times.get((entry.value.SET, entry.descriptor)) or times.get((_shared_set(), entry.descriptor))
                    if src is not None:
                        stamp = float(getattr(entry.value, src[0])) / src[1]
                        first = stamp if first is None else first
                        t = max(last, stamp - first)
                        break
        last = t
        out.append((0.0 if fast else t, event.data))
    return out


def _shared_set() -> int:
    return -1 if registry.SHARED_SET is None else int(registry.SHARED_SET)
