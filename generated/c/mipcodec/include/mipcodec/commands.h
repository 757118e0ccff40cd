/* The typed command API of MicroStrain MIP (docs/conformance.md section 8): one function per command
 * and function it supports, typed parameters in, the typed reply out, over a link
 * (mipcodec/link.h). Each returns the result's kind: MIPC_RESULT_ACK or MIPC_RESULT_SENT on
 * success; MIPC_RESULT_REFUSED when the link's device does not support the command or function
 * (nothing is sent; the check is the session's check_device), NACK, TIMEOUT, INVALID or TRANSPORT.
 * The link's last result (link->result) holds the code and the error text. *reply (may be NULL)
 * is written on ACK only. Generated: do not edit. */
#ifndef MIPC_COMMANDS_H
#define MIPC_COMMANDS_H

#include "mipcodec/link.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Ping. */
mipc_result_kind_t mipc_base_ping(mipc_link_t *link);
/** Set to idle. */
mipc_result_kind_t mipc_base_set_to_idle(mipc_link_t *link);
/** Get device information. */
mipc_result_kind_t mipc_base_get_device_info(mipc_link_t *link, mipc_base_device_info_t *reply);
/** Get device descriptor sets. */
mipc_result_kind_t mipc_base_get_device_descriptors(mipc_link_t *link, mipc_base_device_descriptors_t *reply);
/** Built-in test. */
mipc_result_kind_t mipc_base_built_in_test(mipc_link_t *link, mipc_field_value_t *reply);
/** Resume. */
mipc_result_kind_t mipc_base_resume(mipc_link_t *link);
/** Get extended device descriptor sets. */
mipc_result_kind_t mipc_base_get_extended_descriptors(mipc_link_t *link,
                                                      mipc_base_extended_descriptors_t *reply);
/** Continuous built-in test. */
mipc_result_kind_t mipc_base_continuous_bit(mipc_link_t *link, mipc_base_continuous_bit_result_t *reply);
/** Comm port speed: function write. */
mipc_result_kind_t mipc_base_comm_port_speed_write(mipc_link_t *link, uint8_t port, uint32_t baud);
/** Comm port speed: function read. */
mipc_result_kind_t mipc_base_comm_port_speed_read(mipc_link_t *link, uint8_t port,
                                                  mipc_base_comm_port_speed_response_t *reply);
/** Comm port speed: function save. */
mipc_result_kind_t mipc_base_comm_port_speed_save(mipc_link_t *link, uint8_t port);
/** Comm port speed: function load. */
mipc_result_kind_t mipc_base_comm_port_speed_load(mipc_link_t *link, uint8_t port);
/** Comm port speed: function default. */
mipc_result_kind_t mipc_base_comm_port_speed_default(mipc_link_t *link, uint8_t port);
/** GPS time update: function write. */
mipc_result_kind_t mipc_base_gps_time_update_write(mipc_link_t *link, mipc_gps_time_field_t field_id,
                                                   uint32_t value);
/** GPS time update: function read. */
mipc_result_kind_t mipc_base_gps_time_update_read(mipc_link_t *link, mipc_gps_time_field_t field_id,
                                                  mipc_field_value_t *reply);
/** GPS time update: function write_no_ack. */
mipc_result_kind_t mipc_base_gps_time_update_write_no_ack(mipc_link_t *link, mipc_gps_time_field_t field_id,
                                                          uint32_t value);
/** Device reset. */
mipc_result_kind_t mipc_base_device_reset(mipc_link_t *link);
/** Event control: function write. */
mipc_result_kind_t mipc_threedm_event_control_write(mipc_link_t *link, uint8_t instance,
                                                    mipc_event_control_mode_t mode);
/** Event control: function read. */
mipc_result_kind_t mipc_threedm_event_control_read(mipc_link_t *link, uint8_t instance,
                                                   mipc_threedm_event_control_response_t *reply);
/** Event control: function save. */
mipc_result_kind_t mipc_threedm_event_control_save(mipc_link_t *link, uint8_t instance);
/** Event control: function load. */
mipc_result_kind_t mipc_threedm_event_control_load(mipc_link_t *link, uint8_t instance);
/** Event control: function default. */
mipc_result_kind_t mipc_threedm_event_control_default(mipc_link_t *link, uint8_t instance);
/** Get event trigger status. */
mipc_result_kind_t mipc_threedm_get_event_trigger_status(mipc_link_t *link,
                                                         const uint8_t *requested_instances,
                                                         size_t requested_instances_count,
                                                         mipc_threedm_event_trigger_status_t *reply);
/** Get event action status. */
mipc_result_kind_t mipc_threedm_get_event_action_status(mipc_link_t *link, const uint8_t *requested_instances,
                                                        size_t requested_instances_count,
                                                        mipc_threedm_event_action_status_t *reply);
/** Event trigger configuration: function write. */
mipc_result_kind_t mipc_threedm_event_trigger_config_write(mipc_link_t *link, uint8_t instance,
                                                           mipc_trigger_type_t type,
                                                           const mipc_trigger_params_t *parameters);
/** Event trigger configuration: function read. */
mipc_result_kind_t
mipc_threedm_event_trigger_config_read(mipc_link_t *link, uint8_t instance,
                                       mipc_threedm_event_trigger_config_response_t *reply);
/** Event trigger configuration: function save. */
mipc_result_kind_t mipc_threedm_event_trigger_config_save(mipc_link_t *link, uint8_t instance);
/** Event trigger configuration: function load. */
mipc_result_kind_t mipc_threedm_event_trigger_config_load(mipc_link_t *link, uint8_t instance);
/** Event trigger configuration: function default. */
mipc_result_kind_t mipc_threedm_event_trigger_config_default(mipc_link_t *link, uint8_t instance);
/** Event action configuration: function write. */
mipc_result_kind_t mipc_threedm_event_action_config_write(mipc_link_t *link, uint8_t instance,
                                                          uint8_t trigger, mipc_action_type_t type,
                                                          const mipc_action_params_t *parameters);
/** Event action configuration: function read. */
mipc_result_kind_t mipc_threedm_event_action_config_read(mipc_link_t *link, uint8_t instance,
                                                         mipc_threedm_event_action_config_response_t *reply);
/** Event action configuration: function save. */
mipc_result_kind_t mipc_threedm_event_action_config_save(mipc_link_t *link, uint8_t instance);
/** Event action configuration: function load. */
mipc_result_kind_t mipc_threedm_event_action_config_load(mipc_link_t *link, uint8_t instance);
/** Event action configuration: function default. */
mipc_result_kind_t mipc_threedm_event_action_config_default(mipc_link_t *link, uint8_t instance);
/** Device startup settings: function read. */
mipc_result_kind_t mipc_threedm_device_startup_settings_read(mipc_link_t *link);
/** Device startup settings: function save. */
mipc_result_kind_t mipc_threedm_device_startup_settings_save(mipc_link_t *link);
/** Device startup settings: function load. */
mipc_result_kind_t mipc_threedm_device_startup_settings_load(mipc_link_t *link);
/** Device startup settings: function default. */
mipc_result_kind_t mipc_threedm_device_startup_settings_default(mipc_link_t *link);
/** Sensor-to-vehicle frame transformation (Euler): function write. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_euler_write(mipc_link_t *link, float roll, float pitch,
                                                              float yaw);
/** Sensor-to-vehicle frame transformation (Euler): function read. */
mipc_result_kind_t
mipc_threedm_sensor_to_vehicle_euler_read(mipc_link_t *link,
                                          mipc_threedm_sensor_to_vehicle_euler_response_t *reply);
/** Sensor-to-vehicle frame transformation (Euler): function save. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_euler_save(mipc_link_t *link);
/** Sensor-to-vehicle frame transformation (Euler): function load. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_euler_load(mipc_link_t *link);
/** Sensor-to-vehicle frame transformation (Euler): function default. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_euler_default(mipc_link_t *link);
/** Sensor-to-vehicle frame transformation (quaternion): function write. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_quaternion_write(mipc_link_t *link, const float q[4]);
/** Sensor-to-vehicle frame transformation (quaternion): function read. */
mipc_result_kind_t
mipc_threedm_sensor_to_vehicle_quaternion_read(mipc_link_t *link,
                                               mipc_threedm_sensor_to_vehicle_quaternion_response_t *reply);
/** Sensor-to-vehicle frame transformation (quaternion): function save. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_quaternion_save(mipc_link_t *link);
/** Sensor-to-vehicle frame transformation (quaternion): function load. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_quaternion_load(mipc_link_t *link);
/** Sensor-to-vehicle frame transformation (quaternion): function default. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_quaternion_default(mipc_link_t *link);
/** Sensor-to-vehicle frame transformation (direction cosine matrix): function write. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_dcm_write(mipc_link_t *link, const float dcm[9]);
/** Sensor-to-vehicle frame transformation (direction cosine matrix): function read. */
mipc_result_kind_t
mipc_threedm_sensor_to_vehicle_dcm_read(mipc_link_t *link,
                                        mipc_threedm_sensor_to_vehicle_dcm_response_t *reply);
/** Sensor-to-vehicle frame transformation (direction cosine matrix): function save. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_dcm_save(mipc_link_t *link);
/** Sensor-to-vehicle frame transformation (direction cosine matrix): function load. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_dcm_load(mipc_link_t *link);
/** Sensor-to-vehicle frame transformation (direction cosine matrix): function default. */
mipc_result_kind_t mipc_threedm_sensor_to_vehicle_dcm_default(mipc_link_t *link);
/** Accelerometer bias: function write. */
mipc_result_kind_t mipc_threedm_accel_bias_write(mipc_link_t *link, const float bias[3]);
/** Accelerometer bias: function read. */
mipc_result_kind_t mipc_threedm_accel_bias_read(mipc_link_t *link, mipc_threedm_accel_bias_response_t *reply);
/** Accelerometer bias: function save. */
mipc_result_kind_t mipc_threedm_accel_bias_save(mipc_link_t *link);
/** Accelerometer bias: function load. */
mipc_result_kind_t mipc_threedm_accel_bias_load(mipc_link_t *link);
/** Accelerometer bias: function default. */
mipc_result_kind_t mipc_threedm_accel_bias_default(mipc_link_t *link);
/** Accelerometer bias: function write_no_ack. */
mipc_result_kind_t mipc_threedm_accel_bias_write_no_ack(mipc_link_t *link, const float bias[3]);
/** Gyro bias: function write. */
mipc_result_kind_t mipc_threedm_gyro_bias_write(mipc_link_t *link, const float bias[3]);
/** Gyro bias: function read. */
mipc_result_kind_t mipc_threedm_gyro_bias_read(mipc_link_t *link, mipc_threedm_gyro_bias_response_t *reply);
/** Gyro bias: function save. */
mipc_result_kind_t mipc_threedm_gyro_bias_save(mipc_link_t *link);
/** Gyro bias: function load. */
mipc_result_kind_t mipc_threedm_gyro_bias_load(mipc_link_t *link);
/** Gyro bias: function default. */
mipc_result_kind_t mipc_threedm_gyro_bias_default(mipc_link_t *link);
/** Gyro bias: function write_no_ack. */
mipc_result_kind_t mipc_threedm_gyro_bias_write_no_ack(mipc_link_t *link, const float bias[3]);
/** Capture gyro bias. */
mipc_result_kind_t mipc_threedm_capture_gyro_bias(mipc_link_t *link, uint16_t averaging_time_ms,
                                                  mipc_threedm_gyro_bias_response_t *reply);
/** Magnetometer hard iron offset: function write. */
mipc_result_kind_t mipc_threedm_mag_hard_iron_offset_write(mipc_link_t *link, const float offset[3]);
/** Magnetometer hard iron offset: function read. */
mipc_result_kind_t
mipc_threedm_mag_hard_iron_offset_read(mipc_link_t *link,
                                       mipc_threedm_mag_hard_iron_offset_response_t *reply);
/** Magnetometer hard iron offset: function save. */
mipc_result_kind_t mipc_threedm_mag_hard_iron_offset_save(mipc_link_t *link);
/** Magnetometer hard iron offset: function load. */
mipc_result_kind_t mipc_threedm_mag_hard_iron_offset_load(mipc_link_t *link);
/** Magnetometer hard iron offset: function default. */
mipc_result_kind_t mipc_threedm_mag_hard_iron_offset_default(mipc_link_t *link);
/** Magnetometer hard iron offset: function write_no_ack. */
mipc_result_kind_t mipc_threedm_mag_hard_iron_offset_write_no_ack(mipc_link_t *link, const float offset[3]);
/** Magnetometer soft iron matrix: function write. */
mipc_result_kind_t mipc_threedm_mag_soft_iron_matrix_write(mipc_link_t *link, const float matrix[9]);
/** Magnetometer soft iron matrix: function read. */
mipc_result_kind_t
mipc_threedm_mag_soft_iron_matrix_read(mipc_link_t *link,
                                       mipc_threedm_mag_soft_iron_matrix_response_t *reply);
/** Magnetometer soft iron matrix: function save. */
mipc_result_kind_t mipc_threedm_mag_soft_iron_matrix_save(mipc_link_t *link);
/** Magnetometer soft iron matrix: function load. */
mipc_result_kind_t mipc_threedm_mag_soft_iron_matrix_load(mipc_link_t *link);
/** Magnetometer soft iron matrix: function default. */
mipc_result_kind_t mipc_threedm_mag_soft_iron_matrix_default(mipc_link_t *link);
/** Magnetometer soft iron matrix: function write_no_ack. */
mipc_result_kind_t mipc_threedm_mag_soft_iron_matrix_write_no_ack(mipc_link_t *link, const float matrix[9]);
/** Coning and sculling enable: function write. */
mipc_result_kind_t mipc_threedm_coning_sculling_enable_write(mipc_link_t *link, bool enable);
/** Coning and sculling enable: function read. */
mipc_result_kind_t
mipc_threedm_coning_sculling_enable_read(mipc_link_t *link,
                                         mipc_threedm_coning_sculling_enable_response_t *reply);
/** Coning and sculling enable: function save. */
mipc_result_kind_t mipc_threedm_coning_sculling_enable_save(mipc_link_t *link);
/** Coning and sculling enable: function load. */
mipc_result_kind_t mipc_threedm_coning_sculling_enable_load(mipc_link_t *link);
/** Coning and sculling enable: function default. */
mipc_result_kind_t mipc_threedm_coning_sculling_enable_default(mipc_link_t *link);
/** UART baud rate: function write. */
mipc_result_kind_t mipc_threedm_uart_baudrate_write(mipc_link_t *link, uint32_t baud);
/** UART baud rate: function read. */
mipc_result_kind_t mipc_threedm_uart_baudrate_read(mipc_link_t *link,
                                                   mipc_threedm_uart_baudrate_response_t *reply);
/** UART baud rate: function save. */
mipc_result_kind_t mipc_threedm_uart_baudrate_save(mipc_link_t *link);
/** UART baud rate: function load. */
mipc_result_kind_t mipc_threedm_uart_baudrate_load(mipc_link_t *link);
/** UART baud rate: function default. */
mipc_result_kind_t mipc_threedm_uart_baudrate_default(mipc_link_t *link);
/** GPIO configuration: function write. */
mipc_result_kind_t mipc_threedm_gpio_config_write(mipc_link_t *link, uint8_t pin, mipc_gpio_feature_t feature,
                                                  const mipc_gpio_behavior_t *behavior,
                                                  mipc_gpio_pin_mode_t pin_mode);
/** GPIO configuration: function read. */
mipc_result_kind_t mipc_threedm_gpio_config_read(mipc_link_t *link, uint8_t pin,
                                                 mipc_threedm_gpio_config_response_t *reply);
/** GPIO configuration: function save. */
mipc_result_kind_t mipc_threedm_gpio_config_save(mipc_link_t *link, uint8_t pin);
/** GPIO configuration: function load. */
mipc_result_kind_t mipc_threedm_gpio_config_load(mipc_link_t *link, uint8_t pin);
/** GPIO configuration: function default. */
mipc_result_kind_t mipc_threedm_gpio_config_default(mipc_link_t *link, uint8_t pin);
/** GPIO state: function write. */
mipc_result_kind_t mipc_threedm_gpio_state_write(mipc_link_t *link, uint8_t pin, bool state);
/** GPIO state: function read. */
mipc_result_kind_t mipc_threedm_gpio_state_read(mipc_link_t *link, uint8_t pin,
                                                mipc_threedm_gpio_state_response_t *reply);
/** Odometer configuration: function write. */
mipc_result_kind_t mipc_threedm_odometer_config_write(mipc_link_t *link, mipc_odometer_mode_t mode,
                                                      float scaling, float uncertainty);
/** Odometer configuration: function read. */
mipc_result_kind_t mipc_threedm_odometer_config_read(mipc_link_t *link,
                                                     mipc_threedm_odometer_config_response_t *reply);
/** Odometer configuration: function save. */
mipc_result_kind_t mipc_threedm_odometer_config_save(mipc_link_t *link);
/** Odometer configuration: function load. */
mipc_result_kind_t mipc_threedm_odometer_config_load(mipc_link_t *link);
/** Odometer configuration: function default. */
mipc_result_kind_t mipc_threedm_odometer_config_default(mipc_link_t *link);
/** Advanced low-pass filter settings: function write. */
mipc_result_kind_t mipc_threedm_advanced_lowpass_filter_write(mipc_link_t *link, uint8_t target_descriptor,
                                                              bool enable, bool manual, uint16_t frequency,
                                                              uint8_t reserved);
/** Advanced low-pass filter settings: function read. */
mipc_result_kind_t
mipc_threedm_advanced_lowpass_filter_read(mipc_link_t *link, uint8_t target_descriptor,
                                          mipc_threedm_advanced_lowpass_filter_response_t *reply);
/** Advanced low-pass filter settings: function save. */
mipc_result_kind_t mipc_threedm_advanced_lowpass_filter_save(mipc_link_t *link, uint8_t target_descriptor);
/** Advanced low-pass filter settings: function load. */
mipc_result_kind_t mipc_threedm_advanced_lowpass_filter_load(mipc_link_t *link, uint8_t target_descriptor);
/** Advanced low-pass filter settings: function default. */
mipc_result_kind_t mipc_threedm_advanced_lowpass_filter_default(mipc_link_t *link, uint8_t target_descriptor);
/** Complementary filter settings: function write. */
mipc_result_kind_t mipc_threedm_complementary_filter_write(mipc_link_t *link, bool pitch_roll_enable,
                                                           bool heading_enable,
                                                           float pitch_roll_time_constant,
                                                           float heading_time_constant);
/** Complementary filter settings: function read. */
mipc_result_kind_t
mipc_threedm_complementary_filter_read(mipc_link_t *link,
                                       mipc_threedm_complementary_filter_response_t *reply);
/** Complementary filter settings: function save. */
mipc_result_kind_t mipc_threedm_complementary_filter_save(mipc_link_t *link);
/** Complementary filter settings: function load. */
mipc_result_kind_t mipc_threedm_complementary_filter_load(mipc_link_t *link);
/** Complementary filter settings: function default. */
mipc_result_kind_t mipc_threedm_complementary_filter_default(mipc_link_t *link);
/** Sensor range: function write. */
mipc_result_kind_t mipc_threedm_sensor_range_write(mipc_link_t *link, mipc_sensor_range_type_t sensor,
                                                   uint8_t setting);
/** Sensor range: function read. */
mipc_result_kind_t mipc_threedm_sensor_range_read(mipc_link_t *link, mipc_sensor_range_type_t sensor,
                                                  mipc_threedm_sensor_range_response_t *reply);
/** Sensor range: function save. */
mipc_result_kind_t mipc_threedm_sensor_range_save(mipc_link_t *link, mipc_sensor_range_type_t sensor);
/** Sensor range: function load. */
mipc_result_kind_t mipc_threedm_sensor_range_load(mipc_link_t *link, mipc_sensor_range_type_t sensor);
/** Sensor range: function default. */
mipc_result_kind_t mipc_threedm_sensor_range_default(mipc_link_t *link, mipc_sensor_range_type_t sensor);
/** Get calibrated sensor ranges. */
mipc_result_kind_t mipc_threedm_get_calibrated_sensor_ranges(mipc_link_t *link,
                                                             mipc_sensor_range_type_t sensor,
                                                             mipc_threedm_calibrated_sensor_ranges_t *reply);
/** Low-pass anti-aliasing filter: function write. */
mipc_result_kind_t mipc_threedm_lowpass_filter_write(mipc_link_t *link, uint8_t desc_set, uint8_t field_desc,
                                                     bool enable, bool manual, float frequency);
/** Low-pass anti-aliasing filter: function read. */
mipc_result_kind_t mipc_threedm_lowpass_filter_read(mipc_link_t *link, uint8_t desc_set, uint8_t field_desc,
                                                    mipc_threedm_lowpass_filter_response_t *reply);
/** Low-pass anti-aliasing filter: function save. */
mipc_result_kind_t mipc_threedm_lowpass_filter_save(mipc_link_t *link, uint8_t desc_set, uint8_t field_desc);
/** Low-pass anti-aliasing filter: function load. */
mipc_result_kind_t mipc_threedm_lowpass_filter_load(mipc_link_t *link, uint8_t desc_set, uint8_t field_desc);
/** Low-pass anti-aliasing filter: function default. */
mipc_result_kind_t mipc_threedm_lowpass_filter_default(mipc_link_t *link, uint8_t desc_set,
                                                       uint8_t field_desc);
/** Poll IMU data. */
mipc_result_kind_t mipc_threedm_poll_imu_data(mipc_link_t *link, mipc_gx5_poll_option_t option,
                                              const mipc_gx5_poll_descriptor_t *descriptors,
                                              size_t descriptors_count);
/** Poll GNSS data. */
mipc_result_kind_t mipc_threedm_poll_gnss_data(mipc_link_t *link, mipc_gx5_poll_option_t option,
                                               const mipc_gx5_poll_descriptor_t *descriptors,
                                               size_t descriptors_count);
/** Poll estimation filter data. */
mipc_result_kind_t mipc_threedm_poll_filter_data(mipc_link_t *link, mipc_gx5_poll_option_t option,
                                                 const mipc_gx5_poll_descriptor_t *descriptors,
                                                 size_t descriptors_count);
/** Poll NMEA data. */
mipc_result_kind_t mipc_threedm_poll_nmea_data(mipc_link_t *link, bool suppress_ack,
                                               const mipc_nmea_message_t *format_entries,
                                               size_t format_entries_count);
/** Poll data. */
mipc_result_kind_t mipc_threedm_poll_data(mipc_link_t *link, uint8_t desc_set, bool suppress_ack,
                                          const uint8_t *descriptors, size_t descriptors_count);
/** Get IMU data base rate. */
mipc_result_kind_t mipc_threedm_get_imu_base_rate(mipc_link_t *link, mipc_threedm_imu_base_rate_t *reply);
/** Get GNSS data base rate. */
mipc_result_kind_t mipc_threedm_get_gnss_base_rate(mipc_link_t *link, mipc_threedm_gnss_base_rate_t *reply);
/** Get estimation filter data base rate. */
mipc_result_kind_t mipc_threedm_get_filter_base_rate(mipc_link_t *link,
                                                     mipc_threedm_filter_base_rate_t *reply);
/** Get data base rate. */
mipc_result_kind_t mipc_threedm_get_base_rate(mipc_link_t *link, uint8_t desc_set,
                                              mipc_threedm_base_rate_t *reply);
/** IMU message format: function write. */
mipc_result_kind_t mipc_threedm_imu_message_format_write(mipc_link_t *link,
                                                         const mipc_descriptor_rate_t *descriptors,
                                                         size_t descriptors_count);
/** IMU message format: function read. */
mipc_result_kind_t mipc_threedm_imu_message_format_read(mipc_link_t *link,
                                                        const mipc_descriptor_rate_t *descriptors,
                                                        size_t descriptors_count,
                                                        mipc_threedm_imu_message_format_response_t *reply);
/** IMU message format: function save. */
mipc_result_kind_t mipc_threedm_imu_message_format_save(mipc_link_t *link,
                                                        const mipc_descriptor_rate_t *descriptors,
                                                        size_t descriptors_count);
/** IMU message format: function load. */
mipc_result_kind_t mipc_threedm_imu_message_format_load(mipc_link_t *link,
                                                        const mipc_descriptor_rate_t *descriptors,
                                                        size_t descriptors_count);
/** IMU message format: function default. */
mipc_result_kind_t mipc_threedm_imu_message_format_default(mipc_link_t *link,
                                                           const mipc_descriptor_rate_t *descriptors,
                                                           size_t descriptors_count);
/** GNSS message format: function write. */
mipc_result_kind_t mipc_threedm_gnss_message_format_write(mipc_link_t *link,
                                                          const mipc_descriptor_rate_t *descriptors,
                                                          size_t descriptors_count);
/** GNSS message format: function read. */
mipc_result_kind_t mipc_threedm_gnss_message_format_read(mipc_link_t *link,
                                                         const mipc_descriptor_rate_t *descriptors,
                                                         size_t descriptors_count,
                                                         mipc_threedm_gnss_message_format_response_t *reply);
/** GNSS message format: function save. */
mipc_result_kind_t mipc_threedm_gnss_message_format_save(mipc_link_t *link,
                                                         const mipc_descriptor_rate_t *descriptors,
                                                         size_t descriptors_count);
/** GNSS message format: function load. */
mipc_result_kind_t mipc_threedm_gnss_message_format_load(mipc_link_t *link,
                                                         const mipc_descriptor_rate_t *descriptors,
                                                         size_t descriptors_count);
/** GNSS message format: function default. */
mipc_result_kind_t mipc_threedm_gnss_message_format_default(mipc_link_t *link,
                                                            const mipc_descriptor_rate_t *descriptors,
                                                            size_t descriptors_count);
/** Estimation filter message format: function write. */
mipc_result_kind_t mipc_threedm_filter_message_format_write(mipc_link_t *link,
                                                            const mipc_descriptor_rate_t *descriptors,
                                                            size_t descriptors_count);
/** Estimation filter message format: function read. */
mipc_result_kind_t
mipc_threedm_filter_message_format_read(mipc_link_t *link, const mipc_descriptor_rate_t *descriptors,
                                        size_t descriptors_count,
                                        mipc_threedm_filter_message_format_response_t *reply);
/** Estimation filter message format: function save. */
mipc_result_kind_t mipc_threedm_filter_message_format_save(mipc_link_t *link,
                                                           const mipc_descriptor_rate_t *descriptors,
                                                           size_t descriptors_count);
/** Estimation filter message format: function load. */
mipc_result_kind_t mipc_threedm_filter_message_format_load(mipc_link_t *link,
                                                           const mipc_descriptor_rate_t *descriptors,
                                                           size_t descriptors_count);
/** Estimation filter message format: function default. */
mipc_result_kind_t mipc_threedm_filter_message_format_default(mipc_link_t *link,
                                                              const mipc_descriptor_rate_t *descriptors,
                                                              size_t descriptors_count);
/** NMEA message format: function write. */
mipc_result_kind_t mipc_threedm_nmea_message_format_write(mipc_link_t *link,
                                                          const mipc_nmea_message_t *format_entries,
                                                          size_t format_entries_count);
/** NMEA message format: function read. */
mipc_result_kind_t mipc_threedm_nmea_message_format_read(mipc_link_t *link,
                                                         mipc_threedm_nmea_message_format_response_t *reply);
/** NMEA message format: function save. */
mipc_result_kind_t mipc_threedm_nmea_message_format_save(mipc_link_t *link);
/** NMEA message format: function load. */
mipc_result_kind_t mipc_threedm_nmea_message_format_load(mipc_link_t *link);
/** NMEA message format: function default. */
mipc_result_kind_t mipc_threedm_nmea_message_format_default(mipc_link_t *link);
/** Message format: function write. */
mipc_result_kind_t mipc_threedm_message_format_write(mipc_link_t *link, uint8_t desc_set,
                                                     const mipc_descriptor_rate_t *descriptors,
                                                     size_t descriptors_count);
/** Message format: function read. */
mipc_result_kind_t mipc_threedm_message_format_read(mipc_link_t *link, uint8_t desc_set,
                                                    mipc_threedm_message_format_response_t *reply);
/** Message format: function save. */
mipc_result_kind_t mipc_threedm_message_format_save(mipc_link_t *link, uint8_t desc_set);
/** Message format: function load. */
mipc_result_kind_t mipc_threedm_message_format_load(mipc_link_t *link, uint8_t desc_set);
/** Message format: function default. */
mipc_result_kind_t mipc_threedm_message_format_default(mipc_link_t *link, uint8_t desc_set);
/** Factory streaming. */
mipc_result_kind_t mipc_threedm_factory_streaming(mipc_link_t *link, mipc_factory_streaming_action_t action,
                                                  uint8_t reserved);
/** Data stream control: function write. */
mipc_result_kind_t mipc_threedm_data_stream_control_write_gx5_45(mipc_link_t *link,
                                                                 mipc_gx5_stream_selector_t device_selector,
                                                                 uint8_t enable);
/** Data stream control: function write. */
mipc_result_kind_t mipc_threedm_data_stream_control_write_cv7_ins(mipc_link_t *link, uint8_t desc_set,
                                                                  bool enable);
/** Data stream control: function read. */
mipc_result_kind_t mipc_threedm_data_stream_control_read_gx5_45(mipc_link_t *link,
                                                                mipc_gx5_stream_selector_t device_selector,
                                                                uint8_t enable, mipc_field_value_t *reply);
/** Data stream control: function read. */
mipc_result_kind_t mipc_threedm_data_stream_control_read_cv7_ins(mipc_link_t *link, uint8_t desc_set,
                                                                 mipc_field_value_t *reply);
/** Data stream control: function save. */
mipc_result_kind_t mipc_threedm_data_stream_control_save_gx5_45(mipc_link_t *link,
                                                                mipc_gx5_stream_selector_t device_selector,
                                                                uint8_t enable);
/** Data stream control: function save. */
mipc_result_kind_t mipc_threedm_data_stream_control_save_cv7_ins(mipc_link_t *link, uint8_t desc_set);
/** Data stream control: function load. */
mipc_result_kind_t mipc_threedm_data_stream_control_load_gx5_45(mipc_link_t *link,
                                                                mipc_gx5_stream_selector_t device_selector,
                                                                uint8_t enable);
/** Data stream control: function load. */
mipc_result_kind_t mipc_threedm_data_stream_control_load_cv7_ins(mipc_link_t *link, uint8_t desc_set);
/** Data stream control: function default. */
mipc_result_kind_t mipc_threedm_data_stream_control_default_gx5_45(mipc_link_t *link,
                                                                   mipc_gx5_stream_selector_t device_selector,
                                                                   uint8_t enable);
/** Data stream control: function default. */
mipc_result_kind_t mipc_threedm_data_stream_control_default_cv7_ins(mipc_link_t *link, uint8_t desc_set);
/** Raw RTCM 2.3 message. */
mipc_result_kind_t mipc_threedm_raw_rtcm_message(mipc_link_t *link, const uint8_t *data, size_t data_count);
/** GNSS constellation settings: function write. */
mipc_result_kind_t
mipc_threedm_gnss_constellation_settings_write(mipc_link_t *link, uint16_t max_channels,
                                               const mipc_constellation_settings_t *settings,
                                               size_t settings_count);
/** GNSS constellation settings: function read. */
mipc_result_kind_t mipc_threedm_gnss_constellation_settings_read(
    mipc_link_t *link, uint16_t max_channels, const mipc_constellation_settings_t *settings,
    size_t settings_count, mipc_threedm_gnss_constellation_settings_response_t *reply);
/** GNSS constellation settings: function save. */
mipc_result_kind_t
mipc_threedm_gnss_constellation_settings_save(mipc_link_t *link, uint16_t max_channels,
                                              const mipc_constellation_settings_t *settings,
                                              size_t settings_count);
/** GNSS constellation settings: function load. */
mipc_result_kind_t
mipc_threedm_gnss_constellation_settings_load(mipc_link_t *link, uint16_t max_channels,
                                              const mipc_constellation_settings_t *settings,
                                              size_t settings_count);
/** GNSS constellation settings: function default. */
mipc_result_kind_t
mipc_threedm_gnss_constellation_settings_default(mipc_link_t *link, uint16_t max_channels,
                                                 const mipc_constellation_settings_t *settings,
                                                 size_t settings_count);
/** GNSS SBAS settings: function write. */
mipc_result_kind_t mipc_threedm_gnss_sbas_settings_write(mipc_link_t *link, uint8_t enable_sbas,
                                                         mipc_sbas_options_t sbas_options,
                                                         const uint16_t *included_prns,
                                                         size_t included_prns_count);
/** GNSS SBAS settings: function read. */
mipc_result_kind_t mipc_threedm_gnss_sbas_settings_read(mipc_link_t *link,
                                                        mipc_threedm_gnss_sbas_settings_response_t *reply);
/** GNSS SBAS settings: function save. */
mipc_result_kind_t mipc_threedm_gnss_sbas_settings_save(mipc_link_t *link);
/** GNSS SBAS settings: function load. */
mipc_result_kind_t mipc_threedm_gnss_sbas_settings_load(mipc_link_t *link);
/** GNSS SBAS settings: function default. */
mipc_result_kind_t mipc_threedm_gnss_sbas_settings_default(mipc_link_t *link);
/** GNSS assisted fix control: function write. */
mipc_result_kind_t mipc_threedm_gnss_assisted_fix_control_write(mipc_link_t *link,
                                                                mipc_assisted_fix_option_t option,
                                                                uint8_t flags);
/** GNSS assisted fix control: function read. */
mipc_result_kind_t
mipc_threedm_gnss_assisted_fix_control_read(mipc_link_t *link, mipc_assisted_fix_option_t option,
                                            uint8_t flags,
                                            mipc_threedm_gnss_assisted_fix_control_response_t *reply);
/** GNSS assisted fix control: function save. */
mipc_result_kind_t mipc_threedm_gnss_assisted_fix_control_save(mipc_link_t *link,
                                                               mipc_assisted_fix_option_t option,
                                                               uint8_t flags);
/** GNSS assisted fix control: function load. */
mipc_result_kind_t mipc_threedm_gnss_assisted_fix_control_load(mipc_link_t *link,
                                                               mipc_assisted_fix_option_t option,
                                                               uint8_t flags);
/** GNSS assisted fix control: function default. */
mipc_result_kind_t mipc_threedm_gnss_assisted_fix_control_default(mipc_link_t *link,
                                                                  mipc_assisted_fix_option_t option,
                                                                  uint8_t flags);
/** GNSS assist time update: function write. */
mipc_result_kind_t mipc_threedm_gnss_assist_time_update_write(mipc_link_t *link, double tow,
                                                              uint16_t week_number, float accuracy);
/** GNSS assist time update: function read. */
mipc_result_kind_t
mipc_threedm_gnss_assist_time_update_read(mipc_link_t *link, double tow, uint16_t week_number, float accuracy,
                                          mipc_threedm_gnss_assist_time_update_response_t *reply);
/** PPS source control: function write. */
mipc_result_kind_t mipc_threedm_pps_source_write(mipc_link_t *link, mipc_pps_source_t source);
/** PPS source control: function read. */
mipc_result_kind_t mipc_threedm_pps_source_read(mipc_link_t *link, mipc_threedm_pps_source_response_t *reply);
/** PPS source control: function save. */
mipc_result_kind_t mipc_threedm_pps_source_save(mipc_link_t *link);
/** PPS source control: function load. */
mipc_result_kind_t mipc_threedm_pps_source_load(mipc_link_t *link);
/** PPS source control: function default. */
mipc_result_kind_t mipc_threedm_pps_source_default(mipc_link_t *link);
/** Get supported events. */
mipc_result_kind_t mipc_threedm_get_supported_events(mipc_link_t *link, mipc_supported_events_query_t query,
                                                     mipc_threedm_supported_events_t *reply);
/** Device status. */
mipc_result_kind_t mipc_threedm_device_status(mipc_link_t *link, uint16_t model_number,
                                              mipc_device_status_selector_t status_selector,
                                              mipc_threedm_device_status_response_t *reply);
/** Reset filter. */
mipc_result_kind_t mipc_filter_reset_filter(mipc_link_t *link);
/** Set initial attitude. */
mipc_result_kind_t mipc_filter_set_initial_attitude(mipc_link_t *link, float roll, float pitch,
                                                    float heading);
/** Set initial heading. */
mipc_result_kind_t mipc_filter_set_initial_heading(mipc_link_t *link, float heading);
/** Run navigation filter. */
mipc_result_kind_t mipc_filter_run_filter(mipc_link_t *link);
/** Vehicle dynamics mode: function write. */
mipc_result_kind_t mipc_filter_vehicle_dynamics_mode_write(mipc_link_t *link,
                                                           mipc_vehicle_dynamics_mode_t mode);
/** Vehicle dynamics mode: function read. */
mipc_result_kind_t
mipc_filter_vehicle_dynamics_mode_read(mipc_link_t *link,
                                       mipc_filter_vehicle_dynamics_mode_response_t *reply);
/** Vehicle dynamics mode: function save. */
mipc_result_kind_t mipc_filter_vehicle_dynamics_mode_save(mipc_link_t *link);
/** Vehicle dynamics mode: function load. */
mipc_result_kind_t mipc_filter_vehicle_dynamics_mode_load(mipc_link_t *link);
/** Vehicle dynamics mode: function default. */
mipc_result_kind_t mipc_filter_vehicle_dynamics_mode_default(mipc_link_t *link);
/** Sensor to vehicle frame transformation: function write. */
mipc_result_kind_t mipc_filter_sensor_to_vehicle_transform_write(mipc_link_t *link, float roll, float pitch,
                                                                 float yaw);
/** Sensor to vehicle frame transformation: function read. */
mipc_result_kind_t
mipc_filter_sensor_to_vehicle_transform_read(mipc_link_t *link,
                                             mipc_filter_sensor_to_vehicle_transform_response_t *reply);
/** Sensor to vehicle frame transformation: function save. */
mipc_result_kind_t mipc_filter_sensor_to_vehicle_transform_save(mipc_link_t *link);
/** Sensor to vehicle frame transformation: function load. */
mipc_result_kind_t mipc_filter_sensor_to_vehicle_transform_load(mipc_link_t *link);
/** Sensor to vehicle frame transformation: function default. */
mipc_result_kind_t mipc_filter_sensor_to_vehicle_transform_default(mipc_link_t *link);
/** Sensor to vehicle frame offset: function write. */
mipc_result_kind_t mipc_filter_sensor_to_vehicle_offset_write(mipc_link_t *link, const float offset[3]);
/** Sensor to vehicle frame offset: function read. */
mipc_result_kind_t
mipc_filter_sensor_to_vehicle_offset_read(mipc_link_t *link,
                                          mipc_filter_sensor_to_vehicle_offset_response_t *reply);
/** Sensor to vehicle frame offset: function save. */
mipc_result_kind_t mipc_filter_sensor_to_vehicle_offset_save(mipc_link_t *link);
/** Sensor to vehicle frame offset: function load. */
mipc_result_kind_t mipc_filter_sensor_to_vehicle_offset_load(mipc_link_t *link);
/** Sensor to vehicle frame offset: function default. */
mipc_result_kind_t mipc_filter_sensor_to_vehicle_offset_default(mipc_link_t *link);
/** GNSS antenna offset: function write. */
mipc_result_kind_t mipc_filter_antenna_offset_write(mipc_link_t *link, const float offset[3]);
/** GNSS antenna offset: function read. */
mipc_result_kind_t mipc_filter_antenna_offset_read(mipc_link_t *link,
                                                   mipc_filter_antenna_offset_response_t *reply);
/** GNSS antenna offset: function save. */
mipc_result_kind_t mipc_filter_antenna_offset_save(mipc_link_t *link);
/** GNSS antenna offset: function load. */
mipc_result_kind_t mipc_filter_antenna_offset_load(mipc_link_t *link);
/** GNSS antenna offset: function default. */
mipc_result_kind_t mipc_filter_antenna_offset_default(mipc_link_t *link);
/** Estimation control flags: function write. */
mipc_result_kind_t mipc_filter_estimation_control_write(mipc_link_t *link,
                                                        mipc_estimation_control_flags_t flags);
/** Estimation control flags: function read. */
mipc_result_kind_t mipc_filter_estimation_control_read(mipc_link_t *link,
                                                       mipc_filter_estimation_control_response_t *reply);
/** Estimation control flags: function save. */
mipc_result_kind_t mipc_filter_estimation_control_save(mipc_link_t *link);
/** Estimation control flags: function load. */
mipc_result_kind_t mipc_filter_estimation_control_load(mipc_link_t *link);
/** Estimation control flags: function default. */
mipc_result_kind_t mipc_filter_estimation_control_default(mipc_link_t *link);
/** GNSS source control: function write. */
mipc_result_kind_t mipc_filter_gnss_source_control_write(mipc_link_t *link, mipc_filter_gnss_source_t source);
/** GNSS source control: function read. */
mipc_result_kind_t mipc_filter_gnss_source_control_read(mipc_link_t *link,
                                                        mipc_filter_gnss_source_control_response_t *reply);
/** GNSS source control: function save. */
mipc_result_kind_t mipc_filter_gnss_source_control_save(mipc_link_t *link);
/** GNSS source control: function load. */
mipc_result_kind_t mipc_filter_gnss_source_control_load(mipc_link_t *link);
/** GNSS source control: function default. */
mipc_result_kind_t mipc_filter_gnss_source_control_default(mipc_link_t *link);
/** External GNSS update. */
mipc_result_kind_t mipc_filter_external_gnss_update(mipc_link_t *link, double gps_tow, uint16_t gps_week,
                                                    double latitude, double longitude, double height,
                                                    const float velocity[3],
                                                    const float position_uncertainty[3],
                                                    const float velocity_uncertainty[3]);
/** External heading update. */
mipc_result_kind_t mipc_filter_external_heading_update(mipc_link_t *link, float heading,
                                                       float heading_uncertainty,
                                                       mipc_external_heading_type_t type);
/** Heading update control: function write. */
mipc_result_kind_t mipc_filter_heading_update_control_write(mipc_link_t *link,
                                                            mipc_heading_update_source_t source);
/** Heading update control: function read. */
mipc_result_kind_t
mipc_filter_heading_update_control_read(mipc_link_t *link,
                                        mipc_filter_heading_update_control_response_t *reply);
/** Heading update control: function save. */
mipc_result_kind_t mipc_filter_heading_update_control_save(mipc_link_t *link);
/** Heading update control: function load. */
mipc_result_kind_t mipc_filter_heading_update_control_load(mipc_link_t *link);
/** Heading update control: function default. */
mipc_result_kind_t mipc_filter_heading_update_control_default(mipc_link_t *link);
/** Auto-initialization control: function write. */
mipc_result_kind_t mipc_filter_auto_init_control_write(mipc_link_t *link, uint8_t enable);
/** Auto-initialization control: function read. */
mipc_result_kind_t mipc_filter_auto_init_control_read(mipc_link_t *link,
                                                      mipc_filter_auto_init_control_response_t *reply);
/** Auto-initialization control: function save. */
mipc_result_kind_t mipc_filter_auto_init_control_save(mipc_link_t *link);
/** Auto-initialization control: function load. */
mipc_result_kind_t mipc_filter_auto_init_control_load(mipc_link_t *link);
/** Auto-initialization control: function default. */
mipc_result_kind_t mipc_filter_auto_init_control_default(mipc_link_t *link);
/** Accelerometer noise standard deviation: function write. */
mipc_result_kind_t mipc_filter_accel_noise_write(mipc_link_t *link, const float noise[3]);
/** Accelerometer noise standard deviation: function read. */
mipc_result_kind_t mipc_filter_accel_noise_read(mipc_link_t *link, mipc_filter_accel_noise_response_t *reply);
/** Accelerometer noise standard deviation: function save. */
mipc_result_kind_t mipc_filter_accel_noise_save(mipc_link_t *link);
/** Accelerometer noise standard deviation: function load. */
mipc_result_kind_t mipc_filter_accel_noise_load(mipc_link_t *link);
/** Accelerometer noise standard deviation: function default. */
mipc_result_kind_t mipc_filter_accel_noise_default(mipc_link_t *link);
/** Gyroscope noise standard deviation: function write. */
mipc_result_kind_t mipc_filter_gyro_noise_write(mipc_link_t *link, const float noise[3]);
/** Gyroscope noise standard deviation: function read. */
mipc_result_kind_t mipc_filter_gyro_noise_read(mipc_link_t *link, mipc_filter_gyro_noise_response_t *reply);
/** Gyroscope noise standard deviation: function save. */
mipc_result_kind_t mipc_filter_gyro_noise_save(mipc_link_t *link);
/** Gyroscope noise standard deviation: function load. */
mipc_result_kind_t mipc_filter_gyro_noise_load(mipc_link_t *link);
/** Gyroscope noise standard deviation: function default. */
mipc_result_kind_t mipc_filter_gyro_noise_default(mipc_link_t *link);
/** Accelerometer bias model parameters: function write. */
mipc_result_kind_t mipc_filter_accel_bias_model_write(mipc_link_t *link, const float beta[3],
                                                      const float noise[3]);
/** Accelerometer bias model parameters: function read. */
mipc_result_kind_t mipc_filter_accel_bias_model_read(mipc_link_t *link,
                                                     mipc_filter_accel_bias_model_response_t *reply);
/** Accelerometer bias model parameters: function save. */
mipc_result_kind_t mipc_filter_accel_bias_model_save(mipc_link_t *link);
/** Accelerometer bias model parameters: function load. */
mipc_result_kind_t mipc_filter_accel_bias_model_load(mipc_link_t *link);
/** Accelerometer bias model parameters: function default. */
mipc_result_kind_t mipc_filter_accel_bias_model_default(mipc_link_t *link);
/** Gyroscope bias model parameters: function write. */
mipc_result_kind_t mipc_filter_gyro_bias_model_write(mipc_link_t *link, const float beta[3],
                                                     const float noise[3]);
/** Gyroscope bias model parameters: function read. */
mipc_result_kind_t mipc_filter_gyro_bias_model_read(mipc_link_t *link,
                                                    mipc_filter_gyro_bias_model_response_t *reply);
/** Gyroscope bias model parameters: function save. */
mipc_result_kind_t mipc_filter_gyro_bias_model_save(mipc_link_t *link);
/** Gyroscope bias model parameters: function load. */
mipc_result_kind_t mipc_filter_gyro_bias_model_load(mipc_link_t *link);
/** Gyroscope bias model parameters: function default. */
mipc_result_kind_t mipc_filter_gyro_bias_model_default(mipc_link_t *link);
/** Zero velocity update (ZUPT) control: function write. */
mipc_result_kind_t mipc_filter_zupt_control_write(mipc_link_t *link, uint8_t enable, float threshold);
/** Zero velocity update (ZUPT) control: function read. */
mipc_result_kind_t mipc_filter_zupt_control_read(mipc_link_t *link,
                                                 mipc_filter_zupt_control_response_t *reply);
/** Zero velocity update (ZUPT) control: function save. */
mipc_result_kind_t mipc_filter_zupt_control_save(mipc_link_t *link);
/** Zero velocity update (ZUPT) control: function load. */
mipc_result_kind_t mipc_filter_zupt_control_load(mipc_link_t *link);
/** Zero velocity update (ZUPT) control: function default. */
mipc_result_kind_t mipc_filter_zupt_control_default(mipc_link_t *link);
/** External heading update with timestamp. */
mipc_result_kind_t mipc_filter_external_heading_update_with_time(mipc_link_t *link, double gps_tow,
                                                                 uint16_t gps_week, float heading,
                                                                 float heading_uncertainty,
                                                                 mipc_external_heading_type_t type);
/** Zero angular rate update control: function write. */
mipc_result_kind_t mipc_filter_zero_angular_rate_update_control_write(mipc_link_t *link, uint8_t enable,
                                                                      float threshold);
/** Zero angular rate update control: function read. */
mipc_result_kind_t mipc_filter_zero_angular_rate_update_control_read(
    mipc_link_t *link, mipc_filter_zero_angular_rate_update_control_response_t *reply);
/** Zero angular rate update control: function save. */
mipc_result_kind_t mipc_filter_zero_angular_rate_update_control_save(mipc_link_t *link);
/** Zero angular rate update control: function load. */
mipc_result_kind_t mipc_filter_zero_angular_rate_update_control_load(mipc_link_t *link);
/** Zero angular rate update control: function default. */
mipc_result_kind_t mipc_filter_zero_angular_rate_update_control_default(mipc_link_t *link);
/** Tare orientation: function write. */
mipc_result_kind_t mipc_filter_tare_orientation_write(mipc_link_t *link, mipc_tare_axes_t axes);
/** Tare orientation: function save. */
mipc_result_kind_t mipc_filter_tare_orientation_save(mipc_link_t *link);
/** Tare orientation: function load. */
mipc_result_kind_t mipc_filter_tare_orientation_load(mipc_link_t *link);
/** Tare orientation: function default. */
mipc_result_kind_t mipc_filter_tare_orientation_default(mipc_link_t *link);
/** Commanded zero velocity update. */
mipc_result_kind_t mipc_filter_commanded_zupt(mipc_link_t *link);
/** Commanded zero angular rate update. */
mipc_result_kind_t mipc_filter_commanded_zero_angular_rate_update(mipc_link_t *link);
/** Magnetometer capture auto calibration: function write. */
mipc_result_kind_t mipc_filter_mag_capture_auto_calibration_write(mipc_link_t *link);
/** Magnetometer capture auto calibration: function save. */
mipc_result_kind_t mipc_filter_mag_capture_auto_calibration_save(mipc_link_t *link);
/** Gravity noise standard deviation: function write. */
mipc_result_kind_t mipc_filter_gravity_noise_std_dev_write(mipc_link_t *link, const float noise[3]);
/** Gravity noise standard deviation: function read. */
mipc_result_kind_t
mipc_filter_gravity_noise_std_dev_read(mipc_link_t *link,
                                       mipc_filter_gravity_noise_std_dev_response_t *reply);
/** Gravity noise standard deviation: function save. */
mipc_result_kind_t mipc_filter_gravity_noise_std_dev_save(mipc_link_t *link);
/** Gravity noise standard deviation: function load. */
mipc_result_kind_t mipc_filter_gravity_noise_std_dev_load(mipc_link_t *link);
/** Gravity noise standard deviation: function default. */
mipc_result_kind_t mipc_filter_gravity_noise_std_dev_default(mipc_link_t *link);
/** Pressure altitude noise standard deviation: function write. */
mipc_result_kind_t mipc_filter_pressure_altitude_noise_std_dev_write(mipc_link_t *link, float noise);
/** Pressure altitude noise standard deviation: function read. */
mipc_result_kind_t mipc_filter_pressure_altitude_noise_std_dev_read(
    mipc_link_t *link, mipc_filter_pressure_altitude_noise_std_dev_response_t *reply);
/** Pressure altitude noise standard deviation: function save. */
mipc_result_kind_t mipc_filter_pressure_altitude_noise_std_dev_save(mipc_link_t *link);
/** Pressure altitude noise standard deviation: function load. */
mipc_result_kind_t mipc_filter_pressure_altitude_noise_std_dev_load(mipc_link_t *link);
/** Pressure altitude noise standard deviation: function default. */
mipc_result_kind_t mipc_filter_pressure_altitude_noise_std_dev_default(mipc_link_t *link);
/** Hard iron offset process noise: function write. */
mipc_result_kind_t mipc_filter_hard_iron_offset_noise_write(mipc_link_t *link, const float noise[3]);
/** Hard iron offset process noise: function read. */
mipc_result_kind_t
mipc_filter_hard_iron_offset_noise_read(mipc_link_t *link,
                                        mipc_filter_hard_iron_offset_noise_response_t *reply);
/** Hard iron offset process noise: function save. */
mipc_result_kind_t mipc_filter_hard_iron_offset_noise_save(mipc_link_t *link);
/** Hard iron offset process noise: function load. */
mipc_result_kind_t mipc_filter_hard_iron_offset_noise_load(mipc_link_t *link);
/** Hard iron offset process noise: function default. */
mipc_result_kind_t mipc_filter_hard_iron_offset_noise_default(mipc_link_t *link);
/** Soft iron matrix process noise: function write. */
mipc_result_kind_t mipc_filter_soft_iron_matrix_noise_write(mipc_link_t *link, const float noise[9]);
/** Soft iron matrix process noise: function read. */
mipc_result_kind_t
mipc_filter_soft_iron_matrix_noise_read(mipc_link_t *link,
                                        mipc_filter_soft_iron_matrix_noise_response_t *reply);
/** Soft iron matrix process noise: function save. */
mipc_result_kind_t mipc_filter_soft_iron_matrix_noise_save(mipc_link_t *link);
/** Soft iron matrix process noise: function load. */
mipc_result_kind_t mipc_filter_soft_iron_matrix_noise_load(mipc_link_t *link);
/** Soft iron matrix process noise: function default. */
mipc_result_kind_t mipc_filter_soft_iron_matrix_noise_default(mipc_link_t *link);
/** Magnetometer noise standard deviation: function write. */
mipc_result_kind_t mipc_filter_mag_noise_std_dev_write(mipc_link_t *link, const float noise[3]);
/** Magnetometer noise standard deviation: function read. */
mipc_result_kind_t mipc_filter_mag_noise_std_dev_read(mipc_link_t *link,
                                                      mipc_filter_mag_noise_std_dev_response_t *reply);
/** Magnetometer noise standard deviation: function save. */
mipc_result_kind_t mipc_filter_mag_noise_std_dev_save(mipc_link_t *link);
/** Magnetometer noise standard deviation: function load. */
mipc_result_kind_t mipc_filter_mag_noise_std_dev_load(mipc_link_t *link);
/** Magnetometer noise standard deviation: function default. */
mipc_result_kind_t mipc_filter_mag_noise_std_dev_default(mipc_link_t *link);
/** Declination source: function write. */
mipc_result_kind_t mipc_filter_declination_source_write(mipc_link_t *link,
                                                        mipc_magnetic_param_source_t source,
                                                        float declination);
/** Declination source: function read. */
mipc_result_kind_t mipc_filter_declination_source_read(mipc_link_t *link,
                                                       mipc_filter_declination_source_response_t *reply);
/** Declination source: function save. */
mipc_result_kind_t mipc_filter_declination_source_save(mipc_link_t *link);
/** Declination source: function load. */
mipc_result_kind_t mipc_filter_declination_source_load(mipc_link_t *link);
/** Declination source: function default. */
mipc_result_kind_t mipc_filter_declination_source_default(mipc_link_t *link);
/** Gravity magnitude error adaptive measurement: function write. */
mipc_result_kind_t mipc_filter_gravity_magnitude_adaptive_measurement_write(
    mipc_link_t *link, mipc_adaptive_measurement_mode_t mode, float frequency, float low_limit,
    float high_limit, float low_limit_uncertainty, float high_limit_uncertainty, float minimum_uncertainty);
/** Gravity magnitude error adaptive measurement: function read. */
mipc_result_kind_t mipc_filter_gravity_magnitude_adaptive_measurement_read(
    mipc_link_t *link, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *reply);
/** Gravity magnitude error adaptive measurement: function save. */
mipc_result_kind_t mipc_filter_gravity_magnitude_adaptive_measurement_save(mipc_link_t *link);
/** Gravity magnitude error adaptive measurement: function load. */
mipc_result_kind_t mipc_filter_gravity_magnitude_adaptive_measurement_load(mipc_link_t *link);
/** Gravity magnitude error adaptive measurement: function default. */
mipc_result_kind_t mipc_filter_gravity_magnitude_adaptive_measurement_default(mipc_link_t *link);
/** Magnetometer magnitude error adaptive measurement: function write. */
mipc_result_kind_t mipc_filter_mag_magnitude_adaptive_measurement_write(
    mipc_link_t *link, mipc_adaptive_measurement_mode_t mode, float frequency, float low_limit,
    float high_limit, float low_limit_uncertainty, float high_limit_uncertainty, float minimum_uncertainty);
/** Magnetometer magnitude error adaptive measurement: function read. */
mipc_result_kind_t mipc_filter_mag_magnitude_adaptive_measurement_read(
    mipc_link_t *link, mipc_filter_mag_magnitude_adaptive_measurement_response_t *reply);
/** Magnetometer magnitude error adaptive measurement: function save. */
mipc_result_kind_t mipc_filter_mag_magnitude_adaptive_measurement_save(mipc_link_t *link);
/** Magnetometer magnitude error adaptive measurement: function load. */
mipc_result_kind_t mipc_filter_mag_magnitude_adaptive_measurement_load(mipc_link_t *link);
/** Magnetometer magnitude error adaptive measurement: function default. */
mipc_result_kind_t mipc_filter_mag_magnitude_adaptive_measurement_default(mipc_link_t *link);
/** Magnetometer dip angle error adaptive measurement: function write. */
mipc_result_kind_t mipc_filter_mag_dip_angle_adaptive_measurement_write(mipc_link_t *link,
                                                                        mipc_adaptive_measurement_mode_t mode,
                                                                        float frequency, float high_limit,
                                                                        float high_limit_uncertainty,
                                                                        float minimum_uncertainty);
/** Magnetometer dip angle error adaptive measurement: function read. */
mipc_result_kind_t mipc_filter_mag_dip_angle_adaptive_measurement_read(
    mipc_link_t *link, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *reply);
/** Magnetometer dip angle error adaptive measurement: function save. */
mipc_result_kind_t mipc_filter_mag_dip_angle_adaptive_measurement_save(mipc_link_t *link);
/** Magnetometer dip angle error adaptive measurement: function load. */
mipc_result_kind_t mipc_filter_mag_dip_angle_adaptive_measurement_load(mipc_link_t *link);
/** Magnetometer dip angle error adaptive measurement: function default. */
mipc_result_kind_t mipc_filter_mag_dip_angle_adaptive_measurement_default(mipc_link_t *link);
/** Altitude aiding control: function write. */
mipc_result_kind_t mipc_filter_altitude_aiding_control_write(mipc_link_t *link,
                                                             mipc_altitude_aiding_source_t source);
/** Altitude aiding control: function read. */
mipc_result_kind_t
mipc_filter_altitude_aiding_control_read(mipc_link_t *link,
                                         mipc_filter_altitude_aiding_control_response_t *reply);
/** Altitude aiding control: function save. */
mipc_result_kind_t mipc_filter_altitude_aiding_control_save(mipc_link_t *link);
/** Altitude aiding control: function load. */
mipc_result_kind_t mipc_filter_altitude_aiding_control_load(mipc_link_t *link);
/** Altitude aiding control: function default. */
mipc_result_kind_t mipc_filter_altitude_aiding_control_default(mipc_link_t *link);
/** Pitch/roll aiding control: function write. */
mipc_result_kind_t mipc_filter_pitch_roll_aiding_control_write(mipc_link_t *link,
                                                               mipc_pitch_roll_aiding_source_t source);
/** Pitch/roll aiding control: function read. */
mipc_result_kind_t
mipc_filter_pitch_roll_aiding_control_read(mipc_link_t *link,
                                           mipc_filter_pitch_roll_aiding_control_response_t *reply);
/** Pitch/roll aiding control: function save. */
mipc_result_kind_t mipc_filter_pitch_roll_aiding_control_save(mipc_link_t *link);
/** Pitch/roll aiding control: function load. */
mipc_result_kind_t mipc_filter_pitch_roll_aiding_control_load(mipc_link_t *link);
/** Pitch/roll aiding control: function default. */
mipc_result_kind_t mipc_filter_pitch_roll_aiding_control_default(mipc_link_t *link);
/** Inclination source: function write. */
mipc_result_kind_t mipc_filter_inclination_source_write(mipc_link_t *link,
                                                        mipc_magnetic_param_source_t source,
                                                        float inclination);
/** Inclination source: function read. */
mipc_result_kind_t mipc_filter_inclination_source_read(mipc_link_t *link,
                                                       mipc_filter_inclination_source_response_t *reply);
/** Inclination source: function save. */
mipc_result_kind_t mipc_filter_inclination_source_save(mipc_link_t *link);
/** Inclination source: function load. */
mipc_result_kind_t mipc_filter_inclination_source_load(mipc_link_t *link);
/** Inclination source: function default. */
mipc_result_kind_t mipc_filter_inclination_source_default(mipc_link_t *link);
/** Magnetic field magnitude source: function write. */
mipc_result_kind_t mipc_filter_magnetic_field_magnitude_source_write(mipc_link_t *link,
                                                                     mipc_magnetic_param_source_t source,
                                                                     float magnitude);
/** Magnetic field magnitude source: function read. */
mipc_result_kind_t mipc_filter_magnetic_field_magnitude_source_read(
    mipc_link_t *link, mipc_filter_magnetic_field_magnitude_source_response_t *reply);
/** Magnetic field magnitude source: function save. */
mipc_result_kind_t mipc_filter_magnetic_field_magnitude_source_save(mipc_link_t *link);
/** Magnetic field magnitude source: function load. */
mipc_result_kind_t mipc_filter_magnetic_field_magnitude_source_load(mipc_link_t *link);
/** Magnetic field magnitude source: function default. */
mipc_result_kind_t mipc_filter_magnetic_field_magnitude_source_default(mipc_link_t *link);
/** Aiding measurement control: function write. */
mipc_result_kind_t mipc_filter_aiding_measurement_control_write(mipc_link_t *link,
                                                                mipc_aiding_measurement_source_t source,
                                                                bool enable);
/** Aiding measurement control: function read. */
mipc_result_kind_t
mipc_filter_aiding_measurement_control_read(mipc_link_t *link, mipc_aiding_measurement_source_t source,
                                            mipc_filter_aiding_measurement_control_response_t *reply);
/** Aiding measurement control: function save. */
mipc_result_kind_t mipc_filter_aiding_measurement_control_save(mipc_link_t *link,
                                                               mipc_aiding_measurement_source_t source);
/** Aiding measurement control: function load. */
mipc_result_kind_t mipc_filter_aiding_measurement_control_load(mipc_link_t *link,
                                                               mipc_aiding_measurement_source_t source);
/** Aiding measurement control: function default. */
mipc_result_kind_t mipc_filter_aiding_measurement_control_default(mipc_link_t *link,
                                                                  mipc_aiding_measurement_source_t source);
/** Navigation filter initialization: function write. */
mipc_result_kind_t mipc_filter_initialization_configuration_write(
    mipc_link_t *link, uint8_t wait_for_run_command, mipc_filter_initial_condition_source_t initial_cond_src,
    mipc_heading_alignment_methods_t auto_heading_alignment_selector, float initial_heading,
    float initial_pitch, float initial_roll, const float initial_position[3], const float initial_velocity[3],
    mipc_filter_reference_frame_t reference_frame_selector);
/** Navigation filter initialization: function read. */
mipc_result_kind_t
mipc_filter_initialization_configuration_read(mipc_link_t *link,
                                              mipc_filter_initialization_configuration_response_t *reply);
/** Navigation filter initialization: function save. */
mipc_result_kind_t mipc_filter_initialization_configuration_save(mipc_link_t *link);
/** Navigation filter initialization: function load. */
mipc_result_kind_t mipc_filter_initialization_configuration_load(mipc_link_t *link);
/** Navigation filter initialization: function default. */
mipc_result_kind_t mipc_filter_initialization_configuration_default(mipc_link_t *link);
/** Adaptive filter control: function write. */
mipc_result_kind_t mipc_filter_adaptive_filter_control_write(mipc_link_t *link,
                                                             mipc_adaptive_filter_level_t level,
                                                             uint16_t time_limit);
/** Adaptive filter control: function read. */
mipc_result_kind_t
mipc_filter_adaptive_filter_control_read(mipc_link_t *link,
                                         mipc_filter_adaptive_filter_control_response_t *reply);
/** Adaptive filter control: function save. */
mipc_result_kind_t mipc_filter_adaptive_filter_control_save(mipc_link_t *link);
/** Adaptive filter control: function load. */
mipc_result_kind_t mipc_filter_adaptive_filter_control_load(mipc_link_t *link);
/** Adaptive filter control: function default. */
mipc_result_kind_t mipc_filter_adaptive_filter_control_default(mipc_link_t *link);
/** GNSS multi-antenna offset: function write. */
mipc_result_kind_t mipc_filter_multi_antenna_offset_write(mipc_link_t *link, uint8_t receiver_id,
                                                          const float antenna_offset[3]);
/** GNSS multi-antenna offset: function read. */
mipc_result_kind_t mipc_filter_multi_antenna_offset_read(mipc_link_t *link, uint8_t receiver_id,
                                                         mipc_filter_multi_antenna_offset_response_t *reply);
/** GNSS multi-antenna offset: function save. */
mipc_result_kind_t mipc_filter_multi_antenna_offset_save(mipc_link_t *link, uint8_t receiver_id);
/** GNSS multi-antenna offset: function load. */
mipc_result_kind_t mipc_filter_multi_antenna_offset_load(mipc_link_t *link, uint8_t receiver_id);
/** GNSS multi-antenna offset: function default. */
mipc_result_kind_t mipc_filter_multi_antenna_offset_default(mipc_link_t *link, uint8_t receiver_id);
/** Relative position configuration: function write. */
mipc_result_kind_t
mipc_filter_relative_position_configuration_write(mipc_link_t *link, mipc_relative_position_source_t source,
                                                  mipc_filter_reference_frame_t reference_frame_selector,
                                                  const double reference_coordinates[3]);
/** Relative position configuration: function read. */
mipc_result_kind_t mipc_filter_relative_position_configuration_read(
    mipc_link_t *link, mipc_filter_relative_position_configuration_response_t *reply);
/** Relative position configuration: function save. */
mipc_result_kind_t mipc_filter_relative_position_configuration_save(mipc_link_t *link);
/** Relative position configuration: function load. */
mipc_result_kind_t mipc_filter_relative_position_configuration_load(mipc_link_t *link);
/** Relative position configuration: function default. */
mipc_result_kind_t mipc_filter_relative_position_configuration_default(mipc_link_t *link);
/** Reference point lever arm: function write. */
mipc_result_kind_t mipc_filter_reference_point_lever_arm_write(mipc_link_t *link,
                                                               mipc_reference_point_selector_t ref_point_sel,
                                                               const float lever_arm_offset[3]);
/** Reference point lever arm: function read. */
mipc_result_kind_t
mipc_filter_reference_point_lever_arm_read(mipc_link_t *link,
                                           mipc_filter_reference_point_lever_arm_response_t *reply);
/** Reference point lever arm: function save. */
mipc_result_kind_t mipc_filter_reference_point_lever_arm_save(mipc_link_t *link);
/** Reference point lever arm: function load. */
mipc_result_kind_t mipc_filter_reference_point_lever_arm_load(mipc_link_t *link);
/** Reference point lever arm: function default. */
mipc_result_kind_t mipc_filter_reference_point_lever_arm_default(mipc_link_t *link);
/** Measurement speed lever arm: function write. */
mipc_result_kind_t mipc_filter_speed_lever_arm_write(mipc_link_t *link, uint8_t source,
                                                     const float lever_arm_offset[3]);
/** Measurement speed lever arm: function read. */
mipc_result_kind_t mipc_filter_speed_lever_arm_read(mipc_link_t *link, uint8_t source,
                                                    mipc_filter_speed_lever_arm_response_t *reply);
/** Measurement speed lever arm: function save. */
mipc_result_kind_t mipc_filter_speed_lever_arm_save(mipc_link_t *link, uint8_t source);
/** Measurement speed lever arm: function load. */
mipc_result_kind_t mipc_filter_speed_lever_arm_load(mipc_link_t *link, uint8_t source);
/** Measurement speed lever arm: function default. */
mipc_result_kind_t mipc_filter_speed_lever_arm_default(mipc_link_t *link, uint8_t source);
/** Wheeled vehicle constraint control: function write. */
mipc_result_kind_t mipc_filter_wheeled_vehicle_constraint_control_write(mipc_link_t *link, uint8_t enable);
/** Wheeled vehicle constraint control: function read. */
mipc_result_kind_t mipc_filter_wheeled_vehicle_constraint_control_read(
    mipc_link_t *link, mipc_filter_wheeled_vehicle_constraint_control_response_t *reply);
/** Wheeled vehicle constraint control: function save. */
mipc_result_kind_t mipc_filter_wheeled_vehicle_constraint_control_save(mipc_link_t *link);
/** Wheeled vehicle constraint control: function load. */
mipc_result_kind_t mipc_filter_wheeled_vehicle_constraint_control_load(mipc_link_t *link);
/** Wheeled vehicle constraint control: function default. */
mipc_result_kind_t mipc_filter_wheeled_vehicle_constraint_control_default(mipc_link_t *link);
/** GNSS antenna offset calibration control: function write. */
mipc_result_kind_t mipc_filter_gnss_antenna_calibration_control_write(mipc_link_t *link, uint8_t enable,
                                                                      float max_offset);
/** GNSS antenna offset calibration control: function read. */
mipc_result_kind_t mipc_filter_gnss_antenna_calibration_control_read(
    mipc_link_t *link, mipc_filter_gnss_antenna_calibration_control_response_t *reply);
/** GNSS antenna offset calibration control: function save. */
mipc_result_kind_t mipc_filter_gnss_antenna_calibration_control_save(mipc_link_t *link);
/** GNSS antenna offset calibration control: function load. */
mipc_result_kind_t mipc_filter_gnss_antenna_calibration_control_load(mipc_link_t *link);
/** GNSS antenna offset calibration control: function default. */
mipc_result_kind_t mipc_filter_gnss_antenna_calibration_control_default(mipc_link_t *link);
/** Receiver info. */
mipc_result_kind_t mipc_gnss_receiver_info(mipc_link_t *link, mipc_gnss_receiver_info_response_t *reply);
/** Signal configuration: function write. */
mipc_result_kind_t mipc_gnss_signal_configuration_write(mipc_link_t *link, mipc_gnss_gps_signals_t gps_enable,
                                                        mipc_gnss_glonass_signals_t glonass_enable,
                                                        mipc_gnss_galileo_signals_t galileo_enable,
                                                        mipc_gnss_beidou_signals_t beidou_enable,
                                                        const uint8_t reserved[4]);
/** Signal configuration: function read. */
mipc_result_kind_t mipc_gnss_signal_configuration_read(mipc_link_t *link,
                                                       mipc_gnss_signal_configuration_response_t *reply);
/** Signal configuration: function save. */
mipc_result_kind_t mipc_gnss_signal_configuration_save(mipc_link_t *link);
/** Signal configuration: function load. */
mipc_result_kind_t mipc_gnss_signal_configuration_load(mipc_link_t *link);
/** Signal configuration: function default. */
mipc_result_kind_t mipc_gnss_signal_configuration_default(mipc_link_t *link);
/** SPARTN configuration: function write. */
mipc_result_kind_t mipc_gnss_spartn_configuration_write(mipc_link_t *link, uint8_t enable,
                                                        mipc_spartn_connection_type_t type,
                                                        uint32_t current_key_tow, uint16_t current_key_week,
                                                        const char current_key[32], uint32_t next_key_tow,
                                                        uint16_t next_key_week, const char next_key[32]);
/** SPARTN configuration: function read. */
mipc_result_kind_t mipc_gnss_spartn_configuration_read(mipc_link_t *link,
                                                       mipc_gnss_spartn_configuration_response_t *reply);
/** SPARTN configuration: function save. */
mipc_result_kind_t mipc_gnss_spartn_configuration_save(mipc_link_t *link);
/** SPARTN configuration: function load. */
mipc_result_kind_t mipc_gnss_spartn_configuration_load(mipc_link_t *link);
/** SPARTN configuration: function default. */
mipc_result_kind_t mipc_gnss_spartn_configuration_default(mipc_link_t *link);
/** Frame configuration: function write. */
mipc_result_kind_t mipc_aiding_frame_config_write(mipc_link_t *link, uint8_t frame_id,
                                                  mipc_aiding_frame_format_t format, bool tracking_enabled,
                                                  const float translation[3],
                                                  const mipc_aiding_frame_rotation_t *rotation);
/** Frame configuration: function read. */
mipc_result_kind_t mipc_aiding_frame_config_read(mipc_link_t *link, uint8_t frame_id,
                                                 mipc_aiding_frame_format_t format,
                                                 mipc_aiding_frame_config_response_t *reply);
/** Frame configuration: function save. */
mipc_result_kind_t mipc_aiding_frame_config_save(mipc_link_t *link, uint8_t frame_id);
/** Frame configuration: function load. */
mipc_result_kind_t mipc_aiding_frame_config_load(mipc_link_t *link, uint8_t frame_id);
/** Frame configuration: function default. */
mipc_result_kind_t mipc_aiding_frame_config_default(mipc_link_t *link, uint8_t frame_id);
/** Echo control: function write. */
mipc_result_kind_t mipc_aiding_echo_control_write(mipc_link_t *link, mipc_aiding_echo_mode_t mode);
/** Echo control: function read. */
mipc_result_kind_t mipc_aiding_echo_control_read(mipc_link_t *link,
                                                 mipc_aiding_echo_control_response_t *reply);
/** Echo control: function save. */
mipc_result_kind_t mipc_aiding_echo_control_save(mipc_link_t *link);
/** Echo control: function load. */
mipc_result_kind_t mipc_aiding_echo_control_load(mipc_link_t *link);
/** Echo control: function default. */
mipc_result_kind_t mipc_aiding_echo_control_default(mipc_link_t *link);
/** ECEF position. */
mipc_result_kind_t mipc_aiding_ecef_position(mipc_link_t *link, const mipc_aiding_time_t *time,
                                             uint8_t frame_id, const double position[3],
                                             const float uncertainty[3],
                                             mipc_aiding_vector_valid_flags_t valid_flags);
/** LLH position. */
mipc_result_kind_t mipc_aiding_llh_position(mipc_link_t *link, const mipc_aiding_time_t *time,
                                            uint8_t frame_id, double latitude, double longitude,
                                            double height, const float uncertainty[3],
                                            mipc_aiding_llh_valid_flags_t valid_flags);
/** Height above ellipsoid. */
mipc_result_kind_t mipc_aiding_height_above_ellipsoid(mipc_link_t *link, const mipc_aiding_time_t *time,
                                                      uint8_t frame_id, float height, float uncertainty,
                                                      uint16_t valid_flags);
/** ECEF velocity. */
mipc_result_kind_t mipc_aiding_ecef_velocity(mipc_link_t *link, const mipc_aiding_time_t *time,
                                             uint8_t frame_id, const float velocity[3],
                                             const float uncertainty[3],
                                             mipc_aiding_vector_valid_flags_t valid_flags);
/** NED velocity. */
mipc_result_kind_t mipc_aiding_ned_velocity(mipc_link_t *link, const mipc_aiding_time_t *time,
                                            uint8_t frame_id, const float velocity[3],
                                            const float uncertainty[3],
                                            mipc_aiding_vector_valid_flags_t valid_flags);
/** Body frame velocity. */
mipc_result_kind_t mipc_aiding_body_frame_velocity(mipc_link_t *link, const mipc_aiding_time_t *time,
                                                   uint8_t frame_id, const float velocity[3],
                                                   const float uncertainty[3],
                                                   mipc_aiding_vector_valid_flags_t valid_flags);
/** True heading. */
mipc_result_kind_t mipc_aiding_true_heading(mipc_link_t *link, const mipc_aiding_time_t *time,
                                            uint8_t frame_id, float heading, float uncertainty,
                                            uint16_t valid_flags);
/** Magnetic field. */
mipc_result_kind_t mipc_aiding_magnetic_field(mipc_link_t *link, const mipc_aiding_time_t *time,
                                              uint8_t frame_id, const float magnetic_field[3],
                                              const float uncertainty[3],
                                              mipc_aiding_vector_valid_flags_t valid_flags);
/** Pressure. */
mipc_result_kind_t mipc_aiding_pressure(mipc_link_t *link, const mipc_aiding_time_t *time, uint8_t frame_id,
                                        float pressure, float uncertainty, uint16_t valid_flags);
/** Communication mode: function write. */
mipc_result_kind_t mipc_system_communication_mode_write(mipc_link_t *link, mipc_system_comm_mode_t mode);
/** Communication mode: function read. */
mipc_result_kind_t mipc_system_communication_mode_read(mipc_link_t *link,
                                                       mipc_system_communication_mode_response_t *reply);
/** Communication mode: function save. */
mipc_result_kind_t mipc_system_communication_mode_save(mipc_link_t *link);
/** Communication mode: function load. */
mipc_result_kind_t mipc_system_communication_mode_load(mipc_link_t *link);
/** Communication mode: function default. */
mipc_result_kind_t mipc_system_communication_mode_default(mipc_link_t *link);

#ifdef __cplusplus
}
#endif

#endif
