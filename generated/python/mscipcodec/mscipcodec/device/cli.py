"""The device command line (docs/configure-a-device.md): look at, stream from and configure a
device from the shell.

    mscipcodec-device ADDRESS SUBCOMMAND [OPTIONS]        (also: python -m mscipcodec device ...)

ADDRESS: tcp:HOST:PORT, a serial port path, or `auto` (scan the serial ports, ping each at the
model's baud rates, list what answers). Subcommands: ping, info, stream, send, settings dump|apply|
diff|schema, save-startup, factory-reset, record (record.py, docs/record.md: its own statuses),
ntrip (ntrip.py, docs/rtk-and-nmea.md),
timesync (timesync.py, docs/timesync.md: exit 0 synced, 1 not, 2 usage).
The options of every subcommand (--device, --baud, --timeout-ms) go before or after it.

Exit status: 0 done (diff: the device matches the file); 1 the device said no or differs: a
NACK or no reply to a command sent (a silent device: no reply to the device information command),
a write that failed part way, `diff` found differences,
`ping` or `auto` found no device; 2 nothing was changed: a usage error, an unreadable or invalid
settings file (every problem one `FILE:LINE: message` line), a setting the model does not support
or a link budget exceeded (refused before any write is sent), no connection, a missing optional
library; 130 interrupted (except `stream`, whose normal end that is: 0).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
import types
import typing
from typing import Any, Dict, List, NoReturn, Optional, Sequence, Tuple, Union

from .. import _extras, _link, _sim, capabilities, registry
from .. import _session as _meta
from .._protocol import PACKAGE
from ..codec.layout import Field
from ..codec.stdio import closed_stdout, flushed, silence_stdout
from ..session import CommandRefused, Device, Nack, SessionError, model_matches, model_of, read_identity, shown_name
from ..session.transport import TransportError, open_transport, parse_address
from . import budget
from . import settings as st
from .ntrip import add_parser as ntrip_parser

PROG = f"{PACKAGE}-device"
DEFAULT_BAUD = 115200


class Usage(Exception):
    """A usage error (exit 2)."""


class Trouble(Exception):
    """Nothing was changed (exit 2): worded for stderr, possibly several lines."""


class Refused(Exception):
    """The device said no (exit 1)."""


def _fail(message: str) -> NoReturn:
    raise Trouble(message)


def _say(text: str = "") -> None:
    print(text, flush=True)


def _note(text: str) -> None:
    print(f"{PROG}: {text}", file=sys.stderr, flush=True)


# ------------------------------------------------------------------------------ connecting
class Connection:
    """An open device: its session, model, identity and the link's baud rate (None over TCP)."""

    def __init__(self, device: Device, model: str, identity: Dict[str, Any], baud: Optional[int], address: str):
        self.device = device
        self.model = model
        self.identity = identity
        self.baud = baud
        self.address = address

    def close(self) -> None:
        try:
            self.device.close()
        except (OSError, SessionError):
            pass


def connect(address: str, model: Optional[str], baud: Optional[int], timeout_ms: int) -> Connection:
    """Open the address, identify the device and return the Connection (Trouble on failure)."""
    try:
        kind, _ = parse_address(address)
    except ValueError as e:
        raise Usage(str(e)) from None
    rate = baud or DEFAULT_BAUD
    try:
        transport = open_transport(address, rate)
    except TransportError as e:
        _fail(str(e))
    probe = Device(transport, None, timeout_ms=timeout_ms, check_device=False)
    try:
        identity = read_identity(probe)
    except (SessionError, TransportError) as e:  # a silent device: 1, as no reply to any command sent
        transport.close()
        raise Refused(f"{address}: no answer to the device information command ({e})") from None
    found = model or model_of(identity)
    name = identity.get("model_name")
    if model is not None and name and not model_matches(str(name), model):
        _note(f"connected device is {shown_name(str(name))}, this session was told {model}")
    if found is None:
        transport.close()
        _fail(f"{address}: unknown model {identity.get('model_name')!r}; give --device ({', '.join(registry.DEVICES)})")
    device = Device(transport, found, timeout_ms=timeout_ms)
    return Connection(device, found, identity, rate if kind == "serial" else baud, address)


# --------------------------------------------------------------------------------- helpers
def _function_value(name: str) -> Optional[int]:
    for value, fname in _meta.FUNCTION_NAMES.items():
        if fname == name:
            return value
    return None


def _command_classes(name: str, model: str) -> List[Any]:
    out = []
    for classes in registry.FIELDS.values():
        for cls in classes or ():
            if cls.NAME == name and cls.ROLE == "command" and getattr(cls, "DEVICE", None) in (None, model):
                out.append(cls)
    return out


def _data_field(text: str, model: str) -> Tuple[int, int, str]:
    """(set, descriptor, name) of a data field given by name or as SET:DESCRIPTOR (0x80:0x04)."""
    if ":" in text:
        a, _, b = text.partition(":")
        try:
            set_id, descriptor = int(a, 0), int(b, 0)
        except ValueError:
            raise Usage(f"bad data field {text!r} (a name or SET:DESCRIPTOR, e.g. 0x80:0x04)") from None
        classes = registry.lookup(set_id, descriptor) or ()
        if not classes or classes[0].ROLE != "data":
            raise Usage(f"0x{set_id:02X}:0x{descriptor:02X} is not a data field of the spec")
        return set_id, descriptor, classes[0].NAME
    found = set()
    for (set_id, descriptor), classes in registry.FIELDS.items():
        for cls in classes or ():
            if cls.NAME == text and cls.ROLE == "data" and capabilities.supports(model, set_id, descriptor):
                found.add((set_id, descriptor))
    if not found:
        raise Usage(f"{text!r} is not a data field of {capabilities.describe(model)}")
    if len(found) > 1:
        where = ", ".join(f"0x{s:02X}:0x{d:02X}" for s, d in sorted(found))
        raise Usage(f"{text!r} is a field of several data sets: give SET:DESCRIPTOR ({where})")
    set_id, descriptor = found.pop()
    return set_id, descriptor, text


def _format_setting(model: str, set_id: int) -> Optional[Tuple[st.Setting, Dict[str, Any]]]:
    """The setting that holds a data set's message format on the model, with its key."""
    for s in st.settings_for(model):
        spec = _sim.FORMATS.get(s.cls)
        if spec is None:
            continue
        where = spec[0]
        if isinstance(where, int) and where == set_id:
            return s, {}
        if isinstance(where, str) and where in s.key_attrs:
            return s, {where: set_id}
    return None


def _format_sets(model: str) -> List[int]:
    return sorted(_sim.BASE_RATES.get(model, {}))


def read_base_rates(conn: Connection) -> Dict[int, float]:
    """set -> base rate in Hz, read from the device (the spec's simulation base rates where no
    command reads one)."""
    out: Dict[int, float] = {}
    for set_id in _format_sets(conn.model):
        for cls, where in _sim.RATES.items():
            if not capabilities.supports(conn.model, cls.SET, cls.DESCRIPTOR):
                continue
            if isinstance(where, int) and where != set_id:
                continue
            command = cls() if isinstance(where, int) else cls(**{where: set_id})
            result = conn.device.run(command)
            reply = result.response if result.ok else None
            if reply is not None:
                out[set_id] = float(getattr(reply, reply._ATTRS[-1]))
                break
        else:
            rate = _sim.BASE_RATES.get(conn.model, {}).get(set_id)
            if rate:
                out[set_id] = float(rate)
    return out


def read_formats(conn: Connection) -> Dict[int, List[Tuple[int, int]]]:
    """set -> [(descriptor, decimation)] of every data set's current message format."""
    out: Dict[int, List[Tuple[int, int]]] = {}
    for set_id in _format_sets(conn.model):
        found = _format_setting(conn.model, set_id)
        if found is None:
            continue
        s, key = found
        try:
            entry = st.read_entry(conn.device, s, key)
        except Nack:
            continue
        command = st.command_of(s, {**key, **entry})
        entries = budget.format_entries(command)
        if entries is not None:
            out[set_id] = entries[1]
    return out


def link_baud(conn: Connection, option: Optional[int]) -> Tuple[Optional[int], str]:
    """The baud rate the budget is checked against, and where it comes from."""
    if option:
        return option, " (--baud)"
    if conn.baud:
        return conn.baud, f" ({conn.address})"
    for s in st.settings_for(conn.model):
        param = _sim.BAUD.get(s.cls)
        if param is None or s.keyed:
            continue
        try:
            entry = st.read_entry(conn.device, s, {})
        except SessionError:
            continue
        if isinstance(entry.get(param), int) and entry[param] > 0:  # 0: not set
            return int(entry[param]), f" (the device's {s.name})"
    return None, ""


def check_budget(
    conn: Union[Connection, _Offline],
    formats: Dict[int, List[Tuple[int, int]]],
    baud: Optional[int],
    where: str,
    force: bool,
    base: Optional[Dict[int, float]] = None,
) -> List[str]:
    """The budget lines of the formats; raises Trouble when over budget (unless force: warns)."""
    if not budget.available():
        return ["the spec gives no UART bandwidth calculation"]
    try:
        if base is None:
            assert isinstance(conn, Connection), "an offline check gives the base rates"
            base = read_base_rates(conn)
        streams = budget.streams_for(conn.model, formats, base)
    except budget.BudgetError as e:
        _fail(f"link budget: {e}")
    lines = budget.describe(streams, baud, where)
    total, fits = budget.check(streams, baud or 0)
    if baud and not fits:
        text = (
            f"link budget exceeded: the message formats need {total:.0f} bit/s, the port carries {baud} baud{where} "
            f"(the manuals' UART bandwidth calculation, {budget.source()})"
        )
        if not force:
            raise Trouble(
                "\n".join(
                    [f"{PROG}: {x}" for x in lines] + [f"{PROG}: {text}; nothing was written (--force writes anyway)"]
                )
            )
        _note(f"warning: {text}; writing anyway (--force)")
    return lines


# ------------------------------------------------------------------------------ subcommands
def cmd_ping(conn: Connection, args: argparse.Namespace) -> int:
    ping = _link_command("ping")
    t0 = time.monotonic()
    result = conn.device.run(ping())
    ms = (time.monotonic() - t0) * 1000
    if not result.ok:
        raise Refused(result.describe())
    _say(
        f"{capabilities.MODELS[conn.model].title} {conn.identity.get('serial_number', '')} answered in {ms:.0f} ms".replace(
            "  ", " "
        )
    )
    return 0


def _link_command(name: str) -> Any:
    for rows in _meta.COMMANDS.values():
        for row in rows:
            if row[0].NAME == name:
                return row[0]
    _fail(f"the spec has no {name} command")


def _descriptor_lists(conn: Connection) -> List[Tuple[int, int]]:
    out: List[Tuple[int, int]] = []
    for reply_cls, (_, _, attr) in _sim.DESCRIPTOR_LISTS.items():
        for (set_id, _), rows in _meta.COMMANDS.items():
            for row in rows:
                if set_id == reply_cls.SET and any(r[0] == reply_cls.DESCRIPTOR for r in row[4]):
                    if not capabilities.supports(conn.model, row[0].SET, row[0].DESCRIPTOR):
                        continue
                    result = conn.device.run(row[0]())
                    reply = result.response if result.ok else None
                    for item in getattr(reply, attr, None) or []:
                        if isinstance(item, int):
                            out.append((item >> 8, item & 0xFF))
                        else:
                            a, b = item._ATTRS[:2]
                            out.append((int(getattr(item, a)), int(getattr(item, b))))
    return sorted(set(out))


def cmd_info(conn: Connection, args: argparse.Namespace) -> int:
    m = capabilities.MODELS[conn.model]
    ident = conn.identity
    _say(f"model: {ident.get('model_name') or m.title} ({conn.model}, manual {m.manual})")
    for item, label in (("serial_number", "serial"), ("model_number", "model number"), ("firmware", "firmware")):
        if item in ident:
            _say(f"{label}: {ident[item]}")
    listed = _descriptor_lists(conn)
    by_set: Dict[int, List[int]] = {}
    for s, d in listed:
        by_set.setdefault(s, []).append(d)
    _say(f"descriptors: {len(listed)} (the device's descriptor lists)")
    for s in sorted(by_set):
        name = registry.SET_NAMES.get(s, "")
        _say(f"  0x{s:02X} {name}: " + " ".join(f"{d:02X}" for d in by_set[s]))
    base = read_base_rates(conn)
    _say("base rates: " + (", ".join(f"0x{s:02X} {hz:g} Hz" for s, hz in sorted(base.items())) or "none"))
    baud, where = link_baud(conn, args.baud)
    formats = read_formats(conn)
    _say("link budget:")
    for line in check_budget(conn, formats, baud, where, True, base):
        _say(f"  {line}")
    return 0


def _parse_value(text: str) -> Any:
    try:
        import yaml  # type: ignore[import-untyped, unused-ignore]

        return yaml.safe_load(text)
    except ImportError:
        try:
            return json.loads(text)
        except ValueError:
            return text
    except Exception:  # noqa: BLE001 - yaml's errors: the text as a string
        return text


def cmd_send(conn: Connection, args: argparse.Namespace) -> int:
    classes = _command_classes(args.command, conn.model)
    if not classes:
        names = {c.NAME for cs in registry.FIELDS.values() for c in cs or () if c.ROLE == "command"}
        if args.command in names:
            raise Trouble(f"{PROG}: {args.command} is not supported by {capabilities.describe(conn.model)}")
        raise Usage(f"unknown command {args.command!r}")
    cls = classes[0]
    values: Dict[str, Any] = {}
    rest = list(args.arguments)
    has_function = "function" in cls._ATTRS
    if has_function:
        if not rest or "=" in rest[0]:
            functions = [_meta.FUNCTION_NAMES[f] for f in (_meta.COMMANDS[(cls.SET, cls.DESCRIPTOR)][0][3] or ())]
            raise Usage(f"{cls.NAME}: give the function first ({', '.join(functions)})")
        fn = _function_value(rest.pop(0))
        if fn is None:
            raise Usage(f"unknown function (one of: {', '.join(_meta.FUNCTION_NAMES.values())})")
        values["function"] = fn
    enums = st.enum_types(cls)
    given: Dict[str, Any] = {}
    for arg in rest:
        name, eq, text = arg.partition("=")
        if not eq or name not in cls._ATTRS:
            raise Usage(
                f"{cls.NAME}: expected PARAMETER=VALUE with a parameter of {', '.join(a for a in cls._ATTRS if a != 'function')}, got {arg!r}"
            )
        v = _parse_value(text)
        given[name] = v
        if name in enums:
            try:
                v = st.enum_value(enums[name], v)
            except ValueError as e:
                raise Usage(f"{cls.NAME}.{name}: {e}") from None
        values[name] = v
    try:
        command = _complete_write(conn, cls, values, given) or cls.from_json(values, f"{cls.NAME}.")
    except (ValueError, TypeError) as e:
        raise Usage(str(e)) from None
    result = conn.device.run(command)
    if result.status == "refused":
        raise Trouble(f"{PROG}: {result.describe()}")
    if args.json:
        _say(result.line(1))
    else:
        _say(result.describe() if not result.ok else f"{cls.NAME}: {result.status}")
        for entry in result.reply:
            value = getattr(entry, "value", None)
            if isinstance(value, Field):
                _say(f"{value.NAME} {value.to_json()}")
    return 0 if result.ok else 1


def _complete_write(conn: Connection, cls: Any, values: Dict[str, Any], given: Dict[str, Any]) -> Optional[Field]:
    """`send NAME write P=V ...` with parameters left out: a setting (a command the model also
    reads) is read first (with the key parameters given) and the given parameters replace its
    values (read, modify, write); any other command needs every parameter (Usage). None: nothing
    left out, the values as given."""
    if values.get("function") != _function_value("write"):
        return None
    setting = next(
        (s for s in st.settings_for(conn.model) if (s.cls.SET, s.cls.DESCRIPTOR) == (cls.SET, cls.DESCRIPTOR)), None
    )
    if setting is not None:  # what a settings file entry holds (counts and reserved bytes follow)
        missing = [a for a, _, _ in setting.attrs if a not in given]
    else:
        missing = [a for a in cls._ATTRS if a != "function" and a not in values]
    if not missing:
        return None
    if setting is None:
        raise Usage(
            f"{cls.NAME} write: give every parameter ({', '.join(missing)} left out; "
            "the command has no read to fill them from)"
        )
    absent = [a for a in setting.key_attrs if a not in given]
    if absent:
        raise Usage(
            f"{cls.NAME} write: give {', '.join(absent)} (the key of the read that fills the parameters left out)"
        )
    entry = st.read_entry(conn.device, setting, {a: given[a] for a in setting.key_attrs})
    _note(f"{cls.NAME}: {', '.join(missing)} as read from the device (read, modify, write)")
    return st.command_of(setting, {**entry, **given})


def _header(conn: Connection) -> List[str]:
    m = capabilities.MODELS[conn.model]
    ident = conn.identity
    return [
        f"{PACKAGE} settings of a {m.title} ({conn.model}), serial {ident.get('serial_number', '?')}, "
        f"firmware {ident.get('firmware', '?')}; the manual: {m.manual}",
        f"Schema: {PACKAGE}/settings.schema.json. Units are comments; enum members by name.",
    ]


def cmd_dump(conn: Connection, args: argparse.Namespace) -> int:
    values = st.read_all(conn.device, conn.model, warn=_note)
    text = st.dump_text(values, conn.model, _header(conn))
    if args.file in (None, "-"):
        sys.stdout.write(text)
        sys.stdout.flush()
    else:
        try:
            with open(args.file, "w", encoding="utf-8") as f:
                f.write(text)
        except OSError as e:
            _fail(f"cannot write {args.file}: {e.strerror or e}")
        _note(f"{sum(len(v) if isinstance(v, list) else 1 for v in values.values())} settings written to {args.file}")
    return 0


def _load(path: str, model: str) -> List[st.Planned]:
    try:
        if path == "-":
            text = sys.stdin.read()
        else:
            with open(path, encoding="utf-8") as f:
                text = f.read()
    except (OSError, UnicodeDecodeError) as e:
        _fail(f"cannot read {path}: {getattr(e, 'strerror', None) or e}")
    doc = st.load_text(text, path)
    return st.validate(doc, model, path)


def _planned_formats(conn: Connection, planned: List[st.Planned]) -> Tuple[Dict[int, List[Tuple[int, int]]], bool]:
    """The data sets' message formats after the file is applied (the device's now, the file's
    where it sets one), and whether the file sets any."""
    formats = read_formats(conn)
    mine = _file_formats(planned)
    formats.update(mine)
    return formats, bool(mine)


def _planned_baud(conn: Connection, planned: List[st.Planned], option: Optional[int]) -> Tuple[Optional[int], str]:
    for p in planned:
        param = _sim.BAUD.get(p.setting.cls)
        if param is not None and not p.setting.keyed and p.entries and isinstance(p.entries[0].get(param), int):
            return int(p.entries[0][param]), f" (the file's {p.setting.name})"
    return link_baud(conn, option)


def _file_formats(planned: List[st.Planned]) -> Dict[int, List[Tuple[int, int]]]:
    """The message formats the file sets, per data set."""
    formats: Dict[int, List[Tuple[int, int]]] = {}
    for p in planned:
        for entry in p.entries:
            entries = budget.format_entries(st.command_of(p.setting, entry))
            if entries is not None:
                formats[entries[0]] = entries[1]
    return formats


def precheck_apply(args: argparse.Namespace) -> None:
    """`settings apply FILE --device MODEL`: the file is checked before anything is sent, without
    a connection: its located problems and the settings MODEL does not support, then its own
    message formats against the link budget (a lower bound of what the device will stream: the
    sets the file does not touch only add to it) at the file's baud rate, else --baud, else the
    default rate of a serial port (over TCP without --baud the check waits for the device)."""
    if args.model is None or args.subcommand != "settings" or args.action != "apply":
        return
    planned = _load(args.file, args.model)
    formats = _file_formats(planned)
    if not formats or not budget.available():
        return
    baud: Optional[int] = None
    where = ""
    for p in planned:
        param = _sim.BAUD.get(p.setting.cls)
        if param is not None and not p.setting.keyed and p.entries and isinstance(p.entries[0].get(param), int):
            baud, where = int(p.entries[0][param]), f" (the file's {p.setting.name})"
    if baud is None and args.baud:
        baud, where = args.baud, " (--baud)"
    if baud is None and not args.address.startswith("tcp:"):
        baud, where = DEFAULT_BAUD, f" ({args.address})"
    if baud:
        base = {k: float(v) for k, v in _sim.BASE_RATES.get(args.model, {}).items()}
        check_budget(_Offline(args.model), formats, baud, where, args.force, base)


class _Offline:
    """What check_budget asks of a connection, before there is one: the model."""

    def __init__(self, model: str) -> None:
        self.model = model


def cmd_apply(conn: Connection, args: argparse.Namespace) -> int:
    planned = _load(args.file, conn.model)
    formats, touched = _planned_formats(conn, planned)
    if touched:
        baud, where = _planned_baud(conn, planned, args.baud)
        check_budget(conn, formats, baud, where, args.force)
    changes = st.differences(conn.device, planned)
    # a baud rate change goes last: the link follows it
    changes.sort(key=lambda c: c.setting.cls in _sim.BAUD)
    if not changes:
        _say("nothing to write: the device matches the file")
    written = 0
    for c in changes:
        key = {a: c.file[a] for a in c.setting.key_attrs}
        what = f"{c.setting.name}" + (f" ({c.key})" if c.key else "")
        try:
            conn.device.call(st.command_of(c.setting, c.file))
            if c.setting.cls in _sim.BAUD and conn.baud:
                _follow_baud(conn, c.file.get(_sim.BAUD[c.setting.cls]))
            back = st.normalized(c.setting, st.read_entry(conn.device, c.setting, key))
        except (SessionError, ValueError) as e:
            raise Refused(f"{what}: {e} ({written} of {len(changes)} settings written before it)") from None
        written += 1
        if back != c.file:
            raise Refused(f"{what}: written, but it reads back as {back} ({written} of {len(changes)} written)")
        _say(f"{what}: " + "; ".join(st.changed_params(c.device, c.file)))
    if changes:
        _say(f"{written} settings written and read back")
    if args.save:
        _save(conn)
        _say("saved as startup settings")
    return 0


def _follow_baud(conn: Connection, baud: Any) -> None:
    """After a baud rate write on a serial port: wait the settle time, then use the new rate."""
    transport = conn.device.transport
    if not isinstance(baud, int):
        return
    time.sleep((_link.BAUD_SETTLE_MS or 0) / 1000.0)
    if isinstance(getattr(type(transport), "baudrate", None), property):
        transport.baudrate = baud  # the transport's own setter
    elif getattr(transport, "_port", None) is not None:
        transport._port.baudrate = baud  # pyserial's port
    else:
        return
    conn.baud = baud


def cmd_diff(conn: Connection, args: argparse.Namespace) -> int:
    planned = _load(args.file, conn.model)
    try:
        changes = st.differences(conn.device, planned)
    except SessionError as e:  # trouble, not a difference (exit 2, as diff(1))
        raise Trouble(f"cannot read the device: {e}") from None
    for c in changes:
        what = f"{c.setting.name}" + (f" ({c.key})" if c.key else "")
        for attr, v in c.file.items():
            before = None if c.device is None else c.device.get(attr)
            if before != v:
                _say(f"{what}.{attr}: device {st.flow_text(before)}, file {st.flow_text(v)}")
    return 1 if changes else 0


def _all_settings(conn: Connection) -> Any:
    for cls in _sim.ALL_SETTINGS:
        if getattr(cls, "DEVICE", None) in (None, conn.model) and capabilities.supports(
            conn.model, cls.SET, cls.DESCRIPTOR
        ):
            return cls
    _fail(f"{capabilities.describe(conn.model)} has no command that saves every setting")


def _save(conn: Connection) -> None:
    cls = _all_settings(conn)
    fn = _function_value("save")
    try:
        conn.device.call(cls(function=fn))
    except SessionError as e:
        raise Refused(str(e)) from None


def cmd_save(conn: Connection, args: argparse.Namespace) -> int:
    _save(conn)
    _say("current settings saved as startup settings")
    return 0


def cmd_factory(conn: Connection, args: argparse.Namespace) -> int:
    cls = _all_settings(conn)
    try:
        conn.device.call(cls(function=_function_value("default")))
    except SessionError as e:
        raise Refused(str(e)) from None
    _say("factory default settings loaded (not saved: save-startup saves them)")
    return 0


def cmd_stream(conn: Connection, args: argparse.Namespace) -> int:
    fields = [_data_field(f, conn.model) for f in args.fields]
    sets = {s for s, _, _ in fields}
    if len(sets) != 1:
        raise Usage("stream: give fields of one data set")
    set_id = sets.pop()
    found = _format_setting(conn.model, set_id)
    if found is None:
        raise Trouble(f"{PROG}: {capabilities.describe(conn.model)} has no message format for data set 0x{set_id:02X}")
    s, key = found
    base = read_base_rates(conn)
    hz = base.get(set_id)
    if not hz:
        _fail(f"no base rate known for data set 0x{set_id:02X}")
    rate = args.rate or hz
    if not 0 < rate <= hz:
        raise Usage(f"--rate {rate:g}: expected a rate above 0 and at most the base rate {hz:g} Hz")
    decimation = max(1, round(hz / rate))
    spec = _sim.FORMATS[s.cls]
    item_cls = _list_item_class(s)
    items = [item_cls(**{spec[2]: d, spec[3]: decimation}) for _, d, _ in fields]
    formats = read_formats(conn)
    formats[set_id] = [(d, decimation) for _, d, _ in fields]
    baud, where = link_baud(conn, args.baud)
    for line in check_budget(conn, formats, baud, where, args.force, base):
        _note(f"link budget: {line}")
    previous = st.read_entry(conn.device, s, key)
    entry = {**key, spec[1]: [json.loads(i.to_json()) if hasattr(i, "to_json") else i for i in items]}
    command = st.command_of(s, {**previous, **entry})
    count = 0
    first: Optional[float] = None
    last = 0.0
    closed = False

    def on_packet(packet: Any) -> None:
        nonlocal count, first, last, closed
        if packet.set != set_id:
            return
        now = time.monotonic()
        first = now if first is None else first
        last = now
        count += 1
        if (args.count and count > args.count) or closed:
            return
        try:
            if args.json:
                _say(packet.line())
            else:
                values = [
                    f"{e.name} {e.value.to_json()}"
                    for e in packet.fields
                    if hasattr(e, "value") and isinstance(e.value, Field)
                ]
                _say(" ".join(values))
        except BrokenPipeError:  # the reader went away (`stream ... | head`): stop quietly
            silence_stdout()
            closed = True

    conn.device.on_packet(on_packet)
    try:
        conn.device.call(command)
        _enable(conn, set_id)
        end = time.monotonic() + args.duration if args.duration else math.inf
        while time.monotonic() < end and not (args.count and count >= args.count) and not closed:
            conn.device.pump(int(min(200.0, max(0.0, end - time.monotonic()) * 1000)))
    except KeyboardInterrupt:
        pass
    finally:
        if not args.keep:
            try:
                conn.device.call(st.command_of(s, {**key, **previous}))
            except (SessionError, ValueError, OSError):
                _note("could not restore the previous message format")
    shown = min(count, args.count) if args.count else count
    observed = (count - 1) / (last - first) if first is not None and count > 1 and last > first else 0.0
    _note(
        f"{shown} packets of set 0x{set_id:02X}; observed {observed:.1f} Hz (configured {hz / decimation:g} Hz: base {hz:g} Hz / decimation {decimation})"
    )
    return 0 if count else 1


def _list_item_class(s: st.Setting) -> Any:
    hints = typing.get_type_hints(s.cls)
    spec = _sim.FORMATS[s.cls]
    hint = hints[spec[1]]
    for arg in getattr(hint, "__args__", ()):
        for inner in getattr(arg, "__args__", ()):
            if isinstance(inner, type):
                return inner
    _fail(f"{s.name}: cannot find its list's item type")


def _enable(conn: Connection, set_id: int) -> None:
    """Turn the data set's stream on where the model's stream control addresses it."""
    if set_id in (_sim.UNADDRESSED.get(conn.model) or []):
        return
    for cls, (selector, flag) in _sim.ENABLES.items():
        if getattr(cls, "DEVICE", None) not in (None, conn.model):
            continue
        if not capabilities.supports(conn.model, cls.SET, cls.DESCRIPTOR):
            continue
        hint = typing.get_type_hints(cls).get(flag)
        boolean = hint is bool or bool in getattr(hint, "__args__", ())
        values: Dict[str, Any] = {"function": _function_value("write"), flag: True if boolean else 1}
        for alt in selector:
            name, mapping = (alt, None) if isinstance(alt, str) else alt
            if name in cls._ATTRS:
                if mapping:
                    value = next((k for k, v in mapping.items() if v == set_id), None)
                    if value is None:
                        return
                    values[name] = value
                else:
                    values[name] = set_id
                break
        conn.device.call(cls.from_json(values))
        return


def subcommand_tools() -> types.SimpleNamespace:
    """What the subcommands in their own modules (timesync.py, ntrip.py) use of this command line
    (they cannot import it back: no import circle, no private names across modules)."""
    tools: Dict[str, Any] = dict(command_classes=_command_classes, function_value=_function_value, note=_note)
    tools.update(enable=_enable, format_setting=_format_setting, list_item_class=_list_item_class, st=st)
    return types.SimpleNamespace(read_base_rates=read_base_rates, trouble=Trouble, usage=Usage, **tools)


# ------------------------------------------------------------------------------------ auto
def scan(ports: Optional[Sequence[str]], model: Optional[str], timeout_ms: int) -> int:
    """Ping every serial port at the models' baud rates; one line per device that answers."""
    if ports is None:
        list_ports = _extras.need("serial.tools.list_ports", "device", lambda m: Trouble(f"auto: {m}"))
        ports = [p.device for p in list_ports.comports()]
    rates = _baud_rates()
    found = 0
    for path in ports:
        for rate in rates:
            try:
                conn = connect(path, model, rate, timeout_ms)
            except (Trouble, Usage):
                continue
            m = capabilities.MODELS[conn.model]
            _say(f"{path} {rate} {m.title} ({conn.model}) serial {conn.identity.get('serial_number', '?')}")
            conn.close()
            found += 1
            break
        else:
            _note(f"{path}: no answer at {', '.join(str(r) for r in rates)} baud")
    return 0 if found else 1


def _baud_rates() -> List[int]:
    """The rates to try: the default first, then every rate the spec lists for a model's main
    port (`_link.BAUD_RATES`), highest first."""
    others = {r for values in _link.BAUD_RATES.values() for r in values} - {DEFAULT_BAUD}
    return [DEFAULT_BAUD, *sorted(others, reverse=True)]


# ------------------------------------------------------------------------------------ main
def _common(defaults: bool) -> argparse.ArgumentParser:
    """The options of every subcommand. Given before the subcommand, the main parser reads them
    (with the defaults); after it, a subparser does, whose defaults are suppressed so that they do
    not overwrite what was given before it (argparse copies a subparser's defaults over)."""
    unset: Dict[str, Any] = {} if defaults else {"default": argparse.SUPPRESS}
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument(
        "--device",
        dest="model",
        metavar="ID",
        help=f"the model ({', '.join(registry.DEVICES)}); default: the one the device reports",
        **unset,
    )
    common.add_argument(
        "--baud",
        type=int,
        help="the serial port's baud rate (default 115200); over TCP: the rate the link budget is checked against",
        **unset,
    )
    common.add_argument(
        "--timeout-ms",
        type=int,
        help="reply timeout of each command (default 1000)",
        **(unset or {"default": 1000}),
    )
    common.add_argument("--ports", nargs="+", metavar="PATH", help="auto: scan only these serial ports", **unset)
    return common


def _parser() -> argparse.ArgumentParser:
    common = _common(False)
    p = argparse.ArgumentParser(
        prog=PROG,
        description="Look at, stream from and configure a device (docs/configure-a-device.md). "
        "Exit status: 0 done; 1 the device said no or differs; 2 nothing was changed (usage, bad file, refused before sending).",
        parents=[_common(True)],
    )
    p.add_argument("address", help="tcp:HOST:PORT, a serial port path, or auto")
    sub = p.add_subparsers(dest="subcommand", metavar="SUBCOMMAND", required=True)
    sub.add_parser("ping", parents=[common], help="ping the device")
    sub.add_parser("info", parents=[common], help="model, serial, firmware, descriptors, base rates, link budget")
    s = sub.add_parser("stream", parents=[common], help="set a message format and print the data")
    s.add_argument("fields", nargs="+", metavar="FIELD", help="data field names of one set (or SET:DESCRIPTOR)")
    s.add_argument("--rate", type=float, help="Hz (default: the base rate)")
    s.add_argument("--duration", type=float, help="seconds (default: until interrupted)")
    s.add_argument("--count", type=int, help="stop after N packets")
    s.add_argument("--json", action="store_true", help="canonical JSON lines")
    s.add_argument("--force", action="store_true", help="over the link budget: warn, do not refuse")
    s.add_argument("--keep", action="store_true", help="leave the message format set (default: restore it)")
    c = sub.add_parser("send", parents=[common], help="send one command: NAME [FUNCTION] [PARAM=VALUE ...]")
    c.add_argument("command")
    c.add_argument("arguments", nargs="*")
    c.add_argument("--json", action="store_true", help="the result as the session tool's JSON line")
    g = sub.add_parser(
        "settings", parents=[common], help="settings dump [FILE|-] | apply FILE [--save] | diff FILE | schema"
    )
    gs = g.add_subparsers(dest="action", metavar="ACTION", required=True)
    d = gs.add_parser("dump", parents=[common])
    d.add_argument("file", nargs="?")
    a = gs.add_parser("apply", parents=[common])
    a.add_argument("file")
    a.add_argument("--save", action="store_true", help="then save the settings as startup settings")
    a.add_argument("--force", action="store_true", help="over the link budget: warn, do not refuse")
    f = gs.add_parser("diff", parents=[common])
    f.add_argument("file")
    gs.add_parser("schema", parents=[common], help="print the path of the settings files' JSON Schema")
    r = sub.add_parser(
        "record",
        parents=[common],
        help="record the device's stream to FILE, its Device Information first (docs/record.md)",
    )
    r.add_argument("file", metavar="FILE")
    r.add_argument("--duration", type=float, help="seconds (default: until interrupted or the device goes away)")
    r.add_argument("--split-size", type=float, default=0, metavar="BYTES", help="a new file once one holds BYTES")
    r.add_argument("--split-time", type=float, default=0.0, metavar="S", help="a new file every S seconds")
    ntrip_parser(sub, common)  # ntrip.py
    # timesync: device/timesync.py, docs/timesync.md
    t = sub.add_parser(
        "timesync", parents=[common], help="set up time synchronization and monitor it (docs/timesync.md)"
    )
    t.add_argument("--duration", type=float, default=30.0, help="seconds (default 30)")
    t.add_argument("--json", action="store_true", help="one JSON object a line")
    t.add_argument(
        "--pps-source", metavar="NAME", help="models with a PPS source setting: the source (default: a receiver)"
    )
    sub.add_parser("save-startup", parents=[common], help="save the current settings as startup settings")
    sub.add_parser("factory-reset", parents=[common], help="load the factory default settings")
    return p


COMMANDS = {
    "ping": cmd_ping,
    "info": cmd_info,
    "stream": cmd_stream,
    "send": cmd_send,
    "save-startup": cmd_save,
    "factory-reset": cmd_factory,
}
SETTINGS = {"dump": cmd_dump, "apply": cmd_apply, "diff": cmd_diff}


def main(argv: Optional[List[str]] = None) -> int:
    args = _parser().parse_args(sys.argv[1:] if argv is None else argv)
    try:
        return flushed(_main(args))
    except BrokenPipeError:  # stdout closed by its reader (`settings dump - | head`): quietly, by SIGPIPE
        return closed_stdout()


def _main(args: argparse.Namespace) -> int:
    """The subcommand run: its exit status, every error one line on stderr."""
    conn: Optional[Connection] = None
    try:
        if args.model is not None and args.model not in registry.DEVICES:
            raise Usage(f"unknown device {args.model!r} (one of: {', '.join(registry.DEVICES)})")
        if args.subcommand == "settings" and args.action == "schema":
            _say(st.schema_path())
            return 0
        if args.address == "auto":
            if args.subcommand != "ping":
                raise Usage("auto lists the devices that answer: use `auto ping`")
            return scan(args.ports, args.model, min(args.timeout_ms, 300))
        if args.subcommand == "record":  # the device's own bytes: no session in between
            from .record import record

            return record(
                args.address,
                args.file,
                args.baud or DEFAULT_BAUD,
                args.timeout_ms,
                args.duration,
                args.split_size,
                args.split_time,
            )
        if args.subcommand == "ntrip":  # corrections from a caster (ntrip.py: connects when it needs the device)
            from . import ntrip

            return ntrip.main(
                args, lambda: connect(args.address, args.model, args.baud, args.timeout_ms), subcommand_tools()
            )
        precheck_apply(args)  # with --device: refused before any byte is sent
        conn = connect(args.address, args.model, args.baud, args.timeout_ms)
        if args.subcommand == "settings":
            return SETTINGS[args.action](conn, args)
        if args.subcommand == "timesync":  # device/timesync.py
            from .timesync import TimeSync, check_duration

            check_duration(args.duration)
            return TimeSync(conn, args.pps_source, args.json, _say, tools=subcommand_tools()).run(args.duration)
        return COMMANDS[args.subcommand](conn, args)
    except Usage as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    except Trouble as e:
        text = str(e)
        print(text if text.startswith(PROG) else f"{PROG}: {text}", file=sys.stderr)
        return 2
    except st.FileError as e:
        for line in e.lines:
            print(line, file=sys.stderr)
        print(f"{PROG}: {len(e.lines)} problem(s) in the settings file; nothing was written", file=sys.stderr)
        return 2
    except Refused as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 1
    except CommandRefused as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    except SessionError as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 1
    except ValueError as e:  # a value the spec's layouts refuse
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # stdout closed by its reader: main's
        raise
    except (TransportError, OSError) as e:
        print(f"{PROG}: {getattr(e, 'strerror', None) or e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
    finally:
        if conn is not None:
            conn.close()


if __name__ == "__main__":
    sys.exit(main())
