// Bitfield masks, from generator/testcases.py: the bitfield members that the C, C++, Python and
// Rust packages all check. Generated: do not edit.
#include <gtest/gtest.h>

#include <cstdint>

#include "test_support.hpp"

namespace {

// democ_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, Flags) {
    const democ_flags_t all = static_cast<democ_flags_t>(~static_cast<democ_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(DEMOC_FLAGS_OK_MASK), UINT64_C(0x1));
    EXPECT_EQ(DEMOC_FLAGS_OK_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & DEMOC_FLAGS_OK_MASK) >> DEMOC_FLAGS_OK_SHIFT), UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(DEMOC_FLAGS_LEVEL_MASK), UINT64_C(0xF000));
    EXPECT_EQ(DEMOC_FLAGS_LEVEL_SHIFT, 12);
    EXPECT_EQ(static_cast<uint64_t>((all & DEMOC_FLAGS_LEVEL_MASK) >> DEMOC_FLAGS_LEVEL_SHIFT),
              UINT64_C(0xF));
    EXPECT_EQ(static_cast<uint64_t>(DEMOC_FLAGS_ALL_MASK), UINT64_C(0xFFFF));
    EXPECT_EQ(DEMOC_FLAGS_ALL_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & DEMOC_FLAGS_ALL_MASK) >> DEMOC_FLAGS_ALL_SHIFT), UINT64_C(0xFFFF));
}

} // namespace
