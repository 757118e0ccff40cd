"""Facts of the C language the back end names things by: reserved words and the C type of each
wire primitive. Data only, so that adding a primitive or a keyword is one line here."""

from __future__ import annotations

# C99 and C++ keywords (the headers are also compiled as C++ by the tests) and names the
# generated code uses itself. A spec identifier among them gets a trailing underscore.
KEYWORDS = frozenset(
    """
auto break case char const continue default do double else enum extern float for goto if inline int long
register restrict return short signed sizeof static struct switch typedef union unsigned void volatile while
_Bool _Complex _Imaginary bool true false alignas alignof and and_eq asm bitand bitor catch class compl
const_cast constexpr decltype delete dynamic_cast explicit export friend mutable namespace new noexcept not
not_eq nullptr operator or or_eq private protected public reinterpret_cast static_assert static_cast
template this thread_local throw try typeid typename using virtual wchar_t xor xor_eq char16_t char32_t
""".split()
)

# wire primitive -> (C type, suffix of the runtime functions rd_/wr_/jw_/jr_/ld_ in
# generator/targets/c/runtime/)
PRIMITIVE_TYPES = {
    "bool": ("bool", "bool"),
    "char": ("char", "char"),
    "u8": ("uint8_t", "u8"),
    "u16": ("uint16_t", "u16"),
    "u32": ("uint32_t", "u32"),
    "u64": ("uint64_t", "u64"),
    "s8": ("int8_t", "s8"),
    "s16": ("int16_t", "s16"),
    "s32": ("int32_t", "s32"),
    "s64": ("int64_t", "s64"),
    "float": ("float", "f32"),
    "double": ("double", "f64"),
}
