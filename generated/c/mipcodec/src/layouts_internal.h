/* Private: JSON functions of every field layout. Generated: do not edit. */
#ifndef MIPC_LAYOUTS_INTERNAL_H
#define MIPC_LAYOUTS_INTERNAL_H

#include "mipcodec/dispatch.h"
#include "json_reader.h"
#include "json_writer.h"

/* Keeps a rarely taken path (the general reader, error details) out of line so that the common
 * path around it stays a short function without register saves. */
#if defined(__GNUC__) || defined(__clang__)
#define MIPC_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define MIPC_NOINLINE __declspec(noinline)
#else
#define MIPC_NOINLINE
#endif

void mipc_ack_nack_to_json(mipc_jw_t *w, const mipc_ack_nack_t *in);
int mipc_ack_nack_from_json(mipc_jr_t *jr, size_t pos, mipc_ack_nack_t *out);
void mipc_base_ping_to_json(mipc_jw_t *w, const mipc_base_ping_t *in);
int mipc_base_ping_from_json(mipc_jr_t *jr, size_t pos, mipc_base_ping_t *out);
void mipc_base_set_to_idle_to_json(mipc_jw_t *w, const mipc_base_set_to_idle_t *in);
int mipc_base_set_to_idle_from_json(mipc_jr_t *jr, size_t pos, mipc_base_set_to_idle_t *out);
void mipc_base_get_device_info_to_json(mipc_jw_t *w, const mipc_base_get_device_info_t *in);
int mipc_base_get_device_info_from_json(mipc_jr_t *jr, size_t pos, mipc_base_get_device_info_t *out);
void mipc_base_device_info_to_json(mipc_jw_t *w, const mipc_base_device_info_t *in);
int mipc_base_device_info_from_json(mipc_jr_t *jr, size_t pos, mipc_base_device_info_t *out);
void mipc_base_get_device_descriptors_to_json(mipc_jw_t *w, const mipc_base_get_device_descriptors_t *in);
int mipc_base_get_device_descriptors_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_base_get_device_descriptors_t *out);
void mipc_base_device_descriptors_to_json(mipc_jw_t *w, const mipc_base_device_descriptors_t *in);
int mipc_base_device_descriptors_from_json(mipc_jr_t *jr, size_t pos, mipc_base_device_descriptors_t *out);
void mipc_base_built_in_test_to_json(mipc_jw_t *w, const mipc_base_built_in_test_t *in);
int mipc_base_built_in_test_from_json(mipc_jr_t *jr, size_t pos, mipc_base_built_in_test_t *out);
void mipc_base_built_in_test_result_gx5_45_to_json(mipc_jw_t *w,
                                                   const mipc_base_built_in_test_result_gx5_45_t *in);
int mipc_base_built_in_test_result_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_base_built_in_test_result_gx5_45_t *out);
void mipc_base_built_in_test_result_cv7_ins_to_json(mipc_jw_t *w,
                                                    const mipc_base_built_in_test_result_cv7_ins_t *in);
int mipc_base_built_in_test_result_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_base_built_in_test_result_cv7_ins_t *out);
void mipc_base_resume_to_json(mipc_jw_t *w, const mipc_base_resume_t *in);
int mipc_base_resume_from_json(mipc_jr_t *jr, size_t pos, mipc_base_resume_t *out);
void mipc_base_get_extended_descriptors_to_json(mipc_jw_t *w, const mipc_base_get_extended_descriptors_t *in);
int mipc_base_get_extended_descriptors_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_base_get_extended_descriptors_t *out);
void mipc_base_extended_descriptors_to_json(mipc_jw_t *w, const mipc_base_extended_descriptors_t *in);
int mipc_base_extended_descriptors_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_base_extended_descriptors_t *out);
void mipc_base_continuous_bit_to_json(mipc_jw_t *w, const mipc_base_continuous_bit_t *in);
int mipc_base_continuous_bit_from_json(mipc_jr_t *jr, size_t pos, mipc_base_continuous_bit_t *out);
void mipc_base_continuous_bit_result_to_json(mipc_jw_t *w, const mipc_base_continuous_bit_result_t *in);
int mipc_base_continuous_bit_result_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_base_continuous_bit_result_t *out);
void mipc_base_comm_port_speed_to_json(mipc_jw_t *w, const mipc_base_comm_port_speed_t *in);
int mipc_base_comm_port_speed_from_json(mipc_jr_t *jr, size_t pos, mipc_base_comm_port_speed_t *out);
void mipc_base_comm_port_speed_response_to_json(mipc_jw_t *w, const mipc_base_comm_port_speed_response_t *in);
int mipc_base_comm_port_speed_response_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_base_comm_port_speed_response_t *out);
void mipc_base_gps_time_update_gx5_45_to_json(mipc_jw_t *w, const mipc_base_gps_time_update_gx5_45_t *in);
int mipc_base_gps_time_update_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_base_gps_time_update_gx5_45_t *out);
void mipc_base_gps_time_update_cv7_ins_to_json(mipc_jw_t *w, const mipc_base_gps_time_update_cv7_ins_t *in);
int mipc_base_gps_time_update_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_base_gps_time_update_cv7_ins_t *out);
void mipc_base_gps_week_to_json(mipc_jw_t *w, const mipc_base_gps_week_t *in);
int mipc_base_gps_week_from_json(mipc_jr_t *jr, size_t pos, mipc_base_gps_week_t *out);
void mipc_base_gps_seconds_to_json(mipc_jw_t *w, const mipc_base_gps_seconds_t *in);
int mipc_base_gps_seconds_from_json(mipc_jr_t *jr, size_t pos, mipc_base_gps_seconds_t *out);
void mipc_base_device_reset_to_json(mipc_jw_t *w, const mipc_base_device_reset_t *in);
int mipc_base_device_reset_from_json(mipc_jr_t *jr, size_t pos, mipc_base_device_reset_t *out);
void mipc_threedm_event_control_to_json(mipc_jw_t *w, const mipc_threedm_event_control_t *in);
int mipc_threedm_event_control_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_event_control_t *out);
void mipc_threedm_event_control_response_to_json(mipc_jw_t *w,
                                                 const mipc_threedm_event_control_response_t *in);
int mipc_threedm_event_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_threedm_event_control_response_t *out);
void mipc_threedm_get_event_trigger_status_to_json(mipc_jw_t *w,
                                                   const mipc_threedm_get_event_trigger_status_t *in);
int mipc_threedm_get_event_trigger_status_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_threedm_get_event_trigger_status_t *out);
void mipc_threedm_event_trigger_status_to_json(mipc_jw_t *w, const mipc_threedm_event_trigger_status_t *in);
int mipc_threedm_event_trigger_status_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_event_trigger_status_t *out);
void mipc_threedm_get_event_action_status_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_get_event_action_status_t *in);
int mipc_threedm_get_event_action_status_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_get_event_action_status_t *out);
void mipc_threedm_event_action_status_to_json(mipc_jw_t *w, const mipc_threedm_event_action_status_t *in);
int mipc_threedm_event_action_status_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_event_action_status_t *out);
void mipc_threedm_event_trigger_config_to_json(mipc_jw_t *w, const mipc_threedm_event_trigger_config_t *in);
int mipc_threedm_event_trigger_config_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_event_trigger_config_t *out);
void mipc_threedm_event_trigger_config_response_to_json(
    mipc_jw_t *w, const mipc_threedm_event_trigger_config_response_t *in);
int mipc_threedm_event_trigger_config_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_threedm_event_trigger_config_response_t *out);
void mipc_threedm_event_action_config_to_json(mipc_jw_t *w, const mipc_threedm_event_action_config_t *in);
int mipc_threedm_event_action_config_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_event_action_config_t *out);
void mipc_threedm_event_action_config_response_to_json(mipc_jw_t *w,
                                                       const mipc_threedm_event_action_config_response_t *in);
int mipc_threedm_event_action_config_response_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_event_action_config_response_t *out);
void mipc_threedm_device_startup_settings_gx5_45_to_json(
    mipc_jw_t *w, const mipc_threedm_device_startup_settings_gx5_45_t *in);
int mipc_threedm_device_startup_settings_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                          mipc_threedm_device_startup_settings_gx5_45_t *out);
void mipc_threedm_device_startup_settings_cv7_ins_to_json(
    mipc_jw_t *w, const mipc_threedm_device_startup_settings_cv7_ins_t *in);
int mipc_threedm_device_startup_settings_cv7_ins_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_device_startup_settings_cv7_ins_t *out);
void mipc_threedm_sensor_to_vehicle_euler_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_sensor_to_vehicle_euler_t *in);
int mipc_threedm_sensor_to_vehicle_euler_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_sensor_to_vehicle_euler_t *out);
void mipc_threedm_sensor_to_vehicle_euler_response_to_json(
    mipc_jw_t *w, const mipc_threedm_sensor_to_vehicle_euler_response_t *in);
int mipc_threedm_sensor_to_vehicle_euler_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_sensor_to_vehicle_euler_response_t *out);
void mipc_threedm_sensor_to_vehicle_quaternion_to_json(mipc_jw_t *w,
                                                       const mipc_threedm_sensor_to_vehicle_quaternion_t *in);
int mipc_threedm_sensor_to_vehicle_quaternion_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_sensor_to_vehicle_quaternion_t *out);
void mipc_threedm_sensor_to_vehicle_quaternion_response_to_json(
    mipc_jw_t *w, const mipc_threedm_sensor_to_vehicle_quaternion_response_t *in);
int mipc_threedm_sensor_to_vehicle_quaternion_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out);
void mipc_threedm_sensor_to_vehicle_dcm_to_json(mipc_jw_t *w, const mipc_threedm_sensor_to_vehicle_dcm_t *in);
int mipc_threedm_sensor_to_vehicle_dcm_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_threedm_sensor_to_vehicle_dcm_t *out);
void mipc_threedm_sensor_to_vehicle_dcm_response_to_json(
    mipc_jw_t *w, const mipc_threedm_sensor_to_vehicle_dcm_response_t *in);
int mipc_threedm_sensor_to_vehicle_dcm_response_from_json(mipc_jr_t *jr, size_t pos,
                                                          mipc_threedm_sensor_to_vehicle_dcm_response_t *out);
void mipc_threedm_accel_bias_gx5_45_to_json(mipc_jw_t *w, const mipc_threedm_accel_bias_gx5_45_t *in);
int mipc_threedm_accel_bias_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_threedm_accel_bias_gx5_45_t *out);
void mipc_threedm_accel_bias_cv7_ins_to_json(mipc_jw_t *w, const mipc_threedm_accel_bias_cv7_ins_t *in);
int mipc_threedm_accel_bias_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_threedm_accel_bias_cv7_ins_t *out);
void mipc_threedm_accel_bias_response_to_json(mipc_jw_t *w, const mipc_threedm_accel_bias_response_t *in);
int mipc_threedm_accel_bias_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_accel_bias_response_t *out);
void mipc_threedm_gyro_bias_gx5_45_to_json(mipc_jw_t *w, const mipc_threedm_gyro_bias_gx5_45_t *in);
int mipc_threedm_gyro_bias_gx5_45_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_gyro_bias_gx5_45_t *out);
void mipc_threedm_gyro_bias_cv7_ins_to_json(mipc_jw_t *w, const mipc_threedm_gyro_bias_cv7_ins_t *in);
int mipc_threedm_gyro_bias_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_threedm_gyro_bias_cv7_ins_t *out);
void mipc_threedm_gyro_bias_response_to_json(mipc_jw_t *w, const mipc_threedm_gyro_bias_response_t *in);
int mipc_threedm_gyro_bias_response_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_threedm_gyro_bias_response_t *out);
void mipc_threedm_capture_gyro_bias_to_json(mipc_jw_t *w, const mipc_threedm_capture_gyro_bias_t *in);
int mipc_threedm_capture_gyro_bias_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_threedm_capture_gyro_bias_t *out);
void mipc_threedm_mag_hard_iron_offset_gx5_45_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_mag_hard_iron_offset_gx5_45_t *in);
int mipc_threedm_mag_hard_iron_offset_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_mag_hard_iron_offset_gx5_45_t *out);
void mipc_threedm_mag_hard_iron_offset_cv7_ins_to_json(mipc_jw_t *w,
                                                       const mipc_threedm_mag_hard_iron_offset_cv7_ins_t *in);
int mipc_threedm_mag_hard_iron_offset_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_mag_hard_iron_offset_cv7_ins_t *out);
void mipc_threedm_mag_hard_iron_offset_response_to_json(
    mipc_jw_t *w, const mipc_threedm_mag_hard_iron_offset_response_t *in);
int mipc_threedm_mag_hard_iron_offset_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_threedm_mag_hard_iron_offset_response_t *out);
void mipc_threedm_mag_soft_iron_matrix_gx5_45_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_mag_soft_iron_matrix_gx5_45_t *in);
int mipc_threedm_mag_soft_iron_matrix_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_mag_soft_iron_matrix_gx5_45_t *out);
void mipc_threedm_mag_soft_iron_matrix_cv7_ins_to_json(mipc_jw_t *w,
                                                       const mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *in);
int mipc_threedm_mag_soft_iron_matrix_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *out);
void mipc_threedm_mag_soft_iron_matrix_response_to_json(
    mipc_jw_t *w, const mipc_threedm_mag_soft_iron_matrix_response_t *in);
int mipc_threedm_mag_soft_iron_matrix_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_threedm_mag_soft_iron_matrix_response_t *out);
void mipc_threedm_coning_sculling_enable_to_json(mipc_jw_t *w,
                                                 const mipc_threedm_coning_sculling_enable_t *in);
int mipc_threedm_coning_sculling_enable_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_threedm_coning_sculling_enable_t *out);
void mipc_threedm_coning_sculling_enable_response_to_json(
    mipc_jw_t *w, const mipc_threedm_coning_sculling_enable_response_t *in);
int mipc_threedm_coning_sculling_enable_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_coning_sculling_enable_response_t *out);
void mipc_threedm_uart_baudrate_to_json(mipc_jw_t *w, const mipc_threedm_uart_baudrate_t *in);
int mipc_threedm_uart_baudrate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_uart_baudrate_t *out);
void mipc_threedm_uart_baudrate_response_to_json(mipc_jw_t *w,
                                                 const mipc_threedm_uart_baudrate_response_t *in);
int mipc_threedm_uart_baudrate_response_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_threedm_uart_baudrate_response_t *out);
void mipc_threedm_gpio_config_to_json(mipc_jw_t *w, const mipc_threedm_gpio_config_t *in);
int mipc_threedm_gpio_config_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_gpio_config_t *out);
void mipc_threedm_gpio_config_response_to_json(mipc_jw_t *w, const mipc_threedm_gpio_config_response_t *in);
int mipc_threedm_gpio_config_response_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_gpio_config_response_t *out);
void mipc_threedm_gpio_state_to_json(mipc_jw_t *w, const mipc_threedm_gpio_state_t *in);
int mipc_threedm_gpio_state_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_gpio_state_t *out);
void mipc_threedm_gpio_state_response_to_json(mipc_jw_t *w, const mipc_threedm_gpio_state_response_t *in);
int mipc_threedm_gpio_state_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_gpio_state_response_t *out);
void mipc_threedm_odometer_config_to_json(mipc_jw_t *w, const mipc_threedm_odometer_config_t *in);
int mipc_threedm_odometer_config_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_odometer_config_t *out);
void mipc_threedm_odometer_config_response_to_json(mipc_jw_t *w,
                                                   const mipc_threedm_odometer_config_response_t *in);
int mipc_threedm_odometer_config_response_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_threedm_odometer_config_response_t *out);
void mipc_threedm_advanced_lowpass_filter_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_advanced_lowpass_filter_t *in);
int mipc_threedm_advanced_lowpass_filter_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_advanced_lowpass_filter_t *out);
void mipc_threedm_advanced_lowpass_filter_response_to_json(
    mipc_jw_t *w, const mipc_threedm_advanced_lowpass_filter_response_t *in);
int mipc_threedm_advanced_lowpass_filter_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_advanced_lowpass_filter_response_t *out);
void mipc_threedm_complementary_filter_to_json(mipc_jw_t *w, const mipc_threedm_complementary_filter_t *in);
int mipc_threedm_complementary_filter_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_complementary_filter_t *out);
void mipc_threedm_complementary_filter_response_to_json(
    mipc_jw_t *w, const mipc_threedm_complementary_filter_response_t *in);
int mipc_threedm_complementary_filter_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_threedm_complementary_filter_response_t *out);
void mipc_threedm_sensor_range_to_json(mipc_jw_t *w, const mipc_threedm_sensor_range_t *in);
int mipc_threedm_sensor_range_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_sensor_range_t *out);
void mipc_threedm_sensor_range_response_to_json(mipc_jw_t *w, const mipc_threedm_sensor_range_response_t *in);
int mipc_threedm_sensor_range_response_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_threedm_sensor_range_response_t *out);
void mipc_threedm_get_calibrated_sensor_ranges_to_json(mipc_jw_t *w,
                                                       const mipc_threedm_get_calibrated_sensor_ranges_t *in);
int mipc_threedm_get_calibrated_sensor_ranges_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_get_calibrated_sensor_ranges_t *out);
void mipc_threedm_calibrated_sensor_ranges_to_json(mipc_jw_t *w,
                                                   const mipc_threedm_calibrated_sensor_ranges_t *in);
int mipc_threedm_calibrated_sensor_ranges_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_threedm_calibrated_sensor_ranges_t *out);
void mipc_threedm_lowpass_filter_to_json(mipc_jw_t *w, const mipc_threedm_lowpass_filter_t *in);
int mipc_threedm_lowpass_filter_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_lowpass_filter_t *out);
void mipc_threedm_lowpass_filter_response_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_lowpass_filter_response_t *in);
int mipc_threedm_lowpass_filter_response_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_lowpass_filter_response_t *out);
void mipc_threedm_poll_imu_data_to_json(mipc_jw_t *w, const mipc_threedm_poll_imu_data_t *in);
int mipc_threedm_poll_imu_data_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_poll_imu_data_t *out);
void mipc_threedm_poll_gnss_data_to_json(mipc_jw_t *w, const mipc_threedm_poll_gnss_data_t *in);
int mipc_threedm_poll_gnss_data_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_poll_gnss_data_t *out);
void mipc_threedm_poll_filter_data_to_json(mipc_jw_t *w, const mipc_threedm_poll_filter_data_t *in);
int mipc_threedm_poll_filter_data_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_poll_filter_data_t *out);
void mipc_threedm_poll_nmea_data_to_json(mipc_jw_t *w, const mipc_threedm_poll_nmea_data_t *in);
int mipc_threedm_poll_nmea_data_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_poll_nmea_data_t *out);
void mipc_threedm_poll_data_to_json(mipc_jw_t *w, const mipc_threedm_poll_data_t *in);
int mipc_threedm_poll_data_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_poll_data_t *out);
void mipc_threedm_get_imu_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_get_imu_base_rate_t *in);
int mipc_threedm_get_imu_base_rate_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_threedm_get_imu_base_rate_t *out);
void mipc_threedm_imu_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_imu_base_rate_t *in);
int mipc_threedm_imu_base_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_imu_base_rate_t *out);
void mipc_threedm_get_gnss_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_get_gnss_base_rate_t *in);
int mipc_threedm_get_gnss_base_rate_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_threedm_get_gnss_base_rate_t *out);
void mipc_threedm_gnss_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_gnss_base_rate_t *in);
int mipc_threedm_gnss_base_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_gnss_base_rate_t *out);
void mipc_threedm_get_filter_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_get_filter_base_rate_t *in);
int mipc_threedm_get_filter_base_rate_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_get_filter_base_rate_t *out);
void mipc_threedm_filter_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_filter_base_rate_t *in);
int mipc_threedm_filter_base_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_filter_base_rate_t *out);
void mipc_threedm_get_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_get_base_rate_t *in);
int mipc_threedm_get_base_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_get_base_rate_t *out);
void mipc_threedm_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_base_rate_t *in);
int mipc_threedm_base_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_base_rate_t *out);
void mipc_threedm_imu_message_format_to_json(mipc_jw_t *w, const mipc_threedm_imu_message_format_t *in);
int mipc_threedm_imu_message_format_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_threedm_imu_message_format_t *out);
void mipc_threedm_imu_message_format_response_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_imu_message_format_response_t *in);
int mipc_threedm_imu_message_format_response_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_imu_message_format_response_t *out);
void mipc_threedm_gnss_message_format_to_json(mipc_jw_t *w, const mipc_threedm_gnss_message_format_t *in);
int mipc_threedm_gnss_message_format_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_gnss_message_format_t *out);
void mipc_threedm_gnss_message_format_response_to_json(mipc_jw_t *w,
                                                       const mipc_threedm_gnss_message_format_response_t *in);
int mipc_threedm_gnss_message_format_response_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_gnss_message_format_response_t *out);
void mipc_threedm_filter_message_format_to_json(mipc_jw_t *w, const mipc_threedm_filter_message_format_t *in);
int mipc_threedm_filter_message_format_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_threedm_filter_message_format_t *out);
void mipc_threedm_filter_message_format_response_to_json(
    mipc_jw_t *w, const mipc_threedm_filter_message_format_response_t *in);
int mipc_threedm_filter_message_format_response_from_json(mipc_jr_t *jr, size_t pos,
                                                          mipc_threedm_filter_message_format_response_t *out);
void mipc_threedm_nmea_message_format_to_json(mipc_jw_t *w, const mipc_threedm_nmea_message_format_t *in);
int mipc_threedm_nmea_message_format_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_nmea_message_format_t *out);
void mipc_threedm_nmea_message_format_response_to_json(mipc_jw_t *w,
                                                       const mipc_threedm_nmea_message_format_response_t *in);
int mipc_threedm_nmea_message_format_response_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_nmea_message_format_response_t *out);
void mipc_threedm_message_format_to_json(mipc_jw_t *w, const mipc_threedm_message_format_t *in);
int mipc_threedm_message_format_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_message_format_t *out);
void mipc_threedm_message_format_response_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_message_format_response_t *in);
int mipc_threedm_message_format_response_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_message_format_response_t *out);
void mipc_threedm_factory_streaming_to_json(mipc_jw_t *w, const mipc_threedm_factory_streaming_t *in);
int mipc_threedm_factory_streaming_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_threedm_factory_streaming_t *out);
void mipc_threedm_data_stream_control_gx5_45_to_json(mipc_jw_t *w,
                                                     const mipc_threedm_data_stream_control_gx5_45_t *in);
int mipc_threedm_data_stream_control_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_threedm_data_stream_control_gx5_45_t *out);
void mipc_threedm_data_stream_control_cv7_ins_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_data_stream_control_cv7_ins_t *in);
int mipc_threedm_data_stream_control_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_data_stream_control_cv7_ins_t *out);
void mipc_threedm_data_stream_control_response_gx5_45_to_json(
    mipc_jw_t *w, const mipc_threedm_data_stream_control_response_gx5_45_t *in);
int mipc_threedm_data_stream_control_response_gx5_45_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_data_stream_control_response_gx5_45_t *out);
void mipc_threedm_data_stream_control_response_cv7_ins_to_json(
    mipc_jw_t *w, const mipc_threedm_data_stream_control_response_cv7_ins_t *in);
int mipc_threedm_data_stream_control_response_cv7_ins_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_data_stream_control_response_cv7_ins_t *out);
void mipc_threedm_raw_rtcm_message_to_json(mipc_jw_t *w, const mipc_threedm_raw_rtcm_message_t *in);
int mipc_threedm_raw_rtcm_message_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_raw_rtcm_message_t *out);
void mipc_threedm_gnss_constellation_settings_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_gnss_constellation_settings_t *in);
int mipc_threedm_gnss_constellation_settings_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_gnss_constellation_settings_t *out);
void mipc_threedm_gnss_constellation_settings_response_to_json(
    mipc_jw_t *w, const mipc_threedm_gnss_constellation_settings_response_t *in);
int mipc_threedm_gnss_constellation_settings_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_gnss_constellation_settings_response_t *out);
void mipc_threedm_gnss_sbas_settings_to_json(mipc_jw_t *w, const mipc_threedm_gnss_sbas_settings_t *in);
int mipc_threedm_gnss_sbas_settings_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_threedm_gnss_sbas_settings_t *out);
void mipc_threedm_gnss_sbas_settings_response_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_gnss_sbas_settings_response_t *in);
int mipc_threedm_gnss_sbas_settings_response_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_gnss_sbas_settings_response_t *out);
void mipc_threedm_gnss_assisted_fix_control_to_json(mipc_jw_t *w,
                                                    const mipc_threedm_gnss_assisted_fix_control_t *in);
int mipc_threedm_gnss_assisted_fix_control_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_threedm_gnss_assisted_fix_control_t *out);
void mipc_threedm_gnss_assisted_fix_control_response_to_json(
    mipc_jw_t *w, const mipc_threedm_gnss_assisted_fix_control_response_t *in);
int mipc_threedm_gnss_assisted_fix_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_gnss_assisted_fix_control_response_t *out);
void mipc_threedm_gnss_assist_time_update_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_gnss_assist_time_update_t *in);
int mipc_threedm_gnss_assist_time_update_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_gnss_assist_time_update_t *out);
void mipc_threedm_gnss_assist_time_update_response_to_json(
    mipc_jw_t *w, const mipc_threedm_gnss_assist_time_update_response_t *in);
int mipc_threedm_gnss_assist_time_update_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_gnss_assist_time_update_response_t *out);
void mipc_threedm_pps_source_to_json(mipc_jw_t *w, const mipc_threedm_pps_source_t *in);
int mipc_threedm_pps_source_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_pps_source_t *out);
void mipc_threedm_pps_source_response_to_json(mipc_jw_t *w, const mipc_threedm_pps_source_response_t *in);
int mipc_threedm_pps_source_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_pps_source_response_t *out);
void mipc_threedm_get_supported_events_to_json(mipc_jw_t *w, const mipc_threedm_get_supported_events_t *in);
int mipc_threedm_get_supported_events_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_get_supported_events_t *out);
void mipc_threedm_supported_events_to_json(mipc_jw_t *w, const mipc_threedm_supported_events_t *in);
int mipc_threedm_supported_events_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_supported_events_t *out);
void mipc_threedm_device_status_to_json(mipc_jw_t *w, const mipc_threedm_device_status_t *in);
int mipc_threedm_device_status_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_device_status_t *out);
void mipc_threedm_device_status_response_to_json(mipc_jw_t *w,
                                                 const mipc_threedm_device_status_response_t *in);
int mipc_threedm_device_status_response_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_threedm_device_status_response_t *out);
void mipc_filter_reset_filter_to_json(mipc_jw_t *w, const mipc_filter_reset_filter_t *in);
int mipc_filter_reset_filter_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_reset_filter_t *out);
void mipc_filter_set_initial_attitude_to_json(mipc_jw_t *w, const mipc_filter_set_initial_attitude_t *in);
int mipc_filter_set_initial_attitude_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_set_initial_attitude_t *out);
void mipc_filter_set_initial_heading_to_json(mipc_jw_t *w, const mipc_filter_set_initial_heading_t *in);
int mipc_filter_set_initial_heading_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_set_initial_heading_t *out);
void mipc_filter_run_filter_to_json(mipc_jw_t *w, const mipc_filter_run_filter_t *in);
int mipc_filter_run_filter_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_run_filter_t *out);
void mipc_filter_vehicle_dynamics_mode_to_json(mipc_jw_t *w, const mipc_filter_vehicle_dynamics_mode_t *in);
int mipc_filter_vehicle_dynamics_mode_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_filter_vehicle_dynamics_mode_t *out);
void mipc_filter_vehicle_dynamics_mode_response_to_json(
    mipc_jw_t *w, const mipc_filter_vehicle_dynamics_mode_response_t *in);
int mipc_filter_vehicle_dynamics_mode_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_vehicle_dynamics_mode_response_t *out);
void mipc_filter_sensor_to_vehicle_transform_to_json(mipc_jw_t *w,
                                                     const mipc_filter_sensor_to_vehicle_transform_t *in);
int mipc_filter_sensor_to_vehicle_transform_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_sensor_to_vehicle_transform_t *out);
void mipc_filter_sensor_to_vehicle_transform_response_to_json(
    mipc_jw_t *w, const mipc_filter_sensor_to_vehicle_transform_response_t *in);
int mipc_filter_sensor_to_vehicle_transform_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_sensor_to_vehicle_transform_response_t *out);
void mipc_filter_sensor_to_vehicle_offset_to_json(mipc_jw_t *w,
                                                  const mipc_filter_sensor_to_vehicle_offset_t *in);
int mipc_filter_sensor_to_vehicle_offset_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_sensor_to_vehicle_offset_t *out);
void mipc_filter_sensor_to_vehicle_offset_response_to_json(
    mipc_jw_t *w, const mipc_filter_sensor_to_vehicle_offset_response_t *in);
int mipc_filter_sensor_to_vehicle_offset_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_sensor_to_vehicle_offset_response_t *out);
void mipc_filter_antenna_offset_to_json(mipc_jw_t *w, const mipc_filter_antenna_offset_t *in);
int mipc_filter_antenna_offset_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_antenna_offset_t *out);
void mipc_filter_antenna_offset_response_to_json(mipc_jw_t *w,
                                                 const mipc_filter_antenna_offset_response_t *in);
int mipc_filter_antenna_offset_response_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_antenna_offset_response_t *out);
void mipc_filter_estimation_control_to_json(mipc_jw_t *w, const mipc_filter_estimation_control_t *in);
int mipc_filter_estimation_control_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_estimation_control_t *out);
void mipc_filter_estimation_control_response_to_json(mipc_jw_t *w,
                                                     const mipc_filter_estimation_control_response_t *in);
int mipc_filter_estimation_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_estimation_control_response_t *out);
void mipc_filter_gnss_source_control_to_json(mipc_jw_t *w, const mipc_filter_gnss_source_control_t *in);
int mipc_filter_gnss_source_control_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_gnss_source_control_t *out);
void mipc_filter_gnss_source_control_response_to_json(mipc_jw_t *w,
                                                      const mipc_filter_gnss_source_control_response_t *in);
int mipc_filter_gnss_source_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_gnss_source_control_response_t *out);
void mipc_filter_external_gnss_update_to_json(mipc_jw_t *w, const mipc_filter_external_gnss_update_t *in);
int mipc_filter_external_gnss_update_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_external_gnss_update_t *out);
void mipc_filter_external_heading_update_to_json(mipc_jw_t *w,
                                                 const mipc_filter_external_heading_update_t *in);
int mipc_filter_external_heading_update_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_external_heading_update_t *out);
void mipc_filter_heading_update_control_to_json(mipc_jw_t *w, const mipc_filter_heading_update_control_t *in);
int mipc_filter_heading_update_control_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_heading_update_control_t *out);
void mipc_filter_heading_update_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_heading_update_control_response_t *in);
int mipc_filter_heading_update_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                          mipc_filter_heading_update_control_response_t *out);
void mipc_filter_auto_init_control_to_json(mipc_jw_t *w, const mipc_filter_auto_init_control_t *in);
int mipc_filter_auto_init_control_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_auto_init_control_t *out);
void mipc_filter_auto_init_control_response_to_json(mipc_jw_t *w,
                                                    const mipc_filter_auto_init_control_response_t *in);
int mipc_filter_auto_init_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_auto_init_control_response_t *out);
void mipc_filter_accel_noise_to_json(mipc_jw_t *w, const mipc_filter_accel_noise_t *in);
int mipc_filter_accel_noise_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_accel_noise_t *out);
void mipc_filter_accel_noise_response_to_json(mipc_jw_t *w, const mipc_filter_accel_noise_response_t *in);
int mipc_filter_accel_noise_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_accel_noise_response_t *out);
void mipc_filter_gyro_noise_to_json(mipc_jw_t *w, const mipc_filter_gyro_noise_t *in);
int mipc_filter_gyro_noise_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_gyro_noise_t *out);
void mipc_filter_gyro_noise_response_to_json(mipc_jw_t *w, const mipc_filter_gyro_noise_response_t *in);
int mipc_filter_gyro_noise_response_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_gyro_noise_response_t *out);
void mipc_filter_accel_bias_model_to_json(mipc_jw_t *w, const mipc_filter_accel_bias_model_t *in);
int mipc_filter_accel_bias_model_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_accel_bias_model_t *out);
void mipc_filter_accel_bias_model_response_to_json(mipc_jw_t *w,
                                                   const mipc_filter_accel_bias_model_response_t *in);
int mipc_filter_accel_bias_model_response_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_accel_bias_model_response_t *out);
void mipc_filter_gyro_bias_model_to_json(mipc_jw_t *w, const mipc_filter_gyro_bias_model_t *in);
int mipc_filter_gyro_bias_model_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_gyro_bias_model_t *out);
void mipc_filter_gyro_bias_model_response_to_json(mipc_jw_t *w,
                                                  const mipc_filter_gyro_bias_model_response_t *in);
int mipc_filter_gyro_bias_model_response_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_gyro_bias_model_response_t *out);
void mipc_filter_zupt_control_to_json(mipc_jw_t *w, const mipc_filter_zupt_control_t *in);
int mipc_filter_zupt_control_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_zupt_control_t *out);
void mipc_filter_zupt_control_response_to_json(mipc_jw_t *w, const mipc_filter_zupt_control_response_t *in);
int mipc_filter_zupt_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_filter_zupt_control_response_t *out);
void mipc_filter_external_heading_update_with_time_to_json(
    mipc_jw_t *w, const mipc_filter_external_heading_update_with_time_t *in);
int mipc_filter_external_heading_update_with_time_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_external_heading_update_with_time_t *out);
void mipc_filter_zero_angular_rate_update_control_to_json(
    mipc_jw_t *w, const mipc_filter_zero_angular_rate_update_control_t *in);
int mipc_filter_zero_angular_rate_update_control_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_zero_angular_rate_update_control_t *out);
void mipc_filter_zero_angular_rate_update_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_zero_angular_rate_update_control_response_t *in);
int mipc_filter_zero_angular_rate_update_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_zero_angular_rate_update_control_response_t *out);
void mipc_filter_tare_orientation_to_json(mipc_jw_t *w, const mipc_filter_tare_orientation_t *in);
int mipc_filter_tare_orientation_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_tare_orientation_t *out);
void mipc_filter_commanded_zupt_to_json(mipc_jw_t *w, const mipc_filter_commanded_zupt_t *in);
int mipc_filter_commanded_zupt_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_commanded_zupt_t *out);
void mipc_filter_commanded_zero_angular_rate_update_to_json(
    mipc_jw_t *w, const mipc_filter_commanded_zero_angular_rate_update_t *in);
int mipc_filter_commanded_zero_angular_rate_update_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_commanded_zero_angular_rate_update_t *out);
void mipc_filter_mag_capture_auto_calibration_to_json(mipc_jw_t *w,
                                                      const mipc_filter_mag_capture_auto_calibration_t *in);
int mipc_filter_mag_capture_auto_calibration_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_mag_capture_auto_calibration_t *out);
void mipc_filter_gravity_noise_std_dev_to_json(mipc_jw_t *w, const mipc_filter_gravity_noise_std_dev_t *in);
int mipc_filter_gravity_noise_std_dev_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_filter_gravity_noise_std_dev_t *out);
void mipc_filter_gravity_noise_std_dev_response_to_json(
    mipc_jw_t *w, const mipc_filter_gravity_noise_std_dev_response_t *in);
int mipc_filter_gravity_noise_std_dev_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_gravity_noise_std_dev_response_t *out);
void mipc_filter_pressure_altitude_noise_std_dev_to_json(
    mipc_jw_t *w, const mipc_filter_pressure_altitude_noise_std_dev_t *in);
int mipc_filter_pressure_altitude_noise_std_dev_from_json(mipc_jr_t *jr, size_t pos,
                                                          mipc_filter_pressure_altitude_noise_std_dev_t *out);
void mipc_filter_pressure_altitude_noise_std_dev_response_to_json(
    mipc_jw_t *w, const mipc_filter_pressure_altitude_noise_std_dev_response_t *in);
int mipc_filter_pressure_altitude_noise_std_dev_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_pressure_altitude_noise_std_dev_response_t *out);
void mipc_filter_hard_iron_offset_noise_to_json(mipc_jw_t *w, const mipc_filter_hard_iron_offset_noise_t *in);
int mipc_filter_hard_iron_offset_noise_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_hard_iron_offset_noise_t *out);
void mipc_filter_hard_iron_offset_noise_response_to_json(
    mipc_jw_t *w, const mipc_filter_hard_iron_offset_noise_response_t *in);
int mipc_filter_hard_iron_offset_noise_response_from_json(mipc_jr_t *jr, size_t pos,
                                                          mipc_filter_hard_iron_offset_noise_response_t *out);
void mipc_filter_soft_iron_matrix_noise_to_json(mipc_jw_t *w, const mipc_filter_soft_iron_matrix_noise_t *in);
int mipc_filter_soft_iron_matrix_noise_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_soft_iron_matrix_noise_t *out);
void mipc_filter_soft_iron_matrix_noise_response_to_json(
    mipc_jw_t *w, const mipc_filter_soft_iron_matrix_noise_response_t *in);
int mipc_filter_soft_iron_matrix_noise_response_from_json(mipc_jr_t *jr, size_t pos,
                                                          mipc_filter_soft_iron_matrix_noise_response_t *out);
void mipc_filter_mag_noise_std_dev_to_json(mipc_jw_t *w, const mipc_filter_mag_noise_std_dev_t *in);
int mipc_filter_mag_noise_std_dev_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_mag_noise_std_dev_t *out);
void mipc_filter_mag_noise_std_dev_response_to_json(mipc_jw_t *w,
                                                    const mipc_filter_mag_noise_std_dev_response_t *in);
int mipc_filter_mag_noise_std_dev_response_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_mag_noise_std_dev_response_t *out);
void mipc_filter_declination_source_to_json(mipc_jw_t *w, const mipc_filter_declination_source_t *in);
int mipc_filter_declination_source_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_declination_source_t *out);
void mipc_filter_declination_source_response_to_json(mipc_jw_t *w,
                                                     const mipc_filter_declination_source_response_t *in);
int mipc_filter_declination_source_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_declination_source_response_t *out);
void mipc_filter_gravity_magnitude_adaptive_measurement_to_json(
    mipc_jw_t *w, const mipc_filter_gravity_magnitude_adaptive_measurement_t *in);
int mipc_filter_gravity_magnitude_adaptive_measurement_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gravity_magnitude_adaptive_measurement_t *out);
void mipc_filter_gravity_magnitude_adaptive_measurement_response_to_json(
    mipc_jw_t *w, const mipc_filter_gravity_magnitude_adaptive_measurement_response_t *in);
int mipc_filter_gravity_magnitude_adaptive_measurement_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *out);
void mipc_filter_mag_magnitude_adaptive_measurement_to_json(
    mipc_jw_t *w, const mipc_filter_mag_magnitude_adaptive_measurement_t *in);
int mipc_filter_mag_magnitude_adaptive_measurement_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_magnitude_adaptive_measurement_t *out);
void mipc_filter_mag_magnitude_adaptive_measurement_response_to_json(
    mipc_jw_t *w, const mipc_filter_mag_magnitude_adaptive_measurement_response_t *in);
int mipc_filter_mag_magnitude_adaptive_measurement_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_magnitude_adaptive_measurement_response_t *out);
void mipc_filter_mag_dip_angle_adaptive_measurement_to_json(
    mipc_jw_t *w, const mipc_filter_mag_dip_angle_adaptive_measurement_t *in);
int mipc_filter_mag_dip_angle_adaptive_measurement_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_dip_angle_adaptive_measurement_t *out);
void mipc_filter_mag_dip_angle_adaptive_measurement_response_to_json(
    mipc_jw_t *w, const mipc_filter_mag_dip_angle_adaptive_measurement_response_t *in);
int mipc_filter_mag_dip_angle_adaptive_measurement_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *out);
void mipc_filter_altitude_aiding_control_to_json(mipc_jw_t *w,
                                                 const mipc_filter_altitude_aiding_control_t *in);
int mipc_filter_altitude_aiding_control_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_altitude_aiding_control_t *out);
void mipc_filter_altitude_aiding_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_altitude_aiding_control_response_t *in);
int mipc_filter_altitude_aiding_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_altitude_aiding_control_response_t *out);
void mipc_filter_pitch_roll_aiding_control_to_json(mipc_jw_t *w,
                                                   const mipc_filter_pitch_roll_aiding_control_t *in);
int mipc_filter_pitch_roll_aiding_control_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_pitch_roll_aiding_control_t *out);
void mipc_filter_pitch_roll_aiding_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_pitch_roll_aiding_control_response_t *in);
int mipc_filter_pitch_roll_aiding_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_pitch_roll_aiding_control_response_t *out);
void mipc_filter_inclination_source_to_json(mipc_jw_t *w, const mipc_filter_inclination_source_t *in);
int mipc_filter_inclination_source_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_inclination_source_t *out);
void mipc_filter_inclination_source_response_to_json(mipc_jw_t *w,
                                                     const mipc_filter_inclination_source_response_t *in);
int mipc_filter_inclination_source_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_inclination_source_response_t *out);
void mipc_filter_magnetic_field_magnitude_source_to_json(
    mipc_jw_t *w, const mipc_filter_magnetic_field_magnitude_source_t *in);
int mipc_filter_magnetic_field_magnitude_source_from_json(mipc_jr_t *jr, size_t pos,
                                                          mipc_filter_magnetic_field_magnitude_source_t *out);
void mipc_filter_magnetic_field_magnitude_source_response_to_json(
    mipc_jw_t *w, const mipc_filter_magnetic_field_magnitude_source_response_t *in);
int mipc_filter_magnetic_field_magnitude_source_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_magnetic_field_magnitude_source_response_t *out);
void mipc_filter_aiding_measurement_control_to_json(mipc_jw_t *w,
                                                    const mipc_filter_aiding_measurement_control_t *in);
int mipc_filter_aiding_measurement_control_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_aiding_measurement_control_t *out);
void mipc_filter_aiding_measurement_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_aiding_measurement_control_response_t *in);
int mipc_filter_aiding_measurement_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_aiding_measurement_control_response_t *out);
void mipc_filter_initialization_configuration_to_json(mipc_jw_t *w,
                                                      const mipc_filter_initialization_configuration_t *in);
int mipc_filter_initialization_configuration_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_initialization_configuration_t *out);
void mipc_filter_initialization_configuration_response_to_json(
    mipc_jw_t *w, const mipc_filter_initialization_configuration_response_t *in);
int mipc_filter_initialization_configuration_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_initialization_configuration_response_t *out);
void mipc_filter_adaptive_filter_control_to_json(mipc_jw_t *w,
                                                 const mipc_filter_adaptive_filter_control_t *in);
int mipc_filter_adaptive_filter_control_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_adaptive_filter_control_t *out);
void mipc_filter_adaptive_filter_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_adaptive_filter_control_response_t *in);
int mipc_filter_adaptive_filter_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_adaptive_filter_control_response_t *out);
void mipc_filter_multi_antenna_offset_to_json(mipc_jw_t *w, const mipc_filter_multi_antenna_offset_t *in);
int mipc_filter_multi_antenna_offset_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_multi_antenna_offset_t *out);
void mipc_filter_multi_antenna_offset_response_to_json(mipc_jw_t *w,
                                                       const mipc_filter_multi_antenna_offset_response_t *in);
int mipc_filter_multi_antenna_offset_response_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_multi_antenna_offset_response_t *out);
void mipc_filter_relative_position_configuration_to_json(
    mipc_jw_t *w, const mipc_filter_relative_position_configuration_t *in);
int mipc_filter_relative_position_configuration_from_json(mipc_jr_t *jr, size_t pos,
                                                          mipc_filter_relative_position_configuration_t *out);
void mipc_filter_relative_position_configuration_response_to_json(
    mipc_jw_t *w, const mipc_filter_relative_position_configuration_response_t *in);
int mipc_filter_relative_position_configuration_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_relative_position_configuration_response_t *out);
void mipc_filter_reference_point_lever_arm_to_json(mipc_jw_t *w,
                                                   const mipc_filter_reference_point_lever_arm_t *in);
int mipc_filter_reference_point_lever_arm_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_reference_point_lever_arm_t *out);
void mipc_filter_reference_point_lever_arm_response_to_json(
    mipc_jw_t *w, const mipc_filter_reference_point_lever_arm_response_t *in);
int mipc_filter_reference_point_lever_arm_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_reference_point_lever_arm_response_t *out);
void mipc_filter_speed_lever_arm_to_json(mipc_jw_t *w, const mipc_filter_speed_lever_arm_t *in);
int mipc_filter_speed_lever_arm_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_speed_lever_arm_t *out);
void mipc_filter_speed_lever_arm_response_to_json(mipc_jw_t *w,
                                                  const mipc_filter_speed_lever_arm_response_t *in);
int mipc_filter_speed_lever_arm_response_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_speed_lever_arm_response_t *out);
void mipc_filter_wheeled_vehicle_constraint_control_to_json(
    mipc_jw_t *w, const mipc_filter_wheeled_vehicle_constraint_control_t *in);
int mipc_filter_wheeled_vehicle_constraint_control_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_wheeled_vehicle_constraint_control_t *out);
void mipc_filter_wheeled_vehicle_constraint_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_wheeled_vehicle_constraint_control_response_t *in);
int mipc_filter_wheeled_vehicle_constraint_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_wheeled_vehicle_constraint_control_response_t *out);
void mipc_filter_gnss_antenna_calibration_control_to_json(
    mipc_jw_t *w, const mipc_filter_gnss_antenna_calibration_control_t *in);
int mipc_filter_gnss_antenna_calibration_control_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gnss_antenna_calibration_control_t *out);
void mipc_filter_gnss_antenna_calibration_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_gnss_antenna_calibration_control_response_t *in);
int mipc_filter_gnss_antenna_calibration_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gnss_antenna_calibration_control_response_t *out);
void mipc_gnss_receiver_info_to_json(mipc_jw_t *w, const mipc_gnss_receiver_info_t *in);
int mipc_gnss_receiver_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_info_t *out);
void mipc_gnss_receiver_info_response_to_json(mipc_jw_t *w, const mipc_gnss_receiver_info_response_t *in);
int mipc_gnss_receiver_info_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_gnss_receiver_info_response_t *out);
void mipc_gnss_signal_configuration_to_json(mipc_jw_t *w, const mipc_gnss_signal_configuration_t *in);
int mipc_gnss_signal_configuration_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_gnss_signal_configuration_t *out);
void mipc_gnss_signal_configuration_response_to_json(mipc_jw_t *w,
                                                     const mipc_gnss_signal_configuration_response_t *in);
int mipc_gnss_signal_configuration_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_gnss_signal_configuration_response_t *out);
void mipc_gnss_spartn_configuration_to_json(mipc_jw_t *w, const mipc_gnss_spartn_configuration_t *in);
int mipc_gnss_spartn_configuration_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_gnss_spartn_configuration_t *out);
void mipc_gnss_spartn_configuration_response_to_json(mipc_jw_t *w,
                                                     const mipc_gnss_spartn_configuration_response_t *in);
int mipc_gnss_spartn_configuration_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_gnss_spartn_configuration_response_t *out);
void mipc_aiding_frame_config_to_json(mipc_jw_t *w, const mipc_aiding_frame_config_t *in);
int mipc_aiding_frame_config_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_frame_config_t *out);
void mipc_aiding_frame_config_response_to_json(mipc_jw_t *w, const mipc_aiding_frame_config_response_t *in);
int mipc_aiding_frame_config_response_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_aiding_frame_config_response_t *out);
void mipc_aiding_echo_control_to_json(mipc_jw_t *w, const mipc_aiding_echo_control_t *in);
int mipc_aiding_echo_control_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_echo_control_t *out);
void mipc_aiding_echo_control_response_to_json(mipc_jw_t *w, const mipc_aiding_echo_control_response_t *in);
int mipc_aiding_echo_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_aiding_echo_control_response_t *out);
void mipc_aiding_ecef_position_to_json(mipc_jw_t *w, const mipc_aiding_ecef_position_t *in);
int mipc_aiding_ecef_position_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_ecef_position_t *out);
void mipc_aiding_llh_position_to_json(mipc_jw_t *w, const mipc_aiding_llh_position_t *in);
int mipc_aiding_llh_position_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_llh_position_t *out);
void mipc_aiding_height_above_ellipsoid_to_json(mipc_jw_t *w, const mipc_aiding_height_above_ellipsoid_t *in);
int mipc_aiding_height_above_ellipsoid_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_aiding_height_above_ellipsoid_t *out);
void mipc_aiding_ecef_velocity_to_json(mipc_jw_t *w, const mipc_aiding_ecef_velocity_t *in);
int mipc_aiding_ecef_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_ecef_velocity_t *out);
void mipc_aiding_ned_velocity_to_json(mipc_jw_t *w, const mipc_aiding_ned_velocity_t *in);
int mipc_aiding_ned_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_ned_velocity_t *out);
void mipc_aiding_body_frame_velocity_to_json(mipc_jw_t *w, const mipc_aiding_body_frame_velocity_t *in);
int mipc_aiding_body_frame_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_aiding_body_frame_velocity_t *out);
void mipc_aiding_true_heading_to_json(mipc_jw_t *w, const mipc_aiding_true_heading_t *in);
int mipc_aiding_true_heading_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_true_heading_t *out);
void mipc_aiding_magnetic_field_to_json(mipc_jw_t *w, const mipc_aiding_magnetic_field_t *in);
int mipc_aiding_magnetic_field_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_magnetic_field_t *out);
void mipc_aiding_pressure_to_json(mipc_jw_t *w, const mipc_aiding_pressure_t *in);
int mipc_aiding_pressure_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_pressure_t *out);
void mipc_system_communication_mode_to_json(mipc_jw_t *w, const mipc_system_communication_mode_t *in);
int mipc_system_communication_mode_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_system_communication_mode_t *out);
void mipc_system_communication_mode_response_to_json(mipc_jw_t *w,
                                                     const mipc_system_communication_mode_response_t *in);
int mipc_system_communication_mode_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_system_communication_mode_response_t *out);
void mipc_sensor_scaled_accel_to_json(mipc_jw_t *w, const mipc_sensor_scaled_accel_t *in);
int mipc_sensor_scaled_accel_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_accel_t *out);
void mipc_sensor_scaled_gyro_to_json(mipc_jw_t *w, const mipc_sensor_scaled_gyro_t *in);
int mipc_sensor_scaled_gyro_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_gyro_t *out);
void mipc_sensor_scaled_mag_to_json(mipc_jw_t *w, const mipc_sensor_scaled_mag_t *in);
int mipc_sensor_scaled_mag_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_mag_t *out);
void mipc_sensor_delta_theta_to_json(mipc_jw_t *w, const mipc_sensor_delta_theta_t *in);
int mipc_sensor_delta_theta_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_delta_theta_t *out);
void mipc_sensor_delta_velocity_to_json(mipc_jw_t *w, const mipc_sensor_delta_velocity_t *in);
int mipc_sensor_delta_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_delta_velocity_t *out);
void mipc_sensor_cf_orientation_matrix_to_json(mipc_jw_t *w, const mipc_sensor_cf_orientation_matrix_t *in);
int mipc_sensor_cf_orientation_matrix_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_sensor_cf_orientation_matrix_t *out);
void mipc_sensor_cf_quaternion_to_json(mipc_jw_t *w, const mipc_sensor_cf_quaternion_t *in);
int mipc_sensor_cf_quaternion_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_cf_quaternion_t *out);
void mipc_sensor_cf_euler_angles_to_json(mipc_jw_t *w, const mipc_sensor_cf_euler_angles_t *in);
int mipc_sensor_cf_euler_angles_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_cf_euler_angles_t *out);
void mipc_sensor_cf_stabilized_north_to_json(mipc_jw_t *w, const mipc_sensor_cf_stabilized_north_t *in);
int mipc_sensor_cf_stabilized_north_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_sensor_cf_stabilized_north_t *out);
void mipc_sensor_cf_stabilized_up_to_json(mipc_jw_t *w, const mipc_sensor_cf_stabilized_up_t *in);
int mipc_sensor_cf_stabilized_up_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_cf_stabilized_up_t *out);
void mipc_sensor_gps_timestamp_to_json(mipc_jw_t *w, const mipc_sensor_gps_timestamp_t *in);
int mipc_sensor_gps_timestamp_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_gps_timestamp_t *out);
void mipc_sensor_temperature_statistics_to_json(mipc_jw_t *w, const mipc_sensor_temperature_statistics_t *in);
int mipc_sensor_temperature_statistics_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_sensor_temperature_statistics_t *out);
void mipc_sensor_scaled_pressure_to_json(mipc_jw_t *w, const mipc_sensor_scaled_pressure_t *in);
int mipc_sensor_scaled_pressure_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_pressure_t *out);
void mipc_sensor_overrange_status_to_json(mipc_jw_t *w, const mipc_sensor_overrange_status_t *in);
int mipc_sensor_overrange_status_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_overrange_status_t *out);
void mipc_sensor_odometer_data_to_json(mipc_jw_t *w, const mipc_sensor_odometer_data_t *in);
int mipc_sensor_odometer_data_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_odometer_data_t *out);
void mipc_gnss_data_llh_position_to_json(mipc_jw_t *w, const mipc_gnss_data_llh_position_t *in);
int mipc_gnss_data_llh_position_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_llh_position_t *out);
void mipc_gnss_data_ecef_position_to_json(mipc_jw_t *w, const mipc_gnss_data_ecef_position_t *in);
int mipc_gnss_data_ecef_position_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_ecef_position_t *out);
void mipc_gnss_data_ned_velocity_to_json(mipc_jw_t *w, const mipc_gnss_data_ned_velocity_t *in);
int mipc_gnss_data_ned_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_ned_velocity_t *out);
void mipc_gnss_data_ecef_velocity_to_json(mipc_jw_t *w, const mipc_gnss_data_ecef_velocity_t *in);
int mipc_gnss_data_ecef_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_ecef_velocity_t *out);
void mipc_gnss_data_dop_to_json(mipc_jw_t *w, const mipc_gnss_data_dop_t *in);
int mipc_gnss_data_dop_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_dop_t *out);
void mipc_gnss_data_utc_time_to_json(mipc_jw_t *w, const mipc_gnss_data_utc_time_t *in);
int mipc_gnss_data_utc_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_utc_time_t *out);
void mipc_gnss_data_gps_time_to_json(mipc_jw_t *w, const mipc_gnss_data_gps_time_t *in);
int mipc_gnss_data_gps_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_gps_time_t *out);
void mipc_gnss_data_clock_info_to_json(mipc_jw_t *w, const mipc_gnss_data_clock_info_t *in);
int mipc_gnss_data_clock_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_clock_info_t *out);
void mipc_gnss_data_fix_info_to_json(mipc_jw_t *w, const mipc_gnss_data_fix_info_t *in);
int mipc_gnss_data_fix_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_fix_info_t *out);
void mipc_gnss_data_sv_info_to_json(mipc_jw_t *w, const mipc_gnss_data_sv_info_t *in);
int mipc_gnss_data_sv_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_sv_info_t *out);
void mipc_gnss_data_hardware_status_to_json(mipc_jw_t *w, const mipc_gnss_data_hardware_status_t *in);
int mipc_gnss_data_hardware_status_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_gnss_data_hardware_status_t *out);
void mipc_gnss_data_dgnss_info_to_json(mipc_jw_t *w, const mipc_gnss_data_dgnss_info_t *in);
int mipc_gnss_data_dgnss_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_dgnss_info_t *out);
void mipc_gnss_data_dgnss_channel_status_to_json(mipc_jw_t *w,
                                                 const mipc_gnss_data_dgnss_channel_status_t *in);
int mipc_gnss_data_dgnss_channel_status_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_gnss_data_dgnss_channel_status_t *out);
void mipc_filter_data_llh_position_to_json(mipc_jw_t *w, const mipc_filter_data_llh_position_t *in);
int mipc_filter_data_llh_position_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_llh_position_t *out);
void mipc_filter_data_ned_velocity_to_json(mipc_jw_t *w, const mipc_filter_data_ned_velocity_t *in);
int mipc_filter_data_ned_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_ned_velocity_t *out);
void mipc_filter_data_attitude_quaternion_to_json(mipc_jw_t *w,
                                                  const mipc_filter_data_attitude_quaternion_t *in);
int mipc_filter_data_attitude_quaternion_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_data_attitude_quaternion_t *out);
void mipc_filter_data_attitude_dcm_to_json(mipc_jw_t *w, const mipc_filter_data_attitude_dcm_t *in);
int mipc_filter_data_attitude_dcm_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_attitude_dcm_t *out);
void mipc_filter_data_euler_angles_to_json(mipc_jw_t *w, const mipc_filter_data_euler_angles_t *in);
int mipc_filter_data_euler_angles_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_euler_angles_t *out);
void mipc_filter_data_gyro_bias_to_json(mipc_jw_t *w, const mipc_filter_data_gyro_bias_t *in);
int mipc_filter_data_gyro_bias_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_gyro_bias_t *out);
void mipc_filter_data_accel_bias_to_json(mipc_jw_t *w, const mipc_filter_data_accel_bias_t *in);
int mipc_filter_data_accel_bias_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_accel_bias_t *out);
void mipc_filter_data_llh_position_uncertainty_to_json(mipc_jw_t *w,
                                                       const mipc_filter_data_llh_position_uncertainty_t *in);
int mipc_filter_data_llh_position_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_data_llh_position_uncertainty_t *out);
void mipc_filter_data_ned_velocity_uncertainty_to_json(mipc_jw_t *w,
                                                       const mipc_filter_data_ned_velocity_uncertainty_t *in);
int mipc_filter_data_ned_velocity_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_data_ned_velocity_uncertainty_t *out);
void mipc_filter_data_euler_angles_uncertainty_to_json(mipc_jw_t *w,
                                                       const mipc_filter_data_euler_angles_uncertainty_t *in);
int mipc_filter_data_euler_angles_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_data_euler_angles_uncertainty_t *out);
void mipc_filter_data_gyro_bias_uncertainty_to_json(mipc_jw_t *w,
                                                    const mipc_filter_data_gyro_bias_uncertainty_t *in);
int mipc_filter_data_gyro_bias_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_data_gyro_bias_uncertainty_t *out);
void mipc_filter_data_accel_bias_uncertainty_to_json(mipc_jw_t *w,
                                                     const mipc_filter_data_accel_bias_uncertainty_t *in);
int mipc_filter_data_accel_bias_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_data_accel_bias_uncertainty_t *out);
void mipc_filter_data_linear_accel_to_json(mipc_jw_t *w, const mipc_filter_data_linear_accel_t *in);
int mipc_filter_data_linear_accel_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_linear_accel_t *out);
void mipc_filter_data_comp_angular_rate_to_json(mipc_jw_t *w, const mipc_filter_data_comp_angular_rate_t *in);
int mipc_filter_data_comp_angular_rate_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_data_comp_angular_rate_t *out);
void mipc_filter_data_wgs84_gravity_magnitude_to_json(mipc_jw_t *w,
                                                      const mipc_filter_data_wgs84_gravity_magnitude_t *in);
int mipc_filter_data_wgs84_gravity_magnitude_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_data_wgs84_gravity_magnitude_t *out);
void mipc_filter_data_filter_status_gx5_45_to_json(mipc_jw_t *w,
                                                   const mipc_filter_data_filter_status_gx5_45_t *in);
int mipc_filter_data_filter_status_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_data_filter_status_gx5_45_t *out);
void mipc_filter_data_filter_status_cv7_ins_to_json(mipc_jw_t *w,
                                                    const mipc_filter_data_filter_status_cv7_ins_t *in);
int mipc_filter_data_filter_status_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_data_filter_status_cv7_ins_t *out);
void mipc_filter_data_gps_timestamp_to_json(mipc_jw_t *w, const mipc_filter_data_gps_timestamp_t *in);
int mipc_filter_data_gps_timestamp_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_data_gps_timestamp_t *out);
void mipc_filter_data_quaternion_attitude_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_quaternion_attitude_uncertainty_t *in);
int mipc_filter_data_quaternion_attitude_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_quaternion_attitude_uncertainty_t *out);
void mipc_filter_data_gravity_vector_to_json(mipc_jw_t *w, const mipc_filter_data_gravity_vector_t *in);
int mipc_filter_data_gravity_vector_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_data_gravity_vector_t *out);
void mipc_filter_data_heading_update_state_to_json(mipc_jw_t *w,
                                                   const mipc_filter_data_heading_update_state_t *in);
int mipc_filter_data_heading_update_state_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_data_heading_update_state_t *out);
void mipc_filter_data_magnetic_model_to_json(mipc_jw_t *w, const mipc_filter_data_magnetic_model_t *in);
int mipc_filter_data_magnetic_model_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_data_magnetic_model_t *out);
void mipc_filter_data_gyro_scale_factor_to_json(mipc_jw_t *w, const mipc_filter_data_gyro_scale_factor_t *in);
int mipc_filter_data_gyro_scale_factor_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_data_gyro_scale_factor_t *out);
void mipc_filter_data_accel_scale_factor_to_json(mipc_jw_t *w,
                                                 const mipc_filter_data_accel_scale_factor_t *in);
int mipc_filter_data_accel_scale_factor_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_data_accel_scale_factor_t *out);
void mipc_filter_data_gyro_scale_factor_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_gyro_scale_factor_uncertainty_t *in);
int mipc_filter_data_gyro_scale_factor_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_gyro_scale_factor_uncertainty_t *out);
void mipc_filter_data_accel_scale_factor_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_accel_scale_factor_uncertainty_t *in);
int mipc_filter_data_accel_scale_factor_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_accel_scale_factor_uncertainty_t *out);
void mipc_filter_data_compensated_accel_to_json(mipc_jw_t *w, const mipc_filter_data_compensated_accel_t *in);
int mipc_filter_data_compensated_accel_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_data_compensated_accel_t *out);
void mipc_filter_data_standard_atmosphere_to_json(mipc_jw_t *w,
                                                  const mipc_filter_data_standard_atmosphere_t *in);
int mipc_filter_data_standard_atmosphere_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_data_standard_atmosphere_t *out);
void mipc_filter_data_pressure_altitude_to_json(mipc_jw_t *w, const mipc_filter_data_pressure_altitude_t *in);
int mipc_filter_data_pressure_altitude_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_data_pressure_altitude_t *out);
void mipc_filter_data_mag_auto_hard_iron_offset_to_json(
    mipc_jw_t *w, const mipc_filter_data_mag_auto_hard_iron_offset_t *in);
int mipc_filter_data_mag_auto_hard_iron_offset_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_data_mag_auto_hard_iron_offset_t *out);
void mipc_filter_data_mag_auto_soft_iron_matrix_to_json(
    mipc_jw_t *w, const mipc_filter_data_mag_auto_soft_iron_matrix_t *in);
int mipc_filter_data_mag_auto_soft_iron_matrix_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_data_mag_auto_soft_iron_matrix_t *out);
void mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *in);
int mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *out);
void mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *in);
int mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *out);
void mipc_filter_data_gnss_antenna_offset_correction_to_json(
    mipc_jw_t *w, const mipc_filter_data_gnss_antenna_offset_correction_t *in);
int mipc_filter_data_gnss_antenna_offset_correction_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_gnss_antenna_offset_correction_t *out);
void mipc_filter_data_gnss_antenna_offset_correction_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *in);
int mipc_filter_data_gnss_antenna_offset_correction_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *out);
void mipc_filter_data_multi_antenna_offset_correction_to_json(
    mipc_jw_t *w, const mipc_filter_data_multi_antenna_offset_correction_t *in);
int mipc_filter_data_multi_antenna_offset_correction_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_multi_antenna_offset_correction_t *out);
void mipc_filter_data_multi_antenna_offset_correction_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *in);
int mipc_filter_data_multi_antenna_offset_correction_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *out);
void mipc_filter_data_ecef_position_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_ecef_position_uncertainty_t *in);
int mipc_filter_data_ecef_position_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_data_ecef_position_uncertainty_t *out);
void mipc_filter_data_ecef_velocity_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_ecef_velocity_uncertainty_t *in);
int mipc_filter_data_ecef_velocity_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_data_ecef_velocity_uncertainty_t *out);
void mipc_filter_data_ecef_position_to_json(mipc_jw_t *w, const mipc_filter_data_ecef_position_t *in);
int mipc_filter_data_ecef_position_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_data_ecef_position_t *out);
void mipc_filter_data_ecef_velocity_to_json(mipc_jw_t *w, const mipc_filter_data_ecef_velocity_t *in);
int mipc_filter_data_ecef_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_data_ecef_velocity_t *out);
void mipc_filter_data_ned_relative_position_to_json(mipc_jw_t *w,
                                                    const mipc_filter_data_ned_relative_position_t *in);
int mipc_filter_data_ned_relative_position_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_data_ned_relative_position_t *out);
void mipc_filter_data_gnss_position_aiding_status_to_json(
    mipc_jw_t *w, const mipc_filter_data_gnss_position_aiding_status_t *in);
int mipc_filter_data_gnss_position_aiding_status_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_gnss_position_aiding_status_t *out);
void mipc_filter_data_aiding_measurement_summary_to_json(
    mipc_jw_t *w, const mipc_filter_data_aiding_measurement_summary_t *in);
int mipc_filter_data_aiding_measurement_summary_from_json(mipc_jr_t *jr, size_t pos,
                                                          mipc_filter_data_aiding_measurement_summary_t *out);
void mipc_filter_data_odometer_scale_factor_error_to_json(
    mipc_jw_t *w, const mipc_filter_data_odometer_scale_factor_error_t *in);
int mipc_filter_data_odometer_scale_factor_error_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_odometer_scale_factor_error_t *out);
void mipc_filter_data_odometer_scale_factor_error_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_odometer_scale_factor_error_uncertainty_t *in);
int mipc_filter_data_odometer_scale_factor_error_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_odometer_scale_factor_error_uncertainty_t *out);
void mipc_filter_data_gnss_dual_antenna_status_to_json(mipc_jw_t *w,
                                                       const mipc_filter_data_gnss_dual_antenna_status_t *in);
int mipc_filter_data_gnss_dual_antenna_status_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_data_gnss_dual_antenna_status_t *out);
void mipc_filter_data_aiding_frame_config_error_to_json(
    mipc_jw_t *w, const mipc_filter_data_aiding_frame_config_error_t *in);
int mipc_filter_data_aiding_frame_config_error_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_data_aiding_frame_config_error_t *out);
void mipc_filter_data_aiding_frame_config_error_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_aiding_frame_config_error_uncertainty_t *in);
int mipc_filter_data_aiding_frame_config_error_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_aiding_frame_config_error_uncertainty_t *out);
void mipc_gnss_receiver_1_llh_position_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_llh_position_t *in);
int mipc_gnss_receiver_1_llh_position_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_gnss_receiver_1_llh_position_t *out);
void mipc_gnss_receiver_1_ecef_position_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_ecef_position_t *in);
int mipc_gnss_receiver_1_ecef_position_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_gnss_receiver_1_ecef_position_t *out);
void mipc_gnss_receiver_1_ned_velocity_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_ned_velocity_t *in);
int mipc_gnss_receiver_1_ned_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_gnss_receiver_1_ned_velocity_t *out);
void mipc_gnss_receiver_1_ecef_velocity_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_ecef_velocity_t *in);
int mipc_gnss_receiver_1_ecef_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_gnss_receiver_1_ecef_velocity_t *out);
void mipc_gnss_receiver_1_dop_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_dop_t *in);
int mipc_gnss_receiver_1_dop_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_1_dop_t *out);
void mipc_gnss_receiver_1_utc_time_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_utc_time_t *in);
int mipc_gnss_receiver_1_utc_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_1_utc_time_t *out);
void mipc_gnss_receiver_1_gps_time_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_gps_time_t *in);
int mipc_gnss_receiver_1_gps_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_1_gps_time_t *out);
void mipc_gnss_receiver_1_fix_info_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_fix_info_t *in);
int mipc_gnss_receiver_1_fix_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_1_fix_info_t *out);
void mipc_gnss_receiver_1_hardware_status_to_json(mipc_jw_t *w,
                                                  const mipc_gnss_receiver_1_hardware_status_t *in);
int mipc_gnss_receiver_1_hardware_status_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_gnss_receiver_1_hardware_status_t *out);
void mipc_gnss_receiver_1_clock_info_2_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_clock_info_2_t *in);
int mipc_gnss_receiver_1_clock_info_2_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_gnss_receiver_1_clock_info_2_t *out);
void mipc_gnss_receiver_1_gps_leap_seconds_to_json(mipc_jw_t *w,
                                                   const mipc_gnss_receiver_1_gps_leap_seconds_t *in);
int mipc_gnss_receiver_1_gps_leap_seconds_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_gnss_receiver_1_gps_leap_seconds_t *out);
void mipc_gnss_receiver_1_sbas_info_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_sbas_info_t *in);
int mipc_gnss_receiver_1_sbas_info_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_gnss_receiver_1_sbas_info_t *out);
void mipc_gnss_receiver_1_satellite_status_to_json(mipc_jw_t *w,
                                                   const mipc_gnss_receiver_1_satellite_status_t *in);
int mipc_gnss_receiver_1_satellite_status_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_gnss_receiver_1_satellite_status_t *out);
void mipc_gnss_receiver_1_raw_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_raw_t *in);
int mipc_gnss_receiver_1_raw_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_1_raw_t *out);
void mipc_gnss_receiver_1_gps_ephemeris_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_gps_ephemeris_t *in);
int mipc_gnss_receiver_1_gps_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_gnss_receiver_1_gps_ephemeris_t *out);
void mipc_gnss_receiver_1_glonass_ephemeris_to_json(mipc_jw_t *w,
                                                    const mipc_gnss_receiver_1_glonass_ephemeris_t *in);
int mipc_gnss_receiver_1_glonass_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_gnss_receiver_1_glonass_ephemeris_t *out);
void mipc_gnss_receiver_1_galileo_ephemeris_to_json(mipc_jw_t *w,
                                                    const mipc_gnss_receiver_1_galileo_ephemeris_t *in);
int mipc_gnss_receiver_1_galileo_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_gnss_receiver_1_galileo_ephemeris_t *out);
void mipc_gnss_receiver_1_beidou_ephemeris_to_json(mipc_jw_t *w,
                                                   const mipc_gnss_receiver_1_beidou_ephemeris_t *in);
int mipc_gnss_receiver_1_beidou_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_gnss_receiver_1_beidou_ephemeris_t *out);
void mipc_gnss_receiver_2_llh_position_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_llh_position_t *in);
int mipc_gnss_receiver_2_llh_position_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_gnss_receiver_2_llh_position_t *out);
void mipc_gnss_receiver_2_ecef_position_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_ecef_position_t *in);
int mipc_gnss_receiver_2_ecef_position_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_gnss_receiver_2_ecef_position_t *out);
void mipc_gnss_receiver_2_ned_velocity_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_ned_velocity_t *in);
int mipc_gnss_receiver_2_ned_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_gnss_receiver_2_ned_velocity_t *out);
void mipc_gnss_receiver_2_ecef_velocity_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_ecef_velocity_t *in);
int mipc_gnss_receiver_2_ecef_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_gnss_receiver_2_ecef_velocity_t *out);
void mipc_gnss_receiver_2_dop_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_dop_t *in);
int mipc_gnss_receiver_2_dop_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_2_dop_t *out);
void mipc_gnss_receiver_2_utc_time_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_utc_time_t *in);
int mipc_gnss_receiver_2_utc_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_2_utc_time_t *out);
void mipc_gnss_receiver_2_gps_time_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_gps_time_t *in);
int mipc_gnss_receiver_2_gps_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_2_gps_time_t *out);
void mipc_gnss_receiver_2_fix_info_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_fix_info_t *in);
int mipc_gnss_receiver_2_fix_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_2_fix_info_t *out);
void mipc_gnss_receiver_2_hardware_status_to_json(mipc_jw_t *w,
                                                  const mipc_gnss_receiver_2_hardware_status_t *in);
int mipc_gnss_receiver_2_hardware_status_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_gnss_receiver_2_hardware_status_t *out);
void mipc_gnss_receiver_2_clock_info_2_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_clock_info_2_t *in);
int mipc_gnss_receiver_2_clock_info_2_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_gnss_receiver_2_clock_info_2_t *out);
void mipc_gnss_receiver_2_gps_leap_seconds_to_json(mipc_jw_t *w,
                                                   const mipc_gnss_receiver_2_gps_leap_seconds_t *in);
int mipc_gnss_receiver_2_gps_leap_seconds_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_gnss_receiver_2_gps_leap_seconds_t *out);
void mipc_gnss_receiver_2_sbas_info_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_sbas_info_t *in);
int mipc_gnss_receiver_2_sbas_info_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_gnss_receiver_2_sbas_info_t *out);
void mipc_gnss_receiver_2_satellite_status_to_json(mipc_jw_t *w,
                                                   const mipc_gnss_receiver_2_satellite_status_t *in);
int mipc_gnss_receiver_2_satellite_status_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_gnss_receiver_2_satellite_status_t *out);
void mipc_gnss_receiver_2_raw_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_raw_t *in);
int mipc_gnss_receiver_2_raw_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_2_raw_t *out);
void mipc_gnss_receiver_2_gps_ephemeris_to_json(mipc_jw_t *w, const mipc_gnss_receiver_2_gps_ephemeris_t *in);
int mipc_gnss_receiver_2_gps_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_gnss_receiver_2_gps_ephemeris_t *out);
void mipc_gnss_receiver_2_glonass_ephemeris_to_json(mipc_jw_t *w,
                                                    const mipc_gnss_receiver_2_glonass_ephemeris_t *in);
int mipc_gnss_receiver_2_glonass_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_gnss_receiver_2_glonass_ephemeris_t *out);
void mipc_gnss_receiver_2_galileo_ephemeris_to_json(mipc_jw_t *w,
                                                    const mipc_gnss_receiver_2_galileo_ephemeris_t *in);
int mipc_gnss_receiver_2_galileo_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_gnss_receiver_2_galileo_ephemeris_t *out);
void mipc_gnss_receiver_2_beidou_ephemeris_to_json(mipc_jw_t *w,
                                                   const mipc_gnss_receiver_2_beidou_ephemeris_t *in);
int mipc_gnss_receiver_2_beidou_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_gnss_receiver_2_beidou_ephemeris_t *out);
void mipc_gnss_corrections_base_station_info_to_json(mipc_jw_t *w,
                                                     const mipc_gnss_corrections_base_station_info_t *in);
int mipc_gnss_corrections_base_station_info_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_gnss_corrections_base_station_info_t *out);
void mipc_gnss_corrections_rtk_corrections_status_to_json(
    mipc_jw_t *w, const mipc_gnss_corrections_rtk_corrections_status_t *in);
int mipc_gnss_corrections_rtk_corrections_status_from_json(
    mipc_jr_t *jr, size_t pos, mipc_gnss_corrections_rtk_corrections_status_t *out);
void mipc_gnss_external_llh_position_to_json(mipc_jw_t *w, const mipc_gnss_external_llh_position_t *in);
int mipc_gnss_external_llh_position_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_gnss_external_llh_position_t *out);
void mipc_gnss_external_ned_velocity_to_json(mipc_jw_t *w, const mipc_gnss_external_ned_velocity_t *in);
int mipc_gnss_external_ned_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_gnss_external_ned_velocity_t *out);
void mipc_gnss_external_utc_time_to_json(mipc_jw_t *w, const mipc_gnss_external_utc_time_t *in);
int mipc_gnss_external_utc_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_external_utc_time_t *out);
void mipc_gnss_external_fix_info_to_json(mipc_jw_t *w, const mipc_gnss_external_fix_info_t *in);
int mipc_gnss_external_fix_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_external_fix_info_t *out);
void mipc_gnss_external_satellite_status_to_json(mipc_jw_t *w,
                                                 const mipc_gnss_external_satellite_status_t *in);
int mipc_gnss_external_satellite_status_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_gnss_external_satellite_status_t *out);
void mipc_system_data_built_in_test_to_json(mipc_jw_t *w, const mipc_system_data_built_in_test_t *in);
int mipc_system_data_built_in_test_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_system_data_built_in_test_t *out);
void mipc_system_data_time_sync_status_to_json(mipc_jw_t *w, const mipc_system_data_time_sync_status_t *in);
int mipc_system_data_time_sync_status_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_system_data_time_sync_status_t *out);
void mipc_system_data_gpio_state_to_json(mipc_jw_t *w, const mipc_system_data_gpio_state_t *in);
int mipc_system_data_gpio_state_from_json(mipc_jr_t *jr, size_t pos, mipc_system_data_gpio_state_t *out);
void mipc_shared_event_source_to_json(mipc_jw_t *w, const mipc_shared_event_source_t *in);
int mipc_shared_event_source_from_json(mipc_jr_t *jr, size_t pos, mipc_shared_event_source_t *out);
void mipc_shared_gps_timestamp_to_json(mipc_jw_t *w, const mipc_shared_gps_timestamp_t *in);
int mipc_shared_gps_timestamp_from_json(mipc_jr_t *jr, size_t pos, mipc_shared_gps_timestamp_t *out);
void mipc_shared_delta_time_to_json(mipc_jw_t *w, const mipc_shared_delta_time_t *in);
int mipc_shared_delta_time_from_json(mipc_jr_t *jr, size_t pos, mipc_shared_delta_time_t *out);
void mipc_shared_reference_timestamp_to_json(mipc_jw_t *w, const mipc_shared_reference_timestamp_t *in);
int mipc_shared_reference_timestamp_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_shared_reference_timestamp_t *out);
void mipc_shared_reference_time_delta_to_json(mipc_jw_t *w, const mipc_shared_reference_time_delta_t *in);
int mipc_shared_reference_time_delta_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_shared_reference_time_delta_t *out);
void mipc_shared_external_timestamp_to_json(mipc_jw_t *w, const mipc_shared_external_timestamp_t *in);
int mipc_shared_external_timestamp_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_shared_external_timestamp_t *out);
void mipc_shared_external_time_delta_to_json(mipc_jw_t *w, const mipc_shared_external_time_delta_t *in);
int mipc_shared_external_time_delta_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_shared_external_time_delta_t *out);

/* The "values" object of a decoded field. */
void mipc_value_to_json(mipc_jw_t *w, const mipc_field_value_t *value);
/* The "values" object of a typed struct of layout id (in: a mipc_<layout>_t, e.g. a member of a
 * set's packet struct that a straight-line decoder filled). */
void mipc_layout_to_json(mipc_jw_t *w, mipc_field_id_t id, const void *in);
/* Reads the "values" object of layout id into *value (sets value->id). */
int mipc_value_from_json(mipc_jr_t *jr, size_t pos, mipc_field_id_t id, mipc_field_value_t *value);

#endif
