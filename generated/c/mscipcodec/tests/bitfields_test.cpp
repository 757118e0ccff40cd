// Bitfield masks, from generator/testcases.py: the bitfield members that the C, C++, Python and
// Rust packages all check. Generated: do not edit.
#include <gtest/gtest.h>

#include <cstdint>

#include "test_support.hpp"

namespace {

// mscipc_gps_time_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, GpsTimeFlags) {
    const mscipc_gps_time_flags_t all =
        static_cast<mscipc_gps_time_flags_t>(~static_cast<mscipc_gps_time_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MSCIPC_GPS_TIME_FLAGS_PPS_RECEIVED_MASK), UINT64_C(0x1));
    EXPECT_EQ(MSCIPC_GPS_TIME_FLAGS_PPS_RECEIVED_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MSCIPC_GPS_TIME_FLAGS_PPS_RECEIVED_MASK) >>
                                    MSCIPC_GPS_TIME_FLAGS_PPS_RECEIVED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MSCIPC_GPS_TIME_FLAGS_TIME_SET_MASK), UINT64_C(0x2));
    EXPECT_EQ(MSCIPC_GPS_TIME_FLAGS_TIME_SET_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MSCIPC_GPS_TIME_FLAGS_TIME_SET_MASK) >>
                                    MSCIPC_GPS_TIME_FLAGS_TIME_SET_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MSCIPC_GPS_TIME_FLAGS_TIME_NOT_SET_MASK), UINT64_C(0x4));
    EXPECT_EQ(MSCIPC_GPS_TIME_FLAGS_TIME_NOT_SET_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MSCIPC_GPS_TIME_FLAGS_TIME_NOT_SET_MASK) >>
                                    MSCIPC_GPS_TIME_FLAGS_TIME_NOT_SET_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MSCIPC_GPS_TIME_FLAGS_PPS_LOST_MASK), UINT64_C(0x8));
    EXPECT_EQ(MSCIPC_GPS_TIME_FLAGS_PPS_LOST_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MSCIPC_GPS_TIME_FLAGS_PPS_LOST_MASK) >>
                                    MSCIPC_GPS_TIME_FLAGS_PPS_LOST_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MSCIPC_GPS_TIME_FLAGS_RESERVED_MASK), UINT64_C(0xFFF0));
    EXPECT_EQ(MSCIPC_GPS_TIME_FLAGS_RESERVED_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MSCIPC_GPS_TIME_FLAGS_RESERVED_MASK) >>
                                    MSCIPC_GPS_TIME_FLAGS_RESERVED_SHIFT),
              UINT64_C(0xFFF));
}

} // namespace
