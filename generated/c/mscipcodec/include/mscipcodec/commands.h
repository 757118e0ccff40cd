/* The typed command API of Memsense MS-CIP (docs/conformance.md section 8): one function per command
 * and function it supports, typed parameters in, the typed reply out, over a link
 * (mscipcodec/link.h). Each returns the result's kind: MSCIPC_RESULT_ACK or MSCIPC_RESULT_SENT on
 * success; MSCIPC_RESULT_REFUSED when the link's device does not support the command or function
 * (nothing is sent; the check is the session's check_device), NACK, TIMEOUT, INVALID or TRANSPORT.
 * The link's last result (link->result) holds the code and the error text. *reply (may be NULL)
 * is written on ACK only. Generated: do not edit. */
#ifndef MSCIPC_COMMANDS_H
#define MSCIPC_COMMANDS_H

#include "mscipcodec/link.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Ping. */
mscipc_result_kind_t mscipc_base_ping(mscipc_link_t *link);
/** Get device messages. */
mscipc_result_kind_t mscipc_base_get_device_messages(mscipc_link_t *link,
                                                     mscipc_base_device_messages_t *reply);
/** Device reset. */
mscipc_result_kind_t mscipc_base_device_reset(mscipc_link_t *link);
/** Get device model. */
mscipc_result_kind_t mscipc_base_get_device_model(mscipc_link_t *link, mscipc_base_device_model_t *reply);
/** Get device serial number. */
mscipc_result_kind_t mscipc_base_get_device_sn(mscipc_link_t *link, mscipc_base_device_sn_t *reply);
/** Get device firmware. */
mscipc_result_kind_t mscipc_base_get_device_fw(mscipc_link_t *link, mscipc_base_device_fw_t *reply);
/** Get device calibration date. */
mscipc_result_kind_t mscipc_base_get_device_cal(mscipc_link_t *link, mscipc_base_device_cal_t *reply);
/** Correlate GPS time. */
mscipc_result_kind_t mscipc_base_correlate_gps_time(mscipc_link_t *link, uint16_t week, uint32_t seconds);
/** UART baud rate configure: function write. */
mscipc_result_kind_t mscipc_imu_config_uart_baud_rate_write(mscipc_link_t *link,
                                                            mscipc_baud_rate_t baud_rate);
/** UART baud rate configure: function read. */
mscipc_result_kind_t
mscipc_imu_config_uart_baud_rate_read(mscipc_link_t *link,
                                      mscipc_imu_config_uart_baud_rate_response_t *reply);
/** UART baud rate configure: function save. */
mscipc_result_kind_t mscipc_imu_config_uart_baud_rate_save(mscipc_link_t *link);
/** UART baud rate configure: function load. */
mscipc_result_kind_t mscipc_imu_config_uart_baud_rate_load(mscipc_link_t *link);
/** UART baud rate configure: function default. */
mscipc_result_kind_t mscipc_imu_config_uart_baud_rate_default(mscipc_link_t *link);
/** Configure filter: function write. */
mscipc_result_kind_t mscipc_imu_config_filter_write(mscipc_link_t *link, mscipc_filter_bandwidth_t bandwidth);
/** Configure filter: function read. */
mscipc_result_kind_t mscipc_imu_config_filter_read(mscipc_link_t *link,
                                                   mscipc_imu_config_filter_response_t *reply);
/** Configure filter: function save. */
mscipc_result_kind_t mscipc_imu_config_filter_save(mscipc_link_t *link);
/** Configure filter: function load. */
mscipc_result_kind_t mscipc_imu_config_filter_load(mscipc_link_t *link);
/** Configure filter: function default. */
mscipc_result_kind_t mscipc_imu_config_filter_default(mscipc_link_t *link);
/** IMU sample rate configure: function write. */
mscipc_result_kind_t mscipc_imu_config_sample_rate_write(mscipc_link_t *link, uint16_t decimation);
/** IMU sample rate configure: function read. */
mscipc_result_kind_t mscipc_imu_config_sample_rate_read(mscipc_link_t *link,
                                                        mscipc_imu_config_sample_rate_response_t *reply);
/** IMU sample rate configure: function save. */
mscipc_result_kind_t mscipc_imu_config_sample_rate_save(mscipc_link_t *link);
/** IMU sample rate configure: function load. */
mscipc_result_kind_t mscipc_imu_config_sample_rate_load(mscipc_link_t *link);
/** IMU sample rate configure: function default. */
mscipc_result_kind_t mscipc_imu_config_sample_rate_default(mscipc_link_t *link);
/** Select sensors (Rev A): function write. */
mscipc_result_kind_t mscipc_imu_config_select_sensors_write(mscipc_link_t *link, uint8_t reserved,
                                                            const mscipc_sensor_code_t *sensors,
                                                            size_t sensors_count);
/** Select sensors (Rev A): function read. */
mscipc_result_kind_t
mscipc_imu_config_select_sensors_read(mscipc_link_t *link,
                                      mscipc_imu_config_select_sensors_response_t *reply);
/** Select sensors (Rev A): function save. */
mscipc_result_kind_t mscipc_imu_config_select_sensors_save(mscipc_link_t *link);
/** Select sensors (Rev A): function load. */
mscipc_result_kind_t mscipc_imu_config_select_sensors_load(mscipc_link_t *link);
/** Select sensors (Rev A): function default. */
mscipc_result_kind_t mscipc_imu_config_select_sensors_default(mscipc_link_t *link);
/** Get IMU internal sample rate. */
mscipc_result_kind_t
mscipc_imu_config_get_internal_sample_rate(mscipc_link_t *link,
                                           mscipc_imu_config_internal_sample_rate_t *reply);
/** Config accel range: function write. */
mscipc_result_kind_t mscipc_imu_config_accel_range_write(mscipc_link_t *link, mscipc_accel_range_t range);
/** Config accel range: function read. */
mscipc_result_kind_t mscipc_imu_config_accel_range_read(mscipc_link_t *link,
                                                        mscipc_imu_config_accel_range_response_t *reply);
/** Config accel range: function save. */
mscipc_result_kind_t mscipc_imu_config_accel_range_save(mscipc_link_t *link);
/** Config accel range: function load. */
mscipc_result_kind_t mscipc_imu_config_accel_range_load(mscipc_link_t *link);
/** Config accel range: function default. */
mscipc_result_kind_t mscipc_imu_config_accel_range_default(mscipc_link_t *link);
/** Configure gyro range: function write. */
mscipc_result_kind_t mscipc_imu_config_gyro_range_write(mscipc_link_t *link, mscipc_gyro_range_t range);
/** Configure gyro range: function read. */
mscipc_result_kind_t mscipc_imu_config_gyro_range_read(mscipc_link_t *link,
                                                       mscipc_imu_config_gyro_range_response_t *reply);
/** Configure gyro range: function save. */
mscipc_result_kind_t mscipc_imu_config_gyro_range_save(mscipc_link_t *link);
/** Configure gyro range: function load. */
mscipc_result_kind_t mscipc_imu_config_gyro_range_load(mscipc_link_t *link);
/** Configure gyro range: function default. */
mscipc_result_kind_t mscipc_imu_config_gyro_range_default(mscipc_link_t *link);
/** Configure all: function save. */
mscipc_result_kind_t mscipc_imu_config_config_all_save(mscipc_link_t *link);
/** Configure all: function load. */
mscipc_result_kind_t mscipc_imu_config_config_all_load(mscipc_link_t *link);
/** Configure all: function default. */
mscipc_result_kind_t mscipc_imu_config_config_all_default(mscipc_link_t *link);
/** Data on/off: function write. */
mscipc_result_kind_t mscipc_imu_config_data_on_off_write(mscipc_link_t *link, mscipc_on_off_t control);
/** Data on/off: function read. */
mscipc_result_kind_t mscipc_imu_config_data_on_off_read(mscipc_link_t *link,
                                                        mscipc_imu_config_data_on_off_response_t *reply);
/** Data on/off: function save. */
mscipc_result_kind_t mscipc_imu_config_data_on_off_save(mscipc_link_t *link);
/** Data on/off: function load. */
mscipc_result_kind_t mscipc_imu_config_data_on_off_load(mscipc_link_t *link);
/** Data on/off: function default. */
mscipc_result_kind_t mscipc_imu_config_data_on_off_default(mscipc_link_t *link);
/** XTRIG on/off: function write. */
mscipc_result_kind_t mscipc_imu_config_xtrig_on_off_write(mscipc_link_t *link, mscipc_on_off_t control);
/** XTRIG on/off: function read. */
mscipc_result_kind_t mscipc_imu_config_xtrig_on_off_read(mscipc_link_t *link,
                                                         mscipc_imu_config_xtrig_on_off_response_t *reply);
/** XTRIG on/off: function save. */
mscipc_result_kind_t mscipc_imu_config_xtrig_on_off_save(mscipc_link_t *link);
/** XTRIG on/off: function load. */
mscipc_result_kind_t mscipc_imu_config_xtrig_on_off_load(mscipc_link_t *link);
/** XTRIG on/off: function default. */
mscipc_result_kind_t mscipc_imu_config_xtrig_on_off_default(mscipc_link_t *link);
/** Select sensors (Rev B): function write. */
mscipc_result_kind_t mscipc_imu_config_select_sensors_rev_b_write(mscipc_link_t *link,
                                                                  const mscipc_sensor_code_t *sensors,
                                                                  size_t sensors_count);
/** Select sensors (Rev B): function read. */
mscipc_result_kind_t
mscipc_imu_config_select_sensors_rev_b_read(mscipc_link_t *link,
                                            mscipc_imu_config_select_sensors_rev_b_response_t *reply);
/** Select sensors (Rev B): function save. */
mscipc_result_kind_t mscipc_imu_config_select_sensors_rev_b_save(mscipc_link_t *link);
/** Select sensors (Rev B): function load. */
mscipc_result_kind_t mscipc_imu_config_select_sensors_rev_b_load(mscipc_link_t *link);
/** Select sensors (Rev B): function default. */
mscipc_result_kind_t mscipc_imu_config_select_sensors_rev_b_default(mscipc_link_t *link);
/** Config aux accel range: function write. */
mscipc_result_kind_t mscipc_imu_config_aux_accel_range_write(mscipc_link_t *link, mscipc_accel_range_t range);
/** Config aux accel range: function read. */
mscipc_result_kind_t
mscipc_imu_config_aux_accel_range_read(mscipc_link_t *link,
                                       mscipc_imu_config_aux_accel_range_response_t *reply);
/** Config aux accel range: function save. */
mscipc_result_kind_t mscipc_imu_config_aux_accel_range_save(mscipc_link_t *link);
/** Config aux accel range: function load. */
mscipc_result_kind_t mscipc_imu_config_aux_accel_range_load(mscipc_link_t *link);
/** Config aux accel range: function default. */
mscipc_result_kind_t mscipc_imu_config_aux_accel_range_default(mscipc_link_t *link);

#ifdef __cplusplus
}
#endif

#endif
