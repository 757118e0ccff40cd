/* IMU Configuration Messages (descriptor set 0x02): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MSCIPC_SETS_IMU_CONFIG_H
#define MSCIPC_SETS_IMU_CONFIG_H

#include "mscipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MSCIPC_IMU_CONFIG_SET 0x02

/* ---- uart_baud_rate (command): UART baud rate configure */
#define MSCIPC_IMU_CONFIG_UART_BAUD_RATE_DESCRIPTOR 0x01

/** UART baud rate configure. Set, read, save, load or reset the baud rate. Messages after the reply use the
 * new rate; saving may delay the reply while the setting is written to flash. */
typedef struct {
    mscipc_function_code_t function; /* function selector (write, read, save, load, default) */
    bool has_baud_rate;              /* baud_rate is present */
    mscipc_baud_rate_t baud_rate;    /* New baud rate. [baud] */
} mscipc_imu_config_uart_baud_rate_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_UART_BAUD_RATE_MAX_SIZE 5

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_uart_baud_rate_encode(const mscipc_imu_config_uart_baud_rate_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_uart_baud_rate_decode(const uint8_t *data, size_t len,
                                                        mscipc_imu_config_uart_baud_rate_t *out,
                                                        mscipc_decode_error_t *err);

/* ---- uart_baud_rate_response (response): UART baud rate (read reply, inferred) */
#define MSCIPC_IMU_CONFIG_UART_BAUD_RATE_RESPONSE_DESCRIPTOR 0x81

/** UART baud rate (read reply, inferred). Current baud rate, in reply to "Request current settings". */
typedef struct {
    mscipc_baud_rate_t baud_rate; /* Current baud rate. [baud] */
} mscipc_imu_config_uart_baud_rate_response_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_UART_BAUD_RATE_RESPONSE_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_uart_baud_rate_response_encode(const mscipc_imu_config_uart_baud_rate_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t
mscipc_imu_config_uart_baud_rate_response_decode(const uint8_t *data, size_t len,
                                                 mscipc_imu_config_uart_baud_rate_response_t *out,
                                                 mscipc_decode_error_t *err);

/* ---- filter (command): Configure filter */
#define MSCIPC_IMU_CONFIG_FILTER_DESCRIPTOR 0x03

/** Configure filter. Set, read, save, load or reset the internal digital filter. */
typedef struct {
    mscipc_function_code_t function;     /* function selector (write, read, save, load, default) */
    bool has_bandwidth;                  /* bandwidth is present */
    mscipc_filter_bandwidth_t bandwidth; /* Filter bandwidth control code. */
} mscipc_imu_config_filter_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_FILTER_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_filter_encode(const mscipc_imu_config_filter_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_filter_decode(const uint8_t *data, size_t len,
                                                mscipc_imu_config_filter_t *out, mscipc_decode_error_t *err);

/* ---- filter_response (response): Filter (read reply, inferred) */
#define MSCIPC_IMU_CONFIG_FILTER_RESPONSE_DESCRIPTOR 0x83

/** Filter (read reply, inferred). Current filter bandwidth control code. */
typedef struct {
    mscipc_filter_bandwidth_t bandwidth; /* Filter bandwidth control code. */
} mscipc_imu_config_filter_response_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_FILTER_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_filter_response_encode(const mscipc_imu_config_filter_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_filter_response_decode(const uint8_t *data, size_t len,
                                                         mscipc_imu_config_filter_response_t *out,
                                                         mscipc_decode_error_t *err);

/* ---- sample_rate (command): IMU sample rate configure */
#define MSCIPC_IMU_CONFIG_SAMPLE_RATE_DESCRIPTOR 0x04

/** IMU sample rate configure. Set, read, save, load or reset the output decimation: the output rate is the
 * internal sample rate (0x0206) divided by the decimation (800 Hz / 8 = 100 Hz). */
typedef struct {
    mscipc_function_code_t function; /* function selector (write, read, save, load, default) */
    bool has_decimation;             /* decimation is present */
    uint16_t decimation;             /* Divider of the internal sample rate. */
} mscipc_imu_config_sample_rate_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_SAMPLE_RATE_MAX_SIZE 3

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_sample_rate_encode(const mscipc_imu_config_sample_rate_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_sample_rate_decode(const uint8_t *data, size_t len,
                                                     mscipc_imu_config_sample_rate_t *out,
                                                     mscipc_decode_error_t *err);

/* ---- sample_rate_response (response): IMU sample rate (read reply, inferred) */
#define MSCIPC_IMU_CONFIG_SAMPLE_RATE_RESPONSE_DESCRIPTOR 0x84

/** IMU sample rate (read reply, inferred). Current output decimation. */
typedef struct {
    uint16_t decimation; /* Divider of the internal sample rate. */
} mscipc_imu_config_sample_rate_response_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_SAMPLE_RATE_RESPONSE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_sample_rate_response_encode(const mscipc_imu_config_sample_rate_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_sample_rate_response_decode(const uint8_t *data, size_t len,
                                                              mscipc_imu_config_sample_rate_response_t *out,
                                                              mscipc_decode_error_t *err);

/* ---- select_sensors (command): Select sensors (Rev A) */
#define MSCIPC_IMU_CONFIG_SELECT_SENSORS_DESCRIPTOR 0x05

/** Select sensors (Rev A). Choose the measurements the IMU data message (0xA2) carries, by their data codes.
 * Its size byte is one less than its data on the wire, which the device expects (Select Sensors errata);
 * Select Sensors Rev B (0x020C) is the corrected message. */
typedef struct {
    mscipc_function_code_t function;   /* function selector (write, read, save, load, default) */
    bool has_reserved;                 /* reserved is present */
    uint8_t reserved;                  /* Reserved for future use (0x00). */
    bool has_sensors;                  /* sensors is present */
    size_t sensors_count;              /* number of elements in sensors */
    mscipc_sensor_code_t sensors[251]; /* Measurements to output, in order. */
} mscipc_imu_config_select_sensors_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_SELECT_SENSORS_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_select_sensors_encode(const mscipc_imu_config_select_sensors_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_select_sensors_decode(const uint8_t *data, size_t len,
                                                        mscipc_imu_config_select_sensors_t *out,
                                                        mscipc_decode_error_t *err);

/* ---- select_sensors_response (response): Select sensors (read reply, inferred) */
#define MSCIPC_IMU_CONFIG_SELECT_SENSORS_RESPONSE_DESCRIPTOR 0x85

/** Select sensors (read reply, inferred). The selected measurements. */
typedef struct {
    size_t sensors_count;              /* number of elements in sensors */
    mscipc_sensor_code_t sensors[253]; /* Selected measurements. */
} mscipc_imu_config_select_sensors_response_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_SELECT_SENSORS_RESPONSE_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_select_sensors_response_encode(const mscipc_imu_config_select_sensors_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t
mscipc_imu_config_select_sensors_response_decode(const uint8_t *data, size_t len,
                                                 mscipc_imu_config_select_sensors_response_t *out,
                                                 mscipc_decode_error_t *err);

/* ---- get_internal_sample_rate (command): Get IMU internal sample rate */
#define MSCIPC_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE_DESCRIPTOR 0x06

/** Get IMU internal sample rate. Ask for the internal sample rate that the decimation divides. */
typedef struct {
    uint8_t unused_; /* no parameters */
} mscipc_imu_config_get_internal_sample_rate_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE_MAX_SIZE 0

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_get_internal_sample_rate_encode(const mscipc_imu_config_get_internal_sample_rate_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t
mscipc_imu_config_get_internal_sample_rate_decode(const uint8_t *data, size_t len,
                                                  mscipc_imu_config_get_internal_sample_rate_t *out,
                                                  mscipc_decode_error_t *err);

/* ---- internal_sample_rate (response): IMU internal sample rate */
#define MSCIPC_IMU_CONFIG_INTERNAL_SAMPLE_RATE_DESCRIPTOR 0x86

/** IMU internal sample rate. The internal sample rate in hertz. */
typedef struct {
    uint16_t rate; /* Internal sample rate (e.g. 800). [Hz] */
} mscipc_imu_config_internal_sample_rate_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_INTERNAL_SAMPLE_RATE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_internal_sample_rate_encode(const mscipc_imu_config_internal_sample_rate_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_internal_sample_rate_decode(const uint8_t *data, size_t len,
                                                              mscipc_imu_config_internal_sample_rate_t *out,
                                                              mscipc_decode_error_t *err);

/* ---- accel_range (command): Config accel range */
#define MSCIPC_IMU_CONFIG_ACCEL_RANGE_DESCRIPTOR 0x07

/** Config accel range. Set, read, save, load or reset the accelerometer dynamic range. */
typedef struct {
    mscipc_function_code_t function; /* function selector (write, read, save, load, default) */
    bool has_range;                  /* range is present */
    mscipc_accel_range_t range;      /* Accelerometer range code. */
} mscipc_imu_config_accel_range_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_ACCEL_RANGE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_accel_range_encode(const mscipc_imu_config_accel_range_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_accel_range_decode(const uint8_t *data, size_t len,
                                                     mscipc_imu_config_accel_range_t *out,
                                                     mscipc_decode_error_t *err);

/* ---- accel_range_response (response): Accel range (read reply, inferred) */
#define MSCIPC_IMU_CONFIG_ACCEL_RANGE_RESPONSE_DESCRIPTOR 0x87

/** Accel range (read reply, inferred). Current accelerometer range code. */
typedef struct {
    mscipc_accel_range_t range; /* Accelerometer range code. */
} mscipc_imu_config_accel_range_response_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_ACCEL_RANGE_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_accel_range_response_encode(const mscipc_imu_config_accel_range_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_accel_range_response_decode(const uint8_t *data, size_t len,
                                                              mscipc_imu_config_accel_range_response_t *out,
                                                              mscipc_decode_error_t *err);

/* ---- gyro_range (command): Configure gyro range */
#define MSCIPC_IMU_CONFIG_GYRO_RANGE_DESCRIPTOR 0x08

/** Configure gyro range. Set, read, save, load or reset the gyroscope dynamic range. */
typedef struct {
    mscipc_function_code_t function; /* function selector (write, read, save, load, default) */
    bool has_range;                  /* range is present */
    mscipc_gyro_range_t range;       /* Gyroscope range code. */
} mscipc_imu_config_gyro_range_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_GYRO_RANGE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_gyro_range_encode(const mscipc_imu_config_gyro_range_t *value, uint8_t *buf,
                                                    size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_gyro_range_decode(const uint8_t *data, size_t len,
                                                    mscipc_imu_config_gyro_range_t *out,
                                                    mscipc_decode_error_t *err);

/* ---- gyro_range_response (response): Gyro range (read reply, inferred) */
#define MSCIPC_IMU_CONFIG_GYRO_RANGE_RESPONSE_DESCRIPTOR 0x88

/** Gyro range (read reply, inferred). Current gyroscope range code. */
typedef struct {
    mscipc_gyro_range_t range; /* Gyroscope range code. */
} mscipc_imu_config_gyro_range_response_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_GYRO_RANGE_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_gyro_range_response_encode(const mscipc_imu_config_gyro_range_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_gyro_range_response_decode(const uint8_t *data, size_t len,
                                                             mscipc_imu_config_gyro_range_response_t *out,
                                                             mscipc_decode_error_t *err);

/* ---- config_all (command): Configure all */
#define MSCIPC_IMU_CONFIG_CONFIG_ALL_DESCRIPTOR 0x09

/** Configure all. Save, load or reset to factory defaults every configurable setting. */
typedef struct {
    mscipc_function_code_t function; /* function selector (save, load, default) */
} mscipc_imu_config_config_all_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_CONFIG_ALL_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_config_all_encode(const mscipc_imu_config_config_all_t *value, uint8_t *buf,
                                                    size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_config_all_decode(const uint8_t *data, size_t len,
                                                    mscipc_imu_config_config_all_t *out,
                                                    mscipc_decode_error_t *err);

/* ---- data_on_off (command): Data on/off */
#define MSCIPC_IMU_CONFIG_DATA_ON_OFF_DESCRIPTOR 0x0A

/** Data on/off. Enable or disable the data output. */
typedef struct {
    mscipc_function_code_t function; /* function selector (write, read, save, load, default) */
    bool has_control;                /* control is present */
    mscipc_on_off_t control;         /* Data on or off. */
} mscipc_imu_config_data_on_off_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_DATA_ON_OFF_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_data_on_off_encode(const mscipc_imu_config_data_on_off_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_data_on_off_decode(const uint8_t *data, size_t len,
                                                     mscipc_imu_config_data_on_off_t *out,
                                                     mscipc_decode_error_t *err);

/* ---- data_on_off_response (response): Data on/off (read reply, inferred) */
#define MSCIPC_IMU_CONFIG_DATA_ON_OFF_RESPONSE_DESCRIPTOR 0x8A

/** Data on/off (read reply, inferred). Whether data output is on. */
typedef struct {
    mscipc_on_off_t control; /* Data on or off. */
} mscipc_imu_config_data_on_off_response_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_DATA_ON_OFF_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_data_on_off_response_encode(const mscipc_imu_config_data_on_off_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_data_on_off_response_decode(const uint8_t *data, size_t len,
                                                              mscipc_imu_config_data_on_off_response_t *out,
                                                              mscipc_decode_error_t *err);

/* ---- xtrig_on_off (command): XTRIG on/off */
#define MSCIPC_IMU_CONFIG_XTRIG_ON_OFF_DESCRIPTOR 0x0B

/** XTRIG on/off. Enable or disable the external trigger input. */
typedef struct {
    mscipc_function_code_t function; /* function selector (write, read, save, load, default) */
    bool has_control;                /* control is present */
    mscipc_on_off_t control;         /* External trigger on or off. */
} mscipc_imu_config_xtrig_on_off_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_XTRIG_ON_OFF_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_xtrig_on_off_encode(const mscipc_imu_config_xtrig_on_off_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_xtrig_on_off_decode(const uint8_t *data, size_t len,
                                                      mscipc_imu_config_xtrig_on_off_t *out,
                                                      mscipc_decode_error_t *err);

/* ---- xtrig_on_off_response (response): XTRIG on/off (read reply, inferred) */
#define MSCIPC_IMU_CONFIG_XTRIG_ON_OFF_RESPONSE_DESCRIPTOR 0x8B

/** XTRIG on/off (read reply, inferred). Whether the external trigger input is on. */
typedef struct {
    mscipc_on_off_t control; /* External trigger on or off. */
} mscipc_imu_config_xtrig_on_off_response_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_XTRIG_ON_OFF_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_xtrig_on_off_response_encode(const mscipc_imu_config_xtrig_on_off_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_xtrig_on_off_response_decode(const uint8_t *data, size_t len,
                                                               mscipc_imu_config_xtrig_on_off_response_t *out,
                                                               mscipc_decode_error_t *err);

/* ---- select_sensors_rev_b (command): Select sensors (Rev B) */
#define MSCIPC_IMU_CONFIG_SELECT_SENSORS_REV_B_DESCRIPTOR 0x0C

/** Select sensors (Rev B). Choose the measurements the IMU data message (0xA2) carries, by their data codes;
 * the corrected Select Sensors (size byte counts every data byte, no reserved byte). */
typedef struct {
    mscipc_function_code_t function;   /* function selector (write, read, save, load, default) */
    bool has_sensors;                  /* sensors is present */
    size_t sensors_count;              /* number of elements in sensors */
    mscipc_sensor_code_t sensors[252]; /* Measurements to output, in order. */
} mscipc_imu_config_select_sensors_rev_b_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_SELECT_SENSORS_REV_B_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_select_sensors_rev_b_encode(const mscipc_imu_config_select_sensors_rev_b_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_select_sensors_rev_b_decode(const uint8_t *data, size_t len,
                                                              mscipc_imu_config_select_sensors_rev_b_t *out,
                                                              mscipc_decode_error_t *err);

/* ---- select_sensors_rev_b_response (response): Select sensors Rev B (read reply, inferred) */
#define MSCIPC_IMU_CONFIG_SELECT_SENSORS_REV_B_RESPONSE_DESCRIPTOR 0x8C

/** Select sensors Rev B (read reply, inferred). The selected measurements. */
typedef struct {
    size_t sensors_count;              /* number of elements in sensors */
    mscipc_sensor_code_t sensors[253]; /* Selected measurements. */
} mscipc_imu_config_select_sensors_rev_b_response_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_SELECT_SENSORS_REV_B_RESPONSE_MAX_SIZE 253

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_select_sensors_rev_b_response_encode(
    const mscipc_imu_config_select_sensors_rev_b_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t
mscipc_imu_config_select_sensors_rev_b_response_decode(const uint8_t *data, size_t len,
                                                       mscipc_imu_config_select_sensors_rev_b_response_t *out,
                                                       mscipc_decode_error_t *err);

/* ---- aux_accel_range (command): Config aux accel range */
#define MSCIPC_IMU_CONFIG_AUX_ACCEL_RANGE_DESCRIPTOR 0x0D

/** Config aux accel range. Set, read, save, load or reset the auxiliary accelerometer dynamic range. */
typedef struct {
    mscipc_function_code_t function; /* function selector (write, read, save, load, default) */
    bool has_range;                  /* range is present */
    mscipc_accel_range_t range;      /* Auxiliary accelerometer range code. */
} mscipc_imu_config_aux_accel_range_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_AUX_ACCEL_RANGE_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_config_aux_accel_range_encode(const mscipc_imu_config_aux_accel_range_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_config_aux_accel_range_decode(const uint8_t *data, size_t len,
                                                         mscipc_imu_config_aux_accel_range_t *out,
                                                         mscipc_decode_error_t *err);

/* ---- aux_accel_range_response (response): Aux accel range (read reply, inferred) */
#define MSCIPC_IMU_CONFIG_AUX_ACCEL_RANGE_RESPONSE_DESCRIPTOR 0x8D

/** Aux accel range (read reply, inferred). Current auxiliary accelerometer range code. */
typedef struct {
    mscipc_accel_range_t range; /* Auxiliary accelerometer range code. */
} mscipc_imu_config_aux_accel_range_response_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_CONFIG_AUX_ACCEL_RANGE_RESPONSE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t
mscipc_imu_config_aux_accel_range_response_encode(const mscipc_imu_config_aux_accel_range_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t
mscipc_imu_config_aux_accel_range_response_decode(const uint8_t *data, size_t len,
                                                  mscipc_imu_config_aux_accel_range_response_t *out,
                                                  mscipc_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
