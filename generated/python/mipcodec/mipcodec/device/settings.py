"""Settings as data (docs/configure-a-device.md): read every setting of a connected model into a
YAML file keyed by command name, check a file against the spec and the model, and write only what
differs.

A setting is a command with the write and read functions that the spec's `settings` section does
not exclude (`_settings.SETTINGS`, generated). Its entry in a file holds the parameters of its
write (enum members by name, the counts of lists left out: they follow from the lists); a setting
read per key parameter (the parameters its read sends: a port, a data set) is a list of entries,
each with its key parameters, read for the key values the spec's `settings: keys` gives. The
file's JSON Schema is `settings.schema.json` at the package's top, generated from the spec.

Needs PyYAML (the package's `device` extra).
"""

from __future__ import annotations

import json
import typing
from typing import Any, Dict, List, NamedTuple, Optional, Tuple

from .. import _extras, _settings, capabilities
from ..codec.layout import EncodeError, Enum, Field
from ..session import support_error

READ = 2
WRITE = 1


class Setting(NamedTuple):
    cls: Any  # the command class (its layout for the model)
    reply: Any  # the class of its read's reply field
    name: str
    ident: Tuple[int, int]
    key_attrs: Tuple[str, ...]  # parameters sent with read
    attrs: Tuple[Tuple[str, str, Optional[str]], ...]  # (attribute, reply attribute, units)
    counts: Tuple[Tuple[str, str], ...]  # (count attribute, list attribute)
    keys: Tuple[Tuple[Tuple[str, int], ...], ...]  # the key combinations read by dump
    fill: Tuple[Tuple[str, Any], ...]  # written but not read back (a reserved byte): these values

    @property
    def keyed(self) -> bool:
        return bool(self.key_attrs)


class FileError(Exception):
    """Located errors of a settings file: one `FILE:LINE: message` line each."""

    def __init__(self, lines: List[str]) -> None:
        super().__init__("\n".join(lines))
        self.lines = lines


def settings_for(device: str) -> List[Setting]:
    """The settings of a model, in the spec's order."""
    return [Setting(cls, reply, *row) for cls, reply, row in _settings.SETTINGS.get(device, ())]


def known_names() -> Dict[str, List[str]]:
    """Every setting name of the protocol -> the models that have it."""
    out: Dict[str, List[str]] = {}
    for device, rows in _settings.SETTINGS.items():
        for _, _, row in rows:
            out.setdefault(row[0], []).append(device)
    return out


def enum_types(cls: Any) -> Dict[str, Any]:
    """attribute -> its enum class, for the enum parameters of a command class."""
    out: Dict[str, Any] = {}
    try:
        hints = typing.get_type_hints(cls)
    except Exception:  # noqa: BLE001 - annotations that do not resolve: no enum names
        return out
    for attr, hint in hints.items():
        for arg in getattr(hint, "__args__", (hint,)):
            if isinstance(arg, type) and issubclass(arg, Enum):
                out[attr] = arg
    return out


def enum_name(cls: Any, value: Any) -> Any:
    """The member name (lower case) of an enum value, or the integer when the spec names none."""
    member = cls._value2member_map_.get(int(value))
    return member.name.lower() if member is not None else int(value)


def enum_value(cls: Any, value: Any) -> Any:
    if isinstance(value, str):
        member = cls.__members__.get(value.upper())
        if member is None:
            names = ", ".join(m.lower() for m in cls.__members__)
            raise ValueError(f"{value!r} is not a member of {cls.__name__} (one of: {names})")
        return int(member)
    return value


# ------------------------------------------------------------------------- values <-> commands
def plain_of_reply(setting: Setting, reply: Field) -> Dict[str, Any]:
    """The file entry of one read reply: the write's parameters, enum members by name."""
    values = json.loads(reply.to_json())
    enums = enum_types(setting.cls)
    out: Dict[str, Any] = {}
    for attr, reply_attr, _ in setting.attrs:
        v = values.get(reply_attr)
        if attr in enums and isinstance(v, int):
            v = enum_name(enums[attr], v)
        out[attr] = v
    return out


def command_of(setting: Setting, entry: Dict[str, Any], function: int = WRITE) -> Field:
    """The command that writes a file entry (or reads it, function 2, with its key parameters only).
    Raises ValueError naming the parameter."""
    enums = enum_types(setting.cls)
    values: Dict[str, Any] = {"function": function}
    attrs = setting.key_attrs if function != WRITE else tuple(a for a, _, _ in setting.attrs)
    for attr in attrs:
        if attr not in entry:
            raise ValueError(f"{setting.name}: missing parameter {attr!r}")
        v = entry[attr]
        if attr in enums:
            try:
                v = enum_value(enums[attr], v)
            except ValueError as e:
                raise ValueError(f"{setting.name}.{attr}: {e}") from None
        values[attr] = v
    if function == WRITE:
        for attr, v in setting.fill:
            values[attr] = v
        for count, lst in setting.counts:
            items = values.get(lst)
            values[count] = len(items) if isinstance(items, list) else 0
    try:
        return setting.cls.from_json(values, f"{setting.name}.")  # type: ignore[no-any-return]
    except (EncodeError, ValueError, TypeError) as e:
        raise ValueError(str(e)) from None


def normalized(setting: Setting, entry: Dict[str, Any]) -> Dict[str, Any]:
    """An entry as the device would report it: through the command's encoding (f32 rounding,
    enum names), so a file and a device compare equal when the wire values are."""
    command = command_of(setting, entry)
    try:  # through the wire: a float is what its f32 carries
        command = setting.cls.decode(command.encode())
    except (EncodeError, ValueError) as e:
        raise ValueError(f"{setting.name}: {e}") from None
    values = json.loads(command.to_json())
    for _, lst in setting.counts:  # an empty list decodes as absent
        if values.get(lst) is None:
            values[lst] = []
    enums = enum_types(setting.cls)
    out = {}
    for attr, _, _ in setting.attrs:
        v = values.get(attr)
        if attr in enums and isinstance(v, int):
            v = enum_name(enums[attr], v)
        out[attr] = v
    return out


def key_of(setting: Setting, entry: Dict[str, Any]) -> Tuple[Any, ...]:
    enums = enum_types(setting.cls)
    out = []
    for attr in setting.key_attrs:
        v = entry.get(attr)
        if attr in enums and isinstance(v, str):
            v = enum_value(enums[attr], v)
        out.append(v)
    return tuple(out)


# ---------------------------------------------------------------------------------- reading
def read_entry(device: Any, setting: Setting, key: Dict[str, Any]) -> Dict[str, Any]:
    """Reads one setting (for one key combination) from a session.Device; raises SessionError."""
    result = device.call(command_of(setting, key, READ))
    reply = result.response
    if reply is None or not isinstance(reply, setting.reply):
        raise ValueError(f"{setting.name}: the read's reply carries no {setting.reply.NAME}")
    return plain_of_reply(setting, reply)


def read_all(device: Any, model: str, warn: Any = None) -> Dict[str, Any]:
    """Every setting of the model: name -> entry, or a list of entries for a keyed setting. A read
    the device refuses (NACK) is reported through `warn` and left out."""
    from ..session import Nack

    out: Dict[str, Any] = {}
    for s in settings_for(model):
        try:
            if s.keyed:
                out[s.name] = [read_entry(device, s, dict(k)) for k in s.keys]
            else:
                out[s.name] = read_entry(device, s, {})
        except Nack as e:
            if warn is not None:
                warn(f"{s.name}: not read ({e})")
    return out


# ------------------------------------------------------------------------------------ YAML
def flow_text(value: Any) -> str:
    import yaml  # type: ignore[import-untyped, unused-ignore]

    text: str = yaml.safe_dump(value, default_flow_style=True, width=1 << 30, sort_keys=False).strip()
    if text.endswith("\n..."):
        text = text[: -len("\n...")].strip()
    return text


def dump_text(values: Dict[str, Any], model: str, header: List[str]) -> str:
    """The YAML text of a dump: a header of comments, `device:`, then one block per setting in the
    spec's order, each parameter on its own line with its units as a comment."""
    lines = [f"# {h}" for h in header]
    lines.append(f"device: {model}")
    for s in settings_for(model):
        if s.name not in values:
            continue
        value = values[s.name]
        units = {a: u for a, _, u in s.attrs}
        lines.append(f"{s.name}:")
        entries = value if s.keyed else [value]
        for entry in entries:
            first = True
            for attr, v in entry.items():
                prefix = ("  - " if first else "    ") if s.keyed else "  "
                comment = f"  # {units[attr]}" if units.get(attr) else ""
                lines.append(f"{prefix}{attr}: {flow_text(v)}{comment}")
                first = False
            if s.keyed and not entry:
                lines.append("  - {}")
    return "\n".join(lines) + "\n"


class _Lines:
    """Line numbers of a loaded mapping's keys or a sequence's items (1-based)."""

    line = 0
    lines: Dict[Any, int]


class LineDict(dict, _Lines):  # type: ignore[type-arg]
    pass


class LineList(list, _Lines):  # type: ignore[type-arg]
    pass


def load_text(text: str, filename: str) -> Any:
    """The YAML document with line numbers (LineDict, LineList); raises FileError."""
    try:
        import yaml  # type: ignore[import-untyped, unused-ignore]
    except ImportError:
        raise FileError([f"{filename}: reading settings files: {_extras.missing('yaml', 'device')}"]) from None

    class Loader(yaml.SafeLoader):  # type: ignore[misc, unused-ignore]
        pass

    def mapping(loader: Any, node: Any) -> LineDict:
        loader.flatten_mapping(node)
        d = LineDict()
        d.line = node.start_mark.line + 1
        d.lines = {}
        for k_node, v_node in node.value:
            key = loader.construct_object(k_node, deep=True)
            line = k_node.start_mark.line + 1
            if not isinstance(key, str):
                raise FileError([f"{filename}:{line}: a key must be a name, not {key!r}"])
            if key in d:
                raise FileError([f"{filename}:{line}: {key!r} given twice (first on line {d.lines[key]})"])
            d[key] = loader.construct_object(v_node, deep=True)
            d.lines[key] = line
        return d

    def sequence(loader: Any, node: Any) -> LineList:
        out = LineList()
        out.line = node.start_mark.line + 1
        out.lines = {}
        for i, item in enumerate(node.value):
            out.append(loader.construct_object(item, deep=True))
            out.lines[i] = item.start_mark.line + 1
        return out

    Loader.add_constructor("tag:yaml.org,2002:map", mapping)
    Loader.add_constructor("tag:yaml.org,2002:seq", sequence)
    try:
        doc = yaml.load(text, Loader=Loader)  # noqa: S506 - a SafeLoader subclass
    except yaml.MarkedYAMLError as e:
        mark = e.problem_mark or e.context_mark
        line = mark.line + 1 if mark is not None else 1
        raise FileError([f"{filename}:{line}: not valid YAML: {e.problem or e}"]) from None
    except yaml.YAMLError as e:
        raise FileError([f"{filename}:1: not valid YAML: {e}"]) from None
    if doc is None:
        doc = LineDict()
        doc.line = 1
        doc.lines = {}
    if not isinstance(doc, LineDict):
        raise FileError([f"{filename}:1: expected a mapping of setting names to values"])
    return doc


class Planned(NamedTuple):
    setting: Setting
    entries: List[Dict[str, Any]]  # normalized file entries
    lines: List[int]  # each entry's line


def validate(doc: Any, model: str, filename: str) -> List[Planned]:
    """Every setting of the file checked against the spec and the model; raises FileError with
    every problem found (the whole file is checked before anything is written)."""
    errors: List[str] = []
    ours = {s.name: s for s in settings_for(model)}
    known = known_names()
    manual = capabilities.describe(model)
    planned: List[Planned] = []
    for name, value in doc.items():
        line = doc.lines[name]
        where = f"{filename}:{line}"
        if name == "device":
            if value != model:
                errors.append(f"{where}: the file is for {value!r}, the connected model is {model} ({manual})")
            continue
        s = ours.get(name)
        if s is None:
            if name in known:
                errors.append(f"{where}: {name} is not supported by {manual} (a setting of {', '.join(known[name])})")
            else:
                errors.append(f"{where}: unknown setting {name!r} (not a setting of the spec's commands)")
            continue
        refused = support_error(s.cls(function=WRITE), model)
        if refused:
            errors.append(f"{where}: {refused}")
            continue
        items = value if s.keyed else [value]
        if s.keyed and not isinstance(value, list):
            errors.append(f"{where}: {name} is read per {', '.join(s.key_attrs)}: expected a list of entries")
            continue
        entries: List[Dict[str, Any]] = []
        lines: List[int] = []
        seen: Dict[Tuple[Any, ...], int] = {}
        for i, entry in enumerate(items):
            eline = value.lines.get(i, line) if isinstance(value, LineList) else line
            if not isinstance(entry, dict):
                errors.append(f"{filename}:{eline}: {name}: expected a mapping of parameter names to values")
                continue
            allowed = [a for a, _, _ in s.attrs]
            bad = False
            for attr in entry:
                if attr not in allowed:
                    aline = entry.lines.get(attr, eline) if isinstance(entry, LineDict) else eline
                    errors.append(
                        f"{filename}:{aline}: {name}: unknown parameter {attr!r} (expected: {', '.join(allowed)})"
                    )
                    bad = True
            missing = [a for a in allowed if a not in entry]
            if missing:
                errors.append(f"{filename}:{eline}: {name}: missing {', '.join(missing)}")
                bad = True
            if bad:
                continue
            try:
                norm = normalized(s, dict(entry))
            except ValueError as e:
                errors.append(f"{filename}:{_line_of(entry, str(e), eline)}: {e} ({manual})")
                continue
            key = key_of(s, norm)
            if s.keyed and key in seen:
                errors.append(
                    f"{filename}:{eline}: {name}: the entry for {_key_text(s, norm)} is given twice (first on line {seen[key]})"
                )
                continue
            seen[key] = eline
            entries.append(norm)
            lines.append(eline)
        planned.append(Planned(s, entries, lines))
    if errors:
        raise FileError(errors)
    return planned


def _line_of(entry: Any, message: str, default: int) -> int:
    """The line of the parameter an encoder message names (`name.attr...: ...`)."""
    if isinstance(entry, LineDict):
        for token in message.replace(":", " ").split():
            parts = token.replace("[", ".").split(".")
            for p in parts[:2]:
                if p in entry.lines:
                    return entry.lines[p]
    return default


def _key_text(s: Setting, entry: Dict[str, Any]) -> str:
    return ", ".join(f"{a} {entry.get(a)}" for a in s.key_attrs)


class Change(NamedTuple):
    setting: Setting
    key: str  # "" or "port 17"
    device: Optional[Dict[str, Any]]  # None: the device's read failed
    file: Dict[str, Any]


def differences(device: Any, planned: List[Planned]) -> List[Change]:
    """The file's entries that differ from what the device reads now."""
    out = []
    for p in planned:
        for entry in p.entries:
            key = {a: entry[a] for a in p.setting.key_attrs}
            current = read_entry(device, p.setting, key)
            current_norm = normalized(p.setting, current)
            if current_norm != entry:
                out.append(Change(p.setting, _key_text(p.setting, entry), current_norm, entry))
    return out


def changed_params(old: Optional[Dict[str, Any]], new: Dict[str, Any]) -> List[str]:
    """`attr: old -> new` for each parameter that differs."""
    out = []
    for attr, v in new.items():
        before = None if old is None else old.get(attr)
        if before != v:
            out.append(f"{attr}: {flow_text(before)} -> {flow_text(v)}")
    return out


def schema_path() -> str:
    """The path of the settings files' JSON Schema (generated from the spec)."""
    import os

    return os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "settings.schema.json")
