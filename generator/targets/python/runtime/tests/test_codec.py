"""codec.py and canonical.py: typed layouts, wire errors, canonical JSON of floats and strings."""

import dataclasses
import json
import struct
import sys
import typing
from pathlib import Path

import pytest
from testproto.codec import layout as c
from testproto.codec.canonical import NaN, f32_text, f64_text, float_from_json, string_text

ROOT = Path(__file__).resolve().parents[5]


# ----------------------------------------------------------------------------------- codec
class Mode(c.Enum):
    NONE = 0
    PAIR = 1


@dataclasses.dataclass
class Pair(c.Struct):
    a: int = 0
    b: bool = False

    _ATTRS = ("a", "b")
    _OPS = (c.Run(c.P("a", c.U8), c.P("b", c.BOOL)),)
    _SIZE = 2


class PairOrNothing(c.Union):
    _SELECTOR = Mode
    _MEMBERS = {0: None, 1: Pair}


@dataclasses.dataclass
class Everything(c.Field):
    x: int = 0
    v: typing.List[float] = dataclasses.field(default_factory=lambda: [0.0, 0.0])
    n: int = 0
    items: typing.List[int] = dataclasses.field(default_factory=list)
    mode: Mode = Mode.NONE
    choice: typing.Optional[Pair] = None
    pairs: typing.List[Pair] = dataclasses.field(default_factory=list)
    tail: typing.Optional[typing.List[int]] = None

    _ATTRS = ("x", "v", "n", "items", "mode", "choice", "pairs", "tail")
    _OPS = (
        c.Run(c.P("x", c.U16), c.P("v", c.F32, 2), c.P("n", c.U8)),
        c.Counted("items", c.S16, count="n", maximum=3),
        c.Run(c.P("mode", c.enum(Mode, "u8"))),
        c.Choice("choice", PairOrNothing, selector="mode"),
        c.Repeat("pairs", Pair, 1),
        c.Opt(c.Remaining("tail", c.U16, maximum=4)),
    )


BO = c.BYTE_ORDER


def sample_bytes():
    return (
        struct.pack(BO + "Hff", 7, 1.5, -2.0)
        + struct.pack(BO + "Bhh", 2, -1, 300)
        + bytes([1, 9, 1])
        + bytes([4, 0])
        + struct.pack(BO + "HH", 5, 6)
    )


def test_typed_round_trip():
    data = sample_bytes()
    v = Everything.decode(data)
    assert v == Everything(7, [1.5, -2.0], 2, [-1, 300], Mode.PAIR, Pair(9, True), [Pair(4, False)], [5, 6])
    assert v.encode() == data
    assert v.to_json() == (
        '{"x":7,"v":[1.5,-2.0],"n":2,"items":[-1,300],"mode":1,"choice":{"a":9,"b":true},'
        '"pairs":[{"a":4,"b":false}],"tail":[5,6]}'
    )
    assert Everything.from_json(json.loads(v.to_json())) == v
    short = data[:-4]
    assert Everything.decode(short).tail is None
    assert '"tail"' not in Everything.decode(short).to_json()


@pytest.mark.parametrize(
    "mutate,message",
    [
        (lambda d: d[:8], "v[1]: needs 4 bytes at offset 6, 2 left"),
        (lambda d: d[:10] + b"\x04" + d[11:], "items: count 4 exceeds maximum 3"),
        (lambda d: d[:17] + b"\x02" + d[18:], "choice.b: invalid bool value 2 at offset 17"),
        (lambda d: d[:15] + b"\x05" + d[16:], "choice: no member for selector value 5"),
        (lambda d: d[:18], "pairs[0].a: needs 1 bytes at offset 18, 0 left"),
        (lambda d: d + b"\x01", "tail: 5 bytes left at offset 20, not a multiple of 2"),
        (lambda d: d + b"\x00\x01" * 3, "tail: count 5 exceeds maximum 4"),
    ],
)
def test_decode_errors(mutate, message):
    with pytest.raises(c.DecodeError) as e:
        Everything.decode(mutate(sample_bytes()))
    assert str(e.value) == message


def test_unexpected_bytes():
    with pytest.raises(c.DecodeError) as e:
        Pair.decode(b"\x01\x00\x07")
    assert str(e.value) == "1 unexpected bytes at offset 2"


def test_unknown_enum_values_are_kept():
    v = Everything.decode(sample_bytes()[:15] + b"\x00" + sample_bytes()[18:])
    assert v.mode is Mode.NONE and v.choice is None
    assert c.enum(Mode, "u8").post(7, b"", 0) == 7


def test_encode_errors():
    with pytest.raises(c.EncodeError, match="x: 70000 is out of range for u16"):
        Everything(x=70000).encode()
    with pytest.raises(c.EncodeError, match="items: has 1 elements but n is 0"):
        Everything(items=[1]).encode()
    with pytest.raises(c.EncodeError, match="choice: expected a Pair"):
        Everything(mode=Mode.PAIR).encode()
    with pytest.raises(c.EncodeError, match=r"pairs\[0\].b: 2 is not a bool"):
        Everything(pairs=[Pair(1, 2)]).encode()


# ----------------------------------------------------------------------------------- floats, strings
def test_nan_bits_are_kept():
    for bits in (0x7FE5BF7F, 0x7F800001, 0xFFC00000, 0x7FC00000):
        # x, v[0] = the NaN, v[1] = 0.0, n = 0, mode = none, one pair
        data = struct.pack(BO + "HIf", 1, bits, 0.0) + bytes([0, 0, 0, 0])
        v = Everything.decode(data)
        assert isinstance(v.v[0], NaN) and v.v[0].bits == bits
        assert f32_text(v.v[0]) == ('"nan"' if bits == 0x7FC00000 else f'"nan:0x{bits:08x}"')
        assert v.encode()[2:6] == struct.pack(BO + "I", bits)
    assert float_from_json("nan:0x7fe5bf7f", 32).bits == 0x7FE5BF7F
    assert f64_text(float_from_json("nan:0x7ff0000000000001", 64)) == '"nan:0x7ff0000000000001"'
    assert f64_text(float("nan")) == '"nan"'


@pytest.mark.parametrize(
    "value,text",
    [
        (1.0, "1.0"),
        (0.0001, "0.0001"),
        (1e-05, "1e-05"),
        (1e16, "1e+16"),
        (1.5e16, "1.5e+16"),
        (123.456, "123.456"),
        (-0.0, "-0.0"),
        (2.5e-310, "2.5e-310"),
        (float("inf"), '"inf"'),
        (float("-inf"), '"-inf"'),
    ],
)
def test_float_text(value, text):
    assert f64_text(value) == text


def test_float_text_widens_floats():
    x = struct.unpack(">f", struct.pack(">f", 0.1))[0]
    assert f32_text(x) == "0.10000000149011612"


def test_string_text():
    assert string_text(b'a"\\\x00\x1f \x7e\x7f\xff') == '"a\\"\\\\\\u0000\\u001f ~\\u007f\\u00ff"'


def _facts():
    """generator/targets/python/facts.py: what the back end assumes about this runtime."""
    sys.path.insert(0, str(ROOT))
    try:
        from generator.targets.python import facts
    finally:
        sys.path.remove(str(ROOT))
    return facts


def test_the_generators_type_table_names_these_scalars():
    # Each primitive maps to a scalar of this module and its struct format: they must be the runtime's.
    for name, prim in _facts().PRIMITIVES.items():
        scalar = getattr(c, prim.scalar)
        assert (scalar.type_name, scalar.code) == (name, prim.struct), name


def test_the_generators_reserved_names_cover_the_base_classes():
    # A parameter named like a method of Layout, or a bitfield member like one of Bitfield, is renamed.
    facts = _facts()
    assert {n for n in vars(c.Layout) if not n.startswith("_")} <= facts.LAYOUT_ATTRIBUTES
    assert {n for n in vars(c.Bitfield) if not n.startswith("_")} <= facts.BITFIELD_ATTRIBUTES
