"""Word splitting and casing of spec names, shared by the language back ends.

Spec names are snake_case (fields, parameters, devices, enum values) or CamelCase (types). A
back end turns them into its own identifiers with these functions and then applies its own rules
(keywords, reserved names, prefixes), which stay in the back end.

The languages differ in one place, kept as options of `camel` so that generated names do not
change: Rust keeps a `_` where a digit word follows a digit (`udre_scale_0_5` -> `UdreScale0_5`,
where C++ and Python write `UdreScale05`) and puts `T` before a name that would start with a digit.
"""

from __future__ import annotations

import re


def words(name: str) -> list[str]:
    """The words of a snake_case name; empty words (doubled, leading or trailing `_`) are dropped."""
    return [w for w in name.split("_") if w]


def camel(name: str, *, digit_break: str = "", leading_digit: str = "") -> str:
    """snake_case -> CamelCase: each word's first letter upper-cased, the rest kept, so a name
    that already is CamelCase (`GpsTime`) comes back unchanged.

    digit_break: put between two words when the first ends and the second starts with a digit
        (Rust: "_", so `a_1_2` and `a_12` stay different).
    leading_digit: put before a result that is empty or starts with a digit (Rust: "T").
    """
    out = ""
    for w in words(name):
        piece = w[0].upper() + w[1:]
        if out and out[-1].isdigit() and piece[0].isdigit():
            out += digit_break
        out += piece
    if leading_digit and (not out or out[0].isdigit()):
        out = leading_digit + out
    return out


def snake(name: str) -> str:
    """CamelCase -> snake_case, an acronym kept as one word (`Gx5BitFlags` -> `gx5_bit_flags`,
    `GNSSTime` -> `gnss_time`)."""
    s = re.sub(r"([A-Z]+)([A-Z][a-z])", r"\1_\2", name)
    s = re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", s)
    return s.lower()


def upper(name: str) -> str:
    """A snake_case name as an upper-case constant (`wrong_length` -> `WRONG_LENGTH`)."""
    return name.upper()
