"""Typed values and their wire encoding (spec-independent runtime of mipcodec).

Every generated command, response, data field, reserved field and struct is a dataclass deriving
from `Layout`. Its `_OPS` describe the parameters in wire order:

- `Run(P(...), ...)`: consecutive fixed-size scalars and fixed arrays, packed and unpacked with one
  precompiled `struct.Struct`;
- `Opt(op)`: an optional parameter (read only when at least one byte is left);
- `Counted` / `Remaining` / `Repeat`: arrays counted by an earlier parameter, running to the end
  of the field, or of fixed length (of structs);
- `Nested`: a struct; `Choice`: a union whose member is chosen by an earlier enum parameter.

Decoding errors carry the exact messages of docs/conformance.md section 3.
"""

from __future__ import annotations

import enum as _enum
import struct
from operator import attrgetter
from typing import TYPE_CHECKING, Any, Callable, Dict, FrozenSet, List, Optional, Tuple, Type, TypeVar
from typing import Union as _Union  # `Union` below is the base of generated unions

from .._protocol import BYTE_ORDER
from .canonical import (
    NaN,
    f32_bits,
    f32_text,
    f64_bits,
    f64_text,
    float_from_json,
    is_int,
    string_text,
)

# What the decoders read: any bytes-like object (bytes, bytearray, memoryview).
BytesLike = _Union[bytes, bytearray, memoryview]

_RAW32 = struct.Struct(BYTE_ORDER + "I")
_RAW64 = struct.Struct(BYTE_ORDER + "Q")


class DecodeError(ValueError):
    """Field data that does not match its layout; str(error) is the canonical message."""


class EncodeError(ValueError):
    """A value that cannot be encoded: wrong type, out of range, inconsistent counts."""


class _Bad(Exception):
    """Internal: a value is wrong; the caller adds the parameter path."""


def _show(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


# ------------------------------------------------------------------------------------- scalars
class Scalar:
    """How one wire value is packed, unpacked, checked, printed and read back from JSON."""

    __slots__ = (
        "code",
        "size",
        "type_name",
        "is_bool",
        "float_width",
        "post",
        "prep",
        "check",
        "json",
        "from_json",
        "fast",
    )

    def __init__(
        self,
        code: str,
        size: int,
        type_name: str,
        json: Callable[[Any], str],
        from_json: Callable[[Any], Any],
        check: Callable[[Any], None],
        post: Optional[Callable[[Any, Any, int], Any]] = None,
        prep: Optional[Callable[[Any], Any]] = None,
        is_bool: bool = False,
        float_width: int = 0,
        fast: Optional[Tuple[str, Any]] = None,
    ) -> None:
        self.code = code
        self.size = size
        self.type_name = type_name
        self.json = json
        self.from_json = from_json
        self.check = check
        self.post = post
        self.prep = prep
        self.is_bool = is_bool
        self.float_width = float_width
        # How the C accelerator reads it: (kind, aux), or None (pure-Python decoder); see fast_items.
        self.fast = fast

    def __repr__(self) -> str:
        return f"<scalar {self.type_name}>"


def _int_json(v: Any) -> str:
    return int.__repr__(v)


def _int_from_json(x: Any) -> int:
    if not is_int(x):
        raise _Bad(f"{_show(x)} is not an integer")
    return int(x)


def _int_checker(type_name: str, lo: int, hi: int) -> Callable[[Any], None]:
    def check(v: Any) -> None:
        if not isinstance(v, int) or isinstance(v, bool):
            raise _Bad(f"{_show(v)} is not an integer ({type_name})")
        if not lo <= v <= hi:
            raise _Bad(f"{int(v)} is out of range for {type_name} ({lo}..{hi})")

    return check


def _int_scalar(code: str, size: int, name: str, signed: bool) -> Scalar:
    bits = size * 8
    lo, hi = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)
    return Scalar(
        code, size, name, _int_json, _int_from_json, _int_checker(name, lo, hi), fast=("i" if signed else "u", None)
    )


def _bool_prep(v: Any) -> int:
    if isinstance(v, int) and (v == 0 or v == 1):
        return int(v)
    raise _Bad(f"{_show(v)} is not a bool")


def _bool_check(v: Any) -> None:
    _bool_prep(v)


def _bool_json(v: Any) -> str:
    return "true" if v else "false"


def _bool_from_json(x: Any) -> bool:
    if x is True or x is False:
        return x
    raise _Bad(f"{_show(x)} is not true or false")


def _float_checker(code: str, type_name: str) -> Callable[[Any], None]:
    packer = struct.Struct(BYTE_ORDER + code)

    def check(v: Any) -> None:
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise _Bad(f"{_show(v)} is not a number ({type_name})")
        try:
            packer.pack(v)
        except (OverflowError, struct.error):
            raise _Bad(f"{_show(v)} does not fit in a {type_name}") from None

    return check


def _f32_post(v: float, data: Any, off: int) -> float:
    if v != v:
        return NaN(_RAW32.unpack_from(data, off)[0], 32)
    return v


def _f64_post(v: float, data: Any, off: int) -> float:
    if v != v:
        return NaN(_RAW64.unpack_from(data, off)[0], 64)
    return v


def _char_check(v: Any) -> None:
    if not isinstance(v, (bytes, bytearray)) or len(v) != 1:
        raise _Bad(f"{_show(v)} is not one byte (bytes of length 1)")


def _latin1_from_json(x: Any, n: int) -> bytes:
    if not isinstance(x, str) or len(x) != n:
        raise _Bad(f"{_show(x)} is not a string of exactly {n} characters")
    try:
        return x.encode("latin-1")
    except UnicodeEncodeError:
        raise _Bad(f"{_show(x)} has characters above U+00FF") from None


U8 = _int_scalar("B", 1, "u8", False)
U16 = _int_scalar("H", 2, "u16", False)
U32 = _int_scalar("I", 4, "u32", False)
U64 = _int_scalar("Q", 8, "u64", False)
S8 = _int_scalar("b", 1, "s8", True)
S16 = _int_scalar("h", 2, "s16", True)
S32 = _int_scalar("i", 4, "s32", True)
S64 = _int_scalar("q", 8, "s64", True)


def _float_from_json(width: int) -> Callable[[Any], float]:
    def from_json(x: Any) -> float:
        try:
            return float_from_json(x, width)
        except ValueError as e:
            raise _Bad(str(e)) from None

    return from_json


F32 = Scalar(
    "f",
    4,
    "float",
    f32_text,
    _float_from_json(32),
    _float_checker("f", "float"),
    post=_f32_post,
    float_width=32,
    fast=("f", None),
)
F64 = Scalar(
    "d",
    8,
    "double",
    f64_text,
    _float_from_json(64),
    _float_checker("d", "double"),
    post=_f64_post,
    float_width=64,
    fast=("d", None),
)
BOOL = Scalar("B", 1, "bool", _bool_json, _bool_from_json, _bool_check, prep=_bool_prep, is_bool=True, fast=("?", None))
CHAR = Scalar("c", 1, "char", string_text, lambda x: _latin1_from_json(x, 1), _char_check, fast=("c", None))
_BASES = {"u8": U8, "u16": U16, "u32": U32, "u64": U64, "s8": S8, "s16": S16, "s32": S32, "s64": S64}
_CACHE: Dict[Any, Scalar] = {}


def string(length: int) -> Scalar:
    """A string of exactly `length` bytes (bytes, padding kept)."""
    key = ("string", length)
    if key not in _CACHE:

        def prep(v: Any) -> bytes:
            if isinstance(v, (bytes, bytearray)) and len(v) == length:
                return bytes(v)
            raise _Bad(f"{_show(v)} is not {length} bytes")

        def check(v: Any) -> None:
            prep(v)

        _CACHE[key] = Scalar(
            f"{length}s",
            length,
            f"char[{length}]",
            string_text,
            lambda x: _latin1_from_json(x, length),
            check,
            prep=prep,
            fast=("s", None),
        )
    return _CACHE[key]


def enum(cls: Any, base: str) -> Scalar:
    """An enum read as its base integer; unknown values stay plain ints."""
    key = ("enum", cls, base)
    if key not in _CACHE:
        b = _BASES[base]
        members = cls._value2member_map_

        def post(v: int, data: Any, off: int) -> Any:
            return members.get(v, v)

        def from_json(x: Any) -> Any:
            x = _int_from_json(x)
            return members.get(x, x)

        fast = ("e", members) if base.startswith("u") else None
        _CACHE[key] = Scalar(
            b.code, b.size, f"{cls.__name__} ({base})", _int_json, from_json, b.check, post=post, fast=fast
        )
    return _CACHE[key]


def flags(cls: Any) -> Scalar:
    """A bitfield read as its base integer (every bit kept)."""
    key = ("flags", cls)
    if key not in _CACHE:
        b = _BASES[cls._BASE]

        def post(v: int, data: Any, off: int) -> Any:
            return cls(v)

        def from_json(x: Any) -> Any:
            return cls(_int_from_json(x))

        fast = ("F", cls) if cls._BASE.startswith("u") else None
        _CACHE[key] = Scalar(
            b.code, b.size, f"{cls.__name__} ({cls._BASE})", _int_json, from_json, b.check, post=post, fast=fast
        )
    return _CACHE[key]


_ARRAYS: Dict[Tuple[str, int], struct.Struct] = {}


def _array_struct(code: str, n: int) -> struct.Struct:
    s = _ARRAYS.get((code, n))
    if s is None:
        s = _ARRAYS[(code, n)] = struct.Struct(f"{BYTE_ORDER}{n}{code}")
    return s


def _patch_nan(out: bytearray, at: int, v: Any, width: int) -> None:
    if width == 32:
        out[at : at + 4] = _RAW32.pack(f32_bits(v))
    else:
        out[at : at + 8] = _RAW64.pack(f64_bits(v))


# ------------------------------------------------------------------------------------- enums, bitfields
_E = TypeVar("_E", bound="Enum")
_B = TypeVar("_B", bound="Bitfield")
_L = TypeVar("_L", bound="Layout")


class Enum(_enum.IntEnum):
    """Base of generated enums. Decoding keeps unknown values as plain ints (see `of`)."""

    @classmethod
    def of(cls: Type[_E], value: int) -> _Union[_E, int]:
        """The member with this value, or the plain int when the value is not a member."""
        member: _Union[_E, int] = cls._value2member_map_.get(value, value)  # type: ignore[assignment]
        return member


class Bitfield(int):
    """Base of generated bitfields: an int whose named members are properties.

    Single-bit members read as bool, multi-bit members as int; class constants (UPPER_CASE) are
    the members' masks. Every bit is kept, reserved or not. `|`, `&`, `^` and `~` keep the type.
    """

    _BASE = "u8"
    _ALL = 0xFF
    _MEMBERS: Tuple[Tuple[str, str, str, int, int], ...] = ()

    def __or__(self: _B, other: int) -> _B:
        return type(self)(int(self) | int(other))

    __ror__ = __or__

    def __and__(self: _B, other: int) -> _B:
        return type(self)(int(self) & int(other))

    __rand__ = __and__

    def __xor__(self: _B, other: int) -> _B:
        return type(self)(int(self) ^ int(other))

    __rxor__ = __xor__

    def __invert__(self: _B) -> _B:
        return type(self)(~int(self) & self._ALL)

    def __contains__(self, mask: int) -> bool:
        return int(self) & int(mask) == int(mask)

    def members(self) -> Dict[str, int]:
        """Every named member with a non-zero value: name -> value (1 for single bits)."""
        out: Dict[str, int] = {}
        for name, _attr, _const, first, width in self._MEMBERS:
            v = (int(self) >> first) & ((1 << width) - 1)
            if v:
                out[name] = v
        return out

    def replace(self: _B, **values: int) -> _B:
        """A copy with the given members (by attribute name) set to new values."""
        v = int(self)
        by_attr = {attr: (first, width) for _name, attr, _const, first, width in self._MEMBERS}
        for attr, value in values.items():
            if attr not in by_attr:
                raise AttributeError(f"{type(self).__name__} has no member {attr!r}")
            first, width = by_attr[attr]
            mask = ((1 << width) - 1) << first
            value = int(value)
            if not 0 <= value < (1 << width):
                raise ValueError(f"{attr}: {value} does not fit in {width} bit(s)")
            v = (v & ~mask) | (value << first)
        return type(self)(v)

    def __repr__(self) -> str:
        names = ", ".join(f"{k}={v}" if v > 1 else k for k, v in self.members().items())
        digits = len(hex(self._ALL)) - 2
        return f"{type(self).__name__}(0x{int(self):0{digits}X}{': ' + names if names else ''})"

    __str__ = __repr__


def bitfield(base: str) -> Callable[[Type[_B]], Type[_B]]:
    """Class decorator of generated bitfields: records the base type, turns mask constants into values."""

    def wrap(cls: Type[_B]) -> Type[_B]:
        cls._BASE = base
        cls._ALL = (1 << (_BASES[base].size * 8)) - 1
        for _name, _attr, const, first, width in cls._MEMBERS:
            setattr(cls, const, cls(((1 << width) - 1) << first))
        return cls

    return wrap


if TYPE_CHECKING:
    # What type checkers see of the member properties (at run time they are plain properties).
    class _BitMember:
        def __get__(self, obj: Optional[Bitfield], owner: Any) -> bool: ...

    class _BitsMember:
        def __get__(self, obj: Optional[Bitfield], owner: Any) -> int: ...


def bit(n: int) -> _BitMember:
    """A single-bit member (bool)."""
    return property(lambda self: bool((int(self) >> n) & 1))  # type: ignore[return-value]


def bits(first: int, width: int) -> _BitsMember:
    """A multi-bit member (int)."""
    mask = (1 << width) - 1
    return property(lambda self: (int(self) >> first) & mask)  # type: ignore[return-value]


# ------------------------------------------------------------------------------------- operations
class _Op:
    optional = False
    width = 1
    name = ""
    index = 0

    def bind(self, index: int, names: List[str]) -> None:
        self.index = index

    def names(self) -> List[str]:
        return [self.name]

    # Implemented by every operation (declared here for type checkers).
    def read(self, data: Any, o: int, vals: List[Any], prefix: str) -> int:
        raise NotImplementedError

    def write(self, out: bytearray, vals: Any, prefix: str) -> None:
        raise NotImplementedError

    def to_json(self, vals: Any, parts: List[str]) -> None:
        raise NotImplementedError

    def from_json(self, obj: Dict[str, Any], vals: List[Any], prefix: str) -> None:
        raise NotImplementedError

    def selects_nothing(self, vals: Any) -> bool:
        """True when a union's selected member has no data (only Choice selects)."""
        return False


class P:
    """One scalar parameter (or fixed array of scalars) inside a Run."""

    __slots__ = ("name", "scalar", "count", "offset", "key")

    def __init__(self, name: str, scalar: Scalar, count: Optional[int] = None) -> None:
        self.name = name
        self.scalar = scalar
        self.count = count
        self.offset = 0
        self.key = f'"{name}":'


class Run(_Op):
    """Consecutive fixed-size scalar parameters, read and written with one struct.Struct."""

    def __init__(self, *params: P) -> None:
        self.params = params
        self.width = len(params)
        fmt = BYTE_ORDER
        off = k = 0
        floats: List[Tuple[int, int, int]] = []
        for p in params:
            s = p.scalar
            p.offset = off
            n = 1 if p.count is None else p.count
            fmt += s.code if p.count is None else f"{n}{s.code}"
            if s.float_width:
                floats.extend((k + j, off + j * s.size, s.float_width) for j in range(n))
            off += n * s.size
            k += n
        self.struct = struct.Struct(fmt)
        self.size = off
        self.floats = tuple(floats)
        self.simple = all(p.count is None and p.scalar.post is None and not p.scalar.is_bool for p in params)
        self.name = params[0].name

    def names(self) -> List[str]:
        return [p.name for p in self.params]

    def read(self, data: Any, o: int, vals: List[Any], prefix: str) -> int:
        end = o + self.size
        if end > len(data):
            self._short(data, o, prefix)
        flat = self.struct.unpack_from(data, o)
        if self.simple:
            vals.extend(flat)
            return end
        k = 0
        for p in self.params:
            s = p.scalar
            post = s.post
            if p.count is None:
                v = flat[k]
                k += 1
                if s.is_bool:
                    if v > 1:
                        raise DecodeError(f"{prefix}{p.name}: invalid bool value {v} at offset {o + p.offset}")
                    v = v == 1
                elif post is not None:
                    v = post(v, data, o + p.offset)
            else:
                n = p.count
                v = list(flat[k : k + n])
                k += n
                if s.is_bool:
                    for j, x in enumerate(v):
                        if x > 1:
                            off = o + p.offset + j
                            raise DecodeError(f"{prefix}{p.name}[{j}]: invalid bool value {x} at offset {off}")
                    v = [x == 1 for x in v]
                elif post is not None:
                    base, size = o + p.offset, s.size
                    v = [post(x, data, base + j * size) for j, x in enumerate(v)]
            vals.append(v)
        return end

    def _short(self, data: Any, o: int, prefix: str) -> None:
        """The run does not fit: report the first value (in wire order) that cannot be read."""
        n = len(data)
        for p in self.params:
            s = p.scalar
            for j in range(1 if p.count is None else p.count):
                off = o + p.offset + j * s.size
                path = p.name if p.count is None else f"{p.name}[{j}]"
                if off + s.size > n:
                    raise DecodeError(f"{prefix}{path}: needs {s.size} bytes at offset {off}, {n - off} left")
                if s.is_bool and data[off] > 1:
                    raise DecodeError(f"{prefix}{path}: invalid bool value {data[off]} at offset {off}")
        raise AssertionError("unreachable")  # pragma: no cover

    def write(self, out: bytearray, vals: Any, prefix: str) -> None:
        flat: List[Any] = []
        i = self.index
        for p in self.params:
            v = vals[i]
            i += 1
            prep = p.scalar.prep
            if p.count is None:
                if prep is not None:
                    try:
                        v = prep(v)
                    except _Bad as e:
                        raise EncodeError(f"{prefix}{p.name}: {e}") from None
                flat.append(v)
            else:
                if not isinstance(v, (list, tuple)) or len(v) != p.count:
                    raise EncodeError(f"{prefix}{p.name}: expected a list of {p.count} values, got {_show(v)}")
                if prep is None:
                    flat.extend(v)
                else:
                    for j, x in enumerate(v):
                        try:
                            flat.append(prep(x))
                        except _Bad as e:
                            raise EncodeError(f"{prefix}{p.name}[{j}]: {e}") from None
        start = len(out)
        try:
            out += self.struct.pack(*flat)
        except (struct.error, OverflowError, TypeError, ValueError):
            self._explain(flat, prefix)
        for k, off, width in self.floats:
            v = flat[k]
            if v != v:
                _patch_nan(out, start + off, v, width)

    def _explain(self, flat: List[Any], prefix: str) -> None:
        k = 0
        for p in self.params:
            for j in range(1 if p.count is None else p.count):
                try:
                    p.scalar.check(flat[k])
                except _Bad as e:
                    path = p.name if p.count is None else f"{p.name}[{j}]"
                    raise EncodeError(f"{prefix}{path}: {e}") from None
                k += 1
        raise EncodeError(f"{prefix}{self.name}: cannot encode {_show(flat)}")

    def to_json(self, vals: Any, parts: List[str]) -> None:
        i = self.index
        for p in self.params:
            v = vals[i]
            i += 1
            js = p.scalar.json
            if p.count is None:
                parts.append(p.key + js(v))
            else:
                parts.append(p.key + "[" + ",".join(map(js, v)) + "]")

    def from_json(self, obj: Dict[str, Any], vals: List[Any], prefix: str) -> None:
        for p in self.params:
            if p.name not in obj:
                raise EncodeError(f"{prefix}{p.name}: missing")
            x = obj[p.name]
            fj = p.scalar.from_json
            if p.count is None:
                try:
                    vals.append(fj(x))
                except _Bad as e:
                    raise EncodeError(f"{prefix}{p.name}: {e}") from None
                continue
            if not isinstance(x, list) or len(x) != p.count:
                raise EncodeError(f"{prefix}{p.name}: expected an array of {p.count} values")
            items = []
            for j, item in enumerate(x):
                try:
                    items.append(fj(item))
                except _Bad as err:
                    raise EncodeError(f"{prefix}{p.name}[{j}]: {err}") from None
            vals.append(items)


class Opt(_Op):
    """An optional parameter: read only when at least one byte is left; None when absent."""

    optional = True

    def __init__(self, op: _Op) -> None:
        self.op = op
        self.name = op.name
        self.is_choice = isinstance(op, Choice)

    def bind(self, index: int, names: List[str]) -> None:
        self.index = index
        self.op.bind(index, names)

    def read(self, data: Any, o: int, vals: List[Any], prefix: str) -> int:
        if o >= len(data):
            vals.append(None)
            return o
        return self.op.read(data, o, vals, prefix)

    def write(self, out: bytearray, vals: Any, prefix: str) -> None:
        if vals[self.index] is not None:
            self.op.write(out, vals, prefix)

    def is_empty(self, vals: Any) -> bool:
        """True for an absent (None) union whose selected member has no data: present as null."""
        return self.is_choice and vals[self.index] is None and self.op.selects_nothing(vals)

    def to_json(self, vals: Any, parts: List[str]) -> None:
        if vals[self.index] is not None:
            self.op.to_json(vals, parts)

    def from_json(self, obj: Dict[str, Any], vals: List[Any], prefix: str) -> None:
        if self.name in obj:
            self.op.from_json(obj, vals, prefix)
        else:
            vals.append(None)


def _elem_kind(elem: Any) -> Tuple[Optional[Scalar], Any]:
    return (elem, None) if isinstance(elem, Scalar) else (None, elem)


class _Array(_Op):
    """Shared element reading/writing of the array operations."""

    def __init__(self, name: str, elem: Any, maximum: int) -> None:
        self.name = name
        self.scalar, self.cls = _elem_kind(elem)
        self.maximum = maximum
        self.elem_size = self.scalar.size if self.scalar else getattr(self.cls, "_SIZE", None)

    def read_items(self, data: Any, o: int, n: int, prefix: str) -> Tuple[List[Any], int]:
        s = self.scalar
        if s is None:
            items = []
            cls = self.cls
            for j in range(n):
                v, o = cls._read(data, o, f"{prefix}{self.name}[{j}].")
                items.append(v)
            return items, o
        size = s.size
        end = o + n * size
        if end <= len(data) and not s.is_bool:
            flat = _array_struct(s.code, n).unpack_from(data, o)
            if s.post is None:
                return list(flat), end
            post = s.post
            return [post(x, data, o + j * size) for j, x in enumerate(flat)], end
        items = []
        one = _array_struct(s.code, 1)
        for j in range(n):
            off = o + j * size
            if off + size > len(data):
                raise DecodeError(
                    f"{prefix}{self.name}[{j}]: needs {size} bytes at offset {off}, {len(data) - off} left"
                )
            x = one.unpack_from(data, off)[0]
            if s.is_bool:
                if x > 1:
                    raise DecodeError(f"{prefix}{self.name}[{j}]: invalid bool value {x} at offset {off}")
                x = x == 1
            elif s.post is not None:
                x = s.post(x, data, off)
            items.append(x)
        return items, end

    def write_items(self, out: bytearray, v: Any, prefix: str) -> None:
        s = self.scalar
        if s is None:
            cls = self.cls
            for j, x in enumerate(v):
                if not isinstance(x, cls):
                    raise EncodeError(f"{prefix}{self.name}[{j}]: expected a {cls.__name__}, got {_show(x)}")
                x._write(out, f"{prefix}{self.name}[{j}].")
            return
        flat = list(v)
        if s.prep is not None:
            for j, x in enumerate(flat):
                try:
                    flat[j] = s.prep(x)
                except _Bad as e:
                    raise EncodeError(f"{prefix}{self.name}[{j}]: {e}") from None
        start = len(out)
        try:
            out += _array_struct(s.code, len(flat)).pack(*flat)
        except (struct.error, OverflowError, TypeError, ValueError):
            for j, x in enumerate(flat):
                try:
                    s.check(x)
                except _Bad as e:
                    raise EncodeError(f"{prefix}{self.name}[{j}]: {e}") from None
            raise EncodeError(f"{prefix}{self.name}: cannot encode {_show(flat)}") from None
        if s.float_width:
            for j, x in enumerate(flat):
                if x != x:
                    _patch_nan(out, start + j * s.size, x, s.float_width)

    def check_list(self, v: Any, prefix: str) -> None:
        if not isinstance(v, (list, tuple)):
            raise EncodeError(f"{prefix}{self.name}: expected a list, got {_show(v)}")
        if len(v) > self.maximum:
            raise EncodeError(f"{prefix}{self.name}: {len(v)} elements exceed the maximum {self.maximum}")

    def to_json(self, vals: Any, parts: List[str]) -> None:
        v = vals[self.index]
        if self.scalar is not None:
            parts.append(f'"{self.name}":[' + ",".join(map(self.scalar.json, v)) + "]")
        else:
            parts.append(f'"{self.name}":[' + ",".join(x.to_json() for x in v) + "]")

    def items_from_json(self, x: Any, prefix: str) -> List[Any]:
        if not isinstance(x, list):
            raise EncodeError(f"{prefix}{self.name}: expected an array")
        items = []
        for j, e in enumerate(x):
            if self.scalar is not None:
                try:
                    items.append(self.scalar.from_json(e))
                except _Bad as err:
                    raise EncodeError(f"{prefix}{self.name}[{j}]: {err}") from None
            else:
                items.append(self.cls.from_json(e, f"{prefix}{self.name}[{j}]."))
        return items

    def from_json(self, obj: Dict[str, Any], vals: List[Any], prefix: str) -> None:
        if self.name not in obj:
            raise EncodeError(f"{prefix}{self.name}: missing")
        vals.append(self.items_from_json(obj[self.name], prefix))


class Counted(_Array):
    """An array whose length is the value of an earlier integer parameter."""

    def __init__(self, name: str, elem: Any, count: str, maximum: int) -> None:
        super().__init__(name, elem, maximum)
        self.count_name = count
        self.ref = 0

    def bind(self, index: int, names: List[str]) -> None:
        self.index = index
        self.ref = names.index(self.count_name)

    def read(self, data: Any, o: int, vals: List[Any], prefix: str) -> int:
        n = vals[self.ref]
        if n > self.maximum:
            raise DecodeError(f"{prefix}{self.name}: count {n} exceeds maximum {self.maximum}")
        items, o = self.read_items(data, o, n, prefix)
        vals.append(items)
        return o

    def write(self, out: bytearray, vals: Any, prefix: str) -> None:
        v = vals[self.index]
        self.check_list(v, prefix)
        if vals[self.ref] != len(v):
            raise EncodeError(
                f"{prefix}{self.name}: has {len(v)} elements but {self.count_name} is {_show(vals[self.ref])}"
            )
        self.write_items(out, v, prefix)


class Remaining(_Array):
    """An array that runs to the end of the field data."""

    def read(self, data: Any, o: int, vals: List[Any], prefix: str) -> int:
        h = len(data) - o
        size = self.elem_size
        if size:
            if h % size:
                raise DecodeError(f"{prefix}{self.name}: {h} bytes left at offset {o}, not a multiple of {size}")
            n = h // size
            if n > self.maximum:
                raise DecodeError(f"{prefix}{self.name}: count {n} exceeds maximum {self.maximum}")
            items, o = self.read_items(data, o, n, prefix)
        else:  # elements of varying size: read until the data ends
            items = []
            while o < len(data):
                if len(items) == self.maximum:
                    raise DecodeError(f"{prefix}{self.name}: count {len(items) + 1} exceeds maximum {self.maximum}")
                v, o = self.cls._read(data, o, f"{prefix}{self.name}[{len(items)}].")
                items.append(v)
        vals.append(items)
        return o

    def write(self, out: bytearray, vals: Any, prefix: str) -> None:
        v = vals[self.index]
        self.check_list(v, prefix)
        self.write_items(out, v, prefix)


class Repeat(_Array):
    """A fixed number of non-scalar elements (structs)."""

    def __init__(self, name: str, elem: Any, count: int) -> None:
        super().__init__(name, elem, count)
        self.count = count

    def read(self, data: Any, o: int, vals: List[Any], prefix: str) -> int:
        items, o = self.read_items(data, o, self.count, prefix)
        vals.append(items)
        return o

    def write(self, out: bytearray, vals: Any, prefix: str) -> None:
        v = vals[self.index]
        if not isinstance(v, (list, tuple)) or len(v) != self.count:
            raise EncodeError(f"{prefix}{self.name}: expected a list of {self.count} values, got {_show(v)}")
        self.write_items(out, v, prefix)

    def from_json(self, obj: Dict[str, Any], vals: List[Any], prefix: str) -> None:
        super().from_json(obj, vals, prefix)
        if len(vals[-1]) != self.count:
            raise EncodeError(f"{prefix}{self.name}: expected an array of {self.count} values")


class Nested(_Op):
    """A struct parameter."""

    def __init__(self, name: str, cls: Any) -> None:
        self.name = name
        self.cls = cls

    def read(self, data: Any, o: int, vals: List[Any], prefix: str) -> int:
        v, o = self.cls._read(data, o, f"{prefix}{self.name}.")
        vals.append(v)
        return o

    def write(self, out: bytearray, vals: Any, prefix: str) -> None:
        v = vals[self.index]
        if not isinstance(v, self.cls):
            raise EncodeError(f"{prefix}{self.name}: expected a {self.cls.__name__}, got {_show(v)}")
        v._write(out, f"{prefix}{self.name}.")

    def to_json(self, vals: Any, parts: List[str]) -> None:
        parts.append(f'"{self.name}":' + vals[self.index].to_json())

    def from_json(self, obj: Dict[str, Any], vals: List[Any], prefix: str) -> None:
        if self.name not in obj:
            raise EncodeError(f"{prefix}{self.name}: missing")
        vals.append(self.cls.from_json(obj[self.name], f"{prefix}{self.name}."))


_MISSING = object()


class Choice(_Op):
    """A union: the member struct chosen by the value of an earlier enum parameter (None: no data)."""

    def __init__(self, name: str, union: Any, selector: str) -> None:
        self.name = name
        self.union = union
        self.selector = selector
        self.ref = 0

    def bind(self, index: int, names: List[str]) -> None:
        self.index = index
        self.ref = names.index(self.selector)

    def selects_nothing(self, vals: Any) -> bool:
        sel = vals[self.ref]
        return isinstance(sel, int) and sel in self.union._MEMBERS and self.union._MEMBERS[sel] is None

    def _member(self, vals: Any, prefix: str, error: type) -> Any:
        sel = vals[self.ref]
        member = self.union._MEMBERS.get(sel, _MISSING) if isinstance(sel, int) else _MISSING
        if member is _MISSING:
            shown = int.__repr__(sel) if isinstance(sel, int) else _show(sel)
            raise error(f"{prefix}{self.name}: no member for selector value {shown}")
        return member

    def read(self, data: Any, o: int, vals: List[Any], prefix: str) -> int:
        member = self._member(vals, prefix, DecodeError)
        if member is None:
            vals.append(None)
            return o
        v, o = member._read(data, o, f"{prefix}{self.name}.")
        vals.append(v)
        return o

    def write(self, out: bytearray, vals: Any, prefix: str) -> None:
        v = vals[self.index]
        if vals[self.ref] is None and v is None:
            return
        member = self._member(vals, prefix, EncodeError)
        if member is None:
            if v is not None:
                raise EncodeError(f"{prefix}{self.name}: the selected member has no data, expected None")
            return
        if not isinstance(v, member):
            raise EncodeError(f"{prefix}{self.name}: expected a {member.__name__}, got {_show(v)}")
        v._write(out, f"{prefix}{self.name}.")

    def to_json(self, vals: Any, parts: List[str]) -> None:
        v = vals[self.index]
        parts.append(f'"{self.name}":' + ("null" if v is None else v.to_json()))

    def from_json(self, obj: Dict[str, Any], vals: List[Any], prefix: str) -> None:
        if self.name not in obj:
            raise EncodeError(f"{prefix}{self.name}: missing")
        x = obj[self.name]
        member = self._member(vals, prefix, EncodeError)
        if member is None:
            if x is not None:
                raise EncodeError(f"{prefix}{self.name}: the selected member has no data, expected null")
            vals.append(None)
        else:
            vals.append(member.from_json(x, f"{prefix}{self.name}."))


# ------------------------------------------------------------------------------------- layouts
def _getter(attrs: Tuple[str, ...]) -> Callable[[Any], Tuple[Any, ...]]:
    if not attrs:
        return lambda obj: ()
    if len(attrs) == 1:
        one = attrgetter(attrs[0])
        return lambda obj: (one(obj),)
    return attrgetter(*attrs)


class Layout:
    """Base of generated dataclasses: decode/encode per the `_OPS`, canonical JSON in and out."""

    __slots__ = ()  # subclasses keep a __dict__ unless they declare slots (see `slotted`)

    _OPS: Tuple[Any, ...] = ()
    _ATTRS: Tuple[str, ...] = ()
    _NAMES: Tuple[str, ...] = ()
    _KEYS: FrozenSet[str] = frozenset()
    _OPTIONAL = False
    _SIZE: Optional[int] = None  # wire size when fixed (used for arrays running to the end of a field)
    _get: Callable[[Any], Tuple[Any, ...]]  # the values of _ATTRS, set per class

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        if "_OPS" not in cls.__dict__:
            return
        names: List[str] = []
        for op in cls._OPS:
            op.bind(len(names), names)
            names.extend(op.names())
        cls._NAMES = tuple(names)
        cls._KEYS = frozenset(names)
        cls._OPTIONAL = any(op.optional for op in cls._OPS)
        cls._get = staticmethod(_getter(cls._ATTRS))

    # -- wire
    @classmethod
    def decode(cls: Type[_L], data: BytesLike) -> _L:
        """Decode field data (after the field header); raises DecodeError with the canonical message."""
        value, o = cls._read(data, 0, "")
        if o != len(data):
            raise DecodeError(f"{len(data) - o} unexpected bytes at offset {o}")
        return value

    @classmethod
    def _read(cls: Type[_L], data: Any, o: int, prefix: str) -> Tuple[_L, int]:
        vals: List[Any] = []
        for op in cls._OPS:
            o = op.read(data, o, vals, prefix)
        return cls(*vals), o

    def encode(self) -> bytes:
        """The field data (after the field header); raises EncodeError for values that do not fit."""
        out = bytearray()
        self._write(out, "")
        return bytes(out)

    def _write(self, out: bytearray, prefix: str) -> None:
        vals = self._get(self)
        if self._OPTIONAL:
            self._check_optional(vals, prefix)
        for op in self._OPS:
            op.write(out, vals, prefix)

    def _check_optional(self, vals: Any, prefix: str) -> None:
        absent = None
        for op in self._OPS:
            if not op.optional:
                continue
            if vals[op.index] is None:
                if not op.is_empty(vals):
                    absent = absent or op.name
            elif absent is not None:
                raise EncodeError(
                    f"{prefix}{op.name}: present although the optional parameter {absent} before it is absent"
                )

    # -- canonical JSON
    def to_json(self) -> str:
        """The canonical JSON object of the values (docs/conformance.md section 4)."""
        vals = self._get(self)
        parts: List[str] = []
        last = -1
        if self._OPTIONAL:
            last = max((op.index for op in self._OPS if op.optional and vals[op.index] is not None), default=-1)
        for op in self._OPS:
            if op.optional and vals[op.index] is None:
                # A union member without data is present (null) when a later optional parameter is.
                if op.index < last and op.is_empty(vals):
                    parts.append(f'"{op.name}":null')
                continue
            op.to_json(vals, parts)
        return "{" + ",".join(parts) + "}"

    @classmethod
    def from_json(cls: Type[_L], obj: Any, prefix: str = "") -> _L:
        """Build a value from a parsed canonical JSON object (raises EncodeError naming the path)."""
        if not isinstance(obj, dict):
            raise EncodeError(f"{prefix.rstrip('.') or 'values'}: expected an object, got {_show(obj)}")
        for k in obj:
            if k not in cls._KEYS:
                raise EncodeError(f"{prefix}{k}: unknown parameter")
        vals: List[Any] = []
        for op in cls._OPS:
            op.from_json(obj, vals, prefix)
        return cls(*vals)


class Struct(Layout):
    """Base of generated structs."""


class Field(Layout):
    """Base of generated commands, responses, data fields and reserved fields."""

    __slots__ = ()

    SET: Optional[int] = None
    DESCRIPTOR = 0
    NAME = ""
    ROLE = ""
    DEVICE: Optional[str] = None
    APPLIES_TO: Optional[str] = None


def slotted(cls: Type[_L]) -> Type[_L]:
    """The dataclass `cls` made again with a slot per field and no instance __dict__, as
    dataclass(slots=True) of Python 3.10 makes it (here for every supported version): smaller
    instances, faster attribute access, and values the C accelerator stores without a lookup.
    Fields, equality, repr, pickling and copying are those of the dataclass."""
    import dataclasses

    klass: Any = cls
    names = tuple(f.name for f in dataclasses.fields(klass))
    namespace = dict(klass.__dict__)
    for name in names + ("__dict__", "__weakref__"):
        namespace.pop(name, None)
    namespace["__slots__"] = names
    new: Type[_L] = type(klass)(klass.__name__, klass.__bases__, namespace)
    new.__qualname__ = klass.__qualname__
    return new


def fast_items(cls: Type[Layout]) -> Optional[Tuple[Tuple[str, str, int, int, Any], ...]]:
    """A layout as fixed-size wire items for the C accelerator, or None when the pure-Python decoder
    must read it (optional, counted, nested or union parameters, signed enums).

    Items are (attribute, kind, element size, count or -1 for a scalar, aux); the C side builds the
    same values as `Run.read` and hands every NaN, invalid bool and size mismatch back to `decode`.
    """
    items: List[Tuple[str, str, int, int, Any]] = []
    attrs = cls._ATTRS
    for op in cls._OPS:
        if type(op) is not Run:
            return None
        for p in op.params:
            s = p.scalar
            if s.fast is None or (p.count is not None and s.fast[0] == "s"):
                return None
            if len(items) >= len(attrs):
                return None
            items.append((attrs[len(items)], s.fast[0], s.size, -1 if p.count is None else p.count, s.fast[1]))
    if len(items) != len(attrs):
        return None
    return tuple(items)


class Union:
    """Base of generated unions: `_MEMBERS` maps selector values to member structs (None: no data)."""

    _SELECTOR: Any = None
    _MEMBERS: Dict[int, Optional[Type[Struct]]] = {}

    @classmethod
    def member(cls, selector: int) -> Optional[Type[Struct]]:
        """The member struct for a selector value (None for a member without data); KeyError if none."""
        return cls._MEMBERS[int(selector)]
