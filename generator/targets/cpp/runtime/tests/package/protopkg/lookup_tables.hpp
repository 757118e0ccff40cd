// Stub package "protopkg" for the in-place runtime tests: hand-written in the shape of the
// generated lookup_tables.hpp (templates/cpp/include/lookup_tables.hpp.j2), the tables that the
// runtime's lookup.hpp reads. Set 0x01 is defined (descriptors 0x01..0x03), every other set is
// unknown.
#pragma once

#include <array>
#include <cstdint>

#include "protopkg/devices.hpp"
#include "protopkg/fields.hpp"
#include "protopkg/lookup_types.hpp"

namespace protopkg::detail {

/// Row 1 for set 0x01, row 0 (every descriptor unknown) for the other sets.
inline constexpr std::uint8_t kSetRow[256] = {0, 1};

/// Row 0: unknown set; row 1: descriptors 0x01..0x03 are cases 2..4, the others unknown.
constexpr std::array<std::array<std::uint8_t, 256>, 2> field_cases() {
    std::array<std::array<std::uint8_t, 256>, 2> rows{};
    for (unsigned d = 0; d < 256; ++d) {
        rows[1][d] = static_cast<std::uint8_t>(d >= 0x01 && d <= 0x03 ? 1 + d : 1);
    }
    return rows;
}
inline constexpr std::array<std::array<std::uint8_t, 256>, 2> kFieldCases = field_cases();

using FieldCases = CaseList<Layouts<stub::Ping>, Layouts<stub::InfoGx, stub::InfoCv>, Layouts<stub::Switch>>;

} // namespace protopkg::detail
