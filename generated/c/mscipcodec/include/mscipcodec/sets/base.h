/* Base Messages (descriptor set 0x01): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MSCIPC_SETS_BASE_H
#define MSCIPC_SETS_BASE_H

#include "mscipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MSCIPC_BASE_SET 0x01

/* ---- ping (command): Ping */
#define MSCIPC_BASE_PING_DESCRIPTOR 0x02

/** Ping. Check that the device is responsive; it answers with the ack. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mscipc_base_ping_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_PING_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_ping_encode(const mscipc_base_ping_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_ping_decode(const uint8_t *data, size_t len, mscipc_base_ping_t *out,
                                        mscipc_decode_error_t *err);

/* ---- get_device_messages (command): Get device messages */
#define MSCIPC_BASE_GET_DEVICE_MESSAGES_DESCRIPTOR 0x03

/** Get device messages. Ask which messages the device supports. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mscipc_base_get_device_messages_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_GET_DEVICE_MESSAGES_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_get_device_messages_encode(const mscipc_base_get_device_messages_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_get_device_messages_decode(const uint8_t *data, size_t len,
                                                       mscipc_base_get_device_messages_t *out,
                                                       mscipc_decode_error_t *err);

/* ---- device_messages (response): Device messages */
#define MSCIPC_BASE_DEVICE_MESSAGES_DESCRIPTOR 0x83

/** Device messages. The supported messages, two bytes each (message type, then message code). */
typedef struct {
    size_t messages_count;             /* number of elements in messages */
    mscipc_message_id_t messages[126]; /* Supported messages ("2 * number of commands in bytes"). */
} mscipc_base_device_messages_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_DEVICE_MESSAGES_MAX_SIZE 252

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_device_messages_encode(const mscipc_base_device_messages_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_device_messages_decode(const uint8_t *data, size_t len,
                                                   mscipc_base_device_messages_t *out,
                                                   mscipc_decode_error_t *err);

/* ---- device_reset (command): Device reset */
#define MSCIPC_BASE_DEVICE_RESET_DESCRIPTOR 0x04

/** Device reset. Reset the device; the reset happens right after the ack is sent. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mscipc_base_device_reset_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_DEVICE_RESET_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_device_reset_encode(const mscipc_base_device_reset_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_device_reset_decode(const uint8_t *data, size_t len,
                                                mscipc_base_device_reset_t *out, mscipc_decode_error_t *err);

/* ---- get_device_model (command): Get device model */
#define MSCIPC_BASE_GET_DEVICE_MODEL_DESCRIPTOR 0x05

/** Get device model. Ask for the device model number. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mscipc_base_get_device_model_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_GET_DEVICE_MODEL_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_get_device_model_encode(const mscipc_base_get_device_model_t *value, uint8_t *buf,
                                                    size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_get_device_model_decode(const uint8_t *data, size_t len,
                                                    mscipc_base_get_device_model_t *out,
                                                    mscipc_decode_error_t *err);

/* ---- device_model (response): Device model */
#define MSCIPC_BASE_DEVICE_MODEL_DESCRIPTOR 0x85

/** Device model. The model number, 16 characters, right-justified and padded with spaces. */
typedef struct {
    char model[16]; /* Device model, e.g. " MS_IMU3020". */
} mscipc_base_device_model_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_DEVICE_MODEL_MAX_SIZE 16

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_device_model_encode(const mscipc_base_device_model_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_device_model_decode(const uint8_t *data, size_t len,
                                                mscipc_base_device_model_t *out, mscipc_decode_error_t *err);

/* ---- get_device_sn (command): Get device serial number */
#define MSCIPC_BASE_GET_DEVICE_SN_DESCRIPTOR 0x06

/** Get device serial number. Ask for the device serial number. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mscipc_base_get_device_sn_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_GET_DEVICE_SN_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_get_device_sn_encode(const mscipc_base_get_device_sn_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_get_device_sn_decode(const uint8_t *data, size_t len,
                                                 mscipc_base_get_device_sn_t *out,
                                                 mscipc_decode_error_t *err);

/* ---- device_sn (response): Device serial number */
#define MSCIPC_BASE_DEVICE_SN_DESCRIPTOR 0x86

/** Device serial number. The serial number, 16 characters, right-justified and padded with spaces. */
typedef struct {
    char serial_number[16]; /* Serial number, e.g. " 20268". */
} mscipc_base_device_sn_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_DEVICE_SN_MAX_SIZE 16

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_device_sn_encode(const mscipc_base_device_sn_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_device_sn_decode(const uint8_t *data, size_t len, mscipc_base_device_sn_t *out,
                                             mscipc_decode_error_t *err);

/* ---- get_device_fw (command): Get device firmware */
#define MSCIPC_BASE_GET_DEVICE_FW_DESCRIPTOR 0x07

/** Get device firmware. Ask for the firmware revision. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mscipc_base_get_device_fw_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_GET_DEVICE_FW_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_get_device_fw_encode(const mscipc_base_get_device_fw_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_get_device_fw_decode(const uint8_t *data, size_t len,
                                                 mscipc_base_get_device_fw_t *out,
                                                 mscipc_decode_error_t *err);

/* ---- device_fw (response): Device firmware revision */
#define MSCIPC_BASE_DEVICE_FW_DESCRIPTOR 0x87

/** Device firmware revision. The firmware revision, 16 characters, right-justified and padded with spaces. */
typedef struct {
    char firmware[16]; /* Firmware revision, e.g. " R_1_2_3". */
} mscipc_base_device_fw_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_DEVICE_FW_MAX_SIZE 16

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_device_fw_encode(const mscipc_base_device_fw_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_device_fw_decode(const uint8_t *data, size_t len, mscipc_base_device_fw_t *out,
                                             mscipc_decode_error_t *err);

/* ---- get_device_cal (command): Get device calibration date */
#define MSCIPC_BASE_GET_DEVICE_CAL_DESCRIPTOR 0x08

/** Get device calibration date. Ask for the date the device was calibrated. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mscipc_base_get_device_cal_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_GET_DEVICE_CAL_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_get_device_cal_encode(const mscipc_base_get_device_cal_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_get_device_cal_decode(const uint8_t *data, size_t len,
                                                  mscipc_base_get_device_cal_t *out,
                                                  mscipc_decode_error_t *err);

/* ---- device_cal (response): Device calibration date */
#define MSCIPC_BASE_DEVICE_CAL_DESCRIPTOR 0x88

/** Device calibration date. The calibration date as MM-DD-YYYY, 16 characters, right-justified and padded
 * with spaces. */
typedef struct {
    char date[16]; /* Calibration date MM-DD-YYYY, e.g. " 05-08-2015". */
} mscipc_base_device_cal_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_DEVICE_CAL_MAX_SIZE 16

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_device_cal_encode(const mscipc_base_device_cal_t *value, uint8_t *buf, size_t cap,
                                              size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_device_cal_decode(const uint8_t *data, size_t len, mscipc_base_device_cal_t *out,
                                              mscipc_decode_error_t *err);

/* ---- correlate_gps_time (command): Correlate GPS time */
#define MSCIPC_BASE_CORRELATE_GPS_TIME_DESCRIPTOR 0x09

/** Correlate GPS time. Set the GPS week and time of week that the next 1-PPS pulse on the interface connector
 * marks; send it right after the pulse. Any processor time in GPS format may stand in. */
typedef struct {
    uint16_t week;    /* GPS week number. [weeks] */
    uint32_t seconds; /* GPS time of week in whole seconds. [s] */
} mscipc_base_correlate_gps_time_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_BASE_CORRELATE_GPS_TIME_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_base_correlate_gps_time_encode(const mscipc_base_correlate_gps_time_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_base_correlate_gps_time_decode(const uint8_t *data, size_t len,
                                                      mscipc_base_correlate_gps_time_t *out,
                                                      mscipc_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
