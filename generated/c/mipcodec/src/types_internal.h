/* Private: read/write/JSON functions of the named structs and unions. Generated: do not edit. */
#ifndef MIPC_TYPES_INTERNAL_H
#define MIPC_TYPES_INTERNAL_H

#include "mipcodec/types.h"
#include "json_reader.h"
#include "json_writer.h"
#include "wire.h"

int mipc_action_gpio_params_read(mipc_reader_t *r, mipc_action_gpio_params_t *out);
mipc_status_t mipc_action_gpio_params_write(mipc_writer_t *w, const mipc_action_gpio_params_t *in);
void mipc_action_gpio_params_to_json(mipc_jw_t *w, const mipc_action_gpio_params_t *in);
int mipc_action_gpio_params_from_json(mipc_jr_t *jr, size_t pos, mipc_action_gpio_params_t *out);
int mipc_message_params_read(mipc_reader_t *r, mipc_message_params_t *out);
mipc_status_t mipc_message_params_write(mipc_writer_t *w, const mipc_message_params_t *in);
void mipc_message_params_to_json(mipc_jw_t *w, const mipc_message_params_t *in);
int mipc_message_params_from_json(mipc_jr_t *jr, size_t pos, mipc_message_params_t *out);
int mipc_action_status_entry_read(mipc_reader_t *r, mipc_action_status_entry_t *out);
mipc_status_t mipc_action_status_entry_write(mipc_writer_t *w, const mipc_action_status_entry_t *in);
void mipc_action_status_entry_to_json(mipc_jw_t *w, const mipc_action_status_entry_t *in);
int mipc_action_status_entry_from_json(mipc_jr_t *jr, size_t pos, mipc_action_status_entry_t *out);
int mipc_aiding_frame_euler_read(mipc_reader_t *r, mipc_aiding_frame_euler_t *out);
mipc_status_t mipc_aiding_frame_euler_write(mipc_writer_t *w, const mipc_aiding_frame_euler_t *in);
void mipc_aiding_frame_euler_to_json(mipc_jw_t *w, const mipc_aiding_frame_euler_t *in);
int mipc_aiding_frame_euler_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_frame_euler_t *out);
int mipc_aiding_frame_quaternion_read(mipc_reader_t *r, mipc_aiding_frame_quaternion_t *out);
mipc_status_t mipc_aiding_frame_quaternion_write(mipc_writer_t *w, const mipc_aiding_frame_quaternion_t *in);
void mipc_aiding_frame_quaternion_to_json(mipc_jw_t *w, const mipc_aiding_frame_quaternion_t *in);
int mipc_aiding_frame_quaternion_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_frame_quaternion_t *out);
int mipc_aiding_time_read(mipc_reader_t *r, mipc_aiding_time_t *out);
mipc_status_t mipc_aiding_time_write(mipc_writer_t *w, const mipc_aiding_time_t *in);
void mipc_aiding_time_to_json(mipc_jw_t *w, const mipc_aiding_time_t *in);
int mipc_aiding_time_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_time_t *out);
int mipc_combination_params_read(mipc_reader_t *r, mipc_combination_params_t *out);
mipc_status_t mipc_combination_params_write(mipc_writer_t *w, const mipc_combination_params_t *in);
void mipc_combination_params_to_json(mipc_jw_t *w, const mipc_combination_params_t *in);
int mipc_combination_params_from_json(mipc_jr_t *jr, size_t pos, mipc_combination_params_t *out);
int mipc_constellation_settings_read(mipc_reader_t *r, mipc_constellation_settings_t *out);
mipc_status_t mipc_constellation_settings_write(mipc_writer_t *w, const mipc_constellation_settings_t *in);
void mipc_constellation_settings_to_json(mipc_jw_t *w, const mipc_constellation_settings_t *in);
int mipc_constellation_settings_from_json(mipc_jr_t *jr, size_t pos, mipc_constellation_settings_t *out);
int mipc_cv7_continuous_bit_read(mipc_reader_t *r, mipc_cv7_continuous_bit_t *out);
mipc_status_t mipc_cv7_continuous_bit_write(mipc_writer_t *w, const mipc_cv7_continuous_bit_t *in);
void mipc_cv7_continuous_bit_to_json(mipc_jw_t *w, const mipc_cv7_continuous_bit_t *in);
int mipc_cv7_continuous_bit_from_json(mipc_jr_t *jr, size_t pos, mipc_cv7_continuous_bit_t *out);
int mipc_descriptor_rate_read(mipc_reader_t *r, mipc_descriptor_rate_t *out);
mipc_status_t mipc_descriptor_rate_write(mipc_writer_t *w, const mipc_descriptor_rate_t *in);
void mipc_descriptor_rate_to_json(mipc_jw_t *w, const mipc_descriptor_rate_t *in);
int mipc_descriptor_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_descriptor_rate_t *out);
int mipc_device_info_read(mipc_reader_t *r, mipc_device_info_t *out);
mipc_status_t mipc_device_info_write(mipc_writer_t *w, const mipc_device_info_t *in);
void mipc_device_info_to_json(mipc_jw_t *w, const mipc_device_info_t *in);
int mipc_device_info_from_json(mipc_jr_t *jr, size_t pos, mipc_device_info_t *out);
int mipc_gnss_receiver_info_entry_read(mipc_reader_t *r, mipc_gnss_receiver_info_entry_t *out);
mipc_status_t mipc_gnss_receiver_info_entry_write(mipc_writer_t *w,
                                                  const mipc_gnss_receiver_info_entry_t *in);
void mipc_gnss_receiver_info_entry_to_json(mipc_jw_t *w, const mipc_gnss_receiver_info_entry_t *in);
int mipc_gnss_receiver_info_entry_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_info_entry_t *out);
int mipc_gpio_behavior_unused_read(mipc_reader_t *r, mipc_gpio_behavior_unused_t *out);
mipc_status_t mipc_gpio_behavior_unused_write(mipc_writer_t *w, const mipc_gpio_behavior_unused_t *in);
void mipc_gpio_behavior_unused_to_json(mipc_jw_t *w, const mipc_gpio_behavior_unused_t *in);
int mipc_gpio_behavior_unused_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_unused_t *out);
int mipc_gpio_behavior_io_read(mipc_reader_t *r, mipc_gpio_behavior_io_t *out);
mipc_status_t mipc_gpio_behavior_io_write(mipc_writer_t *w, const mipc_gpio_behavior_io_t *in);
void mipc_gpio_behavior_io_to_json(mipc_jw_t *w, const mipc_gpio_behavior_io_t *in);
int mipc_gpio_behavior_io_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_io_t *out);
int mipc_gpio_behavior_pps_read(mipc_reader_t *r, mipc_gpio_behavior_pps_t *out);
mipc_status_t mipc_gpio_behavior_pps_write(mipc_writer_t *w, const mipc_gpio_behavior_pps_t *in);
void mipc_gpio_behavior_pps_to_json(mipc_jw_t *w, const mipc_gpio_behavior_pps_t *in);
int mipc_gpio_behavior_pps_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_pps_t *out);
int mipc_gpio_behavior_encoder_read(mipc_reader_t *r, mipc_gpio_behavior_encoder_t *out);
mipc_status_t mipc_gpio_behavior_encoder_write(mipc_writer_t *w, const mipc_gpio_behavior_encoder_t *in);
void mipc_gpio_behavior_encoder_to_json(mipc_jw_t *w, const mipc_gpio_behavior_encoder_t *in);
int mipc_gpio_behavior_encoder_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_encoder_t *out);
int mipc_gpio_behavior_timestamp_read(mipc_reader_t *r, mipc_gpio_behavior_timestamp_t *out);
mipc_status_t mipc_gpio_behavior_timestamp_write(mipc_writer_t *w, const mipc_gpio_behavior_timestamp_t *in);
void mipc_gpio_behavior_timestamp_to_json(mipc_jw_t *w, const mipc_gpio_behavior_timestamp_t *in);
int mipc_gpio_behavior_timestamp_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_timestamp_t *out);
int mipc_gpio_behavior_uart_read(mipc_reader_t *r, mipc_gpio_behavior_uart_t *out);
mipc_status_t mipc_gpio_behavior_uart_write(mipc_writer_t *w, const mipc_gpio_behavior_uart_t *in);
void mipc_gpio_behavior_uart_to_json(mipc_jw_t *w, const mipc_gpio_behavior_uart_t *in);
int mipc_gpio_behavior_uart_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_uart_t *out);
int mipc_gx5_basic_status_read(mipc_reader_t *r, mipc_gx5_basic_status_t *out);
mipc_status_t mipc_gx5_basic_status_write(mipc_writer_t *w, const mipc_gx5_basic_status_t *in);
void mipc_gx5_basic_status_to_json(mipc_jw_t *w, const mipc_gx5_basic_status_t *in);
int mipc_gx5_basic_status_from_json(mipc_jr_t *jr, size_t pos, mipc_gx5_basic_status_t *out);
int mipc_gx5_diagnostic_status_read(mipc_reader_t *r, mipc_gx5_diagnostic_status_t *out);
mipc_status_t mipc_gx5_diagnostic_status_write(mipc_writer_t *w, const mipc_gx5_diagnostic_status_t *in);
void mipc_gx5_diagnostic_status_to_json(mipc_jw_t *w, const mipc_gx5_diagnostic_status_t *in);
int mipc_gx5_diagnostic_status_from_json(mipc_jr_t *jr, size_t pos, mipc_gx5_diagnostic_status_t *out);
int mipc_gx5_poll_descriptor_read(mipc_reader_t *r, mipc_gx5_poll_descriptor_t *out);
mipc_status_t mipc_gx5_poll_descriptor_write(mipc_writer_t *w, const mipc_gx5_poll_descriptor_t *in);
void mipc_gx5_poll_descriptor_to_json(mipc_jw_t *w, const mipc_gx5_poll_descriptor_t *in);
int mipc_gx5_poll_descriptor_from_json(mipc_jr_t *jr, size_t pos, mipc_gx5_poll_descriptor_t *out);
int mipc_nmea_message_read(mipc_reader_t *r, mipc_nmea_message_t *out);
mipc_status_t mipc_nmea_message_write(mipc_writer_t *w, const mipc_nmea_message_t *in);
void mipc_nmea_message_to_json(mipc_jw_t *w, const mipc_nmea_message_t *in);
int mipc_nmea_message_from_json(mipc_jr_t *jr, size_t pos, mipc_nmea_message_t *out);
int mipc_sensor_range_entry_read(mipc_reader_t *r, mipc_sensor_range_entry_t *out);
mipc_status_t mipc_sensor_range_entry_write(mipc_writer_t *w, const mipc_sensor_range_entry_t *in);
void mipc_sensor_range_entry_to_json(mipc_jw_t *w, const mipc_sensor_range_entry_t *in);
int mipc_sensor_range_entry_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_range_entry_t *out);
int mipc_supported_action_type_read(mipc_reader_t *r, mipc_supported_action_type_t *out);
mipc_status_t mipc_supported_action_type_write(mipc_writer_t *w, const mipc_supported_action_type_t *in);
void mipc_supported_action_type_to_json(mipc_jw_t *w, const mipc_supported_action_type_t *in);
int mipc_supported_action_type_from_json(mipc_jr_t *jr, size_t pos, mipc_supported_action_type_t *out);
int mipc_supported_actions_read(mipc_reader_t *r, mipc_supported_actions_t *out);
mipc_status_t mipc_supported_actions_write(mipc_writer_t *w, const mipc_supported_actions_t *in);
void mipc_supported_actions_to_json(mipc_jw_t *w, const mipc_supported_actions_t *in);
int mipc_supported_actions_from_json(mipc_jr_t *jr, size_t pos, mipc_supported_actions_t *out);
int mipc_supported_trigger_type_read(mipc_reader_t *r, mipc_supported_trigger_type_t *out);
mipc_status_t mipc_supported_trigger_type_write(mipc_writer_t *w, const mipc_supported_trigger_type_t *in);
void mipc_supported_trigger_type_to_json(mipc_jw_t *w, const mipc_supported_trigger_type_t *in);
int mipc_supported_trigger_type_from_json(mipc_jr_t *jr, size_t pos, mipc_supported_trigger_type_t *out);
int mipc_supported_triggers_read(mipc_reader_t *r, mipc_supported_triggers_t *out);
mipc_status_t mipc_supported_triggers_write(mipc_writer_t *w, const mipc_supported_triggers_t *in);
void mipc_supported_triggers_to_json(mipc_jw_t *w, const mipc_supported_triggers_t *in);
int mipc_supported_triggers_from_json(mipc_jr_t *jr, size_t pos, mipc_supported_triggers_t *out);
int mipc_threshold_params_read(mipc_reader_t *r, mipc_threshold_params_t *out);
mipc_status_t mipc_threshold_params_write(mipc_writer_t *w, const mipc_threshold_params_t *in);
void mipc_threshold_params_to_json(mipc_jw_t *w, const mipc_threshold_params_t *in);
int mipc_threshold_params_from_json(mipc_jr_t *jr, size_t pos, mipc_threshold_params_t *out);
int mipc_trigger_gpio_params_read(mipc_reader_t *r, mipc_trigger_gpio_params_t *out);
mipc_status_t mipc_trigger_gpio_params_write(mipc_writer_t *w, const mipc_trigger_gpio_params_t *in);
void mipc_trigger_gpio_params_to_json(mipc_jw_t *w, const mipc_trigger_gpio_params_t *in);
int mipc_trigger_gpio_params_from_json(mipc_jr_t *jr, size_t pos, mipc_trigger_gpio_params_t *out);
int mipc_trigger_status_entry_read(mipc_reader_t *r, mipc_trigger_status_entry_t *out);
mipc_status_t mipc_trigger_status_entry_write(mipc_writer_t *w, const mipc_trigger_status_entry_t *in);
void mipc_trigger_status_entry_to_json(mipc_jw_t *w, const mipc_trigger_status_entry_t *in);
int mipc_trigger_status_entry_from_json(mipc_jr_t *jr, size_t pos, mipc_trigger_status_entry_t *out);
int mipc_action_params_read(mipc_reader_t *r, mipc_action_type_t selector, mipc_action_params_t *out);
mipc_status_t mipc_action_params_write(mipc_writer_t *w, mipc_action_type_t selector,
                                       const mipc_action_params_t *in);
void mipc_action_params_to_json(mipc_jw_t *w, mipc_action_type_t selector, const mipc_action_params_t *in);
int mipc_action_params_from_json(mipc_jr_t *jr, size_t pos, mipc_action_type_t selector,
                                 mipc_action_params_t *out);
int mipc_aiding_frame_rotation_read(mipc_reader_t *r, mipc_aiding_frame_format_t selector,
                                    mipc_aiding_frame_rotation_t *out);
mipc_status_t mipc_aiding_frame_rotation_write(mipc_writer_t *w, mipc_aiding_frame_format_t selector,
                                               const mipc_aiding_frame_rotation_t *in);
void mipc_aiding_frame_rotation_to_json(mipc_jw_t *w, mipc_aiding_frame_format_t selector,
                                        const mipc_aiding_frame_rotation_t *in);
int mipc_aiding_frame_rotation_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_frame_format_t selector,
                                         mipc_aiding_frame_rotation_t *out);
int mipc_gpio_behavior_read(mipc_reader_t *r, mipc_gpio_feature_t selector, mipc_gpio_behavior_t *out);
mipc_status_t mipc_gpio_behavior_write(mipc_writer_t *w, mipc_gpio_feature_t selector,
                                       const mipc_gpio_behavior_t *in);
void mipc_gpio_behavior_to_json(mipc_jw_t *w, mipc_gpio_feature_t selector, const mipc_gpio_behavior_t *in);
int mipc_gpio_behavior_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_feature_t selector,
                                 mipc_gpio_behavior_t *out);
int mipc_gx5_device_status_read(mipc_reader_t *r, mipc_device_status_selector_t selector,
                                mipc_gx5_device_status_t *out);
mipc_status_t mipc_gx5_device_status_write(mipc_writer_t *w, mipc_device_status_selector_t selector,
                                           const mipc_gx5_device_status_t *in);
void mipc_gx5_device_status_to_json(mipc_jw_t *w, mipc_device_status_selector_t selector,
                                    const mipc_gx5_device_status_t *in);
int mipc_gx5_device_status_from_json(mipc_jr_t *jr, size_t pos, mipc_device_status_selector_t selector,
                                     mipc_gx5_device_status_t *out);
int mipc_supported_events_info_read(mipc_reader_t *r, mipc_supported_events_query_t selector,
                                    mipc_supported_events_info_t *out);
mipc_status_t mipc_supported_events_info_write(mipc_writer_t *w, mipc_supported_events_query_t selector,
                                               const mipc_supported_events_info_t *in);
void mipc_supported_events_info_to_json(mipc_jw_t *w, mipc_supported_events_query_t selector,
                                        const mipc_supported_events_info_t *in);
int mipc_supported_events_info_from_json(mipc_jr_t *jr, size_t pos, mipc_supported_events_query_t selector,
                                         mipc_supported_events_info_t *out);
int mipc_trigger_params_read(mipc_reader_t *r, mipc_trigger_type_t selector, mipc_trigger_params_t *out);
mipc_status_t mipc_trigger_params_write(mipc_writer_t *w, mipc_trigger_type_t selector,
                                        const mipc_trigger_params_t *in);
void mipc_trigger_params_to_json(mipc_jw_t *w, mipc_trigger_type_t selector, const mipc_trigger_params_t *in);
int mipc_trigger_params_from_json(mipc_jr_t *jr, size_t pos, mipc_trigger_type_t selector,
                                  mipc_trigger_params_t *out);

#endif
