/* Named types of the MicroStrain MIP protocol: enums, bitfields, structs and unions.
 * Generated from the spec: do not edit. */
#ifndef MIPC_TYPES_H
#define MIPC_TYPES_H

#include "mipcodec/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Ack/Nack code. Second byte of the ack/nack field; 0 is an ACK, any other value a NACK giving the reason.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_ack_code_t;
/** Success (ACK). */
#define MIPC_ACK_CODE_OK ((mipc_ack_code_t)0u)
/** The command descriptor is not supported by this device. */
#define MIPC_ACK_CODE_UNKNOWN_COMMAND ((mipc_ack_code_t)1u)
/** An otherwise complete packet has a bad checksum (GX5-45: invalid checksum). */
#define MIPC_ACK_CODE_BAD_CHECKSUM ((mipc_ack_code_t)2u)
/** One or more parameters are invalid: out of the allowed range, or not the expected size or type. */
#define MIPC_ACK_CODE_INVALID_PARAMETER ((mipc_ack_code_t)3u)
/** Device could not complete the command. */
#define MIPC_ACK_CODE_COMMAND_FAILED ((mipc_ack_code_t)4u)
/** Device could not complete the command within the expected time. */
#define MIPC_ACK_CODE_COMMAND_TIMEOUT ((mipc_ack_code_t)5u)
/** Unknown descriptor set (CV7 only). (devices: cv7_ins) */
#define MIPC_ACK_CODE_UNKNOWN_DESCRIPTOR_SET ((mipc_ack_code_t)6u)

/** GPIO action mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_action_gpio_mode_t;
/** Pin state will not be changed. */
#define MIPC_ACTION_GPIO_MODE_DISABLED ((mipc_action_gpio_mode_t)0u)
/** High while the trigger is active, low otherwise. */
#define MIPC_ACTION_GPIO_MODE_ACTIVE_HIGH ((mipc_action_gpio_mode_t)1u)
/** Low while the trigger is active, high otherwise. */
#define MIPC_ACTION_GPIO_MODE_ACTIVE_LOW ((mipc_action_gpio_mode_t)2u)
/** Set high each time the trigger activates. */
#define MIPC_ACTION_GPIO_MODE_ONESHOT_HIGH ((mipc_action_gpio_mode_t)5u)
/** Set low each time the trigger activates. */
#define MIPC_ACTION_GPIO_MODE_ONESHOT_LOW ((mipc_action_gpio_mode_t)6u)
/** Toggle each time the trigger activates. */
#define MIPC_ACTION_GPIO_MODE_TOGGLE ((mipc_action_gpio_mode_t)7u)

/** Event action type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_action_type_t;
/** No action. Parameters should be empty. */
#define MIPC_ACTION_TYPE_NONE ((mipc_action_type_t)0u)
/** Control the state of a GPIO pin. */
#define MIPC_ACTION_TYPE_GPIO ((mipc_action_type_t)1u)
/** Output a data packet. */
#define MIPC_ACTION_TYPE_MESSAGE ((mipc_action_type_t)2u)

/** Auto-adaptive filter operating level.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_adaptive_filter_level_t;
/** Adaptive filtering off. */
#define MIPC_ADAPTIVE_FILTER_LEVEL_OFF ((mipc_adaptive_filter_level_t)0u)
/** Conservative. */
#define MIPC_ADAPTIVE_FILTER_LEVEL_CONSERVATIVE ((mipc_adaptive_filter_level_t)1u)
/** Moderate (default). */
#define MIPC_ADAPTIVE_FILTER_LEVEL_MODERATE ((mipc_adaptive_filter_level_t)2u)
/** Aggressive. */
#define MIPC_ADAPTIVE_FILTER_LEVEL_AGGRESSIVE ((mipc_adaptive_filter_level_t)3u)

/** Adaptive measurement mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_adaptive_measurement_mode_t;
/** No adaptive measurement. */
#define MIPC_ADAPTIVE_MEASUREMENT_MODE_DISABLED ((mipc_adaptive_measurement_mode_t)0u)
/** Fixed adaptive measurement using the specified filter and limit parameters. */
#define MIPC_ADAPTIVE_MEASUREMENT_MODE_FIXED ((mipc_adaptive_measurement_mode_t)1u)
/** Auto-adaptive: the Kalman filter re-weights the measurement by its perceived quality (3DM-GX5 and later);
 * limits are ignored. */
#define MIPC_ADAPTIVE_MEASUREMENT_MODE_AUTO ((mipc_adaptive_measurement_mode_t)2u)

/** Aiding command echo mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_aiding_echo_mode_t;
/** The aiding measurement commands are not acknowledged. */
#define MIPC_AIDING_ECHO_MODE_SUPPRESS_ACK ((mipc_aiding_echo_mode_t)0u)
/** Normal ack/nack behavior. */
#define MIPC_AIDING_ECHO_MODE_STANDARD ((mipc_aiding_echo_mode_t)1u)
/** The device echoes the aiding data back as a response. */
#define MIPC_AIDING_ECHO_MODE_RESPONSE ((mipc_aiding_echo_mode_t)2u)

/** Aiding frame rotation format.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_aiding_frame_format_t;
/** Translation vector followed by Euler angles (roll, pitch, yaw). */
#define MIPC_AIDING_FRAME_FORMAT_EULER ((mipc_aiding_frame_format_t)1u)
/** Translation vector followed by a quaternion (w, x, y, z). */
#define MIPC_AIDING_FRAME_FORMAT_QUATERNION ((mipc_aiding_frame_format_t)2u)

/** LLH position aiding valid flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_aiding_llh_valid_flags_t;
/** bit 0: Latitude valid. */
#define MIPC_AIDING_LLH_VALID_FLAGS_LATITUDE_MASK ((mipc_aiding_llh_valid_flags_t)0x1u)
#define MIPC_AIDING_LLH_VALID_FLAGS_LATITUDE_SHIFT 0
/** bit 1: Longitude valid. */
#define MIPC_AIDING_LLH_VALID_FLAGS_LONGITUDE_MASK ((mipc_aiding_llh_valid_flags_t)0x2u)
#define MIPC_AIDING_LLH_VALID_FLAGS_LONGITUDE_SHIFT 1
/** bit 2: Height valid. */
#define MIPC_AIDING_LLH_VALID_FLAGS_HEIGHT_MASK ((mipc_aiding_llh_valid_flags_t)0x4u)
#define MIPC_AIDING_LLH_VALID_FLAGS_HEIGHT_SHIFT 2

/** Aiding measurement source.
 * An integer, so that values the spec does not list are kept. */
typedef uint16_t mipc_aiding_measurement_source_t;
/** GNSS position and velocity. */
#define MIPC_AIDING_MEASUREMENT_SOURCE_GNSS_POS_VEL ((mipc_aiding_measurement_source_t)0u)
/** GNSS heading (dual antenna). */
#define MIPC_AIDING_MEASUREMENT_SOURCE_GNSS_HEADING ((mipc_aiding_measurement_source_t)1u)
/** Pressure altimeter (built-in sensor). */
#define MIPC_AIDING_MEASUREMENT_SOURCE_ALTIMETER ((mipc_aiding_measurement_source_t)2u)
/** Speed sensor / odometer. */
#define MIPC_AIDING_MEASUREMENT_SOURCE_SPEED ((mipc_aiding_measurement_source_t)3u)
/** Magnetometer (built-in sensor). */
#define MIPC_AIDING_MEASUREMENT_SOURCE_MAGNETOMETER ((mipc_aiding_measurement_source_t)4u)
/** External heading input. */
#define MIPC_AIDING_MEASUREMENT_SOURCE_EXTERNAL_HEADING ((mipc_aiding_measurement_source_t)5u)
/** External pressure altimeter input. */
#define MIPC_AIDING_MEASUREMENT_SOURCE_EXTERNAL_ALTIMETER ((mipc_aiding_measurement_source_t)6u)
/** External magnetometer input. */
#define MIPC_AIDING_MEASUREMENT_SOURCE_EXTERNAL_MAGNETOMETER ((mipc_aiding_measurement_source_t)7u)
/** External body frame velocity input. */
#define MIPC_AIDING_MEASUREMENT_SOURCE_BODY_FRAME_VEL ((mipc_aiding_measurement_source_t)8u)
/** All sources (for save, load and default). */
#define MIPC_AIDING_MEASUREMENT_SOURCE_ALL ((mipc_aiding_measurement_source_t)65535u)

/** Aiding measurement timebase. Clock in which the timestamp of an aiding measurement is expressed.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_aiding_timebase_t;
/** Timestamp in the device's internal reference time (nanoseconds since power-on). */
#define MIPC_AIDING_TIMEBASE_INTERNAL_REFERENCE ((mipc_aiding_timebase_t)1u)
/** Timestamp in external time, synchronised by the PPS source and GPS time update. */
#define MIPC_AIDING_TIMEBASE_EXTERNAL_TIME ((mipc_aiding_timebase_t)2u)
/** No timestamp: the measurement is taken at its arrival time, with a fixed latency. */
#define MIPC_AIDING_TIMEBASE_TIME_OF_ARRIVAL ((mipc_aiding_timebase_t)3u)

/** Aiding vector valid flags. Which axes of a 3-axis aiding measurement are valid; axes with 0 are ignored.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_aiding_vector_valid_flags_t;
/** bit 0: X (or north) component valid. */
#define MIPC_AIDING_VECTOR_VALID_FLAGS_X_MASK ((mipc_aiding_vector_valid_flags_t)0x1u)
#define MIPC_AIDING_VECTOR_VALID_FLAGS_X_SHIFT 0
/** bit 1: Y (or east) component valid. */
#define MIPC_AIDING_VECTOR_VALID_FLAGS_Y_MASK ((mipc_aiding_vector_valid_flags_t)0x2u)
#define MIPC_AIDING_VECTOR_VALID_FLAGS_Y_SHIFT 1
/** bit 2: Z (or down) component valid. */
#define MIPC_AIDING_VECTOR_VALID_FLAGS_Z_MASK ((mipc_aiding_vector_valid_flags_t)0x4u)
#define MIPC_AIDING_VECTOR_VALID_FLAGS_Z_SHIFT 2

/** Altitude aiding source.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_altitude_aiding_source_t;
/** No altitude aiding (disabled). */
#define MIPC_ALTITUDE_AIDING_SOURCE_NONE ((mipc_altitude_aiding_source_t)0u)
/** Pressure sensor aiding enabled. */
#define MIPC_ALTITUDE_AIDING_SOURCE_PRESSURE ((mipc_altitude_aiding_source_t)1u)

/** Assisted fix option.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_assisted_fix_option_t;
/** No assisted fix (default). */
#define MIPC_ASSISTED_FIX_OPTION_NONE ((mipc_assisted_fix_option_t)0u)
/** Assisted fix enabled. */
#define MIPC_ASSISTED_FIX_OPTION_ENABLED ((mipc_assisted_fix_option_t)1u)

/** GNSS constellation option flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_constellation_options_t;
/** bit 0: L1SAIF signal (QZSS only). */
#define MIPC_CONSTELLATION_OPTIONS_L1SAIF_MASK ((mipc_constellation_options_t)0x1u)
#define MIPC_CONSTELLATION_OPTIONS_L1SAIF_SHIFT 0

/** 3DM-CV7 commanded built-in test result.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint32_t mipc_cv7_bit_flags_t;
/** bit 0: A critical hardware component has failed or is not operating properly. */
#define MIPC_CV7_BIT_FLAGS_GENERAL_HARDWARE_FAULT_MASK ((mipc_cv7_bit_flags_t)0x1u)
#define MIPC_CV7_BIT_FLAGS_GENERAL_HARDWARE_FAULT_SHIFT 0
/** bit 1: System firmware has detected a serious, unexpected or abnormal condition. */
#define MIPC_CV7_BIT_FLAGS_GENERAL_FIRMWARE_FAULT_MASK ((mipc_cv7_bit_flags_t)0x2u)
#define MIPC_CV7_BIT_FLAGS_GENERAL_FIRMWARE_FAULT_SHIFT 1
/** bit 2: The system cannot keep up with the processing demand. */
#define MIPC_CV7_BIT_FLAGS_TIMING_OVERLOAD_MASK ((mipc_cv7_bit_flags_t)0x4u)
#define MIPC_CV7_BIT_FLAGS_TIMING_OVERLOAD_SHIFT 2
/** bit 3: A data buffer has reached its capacity. */
#define MIPC_CV7_BIT_FLAGS_BUFFER_OVERRUN_MASK ((mipc_cv7_bit_flags_t)0x8u)
#define MIPC_CV7_BIT_FLAGS_BUFFER_OVERRUN_SHIFT 3
/** bits 4-7: (reserved) Reserved (system). */
#define MIPC_CV7_BIT_FLAGS_RESERVED_SYSTEM_MASK ((mipc_cv7_bit_flags_t)0xF0u)
#define MIPC_CV7_BIT_FLAGS_RESERVED_SYSTEM_SHIFT 4
/** bits 8-11: (reserved) Reserved (comms). */
#define MIPC_CV7_BIT_FLAGS_RESERVED_COMMS_MASK ((mipc_cv7_bit_flags_t)0xF00u)
#define MIPC_CV7_BIT_FLAGS_RESERVED_COMMS_SHIFT 8
/** bit 12: The accelerometer has been damaged or is inoperative. */
#define MIPC_CV7_BIT_FLAGS_ACCELEROMETER_FAULT_MASK ((mipc_cv7_bit_flags_t)0x1000u)
#define MIPC_CV7_BIT_FLAGS_ACCELEROMETER_FAULT_SHIFT 12
/** bit 13: The gyroscope has been damaged or is inoperative. */
#define MIPC_CV7_BIT_FLAGS_GYROSCOPE_FAULT_MASK ((mipc_cv7_bit_flags_t)0x2000u)
#define MIPC_CV7_BIT_FLAGS_GYROSCOPE_FAULT_SHIFT 13
/** bit 14: The magnetometer has been damaged or is inoperative. */
#define MIPC_CV7_BIT_FLAGS_MAGNETOMETER_FAULT_MASK ((mipc_cv7_bit_flags_t)0x4000u)
#define MIPC_CV7_BIT_FLAGS_MAGNETOMETER_FAULT_SHIFT 14
/** bit 15: The pressure sensor has been damaged or is inoperative. */
#define MIPC_CV7_BIT_FLAGS_PRESSURE_SENSOR_FAULT_MASK ((mipc_cv7_bit_flags_t)0x8000u)
#define MIPC_CV7_BIT_FLAGS_PRESSURE_SENSOR_FAULT_SHIFT 15
/** bits 16-17: (reserved) Reserved (IMU). */
#define MIPC_CV7_BIT_FLAGS_RESERVED_IMU_MASK ((mipc_cv7_bit_flags_t)0x30000u)
#define MIPC_CV7_BIT_FLAGS_RESERVED_IMU_SHIFT 16
/** bit 18: One or more IMU calibration tables are invalid. */
#define MIPC_CV7_BIT_FLAGS_CALIBRATION_ERROR_MASK ((mipc_cv7_bit_flags_t)0x40000u)
#define MIPC_CV7_BIT_FLAGS_CALIBRATION_ERROR_SHIFT 18
/** bit 19: A problem has been detected in the IMU subsystem. */
#define MIPC_CV7_BIT_FLAGS_GENERAL_IMU_FAULT_MASK ((mipc_cv7_bit_flags_t)0x80000u)
#define MIPC_CV7_BIT_FLAGS_GENERAL_IMU_FAULT_SHIFT 19
/** bits 20-21: (reserved) Reserved (filter). */
#define MIPC_CV7_BIT_FLAGS_RESERVED_FILTER_MASK ((mipc_cv7_bit_flags_t)0x300000u)
#define MIPC_CV7_BIT_FLAGS_RESERVED_FILTER_SHIFT 20
/** bit 22: The filter solution is invalid (NaN in the filter output). */
#define MIPC_CV7_BIT_FLAGS_FILTER_SOLUTION_FAULT_MASK ((mipc_cv7_bit_flags_t)0x400000u)
#define MIPC_CV7_BIT_FLAGS_FILTER_SOLUTION_FAULT_SHIFT 22
/** bit 23: A problem has been detected in the filter subsystem. */
#define MIPC_CV7_BIT_FLAGS_GENERAL_FILTER_FAULT_MASK ((mipc_cv7_bit_flags_t)0x800000u)
#define MIPC_CV7_BIT_FLAGS_GENERAL_FILTER_FAULT_SHIFT 23
/** bits 24-31: (reserved) Reserved. */
#define MIPC_CV7_BIT_FLAGS_RESERVED_MASK ((mipc_cv7_bit_flags_t)0xFF000000u)
#define MIPC_CV7_BIT_FLAGS_RESERVED_SHIFT 24

/** Continuous BIT byte 13: GNSS receivers (bits 104-111).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_cv7_continuous_bit_gnss13_t;
/** bit 0: (reserved) Bit 104 (13.0): GNSS reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_104_MASK ((mipc_cv7_continuous_bit_gnss13_t)0x1u)
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_104_SHIFT 0
/** bit 1: Bit 105 (13.1): no communication with internal GNSS receiver 1. */
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_FAULT_MASK ((mipc_cv7_continuous_bit_gnss13_t)0x2u)
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_FAULT_SHIFT 1
/** bits 2-3: (reserved) Bits 106-107 (13.2-13.3): GNSS reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_106_107_MASK ((mipc_cv7_continuous_bit_gnss13_t)0xCu)
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_106_107_SHIFT 2
/** bit 4: Bit 108 (13.4): internal receiver 1 has no valid solution (check antenna and sky view). */
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_NO_SOLUTION_MASK ((mipc_cv7_continuous_bit_gnss13_t)0x10u)
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_1_NO_SOLUTION_SHIFT 4
/** bit 5: (reserved) Bit 109 (13.5): GNSS reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_109_MASK ((mipc_cv7_continuous_bit_gnss13_t)0x20u)
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_109_SHIFT 5
/** bit 6: Bit 110 (13.6): no communication with internal GNSS receiver 2. */
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_2_FAULT_MASK ((mipc_cv7_continuous_bit_gnss13_t)0x40u)
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RECEIVER_2_FAULT_SHIFT 6
/** bit 7: (reserved) Bit 111 (13.7): GNSS reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_111_MASK ((mipc_cv7_continuous_bit_gnss13_t)0x80u)
#define MIPC_CV7_CONTINUOUS_BIT_GNSS13_RESERVED_111_SHIFT 7

/** Continuous BIT byte 14: GNSS receivers (bits 112-119).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_cv7_continuous_bit_gnss14_t;
/** bit 0: (reserved) Bit 112 (14.0): GNSS reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_112_MASK ((mipc_cv7_continuous_bit_gnss14_t)0x1u)
#define MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_112_SHIFT 0
/** bit 1: Bit 113 (14.1): internal receiver 2 has no valid solution (check antenna and sky view). */
#define MIPC_CV7_CONTINUOUS_BIT_GNSS14_RECEIVER_2_NO_SOLUTION_MASK ((mipc_cv7_continuous_bit_gnss14_t)0x2u)
#define MIPC_CV7_CONTINUOUS_BIT_GNSS14_RECEIVER_2_NO_SOLUTION_SHIFT 1
/** bits 2-7: (reserved) Bits 114-119 (14.2-14.7): GNSS reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_114_119_MASK ((mipc_cv7_continuous_bit_gnss14_t)0xFCu)
#define MIPC_CV7_CONTINUOUS_BIT_GNSS14_RESERVED_114_119_SHIFT 2

/** Continuous BIT byte 4: IMU (bits 32-39).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_cv7_continuous_bit_imu4_t;
/** bit 0: (reserved) Bit 32 (4.0): IMU reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_32_MASK ((mipc_cv7_continuous_bit_imu4_t)0x1u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_32_SHIFT 0
/** bit 1: Bit 33 (4.1): no communication with the IMU. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_COMMUNICATION_FAULT_MASK ((mipc_cv7_continuous_bit_imu4_t)0x2u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_COMMUNICATION_FAULT_SHIFT 1
/** bit 2: Bit 34 (4.2): IMU core processes take longer than their allotted time. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_TIMING_OVERRUN_MASK ((mipc_cv7_continuous_bit_imu4_t)0x4u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_TIMING_OVERRUN_SHIFT 2
/** bit 3: (reserved) Bit 35 (4.3): IMU reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_35_MASK ((mipc_cv7_continuous_bit_imu4_t)0x8u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_35_SHIFT 3
/** bit 4: Bit 36 (4.4): problem with the accelerometer calibration. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_ACCELEROMETER_MASK                                \
    ((mipc_cv7_continuous_bit_imu4_t)0x10u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_ACCELEROMETER_SHIFT 4
/** bit 5: Bit 37 (4.5): problem with the gyroscope calibration. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_GYROSCOPE_MASK                                    \
    ((mipc_cv7_continuous_bit_imu4_t)0x20u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_GYROSCOPE_SHIFT 5
/** bit 6: Bit 38 (4.6): problem with the magnetometer calibration. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_MAGNETOMETER_MASK                                 \
    ((mipc_cv7_continuous_bit_imu4_t)0x40u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_IMU_CALIBRATION_ERROR_MAGNETOMETER_SHIFT 6
/** bit 7: (reserved) Bit 39 (4.7): IMU calibration error, reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_39_MASK ((mipc_cv7_continuous_bit_imu4_t)0x80u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU4_RESERVED_39_SHIFT 7

/** Continuous BIT byte 5: IMU accelerometer and gyroscope (bits 40-47).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_cv7_continuous_bit_imu5_t;
/** bit 0: Bit 40 (5.0): the accelerometer will not initialize. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_GENERAL_FAULT_MASK ((mipc_cv7_continuous_bit_imu5_t)0x1u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_GENERAL_FAULT_SHIFT 0
/** bit 1: Bit 41 (5.1): one or more axes near or beyond the selected range. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_OVERRANGE_MASK ((mipc_cv7_continuous_bit_imu5_t)0x2u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_OVERRANGE_SHIFT 1
/** bit 2: Bit 42 (5.2): accelerometer self-test failed (updated by the commanded BIT only). */
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_SELF_TEST_FAIL_MASK ((mipc_cv7_continuous_bit_imu5_t)0x4u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_ACCELEROMETER_SELF_TEST_FAIL_SHIFT 2
/** bit 3: (reserved) Bit 43 (5.3): accelerometer reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_43_MASK ((mipc_cv7_continuous_bit_imu5_t)0x8u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_43_SHIFT 3
/** bit 4: Bit 44 (5.4): the gyroscope will not initialize. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_GENERAL_FAULT_MASK ((mipc_cv7_continuous_bit_imu5_t)0x10u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_GENERAL_FAULT_SHIFT 4
/** bit 5: Bit 45 (5.5): one or more axes near or beyond the selected range. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_OVERRANGE_MASK ((mipc_cv7_continuous_bit_imu5_t)0x20u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_OVERRANGE_SHIFT 5
/** bit 6: Bit 46 (5.6): gyroscope self-test failed (updated by the commanded BIT only). */
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_SELF_TEST_FAIL_MASK ((mipc_cv7_continuous_bit_imu5_t)0x40u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_GYROSCOPE_SELF_TEST_FAIL_SHIFT 6
/** bit 7: (reserved) Bit 47 (5.7): gyroscope reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_47_MASK ((mipc_cv7_continuous_bit_imu5_t)0x80u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU5_RESERVED_47_SHIFT 7

/** Continuous BIT byte 6: IMU magnetometer and pressure sensor (bits 48-55).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_cv7_continuous_bit_imu6_t;
/** bit 0: Bit 48 (6.0): the magnetometer will not initialize. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_GENERAL_FAULT_MASK ((mipc_cv7_continuous_bit_imu6_t)0x1u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_GENERAL_FAULT_SHIFT 0
/** bit 1: Bit 49 (6.1): one or more axes near or beyond the supported range. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_OVERRANGE_MASK ((mipc_cv7_continuous_bit_imu6_t)0x2u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_OVERRANGE_SHIFT 1
/** bit 2: Bit 50 (6.2): magnetometer self-test failed (updated by the commanded BIT only). */
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_SELF_TEST_FAIL_MASK ((mipc_cv7_continuous_bit_imu6_t)0x4u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_MAGNETOMETER_SELF_TEST_FAIL_SHIFT 2
/** bit 3: (reserved) Bit 51 (6.3): magnetometer reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_51_MASK ((mipc_cv7_continuous_bit_imu6_t)0x8u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_51_SHIFT 3
/** bit 4: Bit 52 (6.4): the pressure sensor will not initialize. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_GENERAL_FAULT_MASK                                      \
    ((mipc_cv7_continuous_bit_imu6_t)0x10u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_GENERAL_FAULT_SHIFT 4
/** bit 5: Bit 53 (6.5): pressure outside the supported range. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_OVERRANGE_MASK ((mipc_cv7_continuous_bit_imu6_t)0x20u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_OVERRANGE_SHIFT 5
/** bit 6: Bit 54 (6.6): pressure sensor self-test failed (updated by the commanded BIT only). */
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_SELF_TEST_FAIL_MASK                                     \
    ((mipc_cv7_continuous_bit_imu6_t)0x40u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_PRESSURE_SENSOR_SELF_TEST_FAIL_SHIFT 6
/** bit 7: (reserved) Bit 55 (6.7): pressure sensor reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_55_MASK ((mipc_cv7_continuous_bit_imu6_t)0x80u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU6_RESERVED_55_SHIFT 7

/** Continuous BIT byte 7: IMU (bits 56-63).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_cv7_continuous_bit_imu7_t;
/** bit 0: Bit 56 (7.0): the device has lost its configuration; contact support. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU7_FACTORY_BITS_INVALID_MASK ((mipc_cv7_continuous_bit_imu7_t)0x1u)
#define MIPC_CV7_CONTINUOUS_BIT_IMU7_FACTORY_BITS_INVALID_SHIFT 0
/** bits 1-7: (reserved) Bits 57-63 (7.1-7.7): reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_IMU7_RESERVED_57_63_MASK ((mipc_cv7_continuous_bit_imu7_t)0xFEu)
#define MIPC_CV7_CONTINUOUS_BIT_IMU7_RESERVED_57_63_SHIFT 1

/** Continuous BIT byte 8: navigation filter (bits 64-71).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_cv7_continuous_bit_nav8_t;
/** bit 0: (reserved) Bit 64 (8.0): reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_64_MASK ((mipc_cv7_continuous_bit_nav8_t)0x1u)
#define MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_64_SHIFT 0
/** bit 1: (reserved) Bit 65 (8.1): reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_65_MASK ((mipc_cv7_continuous_bit_nav8_t)0x2u)
#define MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_65_SHIFT 1
/** bit 2: Bit 66 (8.2): filter processes take longer than their allotted time. */
#define MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_OVERRUN_MASK ((mipc_cv7_continuous_bit_nav8_t)0x4u)
#define MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_OVERRUN_SHIFT 2
/** bit 3: Bit 67 (8.3): filter processes are being skipped. */
#define MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_UNDERRUN_MASK ((mipc_cv7_continuous_bit_nav8_t)0x8u)
#define MIPC_CV7_CONTINUOUS_BIT_NAV8_FILTER_TIMING_UNDERRUN_SHIFT 3
/** bits 4-7: (reserved) Bits 68-71 (8.4-8.7): reserved (printed as GNSS reserved). */
#define MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_68_71_MASK ((mipc_cv7_continuous_bit_nav8_t)0xF0u)
#define MIPC_CV7_CONTINUOUS_BIT_NAV8_RESERVED_68_71_SHIFT 4

/** Continuous BIT byte 0: system (bits 0-7).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_cv7_continuous_bit_system0_t;
/** bit 0: Bit 0 (0.0): the system clock is not operating properly; timing may be inaccurate. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_SYSTEM_CLOCK_FAILURE_MASK ((mipc_cv7_continuous_bit_system0_t)0x1u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_SYSTEM_CLOCK_FAILURE_SHIFT 0
/** bit 1: Bit 1 (0.1): supply voltage out of the recommended range, or an internal power fault. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_POWER_FAULT_MASK ((mipc_cv7_continuous_bit_system0_t)0x2u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_POWER_FAULT_SHIFT 1
/** bits 2-3: (reserved) Bits 2-3 (0.2-0.3): reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_2_3_MASK ((mipc_cv7_continuous_bit_system0_t)0xCu)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_2_3_SHIFT 2
/** bit 4: Bit 4 (0.4): firmware detected an unexpected or abnormal condition. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_FIRMWARE_FAULT_MASK ((mipc_cv7_continuous_bit_system0_t)0x10u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_FIRMWARE_FAULT_SHIFT 4
/** bit 5: Bit 5 (0.5): the system cannot keep up with the processing demand (e.g. too many descriptors). */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_TIMING_OVERLOAD_MASK ((mipc_cv7_continuous_bit_system0_t)0x20u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_TIMING_OVERLOAD_SHIFT 5
/** bit 6: Bit 6 (0.6): a data buffer filled up and data may have been lost (bandwidth exceeded). */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_BUFFER_OVERRUN_MASK ((mipc_cv7_continuous_bit_system0_t)0x40u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_BUFFER_OVERRUN_SHIFT 6
/** bit 7: (reserved) Bit 7 (0.7): reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_7_MASK ((mipc_cv7_continuous_bit_system0_t)0x80u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM0_RESERVED_7_SHIFT 7

/** Continuous BIT byte 2: system, IMU and filter processes (bits 16-23).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_cv7_continuous_bit_system2_t;
/** bit 0: Bit 16 (2.0): the IMU subsystem is not running or did not start. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_PROCESS_FAULT_MASK ((mipc_cv7_continuous_bit_system2_t)0x1u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_PROCESS_FAULT_SHIFT 0
/** bit 1: Bit 17 (2.1): IMU data processing took longer than allowed. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_PROCESS_TIME_EXCEEDED_MASK                                  \
    ((mipc_cv7_continuous_bit_system2_t)0x2u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_PROCESS_TIME_EXCEEDED_SHIFT 1
/** bit 2: Bit 18 (2.2): IMU data is not produced at the expected base rate. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_RATE_ERROR_MASK ((mipc_cv7_continuous_bit_system2_t)0x4u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_DATA_RATE_ERROR_SHIFT 2
/** bit 3: Bit 19 (2.3): the IMU subsystem has stalled. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_STALL_MASK ((mipc_cv7_continuous_bit_system2_t)0x8u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_IMU_STALL_SHIFT 3
/** bits 4-7: Bits 20-23 (2.4-2.7): any filter process fault (the four bits below). */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_FAULT_MASK ((mipc_cv7_continuous_bit_system2_t)0xF0u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_FAULT_SHIFT 4
/** bit 4: Bit 20 (2.4): problem with the navigation filter major cycle. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MAJOR_CYCLE_FAULT_MASK                                        \
    ((mipc_cv7_continuous_bit_system2_t)0x10u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MAJOR_CYCLE_FAULT_SHIFT 4
/** bit 5: Bit 21 (2.5): problem with the navigation filter minor cycle. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MINOR_CYCLE_FAULT_MASK                                        \
    ((mipc_cv7_continuous_bit_system2_t)0x20u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_MINOR_CYCLE_FAULT_SHIFT 5
/** bit 6: Bit 22 (2.6): a navigation filter process is not running at its base rate. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_DATA_RATE_ERROR_MASK ((mipc_cv7_continuous_bit_system2_t)0x40u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_DATA_RATE_ERROR_SHIFT 6
/** bit 7: Bit 23 (2.7): a navigation filter process has stalled. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_STALL_MASK ((mipc_cv7_continuous_bit_system2_t)0x80u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM2_FILTER_PROCESS_STALL_SHIFT 7

/** Continuous BIT byte 3: system, GNSS processes (bits 24-31).
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_cv7_continuous_bit_system3_t;
/** bits 0-3: Bits 24-27 (3.0-3.3): any GNSS subsystem fault (the bits below). */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_SUBSYSTEM_FAULT_MASK ((mipc_cv7_continuous_bit_system3_t)0xFu)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_SUBSYSTEM_FAULT_SHIFT 0
/** bit 0: Bit 24 (3.0): the master GNSS process has not run within its timeout. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_MAIN_PROCESS_FAULT_MASK ((mipc_cv7_continuous_bit_system3_t)0x1u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_MAIN_PROCESS_FAULT_SHIFT 0
/** bit 1: Bit 25 (3.1): no data processed from internal receiver 1 within the timeout. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_1_STALL_MASK ((mipc_cv7_continuous_bit_system3_t)0x2u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_1_STALL_SHIFT 1
/** bit 2: Bit 26 (3.2): no data processed from internal receiver 2 within the timeout. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_2_STALL_MASK ((mipc_cv7_continuous_bit_system3_t)0x4u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_GNSS_RECEIVER_2_STALL_SHIFT 2
/** bit 3: (reserved) Bit 27 (3.3): reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_27_MASK ((mipc_cv7_continuous_bit_system3_t)0x8u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_27_SHIFT 3
/** bits 4-7: (reserved) Bits 28-31 (3.4-3.7): system reserved. */
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_28_31_MASK ((mipc_cv7_continuous_bit_system3_t)0xF0u)
#define MIPC_CV7_CONTINUOUS_BIT_SYSTEM3_RESERVED_28_31_SHIFT 4

/** Device status selector.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_device_status_selector_t;
/** Basic status structure. */
#define MIPC_DEVICE_STATUS_SELECTOR_BASIC ((mipc_device_status_selector_t)1u)
/** Diagnostic status structure. */
#define MIPC_DEVICE_STATUS_SELECTOR_DIAGNOSTIC ((mipc_device_status_selector_t)2u)

/** Estimation control flags. Which optional states the Kalman filter estimates.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_estimation_control_flags_t;
/** bit 0: Estimate gyro bias (recommended). */
#define MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_BIAS_MASK ((mipc_estimation_control_flags_t)0x1u)
#define MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_BIAS_SHIFT 0
/** bit 1: Estimate accelerometer bias (recommended). */
#define MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_BIAS_MASK ((mipc_estimation_control_flags_t)0x2u)
#define MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_BIAS_SHIFT 1
/** bit 2: Estimate gyro scale factor (optional). */
#define MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_SCALE_FACTOR_MASK ((mipc_estimation_control_flags_t)0x4u)
#define MIPC_ESTIMATION_CONTROL_FLAGS_GYRO_SCALE_FACTOR_SHIFT 2
/** bit 3: Estimate accelerometer scale factor (optional). */
#define MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_SCALE_FACTOR_MASK ((mipc_estimation_control_flags_t)0x8u)
#define MIPC_ESTIMATION_CONTROL_FLAGS_ACCEL_SCALE_FACTOR_SHIFT 3
/** bit 4: Estimate the GNSS antenna offset (optional). */
#define MIPC_ESTIMATION_CONTROL_FLAGS_ANTENNA_OFFSET_MASK ((mipc_estimation_control_flags_t)0x10u)
#define MIPC_ESTIMATION_CONTROL_FLAGS_ANTENNA_OFFSET_SHIFT 4
/** bit 5: Hard iron auto-calibration (optional). */
#define MIPC_ESTIMATION_CONTROL_FLAGS_HARD_IRON_AUTO_CAL_MASK ((mipc_estimation_control_flags_t)0x20u)
#define MIPC_ESTIMATION_CONTROL_FLAGS_HARD_IRON_AUTO_CAL_SHIFT 5
/** bit 6: Soft iron auto-calibration (optional). */
#define MIPC_ESTIMATION_CONTROL_FLAGS_SOFT_IRON_AUTO_CAL_MASK ((mipc_estimation_control_flags_t)0x40u)
#define MIPC_ESTIMATION_CONTROL_FLAGS_SOFT_IRON_AUTO_CAL_SHIFT 6
/** bits 7-15: (reserved) Not named by the manual. */
#define MIPC_ESTIMATION_CONTROL_FLAGS_RESERVED_MASK ((mipc_estimation_control_flags_t)0xFF80u)
#define MIPC_ESTIMATION_CONTROL_FLAGS_RESERVED_SHIFT 7

/** Event trigger control mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_event_control_mode_t;
/** Trigger is disabled. */
#define MIPC_EVENT_CONTROL_MODE_DISABLED ((mipc_event_control_mode_t)0u)
/** Trigger is enabled and will work normally. */
#define MIPC_EVENT_CONTROL_MODE_ENABLED ((mipc_event_control_mode_t)1u)
/** Forces the trigger to the active state for testing purposes. */
#define MIPC_EVENT_CONTROL_MODE_TEST ((mipc_event_control_mode_t)2u)
/** Trigger is forced active for one event cycle only, then reverts. */
#define MIPC_EVENT_CONTROL_MODE_TEST_PULSE ((mipc_event_control_mode_t)3u)

/** External heading type. Reference of an externally supplied heading angle.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_external_heading_type_t;
/** True heading (from true north). */
#define MIPC_EXTERNAL_HEADING_TYPE_TRUE_HEADING ((mipc_external_heading_type_t)1u)
/** Magnetic heading (from magnetic north). */
#define MIPC_EXTERNAL_HEADING_TYPE_MAGNETIC_HEADING ((mipc_external_heading_type_t)2u)

/** External time delta valid flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_external_time_delta_valid_flags_t;
/** bit 0: The delta is valid. */
#define MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_DT_NANOS_MASK ((mipc_external_time_delta_valid_flags_t)0x1u)
#define MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_DT_NANOS_SHIFT 0
/** bits 1-15: (reserved) Not listed. */
#define MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_RESERVED_MASK ((mipc_external_time_delta_valid_flags_t)0xFFFEu)
#define MIPC_EXTERNAL_TIME_DELTA_VALID_FLAGS_RESERVED_SHIFT 1

/** External timestamp valid flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_external_timestamp_valid_flags_t;
/** bit 0: The nanoseconds value is valid (external clock synchronised via PPS). */
#define MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_NANOSECONDS_MASK ((mipc_external_timestamp_valid_flags_t)0x1u)
#define MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_NANOSECONDS_SHIFT 0
/** bits 1-15: (reserved) Not listed. */
#define MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_RESERVED_MASK ((mipc_external_timestamp_valid_flags_t)0xFFFEu)
#define MIPC_EXTERNAL_TIMESTAMP_VALID_FLAGS_RESERVED_SHIFT 1

/** Factory streaming action.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_factory_streaming_action_t;
/** Replace the message formats, dropping the descriptors already there. */
#define MIPC_FACTORY_STREAMING_ACTION_OVERWRITE ((mipc_factory_streaming_action_t)0u)
/** Merge the support descriptors into the existing formats (order may change). */
#define MIPC_FACTORY_STREAMING_ACTION_MERGE ((mipc_factory_streaming_action_t)1u)
/** Append the support descriptors to the existing formats (duplicates possible). */
#define MIPC_FACTORY_STREAMING_ACTION_ADD ((mipc_factory_streaming_action_t)2u)

/** Aiding measurement indicator. State of one aiding measurement over the last measurement interval.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_filter_aiding_measurement_indicator_t;
/** bit 0: The measurement is enabled. */
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_ENABLED_MASK                                                \
    ((mipc_filter_aiding_measurement_indicator_t)0x1u)
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_ENABLED_SHIFT 0
/** bit 1: The measurement was used by the filter. */
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_USED_MASK ((mipc_filter_aiding_measurement_indicator_t)0x2u)
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_USED_SHIFT 1
/** bit 2: Measurement residual is high. */
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_RESIDUAL_HIGH_WARNING_MASK                                  \
    ((mipc_filter_aiding_measurement_indicator_t)0x4u)
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_RESIDUAL_HIGH_WARNING_SHIFT 2
/** bit 3: Problem with the measurement's sample time. */
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_SAMPLE_TIME_WARNING_MASK                                    \
    ((mipc_filter_aiding_measurement_indicator_t)0x8u)
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_SAMPLE_TIME_WARNING_SHIFT 3
/** bit 4: The measurement is misconfigured. */
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_CONFIGURATION_ERROR_MASK                                    \
    ((mipc_filter_aiding_measurement_indicator_t)0x10u)
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_CONFIGURATION_ERROR_SHIFT 4
/** bit 5: More measurements than the filter can process. */
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_MAX_NUM_MEAS_EXCEEDED_MASK                                  \
    ((mipc_filter_aiding_measurement_indicator_t)0x20u)
#define MIPC_FILTER_AIDING_MEASUREMENT_INDICATOR_MAX_NUM_MEAS_EXCEEDED_SHIFT 5

/** Aiding measurement type. Which aiding measurement an Aiding Measurement Summary (0x82,0x46) describes.
 * Values 0x20 and above are the measurements commanded through the Aiding command set (0x13); their value is
 * the descriptor of that command. An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_filter_aiding_measurement_type_t;
/** GNSS receiver measurement. */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_GNSS ((mipc_filter_aiding_measurement_type_t)1u)
/** GNSS dual-antenna heading. */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_DUAL_ANTENNA ((mipc_filter_aiding_measurement_type_t)2u)
/** Heading measurement. */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_HEADING ((mipc_filter_aiding_measurement_type_t)3u)
/** Pressure (barometric altitude). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_PRESSURE ((mipc_filter_aiding_measurement_type_t)4u)
/** Magnetometer. */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_MAGNETOMETER ((mipc_filter_aiding_measurement_type_t)5u)
/** Speed sensor (odometer). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_SPEED ((mipc_filter_aiding_measurement_type_t)6u)
/** ECEF position aiding command (0x13,0x21). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_POS_ECEF ((mipc_filter_aiding_measurement_type_t)33u)
/** LLH position aiding command (0x13,0x22). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_POS_LLH ((mipc_filter_aiding_measurement_type_t)34u)
/** Height above ellipsoid aiding command (0x13,0x23). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_HEIGHT_ABOVE_ELLIPSOID                                    \
    ((mipc_filter_aiding_measurement_type_t)35u)
/** ECEF velocity aiding command (0x13,0x28). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_VEL_ECEF ((mipc_filter_aiding_measurement_type_t)40u)
/** NED velocity aiding command (0x13,0x29). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_VEL_NED ((mipc_filter_aiding_measurement_type_t)41u)
/** Body-frame velocity aiding command (0x13,0x2A). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_VEL_BODY_FRAME ((mipc_filter_aiding_measurement_type_t)42u)
/** True heading aiding command (0x13,0x31). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_HEADING_TRUE ((mipc_filter_aiding_measurement_type_t)49u)
/** Magnetic field aiding command (0x13,0x32). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_MAGNETIC_FIELD ((mipc_filter_aiding_measurement_type_t)50u)
/** Pressure aiding command (0x13,0x33). */
#define MIPC_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_PRESSURE ((mipc_filter_aiding_measurement_type_t)51u)

/** Dual-antenna fix type. Kind of GNSS dual-antenna heading solution.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_filter_dual_antenna_fix_type_t;
/** No dual-antenna fix. */
#define MIPC_FILTER_DUAL_ANTENNA_FIX_TYPE_FIX_NONE ((mipc_filter_dual_antenna_fix_type_t)0u)
/** Dual-antenna float solution. */
#define MIPC_FILTER_DUAL_ANTENNA_FIX_TYPE_FIX_DA_FLOAT ((mipc_filter_dual_antenna_fix_type_t)1u)
/** Dual-antenna fixed (integer) solution. */
#define MIPC_FILTER_DUAL_ANTENNA_FIX_TYPE_FIX_DA_FIXED ((mipc_filter_dual_antenna_fix_type_t)2u)

/** Dual-antenna status flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_filter_dual_antenna_status_flags_t;
/** bit 0: Data from receiver 1 are valid. */
#define MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_1_DATA_VALID_MASK                                          \
    ((mipc_filter_dual_antenna_status_flags_t)0x1u)
#define MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_1_DATA_VALID_SHIFT 0
/** bit 1: Data from receiver 2 are valid. */
#define MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_2_DATA_VALID_MASK                                          \
    ((mipc_filter_dual_antenna_status_flags_t)0x2u)
#define MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_2_DATA_VALID_SHIFT 1
/** bit 2: The antenna offsets are valid. */
#define MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_ANTENNA_OFFSETS_VALID_MASK                                     \
    ((mipc_filter_dual_antenna_status_flags_t)0x4u)
#define MIPC_FILTER_DUAL_ANTENNA_STATUS_FLAGS_ANTENNA_OFFSETS_VALID_SHIFT 2

/** Filter dynamics mode (3DM-CV7). Dynamics mode reported in Status (0x82,0x10) by the CV7 (GQ7-family
 * filter). An integer, so that values the spec does not list are kept. */
typedef uint16_t mipc_filter_dynamics_mode_cv7_t;
/** Default dynamics mode (printed GQ7_DEFAULT). */
#define MIPC_FILTER_DYNAMICS_MODE_CV7_DEFAULT ((mipc_filter_dynamics_mode_cv7_t)1u)

/** Filter dynamics mode (3DM-GX5-45). Vehicle dynamics mode the GX5-45 filter runs with, as reported in
 * Filter Status (0x82,0x10). An integer, so that values the spec does not list are kept. */
typedef uint16_t mipc_filter_dynamics_mode_gx5_t;
/** Portable (low-acceleration applications). */
#define MIPC_FILTER_DYNAMICS_MODE_GX5_PORTABLE ((mipc_filter_dynamics_mode_gx5_t)1u)
/** Automotive (wheeled vehicles, low vertical acceleration). */
#define MIPC_FILTER_DYNAMICS_MODE_GX5_AUTOMOTIVE ((mipc_filter_dynamics_mode_gx5_t)2u)
/** Airborne (up to 2 g). */
#define MIPC_FILTER_DYNAMICS_MODE_GX5_AIRBORNE ((mipc_filter_dynamics_mode_gx5_t)3u)

/** GNSS position aiding status. What the filter does with the measurements of one GNSS receiver.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_filter_gnss_aiding_status_flags_t;
/** bit 0: The filter is processing raw range information from this receiver. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_TIGHT_COUPLING_MASK                                             \
    ((mipc_filter_gnss_aiding_status_flags_t)0x1u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_TIGHT_COUPLING_SHIFT 0
/** bit 1: The filter is processing RTK corrections from this receiver. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_DIFFERENTIAL_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x2u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_DIFFERENTIAL_SHIFT 1
/** bit 2: The filter has an RTK integer fix from this receiver. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_INTEGER_FIX_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x4u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_INTEGER_FIX_SHIFT 2
/** bit 3: GPS L1 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L1_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x8u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L1_SHIFT 3
/** bit 4: GPS L2 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L2_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x10u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L2_SHIFT 4
/** bit 5: GPS L5 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L5_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x20u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L5_SHIFT 5
/** bit 6: GLONASS L1 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L1_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x40u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L1_SHIFT 6
/** bit 7: GLONASS L2 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L2_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x80u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L2_SHIFT 7
/** bit 8: Galileo E1 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E1_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x100u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E1_SHIFT 8
/** bit 9: Galileo E5 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E5_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x200u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E5_SHIFT 9
/** bit 10: Galileo E6 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E6_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x400u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E6_SHIFT 10
/** bit 11: BeiDou B1 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B1_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x800u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B1_SHIFT 11
/** bit 12: BeiDou B2 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B2_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x1000u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B2_SHIFT 12
/** bit 13: BeiDou B3 measurements used. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B3_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x2000u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B3_SHIFT 13
/** bit 14: This receiver reports no position fix. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_NO_FIX_MASK ((mipc_filter_gnss_aiding_status_flags_t)0x4000u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_NO_FIX_SHIFT 14
/** bit 15: Probably a problem with this receiver's antenna offset. */
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_CONFIG_ERROR_MASK                                               \
    ((mipc_filter_gnss_aiding_status_flags_t)0x8000u)
#define MIPC_FILTER_GNSS_AIDING_STATUS_FLAGS_CONFIG_ERROR_SHIFT 15

/** Filter GNSS source. Where the filter takes its GNSS position and velocity updates from.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_filter_gnss_source_t;
/** The internal GNSS receiver(s) (GX5-45: Internal GNSS; CV7: ALL_INT, all internal receivers). */
#define MIPC_FILTER_GNSS_SOURCE_ALL_INTERNAL ((mipc_filter_gnss_source_t)1u)
/** External GNSS messages supplied by the user (GX5-45: External GNSS Update 0x0D,0x16). */
#define MIPC_FILTER_GNSS_SOURCE_EXTERNAL ((mipc_filter_gnss_source_t)2u)
/** Internal GNSS receiver 1 only. (devices: cv7_ins) */
#define MIPC_FILTER_GNSS_SOURCE_INTERNAL_1 ((mipc_filter_gnss_source_t)3u)
/** Internal GNSS receiver 2 only. (devices: cv7_ins) */
#define MIPC_FILTER_GNSS_SOURCE_INTERNAL_2 ((mipc_filter_gnss_source_t)4u)

/** Heading update sources in use. Sources currently providing heading updates; 0 means none (heading updates
 * disabled). The whole integer is kept (reserved bits too); members are read with the masks below: (value &
 * X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_filter_heading_source_flags_t;
/** bit 0: Internal magnetometer. */
#define MIPC_FILTER_HEADING_SOURCE_FLAGS_MAGNETOMETER_MASK ((mipc_filter_heading_source_flags_t)0x1u)
#define MIPC_FILTER_HEADING_SOURCE_FLAGS_MAGNETOMETER_SHIFT 0
/** bit 1: GNSS velocity vector. */
#define MIPC_FILTER_HEADING_SOURCE_FLAGS_GNSS_VELOCITY_MASK ((mipc_filter_heading_source_flags_t)0x2u)
#define MIPC_FILTER_HEADING_SOURCE_FLAGS_GNSS_VELOCITY_SHIFT 1
/** bit 2: External Heading Update messages (0x0D,0x17), with or without timestamp (0x0D,0x1F). */
#define MIPC_FILTER_HEADING_SOURCE_FLAGS_EXTERNAL_MASK ((mipc_filter_heading_source_flags_t)0x4u)
#define MIPC_FILTER_HEADING_SOURCE_FLAGS_EXTERNAL_SHIFT 2

/** Heading update state valid flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_filter_heading_update_valid_flags_t;
/** bit 0: The heading update source provided data within the last 2 seconds (0: no update for 2 seconds). */
#define MIPC_FILTER_HEADING_UPDATE_VALID_FLAGS_UPDATED_WITHIN_2S_MASK                                        \
    ((mipc_filter_heading_update_valid_flags_t)0x1u)
#define MIPC_FILTER_HEADING_UPDATE_VALID_FLAGS_UPDATED_WITHIN_2S_SHIFT 0

/** Navigation filter initial condition source.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_filter_initial_condition_source_t;
/** Automatic position, velocity and attitude. */
#define MIPC_FILTER_INITIAL_CONDITION_SOURCE_AUTO_POS_VEL_ATT ((mipc_filter_initial_condition_source_t)0u)
/** Automatic position, velocity, pitch and roll; heading as specified. */
#define MIPC_FILTER_INITIAL_CONDITION_SOURCE_AUTO_POS_VEL_PITCH_ROLL                                         \
    ((mipc_filter_initial_condition_source_t)1u)
/** Automatic position and velocity; attitude fully user-specified. */
#define MIPC_FILTER_INITIAL_CONDITION_SOURCE_AUTO_POS_VEL ((mipc_filter_initial_condition_source_t)2u)
/** User-specified position, velocity and attitude. */
#define MIPC_FILTER_INITIAL_CONDITION_SOURCE_MANUAL ((mipc_filter_initial_condition_source_t)3u)

/** Filter mode (3DM-CV7). Mode the CV7 navigation filter has reached, reported as the filter state in Status
 * (0x82,0x10); it depends on the initial conditions the filter was given. An integer, so that values the spec
 * does not list are kept. */
typedef uint16_t mipc_filter_mode_cv7_t;
/** Initialization: initial conditions incomplete or invalid, or waiting for user input. */
#define MIPC_FILTER_MODE_CV7_INIT ((mipc_filter_mode_cv7_t)1u)
/** Vertical gyro: valid pitch and roll, heading relative to the initial heading. */
#define MIPC_FILTER_MODE_CV7_VERT_GYRO ((mipc_filter_mode_cv7_t)2u)
/** AHRS: as vertical gyro, with an absolute heading reference. */
#define MIPC_FILTER_MODE_CV7_AHRS ((mipc_filter_mode_cv7_t)3u)
/** Full navigation: valid position, velocity, pitch, roll and heading. */
#define MIPC_FILTER_MODE_CV7_FULL_NAV ((mipc_filter_mode_cv7_t)4u)

/** Filter output valid flags. Valid flags of a filter output field: 0x0000 the values are invalid, 0x0001
 * they are valid. The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_filter_output_valid_flags_t;
/** bit 0: The values of this field are valid. */
#define MIPC_FILTER_OUTPUT_VALID_FLAGS_VALID_MASK ((mipc_filter_output_valid_flags_t)0x1u)
#define MIPC_FILTER_OUTPUT_VALID_FLAGS_VALID_SHIFT 0

/** Reference frame of user-specified positions and velocities.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_filter_reference_frame_t;
/** WGS84 Earth-centered, Earth-fixed coordinates. */
#define MIPC_FILTER_REFERENCE_FRAME_ECEF ((mipc_filter_reference_frame_t)1u)
/** WGS84 latitude, longitude and height above ellipsoid. */
#define MIPC_FILTER_REFERENCE_FRAME_LLH ((mipc_filter_reference_frame_t)2u)

/** Filter state (3DM-GX5-45). Operating state of the GX5-45 estimation filter, reported in Filter Status
 * (0x82,0x10). An integer, so that values the spec does not list are kept. */
typedef uint16_t mipc_filter_state_gx5_t;
/** Filter starting up. */
#define MIPC_FILTER_STATE_GX5_STARTUP ((mipc_filter_state_gx5_t)0u)
/** Initializing; the status flags tell what is still missing. */
#define MIPC_FILTER_STATE_GX5_INIT ((mipc_filter_state_gx5_t)1u)
/** Running, the solution is valid. */
#define MIPC_FILTER_STATE_GX5_RUN_SOLUTION_VALID ((mipc_filter_state_gx5_t)2u)
/** Running, the solution has an error; the status flags tell which. */
#define MIPC_FILTER_STATE_GX5_RUN_SOLUTION_ERROR ((mipc_filter_state_gx5_t)3u)

/** Filter status flags (3DM-CV7). CV7 (GQ7-family) filter status flags: the filter condition in bits 0-1 (1
 * stable, 2 converging, 3 unstable/recovering), estimate warnings in bits 2-10 and solution error flags in
 * bits 12-15. The whole integer is kept (reserved bits too); members are read with the masks below: (value &
 * X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_filter_status_flags_cv7_t;
/** bits 0-1: Filter condition: 1 stable, 2 converging, 3 unstable/recovering. */
#define MIPC_FILTER_STATUS_FLAGS_CV7_FILTER_CONDITION_MASK ((mipc_filter_status_flags_cv7_t)0x3u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_FILTER_CONDITION_SHIFT 0
/** bit 2: Low confidence in roll/pitch (e.g. sensor not aligned with the vehicle frame). */
#define MIPC_FILTER_STATUS_FLAGS_CV7_ROLL_PITCH_WARNING_MASK ((mipc_filter_status_flags_cv7_t)0x4u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_ROLL_PITCH_WARNING_SHIFT 2
/** bit 3: Low confidence in heading (heading source not valid). */
#define MIPC_FILTER_STATUS_FLAGS_CV7_HEADING_WARNING_MASK ((mipc_filter_status_flags_cv7_t)0x8u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_HEADING_WARNING_SHIFT 3
/** bit 4: Low confidence in position. */
#define MIPC_FILTER_STATUS_FLAGS_CV7_POSITION_WARNING_MASK ((mipc_filter_status_flags_cv7_t)0x10u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_POSITION_WARNING_SHIFT 4
/** bit 5: Low confidence in velocity. */
#define MIPC_FILTER_STATUS_FLAGS_CV7_VELOCITY_WARNING_MASK ((mipc_filter_status_flags_cv7_t)0x20u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_VELOCITY_WARNING_SHIFT 5
/** bit 6: IMU bias estimate warning (gyro bias high). */
#define MIPC_FILTER_STATUS_FLAGS_CV7_IMU_BIAS_WARNING_MASK ((mipc_filter_status_flags_cv7_t)0x40u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_IMU_BIAS_WARNING_SHIFT 6
/** bit 7: GNSS clock warning (affects the filter timestamp). */
#define MIPC_FILTER_STATUS_FLAGS_CV7_GNSS_CLK_WARNING_MASK ((mipc_filter_status_flags_cv7_t)0x80u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_GNSS_CLK_WARNING_SHIFT 7
/** bit 8: Antenna lever arm offsets are likely incorrect. */
#define MIPC_FILTER_STATUS_FLAGS_CV7_ANTENNA_LEVER_ARM_WARNING_MASK ((mipc_filter_status_flags_cv7_t)0x100u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_ANTENNA_LEVER_ARM_WARNING_SHIFT 8
/** bit 9: Mounting transform is likely incorrect. */
#define MIPC_FILTER_STATUS_FLAGS_CV7_MOUNTING_TRANSFORM_WARNING_MASK ((mipc_filter_status_flags_cv7_t)0x200u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_MOUNTING_TRANSFORM_WARNING_SHIFT 9
/** bit 10: No time synchronization (PPS) pulse detected, or external heading timestamp too old. */
#define MIPC_FILTER_STATUS_FLAGS_CV7_TIME_SYNC_WARNING_MASK ((mipc_filter_status_flags_cv7_t)0x400u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_TIME_SYNC_WARNING_SHIFT 10
/** bit 11: (reserved) Not listed. */
#define MIPC_FILTER_STATUS_FLAGS_CV7_RESERVED_MASK ((mipc_filter_status_flags_cv7_t)0x800u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_RESERVED_SHIFT 11
/** bits 12-15: Filter computation error flags (NaN in the solution); if any is set, all filter outputs are
 * invalid. */
#define MIPC_FILTER_STATUS_FLAGS_CV7_SOLUTION_ERROR_MASK ((mipc_filter_status_flags_cv7_t)0xF000u)
#define MIPC_FILTER_STATUS_FLAGS_CV7_SOLUTION_ERROR_SHIFT 12

/** Filter status flags (3DM-GX5-45). GX5-45 filter status flags. Bits 12 and 13 mean different things
 * depending on the filter state: in the initialization state they say what is not initialized, while running
 * they are estimate warnings. The whole integer is kept (reserved bits too); members are read with the masks
 * below: (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_filter_status_flags_gx5_t;
/** bit 0: Running: IMU unavailable. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_IMU_UNAVAILABLE_MASK ((mipc_filter_status_flags_gx5_t)0x1u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_IMU_UNAVAILABLE_SHIFT 0
/** bit 1: Running: GNSS unavailable. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GPS_UNAVAILABLE_MASK ((mipc_filter_status_flags_gx5_t)0x2u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GPS_UNAVAILABLE_SHIFT 1
/** bit 2: (reserved) Not listed (0x0004). */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RESERVED_MASK ((mipc_filter_status_flags_gx5_t)0x4u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RESERVED_SHIFT 2
/** bit 3: Running: matrix singularity in the calculation. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MATRIX_SINGULARITY_MASK ((mipc_filter_status_flags_gx5_t)0x8u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MATRIX_SINGULARITY_SHIFT 3
/** bit 4: Running: position covariance high (some axis beyond normal limits). */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_POSITION_COVARIANCE_WARNING_MASK                                    \
    ((mipc_filter_status_flags_gx5_t)0x10u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_POSITION_COVARIANCE_WARNING_SHIFT 4
/** bit 5: Running: velocity covariance high (some axis beyond normal limits). */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_VELOCITY_COVARIANCE_WARNING_MASK                                    \
    ((mipc_filter_status_flags_gx5_t)0x20u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_VELOCITY_COVARIANCE_WARNING_SHIFT 5
/** bit 6: Running: attitude covariance high (some axis beyond normal limits). */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ATTITUDE_COVARIANCE_WARNING_MASK                                    \
    ((mipc_filter_status_flags_gx5_t)0x40u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ATTITUDE_COVARIANCE_WARNING_SHIFT 6
/** bit 7: Running: NaN in the solution. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_NAN_IN_SOLUTION_WARNING_MASK ((mipc_filter_status_flags_gx5_t)0x80u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_NAN_IN_SOLUTION_WARNING_SHIFT 7
/** bit 8: Running: gyro bias estimate high. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_BIAS_EST_HIGH_WARNING_MASK                                     \
    ((mipc_filter_status_flags_gx5_t)0x100u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_BIAS_EST_HIGH_WARNING_SHIFT 8
/** bit 9: Running: accel bias estimate high. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_BIAS_EST_HIGH_WARNING_MASK                                    \
    ((mipc_filter_status_flags_gx5_t)0x200u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_BIAS_EST_HIGH_WARNING_SHIFT 9
/** bit 10: Running: gyro scale factor estimate high. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING_MASK                             \
    ((mipc_filter_status_flags_gx5_t)0x400u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING_SHIFT 10
/** bit 11: Running: accel scale factor estimate high. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING_MASK                            \
    ((mipc_filter_status_flags_gx5_t)0x800u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING_SHIFT 11
/** bit 12: Running: magnetometer bias estimate high. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_BIAS_EST_HIGH_WARNING_MASK                                      \
    ((mipc_filter_status_flags_gx5_t)0x1000u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_BIAS_EST_HIGH_WARNING_SHIFT 12
/** bit 13: Running: GNSS antenna offset correction estimate high. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING_MASK                         \
    ((mipc_filter_status_flags_gx5_t)0x2000u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING_SHIFT 13
/** bit 14: Running: hard iron offset estimate high. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_HARD_IRON_EST_HIGH_WARNING_MASK                                 \
    ((mipc_filter_status_flags_gx5_t)0x4000u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_HARD_IRON_EST_HIGH_WARNING_SHIFT 14
/** bit 15: Running: soft iron correction estimate high. */
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_SOFT_IRON_EST_HIGH_WARNING_MASK                                 \
    ((mipc_filter_status_flags_gx5_t)0x8000u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_RUN_MAG_SOFT_IRON_EST_HIGH_WARNING_SHIFT 15
/** bit 12: Initialization: attitude not initialized (same bit as run_mag_bias_est_high_warning). */
#define MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_ATTITUDE_MASK ((mipc_filter_status_flags_gx5_t)0x1000u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_ATTITUDE_SHIFT 12
/** bit 13: Initialization: position and velocity not initialized (same bit as
 * run_ant_offset_correction_est_high_warning). */
#define MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_POSITION_VELOCITY_MASK ((mipc_filter_status_flags_gx5_t)0x2000u)
#define MIPC_FILTER_STATUS_FLAGS_GX5_INIT_NO_POSITION_VELOCITY_SHIFT 13

/** Function selector. First parameter of settings commands; chooses what the command does. Only a read
 * returns a response field (with the ack); parameters not needed for a function may be left out, or sent as
 * placeholders. An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_function_selector_t;
/** Apply new setting. */
#define MIPC_FUNCTION_SELECTOR_WRITE ((mipc_function_selector_t)1u)
/** Read back the current setting (the only function that returns response data). */
#define MIPC_FUNCTION_SELECTOR_READ ((mipc_function_selector_t)2u)
/** Save the current setting to non-volatile memory as the startup setting. */
#define MIPC_FUNCTION_SELECTOR_SAVE ((mipc_function_selector_t)3u)
/** Load the saved startup setting from non-volatile memory. */
#define MIPC_FUNCTION_SELECTOR_LOAD ((mipc_function_selector_t)4u)
/** Reset to the factory default. */
#define MIPC_FUNCTION_SELECTOR_DEFAULT ((mipc_function_selector_t)5u)
/** Apply new setting with no ACK/NACK reply (GX5-45 only). (devices: gx5_45) */
#define MIPC_FUNCTION_SELECTOR_WRITE_NO_ACK ((mipc_function_selector_t)6u)

/** GNSS antenna power. Whether the receiver powers the antenna.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gnss_antenna_power_t;
/** Antenna power off. */
#define MIPC_GNSS_ANTENNA_POWER_OFF ((mipc_gnss_antenna_power_t)0u)
/** Antenna power on. */
#define MIPC_GNSS_ANTENNA_POWER_ON ((mipc_gnss_antenna_power_t)1u)
/** Power state unknown. */
#define MIPC_GNSS_ANTENNA_POWER_UNKNOWN ((mipc_gnss_antenna_power_t)2u)

/** GNSS antenna state. State of the GNSS antenna connection. There is no value 0.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gnss_antenna_state_t;
/** Antenna initialising. */
#define MIPC_GNSS_ANTENNA_STATE_INIT ((mipc_gnss_antenna_state_t)1u)
/** Antenna short circuit. */
#define MIPC_GNSS_ANTENNA_STATE_SHORT ((mipc_gnss_antenna_state_t)2u)
/** Antenna open circuit (not connected). */
#define MIPC_GNSS_ANTENNA_STATE_OPEN ((mipc_gnss_antenna_state_t)3u)
/** Antenna good. */
#define MIPC_GNSS_ANTENNA_STATE_GOOD ((mipc_gnss_antenna_state_t)4u)
/** State unknown. */
#define MIPC_GNSS_ANTENNA_STATE_UNKNOWN ((mipc_gnss_antenna_state_t)5u)

/** Base station indicators. Indicator bits of the base station, as reported in RTCM message 1005/1006.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_base_station_indicators_t;
/** bit 0: GPS indicator. */
#define MIPC_GNSS_BASE_STATION_INDICATORS_GPS_MASK ((mipc_gnss_base_station_indicators_t)0x1u)
#define MIPC_GNSS_BASE_STATION_INDICATORS_GPS_SHIFT 0
/** bit 1: GLONASS indicator. */
#define MIPC_GNSS_BASE_STATION_INDICATORS_GLONASS_MASK ((mipc_gnss_base_station_indicators_t)0x2u)
#define MIPC_GNSS_BASE_STATION_INDICATORS_GLONASS_SHIFT 1
/** bit 2: Galileo indicator. */
#define MIPC_GNSS_BASE_STATION_INDICATORS_GALILEO_MASK ((mipc_gnss_base_station_indicators_t)0x4u)
#define MIPC_GNSS_BASE_STATION_INDICATORS_GALILEO_SHIFT 2
/** bit 3: BeiDou indicator. */
#define MIPC_GNSS_BASE_STATION_INDICATORS_BEIDOU_MASK ((mipc_gnss_base_station_indicators_t)0x8u)
#define MIPC_GNSS_BASE_STATION_INDICATORS_BEIDOU_SHIFT 3
/** bit 4: Reference station indicator. */
#define MIPC_GNSS_BASE_STATION_INDICATORS_REF_STATION_MASK ((mipc_gnss_base_station_indicators_t)0x10u)
#define MIPC_GNSS_BASE_STATION_INDICATORS_REF_STATION_SHIFT 4
/** bit 5: Single receiver oscillator indicator. */
#define MIPC_GNSS_BASE_STATION_INDICATORS_SINGLE_RECEIVER_MASK ((mipc_gnss_base_station_indicators_t)0x20u)
#define MIPC_GNSS_BASE_STATION_INDICATORS_SINGLE_RECEIVER_SHIFT 5
/** bit 6: Quarter cycle indicator, first bit. */
#define MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT1_MASK ((mipc_gnss_base_station_indicators_t)0x40u)
#define MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT1_SHIFT 6
/** bit 7: Quarter cycle indicator, second bit. */
#define MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT2_MASK ((mipc_gnss_base_station_indicators_t)0x80u)
#define MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BIT2_SHIFT 7
/** bits 6-7: Quarter cycle indicator (both bits). */
#define MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BITS_MASK ((mipc_gnss_base_station_indicators_t)0xC0u)
#define MIPC_GNSS_BASE_STATION_INDICATORS_QUARTER_CYCLE_BITS_SHIFT 6
/** bits 8-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_BASE_STATION_INDICATORS_RESERVED_MASK ((mipc_gnss_base_station_indicators_t)0xFF00u)
#define MIPC_GNSS_BASE_STATION_INDICATORS_RESERVED_SHIFT 8

/** Base station information valid flags. Which parameters of the base station information field are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_base_station_info_valid_flags_t;
/** bit 0: Time of week valid. */
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_TOW_MASK ((mipc_gnss_base_station_info_valid_flags_t)0x1u)
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_TOW_SHIFT 0
/** bit 1: Week number valid. */
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_WEEK_NUMBER_MASK                                             \
    ((mipc_gnss_base_station_info_valid_flags_t)0x2u)
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_WEEK_NUMBER_SHIFT 1
/** bit 2: ECEF position valid. */
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_ECEF_POSITION_MASK                                           \
    ((mipc_gnss_base_station_info_valid_flags_t)0x4u)
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_ECEF_POSITION_SHIFT 2
/** bit 3: Antenna height valid. */
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_HEIGHT_MASK ((mipc_gnss_base_station_info_valid_flags_t)0x8u)
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_HEIGHT_SHIFT 3
/** bit 4: Station id valid. */
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_STATION_ID_MASK                                              \
    ((mipc_gnss_base_station_info_valid_flags_t)0x10u)
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_STATION_ID_SHIFT 4
/** bit 5: Indicators valid. */
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_INDICATORS_MASK                                              \
    ((mipc_gnss_base_station_info_valid_flags_t)0x20u)
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_INDICATORS_SHIFT 5
/** bits 0-5: All flags. */
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_base_station_info_valid_flags_t)0x3Fu)
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 6-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_RESERVED_MASK                                                \
    ((mipc_gnss_base_station_info_valid_flags_t)0xFFC0u)
#define MIPC_GNSS_BASE_STATION_INFO_VALID_FLAGS_RESERVED_SHIFT 6

/** BeiDou signals enabled.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_gnss_beidou_signals_t;
/** bit 0: Enable B1. */
#define MIPC_GNSS_BEIDOU_SIGNALS_B1_MASK ((mipc_gnss_beidou_signals_t)0x1u)
#define MIPC_GNSS_BEIDOU_SIGNALS_B1_SHIFT 0
/** bit 1: Enable B2. */
#define MIPC_GNSS_BEIDOU_SIGNALS_B2_MASK ((mipc_gnss_beidou_signals_t)0x2u)
#define MIPC_GNSS_BEIDOU_SIGNALS_B2_SHIFT 1
/** bit 2: Enable B2A. */
#define MIPC_GNSS_BEIDOU_SIGNALS_B2A_MASK ((mipc_gnss_beidou_signals_t)0x4u)
#define MIPC_GNSS_BEIDOU_SIGNALS_B2A_SHIFT 2

/** GNSS clock information 2 valid flags. Which receiver clock parameters are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_clock_info2_valid_flags_t;
/** bit 0: Clock bias valid. */
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_MASK ((mipc_gnss_clock_info2_valid_flags_t)0x1u)
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_SHIFT 0
/** bit 1: Clock drift valid. */
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_MASK ((mipc_gnss_clock_info2_valid_flags_t)0x2u)
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_SHIFT 1
/** bit 2: Bias accuracy estimate valid. */
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_ACCURACY_MASK ((mipc_gnss_clock_info2_valid_flags_t)0x4u)
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_BIAS_ACCURACY_SHIFT 2
/** bit 3: Drift accuracy estimate valid. */
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_ACCURACY_MASK ((mipc_gnss_clock_info2_valid_flags_t)0x8u)
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_DRIFT_ACCURACY_SHIFT 3
/** bits 0-3: All flags. */
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_clock_info2_valid_flags_t)0xFu)
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 4-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_clock_info2_valid_flags_t)0xFFF0u)
#define MIPC_GNSS_CLOCK_INFO2_VALID_FLAGS_RESERVED_SHIFT 4

/** GNSS clock information valid flags. Which clock parameters are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_clock_info_valid_flags_t;
/** bit 0: Clock bias valid. */
#define MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_BIAS_MASK ((mipc_gnss_clock_info_valid_flags_t)0x1u)
#define MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_BIAS_SHIFT 0
/** bit 1: Clock drift valid. */
#define MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_DRIFT_MASK ((mipc_gnss_clock_info_valid_flags_t)0x2u)
#define MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_DRIFT_SHIFT 1
/** bit 2: Accuracy estimate valid. */
#define MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_ACCURACY_ESTIMATE_MASK ((mipc_gnss_clock_info_valid_flags_t)0x4u)
#define MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_ACCURACY_ESTIMATE_SHIFT 2
/** bits 3-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_clock_info_valid_flags_t)0xFFF8u)
#define MIPC_GNSS_CLOCK_INFO_VALID_FLAGS_RESERVED_SHIFT 3

/** GNSS constellation (CV7 GNSS data).
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gnss_constellation_id_t;
/** Constellation unknown or not given. */
#define MIPC_GNSS_CONSTELLATION_ID_UNKNOWN ((mipc_gnss_constellation_id_t)0u)
/** GPS. */
#define MIPC_GNSS_CONSTELLATION_ID_GPS ((mipc_gnss_constellation_id_t)1u)
/** GLONASS. */
#define MIPC_GNSS_CONSTELLATION_ID_GLONASS ((mipc_gnss_constellation_id_t)2u)
/** Galileo. */
#define MIPC_GNSS_CONSTELLATION_ID_GALILEO ((mipc_gnss_constellation_id_t)3u)
/** BeiDou. */
#define MIPC_GNSS_CONSTELLATION_ID_BEIDOU ((mipc_gnss_constellation_id_t)4u)
/** SBAS. */
#define MIPC_GNSS_CONSTELLATION_ID_SBAS ((mipc_gnss_constellation_id_t)5u)

/** DGNSS base station status. Health of the DGNSS reference station as its UDRE (user differential range
 * error) scale factor. An integer, so that values the spec does not list are kept. */
typedef int16_t mipc_gnss_dgnss_base_station_status_t;
/** UDRE scale factor 1.0. */
#define MIPC_GNSS_DGNSS_BASE_STATION_STATUS_UDRE_SCALE_1_0 ((mipc_gnss_dgnss_base_station_status_t)0)
/** UDRE scale factor 0.75. */
#define MIPC_GNSS_DGNSS_BASE_STATION_STATUS_UDRE_SCALE_0_75 ((mipc_gnss_dgnss_base_station_status_t)1)
/** UDRE scale factor 0.5. */
#define MIPC_GNSS_DGNSS_BASE_STATION_STATUS_UDRE_SCALE_0_5 ((mipc_gnss_dgnss_base_station_status_t)2)
/** UDRE scale factor 0.3. */
#define MIPC_GNSS_DGNSS_BASE_STATION_STATUS_UDRE_SCALE_0_3 ((mipc_gnss_dgnss_base_station_status_t)3)
/** UDRE scale factor 0.2. */
#define MIPC_GNSS_DGNSS_BASE_STATION_STATUS_UDRE_SCALE_0_2 ((mipc_gnss_dgnss_base_station_status_t)4)
/** UDRE scale factor 0.1. */
#define MIPC_GNSS_DGNSS_BASE_STATION_STATUS_UDRE_SCALE_0_1 ((mipc_gnss_dgnss_base_station_status_t)5)
/** Reference station transmission not monitored. */
#define MIPC_GNSS_DGNSS_BASE_STATION_STATUS_TRANSMISSION_NOT_MONITORED                                       \
    ((mipc_gnss_dgnss_base_station_status_t)6)
/** Reference station not working. */
#define MIPC_GNSS_DGNSS_BASE_STATION_STATUS_STATION_NOT_WORKING ((mipc_gnss_dgnss_base_station_status_t)7)

/** DGNSS channel status valid flags. Which parameters of a DGNSS channel status entry are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_dgnss_channel_status_valid_flags_t;
/** bit 0: Space vehicle id valid. */
#define MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_SV_ID_MASK                                                \
    ((mipc_gnss_dgnss_channel_status_valid_flags_t)0x1u)
#define MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_SV_ID_SHIFT 0
/** bit 1: Correction age valid. */
#define MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_AGE_MASK                                                  \
    ((mipc_gnss_dgnss_channel_status_valid_flags_t)0x2u)
#define MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_AGE_SHIFT 1
/** bit 2: Pseudorange correction valid. */
#define MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_CORRECTION_MASK                               \
    ((mipc_gnss_dgnss_channel_status_valid_flags_t)0x4u)
#define MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_CORRECTION_SHIFT 2
/** bit 3: Pseudorange rate correction valid. */
#define MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_RATE_CORRECTION_MASK                          \
    ((mipc_gnss_dgnss_channel_status_valid_flags_t)0x8u)
#define MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_PSEUDORANGE_RATE_CORRECTION_SHIFT 3
/** bits 4-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_RESERVED_MASK                                             \
    ((mipc_gnss_dgnss_channel_status_valid_flags_t)0xFFF0u)
#define MIPC_GNSS_DGNSS_CHANNEL_STATUS_VALID_FLAGS_RESERVED_SHIFT 4

/** DGNSS information valid flags. Which parameters of the DGNSS information field are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_dgnss_info_valid_flags_t;
/** bit 0: Newest (latest) correction age valid. */
#define MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_LATEST_AGE_MASK ((mipc_gnss_dgnss_info_valid_flags_t)0x1u)
#define MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_LATEST_AGE_SHIFT 0
/** bit 1: Base station id valid. */
#define MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_ID_MASK ((mipc_gnss_dgnss_info_valid_flags_t)0x2u)
#define MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_ID_SHIFT 1
/** bit 2: Base station status valid. */
#define MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_STATUS_MASK ((mipc_gnss_dgnss_info_valid_flags_t)0x4u)
#define MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_BASE_STATION_STATUS_SHIFT 2
/** bit 3: Number of DGNSS channels valid. */
#define MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_NUM_CHANNELS_MASK ((mipc_gnss_dgnss_info_valid_flags_t)0x8u)
#define MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_NUM_CHANNELS_SHIFT 3
/** bits 4-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_dgnss_info_valid_flags_t)0xFFF0u)
#define MIPC_GNSS_DGNSS_INFO_VALID_FLAGS_RESERVED_SHIFT 4

/** GNSS DOP valid flags. Which dilution-of-precision values are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_dop_valid_flags_t;
/** bit 0: Geometric DOP valid. */
#define MIPC_GNSS_DOP_VALID_FLAGS_GDOP_MASK ((mipc_gnss_dop_valid_flags_t)0x1u)
#define MIPC_GNSS_DOP_VALID_FLAGS_GDOP_SHIFT 0
/** bit 1: Position DOP valid. */
#define MIPC_GNSS_DOP_VALID_FLAGS_PDOP_MASK ((mipc_gnss_dop_valid_flags_t)0x2u)
#define MIPC_GNSS_DOP_VALID_FLAGS_PDOP_SHIFT 1
/** bit 2: Horizontal DOP valid. */
#define MIPC_GNSS_DOP_VALID_FLAGS_HDOP_MASK ((mipc_gnss_dop_valid_flags_t)0x4u)
#define MIPC_GNSS_DOP_VALID_FLAGS_HDOP_SHIFT 2
/** bit 3: Vertical DOP valid. */
#define MIPC_GNSS_DOP_VALID_FLAGS_VDOP_MASK ((mipc_gnss_dop_valid_flags_t)0x8u)
#define MIPC_GNSS_DOP_VALID_FLAGS_VDOP_SHIFT 3
/** bit 4: Time DOP valid. */
#define MIPC_GNSS_DOP_VALID_FLAGS_TDOP_MASK ((mipc_gnss_dop_valid_flags_t)0x10u)
#define MIPC_GNSS_DOP_VALID_FLAGS_TDOP_SHIFT 4
/** bit 5: Northing DOP valid. */
#define MIPC_GNSS_DOP_VALID_FLAGS_NDOP_MASK ((mipc_gnss_dop_valid_flags_t)0x20u)
#define MIPC_GNSS_DOP_VALID_FLAGS_NDOP_SHIFT 5
/** bit 6: Easting DOP valid. */
#define MIPC_GNSS_DOP_VALID_FLAGS_EDOP_MASK ((mipc_gnss_dop_valid_flags_t)0x40u)
#define MIPC_GNSS_DOP_VALID_FLAGS_EDOP_SHIFT 6
/** bits 0-6: All flags. */
#define MIPC_GNSS_DOP_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_dop_valid_flags_t)0x7Fu)
#define MIPC_GNSS_DOP_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 7-15: (reserved) Not named by the manuals. */
#define MIPC_GNSS_DOP_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_dop_valid_flags_t)0xFF80u)
#define MIPC_GNSS_DOP_VALID_FLAGS_RESERVED_SHIFT 7

/** GNSS ECEF position valid flags. Which parameters of a GNSS ECEF position field are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_ecef_position_valid_flags_t;
/** bit 0: ECEF position valid. */
#define MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_MASK ((mipc_gnss_ecef_position_valid_flags_t)0x1u)
#define MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_SHIFT 0
/** bit 1: Position accuracy valid. */
#define MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_ACCURACY_MASK                                           \
    ((mipc_gnss_ecef_position_valid_flags_t)0x2u)
#define MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_POSITION_ACCURACY_SHIFT 1
/** bits 0-1: All flags. */
#define MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_ecef_position_valid_flags_t)0x3u)
#define MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 2-15: (reserved) Not named by the manuals. */
#define MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_ecef_position_valid_flags_t)0xFFFCu)
#define MIPC_GNSS_ECEF_POSITION_VALID_FLAGS_RESERVED_SHIFT 2

/** GNSS ECEF velocity valid flags. Which parameters of a GNSS ECEF velocity field are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_ecef_velocity_valid_flags_t;
/** bit 0: ECEF velocity valid. */
#define MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_MASK ((mipc_gnss_ecef_velocity_valid_flags_t)0x1u)
#define MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_SHIFT 0
/** bit 1: Velocity accuracy valid. */
#define MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_ACCURACY_MASK                                           \
    ((mipc_gnss_ecef_velocity_valid_flags_t)0x2u)
#define MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_VELOCITY_ACCURACY_SHIFT 1
/** bits 0-1: All flags. */
#define MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_ecef_velocity_valid_flags_t)0x3u)
#define MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 2-15: (reserved) Not named by the manuals. */
#define MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_ecef_velocity_valid_flags_t)0xFFFCu)
#define MIPC_GNSS_ECEF_VELOCITY_VALID_FLAGS_RESERVED_SHIFT 2

/** GPS/Galileo/BeiDou ephemeris valid flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_ephemeris_valid_flags_t;
/** bit 0: Ephemeris data valid. */
#define MIPC_GNSS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_MASK ((mipc_gnss_ephemeris_valid_flags_t)0x1u)
#define MIPC_GNSS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_SHIFT 0
/** bit 1: Modernized navigation data present (the manual gives only the name, not which parameters it
 * covers). */
#define MIPC_GNSS_EPHEMERIS_VALID_FLAGS_MODERN_DATA_MASK ((mipc_gnss_ephemeris_valid_flags_t)0x2u)
#define MIPC_GNSS_EPHEMERIS_VALID_FLAGS_MODERN_DATA_SHIFT 1
/** bit 2: isc_l2c holds the L5 inter-signal correction instead of L2. */
#define MIPC_GNSS_EPHEMERIS_VALID_FLAGS_ISC_L5_MASK ((mipc_gnss_ephemeris_valid_flags_t)0x4u)
#define MIPC_GNSS_EPHEMERIS_VALID_FLAGS_ISC_L5_SHIFT 2
/** bits 0-2: All valid flags (the manual's 'flags 0-2' entry). */
#define MIPC_GNSS_EPHEMERIS_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_ephemeris_valid_flags_t)0x7u)
#define MIPC_GNSS_EPHEMERIS_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 3-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_EPHEMERIS_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_ephemeris_valid_flags_t)0xFFF8u)
#define MIPC_GNSS_EPHEMERIS_VALID_FLAGS_RESERVED_SHIFT 3

/** GNSS fix flags. Corrections used in the position fix.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_fix_flags_t;
/** bit 0: SBAS corrections used. */
#define MIPC_GNSS_FIX_FLAGS_SBAS_USED_MASK ((mipc_gnss_fix_flags_t)0x1u)
#define MIPC_GNSS_FIX_FLAGS_SBAS_USED_SHIFT 0
/** bit 1: Differential (DGNSS) corrections used. */
#define MIPC_GNSS_FIX_FLAGS_DGNSS_USED_MASK ((mipc_gnss_fix_flags_t)0x2u)
#define MIPC_GNSS_FIX_FLAGS_DGNSS_USED_SHIFT 1
/** bits 2-15: (reserved) Not named by the manuals. */
#define MIPC_GNSS_FIX_FLAGS_RESERVED_MASK ((mipc_gnss_fix_flags_t)0xFFFCu)
#define MIPC_GNSS_FIX_FLAGS_RESERVED_SHIFT 2

/** GNSS fix information valid flags. Which parameters of a GNSS fix information field are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_fix_info_valid_flags_t;
/** bit 0: Fix type valid. */
#define MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_TYPE_MASK ((mipc_gnss_fix_info_valid_flags_t)0x1u)
#define MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_TYPE_SHIFT 0
/** bit 1: Number of satellites valid. */
#define MIPC_GNSS_FIX_INFO_VALID_FLAGS_NUM_SV_MASK ((mipc_gnss_fix_info_valid_flags_t)0x2u)
#define MIPC_GNSS_FIX_INFO_VALID_FLAGS_NUM_SV_SHIFT 1
/** bit 2: Fix flags valid. */
#define MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_FLAGS_MASK ((mipc_gnss_fix_info_valid_flags_t)0x4u)
#define MIPC_GNSS_FIX_INFO_VALID_FLAGS_FIX_FLAGS_SHIFT 2
/** bits 0-2: All flags. */
#define MIPC_GNSS_FIX_INFO_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_fix_info_valid_flags_t)0x7u)
#define MIPC_GNSS_FIX_INFO_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 3-15: (reserved) Not named by the manuals. */
#define MIPC_GNSS_FIX_INFO_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_fix_info_valid_flags_t)0xFFF8u)
#define MIPC_GNSS_FIX_INFO_VALID_FLAGS_RESERVED_SHIFT 3

/** GNSS fix type (CV7). Type of position fix a CV7 GNSS receiver reports.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gnss_fix_type_cv7_t;
/** 3D fix. */
#define MIPC_GNSS_FIX_TYPE_CV7_FIX_3D ((mipc_gnss_fix_type_cv7_t)0u)
/** 2D fix. */
#define MIPC_GNSS_FIX_TYPE_CV7_FIX_2D ((mipc_gnss_fix_type_cv7_t)1u)
/** Time only. */
#define MIPC_GNSS_FIX_TYPE_CV7_FIX_TIME_ONLY ((mipc_gnss_fix_type_cv7_t)2u)
/** No fix. */
#define MIPC_GNSS_FIX_TYPE_CV7_FIX_NONE ((mipc_gnss_fix_type_cv7_t)3u)
/** Invalid. */
#define MIPC_GNSS_FIX_TYPE_CV7_FIX_INVALID ((mipc_gnss_fix_type_cv7_t)4u)
/** RTK solution, float ambiguities. */
#define MIPC_GNSS_FIX_TYPE_CV7_FIX_RTK_FLOAT ((mipc_gnss_fix_type_cv7_t)5u)
/** RTK solution, fixed ambiguities. */
#define MIPC_GNSS_FIX_TYPE_CV7_FIX_RTK_FIXED ((mipc_gnss_fix_type_cv7_t)6u)
/** Differential (DGNSS) solution. */
#define MIPC_GNSS_FIX_TYPE_CV7_FIX_DIFFERENTIAL ((mipc_gnss_fix_type_cv7_t)7u)

/** GNSS fix type (GX5-45). Type of position fix the GX5-45 GNSS receiver reports.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gnss_fix_type_gx5_t;
/** 3D fix. */
#define MIPC_GNSS_FIX_TYPE_GX5_FIX_3D ((mipc_gnss_fix_type_gx5_t)0u)
/** 2D fix. */
#define MIPC_GNSS_FIX_TYPE_GX5_FIX_2D ((mipc_gnss_fix_type_gx5_t)1u)
/** Time only. */
#define MIPC_GNSS_FIX_TYPE_GX5_FIX_TIME_ONLY ((mipc_gnss_fix_type_gx5_t)2u)
/** No fix. */
#define MIPC_GNSS_FIX_TYPE_GX5_FIX_NONE ((mipc_gnss_fix_type_gx5_t)3u)
/** Invalid. */
#define MIPC_GNSS_FIX_TYPE_GX5_FIX_INVALID ((mipc_gnss_fix_type_gx5_t)4u)

/** Galileo signals enabled.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_gnss_galileo_signals_t;
/** bit 0: Enable E1. */
#define MIPC_GNSS_GALILEO_SIGNALS_E1_MASK ((mipc_gnss_galileo_signals_t)0x1u)
#define MIPC_GNSS_GALILEO_SIGNALS_E1_SHIFT 0
/** bit 1: Enable E5B. */
#define MIPC_GNSS_GALILEO_SIGNALS_E5B_MASK ((mipc_gnss_galileo_signals_t)0x2u)
#define MIPC_GNSS_GALILEO_SIGNALS_E5B_SHIFT 1
/** bit 2: Enable E5A. */
#define MIPC_GNSS_GALILEO_SIGNALS_E5A_MASK ((mipc_gnss_galileo_signals_t)0x4u)
#define MIPC_GNSS_GALILEO_SIGNALS_E5A_SHIFT 2

/** GLONASS ephemeris valid flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_glonass_ephemeris_valid_flags_t;
/** bit 0: Ephemeris data valid. */
#define MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_MASK                                               \
    ((mipc_gnss_glonass_ephemeris_valid_flags_t)0x1u)
#define MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_EPHEMERIS_SHIFT 0
/** bit 0: All valid flags (the manual's 'flags 0' entry: the single bit 0). */
#define MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_glonass_ephemeris_valid_flags_t)0x1u)
#define MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 1-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_RESERVED_MASK                                                \
    ((mipc_gnss_glonass_ephemeris_valid_flags_t)0xFFFEu)
#define MIPC_GNSS_GLONASS_EPHEMERIS_VALID_FLAGS_RESERVED_SHIFT 1

/** GLONASS satellite type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gnss_glonass_satellite_type_t;
/** GLONASS satellite. */
#define MIPC_GNSS_GLONASS_SATELLITE_TYPE_GLONASS ((mipc_gnss_glonass_satellite_type_t)0u)
/** GLONASS-M satellite. */
#define MIPC_GNSS_GLONASS_SATELLITE_TYPE_GLONASS_M ((mipc_gnss_glonass_satellite_type_t)1u)

/** GLONASS signals enabled.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_gnss_glonass_signals_t;
/** bit 0: Enable L1OF. */
#define MIPC_GNSS_GLONASS_SIGNALS_L1OF_MASK ((mipc_gnss_glonass_signals_t)0x1u)
#define MIPC_GNSS_GLONASS_SIGNALS_L1OF_SHIFT 0
/** bit 1: Enable L2OF. */
#define MIPC_GNSS_GLONASS_SIGNALS_L2OF_MASK ((mipc_gnss_glonass_signals_t)0x2u)
#define MIPC_GNSS_GLONASS_SIGNALS_L2OF_SHIFT 1

/** GPS signals enabled.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_gnss_gps_signals_t;
/** bit 0: Enable L1 C/A. */
#define MIPC_GNSS_GPS_SIGNALS_L1CA_MASK ((mipc_gnss_gps_signals_t)0x1u)
#define MIPC_GNSS_GPS_SIGNALS_L1CA_SHIFT 0
/** bit 1: Enable L2C. */
#define MIPC_GNSS_GPS_SIGNALS_L2C_MASK ((mipc_gnss_gps_signals_t)0x2u)
#define MIPC_GNSS_GPS_SIGNALS_L2C_SHIFT 1
/** bit 2: Enable L5. */
#define MIPC_GNSS_GPS_SIGNALS_L5_MASK ((mipc_gnss_gps_signals_t)0x4u)
#define MIPC_GNSS_GPS_SIGNALS_L5_SHIFT 2

/** GNSS GPS time valid flags. Validity of a GNSS GPS time field.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_gps_time_valid_flags_t;
/** bit 0: Time of week valid. */
#define MIPC_GNSS_GPS_TIME_VALID_FLAGS_TOW_MASK ((mipc_gnss_gps_time_valid_flags_t)0x1u)
#define MIPC_GNSS_GPS_TIME_VALID_FLAGS_TOW_SHIFT 0
/** bit 1: Week number valid. */
#define MIPC_GNSS_GPS_TIME_VALID_FLAGS_WEEK_NUMBER_MASK ((mipc_gnss_gps_time_valid_flags_t)0x2u)
#define MIPC_GNSS_GPS_TIME_VALID_FLAGS_WEEK_NUMBER_SHIFT 1
/** bits 0-1: All flags. */
#define MIPC_GNSS_GPS_TIME_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_gps_time_valid_flags_t)0x3u)
#define MIPC_GNSS_GPS_TIME_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 2-15: (reserved) Not named by the manuals. */
#define MIPC_GNSS_GPS_TIME_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_gps_time_valid_flags_t)0xFFFCu)
#define MIPC_GNSS_GPS_TIME_VALID_FLAGS_RESERVED_SHIFT 2

/** GNSS hardware status valid flags. Which parameters of a GNSS hardware status field are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_hardware_status_valid_flags_t;
/** bit 0: Receiver (sensor) state valid. */
#define MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_SENSOR_STATE_MASK                                              \
    ((mipc_gnss_hardware_status_valid_flags_t)0x1u)
#define MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_SENSOR_STATE_SHIFT 0
/** bit 1: Antenna state valid. */
#define MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_STATE_MASK                                             \
    ((mipc_gnss_hardware_status_valid_flags_t)0x2u)
#define MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_STATE_SHIFT 1
/** bit 2: Antenna power valid. */
#define MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_POWER_MASK                                             \
    ((mipc_gnss_hardware_status_valid_flags_t)0x4u)
#define MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_ANTENNA_POWER_SHIFT 2
/** bits 0-2: All flags. */
#define MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_hardware_status_valid_flags_t)0x7u)
#define MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 3-15: (reserved) Not named by the manuals. */
#define MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_hardware_status_valid_flags_t)0xFFF8u)
#define MIPC_GNSS_HARDWARE_STATUS_VALID_FLAGS_RESERVED_SHIFT 3

/** GPS leap seconds valid flags. Validity of the GPS leap seconds field.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_leap_seconds_valid_flags_t;
/** bit 0: (reserved) Not named by the manual. */
#define MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_0_MASK ((mipc_gnss_leap_seconds_valid_flags_t)0x1u)
#define MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_0_SHIFT 0
/** bit 1: Leap seconds valid. */
#define MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_LEAP_SECONDS_MASK ((mipc_gnss_leap_seconds_valid_flags_t)0x2u)
#define MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_LEAP_SECONDS_SHIFT 1
/** bits 2-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_leap_seconds_valid_flags_t)0xFFFCu)
#define MIPC_GNSS_LEAP_SECONDS_VALID_FLAGS_RESERVED_SHIFT 2

/** GNSS LLH position valid flags. Which parameters of a GNSS LLH position field are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_llh_position_valid_flags_t;
/** bit 0: Latitude and longitude valid. */
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_LAT_LON_MASK ((mipc_gnss_llh_position_valid_flags_t)0x1u)
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_LAT_LON_SHIFT 0
/** bit 1: Height above ellipsoid valid. */
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_ELLIPSOID_HEIGHT_MASK ((mipc_gnss_llh_position_valid_flags_t)0x2u)
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_ELLIPSOID_HEIGHT_SHIFT 1
/** bit 2: Height above mean sea level valid. */
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_MSL_HEIGHT_MASK ((mipc_gnss_llh_position_valid_flags_t)0x4u)
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_MSL_HEIGHT_SHIFT 2
/** bit 3: Horizontal accuracy valid. */
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_HORIZONTAL_ACCURACY_MASK                                          \
    ((mipc_gnss_llh_position_valid_flags_t)0x8u)
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_HORIZONTAL_ACCURACY_SHIFT 3
/** bit 4: Vertical accuracy valid. */
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_VERTICAL_ACCURACY_MASK                                            \
    ((mipc_gnss_llh_position_valid_flags_t)0x10u)
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_VERTICAL_ACCURACY_SHIFT 4
/** bits 0-4: All flags. */
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_llh_position_valid_flags_t)0x1Fu)
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 5-15: (reserved) Not named by the manuals. */
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_llh_position_valid_flags_t)0xFFE0u)
#define MIPC_GNSS_LLH_POSITION_VALID_FLAGS_RESERVED_SHIFT 5

/** GNSS NED velocity valid flags. Which parameters of a GNSS NED velocity field are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_ned_velocity_valid_flags_t;
/** bit 0: NED velocity vector valid. */
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_VELOCITY_MASK ((mipc_gnss_ned_velocity_valid_flags_t)0x1u)
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_VELOCITY_SHIFT 0
/** bit 1: 3D speed valid. */
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_3D_MASK ((mipc_gnss_ned_velocity_valid_flags_t)0x2u)
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_3D_SHIFT 1
/** bit 2: Ground speed valid. */
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_GROUND_SPEED_MASK ((mipc_gnss_ned_velocity_valid_flags_t)0x4u)
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_GROUND_SPEED_SHIFT 2
/** bit 3: Heading valid. */
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_MASK ((mipc_gnss_ned_velocity_valid_flags_t)0x8u)
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_SHIFT 3
/** bit 4: Speed accuracy valid. */
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_ACCURACY_MASK ((mipc_gnss_ned_velocity_valid_flags_t)0x10u)
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_SPEED_ACCURACY_SHIFT 4
/** bit 5: Heading accuracy valid. */
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_ACCURACY_MASK ((mipc_gnss_ned_velocity_valid_flags_t)0x20u)
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_HEADING_ACCURACY_SHIFT 5
/** bits 0-5: All flags. */
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_ned_velocity_valid_flags_t)0x3Fu)
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 6-15: (reserved) Not named by the manuals. */
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_ned_velocity_valid_flags_t)0xFFC0u)
#define MIPC_GNSS_NED_VELOCITY_VALID_FLAGS_RESERVED_SHIFT 6

/** Raw observation valid flags. Which parameters of a raw observation field hold valid data.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_raw_valid_flags_t;
/** bit 0: Time of week valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_TOW_MASK ((mipc_gnss_raw_valid_flags_t)0x1u)
#define MIPC_GNSS_RAW_VALID_FLAGS_TOW_SHIFT 0
/** bit 1: Week number valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_WEEK_NUMBER_MASK ((mipc_gnss_raw_valid_flags_t)0x2u)
#define MIPC_GNSS_RAW_VALID_FLAGS_WEEK_NUMBER_SHIFT 1
/** bit 2: Receiver id valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_RECEIVER_ID_MASK ((mipc_gnss_raw_valid_flags_t)0x4u)
#define MIPC_GNSS_RAW_VALID_FLAGS_RECEIVER_ID_SHIFT 2
/** bit 3: Tracking channel valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_TRACKING_CHANNEL_MASK ((mipc_gnss_raw_valid_flags_t)0x8u)
#define MIPC_GNSS_RAW_VALID_FLAGS_TRACKING_CHANNEL_SHIFT 3
/** bit 4: Constellation id valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_GNSS_ID_MASK ((mipc_gnss_raw_valid_flags_t)0x10u)
#define MIPC_GNSS_RAW_VALID_FLAGS_GNSS_ID_SHIFT 4
/** bit 5: Satellite id valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_SATELLITE_ID_MASK ((mipc_gnss_raw_valid_flags_t)0x20u)
#define MIPC_GNSS_RAW_VALID_FLAGS_SATELLITE_ID_SHIFT 5
/** bit 6: Signal id valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_ID_MASK ((mipc_gnss_raw_valid_flags_t)0x40u)
#define MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_ID_SHIFT 6
/** bit 7: Signal strength valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_STRENGTH_MASK ((mipc_gnss_raw_valid_flags_t)0x80u)
#define MIPC_GNSS_RAW_VALID_FLAGS_SIGNAL_STRENGTH_SHIFT 7
/** bit 8: Quality valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_QUALITY_MASK ((mipc_gnss_raw_valid_flags_t)0x100u)
#define MIPC_GNSS_RAW_VALID_FLAGS_QUALITY_SHIFT 8
/** bit 9: Pseudorange valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_PSEUDORANGE_MASK ((mipc_gnss_raw_valid_flags_t)0x200u)
#define MIPC_GNSS_RAW_VALID_FLAGS_PSEUDORANGE_SHIFT 9
/** bit 10: Carrier phase valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_MASK ((mipc_gnss_raw_valid_flags_t)0x400u)
#define MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_SHIFT 10
/** bit 11: Doppler valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_MASK ((mipc_gnss_raw_valid_flags_t)0x800u)
#define MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_SHIFT 11
/** bit 12: Pseudorange uncertainty valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_RANGE_UNCERTAINTY_MASK ((mipc_gnss_raw_valid_flags_t)0x1000u)
#define MIPC_GNSS_RAW_VALID_FLAGS_RANGE_UNCERTAINTY_SHIFT 12
/** bit 13: Carrier phase uncertainty valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_UNCERTAINTY_MASK ((mipc_gnss_raw_valid_flags_t)0x2000u)
#define MIPC_GNSS_RAW_VALID_FLAGS_CARRIER_PHASE_UNCERTAINTY_SHIFT 13
/** bit 14: Doppler uncertainty valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_UNCERTAINTY_MASK ((mipc_gnss_raw_valid_flags_t)0x4000u)
#define MIPC_GNSS_RAW_VALID_FLAGS_DOPPLER_UNCERTAINTY_SHIFT 14
/** bit 15: Lock time valid. */
#define MIPC_GNSS_RAW_VALID_FLAGS_LOCK_TIME_MASK ((mipc_gnss_raw_valid_flags_t)0x8000u)
#define MIPC_GNSS_RAW_VALID_FLAGS_LOCK_TIME_SHIFT 15
/** bits 0-15: All valid flags (the manual's 'flags 0-15' entry). */
#define MIPC_GNSS_RAW_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_raw_valid_flags_t)0xFFFFu)
#define MIPC_GNSS_RAW_VALID_FLAGS_FLAGS_SHIFT 0

/** GNSS receiver (sensor) state. Power state of the GNSS receiver (GX5-45 "Sensor State", CV7 "Receiver
 * State"). An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gnss_receiver_state_t;
/** Receiver off. */
#define MIPC_GNSS_RECEIVER_STATE_OFF ((mipc_gnss_receiver_state_t)0u)
/** Receiver on. */
#define MIPC_GNSS_RECEIVER_STATE_ON ((mipc_gnss_receiver_state_t)1u)
/** State unknown. */
#define MIPC_GNSS_RECEIVER_STATE_UNKNOWN ((mipc_gnss_receiver_state_t)2u)

/** Satellite status valid flags. Which parameters of a satellite status field hold valid data.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_satellite_status_valid_flags_t;
/** bit 0: Time of week valid. */
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_TOW_MASK ((mipc_gnss_satellite_status_valid_flags_t)0x1u)
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_TOW_SHIFT 0
/** bit 1: Week number valid. */
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_WEEK_NUMBER_MASK                                              \
    ((mipc_gnss_satellite_status_valid_flags_t)0x2u)
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_WEEK_NUMBER_SHIFT 1
/** bit 2: Constellation id valid. */
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_GNSS_ID_MASK ((mipc_gnss_satellite_status_valid_flags_t)0x4u)
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_GNSS_ID_SHIFT 2
/** bit 3: Satellite id valid. */
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_SATELLITE_ID_MASK                                             \
    ((mipc_gnss_satellite_status_valid_flags_t)0x8u)
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_SATELLITE_ID_SHIFT 3
/** bit 4: Elevation valid. */
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_ELEVATION_MASK                                                \
    ((mipc_gnss_satellite_status_valid_flags_t)0x10u)
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_ELEVATION_SHIFT 4
/** bit 5: Azimuth valid. */
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_AZIMUTH_MASK ((mipc_gnss_satellite_status_valid_flags_t)0x20u)
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_AZIMUTH_SHIFT 5
/** bit 6: Health valid. */
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_HEALTH_MASK ((mipc_gnss_satellite_status_valid_flags_t)0x40u)
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_HEALTH_SHIFT 6
/** bits 0-6: All valid flags (the manual's 'flags 0-6' entry). */
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_satellite_status_valid_flags_t)0x7Fu)
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 7-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_RESERVED_MASK                                                 \
    ((mipc_gnss_satellite_status_valid_flags_t)0xFF80u)
#define MIPC_GNSS_SATELLITE_STATUS_VALID_FLAGS_RESERVED_SHIFT 7

/** SBAS information valid flags. Which parameters of the SBAS information field are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_sbas_info_valid_flags_t;
/** bit 0: Time of week valid. */
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_TOW_MASK ((mipc_gnss_sbas_info_valid_flags_t)0x1u)
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_TOW_SHIFT 0
/** bit 1: Week number valid. */
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_WEEK_NUMBER_MASK ((mipc_gnss_sbas_info_valid_flags_t)0x2u)
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_WEEK_NUMBER_SHIFT 1
/** bit 2: SBAS system valid. */
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_SYSTEM_MASK ((mipc_gnss_sbas_info_valid_flags_t)0x4u)
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_SYSTEM_SHIFT 2
/** bit 3: SBAS satellite id valid. */
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_ID_MASK ((mipc_gnss_sbas_info_valid_flags_t)0x8u)
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_ID_SHIFT 3
/** bit 4: Number of corrections valid. */
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_COUNT_MASK ((mipc_gnss_sbas_info_valid_flags_t)0x10u)
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_COUNT_SHIFT 4
/** bit 5: SBAS status valid. */
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_STATUS_MASK ((mipc_gnss_sbas_info_valid_flags_t)0x20u)
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_SBAS_STATUS_SHIFT 5
/** bits 0-5: All flags. */
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_FLAGS_MASK ((mipc_gnss_sbas_info_valid_flags_t)0x3Fu)
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 6-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_sbas_info_valid_flags_t)0xFFC0u)
#define MIPC_GNSS_SBAS_INFO_VALID_FLAGS_RESERVED_SHIFT 6

/** SBAS status. Status of the SBAS service.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_gnss_sbas_status_t;
/** bit 0: SBAS ranging available. */
#define MIPC_GNSS_SBAS_STATUS_RANGE_AVAILABLE_MASK ((mipc_gnss_sbas_status_t)0x1u)
#define MIPC_GNSS_SBAS_STATUS_RANGE_AVAILABLE_SHIFT 0
/** bit 1: SBAS corrections available. */
#define MIPC_GNSS_SBAS_STATUS_CORRECTIONS_AVAILABLE_MASK ((mipc_gnss_sbas_status_t)0x2u)
#define MIPC_GNSS_SBAS_STATUS_CORRECTIONS_AVAILABLE_SHIFT 1
/** bit 2: SBAS integrity information available. */
#define MIPC_GNSS_SBAS_STATUS_INTEGRITY_AVAILABLE_MASK ((mipc_gnss_sbas_status_t)0x4u)
#define MIPC_GNSS_SBAS_STATUS_INTEGRITY_AVAILABLE_SHIFT 2
/** bit 3: SBAS is in test mode. */
#define MIPC_GNSS_SBAS_STATUS_TEST_MODE_MASK ((mipc_gnss_sbas_status_t)0x8u)
#define MIPC_GNSS_SBAS_STATUS_TEST_MODE_SHIFT 3
/** bits 4-7: (reserved) Not named by the manual. */
#define MIPC_GNSS_SBAS_STATUS_RESERVED_MASK ((mipc_gnss_sbas_status_t)0xF0u)
#define MIPC_GNSS_SBAS_STATUS_RESERVED_SHIFT 4

/** SBAS system. Satellite-based augmentation system the receiver is using.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gnss_sbas_system_t;
/** Unknown. */
#define MIPC_GNSS_SBAS_SYSTEM_UNKNOWN ((mipc_gnss_sbas_system_t)0u)
/** WAAS (North America). */
#define MIPC_GNSS_SBAS_SYSTEM_WAAS ((mipc_gnss_sbas_system_t)1u)
/** EGNOS (Europe). */
#define MIPC_GNSS_SBAS_SYSTEM_EGNOS ((mipc_gnss_sbas_system_t)2u)
/** MSAS (Japan). */
#define MIPC_GNSS_SBAS_SYSTEM_MSAS ((mipc_gnss_sbas_system_t)3u)
/** GAGAN (India). */
#define MIPC_GNSS_SBAS_SYSTEM_GAGAN ((mipc_gnss_sbas_system_t)4u)

/** GNSS signal identifier. The constellation, frequency band and code/channel component of one observation.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gnss_signal_id_t;
/** Unknown or unspecified signal. */
#define MIPC_GNSS_SIGNAL_ID_UNKNOWN ((mipc_gnss_signal_id_t)0u)
/** GPS L1 C/A. */
#define MIPC_GNSS_SIGNAL_ID_GPS_L1CA ((mipc_gnss_signal_id_t)1u)
/** GPS L1 P. */
#define MIPC_GNSS_SIGNAL_ID_GPS_L1P ((mipc_gnss_signal_id_t)2u)
/** GPS L1 Z-tracking. */
#define MIPC_GNSS_SIGNAL_ID_GPS_L1Z ((mipc_gnss_signal_id_t)3u)
/** GPS L2 C/A. */
#define MIPC_GNSS_SIGNAL_ID_GPS_L2CA ((mipc_gnss_signal_id_t)4u)
/** GPS L2 P. */
#define MIPC_GNSS_SIGNAL_ID_GPS_L2P ((mipc_gnss_signal_id_t)5u)
/** GPS L2 Z-tracking. */
#define MIPC_GNSS_SIGNAL_ID_GPS_L2Z ((mipc_gnss_signal_id_t)6u)
/** GPS L2C long code (L). */
#define MIPC_GNSS_SIGNAL_ID_GPS_L2CL ((mipc_gnss_signal_id_t)7u)
/** GPS L2C medium code (M). */
#define MIPC_GNSS_SIGNAL_ID_GPS_L2CM ((mipc_gnss_signal_id_t)8u)
/** GPS L2C combined M+L. */
#define MIPC_GNSS_SIGNAL_ID_GPS_L2CML ((mipc_gnss_signal_id_t)9u)
/** GPS L5 I (data). */
#define MIPC_GNSS_SIGNAL_ID_GPS_L5I ((mipc_gnss_signal_id_t)10u)
/** GPS L5 Q (pilot). */
#define MIPC_GNSS_SIGNAL_ID_GPS_L5Q ((mipc_gnss_signal_id_t)11u)
/** GPS L5 combined I+Q. */
#define MIPC_GNSS_SIGNAL_ID_GPS_L5IQ ((mipc_gnss_signal_id_t)12u)
/** GPS L1C data (D). */
#define MIPC_GNSS_SIGNAL_ID_GPS_L1CD ((mipc_gnss_signal_id_t)13u)
/** GPS L1C pilot (P). */
#define MIPC_GNSS_SIGNAL_ID_GPS_L1CP ((mipc_gnss_signal_id_t)14u)
/** GPS L1C combined D+P. */
#define MIPC_GNSS_SIGNAL_ID_GPS_L1CDP ((mipc_gnss_signal_id_t)15u)
/** GLONASS G1 C/A. */
#define MIPC_GNSS_SIGNAL_ID_GLONASS_G1CA ((mipc_gnss_signal_id_t)32u)
/** GLONASS G1 P. */
#define MIPC_GNSS_SIGNAL_ID_GLONASS_G1P ((mipc_gnss_signal_id_t)33u)
/** GLONASS G2 C/A. */
#define MIPC_GNSS_SIGNAL_ID_GLONASS_G2C ((mipc_gnss_signal_id_t)34u)
/** GLONASS G2 P. */
#define MIPC_GNSS_SIGNAL_ID_GLONASS_G2P ((mipc_gnss_signal_id_t)35u)
/** Galileo E1 C (pilot). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E1C ((mipc_gnss_signal_id_t)64u)
/** Galileo E1 A (PRS). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E1A ((mipc_gnss_signal_id_t)65u)
/** Galileo E1 B (data). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E1B ((mipc_gnss_signal_id_t)66u)
/** Galileo E1 combined B+C. */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E1BC ((mipc_gnss_signal_id_t)67u)
/** Galileo E1 combined A+B+C. */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E1ABC ((mipc_gnss_signal_id_t)68u)
/** Galileo E6 C (pilot). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E6C ((mipc_gnss_signal_id_t)69u)
/** Galileo E6 A (PRS). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E6A ((mipc_gnss_signal_id_t)70u)
/** Galileo E6 B (data). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E6B ((mipc_gnss_signal_id_t)71u)
/** Galileo E6 combined B+C. */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E6BC ((mipc_gnss_signal_id_t)72u)
/** Galileo E6 combined A+B+C. */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E6ABC ((mipc_gnss_signal_id_t)73u)
/** Galileo E5b I (data). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E5BI ((mipc_gnss_signal_id_t)74u)
/** Galileo E5b Q (pilot). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E5BQ ((mipc_gnss_signal_id_t)75u)
/** Galileo E5b combined I+Q. */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E5BIQ ((mipc_gnss_signal_id_t)76u)
/** Galileo E5 AltBOC (E5a+E5b) I (data). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E5ABI ((mipc_gnss_signal_id_t)77u)
/** Galileo E5 AltBOC (E5a+E5b) Q (pilot). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E5ABQ ((mipc_gnss_signal_id_t)78u)
/** Galileo E5 AltBOC (E5a+E5b) combined I+Q. */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E5ABIQ ((mipc_gnss_signal_id_t)79u)
/** Galileo E5a I (data). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E5AI ((mipc_gnss_signal_id_t)80u)
/** Galileo E5a Q (pilot). */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E5AQ ((mipc_gnss_signal_id_t)81u)
/** Galileo E5a combined I+Q. */
#define MIPC_GNSS_SIGNAL_ID_GALILEO_E5AIQ ((mipc_gnss_signal_id_t)82u)
/** SBAS L1 C/A. */
#define MIPC_GNSS_SIGNAL_ID_SBAS_L1CA ((mipc_gnss_signal_id_t)96u)
/** SBAS L5 I (data). */
#define MIPC_GNSS_SIGNAL_ID_SBAS_L5I ((mipc_gnss_signal_id_t)97u)
/** SBAS L5 Q (pilot). */
#define MIPC_GNSS_SIGNAL_ID_SBAS_L5Q ((mipc_gnss_signal_id_t)98u)
/** SBAS L5 combined I+Q. */
#define MIPC_GNSS_SIGNAL_ID_SBAS_L5IQ ((mipc_gnss_signal_id_t)99u)
/** QZSS L1 C/A. */
#define MIPC_GNSS_SIGNAL_ID_QZSS_L1CA ((mipc_gnss_signal_id_t)128u)
/** QZSS LEX short code (S). */
#define MIPC_GNSS_SIGNAL_ID_QZSS_LEXS ((mipc_gnss_signal_id_t)129u)
/** QZSS LEX long code (L). */
#define MIPC_GNSS_SIGNAL_ID_QZSS_LEXL ((mipc_gnss_signal_id_t)130u)
/** QZSS LEX combined S+L. */
#define MIPC_GNSS_SIGNAL_ID_QZSS_LEXSL ((mipc_gnss_signal_id_t)131u)
/** QZSS L2C medium code (M). */
#define MIPC_GNSS_SIGNAL_ID_QZSS_L2CM ((mipc_gnss_signal_id_t)132u)
/** QZSS L2C long code (L). */
#define MIPC_GNSS_SIGNAL_ID_QZSS_L2CL ((mipc_gnss_signal_id_t)133u)
/** QZSS L2C combined M+L. */
#define MIPC_GNSS_SIGNAL_ID_QZSS_L2CML ((mipc_gnss_signal_id_t)134u)
/** QZSS L5 I (data). */
#define MIPC_GNSS_SIGNAL_ID_QZSS_L5I ((mipc_gnss_signal_id_t)135u)
/** QZSS L5 Q (pilot). */
#define MIPC_GNSS_SIGNAL_ID_QZSS_L5Q ((mipc_gnss_signal_id_t)136u)
/** QZSS L5 combined I+Q. */
#define MIPC_GNSS_SIGNAL_ID_QZSS_L5IQ ((mipc_gnss_signal_id_t)137u)
/** QZSS L1C data (D). */
#define MIPC_GNSS_SIGNAL_ID_QZSS_L1CD ((mipc_gnss_signal_id_t)138u)
/** QZSS L1C pilot (P). */
#define MIPC_GNSS_SIGNAL_ID_QZSS_L1CP ((mipc_gnss_signal_id_t)139u)
/** QZSS L1C combined D+P. */
#define MIPC_GNSS_SIGNAL_ID_QZSS_L1CDP ((mipc_gnss_signal_id_t)140u)
/** BeiDou B1 I. */
#define MIPC_GNSS_SIGNAL_ID_BEIDOU_B1I ((mipc_gnss_signal_id_t)160u)
/** BeiDou B1 Q. */
#define MIPC_GNSS_SIGNAL_ID_BEIDOU_B1Q ((mipc_gnss_signal_id_t)161u)
/** BeiDou B1 combined I+Q. */
#define MIPC_GNSS_SIGNAL_ID_BEIDOU_B1IQ ((mipc_gnss_signal_id_t)162u)
/** BeiDou B3 I. */
#define MIPC_GNSS_SIGNAL_ID_BEIDOU_B3I ((mipc_gnss_signal_id_t)163u)
/** BeiDou B3 Q. */
#define MIPC_GNSS_SIGNAL_ID_BEIDOU_B3Q ((mipc_gnss_signal_id_t)164u)
/** BeiDou B3 combined I+Q. */
#define MIPC_GNSS_SIGNAL_ID_BEIDOU_B3IQ ((mipc_gnss_signal_id_t)165u)
/** BeiDou B2 I. */
#define MIPC_GNSS_SIGNAL_ID_BEIDOU_B2I ((mipc_gnss_signal_id_t)166u)
/** BeiDou B2 Q. */
#define MIPC_GNSS_SIGNAL_ID_BEIDOU_B2Q ((mipc_gnss_signal_id_t)167u)
/** BeiDou B2 combined I+Q. */
#define MIPC_GNSS_SIGNAL_ID_BEIDOU_B2IQ ((mipc_gnss_signal_id_t)168u)
/** BeiDou B2a. */
#define MIPC_GNSS_SIGNAL_ID_BEIDOU_B2A ((mipc_gnss_signal_id_t)169u)

/** GNSS raw observation signal quality. Tracking state of the signal an observation comes from.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gnss_signal_quality_t;
/** No signal. */
#define MIPC_GNSS_SIGNAL_QUALITY_NONE ((mipc_gnss_signal_quality_t)0u)
/** Searching for the signal. */
#define MIPC_GNSS_SIGNAL_QUALITY_SEARCHING ((mipc_gnss_signal_quality_t)1u)
/** Signal acquired. */
#define MIPC_GNSS_SIGNAL_QUALITY_ACQUIRED ((mipc_gnss_signal_quality_t)2u)
/** Signal detected but unusable. */
#define MIPC_GNSS_SIGNAL_QUALITY_UNUSABLE ((mipc_gnss_signal_quality_t)3u)
/** Time locked. */
#define MIPC_GNSS_SIGNAL_QUALITY_TIME_LOCKED ((mipc_gnss_signal_quality_t)4u)
/** Fully locked. */
#define MIPC_GNSS_SIGNAL_QUALITY_FULLY_LOCKED ((mipc_gnss_signal_quality_t)5u)

/** Space vehicle flags. Use and health of one space vehicle.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_sv_flags_t;
/** bit 0: The SV is used in the navigation solution. */
#define MIPC_GNSS_SV_FLAGS_USED_FOR_NAVIGATION_MASK ((mipc_gnss_sv_flags_t)0x1u)
#define MIPC_GNSS_SV_FLAGS_USED_FOR_NAVIGATION_SHIFT 0
/** bit 1: The SV is healthy. */
#define MIPC_GNSS_SV_FLAGS_HEALTHY_MASK ((mipc_gnss_sv_flags_t)0x2u)
#define MIPC_GNSS_SV_FLAGS_HEALTHY_SHIFT 1
/** bits 2-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_SV_FLAGS_RESERVED_MASK ((mipc_gnss_sv_flags_t)0xFFFCu)
#define MIPC_GNSS_SV_FLAGS_RESERVED_SHIFT 2

/** Space vehicle information valid flags. Which parameters of a space vehicle information entry are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_sv_info_valid_flags_t;
/** bit 0: Channel valid. */
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_CHANNEL_MASK ((mipc_gnss_sv_info_valid_flags_t)0x1u)
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_CHANNEL_SHIFT 0
/** bit 1: Space vehicle id valid. */
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_ID_MASK ((mipc_gnss_sv_info_valid_flags_t)0x2u)
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_ID_SHIFT 1
/** bit 2: (reserved) Not named by the manual (its list skips 0x0004). */
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_2_MASK ((mipc_gnss_sv_info_valid_flags_t)0x4u)
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_2_SHIFT 2
/** bit 3: Carrier to noise ratio valid. */
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_CARRIER_TO_NOISE_RATIO_MASK ((mipc_gnss_sv_info_valid_flags_t)0x8u)
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_CARRIER_TO_NOISE_RATIO_SHIFT 3
/** bit 4: Azimuth valid. */
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_AZIMUTH_MASK ((mipc_gnss_sv_info_valid_flags_t)0x10u)
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_AZIMUTH_SHIFT 4
/** bit 5: Elevation valid. */
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_ELEVATION_MASK ((mipc_gnss_sv_info_valid_flags_t)0x20u)
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_ELEVATION_SHIFT 5
/** bit 6: Space vehicle flags valid. */
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_FLAGS_MASK ((mipc_gnss_sv_info_valid_flags_t)0x40u)
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_SV_FLAGS_SHIFT 6
/** bits 7-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_MASK ((mipc_gnss_sv_info_valid_flags_t)0xFF80u)
#define MIPC_GNSS_SV_INFO_VALID_FLAGS_RESERVED_SHIFT 7

/** GNSS UTC time valid flags (CV7). Validity of a CV7 GNSS UTC time field.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_utc_time_valid_flags_cv7_t;
/** bit 0: Date and time valid. */
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_GNSS_DATE_TIME_MASK ((mipc_gnss_utc_time_valid_flags_cv7_t)0x1u)
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_GNSS_DATE_TIME_SHIFT 0
/** bit 1: The GPS-UTC leap second offset is known, so the UTC time is exact. */
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_LEAP_SECONDS_KNOWN_MASK                                           \
    ((mipc_gnss_utc_time_valid_flags_cv7_t)0x2u)
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_LEAP_SECONDS_KNOWN_SHIFT 1
/** bits 0-1: All flags. */
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_FLAGS_MASK ((mipc_gnss_utc_time_valid_flags_cv7_t)0x3u)
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_FLAGS_SHIFT 0
/** bits 2-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_RESERVED_MASK ((mipc_gnss_utc_time_valid_flags_cv7_t)0xFFFCu)
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_CV7_RESERVED_SHIFT 2

/** GNSS UTC time valid flags (GX5-45). Validity of the GX5-45 GNSS UTC time field.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_gnss_utc_time_valid_flags_gx5_t;
/** bit 0: Date valid. */
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_DATE_VALID_MASK ((mipc_gnss_utc_time_valid_flags_gx5_t)0x1u)
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_DATE_VALID_SHIFT 0
/** bit 1: Time valid. */
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_TIME_VALID_MASK ((mipc_gnss_utc_time_valid_flags_gx5_t)0x2u)
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_TIME_VALID_SHIFT 1
/** bits 2-15: (reserved) Not named by the manual. */
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_RESERVED_MASK ((mipc_gnss_utc_time_valid_flags_gx5_t)0xFFFCu)
#define MIPC_GNSS_UTC_TIME_VALID_FLAGS_GX5_RESERVED_SHIFT 2

/** GPIO behavior for the ENCODER feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gpio_encoder_behavior_t;
/** No behavior. */
#define MIPC_GPIO_ENCODER_BEHAVIOR_UNUSED ((mipc_gpio_encoder_behavior_t)0u)
/** ENCODER_A: quadrature input A; one pin at most (the latest command wins). */
#define MIPC_GPIO_ENCODER_BEHAVIOR_ENCODER_A ((mipc_gpio_encoder_behavior_t)1u)
/** ENCODER_B: quadrature input B; one pin at most (the latest command wins). */
#define MIPC_GPIO_ENCODER_BEHAVIOR_ENCODER_B ((mipc_gpio_encoder_behavior_t)2u)

/** GPIO pin feature. What a user GPIO pin is used for; selects how the behavior byte is read.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gpio_feature_t;
/** Pin not used; reading its state may or may not work. */
#define MIPC_GPIO_FEATURE_UNUSED ((mipc_gpio_feature_t)0u)
/** General purpose input or output (direct control or monitoring of the pin state). */
#define MIPC_GPIO_FEATURE_GPIO ((mipc_gpio_feature_t)1u)
/** Pulse-per-second input or output. */
#define MIPC_GPIO_FEATURE_PPS ((mipc_gpio_feature_t)2u)
/** Motor encoder / odometer input. */
#define MIPC_GPIO_FEATURE_ENCODER ((mipc_gpio_feature_t)3u)
/** Precision timestamping of edges (for event triggers, 0x0C,0x2E). */
#define MIPC_GPIO_FEATURE_TIMESTAMP ((mipc_gpio_feature_t)4u)
/** UART data or control line. */
#define MIPC_GPIO_FEATURE_UART ((mipc_gpio_feature_t)5u)

/** GPIO behavior for the GPIO feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gpio_io_behavior_t;
/** No behavior. */
#define MIPC_GPIO_IO_BEHAVIOR_UNUSED ((mipc_gpio_io_behavior_t)0u)
/** GPIO_INPUT: the pin is an input that can be streamed or polled (the default). */
#define MIPC_GPIO_IO_BEHAVIOR_INPUT ((mipc_gpio_io_behavior_t)1u)
/** GPIO_OUTPUT_LOW: output, initially low (restored at startup if saved). */
#define MIPC_GPIO_IO_BEHAVIOR_OUTPUT_LOW ((mipc_gpio_io_behavior_t)2u)
/** GPIO_OUTPUT_HIGH: output, initially high (restored at startup if saved). */
#define MIPC_GPIO_IO_BEHAVIOR_OUTPUT_HIGH ((mipc_gpio_io_behavior_t)3u)

/** GPIO pin electrical mode. Electrical configuration of a GPIO pin; which combinations a (feature, behavior)
 * pair supports is listed in the User GPIO pin-mode table (line 1338). The whole integer is kept (reserved
 * bits too); members are read with the masks below: (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_gpio_pin_mode_t;
/** bit 0: Open-drain output: LOW or floating instead of LOW or HIGH; usually with a pull-up. */
#define MIPC_GPIO_PIN_MODE_OPEN_DRAIN_MASK ((mipc_gpio_pin_mode_t)0x1u)
#define MIPC_GPIO_PIN_MODE_OPEN_DRAIN_SHIFT 0
/** bit 1: Internal pull-down resistor enabled (not with pullup). */
#define MIPC_GPIO_PIN_MODE_PULLDOWN_MASK ((mipc_gpio_pin_mode_t)0x2u)
#define MIPC_GPIO_PIN_MODE_PULLDOWN_SHIFT 1
/** bit 2: Internal pull-up resistor enabled (not with pulldown); may lower the allowed input voltage. */
#define MIPC_GPIO_PIN_MODE_PULLUP_MASK ((mipc_gpio_pin_mode_t)0x4u)
#define MIPC_GPIO_PIN_MODE_PULLUP_SHIFT 2

/** GPIO pin states.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_gpio_pin_states_t;
/** bit 0: State of GPIO pin 1. */
#define MIPC_GPIO_PIN_STATES_PIN_1_MASK ((mipc_gpio_pin_states_t)0x1u)
#define MIPC_GPIO_PIN_STATES_PIN_1_SHIFT 0
/** bit 1: State of GPIO pin 2. */
#define MIPC_GPIO_PIN_STATES_PIN_2_MASK ((mipc_gpio_pin_states_t)0x2u)
#define MIPC_GPIO_PIN_STATES_PIN_2_SHIFT 1
/** bit 2: State of GPIO pin 3. */
#define MIPC_GPIO_PIN_STATES_PIN_3_MASK ((mipc_gpio_pin_states_t)0x4u)
#define MIPC_GPIO_PIN_STATES_PIN_3_SHIFT 2
/** bit 3: State of GPIO pin 4. */
#define MIPC_GPIO_PIN_STATES_PIN_4_MASK ((mipc_gpio_pin_states_t)0x8u)
#define MIPC_GPIO_PIN_STATES_PIN_4_SHIFT 3
/** bits 4-7: (reserved) No such pins; read as 0. */
#define MIPC_GPIO_PIN_STATES_RESERVED_MASK ((mipc_gpio_pin_states_t)0xF0u)
#define MIPC_GPIO_PIN_STATES_RESERVED_SHIFT 4

/** GPIO behavior for the PPS feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gpio_pps_behavior_t;
/** No behavior. */
#define MIPC_GPIO_PPS_BEHAVIOR_UNUSED ((mipc_gpio_pps_behavior_t)0u)
/** PPS_INPUT: receives the PPS signal; one pin at most; needs PPS source GPIO (0x0C,0x28). */
#define MIPC_GPIO_PPS_BEHAVIOR_INPUT ((mipc_gpio_pps_behavior_t)1u)
/** PPS_OUTPUT: transmits the device's PPS signal. */
#define MIPC_GPIO_PPS_BEHAVIOR_OUTPUT ((mipc_gpio_pps_behavior_t)2u)

/** GPIO behavior for the TIMESTAMP feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gpio_timestamp_behavior_t;
/** No behavior. */
#define MIPC_GPIO_TIMESTAMP_BEHAVIOR_UNUSED ((mipc_gpio_timestamp_behavior_t)0u)
/** TIMESTAMP_RISING: rising edges are timestamped. */
#define MIPC_GPIO_TIMESTAMP_BEHAVIOR_RISING ((mipc_gpio_timestamp_behavior_t)1u)
/** TIMESTAMP_FALLING: falling edges are timestamped. */
#define MIPC_GPIO_TIMESTAMP_BEHAVIOR_FALLING ((mipc_gpio_timestamp_behavior_t)2u)
/** TIMESTAMP_EITHER: both edges are timestamped. */
#define MIPC_GPIO_TIMESTAMP_BEHAVIOR_EITHER ((mipc_gpio_timestamp_behavior_t)3u)

/** GPIO behavior for the UART feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gpio_uart_behavior_t;
/** No behavior. */
#define MIPC_GPIO_UART_BEHAVIOR_UNUSED ((mipc_gpio_uart_behavior_t)0u)
/** UART_PORT2_TX: UART port 2 transmit. */
#define MIPC_GPIO_UART_BEHAVIOR_PORT2_TX ((mipc_gpio_uart_behavior_t)33u)
/** UART_PORT2_RX: UART port 2 receive. */
#define MIPC_GPIO_UART_BEHAVIOR_PORT2_RX ((mipc_gpio_uart_behavior_t)34u)
/** UART_PORT3_TX: UART port 3 transmit. */
#define MIPC_GPIO_UART_BEHAVIOR_PORT3_TX ((mipc_gpio_uart_behavior_t)49u)
/** UART_PORT3_RX: UART port 3 receive. */
#define MIPC_GPIO_UART_BEHAVIOR_PORT3_RX ((mipc_gpio_uart_behavior_t)50u)

/** GPIO behavior for the UNUSED feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gpio_unused_behavior_t;
/** No behavior (0 unless otherwise specified). */
#define MIPC_GPIO_UNUSED_BEHAVIOR_UNUSED ((mipc_gpio_unused_behavior_t)0u)

/** GPS time field selector.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gps_time_field_t;
/** Week number (GX5-45: GPS Week Number). */
#define MIPC_GPS_TIME_FIELD_WEEK_NUMBER ((mipc_gps_time_field_t)1u)
/** Time of week in seconds (GX5-45: GPS Seconds). */
#define MIPC_GPS_TIME_FIELD_TIME_OF_WEEK ((mipc_gps_time_field_t)2u)

/** 3DM-GX5-45 built-in test error flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint32_t mipc_gx5_bit_flags_t;
/** bit 0: Processor board: watchdog reset (latching, cleared after first commanded BIT). */
#define MIPC_GX5_BIT_FLAGS_PROCESSOR_WDT_RESET_MASK ((mipc_gx5_bit_flags_t)0x1u)
#define MIPC_GX5_BIT_FLAGS_PROCESSOR_WDT_RESET_SHIFT 0
/** bit 8: Sensor board: IMU communication fault. */
#define MIPC_GX5_BIT_FLAGS_IMU_COMMUNICATION_FAULT_MASK ((mipc_gx5_bit_flags_t)0x100u)
#define MIPC_GX5_BIT_FLAGS_IMU_COMMUNICATION_FAULT_SHIFT 8
/** bit 9: Sensor board: magnetometer fault (if applicable). */
#define MIPC_GX5_BIT_FLAGS_MAGNETOMETER_FAULT_MASK ((mipc_gx5_bit_flags_t)0x200u)
#define MIPC_GX5_BIT_FLAGS_MAGNETOMETER_FAULT_SHIFT 9
/** bit 10: Sensor board: pressure sensor fault (if applicable). */
#define MIPC_GX5_BIT_FLAGS_PRESSURE_SENSOR_FAULT_MASK ((mipc_gx5_bit_flags_t)0x400u)
#define MIPC_GX5_BIT_FLAGS_PRESSURE_SENSOR_FAULT_SHIFT 10
/** bit 24: Kalman filter: solution fault. */
#define MIPC_GX5_BIT_FLAGS_FILTER_SOLUTION_FAULT_MASK ((mipc_gx5_bit_flags_t)0x1000000u)
#define MIPC_GX5_BIT_FLAGS_FILTER_SOLUTION_FAULT_SHIFT 24

/** GNSS constellation ID (GX5-45 constellation settings).
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gx5_constellation_id_t;
/** GPS (G1-G32). */
#define MIPC_GX5_CONSTELLATION_ID_GPS ((mipc_gx5_constellation_id_t)0u)
/** SBAS (S120-S158). */
#define MIPC_GX5_CONSTELLATION_ID_SBAS ((mipc_gx5_constellation_id_t)1u)
/** Galileo (E1-E36). */
#define MIPC_GX5_CONSTELLATION_ID_GALILEO ((mipc_gx5_constellation_id_t)2u)
/** BeiDou (B1-B37). */
#define MIPC_GX5_CONSTELLATION_ID_BEIDOU ((mipc_gx5_constellation_id_t)3u)
/** QZSS (Q1-Q5). */
#define MIPC_GX5_CONSTELLATION_ID_QZSS ((mipc_gx5_constellation_id_t)5u)
/** GLONASS (R1-R32). */
#define MIPC_GX5_CONSTELLATION_ID_GLONASS ((mipc_gx5_constellation_id_t)6u)

/** Poll option selector. First byte of the GX5-45 poll commands; chooses whether the ACK/NACK is sent.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gx5_poll_option_t;
/** Normal ACK/NACK reply. */
#define MIPC_GX5_POLL_OPTION_NORMAL ((mipc_gx5_poll_option_t)0u)
/** No ACK/NACK reply; only the data packet is sent. */
#define MIPC_GX5_POLL_OPTION_SUPPRESS_ACK ((mipc_gx5_poll_option_t)1u)

/** Continuous data stream selector (GX5-45). Which data stream the GX5-45 Enable/Disable Continuous Data
 * Stream command controls. An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_gx5_stream_selector_t;
/** IMU data stream (set 0x80). */
#define MIPC_GX5_STREAM_SELECTOR_IMU ((mipc_gx5_stream_selector_t)1u)
/** Estimation filter data stream (set 0x82). */
#define MIPC_GX5_STREAM_SELECTOR_ESTIMATION_FILTER ((mipc_gx5_stream_selector_t)3u)

/** Allowed automatic heading alignment methods.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_heading_alignment_methods_t;
/** bit 0: Dual-antenna GNSS alignment. */
#define MIPC_HEADING_ALIGNMENT_METHODS_DUAL_ANTENNA_MASK ((mipc_heading_alignment_methods_t)0x1u)
#define MIPC_HEADING_ALIGNMENT_METHODS_DUAL_ANTENNA_SHIFT 0
/** bit 1: GNSS kinematic alignment: the GNSS velocity (above 2 m/s) determines the initial heading. */
#define MIPC_HEADING_ALIGNMENT_METHODS_KINEMATIC_MASK ((mipc_heading_alignment_methods_t)0x2u)
#define MIPC_HEADING_ALIGNMENT_METHODS_KINEMATIC_SHIFT 1
/** bit 2: The internal magnetometer determines the initial heading. */
#define MIPC_HEADING_ALIGNMENT_METHODS_MAGNETOMETER_MASK ((mipc_heading_alignment_methods_t)0x4u)
#define MIPC_HEADING_ALIGNMENT_METHODS_MAGNETOMETER_SHIFT 2
/** bit 3: An external heading input determines the initial heading. */
#define MIPC_HEADING_ALIGNMENT_METHODS_EXTERNAL_MASK ((mipc_heading_alignment_methods_t)0x8u)
#define MIPC_HEADING_ALIGNMENT_METHODS_EXTERNAL_SHIFT 3

/** Heading update source. Which aiding sources the filter uses for heading updates.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_heading_update_source_t;
/** No heading aiding; heading still converges from GNSS under sufficient acceleration. */
#define MIPC_HEADING_UPDATE_SOURCE_NONE ((mipc_heading_update_source_t)0u)
/** Internal magnetometer. */
#define MIPC_HEADING_UPDATE_SOURCE_MAGNETOMETER ((mipc_heading_update_source_t)1u)
/** Internal GNSS velocity vector (needs little side-slip and the vehicle X axis along the direction of
 * travel). */
#define MIPC_HEADING_UPDATE_SOURCE_GNSS_VELOCITY ((mipc_heading_update_source_t)2u)
/** External heading messages (0x0D,0x17 / 0x0D,0x1F). */
#define MIPC_HEADING_UPDATE_SOURCE_EXTERNAL ((mipc_heading_update_source_t)3u)
/** GNSS velocity vector and magnetometer. */
#define MIPC_HEADING_UPDATE_SOURCE_GNSS_VELOCITY_AND_MAGNETOMETER ((mipc_heading_update_source_t)4u)
/** GNSS velocity vector and external heading messages. */
#define MIPC_HEADING_UPDATE_SOURCE_GNSS_VELOCITY_AND_EXTERNAL ((mipc_heading_update_source_t)5u)
/** Magnetometer and external heading messages. */
#define MIPC_HEADING_UPDATE_SOURCE_MAGNETOMETER_AND_EXTERNAL ((mipc_heading_update_source_t)6u)
/** GNSS velocity vector, magnetometer and external heading messages. */
#define MIPC_HEADING_UPDATE_SOURCE_GNSS_VELOCITY_MAGNETOMETER_AND_EXTERNAL ((mipc_heading_update_source_t)7u)

/** Source of a magnetic field parameter (declination, inclination, magnitude). Where the filter takes a local
 * magnetic field parameter from: nowhere (a fixed fallback), the internal World Magnetic Model, or a value
 * the user supplies. An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_magnetic_param_source_t;
/** No source: no correction (declination, inclination) or a fixed 0.5 gauss (magnitude). */
#define MIPC_MAGNETIC_PARAM_SOURCE_NONE ((mipc_magnetic_param_source_t)1u)
/** Internal World Magnetic Model at the current position estimate (default). */
#define MIPC_MAGNETIC_PARAM_SOURCE_WMM ((mipc_magnetic_param_source_t)2u)
/** Value supplied by the user; the device does not validate it. */
#define MIPC_MAGNETIC_PARAM_SOURCE_MANUAL ((mipc_magnetic_param_source_t)3u)

/** Odometer data valid flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_odometer_data_valid_flags_t;
/** bit 0: Set when the odometer is configured (speed and uncertainty are valid). */
#define MIPC_ODOMETER_DATA_VALID_FLAGS_VALID_MASK ((mipc_odometer_data_valid_flags_t)0x1u)
#define MIPC_ODOMETER_DATA_VALID_FLAGS_VALID_SHIFT 0
/** bits 1-15: (reserved) Not described. */
#define MIPC_ODOMETER_DATA_VALID_FLAGS_RESERVED_MASK ((mipc_odometer_data_valid_flags_t)0xFFFEu)
#define MIPC_ODOMETER_DATA_VALID_FLAGS_RESERVED_SHIFT 1

/** Odometer mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_odometer_mode_t;
/** Encoder disabled. */
#define MIPC_ODOMETER_MODE_DISABLED ((mipc_odometer_mode_t)0u)
/** Quadrature encoder mode. */
#define MIPC_ODOMETER_MODE_QUADRATURE ((mipc_odometer_mode_t)2u)

/** Sensor over-range status. One bit per sensor axis that is near or beyond its range.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_overrange_status_flags_t;
/** bit 0: Accelerometer X axis over range. */
#define MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_X_MASK ((mipc_overrange_status_flags_t)0x1u)
#define MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_X_SHIFT 0
/** bit 1: Accelerometer Y axis over range. */
#define MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Y_MASK ((mipc_overrange_status_flags_t)0x2u)
#define MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Y_SHIFT 1
/** bit 2: Accelerometer Z axis over range. */
#define MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Z_MASK ((mipc_overrange_status_flags_t)0x4u)
#define MIPC_OVERRANGE_STATUS_FLAGS_ACCEL_Z_SHIFT 2
/** bit 3: (reserved) Not listed. */
#define MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_3_MASK ((mipc_overrange_status_flags_t)0x8u)
#define MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_3_SHIFT 3
/** bit 4: Gyroscope X axis over range. */
#define MIPC_OVERRANGE_STATUS_FLAGS_GYRO_X_MASK ((mipc_overrange_status_flags_t)0x10u)
#define MIPC_OVERRANGE_STATUS_FLAGS_GYRO_X_SHIFT 4
/** bit 5: Gyroscope Y axis over range. */
#define MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Y_MASK ((mipc_overrange_status_flags_t)0x20u)
#define MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Y_SHIFT 5
/** bit 6: Gyroscope Z axis over range. */
#define MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Z_MASK ((mipc_overrange_status_flags_t)0x40u)
#define MIPC_OVERRANGE_STATUS_FLAGS_GYRO_Z_SHIFT 6
/** bit 7: (reserved) Not listed. */
#define MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_7_MASK ((mipc_overrange_status_flags_t)0x80u)
#define MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_7_SHIFT 7
/** bit 8: Magnetometer X axis over range. */
#define MIPC_OVERRANGE_STATUS_FLAGS_MAG_X_MASK ((mipc_overrange_status_flags_t)0x100u)
#define MIPC_OVERRANGE_STATUS_FLAGS_MAG_X_SHIFT 8
/** bit 9: Magnetometer Y axis over range. */
#define MIPC_OVERRANGE_STATUS_FLAGS_MAG_Y_MASK ((mipc_overrange_status_flags_t)0x200u)
#define MIPC_OVERRANGE_STATUS_FLAGS_MAG_Y_SHIFT 9
/** bit 10: Magnetometer Z axis over range. */
#define MIPC_OVERRANGE_STATUS_FLAGS_MAG_Z_MASK ((mipc_overrange_status_flags_t)0x400u)
#define MIPC_OVERRANGE_STATUS_FLAGS_MAG_Z_SHIFT 10
/** bit 11: (reserved) Not listed. */
#define MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_11_MASK ((mipc_overrange_status_flags_t)0x800u)
#define MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_11_SHIFT 11
/** bit 12: Pressure sensor over range. */
#define MIPC_OVERRANGE_STATUS_FLAGS_PRESS_MASK ((mipc_overrange_status_flags_t)0x1000u)
#define MIPC_OVERRANGE_STATUS_FLAGS_PRESS_SHIFT 12
/** bits 13-15: (reserved) Not listed. */
#define MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_13_15_MASK ((mipc_overrange_status_flags_t)0xE000u)
#define MIPC_OVERRANGE_STATUS_FLAGS_RESERVED_13_15_SHIFT 13

/** Pitch/roll aiding source.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_pitch_roll_aiding_source_t;
/** No pitch/roll aiding (disabled). */
#define MIPC_PITCH_ROLL_AIDING_SOURCE_NONE ((mipc_pitch_roll_aiding_source_t)0u)
/** Gravity vector aiding enabled. */
#define MIPC_PITCH_ROLL_AIDING_SOURCE_GRAVITY_VECTOR ((mipc_pitch_roll_aiding_source_t)1u)

/** PPS source.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_pps_source_t;
/** No PPS (the table says it is not valid as a command value; see note). */
#define MIPC_PPS_SOURCE_DISABLED ((mipc_pps_source_t)0u)
/** PPS from GNSS receiver 1. */
#define MIPC_PPS_SOURCE_RECEIVER_1 ((mipc_pps_source_t)1u)
/** PPS from GNSS receiver 2. */
#define MIPC_PPS_SOURCE_RECEIVER_2 ((mipc_pps_source_t)2u)
/** PPS applied to a GPIO pin (pin chosen with GPIO Configuration 0x0C,0x41). */
#define MIPC_PPS_SOURCE_GPIO ((mipc_pps_source_t)3u)
/** PPS generated from the system oscillator. */
#define MIPC_PPS_SOURCE_GENERATED ((mipc_pps_source_t)4u)

/** Filter reference point.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_reference_point_selector_t;
/** The origin of the vehicle (the only value; the parameter is reserved and must be 1). */
#define MIPC_REFERENCE_POINT_SELECTOR_VEH ((mipc_reference_point_selector_t)1u)

/** Reference location source for relative position outputs.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_relative_position_source_t;
/** Automatic: the RTK base station location. */
#define MIPC_RELATIVE_POSITION_SOURCE_AUTO ((mipc_relative_position_source_t)0u)
/** The reference coordinates given in the command. */
#define MIPC_RELATIVE_POSITION_SOURCE_MANUAL ((mipc_relative_position_source_t)1u)

/** RTK corrections epoch status. Status of the corrections received during the epoch.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_rtk_corrections_epoch_status_t;
/** bit 0: Antenna location (station coordinates) received. */
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_LOCATION_RECEIVED_MASK                                     \
    ((mipc_rtk_corrections_epoch_status_t)0x1u)
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_LOCATION_RECEIVED_SHIFT 0
/** bit 1: Antenna description received. */
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_DESCRIPTION_RECEIVED_MASK                                  \
    ((mipc_rtk_corrections_epoch_status_t)0x2u)
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_ANTENNA_DESCRIPTION_RECEIVED_SHIFT 1
/** bit 2: GPS corrections received. */
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GPS_RECEIVED_MASK ((mipc_rtk_corrections_epoch_status_t)0x4u)
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GPS_RECEIVED_SHIFT 2
/** bit 3: GLONASS corrections received. */
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GLONASS_RECEIVED_MASK ((mipc_rtk_corrections_epoch_status_t)0x8u)
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GLONASS_RECEIVED_SHIFT 3
/** bit 4: Galileo corrections received. */
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GALILEO_RECEIVED_MASK ((mipc_rtk_corrections_epoch_status_t)0x10u)
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_GALILEO_RECEIVED_SHIFT 4
/** bit 5: BeiDou corrections received. */
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_BEIDOU_RECEIVED_MASK ((mipc_rtk_corrections_epoch_status_t)0x20u)
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_BEIDOU_RECEIVED_SHIFT 5
/** bit 6: GPS corrections come from MSM messages rather than RTCM 1001-1004. */
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GPS_MSM_MESSAGES_MASK                                        \
    ((mipc_rtk_corrections_epoch_status_t)0x40u)
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GPS_MSM_MESSAGES_SHIFT 6
/** bit 7: GLONASS corrections come from MSM messages rather than RTCM 1009-1012. */
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GLONASS_MSM_MESSAGES_MASK                                    \
    ((mipc_rtk_corrections_epoch_status_t)0x80u)
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_USING_GLONASS_MSM_MESSAGES_SHIFT 7
/** bit 8: Reading the dongle status was attempted and failed. */
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_DONGLE_STATUS_READ_FAILED_MASK                                     \
    ((mipc_rtk_corrections_epoch_status_t)0x100u)
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_DONGLE_STATUS_READ_FAILED_SHIFT 8
/** bits 9-15: (reserved) Not named by the manual. */
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_RESERVED_MASK ((mipc_rtk_corrections_epoch_status_t)0xFE00u)
#define MIPC_RTK_CORRECTIONS_EPOCH_STATUS_RESERVED_SHIFT 9

/** RTK corrections status valid flags. Which parameters of the RTK corrections status field are valid.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_rtk_corrections_status_valid_flags_t;
/** bit 0: Time of week valid. */
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_TOW_MASK ((mipc_rtk_corrections_status_valid_flags_t)0x1u)
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_TOW_SHIFT 0
/** bit 1: Week number valid. */
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_WEEK_NUMBER_MASK                                             \
    ((mipc_rtk_corrections_status_valid_flags_t)0x2u)
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_WEEK_NUMBER_SHIFT 1
/** bit 2: Epoch status valid. */
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_EPOCH_STATUS_MASK                                            \
    ((mipc_rtk_corrections_status_valid_flags_t)0x4u)
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_EPOCH_STATUS_SHIFT 2
/** bit 3: Dongle status valid. */
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_DONGLE_STATUS_MASK                                           \
    ((mipc_rtk_corrections_status_valid_flags_t)0x8u)
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_DONGLE_STATUS_SHIFT 3
/** bit 4: GPS correction latency valid. */
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GPS_LATENCY_MASK                                             \
    ((mipc_rtk_corrections_status_valid_flags_t)0x10u)
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GPS_LATENCY_SHIFT 4
/** bit 5: GLONASS correction latency valid. */
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GLONASS_LATENCY_MASK                                         \
    ((mipc_rtk_corrections_status_valid_flags_t)0x20u)
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GLONASS_LATENCY_SHIFT 5
/** bit 6: Galileo correction latency valid. */
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GALILEO_LATENCY_MASK                                         \
    ((mipc_rtk_corrections_status_valid_flags_t)0x40u)
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_GALILEO_LATENCY_SHIFT 6
/** bit 7: BeiDou correction latency valid. */
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_BEIDOU_LATENCY_MASK                                          \
    ((mipc_rtk_corrections_status_valid_flags_t)0x80u)
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_BEIDOU_LATENCY_SHIFT 7
/** bits 0-7: All flags. */
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_FLAGS_MASK ((mipc_rtk_corrections_status_valid_flags_t)0xFFu)
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_FLAGS_SHIFT 0
/** bits 8-15: (reserved) Not named by the manual. */
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_RESERVED_MASK                                                \
    ((mipc_rtk_corrections_status_valid_flags_t)0xFF00u)
#define MIPC_RTK_CORRECTIONS_STATUS_VALID_FLAGS_RESERVED_SHIFT 8

/** SBAS options.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_sbas_options_t;
/** bit 0: Use SBAS pseudoranges in the position solution (GX5-45 default on). */
#define MIPC_SBAS_OPTIONS_ENABLE_RANGING_MASK ((mipc_sbas_options_t)0x1u)
#define MIPC_SBAS_OPTIONS_ENABLE_RANGING_SHIFT 0
/** bit 1: Use SBAS differential corrections (GX5-45 default on). */
#define MIPC_SBAS_OPTIONS_ENABLE_CORRECTIONS_MASK ((mipc_sbas_options_t)0x2u)
#define MIPC_SBAS_OPTIONS_ENABLE_CORRECTIONS_SHIFT 1
/** bit 2: Use SBAS integrity information; only satellites with integrity data are used. */
#define MIPC_SBAS_OPTIONS_APPLY_INTEGRITY_MASK ((mipc_sbas_options_t)0x4u)
#define MIPC_SBAS_OPTIONS_APPLY_INTEGRITY_SHIFT 2

/** Sensor GPS timestamp flags (0x80,0x12). Status of the GPS timestamp attached to sensor data. Bits 0-2 mean
 * the same on both devices (the GX5-45 calls them PPS Beacon Good, GPS Time Refresh and GPS Time
 * Initialized); bits 3 and 4 exist only on the CV7. The whole integer is kept (reserved bits too); members
 * are read with the masks below: (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_sensor_gps_timestamp_flags_t;
/** bit 0: PPS signal present (GX5-45: PPS Beacon Good); when clear the internal clock stands in for the PPS.
 */
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_PPS_VALID_MASK ((mipc_sensor_gps_timestamp_flags_t)0x1u)
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_PPS_VALID_SHIFT 0
/** bit 1: Toggles each time the time is updated (GPS time, or the GPS Time Update command 0x01,0x72). */
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_REFRESH_MASK ((mipc_sensor_gps_timestamp_flags_t)0x2u)
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_REFRESH_SHIFT 1
/** bit 2: Set once the time has been set at least once (the first time refresh); stays set. */
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_INITIALIZED_MASK ((mipc_sensor_gps_timestamp_flags_t)0x4u)
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TIME_INITIALIZED_SHIFT 2
/** bit 3: Time of week is valid. (devices: cv7_ins) */
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TOW_VALID_MASK ((mipc_sensor_gps_timestamp_flags_t)0x8u)
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_TOW_VALID_SHIFT 3
/** bit 4: Week number is valid. (devices: cv7_ins) */
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_WEEK_NUMBER_VALID_MASK ((mipc_sensor_gps_timestamp_flags_t)0x10u)
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_WEEK_NUMBER_VALID_SHIFT 4
/** bits 5-15: (reserved) Not defined by either manual (GX5-45: bits 3-15). */
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_RESERVED_MASK ((mipc_sensor_gps_timestamp_flags_t)0xFFE0u)
#define MIPC_SENSOR_GPS_TIMESTAMP_FLAGS_RESERVED_SHIFT 5

/** Sensor whose range is set or queried.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_sensor_range_type_t;
/** All sensors; only with save, load and default. */
#define MIPC_SENSOR_RANGE_TYPE_ALL ((mipc_sensor_range_type_t)0u)
/** Accelerometer; range in g. */
#define MIPC_SENSOR_RANGE_TYPE_ACCEL ((mipc_sensor_range_type_t)1u)
/** Gyroscope; range in degrees/s. */
#define MIPC_SENSOR_RANGE_TYPE_GYRO ((mipc_sensor_range_type_t)2u)
/** Magnetometer; range in Gauss. */
#define MIPC_SENSOR_RANGE_TYPE_MAG ((mipc_sensor_range_type_t)3u)
/** Pressure sensor; range in hPa. */
#define MIPC_SENSOR_RANGE_TYPE_PRESS ((mipc_sensor_range_type_t)4u)

/** Shared GPS timestamp valid flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mipc_shared_gps_timestamp_valid_flags_t;
/** bit 0: The whole-second time of week has been set. */
#define MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TOW_MASK ((mipc_shared_gps_timestamp_valid_flags_t)0x1u)
#define MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TOW_SHIFT 0
/** bit 1: The week number has been set. */
#define MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_WEEK_NUMBER_MASK ((mipc_shared_gps_timestamp_valid_flags_t)0x2u)
#define MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_WEEK_NUMBER_SHIFT 1
/** bits 0-1: Both time of week and week number have been set. */
#define MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TIME_VALID_MASK ((mipc_shared_gps_timestamp_valid_flags_t)0x3u)
#define MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_TIME_VALID_SHIFT 0
/** bits 2-15: (reserved) Not listed. */
#define MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_RESERVED_MASK ((mipc_shared_gps_timestamp_valid_flags_t)0xFFFCu)
#define MIPC_SHARED_GPS_TIMESTAMP_VALID_FLAGS_RESERVED_SHIFT 2

/** SPARTN connection type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_spartn_connection_type_t;
/** No SPARTN connection. */
#define MIPC_SPARTN_CONNECTION_TYPE_NONE ((mipc_spartn_connection_type_t)0u)
/** Corrections over a network connection (e.g. NTRIP). */
#define MIPC_SPARTN_CONNECTION_TYPE_NETWORK ((mipc_spartn_connection_type_t)1u)
/** Corrections from an L-band correction receiver. */
#define MIPC_SPARTN_CONNECTION_TYPE_L_BAND ((mipc_spartn_connection_type_t)2u)

/** Supported events query.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_supported_events_query_t;
/** Report the supported trigger types and how many of each. */
#define MIPC_SUPPORTED_EVENTS_QUERY_TRIGGER_TYPES ((mipc_supported_events_query_t)1u)
/** Report the supported action types and how many of each. */
#define MIPC_SUPPORTED_EVENTS_QUERY_ACTION_TYPES ((mipc_supported_events_query_t)2u)

/** Communication mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_system_comm_mode_t;
/** 3DM-GX5-45 MIP packets (default). */
#define MIPC_SYSTEM_COMM_MODE_STANDARD ((mipc_system_comm_mode_t)1u)
/** Direct to the internal IMU: MIP IMU protocol. */
#define MIPC_SYSTEM_COMM_MODE_SENSOR_DIRECT ((mipc_system_comm_mode_t)2u)
/** Direct to the GNSS receiver: NMEA and UBX (GNSS models only). */
#define MIPC_SYSTEM_COMM_MODE_GNSS_DIRECT ((mipc_system_comm_mode_t)3u)

/** Tare orientation axes. Axes to tare; 0 (no bit set) resets all axes.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_tare_axes_t;
/** bit 0: Tare the roll axis. */
#define MIPC_TARE_AXES_ROLL_MASK ((mipc_tare_axes_t)0x1u)
#define MIPC_TARE_AXES_ROLL_SHIFT 0
/** bit 1: Tare the pitch axis. */
#define MIPC_TARE_AXES_PITCH_MASK ((mipc_tare_axes_t)0x2u)
#define MIPC_TARE_AXES_PITCH_SHIFT 1
/** bit 2: Tare the yaw axis. */
#define MIPC_TARE_AXES_YAW_MASK ((mipc_tare_axes_t)0x4u)
#define MIPC_TARE_AXES_YAW_SHIFT 2

/** Threshold comparison type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_threshold_type_t;
/** Active if low_thres <= value <= high_thres (reversed thresholds invert it). */
#define MIPC_THRESHOLD_TYPE_WINDOW ((mipc_threshold_type_t)1u)
/** Active when (value % high_thres) <= low_thres: periodic triggering. */
#define MIPC_THRESHOLD_TYPE_INTERVAL ((mipc_threshold_type_t)2u)

/** GPIO trigger mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_trigger_gpio_mode_t;
/** The pin has no effect and the trigger never activates. */
#define MIPC_TRIGGER_GPIO_MODE_DISABLED ((mipc_trigger_gpio_mode_t)0u)
/** Active while the pin is high. */
#define MIPC_TRIGGER_GPIO_MODE_WHILE_HIGH ((mipc_trigger_gpio_mode_t)1u)
/** Active while the pin is low. */
#define MIPC_TRIGGER_GPIO_MODE_WHILE_LOW ((mipc_trigger_gpio_mode_t)2u)
/** Use if the pin is configured for timestamping (0x0C,0x41). */
#define MIPC_TRIGGER_GPIO_MODE_EDGE ((mipc_trigger_gpio_mode_t)4u)

/** Event trigger status.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mipc_trigger_status_t;
/** bit 0: The trigger is currently active (by its logic or in test mode). */
#define MIPC_TRIGGER_STATUS_ACTIVE_MASK ((mipc_trigger_status_t)0x1u)
#define MIPC_TRIGGER_STATUS_ACTIVE_SHIFT 0
/** bit 1: The trigger is enabled. */
#define MIPC_TRIGGER_STATUS_ENABLED_MASK ((mipc_trigger_status_t)0x2u)
#define MIPC_TRIGGER_STATUS_ENABLED_SHIFT 1
/** bit 2: The trigger is in test mode. */
#define MIPC_TRIGGER_STATUS_TEST_MASK ((mipc_trigger_status_t)0x4u)
#define MIPC_TRIGGER_STATUS_TEST_SHIFT 2

/** Event trigger type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_trigger_type_t;
/** No trigger selected. The state will always be inactive. */
#define MIPC_TRIGGER_TYPE_NONE ((mipc_trigger_type_t)0u)
/** Trigger based on the state of a GPIO pin. */
#define MIPC_TRIGGER_TYPE_GPIO ((mipc_trigger_type_t)1u)
/** Compare a data quantity against a high and low threshold. */
#define MIPC_TRIGGER_TYPE_THRESHOLD ((mipc_trigger_type_t)2u)
/** Logical combination of two or more triggers. */
#define MIPC_TRIGGER_TYPE_COMBINATION ((mipc_trigger_type_t)3u)

/** Vehicle dynamics mode. Dynamics model the filter assumes for the vehicle (altitude and velocity limits).
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mipc_vehicle_dynamics_mode_t;
/** Low-acceleration applications (default); up to 12,000 m, 310 m/s horizontal, 50 m/s vertical. */
#define MIPC_VEHICLE_DYNAMICS_MODE_PORTABLE ((mipc_vehicle_dynamics_mode_t)1u)
/** Wheeled vehicles with low vertical acceleration; up to 6,000 m, 84 m/s horizontal, 15 m/s vertical. */
#define MIPC_VEHICLE_DYNAMICS_MODE_AUTOMOTIVE ((mipc_vehicle_dynamics_mode_t)2u)
/** Airborne up to 2 g; up to 50,000 m, 250 m/s horizontal, 100 m/s vertical. */
#define MIPC_VEHICLE_DYNAMICS_MODE_AIRBORNE ((mipc_vehicle_dynamics_mode_t)3u)
/** Airborne up to 4 g; same altitude and velocity limits as airborne. */
#define MIPC_VEHICLE_DYNAMICS_MODE_AIRBORNE_HIGH_G ((mipc_vehicle_dynamics_mode_t)4u)

/** ActionGpioParams.  */
typedef struct {
    uint8_t pin;                  /* GPIO pin number. */
    mipc_action_gpio_mode_t mode; /* Behavior of the pin. */
} mipc_action_gpio_params_t;

/** MessageParams.  */
typedef struct {
    uint8_t desc_set;        /* MIP data descriptor set. */
    uint16_t decimation;     /* Decimation from the base rate; 0 emits one packet per activation. */
    uint8_t num_fields;      /* Number of fields in the packet (at most 12). */
    uint8_t descriptors[12]; /* Field descriptors. */
} mipc_message_params_t;

/** ActionParams.
 * The member is chosen by a parameter of type mipc_action_type_t next to it. */
typedef union {
    mipc_action_gpio_params_t gpio; /* gpio:  */
    mipc_message_params_t message;  /* message:  */
    uint8_t none_;                  /* members without data */
} mipc_action_params_t;

/** ActionStatusEntry.  */
typedef struct {
    mipc_action_type_t action_type; /* Configured action type. */
    uint8_t trigger_id;             /* Associated trigger instance. */
} mipc_action_status_entry_t;

/** Aiding frame rotation as Euler angles.  */
typedef struct {
    float
        euler[3]; /* Roll, pitch, yaw of the frame relative to the vehicle frame, each within +/- pi. [rad] */
} mipc_aiding_frame_euler_t;

/** Aiding frame rotation as a quaternion.  */
typedef struct {
    float quaternion[4]; /* Rotation of the frame relative to the vehicle frame, (w, x, y, z). */
} mipc_aiding_frame_quaternion_t;

/** Aiding frame rotation. Rotation of an aiding frame, as Euler angles or as a quaternion depending on the
 * format. The member is chosen by a parameter of type mipc_aiding_frame_format_t next to it. */
typedef union {
    mipc_aiding_frame_euler_t euler;           /* euler:  */
    mipc_aiding_frame_quaternion_t quaternion; /* quaternion:  */
    uint8_t none_;                             /* members without data */
} mipc_aiding_frame_rotation_t;

/** Aiding measurement timestamp. Timestamp carried first in every aiding measurement command. */
typedef struct {
    mipc_aiding_timebase_t timebase; /* Clock of the timestamp. */
    uint8_t reserved;                /* Reserved. */
    uint64_t nanoseconds; /* Time of the measurement in nanoseconds, in the timebase's clock. [ns] */
} mipc_aiding_time_t;

/** CombinationParams.  */
typedef struct {
    uint16_t logic_table;      /* Last column of the truth table of the inputs. */
    uint8_t input_triggers[4]; /* Trigger IDs of the inputs; 0 for unused inputs. */
} mipc_combination_params_t;

/** GNSS constellation configuration entry.  */
typedef struct {
    mipc_gx5_constellation_id_t constellation_id; /* Constellation. */
    uint8_t enable;                               /* 0x00 disable, 0x01 enable. */
    uint8_t reserved_channels; /* Tracking channels reserved for this constellation (0-32; all constellations
                                  together at most 32). */
    uint8_t max_channels;      /* Maximum tracking channels for this constellation (0-32, not below
                                  reserved_channels). */
    mipc_constellation_options_t option_flags; /* Constellation options. */
} mipc_constellation_settings_t;

/** 3DM-CV7 continuous built-in test result (128 bits). The 16-byte continuous BIT bit map, one member per
 * byte in wire order. Bit n of the map is bit (n mod 8) of byte n div 8 ("Relative Index (Byte.Bit)"). Bytes
 * 0-3 are system bits, 4-7 IMU bits, 8-11 navigation filter bits and 12-15 GNSS bits. The bits latch until
 * the message is sent; all unspecified bits are reserved and must be ignored. */
typedef struct {
    mipc_cv7_continuous_bit_system0_t system_byte_0; /* Bits 0-7: system. */
    uint8_t reserved_byte_1;                         /* Bits 8-15: reserved (0.7-1.7). */
    mipc_cv7_continuous_bit_system2_t system_byte_2; /* Bits 16-23: IMU and filter process faults. */
    mipc_cv7_continuous_bit_system3_t system_byte_3; /* Bits 24-31: GNSS process faults. */
    mipc_cv7_continuous_bit_imu4_t imu_byte_4;       /* Bits 32-39: IMU communication, timing, calibration. */
    mipc_cv7_continuous_bit_imu5_t imu_byte_5;       /* Bits 40-47: accelerometer and gyroscope. */
    mipc_cv7_continuous_bit_imu6_t imu_byte_6;       /* Bits 48-55: magnetometer and pressure sensor. */
    mipc_cv7_continuous_bit_imu7_t imu_byte_7;       /* Bits 56-63: factory bits. */
    mipc_cv7_continuous_bit_nav8_t nav_byte_8;       /* Bits 64-71: filter timing. */
    uint8_t reserved_byte_9;                         /* Bits 72-79: reserved. */
    uint8_t reserved_byte_10;                        /* Bits 80-87: reserved. */
    uint8_t reserved_byte_11;                        /* Bits 88-95: reserved. */
    uint8_t reserved_byte_12;                        /* Bits 96-103: reserved. */
    mipc_cv7_continuous_bit_gnss13_t gnss_byte_13;   /* Bits 104-111: GNSS receivers. */
    mipc_cv7_continuous_bit_gnss14_t gnss_byte_14;   /* Bits 112-119: GNSS receivers. */
    uint8_t reserved_byte_15;                        /* Bits 120-127: reserved. */
} mipc_cv7_continuous_bit_t;

/** Descriptor and rate decimation. One entry of a message format list. */
typedef struct {
    uint8_t descriptor;  /* Data field descriptor. */
    uint16_t decimation; /* Rate decimation: the field is output at base rate / decimation. */
} mipc_descriptor_rate_t;

/** Device information. Firmware version and five 16-character identification strings, padded with spaces. */
typedef struct {
    uint16_t firmware_version; /* Firmware version number. */
    char model_name[16];       /* Model name. */
    char model_number[16];     /* Model number. */
    char serial_number[16];    /* Serial number. */
    char lot_number[16];       /* Lot number. */
    char device_options[16];   /* Device options (e.g. sensor ranges). */
} mipc_device_info_t;

/** GNSS receiver information. Identity of one physical GNSS receiver in the device. */
typedef struct {
    uint8_t receiver_id;             /* Receiver id (1, 2, ...). */
    uint8_t mip_data_descriptor_set; /* MIP data descriptor set of this receiver's data. */
    char description[32];            /* ASCII, comma-delimited: module name/model, firmware version. */
} mipc_gnss_receiver_info_entry_t;

/** GpioBehaviorUnused.  */
typedef struct {
    mipc_gpio_unused_behavior_t behavior; /* Behavior value (0). */
} mipc_gpio_behavior_unused_t;

/** GpioBehaviorIo.  */
typedef struct {
    mipc_gpio_io_behavior_t behavior; /* Input, or output with its initial state. */
} mipc_gpio_behavior_io_t;

/** GpioBehaviorPps.  */
typedef struct {
    mipc_gpio_pps_behavior_t behavior; /* PPS input or output. */
} mipc_gpio_behavior_pps_t;

/** GpioBehaviorEncoder.  */
typedef struct {
    mipc_gpio_encoder_behavior_t behavior; /* Quadrature channel A or B. */
} mipc_gpio_behavior_encoder_t;

/** GpioBehaviorTimestamp.  */
typedef struct {
    mipc_gpio_timestamp_behavior_t behavior; /* Which edges are timestamped. */
} mipc_gpio_behavior_timestamp_t;

/** GpioBehaviorUart.  */
typedef struct {
    mipc_gpio_uart_behavior_t behavior; /* UART port and direction. */
} mipc_gpio_behavior_uart_t;

/** GPIO behavior, read according to the feature. The behavior byte's meaning depends on the feature: the same
 * number names a different behavior per feature (2 is GPIO_OUTPUT_LOW for GPIO, PPS_OUTPUT for PPS, ENCODER_B
 * for ENCODER, TIMESTAMP_FALLING for TIMESTAMP). Every member is one u8. The member is chosen by a parameter
 * of type mipc_gpio_feature_t next to it. */
typedef union {
    mipc_gpio_behavior_unused_t unused; /* unused: Feature UNUSED: behavior 0. */
    mipc_gpio_behavior_io_t gpio; /* gpio: Feature GPIO: GPIO_INPUT / GPIO_OUTPUT_LOW / GPIO_OUTPUT_HIGH. */
    mipc_gpio_behavior_pps_t pps; /* pps: Feature PPS: PPS_INPUT / PPS_OUTPUT. */
    mipc_gpio_behavior_encoder_t encoder; /* encoder: Feature ENCODER: ENCODER_A / ENCODER_B. */
    mipc_gpio_behavior_timestamp_t
        timestamp;                  /* timestamp: Feature TIMESTAMP: TIMESTAMP_RISING / _FALLING / _EITHER. */
    mipc_gpio_behavior_uart_t uart; /* uart: Feature UART: UART_PORT2_TX/RX, UART_PORT3_TX/RX. */
    uint8_t none_;                  /* members without data */
} mipc_gpio_behavior_t;

/** GX5-45 basic device status. Remainder of the basic device status reply after the model number and selector
 * echoes. */
typedef struct {
    uint32_t status_flags; /* Status flags (reserved). */
    uint16_t system_state; /* System state (values not documented). */
    uint32_t system_timer; /* Time since start-up. [ms] */
} mipc_gx5_basic_status_t;

/** GX5-45 diagnostic device status. Remainder of the diagnostic device status reply after the model number
 * and selector echoes. */
typedef struct {
    uint32_t status_flags;           /* Status flags (reserved). */
    uint16_t system_state;           /* System state (values not documented). */
    uint32_t system_timer;           /* Time since start-up. [ms] */
    uint8_t gnss_power_state;        /* GNSS receiver power: 1 on, 0 off. */
    uint32_t pps_pulse_count;        /* Number of 1PPS pulses received. [count] */
    uint32_t last_pps_time;          /* System timer value at the last 1PPS pulse. [ms] */
    uint8_t imu_stream_enabled;      /* IMU stream: 1 on, 0 off. */
    uint8_t gnss_stream_enabled;     /* GNSS stream: 1 on, 0 off. */
    uint8_t filter_stream_enabled;   /* Estimation filter stream: 1 on, 0 off. */
    uint32_t imu_dropped_packets;    /* Outgoing IMU stream packets dropped. [count] */
    uint32_t gnss_dropped_packets;   /* Outgoing GNSS stream packets dropped. [count] */
    uint32_t filter_dropped_packets; /* Outgoing estimation filter stream packets dropped. [count] */
    uint32_t com_bytes_written;      /* Bytes written to the com port. [count] */
    uint32_t com_bytes_read;         /* Bytes read from the com port. [count] */
    uint32_t com_write_overruns;     /* Overruns when writing to the com port. [count] */
    uint32_t imu_parse_errors;       /* IMU message parsing errors. [count] */
    uint32_t imu_messages_read;      /* IMU messages read in total. [count] */
    uint32_t last_imu_message_time;  /* System timer value at the last IMU message read. [ms] */
    uint32_t gnss_parse_errors;      /* GNSS message parsing errors. [count] */
    uint32_t gnss_messages_read;     /* GNSS messages read in total. [count] */
    uint32_t last_gnss_message_time; /* System timer value at the last GNSS message read. [ms] */
} mipc_gx5_diagnostic_status_t;

/** GX5-45 device status structure.
 * The member is chosen by a parameter of type mipc_device_status_selector_t next to it. */
typedef union {
    mipc_gx5_basic_status_t basic;           /* basic:  */
    mipc_gx5_diagnostic_status_t diagnostic; /* diagnostic:  */
    uint8_t none_;                           /* members without data */
} mipc_gx5_device_status_t;

/** Poll format entry (GX5-45).  */
typedef struct {
    uint8_t descriptor; /* Data field descriptor to include in the polled packet. */
    uint16_t reserved;  /* Reserved; 0 in every example. */
} mipc_gx5_poll_descriptor_t;

/** NMEA message format entry.  */
typedef struct {
    uint8_t message_id; /* NMEA sentence type (GGA, GLL, GSV, RMC, VTG, HDT, ZDA, GST, PMSRA, PMSRR; codes not
                           documented). */
    uint8_t talker_id;  /* Talker ID (GN, GP, GA, GL; ignored for GSV and proprietary sentences; codes not
                           documented). */
    uint8_t source_desc_set; /* Data descriptor set the sentence is built from (IMU, filter, GNSS 1 or 2). */
    uint16_t decimation;     /* Decimation relative to the base rate of the source descriptor set. */
} mipc_nmea_message_t;

/** Calibrated sensor range entry.  */
typedef struct {
    uint8_t setting; /* Value to use as setting in Sensor Range (0x0C,0x52). */
    float range;     /* Range this setting gives; units depend on the sensor (see SensorRangeType). */
} mipc_sensor_range_entry_t;

/** Supported action type.  */
typedef struct {
    mipc_action_type_t type; /* Action type, as in Event Action Configuration (0x0C,0x2F). */
    uint8_t count;           /* Maximum number of instances of this type. */
} mipc_supported_action_type_t;

/** Supported actions (query = action types).  */
typedef struct {
    uint8_t max_instances; /* Number of action slots; instance numbers run 1..max_instances. */
    uint8_t num_entries;   /* Number of supported action types. */
    mipc_supported_action_type_t entries[125]; /* Supported action types. */
} mipc_supported_actions_t;

/** Supported trigger type.  */
typedef struct {
    mipc_trigger_type_t type; /* Trigger type, as in Event Trigger Configuration (0x0C,0x2E). */
    uint8_t count;            /* Maximum number of instances of this type. */
} mipc_supported_trigger_type_t;

/** Supported triggers (query = trigger types).  */
typedef struct {
    uint8_t max_instances; /* Number of trigger slots; instance numbers run 1..max_instances. */
    uint8_t num_entries;   /* Number of supported trigger types. */
    mipc_supported_trigger_type_t entries[125]; /* Supported trigger types. */
} mipc_supported_triggers_t;

/** Supported event types, by query.
 * The member is chosen by a parameter of type mipc_supported_events_query_t next to it. */
typedef union {
    mipc_supported_triggers_t trigger_types; /* trigger_types:  */
    mipc_supported_actions_t action_types;   /* action_types:  */
    uint8_t none_;                           /* members without data */
} mipc_supported_events_info_t;

/** ThresholdParams.  */
typedef struct {
    uint8_t desc_set;           /* Descriptor set of the target data quantity. */
    uint8_t field_desc;         /* Field descriptor of the target data quantity. */
    uint8_t param_id;           /* 1-based index of the target parameter within the field. */
    mipc_threshold_type_t type; /* Type of comparison. */
    double low_thres;           /* Low threshold (window) or active time (interval). */
    double high_thres;          /* High threshold (window) or interval (interval). */
} mipc_threshold_params_t;

/** TriggerGpioParams.  */
typedef struct {
    uint8_t pin;                   /* GPIO pin number. */
    mipc_trigger_gpio_mode_t mode; /* How the pin state affects the trigger. */
} mipc_trigger_gpio_params_t;

/** TriggerParams.
 * The member is chosen by a parameter of type mipc_trigger_type_t next to it. */
typedef union {
    mipc_trigger_gpio_params_t gpio;       /* gpio:  */
    mipc_threshold_params_t threshold;     /* threshold:  */
    mipc_combination_params_t combination; /* combination:  */
    uint8_t none_;                         /* members without data */
} mipc_trigger_params_t;

/** TriggerStatusEntry.  */
typedef struct {
    mipc_trigger_type_t type;     /* Configured trigger type. */
    mipc_trigger_status_t status; /* Trigger status. */
} mipc_trigger_status_entry_t;

#ifdef __cplusplus
}
#endif

#endif
