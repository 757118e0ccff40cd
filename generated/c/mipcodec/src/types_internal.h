/* Private: read/write/JSON functions of the named structs and unions. Generated: do not edit. */
#ifndef MIP_TYPES_INTERNAL_H
#define MIP_TYPES_INTERNAL_H

#include "mipcodec/types.h"
#include "json_reader.h"
#include "json_writer.h"
#include "wire.h"

int mip_action_gpio_params_read(mip_reader_t *r, mip_action_gpio_params_t *out);
mip_status_t mip_action_gpio_params_write(mip_writer_t *w, const mip_action_gpio_params_t *in);
void mip_action_gpio_params_to_json(mip_jw_t *w, const mip_action_gpio_params_t *in);
int mip_action_gpio_params_from_json(mip_jr_t *jr, size_t pos, mip_action_gpio_params_t *out);
int mip_message_params_read(mip_reader_t *r, mip_message_params_t *out);
mip_status_t mip_message_params_write(mip_writer_t *w, const mip_message_params_t *in);
void mip_message_params_to_json(mip_jw_t *w, const mip_message_params_t *in);
int mip_message_params_from_json(mip_jr_t *jr, size_t pos, mip_message_params_t *out);
int mip_action_status_entry_read(mip_reader_t *r, mip_action_status_entry_t *out);
mip_status_t mip_action_status_entry_write(mip_writer_t *w, const mip_action_status_entry_t *in);
void mip_action_status_entry_to_json(mip_jw_t *w, const mip_action_status_entry_t *in);
int mip_action_status_entry_from_json(mip_jr_t *jr, size_t pos, mip_action_status_entry_t *out);
int mip_aiding_frame_euler_read(mip_reader_t *r, mip_aiding_frame_euler_t *out);
mip_status_t mip_aiding_frame_euler_write(mip_writer_t *w, const mip_aiding_frame_euler_t *in);
void mip_aiding_frame_euler_to_json(mip_jw_t *w, const mip_aiding_frame_euler_t *in);
int mip_aiding_frame_euler_from_json(mip_jr_t *jr, size_t pos, mip_aiding_frame_euler_t *out);
int mip_aiding_frame_quaternion_read(mip_reader_t *r, mip_aiding_frame_quaternion_t *out);
mip_status_t mip_aiding_frame_quaternion_write(mip_writer_t *w, const mip_aiding_frame_quaternion_t *in);
void mip_aiding_frame_quaternion_to_json(mip_jw_t *w, const mip_aiding_frame_quaternion_t *in);
int mip_aiding_frame_quaternion_from_json(mip_jr_t *jr, size_t pos, mip_aiding_frame_quaternion_t *out);
int mip_aiding_time_read(mip_reader_t *r, mip_aiding_time_t *out);
mip_status_t mip_aiding_time_write(mip_writer_t *w, const mip_aiding_time_t *in);
void mip_aiding_time_to_json(mip_jw_t *w, const mip_aiding_time_t *in);
int mip_aiding_time_from_json(mip_jr_t *jr, size_t pos, mip_aiding_time_t *out);
int mip_combination_params_read(mip_reader_t *r, mip_combination_params_t *out);
mip_status_t mip_combination_params_write(mip_writer_t *w, const mip_combination_params_t *in);
void mip_combination_params_to_json(mip_jw_t *w, const mip_combination_params_t *in);
int mip_combination_params_from_json(mip_jr_t *jr, size_t pos, mip_combination_params_t *out);
int mip_constellation_settings_read(mip_reader_t *r, mip_constellation_settings_t *out);
mip_status_t mip_constellation_settings_write(mip_writer_t *w, const mip_constellation_settings_t *in);
void mip_constellation_settings_to_json(mip_jw_t *w, const mip_constellation_settings_t *in);
int mip_constellation_settings_from_json(mip_jr_t *jr, size_t pos, mip_constellation_settings_t *out);
int mip_cv7_continuous_bit_read(mip_reader_t *r, mip_cv7_continuous_bit_t *out);
mip_status_t mip_cv7_continuous_bit_write(mip_writer_t *w, const mip_cv7_continuous_bit_t *in);
void mip_cv7_continuous_bit_to_json(mip_jw_t *w, const mip_cv7_continuous_bit_t *in);
int mip_cv7_continuous_bit_from_json(mip_jr_t *jr, size_t pos, mip_cv7_continuous_bit_t *out);
int mip_descriptor_rate_read(mip_reader_t *r, mip_descriptor_rate_t *out);
mip_status_t mip_descriptor_rate_write(mip_writer_t *w, const mip_descriptor_rate_t *in);
void mip_descriptor_rate_to_json(mip_jw_t *w, const mip_descriptor_rate_t *in);
int mip_descriptor_rate_from_json(mip_jr_t *jr, size_t pos, mip_descriptor_rate_t *out);
int mip_device_info_read(mip_reader_t *r, mip_device_info_t *out);
mip_status_t mip_device_info_write(mip_writer_t *w, const mip_device_info_t *in);
void mip_device_info_to_json(mip_jw_t *w, const mip_device_info_t *in);
int mip_device_info_from_json(mip_jr_t *jr, size_t pos, mip_device_info_t *out);
int mip_gnss_receiver_info_entry_read(mip_reader_t *r, mip_gnss_receiver_info_entry_t *out);
mip_status_t mip_gnss_receiver_info_entry_write(mip_writer_t *w, const mip_gnss_receiver_info_entry_t *in);
void mip_gnss_receiver_info_entry_to_json(mip_jw_t *w, const mip_gnss_receiver_info_entry_t *in);
int mip_gnss_receiver_info_entry_from_json(mip_jr_t *jr, size_t pos, mip_gnss_receiver_info_entry_t *out);
int mip_gpio_behavior_unused_read(mip_reader_t *r, mip_gpio_behavior_unused_t *out);
mip_status_t mip_gpio_behavior_unused_write(mip_writer_t *w, const mip_gpio_behavior_unused_t *in);
void mip_gpio_behavior_unused_to_json(mip_jw_t *w, const mip_gpio_behavior_unused_t *in);
int mip_gpio_behavior_unused_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_unused_t *out);
int mip_gpio_behavior_io_read(mip_reader_t *r, mip_gpio_behavior_io_t *out);
mip_status_t mip_gpio_behavior_io_write(mip_writer_t *w, const mip_gpio_behavior_io_t *in);
void mip_gpio_behavior_io_to_json(mip_jw_t *w, const mip_gpio_behavior_io_t *in);
int mip_gpio_behavior_io_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_io_t *out);
int mip_gpio_behavior_pps_read(mip_reader_t *r, mip_gpio_behavior_pps_t *out);
mip_status_t mip_gpio_behavior_pps_write(mip_writer_t *w, const mip_gpio_behavior_pps_t *in);
void mip_gpio_behavior_pps_to_json(mip_jw_t *w, const mip_gpio_behavior_pps_t *in);
int mip_gpio_behavior_pps_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_pps_t *out);
int mip_gpio_behavior_encoder_read(mip_reader_t *r, mip_gpio_behavior_encoder_t *out);
mip_status_t mip_gpio_behavior_encoder_write(mip_writer_t *w, const mip_gpio_behavior_encoder_t *in);
void mip_gpio_behavior_encoder_to_json(mip_jw_t *w, const mip_gpio_behavior_encoder_t *in);
int mip_gpio_behavior_encoder_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_encoder_t *out);
int mip_gpio_behavior_timestamp_read(mip_reader_t *r, mip_gpio_behavior_timestamp_t *out);
mip_status_t mip_gpio_behavior_timestamp_write(mip_writer_t *w, const mip_gpio_behavior_timestamp_t *in);
void mip_gpio_behavior_timestamp_to_json(mip_jw_t *w, const mip_gpio_behavior_timestamp_t *in);
int mip_gpio_behavior_timestamp_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_timestamp_t *out);
int mip_gpio_behavior_uart_read(mip_reader_t *r, mip_gpio_behavior_uart_t *out);
mip_status_t mip_gpio_behavior_uart_write(mip_writer_t *w, const mip_gpio_behavior_uart_t *in);
void mip_gpio_behavior_uart_to_json(mip_jw_t *w, const mip_gpio_behavior_uart_t *in);
int mip_gpio_behavior_uart_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_uart_t *out);
int mip_gx5_basic_status_read(mip_reader_t *r, mip_gx5_basic_status_t *out);
mip_status_t mip_gx5_basic_status_write(mip_writer_t *w, const mip_gx5_basic_status_t *in);
void mip_gx5_basic_status_to_json(mip_jw_t *w, const mip_gx5_basic_status_t *in);
int mip_gx5_basic_status_from_json(mip_jr_t *jr, size_t pos, mip_gx5_basic_status_t *out);
int mip_gx5_diagnostic_status_read(mip_reader_t *r, mip_gx5_diagnostic_status_t *out);
mip_status_t mip_gx5_diagnostic_status_write(mip_writer_t *w, const mip_gx5_diagnostic_status_t *in);
void mip_gx5_diagnostic_status_to_json(mip_jw_t *w, const mip_gx5_diagnostic_status_t *in);
int mip_gx5_diagnostic_status_from_json(mip_jr_t *jr, size_t pos, mip_gx5_diagnostic_status_t *out);
int mip_gx5_poll_descriptor_read(mip_reader_t *r, mip_gx5_poll_descriptor_t *out);
mip_status_t mip_gx5_poll_descriptor_write(mip_writer_t *w, const mip_gx5_poll_descriptor_t *in);
void mip_gx5_poll_descriptor_to_json(mip_jw_t *w, const mip_gx5_poll_descriptor_t *in);
int mip_gx5_poll_descriptor_from_json(mip_jr_t *jr, size_t pos, mip_gx5_poll_descriptor_t *out);
int mip_nmea_message_read(mip_reader_t *r, mip_nmea_message_t *out);
mip_status_t mip_nmea_message_write(mip_writer_t *w, const mip_nmea_message_t *in);
void mip_nmea_message_to_json(mip_jw_t *w, const mip_nmea_message_t *in);
int mip_nmea_message_from_json(mip_jr_t *jr, size_t pos, mip_nmea_message_t *out);
int mip_sensor_range_entry_read(mip_reader_t *r, mip_sensor_range_entry_t *out);
mip_status_t mip_sensor_range_entry_write(mip_writer_t *w, const mip_sensor_range_entry_t *in);
void mip_sensor_range_entry_to_json(mip_jw_t *w, const mip_sensor_range_entry_t *in);
int mip_sensor_range_entry_from_json(mip_jr_t *jr, size_t pos, mip_sensor_range_entry_t *out);
int mip_supported_action_type_read(mip_reader_t *r, mip_supported_action_type_t *out);
mip_status_t mip_supported_action_type_write(mip_writer_t *w, const mip_supported_action_type_t *in);
void mip_supported_action_type_to_json(mip_jw_t *w, const mip_supported_action_type_t *in);
int mip_supported_action_type_from_json(mip_jr_t *jr, size_t pos, mip_supported_action_type_t *out);
int mip_supported_actions_read(mip_reader_t *r, mip_supported_actions_t *out);
mip_status_t mip_supported_actions_write(mip_writer_t *w, const mip_supported_actions_t *in);
void mip_supported_actions_to_json(mip_jw_t *w, const mip_supported_actions_t *in);
int mip_supported_actions_from_json(mip_jr_t *jr, size_t pos, mip_supported_actions_t *out);
int mip_supported_trigger_type_read(mip_reader_t *r, mip_supported_trigger_type_t *out);
mip_status_t mip_supported_trigger_type_write(mip_writer_t *w, const mip_supported_trigger_type_t *in);
void mip_supported_trigger_type_to_json(mip_jw_t *w, const mip_supported_trigger_type_t *in);
int mip_supported_trigger_type_from_json(mip_jr_t *jr, size_t pos, mip_supported_trigger_type_t *out);
int mip_supported_triggers_read(mip_reader_t *r, mip_supported_triggers_t *out);
mip_status_t mip_supported_triggers_write(mip_writer_t *w, const mip_supported_triggers_t *in);
void mip_supported_triggers_to_json(mip_jw_t *w, const mip_supported_triggers_t *in);
int mip_supported_triggers_from_json(mip_jr_t *jr, size_t pos, mip_supported_triggers_t *out);
int mip_threshold_params_read(mip_reader_t *r, mip_threshold_params_t *out);
mip_status_t mip_threshold_params_write(mip_writer_t *w, const mip_threshold_params_t *in);
void mip_threshold_params_to_json(mip_jw_t *w, const mip_threshold_params_t *in);
int mip_threshold_params_from_json(mip_jr_t *jr, size_t pos, mip_threshold_params_t *out);
int mip_trigger_gpio_params_read(mip_reader_t *r, mip_trigger_gpio_params_t *out);
mip_status_t mip_trigger_gpio_params_write(mip_writer_t *w, const mip_trigger_gpio_params_t *in);
void mip_trigger_gpio_params_to_json(mip_jw_t *w, const mip_trigger_gpio_params_t *in);
int mip_trigger_gpio_params_from_json(mip_jr_t *jr, size_t pos, mip_trigger_gpio_params_t *out);
int mip_trigger_status_entry_read(mip_reader_t *r, mip_trigger_status_entry_t *out);
mip_status_t mip_trigger_status_entry_write(mip_writer_t *w, const mip_trigger_status_entry_t *in);
void mip_trigger_status_entry_to_json(mip_jw_t *w, const mip_trigger_status_entry_t *in);
int mip_trigger_status_entry_from_json(mip_jr_t *jr, size_t pos, mip_trigger_status_entry_t *out);
int mip_action_params_read(mip_reader_t *r, mip_action_type_t selector, mip_action_params_t *out);
mip_status_t mip_action_params_write(mip_writer_t *w, mip_action_type_t selector,
                                     const mip_action_params_t *in);
void mip_action_params_to_json(mip_jw_t *w, mip_action_type_t selector, const mip_action_params_t *in);
int mip_action_params_from_json(mip_jr_t *jr, size_t pos, mip_action_type_t selector,
                                mip_action_params_t *out);
int mip_aiding_frame_rotation_read(mip_reader_t *r, mip_aiding_frame_format_t selector,
                                   mip_aiding_frame_rotation_t *out);
mip_status_t mip_aiding_frame_rotation_write(mip_writer_t *w, mip_aiding_frame_format_t selector,
                                             const mip_aiding_frame_rotation_t *in);
void mip_aiding_frame_rotation_to_json(mip_jw_t *w, mip_aiding_frame_format_t selector,
                                       const mip_aiding_frame_rotation_t *in);
int mip_aiding_frame_rotation_from_json(mip_jr_t *jr, size_t pos, mip_aiding_frame_format_t selector,
                                        mip_aiding_frame_rotation_t *out);
int mip_gpio_behavior_read(mip_reader_t *r, mip_gpio_feature_t selector, mip_gpio_behavior_t *out);
mip_status_t mip_gpio_behavior_write(mip_writer_t *w, mip_gpio_feature_t selector,
                                     const mip_gpio_behavior_t *in);
void mip_gpio_behavior_to_json(mip_jw_t *w, mip_gpio_feature_t selector, const mip_gpio_behavior_t *in);
int mip_gpio_behavior_from_json(mip_jr_t *jr, size_t pos, mip_gpio_feature_t selector,
                                mip_gpio_behavior_t *out);
int mip_gx5_device_status_read(mip_reader_t *r, mip_device_status_selector_t selector,
                               mip_gx5_device_status_t *out);
mip_status_t mip_gx5_device_status_write(mip_writer_t *w, mip_device_status_selector_t selector,
                                         const mip_gx5_device_status_t *in);
void mip_gx5_device_status_to_json(mip_jw_t *w, mip_device_status_selector_t selector,
                                   const mip_gx5_device_status_t *in);
int mip_gx5_device_status_from_json(mip_jr_t *jr, size_t pos, mip_device_status_selector_t selector,
                                    mip_gx5_device_status_t *out);
int mip_supported_events_info_read(mip_reader_t *r, mip_supported_events_query_t selector,
                                   mip_supported_events_info_t *out);
mip_status_t mip_supported_events_info_write(mip_writer_t *w, mip_supported_events_query_t selector,
                                             const mip_supported_events_info_t *in);
void mip_supported_events_info_to_json(mip_jw_t *w, mip_supported_events_query_t selector,
                                       const mip_supported_events_info_t *in);
int mip_supported_events_info_from_json(mip_jr_t *jr, size_t pos, mip_supported_events_query_t selector,
                                        mip_supported_events_info_t *out);
int mip_trigger_params_read(mip_reader_t *r, mip_trigger_type_t selector, mip_trigger_params_t *out);
mip_status_t mip_trigger_params_write(mip_writer_t *w, mip_trigger_type_t selector,
                                      const mip_trigger_params_t *in);
void mip_trigger_params_to_json(mip_jw_t *w, mip_trigger_type_t selector, const mip_trigger_params_t *in);
int mip_trigger_params_from_json(mip_jr_t *jr, size_t pos, mip_trigger_type_t selector,
                                 mip_trigger_params_t *out);

#endif
