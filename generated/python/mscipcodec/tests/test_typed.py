"""Typed round trips of mscipcodec: every layout class with sample values, every bitfield member
(tests/typed_cases.py, generated from the spec). Plain source, the same in every package
(generator/targets/python/runtime/package_tests/)."""

import pytest
from typed_cases import BITFIELD_MEMBERS, SAMPLES, canonical, framing, packets, registry

loads = canonical.loads
MAX_FIELD_DATA, PacketBuilder = framing.MAX_FIELD_DATA, framing.PacketBuilder
DecodedField, decode_packet = packets.DecodedField, packets.decode_packet
SET_KINDS = registry.SET_KINDS


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
