/* Dispatch by (descriptor set, descriptor): devices, set kinds, the value of any field, and
 * decode/encode of any field (docs/conformance.md section 2). Generated: do not edit. */
#ifndef MSCIPC_DISPATCH_H
#define MSCIPC_DISPATCH_H

#include "mscipcodec/field_iter.h"
#include "mscipcodec/reserved.h"
#include "mscipcodec/sets/base.h"
#include "mscipcodec/sets/imu_config.h"
#include "mscipcodec/sets/imu_data.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Devices named by the spec; MSCIPC_DEVICE_ANY tries every per-device variant. */
typedef enum {
    MSCIPC_DEVICE_ANY = 0,
    MSCIPC_DEVICE_MS_IMU3020 = 1 /* MS-IMU3020 */
} mscipc_device_t;

/** The id of a device ("ms_imu3020"), or NULL for MSCIPC_DEVICE_ANY. */
const char *mscipc_device_id(mscipc_device_t device);
/** Looks up a device by id; false if there is none. */
bool mscipc_device_from_id(const char *id, mscipc_device_t *out);
/** The device's title ("MS-IMU3020") and the file name of its manual, or NULL for
 * MSCIPC_DEVICE_ANY. */
const char *mscipc_device_title(mscipc_device_t device);
const char *mscipc_device_manual(mscipc_device_t device);
/** What the device supports, as its manual documents it (the IR's `capabilities`): the
 * (set << 8) | descriptor of every command, or of every data quantity, ascending, in a constant
 * table; *count is set to its length (0 and NULL for MSCIPC_DEVICE_ANY). No allocation. */
const uint16_t *mscipc_device_commands(mscipc_device_t device, size_t *count);
const uint16_t *mscipc_device_data(mscipc_device_t device, size_t *count);
/** The baud rates of the device's main port as its manual lists them (the IR's `link`), ascending,
 * in a constant table; *count is set to its length (0 and NULL for MSCIPC_DEVICE_ANY or a model
 * whose manual lists none). */
const uint32_t *mscipc_device_baud_rates(mscipc_device_t device, size_t *count);
/** The default baud rate of the device's main port; 0 when its manual states none. */
uint32_t mscipc_device_default_baud(mscipc_device_t device);
/** True when the device's manual documents the command or data quantity (set, descriptor); the
 * sessions refuse a command for which this is false, before sending it. */
bool mscipc_device_supports(mscipc_device_t device, uint8_t set, uint8_t descriptor);

/** Kind of a descriptor set, from the set_kinds ranges. */
typedef enum {
    MSCIPC_SET_KIND_NONE = 0,
    MSCIPC_SET_KIND_COMMAND = 1, /* 0x01..0x7F */
    MSCIPC_SET_KIND_DATA = 2     /* 0x80..0xFF */
} mscipc_set_kind_t;

mscipc_set_kind_t mscipc_set_kind(uint8_t set);

/** One id per field layout (per-device variants have one each). */
typedef enum {
    MSCIPC_FIELD_NONE = 0,
    MSCIPC_FIELD_ACK,
    MSCIPC_FIELD_BASE_PING,
    MSCIPC_FIELD_BASE_GET_DEVICE_MESSAGES,
    MSCIPC_FIELD_BASE_DEVICE_MESSAGES,
    MSCIPC_FIELD_BASE_DEVICE_RESET,
    MSCIPC_FIELD_BASE_GET_DEVICE_MODEL,
    MSCIPC_FIELD_BASE_DEVICE_MODEL,
    MSCIPC_FIELD_BASE_GET_DEVICE_SN,
    MSCIPC_FIELD_BASE_DEVICE_SN,
    MSCIPC_FIELD_BASE_GET_DEVICE_FW,
    MSCIPC_FIELD_BASE_DEVICE_FW,
    MSCIPC_FIELD_BASE_GET_DEVICE_CAL,
    MSCIPC_FIELD_BASE_DEVICE_CAL,
    MSCIPC_FIELD_BASE_CORRELATE_GPS_TIME,
    MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE,
    MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE_RESPONSE,
    MSCIPC_FIELD_IMU_CONFIG_FILTER,
    MSCIPC_FIELD_IMU_CONFIG_FILTER_RESPONSE,
    MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE,
    MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE_RESPONSE,
    MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS,
    MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_RESPONSE,
    MSCIPC_FIELD_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE,
    MSCIPC_FIELD_IMU_CONFIG_INTERNAL_SAMPLE_RATE,
    MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE,
    MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE_RESPONSE,
    MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE,
    MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE_RESPONSE,
    MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL,
    MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF,
    MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF_RESPONSE,
    MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF,
    MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF_RESPONSE,
    MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B,
    MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B_RESPONSE,
    MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE,
    MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE_RESPONSE,
    MSCIPC_FIELD_IMU_DATA_SCALED_ACCEL,
    MSCIPC_FIELD_IMU_DATA_SCALED_GYRO,
    MSCIPC_FIELD_IMU_DATA_SCALED_MAG,
    MSCIPC_FIELD_IMU_DATA_DELTA_THETA,
    MSCIPC_FIELD_IMU_DATA_DELTA_VELOCITY,
    MSCIPC_FIELD_IMU_DATA_SCALED_PRESSURE,
    MSCIPC_FIELD_IMU_DATA_SCALED_TEMPERATURE,
    MSCIPC_FIELD_IMU_DATA_GPS_CORRELATED_TIME,
    MSCIPC_FIELD_IMU_DATA_SCALED_AUX_ACCEL,
    MSCIPC_FIELD_COUNT
} mscipc_field_id_t;

/** A decoded field: which layout, and its value. */
typedef struct {
    mscipc_field_id_t id;
    union {
        mscipc_ack_t ack;
        mscipc_base_ping_t base_ping;
        mscipc_base_get_device_messages_t base_get_device_messages;
        mscipc_base_device_messages_t base_device_messages;
        mscipc_base_device_reset_t base_device_reset;
        mscipc_base_get_device_model_t base_get_device_model;
        mscipc_base_device_model_t base_device_model;
        mscipc_base_get_device_sn_t base_get_device_sn;
        mscipc_base_device_sn_t base_device_sn;
        mscipc_base_get_device_fw_t base_get_device_fw;
        mscipc_base_device_fw_t base_device_fw;
        mscipc_base_get_device_cal_t base_get_device_cal;
        mscipc_base_device_cal_t base_device_cal;
        mscipc_base_correlate_gps_time_t base_correlate_gps_time;
        mscipc_imu_config_uart_baud_rate_t imu_config_uart_baud_rate;
        mscipc_imu_config_uart_baud_rate_response_t imu_config_uart_baud_rate_response;
        mscipc_imu_config_filter_t imu_config_filter;
        mscipc_imu_config_filter_response_t imu_config_filter_response;
        mscipc_imu_config_sample_rate_t imu_config_sample_rate;
        mscipc_imu_config_sample_rate_response_t imu_config_sample_rate_response;
        mscipc_imu_config_select_sensors_t imu_config_select_sensors;
        mscipc_imu_config_select_sensors_response_t imu_config_select_sensors_response;
        mscipc_imu_config_get_internal_sample_rate_t imu_config_get_internal_sample_rate;
        mscipc_imu_config_internal_sample_rate_t imu_config_internal_sample_rate;
        mscipc_imu_config_accel_range_t imu_config_accel_range;
        mscipc_imu_config_accel_range_response_t imu_config_accel_range_response;
        mscipc_imu_config_gyro_range_t imu_config_gyro_range;
        mscipc_imu_config_gyro_range_response_t imu_config_gyro_range_response;
        mscipc_imu_config_config_all_t imu_config_config_all;
        mscipc_imu_config_data_on_off_t imu_config_data_on_off;
        mscipc_imu_config_data_on_off_response_t imu_config_data_on_off_response;
        mscipc_imu_config_xtrig_on_off_t imu_config_xtrig_on_off;
        mscipc_imu_config_xtrig_on_off_response_t imu_config_xtrig_on_off_response;
        mscipc_imu_config_select_sensors_rev_b_t imu_config_select_sensors_rev_b;
        mscipc_imu_config_select_sensors_rev_b_response_t imu_config_select_sensors_rev_b_response;
        mscipc_imu_config_aux_accel_range_t imu_config_aux_accel_range;
        mscipc_imu_config_aux_accel_range_response_t imu_config_aux_accel_range_response;
        mscipc_imu_data_scaled_accel_t imu_data_scaled_accel;
        mscipc_imu_data_scaled_gyro_t imu_data_scaled_gyro;
        mscipc_imu_data_scaled_mag_t imu_data_scaled_mag;
        mscipc_imu_data_delta_theta_t imu_data_delta_theta;
        mscipc_imu_data_delta_velocity_t imu_data_delta_velocity;
        mscipc_imu_data_scaled_pressure_t imu_data_scaled_pressure;
        mscipc_imu_data_scaled_temperature_t imu_data_scaled_temperature;
        mscipc_imu_data_gps_correlated_time_t imu_data_gps_correlated_time;
        mscipc_imu_data_scaled_aux_accel_t imu_data_scaled_aux_accel;
    } u;
} mscipc_field_value_t;

/** What the spec says about a field layout. */
typedef struct {
    mscipc_field_id_t id;
    const char *name;   /* field name */
    const char *device; /* device id when the field has per-device variants, else NULL */
    mscipc_device_t device_id;
    uint8_t descriptor;
} mscipc_layout_info_t;

/** A field: its layouts are ids first_layout .. first_layout + layout_count - 1, in IR order. */
typedef struct {
    const char *name;
    uint8_t descriptor;
    mscipc_field_id_t first_layout;
    size_t layout_count;
} mscipc_field_info_t;

/** Information on a layout id (NULL if out of range). */
const mscipc_layout_info_t *mscipc_layout_info(mscipc_field_id_t id);

/**
 * The field (set, descriptor) designates: a field of the set, a reserved field of the set's
 * kind, or a shared data field. NULL if none; *why is then MSCIPC_ERR_UNKNOWN_SET or
 * MSCIPC_ERR_UNKNOWN_DESCRIPTOR.
 */
const mscipc_field_info_t *mscipc_find_field(uint8_t set, uint8_t descriptor, mscipc_status_t *why);

/**
 * Decodes field data. Per-device variants are tried in IR order (only the one of `device`
 * when it has one); the first that decodes wins. If none does, *err is the error of the first.
 */
mscipc_status_t mscipc_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                    mscipc_device_t device, mscipc_field_value_t *out,
                                    mscipc_decode_error_t *err);

/** A packet of any data set decoded by its set's straight-line decoder (mscipc_decode_packet). */
typedef struct {
    uint8_t set;
    union {
        mscipc_imu_data_packet_t imu_data;
        uint8_t none_; /* no data set */
    } u;
} mscipc_packet_t;

/**
 * Decodes a packet (sync, header and payload; its checksum is the parser's business) of a data set
 * with that set's straight-line decoder (<set>_decode_packet: entries it leaves go to other, which
 * may be NULL, with ctx) into the set's member of out->u, and returns its index (the fields
 * decoded, in packet order). For a set without one (not a data set, or not defined) every entry
 * goes to other and it returns NULL.
 */
const mscipc_packet_index_t *mscipc_decode_packet(const uint8_t *packet, mscipc_packet_t *out,
                                                  mscipc_field_entry_fn other, void *ctx);

/**
 * mscipc_decode_packet through a layout cache (issue 38), with the same contract and results: a
 * packet whose shape (set, payload length, every field header) is in the cache is decoded at the
 * shape's offsets, without the header walk and the dispatch per descriptor; any other packet
 * takes mscipc_decode_packet, and its shape is recorded (round-robin over
 * MSCIPC_LAYOUT_CACHE_SHAPES slots) when every entry was decoded into a member. cache: one per
 * stream, initialised with mscipc_layout_cache_init; fixed size, no allocation.
 */
const mscipc_packet_index_t *mscipc_decode_packet_cached(mscipc_layout_cache_t *cache, const uint8_t *packet,
                                                         mscipc_packet_t *out, mscipc_field_entry_fn other,
                                                         void *ctx);

/** Encodes the data of a decoded field (no field header). */
mscipc_status_t mscipc_encode_field(const mscipc_field_value_t *value, uint8_t *buf, size_t cap,
                                    size_t *len_out);

#ifdef __cplusplus
}
#endif

#endif
