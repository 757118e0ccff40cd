// (set, descriptor) -> the layouts of that field (docs/conformance.md section 2): fields of a
// defined set, then reserved fields by set kind, then shared data fields in data sets. That search
// is done by the generator, which writes its answers as the tables of lookup_tables.hpp (the one
// generated input here); here it is two table loads (field_case) and one indirect call.
#pragma once

#include <cstdint>
#include <type_traits>

#include "protopkg/lookup_tables.hpp"
#include "protopkg/lookup_types.hpp"

namespace protopkg {

/// The case of field (set, descriptor): 0 unknown set, 1 unknown descriptor, else the field's layouts.
inline unsigned field_case(std::uint8_t set, std::uint8_t descriptor) {
    return detail::kFieldCases[detail::kSetRow[set]][descriptor];
}

/// Calls f(Layouts<...>{}) for the layouts of case field_case(set, descriptor) (>= 2); false for 0 and 1.
template <class F> bool visit_case(unsigned c, F &&f) {
    using Calls = detail::FieldCases::Calls<std::remove_reference_t<F>>;
    if (c < 2 || c >= sizeof Calls::kCalls / sizeof Calls::kCalls[0]) {
        return false;
    }
    Calls::kCalls[c](f);
    return true;
}

/// Calls f(Layouts<...>{}) for the field (set, descriptor) and returns found, or says why not.
template <class F> Lookup lookup_field(std::uint8_t set, std::uint8_t descriptor, F &&f) {
    const unsigned c = field_case(set, descriptor);
    if (c == 0) {
        return Lookup::unknown_set;
    }
    if (c == 1) {
        return Lookup::unknown_descriptor;
    }
    visit_case(c, f);
    return Lookup::found;
}

} // namespace protopkg
