"""Facts of the C++ language that the C++ back end needs, as data: reserved words and the C++
type of each IR primitive. Nothing here knows about a protocol."""

from __future__ import annotations

from generator.targets import GettingStarted

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

# Identifiers besides KEYWORDS that a C++ program cannot use as a member or namespace name: an IR
# name among them gets a "_" suffix too (backend.ident), and the name check (generator/name_check.py,
# targets/cpp/identifiers.py) refuses any generated identifier left equal to one.
# - The C++ library's macros with lower-case names ([headers], the C headers' macros C++ keeps:
#   `assert` <cassert>, `errno` <cerrno>, `stdin`/`stdout`/`stderr` <cstdio>, `offsetof` <cstddef>,
#   `setjmp` <csetjmp>, `va_arg`/`va_copy`/`va_end`/`va_start` <cstdarg>, `math_errhandling`
#   <cmath>), some already in KEYWORDS above.
# - g++'s and clang++'s system-specific predefined macros in their default GNU modes (GCC manual,
#   "System-specific Predefined Macros"): `linux` and `unix` (`g++ -dM -E -x c++ /dev/null` on
#   Linux), `i386` (with `-m32`).
RESERVED = frozenset(
    """
    assert errno stdin stdout stderr offsetof setjmp va_arg va_copy va_end va_start math_errhandling
    linux unix i386
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


# The getting-started page (generated/docs/getting-started/cpp.md).
GETTING_STARTED = GettingStarted(
    install="Copy `generated/cpp/{pkg}/` into your tree (a C++17 library: CMake builds it) and add it to your CMake build (or"
    " install it and use `find_package({pkg} CONFIG REQUIRED)` or pkg-config: see the package's README):",
    setup="add_subdirectory(third_party/{pkg})\ntarget_link_libraries(your_app PRIVATE {pkg}::cpp)",
    setup_lang="cmake",
    setup_outside="project",
    include_intro="and include the package's umbrella header:",
    run_package_var="CPP_PACKAGE",
    outside_run="cmake -S . -B build -D{PKG}_BUILD_EXAMPLES=ON && cmake --build build --target {pkg}-configure-and-stream\n"
    "build/{pkg}-configure-and-stream ADDRESS 5",
)
