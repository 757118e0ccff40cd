"""Typed round trips (generated): every layout class with sample values; every bitfield member."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import pytest
from democodec import commands, data, receiver_1, receiver_2, reserved, shared, types
from democodec.canonical import loads
from democodec.framing import MAX_FIELD_DATA, PacketBuilder
from democodec.packets import DecodedField, decode_packet
from democodec.registry import SET_KINDS

SAMPLES = [
    ("commands.Ping", lambda: commands.Ping()),
    (
        "commands.Configure",
        lambda: commands.Configure(
            function=types.Function.SAVE,
            instance=51,
            mode=types.Mode.GPIO,
            params=types.GpioParams(pin=88, polarity=False),
            suppress_ack=True,
        ),
    ),
    (
        "commands.Configuration",
        lambda: commands.Configuration(
            instance=94,
            count=2,
            rates=[131, 168],
            name=b"bcd\x00\x00\x00\x00\x00",
            label=b"cde             ",
            matrix=[1e16, 123.456, -0.0, 0.1, -2.5e-310, 1e16, 123.456, -0.0, 0.1],
            fixed=[110, -48, 184, -50],
            flags=types.Flags(0x1),
            signed=types.Signed.PLUS_ONE,
            tail=[b"S", b"T"],
        ),
    ),
    ("commands.PerDevice_dev_a", lambda: commands.PerDevice_dev_a(a=211)),
    ("commands.PerDevice_dev_b", lambda: commands.PerDevice_dev_b(b=156, extra=193)),
    ("data.Sample", lambda: data.Sample(quat=[1024.0, -0.0, 1.5, -2.25], big=70, small=35, f=-0.0)),
    ("receiver_1.LlhPosition", lambda: receiver_1.LlhPosition(latitude=-2.5e-310, longitude=1e16, valid_flags=233)),
    ("receiver_2.LlhPosition", lambda: receiver_2.LlhPosition(latitude=123.456, longitude=-0.0, valid_flags=217)),
    ("shared.Timestamp", lambda: shared.Timestamp(nanoseconds=193)),
    ("reserved.Ack", lambda: reserved.Ack(echo=243, code=29)),
    ("types.GpioParams", lambda: types.GpioParams(pin=250, polarity=True)),
    ("types.ThresholdParams", lambda: types.ThresholdParams(low=123.456, high=-0.0, axes=[1.5, -2.25, 0.375])),
]

BITFIELD_MEMBERS = [
    (types.Flags, "ok", "OK", 0, 1, 0x1),
    (types.Flags, "level", "LEVEL", 12, 4, 0xF000),
    (types.Flags, "all", "ALL", 0, 16, 0xFFFF),
]


@pytest.mark.parametrize("name,make", SAMPLES, ids=[s[0] for s in SAMPLES])
def test_encode_decode_round_trip(name, make):
    value = make()
    data = value.encode()
    back = type(value).decode(data)
    assert back == value
    assert back.encode() == data
    assert type(value).from_json(loads(value.to_json())) == value


FIELD_SAMPLES = [s for s in SAMPLES if not s[0].startswith("types.")]


@pytest.mark.parametrize("name,make", FIELD_SAMPLES, ids=[s[0] for s in FIELD_SAMPLES])
def test_in_a_packet(name, make):
    value = make()
    data = value.encode()
    assert len(data) <= MAX_FIELD_DATA, "a sample value must fit in one field"
    set_id = value.SET
    if set_id is None:
        set_id = next(first for kind, first, _last in SET_KINDS if kind == value.APPLIES_TO)
    packet = PacketBuilder(set_id).add(value).build()
    decoded = decode_packet(packet, device=value.DEVICE)
    assert len(decoded.fields) == 1
    entry = decoded.fields[0]
    assert isinstance(entry, DecodedField), entry
    assert entry.value == value


@pytest.mark.parametrize(
    "cls,attr,const,first,width,mask", BITFIELD_MEMBERS, ids=[f"{b[0].__name__}.{b[1]}" for b in BITFIELD_MEMBERS]
)
def test_bitfield_member(cls, attr, const, first, width, mask):
    constant = getattr(cls, const)
    assert isinstance(constant, cls) and constant == mask
    value = cls(mask)
    got = getattr(value, attr)
    if width == 1:
        assert got is True
        assert getattr(cls(0), attr) is False
    else:
        assert got == (1 << width) - 1
    assert cls(0).replace(**{attr: (1 << width) - 1}) == mask
    assert constant in (constant | cls(0))
    assert isinstance(cls(0) | constant, cls)
    assert int(~cls(0)) == cls._ALL
