"""What a user's own code can do by mistake (issue 28): decode_packet of bad bytes, an unknown
device, a typed field of another descriptor set. Bad input raises FramingError (a ValueError of
the package) naming what is wrong; the pure and the accelerated code take the same input types
(tests/lang/python.sh runs this file both ways)."""

import array

import pytest
from testproto import control, registry, reserved, sensor, shared
from testproto.codec.framing import CHECKSUM_SIZE, HEADER_SIZE, LENGTH_OFFSET, SYNC, FramingError, PacketBuilder, parse
from testproto.codec.packets import Decoder, decode_all, decode_field, decode_packet, event_line

SET_ID = control.Ping.SET


def _packet():
    return PacketBuilder(SET_ID).add(control.Ping()).build()


def test_a_good_packet_decodes_from_every_bytes_like_type():
    good = _packet()
    expected = decode_packet(good)
    assert expected.set == SET_ID and len(expected.fields) == 1
    for form in (bytearray(good), memoryview(good), memoryview(b"xx" + good)[2:], array.array("B", good)):
        assert decode_packet(form).line() == expected.line()


@pytest.mark.parametrize("bad", ["7565", [0x75, 0x65], 5, None, 3.0])
def test_a_packet_that_is_not_bytes_like_is_a_type_error(bad):
    with pytest.raises(TypeError, match="packet must be bytes-like"):
        decode_packet(bad)


@pytest.mark.parametrize("n", range(HEADER_SIZE + CHECKSUM_SIZE))
def test_too_short_for_a_header_and_checksum(n):
    with pytest.raises(FramingError, match=rf"a packet of {n} bytes is shorter than a header and checksum"):
        decode_packet(_packet()[:n])


def test_wrong_sync_length_or_checksum_is_an_error_unless_the_check_is_skipped():
    good = _packet()
    bad_sync = bytes([good[0] ^ 0xFF]) + good[1:]
    with pytest.raises(FramingError, match="does not start with the sync bytes " + SYNC.hex(" ")):
        decode_packet(bad_sync)
    bad_sum = good[:-1] + bytes([good[-1] ^ 0x01])
    with pytest.raises(FramingError, match=r"checksum .* is wrong, expected .* \(pass check=False"):
        decode_packet(bad_sum)
    overrun = bytearray(good)
    overrun[LENGTH_OFFSET] = 200
    with pytest.raises(FramingError, match=r"the length byte says 200 payload bytes, the packet holds \d+"):
        decode_packet(bytes(overrun))
    with pytest.raises(FramingError, match="the length byte says"):
        decode_packet(good + b"\x00")  # one byte too many
    # Asked for: decoded as they are, the payload being the bytes between header and checksum.
    assert decode_packet(bad_sum, check=False).line() == decode_packet(good).line()
    assert decode_packet(bytes(overrun), check=False).set == SET_ID


@pytest.mark.parametrize("device", ["nope", "", "ALPHA", 3])
def test_an_unknown_device_is_an_error(device):
    good = _packet()
    message = r"unknown device .* \(expected None or one of " + ", ".join(registry.DEVICES) + r"\)"
    with pytest.raises(FramingError, match=message):
        decode_packet(good, device=device)
    with pytest.raises(FramingError, match=message):
        Decoder(device=device)
    with pytest.raises(FramingError, match=message):
        decode_all(good, device=device)
    with pytest.raises(FramingError, match=message):
        event_line(parse(good)[0], device=device)
    with pytest.raises(FramingError, match=message):
        decode_field(SET_ID, control.Ping.DESCRIPTOR, b"", device=device)
    for known in registry.DEVICES:
        assert decode_packet(good, device=known).set == SET_ID


def test_a_typed_field_of_another_set_is_refused():
    # The case: a command of one set added to a packet of another becomes another command.
    data_set = sensor.Reading.SET
    with pytest.raises(
        FramingError, match=r"ping \(descriptor 0x01\) is not a field of descriptor set 0x%02x" % data_set
    ):
        PacketBuilder(data_set).add(control.Ping())
    with pytest.raises(FramingError, match="reading .* is not a field of descriptor set 0x%02x" % SET_ID):
        PacketBuilder(SET_ID).add(sensor.Reading())
    # A reserved field only in a set of its kind; a shared data field only in a data set.
    with pytest.raises(FramingError, match="ack_nack .* is not a field of descriptor set 0x%02x" % data_set):
        PacketBuilder(data_set).add(reserved.AckNack())
    with pytest.raises(FramingError, match="timestamp .* is not a field of descriptor set 0x%02x" % SET_ID):
        PacketBuilder(SET_ID).add(shared.Timestamp())
    # Its own set, the reserved fields of the set's kind and shared data in a data set are fine.
    assert PacketBuilder(SET_ID).add(control.Ping()).build() == _packet()
    assert decode_packet(PacketBuilder(SET_ID).add(reserved.AckNack()).build()).values() == [reserved.AckNack()]
    built = PacketBuilder(data_set).add(sensor.Reading()).add(shared.Timestamp(ticks=7)).build()
    assert decode_packet(built).values()[1] == shared.Timestamp(ticks=7)
