/* Private: JSON functions of every field layout. Generated: do not edit. */
#ifndef MSCIPC_LAYOUTS_INTERNAL_H
#define MSCIPC_LAYOUTS_INTERNAL_H

#include "mscipcodec/dispatch.h"
#include "json_reader.h"
#include "json_writer.h"

/* Keeps a rarely taken path (the general reader, error details) out of line so that the common
 * path around it stays a short function without register saves. */
#if defined(__GNUC__) || defined(__clang__)
#define MSCIPC_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define MSCIPC_NOINLINE __declspec(noinline)
#else
#define MSCIPC_NOINLINE
#endif

void mscipc_ack_to_json(mscipc_jw_t *w, const mscipc_ack_t *in);
int mscipc_ack_from_json(mscipc_jr_t *jr, size_t pos, mscipc_ack_t *out);
void mscipc_base_ping_to_json(mscipc_jw_t *w, const mscipc_base_ping_t *in);
int mscipc_base_ping_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_ping_t *out);
void mscipc_base_get_device_messages_to_json(mscipc_jw_t *w, const mscipc_base_get_device_messages_t *in);
int mscipc_base_get_device_messages_from_json(mscipc_jr_t *jr, size_t pos,
                                              mscipc_base_get_device_messages_t *out);
void mscipc_base_device_messages_to_json(mscipc_jw_t *w, const mscipc_base_device_messages_t *in);
int mscipc_base_device_messages_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_messages_t *out);
void mscipc_base_device_reset_to_json(mscipc_jw_t *w, const mscipc_base_device_reset_t *in);
int mscipc_base_device_reset_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_reset_t *out);
void mscipc_base_get_device_model_to_json(mscipc_jw_t *w, const mscipc_base_get_device_model_t *in);
int mscipc_base_get_device_model_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_get_device_model_t *out);
void mscipc_base_device_model_to_json(mscipc_jw_t *w, const mscipc_base_device_model_t *in);
int mscipc_base_device_model_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_model_t *out);
void mscipc_base_get_device_sn_to_json(mscipc_jw_t *w, const mscipc_base_get_device_sn_t *in);
int mscipc_base_get_device_sn_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_get_device_sn_t *out);
void mscipc_base_device_sn_to_json(mscipc_jw_t *w, const mscipc_base_device_sn_t *in);
int mscipc_base_device_sn_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_sn_t *out);
void mscipc_base_get_device_fw_to_json(mscipc_jw_t *w, const mscipc_base_get_device_fw_t *in);
int mscipc_base_get_device_fw_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_get_device_fw_t *out);
void mscipc_base_device_fw_to_json(mscipc_jw_t *w, const mscipc_base_device_fw_t *in);
int mscipc_base_device_fw_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_fw_t *out);
void mscipc_base_get_device_cal_to_json(mscipc_jw_t *w, const mscipc_base_get_device_cal_t *in);
int mscipc_base_get_device_cal_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_get_device_cal_t *out);
void mscipc_base_device_cal_to_json(mscipc_jw_t *w, const mscipc_base_device_cal_t *in);
int mscipc_base_device_cal_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_cal_t *out);
void mscipc_base_correlate_gps_time_to_json(mscipc_jw_t *w, const mscipc_base_correlate_gps_time_t *in);
int mscipc_base_correlate_gps_time_from_json(mscipc_jr_t *jr, size_t pos,
                                             mscipc_base_correlate_gps_time_t *out);
void mscipc_imu_config_uart_baud_rate_to_json(mscipc_jw_t *w, const mscipc_imu_config_uart_baud_rate_t *in);
int mscipc_imu_config_uart_baud_rate_from_json(mscipc_jr_t *jr, size_t pos,
                                               mscipc_imu_config_uart_baud_rate_t *out);
void mscipc_imu_config_uart_baud_rate_response_to_json(mscipc_jw_t *w,
                                                       const mscipc_imu_config_uart_baud_rate_response_t *in);
int mscipc_imu_config_uart_baud_rate_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                        mscipc_imu_config_uart_baud_rate_response_t *out);
void mscipc_imu_config_filter_to_json(mscipc_jw_t *w, const mscipc_imu_config_filter_t *in);
int mscipc_imu_config_filter_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_config_filter_t *out);
void mscipc_imu_config_filter_response_to_json(mscipc_jw_t *w, const mscipc_imu_config_filter_response_t *in);
int mscipc_imu_config_filter_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                mscipc_imu_config_filter_response_t *out);
void mscipc_imu_config_sample_rate_to_json(mscipc_jw_t *w, const mscipc_imu_config_sample_rate_t *in);
int mscipc_imu_config_sample_rate_from_json(mscipc_jr_t *jr, size_t pos,
                                            mscipc_imu_config_sample_rate_t *out);
void mscipc_imu_config_sample_rate_response_to_json(mscipc_jw_t *w,
                                                    const mscipc_imu_config_sample_rate_response_t *in);
int mscipc_imu_config_sample_rate_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                     mscipc_imu_config_sample_rate_response_t *out);
void mscipc_imu_config_select_sensors_to_json(mscipc_jw_t *w, const mscipc_imu_config_select_sensors_t *in);
int mscipc_imu_config_select_sensors_from_json(mscipc_jr_t *jr, size_t pos,
                                               mscipc_imu_config_select_sensors_t *out);
void mscipc_imu_config_select_sensors_response_to_json(mscipc_jw_t *w,
                                                       const mscipc_imu_config_select_sensors_response_t *in);
int mscipc_imu_config_select_sensors_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                        mscipc_imu_config_select_sensors_response_t *out);
void mscipc_imu_config_get_internal_sample_rate_to_json(
    mscipc_jw_t *w, const mscipc_imu_config_get_internal_sample_rate_t *in);
int mscipc_imu_config_get_internal_sample_rate_from_json(mscipc_jr_t *jr, size_t pos,
                                                         mscipc_imu_config_get_internal_sample_rate_t *out);
void mscipc_imu_config_internal_sample_rate_to_json(mscipc_jw_t *w,
                                                    const mscipc_imu_config_internal_sample_rate_t *in);
int mscipc_imu_config_internal_sample_rate_from_json(mscipc_jr_t *jr, size_t pos,
                                                     mscipc_imu_config_internal_sample_rate_t *out);
void mscipc_imu_config_accel_range_to_json(mscipc_jw_t *w, const mscipc_imu_config_accel_range_t *in);
int mscipc_imu_config_accel_range_from_json(mscipc_jr_t *jr, size_t pos,
                                            mscipc_imu_config_accel_range_t *out);
void mscipc_imu_config_accel_range_response_to_json(mscipc_jw_t *w,
                                                    const mscipc_imu_config_accel_range_response_t *in);
int mscipc_imu_config_accel_range_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                     mscipc_imu_config_accel_range_response_t *out);
void mscipc_imu_config_gyro_range_to_json(mscipc_jw_t *w, const mscipc_imu_config_gyro_range_t *in);
int mscipc_imu_config_gyro_range_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_config_gyro_range_t *out);
void mscipc_imu_config_gyro_range_response_to_json(mscipc_jw_t *w,
                                                   const mscipc_imu_config_gyro_range_response_t *in);
int mscipc_imu_config_gyro_range_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                    mscipc_imu_config_gyro_range_response_t *out);
void mscipc_imu_config_config_all_to_json(mscipc_jw_t *w, const mscipc_imu_config_config_all_t *in);
int mscipc_imu_config_config_all_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_config_config_all_t *out);
void mscipc_imu_config_data_on_off_to_json(mscipc_jw_t *w, const mscipc_imu_config_data_on_off_t *in);
int mscipc_imu_config_data_on_off_from_json(mscipc_jr_t *jr, size_t pos,
                                            mscipc_imu_config_data_on_off_t *out);
void mscipc_imu_config_data_on_off_response_to_json(mscipc_jw_t *w,
                                                    const mscipc_imu_config_data_on_off_response_t *in);
int mscipc_imu_config_data_on_off_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                     mscipc_imu_config_data_on_off_response_t *out);
void mscipc_imu_config_xtrig_on_off_to_json(mscipc_jw_t *w, const mscipc_imu_config_xtrig_on_off_t *in);
int mscipc_imu_config_xtrig_on_off_from_json(mscipc_jr_t *jr, size_t pos,
                                             mscipc_imu_config_xtrig_on_off_t *out);
void mscipc_imu_config_xtrig_on_off_response_to_json(mscipc_jw_t *w,
                                                     const mscipc_imu_config_xtrig_on_off_response_t *in);
int mscipc_imu_config_xtrig_on_off_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                      mscipc_imu_config_xtrig_on_off_response_t *out);
void mscipc_imu_config_select_sensors_rev_b_to_json(mscipc_jw_t *w,
                                                    const mscipc_imu_config_select_sensors_rev_b_t *in);
int mscipc_imu_config_select_sensors_rev_b_from_json(mscipc_jr_t *jr, size_t pos,
                                                     mscipc_imu_config_select_sensors_rev_b_t *out);
void mscipc_imu_config_select_sensors_rev_b_response_to_json(
    mscipc_jw_t *w, const mscipc_imu_config_select_sensors_rev_b_response_t *in);
int mscipc_imu_config_select_sensors_rev_b_response_from_json(
    mscipc_jr_t *jr, size_t pos, mscipc_imu_config_select_sensors_rev_b_response_t *out);
void mscipc_imu_config_aux_accel_range_to_json(mscipc_jw_t *w, const mscipc_imu_config_aux_accel_range_t *in);
int mscipc_imu_config_aux_accel_range_from_json(mscipc_jr_t *jr, size_t pos,
                                                mscipc_imu_config_aux_accel_range_t *out);
void mscipc_imu_config_aux_accel_range_response_to_json(
    mscipc_jw_t *w, const mscipc_imu_config_aux_accel_range_response_t *in);
int mscipc_imu_config_aux_accel_range_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                         mscipc_imu_config_aux_accel_range_response_t *out);
void mscipc_imu_data_scaled_accel_to_json(mscipc_jw_t *w, const mscipc_imu_data_scaled_accel_t *in);
int mscipc_imu_data_scaled_accel_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_data_scaled_accel_t *out);
void mscipc_imu_data_scaled_gyro_to_json(mscipc_jw_t *w, const mscipc_imu_data_scaled_gyro_t *in);
int mscipc_imu_data_scaled_gyro_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_data_scaled_gyro_t *out);
void mscipc_imu_data_scaled_mag_to_json(mscipc_jw_t *w, const mscipc_imu_data_scaled_mag_t *in);
int mscipc_imu_data_scaled_mag_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_data_scaled_mag_t *out);
void mscipc_imu_data_delta_theta_to_json(mscipc_jw_t *w, const mscipc_imu_data_delta_theta_t *in);
int mscipc_imu_data_delta_theta_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_data_delta_theta_t *out);
void mscipc_imu_data_delta_velocity_to_json(mscipc_jw_t *w, const mscipc_imu_data_delta_velocity_t *in);
int mscipc_imu_data_delta_velocity_from_json(mscipc_jr_t *jr, size_t pos,
                                             mscipc_imu_data_delta_velocity_t *out);
void mscipc_imu_data_scaled_pressure_to_json(mscipc_jw_t *w, const mscipc_imu_data_scaled_pressure_t *in);
int mscipc_imu_data_scaled_pressure_from_json(mscipc_jr_t *jr, size_t pos,
                                              mscipc_imu_data_scaled_pressure_t *out);
void mscipc_imu_data_scaled_temperature_to_json(mscipc_jw_t *w,
                                                const mscipc_imu_data_scaled_temperature_t *in);
int mscipc_imu_data_scaled_temperature_from_json(mscipc_jr_t *jr, size_t pos,
                                                 mscipc_imu_data_scaled_temperature_t *out);
void mscipc_imu_data_gps_correlated_time_to_json(mscipc_jw_t *w,
                                                 const mscipc_imu_data_gps_correlated_time_t *in);
int mscipc_imu_data_gps_correlated_time_from_json(mscipc_jr_t *jr, size_t pos,
                                                  mscipc_imu_data_gps_correlated_time_t *out);
void mscipc_imu_data_scaled_aux_accel_to_json(mscipc_jw_t *w, const mscipc_imu_data_scaled_aux_accel_t *in);
int mscipc_imu_data_scaled_aux_accel_from_json(mscipc_jr_t *jr, size_t pos,
                                               mscipc_imu_data_scaled_aux_accel_t *out);

/* The "values" object of a decoded field. */
void mscipc_value_to_json(mscipc_jw_t *w, const mscipc_field_value_t *value);
/* The "values" object of a typed struct of layout id (in: a mscipc_<layout>_t, e.g. a member of a
 * set's packet struct that a straight-line decoder filled). */
void mscipc_layout_to_json(mscipc_jw_t *w, mscipc_field_id_t id, const void *in);
/* Reads the "values" object of layout id into *value (sets value->id). */
int mscipc_value_from_json(mscipc_jr_t *jr, size_t pos, mscipc_field_id_t id, mscipc_field_value_t *value);

#endif
