"""Reference implementation of the canonical JSON of docs/conformance.md section 4.

Used by the generator to turn golden vectors into the exact text every language must print.
It is not the code under test: each generated library has its own implementation.
"""

from __future__ import annotations

import math
import struct


def float_text(value: float, bits: int | None = None, single: bool = False) -> str:
    """Canonical text of a float/double value. `bits` are the raw bits when known (for NaN)."""
    if math.isnan(value):
        if bits is None:
            bits = (
                struct.unpack(">I", struct.pack(">f", value))[0]
                if single
                else struct.unpack(">Q", struct.pack(">d", value))[0]
            )
        canonical = 0x7FC00000 if single else 0x7FF8000000000000
        if bits == canonical:
            return '"nan"'
        return '"nan:0x%0*x"' % (8 if single else 16, bits)
    if math.isinf(value):
        return '"inf"' if value > 0 else '"-inf"'
    return repr(float(value))


def string_text(raw: bytes) -> str:
    out = ['"']
    for b in raw:
        if b == 0x22:
            out.append('\\"')
        elif b == 0x5C:
            out.append("\\\\")
        elif b < 0x20 or b >= 0x7F:
            out.append("\\u%04x" % b)
        else:
            out.append(chr(b))
    out.append('"')
    return "".join(out)
