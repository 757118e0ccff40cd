"""The wire primitives and the built-in aggregate aliases (vector/matrix/quaternion types).

Language back ends map these names to their own types; this table holds only wire facts.
"""

from __future__ import annotations

# name -> (size in bytes, kind, signed)
PRIMITIVES: dict[str, tuple[int, str, bool]] = {
    "bool": (1, "bool", False),
    "char": (1, "char", False),
    "u8": (1, "int", False),
    "u16": (2, "int", False),
    "u32": (4, "int", False),
    "u64": (8, "int", False),
    "s8": (1, "int", True),
    "s16": (2, "int", True),
    "s32": (4, "int", True),
    "s64": (8, "int", True),
    "float": (4, "float", True),
    "double": (8, "float", True),
}

# Standard MIP vector types (3dm-cv7-ins-docs.txt "Vector Types", line 8851): element and count.
ALIASES: dict[str, tuple[str, int]] = {
    "vector3f": ("float", 3),
    "vector3d": ("double", 3),
    "vector4f": ("float", 4),
    "vector4d": ("double", 4),
    "quatf": ("float", 4),
    "matrix3f": ("float", 9),
    "matrix3d": ("double", 9),
}

INTEGER_TYPES = [n for n, (_, k, _) in PRIMITIVES.items() if k == "int"]


def int_range(name: str) -> tuple[int, int]:
    size, _, signed = PRIMITIVES[name]
    bits = size * 8
    if signed:
        return -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    return 0, (1 << bits) - 1
