/* Dispatch by (descriptor set, descriptor): devices, set kinds, the value of any field, and
 * decode/encode of any field (docs/conformance.md section 2). Generated: do not edit. */
#ifndef MIP_DISPATCH_H
#define MIP_DISPATCH_H

#include "mipcodec/reserved.h"
#include "mipcodec/sets/base.h"
#include "mipcodec/sets/threedm.h"
#include "mipcodec/sets/sensor.h"

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
    MIP_FIELD_SENSOR_SCALED_ACCEL = 33,
    MIP_FIELD_SENSOR_SCALED_GYRO = 34,
    MIP_FIELD_SENSOR_SCALED_MAG = 35,
    MIP_FIELD_COUNT = 36
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
        mip_sensor_scaled_accel_t sensor_scaled_accel;
        mip_sensor_scaled_gyro_t sensor_scaled_gyro;
        mip_sensor_scaled_mag_t sensor_scaled_mag;
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
