/* Dispatch by (descriptor set, descriptor): devices, set kinds, the value of any field, and
 * decode/encode of any field (docs/conformance.md section 2). Generated: do not edit. */
#ifndef MIP_DISPATCH_H
#define MIP_DISPATCH_H

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

/** Devices named by the spec; MIP_DEVICE_ANY tries every per-device variant. */
typedef enum {
    MIP_DEVICE_ANY = 0,
    MIP_DEVICE_GX5_45 = 1, /* 3DM-GX5-45 */
    MIP_DEVICE_CV7_INS = 2 /* 3DM-CV7-GNSS/INS */
} mip_device_t;

/** The id of a device ("gx5_45"), or NULL for MIP_DEVICE_ANY. */
const char *mip_device_id(mip_device_t device);
/** Looks up a device by id; false if there is none. */
bool mip_device_from_id(const char *id, mip_device_t *out);

/** Kind of a descriptor set, from the set_kinds ranges. */
typedef enum {
    MIP_SET_KIND_NONE = 0,
    MIP_SET_KIND_COMMAND = 1, /* 0x01..0x7F */
    MIP_SET_KIND_DATA = 2     /* 0x80..0xFF */
} mip_set_kind_t;

mip_set_kind_t mip_set_kind(uint8_t set);

/** One id per field layout (per-device variants have one each). */
typedef enum {
    MIP_FIELD_NONE = 0,
    MIP_FIELD_ACK_NACK = 1,
    MIP_FIELD_BASE_PING = 2,
    MIP_FIELD_BASE_SET_TO_IDLE = 3,
    MIP_FIELD_BASE_GET_DEVICE_INFO = 4,
    MIP_FIELD_BASE_DEVICE_INFO = 5,
    MIP_FIELD_BASE_GET_DEVICE_DESCRIPTORS = 6,
    MIP_FIELD_BASE_DEVICE_DESCRIPTORS = 7,
    MIP_FIELD_BASE_BUILT_IN_TEST = 8,
    MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45 = 9,
    MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS = 10,
    MIP_FIELD_BASE_RESUME = 11,
    MIP_FIELD_BASE_GET_EXTENDED_DESCRIPTORS = 12,
    MIP_FIELD_BASE_EXTENDED_DESCRIPTORS = 13,
    MIP_FIELD_BASE_CONTINUOUS_BIT = 14,
    MIP_FIELD_BASE_CONTINUOUS_BIT_RESULT = 15,
    MIP_FIELD_BASE_COMM_PORT_SPEED = 16,
    MIP_FIELD_BASE_COMM_PORT_SPEED_RESPONSE = 17,
    MIP_FIELD_BASE_GPS_TIME_UPDATE_GX5_45 = 18,
    MIP_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS = 19,
    MIP_FIELD_BASE_GPS_WEEK = 20,
    MIP_FIELD_BASE_GPS_SECONDS = 21,
    MIP_FIELD_BASE_DEVICE_RESET = 22,
    MIP_FIELD_THREEDM_EVENT_CONTROL = 23,
    MIP_FIELD_THREEDM_EVENT_CONTROL_RESPONSE = 24,
    MIP_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS = 25,
    MIP_FIELD_THREEDM_EVENT_TRIGGER_STATUS = 26,
    MIP_FIELD_THREEDM_GET_EVENT_ACTION_STATUS = 27,
    MIP_FIELD_THREEDM_EVENT_ACTION_STATUS = 28,
    MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG = 29,
    MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE = 30,
    MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG = 31,
    MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE = 32,
    MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45 = 33,
    MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS = 34,
    MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER = 35,
    MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE = 36,
    MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION = 37,
    MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE = 38,
    MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM = 39,
    MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE = 40,
    MIP_FIELD_THREEDM_ACCEL_BIAS_GX5_45 = 41,
    MIP_FIELD_THREEDM_ACCEL_BIAS_CV7_INS = 42,
    MIP_FIELD_THREEDM_ACCEL_BIAS_RESPONSE = 43,
    MIP_FIELD_THREEDM_GYRO_BIAS_GX5_45 = 44,
    MIP_FIELD_THREEDM_GYRO_BIAS_CV7_INS = 45,
    MIP_FIELD_THREEDM_GYRO_BIAS_RESPONSE = 46,
    MIP_FIELD_THREEDM_CAPTURE_GYRO_BIAS = 47,
    MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45 = 48,
    MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS = 49,
    MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE = 50,
    MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45 = 51,
    MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS = 52,
    MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE = 53,
    MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE = 54,
    MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE = 55,
    MIP_FIELD_THREEDM_UART_BAUDRATE = 56,
    MIP_FIELD_THREEDM_UART_BAUDRATE_RESPONSE = 57,
    MIP_FIELD_THREEDM_GPIO_CONFIG = 58,
    MIP_FIELD_THREEDM_GPIO_CONFIG_RESPONSE = 59,
    MIP_FIELD_THREEDM_GPIO_STATE = 60,
    MIP_FIELD_THREEDM_GPIO_STATE_RESPONSE = 61,
    MIP_FIELD_THREEDM_ODOMETER_CONFIG = 62,
    MIP_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE = 63,
    MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER = 64,
    MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE = 65,
    MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER = 66,
    MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE = 67,
    MIP_FIELD_THREEDM_SENSOR_RANGE = 68,
    MIP_FIELD_THREEDM_SENSOR_RANGE_RESPONSE = 69,
    MIP_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES = 70,
    MIP_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES = 71,
    MIP_FIELD_THREEDM_LOWPASS_FILTER = 72,
    MIP_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE = 73,
    MIP_FIELD_THREEDM_POLL_IMU_DATA = 74,
    MIP_FIELD_THREEDM_POLL_GNSS_DATA = 75,
    MIP_FIELD_THREEDM_POLL_FILTER_DATA = 76,
    MIP_FIELD_THREEDM_POLL_NMEA_DATA = 77,
    MIP_FIELD_THREEDM_POLL_DATA = 78,
    MIP_FIELD_THREEDM_GET_IMU_BASE_RATE = 79,
    MIP_FIELD_THREEDM_IMU_BASE_RATE = 80,
    MIP_FIELD_THREEDM_GET_GNSS_BASE_RATE = 81,
    MIP_FIELD_THREEDM_GNSS_BASE_RATE = 82,
    MIP_FIELD_THREEDM_GET_FILTER_BASE_RATE = 83,
    MIP_FIELD_THREEDM_FILTER_BASE_RATE = 84,
    MIP_FIELD_THREEDM_GET_BASE_RATE = 85,
    MIP_FIELD_THREEDM_BASE_RATE = 86,
    MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT = 87,
    MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE = 88,
    MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT = 89,
    MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE = 90,
    MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT = 91,
    MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE = 92,
    MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT = 93,
    MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE = 94,
    MIP_FIELD_THREEDM_MESSAGE_FORMAT = 95,
    MIP_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE = 96,
    MIP_FIELD_THREEDM_FACTORY_STREAMING = 97,
    MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45 = 98,
    MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS = 99,
    MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45 = 100,
    MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS = 101,
    MIP_FIELD_THREEDM_RAW_RTCM_MESSAGE = 102,
    MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS = 103,
    MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE = 104,
    MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS = 105,
    MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE = 106,
    MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL = 107,
    MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE = 108,
    MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE = 109,
    MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE = 110,
    MIP_FIELD_THREEDM_PPS_SOURCE = 111,
    MIP_FIELD_THREEDM_PPS_SOURCE_RESPONSE = 112,
    MIP_FIELD_THREEDM_GET_SUPPORTED_EVENTS = 113,
    MIP_FIELD_THREEDM_SUPPORTED_EVENTS = 114,
    MIP_FIELD_THREEDM_DEVICE_STATUS = 115,
    MIP_FIELD_THREEDM_DEVICE_STATUS_RESPONSE = 116,
    MIP_FIELD_FILTER_RESET_FILTER = 117,
    MIP_FIELD_FILTER_SET_INITIAL_ATTITUDE = 118,
    MIP_FIELD_FILTER_SET_INITIAL_HEADING = 119,
    MIP_FIELD_FILTER_RUN_FILTER = 120,
    MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE = 121,
    MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE = 122,
    MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM = 123,
    MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE = 124,
    MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET = 125,
    MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE = 126,
    MIP_FIELD_FILTER_ANTENNA_OFFSET = 127,
    MIP_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE = 128,
    MIP_FIELD_FILTER_ESTIMATION_CONTROL = 129,
    MIP_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE = 130,
    MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL = 131,
    MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE = 132,
    MIP_FIELD_FILTER_EXTERNAL_GNSS_UPDATE = 133,
    MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE = 134,
    MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL = 135,
    MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE = 136,
    MIP_FIELD_FILTER_AUTO_INIT_CONTROL = 137,
    MIP_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE = 138,
    MIP_FIELD_FILTER_ACCEL_NOISE = 139,
    MIP_FIELD_FILTER_ACCEL_NOISE_RESPONSE = 140,
    MIP_FIELD_FILTER_GYRO_NOISE = 141,
    MIP_FIELD_FILTER_GYRO_NOISE_RESPONSE = 142,
    MIP_FIELD_FILTER_ACCEL_BIAS_MODEL = 143,
    MIP_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE = 144,
    MIP_FIELD_FILTER_GYRO_BIAS_MODEL = 145,
    MIP_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE = 146,
    MIP_FIELD_FILTER_ZUPT_CONTROL = 147,
    MIP_FIELD_FILTER_ZUPT_CONTROL_RESPONSE = 148,
    MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME = 149,
    MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL = 150,
    MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE = 151,
    MIP_FIELD_FILTER_TARE_ORIENTATION = 152,
    MIP_FIELD_FILTER_COMMANDED_ZUPT = 153,
    MIP_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE = 154,
    MIP_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION = 155,
    MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV = 156,
    MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE = 157,
    MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV = 158,
    MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE = 159,
    MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE = 160,
    MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE = 161,
    MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE = 162,
    MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE = 163,
    MIP_FIELD_FILTER_MAG_NOISE_STD_DEV = 164,
    MIP_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE = 165,
    MIP_FIELD_FILTER_DECLINATION_SOURCE = 166,
    MIP_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE = 167,
    MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT = 168,
    MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE = 169,
    MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT = 170,
    MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE = 171,
    MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT = 172,
    MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE = 173,
    MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL = 174,
    MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE = 175,
    MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL = 176,
    MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE = 177,
    MIP_FIELD_FILTER_INCLINATION_SOURCE = 178,
    MIP_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE = 179,
    MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE = 180,
    MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE = 181,
    MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL = 182,
    MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE = 183,
    MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION = 184,
    MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE = 185,
    MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL = 186,
    MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE = 187,
    MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET = 188,
    MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE = 189,
    MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION = 190,
    MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE = 191,
    MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM = 192,
    MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE = 193,
    MIP_FIELD_FILTER_SPEED_LEVER_ARM = 194,
    MIP_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE = 195,
    MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL = 196,
    MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE = 197,
    MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL = 198,
    MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE = 199,
    MIP_FIELD_GNSS_RECEIVER_INFO = 200,
    MIP_FIELD_GNSS_RECEIVER_INFO_RESPONSE = 201,
    MIP_FIELD_GNSS_SIGNAL_CONFIGURATION = 202,
    MIP_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE = 203,
    MIP_FIELD_GNSS_SPARTN_CONFIGURATION = 204,
    MIP_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE = 205,
    MIP_FIELD_AIDING_FRAME_CONFIG = 206,
    MIP_FIELD_AIDING_FRAME_CONFIG_RESPONSE = 207,
    MIP_FIELD_AIDING_ECHO_CONTROL = 208,
    MIP_FIELD_AIDING_ECHO_CONTROL_RESPONSE = 209,
    MIP_FIELD_AIDING_ECEF_POSITION = 210,
    MIP_FIELD_AIDING_LLH_POSITION = 211,
    MIP_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID = 212,
    MIP_FIELD_AIDING_ECEF_VELOCITY = 213,
    MIP_FIELD_AIDING_NED_VELOCITY = 214,
    MIP_FIELD_AIDING_BODY_FRAME_VELOCITY = 215,
    MIP_FIELD_AIDING_TRUE_HEADING = 216,
    MIP_FIELD_AIDING_MAGNETIC_FIELD = 217,
    MIP_FIELD_AIDING_PRESSURE = 218,
    MIP_FIELD_SYSTEM_COMMUNICATION_MODE = 219,
    MIP_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE = 220,
    MIP_FIELD_SENSOR_SCALED_ACCEL = 221,
    MIP_FIELD_SENSOR_SCALED_GYRO = 222,
    MIP_FIELD_SENSOR_SCALED_MAG = 223,
    MIP_FIELD_SENSOR_DELTA_THETA = 224,
    MIP_FIELD_SENSOR_DELTA_VELOCITY = 225,
    MIP_FIELD_SENSOR_CF_ORIENTATION_MATRIX = 226,
    MIP_FIELD_SENSOR_CF_QUATERNION = 227,
    MIP_FIELD_SENSOR_CF_EULER_ANGLES = 228,
    MIP_FIELD_SENSOR_CF_STABILIZED_NORTH = 229,
    MIP_FIELD_SENSOR_CF_STABILIZED_UP = 230,
    MIP_FIELD_SENSOR_GPS_TIMESTAMP = 231,
    MIP_FIELD_SENSOR_TEMPERATURE_STATISTICS = 232,
    MIP_FIELD_SENSOR_SCALED_PRESSURE = 233,
    MIP_FIELD_SENSOR_OVERRANGE_STATUS = 234,
    MIP_FIELD_SENSOR_ODOMETER_DATA = 235,
    MIP_FIELD_GNSS_DATA_LLH_POSITION = 236,
    MIP_FIELD_GNSS_DATA_ECEF_POSITION = 237,
    MIP_FIELD_GNSS_DATA_NED_VELOCITY = 238,
    MIP_FIELD_GNSS_DATA_ECEF_VELOCITY = 239,
    MIP_FIELD_GNSS_DATA_DOP = 240,
    MIP_FIELD_GNSS_DATA_UTC_TIME = 241,
    MIP_FIELD_GNSS_DATA_GPS_TIME = 242,
    MIP_FIELD_GNSS_DATA_CLOCK_INFO = 243,
    MIP_FIELD_GNSS_DATA_FIX_INFO = 244,
    MIP_FIELD_GNSS_DATA_SV_INFO = 245,
    MIP_FIELD_GNSS_DATA_HARDWARE_STATUS = 246,
    MIP_FIELD_GNSS_DATA_DGNSS_INFO = 247,
    MIP_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS = 248,
    MIP_FIELD_FILTER_DATA_LLH_POSITION = 249,
    MIP_FIELD_FILTER_DATA_NED_VELOCITY = 250,
    MIP_FIELD_FILTER_DATA_ATTITUDE_QUATERNION = 251,
    MIP_FIELD_FILTER_DATA_ATTITUDE_DCM = 252,
    MIP_FIELD_FILTER_DATA_EULER_ANGLES = 253,
    MIP_FIELD_FILTER_DATA_GYRO_BIAS = 254,
    MIP_FIELD_FILTER_DATA_ACCEL_BIAS = 255,
    MIP_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY = 256,
    MIP_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY = 257,
    MIP_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY = 258,
    MIP_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY = 259,
    MIP_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY = 260,
    MIP_FIELD_FILTER_DATA_LINEAR_ACCEL = 261,
    MIP_FIELD_FILTER_DATA_COMP_ANGULAR_RATE = 262,
    MIP_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE = 263,
    MIP_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45 = 264,
    MIP_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS = 265,
    MIP_FIELD_FILTER_DATA_GPS_TIMESTAMP = 266,
    MIP_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY = 267,
    MIP_FIELD_FILTER_DATA_GRAVITY_VECTOR = 268,
    MIP_FIELD_FILTER_DATA_HEADING_UPDATE_STATE = 269,
    MIP_FIELD_FILTER_DATA_MAGNETIC_MODEL = 270,
    MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR = 271,
    MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR = 272,
    MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY = 273,
    MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY = 274,
    MIP_FIELD_FILTER_DATA_COMPENSATED_ACCEL = 275,
    MIP_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE = 276,
    MIP_FIELD_FILTER_DATA_PRESSURE_ALTITUDE = 277,
    MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET = 278,
    MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX = 279,
    MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY = 280,
    MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY = 281,
    MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION = 282,
    MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY = 283,
    MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION = 284,
    MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY = 285,
    MIP_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY = 286,
    MIP_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY = 287,
    MIP_FIELD_FILTER_DATA_ECEF_POSITION = 288,
    MIP_FIELD_FILTER_DATA_ECEF_VELOCITY = 289,
    MIP_FIELD_FILTER_DATA_NED_RELATIVE_POSITION = 290,
    MIP_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS = 291,
    MIP_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY = 292,
    MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR = 293,
    MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY = 294,
    MIP_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS = 295,
    MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR = 296,
    MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY = 297,
    MIP_FIELD_GNSS_RECEIVER_1_LLH_POSITION = 298,
    MIP_FIELD_GNSS_RECEIVER_1_ECEF_POSITION = 299,
    MIP_FIELD_GNSS_RECEIVER_1_NED_VELOCITY = 300,
    MIP_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY = 301,
    MIP_FIELD_GNSS_RECEIVER_1_DOP = 302,
    MIP_FIELD_GNSS_RECEIVER_1_UTC_TIME = 303,
    MIP_FIELD_GNSS_RECEIVER_1_GPS_TIME = 304,
    MIP_FIELD_GNSS_RECEIVER_1_FIX_INFO = 305,
    MIP_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS = 306,
    MIP_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2 = 307,
    MIP_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS = 308,
    MIP_FIELD_GNSS_RECEIVER_1_SBAS_INFO = 309,
    MIP_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS = 310,
    MIP_FIELD_GNSS_RECEIVER_1_RAW = 311,
    MIP_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS = 312,
    MIP_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS = 313,
    MIP_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS = 314,
    MIP_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS = 315,
    MIP_FIELD_GNSS_RECEIVER_2_LLH_POSITION = 316,
    MIP_FIELD_GNSS_RECEIVER_2_ECEF_POSITION = 317,
    MIP_FIELD_GNSS_RECEIVER_2_NED_VELOCITY = 318,
    MIP_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY = 319,
    MIP_FIELD_GNSS_RECEIVER_2_DOP = 320,
    MIP_FIELD_GNSS_RECEIVER_2_UTC_TIME = 321,
    MIP_FIELD_GNSS_RECEIVER_2_GPS_TIME = 322,
    MIP_FIELD_GNSS_RECEIVER_2_FIX_INFO = 323,
    MIP_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS = 324,
    MIP_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2 = 325,
    MIP_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS = 326,
    MIP_FIELD_GNSS_RECEIVER_2_SBAS_INFO = 327,
    MIP_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS = 328,
    MIP_FIELD_GNSS_RECEIVER_2_RAW = 329,
    MIP_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS = 330,
    MIP_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS = 331,
    MIP_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS = 332,
    MIP_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS = 333,
    MIP_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO = 334,
    MIP_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS = 335,
    MIP_FIELD_GNSS_EXTERNAL_LLH_POSITION = 336,
    MIP_FIELD_GNSS_EXTERNAL_NED_VELOCITY = 337,
    MIP_FIELD_GNSS_EXTERNAL_UTC_TIME = 338,
    MIP_FIELD_GNSS_EXTERNAL_FIX_INFO = 339,
    MIP_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS = 340,
    MIP_FIELD_SYSTEM_DATA_BUILT_IN_TEST = 341,
    MIP_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS = 342,
    MIP_FIELD_SYSTEM_DATA_GPIO_STATE = 343,
    MIP_FIELD_SHARED_EVENT_SOURCE = 344,
    MIP_FIELD_SHARED_GPS_TIMESTAMP = 345,
    MIP_FIELD_SHARED_DELTA_TIME = 346,
    MIP_FIELD_SHARED_REFERENCE_TIMESTAMP = 347,
    MIP_FIELD_SHARED_REFERENCE_TIME_DELTA = 348,
    MIP_FIELD_SHARED_EXTERNAL_TIMESTAMP = 349,
    MIP_FIELD_SHARED_EXTERNAL_TIME_DELTA = 350,
    MIP_FIELD_COUNT = 351
} mip_field_id_t;

/** A decoded field: which layout, and its value. */
typedef struct {
    mip_field_id_t id;
    union {
        mip_ack_nack_t ack_nack;
        mip_base_ping_t base_ping;
        mip_base_set_to_idle_t base_set_to_idle;
        mip_base_get_device_info_t base_get_device_info;
        mip_base_device_info_t base_device_info;
        mip_base_get_device_descriptors_t base_get_device_descriptors;
        mip_base_device_descriptors_t base_device_descriptors;
        mip_base_built_in_test_t base_built_in_test;
        mip_base_built_in_test_result_gx5_45_t base_built_in_test_result_gx5_45;
        mip_base_built_in_test_result_cv7_ins_t base_built_in_test_result_cv7_ins;
        mip_base_resume_t base_resume;
        mip_base_get_extended_descriptors_t base_get_extended_descriptors;
        mip_base_extended_descriptors_t base_extended_descriptors;
        mip_base_continuous_bit_t base_continuous_bit;
        mip_base_continuous_bit_result_t base_continuous_bit_result;
        mip_base_comm_port_speed_t base_comm_port_speed;
        mip_base_comm_port_speed_response_t base_comm_port_speed_response;
        mip_base_gps_time_update_gx5_45_t base_gps_time_update_gx5_45;
        mip_base_gps_time_update_cv7_ins_t base_gps_time_update_cv7_ins;
        mip_base_gps_week_t base_gps_week;
        mip_base_gps_seconds_t base_gps_seconds;
        mip_base_device_reset_t base_device_reset;
        mip_threedm_event_control_t threedm_event_control;
        mip_threedm_event_control_response_t threedm_event_control_response;
        mip_threedm_get_event_trigger_status_t threedm_get_event_trigger_status;
        mip_threedm_event_trigger_status_t threedm_event_trigger_status;
        mip_threedm_get_event_action_status_t threedm_get_event_action_status;
        mip_threedm_event_action_status_t threedm_event_action_status;
        mip_threedm_event_trigger_config_t threedm_event_trigger_config;
        mip_threedm_event_trigger_config_response_t threedm_event_trigger_config_response;
        mip_threedm_event_action_config_t threedm_event_action_config;
        mip_threedm_event_action_config_response_t threedm_event_action_config_response;
        mip_threedm_device_startup_settings_gx5_45_t threedm_device_startup_settings_gx5_45;
        mip_threedm_device_startup_settings_cv7_ins_t threedm_device_startup_settings_cv7_ins;
        mip_threedm_sensor_to_vehicle_euler_t threedm_sensor_to_vehicle_euler;
        mip_threedm_sensor_to_vehicle_euler_response_t threedm_sensor_to_vehicle_euler_response;
        mip_threedm_sensor_to_vehicle_quaternion_t threedm_sensor_to_vehicle_quaternion;
        mip_threedm_sensor_to_vehicle_quaternion_response_t threedm_sensor_to_vehicle_quaternion_response;
        mip_threedm_sensor_to_vehicle_dcm_t threedm_sensor_to_vehicle_dcm;
        mip_threedm_sensor_to_vehicle_dcm_response_t threedm_sensor_to_vehicle_dcm_response;
        mip_threedm_accel_bias_gx5_45_t threedm_accel_bias_gx5_45;
        mip_threedm_accel_bias_cv7_ins_t threedm_accel_bias_cv7_ins;
        mip_threedm_accel_bias_response_t threedm_accel_bias_response;
        mip_threedm_gyro_bias_gx5_45_t threedm_gyro_bias_gx5_45;
        mip_threedm_gyro_bias_cv7_ins_t threedm_gyro_bias_cv7_ins;
        mip_threedm_gyro_bias_response_t threedm_gyro_bias_response;
        mip_threedm_capture_gyro_bias_t threedm_capture_gyro_bias;
        mip_threedm_mag_hard_iron_offset_gx5_45_t threedm_mag_hard_iron_offset_gx5_45;
        mip_threedm_mag_hard_iron_offset_cv7_ins_t threedm_mag_hard_iron_offset_cv7_ins;
        mip_threedm_mag_hard_iron_offset_response_t threedm_mag_hard_iron_offset_response;
        mip_threedm_mag_soft_iron_matrix_gx5_45_t threedm_mag_soft_iron_matrix_gx5_45;
        mip_threedm_mag_soft_iron_matrix_cv7_ins_t threedm_mag_soft_iron_matrix_cv7_ins;
        mip_threedm_mag_soft_iron_matrix_response_t threedm_mag_soft_iron_matrix_response;
        mip_threedm_coning_sculling_enable_t threedm_coning_sculling_enable;
        mip_threedm_coning_sculling_enable_response_t threedm_coning_sculling_enable_response;
        mip_threedm_uart_baudrate_t threedm_uart_baudrate;
        mip_threedm_uart_baudrate_response_t threedm_uart_baudrate_response;
        mip_threedm_gpio_config_t threedm_gpio_config;
        mip_threedm_gpio_config_response_t threedm_gpio_config_response;
        mip_threedm_gpio_state_t threedm_gpio_state;
        mip_threedm_gpio_state_response_t threedm_gpio_state_response;
        mip_threedm_odometer_config_t threedm_odometer_config;
        mip_threedm_odometer_config_response_t threedm_odometer_config_response;
        mip_threedm_advanced_lowpass_filter_t threedm_advanced_lowpass_filter;
        mip_threedm_advanced_lowpass_filter_response_t threedm_advanced_lowpass_filter_response;
        mip_threedm_complementary_filter_t threedm_complementary_filter;
        mip_threedm_complementary_filter_response_t threedm_complementary_filter_response;
        mip_threedm_sensor_range_t threedm_sensor_range;
        mip_threedm_sensor_range_response_t threedm_sensor_range_response;
        mip_threedm_get_calibrated_sensor_ranges_t threedm_get_calibrated_sensor_ranges;
        mip_threedm_calibrated_sensor_ranges_t threedm_calibrated_sensor_ranges;
        mip_threedm_lowpass_filter_t threedm_lowpass_filter;
        mip_threedm_lowpass_filter_response_t threedm_lowpass_filter_response;
        mip_threedm_poll_imu_data_t threedm_poll_imu_data;
        mip_threedm_poll_gnss_data_t threedm_poll_gnss_data;
        mip_threedm_poll_filter_data_t threedm_poll_filter_data;
        mip_threedm_poll_nmea_data_t threedm_poll_nmea_data;
        mip_threedm_poll_data_t threedm_poll_data;
        mip_threedm_get_imu_base_rate_t threedm_get_imu_base_rate;
        mip_threedm_imu_base_rate_t threedm_imu_base_rate;
        mip_threedm_get_gnss_base_rate_t threedm_get_gnss_base_rate;
        mip_threedm_gnss_base_rate_t threedm_gnss_base_rate;
        mip_threedm_get_filter_base_rate_t threedm_get_filter_base_rate;
        mip_threedm_filter_base_rate_t threedm_filter_base_rate;
        mip_threedm_get_base_rate_t threedm_get_base_rate;
        mip_threedm_base_rate_t threedm_base_rate;
        mip_threedm_imu_message_format_t threedm_imu_message_format;
        mip_threedm_imu_message_format_response_t threedm_imu_message_format_response;
        mip_threedm_gnss_message_format_t threedm_gnss_message_format;
        mip_threedm_gnss_message_format_response_t threedm_gnss_message_format_response;
        mip_threedm_filter_message_format_t threedm_filter_message_format;
        mip_threedm_filter_message_format_response_t threedm_filter_message_format_response;
        mip_threedm_nmea_message_format_t threedm_nmea_message_format;
        mip_threedm_nmea_message_format_response_t threedm_nmea_message_format_response;
        mip_threedm_message_format_t threedm_message_format;
        mip_threedm_message_format_response_t threedm_message_format_response;
        mip_threedm_factory_streaming_t threedm_factory_streaming;
        mip_threedm_data_stream_control_gx5_45_t threedm_data_stream_control_gx5_45;
        mip_threedm_data_stream_control_cv7_ins_t threedm_data_stream_control_cv7_ins;
        mip_threedm_data_stream_control_response_gx5_45_t threedm_data_stream_control_response_gx5_45;
        mip_threedm_data_stream_control_response_cv7_ins_t threedm_data_stream_control_response_cv7_ins;
        mip_threedm_raw_rtcm_message_t threedm_raw_rtcm_message;
        mip_threedm_gnss_constellation_settings_t threedm_gnss_constellation_settings;
        mip_threedm_gnss_constellation_settings_response_t threedm_gnss_constellation_settings_response;
        mip_threedm_gnss_sbas_settings_t threedm_gnss_sbas_settings;
        mip_threedm_gnss_sbas_settings_response_t threedm_gnss_sbas_settings_response;
        mip_threedm_gnss_assisted_fix_control_t threedm_gnss_assisted_fix_control;
        mip_threedm_gnss_assisted_fix_control_response_t threedm_gnss_assisted_fix_control_response;
        mip_threedm_gnss_assist_time_update_t threedm_gnss_assist_time_update;
        mip_threedm_gnss_assist_time_update_response_t threedm_gnss_assist_time_update_response;
        mip_threedm_pps_source_t threedm_pps_source;
        mip_threedm_pps_source_response_t threedm_pps_source_response;
        mip_threedm_get_supported_events_t threedm_get_supported_events;
        mip_threedm_supported_events_t threedm_supported_events;
        mip_threedm_device_status_t threedm_device_status;
        mip_threedm_device_status_response_t threedm_device_status_response;
        mip_filter_reset_filter_t filter_reset_filter;
        mip_filter_set_initial_attitude_t filter_set_initial_attitude;
        mip_filter_set_initial_heading_t filter_set_initial_heading;
        mip_filter_run_filter_t filter_run_filter;
        mip_filter_vehicle_dynamics_mode_t filter_vehicle_dynamics_mode;
        mip_filter_vehicle_dynamics_mode_response_t filter_vehicle_dynamics_mode_response;
        mip_filter_sensor_to_vehicle_transform_t filter_sensor_to_vehicle_transform;
        mip_filter_sensor_to_vehicle_transform_response_t filter_sensor_to_vehicle_transform_response;
        mip_filter_sensor_to_vehicle_offset_t filter_sensor_to_vehicle_offset;
        mip_filter_sensor_to_vehicle_offset_response_t filter_sensor_to_vehicle_offset_response;
        mip_filter_antenna_offset_t filter_antenna_offset;
        mip_filter_antenna_offset_response_t filter_antenna_offset_response;
        mip_filter_estimation_control_t filter_estimation_control;
        mip_filter_estimation_control_response_t filter_estimation_control_response;
        mip_filter_gnss_source_control_t filter_gnss_source_control;
        mip_filter_gnss_source_control_response_t filter_gnss_source_control_response;
        mip_filter_external_gnss_update_t filter_external_gnss_update;
        mip_filter_external_heading_update_t filter_external_heading_update;
        mip_filter_heading_update_control_t filter_heading_update_control;
        mip_filter_heading_update_control_response_t filter_heading_update_control_response;
        mip_filter_auto_init_control_t filter_auto_init_control;
        mip_filter_auto_init_control_response_t filter_auto_init_control_response;
        mip_filter_accel_noise_t filter_accel_noise;
        mip_filter_accel_noise_response_t filter_accel_noise_response;
        mip_filter_gyro_noise_t filter_gyro_noise;
        mip_filter_gyro_noise_response_t filter_gyro_noise_response;
        mip_filter_accel_bias_model_t filter_accel_bias_model;
        mip_filter_accel_bias_model_response_t filter_accel_bias_model_response;
        mip_filter_gyro_bias_model_t filter_gyro_bias_model;
        mip_filter_gyro_bias_model_response_t filter_gyro_bias_model_response;
        mip_filter_zupt_control_t filter_zupt_control;
        mip_filter_zupt_control_response_t filter_zupt_control_response;
        mip_filter_external_heading_update_with_time_t filter_external_heading_update_with_time;
        mip_filter_zero_angular_rate_update_control_t filter_zero_angular_rate_update_control;
        mip_filter_zero_angular_rate_update_control_response_t
            filter_zero_angular_rate_update_control_response;
        mip_filter_tare_orientation_t filter_tare_orientation;
        mip_filter_commanded_zupt_t filter_commanded_zupt;
        mip_filter_commanded_zero_angular_rate_update_t filter_commanded_zero_angular_rate_update;
        mip_filter_mag_capture_auto_calibration_t filter_mag_capture_auto_calibration;
        mip_filter_gravity_noise_std_dev_t filter_gravity_noise_std_dev;
        mip_filter_gravity_noise_std_dev_response_t filter_gravity_noise_std_dev_response;
        mip_filter_pressure_altitude_noise_std_dev_t filter_pressure_altitude_noise_std_dev;
        mip_filter_pressure_altitude_noise_std_dev_response_t filter_pressure_altitude_noise_std_dev_response;
        mip_filter_hard_iron_offset_noise_t filter_hard_iron_offset_noise;
        mip_filter_hard_iron_offset_noise_response_t filter_hard_iron_offset_noise_response;
        mip_filter_soft_iron_matrix_noise_t filter_soft_iron_matrix_noise;
        mip_filter_soft_iron_matrix_noise_response_t filter_soft_iron_matrix_noise_response;
        mip_filter_mag_noise_std_dev_t filter_mag_noise_std_dev;
        mip_filter_mag_noise_std_dev_response_t filter_mag_noise_std_dev_response;
        mip_filter_declination_source_t filter_declination_source;
        mip_filter_declination_source_response_t filter_declination_source_response;
        mip_filter_gravity_magnitude_adaptive_measurement_t filter_gravity_magnitude_adaptive_measurement;
        mip_filter_gravity_magnitude_adaptive_measurement_response_t
            filter_gravity_magnitude_adaptive_measurement_response;
        mip_filter_mag_magnitude_adaptive_measurement_t filter_mag_magnitude_adaptive_measurement;
        mip_filter_mag_magnitude_adaptive_measurement_response_t
            filter_mag_magnitude_adaptive_measurement_response;
        mip_filter_mag_dip_angle_adaptive_measurement_t filter_mag_dip_angle_adaptive_measurement;
        mip_filter_mag_dip_angle_adaptive_measurement_response_t
            filter_mag_dip_angle_adaptive_measurement_response;
        mip_filter_altitude_aiding_control_t filter_altitude_aiding_control;
        mip_filter_altitude_aiding_control_response_t filter_altitude_aiding_control_response;
        mip_filter_pitch_roll_aiding_control_t filter_pitch_roll_aiding_control;
        mip_filter_pitch_roll_aiding_control_response_t filter_pitch_roll_aiding_control_response;
        mip_filter_inclination_source_t filter_inclination_source;
        mip_filter_inclination_source_response_t filter_inclination_source_response;
        mip_filter_magnetic_field_magnitude_source_t filter_magnetic_field_magnitude_source;
        mip_filter_magnetic_field_magnitude_source_response_t filter_magnetic_field_magnitude_source_response;
        mip_filter_aiding_measurement_control_t filter_aiding_measurement_control;
        mip_filter_aiding_measurement_control_response_t filter_aiding_measurement_control_response;
        mip_filter_initialization_configuration_t filter_initialization_configuration;
        mip_filter_initialization_configuration_response_t filter_initialization_configuration_response;
        mip_filter_adaptive_filter_control_t filter_adaptive_filter_control;
        mip_filter_adaptive_filter_control_response_t filter_adaptive_filter_control_response;
        mip_filter_multi_antenna_offset_t filter_multi_antenna_offset;
        mip_filter_multi_antenna_offset_response_t filter_multi_antenna_offset_response;
        mip_filter_relative_position_configuration_t filter_relative_position_configuration;
        mip_filter_relative_position_configuration_response_t filter_relative_position_configuration_response;
        mip_filter_reference_point_lever_arm_t filter_reference_point_lever_arm;
        mip_filter_reference_point_lever_arm_response_t filter_reference_point_lever_arm_response;
        mip_filter_speed_lever_arm_t filter_speed_lever_arm;
        mip_filter_speed_lever_arm_response_t filter_speed_lever_arm_response;
        mip_filter_wheeled_vehicle_constraint_control_t filter_wheeled_vehicle_constraint_control;
        mip_filter_wheeled_vehicle_constraint_control_response_t
            filter_wheeled_vehicle_constraint_control_response;
        mip_filter_gnss_antenna_calibration_control_t filter_gnss_antenna_calibration_control;
        mip_filter_gnss_antenna_calibration_control_response_t
            filter_gnss_antenna_calibration_control_response;
        mip_gnss_receiver_info_t gnss_receiver_info;
        mip_gnss_receiver_info_response_t gnss_receiver_info_response;
        mip_gnss_signal_configuration_t gnss_signal_configuration;
        mip_gnss_signal_configuration_response_t gnss_signal_configuration_response;
        mip_gnss_spartn_configuration_t gnss_spartn_configuration;
        mip_gnss_spartn_configuration_response_t gnss_spartn_configuration_response;
        mip_aiding_frame_config_t aiding_frame_config;
        mip_aiding_frame_config_response_t aiding_frame_config_response;
        mip_aiding_echo_control_t aiding_echo_control;
        mip_aiding_echo_control_response_t aiding_echo_control_response;
        mip_aiding_ecef_position_t aiding_ecef_position;
        mip_aiding_llh_position_t aiding_llh_position;
        mip_aiding_height_above_ellipsoid_t aiding_height_above_ellipsoid;
        mip_aiding_ecef_velocity_t aiding_ecef_velocity;
        mip_aiding_ned_velocity_t aiding_ned_velocity;
        mip_aiding_body_frame_velocity_t aiding_body_frame_velocity;
        mip_aiding_true_heading_t aiding_true_heading;
        mip_aiding_magnetic_field_t aiding_magnetic_field;
        mip_aiding_pressure_t aiding_pressure;
        mip_system_communication_mode_t system_communication_mode;
        mip_system_communication_mode_response_t system_communication_mode_response;
        mip_sensor_scaled_accel_t sensor_scaled_accel;
        mip_sensor_scaled_gyro_t sensor_scaled_gyro;
        mip_sensor_scaled_mag_t sensor_scaled_mag;
        mip_sensor_delta_theta_t sensor_delta_theta;
        mip_sensor_delta_velocity_t sensor_delta_velocity;
        mip_sensor_cf_orientation_matrix_t sensor_cf_orientation_matrix;
        mip_sensor_cf_quaternion_t sensor_cf_quaternion;
        mip_sensor_cf_euler_angles_t sensor_cf_euler_angles;
        mip_sensor_cf_stabilized_north_t sensor_cf_stabilized_north;
        mip_sensor_cf_stabilized_up_t sensor_cf_stabilized_up;
        mip_sensor_gps_timestamp_t sensor_gps_timestamp;
        mip_sensor_temperature_statistics_t sensor_temperature_statistics;
        mip_sensor_scaled_pressure_t sensor_scaled_pressure;
        mip_sensor_overrange_status_t sensor_overrange_status;
        mip_sensor_odometer_data_t sensor_odometer_data;
        mip_gnss_data_llh_position_t gnss_data_llh_position;
        mip_gnss_data_ecef_position_t gnss_data_ecef_position;
        mip_gnss_data_ned_velocity_t gnss_data_ned_velocity;
        mip_gnss_data_ecef_velocity_t gnss_data_ecef_velocity;
        mip_gnss_data_dop_t gnss_data_dop;
        mip_gnss_data_utc_time_t gnss_data_utc_time;
        mip_gnss_data_gps_time_t gnss_data_gps_time;
        mip_gnss_data_clock_info_t gnss_data_clock_info;
        mip_gnss_data_fix_info_t gnss_data_fix_info;
        mip_gnss_data_sv_info_t gnss_data_sv_info;
        mip_gnss_data_hardware_status_t gnss_data_hardware_status;
        mip_gnss_data_dgnss_info_t gnss_data_dgnss_info;
        mip_gnss_data_dgnss_channel_status_t gnss_data_dgnss_channel_status;
        mip_filter_data_llh_position_t filter_data_llh_position;
        mip_filter_data_ned_velocity_t filter_data_ned_velocity;
        mip_filter_data_attitude_quaternion_t filter_data_attitude_quaternion;
        mip_filter_data_attitude_dcm_t filter_data_attitude_dcm;
        mip_filter_data_euler_angles_t filter_data_euler_angles;
        mip_filter_data_gyro_bias_t filter_data_gyro_bias;
        mip_filter_data_accel_bias_t filter_data_accel_bias;
        mip_filter_data_llh_position_uncertainty_t filter_data_llh_position_uncertainty;
        mip_filter_data_ned_velocity_uncertainty_t filter_data_ned_velocity_uncertainty;
        mip_filter_data_euler_angles_uncertainty_t filter_data_euler_angles_uncertainty;
        mip_filter_data_gyro_bias_uncertainty_t filter_data_gyro_bias_uncertainty;
        mip_filter_data_accel_bias_uncertainty_t filter_data_accel_bias_uncertainty;
        mip_filter_data_linear_accel_t filter_data_linear_accel;
        mip_filter_data_comp_angular_rate_t filter_data_comp_angular_rate;
        mip_filter_data_wgs84_gravity_magnitude_t filter_data_wgs84_gravity_magnitude;
        mip_filter_data_filter_status_gx5_45_t filter_data_filter_status_gx5_45;
        mip_filter_data_filter_status_cv7_ins_t filter_data_filter_status_cv7_ins;
        mip_filter_data_gps_timestamp_t filter_data_gps_timestamp;
        mip_filter_data_quaternion_attitude_uncertainty_t filter_data_quaternion_attitude_uncertainty;
        mip_filter_data_gravity_vector_t filter_data_gravity_vector;
        mip_filter_data_heading_update_state_t filter_data_heading_update_state;
        mip_filter_data_magnetic_model_t filter_data_magnetic_model;
        mip_filter_data_gyro_scale_factor_t filter_data_gyro_scale_factor;
        mip_filter_data_accel_scale_factor_t filter_data_accel_scale_factor;
        mip_filter_data_gyro_scale_factor_uncertainty_t filter_data_gyro_scale_factor_uncertainty;
        mip_filter_data_accel_scale_factor_uncertainty_t filter_data_accel_scale_factor_uncertainty;
        mip_filter_data_compensated_accel_t filter_data_compensated_accel;
        mip_filter_data_standard_atmosphere_t filter_data_standard_atmosphere;
        mip_filter_data_pressure_altitude_t filter_data_pressure_altitude;
        mip_filter_data_mag_auto_hard_iron_offset_t filter_data_mag_auto_hard_iron_offset;
        mip_filter_data_mag_auto_soft_iron_matrix_t filter_data_mag_auto_soft_iron_matrix;
        mip_filter_data_mag_auto_hard_iron_offset_uncertainty_t
            filter_data_mag_auto_hard_iron_offset_uncertainty;
        mip_filter_data_mag_auto_soft_iron_matrix_uncertainty_t
            filter_data_mag_auto_soft_iron_matrix_uncertainty;
        mip_filter_data_gnss_antenna_offset_correction_t filter_data_gnss_antenna_offset_correction;
        mip_filter_data_gnss_antenna_offset_correction_uncertainty_t
            filter_data_gnss_antenna_offset_correction_uncertainty;
        mip_filter_data_multi_antenna_offset_correction_t filter_data_multi_antenna_offset_correction;
        mip_filter_data_multi_antenna_offset_correction_uncertainty_t
            filter_data_multi_antenna_offset_correction_uncertainty;
        mip_filter_data_ecef_position_uncertainty_t filter_data_ecef_position_uncertainty;
        mip_filter_data_ecef_velocity_uncertainty_t filter_data_ecef_velocity_uncertainty;
        mip_filter_data_ecef_position_t filter_data_ecef_position;
        mip_filter_data_ecef_velocity_t filter_data_ecef_velocity;
        mip_filter_data_ned_relative_position_t filter_data_ned_relative_position;
        mip_filter_data_gnss_position_aiding_status_t filter_data_gnss_position_aiding_status;
        mip_filter_data_aiding_measurement_summary_t filter_data_aiding_measurement_summary;
        mip_filter_data_odometer_scale_factor_error_t filter_data_odometer_scale_factor_error;
        mip_filter_data_odometer_scale_factor_error_uncertainty_t
            filter_data_odometer_scale_factor_error_uncertainty;
        mip_filter_data_gnss_dual_antenna_status_t filter_data_gnss_dual_antenna_status;
        mip_filter_data_aiding_frame_config_error_t filter_data_aiding_frame_config_error;
        mip_filter_data_aiding_frame_config_error_uncertainty_t
            filter_data_aiding_frame_config_error_uncertainty;
        mip_gnss_receiver_1_llh_position_t gnss_receiver_1_llh_position;
        mip_gnss_receiver_1_ecef_position_t gnss_receiver_1_ecef_position;
        mip_gnss_receiver_1_ned_velocity_t gnss_receiver_1_ned_velocity;
        mip_gnss_receiver_1_ecef_velocity_t gnss_receiver_1_ecef_velocity;
        mip_gnss_receiver_1_dop_t gnss_receiver_1_dop;
        mip_gnss_receiver_1_utc_time_t gnss_receiver_1_utc_time;
        mip_gnss_receiver_1_gps_time_t gnss_receiver_1_gps_time;
        mip_gnss_receiver_1_fix_info_t gnss_receiver_1_fix_info;
        mip_gnss_receiver_1_hardware_status_t gnss_receiver_1_hardware_status;
        mip_gnss_receiver_1_clock_info_2_t gnss_receiver_1_clock_info_2;
        mip_gnss_receiver_1_gps_leap_seconds_t gnss_receiver_1_gps_leap_seconds;
        mip_gnss_receiver_1_sbas_info_t gnss_receiver_1_sbas_info;
        mip_gnss_receiver_1_satellite_status_t gnss_receiver_1_satellite_status;
        mip_gnss_receiver_1_raw_t gnss_receiver_1_raw;
        mip_gnss_receiver_1_gps_ephemeris_t gnss_receiver_1_gps_ephemeris;
        mip_gnss_receiver_1_glonass_ephemeris_t gnss_receiver_1_glonass_ephemeris;
        mip_gnss_receiver_1_galileo_ephemeris_t gnss_receiver_1_galileo_ephemeris;
        mip_gnss_receiver_1_beidou_ephemeris_t gnss_receiver_1_beidou_ephemeris;
        mip_gnss_receiver_2_llh_position_t gnss_receiver_2_llh_position;
        mip_gnss_receiver_2_ecef_position_t gnss_receiver_2_ecef_position;
        mip_gnss_receiver_2_ned_velocity_t gnss_receiver_2_ned_velocity;
        mip_gnss_receiver_2_ecef_velocity_t gnss_receiver_2_ecef_velocity;
        mip_gnss_receiver_2_dop_t gnss_receiver_2_dop;
        mip_gnss_receiver_2_utc_time_t gnss_receiver_2_utc_time;
        mip_gnss_receiver_2_gps_time_t gnss_receiver_2_gps_time;
        mip_gnss_receiver_2_fix_info_t gnss_receiver_2_fix_info;
        mip_gnss_receiver_2_hardware_status_t gnss_receiver_2_hardware_status;
        mip_gnss_receiver_2_clock_info_2_t gnss_receiver_2_clock_info_2;
        mip_gnss_receiver_2_gps_leap_seconds_t gnss_receiver_2_gps_leap_seconds;
        mip_gnss_receiver_2_sbas_info_t gnss_receiver_2_sbas_info;
        mip_gnss_receiver_2_satellite_status_t gnss_receiver_2_satellite_status;
        mip_gnss_receiver_2_raw_t gnss_receiver_2_raw;
        mip_gnss_receiver_2_gps_ephemeris_t gnss_receiver_2_gps_ephemeris;
        mip_gnss_receiver_2_glonass_ephemeris_t gnss_receiver_2_glonass_ephemeris;
        mip_gnss_receiver_2_galileo_ephemeris_t gnss_receiver_2_galileo_ephemeris;
        mip_gnss_receiver_2_beidou_ephemeris_t gnss_receiver_2_beidou_ephemeris;
        mip_gnss_corrections_base_station_info_t gnss_corrections_base_station_info;
        mip_gnss_corrections_rtk_corrections_status_t gnss_corrections_rtk_corrections_status;
        mip_gnss_external_llh_position_t gnss_external_llh_position;
        mip_gnss_external_ned_velocity_t gnss_external_ned_velocity;
        mip_gnss_external_utc_time_t gnss_external_utc_time;
        mip_gnss_external_fix_info_t gnss_external_fix_info;
        mip_gnss_external_satellite_status_t gnss_external_satellite_status;
        mip_system_data_built_in_test_t system_data_built_in_test;
        mip_system_data_time_sync_status_t system_data_time_sync_status;
        mip_system_data_gpio_state_t system_data_gpio_state;
        mip_shared_event_source_t shared_event_source;
        mip_shared_gps_timestamp_t shared_gps_timestamp;
        mip_shared_delta_time_t shared_delta_time;
        mip_shared_reference_timestamp_t shared_reference_timestamp;
        mip_shared_reference_time_delta_t shared_reference_time_delta;
        mip_shared_external_timestamp_t shared_external_timestamp;
        mip_shared_external_time_delta_t shared_external_time_delta;
    } u;
} mip_field_value_t;

/** What the spec says about a field layout. */
typedef struct {
    mip_field_id_t id;
    const char *name;   /* field name */
    const char *device; /* device id when the field has per-device variants, else NULL */
    mip_device_t device_id;
    uint8_t descriptor;
} mip_layout_info_t;

/** A field: its layouts are ids first_layout .. first_layout + layout_count - 1, in IR order. */
typedef struct {
    const char *name;
    uint8_t descriptor;
    mip_field_id_t first_layout;
    size_t layout_count;
} mip_field_info_t;

/** Information on a layout id (NULL if out of range). */
const mip_layout_info_t *mip_layout_info(mip_field_id_t id);

/**
 * The field (set, descriptor) designates: a field of the set, a reserved field of the set's
 * kind, or a shared data field. NULL if none; *why is then MIP_ERR_UNKNOWN_SET or
 * MIP_ERR_UNKNOWN_DESCRIPTOR.
 */
const mip_field_info_t *mip_find_field(uint8_t set, uint8_t descriptor, mip_status_t *why);

/**
 * Decodes field data. Per-device variants are tried in IR order (only the one of `device`
 * when it has one); the first that decodes wins. If none does, *err is the error of the first.
 */
mip_status_t mip_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                              mip_device_t device, mip_field_value_t *out, mip_decode_error_t *err);

/** Encodes the data of a decoded field (no field header). */
mip_status_t mip_encode_field(const mip_field_value_t *value, uint8_t *buf, size_t cap, size_t *len_out);

#ifdef __cplusplus
}
#endif

#endif
