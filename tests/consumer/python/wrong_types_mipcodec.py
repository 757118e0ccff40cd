"""Type errors mypy --strict must report against the installed mipcodec (one per line marked
`# expected error`): if the package lost its py.typed marker or its return types became Any,
these lines would pass unnoticed. Never run, only type-checked by tests/consumer/test_python_package.py.
"""

from __future__ import annotations

from mipcodec import Packet, decode_packet
from mipcodec.reserved import AckNack
from mipcodec.sensor import ScaledAccel

name: int = ScaledAccel.decode(b"").NAME  # expected error
accel: ScaledAccel = decode_packet(b"")  # expected error
packet: Packet = ScaledAccel.from_json({})  # expected error
count: str = decode_packet(b"").set  # expected error
code: str = AckNack.decode(b"").ack_code.name  # expected error
