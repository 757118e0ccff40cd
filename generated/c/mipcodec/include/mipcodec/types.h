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

/** Assisted fix option.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_assisted_fix_option_t;
#define MIP_ASSISTED_FIX_OPTION_NONE ((mip_assisted_fix_option_t)0u)    /* No assisted fix (default). */
#define MIP_ASSISTED_FIX_OPTION_ENABLED ((mip_assisted_fix_option_t)1u) /* Assisted fix enabled. */

/** GNSS constellation option flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mip_constellation_options_t;
#define MIP_CONSTELLATION_OPTIONS_L1SAIF_MASK                                                                \
    ((mip_constellation_options_t)0x1u) /* bit 0: L1SAIF signal (QZSS only). */
#define MIP_CONSTELLATION_OPTIONS_L1SAIF_SHIFT 0

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

/** Device status selector.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_device_status_selector_t;
#define MIP_DEVICE_STATUS_SELECTOR_BASIC ((mip_device_status_selector_t)1u) /* Basic status structure. */
#define MIP_DEVICE_STATUS_SELECTOR_DIAGNOSTIC                                                                \
    ((mip_device_status_selector_t)2u) /* Diagnostic status structure. */

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

/** Factory streaming action.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_factory_streaming_action_t;
#define MIP_FACTORY_STREAMING_ACTION_OVERWRITE                                                               \
    ((mip_factory_streaming_action_t)0u) /* Replace the message formats, dropping the descriptors already    \
                                            there. */
#define MIP_FACTORY_STREAMING_ACTION_MERGE                                                                   \
    ((mip_factory_streaming_action_t)1u) /* Merge the support descriptors into the existing formats (order   \
                                            may change). */
#define MIP_FACTORY_STREAMING_ACTION_ADD                                                                     \
    ((mip_factory_streaming_action_t)2u) /* Append the support descriptors to the existing formats           \
                                            (duplicates possible). */

/** Aiding measurement indicator. State of one aiding measurement over the last measurement interval.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mip_filter_aiding_measurement_indicator_t;
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_ENABLED_MASK                                                 \
    ((mip_filter_aiding_measurement_indicator_t)0x1u) /* bit 0: The measurement is enabled. */
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_ENABLED_SHIFT 0
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_USED_MASK                                                    \
    ((mip_filter_aiding_measurement_indicator_t)0x2u) /* bit 1: The measurement was used by the filter. */
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_USED_SHIFT 1
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_RESIDUAL_HIGH_WARNING_MASK                                   \
    ((mip_filter_aiding_measurement_indicator_t)0x4u) /* bit 2: Measurement residual is high. */
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_RESIDUAL_HIGH_WARNING_SHIFT 2
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_SAMPLE_TIME_WARNING_MASK                                     \
    ((mip_filter_aiding_measurement_indicator_t)0x8u) /* bit 3: Problem with the measurement's sample time.  \
                                                       */
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_SAMPLE_TIME_WARNING_SHIFT 3
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_CONFIGURATION_ERROR_MASK                                     \
    ((mip_filter_aiding_measurement_indicator_t)0x10u) /* bit 4: The measurement is misconfigured. */
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_CONFIGURATION_ERROR_SHIFT 4
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_MAX_NUM_MEAS_EXCEEDED_MASK                                   \
    ((mip_filter_aiding_measurement_indicator_t)0x20u) /* bit 5: More measurements than the filter can       \
                                                          process. */
#define MIP_FILTER_AIDING_MEASUREMENT_INDICATOR_MAX_NUM_MEAS_EXCEEDED_SHIFT 5

/** Aiding measurement type. Which aiding measurement an Aiding Measurement Summary (0x82,0x46) describes.
 * Values 0x20 and above are the measurements commanded through the Aiding command set (0x13); their value is
 * the descriptor of that command. An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_filter_aiding_measurement_type_t;
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_GNSS                                                              \
    ((mip_filter_aiding_measurement_type_t)1u) /* GNSS receiver measurement. */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_DUAL_ANTENNA                                                      \
    ((mip_filter_aiding_measurement_type_t)2u) /* GNSS dual-antenna heading. */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_HEADING                                                           \
    ((mip_filter_aiding_measurement_type_t)3u) /* Heading measurement. */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_PRESSURE                                                          \
    ((mip_filter_aiding_measurement_type_t)4u) /* Pressure (barometric altitude). */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_MAGNETOMETER                                                      \
    ((mip_filter_aiding_measurement_type_t)5u) /* Magnetometer. */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_SPEED                                                             \
    ((mip_filter_aiding_measurement_type_t)6u) /* Speed sensor (odometer). */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_POS_ECEF                                                   \
    ((mip_filter_aiding_measurement_type_t)33u) /* ECEF position aiding command (0x13,0x21). */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_POS_LLH                                                    \
    ((mip_filter_aiding_measurement_type_t)34u) /* LLH position aiding command (0x13,0x22). */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_HEIGHT_ABOVE_ELLIPSOID                                     \
    ((mip_filter_aiding_measurement_type_t)35u) /* Height above ellipsoid aiding command (0x13,0x23). */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_VEL_ECEF                                                   \
    ((mip_filter_aiding_measurement_type_t)40u) /* ECEF velocity aiding command (0x13,0x28). */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_VEL_NED                                                    \
    ((mip_filter_aiding_measurement_type_t)41u) /* NED velocity aiding command (0x13,0x29). */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_VEL_BODY_FRAME                                             \
    ((mip_filter_aiding_measurement_type_t)42u) /* Body-frame velocity aiding command (0x13,0x2A). */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_HEADING_TRUE                                               \
    ((mip_filter_aiding_measurement_type_t)49u) /* True heading aiding command (0x13,0x31). */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_MAGNETIC_FIELD                                             \
    ((mip_filter_aiding_measurement_type_t)50u) /* Magnetic field aiding command (0x13,0x32). */
#define MIP_FILTER_AIDING_MEASUREMENT_TYPE_AIDING_PRESSURE                                                   \
    ((mip_filter_aiding_measurement_type_t)51u) /* Pressure aiding command (0x13,0x33). */

/** Dual-antenna fix type. Kind of GNSS dual-antenna heading solution.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_filter_dual_antenna_fix_type_t;
#define MIP_FILTER_DUAL_ANTENNA_FIX_TYPE_FIX_NONE                                                            \
    ((mip_filter_dual_antenna_fix_type_t)0u) /* No dual-antenna fix. */
#define MIP_FILTER_DUAL_ANTENNA_FIX_TYPE_FIX_DA_FLOAT                                                        \
    ((mip_filter_dual_antenna_fix_type_t)1u) /* Dual-antenna float solution. */
#define MIP_FILTER_DUAL_ANTENNA_FIX_TYPE_FIX_DA_FIXED                                                        \
    ((mip_filter_dual_antenna_fix_type_t)2u) /* Dual-antenna fixed (integer) solution. */

/** Dual-antenna status flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mip_filter_dual_antenna_status_flags_t;
#define MIP_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_1_DATA_VALID_MASK                                           \
    ((mip_filter_dual_antenna_status_flags_t)0x1u) /* bit 0: Data from receiver 1 are valid. */
#define MIP_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_1_DATA_VALID_SHIFT 0
#define MIP_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_2_DATA_VALID_MASK                                           \
    ((mip_filter_dual_antenna_status_flags_t)0x2u) /* bit 1: Data from receiver 2 are valid. */
#define MIP_FILTER_DUAL_ANTENNA_STATUS_FLAGS_RCV_2_DATA_VALID_SHIFT 1
#define MIP_FILTER_DUAL_ANTENNA_STATUS_FLAGS_ANTENNA_OFFSETS_VALID_MASK                                      \
    ((mip_filter_dual_antenna_status_flags_t)0x4u) /* bit 2: The antenna offsets are valid. */
#define MIP_FILTER_DUAL_ANTENNA_STATUS_FLAGS_ANTENNA_OFFSETS_VALID_SHIFT 2

/** Filter dynamics mode (3DM-CV7). Dynamics mode reported in Status (0x82,0x10) by the CV7 (GQ7-family
 * filter). An integer, so that values the spec does not list are kept. */
typedef uint16_t mip_filter_dynamics_mode_cv7_t;
#define MIP_FILTER_DYNAMICS_MODE_CV7_DEFAULT                                                                 \
    ((mip_filter_dynamics_mode_cv7_t)1u) /* Default dynamics mode (printed GQ7_DEFAULT). */

/** Filter dynamics mode (3DM-GX5-45). Vehicle dynamics mode the GX5-45 filter runs with, as reported in
 * Filter Status (0x82,0x10). An integer, so that values the spec does not list are kept. */
typedef uint16_t mip_filter_dynamics_mode_gx5_t;
#define MIP_FILTER_DYNAMICS_MODE_GX5_PORTABLE                                                                \
    ((mip_filter_dynamics_mode_gx5_t)1u) /* Portable (low-acceleration applications). */
#define MIP_FILTER_DYNAMICS_MODE_GX5_AUTOMOTIVE                                                              \
    ((mip_filter_dynamics_mode_gx5_t)2u) /* Automotive (wheeled vehicles, low vertical acceleration). */
#define MIP_FILTER_DYNAMICS_MODE_GX5_AIRBORNE ((mip_filter_dynamics_mode_gx5_t)3u) /* Airborne (up to 2 g).  \
                                                                                    */

/** GNSS position aiding status. What the filter does with the measurements of one GNSS receiver.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mip_filter_gnss_aiding_status_flags_t;
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_TIGHT_COUPLING_MASK                                              \
    ((mip_filter_gnss_aiding_status_flags_t)0x1u) /* bit 0: The filter is processing raw range information   \
                                                     from this receiver. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_TIGHT_COUPLING_SHIFT 0
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_DIFFERENTIAL_MASK                                                \
    ((mip_filter_gnss_aiding_status_flags_t)0x2u) /* bit 1: The filter is processing RTK corrections from    \
                                                     this receiver. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_DIFFERENTIAL_SHIFT 1
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_INTEGER_FIX_MASK                                                 \
    ((mip_filter_gnss_aiding_status_flags_t)0x4u) /* bit 2: The filter has an RTK integer fix from this      \
                                                     receiver. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_INTEGER_FIX_SHIFT 2
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L1_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x8u) /* bit 3: GPS L1 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L1_SHIFT 3
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L2_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x10u) /* bit 4: GPS L2 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L2_SHIFT 4
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L5_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x20u) /* bit 5: GPS L5 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GPS_L5_SHIFT 5
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L1_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x40u) /* bit 6: GLONASS L1 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L1_SHIFT 6
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L2_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x80u) /* bit 7: GLONASS L2 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GLO_L2_SHIFT 7
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E1_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x100u) /* bit 8: Galileo E1 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E1_SHIFT 8
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E5_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x200u) /* bit 9: Galileo E5 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E5_SHIFT 9
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E6_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x400u) /* bit 10: Galileo E6 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_GAL_E6_SHIFT 10
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B1_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x800u) /* bit 11: BeiDou B1 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B1_SHIFT 11
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B2_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x1000u) /* bit 12: BeiDou B2 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B2_SHIFT 12
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B3_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x2000u) /* bit 13: BeiDou B3 measurements used. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_BEI_B3_SHIFT 13
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_NO_FIX_MASK                                                      \
    ((mip_filter_gnss_aiding_status_flags_t)0x4000u) /* bit 14: This receiver reports no position fix. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_NO_FIX_SHIFT 14
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_CONFIG_ERROR_MASK                                                \
    ((mip_filter_gnss_aiding_status_flags_t)0x8000u) /* bit 15: Probably a problem with this receiver's      \
                                                        antenna offset. */
#define MIP_FILTER_GNSS_AIDING_STATUS_FLAGS_CONFIG_ERROR_SHIFT 15

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

/** Heading update sources in use. Sources currently providing heading updates; 0 means none (heading updates
 * disabled). The whole integer is kept (reserved bits too); members are read with the masks below: (value &
 * X_MASK) >> X_SHIFT. */
typedef uint16_t mip_filter_heading_source_flags_t;
#define MIP_FILTER_HEADING_SOURCE_FLAGS_MAGNETOMETER_MASK                                                    \
    ((mip_filter_heading_source_flags_t)0x1u) /* bit 0: Internal magnetometer. */
#define MIP_FILTER_HEADING_SOURCE_FLAGS_MAGNETOMETER_SHIFT 0
#define MIP_FILTER_HEADING_SOURCE_FLAGS_GNSS_VELOCITY_MASK                                                   \
    ((mip_filter_heading_source_flags_t)0x2u) /* bit 1: GNSS velocity vector. */
#define MIP_FILTER_HEADING_SOURCE_FLAGS_GNSS_VELOCITY_SHIFT 1
#define MIP_FILTER_HEADING_SOURCE_FLAGS_EXTERNAL_MASK                                                        \
    ((mip_filter_heading_source_flags_t)0x4u) /* bit 2: External Heading Update messages (0x0D,0x17), with   \
                                                 or without timestamp (0x0D,0x1F). */
#define MIP_FILTER_HEADING_SOURCE_FLAGS_EXTERNAL_SHIFT 2

/** Heading update state valid flags.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mip_filter_heading_update_valid_flags_t;
#define MIP_FILTER_HEADING_UPDATE_VALID_FLAGS_UPDATED_WITHIN_2S_MASK                                         \
    ((mip_filter_heading_update_valid_flags_t)0x1u) /* bit 0: The heading update source provided data within \
                                                       the last 2 seconds (0: no update for 2 seconds). */
#define MIP_FILTER_HEADING_UPDATE_VALID_FLAGS_UPDATED_WITHIN_2S_SHIFT 0

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

/** Filter mode (3DM-CV7). Mode the CV7 navigation filter has reached, reported as the filter state in Status
 * (0x82,0x10); it depends on the initial conditions the filter was given. An integer, so that values the spec
 * does not list are kept. */
typedef uint16_t mip_filter_mode_cv7_t;
#define MIP_FILTER_MODE_CV7_INIT                                                                             \
    ((mip_filter_mode_cv7_t)1u) /* Initialization: initial conditions incomplete or invalid, or waiting for  \
                                   user input. */
#define MIP_FILTER_MODE_CV7_VERT_GYRO                                                                        \
    ((mip_filter_mode_cv7_t)2u) /* Vertical gyro: valid pitch and roll, heading relative to the initial      \
                                   heading. */
#define MIP_FILTER_MODE_CV7_AHRS                                                                             \
    ((mip_filter_mode_cv7_t)3u) /* AHRS: as vertical gyro, with an absolute heading reference. */
#define MIP_FILTER_MODE_CV7_FULL_NAV                                                                         \
    ((mip_filter_mode_cv7_t)4u) /* Full navigation: valid position, velocity, pitch, roll and heading. */

/** Filter output valid flags. Valid flags of a filter output field: 0x0000 the values are invalid, 0x0001
 * they are valid. The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mip_filter_output_valid_flags_t;
#define MIP_FILTER_OUTPUT_VALID_FLAGS_VALID_MASK                                                             \
    ((mip_filter_output_valid_flags_t)0x1u) /* bit 0: The values of this field are valid. */
#define MIP_FILTER_OUTPUT_VALID_FLAGS_VALID_SHIFT 0

/** Reference frame of user-specified positions and velocities.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_filter_reference_frame_t;
#define MIP_FILTER_REFERENCE_FRAME_ECEF                                                                      \
    ((mip_filter_reference_frame_t)1u) /* WGS84 Earth-centered, Earth-fixed coordinates. */
#define MIP_FILTER_REFERENCE_FRAME_LLH                                                                       \
    ((mip_filter_reference_frame_t)2u) /* WGS84 latitude, longitude and height above ellipsoid. */

/** Filter state (3DM-GX5-45). Operating state of the GX5-45 estimation filter, reported in Filter Status
 * (0x82,0x10). An integer, so that values the spec does not list are kept. */
typedef uint16_t mip_filter_state_gx5_t;
#define MIP_FILTER_STATE_GX5_STARTUP ((mip_filter_state_gx5_t)0u) /* Filter starting up. */
#define MIP_FILTER_STATE_GX5_INIT                                                                            \
    ((mip_filter_state_gx5_t)1u) /* Initializing; the status flags tell what is still missing. */
#define MIP_FILTER_STATE_GX5_RUN_SOLUTION_VALID                                                              \
    ((mip_filter_state_gx5_t)2u) /* Running, the solution is valid. */
#define MIP_FILTER_STATE_GX5_RUN_SOLUTION_ERROR                                                              \
    ((mip_filter_state_gx5_t)3u) /* Running, the solution has an error; the status flags tell which. */

/** Filter status flags (3DM-CV7). CV7 (GQ7-family) filter status flags: the filter condition in bits 0-1 (1
 * stable, 2 converging, 3 unstable/recovering), estimate warnings in bits 2-10 and solution error flags in
 * bits 12-15. The whole integer is kept (reserved bits too); members are read with the masks below: (value &
 * X_MASK) >> X_SHIFT. */
typedef uint16_t mip_filter_status_flags_cv7_t;
#define MIP_FILTER_STATUS_FLAGS_CV7_FILTER_CONDITION_MASK                                                    \
    ((mip_filter_status_flags_cv7_t)0x3u) /* bits 0-1: Filter condition: 1 stable, 2 converging, 3           \
                                             unstable/recovering. */
#define MIP_FILTER_STATUS_FLAGS_CV7_FILTER_CONDITION_SHIFT 0
#define MIP_FILTER_STATUS_FLAGS_CV7_ROLL_PITCH_WARNING_MASK                                                  \
    ((mip_filter_status_flags_cv7_t)0x4u) /* bit 2: Low confidence in roll/pitch (e.g. sensor not aligned    \
                                             with the vehicle frame). */
#define MIP_FILTER_STATUS_FLAGS_CV7_ROLL_PITCH_WARNING_SHIFT 2
#define MIP_FILTER_STATUS_FLAGS_CV7_HEADING_WARNING_MASK                                                     \
    ((mip_filter_status_flags_cv7_t)0x8u) /* bit 3: Low confidence in heading (heading source not valid). */
#define MIP_FILTER_STATUS_FLAGS_CV7_HEADING_WARNING_SHIFT 3
#define MIP_FILTER_STATUS_FLAGS_CV7_POSITION_WARNING_MASK                                                    \
    ((mip_filter_status_flags_cv7_t)0x10u) /* bit 4: Low confidence in position. */
#define MIP_FILTER_STATUS_FLAGS_CV7_POSITION_WARNING_SHIFT 4
#define MIP_FILTER_STATUS_FLAGS_CV7_VELOCITY_WARNING_MASK                                                    \
    ((mip_filter_status_flags_cv7_t)0x20u) /* bit 5: Low confidence in velocity. */
#define MIP_FILTER_STATUS_FLAGS_CV7_VELOCITY_WARNING_SHIFT 5
#define MIP_FILTER_STATUS_FLAGS_CV7_IMU_BIAS_WARNING_MASK                                                    \
    ((mip_filter_status_flags_cv7_t)0x40u) /* bit 6: IMU bias estimate warning (gyro bias high). */
#define MIP_FILTER_STATUS_FLAGS_CV7_IMU_BIAS_WARNING_SHIFT 6
#define MIP_FILTER_STATUS_FLAGS_CV7_GNSS_CLK_WARNING_MASK                                                    \
    ((mip_filter_status_flags_cv7_t)0x80u) /* bit 7: GNSS clock warning (affects the filter timestamp). */
#define MIP_FILTER_STATUS_FLAGS_CV7_GNSS_CLK_WARNING_SHIFT 7
#define MIP_FILTER_STATUS_FLAGS_CV7_ANTENNA_LEVER_ARM_WARNING_MASK                                           \
    ((mip_filter_status_flags_cv7_t)0x100u) /* bit 8: Antenna lever arm offsets are likely incorrect. */
#define MIP_FILTER_STATUS_FLAGS_CV7_ANTENNA_LEVER_ARM_WARNING_SHIFT 8
#define MIP_FILTER_STATUS_FLAGS_CV7_MOUNTING_TRANSFORM_WARNING_MASK                                          \
    ((mip_filter_status_flags_cv7_t)0x200u) /* bit 9: Mounting transform is likely incorrect. */
#define MIP_FILTER_STATUS_FLAGS_CV7_MOUNTING_TRANSFORM_WARNING_SHIFT 9
#define MIP_FILTER_STATUS_FLAGS_CV7_TIME_SYNC_WARNING_MASK                                                   \
    ((mip_filter_status_flags_cv7_t)0x400u) /* bit 10: No time synchronization (PPS) pulse detected, or      \
                                               external heading timestamp too old. */
#define MIP_FILTER_STATUS_FLAGS_CV7_TIME_SYNC_WARNING_SHIFT 10
#define MIP_FILTER_STATUS_FLAGS_CV7_RESERVED_MASK                                                            \
    ((mip_filter_status_flags_cv7_t)0x800u) /* bit 11: (reserved) Not listed. */
#define MIP_FILTER_STATUS_FLAGS_CV7_RESERVED_SHIFT 11
#define MIP_FILTER_STATUS_FLAGS_CV7_SOLUTION_ERROR_MASK                                                      \
    ((mip_filter_status_flags_cv7_t)0xF000u) /* bits 12-15: Filter computation error flags (NaN in the       \
                                                solution); if any is set, all filter outputs are invalid. */
#define MIP_FILTER_STATUS_FLAGS_CV7_SOLUTION_ERROR_SHIFT 12

/** Filter status flags (3DM-GX5-45). GX5-45 filter status flags. Bits 12 and 13 mean different things
 * depending on the filter state: in the initialization state they say what is not initialized, while running
 * they are estimate warnings. The whole integer is kept (reserved bits too); members are read with the masks
 * below: (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mip_filter_status_flags_gx5_t;
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_IMU_UNAVAILABLE_MASK                                                 \
    ((mip_filter_status_flags_gx5_t)0x1u) /* bit 0: Running: IMU unavailable. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_IMU_UNAVAILABLE_SHIFT 0
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_GPS_UNAVAILABLE_MASK                                                 \
    ((mip_filter_status_flags_gx5_t)0x2u) /* bit 1: Running: GNSS unavailable. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_GPS_UNAVAILABLE_SHIFT 1
#define MIP_FILTER_STATUS_FLAGS_GX5_RESERVED_MASK                                                            \
    ((mip_filter_status_flags_gx5_t)0x4u) /* bit 2: (reserved) Not listed (0x0004). */
#define MIP_FILTER_STATUS_FLAGS_GX5_RESERVED_SHIFT 2
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_MATRIX_SINGULARITY_MASK                                              \
    ((mip_filter_status_flags_gx5_t)0x8u) /* bit 3: Running: matrix singularity in the calculation. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_MATRIX_SINGULARITY_SHIFT 3
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_POSITION_COVARIANCE_WARNING_MASK                                     \
    ((mip_filter_status_flags_gx5_t)0x10u) /* bit 4: Running: position covariance high (some axis beyond     \
                                              normal limits). */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_POSITION_COVARIANCE_WARNING_SHIFT 4
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_VELOCITY_COVARIANCE_WARNING_MASK                                     \
    ((mip_filter_status_flags_gx5_t)0x20u) /* bit 5: Running: velocity covariance high (some axis beyond     \
                                              normal limits). */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_VELOCITY_COVARIANCE_WARNING_SHIFT 5
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_ATTITUDE_COVARIANCE_WARNING_MASK                                     \
    ((mip_filter_status_flags_gx5_t)0x40u) /* bit 6: Running: attitude covariance high (some axis beyond     \
                                              normal limits). */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_ATTITUDE_COVARIANCE_WARNING_SHIFT 6
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_NAN_IN_SOLUTION_WARNING_MASK                                         \
    ((mip_filter_status_flags_gx5_t)0x80u) /* bit 7: Running: NaN in the solution. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_NAN_IN_SOLUTION_WARNING_SHIFT 7
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_BIAS_EST_HIGH_WARNING_MASK                                      \
    ((mip_filter_status_flags_gx5_t)0x100u) /* bit 8: Running: gyro bias estimate high. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_BIAS_EST_HIGH_WARNING_SHIFT 8
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_BIAS_EST_HIGH_WARNING_MASK                                     \
    ((mip_filter_status_flags_gx5_t)0x200u) /* bit 9: Running: accel bias estimate high. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_BIAS_EST_HIGH_WARNING_SHIFT 9
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING_MASK                              \
    ((mip_filter_status_flags_gx5_t)0x400u) /* bit 10: Running: gyro scale factor estimate high. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING_SHIFT 10
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING_MASK                             \
    ((mip_filter_status_flags_gx5_t)0x800u) /* bit 11: Running: accel scale factor estimate high. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING_SHIFT 11
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_MAG_BIAS_EST_HIGH_WARNING_MASK                                       \
    ((mip_filter_status_flags_gx5_t)0x1000u) /* bit 12: Running: magnetometer bias estimate high. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_MAG_BIAS_EST_HIGH_WARNING_SHIFT 12
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING_MASK                          \
    ((mip_filter_status_flags_gx5_t)0x2000u) /* bit 13: Running: GNSS antenna offset correction estimate     \
                                                high. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING_SHIFT 13
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_MAG_HARD_IRON_EST_HIGH_WARNING_MASK                                  \
    ((mip_filter_status_flags_gx5_t)0x4000u) /* bit 14: Running: hard iron offset estimate high. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_MAG_HARD_IRON_EST_HIGH_WARNING_SHIFT 14
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_MAG_SOFT_IRON_EST_HIGH_WARNING_MASK                                  \
    ((mip_filter_status_flags_gx5_t)0x8000u) /* bit 15: Running: soft iron correction estimate high. */
#define MIP_FILTER_STATUS_FLAGS_GX5_RUN_MAG_SOFT_IRON_EST_HIGH_WARNING_SHIFT 15
#define MIP_FILTER_STATUS_FLAGS_GX5_INIT_NO_ATTITUDE_MASK                                                    \
    ((mip_filter_status_flags_gx5_t)0x1000u) /* bit 12: Initialization: attitude not initialized (same bit   \
                                                as run_mag_bias_est_high_warning). */
#define MIP_FILTER_STATUS_FLAGS_GX5_INIT_NO_ATTITUDE_SHIFT 12
#define MIP_FILTER_STATUS_FLAGS_GX5_INIT_NO_POSITION_VELOCITY_MASK                                           \
    ((mip_filter_status_flags_gx5_t)0x2000u) /* bit 13: Initialization: position and velocity not            \
                                                initialized (same bit as                                     \
                                                run_ant_offset_correction_est_high_warning). */
#define MIP_FILTER_STATUS_FLAGS_GX5_INIT_NO_POSITION_VELOCITY_SHIFT 13

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

/** GPIO behavior for the ENCODER feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gpio_encoder_behavior_t;
#define MIP_GPIO_ENCODER_BEHAVIOR_UNUSED ((mip_gpio_encoder_behavior_t)0u) /* No behavior. */
#define MIP_GPIO_ENCODER_BEHAVIOR_ENCODER_A                                                                  \
    ((mip_gpio_encoder_behavior_t)1u) /* ENCODER_A: quadrature input A; one pin at most (the latest command  \
                                         wins). */
#define MIP_GPIO_ENCODER_BEHAVIOR_ENCODER_B                                                                  \
    ((mip_gpio_encoder_behavior_t)2u) /* ENCODER_B: quadrature input B; one pin at most (the latest command  \
                                         wins). */

/** GPIO pin feature. What a user GPIO pin is used for; selects how the behavior byte is read.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gpio_feature_t;
#define MIP_GPIO_FEATURE_UNUSED                                                                              \
    ((mip_gpio_feature_t)0u) /* Pin not used; reading its state may or may not work. */
#define MIP_GPIO_FEATURE_GPIO                                                                                \
    ((mip_gpio_feature_t)1u) /* General purpose input or output (direct control or monitoring of the pin     \
                                state). */
#define MIP_GPIO_FEATURE_PPS ((mip_gpio_feature_t)2u)     /* Pulse-per-second input or output. */
#define MIP_GPIO_FEATURE_ENCODER ((mip_gpio_feature_t)3u) /* Motor encoder / odometer input. */
#define MIP_GPIO_FEATURE_TIMESTAMP                                                                           \
    ((mip_gpio_feature_t)4u) /* Precision timestamping of edges (for event triggers, 0x0C,0x2E). */
#define MIP_GPIO_FEATURE_UART ((mip_gpio_feature_t)5u) /* UART data or control line. */

/** GPIO behavior for the GPIO feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gpio_io_behavior_t;
#define MIP_GPIO_IO_BEHAVIOR_UNUSED ((mip_gpio_io_behavior_t)0u) /* No behavior. */
#define MIP_GPIO_IO_BEHAVIOR_INPUT                                                                           \
    ((mip_gpio_io_behavior_t)1u) /* GPIO_INPUT: the pin is an input that can be streamed or polled (the      \
                                    default). */
#define MIP_GPIO_IO_BEHAVIOR_OUTPUT_LOW                                                                      \
    ((mip_gpio_io_behavior_t)2u) /* GPIO_OUTPUT_LOW: output, initially low (restored at startup if saved).   \
                                  */
#define MIP_GPIO_IO_BEHAVIOR_OUTPUT_HIGH                                                                     \
    ((mip_gpio_io_behavior_t)3u) /* GPIO_OUTPUT_HIGH: output, initially high (restored at startup if saved). \
                                  */

/** GPIO pin electrical mode. Electrical configuration of a GPIO pin; which combinations a (feature, behavior)
 * pair supports is listed in the User GPIO pin-mode table (line 1338). The whole integer is kept (reserved
 * bits too); members are read with the masks below: (value & X_MASK) >> X_SHIFT. */
typedef uint8_t mip_gpio_pin_mode_t;
#define MIP_GPIO_PIN_MODE_OPEN_DRAIN_MASK                                                                    \
    ((mip_gpio_pin_mode_t)0x1u) /* bit 0: Open-drain output: LOW or floating instead of LOW or HIGH; usually \
                                   with a pull-up. */
#define MIP_GPIO_PIN_MODE_OPEN_DRAIN_SHIFT 0
#define MIP_GPIO_PIN_MODE_PULLDOWN_MASK                                                                      \
    ((mip_gpio_pin_mode_t)0x2u) /* bit 1: Internal pull-down resistor enabled (not with pullup). */
#define MIP_GPIO_PIN_MODE_PULLDOWN_SHIFT 1
#define MIP_GPIO_PIN_MODE_PULLUP_MASK                                                                        \
    ((mip_gpio_pin_mode_t)0x4u) /* bit 2: Internal pull-up resistor enabled (not with pulldown); may lower   \
                                   the allowed input voltage. */
#define MIP_GPIO_PIN_MODE_PULLUP_SHIFT 2

/** GPIO behavior for the PPS feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gpio_pps_behavior_t;
#define MIP_GPIO_PPS_BEHAVIOR_UNUSED ((mip_gpio_pps_behavior_t)0u) /* No behavior. */
#define MIP_GPIO_PPS_BEHAVIOR_INPUT                                                                          \
    ((mip_gpio_pps_behavior_t)1u) /* PPS_INPUT: receives the PPS signal; one pin at most; needs PPS source   \
                                     GPIO (0x0C,0x28). */
#define MIP_GPIO_PPS_BEHAVIOR_OUTPUT                                                                         \
    ((mip_gpio_pps_behavior_t)2u) /* PPS_OUTPUT: transmits the device's PPS signal. */

/** GPIO behavior for the TIMESTAMP feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gpio_timestamp_behavior_t;
#define MIP_GPIO_TIMESTAMP_BEHAVIOR_UNUSED ((mip_gpio_timestamp_behavior_t)0u) /* No behavior. */
#define MIP_GPIO_TIMESTAMP_BEHAVIOR_RISING                                                                   \
    ((mip_gpio_timestamp_behavior_t)1u) /* TIMESTAMP_RISING: rising edges are timestamped. */
#define MIP_GPIO_TIMESTAMP_BEHAVIOR_FALLING                                                                  \
    ((mip_gpio_timestamp_behavior_t)2u) /* TIMESTAMP_FALLING: falling edges are timestamped. */
#define MIP_GPIO_TIMESTAMP_BEHAVIOR_EITHER                                                                   \
    ((mip_gpio_timestamp_behavior_t)3u) /* TIMESTAMP_EITHER: both edges are timestamped. */

/** GPIO behavior for the UART feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gpio_uart_behavior_t;
#define MIP_GPIO_UART_BEHAVIOR_UNUSED ((mip_gpio_uart_behavior_t)0u) /* No behavior. */
#define MIP_GPIO_UART_BEHAVIOR_PORT2_TX                                                                      \
    ((mip_gpio_uart_behavior_t)33u) /* UART_PORT2_TX: UART port 2 transmit. */
#define MIP_GPIO_UART_BEHAVIOR_PORT2_RX                                                                      \
    ((mip_gpio_uart_behavior_t)34u) /* UART_PORT2_RX: UART port 2 receive. */
#define MIP_GPIO_UART_BEHAVIOR_PORT3_TX                                                                      \
    ((mip_gpio_uart_behavior_t)49u) /* UART_PORT3_TX: UART port 3 transmit. */
#define MIP_GPIO_UART_BEHAVIOR_PORT3_RX                                                                      \
    ((mip_gpio_uart_behavior_t)50u) /* UART_PORT3_RX: UART port 3 receive. */

/** GPIO behavior for the UNUSED feature.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gpio_unused_behavior_t;
#define MIP_GPIO_UNUSED_BEHAVIOR_UNUSED                                                                      \
    ((mip_gpio_unused_behavior_t)0u) /* No behavior (0 unless otherwise specified). */

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

/** GNSS constellation ID (GX5-45 constellation settings).
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gx5_constellation_id_t;
#define MIP_GX5_CONSTELLATION_ID_GPS ((mip_gx5_constellation_id_t)0u)     /* GPS (G1-G32). */
#define MIP_GX5_CONSTELLATION_ID_SBAS ((mip_gx5_constellation_id_t)1u)    /* SBAS (S120-S158). */
#define MIP_GX5_CONSTELLATION_ID_GALILEO ((mip_gx5_constellation_id_t)2u) /* Galileo (E1-E36). */
#define MIP_GX5_CONSTELLATION_ID_BEIDOU ((mip_gx5_constellation_id_t)3u)  /* BeiDou (B1-B37). */
#define MIP_GX5_CONSTELLATION_ID_QZSS ((mip_gx5_constellation_id_t)5u)    /* QZSS (Q1-Q5). */
#define MIP_GX5_CONSTELLATION_ID_GLONASS ((mip_gx5_constellation_id_t)6u) /* GLONASS (R1-R32). */

/** Poll option selector. First byte of the GX5-45 poll commands; chooses whether the ACK/NACK is sent.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gx5_poll_option_t;
#define MIP_GX5_POLL_OPTION_NORMAL ((mip_gx5_poll_option_t)0u) /* Normal ACK/NACK reply. */
#define MIP_GX5_POLL_OPTION_SUPPRESS_ACK                                                                     \
    ((mip_gx5_poll_option_t)1u) /* No ACK/NACK reply; only the data packet is sent. */

/** Continuous data stream selector (GX5-45). Which data stream the GX5-45 Enable/Disable Continuous Data
 * Stream command controls. An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_gx5_stream_selector_t;
#define MIP_GX5_STREAM_SELECTOR_IMU ((mip_gx5_stream_selector_t)1u) /* IMU data stream (set 0x80). */
#define MIP_GX5_STREAM_SELECTOR_ESTIMATION_FILTER                                                            \
    ((mip_gx5_stream_selector_t)3u) /* Estimation filter data stream (set 0x82). */

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

/** Odometer mode.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_odometer_mode_t;
#define MIP_ODOMETER_MODE_DISABLED ((mip_odometer_mode_t)0u)   /* Encoder disabled. */
#define MIP_ODOMETER_MODE_QUADRATURE ((mip_odometer_mode_t)2u) /* Quadrature encoder mode. */

/** Pitch/roll aiding source.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_pitch_roll_aiding_source_t;
#define MIP_PITCH_ROLL_AIDING_SOURCE_NONE                                                                    \
    ((mip_pitch_roll_aiding_source_t)0u) /* No pitch/roll aiding (disabled). */
#define MIP_PITCH_ROLL_AIDING_SOURCE_GRAVITY_VECTOR                                                          \
    ((mip_pitch_roll_aiding_source_t)1u) /* Gravity vector aiding enabled. */

/** PPS source.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_pps_source_t;
#define MIP_PPS_SOURCE_DISABLED                                                                              \
    ((mip_pps_source_t)0u) /* No PPS (the table says it is not valid as a command value; see note). */
#define MIP_PPS_SOURCE_RECEIVER_1 ((mip_pps_source_t)1u) /* PPS from GNSS receiver 1. */
#define MIP_PPS_SOURCE_RECEIVER_2 ((mip_pps_source_t)2u) /* PPS from GNSS receiver 2. */
#define MIP_PPS_SOURCE_GPIO                                                                                  \
    ((mip_pps_source_t)3u) /* PPS applied to a GPIO pin (pin chosen with GPIO Configuration 0x0C,0x41). */
#define MIP_PPS_SOURCE_GENERATED ((mip_pps_source_t)4u) /* PPS generated from the system oscillator. */

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

/** SBAS options.
 * The whole integer is kept (reserved bits too); members are read with the masks below:
 * (value & X_MASK) >> X_SHIFT. */
typedef uint16_t mip_sbas_options_t;
#define MIP_SBAS_OPTIONS_ENABLE_RANGING_MASK                                                                 \
    ((mip_sbas_options_t)0x1u) /* bit 0: Use SBAS pseudoranges in the position solution (GX5-45 default on). \
                                */
#define MIP_SBAS_OPTIONS_ENABLE_RANGING_SHIFT 0
#define MIP_SBAS_OPTIONS_ENABLE_CORRECTIONS_MASK                                                             \
    ((mip_sbas_options_t)0x2u) /* bit 1: Use SBAS differential corrections (GX5-45 default on). */
#define MIP_SBAS_OPTIONS_ENABLE_CORRECTIONS_SHIFT 1
#define MIP_SBAS_OPTIONS_APPLY_INTEGRITY_MASK                                                                \
    ((mip_sbas_options_t)0x4u) /* bit 2: Use SBAS integrity information; only satellites with integrity data \
                                  are used. */
#define MIP_SBAS_OPTIONS_APPLY_INTEGRITY_SHIFT 2

/** Sensor whose range is set or queried.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_sensor_range_type_t;
#define MIP_SENSOR_RANGE_TYPE_ALL                                                                            \
    ((mip_sensor_range_type_t)0u) /* All sensors; only with save, load and default. */
#define MIP_SENSOR_RANGE_TYPE_ACCEL ((mip_sensor_range_type_t)1u) /* Accelerometer; range in g. */
#define MIP_SENSOR_RANGE_TYPE_GYRO ((mip_sensor_range_type_t)2u)  /* Gyroscope; range in degrees/s. */
#define MIP_SENSOR_RANGE_TYPE_MAG ((mip_sensor_range_type_t)3u)   /* Magnetometer; range in Gauss. */
#define MIP_SENSOR_RANGE_TYPE_PRESS ((mip_sensor_range_type_t)4u) /* Pressure sensor; range in hPa. */

/** SPARTN connection type.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_spartn_connection_type_t;
#define MIP_SPARTN_CONNECTION_TYPE_NONE ((mip_spartn_connection_type_t)0u) /* No SPARTN connection. */
#define MIP_SPARTN_CONNECTION_TYPE_NETWORK                                                                   \
    ((mip_spartn_connection_type_t)1u) /* Corrections over a network connection (e.g. NTRIP). */
#define MIP_SPARTN_CONNECTION_TYPE_L_BAND                                                                    \
    ((mip_spartn_connection_type_t)2u) /* Corrections from an L-band correction receiver. */

/** Supported events query.
 * An integer, so that values the spec does not list are kept. */
typedef uint8_t mip_supported_events_query_t;
#define MIP_SUPPORTED_EVENTS_QUERY_TRIGGER_TYPES                                                             \
    ((mip_supported_events_query_t)1u) /* Report the supported trigger types and how many of each. */
#define MIP_SUPPORTED_EVENTS_QUERY_ACTION_TYPES                                                              \
    ((mip_supported_events_query_t)2u) /* Report the supported action types and how many of each. */

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

/** GNSS constellation configuration entry.  */
typedef struct {
    mip_gx5_constellation_id_t constellation_id; /* Constellation. */
    uint8_t enable;                              /* 0x00 disable, 0x01 enable. */
    uint8_t reserved_channels; /* Tracking channels reserved for this constellation (0-32; all constellations
                                  together at most 32). */
    uint8_t max_channels;      /* Maximum tracking channels for this constellation (0-32, not below
                                  reserved_channels). */
    mip_constellation_options_t option_flags; /* Constellation options. */
} mip_constellation_settings_t;

/** Descriptor and rate decimation. One entry of a message format list. */
typedef struct {
    uint8_t descriptor;  /* Data field descriptor. */
    uint16_t decimation; /* Rate decimation: the field is output at base rate / decimation. */
} mip_descriptor_rate_t;

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

/** GpioBehaviorUnused.  */
typedef struct {
    mip_gpio_unused_behavior_t behavior; /* Behavior value (0). */
} mip_gpio_behavior_unused_t;

/** GpioBehaviorIo.  */
typedef struct {
    mip_gpio_io_behavior_t behavior; /* Input, or output with its initial state. */
} mip_gpio_behavior_io_t;

/** GpioBehaviorPps.  */
typedef struct {
    mip_gpio_pps_behavior_t behavior; /* PPS input or output. */
} mip_gpio_behavior_pps_t;

/** GpioBehaviorEncoder.  */
typedef struct {
    mip_gpio_encoder_behavior_t behavior; /* Quadrature channel A or B. */
} mip_gpio_behavior_encoder_t;

/** GpioBehaviorTimestamp.  */
typedef struct {
    mip_gpio_timestamp_behavior_t behavior; /* Which edges are timestamped. */
} mip_gpio_behavior_timestamp_t;

/** GpioBehaviorUart.  */
typedef struct {
    mip_gpio_uart_behavior_t behavior; /* UART port and direction. */
} mip_gpio_behavior_uart_t;

/** GPIO behavior, read according to the feature. The behavior byte's meaning depends on the feature: the same
 * number names a different behavior per feature (2 is GPIO_OUTPUT_LOW for GPIO, PPS_OUTPUT for PPS, ENCODER_B
 * for ENCODER, TIMESTAMP_FALLING for TIMESTAMP). Every member is one u8. The member is chosen by a parameter
 * of type mip_gpio_feature_t next to it. */
typedef union {
    mip_gpio_behavior_unused_t unused; /* unused: Feature UNUSED: behavior 0. */
    mip_gpio_behavior_io_t gpio; /* gpio: Feature GPIO: GPIO_INPUT / GPIO_OUTPUT_LOW / GPIO_OUTPUT_HIGH. */
    mip_gpio_behavior_pps_t pps; /* pps: Feature PPS: PPS_INPUT / PPS_OUTPUT. */
    mip_gpio_behavior_encoder_t encoder; /* encoder: Feature ENCODER: ENCODER_A / ENCODER_B. */
    mip_gpio_behavior_timestamp_t
        timestamp;                 /* timestamp: Feature TIMESTAMP: TIMESTAMP_RISING / _FALLING / _EITHER. */
    mip_gpio_behavior_uart_t uart; /* uart: Feature UART: UART_PORT2_TX/RX, UART_PORT3_TX/RX. */
    uint8_t none_;                 /* members without data */
} mip_gpio_behavior_t;

/** GX5-45 basic device status. Remainder of the basic device status reply after the model number and selector
 * echoes. */
typedef struct {
    uint32_t status_flags; /* Status flags (reserved). */
    uint16_t system_state; /* System state (values not documented). */
    uint32_t system_timer; /* Time since start-up. [ms] */
} mip_gx5_basic_status_t;

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
} mip_gx5_diagnostic_status_t;

/** GX5-45 device status structure.
 * The member is chosen by a parameter of type mip_device_status_selector_t next to it. */
typedef union {
    mip_gx5_basic_status_t basic;           /* basic:  */
    mip_gx5_diagnostic_status_t diagnostic; /* diagnostic:  */
    uint8_t none_;                          /* members without data */
} mip_gx5_device_status_t;

/** Poll format entry (GX5-45).  */
typedef struct {
    uint8_t descriptor; /* Data field descriptor to include in the polled packet. */
    uint16_t reserved;  /* Reserved; 0 in every example. */
} mip_gx5_poll_descriptor_t;

/** NMEA message format entry.  */
typedef struct {
    uint8_t message_id; /* NMEA sentence type (GGA, GLL, GSV, RMC, VTG, HDT, ZDA, GST, PMSRA, PMSRR; codes not
                           documented). */
    uint8_t talker_id;  /* Talker ID (GN, GP, GA, GL; ignored for GSV and proprietary sentences; codes not
                           documented). */
    uint8_t source_desc_set; /* Data descriptor set the sentence is built from (IMU, filter, GNSS 1 or 2). */
    uint16_t decimation;     /* Decimation relative to the base rate of the source descriptor set. */
} mip_nmea_message_t;

/** Calibrated sensor range entry.  */
typedef struct {
    uint8_t setting; /* Value to use as setting in Sensor Range (0x0C,0x52). */
    float range;     /* Range this setting gives; units depend on the sensor (see SensorRangeType). */
} mip_sensor_range_entry_t;

/** Supported action type.  */
typedef struct {
    mip_action_type_t type; /* Action type, as in Event Action Configuration (0x0C,0x2F). */
    uint8_t count;          /* Maximum number of instances of this type. */
} mip_supported_action_type_t;

/** Supported actions (query = action types).  */
typedef struct {
    uint8_t max_instances; /* Number of action slots; instance numbers run 1..max_instances. */
    uint8_t num_entries;   /* Number of supported action types. */
    mip_supported_action_type_t entries[125]; /* Supported action types. */
} mip_supported_actions_t;

/** Supported trigger type.  */
typedef struct {
    mip_trigger_type_t type; /* Trigger type, as in Event Trigger Configuration (0x0C,0x2E). */
    uint8_t count;           /* Maximum number of instances of this type. */
} mip_supported_trigger_type_t;

/** Supported triggers (query = trigger types).  */
typedef struct {
    uint8_t max_instances; /* Number of trigger slots; instance numbers run 1..max_instances. */
    uint8_t num_entries;   /* Number of supported trigger types. */
    mip_supported_trigger_type_t entries[125]; /* Supported trigger types. */
} mip_supported_triggers_t;

/** Supported event types, by query.
 * The member is chosen by a parameter of type mip_supported_events_query_t next to it. */
typedef union {
    mip_supported_triggers_t trigger_types; /* trigger_types:  */
    mip_supported_actions_t action_types;   /* action_types:  */
    uint8_t none_;                          /* members without data */
} mip_supported_events_info_t;

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
