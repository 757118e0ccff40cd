/* Named types of the MicroStrain MIP protocol: enums, bitfields, structs and unions.
 * Generated from the spec: do not edit. */
#ifndef MIP_TYPES_H
#define MIP_TYPES_H

#include "mipcodec/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Ack/Nack code. Second byte of the ack/nack field; 0 is an ACK, any other value a NACK giving the reason.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_ack_code_t;
#define MIP_ACK_CODE_OK ((mip_ack_code_t)0u) /* Success (ACK). */
#define MIP_ACK_CODE_UNKNOWN_COMMAND                                                                         \
    ((mip_ack_code_t)1u) /* The command descriptor is not supported by this device. */
#define MIP_ACK_CODE_BAD_CHECKSUM                                                                            \
    ((mip_ack_code_t)2u) /* An otherwise complete packet has a bad checksum (GX5-45: invalid checksum). */
#define MIP_ACK_CODE_INVALID_PARAMETER                                                                       \
    ((mip_ack_code_t)3u) /* One or more parameters are invalid: out of the allowed range, or not the         \
                            expected size or type. */
#define MIP_ACK_CODE_COMMAND_FAILED ((mip_ack_code_t)4u) /* Device could not complete the command. */
#define MIP_ACK_CODE_COMMAND_TIMEOUT                                                                         \
    ((mip_ack_code_t)5u) /* Device could not complete the command within the expected time. */
#define MIP_ACK_CODE_UNKNOWN_DESCRIPTOR_SET                                                                  \
    ((mip_ack_code_t)6u) /* Unknown descriptor set (CV7 only). (devices: cv7_ins) */

/** GPIO action mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_action_gpio_mode_t;
#define MIP_ACTION_GPIO_MODE_DISABLED ((mip_action_gpio_mode_t)0u) /* Pin state will not be changed. */
#define MIP_ACTION_GPIO_MODE_ACTIVE_HIGH                                                                     \
    ((mip_action_gpio_mode_t)1u) /* High while the trigger is active, low otherwise. */
#define MIP_ACTION_GPIO_MODE_ACTIVE_LOW                                                                      \
    ((mip_action_gpio_mode_t)2u) /* Low while the trigger is active, high otherwise. */
#define MIP_ACTION_GPIO_MODE_ONESHOT_HIGH                                                                    \
    ((mip_action_gpio_mode_t)5u) /* Set high each time the trigger activates. */
#define MIP_ACTION_GPIO_MODE_ONESHOT_LOW                                                                     \
    ((mip_action_gpio_mode_t)6u) /* Set low each time the trigger activates. */
#define MIP_ACTION_GPIO_MODE_TOGGLE ((mip_action_gpio_mode_t)7u) /* Toggle each time the trigger activates.  \
                                                                  */

/** Event action type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_action_type_t;
#define MIP_ACTION_TYPE_NONE ((mip_action_type_t)0u)    /* No action. Parameters should be empty. */
#define MIP_ACTION_TYPE_GPIO ((mip_action_type_t)1u)    /* Control the state of a GPIO pin. */
#define MIP_ACTION_TYPE_MESSAGE ((mip_action_type_t)2u) /* Output a data packet. */

/** Auto-adaptive filter operating level.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_adaptive_filter_level_t;
#define MIP_ADAPTIVE_FILTER_LEVEL_OFF ((mip_adaptive_filter_level_t)0u)          /* Adaptive filtering off. */
#define MIP_ADAPTIVE_FILTER_LEVEL_CONSERVATIVE ((mip_adaptive_filter_level_t)1u) /* Conservative. */
#define MIP_ADAPTIVE_FILTER_LEVEL_MODERATE ((mip_adaptive_filter_level_t)2u)     /* Moderate (default). */
#define MIP_ADAPTIVE_FILTER_LEVEL_AGGRESSIVE ((mip_adaptive_filter_level_t)3u)   /* Aggressive. */

/** Adaptive measurement mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_adaptive_measurement_mode_t;
#define MIP_ADAPTIVE_MEASUREMENT_MODE_DISABLED                                                               \
    ((mip_adaptive_measurement_mode_t)0u) /* No adaptive measurement. */
#define MIP_ADAPTIVE_MEASUREMENT_MODE_FIXED                                                                  \
    ((mip_adaptive_measurement_mode_t)1u) /* Fixed adaptive measurement using the specified filter and limit \
                                             parameters. */
#define MIP_ADAPTIVE_MEASUREMENT_MODE_AUTO                                                                   \
    ((mip_adaptive_measurement_mode_t)2u) /* Auto-adaptive: the Kalman filter re-weights the measurement by  \
                                             its perceived quality (3DM-GX5 and later); limits are ignored.  \
                                           */

/** Aiding command echo mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_aiding_echo_mode_t;
#define MIP_AIDING_ECHO_MODE_SUPPRESS_ACK                                                                    \
    ((mip_aiding_echo_mode_t)0u) /* The aiding measurement commands are not acknowledged. */
#define MIP_AIDING_ECHO_MODE_STANDARD ((mip_aiding_echo_mode_t)1u) /* Normal ack/nack behavior. */
#define MIP_AIDING_ECHO_MODE_RESPONSE                                                                        \
    ((mip_aiding_echo_mode_t)2u) /* The device echoes the aiding data back as a response. */

/** Aiding frame rotation format.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_aiding_frame_format_t;
#define MIP_AIDING_FRAME_FORMAT_EULER                                                                        \
    ((mip_aiding_frame_format_t)1u) /* Translation vector followed by Euler angles (roll, pitch, yaw). */
#define MIP_AIDING_FRAME_FORMAT_QUATERNION                                                                   \
    ((mip_aiding_frame_format_t)2u) /* Translation vector followed by a quaternion (w, x, y, z). */

/** LLH position aiding valid flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mip_aiding_llh_valid_flags_t;
#define MIP_AIDING_LLH_VALID_FLAGS_LATITUDE_MASK                                                             \
    ((mip_aiding_llh_valid_flags_t)0x1u) /* bit 0: Latitude valid. */
#define MIP_AIDING_LLH_VALID_FLAGS_LATITUDE_SHIFT 0
#define MIP_AIDING_LLH_VALID_FLAGS_LONGITUDE_MASK                                                            \
    ((mip_aiding_llh_valid_flags_t)0x2u) /* bit 1: Longitude valid. */
#define MIP_AIDING_LLH_VALID_FLAGS_LONGITUDE_SHIFT 1
#define MIP_AIDING_LLH_VALID_FLAGS_HEIGHT_MASK ((mip_aiding_llh_valid_flags_t)0x4u) /* bit 2: Height valid.  \
                                                                                     */
#define MIP_AIDING_LLH_VALID_FLAGS_HEIGHT_SHIFT 2

/** Aiding measurement source.
 * An integer, so that values the spec does not list are kept. */
typedef uint16_t mip_aiding_measurement_source_t;
#define MIP_AIDING_MEASUREMENT_SOURCE_GNSS_POS_VEL                                                           \
    ((mip_aiding_measurement_source_t)0u) /* GNSS position and velocity. */
#define MIP_AIDING_MEASUREMENT_SOURCE_GNSS_HEADING                                                           \
    ((mip_aiding_measurement_source_t)1u) /* GNSS heading (dual antenna). */
#define MIP_AIDING_MEASUREMENT_SOURCE_ALTIMETER                                                              \
    ((mip_aiding_measurement_source_t)2u) /* Pressure altimeter (built-in sensor). */
#define MIP_AIDING_MEASUREMENT_SOURCE_SPEED                                                                  \
    ((mip_aiding_measurement_source_t)3u) /* Speed sensor / odometer. */
#define MIP_AIDING_MEASUREMENT_SOURCE_MAGNETOMETER                                                           \
    ((mip_aiding_measurement_source_t)4u) /* Magnetometer (built-in sensor). */
#define MIP_AIDING_MEASUREMENT_SOURCE_EXTERNAL_HEADING                                                       \
    ((mip_aiding_measurement_source_t)5u) /* External heading input. */
#define MIP_AIDING_MEASUREMENT_SOURCE_EXTERNAL_ALTIMETER                                                     \
    ((mip_aiding_measurement_source_t)6u) /* External pressure altimeter input. */
#define MIP_AIDING_MEASUREMENT_SOURCE_EXTERNAL_MAGNETOMETER                                                  \
    ((mip_aiding_measurement_source_t)7u) /* External magnetometer input. */
#define MIP_AIDING_MEASUREMENT_SOURCE_BODY_FRAME_VEL                                                         \
    ((mip_aiding_measurement_source_t)8u) /* External body frame velocity input. */
#define MIP_AIDING_MEASUREMENT_SOURCE_ALL                                                                    \
    ((mip_aiding_measurement_source_t)65535u) /* All sources (for save, load and default). */

/** Aiding measurement timebase. Clock in which the timestamp of an aiding measurement is expressed.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_aiding_timebase_t;
#define MIP_AIDING_TIMEBASE_INTERNAL_REFERENCE                                                               \
    ((mip_aiding_timebase_t)1u) /* Timestamp in the device's internal reference time (nanoseconds since      \
                                   power-on). */
#define MIP_AIDING_TIMEBASE_EXTERNAL_TIME                                                                    \
    ((mip_aiding_timebase_t)2u) /* Timestamp in external time, synchronised by the PPS source and GPS time   \
                                   update. */
#define MIP_AIDING_TIMEBASE_TIME_OF_ARRIVAL                                                                  \
    ((mip_aiding_timebase_t)3u) /* No timestamp: the measurement is taken at its arrival time, with a fixed  \
                                   latency. */

/** Aiding vector valid flags. Which axes of a 3-axis aiding measurement are valid; axes with 0 are ignored.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mip_aiding_vector_valid_flags_t;
#define MIP_AIDING_VECTOR_VALID_FLAGS_X_MASK                                                                 \
    ((mip_aiding_vector_valid_flags_t)0x1u) /* bit 0: X (or north) component valid. */
#define MIP_AIDING_VECTOR_VALID_FLAGS_X_SHIFT 0
#define MIP_AIDING_VECTOR_VALID_FLAGS_Y_MASK                                                                 \
    ((mip_aiding_vector_valid_flags_t)0x2u) /* bit 1: Y (or east) component valid. */
#define MIP_AIDING_VECTOR_VALID_FLAGS_Y_SHIFT 1
#define MIP_AIDING_VECTOR_VALID_FLAGS_Z_MASK                                                                 \
    ((mip_aiding_vector_valid_flags_t)0x4u) /* bit 2: Z (or down) component valid. */
#define MIP_AIDING_VECTOR_VALID_FLAGS_Z_SHIFT 2

/** Altitude aiding source.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_altitude_aiding_source_t;
#define MIP_ALTITUDE_AIDING_SOURCE_NONE                                                                      \
    ((mip_altitude_aiding_source_t)0u) /* No altitude aiding (disabled). */
#define MIP_ALTITUDE_AIDING_SOURCE_PRESSURE                                                                  \
    ((mip_altitude_aiding_source_t)1u) /* Pressure sensor aiding enabled. */

/** 3DM-CV7 commanded built-in test result.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint32_t mip_cv7_bit_flags_t;
#define MIP_CV7_BIT_FLAGS_GENERAL_HARDWARE_FAULT_MASK                                                        \
    ((mip_cv7_bit_flags_t)0x1u) /* bit 0: A critical hardware component has failed or is not operating       \
                                   properly. */
#define MIP_CV7_BIT_FLAGS_GENERAL_HARDWARE_FAULT_SHIFT 0
#define MIP_CV7_BIT_FLAGS_GENERAL_FIRMWARE_FAULT_MASK                                                        \
    ((mip_cv7_bit_flags_t)0x2u) /* bit 1: System firmware has detected a serious, unexpected or abnormal     \
                                   condition. */
#define MIP_CV7_BIT_FLAGS_GENERAL_FIRMWARE_FAULT_SHIFT 1
#define MIP_CV7_BIT_FLAGS_TIMING_OVERLOAD_MASK                                                               \
    ((mip_cv7_bit_flags_t)0x4u) /* bit 2: The system cannot keep up with the processing demand. */
#define MIP_CV7_BIT_FLAGS_TIMING_OVERLOAD_SHIFT 2
#define MIP_CV7_BIT_FLAGS_BUFFER_OVERRUN_MASK                                                                \
    ((mip_cv7_bit_flags_t)0x8u) /* bit 3: A data buffer has reached its capacity. */
#define MIP_CV7_BIT_FLAGS_BUFFER_OVERRUN_SHIFT 3
#define MIP_CV7_BIT_FLAGS_RESERVED_SYSTEM_MASK                                                               \
    ((mip_cv7_bit_flags_t)0xF0u) /* bits 4-7: (reserved) Reserved (system). */
#define MIP_CV7_BIT_FLAGS_RESERVED_SYSTEM_SHIFT 4
#define MIP_CV7_BIT_FLAGS_RESERVED_COMMS_MASK                                                                \
    ((mip_cv7_bit_flags_t)0xF00u) /* bits 8-11: (reserved) Reserved (comms). */
#define MIP_CV7_BIT_FLAGS_RESERVED_COMMS_SHIFT 8
#define MIP_CV7_BIT_FLAGS_ACCELEROMETER_FAULT_MASK                                                           \
    ((mip_cv7_bit_flags_t)0x1000u) /* bit 12: The accelerometer has been damaged or is inoperative. */
#define MIP_CV7_BIT_FLAGS_ACCELEROMETER_FAULT_SHIFT 12
#define MIP_CV7_BIT_FLAGS_GYROSCOPE_FAULT_MASK                                                               \
    ((mip_cv7_bit_flags_t)0x2000u) /* bit 13: The gyroscope has been damaged or is inoperative. */
#define MIP_CV7_BIT_FLAGS_GYROSCOPE_FAULT_SHIFT 13
#define MIP_CV7_BIT_FLAGS_MAGNETOMETER_FAULT_MASK                                                            \
    ((mip_cv7_bit_flags_t)0x4000u) /* bit 14: The magnetometer has been damaged or is inoperative. */
#define MIP_CV7_BIT_FLAGS_MAGNETOMETER_FAULT_SHIFT 14
#define MIP_CV7_BIT_FLAGS_PRESSURE_SENSOR_FAULT_MASK                                                         \
    ((mip_cv7_bit_flags_t)0x8000u) /* bit 15: The pressure sensor has been damaged or is inoperative. */
#define MIP_CV7_BIT_FLAGS_PRESSURE_SENSOR_FAULT_SHIFT 15
#define MIP_CV7_BIT_FLAGS_RESERVED_IMU_MASK                                                                  \
    ((mip_cv7_bit_flags_t)0x30000u) /* bits 16-17: (reserved) Reserved (IMU). */
#define MIP_CV7_BIT_FLAGS_RESERVED_IMU_SHIFT 16
#define MIP_CV7_BIT_FLAGS_CALIBRATION_ERROR_MASK                                                             \
    ((mip_cv7_bit_flags_t)0x40000u) /* bit 18: One or more IMU calibration tables are invalid. */
#define MIP_CV7_BIT_FLAGS_CALIBRATION_ERROR_SHIFT 18
#define MIP_CV7_BIT_FLAGS_GENERAL_IMU_FAULT_MASK                                                             \
    ((mip_cv7_bit_flags_t)0x80000u) /* bit 19: A problem has been detected in the IMU subsystem. */
#define MIP_CV7_BIT_FLAGS_GENERAL_IMU_FAULT_SHIFT 19
#define MIP_CV7_BIT_FLAGS_RESERVED_FILTER_MASK                                                               \
    ((mip_cv7_bit_flags_t)0x300000u) /* bits 20-21: (reserved) Reserved (filter). */
#define MIP_CV7_BIT_FLAGS_RESERVED_FILTER_SHIFT 20
#define MIP_CV7_BIT_FLAGS_FILTER_SOLUTION_FAULT_MASK                                                         \
    ((mip_cv7_bit_flags_t)0x400000u) /* bit 22: The filter solution is invalid (NaN in the filter output).   \
                                      */
#define MIP_CV7_BIT_FLAGS_FILTER_SOLUTION_FAULT_SHIFT 22
#define MIP_CV7_BIT_FLAGS_GENERAL_FILTER_FAULT_MASK                                                          \
    ((mip_cv7_bit_flags_t)0x800000u) /* bit 23: A problem has been detected in the filter subsystem. */
#define MIP_CV7_BIT_FLAGS_GENERAL_FILTER_FAULT_SHIFT 23
#define MIP_CV7_BIT_FLAGS_RESERVED_MASK                                                                      \
    ((mip_cv7_bit_flags_t)0xFF000000u) /* bits 24-31: (reserved) Reserved. */
#define MIP_CV7_BIT_FLAGS_RESERVED_SHIFT 24

/** Estimation control flags. Which optional states the Kalman filter estimates.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mip_estimation_control_flags_t;
#define MIP_ESTIMATION_CONTROL_FLAGS_GYRO_BIAS_MASK                                                          \
    ((mip_estimation_control_flags_t)0x1u) /* bit 0: Estimate gyro bias (recommended). */
#define MIP_ESTIMATION_CONTROL_FLAGS_GYRO_BIAS_SHIFT 0
#define MIP_ESTIMATION_CONTROL_FLAGS_ACCEL_BIAS_MASK                                                         \
    ((mip_estimation_control_flags_t)0x2u) /* bit 1: Estimate accelerometer bias (recommended). */
#define MIP_ESTIMATION_CONTROL_FLAGS_ACCEL_BIAS_SHIFT 1
#define MIP_ESTIMATION_CONTROL_FLAGS_GYRO_SCALE_FACTOR_MASK                                                  \
    ((mip_estimation_control_flags_t)0x4u) /* bit 2: Estimate gyro scale factor (optional). */
#define MIP_ESTIMATION_CONTROL_FLAGS_GYRO_SCALE_FACTOR_SHIFT 2
#define MIP_ESTIMATION_CONTROL_FLAGS_ACCEL_SCALE_FACTOR_MASK                                                 \
    ((mip_estimation_control_flags_t)0x8u) /* bit 3: Estimate accelerometer scale factor (optional). */
#define MIP_ESTIMATION_CONTROL_FLAGS_ACCEL_SCALE_FACTOR_SHIFT 3
#define MIP_ESTIMATION_CONTROL_FLAGS_ANTENNA_OFFSET_MASK                                                     \
    ((mip_estimation_control_flags_t)0x10u) /* bit 4: Estimate the GNSS antenna offset (optional). */
#define MIP_ESTIMATION_CONTROL_FLAGS_ANTENNA_OFFSET_SHIFT 4
#define MIP_ESTIMATION_CONTROL_FLAGS_HARD_IRON_AUTO_CAL_MASK                                                 \
    ((mip_estimation_control_flags_t)0x20u) /* bit 5: Hard iron auto-calibration (optional). */
#define MIP_ESTIMATION_CONTROL_FLAGS_HARD_IRON_AUTO_CAL_SHIFT 5
#define MIP_ESTIMATION_CONTROL_FLAGS_SOFT_IRON_AUTO_CAL_MASK                                                 \
    ((mip_estimation_control_flags_t)0x40u) /* bit 6: Soft iron auto-calibration (optional). */
#define MIP_ESTIMATION_CONTROL_FLAGS_SOFT_IRON_AUTO_CAL_SHIFT 6
#define MIP_ESTIMATION_CONTROL_FLAGS_RESERVED_MASK                                                           \
    ((mip_estimation_control_flags_t)0xFF80u) /* bits 7-15: (reserved) Not named by the manual. */
#define MIP_ESTIMATION_CONTROL_FLAGS_RESERVED_SHIFT 7

/** Event trigger control mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_event_control_mode_t;
#define MIP_EVENT_CONTROL_MODE_DISABLED ((mip_event_control_mode_t)0u) /* Trigger is disabled. */
#define MIP_EVENT_CONTROL_MODE_ENABLED                                                                       \
    ((mip_event_control_mode_t)1u) /* Trigger is enabled and will work normally. */
#define MIP_EVENT_CONTROL_MODE_TEST                                                                          \
    ((mip_event_control_mode_t)2u) /* Forces the trigger to the active state for testing purposes. */
#define MIP_EVENT_CONTROL_MODE_TEST_PULSE                                                                    \
    ((mip_event_control_mode_t)3u) /* Trigger is forced active for one event cycle only, then reverts. */

/** External heading type. Reference of an externally supplied heading angle.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_external_heading_type_t;
#define MIP_EXTERNAL_HEADING_TYPE_TRUE_HEADING                                                               \
    ((mip_external_heading_type_t)1u) /* True heading (from true north). */
#define MIP_EXTERNAL_HEADING_TYPE_MAGNETIC_HEADING                                                           \
    ((mip_external_heading_type_t)2u) /* Magnetic heading (from magnetic north). */

/** Filter GNSS source. Where the filter takes its GNSS position and velocity updates from.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_filter_gnss_source_t;
#define MIP_FILTER_GNSS_SOURCE_ALL_INTERNAL                                                                  \
    ((mip_filter_gnss_source_t)1u) /* The internal GNSS receiver(s) (GX5-45: Internal GNSS; CV7: ALL_INT,    \
                                      all internal receivers). */
#define MIP_FILTER_GNSS_SOURCE_EXTERNAL                                                                      \
    ((mip_filter_gnss_source_t)2u) /* External GNSS messages supplied by the user (GX5-45: External GNSS     \
                                      Update 0x0D,0x16). */
#define MIP_FILTER_GNSS_SOURCE_INTERNAL_1                                                                    \
    ((mip_filter_gnss_source_t)3u) /* Internal GNSS receiver 1 only. (devices: cv7_ins) */
#define MIP_FILTER_GNSS_SOURCE_INTERNAL_2                                                                    \
    ((mip_filter_gnss_source_t)4u) /* Internal GNSS receiver 2 only. (devices: cv7_ins) */

/** Navigation filter initial condition source.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_filter_initial_condition_source_t;
#define MIP_FILTER_INITIAL_CONDITION_SOURCE_AUTO_POS_VEL_ATT                                                 \
    ((mip_filter_initial_condition_source_t)0u) /* Automatic position, velocity and attitude. */
#define MIP_FILTER_INITIAL_CONDITION_SOURCE_AUTO_POS_VEL_PITCH_ROLL                                          \
    ((mip_filter_initial_condition_source_t)1u) /* Automatic position, velocity, pitch and roll; heading as  \
                                                   specified. */
#define MIP_FILTER_INITIAL_CONDITION_SOURCE_AUTO_POS_VEL                                                     \
    ((mip_filter_initial_condition_source_t)2u) /* Automatic position and velocity; attitude fully           \
                                                   user-specified. */
#define MIP_FILTER_INITIAL_CONDITION_SOURCE_MANUAL                                                           \
    ((mip_filter_initial_condition_source_t)3u) /* User-specified position, velocity and attitude. */

/** Reference frame of user-specified positions and velocities.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_filter_reference_frame_t;
#define MIP_FILTER_REFERENCE_FRAME_ECEF                                                                      \
    ((mip_filter_reference_frame_t)1u) /* WGS84 Earth-centered, Earth-fixed coordinates. */
#define MIP_FILTER_REFERENCE_FRAME_LLH                                                                       \
    ((mip_filter_reference_frame_t)2u) /* WGS84 latitude, longitude and height above ellipsoid. */

/** Function selector. First parameter of settings commands; chooses what the command does. Only a read
 * returns a response field (with the ack); parameters not needed for a function may be left out, or sent as
 * placeholders. An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_function_selector_t;
#define MIP_FUNCTION_SELECTOR_WRITE ((mip_function_selector_t)1u) /* Apply new setting. */
#define MIP_FUNCTION_SELECTOR_READ                                                                           \
    ((mip_function_selector_t)2u) /* Read back the current setting (the only function that returns response  \
                                     data). */
#define MIP_FUNCTION_SELECTOR_SAVE                                                                           \
    ((mip_function_selector_t)3u) /* Save the current setting to non-volatile memory as the startup setting. \
                                   */
#define MIP_FUNCTION_SELECTOR_LOAD                                                                           \
    ((mip_function_selector_t)4u) /* Load the saved startup setting from non-volatile memory. */
#define MIP_FUNCTION_SELECTOR_DEFAULT ((mip_function_selector_t)5u) /* Reset to the factory default. */
#define MIP_FUNCTION_SELECTOR_WRITE_NO_ACK                                                                   \
    ((mip_function_selector_t)6u) /* Apply new setting with no ACK/NACK reply (GX5-45 only). (devices:       \
                                     gx5_45) */

/** BeiDou signals enabled.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mip_gnss_beidou_signals_t;
#define MIP_GNSS_BEIDOU_SIGNALS_B1_MASK ((mip_gnss_beidou_signals_t)0x1u) /* bit 0: Enable B1. */
#define MIP_GNSS_BEIDOU_SIGNALS_B1_SHIFT 0
#define MIP_GNSS_BEIDOU_SIGNALS_B2_MASK ((mip_gnss_beidou_signals_t)0x2u) /* bit 1: Enable B2. */
#define MIP_GNSS_BEIDOU_SIGNALS_B2_SHIFT 1
#define MIP_GNSS_BEIDOU_SIGNALS_B2A_MASK ((mip_gnss_beidou_signals_t)0x4u) /* bit 2: Enable B2A. */
#define MIP_GNSS_BEIDOU_SIGNALS_B2A_SHIFT 2

/** Galileo signals enabled.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mip_gnss_galileo_signals_t;
#define MIP_GNSS_GALILEO_SIGNALS_E1_MASK ((mip_gnss_galileo_signals_t)0x1u) /* bit 0: Enable E1. */
#define MIP_GNSS_GALILEO_SIGNALS_E1_SHIFT 0
#define MIP_GNSS_GALILEO_SIGNALS_E5B_MASK ((mip_gnss_galileo_signals_t)0x2u) /* bit 1: Enable E5B. */
#define MIP_GNSS_GALILEO_SIGNALS_E5B_SHIFT 1
#define MIP_GNSS_GALILEO_SIGNALS_E5A_MASK ((mip_gnss_galileo_signals_t)0x4u) /* bit 2: Enable E5A. */
#define MIP_GNSS_GALILEO_SIGNALS_E5A_SHIFT 2

/** GLONASS signals enabled.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mip_gnss_glonass_signals_t;
#define MIP_GNSS_GLONASS_SIGNALS_L1OF_MASK ((mip_gnss_glonass_signals_t)0x1u) /* bit 0: Enable L1OF. */
#define MIP_GNSS_GLONASS_SIGNALS_L1OF_SHIFT 0
#define MIP_GNSS_GLONASS_SIGNALS_L2OF_MASK ((mip_gnss_glonass_signals_t)0x2u) /* bit 1: Enable L2OF. */
#define MIP_GNSS_GLONASS_SIGNALS_L2OF_SHIFT 1

/** GPS signals enabled.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mip_gnss_gps_signals_t;
#define MIP_GNSS_GPS_SIGNALS_L1CA_MASK ((mip_gnss_gps_signals_t)0x1u) /* bit 0: Enable L1 C/A. */
#define MIP_GNSS_GPS_SIGNALS_L1CA_SHIFT 0
#define MIP_GNSS_GPS_SIGNALS_L2C_MASK ((mip_gnss_gps_signals_t)0x2u) /* bit 1: Enable L2C. */
#define MIP_GNSS_GPS_SIGNALS_L2C_SHIFT 1
#define MIP_GNSS_GPS_SIGNALS_L5_MASK ((mip_gnss_gps_signals_t)0x4u) /* bit 2: Enable L5. */
#define MIP_GNSS_GPS_SIGNALS_L5_SHIFT 2

/** GPS time field selector.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gps_time_field_t;
#define MIP_GPS_TIME_FIELD_WEEK_NUMBER ((mip_gps_time_field_t)1u) /* Week number (GX5-45: GPS Week Number).  \
                                                                   */
#define MIP_GPS_TIME_FIELD_TIME_OF_WEEK                                                                      \
    ((mip_gps_time_field_t)2u) /* Time of week in seconds (GX5-45: GPS Seconds). */

/** 3DM-GX5-45 built-in test error flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint32_t mip_gx5_bit_flags_t;
#define MIP_GX5_BIT_FLAGS_PROCESSOR_WDT_RESET_MASK                                                           \
    ((mip_gx5_bit_flags_t)0x1u) /* bit 0: Processor board: watchdog reset (latching, cleared after first     \
                                   commanded BIT). */
#define MIP_GX5_BIT_FLAGS_PROCESSOR_WDT_RESET_SHIFT 0
#define MIP_GX5_BIT_FLAGS_IMU_COMMUNICATION_FAULT_MASK                                                       \
    ((mip_gx5_bit_flags_t)0x100u) /* bit 8: Sensor board: IMU communication fault. */
#define MIP_GX5_BIT_FLAGS_IMU_COMMUNICATION_FAULT_SHIFT 8
#define MIP_GX5_BIT_FLAGS_MAGNETOMETER_FAULT_MASK                                                            \
    ((mip_gx5_bit_flags_t)0x200u) /* bit 9: Sensor board: magnetometer fault (if applicable). */
#define MIP_GX5_BIT_FLAGS_MAGNETOMETER_FAULT_SHIFT 9
#define MIP_GX5_BIT_FLAGS_PRESSURE_SENSOR_FAULT_MASK                                                         \
    ((mip_gx5_bit_flags_t)0x400u) /* bit 10: Sensor board: pressure sensor fault (if applicable). */
#define MIP_GX5_BIT_FLAGS_PRESSURE_SENSOR_FAULT_SHIFT 10
#define MIP_GX5_BIT_FLAGS_FILTER_SOLUTION_FAULT_MASK                                                         \
    ((mip_gx5_bit_flags_t)0x1000000u) /* bit 24: Kalman filter: solution fault. */
#define MIP_GX5_BIT_FLAGS_FILTER_SOLUTION_FAULT_SHIFT 24

/** Allowed automatic heading alignment methods.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mip_heading_alignment_methods_t;
#define MIP_HEADING_ALIGNMENT_METHODS_DUAL_ANTENNA_MASK                                                      \
    ((mip_heading_alignment_methods_t)0x1u) /* bit 0: Dual-antenna GNSS alignment. */
#define MIP_HEADING_ALIGNMENT_METHODS_DUAL_ANTENNA_SHIFT 0
#define MIP_HEADING_ALIGNMENT_METHODS_KINEMATIC_MASK                                                         \
    ((mip_heading_alignment_methods_t)0x2u) /* bit 1: GNSS kinematic alignment: the GNSS velocity (above 2   \
                                               m/s) determines the initial heading. */
#define MIP_HEADING_ALIGNMENT_METHODS_KINEMATIC_SHIFT 1
#define MIP_HEADING_ALIGNMENT_METHODS_MAGNETOMETER_MASK                                                      \
    ((mip_heading_alignment_methods_t)0x4u) /* bit 2: The internal magnetometer determines the initial       \
                                               heading. */
#define MIP_HEADING_ALIGNMENT_METHODS_MAGNETOMETER_SHIFT 2
#define MIP_HEADING_ALIGNMENT_METHODS_EXTERNAL_MASK                                                          \
    ((mip_heading_alignment_methods_t)0x8u) /* bit 3: An external heading input determines the initial       \
                                               heading. */
#define MIP_HEADING_ALIGNMENT_METHODS_EXTERNAL_SHIFT 3

/** Heading update source. Which aiding sources the filter uses for heading updates.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_heading_update_source_t;
#define MIP_HEADING_UPDATE_SOURCE_NONE                                                                       \
    ((mip_heading_update_source_t)0u) /* No heading aiding; heading still converges from GNSS under          \
                                         sufficient acceleration. */
#define MIP_HEADING_UPDATE_SOURCE_MAGNETOMETER ((mip_heading_update_source_t)1u) /* Internal magnetometer.   \
                                                                                  */
#define MIP_HEADING_UPDATE_SOURCE_GNSS_VELOCITY                                                              \
    ((mip_heading_update_source_t)2u) /* Internal GNSS velocity vector (needs little side-slip and the       \
                                         vehicle X axis along the direction of travel). */
#define MIP_HEADING_UPDATE_SOURCE_EXTERNAL                                                                   \
    ((mip_heading_update_source_t)3u) /* External heading messages (0x0D,0x17 / 0x0D,0x1F). */
#define MIP_HEADING_UPDATE_SOURCE_GNSS_VELOCITY_AND_MAGNETOMETER                                             \
    ((mip_heading_update_source_t)4u) /* GNSS velocity vector and magnetometer. */
#define MIP_HEADING_UPDATE_SOURCE_GNSS_VELOCITY_AND_EXTERNAL                                                 \
    ((mip_heading_update_source_t)5u) /* GNSS velocity vector and external heading messages. */
#define MIP_HEADING_UPDATE_SOURCE_MAGNETOMETER_AND_EXTERNAL                                                  \
    ((mip_heading_update_source_t)6u) /* Magnetometer and external heading messages. */
#define MIP_HEADING_UPDATE_SOURCE_GNSS_VELOCITY_MAGNETOMETER_AND_EXTERNAL                                    \
    ((mip_heading_update_source_t)7u) /* GNSS velocity vector, magnetometer and external heading messages.   \
                                       */

/** Source of a magnetic field parameter (declination, inclination, magnitude). Where the filter takes a local
 * magnetic field parameter from: nowhere (a fixed fallback), the internal World Magnetic Model, or a value
 * the user supplies. An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_magnetic_param_source_t;
#define MIP_MAGNETIC_PARAM_SOURCE_NONE                                                                       \
    ((mip_magnetic_param_source_t)1u) /* No source: no correction (declination, inclination) or a fixed 0.5  \
                                         gauss (magnitude). */
#define MIP_MAGNETIC_PARAM_SOURCE_WMM                                                                        \
    ((mip_magnetic_param_source_t)2u) /* Internal World Magnetic Model at the current position estimate      \
                                         (default). */
#define MIP_MAGNETIC_PARAM_SOURCE_MANUAL                                                                     \
    ((mip_magnetic_param_source_t)3u) /* Value supplied by the user; the device does not validate it. */

/** Pitch/roll aiding source.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_pitch_roll_aiding_source_t;
#define MIP_PITCH_ROLL_AIDING_SOURCE_NONE                                                                    \
    ((mip_pitch_roll_aiding_source_t)0u) /* No pitch/roll aiding (disabled). */
#define MIP_PITCH_ROLL_AIDING_SOURCE_GRAVITY_VECTOR                                                          \
    ((mip_pitch_roll_aiding_source_t)1u) /* Gravity vector aiding enabled. */

/** Filter reference point.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_reference_point_selector_t;
#define MIP_REFERENCE_POINT_SELECTOR_VEH                                                                     \
    ((mip_reference_point_selector_t)1u) /* The origin of the vehicle (the only value; the parameter is      \
                                            reserved and must be 1). */

/** Reference location source for relative position outputs.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_relative_position_source_t;
#define MIP_RELATIVE_POSITION_SOURCE_AUTO                                                                    \
    ((mip_relative_position_source_t)0u) /* Automatic: the RTK base station location. */
#define MIP_RELATIVE_POSITION_SOURCE_MANUAL                                                                  \
    ((mip_relative_position_source_t)1u) /* The reference coordinates given in the command. */

/** SPARTN connection type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_spartn_connection_type_t;
#define MIP_SPARTN_CONNECTION_TYPE_NONE ((mip_spartn_connection_type_t)0u) /* No SPARTN connection. */
#define MIP_SPARTN_CONNECTION_TYPE_NETWORK                                                                   \
    ((mip_spartn_connection_type_t)1u) /* Corrections over a network connection (e.g. NTRIP). */
#define MIP_SPARTN_CONNECTION_TYPE_L_BAND                                                                    \
    ((mip_spartn_connection_type_t)2u) /* Corrections from an L-band correction receiver. */

/** Communication mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_system_comm_mode_t;
#define MIP_SYSTEM_COMM_MODE_STANDARD ((mip_system_comm_mode_t)1u) /* 3DM-GX5-45 MIP packets (default). */
#define MIP_SYSTEM_COMM_MODE_SENSOR_DIRECT                                                                   \
    ((mip_system_comm_mode_t)2u) /* Direct to the internal IMU: MIP IMU protocol. */
#define MIP_SYSTEM_COMM_MODE_GNSS_DIRECT                                                                     \
    ((mip_system_comm_mode_t)3u) /* Direct to the GNSS receiver: NMEA and UBX (GNSS models only). */

/** Tare orientation axes. Axes to tare; 0 (no bit set) resets all axes.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mip_tare_axes_t;
#define MIP_TARE_AXES_ROLL_MASK ((mip_tare_axes_t)0x1u) /* bit 0: Tare the roll axis. */
#define MIP_TARE_AXES_ROLL_SHIFT 0
#define MIP_TARE_AXES_PITCH_MASK ((mip_tare_axes_t)0x2u) /* bit 1: Tare the pitch axis. */
#define MIP_TARE_AXES_PITCH_SHIFT 1
#define MIP_TARE_AXES_YAW_MASK ((mip_tare_axes_t)0x4u) /* bit 2: Tare the yaw axis. */
#define MIP_TARE_AXES_YAW_SHIFT 2

/** Threshold comparison type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_threshold_type_t;
#define MIP_THRESHOLD_TYPE_WINDOW                                                                            \
    ((mip_threshold_type_t)1u) /* Active if low_thres <= value <= high_thres (reversed thresholds invert     \
                                  it). */
#define MIP_THRESHOLD_TYPE_INTERVAL                                                                          \
    ((mip_threshold_type_t)2u) /* Active when (value % high_thres) <= low_thres: periodic triggering. */

/** GPIO trigger mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_trigger_gpio_mode_t;
#define MIP_TRIGGER_GPIO_MODE_DISABLED                                                                       \
    ((mip_trigger_gpio_mode_t)0u) /* The pin has no effect and the trigger never activates. */
#define MIP_TRIGGER_GPIO_MODE_WHILE_HIGH ((mip_trigger_gpio_mode_t)1u) /* Active while the pin is high. */
#define MIP_TRIGGER_GPIO_MODE_WHILE_LOW ((mip_trigger_gpio_mode_t)2u)  /* Active while the pin is low. */
#define MIP_TRIGGER_GPIO_MODE_EDGE                                                                           \
    ((mip_trigger_gpio_mode_t)4u) /* Use if the pin is configured for timestamping (0x0C,0x41). */

/** Event trigger status.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mip_trigger_status_t;
#define MIP_TRIGGER_STATUS_ACTIVE_MASK                                                                       \
    ((mip_trigger_status_t)0x1u) /* bit 0: The trigger is currently active (by its logic or in test mode).   \
                                  */
#define MIP_TRIGGER_STATUS_ACTIVE_SHIFT 0
#define MIP_TRIGGER_STATUS_ENABLED_MASK ((mip_trigger_status_t)0x2u) /* bit 1: The trigger is enabled. */
#define MIP_TRIGGER_STATUS_ENABLED_SHIFT 1
#define MIP_TRIGGER_STATUS_TEST_MASK ((mip_trigger_status_t)0x4u) /* bit 2: The trigger is in test mode. */
#define MIP_TRIGGER_STATUS_TEST_SHIFT 2

/** Event trigger type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_trigger_type_t;
#define MIP_TRIGGER_TYPE_NONE                                                                                \
    ((mip_trigger_type_t)0u) /* No trigger selected. The state will always be inactive. */
#define MIP_TRIGGER_TYPE_GPIO ((mip_trigger_type_t)1u) /* Trigger based on the state of a GPIO pin. */
#define MIP_TRIGGER_TYPE_THRESHOLD                                                                           \
    ((mip_trigger_type_t)2u) /* Compare a data quantity against a high and low threshold. */
#define MIP_TRIGGER_TYPE_COMBINATION                                                                         \
    ((mip_trigger_type_t)3u) /* Logical combination of two or more triggers. */

/** Vehicle dynamics mode. Dynamics model the filter assumes for the vehicle (altitude and velocity limits).
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_vehicle_dynamics_mode_t;
#define MIP_VEHICLE_DYNAMICS_MODE_PORTABLE                                                                   \
    ((mip_vehicle_dynamics_mode_t)1u) /* Low-acceleration applications (default); up to 12,000 m, 310 m/s    \
                                         horizontal, 50 m/s vertical. */
#define MIP_VEHICLE_DYNAMICS_MODE_AUTOMOTIVE                                                                 \
    ((mip_vehicle_dynamics_mode_t)2u) /* Wheeled vehicles with low vertical acceleration; up to 6,000 m, 84  \
                                         m/s horizontal, 15 m/s vertical. */
#define MIP_VEHICLE_DYNAMICS_MODE_AIRBORNE                                                                   \
    ((mip_vehicle_dynamics_mode_t)3u) /* Airborne up to 2 g; up to 50,000 m, 250 m/s horizontal, 100 m/s     \
                                         vertical. */
#define MIP_VEHICLE_DYNAMICS_MODE_AIRBORNE_HIGH_G                                                            \
    ((mip_vehicle_dynamics_mode_t)4u) /* Airborne up to 4 g; same altitude and velocity limits as airborne.  \
                                       */

/** ActionGpioParams.  */
typedef struct {
    uint8_t pin;                 /* GPIO pin number. */
    mip_action_gpio_mode_t mode; /* Behavior of the pin. */
} mip_action_gpio_params_t;

/** MessageParams.  */
typedef struct {
    uint8_t desc_set;        /* MIP data descriptor set. */
    uint16_t decimation;     /* Decimation from the base rate; 0 emits one packet per activation. */
    uint8_t num_fields;      /* Number of fields in the packet (at most 12). */
    uint8_t descriptors[12]; /* Field descriptors. */
} mip_message_params_t;

/** ActionParams.
 * The member is chosen by a parameter of type mip_action_type_t next to it. */
typedef union {
    mip_action_gpio_params_t gpio; /* gpio:  */
    mip_message_params_t message;  /* message:  */
    uint8_t none_;                 /* members without data */
} mip_action_params_t;

/** ActionStatusEntry.  */
typedef struct {
    mip_action_type_t action_type; /* Configured action type. */
    uint8_t trigger_id;            /* Associated trigger instance. */
} mip_action_status_entry_t;

/** Aiding frame rotation as Euler angles.  */
typedef struct {
    float
        euler[3]; /* Roll, pitch, yaw of the frame relative to the vehicle frame, each within +/- pi. [rad] */
} mip_aiding_frame_euler_t;

/** Aiding frame rotation as a quaternion.  */
typedef struct {
    float quaternion[4]; /* Rotation of the frame relative to the vehicle frame, (w, x, y, z). */
} mip_aiding_frame_quaternion_t;

/** Aiding frame rotation. Rotation of an aiding frame, as Euler angles or as a quaternion depending on the
 * format. The member is chosen by a parameter of type mip_aiding_frame_format_t next to it. */
typedef union {
    mip_aiding_frame_euler_t euler;           /* euler:  */
    mip_aiding_frame_quaternion_t quaternion; /* quaternion:  */
    uint8_t none_;                            /* members without data */
} mip_aiding_frame_rotation_t;

/** Aiding measurement timestamp. Timestamp carried first in every aiding measurement command. */
typedef struct {
    mip_aiding_timebase_t timebase; /* Clock of the timestamp. */
    uint8_t reserved;               /* Reserved. */
    uint64_t nanoseconds; /* Time of the measurement in nanoseconds, in the timebase's clock. [ns] */
} mip_aiding_time_t;

/** CombinationParams.  */
typedef struct {
    uint16_t logic_table;      /* Last column of the truth table of the inputs. */
    uint8_t input_triggers[4]; /* Trigger IDs of the inputs; 0 for unused inputs. */
} mip_combination_params_t;

/** Device information. Firmware version and five 16-character identification strings, padded with spaces. */
typedef struct {
    uint16_t firmware_version; /* Firmware version number. */
    char model_name[16];       /* Model name. */
    char model_number[16];     /* Model number. */
    char serial_number[16];    /* Serial number. */
    char lot_number[16];       /* Lot number. */
    char device_options[16];   /* Device options (e.g. sensor ranges). */
} mip_device_info_t;

/** GNSS receiver information. Identity of one physical GNSS receiver in the device. */
typedef struct {
    uint8_t receiver_id;             /* Receiver id (1, 2, ...). */
    uint8_t mip_data_descriptor_set; /* MIP data descriptor set of this receiver's data. */
    char description[32];            /* ASCII, comma-delimited: module name/model, firmware version. */
} mip_gnss_receiver_info_entry_t;

/** ThresholdParams.  */
typedef struct {
    uint8_t desc_set;          /* Descriptor set of the target data quantity. */
    uint8_t field_desc;        /* Field descriptor of the target data quantity. */
    uint8_t param_id;          /* 1-based index of the target parameter within the field. */
    mip_threshold_type_t type; /* Type of comparison. */
    double low_thres;          /* Low threshold (window) or active time (interval). */
    double high_thres;         /* High threshold (window) or interval (interval). */
} mip_threshold_params_t;

/** TriggerGpioParams.  */
typedef struct {
    uint8_t pin;                  /* GPIO pin number. */
    mip_trigger_gpio_mode_t mode; /* How the pin state affects the trigger. */
} mip_trigger_gpio_params_t;

/** TriggerParams.
 * The member is chosen by a parameter of type mip_trigger_type_t next to it. */
typedef union {
    mip_trigger_gpio_params_t gpio;       /* gpio:  */
    mip_threshold_params_t threshold;     /* threshold:  */
    mip_combination_params_t combination; /* combination:  */
    uint8_t none_;                        /* members without data */
} mip_trigger_params_t;

/** TriggerStatusEntry.  */
typedef struct {
    mip_trigger_type_t type;     /* Configured trigger type. */
    mip_trigger_status_t status; /* Trigger status. */
} mip_trigger_status_entry_t;

#ifdef __cplusplus
}
#endif

#endif
