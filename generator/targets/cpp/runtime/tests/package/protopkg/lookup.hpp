// Stub package "protopkg" for the in-place runtime tests: hand-written in the shape of the
// generated lookup.hpp (templates/cpp/include/lookup.hpp.j2), with a switch for its tables.
// Set 0x01 is defined (descriptors 0x01..0x03), every other set is unknown.
#pragma once

#include <cstdint>
#include <type_traits>

#include "protopkg/devices.hpp"
#include "protopkg/fields.hpp"

namespace protopkg {

template <class... Ts> struct Layouts {};

enum class Lookup : std::uint8_t { found, unknown_set, unknown_descriptor };

/// The case of field (set, descriptor): 0 unknown set, 1 unknown descriptor, else the field's layouts.
inline unsigned field_case(std::uint8_t set, std::uint8_t descriptor) {
    if (set != 0x01) {
        return 0;
    }
    return descriptor >= 0x01 && descriptor <= 0x03 ? 1u + descriptor : 1u;
}

template <class F> bool visit_case(unsigned c, F &&f) {
    switch (c) {
    case 2:
        f(Layouts<stub::Ping>{});
        return true;
    case 3:
        f(Layouts<stub::InfoGx, stub::InfoCv>{});
        return true;
    case 4:
        f(Layouts<stub::Switch>{});
        return true;
    default:
        return false;
    }
}

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
