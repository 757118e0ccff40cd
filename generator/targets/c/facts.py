"""Facts of the C language the back end names things by: reserved words and the C type of each
wire primitive. Data only, so that adding a primitive or a keyword is one line here."""

from __future__ import annotations

from generator.targets import GettingStarted

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

# Identifiers that are not keywords but that a C program including the standard headers, or
# compiled by gcc or clang in their default GNU modes, cannot use as a struct member: a spec
# identifier among them gets a trailing underscore too (backend.member), and the name check
# (generator/name_check.py, targets/c/identifiers.py) refuses any generated identifier left equal to one.
# - The C library's macros with lower-case names (ISO C17, clause 7): `assert` and
#   `static_assert` (7.2 <assert.h>), `complex`, `imaginary` (7.3 <complex.h>), `errno` (7.5
#   <errno.h>), `math_errhandling` (7.12 <math.h>), `setjmp` (7.13 <setjmp.h>), `va_arg`,
#   `va_copy`, `va_end`, `va_start` (7.16 <stdarg.h>), `offsetof` (7.19 <stddef.h>), `stdin`,
#   `stdout`, `stderr` (7.21 <stdio.h>), `noreturn` (7.23 <stdnoreturn.h>); and `NULL`, `EOF`.
#   The function-like ones (`assert`, `setjmp`, `va_*`, `offsetof`) only expand before a `(`;
#   they are listed too, so that no generated name depends on how it happens to be used.
# - The compilers' system-specific predefined macros (GCC manual, "System-specific Predefined
#   Macros": the non-reserved spellings in GNU modes): `linux` and `unix` (`gcc -dM -E` on
#   Linux), `i386` (`gcc -m32 -dM -E`, 32-bit x86).
RESERVED = frozenset(
    """
assert static_assert complex imaginary errno math_errhandling setjmp va_arg va_copy va_end va_start
offsetof stdin stdout stderr noreturn NULL EOF
linux unix i386
""".split()
)


# The getting-started page (generated/docs/getting-started/c.md).
GETTING_STARTED = GettingStarted(
    install="Copy `generated/c/{pkg}/` into your tree (C99, no allocation, no dependencies) and add it to your"
    " CMake build (or install it and use `find_package({pkg} CONFIG REQUIRED)` or pkg-config: see"
    " the package's README). Its tests, tools and examples stay off when it is not the top-level"
    " project:",
    setup="add_subdirectory(third_party/{pkg})\n"
    "target_link_libraries(your_app PRIVATE {pkg}::c)   # {pkg}::c_json for canonical JSON lines",
    setup_lang="cmake",
    setup_outside="project",
    include_intro="and include the package's umbrella header:",
    run_package_var="C_PACKAGE",
    # only the example run (--target): the package's other examples are not needed for it
    outside_run="cmake -S . -B build -D{PKG}_BUILD_EXAMPLES=ON && cmake --build build --target {pkg}-configure-and-stream\n"
    "build/{pkg}-configure-and-stream ADDRESS 5",
)
