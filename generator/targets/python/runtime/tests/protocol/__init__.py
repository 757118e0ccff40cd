"""A small test protocol for the runtime's unit tests (generator/targets/python/runtime/tests/).

The tests' conftest.py copies the runtime files and these hand-written stand-ins for the generated
modules (_protocol, _protocol.h, types, registry, one module per descriptor set, reserved) into
one package, `testproto`, under build/python/runtime/. Its two framings (_protocol.py here,
framing_b/ with TESTPROTO_FRAMING=b) take the two branches of each framing choice of the runtime
(byte order, field header order, what the length byte counts, checksum byte order); both have a
maximum payload below 255, a field with an irregular length byte, per-device variants and shared
timestamps.
"""

from .framing import ACCELERATED
from .packets import Decoder, decode_all, decode_columns

__all__ = ["ACCELERATED", "Decoder", "decode_all", "decode_columns"]
