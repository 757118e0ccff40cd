"""MCAP files of a log (docs/mcap.md): `python -m <package> export LOG --format mcap --out FILE.mcap`
and the recorder's `<package>-device ADDRESS record FILE.mcap`.

On the log pipeline (pipeline.py): the log's device (its Device Information reply, else
`--device`), the one time model (`PacketClock`), the CSV export's values (`writers.Layout`).
Each packet gives:

- a JSON message per data field on `/<protocol>/<set>/<field>` (`shared/` before a shared field
  the packet carries), with the generated JSON Schema of its layout (`_mcap_schemas`);
- the ROS 2 messages the mapping table (ros.py) makes of its fields, in CDR.

**Time.** log_time = publish_time = the packet's UTC ns from the time model, never decreasing in
the file (a backward step of the device's time is kept in the message's `t_ns` / `header.stamp`,
while its log_time stays at the last one). A packet without a known time: its ROS messages are left
out (a ROS header needs a time); its JSON messages are kept, with the log_time of the first known
time when none came before it, else of the last known time; a log with no known time at all has
them at the log file's modification time (for a recording: the end of the recording).

**Metadata** (`device`): model, serial, firmware, device id and where it came from; (`protocol`):
package, version, protocol, spec hash. Chunked (1 MiB), zstd-compressed, indexed, with statistics
and a summary (the `mcap` library's writer; the package's `[mcap]` extra).

**Whole or nothing.** The file is written under a temporary name beside FILE and renamed when it
is finished (`writers.Outputs`): a full disk, a crash or Ctrl-C leaves no partial FILE.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
from typing import Any, Dict, List, Optional, Tuple

from .. import _mcap_schemas, registry
from .._protocol import PACKAGE as PROG
from ..codec.packets import DecodedField, Packet
from . import ros
from .pipeline import LogDevice, PacketClock
from .writers import COLUMN_SETS, Events, Layout, Outputs, Source, ToolError, f32_text, need, table_name

CHUNK_SIZE = 1 << 20


def add_options(e: argparse.ArgumentParser) -> None:
    """`export`'s MCAP options."""
    e.add_argument(
        "--topic-prefix", default="", metavar="P", help="--format mcap: put every topic under /P (default: none)"
    )
    e.add_argument(
        "--frame",
        action="append",
        default=[],
        metavar="NAME=ID",
        help="--format mcap: the frame id of a frame (imu_link, base_link, odom, gnss_link by default; "
        "NAME one of sensor, vehicle, odom, gnss); repeatable",
    )


def topics_of(prefix: str, frames: List[str]) -> ros.Topics:
    mapping: Dict[str, str] = {}
    for item in frames:
        name, eq, value = item.partition("=")
        if not eq or not name or not value:
            raise ToolError(f"--frame: expected NAME=ID, not {item!r}")
        mapping[name] = value
    try:
        return ros.Topics(prefix, mapping)
    except ValueError as e:
        raise ToolError(str(e)) from None


def _cell(kind: str, cell: Any) -> Any:
    """A CSV cell as a JSON value (the schema's leaves)."""
    if cell is None:
        return None
    if kind == "json":
        return json.loads(cell)
    if kind == "float32":
        return float(f32_text(cell)) if math.isfinite(cell) else None
    if kind == "float64":
        return cell if math.isfinite(cell) else None
    return cell


def _put(obj: Any, path: Tuple[Any, ...], value: Any) -> None:
    for i, step in enumerate(path):
        last = i == len(path) - 1
        nxt = path[i + 1] if not last else None
        empty: Any = [] if isinstance(nxt, int) else {}
        if isinstance(step, int):
            while len(obj) <= step:
                obj.append(None)
            if last:
                obj[step] = value
            else:
                if obj[step] is None:
                    obj[step] = empty
                obj = obj[step]
        elif last:
            obj[step] = value
        else:
            obj = obj.setdefault(step, empty)


def json_message(specs: Any, cells: List[Any], t_ns: Optional[int], offset: int) -> Dict[str, Any]:
    """The JSON message of one decoded field (docs/mcap.md; its schema: `_mcap_schemas`)."""
    out: Dict[str, Any] = {"t_ns": t_ns, "log_offset": offset}
    for (_name, path, _units, kind, _enum), cell in zip(specs, cells):
        if len(path) == 1:  # a parameter (the most of them)
            out[path[0]] = _cell(kind, cell)
        else:
            _put(out, tuple(path), _cell(kind, cell))
    return out


class McapLog:
    """The MCAP writer of one log's packets (in log order, each with its UTC ns or None)."""

    def __init__(self, stream: Any, device: LogDevice, topics: ros.Topics, fallback_ns: int) -> None:
        writer_mod = need("mcap.writer", "mcap")
        self.device = device
        self.topics = topics
        self.fallback_ns = fallback_ns
        self.writer = writer_mod.Writer(stream, chunk_size=CHUNK_SIZE, compression=writer_mod.CompressionType.ZSTD)
        from .. import __version__

        self.writer.start(profile="ros2", library=f"{PROG} {__version__}")
        self.schemas: Dict[str, int] = {}
        self.channels: Dict[str, int] = {}
        self.sequence: Dict[int, int] = {}
        self.layouts: Dict[Any, Layout] = {}
        self.mapper = ros.Mapper(topics, device.device)
        self.last: Optional[int] = None  # the last log_time written
        self.waiting: List[Tuple[int, bytes]] = []  # JSON messages before the first known time
        self.counts: Dict[str, int] = {}
        self.json_channels: Dict[Tuple[int, Any], Tuple[int, str]] = {}

    def _channel(self, topic: str, schema: str, encoding: str, data: bytes, message_encoding: str) -> int:
        cid = self.channels.get(topic)
        if cid is None:
            sid = self.schemas.get(schema)
            if sid is None:
                sid = self.schemas[schema] = self.writer.register_schema(name=schema, encoding=encoding, data=data)
            cid = self.channels[topic] = self.writer.register_channel(
                topic=topic, message_encoding=message_encoding, schema_id=sid
            )
        return cid

    def _write(self, cid: int, log_time: int, data: bytes) -> None:
        seq = self.sequence.get(cid, 0)
        self.sequence[cid] = seq + 1
        self.writer.add_message(channel_id=cid, log_time=log_time, data=data, publish_time=log_time, sequence=seq)

    def _json_channel(self, set_id: int, cls: Any) -> int:
        found = self.json_channels.get((set_id, cls))
        if found is None:
            found = self.json_channels[(set_id, cls)] = self._new_json_channel(set_id, cls)
        cid, topic = found
        self.counts[topic] = self.counts.get(topic, 0) + 1
        return cid

    def _new_json_channel(self, set_id: int, cls: Any) -> Tuple[int, str]:
        name = table_name(set_id, cls)
        if cls.DEVICE:
            name = name[: -len(cls.DEVICE) - 1]
        topic = self.topics.topic(f"{_mcap_schemas.PROTOCOL}/{name.replace('.', '/')}")
        key = (cls.SET, cls.DESCRIPTOR, cls.DEVICE)
        schema = f"{_mcap_schemas.PROTOCOL}.{registry.SET_NAMES.get(cls.SET, cls.SET)}.{cls.NAME}"
        if cls.DEVICE:
            schema += f".{cls.DEVICE}"
        return self._channel(topic, schema, "jsonschema", _mcap_schemas.SCHEMAS[key].encode(), "json"), topic

    def packet(self, p: Packet, t_ns: Optional[int]) -> None:
        set_name = registry.SET_NAMES.get(p.set)
        if set_name is None or p.set not in COLUMN_SETS:
            return
        log_time: Optional[int] = None
        if t_ns is not None:
            log_time = t_ns if self.last is None else max(self.last, t_ns)
            if self.last is None:
                self._release(log_time)
            self.last = log_time
        elif self.last is not None:
            log_time = self.last
        values = ros.Values()
        for f in p.fields:
            if not isinstance(f, DecodedField):
                continue
            cls = type(f.value)
            key = (cls.SET, cls.DESCRIPTOR, cls.DEVICE)
            if key not in _mcap_schemas.SCHEMAS:
                continue
            lay = self.layouts.get(cls)
            if lay is None:
                lay = self.layouts[cls] = Layout(cls, False)
            cells = lay.cells(f.value)
            values.add(key, cells)
            data = json.dumps(json_message(lay.specs, cells, t_ns, p.offset), separators=(",", ":")).encode()
            cid = self._json_channel(p.set, cls)
            if log_time is None:
                self.waiting.append((cid, data))
            else:
                self._write(cid, log_time, data)
        if t_ns is None or log_time is None:
            return  # no ROS message without a time
        self._ros(self.mapper.messages(set_name, values, t_ns, log_time))

    def _ros(self, messages: List[Tuple[int, ros.Message]]) -> None:
        for log_time, (topic, ros_type, msg) in messages:
            cid = self._channel(topic, ros.schema_name(ros_type), "ros2msg", ros.definition(ros_type).encode(), "cdr")
            self.counts[topic] = self.counts.get(topic, 0) + 1
            self._write(cid, log_time, ros.encode(ros_type, msg))

    def _release(self, log_time: int) -> None:
        for cid, data in self.waiting:
            self._write(cid, log_time, data)
        self.waiting = []

    def finish(self) -> None:
        """The waiting messages (a log without any known time), the metadata, the summary."""
        self._ros(self.mapper.flush())
        self._release(self.fallback_ns)
        from .. import SPEC_HASH, __version__

        ident = self.device.identity
        self.writer.add_metadata(
            "device",
            {
                "model": str(ident.model),
                "serial": str(ident.serial),
                "firmware": "" if ident.firmware is None else str(ident.firmware),
                "device": self.device.device or "",
                "source": self.device.source,
            },
        )
        self.writer.add_metadata(
            "protocol",
            {"package": PROG, "version": __version__, "protocol": _mcap_schemas.PROTOCOL, "spec_hash": SPEC_HASH},
        )
        self.writer.finish()


def write_mcap(
    log: str, out: str, given: Optional[str], topics: ros.Topics, outputs: Outputs, progress: bool = True
) -> Tuple[Dict[str, int], str]:
    """The MCAP file `out` of the log file `log` (under a temporary name of `outputs`: the caller
    commits); returns (messages per topic, the tally line)."""
    need("mcap.writer", "mcap")
    dev = LogDevice.of(log, given)
    clock = PacketClock(log)
    try:
        fallback = os.stat(log).st_mtime_ns if log != "-" else 0
    except OSError as e:
        raise ToolError(f"cannot open {log!r}: {e.strerror or e}") from None
    source = Source(log, progress=progress)
    stream = Events(dev.device)
    tmp = outputs.claim(out)
    packets = skipped = 0
    with open(tmp, "wb") as f:
        m = McapLog(f, dev, topics, fallback)

        def take(evs: List[Any]) -> None:
            nonlocal packets, skipped
            for ev in evs:
                if isinstance(ev, Packet):
                    packets += 1
                    dev.packet(ev, stream.decoder)
                    m.packet(ev, clock.t_ns(ev))
                else:
                    skipped += len(ev.data)

        for chunk in source.chunks():
            take(stream.feed(chunk))
        take(stream.flush())
        m.finish()
    return m.counts, f"{packets} packets, {skipped} bytes skipped"


def export_mcap(args: argparse.Namespace) -> int:
    """`export LOG --format mcap --out FILE.mcap` (commands.export)."""
    for option in ("join", "follow", "enum_numbers", "fields"):
        if getattr(args, option):
            raise ToolError(f"--format mcap does not take --{option.replace('_', '-')}")
    if args.log == "-":
        raise ToolError("--format mcap reads a log file, not stdin (the time model reads the file first)")
    topics = topics_of(args.topic_prefix, args.frame)
    with Outputs(args.force).writing(args.out) as outputs:
        counts, tally = write_mcap(args.log, args.out, args.device, topics, outputs)
    for topic, n in sorted(counts.items()):
        print(f"{args.out}: {topic}: {n} messages")
    print(tally, file=sys.stderr)
    return 0


__all__ = ["McapLog", "add_options", "export_mcap", "json_message", "topics_of", "write_mcap"]
