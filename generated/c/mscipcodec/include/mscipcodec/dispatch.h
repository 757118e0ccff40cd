/* Dispatch by (descriptor set, descriptor): devices, set kinds, the value of any field, and
 * decode/encode of any field (docs/conformance.md section 2). Generated: do not edit. */
#ifndef MSCIP_DISPATCH_H
#define MSCIP_DISPATCH_H

#include "mscipcodec/reserved.h"
#include "mscipcodec/sets/base.h"
#include "mscipcodec/sets/imu_config.h"
#include "mscipcodec/sets/imu_data.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Devices named by the spec; MSCIP_DEVICE_ANY tries every per-device variant. */
typedef enum {
    MSCIP_DEVICE_ANY = 0,
    MSCIP_DEVICE_MS_IMU3020 = 1 /* MS-IMU3020 */
} mscip_device_t;

/** The id of a device ("ms_imu3020"), or NULL for MSCIP_DEVICE_ANY. */
const char *mscip_device_id(mscip_device_t device);
/** Looks up a device by id; false if there is none. */
bool mscip_device_from_id(const char *id, mscip_device_t *out);

/** Kind of a descriptor set, from the set_kinds ranges. */
typedef enum {
    MSCIP_SET_KIND_NONE = 0,
    MSCIP_SET_KIND_COMMAND = 1, /* 0x01..0x7F */
    MSCIP_SET_KIND_DATA = 2     /* 0x80..0xFF */
} mscip_set_kind_t;

mscip_set_kind_t mscip_set_kind(uint8_t set);

/** One id per field layout (per-device variants have one each). */
typedef enum {
    MSCIP_FIELD_NONE = 0,
    MSCIP_FIELD_ACK = 1,
    MSCIP_FIELD_BASE_PING = 2,
    MSCIP_FIELD_BASE_GET_DEVICE_MESSAGES = 3,
    MSCIP_FIELD_BASE_DEVICE_MESSAGES = 4,
    MSCIP_FIELD_BASE_DEVICE_RESET = 5,
    MSCIP_FIELD_BASE_GET_DEVICE_MODEL = 6,
    MSCIP_FIELD_BASE_DEVICE_MODEL = 7,
    MSCIP_FIELD_BASE_GET_DEVICE_SN = 8,
    MSCIP_FIELD_BASE_DEVICE_SN = 9,
    MSCIP_FIELD_BASE_GET_DEVICE_FW = 10,
    MSCIP_FIELD_BASE_DEVICE_FW = 11,
    MSCIP_FIELD_BASE_GET_DEVICE_CAL = 12,
    MSCIP_FIELD_BASE_DEVICE_CAL = 13,
    MSCIP_FIELD_BASE_CORRELATE_GPS_TIME = 14,
    MSCIP_FIELD_IMU_CONFIG_UART_BAUD_RATE = 15,
    MSCIP_FIELD_IMU_CONFIG_UART_BAUD_RATE_RESPONSE = 16,
    MSCIP_FIELD_IMU_CONFIG_FILTER = 17,
    MSCIP_FIELD_IMU_CONFIG_FILTER_RESPONSE = 18,
    MSCIP_FIELD_IMU_CONFIG_SAMPLE_RATE = 19,
    MSCIP_FIELD_IMU_CONFIG_SAMPLE_RATE_RESPONSE = 20,
    MSCIP_FIELD_IMU_CONFIG_SELECT_SENSORS = 21,
    MSCIP_FIELD_IMU_CONFIG_SELECT_SENSORS_RESPONSE = 22,
    MSCIP_FIELD_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE = 23,
    MSCIP_FIELD_IMU_CONFIG_INTERNAL_SAMPLE_RATE = 24,
    MSCIP_FIELD_IMU_CONFIG_ACCEL_RANGE = 25,
    MSCIP_FIELD_IMU_CONFIG_ACCEL_RANGE_RESPONSE = 26,
    MSCIP_FIELD_IMU_CONFIG_GYRO_RANGE = 27,
    MSCIP_FIELD_IMU_CONFIG_GYRO_RANGE_RESPONSE = 28,
    MSCIP_FIELD_IMU_CONFIG_CONFIG_ALL = 29,
    MSCIP_FIELD_IMU_CONFIG_DATA_ON_OFF = 30,
    MSCIP_FIELD_IMU_CONFIG_DATA_ON_OFF_RESPONSE = 31,
    MSCIP_FIELD_IMU_CONFIG_XTRIG_ON_OFF = 32,
    MSCIP_FIELD_IMU_CONFIG_XTRIG_ON_OFF_RESPONSE = 33,
    MSCIP_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B = 34,
    MSCIP_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B_RESPONSE = 35,
    MSCIP_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE = 36,
    MSCIP_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE_RESPONSE = 37,
    MSCIP_FIELD_IMU_DATA_SCALED_ACCEL = 38,
    MSCIP_FIELD_IMU_DATA_SCALED_GYRO = 39,
    MSCIP_FIELD_IMU_DATA_SCALED_MAG = 40,
    MSCIP_FIELD_IMU_DATA_DELTA_THETA = 41,
    MSCIP_FIELD_IMU_DATA_DELTA_VELOCITY = 42,
    MSCIP_FIELD_IMU_DATA_SCALED_PRESSURE = 43,
    MSCIP_FIELD_IMU_DATA_SCALED_TEMPERATURE = 44,
    MSCIP_FIELD_IMU_DATA_GPS_CORRELATED_TIME = 45,
    MSCIP_FIELD_IMU_DATA_SCALED_AUX_ACCEL = 46,
    MSCIP_FIELD_COUNT = 47
} mscip_field_id_t;

/** A decoded field: which layout, and its value. */
typedef struct {
    mscip_field_id_t id;
    union {
        mscip_ack_t ack;
        mscip_base_ping_t base_ping;
        mscip_base_get_device_messages_t base_get_device_messages;
        mscip_base_device_messages_t base_device_messages;
        mscip_base_device_reset_t base_device_reset;
        mscip_base_get_device_model_t base_get_device_model;
        mscip_base_device_model_t base_device_model;
        mscip_base_get_device_sn_t base_get_device_sn;
        mscip_base_device_sn_t base_device_sn;
        mscip_base_get_device_fw_t base_get_device_fw;
        mscip_base_device_fw_t base_device_fw;
        mscip_base_get_device_cal_t base_get_device_cal;
        mscip_base_device_cal_t base_device_cal;
        mscip_base_correlate_gps_time_t base_correlate_gps_time;
        mscip_imu_config_uart_baud_rate_t imu_config_uart_baud_rate;
        mscip_imu_config_uart_baud_rate_response_t imu_config_uart_baud_rate_response;
        mscip_imu_config_filter_t imu_config_filter;
        mscip_imu_config_filter_response_t imu_config_filter_response;
        mscip_imu_config_sample_rate_t imu_config_sample_rate;
        mscip_imu_config_sample_rate_response_t imu_config_sample_rate_response;
        mscip_imu_config_select_sensors_t imu_config_select_sensors;
        mscip_imu_config_select_sensors_response_t imu_config_select_sensors_response;
        mscip_imu_config_get_internal_sample_rate_t imu_config_get_internal_sample_rate;
        mscip_imu_config_internal_sample_rate_t imu_config_internal_sample_rate;
        mscip_imu_config_accel_range_t imu_config_accel_range;
        mscip_imu_config_accel_range_response_t imu_config_accel_range_response;
        mscip_imu_config_gyro_range_t imu_config_gyro_range;
        mscip_imu_config_gyro_range_response_t imu_config_gyro_range_response;
        mscip_imu_config_config_all_t imu_config_config_all;
        mscip_imu_config_data_on_off_t imu_config_data_on_off;
        mscip_imu_config_data_on_off_response_t imu_config_data_on_off_response;
        mscip_imu_config_xtrig_on_off_t imu_config_xtrig_on_off;
        mscip_imu_config_xtrig_on_off_response_t imu_config_xtrig_on_off_response;
        mscip_imu_config_select_sensors_rev_b_t imu_config_select_sensors_rev_b;
        mscip_imu_config_select_sensors_rev_b_response_t imu_config_select_sensors_rev_b_response;
        mscip_imu_config_aux_accel_range_t imu_config_aux_accel_range;
        mscip_imu_config_aux_accel_range_response_t imu_config_aux_accel_range_response;
        mscip_imu_data_scaled_accel_t imu_data_scaled_accel;
        mscip_imu_data_scaled_gyro_t imu_data_scaled_gyro;
        mscip_imu_data_scaled_mag_t imu_data_scaled_mag;
        mscip_imu_data_delta_theta_t imu_data_delta_theta;
        mscip_imu_data_delta_velocity_t imu_data_delta_velocity;
        mscip_imu_data_scaled_pressure_t imu_data_scaled_pressure;
        mscip_imu_data_scaled_temperature_t imu_data_scaled_temperature;
        mscip_imu_data_gps_correlated_time_t imu_data_gps_correlated_time;
        mscip_imu_data_scaled_aux_accel_t imu_data_scaled_aux_accel;
    } u;
} mscip_field_value_t;

/** What the spec says about a field layout. */
typedef struct {
    mscip_field_id_t id;
    const char *name;   /* field name */
    const char *device; /* device id when the field has per-device variants, else NULL */
    mscip_device_t device_id;
    uint8_t descriptor;
} mscip_layout_info_t;

/** A field: its layouts are ids first_layout .. first_layout + layout_count - 1, in IR order. */
typedef struct {
    const char *name;
    uint8_t descriptor;
    mscip_field_id_t first_layout;
    size_t layout_count;
} mscip_field_info_t;

/** Information on a layout id (NULL if out of range). */
const mscip_layout_info_t *mscip_layout_info(mscip_field_id_t id);

/**
 * The field (set, descriptor) designates: a field of the set, a reserved field of the set's
 * kind, or a shared data field. NULL if none; *why is then MSCIP_ERR_UNKNOWN_SET or
 * MSCIP_ERR_UNKNOWN_DESCRIPTOR.
 */
const mscip_field_info_t *mscip_find_field(uint8_t set, uint8_t descriptor, mscip_status_t *why);

/**
 * Decodes field data. Per-device variants are tried in IR order (only the one of `device`
 * when it has one); the first that decodes wins. If none does, *err is the error of the first.
 */
mscip_status_t mscip_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                  mscip_device_t device, mscip_field_value_t *out, mscip_decode_error_t *err);

/** Encodes the data of a decoded field (no field header). */
mscip_status_t mscip_encode_field(const mscip_field_value_t *value, uint8_t *buf, size_t cap,
                                  size_t *len_out);

#ifdef __cplusplus
}
#endif

#endif
