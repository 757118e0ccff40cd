"""Memsense MS-CIP: typed encoder/decoder generated from the protocol spec.

Modules: one per descriptor set (base, imu_config, imu_data) holding a
dataclass per command, response and data field; `types` (enums, bitfields, structs, unions);
`reserved` (fields reserved in every set of a kind); `framing` (checksum, packet builder, stream
parser, field splitter); `packets` (dispatch and canonical JSON lines); `samples` (continuation
packets grouped by shared timestamp); `cli` (decode/encode).

    from mscipcodec import Parser, PacketBuilder, decode_packet
    for event in Parser().feed(data):
        ...

`__version__` is the package's version (semantic versioning; every package of a release has it)
and `SPEC_HASH` the first 16 hex digits of the SHA-256 of the mscip protocol's canonical
IR: two packages with the same hash were generated from the same spec.
"""

import importlib
from typing import TYPE_CHECKING, Any, List

from .codec.canonical import NaN
from .codec.framing import (
    ACCELERATED,
    FramingError,
    Nmea,
    PacketBuilder,
    Parser,
    RawPacket,
    Rtcm,
    Skip,
    build_packet,
    checksum_bytes,
    fletcher16,
    iter_fields,
    parse,
)
from .codec.layout import DecodeError, EncodeError, Field, Layout, Struct
from .codec.packets import (
    Columns,
    DecodedField,
    Decoder,
    Packet,
    RawField,
    Trailing,
    decode_all,
    decode_bytes,
    decode_columns,
    decode_field,
    decode_packet,
    decode_stream,
    encode_line,
    encode_lines,
)
from .codec.samples import Sample, SampleGrouper, SampleTracker, sample_key
from .registry import DEVICES, lookup

if TYPE_CHECKING:
    from . import base, imu_config, imu_data, reserved, types
    from .session import Device, Result, Session, connect

# The modules of the sets, types, reserved fields and the session are imported on first use
# (PEP 562): a tool that decodes a log loads only the sets the log holds (the registry imports
# them as their fields are looked up). `mscipcodec.session` stays an attribute of the package, as
# when it was imported eagerly.
_LAZY_MODULES = frozenset(
    (
        "base",
        "imu_config",
        "imu_data",
        "reserved",
        "session",
        "types",
    )
)
_LAZY_NAMES = {
    "Device": "session",
    "Result": "session",
    "Session": "session",
    "connect": "session",
}


def __getattr__(name: str) -> Any:
    if name in _LAZY_MODULES:
        return importlib.import_module(f"{__name__}.{name}")
    module = _LAZY_NAMES.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value


def __dir__() -> List[str]:
    return sorted(set(globals()) | set(__all__))


__version__ = "0.1.0"
SPEC_HASH = "3314b414c7a35ed5"

__all__ = [
    "SPEC_HASH",
    "__version__",
    "base",
    "imu_config",
    "imu_data",
    "reserved",
    "types",
    "NaN",
    "ACCELERATED",
    "FramingError",
    "Nmea",
    "PacketBuilder",
    "Parser",
    "RawPacket",
    "Rtcm",
    "Skip",
    "build_packet",
    "checksum_bytes",
    "fletcher16",
    "iter_fields",
    "parse",
    "DecodeError",
    "EncodeError",
    "Field",
    "Layout",
    "Struct",
    "Columns",
    "DecodedField",
    "Decoder",
    "Packet",
    "RawField",
    "Trailing",
    "decode_all",
    "decode_bytes",
    "decode_columns",
    "decode_field",
    "decode_packet",
    "decode_stream",
    "encode_line",
    "encode_lines",
    "Sample",
    "SampleGrouper",
    "SampleTracker",
    "sample_key",
    "DEVICES",
    "lookup",
    "Device",
    "Result",
    "Session",
    "connect",
]
