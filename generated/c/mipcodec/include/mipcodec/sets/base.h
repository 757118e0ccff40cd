/* Base Command Set (descriptor set 0x01): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_BASE_H
#define MIPC_SETS_BASE_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_BASE_SET 0x01

/* ---- ping (command): Ping */
#define MIPC_BASE_PING_DESCRIPTOR 0x01

/** Ping. Test communications with a device. The device responds with an ACK if present. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_base_ping_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_PING_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_ping_encode(const mipc_base_ping_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_ping_decode(const uint8_t *data, size_t len, mipc_base_ping_t *out,
                                    mipc_decode_error_t *err);

/* ---- set_to_idle (command): Set to idle */
#define MIPC_BASE_SET_TO_IDLE_DESCRIPTOR 0x02

/** Set to idle. Turn off all device data streams; suspends streaming or wakes the device from sleep so it can
 * answer status and setup commands. Resume restores the previous mode. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_base_set_to_idle_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_SET_TO_IDLE_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_set_to_idle_encode(const mipc_base_set_to_idle_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_set_to_idle_decode(const uint8_t *data, size_t len, mipc_base_set_to_idle_t *out,
                                           mipc_decode_error_t *err);

/* ---- get_device_info (command): Get device information */
#define MIPC_BASE_GET_DEVICE_INFO_DESCRIPTOR 0x03

/** Get device information. Get the device ID strings and firmware version. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_base_get_device_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_GET_DEVICE_INFO_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_get_device_info_encode(const mipc_base_get_device_info_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_get_device_info_decode(const uint8_t *data, size_t len,
                                               mipc_base_get_device_info_t *out, mipc_decode_error_t *err);

/* ---- device_info (response): Device information */
#define MIPC_BASE_DEVICE_INFO_DESCRIPTOR 0x81

/** Device information. Reply to Get device information. */
typedef struct {
    mipc_device_info_t info; /* Device information. */
} mipc_base_device_info_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_DEVICE_INFO_MAX_SIZE 82

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_device_info_encode(const mipc_base_device_info_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_device_info_decode(const uint8_t *data, size_t len, mipc_base_device_info_t *out,
                                           mipc_decode_error_t *err);

/* ---- get_device_descriptors (command): Get device descriptor sets */
#define MIPC_BASE_GET_DEVICE_DESCRIPTORS_DESCRIPTOR 0x04

/** Get device descriptor sets. Get the command and data descriptors supported by the device. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_base_get_device_descriptors_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_GET_DEVICE_DESCRIPTORS_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_get_device_descriptors_encode(const mipc_base_get_device_descriptors_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_get_device_descriptors_decode(const uint8_t *data, size_t len,
                                                      mipc_base_get_device_descriptors_t *out,
                                                      mipc_decode_error_t *err);

/* ---- device_descriptors (response): Device descriptors */
#define MIPC_BASE_DEVICE_DESCRIPTORS_DESCRIPTOR 0x82

/** Device descriptors. Array of 16-bit values: the MSB is the descriptor set and the LSB the descriptor. The
 * array runs to the end of the field. */
typedef struct {
    size_t descriptors_count;  /* number of elements in descriptors */
    uint16_t descriptors[126]; /* Supported descriptors, (set << 8) | descriptor. */
} mipc_base_device_descriptors_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_DEVICE_DESCRIPTORS_MAX_SIZE 252

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_device_descriptors_encode(const mipc_base_device_descriptors_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_device_descriptors_decode(const uint8_t *data, size_t len,
                                                  mipc_base_device_descriptors_t *out,
                                                  mipc_decode_error_t *err);

/* ---- built_in_test (command): Built-in test */
#define MIPC_BASE_BUILT_IN_TEST_DESCRIPTOR 0x05

/** Built-in test. Run the device built-in test (BIT). The result is a 32-bit value; 0 means all tests passed.
 */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_base_built_in_test_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_BUILT_IN_TEST_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_built_in_test_encode(const mipc_base_built_in_test_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_built_in_test_decode(const uint8_t *data, size_t len, mipc_base_built_in_test_t *out,
                                             mipc_decode_error_t *err);

/* ---- built_in_test_result (response, 2 per-device variants): Built-in test result */
#define MIPC_BASE_BUILT_IN_TEST_RESULT_DESCRIPTOR 0x83

/** Built-in test result (gx5_45). Result of the commanded built-in test. The flags are device specific. */
typedef struct {
    mipc_gx5_bit_flags_t flags; /* BIT error flags; 0 means all tests passed. */
} mipc_base_built_in_test_result_gx5_45_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_BUILT_IN_TEST_RESULT_GX5_45_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_base_built_in_test_result_gx5_45_encode(const mipc_base_built_in_test_result_gx5_45_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_built_in_test_result_gx5_45_decode(const uint8_t *data, size_t len,
                                                           mipc_base_built_in_test_result_gx5_45_t *out,
                                                           mipc_decode_error_t *err);

/** Built-in test result (cv7_ins). Result of the commanded built-in test. The flags are device specific. */
typedef struct {
    mipc_cv7_bit_flags_t flags; /* BIT result bitfield; 0 means all tests passed. */
} mipc_base_built_in_test_result_cv7_ins_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_BUILT_IN_TEST_RESULT_CV7_INS_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_base_built_in_test_result_cv7_ins_encode(const mipc_base_built_in_test_result_cv7_ins_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_built_in_test_result_cv7_ins_decode(const uint8_t *data, size_t len,
                                                            mipc_base_built_in_test_result_cv7_ins_t *out,
                                                            mipc_decode_error_t *err);

/* ---- resume (command): Resume */
#define MIPC_BASE_RESUME_DESCRIPTOR 0x06

/** Resume. Place the device back into the mode it was in before Set to idle (default mode if none). */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_base_resume_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_RESUME_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_resume_encode(const mipc_base_resume_t *value, uint8_t *buf, size_t cap,
                                      size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_resume_decode(const uint8_t *data, size_t len, mipc_base_resume_t *out,
                                      mipc_decode_error_t *err);

/* ---- get_extended_descriptors (command): Get extended device descriptor sets */
#define MIPC_BASE_GET_EXTENDED_DESCRIPTORS_DESCRIPTOR 0x07

/** Get extended device descriptor sets. Get the descriptors supported in addition to those returned by Get
 * device descriptor sets. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_base_get_extended_descriptors_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_GET_EXTENDED_DESCRIPTORS_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_get_extended_descriptors_encode(const mipc_base_get_extended_descriptors_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_get_extended_descriptors_decode(const uint8_t *data, size_t len,
                                                        mipc_base_get_extended_descriptors_t *out,
                                                        mipc_decode_error_t *err);

/* ---- extended_descriptors (response): Extended device descriptors */
#define MIPC_BASE_EXTENDED_DESCRIPTORS_DESCRIPTOR 0x86

/** Extended device descriptors. Array of 16-bit descriptors (MSB set, LSB descriptor) running to the end of
 * the field. */
typedef struct {
    size_t descriptors_count;  /* number of elements in descriptors */
    uint16_t descriptors[126]; /* Supported extended descriptors, (set << 8) | descriptor. */
} mipc_base_extended_descriptors_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_EXTENDED_DESCRIPTORS_MAX_SIZE 252

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_extended_descriptors_encode(const mipc_base_extended_descriptors_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_extended_descriptors_decode(const uint8_t *data, size_t len,
                                                    mipc_base_extended_descriptors_t *out,
                                                    mipc_decode_error_t *err);

/* ---- continuous_bit (command): Continuous built-in test */
#define MIPC_BASE_CONTINUOUS_BIT_DESCRIPTOR 0x08

/** Continuous built-in test. Report the result of the continuous built-in test (non-disruptive). */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_base_continuous_bit_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_CONTINUOUS_BIT_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_continuous_bit_encode(const mipc_base_continuous_bit_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_continuous_bit_decode(const uint8_t *data, size_t len,
                                              mipc_base_continuous_bit_t *out, mipc_decode_error_t *err);

/* ---- continuous_bit_result (response): Continuous built-in test result */
#define MIPC_BASE_CONTINUOUS_BIT_RESULT_DESCRIPTOR 0x88

/** Continuous built-in test result. Device-specific 128-bit bitfield, least-significant byte first: bit 0 is
 * bit 0 of result[0], bit 127 is bit 7 of result[15]. */
typedef struct {
    mipc_cv7_continuous_bit_t result; /* Continuous BIT bit map (16 bytes, least-significant byte first), as
                                         in system data 0xA0,0x01. */
} mipc_base_continuous_bit_result_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_CONTINUOUS_BIT_RESULT_MAX_SIZE 16

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_continuous_bit_result_encode(const mipc_base_continuous_bit_result_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_continuous_bit_result_decode(const uint8_t *data, size_t len,
                                                     mipc_base_continuous_bit_result_t *out,
                                                     mipc_decode_error_t *err);

/* ---- comm_port_speed (command): Comm port speed */
#define MIPC_BASE_COMM_PORT_SPEED_DESCRIPTOR 0x09

/** Comm port speed. Controls the baud rate of a port. The device waits up to 250 ms for pending data before
 * applying the change; send it alone, with the device idle. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, save, load, default) */
    uint8_t port;  /* Port ID (0x01 main, 0x11-0x13 UART1-3, 0x21 USB); 0 means all ports for save, load and
                      default. */
    bool has_baud; /* baud is present */
    uint32_t baud; /* Port baud rate; must be a supported rate. [bit/s] */
} mipc_base_comm_port_speed_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_COMM_PORT_SPEED_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_comm_port_speed_encode(const mipc_base_comm_port_speed_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_comm_port_speed_decode(const uint8_t *data, size_t len,
                                               mipc_base_comm_port_speed_t *out, mipc_decode_error_t *err);

/* ---- comm_port_speed_response (response): Comm port speed (response) */
#define MIPC_BASE_COMM_PORT_SPEED_RESPONSE_DESCRIPTOR 0x89

/** Comm port speed (response). Current baud rate of a port. */
typedef struct {
    uint8_t port;  /* Port ID (0x01 main, 0x11-0x13 UART1-3, 0x21 USB). */
    uint32_t baud; /* Port baud rate. [bit/s] */
} mipc_base_comm_port_speed_response_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_COMM_PORT_SPEED_RESPONSE_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_comm_port_speed_response_encode(const mipc_base_comm_port_speed_response_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_comm_port_speed_response_decode(const uint8_t *data, size_t len,
                                                        mipc_base_comm_port_speed_response_t *out,
                                                        mipc_decode_error_t *err);

/* ---- gps_time_update (command, 2 per-device variants): GPS time update */
#define MIPC_BASE_GPS_TIME_UPDATE_DESCRIPTOR 0x72

/** GPS time update (gx5_45). Set the device's internal GPS time (week number or time of week). Combined with
 * a PPS input this synchronises the device's timestamps with an external GPS clock. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write, read, write_no_ack) */
    mipc_gps_time_field_t field_id;    /* Which time value: 1 GPS week number, 2 GPS seconds. */
    bool has_value;                    /* value is present */
    uint32_t value;                    /* New week number or seconds, depending on field_id. */
} mipc_base_gps_time_update_gx5_45_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_GPS_TIME_UPDATE_GX5_45_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_gps_time_update_gx5_45_encode(const mipc_base_gps_time_update_gx5_45_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_gps_time_update_gx5_45_decode(const uint8_t *data, size_t len,
                                                      mipc_base_gps_time_update_gx5_45_t *out,
                                                      mipc_decode_error_t *err);

/** GPS time update (cv7_ins). Set the device's internal GPS time (week number or time of week). Combined with
 * a PPS input this synchronises the device's timestamps with an external GPS clock. */
typedef struct {
    mipc_function_selector_t function; /* function selector (write) */
    mipc_gps_time_field_t field_id;    /* Determines how to interpret value. */
    uint32_t value;                    /* Week number or time of week, depending on field_id. */
} mipc_base_gps_time_update_cv7_ins_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_GPS_TIME_UPDATE_CV7_INS_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_gps_time_update_cv7_ins_encode(const mipc_base_gps_time_update_cv7_ins_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_gps_time_update_cv7_ins_decode(const uint8_t *data, size_t len,
                                                       mipc_base_gps_time_update_cv7_ins_t *out,
                                                       mipc_decode_error_t *err);

/* ---- gps_week (response): Current GPS week */
#define MIPC_BASE_GPS_WEEK_DESCRIPTOR 0x84

/** Current GPS week. Reply to GPS time update read with field selector 1 (week). */
typedef struct {
    uint32_t week; /* Current GPS week value. [weeks] */
} mipc_base_gps_week_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_GPS_WEEK_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_gps_week_encode(const mipc_base_gps_week_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_gps_week_decode(const uint8_t *data, size_t len, mipc_base_gps_week_t *out,
                                        mipc_decode_error_t *err);

/* ---- gps_seconds (response): Current GPS seconds */
#define MIPC_BASE_GPS_SECONDS_DESCRIPTOR 0x85

/** Current GPS seconds. Reply to GPS time update read with field selector 2 (seconds). */
typedef struct {
    uint32_t seconds; /* Current GPS seconds value. [s] */
} mipc_base_gps_seconds_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_GPS_SECONDS_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_gps_seconds_encode(const mipc_base_gps_seconds_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_gps_seconds_decode(const uint8_t *data, size_t len, mipc_base_gps_seconds_t *out,
                                           mipc_decode_error_t *err);

/* ---- device_reset (command): Device reset */
#define MIPC_BASE_DEVICE_RESET_DESCRIPTOR 0x7E

/** Device reset. Resets the device. The device ACKs and then immediately resets. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mipc_base_device_reset_t;

/* Largest encoded data (after the field header). */
#define MIPC_BASE_DEVICE_RESET_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_base_device_reset_encode(const mipc_base_device_reset_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_base_device_reset_decode(const uint8_t *data, size_t len, mipc_base_device_reset_t *out,
                                            mipc_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
