/* Dispatch by (descriptor set, descriptor): devices, set kinds, the value of any field, and
 * decode/encode of any field (docs/conformance.md section 2). Generated: do not edit. */
#ifndef MIPC_DISPATCH_H
#define MIPC_DISPATCH_H

#include "mipcodec/field_iter.h"
#include "mipcodec/reserved.h"
#include "mipcodec/sets/base.h"
#include "mipcodec/sets/threedm.h"
#include "mipcodec/sets/filter.h"
#include "mipcodec/sets/gnss.h"
#include "mipcodec/sets/aiding.h"
#include "mipcodec/sets/system.h"
#include "mipcodec/sets/sensor.h"
#include "mipcodec/sets/gnss_data.h"
#include "mipcodec/sets/filter_data.h"
#include "mipcodec/sets/gnss_receiver_1.h"
#include "mipcodec/sets/gnss_receiver_2.h"
#include "mipcodec/sets/gnss_corrections.h"
#include "mipcodec/sets/gnss_external.h"
#include "mipcodec/sets/system_data.h"
#include "mipcodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Devices named by the spec; MIPC_DEVICE_ANY tries every per-device variant. */
typedef enum {
    MIPC_DEVICE_ANY = 0,
    MIPC_DEVICE_GX5_45 = 1, /* 3DM-GX5-45 */
    MIPC_DEVICE_CV7_INS = 2 /* 3DM-CV7-GNSS/INS */
} mipc_device_t;

/** The id of a device ("gx5_45"), or NULL for MIPC_DEVICE_ANY. */
const char *mipc_device_id(mipc_device_t device);
/** Looks up a device by id; false if there is none. */
bool mipc_device_from_id(const char *id, mipc_device_t *out);
/** The device's title ("3DM-GX5-45") and the file name of its manual, or NULL for
 * MIPC_DEVICE_ANY. */
const char *mipc_device_title(mipc_device_t device);
const char *mipc_device_manual(mipc_device_t device);
/** What the device supports, as its manual documents it (the IR's `capabilities`): the
 * (set << 8) | descriptor of every command, or of every data quantity, ascending, in a constant
 * table; *count is set to its length (0 and NULL for MIPC_DEVICE_ANY). No allocation. */
const uint16_t *mipc_device_commands(mipc_device_t device, size_t *count);
const uint16_t *mipc_device_data(mipc_device_t device, size_t *count);
/** The baud rates of the device's main port as its manual lists them (the IR's `link`), ascending,
 * in a constant table; *count is set to its length (0 and NULL for MIPC_DEVICE_ANY or a model
 * whose manual lists none). */
const uint32_t *mipc_device_baud_rates(mipc_device_t device, size_t *count);
/** The default baud rate of the device's main port; 0 when its manual states none. */
uint32_t mipc_device_default_baud(mipc_device_t device);
/** True when the device's manual documents the command or data quantity (set, descriptor); the
 * sessions refuse a command for which this is false, before sending it. */
bool mipc_device_supports(mipc_device_t device, uint8_t set, uint8_t descriptor);

/** Kind of a descriptor set, from the set_kinds ranges. */
typedef enum {
    MIPC_SET_KIND_NONE = 0,
    MIPC_SET_KIND_COMMAND = 1, /* 0x01..0x7F */
    MIPC_SET_KIND_DATA = 2     /* 0x80..0xFF */
} mipc_set_kind_t;

mipc_set_kind_t mipc_set_kind(uint8_t set);

/** One id per field layout (per-device variants have one each). */
typedef enum {
    MIPC_FIELD_NONE = 0,
    MIPC_FIELD_ACK_NACK,
    MIPC_FIELD_BASE_PING,
    MIPC_FIELD_BASE_SET_TO_IDLE,
    MIPC_FIELD_BASE_GET_DEVICE_INFO,
    MIPC_FIELD_BASE_DEVICE_INFO,
    MIPC_FIELD_BASE_GET_DEVICE_DESCRIPTORS,
    MIPC_FIELD_BASE_DEVICE_DESCRIPTORS,
    MIPC_FIELD_BASE_BUILT_IN_TEST,
    MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45,
    MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS,
    MIPC_FIELD_BASE_RESUME,
    MIPC_FIELD_BASE_GET_EXTENDED_DESCRIPTORS,
    MIPC_FIELD_BASE_EXTENDED_DESCRIPTORS,
    MIPC_FIELD_BASE_CONTINUOUS_BIT,
    MIPC_FIELD_BASE_CONTINUOUS_BIT_RESULT,
    MIPC_FIELD_BASE_COMM_PORT_SPEED,
    MIPC_FIELD_BASE_COMM_PORT_SPEED_RESPONSE,
    MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45,
    MIPC_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS,
    MIPC_FIELD_BASE_GPS_WEEK,
    MIPC_FIELD_BASE_GPS_SECONDS,
    MIPC_FIELD_BASE_DEVICE_RESET,
    MIPC_FIELD_THREEDM_EVENT_CONTROL,
    MIPC_FIELD_THREEDM_EVENT_CONTROL_RESPONSE,
    MIPC_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS,
    MIPC_FIELD_THREEDM_EVENT_TRIGGER_STATUS,
    MIPC_FIELD_THREEDM_GET_EVENT_ACTION_STATUS,
    MIPC_FIELD_THREEDM_EVENT_ACTION_STATUS,
    MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG,
    MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE,
    MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG,
    MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE,
    MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45,
    MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS,
    MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER,
    MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE,
    MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION,
    MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE,
    MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM,
    MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE,
    MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45,
    MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS,
    MIPC_FIELD_THREEDM_ACCEL_BIAS_RESPONSE,
    MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45,
    MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS,
    MIPC_FIELD_THREEDM_GYRO_BIAS_RESPONSE,
    MIPC_FIELD_THREEDM_CAPTURE_GYRO_BIAS,
    MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45,
    MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS,
    MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE,
    MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45,
    MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS,
    MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE,
    MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE,
    MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE,
    MIPC_FIELD_THREEDM_UART_BAUDRATE,
    MIPC_FIELD_THREEDM_UART_BAUDRATE_RESPONSE,
    MIPC_FIELD_THREEDM_GPIO_CONFIG,
    MIPC_FIELD_THREEDM_GPIO_CONFIG_RESPONSE,
    MIPC_FIELD_THREEDM_GPIO_STATE,
    MIPC_FIELD_THREEDM_GPIO_STATE_RESPONSE,
    MIPC_FIELD_THREEDM_ODOMETER_CONFIG,
    MIPC_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE,
    MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER,
    MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE,
    MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER,
    MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE,
    MIPC_FIELD_THREEDM_SENSOR_RANGE,
    MIPC_FIELD_THREEDM_SENSOR_RANGE_RESPONSE,
    MIPC_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES,
    MIPC_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES,
    MIPC_FIELD_THREEDM_LOWPASS_FILTER,
    MIPC_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE,
    MIPC_FIELD_THREEDM_POLL_IMU_DATA,
    MIPC_FIELD_THREEDM_POLL_GNSS_DATA,
    MIPC_FIELD_THREEDM_POLL_FILTER_DATA,
    MIPC_FIELD_THREEDM_POLL_NMEA_DATA,
    MIPC_FIELD_THREEDM_POLL_DATA,
    MIPC_FIELD_THREEDM_GET_IMU_BASE_RATE,
    MIPC_FIELD_THREEDM_IMU_BASE_RATE,
    MIPC_FIELD_THREEDM_GET_GNSS_BASE_RATE,
    MIPC_FIELD_THREEDM_GNSS_BASE_RATE,
    MIPC_FIELD_THREEDM_GET_FILTER_BASE_RATE,
    MIPC_FIELD_THREEDM_FILTER_BASE_RATE,
    MIPC_FIELD_THREEDM_GET_BASE_RATE,
    MIPC_FIELD_THREEDM_BASE_RATE,
    MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT,
    MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE,
    MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT,
    MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE,
    MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT,
    MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE,
    MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT,
    MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE,
    MIPC_FIELD_THREEDM_MESSAGE_FORMAT,
    MIPC_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE,
    MIPC_FIELD_THREEDM_FACTORY_STREAMING,
    MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45,
    MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS,
    MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45,
    MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS,
    MIPC_FIELD_THREEDM_RAW_RTCM_MESSAGE,
    MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS,
    MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE,
    MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS,
    MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE,
    MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL,
    MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE,
    MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE,
    MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE,
    MIPC_FIELD_THREEDM_PPS_SOURCE,
    MIPC_FIELD_THREEDM_PPS_SOURCE_RESPONSE,
    MIPC_FIELD_THREEDM_GET_SUPPORTED_EVENTS,
    MIPC_FIELD_THREEDM_SUPPORTED_EVENTS,
    MIPC_FIELD_THREEDM_DEVICE_STATUS,
    MIPC_FIELD_THREEDM_DEVICE_STATUS_RESPONSE,
    MIPC_FIELD_FILTER_RESET_FILTER,
    MIPC_FIELD_FILTER_SET_INITIAL_ATTITUDE,
    MIPC_FIELD_FILTER_SET_INITIAL_HEADING,
    MIPC_FIELD_FILTER_RUN_FILTER,
    MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE,
    MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE,
    MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM,
    MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE,
    MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET,
    MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE,
    MIPC_FIELD_FILTER_ANTENNA_OFFSET,
    MIPC_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE,
    MIPC_FIELD_FILTER_ESTIMATION_CONTROL,
    MIPC_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL,
    MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_EXTERNAL_GNSS_UPDATE,
    MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE,
    MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL,
    MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_AUTO_INIT_CONTROL,
    MIPC_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_ACCEL_NOISE,
    MIPC_FIELD_FILTER_ACCEL_NOISE_RESPONSE,
    MIPC_FIELD_FILTER_GYRO_NOISE,
    MIPC_FIELD_FILTER_GYRO_NOISE_RESPONSE,
    MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL,
    MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE,
    MIPC_FIELD_FILTER_GYRO_BIAS_MODEL,
    MIPC_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE,
    MIPC_FIELD_FILTER_ZUPT_CONTROL,
    MIPC_FIELD_FILTER_ZUPT_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME,
    MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL,
    MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_TARE_ORIENTATION,
    MIPC_FIELD_FILTER_COMMANDED_ZUPT,
    MIPC_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE,
    MIPC_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION,
    MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV,
    MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE,
    MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV,
    MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE,
    MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE,
    MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE,
    MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE,
    MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE,
    MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV,
    MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE,
    MIPC_FIELD_FILTER_DECLINATION_SOURCE,
    MIPC_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE,
    MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT,
    MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE,
    MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT,
    MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE,
    MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT,
    MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE,
    MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL,
    MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL,
    MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_INCLINATION_SOURCE,
    MIPC_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE,
    MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE,
    MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE,
    MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL,
    MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION,
    MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE,
    MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL,
    MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET,
    MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE,
    MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION,
    MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE,
    MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM,
    MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE,
    MIPC_FIELD_FILTER_SPEED_LEVER_ARM,
    MIPC_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE,
    MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL,
    MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE,
    MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL,
    MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE,
    MIPC_FIELD_GNSS_RECEIVER_INFO,
    MIPC_FIELD_GNSS_RECEIVER_INFO_RESPONSE,
    MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION,
    MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE,
    MIPC_FIELD_GNSS_SPARTN_CONFIGURATION,
    MIPC_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE,
    MIPC_FIELD_AIDING_FRAME_CONFIG,
    MIPC_FIELD_AIDING_FRAME_CONFIG_RESPONSE,
    MIPC_FIELD_AIDING_ECHO_CONTROL,
    MIPC_FIELD_AIDING_ECHO_CONTROL_RESPONSE,
    MIPC_FIELD_AIDING_ECEF_POSITION,
    MIPC_FIELD_AIDING_LLH_POSITION,
    MIPC_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID,
    MIPC_FIELD_AIDING_ECEF_VELOCITY,
    MIPC_FIELD_AIDING_NED_VELOCITY,
    MIPC_FIELD_AIDING_BODY_FRAME_VELOCITY,
    MIPC_FIELD_AIDING_TRUE_HEADING,
    MIPC_FIELD_AIDING_MAGNETIC_FIELD,
    MIPC_FIELD_AIDING_PRESSURE,
    MIPC_FIELD_SYSTEM_COMMUNICATION_MODE,
    MIPC_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE,
    MIPC_FIELD_SENSOR_SCALED_ACCEL,
    MIPC_FIELD_SENSOR_SCALED_GYRO,
    MIPC_FIELD_SENSOR_SCALED_MAG,
    MIPC_FIELD_SENSOR_DELTA_THETA,
    MIPC_FIELD_SENSOR_DELTA_VELOCITY,
    MIPC_FIELD_SENSOR_CF_ORIENTATION_MATRIX,
    MIPC_FIELD_SENSOR_CF_QUATERNION,
    MIPC_FIELD_SENSOR_CF_EULER_ANGLES,
    MIPC_FIELD_SENSOR_CF_STABILIZED_NORTH,
    MIPC_FIELD_SENSOR_CF_STABILIZED_UP,
    MIPC_FIELD_SENSOR_GPS_TIMESTAMP,
    MIPC_FIELD_SENSOR_TEMPERATURE_STATISTICS,
    MIPC_FIELD_SENSOR_SCALED_PRESSURE,
    MIPC_FIELD_SENSOR_OVERRANGE_STATUS,
    MIPC_FIELD_SENSOR_ODOMETER_DATA,
    MIPC_FIELD_GNSS_DATA_LLH_POSITION,
    MIPC_FIELD_GNSS_DATA_ECEF_POSITION,
    MIPC_FIELD_GNSS_DATA_NED_VELOCITY,
    MIPC_FIELD_GNSS_DATA_ECEF_VELOCITY,
    MIPC_FIELD_GNSS_DATA_DOP,
    MIPC_FIELD_GNSS_DATA_UTC_TIME,
    MIPC_FIELD_GNSS_DATA_GPS_TIME,
    MIPC_FIELD_GNSS_DATA_CLOCK_INFO,
    MIPC_FIELD_GNSS_DATA_FIX_INFO,
    MIPC_FIELD_GNSS_DATA_SV_INFO,
    MIPC_FIELD_GNSS_DATA_HARDWARE_STATUS,
    MIPC_FIELD_GNSS_DATA_DGNSS_INFO,
    MIPC_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS,
    MIPC_FIELD_FILTER_DATA_LLH_POSITION,
    MIPC_FIELD_FILTER_DATA_NED_VELOCITY,
    MIPC_FIELD_FILTER_DATA_ATTITUDE_QUATERNION,
    MIPC_FIELD_FILTER_DATA_ATTITUDE_DCM,
    MIPC_FIELD_FILTER_DATA_EULER_ANGLES,
    MIPC_FIELD_FILTER_DATA_GYRO_BIAS,
    MIPC_FIELD_FILTER_DATA_ACCEL_BIAS,
    MIPC_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_LINEAR_ACCEL,
    MIPC_FIELD_FILTER_DATA_COMP_ANGULAR_RATE,
    MIPC_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE,
    MIPC_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45,
    MIPC_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS,
    MIPC_FIELD_FILTER_DATA_GPS_TIMESTAMP,
    MIPC_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_GRAVITY_VECTOR,
    MIPC_FIELD_FILTER_DATA_HEADING_UPDATE_STATE,
    MIPC_FIELD_FILTER_DATA_MAGNETIC_MODEL,
    MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR,
    MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR,
    MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_COMPENSATED_ACCEL,
    MIPC_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE,
    MIPC_FIELD_FILTER_DATA_PRESSURE_ALTITUDE,
    MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET,
    MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX,
    MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION,
    MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION,
    MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_ECEF_POSITION,
    MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY,
    MIPC_FIELD_FILTER_DATA_NED_RELATIVE_POSITION,
    MIPC_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS,
    MIPC_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY,
    MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR,
    MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY,
    MIPC_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS,
    MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR,
    MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY,
    MIPC_FIELD_GNSS_RECEIVER_1_LLH_POSITION,
    MIPC_FIELD_GNSS_RECEIVER_1_ECEF_POSITION,
    MIPC_FIELD_GNSS_RECEIVER_1_NED_VELOCITY,
    MIPC_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY,
    MIPC_FIELD_GNSS_RECEIVER_1_DOP,
    MIPC_FIELD_GNSS_RECEIVER_1_UTC_TIME,
    MIPC_FIELD_GNSS_RECEIVER_1_GPS_TIME,
    MIPC_FIELD_GNSS_RECEIVER_1_FIX_INFO,
    MIPC_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS,
    MIPC_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2,
    MIPC_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS,
    MIPC_FIELD_GNSS_RECEIVER_1_SBAS_INFO,
    MIPC_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS,
    MIPC_FIELD_GNSS_RECEIVER_1_RAW,
    MIPC_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS,
    MIPC_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS,
    MIPC_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS,
    MIPC_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS,
    MIPC_FIELD_GNSS_RECEIVER_2_LLH_POSITION,
    MIPC_FIELD_GNSS_RECEIVER_2_ECEF_POSITION,
    MIPC_FIELD_GNSS_RECEIVER_2_NED_VELOCITY,
    MIPC_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY,
    MIPC_FIELD_GNSS_RECEIVER_2_DOP,
    MIPC_FIELD_GNSS_RECEIVER_2_UTC_TIME,
    MIPC_FIELD_GNSS_RECEIVER_2_GPS_TIME,
    MIPC_FIELD_GNSS_RECEIVER_2_FIX_INFO,
    MIPC_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS,
    MIPC_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2,
    MIPC_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS,
    MIPC_FIELD_GNSS_RECEIVER_2_SBAS_INFO,
    MIPC_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS,
    MIPC_FIELD_GNSS_RECEIVER_2_RAW,
    MIPC_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS,
    MIPC_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS,
    MIPC_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS,
    MIPC_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS,
    MIPC_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO,
    MIPC_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS,
    MIPC_FIELD_GNSS_EXTERNAL_LLH_POSITION,
    MIPC_FIELD_GNSS_EXTERNAL_NED_VELOCITY,
    MIPC_FIELD_GNSS_EXTERNAL_UTC_TIME,
    MIPC_FIELD_GNSS_EXTERNAL_FIX_INFO,
    MIPC_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS,
    MIPC_FIELD_SYSTEM_DATA_BUILT_IN_TEST,
    MIPC_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS,
    MIPC_FIELD_SYSTEM_DATA_GPIO_STATE,
    MIPC_FIELD_SHARED_EVENT_SOURCE,
    MIPC_FIELD_SHARED_GPS_TIMESTAMP,
    MIPC_FIELD_SHARED_DELTA_TIME,
    MIPC_FIELD_SHARED_REFERENCE_TIMESTAMP,
    MIPC_FIELD_SHARED_REFERENCE_TIME_DELTA,
    MIPC_FIELD_SHARED_EXTERNAL_TIMESTAMP,
    MIPC_FIELD_SHARED_EXTERNAL_TIME_DELTA,
    MIPC_FIELD_COUNT
} mipc_field_id_t;

/** A decoded field: which layout, and its value. */
typedef struct {
    mipc_field_id_t id;
    union {
        mipc_ack_nack_t ack_nack;
        mipc_base_ping_t base_ping;
        mipc_base_set_to_idle_t base_set_to_idle;
        mipc_base_get_device_info_t base_get_device_info;
        mipc_base_device_info_t base_device_info;
        mipc_base_get_device_descriptors_t base_get_device_descriptors;
        mipc_base_device_descriptors_t base_device_descriptors;
        mipc_base_built_in_test_t base_built_in_test;
        mipc_base_built_in_test_result_gx5_45_t base_built_in_test_result_gx5_45;
        mipc_base_built_in_test_result_cv7_ins_t base_built_in_test_result_cv7_ins;
        mipc_base_resume_t base_resume;
        mipc_base_get_extended_descriptors_t base_get_extended_descriptors;
        mipc_base_extended_descriptors_t base_extended_descriptors;
        mipc_base_continuous_bit_t base_continuous_bit;
        mipc_base_continuous_bit_result_t base_continuous_bit_result;
        mipc_base_comm_port_speed_t base_comm_port_speed;
        mipc_base_comm_port_speed_response_t base_comm_port_speed_response;
        mipc_base_gps_time_update_gx5_45_t base_gps_time_update_gx5_45;
        mipc_base_gps_time_update_cv7_ins_t base_gps_time_update_cv7_ins;
        mipc_base_gps_week_t base_gps_week;
        mipc_base_gps_seconds_t base_gps_seconds;
        mipc_base_device_reset_t base_device_reset;
        mipc_threedm_event_control_t threedm_event_control;
        mipc_threedm_event_control_response_t threedm_event_control_response;
        mipc_threedm_get_event_trigger_status_t threedm_get_event_trigger_status;
        mipc_threedm_event_trigger_status_t threedm_event_trigger_status;
        mipc_threedm_get_event_action_status_t threedm_get_event_action_status;
        mipc_threedm_event_action_status_t threedm_event_action_status;
        mipc_threedm_event_trigger_config_t threedm_event_trigger_config;
        mipc_threedm_event_trigger_config_response_t threedm_event_trigger_config_response;
        mipc_threedm_event_action_config_t threedm_event_action_config;
        mipc_threedm_event_action_config_response_t threedm_event_action_config_response;
        mipc_threedm_device_startup_settings_gx5_45_t threedm_device_startup_settings_gx5_45;
        mipc_threedm_device_startup_settings_cv7_ins_t threedm_device_startup_settings_cv7_ins;
        mipc_threedm_sensor_to_vehicle_euler_t threedm_sensor_to_vehicle_euler;
        mipc_threedm_sensor_to_vehicle_euler_response_t threedm_sensor_to_vehicle_euler_response;
        mipc_threedm_sensor_to_vehicle_quaternion_t threedm_sensor_to_vehicle_quaternion;
        mipc_threedm_sensor_to_vehicle_quaternion_response_t threedm_sensor_to_vehicle_quaternion_response;
        mipc_threedm_sensor_to_vehicle_dcm_t threedm_sensor_to_vehicle_dcm;
        mipc_threedm_sensor_to_vehicle_dcm_response_t threedm_sensor_to_vehicle_dcm_response;
        mipc_threedm_accel_bias_gx5_45_t threedm_accel_bias_gx5_45;
        mipc_threedm_accel_bias_cv7_ins_t threedm_accel_bias_cv7_ins;
        mipc_threedm_accel_bias_response_t threedm_accel_bias_response;
        mipc_threedm_gyro_bias_gx5_45_t threedm_gyro_bias_gx5_45;
        mipc_threedm_gyro_bias_cv7_ins_t threedm_gyro_bias_cv7_ins;
        mipc_threedm_gyro_bias_response_t threedm_gyro_bias_response;
        mipc_threedm_capture_gyro_bias_t threedm_capture_gyro_bias;
        mipc_threedm_mag_hard_iron_offset_gx5_45_t threedm_mag_hard_iron_offset_gx5_45;
        mipc_threedm_mag_hard_iron_offset_cv7_ins_t threedm_mag_hard_iron_offset_cv7_ins;
        mipc_threedm_mag_hard_iron_offset_response_t threedm_mag_hard_iron_offset_response;
        mipc_threedm_mag_soft_iron_matrix_gx5_45_t threedm_mag_soft_iron_matrix_gx5_45;
        mipc_threedm_mag_soft_iron_matrix_cv7_ins_t threedm_mag_soft_iron_matrix_cv7_ins;
        mipc_threedm_mag_soft_iron_matrix_response_t threedm_mag_soft_iron_matrix_response;
        mipc_threedm_coning_sculling_enable_t threedm_coning_sculling_enable;
        mipc_threedm_coning_sculling_enable_response_t threedm_coning_sculling_enable_response;
        mipc_threedm_uart_baudrate_t threedm_uart_baudrate;
        mipc_threedm_uart_baudrate_response_t threedm_uart_baudrate_response;
        mipc_threedm_gpio_config_t threedm_gpio_config;
        mipc_threedm_gpio_config_response_t threedm_gpio_config_response;
        mipc_threedm_gpio_state_t threedm_gpio_state;
        mipc_threedm_gpio_state_response_t threedm_gpio_state_response;
        mipc_threedm_odometer_config_t threedm_odometer_config;
        mipc_threedm_odometer_config_response_t threedm_odometer_config_response;
        mipc_threedm_advanced_lowpass_filter_t threedm_advanced_lowpass_filter;
        mipc_threedm_advanced_lowpass_filter_response_t threedm_advanced_lowpass_filter_response;
        mipc_threedm_complementary_filter_t threedm_complementary_filter;
        mipc_threedm_complementary_filter_response_t threedm_complementary_filter_response;
        mipc_threedm_sensor_range_t threedm_sensor_range;
        mipc_threedm_sensor_range_response_t threedm_sensor_range_response;
        mipc_threedm_get_calibrated_sensor_ranges_t threedm_get_calibrated_sensor_ranges;
        mipc_threedm_calibrated_sensor_ranges_t threedm_calibrated_sensor_ranges;
        mipc_threedm_lowpass_filter_t threedm_lowpass_filter;
        mipc_threedm_lowpass_filter_response_t threedm_lowpass_filter_response;
        mipc_threedm_poll_imu_data_t threedm_poll_imu_data;
        mipc_threedm_poll_gnss_data_t threedm_poll_gnss_data;
        mipc_threedm_poll_filter_data_t threedm_poll_filter_data;
        mipc_threedm_poll_nmea_data_t threedm_poll_nmea_data;
        mipc_threedm_poll_data_t threedm_poll_data;
        mipc_threedm_get_imu_base_rate_t threedm_get_imu_base_rate;
        mipc_threedm_imu_base_rate_t threedm_imu_base_rate;
        mipc_threedm_get_gnss_base_rate_t threedm_get_gnss_base_rate;
        mipc_threedm_gnss_base_rate_t threedm_gnss_base_rate;
        mipc_threedm_get_filter_base_rate_t threedm_get_filter_base_rate;
        mipc_threedm_filter_base_rate_t threedm_filter_base_rate;
        mipc_threedm_get_base_rate_t threedm_get_base_rate;
        mipc_threedm_base_rate_t threedm_base_rate;
        mipc_threedm_imu_message_format_t threedm_imu_message_format;
        mipc_threedm_imu_message_format_response_t threedm_imu_message_format_response;
        mipc_threedm_gnss_message_format_t threedm_gnss_message_format;
        mipc_threedm_gnss_message_format_response_t threedm_gnss_message_format_response;
        mipc_threedm_filter_message_format_t threedm_filter_message_format;
        mipc_threedm_filter_message_format_response_t threedm_filter_message_format_response;
        mipc_threedm_nmea_message_format_t threedm_nmea_message_format;
        mipc_threedm_nmea_message_format_response_t threedm_nmea_message_format_response;
        mipc_threedm_message_format_t threedm_message_format;
        mipc_threedm_message_format_response_t threedm_message_format_response;
        mipc_threedm_factory_streaming_t threedm_factory_streaming;
        mipc_threedm_data_stream_control_gx5_45_t threedm_data_stream_control_gx5_45;
        mipc_threedm_data_stream_control_cv7_ins_t threedm_data_stream_control_cv7_ins;
        mipc_threedm_data_stream_control_response_gx5_45_t threedm_data_stream_control_response_gx5_45;
        mipc_threedm_data_stream_control_response_cv7_ins_t threedm_data_stream_control_response_cv7_ins;
        mipc_threedm_raw_rtcm_message_t threedm_raw_rtcm_message;
        mipc_threedm_gnss_constellation_settings_t threedm_gnss_constellation_settings;
        mipc_threedm_gnss_constellation_settings_response_t threedm_gnss_constellation_settings_response;
        mipc_threedm_gnss_sbas_settings_t threedm_gnss_sbas_settings;
        mipc_threedm_gnss_sbas_settings_response_t threedm_gnss_sbas_settings_response;
        mipc_threedm_gnss_assisted_fix_control_t threedm_gnss_assisted_fix_control;
        mipc_threedm_gnss_assisted_fix_control_response_t threedm_gnss_assisted_fix_control_response;
        mipc_threedm_gnss_assist_time_update_t threedm_gnss_assist_time_update;
        mipc_threedm_gnss_assist_time_update_response_t threedm_gnss_assist_time_update_response;
        mipc_threedm_pps_source_t threedm_pps_source;
        mipc_threedm_pps_source_response_t threedm_pps_source_response;
        mipc_threedm_get_supported_events_t threedm_get_supported_events;
        mipc_threedm_supported_events_t threedm_supported_events;
        mipc_threedm_device_status_t threedm_device_status;
        mipc_threedm_device_status_response_t threedm_device_status_response;
        mipc_filter_reset_filter_t filter_reset_filter;
        mipc_filter_set_initial_attitude_t filter_set_initial_attitude;
        mipc_filter_set_initial_heading_t filter_set_initial_heading;
        mipc_filter_run_filter_t filter_run_filter;
        mipc_filter_vehicle_dynamics_mode_t filter_vehicle_dynamics_mode;
        mipc_filter_vehicle_dynamics_mode_response_t filter_vehicle_dynamics_mode_response;
        mipc_filter_sensor_to_vehicle_transform_t filter_sensor_to_vehicle_transform;
        mipc_filter_sensor_to_vehicle_transform_response_t filter_sensor_to_vehicle_transform_response;
        mipc_filter_sensor_to_vehicle_offset_t filter_sensor_to_vehicle_offset;
        mipc_filter_sensor_to_vehicle_offset_response_t filter_sensor_to_vehicle_offset_response;
        mipc_filter_antenna_offset_t filter_antenna_offset;
        mipc_filter_antenna_offset_response_t filter_antenna_offset_response;
        mipc_filter_estimation_control_t filter_estimation_control;
        mipc_filter_estimation_control_response_t filter_estimation_control_response;
        mipc_filter_gnss_source_control_t filter_gnss_source_control;
        mipc_filter_gnss_source_control_response_t filter_gnss_source_control_response;
        mipc_filter_external_gnss_update_t filter_external_gnss_update;
        mipc_filter_external_heading_update_t filter_external_heading_update;
        mipc_filter_heading_update_control_t filter_heading_update_control;
        mipc_filter_heading_update_control_response_t filter_heading_update_control_response;
        mipc_filter_auto_init_control_t filter_auto_init_control;
        mipc_filter_auto_init_control_response_t filter_auto_init_control_response;
        mipc_filter_accel_noise_t filter_accel_noise;
        mipc_filter_accel_noise_response_t filter_accel_noise_response;
        mipc_filter_gyro_noise_t filter_gyro_noise;
        mipc_filter_gyro_noise_response_t filter_gyro_noise_response;
        mipc_filter_accel_bias_model_t filter_accel_bias_model;
        mipc_filter_accel_bias_model_response_t filter_accel_bias_model_response;
        mipc_filter_gyro_bias_model_t filter_gyro_bias_model;
        mipc_filter_gyro_bias_model_response_t filter_gyro_bias_model_response;
        mipc_filter_zupt_control_t filter_zupt_control;
        mipc_filter_zupt_control_response_t filter_zupt_control_response;
        mipc_filter_external_heading_update_with_time_t filter_external_heading_update_with_time;
        mipc_filter_zero_angular_rate_update_control_t filter_zero_angular_rate_update_control;
        mipc_filter_zero_angular_rate_update_control_response_t
            filter_zero_angular_rate_update_control_response;
        mipc_filter_tare_orientation_t filter_tare_orientation;
        mipc_filter_commanded_zupt_t filter_commanded_zupt;
        mipc_filter_commanded_zero_angular_rate_update_t filter_commanded_zero_angular_rate_update;
        mipc_filter_mag_capture_auto_calibration_t filter_mag_capture_auto_calibration;
        mipc_filter_gravity_noise_std_dev_t filter_gravity_noise_std_dev;
        mipc_filter_gravity_noise_std_dev_response_t filter_gravity_noise_std_dev_response;
        mipc_filter_pressure_altitude_noise_std_dev_t filter_pressure_altitude_noise_std_dev;
        mipc_filter_pressure_altitude_noise_std_dev_response_t
            filter_pressure_altitude_noise_std_dev_response;
        mipc_filter_hard_iron_offset_noise_t filter_hard_iron_offset_noise;
        mipc_filter_hard_iron_offset_noise_response_t filter_hard_iron_offset_noise_response;
        mipc_filter_soft_iron_matrix_noise_t filter_soft_iron_matrix_noise;
        mipc_filter_soft_iron_matrix_noise_response_t filter_soft_iron_matrix_noise_response;
        mipc_filter_mag_noise_std_dev_t filter_mag_noise_std_dev;
        mipc_filter_mag_noise_std_dev_response_t filter_mag_noise_std_dev_response;
        mipc_filter_declination_source_t filter_declination_source;
        mipc_filter_declination_source_response_t filter_declination_source_response;
        mipc_filter_gravity_magnitude_adaptive_measurement_t filter_gravity_magnitude_adaptive_measurement;
        mipc_filter_gravity_magnitude_adaptive_measurement_response_t
            filter_gravity_magnitude_adaptive_measurement_response;
        mipc_filter_mag_magnitude_adaptive_measurement_t filter_mag_magnitude_adaptive_measurement;
        mipc_filter_mag_magnitude_adaptive_measurement_response_t
            filter_mag_magnitude_adaptive_measurement_response;
        mipc_filter_mag_dip_angle_adaptive_measurement_t filter_mag_dip_angle_adaptive_measurement;
        mipc_filter_mag_dip_angle_adaptive_measurement_response_t
            filter_mag_dip_angle_adaptive_measurement_response;
        mipc_filter_altitude_aiding_control_t filter_altitude_aiding_control;
        mipc_filter_altitude_aiding_control_response_t filter_altitude_aiding_control_response;
        mipc_filter_pitch_roll_aiding_control_t filter_pitch_roll_aiding_control;
        mipc_filter_pitch_roll_aiding_control_response_t filter_pitch_roll_aiding_control_response;
        mipc_filter_inclination_source_t filter_inclination_source;
        mipc_filter_inclination_source_response_t filter_inclination_source_response;
        mipc_filter_magnetic_field_magnitude_source_t filter_magnetic_field_magnitude_source;
        mipc_filter_magnetic_field_magnitude_source_response_t
            filter_magnetic_field_magnitude_source_response;
        mipc_filter_aiding_measurement_control_t filter_aiding_measurement_control;
        mipc_filter_aiding_measurement_control_response_t filter_aiding_measurement_control_response;
        mipc_filter_initialization_configuration_t filter_initialization_configuration;
        mipc_filter_initialization_configuration_response_t filter_initialization_configuration_response;
        mipc_filter_adaptive_filter_control_t filter_adaptive_filter_control;
        mipc_filter_adaptive_filter_control_response_t filter_adaptive_filter_control_response;
        mipc_filter_multi_antenna_offset_t filter_multi_antenna_offset;
        mipc_filter_multi_antenna_offset_response_t filter_multi_antenna_offset_response;
        mipc_filter_relative_position_configuration_t filter_relative_position_configuration;
        mipc_filter_relative_position_configuration_response_t
            filter_relative_position_configuration_response;
        mipc_filter_reference_point_lever_arm_t filter_reference_point_lever_arm;
        mipc_filter_reference_point_lever_arm_response_t filter_reference_point_lever_arm_response;
        mipc_filter_speed_lever_arm_t filter_speed_lever_arm;
        mipc_filter_speed_lever_arm_response_t filter_speed_lever_arm_response;
        mipc_filter_wheeled_vehicle_constraint_control_t filter_wheeled_vehicle_constraint_control;
        mipc_filter_wheeled_vehicle_constraint_control_response_t
            filter_wheeled_vehicle_constraint_control_response;
        mipc_filter_gnss_antenna_calibration_control_t filter_gnss_antenna_calibration_control;
        mipc_filter_gnss_antenna_calibration_control_response_t
            filter_gnss_antenna_calibration_control_response;
        mipc_gnss_receiver_info_t gnss_receiver_info;
        mipc_gnss_receiver_info_response_t gnss_receiver_info_response;
        mipc_gnss_signal_configuration_t gnss_signal_configuration;
        mipc_gnss_signal_configuration_response_t gnss_signal_configuration_response;
        mipc_gnss_spartn_configuration_t gnss_spartn_configuration;
        mipc_gnss_spartn_configuration_response_t gnss_spartn_configuration_response;
        mipc_aiding_frame_config_t aiding_frame_config;
        mipc_aiding_frame_config_response_t aiding_frame_config_response;
        mipc_aiding_echo_control_t aiding_echo_control;
        mipc_aiding_echo_control_response_t aiding_echo_control_response;
        mipc_aiding_ecef_position_t aiding_ecef_position;
        mipc_aiding_llh_position_t aiding_llh_position;
        mipc_aiding_height_above_ellipsoid_t aiding_height_above_ellipsoid;
        mipc_aiding_ecef_velocity_t aiding_ecef_velocity;
        mipc_aiding_ned_velocity_t aiding_ned_velocity;
        mipc_aiding_body_frame_velocity_t aiding_body_frame_velocity;
        mipc_aiding_true_heading_t aiding_true_heading;
        mipc_aiding_magnetic_field_t aiding_magnetic_field;
        mipc_aiding_pressure_t aiding_pressure;
        mipc_system_communication_mode_t system_communication_mode;
        mipc_system_communication_mode_response_t system_communication_mode_response;
        mipc_sensor_scaled_accel_t sensor_scaled_accel;
        mipc_sensor_scaled_gyro_t sensor_scaled_gyro;
        mipc_sensor_scaled_mag_t sensor_scaled_mag;
        mipc_sensor_delta_theta_t sensor_delta_theta;
        mipc_sensor_delta_velocity_t sensor_delta_velocity;
        mipc_sensor_cf_orientation_matrix_t sensor_cf_orientation_matrix;
        mipc_sensor_cf_quaternion_t sensor_cf_quaternion;
        mipc_sensor_cf_euler_angles_t sensor_cf_euler_angles;
        mipc_sensor_cf_stabilized_north_t sensor_cf_stabilized_north;
        mipc_sensor_cf_stabilized_up_t sensor_cf_stabilized_up;
        mipc_sensor_gps_timestamp_t sensor_gps_timestamp;
        mipc_sensor_temperature_statistics_t sensor_temperature_statistics;
        mipc_sensor_scaled_pressure_t sensor_scaled_pressure;
        mipc_sensor_overrange_status_t sensor_overrange_status;
        mipc_sensor_odometer_data_t sensor_odometer_data;
        mipc_gnss_data_llh_position_t gnss_data_llh_position;
        mipc_gnss_data_ecef_position_t gnss_data_ecef_position;
        mipc_gnss_data_ned_velocity_t gnss_data_ned_velocity;
        mipc_gnss_data_ecef_velocity_t gnss_data_ecef_velocity;
        mipc_gnss_data_dop_t gnss_data_dop;
        mipc_gnss_data_utc_time_t gnss_data_utc_time;
        mipc_gnss_data_gps_time_t gnss_data_gps_time;
        mipc_gnss_data_clock_info_t gnss_data_clock_info;
        mipc_gnss_data_fix_info_t gnss_data_fix_info;
        mipc_gnss_data_sv_info_t gnss_data_sv_info;
        mipc_gnss_data_hardware_status_t gnss_data_hardware_status;
        mipc_gnss_data_dgnss_info_t gnss_data_dgnss_info;
        mipc_gnss_data_dgnss_channel_status_t gnss_data_dgnss_channel_status;
        mipc_filter_data_llh_position_t filter_data_llh_position;
        mipc_filter_data_ned_velocity_t filter_data_ned_velocity;
        mipc_filter_data_attitude_quaternion_t filter_data_attitude_quaternion;
        mipc_filter_data_attitude_dcm_t filter_data_attitude_dcm;
        mipc_filter_data_euler_angles_t filter_data_euler_angles;
        mipc_filter_data_gyro_bias_t filter_data_gyro_bias;
        mipc_filter_data_accel_bias_t filter_data_accel_bias;
        mipc_filter_data_llh_position_uncertainty_t filter_data_llh_position_uncertainty;
        mipc_filter_data_ned_velocity_uncertainty_t filter_data_ned_velocity_uncertainty;
        mipc_filter_data_euler_angles_uncertainty_t filter_data_euler_angles_uncertainty;
        mipc_filter_data_gyro_bias_uncertainty_t filter_data_gyro_bias_uncertainty;
        mipc_filter_data_accel_bias_uncertainty_t filter_data_accel_bias_uncertainty;
        mipc_filter_data_linear_accel_t filter_data_linear_accel;
        mipc_filter_data_comp_angular_rate_t filter_data_comp_angular_rate;
        mipc_filter_data_wgs84_gravity_magnitude_t filter_data_wgs84_gravity_magnitude;
        mipc_filter_data_filter_status_gx5_45_t filter_data_filter_status_gx5_45;
        mipc_filter_data_filter_status_cv7_ins_t filter_data_filter_status_cv7_ins;
        mipc_filter_data_gps_timestamp_t filter_data_gps_timestamp;
        mipc_filter_data_quaternion_attitude_uncertainty_t filter_data_quaternion_attitude_uncertainty;
        mipc_filter_data_gravity_vector_t filter_data_gravity_vector;
        mipc_filter_data_heading_update_state_t filter_data_heading_update_state;
        mipc_filter_data_magnetic_model_t filter_data_magnetic_model;
        mipc_filter_data_gyro_scale_factor_t filter_data_gyro_scale_factor;
        mipc_filter_data_accel_scale_factor_t filter_data_accel_scale_factor;
        mipc_filter_data_gyro_scale_factor_uncertainty_t filter_data_gyro_scale_factor_uncertainty;
        mipc_filter_data_accel_scale_factor_uncertainty_t filter_data_accel_scale_factor_uncertainty;
        mipc_filter_data_compensated_accel_t filter_data_compensated_accel;
        mipc_filter_data_standard_atmosphere_t filter_data_standard_atmosphere;
        mipc_filter_data_pressure_altitude_t filter_data_pressure_altitude;
        mipc_filter_data_mag_auto_hard_iron_offset_t filter_data_mag_auto_hard_iron_offset;
        mipc_filter_data_mag_auto_soft_iron_matrix_t filter_data_mag_auto_soft_iron_matrix;
        mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t
            filter_data_mag_auto_hard_iron_offset_uncertainty;
        mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t
            filter_data_mag_auto_soft_iron_matrix_uncertainty;
        mipc_filter_data_gnss_antenna_offset_correction_t filter_data_gnss_antenna_offset_correction;
        mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t
            filter_data_gnss_antenna_offset_correction_uncertainty;
        mipc_filter_data_multi_antenna_offset_correction_t filter_data_multi_antenna_offset_correction;
        mipc_filter_data_multi_antenna_offset_correction_uncertainty_t
            filter_data_multi_antenna_offset_correction_uncertainty;
        mipc_filter_data_ecef_position_uncertainty_t filter_data_ecef_position_uncertainty;
        mipc_filter_data_ecef_velocity_uncertainty_t filter_data_ecef_velocity_uncertainty;
        mipc_filter_data_ecef_position_t filter_data_ecef_position;
        mipc_filter_data_ecef_velocity_t filter_data_ecef_velocity;
        mipc_filter_data_ned_relative_position_t filter_data_ned_relative_position;
        mipc_filter_data_gnss_position_aiding_status_t filter_data_gnss_position_aiding_status;
        mipc_filter_data_aiding_measurement_summary_t filter_data_aiding_measurement_summary;
        mipc_filter_data_odometer_scale_factor_error_t filter_data_odometer_scale_factor_error;
        mipc_filter_data_odometer_scale_factor_error_uncertainty_t
            filter_data_odometer_scale_factor_error_uncertainty;
        mipc_filter_data_gnss_dual_antenna_status_t filter_data_gnss_dual_antenna_status;
        mipc_filter_data_aiding_frame_config_error_t filter_data_aiding_frame_config_error;
        mipc_filter_data_aiding_frame_config_error_uncertainty_t
            filter_data_aiding_frame_config_error_uncertainty;
        mipc_gnss_receiver_1_llh_position_t gnss_receiver_1_llh_position;
        mipc_gnss_receiver_1_ecef_position_t gnss_receiver_1_ecef_position;
        mipc_gnss_receiver_1_ned_velocity_t gnss_receiver_1_ned_velocity;
        mipc_gnss_receiver_1_ecef_velocity_t gnss_receiver_1_ecef_velocity;
        mipc_gnss_receiver_1_dop_t gnss_receiver_1_dop;
        mipc_gnss_receiver_1_utc_time_t gnss_receiver_1_utc_time;
        mipc_gnss_receiver_1_gps_time_t gnss_receiver_1_gps_time;
        mipc_gnss_receiver_1_fix_info_t gnss_receiver_1_fix_info;
        mipc_gnss_receiver_1_hardware_status_t gnss_receiver_1_hardware_status;
        mipc_gnss_receiver_1_clock_info_2_t gnss_receiver_1_clock_info_2;
        mipc_gnss_receiver_1_gps_leap_seconds_t gnss_receiver_1_gps_leap_seconds;
        mipc_gnss_receiver_1_sbas_info_t gnss_receiver_1_sbas_info;
        mipc_gnss_receiver_1_satellite_status_t gnss_receiver_1_satellite_status;
        mipc_gnss_receiver_1_raw_t gnss_receiver_1_raw;
        mipc_gnss_receiver_1_gps_ephemeris_t gnss_receiver_1_gps_ephemeris;
        mipc_gnss_receiver_1_glonass_ephemeris_t gnss_receiver_1_glonass_ephemeris;
        mipc_gnss_receiver_1_galileo_ephemeris_t gnss_receiver_1_galileo_ephemeris;
        mipc_gnss_receiver_1_beidou_ephemeris_t gnss_receiver_1_beidou_ephemeris;
        mipc_gnss_receiver_2_llh_position_t gnss_receiver_2_llh_position;
        mipc_gnss_receiver_2_ecef_position_t gnss_receiver_2_ecef_position;
        mipc_gnss_receiver_2_ned_velocity_t gnss_receiver_2_ned_velocity;
        mipc_gnss_receiver_2_ecef_velocity_t gnss_receiver_2_ecef_velocity;
        mipc_gnss_receiver_2_dop_t gnss_receiver_2_dop;
        mipc_gnss_receiver_2_utc_time_t gnss_receiver_2_utc_time;
        mipc_gnss_receiver_2_gps_time_t gnss_receiver_2_gps_time;
        mipc_gnss_receiver_2_fix_info_t gnss_receiver_2_fix_info;
        mipc_gnss_receiver_2_hardware_status_t gnss_receiver_2_hardware_status;
        mipc_gnss_receiver_2_clock_info_2_t gnss_receiver_2_clock_info_2;
        mipc_gnss_receiver_2_gps_leap_seconds_t gnss_receiver_2_gps_leap_seconds;
        mipc_gnss_receiver_2_sbas_info_t gnss_receiver_2_sbas_info;
        mipc_gnss_receiver_2_satellite_status_t gnss_receiver_2_satellite_status;
        mipc_gnss_receiver_2_raw_t gnss_receiver_2_raw;
        mipc_gnss_receiver_2_gps_ephemeris_t gnss_receiver_2_gps_ephemeris;
        mipc_gnss_receiver_2_glonass_ephemeris_t gnss_receiver_2_glonass_ephemeris;
        mipc_gnss_receiver_2_galileo_ephemeris_t gnss_receiver_2_galileo_ephemeris;
        mipc_gnss_receiver_2_beidou_ephemeris_t gnss_receiver_2_beidou_ephemeris;
        mipc_gnss_corrections_base_station_info_t gnss_corrections_base_station_info;
        mipc_gnss_corrections_rtk_corrections_status_t gnss_corrections_rtk_corrections_status;
        mipc_gnss_external_llh_position_t gnss_external_llh_position;
        mipc_gnss_external_ned_velocity_t gnss_external_ned_velocity;
        mipc_gnss_external_utc_time_t gnss_external_utc_time;
        mipc_gnss_external_fix_info_t gnss_external_fix_info;
        mipc_gnss_external_satellite_status_t gnss_external_satellite_status;
        mipc_system_data_built_in_test_t system_data_built_in_test;
        mipc_system_data_time_sync_status_t system_data_time_sync_status;
        mipc_system_data_gpio_state_t system_data_gpio_state;
        mipc_shared_event_source_t shared_event_source;
        mipc_shared_gps_timestamp_t shared_gps_timestamp;
        mipc_shared_delta_time_t shared_delta_time;
        mipc_shared_reference_timestamp_t shared_reference_timestamp;
        mipc_shared_reference_time_delta_t shared_reference_time_delta;
        mipc_shared_external_timestamp_t shared_external_timestamp;
        mipc_shared_external_time_delta_t shared_external_time_delta;
    } u;
} mipc_field_value_t;

/** What the spec says about a field layout. */
typedef struct {
    mipc_field_id_t id;
    const char *name;   /* field name */
    const char *device; /* device id when the field has per-device variants, else NULL */
    mipc_device_t device_id;
    uint8_t descriptor;
} mipc_layout_info_t;

/** A field: its layouts are ids first_layout .. first_layout + layout_count - 1, in IR order. */
typedef struct {
    const char *name;
    uint8_t descriptor;
    mipc_field_id_t first_layout;
    size_t layout_count;
} mipc_field_info_t;

/** Information on a layout id (NULL if out of range). */
const mipc_layout_info_t *mipc_layout_info(mipc_field_id_t id);

/**
 * The field (set, descriptor) designates: a field of the set, a reserved field of the set's
 * kind, or a shared data field. NULL if none; *why is then MIPC_ERR_UNKNOWN_SET or
 * MIPC_ERR_UNKNOWN_DESCRIPTOR.
 */
const mipc_field_info_t *mipc_find_field(uint8_t set, uint8_t descriptor, mipc_status_t *why);

/**
 * Decodes field data. Per-device variants are tried in IR order (only the one of `device`
 * when it has one); the first that decodes wins. If none does, *err is the error of the first.
 */
mipc_status_t mipc_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                mipc_device_t device, mipc_field_value_t *out, mipc_decode_error_t *err);

/** A packet of any data set decoded by its set's straight-line decoder (mipc_decode_packet). */
typedef struct {
    uint8_t set;
    union {
        mipc_sensor_packet_t sensor;
        mipc_gnss_data_packet_t gnss_data;
        mipc_filter_data_packet_t filter_data;
        mipc_gnss_receiver_1_packet_t gnss_receiver_1;
        mipc_gnss_receiver_2_packet_t gnss_receiver_2;
        mipc_gnss_corrections_packet_t gnss_corrections;
        mipc_gnss_external_packet_t gnss_external;
        mipc_system_data_packet_t system_data;
        mipc_shared_packet_t shared;
        uint8_t none_; /* no data set */
    } u;
} mipc_packet_t;

/**
 * Decodes a packet (sync, header and payload; its checksum is the parser's business) of a data set
 * with that set's straight-line decoder (<set>_decode_packet: entries it leaves go to other, which
 * may be NULL, with ctx) into the set's member of out->u, and returns its index (the fields
 * decoded, in packet order). For a set without one (not a data set, or not defined) every entry
 * goes to other and it returns NULL.
 */
const mipc_packet_index_t *mipc_decode_packet(const uint8_t *packet, mipc_packet_t *out,
                                              mipc_field_entry_fn other, void *ctx);

/**
 * mipc_decode_packet through a layout cache (issue 38), with the same contract and results: a
 * packet whose shape (set, payload length, every field header) is in the cache is decoded at the
 * shape's offsets, without the header walk and the dispatch per descriptor; any other packet
 * takes mipc_decode_packet, and its shape is recorded (round-robin over
 * MIPC_LAYOUT_CACHE_SHAPES slots) when every entry was decoded into a member. cache: one per
 * stream, initialised with mipc_layout_cache_init; fixed size, no allocation.
 */
const mipc_packet_index_t *mipc_decode_packet_cached(mipc_layout_cache_t *cache, const uint8_t *packet,
                                                     mipc_packet_t *out, mipc_field_entry_fn other,
                                                     void *ctx);

/** Encodes the data of a decoded field (no field header). */
mipc_status_t mipc_encode_field(const mipc_field_value_t *value, uint8_t *buf, size_t cap, size_t *len_out);

#ifdef __cplusplus
}
#endif

#endif
