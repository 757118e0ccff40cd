// Bitfield masks, from generator/testcases.py: the bitfield members that the C, C++, Python and
// Rust packages all check. Generated: do not edit.
#include <gtest/gtest.h>

#include <cstdint>

#include "test_support.hpp"

namespace {

// mipc_aiding_llh_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, AidingLlhValidFlags) {
    const mipc_aiding_llh_valid_flags_t all =
        static_cast<mipc_aiding_llh_valid_flags_t>(~static_cast<mipc_aiding_llh_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_AIDING_LLH_VALID_FLAGS_LATITUDE_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_AIDING_LLH_VALID_FLAGS_LATITUDE_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_AIDING_LLH_VALID_FLAGS_LATITUDE_MASK) >>
                                    MIPC_AIDING_LLH_VALID_FLAGS_LATITUDE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_AIDING_LLH_VALID_FLAGS_LONGITUDE_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_AIDING_LLH_VALID_FLAGS_LONGITUDE_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_AIDING_LLH_VALID_FLAGS_LONGITUDE_MASK) >>
                                    MIPC_AIDING_LLH_VALID_FLAGS_LONGITUDE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_AIDING_LLH_VALID_FLAGS_HEIGHT_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_AIDING_LLH_VALID_FLAGS_HEIGHT_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_AIDING_LLH_VALID_FLAGS_HEIGHT_MASK) >>
                                    MIPC_AIDING_LLH_VALID_FLAGS_HEIGHT_SHIFT),
              UINT64_C(0x1));
}

// mipc_aiding_vector_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, AidingVectorValidFlags) {
    const mipc_aiding_vector_valid_flags_t all =
        static_cast<mipc_aiding_vector_valid_flags_t>(~static_cast<mipc_aiding_vector_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_AIDING_VECTOR_VALID_FLAGS_X_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_AIDING_VECTOR_VALID_FLAGS_X_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_AIDING_VECTOR_VALID_FLAGS_X_MASK) >>
                                    MIPC_AIDING_VECTOR_VALID_FLAGS_X_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_AIDING_VECTOR_VALID_FLAGS_Y_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_AIDING_VECTOR_VALID_FLAGS_Y_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_AIDING_VECTOR_VALID_FLAGS_Y_MASK) >>
                                    MIPC_AIDING_VECTOR_VALID_FLAGS_Y_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_AIDING_VECTOR_VALID_FLAGS_Z_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_AIDING_VECTOR_VALID_FLAGS_Z_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_AIDING_VECTOR_VALID_FLAGS_Z_MASK) >>
                                    MIPC_AIDING_VECTOR_VALID_FLAGS_Z_SHIFT),
              UINT64_C(0x1));
}

// mipc_constellation_options_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, ConstellationOptions) {
    const mipc_constellation_options_t all =
        static_cast<mipc_constellation_options_t>(~static_cast<mipc_constellation_options_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CONSTELLATION_OPTIONS_L1SAIF_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_CONSTELLATION_OPTIONS_L1SAIF_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CONSTELLATION_OPTIONS_L1SAIF_MASK) >>
                                    MIPC_CONSTELLATION_OPTIONS_L1SAIF_SHIFT),
              UINT64_C(0x1));
}

// mipc_cv7_bit_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, Cv7BitFlags) {
    const mipc_cv7_bit_flags_t all = static_cast<mipc_cv7_bit_flags_t>(~static_cast<mipc_cv7_bit_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_GENERAL_HARDWARE_FAULT_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_GENERAL_HARDWARE_FAULT_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_GENERAL_HARDWARE_FAULT_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_GENERAL_HARDWARE_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_GENERAL_FIRMWARE_FAULT_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_GENERAL_FIRMWARE_FAULT_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_GENERAL_FIRMWARE_FAULT_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_GENERAL_FIRMWARE_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_TIMING_OVERLOAD_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_TIMING_OVERLOAD_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_TIMING_OVERLOAD_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_TIMING_OVERLOAD_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_BUFFER_OVERRUN_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_BUFFER_OVERRUN_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_BUFFER_OVERRUN_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_BUFFER_OVERRUN_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_RESERVED_SYSTEM_MASK), UINT64_C(0xF0));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_RESERVED_SYSTEM_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_RESERVED_SYSTEM_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_RESERVED_SYSTEM_SHIFT),
              UINT64_C(0xF));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_RESERVED_COMMS_MASK), UINT64_C(0xF00));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_RESERVED_COMMS_SHIFT, 8);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_RESERVED_COMMS_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_RESERVED_COMMS_SHIFT),
              UINT64_C(0xF));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_ACCELEROMETER_FAULT_MASK), UINT64_C(0x1000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_ACCELEROMETER_FAULT_SHIFT, 12);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_ACCELEROMETER_FAULT_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_ACCELEROMETER_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_GYROSCOPE_FAULT_MASK), UINT64_C(0x2000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_GYROSCOPE_FAULT_SHIFT, 13);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_GYROSCOPE_FAULT_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_GYROSCOPE_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_MAGNETOMETER_FAULT_MASK), UINT64_C(0x4000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_MAGNETOMETER_FAULT_SHIFT, 14);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_MAGNETOMETER_FAULT_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_MAGNETOMETER_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_PRESSURE_SENSOR_FAULT_MASK), UINT64_C(0x8000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_PRESSURE_SENSOR_FAULT_SHIFT, 15);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_PRESSURE_SENSOR_FAULT_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_PRESSURE_SENSOR_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_RESERVED_IMU_MASK), UINT64_C(0x30000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_RESERVED_IMU_SHIFT, 16);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_RESERVED_IMU_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_RESERVED_IMU_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_CALIBRATION_ERROR_MASK), UINT64_C(0x40000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_CALIBRATION_ERROR_SHIFT, 18);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_CALIBRATION_ERROR_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_CALIBRATION_ERROR_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_GENERAL_IMU_FAULT_MASK), UINT64_C(0x80000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_GENERAL_IMU_FAULT_SHIFT, 19);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_GENERAL_IMU_FAULT_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_GENERAL_IMU_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_RESERVED_FILTER_MASK), UINT64_C(0x300000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_RESERVED_FILTER_SHIFT, 20);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_RESERVED_FILTER_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_RESERVED_FILTER_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_FILTER_SOLUTION_FAULT_MASK), UINT64_C(0x400000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_FILTER_SOLUTION_FAULT_SHIFT, 22);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_FILTER_SOLUTION_FAULT_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_FILTER_SOLUTION_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_GENERAL_FILTER_FAULT_MASK), UINT64_C(0x800000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_GENERAL_FILTER_FAULT_SHIFT, 23);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_GENERAL_FILTER_FAULT_MASK) >>
                                    MIPC_CV7_BIT_FLAGS_GENERAL_FILTER_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_BIT_FLAGS_RESERVED_MASK), UINT64_C(0xFF000000));
    EXPECT_EQ(MIPC_CV7_BIT_FLAGS_RESERVED_SHIFT, 24);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_CV7_BIT_FLAGS_RESERVED_MASK) >> MIPC_CV7_BIT_FLAGS_RESERVED_SHIFT),
        UINT64_C(0xFF));
}

// mipc_cv7_continuous_bit_gnss13_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, Cv7ContinuousBitGnss13) {
    const mipc_cv7_continuous_bit_gnss13_t all =
        static_cast<mipc_cv7_continuous_bit_gnss13_t>(~static_cast<mipc_cv7_continuous_bit_gnss13_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_104_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_104_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_104_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_104_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_FAULT_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_FAULT_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_106_107_MASK), UINT64_C(0xC));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_106_107_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_106_107_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_106_107_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_NO_SOLUTION_MASK),
              UINT64_C(0x10));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_NO_SOLUTION_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_NO_SOLUTION_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_NO_SOLUTION_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_109_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_109_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_109_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_109_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_2_FAULT_MASK), UINT64_C(0x40));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_2_FAULT_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_2_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_2_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_111_MASK), UINT64_C(0x80));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_111_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_111_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_111_SHIFT),
              UINT64_C(0x1));
}

// mipc_cv7_continuous_bit_gnss14_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, Cv7ContinuousBitGnss14) {
    const mipc_cv7_continuous_bit_gnss14_t all =
        static_cast<mipc_cv7_continuous_bit_gnss14_t>(~static_cast<mipc_cv7_continuous_bit_gnss14_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_112_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_112_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_112_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_112_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_GNSS14_RECEIVER_2_NO_SOLUTION_MASK),
              UINT64_C(0x2));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_GNSS14_RECEIVER_2_NO_SOLUTION_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_GNSS14_RECEIVER_2_NO_SOLUTION_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_GNSS14_RECEIVER_2_NO_SOLUTION_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_114_119_MASK), UINT64_C(0xFC));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_114_119_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_114_119_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_114_119_SHIFT),
              UINT64_C(0x3F));
}

// mipc_cv7_continuous_bit_imu4_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, Cv7ContinuousBitImu4) {
    const mipc_cv7_continuous_bit_imu4_t all =
        static_cast<mipc_cv7_continuous_bit_imu4_t>(~static_cast<mipc_cv7_continuous_bit_imu4_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_32_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_32_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_32_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_32_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_COMMUNICATION_FAULT_MASK),
              UINT64_C(0x2));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_COMMUNICATION_FAULT_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_COMMUNICATION_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_COMMUNICATION_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_TIMING_OVERRUN_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_TIMING_OVERRUN_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_TIMING_OVERRUN_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_TIMING_OVERRUN_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_35_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_35_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_35_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_35_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_ACCELEROMETER_MASK),
              UINT64_C(0x10));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_ACCELEROMETER_SHIFT, 4);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_ACCELEROMETER_MASK) >>
                              MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_ACCELEROMETER_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_GYROSCOPE_MASK),
              UINT64_C(0x20));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_GYROSCOPE_SHIFT, 5);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_GYROSCOPE_MASK) >>
                              MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_GYROSCOPE_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_MAGNETOMETER_MASK),
              UINT64_C(0x40));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_MAGNETOMETER_SHIFT, 6);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_MAGNETOMETER_MASK) >>
                              MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_MAGNETOMETER_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_39_MASK), UINT64_C(0x80));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_39_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_39_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_39_SHIFT),
              UINT64_C(0x1));
}

// mipc_cv7_continuous_bit_imu5_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, Cv7ContinuousBitImu5) {
    const mipc_cv7_continuous_bit_imu5_t all =
        static_cast<mipc_cv7_continuous_bit_imu5_t>(~static_cast<mipc_cv7_continuous_bit_imu5_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_GENERAL_FAULT_MASK),
              UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_GENERAL_FAULT_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_GENERAL_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_GENERAL_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_OVERRANGE_MASK),
              UINT64_C(0x2));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_OVERRANGE_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_OVERRANGE_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_OVERRANGE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_SELF_TEST_FAIL_MASK),
              UINT64_C(0x4));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_SELF_TEST_FAIL_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_SELF_TEST_FAIL_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_SELF_TEST_FAIL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_43_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_43_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_43_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_43_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_GENERAL_FAULT_MASK),
              UINT64_C(0x10));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_GENERAL_FAULT_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_GENERAL_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_GENERAL_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_OVERRANGE_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_OVERRANGE_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_OVERRANGE_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_OVERRANGE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_SELF_TEST_FAIL_MASK),
              UINT64_C(0x40));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_SELF_TEST_FAIL_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_SELF_TEST_FAIL_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_SELF_TEST_FAIL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_47_MASK), UINT64_C(0x80));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_47_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_47_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_47_SHIFT),
              UINT64_C(0x1));
}

// mipc_cv7_continuous_bit_imu6_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, Cv7ContinuousBitImu6) {
    const mipc_cv7_continuous_bit_imu6_t all =
        static_cast<mipc_cv7_continuous_bit_imu6_t>(~static_cast<mipc_cv7_continuous_bit_imu6_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_GENERAL_FAULT_MASK),
              UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_GENERAL_FAULT_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_GENERAL_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_GENERAL_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_OVERRANGE_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_OVERRANGE_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_OVERRANGE_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_OVERRANGE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_SELF_TEST_FAIL_MASK),
              UINT64_C(0x4));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_SELF_TEST_FAIL_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_SELF_TEST_FAIL_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_SELF_TEST_FAIL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_51_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_51_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_51_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_51_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_GENERAL_FAULT_MASK),
              UINT64_C(0x10));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_GENERAL_FAULT_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_GENERAL_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_GENERAL_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_OVERRANGE_MASK),
              UINT64_C(0x20));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_OVERRANGE_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_OVERRANGE_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_OVERRANGE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_SELF_TEST_FAIL_MASK),
              UINT64_C(0x40));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_SELF_TEST_FAIL_SHIFT, 6);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_SELF_TEST_FAIL_MASK) >>
                              MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_SELF_TEST_FAIL_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_55_MASK), UINT64_C(0x80));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_55_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_55_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_55_SHIFT),
              UINT64_C(0x1));
}

// mipc_cv7_continuous_bit_imu7_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, Cv7ContinuousBitImu7) {
    const mipc_cv7_continuous_bit_imu7_t all =
        static_cast<mipc_cv7_continuous_bit_imu7_t>(~static_cast<mipc_cv7_continuous_bit_imu7_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU7_FACTORY_BITS_INVALID_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU7_FACTORY_BITS_INVALID_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU7_FACTORY_BITS_INVALID_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU7_FACTORY_BITS_INVALID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_IMU7_RESERVED_57_63_MASK), UINT64_C(0xFE));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_IMU7_RESERVED_57_63_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_IMU7_RESERVED_57_63_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_IMU7_RESERVED_57_63_SHIFT),
              UINT64_C(0x7F));
}

// mipc_cv7_continuous_bit_nav8_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, Cv7ContinuousBitNav8) {
    const mipc_cv7_continuous_bit_nav8_t all =
        static_cast<mipc_cv7_continuous_bit_nav8_t>(~static_cast<mipc_cv7_continuous_bit_nav8_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_64_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_64_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_64_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_64_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_65_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_65_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_65_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_65_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_OVERRUN_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_OVERRUN_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_OVERRUN_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_OVERRUN_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_UNDERRUN_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_UNDERRUN_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_UNDERRUN_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_UNDERRUN_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_68_71_MASK), UINT64_C(0xF0));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_68_71_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_68_71_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_68_71_SHIFT),
              UINT64_C(0xF));
}

// mipc_cv7_continuous_bit_system0_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, Cv7ContinuousBitSystem0) {
    const mipc_cv7_continuous_bit_system0_t all =
        static_cast<mipc_cv7_continuous_bit_system0_t>(~static_cast<mipc_cv7_continuous_bit_system0_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_SYSTEM_CLOCK_FAILURE_MASK),
              UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_SYSTEM_CLOCK_FAILURE_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_SYSTEM_CLOCK_FAILURE_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_SYSTEM_CLOCK_FAILURE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_POWER_FAULT_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_POWER_FAULT_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_POWER_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_POWER_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_2_3_MASK), UINT64_C(0xC));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_2_3_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_2_3_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_2_3_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_FIRMWARE_FAULT_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_FIRMWARE_FAULT_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_FIRMWARE_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_FIRMWARE_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_TIMING_OVERLOAD_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_TIMING_OVERLOAD_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_TIMING_OVERLOAD_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_TIMING_OVERLOAD_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_BUFFER_OVERRUN_MASK), UINT64_C(0x40));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_BUFFER_OVERRUN_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_BUFFER_OVERRUN_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_BUFFER_OVERRUN_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_7_MASK), UINT64_C(0x80));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_7_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_7_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_7_SHIFT),
              UINT64_C(0x1));
}

// mipc_cv7_continuous_bit_system2_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, Cv7ContinuousBitSystem2) {
    const mipc_cv7_continuous_bit_system2_t all =
        static_cast<mipc_cv7_continuous_bit_system2_t>(~static_cast<mipc_cv7_continuous_bit_system2_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_PROCESS_FAULT_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_PROCESS_FAULT_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_PROCESS_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_PROCESS_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_PROCESS_TIME_EXCEEDED_MASK),
              UINT64_C(0x2));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_PROCESS_TIME_EXCEEDED_SHIFT, 1);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_PROCESS_TIME_EXCEEDED_MASK) >>
                              MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_PROCESS_TIME_EXCEEDED_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_RATE_ERROR_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_RATE_ERROR_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_RATE_ERROR_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_RATE_ERROR_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_STALL_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_STALL_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_STALL_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_STALL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_FAULT_MASK),
              UINT64_C(0xF0));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_FAULT_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_FAULT_SHIFT),
              UINT64_C(0xF));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MAJOR_CYCLE_FAULT_MASK),
              UINT64_C(0x10));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MAJOR_CYCLE_FAULT_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MAJOR_CYCLE_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MAJOR_CYCLE_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MINOR_CYCLE_FAULT_MASK),
              UINT64_C(0x20));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MINOR_CYCLE_FAULT_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MINOR_CYCLE_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MINOR_CYCLE_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_DATA_RATE_ERROR_MASK),
              UINT64_C(0x40));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_DATA_RATE_ERROR_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_DATA_RATE_ERROR_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_DATA_RATE_ERROR_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_STALL_MASK),
              UINT64_C(0x80));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_STALL_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_STALL_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_STALL_SHIFT),
              UINT64_C(0x1));
}

// mipc_cv7_continuous_bit_system3_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, Cv7ContinuousBitSystem3) {
    const mipc_cv7_continuous_bit_system3_t all =
        static_cast<mipc_cv7_continuous_bit_system3_t>(~static_cast<mipc_cv7_continuous_bit_system3_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_SUBSYSTEM_FAULT_MASK),
              UINT64_C(0xF));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_SUBSYSTEM_FAULT_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_SUBSYSTEM_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_SUBSYSTEM_FAULT_SHIFT),
              UINT64_C(0xF));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_MAIN_PROCESS_FAULT_MASK),
              UINT64_C(0x1));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_MAIN_PROCESS_FAULT_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_MAIN_PROCESS_FAULT_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_MAIN_PROCESS_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_1_STALL_MASK),
              UINT64_C(0x2));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_1_STALL_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_1_STALL_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_1_STALL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_2_STALL_MASK),
              UINT64_C(0x4));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_2_STALL_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_2_STALL_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_2_STALL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_27_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_27_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_27_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_27_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_28_31_MASK), UINT64_C(0xF0));
    EXPECT_EQ(MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_28_31_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_28_31_MASK) >>
                                    MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_28_31_SHIFT),
              UINT64_C(0xF));
}

// mipc_estimation_control_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, EstimationControlFlags) {
    const mipc_estimation_control_flags_t all =
        static_cast<mipc_estimation_control_flags_t>(~static_cast<mipc_estimation_control_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_BIAS_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_BIAS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_BIAS_MASK) >>
                                    MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_BIAS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_BIAS_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_BIAS_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_BIAS_MASK) >>
                                    MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_BIAS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_SCALE_FACTOR_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_SCALE_FACTOR_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_SCALE_FACTOR_MASK) >>
                                    MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_SCALE_FACTOR_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_SCALE_FACTOR_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_SCALE_FACTOR_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_SCALE_FACTOR_MASK) >>
                                    MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_SCALE_FACTOR_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_ESTIMATION_CONTROL_FLAGS_ANTENNA_OFFSET_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_ESTIMATION_CONTROL_FLAGS_ANTENNA_OFFSET_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_ESTIMATION_CONTROL_FLAGS_ANTENNA_OFFSET_MASK) >>
                                    MIPC_ESTIMATION_CONTROL_FLAGS_ANTENNA_OFFSET_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_ESTIMATION_CONTROL_FLAGS_HARD_IRON_AUTO_CAL_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_ESTIMATION_CONTROL_FLAGS_HARD_IRON_AUTO_CAL_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_ESTIMATION_CONTROL_FLAGS_HARD_IRON_AUTO_CAL_MASK) >>
                                    MIPC_ESTIMATION_CONTROL_FLAGS_HARD_IRON_AUTO_CAL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_ESTIMATION_CONTROL_FLAGS_SOFT_IRON_AUTO_CAL_MASK), UINT64_C(0x40));
    EXPECT_EQ(MIPC_ESTIMATION_CONTROL_FLAGS_SOFT_IRON_AUTO_CAL_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_ESTIMATION_CONTROL_FLAGS_SOFT_IRON_AUTO_CAL_MASK) >>
                                    MIPC_ESTIMATION_CONTROL_FLAGS_SOFT_IRON_AUTO_CAL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_ESTIMATION_CONTROL_FLAGS_RESERVED_MASK), UINT64_C(0xFF80));
    EXPECT_EQ(MIPC_ESTIMATION_CONTROL_FLAGS_RESERVED_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_ESTIMATION_CONTROL_FLAGS_RESERVED_MASK) >>
                                    MIPC_ESTIMATION_CONTROL_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x1FF));
}

// mipc_external_time_delta_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, ExternalTimeDeltaValidFlags) {
    const mipc_external_time_delta_valid_flags_t all = static_cast<mipc_external_time_delta_valid_flags_t>(
        ~static_cast<mipc_external_time_delta_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_DT_NANOS_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_DT_NANOS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_DT_NANOS_MASK) >>
                                    MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_DT_NANOS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFFE));
    EXPECT_EQ(MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_RESERVED_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x7FFF));
}

// mipc_external_timestamp_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, ExternalTimestampValidFlags) {
    const mipc_external_timestamp_valid_flags_t all = static_cast<mipc_external_timestamp_valid_flags_t>(
        ~static_cast<mipc_external_timestamp_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_NANOSECONDS_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_NANOSECONDS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_NANOSECONDS_MASK) >>
                                    MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_NANOSECONDS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFFE));
    EXPECT_EQ(MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_RESERVED_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x7FFF));
}

// mipc_filter_aiding_measurement_indicator_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, FilterAidingMeasurementIndicator) {
    const mipc_filter_aiding_measurement_indicator_t all =
        static_cast<mipc_filter_aiding_measurement_indicator_t>(
            ~static_cast<mipc_filter_aiding_measurement_indicator_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_ENABLED_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_ENABLED_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_ENABLED_MASK) >>
                                    MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_ENABLED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_USED_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_USED_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_USED_MASK) >>
                                    MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_USED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_RESIDUAL_HIGH_WARNING_MASK),
              UINT64_C(0x4));
    EXPECT_EQ(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_RESIDUAL_HIGH_WARNING_SHIFT, 2);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_RESIDUAL_HIGH_WARNING_MASK) >>
                              MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_RESIDUAL_HIGH_WARNING_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_SAMPLE_TIME_WARNING_MASK),
              UINT64_C(0x8));
    EXPECT_EQ(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_SAMPLE_TIME_WARNING_SHIFT, 3);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_SAMPLE_TIME_WARNING_MASK) >>
                              MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_SAMPLE_TIME_WARNING_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_CONFIGURATION_ERROR_MASK),
              UINT64_C(0x10));
    EXPECT_EQ(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_CONFIGURATION_ERROR_SHIFT, 4);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_CONFIGURATION_ERROR_MASK) >>
                              MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_CONFIGURATION_ERROR_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_MAX_NUM_MEAS_EXCEEDED_MASK),
              UINT64_C(0x20));
    EXPECT_EQ(MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_MAX_NUM_MEAS_EXCEEDED_SHIFT, 5);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_MAX_NUM_MEAS_EXCEEDED_MASK) >>
                              MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_MAX_NUM_MEAS_EXCEEDED_SHIFT),
        UINT64_C(0x1));
}

// mipc_filter_dual_antenna_status_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, FilterDualAntennaStatusFlags) {
    const mipc_filter_dual_antenna_status_flags_t all = static_cast<mipc_filter_dual_antenna_status_flags_t>(
        ~static_cast<mipc_filter_dual_antenna_status_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_1_DATA_VALID_MASK),
              UINT64_C(0x1));
    EXPECT_EQ(MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_1_DATA_VALID_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_1_DATA_VALID_MASK) >>
                                    MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_1_DATA_VALID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_2_DATA_VALID_MASK),
              UINT64_C(0x2));
    EXPECT_EQ(MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_2_DATA_VALID_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_2_DATA_VALID_MASK) >>
                                    MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_2_DATA_VALID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_ANTENNA_OFFSETS_VALID_MASK),
              UINT64_C(0x4));
    EXPECT_EQ(MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_ANTENNA_OFFSETS_VALID_SHIFT, 2);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_ANTENNA_OFFSETS_VALID_MASK) >>
                              MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_ANTENNA_OFFSETS_VALID_SHIFT),
        UINT64_C(0x1));
}

// mipc_filter_gnss_aiding_status_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, FilterGnssAidingStatusFlags) {
    const mipc_filter_gnss_aiding_status_flags_t all = static_cast<mipc_filter_gnss_aiding_status_flags_t>(
        ~static_cast<mipc_filter_gnss_aiding_status_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_TIGHT_COUPLING_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_TIGHT_COUPLING_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_TIGHT_COUPLING_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_TIGHT_COUPLING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_DIFFERENTIAL_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_DIFFERENTIAL_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_DIFFERENTIAL_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_DIFFERENTIAL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_INTEGER_FIX_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_INTEGER_FIX_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_INTEGER_FIX_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_INTEGER_FIX_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L1_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L1_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L1_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L1_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L2_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L2_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L2_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L2_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L5_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L5_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L5_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L5_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L1_MASK), UINT64_C(0x40));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L1_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L1_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L1_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L2_MASK), UINT64_C(0x80));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L2_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L2_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L2_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E1_MASK), UINT64_C(0x100));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E1_SHIFT, 8);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E1_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E1_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E5_MASK), UINT64_C(0x200));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E5_SHIFT, 9);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E5_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E5_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E6_MASK), UINT64_C(0x400));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E6_SHIFT, 10);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E6_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E6_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B1_MASK), UINT64_C(0x800));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B1_SHIFT, 11);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B1_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B1_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B2_MASK), UINT64_C(0x1000));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B2_SHIFT, 12);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B2_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B2_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B3_MASK), UINT64_C(0x2000));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B3_SHIFT, 13);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B3_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B3_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_NO_FIX_MASK), UINT64_C(0x4000));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_NO_FIX_SHIFT, 14);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_NO_FIX_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_NO_FIX_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_CONFIG_ERROR_MASK),
              UINT64_C(0x8000));
    EXPECT_EQ(MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_CONFIG_ERROR_SHIFT, 15);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_CONFIG_ERROR_MASK) >>
                                    MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_CONFIG_ERROR_SHIFT),
              UINT64_C(0x1));
}

// mipc_filter_heading_source_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, FilterHeadingSourceFlags) {
    const mipc_filter_heading_source_flags_t all =
        static_cast<mipc_filter_heading_source_flags_t>(~static_cast<mipc_filter_heading_source_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_HEADING_SOURCE_FLAGS_MAGNETOMETER_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_FILTER_HEADING_SOURCE_FLAGS_MAGNETOMETER_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_HEADING_SOURCE_FLAGS_MAGNETOMETER_MASK) >>
                                    MIPC_FILTER_HEADING_SOURCE_FLAGS_MAGNETOMETER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_HEADING_SOURCE_FLAGS_GNSS_VELOCITY_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_FILTER_HEADING_SOURCE_FLAGS_GNSS_VELOCITY_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_HEADING_SOURCE_FLAGS_GNSS_VELOCITY_MASK) >>
                                    MIPC_FILTER_HEADING_SOURCE_FLAGS_GNSS_VELOCITY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_HEADING_SOURCE_FLAGS_EXTERNAL_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_FILTER_HEADING_SOURCE_FLAGS_EXTERNAL_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_HEADING_SOURCE_FLAGS_EXTERNAL_MASK) >>
                                    MIPC_FILTER_HEADING_SOURCE_FLAGS_EXTERNAL_SHIFT),
              UINT64_C(0x1));
}

// mipc_filter_heading_update_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, FilterHeadingUpdateValidFlags) {
    const mipc_filter_heading_update_valid_flags_t all =
        static_cast<mipc_filter_heading_update_valid_flags_t>(
            ~static_cast<mipc_filter_heading_update_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_HEADING_UPDATE_VALID_FLAGS_UPDATED_WITHIN_2S_MASK),
              UINT64_C(0x1));
    EXPECT_EQ(MIPC_FILTER_HEADING_UPDATE_VALID_FLAGS_UPDATED_WITHIN_2S_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_HEADING_UPDATE_VALID_FLAGS_UPDATED_WITHIN_2S_MASK) >>
                                    MIPC_FILTER_HEADING_UPDATE_VALID_FLAGS_UPDATED_WITHIN_2S_SHIFT),
              UINT64_C(0x1));
}

// mipc_filter_output_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, FilterOutputValidFlags) {
    const mipc_filter_output_valid_flags_t all =
        static_cast<mipc_filter_output_valid_flags_t>(~static_cast<mipc_filter_output_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_OUTPUT_VALID_FLAGS_VALID_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_FILTER_OUTPUT_VALID_FLAGS_VALID_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_OUTPUT_VALID_FLAGS_VALID_MASK) >>
                                    MIPC_FILTER_OUTPUT_VALID_FLAGS_VALID_SHIFT),
              UINT64_C(0x1));
}

// mipc_filter_status_flags_cv7_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, FilterStatusFlagsCv7) {
    const mipc_filter_status_flags_cv7_t all =
        static_cast<mipc_filter_status_flags_cv7_t>(~static_cast<mipc_filter_status_flags_cv7_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_FILTER_CONDITION_MASK), UINT64_C(0x3));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_FILTER_CONDITION_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_FILTER_CONDITION_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_FILTER_CONDITION_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_ROLL_PITCH_WARNING_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_ROLL_PITCH_WARNING_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_ROLL_PITCH_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_ROLL_PITCH_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_HEADING_WARNING_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_HEADING_WARNING_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_HEADING_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_HEADING_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_POSITION_WARNING_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_POSITION_WARNING_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_POSITION_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_POSITION_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_VELOCITY_WARNING_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_VELOCITY_WARNING_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_VELOCITY_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_VELOCITY_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_IMU_BIAS_WARNING_MASK), UINT64_C(0x40));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_IMU_BIAS_WARNING_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_IMU_BIAS_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_IMU_BIAS_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_GNSS_CLK_WARNING_MASK), UINT64_C(0x80));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_GNSS_CLK_WARNING_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_GNSS_CLK_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_GNSS_CLK_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_ANTENNA_LEVER_ARM_WARNING_MASK),
              UINT64_C(0x100));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_ANTENNA_LEVER_ARM_WARNING_SHIFT, 8);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_ANTENNA_LEVER_ARM_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_ANTENNA_LEVER_ARM_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_MOUNTING_TRANSFORM_WARNING_MASK),
              UINT64_C(0x200));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_MOUNTING_TRANSFORM_WARNING_SHIFT, 9);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_MOUNTING_TRANSFORM_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_MOUNTING_TRANSFORM_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_TIME_SYNC_WARNING_MASK), UINT64_C(0x400));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_TIME_SYNC_WARNING_SHIFT, 10);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_TIME_SYNC_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_TIME_SYNC_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_RESERVED_MASK), UINT64_C(0x800));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_RESERVED_SHIFT, 11);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_RESERVED_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_RESERVED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_CV7_SOLUTION_ERROR_MASK), UINT64_C(0xF000));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_CV7_SOLUTION_ERROR_SHIFT, 12);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_CV7_SOLUTION_ERROR_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_CV7_SOLUTION_ERROR_SHIFT),
              UINT64_C(0xF));
}

// mipc_filter_status_flags_gx5_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, FilterStatusFlagsGx5) {
    const mipc_filter_status_flags_gx5_t all =
        static_cast<mipc_filter_status_flags_gx5_t>(~static_cast<mipc_filter_status_flags_gx5_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_IMU_UNAVAILABLE_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_IMU_UNAVAILABLE_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_IMU_UNAVAILABLE_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_GX5_RUN_IMU_UNAVAILABLE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GPS_UNAVAILABLE_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GPS_UNAVAILABLE_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GPS_UNAVAILABLE_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GPS_UNAVAILABLE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RESERVED_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RESERVED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RESERVED_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_GX5_RESERVED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MATRIX_SINGULARITY_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MATRIX_SINGULARITY_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MATRIX_SINGULARITY_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MATRIX_SINGULARITY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_POSITION_COVARIANCE_WARNING_MASK),
              UINT64_C(0x10));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_POSITION_COVARIANCE_WARNING_SHIFT, 4);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_POSITION_COVARIANCE_WARNING_MASK) >>
                              MIPC_FILTER_STATUS_FLAGS_GX5_RUN_POSITION_COVARIANCE_WARNING_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_VELOCITY_COVARIANCE_WARNING_MASK),
              UINT64_C(0x20));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_VELOCITY_COVARIANCE_WARNING_SHIFT, 5);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_VELOCITY_COVARIANCE_WARNING_MASK) >>
                              MIPC_FILTER_STATUS_FLAGS_GX5_RUN_VELOCITY_COVARIANCE_WARNING_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ATTITUDE_COVARIANCE_WARNING_MASK),
              UINT64_C(0x40));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ATTITUDE_COVARIANCE_WARNING_SHIFT, 6);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ATTITUDE_COVARIANCE_WARNING_MASK) >>
                              MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ATTITUDE_COVARIANCE_WARNING_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_NAN_IN_SOLUTION_WARNING_MASK),
              UINT64_C(0x80));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_NAN_IN_SOLUTION_WARNING_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_NAN_IN_SOLUTION_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_GX5_RUN_NAN_IN_SOLUTION_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_BIAS_EST_HIGH_WARNING_MASK),
              UINT64_C(0x100));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_BIAS_EST_HIGH_WARNING_SHIFT, 8);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_BIAS_EST_HIGH_WARNING_MASK) >>
                              MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_BIAS_EST_HIGH_WARNING_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_BIAS_EST_HIGH_WARNING_MASK),
              UINT64_C(0x200));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_BIAS_EST_HIGH_WARNING_SHIFT, 9);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_BIAS_EST_HIGH_WARNING_MASK) >>
                              MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_BIAS_EST_HIGH_WARNING_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING_MASK),
              UINT64_C(0x400));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING_SHIFT, 10);
    EXPECT_EQ(static_cast<uint64_t>(
                  (all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING_MASK) >>
                  MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(
        static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING_MASK),
        UINT64_C(0x800));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING_SHIFT, 11);
    EXPECT_EQ(static_cast<uint64_t>(
                  (all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING_MASK) >>
                  MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_BIAS_EST_HIGH_WARNING_MASK),
              UINT64_C(0x1000));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_BIAS_EST_HIGH_WARNING_SHIFT, 12);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_BIAS_EST_HIGH_WARNING_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_BIAS_EST_HIGH_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(
        static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING_MASK),
        UINT64_C(0x2000));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING_SHIFT, 13);
    EXPECT_EQ(static_cast<uint64_t>(
                  (all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING_MASK) >>
                  MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_HARD_IRON_EST_HIGH_WARNING_MASK),
              UINT64_C(0x4000));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_HARD_IRON_EST_HIGH_WARNING_SHIFT, 14);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_HARD_IRON_EST_HIGH_WARNING_MASK) >>
                              MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_HARD_IRON_EST_HIGH_WARNING_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_SOFT_IRON_EST_HIGH_WARNING_MASK),
              UINT64_C(0x8000));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_SOFT_IRON_EST_HIGH_WARNING_SHIFT, 15);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_SOFT_IRON_EST_HIGH_WARNING_MASK) >>
                              MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_SOFT_IRON_EST_HIGH_WARNING_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_ATTITUDE_MASK), UINT64_C(0x1000));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_ATTITUDE_SHIFT, 12);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_ATTITUDE_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_ATTITUDE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_POSITION_VELOCITY_MASK),
              UINT64_C(0x2000));
    EXPECT_EQ(MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_POSITION_VELOCITY_SHIFT, 13);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_POSITION_VELOCITY_MASK) >>
                                    MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_POSITION_VELOCITY_SHIFT),
              UINT64_C(0x1));
}

// mipc_gnss_base_station_indicators_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssBaseStationIndicators) {
    const mipc_gnss_base_station_indicators_t all = static_cast<mipc_gnss_base_station_indicators_t>(
        ~static_cast<mipc_gnss_base_station_indicators_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INDICATORS_GPS_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INDICATORS_GPS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INDICATORS_GPS_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INDICATORS_GPS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INDICATORS_GLONASS_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INDICATORS_GLONASS_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INDICATORS_GLONASS_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INDICATORS_GLONASS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INDICATORS_GALILEO_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INDICATORS_GALILEO_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INDICATORS_GALILEO_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INDICATORS_GALILEO_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INDICATORS_BEIDOU_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INDICATORS_BEIDOU_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INDICATORS_BEIDOU_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INDICATORS_BEIDOU_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INDICATORS_REF_STATION_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INDICATORS_REF_STATION_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INDICATORS_REF_STATION_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INDICATORS_REF_STATION_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INDICATORS_SINGLE_RECEIVER_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INDICATORS_SINGLE_RECEIVER_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INDICATORS_SINGLE_RECEIVER_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INDICATORS_SINGLE_RECEIVER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT1_MASK),
              UINT64_C(0x40));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT1_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT1_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT1_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT2_MASK),
              UINT64_C(0x80));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT2_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT2_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT2_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BITS_MASK),
              UINT64_C(0xC0));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BITS_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BITS_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BITS_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INDICATORS_RESERVED_MASK), UINT64_C(0xFF00));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INDICATORS_RESERVED_SHIFT, 8);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INDICATORS_RESERVED_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INDICATORS_RESERVED_SHIFT),
              UINT64_C(0xFF));
}

// mipc_gnss_base_station_info_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssBaseStationInfoValidFlags) {
    const mipc_gnss_base_station_info_valid_flags_t all =
        static_cast<mipc_gnss_base_station_info_valid_flags_t>(
            ~static_cast<mipc_gnss_base_station_info_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_TOW_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_TOW_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_TOW_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_TOW_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_WEEK_NUMBER_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_WEEK_NUMBER_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_WEEK_NUMBER_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_WEEK_NUMBER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_ECEF_POSITION_MASK),
              UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_ECEF_POSITION_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_ECEF_POSITION_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_ECEF_POSITION_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_HEIGHT_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_HEIGHT_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_HEIGHT_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_HEIGHT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_STATION_ID_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_STATION_ID_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_STATION_ID_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_STATION_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_INDICATORS_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_INDICATORS_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_INDICATORS_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_INDICATORS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x3F));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x3F));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFC0));
    EXPECT_EQ(MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_RESERVED_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x3FF));
}

// mipc_gnss_beidou_signals_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, GnssBeidouSignals) {
    const mipc_gnss_beidou_signals_t all =
        static_cast<mipc_gnss_beidou_signals_t>(~static_cast<mipc_gnss_beidou_signals_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BEIDOU_SIGNALS_B1_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_BEIDOU_SIGNALS_B1_SHIFT, 0);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GNSS_BEIDOU_SIGNALS_B1_MASK) >> MIPC_GNSS_BEIDOU_SIGNALS_B1_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BEIDOU_SIGNALS_B2_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_BEIDOU_SIGNALS_B2_SHIFT, 1);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GNSS_BEIDOU_SIGNALS_B2_MASK) >> MIPC_GNSS_BEIDOU_SIGNALS_B2_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_BEIDOU_SIGNALS_B2A_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_BEIDOU_SIGNALS_B2A_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_BEIDOU_SIGNALS_B2A_MASK) >>
                                    MIPC_GNSS_BEIDOU_SIGNALS_B2A_SHIFT),
              UINT64_C(0x1));
}

// mipc_gnss_clock_info2_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssClockInfo2ValidFlags) {
    const mipc_gnss_clock_info2_valid_flags_t all = static_cast<mipc_gnss_clock_info2_valid_flags_t>(
        ~static_cast<mipc_gnss_clock_info2_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_MASK) >>
                                    MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_MASK) >>
                                    MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_ACCURACY_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_ACCURACY_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_ACCURACY_MASK) >>
                                    MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_ACCURACY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_ACCURACY_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_ACCURACY_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_ACCURACY_MASK) >>
                                    MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_ACCURACY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_FLAGS_MASK), UINT64_C(0xF));
    EXPECT_EQ(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0xF));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFF0));
    EXPECT_EQ(MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_RESERVED_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0xFFF));
}

// mipc_gnss_clock_info_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssClockInfoValidFlags) {
    const mipc_gnss_clock_info_valid_flags_t all =
        static_cast<mipc_gnss_clock_info_valid_flags_t>(~static_cast<mipc_gnss_clock_info_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_BIAS_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_BIAS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_BIAS_MASK) >>
                                    MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_BIAS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_DRIFT_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_DRIFT_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_DRIFT_MASK) >>
                                    MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_DRIFT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_ACCURACY_ESTIMATE_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_ACCURACY_ESTIMATE_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_ACCURACY_ESTIMATE_MASK) >>
                                    MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_ACCURACY_ESTIMATE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFF8));
    EXPECT_EQ(MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_RESERVED_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x1FFF));
}

// mipc_gnss_dgnss_channel_status_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of
// an all-ones value.
TEST(Bitfields, GnssDgnssChannelStatusValidFlags) {
    const mipc_gnss_dgnss_channel_status_valid_flags_t all =
        static_cast<mipc_gnss_dgnss_channel_status_valid_flags_t>(
            ~static_cast<mipc_gnss_dgnss_channel_status_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_SV_ID_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_SV_ID_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_SV_ID_MASK) >>
                                    MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_SV_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_AGE_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_AGE_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_AGE_MASK) >>
                                    MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_AGE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_CORRECTION_MASK),
              UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_CORRECTION_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>(
                  (all & MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_CORRECTION_MASK) >>
                  MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_CORRECTION_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(
        static_cast<uint64_t>(MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_RATE_CORRECTION_MASK),
        UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_RATE_CORRECTION_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>(
                  (all & MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_RATE_CORRECTION_MASK) >>
                  MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_RATE_CORRECTION_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_RESERVED_MASK),
              UINT64_C(0xFFF0));
    EXPECT_EQ(MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_RESERVED_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0xFFF));
}

// mipc_gnss_dgnss_info_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssDgnssInfoValidFlags) {
    const mipc_gnss_dgnss_info_valid_flags_t all =
        static_cast<mipc_gnss_dgnss_info_valid_flags_t>(~static_cast<mipc_gnss_dgnss_info_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_LATEST_AGE_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_LATEST_AGE_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_LATEST_AGE_MASK) >>
                                    MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_LATEST_AGE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_ID_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_ID_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_ID_MASK) >>
                                    MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_STATUS_MASK),
              UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_STATUS_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_STATUS_MASK) >>
                                    MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_STATUS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_NUM_CHANNELS_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_NUM_CHANNELS_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_NUM_CHANNELS_MASK) >>
                                    MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_NUM_CHANNELS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFF0));
    EXPECT_EQ(MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_RESERVED_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0xFFF));
}

// mipc_gnss_dop_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, GnssDopValidFlags) {
    const mipc_gnss_dop_valid_flags_t all =
        static_cast<mipc_gnss_dop_valid_flags_t>(~static_cast<mipc_gnss_dop_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DOP_VALID_FLAGS_GDOP_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_DOP_VALID_FLAGS_GDOP_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DOP_VALID_FLAGS_GDOP_MASK) >>
                                    MIPC_GNSS_DOP_VALID_FLAGS_GDOP_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DOP_VALID_FLAGS_PDOP_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_DOP_VALID_FLAGS_PDOP_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DOP_VALID_FLAGS_PDOP_MASK) >>
                                    MIPC_GNSS_DOP_VALID_FLAGS_PDOP_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DOP_VALID_FLAGS_HDOP_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_DOP_VALID_FLAGS_HDOP_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DOP_VALID_FLAGS_HDOP_MASK) >>
                                    MIPC_GNSS_DOP_VALID_FLAGS_HDOP_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DOP_VALID_FLAGS_VDOP_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_DOP_VALID_FLAGS_VDOP_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DOP_VALID_FLAGS_VDOP_MASK) >>
                                    MIPC_GNSS_DOP_VALID_FLAGS_VDOP_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DOP_VALID_FLAGS_TDOP_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_GNSS_DOP_VALID_FLAGS_TDOP_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DOP_VALID_FLAGS_TDOP_MASK) >>
                                    MIPC_GNSS_DOP_VALID_FLAGS_TDOP_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DOP_VALID_FLAGS_NDOP_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_GNSS_DOP_VALID_FLAGS_NDOP_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DOP_VALID_FLAGS_NDOP_MASK) >>
                                    MIPC_GNSS_DOP_VALID_FLAGS_NDOP_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DOP_VALID_FLAGS_EDOP_MASK), UINT64_C(0x40));
    EXPECT_EQ(MIPC_GNSS_DOP_VALID_FLAGS_EDOP_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DOP_VALID_FLAGS_EDOP_MASK) >>
                                    MIPC_GNSS_DOP_VALID_FLAGS_EDOP_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DOP_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x7F));
    EXPECT_EQ(MIPC_GNSS_DOP_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DOP_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_DOP_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x7F));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_DOP_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFF80));
    EXPECT_EQ(MIPC_GNSS_DOP_VALID_FLAGS_RESERVED_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_DOP_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_DOP_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x1FF));
}

// mipc_gnss_ecef_position_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssEcefPositionValidFlags) {
    const mipc_gnss_ecef_position_valid_flags_t all = static_cast<mipc_gnss_ecef_position_valid_flags_t>(
        ~static_cast<mipc_gnss_ecef_position_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_MASK) >>
                                    MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_ACCURACY_MASK),
              UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_ACCURACY_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_ACCURACY_MASK) >>
                                    MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_ACCURACY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x3));
    EXPECT_EQ(MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFFC));
    EXPECT_EQ(MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_RESERVED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x3FFF));
}

// mipc_gnss_ecef_velocity_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssEcefVelocityValidFlags) {
    const mipc_gnss_ecef_velocity_valid_flags_t all = static_cast<mipc_gnss_ecef_velocity_valid_flags_t>(
        ~static_cast<mipc_gnss_ecef_velocity_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_MASK) >>
                                    MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_ACCURACY_MASK),
              UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_ACCURACY_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_ACCURACY_MASK) >>
                                    MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_ACCURACY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x3));
    EXPECT_EQ(MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFFC));
    EXPECT_EQ(MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_RESERVED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x3FFF));
}

// mipc_gnss_ephemeris_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, GnssEphemerisValidFlags) {
    const mipc_gnss_ephemeris_valid_flags_t all =
        static_cast<mipc_gnss_ephemeris_valid_flags_t>(~static_cast<mipc_gnss_ephemeris_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_MASK) >>
                                    MIPC_GNSS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_EPHEMERIS_VALID_FLAGS_MODERN_DATA_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_EPHEMERIS_VALID_FLAGS_MODERN_DATA_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_EPHEMERIS_VALID_FLAGS_MODERN_DATA_MASK) >>
                                    MIPC_GNSS_EPHEMERIS_VALID_FLAGS_MODERN_DATA_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_EPHEMERIS_VALID_FLAGS_ISC_L5_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_EPHEMERIS_VALID_FLAGS_ISC_L5_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_EPHEMERIS_VALID_FLAGS_ISC_L5_MASK) >>
                                    MIPC_GNSS_EPHEMERIS_VALID_FLAGS_ISC_L5_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_EPHEMERIS_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x7));
    EXPECT_EQ(MIPC_GNSS_EPHEMERIS_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_EPHEMERIS_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_EPHEMERIS_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x7));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_EPHEMERIS_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFF8));
    EXPECT_EQ(MIPC_GNSS_EPHEMERIS_VALID_FLAGS_RESERVED_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_EPHEMERIS_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_EPHEMERIS_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x1FFF));
}

// mipc_gnss_fix_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, GnssFixFlags) {
    const mipc_gnss_fix_flags_t all =
        static_cast<mipc_gnss_fix_flags_t>(~static_cast<mipc_gnss_fix_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_FIX_FLAGS_SBAS_USED_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_FIX_FLAGS_SBAS_USED_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_FIX_FLAGS_SBAS_USED_MASK) >>
                                    MIPC_GNSS_FIX_FLAGS_SBAS_USED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_FIX_FLAGS_DGNSS_USED_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_FIX_FLAGS_DGNSS_USED_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_FIX_FLAGS_DGNSS_USED_MASK) >>
                                    MIPC_GNSS_FIX_FLAGS_DGNSS_USED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_FIX_FLAGS_RESERVED_MASK), UINT64_C(0xFFFC));
    EXPECT_EQ(MIPC_GNSS_FIX_FLAGS_RESERVED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_FIX_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_FIX_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x3FFF));
}

// mipc_gnss_fix_info_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, GnssFixInfoValidFlags) {
    const mipc_gnss_fix_info_valid_flags_t all =
        static_cast<mipc_gnss_fix_info_valid_flags_t>(~static_cast<mipc_gnss_fix_info_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_TYPE_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_TYPE_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_TYPE_MASK) >>
                                    MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_TYPE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_FIX_INFO_VALID_FLAGS_NUM_SV_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_FIX_INFO_VALID_FLAGS_NUM_SV_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_FIX_INFO_VALID_FLAGS_NUM_SV_MASK) >>
                                    MIPC_GNSS_FIX_INFO_VALID_FLAGS_NUM_SV_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_FLAGS_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_FLAGS_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_FLAGS_MASK) >>
                                    MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_FLAGS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_FIX_INFO_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x7));
    EXPECT_EQ(MIPC_GNSS_FIX_INFO_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_FIX_INFO_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_FIX_INFO_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x7));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_FIX_INFO_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFF8));
    EXPECT_EQ(MIPC_GNSS_FIX_INFO_VALID_FLAGS_RESERVED_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_FIX_INFO_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_FIX_INFO_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x1FFF));
}

// mipc_gnss_galileo_signals_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, GnssGalileoSignals) {
    const mipc_gnss_galileo_signals_t all =
        static_cast<mipc_gnss_galileo_signals_t>(~static_cast<mipc_gnss_galileo_signals_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GALILEO_SIGNALS_E1_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_GALILEO_SIGNALS_E1_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GALILEO_SIGNALS_E1_MASK) >>
                                    MIPC_GNSS_GALILEO_SIGNALS_E1_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GALILEO_SIGNALS_E5B_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_GALILEO_SIGNALS_E5B_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GALILEO_SIGNALS_E5B_MASK) >>
                                    MIPC_GNSS_GALILEO_SIGNALS_E5B_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GALILEO_SIGNALS_E5A_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_GALILEO_SIGNALS_E5A_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GALILEO_SIGNALS_E5A_MASK) >>
                                    MIPC_GNSS_GALILEO_SIGNALS_E5A_SHIFT),
              UINT64_C(0x1));
}

// mipc_gnss_glonass_ephemeris_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssGlonassEphemerisValidFlags) {
    const mipc_gnss_glonass_ephemeris_valid_flags_t all =
        static_cast<mipc_gnss_glonass_ephemeris_valid_flags_t>(
            ~static_cast<mipc_gnss_glonass_ephemeris_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_MASK) >>
                                    MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFFE));
    EXPECT_EQ(MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_RESERVED_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x7FFF));
}

// mipc_gnss_glonass_signals_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, GnssGlonassSignals) {
    const mipc_gnss_glonass_signals_t all =
        static_cast<mipc_gnss_glonass_signals_t>(~static_cast<mipc_gnss_glonass_signals_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GLONASS_SIGNALS_L1OF_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_GLONASS_SIGNALS_L1OF_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GLONASS_SIGNALS_L1OF_MASK) >>
                                    MIPC_GNSS_GLONASS_SIGNALS_L1OF_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GLONASS_SIGNALS_L2OF_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_GLONASS_SIGNALS_L2OF_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GLONASS_SIGNALS_L2OF_MASK) >>
                                    MIPC_GNSS_GLONASS_SIGNALS_L2OF_SHIFT),
              UINT64_C(0x1));
}

// mipc_gnss_gps_signals_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, GnssGpsSignals) {
    const mipc_gnss_gps_signals_t all =
        static_cast<mipc_gnss_gps_signals_t>(~static_cast<mipc_gnss_gps_signals_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GPS_SIGNALS_L1CA_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_GPS_SIGNALS_L1CA_SHIFT, 0);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GNSS_GPS_SIGNALS_L1CA_MASK) >> MIPC_GNSS_GPS_SIGNALS_L1CA_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GPS_SIGNALS_L2C_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_GPS_SIGNALS_L2C_SHIFT, 1);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GNSS_GPS_SIGNALS_L2C_MASK) >> MIPC_GNSS_GPS_SIGNALS_L2C_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GPS_SIGNALS_L5_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_GPS_SIGNALS_L5_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GPS_SIGNALS_L5_MASK) >> MIPC_GNSS_GPS_SIGNALS_L5_SHIFT),
              UINT64_C(0x1));
}

// mipc_gnss_gps_time_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, GnssGpsTimeValidFlags) {
    const mipc_gnss_gps_time_valid_flags_t all =
        static_cast<mipc_gnss_gps_time_valid_flags_t>(~static_cast<mipc_gnss_gps_time_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GPS_TIME_VALID_FLAGS_TOW_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_GPS_TIME_VALID_FLAGS_TOW_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GPS_TIME_VALID_FLAGS_TOW_MASK) >>
                                    MIPC_GNSS_GPS_TIME_VALID_FLAGS_TOW_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GPS_TIME_VALID_FLAGS_WEEK_NUMBER_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_GPS_TIME_VALID_FLAGS_WEEK_NUMBER_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GPS_TIME_VALID_FLAGS_WEEK_NUMBER_MASK) >>
                                    MIPC_GNSS_GPS_TIME_VALID_FLAGS_WEEK_NUMBER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GPS_TIME_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x3));
    EXPECT_EQ(MIPC_GNSS_GPS_TIME_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GPS_TIME_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_GPS_TIME_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_GPS_TIME_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFFC));
    EXPECT_EQ(MIPC_GNSS_GPS_TIME_VALID_FLAGS_RESERVED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_GPS_TIME_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_GPS_TIME_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x3FFF));
}

// mipc_gnss_hardware_status_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssHardwareStatusValidFlags) {
    const mipc_gnss_hardware_status_valid_flags_t all = static_cast<mipc_gnss_hardware_status_valid_flags_t>(
        ~static_cast<mipc_gnss_hardware_status_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_SENSOR_STATE_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_SENSOR_STATE_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_SENSOR_STATE_MASK) >>
                                    MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_SENSOR_STATE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_STATE_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_STATE_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_STATE_MASK) >>
                                    MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_STATE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_POWER_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_POWER_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_POWER_MASK) >>
                                    MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_POWER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x7));
    EXPECT_EQ(MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x7));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFF8));
    EXPECT_EQ(MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_RESERVED_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x1FFF));
}

// mipc_gnss_leap_seconds_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssLeapSecondsValidFlags) {
    const mipc_gnss_leap_seconds_valid_flags_t all = static_cast<mipc_gnss_leap_seconds_valid_flags_t>(
        ~static_cast<mipc_gnss_leap_seconds_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_0_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_0_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_0_MASK) >>
                                    MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_0_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_LEAP_SECONDS_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_LEAP_SECONDS_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_LEAP_SECONDS_MASK) >>
                                    MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_LEAP_SECONDS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFFC));
    EXPECT_EQ(MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x3FFF));
}

// mipc_gnss_llh_position_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssLlhPositionValidFlags) {
    const mipc_gnss_llh_position_valid_flags_t all = static_cast<mipc_gnss_llh_position_valid_flags_t>(
        ~static_cast<mipc_gnss_llh_position_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_LAT_LON_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_LAT_LON_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_LLH_POSITION_VALID_FLAGS_LAT_LON_MASK) >>
                                    MIPC_GNSS_LLH_POSITION_VALID_FLAGS_LAT_LON_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_ELLIPSOID_HEIGHT_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_ELLIPSOID_HEIGHT_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_LLH_POSITION_VALID_FLAGS_ELLIPSOID_HEIGHT_MASK) >>
                                    MIPC_GNSS_LLH_POSITION_VALID_FLAGS_ELLIPSOID_HEIGHT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_MSL_HEIGHT_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_MSL_HEIGHT_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_LLH_POSITION_VALID_FLAGS_MSL_HEIGHT_MASK) >>
                                    MIPC_GNSS_LLH_POSITION_VALID_FLAGS_MSL_HEIGHT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_HORIZONTAL_ACCURACY_MASK),
              UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_HORIZONTAL_ACCURACY_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_LLH_POSITION_VALID_FLAGS_HORIZONTAL_ACCURACY_MASK) >>
                                    MIPC_GNSS_LLH_POSITION_VALID_FLAGS_HORIZONTAL_ACCURACY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_VERTICAL_ACCURACY_MASK),
              UINT64_C(0x10));
    EXPECT_EQ(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_VERTICAL_ACCURACY_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_LLH_POSITION_VALID_FLAGS_VERTICAL_ACCURACY_MASK) >>
                                    MIPC_GNSS_LLH_POSITION_VALID_FLAGS_VERTICAL_ACCURACY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x1F));
    EXPECT_EQ(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_LLH_POSITION_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_LLH_POSITION_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x1F));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFE0));
    EXPECT_EQ(MIPC_GNSS_LLH_POSITION_VALID_FLAGS_RESERVED_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_LLH_POSITION_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_LLH_POSITION_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x7FF));
}

// mipc_gnss_ned_velocity_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssNedVelocityValidFlags) {
    const mipc_gnss_ned_velocity_valid_flags_t all = static_cast<mipc_gnss_ned_velocity_valid_flags_t>(
        ~static_cast<mipc_gnss_ned_velocity_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_VELOCITY_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_VELOCITY_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_VELOCITY_MASK) >>
                                    MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_VELOCITY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_3D_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_3D_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_3D_MASK) >>
                                    MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_3D_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_GROUND_SPEED_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_GROUND_SPEED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_GROUND_SPEED_MASK) >>
                                    MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_GROUND_SPEED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_MASK) >>
                                    MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_ACCURACY_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_ACCURACY_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_ACCURACY_MASK) >>
                                    MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_ACCURACY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_ACCURACY_MASK),
              UINT64_C(0x20));
    EXPECT_EQ(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_ACCURACY_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_ACCURACY_MASK) >>
                                    MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_ACCURACY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x3F));
    EXPECT_EQ(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x3F));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFC0));
    EXPECT_EQ(MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_RESERVED_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x3FF));
}

// mipc_gnss_raw_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, GnssRawValidFlags) {
    const mipc_gnss_raw_valid_flags_t all =
        static_cast<mipc_gnss_raw_valid_flags_t>(~static_cast<mipc_gnss_raw_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_TOW_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_TOW_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_TOW_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_TOW_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_WEEK_NUMBER_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_WEEK_NUMBER_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_WEEK_NUMBER_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_WEEK_NUMBER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_RECEIVER_ID_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_RECEIVER_ID_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_RECEIVER_ID_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_RECEIVER_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_TRACKING_CHANNEL_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_TRACKING_CHANNEL_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_TRACKING_CHANNEL_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_TRACKING_CHANNEL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_GNSS_ID_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_GNSS_ID_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_GNSS_ID_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_GNSS_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_SATELLITE_ID_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_SATELLITE_ID_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_SATELLITE_ID_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_SATELLITE_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_ID_MASK), UINT64_C(0x40));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_ID_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_ID_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_STRENGTH_MASK), UINT64_C(0x80));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_STRENGTH_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_STRENGTH_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_STRENGTH_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_QUALITY_MASK), UINT64_C(0x100));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_QUALITY_SHIFT, 8);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_QUALITY_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_QUALITY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_PSEUDORANGE_MASK), UINT64_C(0x200));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_PSEUDORANGE_SHIFT, 9);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_PSEUDORANGE_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_PSEUDORANGE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_MASK), UINT64_C(0x400));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_SHIFT, 10);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_MASK), UINT64_C(0x800));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_SHIFT, 11);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_RANGE_UNCERTAINTY_MASK), UINT64_C(0x1000));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_RANGE_UNCERTAINTY_SHIFT, 12);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_RANGE_UNCERTAINTY_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_RANGE_UNCERTAINTY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_UNCERTAINTY_MASK),
              UINT64_C(0x2000));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_UNCERTAINTY_SHIFT, 13);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_UNCERTAINTY_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_UNCERTAINTY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_UNCERTAINTY_MASK), UINT64_C(0x4000));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_UNCERTAINTY_SHIFT, 14);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_UNCERTAINTY_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_UNCERTAINTY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_LOCK_TIME_MASK), UINT64_C(0x8000));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_LOCK_TIME_SHIFT, 15);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_LOCK_TIME_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_LOCK_TIME_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_RAW_VALID_FLAGS_FLAGS_MASK), UINT64_C(0xFFFF));
    EXPECT_EQ(MIPC_GNSS_RAW_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_RAW_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_RAW_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0xFFFF));
}

// mipc_gnss_satellite_status_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssSatelliteStatusValidFlags) {
    const mipc_gnss_satellite_status_valid_flags_t all =
        static_cast<mipc_gnss_satellite_status_valid_flags_t>(
            ~static_cast<mipc_gnss_satellite_status_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_TOW_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_TOW_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_TOW_MASK) >>
                                    MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_TOW_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_WEEK_NUMBER_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_WEEK_NUMBER_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_WEEK_NUMBER_MASK) >>
                                    MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_WEEK_NUMBER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_GNSS_ID_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_GNSS_ID_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_GNSS_ID_MASK) >>
                                    MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_GNSS_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_SATELLITE_ID_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_SATELLITE_ID_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_SATELLITE_ID_MASK) >>
                                    MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_SATELLITE_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_ELEVATION_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_ELEVATION_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_ELEVATION_MASK) >>
                                    MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_ELEVATION_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_AZIMUTH_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_AZIMUTH_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_AZIMUTH_MASK) >>
                                    MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_AZIMUTH_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_HEALTH_MASK), UINT64_C(0x40));
    EXPECT_EQ(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_HEALTH_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_HEALTH_MASK) >>
                                    MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_HEALTH_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x7F));
    EXPECT_EQ(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x7F));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFF80));
    EXPECT_EQ(MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_RESERVED_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x1FF));
}

// mipc_gnss_sbas_info_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, GnssSbasInfoValidFlags) {
    const mipc_gnss_sbas_info_valid_flags_t all =
        static_cast<mipc_gnss_sbas_info_valid_flags_t>(~static_cast<mipc_gnss_sbas_info_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_TOW_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_TOW_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_INFO_VALID_FLAGS_TOW_MASK) >>
                                    MIPC_GNSS_SBAS_INFO_VALID_FLAGS_TOW_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_WEEK_NUMBER_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_WEEK_NUMBER_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_INFO_VALID_FLAGS_WEEK_NUMBER_MASK) >>
                                    MIPC_GNSS_SBAS_INFO_VALID_FLAGS_WEEK_NUMBER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_SYSTEM_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_SYSTEM_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_SYSTEM_MASK) >>
                                    MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_SYSTEM_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_ID_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_ID_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_ID_MASK) >>
                                    MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_COUNT_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_COUNT_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_INFO_VALID_FLAGS_COUNT_MASK) >>
                                    MIPC_GNSS_SBAS_INFO_VALID_FLAGS_COUNT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_STATUS_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_STATUS_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_STATUS_MASK) >>
                                    MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_STATUS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_FLAGS_MASK), UINT64_C(0x3F));
    EXPECT_EQ(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_INFO_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_GNSS_SBAS_INFO_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0x3F));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFC0));
    EXPECT_EQ(MIPC_GNSS_SBAS_INFO_VALID_FLAGS_RESERVED_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_INFO_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_SBAS_INFO_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x3FF));
}

// mipc_gnss_sbas_status_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, GnssSbasStatus) {
    const mipc_gnss_sbas_status_t all =
        static_cast<mipc_gnss_sbas_status_t>(~static_cast<mipc_gnss_sbas_status_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_STATUS_RANGE_AVAILABLE_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_SBAS_STATUS_RANGE_AVAILABLE_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_STATUS_RANGE_AVAILABLE_MASK) >>
                                    MIPC_GNSS_SBAS_STATUS_RANGE_AVAILABLE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_STATUS_CORRECTIONS_AVAILABLE_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_SBAS_STATUS_CORRECTIONS_AVAILABLE_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_STATUS_CORRECTIONS_AVAILABLE_MASK) >>
                                    MIPC_GNSS_SBAS_STATUS_CORRECTIONS_AVAILABLE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_STATUS_INTEGRITY_AVAILABLE_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_SBAS_STATUS_INTEGRITY_AVAILABLE_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_STATUS_INTEGRITY_AVAILABLE_MASK) >>
                                    MIPC_GNSS_SBAS_STATUS_INTEGRITY_AVAILABLE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_STATUS_TEST_MODE_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_SBAS_STATUS_TEST_MODE_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_STATUS_TEST_MODE_MASK) >>
                                    MIPC_GNSS_SBAS_STATUS_TEST_MODE_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SBAS_STATUS_RESERVED_MASK), UINT64_C(0xF0));
    EXPECT_EQ(MIPC_GNSS_SBAS_STATUS_RESERVED_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SBAS_STATUS_RESERVED_MASK) >>
                                    MIPC_GNSS_SBAS_STATUS_RESERVED_SHIFT),
              UINT64_C(0xF));
}

// mipc_gnss_sv_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, GnssSvFlags) {
    const mipc_gnss_sv_flags_t all = static_cast<mipc_gnss_sv_flags_t>(~static_cast<mipc_gnss_sv_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_FLAGS_USED_FOR_NAVIGATION_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_SV_FLAGS_USED_FOR_NAVIGATION_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SV_FLAGS_USED_FOR_NAVIGATION_MASK) >>
                                    MIPC_GNSS_SV_FLAGS_USED_FOR_NAVIGATION_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_FLAGS_HEALTHY_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_SV_FLAGS_HEALTHY_SHIFT, 1);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GNSS_SV_FLAGS_HEALTHY_MASK) >> MIPC_GNSS_SV_FLAGS_HEALTHY_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_FLAGS_RESERVED_MASK), UINT64_C(0xFFFC));
    EXPECT_EQ(MIPC_GNSS_SV_FLAGS_RESERVED_SHIFT, 2);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GNSS_SV_FLAGS_RESERVED_MASK) >> MIPC_GNSS_SV_FLAGS_RESERVED_SHIFT),
        UINT64_C(0x3FFF));
}

// mipc_gnss_sv_info_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, GnssSvInfoValidFlags) {
    const mipc_gnss_sv_info_valid_flags_t all =
        static_cast<mipc_gnss_sv_info_valid_flags_t>(~static_cast<mipc_gnss_sv_info_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_INFO_VALID_FLAGS_CHANNEL_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_SV_INFO_VALID_FLAGS_CHANNEL_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SV_INFO_VALID_FLAGS_CHANNEL_MASK) >>
                                    MIPC_GNSS_SV_INFO_VALID_FLAGS_CHANNEL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_ID_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_ID_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_ID_MASK) >>
                                    MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_ID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_2_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_2_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_2_MASK) >>
                                    MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_2_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_INFO_VALID_FLAGS_CARRIER_TO_NOISE_RATIO_MASK),
              UINT64_C(0x8));
    EXPECT_EQ(MIPC_GNSS_SV_INFO_VALID_FLAGS_CARRIER_TO_NOISE_RATIO_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SV_INFO_VALID_FLAGS_CARRIER_TO_NOISE_RATIO_MASK) >>
                                    MIPC_GNSS_SV_INFO_VALID_FLAGS_CARRIER_TO_NOISE_RATIO_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_INFO_VALID_FLAGS_AZIMUTH_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_GNSS_SV_INFO_VALID_FLAGS_AZIMUTH_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SV_INFO_VALID_FLAGS_AZIMUTH_MASK) >>
                                    MIPC_GNSS_SV_INFO_VALID_FLAGS_AZIMUTH_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_INFO_VALID_FLAGS_ELEVATION_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_GNSS_SV_INFO_VALID_FLAGS_ELEVATION_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SV_INFO_VALID_FLAGS_ELEVATION_MASK) >>
                                    MIPC_GNSS_SV_INFO_VALID_FLAGS_ELEVATION_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_FLAGS_MASK), UINT64_C(0x40));
    EXPECT_EQ(MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_FLAGS_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_FLAGS_MASK) >>
                                    MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_FLAGS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFF80));
    EXPECT_EQ(MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x1FF));
}

// mipc_gnss_utc_time_valid_flags_cv7_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssUtcTimeValidFlagsCv7) {
    const mipc_gnss_utc_time_valid_flags_cv7_t all = static_cast<mipc_gnss_utc_time_valid_flags_cv7_t>(
        ~static_cast<mipc_gnss_utc_time_valid_flags_cv7_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_GNSS_DATE_TIME_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_GNSS_DATE_TIME_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_GNSS_DATE_TIME_MASK) >>
                                    MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_GNSS_DATE_TIME_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_LEAP_SECONDS_KNOWN_MASK),
              UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_LEAP_SECONDS_KNOWN_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_LEAP_SECONDS_KNOWN_MASK) >>
                                    MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_LEAP_SECONDS_KNOWN_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_FLAGS_MASK), UINT64_C(0x3));
    EXPECT_EQ(MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_FLAGS_MASK) >>
                                    MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_FLAGS_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_RESERVED_MASK), UINT64_C(0xFFFC));
    EXPECT_EQ(MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_RESERVED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_RESERVED_MASK) >>
                                    MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_RESERVED_SHIFT),
              UINT64_C(0x3FFF));
}

// mipc_gnss_utc_time_valid_flags_gx5_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, GnssUtcTimeValidFlagsGx5) {
    const mipc_gnss_utc_time_valid_flags_gx5_t all = static_cast<mipc_gnss_utc_time_valid_flags_gx5_t>(
        ~static_cast<mipc_gnss_utc_time_valid_flags_gx5_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_DATE_VALID_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_DATE_VALID_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_DATE_VALID_MASK) >>
                                    MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_DATE_VALID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_TIME_VALID_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_TIME_VALID_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_TIME_VALID_MASK) >>
                                    MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_TIME_VALID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_RESERVED_MASK), UINT64_C(0xFFFC));
    EXPECT_EQ(MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_RESERVED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_RESERVED_MASK) >>
                                    MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_RESERVED_SHIFT),
              UINT64_C(0x3FFF));
}

// mipc_gpio_pin_mode_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, GpioPinMode) {
    const mipc_gpio_pin_mode_t all = static_cast<mipc_gpio_pin_mode_t>(~static_cast<mipc_gpio_pin_mode_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GPIO_PIN_MODE_OPEN_DRAIN_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GPIO_PIN_MODE_OPEN_DRAIN_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GPIO_PIN_MODE_OPEN_DRAIN_MASK) >>
                                    MIPC_GPIO_PIN_MODE_OPEN_DRAIN_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GPIO_PIN_MODE_PULLDOWN_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GPIO_PIN_MODE_PULLDOWN_SHIFT, 1);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GPIO_PIN_MODE_PULLDOWN_MASK) >> MIPC_GPIO_PIN_MODE_PULLDOWN_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GPIO_PIN_MODE_PULLUP_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GPIO_PIN_MODE_PULLUP_SHIFT, 2);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GPIO_PIN_MODE_PULLUP_MASK) >> MIPC_GPIO_PIN_MODE_PULLUP_SHIFT),
        UINT64_C(0x1));
}

// mipc_gpio_pin_states_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, GpioPinStates) {
    const mipc_gpio_pin_states_t all =
        static_cast<mipc_gpio_pin_states_t>(~static_cast<mipc_gpio_pin_states_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GPIO_PIN_STATES_PIN_1_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GPIO_PIN_STATES_PIN_1_SHIFT, 0);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GPIO_PIN_STATES_PIN_1_MASK) >> MIPC_GPIO_PIN_STATES_PIN_1_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GPIO_PIN_STATES_PIN_2_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_GPIO_PIN_STATES_PIN_2_SHIFT, 1);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GPIO_PIN_STATES_PIN_2_MASK) >> MIPC_GPIO_PIN_STATES_PIN_2_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GPIO_PIN_STATES_PIN_3_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_GPIO_PIN_STATES_PIN_3_SHIFT, 2);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GPIO_PIN_STATES_PIN_3_MASK) >> MIPC_GPIO_PIN_STATES_PIN_3_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GPIO_PIN_STATES_PIN_4_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_GPIO_PIN_STATES_PIN_4_SHIFT, 3);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_GPIO_PIN_STATES_PIN_4_MASK) >> MIPC_GPIO_PIN_STATES_PIN_4_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GPIO_PIN_STATES_RESERVED_MASK), UINT64_C(0xF0));
    EXPECT_EQ(MIPC_GPIO_PIN_STATES_RESERVED_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GPIO_PIN_STATES_RESERVED_MASK) >>
                                    MIPC_GPIO_PIN_STATES_RESERVED_SHIFT),
              UINT64_C(0xF));
}

// mipc_gx5_bit_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, Gx5BitFlags) {
    const mipc_gx5_bit_flags_t all = static_cast<mipc_gx5_bit_flags_t>(~static_cast<mipc_gx5_bit_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GX5_BIT_FLAGS_PROCESSOR_WDT_RESET_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_GX5_BIT_FLAGS_PROCESSOR_WDT_RESET_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GX5_BIT_FLAGS_PROCESSOR_WDT_RESET_MASK) >>
                                    MIPC_GX5_BIT_FLAGS_PROCESSOR_WDT_RESET_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GX5_BIT_FLAGS_IMU_COMMUNICATION_FAULT_MASK), UINT64_C(0x100));
    EXPECT_EQ(MIPC_GX5_BIT_FLAGS_IMU_COMMUNICATION_FAULT_SHIFT, 8);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GX5_BIT_FLAGS_IMU_COMMUNICATION_FAULT_MASK) >>
                                    MIPC_GX5_BIT_FLAGS_IMU_COMMUNICATION_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GX5_BIT_FLAGS_MAGNETOMETER_FAULT_MASK), UINT64_C(0x200));
    EXPECT_EQ(MIPC_GX5_BIT_FLAGS_MAGNETOMETER_FAULT_SHIFT, 9);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GX5_BIT_FLAGS_MAGNETOMETER_FAULT_MASK) >>
                                    MIPC_GX5_BIT_FLAGS_MAGNETOMETER_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GX5_BIT_FLAGS_PRESSURE_SENSOR_FAULT_MASK), UINT64_C(0x400));
    EXPECT_EQ(MIPC_GX5_BIT_FLAGS_PRESSURE_SENSOR_FAULT_SHIFT, 10);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GX5_BIT_FLAGS_PRESSURE_SENSOR_FAULT_MASK) >>
                                    MIPC_GX5_BIT_FLAGS_PRESSURE_SENSOR_FAULT_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_GX5_BIT_FLAGS_FILTER_SOLUTION_FAULT_MASK), UINT64_C(0x1000000));
    EXPECT_EQ(MIPC_GX5_BIT_FLAGS_FILTER_SOLUTION_FAULT_SHIFT, 24);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_GX5_BIT_FLAGS_FILTER_SOLUTION_FAULT_MASK) >>
                                    MIPC_GX5_BIT_FLAGS_FILTER_SOLUTION_FAULT_SHIFT),
              UINT64_C(0x1));
}

// mipc_heading_alignment_methods_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, HeadingAlignmentMethods) {
    const mipc_heading_alignment_methods_t all =
        static_cast<mipc_heading_alignment_methods_t>(~static_cast<mipc_heading_alignment_methods_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_HEADING_ALIGNMENT_METHODS_DUAL_ANTENNA_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_HEADING_ALIGNMENT_METHODS_DUAL_ANTENNA_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_HEADING_ALIGNMENT_METHODS_DUAL_ANTENNA_MASK) >>
                                    MIPC_HEADING_ALIGNMENT_METHODS_DUAL_ANTENNA_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_HEADING_ALIGNMENT_METHODS_KINEMATIC_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_HEADING_ALIGNMENT_METHODS_KINEMATIC_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_HEADING_ALIGNMENT_METHODS_KINEMATIC_MASK) >>
                                    MIPC_HEADING_ALIGNMENT_METHODS_KINEMATIC_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_HEADING_ALIGNMENT_METHODS_MAGNETOMETER_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_HEADING_ALIGNMENT_METHODS_MAGNETOMETER_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_HEADING_ALIGNMENT_METHODS_MAGNETOMETER_MASK) >>
                                    MIPC_HEADING_ALIGNMENT_METHODS_MAGNETOMETER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_HEADING_ALIGNMENT_METHODS_EXTERNAL_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_HEADING_ALIGNMENT_METHODS_EXTERNAL_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_HEADING_ALIGNMENT_METHODS_EXTERNAL_MASK) >>
                                    MIPC_HEADING_ALIGNMENT_METHODS_EXTERNAL_SHIFT),
              UINT64_C(0x1));
}

// mipc_odometer_data_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, OdometerDataValidFlags) {
    const mipc_odometer_data_valid_flags_t all =
        static_cast<mipc_odometer_data_valid_flags_t>(~static_cast<mipc_odometer_data_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_ODOMETER_DATA_VALID_FLAGS_VALID_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_ODOMETER_DATA_VALID_FLAGS_VALID_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_ODOMETER_DATA_VALID_FLAGS_VALID_MASK) >>
                                    MIPC_ODOMETER_DATA_VALID_FLAGS_VALID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_ODOMETER_DATA_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFFE));
    EXPECT_EQ(MIPC_ODOMETER_DATA_VALID_FLAGS_RESERVED_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_ODOMETER_DATA_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_ODOMETER_DATA_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x7FFF));
}

// mipc_overrange_status_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, OverrangeStatusFlags) {
    const mipc_overrange_status_flags_t all =
        static_cast<mipc_overrange_status_flags_t>(~static_cast<mipc_overrange_status_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_X_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_X_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_X_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_X_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Y_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Y_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Y_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Y_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Z_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Z_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Z_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Z_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_3_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_3_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_3_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_3_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_GYRO_X_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_GYRO_X_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_GYRO_X_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_GYRO_X_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Y_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Y_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Y_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Y_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Z_MASK), UINT64_C(0x40));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Z_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Z_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Z_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_7_MASK), UINT64_C(0x80));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_7_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_7_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_7_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_MAG_X_MASK), UINT64_C(0x100));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_MAG_X_SHIFT, 8);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_MAG_X_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_MAG_X_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_MAG_Y_MASK), UINT64_C(0x200));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_MAG_Y_SHIFT, 9);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_MAG_Y_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_MAG_Y_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_MAG_Z_MASK), UINT64_C(0x400));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_MAG_Z_SHIFT, 10);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_MAG_Z_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_MAG_Z_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_11_MASK), UINT64_C(0x800));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_11_SHIFT, 11);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_11_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_11_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_PRESS_MASK), UINT64_C(0x1000));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_PRESS_SHIFT, 12);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_PRESS_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_PRESS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_13_15_MASK), UINT64_C(0xE000));
    EXPECT_EQ(MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_13_15_SHIFT, 13);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_13_15_MASK) >>
                                    MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_13_15_SHIFT),
              UINT64_C(0x7));
}

// mipc_rtk_corrections_epoch_status_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, RtkCorrectionsEpochStatus) {
    const mipc_rtk_corrections_epoch_status_t all = static_cast<mipc_rtk_corrections_epoch_status_t>(
        ~static_cast<mipc_rtk_corrections_epoch_status_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_LOCATION_RECEIVED_MASK),
              UINT64_C(0x1));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_LOCATION_RECEIVED_SHIFT, 0);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_LOCATION_RECEIVED_MASK) >>
                              MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_LOCATION_RECEIVED_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_DESCRIPTION_RECEIVED_MASK),
              UINT64_C(0x2));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_DESCRIPTION_RECEIVED_SHIFT, 1);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_DESCRIPTION_RECEIVED_MASK) >>
                              MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_DESCRIPTION_RECEIVED_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GPS_RECEIVED_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GPS_RECEIVED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GPS_RECEIVED_MASK) >>
                                    MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GPS_RECEIVED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GLONASS_RECEIVED_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GLONASS_RECEIVED_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GLONASS_RECEIVED_MASK) >>
                                    MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GLONASS_RECEIVED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GALILEO_RECEIVED_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GALILEO_RECEIVED_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GALILEO_RECEIVED_MASK) >>
                                    MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GALILEO_RECEIVED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_BEIDOU_RECEIVED_MASK), UINT64_C(0x20));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_BEIDOU_RECEIVED_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_EPOCH_STATUS_BEIDOU_RECEIVED_MASK) >>
                                    MIPC_RTK_CORRECTIONS_EPOCH_STATUS_BEIDOU_RECEIVED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GPS_MSM_MESSAGES_MASK),
              UINT64_C(0x40));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GPS_MSM_MESSAGES_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GPS_MSM_MESSAGES_MASK) >>
                                    MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GPS_MSM_MESSAGES_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GLONASS_MSM_MESSAGES_MASK),
              UINT64_C(0x80));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GLONASS_MSM_MESSAGES_SHIFT, 7);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GLONASS_MSM_MESSAGES_MASK) >>
                              MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GLONASS_MSM_MESSAGES_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_DONGLE_STATUS_READ_FAILED_MASK),
              UINT64_C(0x100));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_DONGLE_STATUS_READ_FAILED_SHIFT, 8);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_EPOCH_STATUS_DONGLE_STATUS_READ_FAILED_MASK) >>
                              MIPC_RTK_CORRECTIONS_EPOCH_STATUS_DONGLE_STATUS_READ_FAILED_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_RESERVED_MASK), UINT64_C(0xFE00));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_EPOCH_STATUS_RESERVED_SHIFT, 9);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_EPOCH_STATUS_RESERVED_MASK) >>
                                    MIPC_RTK_CORRECTIONS_EPOCH_STATUS_RESERVED_SHIFT),
              UINT64_C(0x7F));
}

// mipc_rtk_corrections_status_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, RtkCorrectionsStatusValidFlags) {
    const mipc_rtk_corrections_status_valid_flags_t all =
        static_cast<mipc_rtk_corrections_status_valid_flags_t>(
            ~static_cast<mipc_rtk_corrections_status_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_TOW_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_TOW_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_TOW_MASK) >>
                                    MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_TOW_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_WEEK_NUMBER_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_WEEK_NUMBER_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_WEEK_NUMBER_MASK) >>
                                    MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_WEEK_NUMBER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_EPOCH_STATUS_MASK),
              UINT64_C(0x4));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_EPOCH_STATUS_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_EPOCH_STATUS_MASK) >>
                                    MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_EPOCH_STATUS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_DONGLE_STATUS_MASK),
              UINT64_C(0x8));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_DONGLE_STATUS_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_DONGLE_STATUS_MASK) >>
                                    MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_DONGLE_STATUS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GPS_LATENCY_MASK),
              UINT64_C(0x10));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GPS_LATENCY_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GPS_LATENCY_MASK) >>
                                    MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GPS_LATENCY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GLONASS_LATENCY_MASK),
              UINT64_C(0x20));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GLONASS_LATENCY_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GLONASS_LATENCY_MASK) >>
                                    MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GLONASS_LATENCY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GALILEO_LATENCY_MASK),
              UINT64_C(0x40));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GALILEO_LATENCY_SHIFT, 6);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GALILEO_LATENCY_MASK) >>
                                    MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GALILEO_LATENCY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_BEIDOU_LATENCY_MASK),
              UINT64_C(0x80));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_BEIDOU_LATENCY_SHIFT, 7);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_BEIDOU_LATENCY_MASK) >>
                                    MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_BEIDOU_LATENCY_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_FLAGS_MASK), UINT64_C(0xFF));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_FLAGS_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_FLAGS_MASK) >>
                                    MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_FLAGS_SHIFT),
              UINT64_C(0xFF));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFF00));
    EXPECT_EQ(MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_RESERVED_SHIFT, 8);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0xFF));
}

// mipc_sbas_options_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, SbasOptions) {
    const mipc_sbas_options_t all = static_cast<mipc_sbas_options_t>(~static_cast<mipc_sbas_options_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SBAS_OPTIONS_ENABLE_RANGING_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_SBAS_OPTIONS_ENABLE_RANGING_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SBAS_OPTIONS_ENABLE_RANGING_MASK) >>
                                    MIPC_SBAS_OPTIONS_ENABLE_RANGING_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SBAS_OPTIONS_ENABLE_CORRECTIONS_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_SBAS_OPTIONS_ENABLE_CORRECTIONS_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SBAS_OPTIONS_ENABLE_CORRECTIONS_MASK) >>
                                    MIPC_SBAS_OPTIONS_ENABLE_CORRECTIONS_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SBAS_OPTIONS_APPLY_INTEGRITY_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_SBAS_OPTIONS_APPLY_INTEGRITY_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SBAS_OPTIONS_APPLY_INTEGRITY_MASK) >>
                                    MIPC_SBAS_OPTIONS_APPLY_INTEGRITY_SHIFT),
              UINT64_C(0x1));
}

// mipc_sensor_gps_timestamp_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones
// value.
TEST(Bitfields, SensorGpsTimestampFlags) {
    const mipc_sensor_gps_timestamp_flags_t all =
        static_cast<mipc_sensor_gps_timestamp_flags_t>(~static_cast<mipc_sensor_gps_timestamp_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_PPS_VALID_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_PPS_VALID_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_PPS_VALID_MASK) >>
                                    MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_PPS_VALID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_REFRESH_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_REFRESH_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_REFRESH_MASK) >>
                                    MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_REFRESH_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_INITIALIZED_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_INITIALIZED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_INITIALIZED_MASK) >>
                                    MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_INITIALIZED_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TOW_VALID_MASK), UINT64_C(0x8));
    EXPECT_EQ(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TOW_VALID_SHIFT, 3);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TOW_VALID_MASK) >>
                                    MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TOW_VALID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_WEEK_NUMBER_VALID_MASK), UINT64_C(0x10));
    EXPECT_EQ(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_WEEK_NUMBER_VALID_SHIFT, 4);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_WEEK_NUMBER_VALID_MASK) >>
                                    MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_WEEK_NUMBER_VALID_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_RESERVED_MASK), UINT64_C(0xFFE0));
    EXPECT_EQ(MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_RESERVED_SHIFT, 5);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_RESERVED_MASK) >>
                                    MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x7FF));
}

// mipc_shared_gps_timestamp_valid_flags_t: each member's mask and shift, and (value & MASK) >> SHIFT of an
// all-ones value.
TEST(Bitfields, SharedGpsTimestampValidFlags) {
    const mipc_shared_gps_timestamp_valid_flags_t all = static_cast<mipc_shared_gps_timestamp_valid_flags_t>(
        ~static_cast<mipc_shared_gps_timestamp_valid_flags_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TOW_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TOW_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TOW_MASK) >>
                                    MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TOW_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_WEEK_NUMBER_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_WEEK_NUMBER_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_WEEK_NUMBER_MASK) >>
                                    MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_WEEK_NUMBER_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TIME_VALID_MASK), UINT64_C(0x3));
    EXPECT_EQ(MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TIME_VALID_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TIME_VALID_MASK) >>
                                    MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TIME_VALID_SHIFT),
              UINT64_C(0x3));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_RESERVED_MASK), UINT64_C(0xFFFC));
    EXPECT_EQ(MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_RESERVED_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_RESERVED_MASK) >>
                                    MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_RESERVED_SHIFT),
              UINT64_C(0x3FFF));
}

// mipc_tare_axes_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, TareAxes) {
    const mipc_tare_axes_t all = static_cast<mipc_tare_axes_t>(~static_cast<mipc_tare_axes_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_TARE_AXES_ROLL_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_TARE_AXES_ROLL_SHIFT, 0);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_TARE_AXES_ROLL_MASK) >> MIPC_TARE_AXES_ROLL_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_TARE_AXES_PITCH_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_TARE_AXES_PITCH_SHIFT, 1);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_TARE_AXES_PITCH_MASK) >> MIPC_TARE_AXES_PITCH_SHIFT),
              UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_TARE_AXES_YAW_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_TARE_AXES_YAW_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_TARE_AXES_YAW_MASK) >> MIPC_TARE_AXES_YAW_SHIFT),
              UINT64_C(0x1));
}

// mipc_trigger_status_t: each member's mask and shift, and (value & MASK) >> SHIFT of an all-ones value.
TEST(Bitfields, TriggerStatus) {
    const mipc_trigger_status_t all =
        static_cast<mipc_trigger_status_t>(~static_cast<mipc_trigger_status_t>(0));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_TRIGGER_STATUS_ACTIVE_MASK), UINT64_C(0x1));
    EXPECT_EQ(MIPC_TRIGGER_STATUS_ACTIVE_SHIFT, 0);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_TRIGGER_STATUS_ACTIVE_MASK) >> MIPC_TRIGGER_STATUS_ACTIVE_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_TRIGGER_STATUS_ENABLED_MASK), UINT64_C(0x2));
    EXPECT_EQ(MIPC_TRIGGER_STATUS_ENABLED_SHIFT, 1);
    EXPECT_EQ(
        static_cast<uint64_t>((all & MIPC_TRIGGER_STATUS_ENABLED_MASK) >> MIPC_TRIGGER_STATUS_ENABLED_SHIFT),
        UINT64_C(0x1));
    EXPECT_EQ(static_cast<uint64_t>(MIPC_TRIGGER_STATUS_TEST_MASK), UINT64_C(0x4));
    EXPECT_EQ(MIPC_TRIGGER_STATUS_TEST_SHIFT, 2);
    EXPECT_EQ(static_cast<uint64_t>((all & MIPC_TRIGGER_STATUS_TEST_MASK) >> MIPC_TRIGGER_STATUS_TEST_SHIFT),
              UINT64_C(0x1));
}

} // namespace
