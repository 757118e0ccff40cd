"""Canonical JSON (docs/conformance.md section 4): the writer, and the strict reader used by encode.

Floats keep their exact bits: a decoded NaN is a `NaN` (a float subclass remembering its bit
pattern and width), printed as "nan" for the canonical quiet NaN and "nan:0x<bits>" otherwise,
and encoded back to the same bits.
"""

from __future__ import annotations

import json
import math
import re
import struct
from typing import Any, Dict, List, Tuple

F32_QUIET_NAN = 0x7FC00000
F64_QUIET_NAN = 0x7FF8000000000000

_F32 = struct.Struct(">f")
_U32 = struct.Struct(">I")
_F64 = struct.Struct(">d")
_U64 = struct.Struct(">Q")
_INF = math.inf


class NaN(float):
    """A NaN that keeps its exact bit pattern: `bits` (int) and `width` (32 or 64).

    It compares like any NaN (unequal to everything, itself included); compare `bits` instead.
    """

    bits: int
    width: int

    def __new__(cls, bits: int, width: int = 64) -> NaN:
        self = float.__new__(cls, "nan")
        self.bits = bits
        self.width = width
        return self

    def __repr__(self) -> str:
        return f"NaN(0x{self.bits:0{self.width // 4}x}, {self.width})"

    def __reduce__(self) -> Tuple[Any, ...]:
        return (NaN, (self.bits, self.width))


def f32_bits(v: Any) -> int:
    """The bits a value has as a float (a 64-bit NaN is narrowed like a C cast)."""
    if isinstance(v, NaN):
        if v.width == 32:
            return v.bits
        b = v.bits
        return ((b >> 32) & 0x80000000) | 0x7FC00000 | ((b >> 29) & 0x003FFFFF)
    bits: int = _U32.unpack(_F32.pack(v))[0]
    return bits


def f64_bits(v: Any) -> int:
    """The bits a value has as a double (a 32-bit NaN is widened exactly)."""
    if isinstance(v, NaN):
        if v.width == 64:
            return v.bits
        b = v.bits
        return ((b & 0x80000000) << 32) | 0x7FF0000000000000 | ((b & 0x007FFFFF) << 29)
    bits: int = _U64.unpack(_F64.pack(v))[0]
    return bits


def f32_from_bits(bits: int) -> float:
    v = _F32.unpack(_U32.pack(bits))[0]
    return NaN(bits, 32) if v != v else v


def f64_from_bits(bits: int) -> float:
    v = _F64.unpack(_U64.pack(bits))[0]
    return NaN(bits, 64) if v != v else v


def f32_text(v: Any) -> str:
    """Canonical text of a float value (widened to double exactly)."""
    if v != v:
        bits = f32_bits(v)
        return '"nan"' if bits == F32_QUIET_NAN else f'"nan:0x{bits:08x}"'
    if v == _INF:
        return '"inf"'
    if v == -_INF:
        return '"-inf"'
    return repr(float(v))


def f64_text(v: Any) -> str:
    """Canonical text of a double value: Python's repr(float), shortest round trip."""
    if v != v:
        bits = f64_bits(v)
        return '"nan"' if bits == F64_QUIET_NAN else f'"nan:0x{bits:016x}"'
    if v == _INF:
        return '"inf"'
    if v == -_INF:
        return '"-inf"'
    return repr(float(v))


_ESCAPES: Dict[int, str] = {b: f"\\u{b:04x}" for b in list(range(0x20)) + list(range(0x7F, 0x100))}
_ESCAPES[0x22] = '\\"'
_ESCAPES[0x5C] = "\\\\"


def string_text(data: Any) -> str:
    """Canonical JSON string of raw bytes: byte b is U+00bb, escaped as in section 4."""
    return '"' + bytes(data).decode("latin-1").translate(_ESCAPES) + '"'


def error_text(message: str) -> str:
    return string_text(message.encode("latin-1", "replace"))


_NAN_TEXT = {32: re.compile(r"nan:0x([0-9a-fA-F]{8})"), 64: re.compile(r"nan:0x([0-9a-fA-F]{16})")}


class _NegativeZero(int):
    """The JSON number `-0`: the integer 0, and -0.0 where a float is expected (section 5)."""


NEGATIVE_ZERO = _NegativeZero(0)


def is_int(x: Any) -> bool:
    """True for a JSON integer as read by `loads` (not a bool, not a float)."""
    return type(x) is int or type(x) is _NegativeZero


def float_from_json(x: Any, width: int) -> float:
    """A float/double value from its JSON form (raises ValueError): a number is rounded to the
    nearest double, which must be finite (the float range is checked when packing); "inf",
    "-inf", "nan" and "nan:0x<bits>" (hex digits in either case)."""
    if type(x) is _NegativeZero:
        return -0.0
    if isinstance(x, bool):
        raise ValueError(f"{x!r} is not a number")
    if isinstance(x, int):
        try:
            return float(x)
        except OverflowError:
            raise ValueError(f"{x} is out of range for a double") from None
    if isinstance(x, float):
        if x in (_INF, -_INF):  # only a number too large for a double reads as infinite
            raise ValueError("the number is out of range for a double")
        return x
    if isinstance(x, str):
        if x == "inf":
            return _INF
        if x == "-inf":
            return -_INF
        if x == "nan":
            return NaN(F32_QUIET_NAN if width == 32 else F64_QUIET_NAN, width)
        m = _NAN_TEXT[width].fullmatch(x)
        if m:
            v = f32_from_bits(int(m.group(1), 16)) if width == 32 else f64_from_bits(int(m.group(1), 16))
            if isinstance(v, NaN):
                return v
            raise ValueError(f"{x!r} is not a NaN bit pattern")
    text = repr(x)
    raise ValueError(f"{text if len(text) < 40 else text[:37] + '...'} is not a number, inf, -inf, nan or nan:0x<bits>")


# ----------------------------------------------------------------------------------- reader
class JsonError(ValueError):
    """A line that is not acceptable canonical JSON."""


def _no_constants(name: str) -> Any:
    raise JsonError(f'{name} is not valid JSON (write "nan", "inf" or "-inf" as strings)')


def _no_duplicates(pairs: List[Tuple[str, Any]]) -> Dict[str, Any]:
    out: Dict[str, Any] = {}
    for k, v in pairs:
        if k in out:
            raise JsonError(f"duplicate key {k!r}")
        out[k] = v
    return out


def _parse_int(text: str) -> int:
    return NEGATIVE_ZERO if text == "-0" else int(text)


def loads(text: str) -> Any:
    """Parse one JSON document strictly (no NaN/Infinity literals, no duplicate keys)."""
    try:
        return json.loads(text, parse_constant=_no_constants, object_pairs_hook=_no_duplicates, parse_int=_parse_int)
    except JsonError:
        raise
    except (ValueError, RecursionError) as e:
        raise JsonError(f"not valid JSON: {e}") from None


_HEX = re.compile(r"(?:[0-9a-fA-F]{2})*")


def hex_bytes(text: Any, what: str) -> bytes:
    """Bytes from a hex string as printed by decode (pairs of hex digits, no separators)."""
    if not isinstance(text, str) or not _HEX.fullmatch(text):
        raise JsonError(f"{what}: expected a string of hex digit pairs")
    return bytes.fromhex(text)


def skip_line(offset: int, data: Any) -> str:
    """The canonical line of a skip run."""
    return '{"offset":' + str(offset) + ',"skipped":"' + bytes(data).hex() + '"}'


def foreign_line(offset: int, data: Any) -> str:
    """The canonical line of an NMEA sentence (without its CR LF; only '"' and '\\' need escaping
    in its printable ASCII) or of an RTCM3 frame (message type and payload length)."""
    data = bytes(data)
    if data[0] == 0xD3:
        kind = (data[3] << 4) | (data[4] >> 4)
        return '{"offset":' + str(offset) + ',"rtcm":' + str(kind) + ',"length":' + str(len(data) - 6) + "}"
    text = data[:-2].decode("ascii").replace("\\", "\\\\").replace('"', '\\"')
    return '{"offset":' + str(offset) + ',"nmea":"' + text + '"}'
