// The types of the field lookup (docs/conformance.md section 2) that the generated tables of
// lookup_tables.hpp are written in: a list of layout types, the answer of a lookup, and the list
// of a package's field cases, called through a table.
#pragma once

#include <cstdint>

namespace protopkg {

/// A list of layout types (one, or one per device variant, in IR order).
template <class... Ts> struct Layouts {};

enum class Lookup : std::uint8_t { found, unknown_set, unknown_descriptor };

namespace detail {

/// One field case: calls f with the case's Layouts<...>. A function template of its own, not a
/// member of CaseList, so that its name does not spell out every case of the package (with MinGW
/// the names of a few hundred such functions overflowed the PE object's string table).
template <class F, class L> void call_case(F &f) {
    f(L{});
}

/// The field cases 2, 3, ... of a package (0 is an unknown set, 1 an unknown descriptor), each a
/// Layouts<...>. One function per case, called through a table: each keeps its own (small) stack
/// frame, and the dispatch is one bounds check, one load and one indirect call.
template <class... Cases> struct CaseList {
    template <class F> struct Calls {
        static constexpr void (*kCalls[])(F &) = {nullptr, nullptr, &call_case<F, Cases>...};
    };
};

} // namespace detail

} // namespace protopkg
