/* Private: JSON functions of every field layout. Generated: do not edit. */
#ifndef MIP_LAYOUTS_INTERNAL_H
#define MIP_LAYOUTS_INTERNAL_H

#include "mipcodec/dispatch.h"
#include "json_reader.h"
#include "json_writer.h"

void mip_ack_nack_to_json(mip_jw_t *w, const mip_ack_nack_t *in);
int mip_ack_nack_from_json(mip_jr_t *jr, size_t pos, mip_ack_nack_t *out);
void mip_base_ping_to_json(mip_jw_t *w, const mip_base_ping_t *in);
int mip_base_ping_from_json(mip_jr_t *jr, size_t pos, mip_base_ping_t *out);
void mip_base_set_to_idle_to_json(mip_jw_t *w, const mip_base_set_to_idle_t *in);
int mip_base_set_to_idle_from_json(mip_jr_t *jr, size_t pos, mip_base_set_to_idle_t *out);
void mip_base_get_device_info_to_json(mip_jw_t *w, const mip_base_get_device_info_t *in);
int mip_base_get_device_info_from_json(mip_jr_t *jr, size_t pos, mip_base_get_device_info_t *out);
void mip_base_device_info_to_json(mip_jw_t *w, const mip_base_device_info_t *in);
int mip_base_device_info_from_json(mip_jr_t *jr, size_t pos, mip_base_device_info_t *out);
void mip_base_get_device_descriptors_to_json(mip_jw_t *w, const mip_base_get_device_descriptors_t *in);
int mip_base_get_device_descriptors_from_json(mip_jr_t *jr, size_t pos,
                                              mip_base_get_device_descriptors_t *out);
void mip_base_device_descriptors_to_json(mip_jw_t *w, const mip_base_device_descriptors_t *in);
int mip_base_device_descriptors_from_json(mip_jr_t *jr, size_t pos, mip_base_device_descriptors_t *out);
void mip_base_built_in_test_to_json(mip_jw_t *w, const mip_base_built_in_test_t *in);
int mip_base_built_in_test_from_json(mip_jr_t *jr, size_t pos, mip_base_built_in_test_t *out);
void mip_base_built_in_test_result_gx5_45_to_json(mip_jw_t *w,
                                                  const mip_base_built_in_test_result_gx5_45_t *in);
int mip_base_built_in_test_result_gx5_45_from_json(mip_jr_t *jr, size_t pos,
                                                   mip_base_built_in_test_result_gx5_45_t *out);
void mip_base_built_in_test_result_cv7_ins_to_json(mip_jw_t *w,
                                                   const mip_base_built_in_test_result_cv7_ins_t *in);
int mip_base_built_in_test_result_cv7_ins_from_json(mip_jr_t *jr, size_t pos,
                                                    mip_base_built_in_test_result_cv7_ins_t *out);
void mip_base_resume_to_json(mip_jw_t *w, const mip_base_resume_t *in);
int mip_base_resume_from_json(mip_jr_t *jr, size_t pos, mip_base_resume_t *out);
void mip_base_get_extended_descriptors_to_json(mip_jw_t *w, const mip_base_get_extended_descriptors_t *in);
int mip_base_get_extended_descriptors_from_json(mip_jr_t *jr, size_t pos,
                                                mip_base_get_extended_descriptors_t *out);
void mip_base_extended_descriptors_to_json(mip_jw_t *w, const mip_base_extended_descriptors_t *in);
int mip_base_extended_descriptors_from_json(mip_jr_t *jr, size_t pos, mip_base_extended_descriptors_t *out);
void mip_base_continuous_bit_to_json(mip_jw_t *w, const mip_base_continuous_bit_t *in);
int mip_base_continuous_bit_from_json(mip_jr_t *jr, size_t pos, mip_base_continuous_bit_t *out);
void mip_base_continuous_bit_result_to_json(mip_jw_t *w, const mip_base_continuous_bit_result_t *in);
int mip_base_continuous_bit_result_from_json(mip_jr_t *jr, size_t pos, mip_base_continuous_bit_result_t *out);
void mip_base_comm_port_speed_to_json(mip_jw_t *w, const mip_base_comm_port_speed_t *in);
int mip_base_comm_port_speed_from_json(mip_jr_t *jr, size_t pos, mip_base_comm_port_speed_t *out);
void mip_base_comm_port_speed_response_to_json(mip_jw_t *w, const mip_base_comm_port_speed_response_t *in);
int mip_base_comm_port_speed_response_from_json(mip_jr_t *jr, size_t pos,
                                                mip_base_comm_port_speed_response_t *out);
void mip_base_gps_time_update_gx5_45_to_json(mip_jw_t *w, const mip_base_gps_time_update_gx5_45_t *in);
int mip_base_gps_time_update_gx5_45_from_json(mip_jr_t *jr, size_t pos,
                                              mip_base_gps_time_update_gx5_45_t *out);
void mip_base_gps_time_update_cv7_ins_to_json(mip_jw_t *w, const mip_base_gps_time_update_cv7_ins_t *in);
int mip_base_gps_time_update_cv7_ins_from_json(mip_jr_t *jr, size_t pos,
                                               mip_base_gps_time_update_cv7_ins_t *out);
void mip_base_gps_week_to_json(mip_jw_t *w, const mip_base_gps_week_t *in);
int mip_base_gps_week_from_json(mip_jr_t *jr, size_t pos, mip_base_gps_week_t *out);
void mip_base_gps_seconds_to_json(mip_jw_t *w, const mip_base_gps_seconds_t *in);
int mip_base_gps_seconds_from_json(mip_jr_t *jr, size_t pos, mip_base_gps_seconds_t *out);
void mip_base_device_reset_to_json(mip_jw_t *w, const mip_base_device_reset_t *in);
int mip_base_device_reset_from_json(mip_jr_t *jr, size_t pos, mip_base_device_reset_t *out);
void mip_threedm_event_control_to_json(mip_jw_t *w, const mip_threedm_event_control_t *in);
int mip_threedm_event_control_from_json(mip_jr_t *jr, size_t pos, mip_threedm_event_control_t *out);
void mip_threedm_event_control_response_to_json(mip_jw_t *w, const mip_threedm_event_control_response_t *in);
int mip_threedm_event_control_response_from_json(mip_jr_t *jr, size_t pos,
                                                 mip_threedm_event_control_response_t *out);
void mip_threedm_get_event_trigger_status_to_json(mip_jw_t *w,
                                                  const mip_threedm_get_event_trigger_status_t *in);
int mip_threedm_get_event_trigger_status_from_json(mip_jr_t *jr, size_t pos,
                                                   mip_threedm_get_event_trigger_status_t *out);
void mip_threedm_event_trigger_status_to_json(mip_jw_t *w, const mip_threedm_event_trigger_status_t *in);
int mip_threedm_event_trigger_status_from_json(mip_jr_t *jr, size_t pos,
                                               mip_threedm_event_trigger_status_t *out);
void mip_threedm_get_event_action_status_to_json(mip_jw_t *w,
                                                 const mip_threedm_get_event_action_status_t *in);
int mip_threedm_get_event_action_status_from_json(mip_jr_t *jr, size_t pos,
                                                  mip_threedm_get_event_action_status_t *out);
void mip_threedm_event_action_status_to_json(mip_jw_t *w, const mip_threedm_event_action_status_t *in);
int mip_threedm_event_action_status_from_json(mip_jr_t *jr, size_t pos,
                                              mip_threedm_event_action_status_t *out);
void mip_threedm_event_trigger_config_to_json(mip_jw_t *w, const mip_threedm_event_trigger_config_t *in);
int mip_threedm_event_trigger_config_from_json(mip_jr_t *jr, size_t pos,
                                               mip_threedm_event_trigger_config_t *out);
void mip_threedm_event_trigger_config_response_to_json(mip_jw_t *w,
                                                       const mip_threedm_event_trigger_config_response_t *in);
int mip_threedm_event_trigger_config_response_from_json(mip_jr_t *jr, size_t pos,
                                                        mip_threedm_event_trigger_config_response_t *out);
void mip_threedm_event_action_config_to_json(mip_jw_t *w, const mip_threedm_event_action_config_t *in);
int mip_threedm_event_action_config_from_json(mip_jr_t *jr, size_t pos,
                                              mip_threedm_event_action_config_t *out);
void mip_threedm_event_action_config_response_to_json(mip_jw_t *w,
                                                      const mip_threedm_event_action_config_response_t *in);
int mip_threedm_event_action_config_response_from_json(mip_jr_t *jr, size_t pos,
                                                       mip_threedm_event_action_config_response_t *out);
void mip_sensor_scaled_accel_to_json(mip_jw_t *w, const mip_sensor_scaled_accel_t *in);
int mip_sensor_scaled_accel_from_json(mip_jr_t *jr, size_t pos, mip_sensor_scaled_accel_t *out);
void mip_sensor_scaled_gyro_to_json(mip_jw_t *w, const mip_sensor_scaled_gyro_t *in);
int mip_sensor_scaled_gyro_from_json(mip_jr_t *jr, size_t pos, mip_sensor_scaled_gyro_t *out);
void mip_sensor_scaled_mag_to_json(mip_jw_t *w, const mip_sensor_scaled_mag_t *in);
int mip_sensor_scaled_mag_from_json(mip_jr_t *jr, size_t pos, mip_sensor_scaled_mag_t *out);

/* The "values" object of a decoded field. */
void mip_value_to_json(mip_jw_t *w, const mip_field_value_t *value);
/* Reads the "values" object of layout id into *value (sets value->id). */
int mip_value_from_json(mip_jr_t *jr, size_t pos, mip_field_id_t id, mip_field_value_t *value);

#endif
