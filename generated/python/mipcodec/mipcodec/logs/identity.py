"""A log's identity: its device information reply (model, serial, firmware), the registry device
it names and the per-device decode of a `decode_columns` block for that device; the reading of a
local log (`file_reader`, `ReadError`). Used by the dataset (dataset.py) and by the log pipeline
(pipeline.py) of every log tool."""

from __future__ import annotations

import importlib
import os
import re
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional, Tuple

from .. import registry
from .._protocol import CHECKSUM_SIZE, HEADER_SIZE, LENGTH_OFFSET, MAX_PACKET, SYNC

UNKNOWN = "unknown"  # model / serial of a log that names neither, without --model / --serial
ReadAt = Callable[[int, int], bytes]


class ReadError(Exception):
    """A log that cannot be read (recorded in `_files` as `unreadable`, the run goes on)."""


def file_reader(path: str) -> Tuple[ReadAt, int]:
    """(read_at(offset, length) -> bytes, size) of a local file; an OSError reading it is a
    ReadError (so that it is told apart from a failed write)."""
    try:
        size = os.path.getsize(path)
        if os.path.isdir(path):
            raise ReadError("is a directory")
    except OSError as e:
        raise ReadError(e.strerror or str(e)) from None

    def read_at(offset: int, length: int) -> bytes:
        try:
            with open(path, "rb") as f:
                f.seek(offset)
                return f.read(length)
        except OSError as e:
            raise ReadError(e.strerror or str(e)) from None

    return read_at, size


# ------------------------------------------------------------------------------ the identity
@dataclass(frozen=True)
class Identity:
    """Partition values and file metadata of a log: model, serial (never empty), firmware or None."""

    model: str = UNKNOWN
    serial: str = UNKNOWN
    firmware: Optional[str] = None


def partition_value(text: Optional[str]) -> str:
    """A model or serial as a partition value: stripped; characters a path or Hive partition
    cannot hold (/ \\ = : and control characters) as '-'; empty -> `unknown`."""
    t = re.sub(r"[/\\=:\x00-\x1f\x7f]", "-", (text or "").strip())
    return t or UNKNOWN


def model_slug(name: str) -> str:
    """The model partition value of a reported model name: lower case, runs of other characters
    than letters and digits as '-' ("3DM-GX5-45" -> "3dm-gx5-45")."""
    return re.sub(r"[^a-z0-9]+", "-", name.strip().lower()).strip("-") or UNKNOWN


def identity_from_packet(packet: Any) -> Optional[Identity]:
    """The identity a decoded packet reports when it is a device information reply, else None."""
    reports = identity_reports()
    from ..codec.packets import DecodedField

    for f in packet.fields:
        if not isinstance(f, DecodedField):
            continue
        items = reports.get(type(f.value))
        if items is None:
            continue
        found: Dict[str, Any] = {}
        for path, item, _fmt in items:
            v: Any = f.value
            for name in path:
                v = getattr(v, name, None)
            if isinstance(v, (bytes, bytearray)):
                v = bytes(v).decode("latin-1")
            if isinstance(v, str):
                v = v.strip(" \x00")
            found[item] = v
        model = str(found.get("model_name") or "").strip()
        serial = str(found.get("serial_number") or "").strip()
        firmware = found.get("firmware")
        return Identity(
            model_slug(model) if model else UNKNOWN,
            partition_value(serial),
            None if firmware is None else str(firmware),
        )
    return None


def identity_reports() -> Dict[Any, Any]:
    """Device information reply class -> its identity items (the generated `_identity.IDENTITY_REPORTS`)."""
    try:
        sim = importlib.import_module(".._identity", __package__)
    except ImportError:
        return {}
    reports: Dict[Any, Any] = getattr(sim, "IDENTITY_REPORTS", {})
    return reports


def log_identity(read_at: ReadAt, size: int, model: Optional[str] = None, serial: Optional[str] = None) -> Identity:
    """The log's identity: from its first device information reply (Get Device Information,
    searched through the whole log in pieces), else `model` / `serial` (as given, made partition
    safe), else `unknown`. A reply's values win over the options."""
    from ..codec.packets import Packet, decode_all

    reports = identity_reports()
    sets = {cls.SET for cls in reports if getattr(cls, "SET", None) is not None}
    found: Optional[Identity] = None
    for set_id in sorted(sets):
        needle = bytes(SYNC) + bytes([set_id])
        pos = 0
        piece = 1 << 20  # doubled up to 16 MiB: the reply is mostly near the start (one read, not 16 MiB)
        while pos < size and found is None:
            data = read_at(pos, min(piece + MAX_PACKET, size - pos))
            i = data.find(needle)
            while 0 <= i < min(piece, len(data)) and found is None:
                for e in decode_all(data[i : i + MAX_PACKET]):
                    if isinstance(e, Packet):
                        found = identity_from_packet(e)
                    break  # only the packet at i
                i = data.find(needle, i + 1)
            pos += piece
            piece = min(2 * piece, 16 << 20)
        if found is not None:
            break
    fallback = Identity(
        partition_value(model) if model else UNKNOWN, partition_value(serial) if serial else UNKNOWN, None
    )
    if found is None:
        return fallback
    return Identity(
        found.model if found.model != UNKNOWN else fallback.model,
        found.serial if found.serial != UNKNOWN else fallback.serial,
        found.firmware,
    )


def plain_name(text: str) -> str:
    """Upper case without spaces and punctuation; a character outside ASCII is kept (it matches no
    model name: the spec's are ASCII). The rule of every language (generator/linkfacts.py)."""
    return "".join(c for c in text.upper() if (c.isascii() and c.isalnum()) or not c.isascii())


def model_matches(name: str, device: str) -> bool:
    """True when a reported model name is the device's: its title or the spec's identity model
    name, compared without case, spaces and punctuation (MS_IMU3020 is MS-IMU3020). Here rather
    than in the session (which uses it) so that the log tools need not import the session and the
    simulator's tables (`_sim`, every command module: a tenth of a second of every log command)."""
    from .. import capabilities

    try:
        known_ids: Dict[str, Dict[str, Any]] = importlib.import_module(".._identity", __package__).IDENTITY
    except (ImportError, AttributeError):
        known_ids = {}
    known = (capabilities.MODELS[device].title, str(known_ids.get(device, {}).get("model_name", "")))
    return bool(plain_name(name)) and plain_name(name) in {plain_name(k) for k in known if k}


def device_of(model: str) -> Optional[str]:
    """The registry device id of a log's model partition value: a device id as given (`--model
    cv7_ins`), or the device whose model name the reported one is (`3dm-cv7-gnss-ins` is the
    3DM-CV7-GNSS/INS: compared without case and punctuation, `model_matches`); None when it is
    none of them (`unknown`)."""
    if model in registry.DEVICES:
        return model
    return next((d for d in registry.DEVICES if model != UNKNOWN and model_matches(model, d)), None)


def for_device(cols: Any, data: bytes, device: Optional[str]) -> None:
    """Decode the fields that have per-device layouts with the log's device: decode_columns
    decodes them with the first device's layout (it has no device argument). A table whose layout
    `device` reads the same way (`_same_wire_layout`) keeps its rows under `device`'s class; the
    rows of any other move to `cols.others` as the packet decoder gives them for `device`.
    Nothing changes for device None."""
    if device is None:
        return
    from ..codec.packets import DecodedField, Table, decode_packet

    def redo(off: int, k: int) -> Any:
        n = HEADER_SIZE + data[off + LENGTH_OFFSET] + CHECKSUM_SIZE
        return decode_packet(bytes(data[off : off + n]), off, device, check=False).fields[k]

    moved: List[Tuple[int, int, Any]] = []
    for key, t in list(cols.tables.items()):
        dev = getattr(t.cls, "DEVICE", None)
        if dev is None or dev == device or t.rows == 0:
            continue
        same = _same_wire_layout(t.cls, device)
        if same is not None:  # the same numbers read the same way: the rows stay, named for `device`
            cols.tables[key] = Table(
                t.set, t.descriptor, same, t.rows, t._raw_offsets, t._raw_index, [t._raw[item[0]] for item in t._items]
            )
            continue
        moved.extend((int(o), int(k), redo(int(o), int(k))) for o, k in zip(t.offsets, t.index))
        del cols.tables[key]
    others: List[Tuple[int, int, Any]] = []
    for off, k, entry in cols.others:
        dev = getattr(getattr(entry, "value", None), "DEVICE", None) if isinstance(entry, DecodedField) else None
        others.append((off, k, redo(off, k)) if dev is not None and dev != device else (off, k, entry))
    if moved or others != cols.others:
        cols.others = sorted(others + moved, key=lambda x: (x[0], x[1]))


def _same_wire_layout(cls: Any, device: str) -> Any:
    """The layout class of `device` for the field of `cls` when the C accelerator reads both the
    same way (`fast_items`: the same attributes, kinds, sizes and counts, in order; enums and
    bit fields are kept as their wire numbers, so only their names differ), else None."""
    from ..codec.layout import fast_items

    mine = fast_items(cls)
    for other in registry.lookup(cls.SET, cls.DESCRIPTOR) or ():
        if getattr(other, "DEVICE", None) != device:
            continue
        theirs = fast_items(other)
        if mine is not None and theirs is not None and [i[:4] for i in mine] == [i[:4] for i in theirs]:
            return other
        return None
    return None
