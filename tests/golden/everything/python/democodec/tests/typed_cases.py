"""Typed samples of democodec (generated): a sample value of every layout class and every bitfield
member, checked by tests/test_typed.py."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

from democodec import commands, data, receiver_1, receiver_2, reserved, shared, types
from democodec import registry
from democodec.codec import canonical, framing, packets

__all__ = ["BITFIELD_MEMBERS", "SAMPLES", "canonical", "framing", "packets", "registry"]

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
