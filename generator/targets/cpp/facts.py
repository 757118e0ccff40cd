"""Facts of the C++ language that the C++ back end needs, as data: reserved words and the C++
type of each IR primitive. Nothing here knows about a protocol."""

from __future__ import annotations

# C++20 keywords and alternative tokens, and names (std, common macros) that a generated member or
# namespace must not shadow: an IR name among these gets a "_" suffix (backend.ident).
KEYWORDS = frozenset(
    """
    alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t char16_t char32_t class
    compl concept const consteval constexpr constinit const_cast continue co_await co_return co_yield decltype
    default delete do double dynamic_cast else enum explicit export extern false float for friend goto if inline
    int long mutable namespace new noexcept not not_eq nullptr operator or or_eq private protected public register
    reinterpret_cast requires return short signed sizeof static static_assert static_cast struct switch template
    this thread_local throw true try typedef typeid typename union unsigned using virtual void volatile wchar_t
    while xor xor_eq
    std NULL assert errno stdin stdout stderr EOF
    """.split()
)

# The C++ type of each IR primitive (generator/primitives.py names): fixed-width integers from
# <cstdint>, IEEE-754 float and double, one-byte char and bool.
PRIMITIVE_TYPES = {
    "bool": "bool",
    "char": "char",
    "u8": "std::uint8_t",
    "u16": "std::uint16_t",
    "u32": "std::uint32_t",
    "u64": "std::uint64_t",
    "s8": "std::int8_t",
    "s16": "std::int16_t",
    "s32": "std::int32_t",
    "s64": "std::int64_t",
    "float": "float",
    "double": "double",
}
