/* Canonical JSON of a decoded field value (the mipcodec_json library). Generated from the spec: do
 * not edit. */
#include "mipcodec/dispatch.h"
#include "layouts_internal.h"

void mipc_value_to_json(mipc_jw_t *w, const mipc_field_value_t *value) {
    mipc_layout_to_json(w, value->id, &value->u);
}

void mipc_layout_to_json(mipc_jw_t *w, mipc_field_id_t id, const void *in) {
    switch (id) {
    case MIPC_FIELD_ACK_NACK:
        mipc_ack_nack_to_json(w, (const mipc_ack_nack_t *)in);
        return;
    case MIPC_FIELD_BASE_PING:
        mipc_base_ping_to_json(w, (const mipc_base_ping_t *)in);
        return;
    case MIPC_FIELD_BASE_SET_TO_IDLE:
        mipc_base_set_to_idle_to_json(w, (const mipc_base_set_to_idle_t *)in);
        return;
    case MIPC_FIELD_BASE_GET_DEVICE_INFO:
        mipc_base_get_device_info_to_json(w, (const mipc_base_get_device_info_t *)in);
        return;
    case MIPC_FIELD_BASE_DEVICE_INFO:
        mipc_base_device_info_to_json(w, (const mipc_base_device_info_t *)in);
        return;
    case MIPC_FIELD_BASE_GET_DEVICE_DESCRIPTORS:
        mipc_base_get_device_descriptors_to_json(w, (const mipc_base_get_device_descriptors_t *)in);
        return;
    case MIPC_FIELD_BASE_DEVICE_DESCRIPTORS:
        mipc_base_device_descriptors_to_json(w, (const mipc_base_device_descriptors_t *)in);
        return;
    case MIPC_FIELD_BASE_BUILT_IN_TEST:
        mipc_base_built_in_test_to_json(w, (const mipc_base_built_in_test_t *)in);
        return;
    case MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45:
        mipc_base_built_in_test_result_gx5_45_to_json(w, (const mipc_base_built_in_test_result_gx5_45_t *)in);
        return;
    case MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS:
        mipc_base_built_in_test_result_cv7_ins_to_json(w,
                                                       (const mipc_base_built_in_test_result_cv7_ins_t *)in);
        return;
    case MIPC_FIELD_BASE_RESUME:
        mipc_base_resume_to_json(w, (const mipc_base_resume_t *)in);
        return;
    case MIPC_FIELD_BASE_GET_EXTENDED_DESCRIPTORS:
        mipc_base_get_extended_descriptors_to_json(w, (const mipc_base_get_extended_descriptors_t *)in);
        return;
    case MIPC_FIELD_BASE_EXTENDED_DESCRIPTORS:
        mipc_base_extended_descriptors_to_json(w, (const mipc_base_extended_descriptors_t *)in);
        return;
    case MIPC_FIELD_BASE_CONTINUOUS_BIT:
        mipc_base_continuous_bit_to_json(w, (const mipc_base_continuous_bit_t *)in);
        return;
    case MIPC_FIELD_BASE_CONTINUOUS_BIT_RESULT:
        mipc_base_continuous_bit_result_to_json(w, (const mipc_base_continuous_bit_result_t *)in);
        return;
    case MIPC_FIELD_BASE_COMM_PORT_SPEED:
        mipc_base_comm_port_speed_to_json(w, (const mipc_base_comm_port_speed_t *)in);
        return;
    case MIPC_FIELD_BASE_COMM_PORT_SPEED_RESPONSE:
        mipc_base_comm_port_speed_response_to_json(w, (const mipc_base_comm_port_speed_response_t *)in);
        return;
    case MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45:
        mipc_base_gps_time_update_gx5_45_to_json(w, (const mipc_base_gps_time_update_gx5_45_t *)in);
        return;
    case MIPC_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS:
        mipc_base_gps_time_update_cv7_ins_to_json(w, (const mipc_base_gps_time_update_cv7_ins_t *)in);
        return;
    case MIPC_FIELD_BASE_GPS_WEEK:
        mipc_base_gps_week_to_json(w, (const mipc_base_gps_week_t *)in);
        return;
    case MIPC_FIELD_BASE_GPS_SECONDS:
        mipc_base_gps_seconds_to_json(w, (const mipc_base_gps_seconds_t *)in);
        return;
    case MIPC_FIELD_BASE_DEVICE_RESET:
        mipc_base_device_reset_to_json(w, (const mipc_base_device_reset_t *)in);
        return;
    case MIPC_FIELD_THREEDM_EVENT_CONTROL:
        mipc_threedm_event_control_to_json(w, (const mipc_threedm_event_control_t *)in);
        return;
    case MIPC_FIELD_THREEDM_EVENT_CONTROL_RESPONSE:
        mipc_threedm_event_control_response_to_json(w, (const mipc_threedm_event_control_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS:
        mipc_threedm_get_event_trigger_status_to_json(w, (const mipc_threedm_get_event_trigger_status_t *)in);
        return;
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_STATUS:
        mipc_threedm_event_trigger_status_to_json(w, (const mipc_threedm_event_trigger_status_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GET_EVENT_ACTION_STATUS:
        mipc_threedm_get_event_action_status_to_json(w, (const mipc_threedm_get_event_action_status_t *)in);
        return;
    case MIPC_FIELD_THREEDM_EVENT_ACTION_STATUS:
        mipc_threedm_event_action_status_to_json(w, (const mipc_threedm_event_action_status_t *)in);
        return;
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG:
        mipc_threedm_event_trigger_config_to_json(w, (const mipc_threedm_event_trigger_config_t *)in);
        return;
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE:
        mipc_threedm_event_trigger_config_response_to_json(
            w, (const mipc_threedm_event_trigger_config_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG:
        mipc_threedm_event_action_config_to_json(w, (const mipc_threedm_event_action_config_t *)in);
        return;
    case MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE:
        mipc_threedm_event_action_config_response_to_json(
            w, (const mipc_threedm_event_action_config_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45:
        mipc_threedm_device_startup_settings_gx5_45_to_json(
            w, (const mipc_threedm_device_startup_settings_gx5_45_t *)in);
        return;
    case MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS:
        mipc_threedm_device_startup_settings_cv7_ins_to_json(
            w, (const mipc_threedm_device_startup_settings_cv7_ins_t *)in);
        return;
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER:
        mipc_threedm_sensor_to_vehicle_euler_to_json(w, (const mipc_threedm_sensor_to_vehicle_euler_t *)in);
        return;
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE:
        mipc_threedm_sensor_to_vehicle_euler_response_to_json(
            w, (const mipc_threedm_sensor_to_vehicle_euler_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION:
        mipc_threedm_sensor_to_vehicle_quaternion_to_json(
            w, (const mipc_threedm_sensor_to_vehicle_quaternion_t *)in);
        return;
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE:
        mipc_threedm_sensor_to_vehicle_quaternion_response_to_json(
            w, (const mipc_threedm_sensor_to_vehicle_quaternion_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM:
        mipc_threedm_sensor_to_vehicle_dcm_to_json(w, (const mipc_threedm_sensor_to_vehicle_dcm_t *)in);
        return;
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE:
        mipc_threedm_sensor_to_vehicle_dcm_response_to_json(
            w, (const mipc_threedm_sensor_to_vehicle_dcm_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45:
        mipc_threedm_accel_bias_gx5_45_to_json(w, (const mipc_threedm_accel_bias_gx5_45_t *)in);
        return;
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS:
        mipc_threedm_accel_bias_cv7_ins_to_json(w, (const mipc_threedm_accel_bias_cv7_ins_t *)in);
        return;
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_RESPONSE:
        mipc_threedm_accel_bias_response_to_json(w, (const mipc_threedm_accel_bias_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45:
        mipc_threedm_gyro_bias_gx5_45_to_json(w, (const mipc_threedm_gyro_bias_gx5_45_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS:
        mipc_threedm_gyro_bias_cv7_ins_to_json(w, (const mipc_threedm_gyro_bias_cv7_ins_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GYRO_BIAS_RESPONSE:
        mipc_threedm_gyro_bias_response_to_json(w, (const mipc_threedm_gyro_bias_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_CAPTURE_GYRO_BIAS:
        mipc_threedm_capture_gyro_bias_to_json(w, (const mipc_threedm_capture_gyro_bias_t *)in);
        return;
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45:
        mipc_threedm_mag_hard_iron_offset_gx5_45_to_json(
            w, (const mipc_threedm_mag_hard_iron_offset_gx5_45_t *)in);
        return;
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS:
        mipc_threedm_mag_hard_iron_offset_cv7_ins_to_json(
            w, (const mipc_threedm_mag_hard_iron_offset_cv7_ins_t *)in);
        return;
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE:
        mipc_threedm_mag_hard_iron_offset_response_to_json(
            w, (const mipc_threedm_mag_hard_iron_offset_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45:
        mipc_threedm_mag_soft_iron_matrix_gx5_45_to_json(
            w, (const mipc_threedm_mag_soft_iron_matrix_gx5_45_t *)in);
        return;
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS:
        mipc_threedm_mag_soft_iron_matrix_cv7_ins_to_json(
            w, (const mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *)in);
        return;
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE:
        mipc_threedm_mag_soft_iron_matrix_response_to_json(
            w, (const mipc_threedm_mag_soft_iron_matrix_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE:
        mipc_threedm_coning_sculling_enable_to_json(w, (const mipc_threedm_coning_sculling_enable_t *)in);
        return;
    case MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE:
        mipc_threedm_coning_sculling_enable_response_to_json(
            w, (const mipc_threedm_coning_sculling_enable_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_UART_BAUDRATE:
        mipc_threedm_uart_baudrate_to_json(w, (const mipc_threedm_uart_baudrate_t *)in);
        return;
    case MIPC_FIELD_THREEDM_UART_BAUDRATE_RESPONSE:
        mipc_threedm_uart_baudrate_response_to_json(w, (const mipc_threedm_uart_baudrate_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GPIO_CONFIG:
        mipc_threedm_gpio_config_to_json(w, (const mipc_threedm_gpio_config_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GPIO_CONFIG_RESPONSE:
        mipc_threedm_gpio_config_response_to_json(w, (const mipc_threedm_gpio_config_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GPIO_STATE:
        mipc_threedm_gpio_state_to_json(w, (const mipc_threedm_gpio_state_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GPIO_STATE_RESPONSE:
        mipc_threedm_gpio_state_response_to_json(w, (const mipc_threedm_gpio_state_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_ODOMETER_CONFIG:
        mipc_threedm_odometer_config_to_json(w, (const mipc_threedm_odometer_config_t *)in);
        return;
    case MIPC_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE:
        mipc_threedm_odometer_config_response_to_json(w, (const mipc_threedm_odometer_config_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER:
        mipc_threedm_advanced_lowpass_filter_to_json(w, (const mipc_threedm_advanced_lowpass_filter_t *)in);
        return;
    case MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE:
        mipc_threedm_advanced_lowpass_filter_response_to_json(
            w, (const mipc_threedm_advanced_lowpass_filter_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER:
        mipc_threedm_complementary_filter_to_json(w, (const mipc_threedm_complementary_filter_t *)in);
        return;
    case MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE:
        mipc_threedm_complementary_filter_response_to_json(
            w, (const mipc_threedm_complementary_filter_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_SENSOR_RANGE:
        mipc_threedm_sensor_range_to_json(w, (const mipc_threedm_sensor_range_t *)in);
        return;
    case MIPC_FIELD_THREEDM_SENSOR_RANGE_RESPONSE:
        mipc_threedm_sensor_range_response_to_json(w, (const mipc_threedm_sensor_range_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES:
        mipc_threedm_get_calibrated_sensor_ranges_to_json(
            w, (const mipc_threedm_get_calibrated_sensor_ranges_t *)in);
        return;
    case MIPC_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES:
        mipc_threedm_calibrated_sensor_ranges_to_json(w, (const mipc_threedm_calibrated_sensor_ranges_t *)in);
        return;
    case MIPC_FIELD_THREEDM_LOWPASS_FILTER:
        mipc_threedm_lowpass_filter_to_json(w, (const mipc_threedm_lowpass_filter_t *)in);
        return;
    case MIPC_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE:
        mipc_threedm_lowpass_filter_response_to_json(w, (const mipc_threedm_lowpass_filter_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_POLL_IMU_DATA:
        mipc_threedm_poll_imu_data_to_json(w, (const mipc_threedm_poll_imu_data_t *)in);
        return;
    case MIPC_FIELD_THREEDM_POLL_GNSS_DATA:
        mipc_threedm_poll_gnss_data_to_json(w, (const mipc_threedm_poll_gnss_data_t *)in);
        return;
    case MIPC_FIELD_THREEDM_POLL_FILTER_DATA:
        mipc_threedm_poll_filter_data_to_json(w, (const mipc_threedm_poll_filter_data_t *)in);
        return;
    case MIPC_FIELD_THREEDM_POLL_NMEA_DATA:
        mipc_threedm_poll_nmea_data_to_json(w, (const mipc_threedm_poll_nmea_data_t *)in);
        return;
    case MIPC_FIELD_THREEDM_POLL_DATA:
        mipc_threedm_poll_data_to_json(w, (const mipc_threedm_poll_data_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GET_IMU_BASE_RATE:
        mipc_threedm_get_imu_base_rate_to_json(w, (const mipc_threedm_get_imu_base_rate_t *)in);
        return;
    case MIPC_FIELD_THREEDM_IMU_BASE_RATE:
        mipc_threedm_imu_base_rate_to_json(w, (const mipc_threedm_imu_base_rate_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GET_GNSS_BASE_RATE:
        mipc_threedm_get_gnss_base_rate_to_json(w, (const mipc_threedm_get_gnss_base_rate_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_BASE_RATE:
        mipc_threedm_gnss_base_rate_to_json(w, (const mipc_threedm_gnss_base_rate_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GET_FILTER_BASE_RATE:
        mipc_threedm_get_filter_base_rate_to_json(w, (const mipc_threedm_get_filter_base_rate_t *)in);
        return;
    case MIPC_FIELD_THREEDM_FILTER_BASE_RATE:
        mipc_threedm_filter_base_rate_to_json(w, (const mipc_threedm_filter_base_rate_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GET_BASE_RATE:
        mipc_threedm_get_base_rate_to_json(w, (const mipc_threedm_get_base_rate_t *)in);
        return;
    case MIPC_FIELD_THREEDM_BASE_RATE:
        mipc_threedm_base_rate_to_json(w, (const mipc_threedm_base_rate_t *)in);
        return;
    case MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT:
        mipc_threedm_imu_message_format_to_json(w, (const mipc_threedm_imu_message_format_t *)in);
        return;
    case MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE:
        mipc_threedm_imu_message_format_response_to_json(
            w, (const mipc_threedm_imu_message_format_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT:
        mipc_threedm_gnss_message_format_to_json(w, (const mipc_threedm_gnss_message_format_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE:
        mipc_threedm_gnss_message_format_response_to_json(
            w, (const mipc_threedm_gnss_message_format_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT:
        mipc_threedm_filter_message_format_to_json(w, (const mipc_threedm_filter_message_format_t *)in);
        return;
    case MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE:
        mipc_threedm_filter_message_format_response_to_json(
            w, (const mipc_threedm_filter_message_format_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT:
        mipc_threedm_nmea_message_format_to_json(w, (const mipc_threedm_nmea_message_format_t *)in);
        return;
    case MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE:
        mipc_threedm_nmea_message_format_response_to_json(
            w, (const mipc_threedm_nmea_message_format_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_MESSAGE_FORMAT:
        mipc_threedm_message_format_to_json(w, (const mipc_threedm_message_format_t *)in);
        return;
    case MIPC_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE:
        mipc_threedm_message_format_response_to_json(w, (const mipc_threedm_message_format_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_FACTORY_STREAMING:
        mipc_threedm_factory_streaming_to_json(w, (const mipc_threedm_factory_streaming_t *)in);
        return;
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45:
        mipc_threedm_data_stream_control_gx5_45_to_json(
            w, (const mipc_threedm_data_stream_control_gx5_45_t *)in);
        return;
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS:
        mipc_threedm_data_stream_control_cv7_ins_to_json(
            w, (const mipc_threedm_data_stream_control_cv7_ins_t *)in);
        return;
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45:
        mipc_threedm_data_stream_control_response_gx5_45_to_json(
            w, (const mipc_threedm_data_stream_control_response_gx5_45_t *)in);
        return;
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS:
        mipc_threedm_data_stream_control_response_cv7_ins_to_json(
            w, (const mipc_threedm_data_stream_control_response_cv7_ins_t *)in);
        return;
    case MIPC_FIELD_THREEDM_RAW_RTCM_MESSAGE:
        mipc_threedm_raw_rtcm_message_to_json(w, (const mipc_threedm_raw_rtcm_message_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS:
        mipc_threedm_gnss_constellation_settings_to_json(
            w, (const mipc_threedm_gnss_constellation_settings_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE:
        mipc_threedm_gnss_constellation_settings_response_to_json(
            w, (const mipc_threedm_gnss_constellation_settings_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS:
        mipc_threedm_gnss_sbas_settings_to_json(w, (const mipc_threedm_gnss_sbas_settings_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE:
        mipc_threedm_gnss_sbas_settings_response_to_json(
            w, (const mipc_threedm_gnss_sbas_settings_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL:
        mipc_threedm_gnss_assisted_fix_control_to_json(w,
                                                       (const mipc_threedm_gnss_assisted_fix_control_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE:
        mipc_threedm_gnss_assisted_fix_control_response_to_json(
            w, (const mipc_threedm_gnss_assisted_fix_control_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE:
        mipc_threedm_gnss_assist_time_update_to_json(w, (const mipc_threedm_gnss_assist_time_update_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE:
        mipc_threedm_gnss_assist_time_update_response_to_json(
            w, (const mipc_threedm_gnss_assist_time_update_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_PPS_SOURCE:
        mipc_threedm_pps_source_to_json(w, (const mipc_threedm_pps_source_t *)in);
        return;
    case MIPC_FIELD_THREEDM_PPS_SOURCE_RESPONSE:
        mipc_threedm_pps_source_response_to_json(w, (const mipc_threedm_pps_source_response_t *)in);
        return;
    case MIPC_FIELD_THREEDM_GET_SUPPORTED_EVENTS:
        mipc_threedm_get_supported_events_to_json(w, (const mipc_threedm_get_supported_events_t *)in);
        return;
    case MIPC_FIELD_THREEDM_SUPPORTED_EVENTS:
        mipc_threedm_supported_events_to_json(w, (const mipc_threedm_supported_events_t *)in);
        return;
    case MIPC_FIELD_THREEDM_DEVICE_STATUS:
        mipc_threedm_device_status_to_json(w, (const mipc_threedm_device_status_t *)in);
        return;
    case MIPC_FIELD_THREEDM_DEVICE_STATUS_RESPONSE:
        mipc_threedm_device_status_response_to_json(w, (const mipc_threedm_device_status_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_RESET_FILTER:
        mipc_filter_reset_filter_to_json(w, (const mipc_filter_reset_filter_t *)in);
        return;
    case MIPC_FIELD_FILTER_SET_INITIAL_ATTITUDE:
        mipc_filter_set_initial_attitude_to_json(w, (const mipc_filter_set_initial_attitude_t *)in);
        return;
    case MIPC_FIELD_FILTER_SET_INITIAL_HEADING:
        mipc_filter_set_initial_heading_to_json(w, (const mipc_filter_set_initial_heading_t *)in);
        return;
    case MIPC_FIELD_FILTER_RUN_FILTER:
        mipc_filter_run_filter_to_json(w, (const mipc_filter_run_filter_t *)in);
        return;
    case MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE:
        mipc_filter_vehicle_dynamics_mode_to_json(w, (const mipc_filter_vehicle_dynamics_mode_t *)in);
        return;
    case MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE:
        mipc_filter_vehicle_dynamics_mode_response_to_json(
            w, (const mipc_filter_vehicle_dynamics_mode_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM:
        mipc_filter_sensor_to_vehicle_transform_to_json(
            w, (const mipc_filter_sensor_to_vehicle_transform_t *)in);
        return;
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE:
        mipc_filter_sensor_to_vehicle_transform_response_to_json(
            w, (const mipc_filter_sensor_to_vehicle_transform_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET:
        mipc_filter_sensor_to_vehicle_offset_to_json(w, (const mipc_filter_sensor_to_vehicle_offset_t *)in);
        return;
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE:
        mipc_filter_sensor_to_vehicle_offset_response_to_json(
            w, (const mipc_filter_sensor_to_vehicle_offset_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_ANTENNA_OFFSET:
        mipc_filter_antenna_offset_to_json(w, (const mipc_filter_antenna_offset_t *)in);
        return;
    case MIPC_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE:
        mipc_filter_antenna_offset_response_to_json(w, (const mipc_filter_antenna_offset_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_ESTIMATION_CONTROL:
        mipc_filter_estimation_control_to_json(w, (const mipc_filter_estimation_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE:
        mipc_filter_estimation_control_response_to_json(
            w, (const mipc_filter_estimation_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL:
        mipc_filter_gnss_source_control_to_json(w, (const mipc_filter_gnss_source_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE:
        mipc_filter_gnss_source_control_response_to_json(
            w, (const mipc_filter_gnss_source_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_EXTERNAL_GNSS_UPDATE:
        mipc_filter_external_gnss_update_to_json(w, (const mipc_filter_external_gnss_update_t *)in);
        return;
    case MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE:
        mipc_filter_external_heading_update_to_json(w, (const mipc_filter_external_heading_update_t *)in);
        return;
    case MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL:
        mipc_filter_heading_update_control_to_json(w, (const mipc_filter_heading_update_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE:
        mipc_filter_heading_update_control_response_to_json(
            w, (const mipc_filter_heading_update_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_AUTO_INIT_CONTROL:
        mipc_filter_auto_init_control_to_json(w, (const mipc_filter_auto_init_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE:
        mipc_filter_auto_init_control_response_to_json(w,
                                                       (const mipc_filter_auto_init_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_ACCEL_NOISE:
        mipc_filter_accel_noise_to_json(w, (const mipc_filter_accel_noise_t *)in);
        return;
    case MIPC_FIELD_FILTER_ACCEL_NOISE_RESPONSE:
        mipc_filter_accel_noise_response_to_json(w, (const mipc_filter_accel_noise_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_GYRO_NOISE:
        mipc_filter_gyro_noise_to_json(w, (const mipc_filter_gyro_noise_t *)in);
        return;
    case MIPC_FIELD_FILTER_GYRO_NOISE_RESPONSE:
        mipc_filter_gyro_noise_response_to_json(w, (const mipc_filter_gyro_noise_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL:
        mipc_filter_accel_bias_model_to_json(w, (const mipc_filter_accel_bias_model_t *)in);
        return;
    case MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE:
        mipc_filter_accel_bias_model_response_to_json(w, (const mipc_filter_accel_bias_model_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_GYRO_BIAS_MODEL:
        mipc_filter_gyro_bias_model_to_json(w, (const mipc_filter_gyro_bias_model_t *)in);
        return;
    case MIPC_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE:
        mipc_filter_gyro_bias_model_response_to_json(w, (const mipc_filter_gyro_bias_model_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_ZUPT_CONTROL:
        mipc_filter_zupt_control_to_json(w, (const mipc_filter_zupt_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_ZUPT_CONTROL_RESPONSE:
        mipc_filter_zupt_control_response_to_json(w, (const mipc_filter_zupt_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME:
        mipc_filter_external_heading_update_with_time_to_json(
            w, (const mipc_filter_external_heading_update_with_time_t *)in);
        return;
    case MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL:
        mipc_filter_zero_angular_rate_update_control_to_json(
            w, (const mipc_filter_zero_angular_rate_update_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE:
        mipc_filter_zero_angular_rate_update_control_response_to_json(
            w, (const mipc_filter_zero_angular_rate_update_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_TARE_ORIENTATION:
        mipc_filter_tare_orientation_to_json(w, (const mipc_filter_tare_orientation_t *)in);
        return;
    case MIPC_FIELD_FILTER_COMMANDED_ZUPT:
        mipc_filter_commanded_zupt_to_json(w, (const mipc_filter_commanded_zupt_t *)in);
        return;
    case MIPC_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE:
        mipc_filter_commanded_zero_angular_rate_update_to_json(
            w, (const mipc_filter_commanded_zero_angular_rate_update_t *)in);
        return;
    case MIPC_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION:
        mipc_filter_mag_capture_auto_calibration_to_json(
            w, (const mipc_filter_mag_capture_auto_calibration_t *)in);
        return;
    case MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV:
        mipc_filter_gravity_noise_std_dev_to_json(w, (const mipc_filter_gravity_noise_std_dev_t *)in);
        return;
    case MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE:
        mipc_filter_gravity_noise_std_dev_response_to_json(
            w, (const mipc_filter_gravity_noise_std_dev_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV:
        mipc_filter_pressure_altitude_noise_std_dev_to_json(
            w, (const mipc_filter_pressure_altitude_noise_std_dev_t *)in);
        return;
    case MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE:
        mipc_filter_pressure_altitude_noise_std_dev_response_to_json(
            w, (const mipc_filter_pressure_altitude_noise_std_dev_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE:
        mipc_filter_hard_iron_offset_noise_to_json(w, (const mipc_filter_hard_iron_offset_noise_t *)in);
        return;
    case MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE:
        mipc_filter_hard_iron_offset_noise_response_to_json(
            w, (const mipc_filter_hard_iron_offset_noise_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE:
        mipc_filter_soft_iron_matrix_noise_to_json(w, (const mipc_filter_soft_iron_matrix_noise_t *)in);
        return;
    case MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE:
        mipc_filter_soft_iron_matrix_noise_response_to_json(
            w, (const mipc_filter_soft_iron_matrix_noise_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV:
        mipc_filter_mag_noise_std_dev_to_json(w, (const mipc_filter_mag_noise_std_dev_t *)in);
        return;
    case MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE:
        mipc_filter_mag_noise_std_dev_response_to_json(w,
                                                       (const mipc_filter_mag_noise_std_dev_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_DECLINATION_SOURCE:
        mipc_filter_declination_source_to_json(w, (const mipc_filter_declination_source_t *)in);
        return;
    case MIPC_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE:
        mipc_filter_declination_source_response_to_json(
            w, (const mipc_filter_declination_source_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        mipc_filter_gravity_magnitude_adaptive_measurement_to_json(
            w, (const mipc_filter_gravity_magnitude_adaptive_measurement_t *)in);
        return;
    case MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        mipc_filter_gravity_magnitude_adaptive_measurement_response_to_json(
            w, (const mipc_filter_gravity_magnitude_adaptive_measurement_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        mipc_filter_mag_magnitude_adaptive_measurement_to_json(
            w, (const mipc_filter_mag_magnitude_adaptive_measurement_t *)in);
        return;
    case MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        mipc_filter_mag_magnitude_adaptive_measurement_response_to_json(
            w, (const mipc_filter_mag_magnitude_adaptive_measurement_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT:
        mipc_filter_mag_dip_angle_adaptive_measurement_to_json(
            w, (const mipc_filter_mag_dip_angle_adaptive_measurement_t *)in);
        return;
    case MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE:
        mipc_filter_mag_dip_angle_adaptive_measurement_response_to_json(
            w, (const mipc_filter_mag_dip_angle_adaptive_measurement_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL:
        mipc_filter_altitude_aiding_control_to_json(w, (const mipc_filter_altitude_aiding_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE:
        mipc_filter_altitude_aiding_control_response_to_json(
            w, (const mipc_filter_altitude_aiding_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL:
        mipc_filter_pitch_roll_aiding_control_to_json(w, (const mipc_filter_pitch_roll_aiding_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE:
        mipc_filter_pitch_roll_aiding_control_response_to_json(
            w, (const mipc_filter_pitch_roll_aiding_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_INCLINATION_SOURCE:
        mipc_filter_inclination_source_to_json(w, (const mipc_filter_inclination_source_t *)in);
        return;
    case MIPC_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE:
        mipc_filter_inclination_source_response_to_json(
            w, (const mipc_filter_inclination_source_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE:
        mipc_filter_magnetic_field_magnitude_source_to_json(
            w, (const mipc_filter_magnetic_field_magnitude_source_t *)in);
        return;
    case MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE:
        mipc_filter_magnetic_field_magnitude_source_response_to_json(
            w, (const mipc_filter_magnetic_field_magnitude_source_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL:
        mipc_filter_aiding_measurement_control_to_json(w,
                                                       (const mipc_filter_aiding_measurement_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE:
        mipc_filter_aiding_measurement_control_response_to_json(
            w, (const mipc_filter_aiding_measurement_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION:
        mipc_filter_initialization_configuration_to_json(
            w, (const mipc_filter_initialization_configuration_t *)in);
        return;
    case MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE:
        mipc_filter_initialization_configuration_response_to_json(
            w, (const mipc_filter_initialization_configuration_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL:
        mipc_filter_adaptive_filter_control_to_json(w, (const mipc_filter_adaptive_filter_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE:
        mipc_filter_adaptive_filter_control_response_to_json(
            w, (const mipc_filter_adaptive_filter_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET:
        mipc_filter_multi_antenna_offset_to_json(w, (const mipc_filter_multi_antenna_offset_t *)in);
        return;
    case MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE:
        mipc_filter_multi_antenna_offset_response_to_json(
            w, (const mipc_filter_multi_antenna_offset_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION:
        mipc_filter_relative_position_configuration_to_json(
            w, (const mipc_filter_relative_position_configuration_t *)in);
        return;
    case MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE:
        mipc_filter_relative_position_configuration_response_to_json(
            w, (const mipc_filter_relative_position_configuration_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM:
        mipc_filter_reference_point_lever_arm_to_json(w, (const mipc_filter_reference_point_lever_arm_t *)in);
        return;
    case MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE:
        mipc_filter_reference_point_lever_arm_response_to_json(
            w, (const mipc_filter_reference_point_lever_arm_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_SPEED_LEVER_ARM:
        mipc_filter_speed_lever_arm_to_json(w, (const mipc_filter_speed_lever_arm_t *)in);
        return;
    case MIPC_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE:
        mipc_filter_speed_lever_arm_response_to_json(w, (const mipc_filter_speed_lever_arm_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL:
        mipc_filter_wheeled_vehicle_constraint_control_to_json(
            w, (const mipc_filter_wheeled_vehicle_constraint_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE:
        mipc_filter_wheeled_vehicle_constraint_control_response_to_json(
            w, (const mipc_filter_wheeled_vehicle_constraint_control_response_t *)in);
        return;
    case MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL:
        mipc_filter_gnss_antenna_calibration_control_to_json(
            w, (const mipc_filter_gnss_antenna_calibration_control_t *)in);
        return;
    case MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE:
        mipc_filter_gnss_antenna_calibration_control_response_to_json(
            w, (const mipc_filter_gnss_antenna_calibration_control_response_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_INFO:
        mipc_gnss_receiver_info_to_json(w, (const mipc_gnss_receiver_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_INFO_RESPONSE:
        mipc_gnss_receiver_info_response_to_json(w, (const mipc_gnss_receiver_info_response_t *)in);
        return;
    case MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION:
        mipc_gnss_signal_configuration_to_json(w, (const mipc_gnss_signal_configuration_t *)in);
        return;
    case MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE:
        mipc_gnss_signal_configuration_response_to_json(
            w, (const mipc_gnss_signal_configuration_response_t *)in);
        return;
    case MIPC_FIELD_GNSS_SPARTN_CONFIGURATION:
        mipc_gnss_spartn_configuration_to_json(w, (const mipc_gnss_spartn_configuration_t *)in);
        return;
    case MIPC_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE:
        mipc_gnss_spartn_configuration_response_to_json(
            w, (const mipc_gnss_spartn_configuration_response_t *)in);
        return;
    case MIPC_FIELD_AIDING_FRAME_CONFIG:
        mipc_aiding_frame_config_to_json(w, (const mipc_aiding_frame_config_t *)in);
        return;
    case MIPC_FIELD_AIDING_FRAME_CONFIG_RESPONSE:
        mipc_aiding_frame_config_response_to_json(w, (const mipc_aiding_frame_config_response_t *)in);
        return;
    case MIPC_FIELD_AIDING_ECHO_CONTROL:
        mipc_aiding_echo_control_to_json(w, (const mipc_aiding_echo_control_t *)in);
        return;
    case MIPC_FIELD_AIDING_ECHO_CONTROL_RESPONSE:
        mipc_aiding_echo_control_response_to_json(w, (const mipc_aiding_echo_control_response_t *)in);
        return;
    case MIPC_FIELD_AIDING_ECEF_POSITION:
        mipc_aiding_ecef_position_to_json(w, (const mipc_aiding_ecef_position_t *)in);
        return;
    case MIPC_FIELD_AIDING_LLH_POSITION:
        mipc_aiding_llh_position_to_json(w, (const mipc_aiding_llh_position_t *)in);
        return;
    case MIPC_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID:
        mipc_aiding_height_above_ellipsoid_to_json(w, (const mipc_aiding_height_above_ellipsoid_t *)in);
        return;
    case MIPC_FIELD_AIDING_ECEF_VELOCITY:
        mipc_aiding_ecef_velocity_to_json(w, (const mipc_aiding_ecef_velocity_t *)in);
        return;
    case MIPC_FIELD_AIDING_NED_VELOCITY:
        mipc_aiding_ned_velocity_to_json(w, (const mipc_aiding_ned_velocity_t *)in);
        return;
    case MIPC_FIELD_AIDING_BODY_FRAME_VELOCITY:
        mipc_aiding_body_frame_velocity_to_json(w, (const mipc_aiding_body_frame_velocity_t *)in);
        return;
    case MIPC_FIELD_AIDING_TRUE_HEADING:
        mipc_aiding_true_heading_to_json(w, (const mipc_aiding_true_heading_t *)in);
        return;
    case MIPC_FIELD_AIDING_MAGNETIC_FIELD:
        mipc_aiding_magnetic_field_to_json(w, (const mipc_aiding_magnetic_field_t *)in);
        return;
    case MIPC_FIELD_AIDING_PRESSURE:
        mipc_aiding_pressure_to_json(w, (const mipc_aiding_pressure_t *)in);
        return;
    case MIPC_FIELD_SYSTEM_COMMUNICATION_MODE:
        mipc_system_communication_mode_to_json(w, (const mipc_system_communication_mode_t *)in);
        return;
    case MIPC_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE:
        mipc_system_communication_mode_response_to_json(
            w, (const mipc_system_communication_mode_response_t *)in);
        return;
    case MIPC_FIELD_SENSOR_SCALED_ACCEL:
        mipc_sensor_scaled_accel_to_json(w, (const mipc_sensor_scaled_accel_t *)in);
        return;
    case MIPC_FIELD_SENSOR_SCALED_GYRO:
        mipc_sensor_scaled_gyro_to_json(w, (const mipc_sensor_scaled_gyro_t *)in);
        return;
    case MIPC_FIELD_SENSOR_SCALED_MAG:
        mipc_sensor_scaled_mag_to_json(w, (const mipc_sensor_scaled_mag_t *)in);
        return;
    case MIPC_FIELD_SENSOR_DELTA_THETA:
        mipc_sensor_delta_theta_to_json(w, (const mipc_sensor_delta_theta_t *)in);
        return;
    case MIPC_FIELD_SENSOR_DELTA_VELOCITY:
        mipc_sensor_delta_velocity_to_json(w, (const mipc_sensor_delta_velocity_t *)in);
        return;
    case MIPC_FIELD_SENSOR_CF_ORIENTATION_MATRIX:
        mipc_sensor_cf_orientation_matrix_to_json(w, (const mipc_sensor_cf_orientation_matrix_t *)in);
        return;
    case MIPC_FIELD_SENSOR_CF_QUATERNION:
        mipc_sensor_cf_quaternion_to_json(w, (const mipc_sensor_cf_quaternion_t *)in);
        return;
    case MIPC_FIELD_SENSOR_CF_EULER_ANGLES:
        mipc_sensor_cf_euler_angles_to_json(w, (const mipc_sensor_cf_euler_angles_t *)in);
        return;
    case MIPC_FIELD_SENSOR_CF_STABILIZED_NORTH:
        mipc_sensor_cf_stabilized_north_to_json(w, (const mipc_sensor_cf_stabilized_north_t *)in);
        return;
    case MIPC_FIELD_SENSOR_CF_STABILIZED_UP:
        mipc_sensor_cf_stabilized_up_to_json(w, (const mipc_sensor_cf_stabilized_up_t *)in);
        return;
    case MIPC_FIELD_SENSOR_GPS_TIMESTAMP:
        mipc_sensor_gps_timestamp_to_json(w, (const mipc_sensor_gps_timestamp_t *)in);
        return;
    case MIPC_FIELD_SENSOR_TEMPERATURE_STATISTICS:
        mipc_sensor_temperature_statistics_to_json(w, (const mipc_sensor_temperature_statistics_t *)in);
        return;
    case MIPC_FIELD_SENSOR_SCALED_PRESSURE:
        mipc_sensor_scaled_pressure_to_json(w, (const mipc_sensor_scaled_pressure_t *)in);
        return;
    case MIPC_FIELD_SENSOR_OVERRANGE_STATUS:
        mipc_sensor_overrange_status_to_json(w, (const mipc_sensor_overrange_status_t *)in);
        return;
    case MIPC_FIELD_SENSOR_ODOMETER_DATA:
        mipc_sensor_odometer_data_to_json(w, (const mipc_sensor_odometer_data_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_LLH_POSITION:
        mipc_gnss_data_llh_position_to_json(w, (const mipc_gnss_data_llh_position_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_ECEF_POSITION:
        mipc_gnss_data_ecef_position_to_json(w, (const mipc_gnss_data_ecef_position_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_NED_VELOCITY:
        mipc_gnss_data_ned_velocity_to_json(w, (const mipc_gnss_data_ned_velocity_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_ECEF_VELOCITY:
        mipc_gnss_data_ecef_velocity_to_json(w, (const mipc_gnss_data_ecef_velocity_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_DOP:
        mipc_gnss_data_dop_to_json(w, (const mipc_gnss_data_dop_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_UTC_TIME:
        mipc_gnss_data_utc_time_to_json(w, (const mipc_gnss_data_utc_time_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_GPS_TIME:
        mipc_gnss_data_gps_time_to_json(w, (const mipc_gnss_data_gps_time_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_CLOCK_INFO:
        mipc_gnss_data_clock_info_to_json(w, (const mipc_gnss_data_clock_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_FIX_INFO:
        mipc_gnss_data_fix_info_to_json(w, (const mipc_gnss_data_fix_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_SV_INFO:
        mipc_gnss_data_sv_info_to_json(w, (const mipc_gnss_data_sv_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_HARDWARE_STATUS:
        mipc_gnss_data_hardware_status_to_json(w, (const mipc_gnss_data_hardware_status_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_DGNSS_INFO:
        mipc_gnss_data_dgnss_info_to_json(w, (const mipc_gnss_data_dgnss_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS:
        mipc_gnss_data_dgnss_channel_status_to_json(w, (const mipc_gnss_data_dgnss_channel_status_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_LLH_POSITION:
        mipc_filter_data_llh_position_to_json(w, (const mipc_filter_data_llh_position_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_NED_VELOCITY:
        mipc_filter_data_ned_velocity_to_json(w, (const mipc_filter_data_ned_velocity_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ATTITUDE_QUATERNION:
        mipc_filter_data_attitude_quaternion_to_json(w, (const mipc_filter_data_attitude_quaternion_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ATTITUDE_DCM:
        mipc_filter_data_attitude_dcm_to_json(w, (const mipc_filter_data_attitude_dcm_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_EULER_ANGLES:
        mipc_filter_data_euler_angles_to_json(w, (const mipc_filter_data_euler_angles_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_GYRO_BIAS:
        mipc_filter_data_gyro_bias_to_json(w, (const mipc_filter_data_gyro_bias_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ACCEL_BIAS:
        mipc_filter_data_accel_bias_to_json(w, (const mipc_filter_data_accel_bias_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY:
        mipc_filter_data_llh_position_uncertainty_to_json(
            w, (const mipc_filter_data_llh_position_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY:
        mipc_filter_data_ned_velocity_uncertainty_to_json(
            w, (const mipc_filter_data_ned_velocity_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY:
        mipc_filter_data_euler_angles_uncertainty_to_json(
            w, (const mipc_filter_data_euler_angles_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY:
        mipc_filter_data_gyro_bias_uncertainty_to_json(w,
                                                       (const mipc_filter_data_gyro_bias_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY:
        mipc_filter_data_accel_bias_uncertainty_to_json(
            w, (const mipc_filter_data_accel_bias_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_LINEAR_ACCEL:
        mipc_filter_data_linear_accel_to_json(w, (const mipc_filter_data_linear_accel_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_COMP_ANGULAR_RATE:
        mipc_filter_data_comp_angular_rate_to_json(w, (const mipc_filter_data_comp_angular_rate_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE:
        mipc_filter_data_wgs84_gravity_magnitude_to_json(
            w, (const mipc_filter_data_wgs84_gravity_magnitude_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45:
        mipc_filter_data_filter_status_gx5_45_to_json(w, (const mipc_filter_data_filter_status_gx5_45_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS:
        mipc_filter_data_filter_status_cv7_ins_to_json(w,
                                                       (const mipc_filter_data_filter_status_cv7_ins_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_GPS_TIMESTAMP:
        mipc_filter_data_gps_timestamp_to_json(w, (const mipc_filter_data_gps_timestamp_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY:
        mipc_filter_data_quaternion_attitude_uncertainty_to_json(
            w, (const mipc_filter_data_quaternion_attitude_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_GRAVITY_VECTOR:
        mipc_filter_data_gravity_vector_to_json(w, (const mipc_filter_data_gravity_vector_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_HEADING_UPDATE_STATE:
        mipc_filter_data_heading_update_state_to_json(w, (const mipc_filter_data_heading_update_state_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_MAGNETIC_MODEL:
        mipc_filter_data_magnetic_model_to_json(w, (const mipc_filter_data_magnetic_model_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR:
        mipc_filter_data_gyro_scale_factor_to_json(w, (const mipc_filter_data_gyro_scale_factor_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR:
        mipc_filter_data_accel_scale_factor_to_json(w, (const mipc_filter_data_accel_scale_factor_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY:
        mipc_filter_data_gyro_scale_factor_uncertainty_to_json(
            w, (const mipc_filter_data_gyro_scale_factor_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY:
        mipc_filter_data_accel_scale_factor_uncertainty_to_json(
            w, (const mipc_filter_data_accel_scale_factor_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_COMPENSATED_ACCEL:
        mipc_filter_data_compensated_accel_to_json(w, (const mipc_filter_data_compensated_accel_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE:
        mipc_filter_data_standard_atmosphere_to_json(w, (const mipc_filter_data_standard_atmosphere_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_PRESSURE_ALTITUDE:
        mipc_filter_data_pressure_altitude_to_json(w, (const mipc_filter_data_pressure_altitude_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET:
        mipc_filter_data_mag_auto_hard_iron_offset_to_json(
            w, (const mipc_filter_data_mag_auto_hard_iron_offset_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX:
        mipc_filter_data_mag_auto_soft_iron_matrix_to_json(
            w, (const mipc_filter_data_mag_auto_soft_iron_matrix_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY:
        mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_to_json(
            w, (const mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY:
        mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_to_json(
            w, (const mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION:
        mipc_filter_data_gnss_antenna_offset_correction_to_json(
            w, (const mipc_filter_data_gnss_antenna_offset_correction_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        mipc_filter_data_gnss_antenna_offset_correction_uncertainty_to_json(
            w, (const mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION:
        mipc_filter_data_multi_antenna_offset_correction_to_json(
            w, (const mipc_filter_data_multi_antenna_offset_correction_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        mipc_filter_data_multi_antenna_offset_correction_uncertainty_to_json(
            w, (const mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY:
        mipc_filter_data_ecef_position_uncertainty_to_json(
            w, (const mipc_filter_data_ecef_position_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY:
        mipc_filter_data_ecef_velocity_uncertainty_to_json(
            w, (const mipc_filter_data_ecef_velocity_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ECEF_POSITION:
        mipc_filter_data_ecef_position_to_json(w, (const mipc_filter_data_ecef_position_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY:
        mipc_filter_data_ecef_velocity_to_json(w, (const mipc_filter_data_ecef_velocity_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_NED_RELATIVE_POSITION:
        mipc_filter_data_ned_relative_position_to_json(w,
                                                       (const mipc_filter_data_ned_relative_position_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS:
        mipc_filter_data_gnss_position_aiding_status_to_json(
            w, (const mipc_filter_data_gnss_position_aiding_status_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY:
        mipc_filter_data_aiding_measurement_summary_to_json(
            w, (const mipc_filter_data_aiding_measurement_summary_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR:
        mipc_filter_data_odometer_scale_factor_error_to_json(
            w, (const mipc_filter_data_odometer_scale_factor_error_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY:
        mipc_filter_data_odometer_scale_factor_error_uncertainty_to_json(
            w, (const mipc_filter_data_odometer_scale_factor_error_uncertainty_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS:
        mipc_filter_data_gnss_dual_antenna_status_to_json(
            w, (const mipc_filter_data_gnss_dual_antenna_status_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR:
        mipc_filter_data_aiding_frame_config_error_to_json(
            w, (const mipc_filter_data_aiding_frame_config_error_t *)in);
        return;
    case MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY:
        mipc_filter_data_aiding_frame_config_error_uncertainty_to_json(
            w, (const mipc_filter_data_aiding_frame_config_error_uncertainty_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_LLH_POSITION:
        mipc_gnss_receiver_1_llh_position_to_json(w, (const mipc_gnss_receiver_1_llh_position_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_ECEF_POSITION:
        mipc_gnss_receiver_1_ecef_position_to_json(w, (const mipc_gnss_receiver_1_ecef_position_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_NED_VELOCITY:
        mipc_gnss_receiver_1_ned_velocity_to_json(w, (const mipc_gnss_receiver_1_ned_velocity_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY:
        mipc_gnss_receiver_1_ecef_velocity_to_json(w, (const mipc_gnss_receiver_1_ecef_velocity_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_DOP:
        mipc_gnss_receiver_1_dop_to_json(w, (const mipc_gnss_receiver_1_dop_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_UTC_TIME:
        mipc_gnss_receiver_1_utc_time_to_json(w, (const mipc_gnss_receiver_1_utc_time_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_TIME:
        mipc_gnss_receiver_1_gps_time_to_json(w, (const mipc_gnss_receiver_1_gps_time_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_FIX_INFO:
        mipc_gnss_receiver_1_fix_info_to_json(w, (const mipc_gnss_receiver_1_fix_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS:
        mipc_gnss_receiver_1_hardware_status_to_json(w, (const mipc_gnss_receiver_1_hardware_status_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2:
        mipc_gnss_receiver_1_clock_info_2_to_json(w, (const mipc_gnss_receiver_1_clock_info_2_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS:
        mipc_gnss_receiver_1_gps_leap_seconds_to_json(w, (const mipc_gnss_receiver_1_gps_leap_seconds_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_SBAS_INFO:
        mipc_gnss_receiver_1_sbas_info_to_json(w, (const mipc_gnss_receiver_1_sbas_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS:
        mipc_gnss_receiver_1_satellite_status_to_json(w, (const mipc_gnss_receiver_1_satellite_status_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_RAW:
        mipc_gnss_receiver_1_raw_to_json(w, (const mipc_gnss_receiver_1_raw_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS:
        mipc_gnss_receiver_1_gps_ephemeris_to_json(w, (const mipc_gnss_receiver_1_gps_ephemeris_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS:
        mipc_gnss_receiver_1_glonass_ephemeris_to_json(w,
                                                       (const mipc_gnss_receiver_1_glonass_ephemeris_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS:
        mipc_gnss_receiver_1_galileo_ephemeris_to_json(w,
                                                       (const mipc_gnss_receiver_1_galileo_ephemeris_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS:
        mipc_gnss_receiver_1_beidou_ephemeris_to_json(w, (const mipc_gnss_receiver_1_beidou_ephemeris_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_LLH_POSITION:
        mipc_gnss_receiver_2_llh_position_to_json(w, (const mipc_gnss_receiver_2_llh_position_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_ECEF_POSITION:
        mipc_gnss_receiver_2_ecef_position_to_json(w, (const mipc_gnss_receiver_2_ecef_position_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_NED_VELOCITY:
        mipc_gnss_receiver_2_ned_velocity_to_json(w, (const mipc_gnss_receiver_2_ned_velocity_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY:
        mipc_gnss_receiver_2_ecef_velocity_to_json(w, (const mipc_gnss_receiver_2_ecef_velocity_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_DOP:
        mipc_gnss_receiver_2_dop_to_json(w, (const mipc_gnss_receiver_2_dop_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_UTC_TIME:
        mipc_gnss_receiver_2_utc_time_to_json(w, (const mipc_gnss_receiver_2_utc_time_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_TIME:
        mipc_gnss_receiver_2_gps_time_to_json(w, (const mipc_gnss_receiver_2_gps_time_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_FIX_INFO:
        mipc_gnss_receiver_2_fix_info_to_json(w, (const mipc_gnss_receiver_2_fix_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS:
        mipc_gnss_receiver_2_hardware_status_to_json(w, (const mipc_gnss_receiver_2_hardware_status_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2:
        mipc_gnss_receiver_2_clock_info_2_to_json(w, (const mipc_gnss_receiver_2_clock_info_2_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS:
        mipc_gnss_receiver_2_gps_leap_seconds_to_json(w, (const mipc_gnss_receiver_2_gps_leap_seconds_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_SBAS_INFO:
        mipc_gnss_receiver_2_sbas_info_to_json(w, (const mipc_gnss_receiver_2_sbas_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS:
        mipc_gnss_receiver_2_satellite_status_to_json(w, (const mipc_gnss_receiver_2_satellite_status_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_RAW:
        mipc_gnss_receiver_2_raw_to_json(w, (const mipc_gnss_receiver_2_raw_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS:
        mipc_gnss_receiver_2_gps_ephemeris_to_json(w, (const mipc_gnss_receiver_2_gps_ephemeris_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS:
        mipc_gnss_receiver_2_glonass_ephemeris_to_json(w,
                                                       (const mipc_gnss_receiver_2_glonass_ephemeris_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS:
        mipc_gnss_receiver_2_galileo_ephemeris_to_json(w,
                                                       (const mipc_gnss_receiver_2_galileo_ephemeris_t *)in);
        return;
    case MIPC_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS:
        mipc_gnss_receiver_2_beidou_ephemeris_to_json(w, (const mipc_gnss_receiver_2_beidou_ephemeris_t *)in);
        return;
    case MIPC_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO:
        mipc_gnss_corrections_base_station_info_to_json(
            w, (const mipc_gnss_corrections_base_station_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS:
        mipc_gnss_corrections_rtk_corrections_status_to_json(
            w, (const mipc_gnss_corrections_rtk_corrections_status_t *)in);
        return;
    case MIPC_FIELD_GNSS_EXTERNAL_LLH_POSITION:
        mipc_gnss_external_llh_position_to_json(w, (const mipc_gnss_external_llh_position_t *)in);
        return;
    case MIPC_FIELD_GNSS_EXTERNAL_NED_VELOCITY:
        mipc_gnss_external_ned_velocity_to_json(w, (const mipc_gnss_external_ned_velocity_t *)in);
        return;
    case MIPC_FIELD_GNSS_EXTERNAL_UTC_TIME:
        mipc_gnss_external_utc_time_to_json(w, (const mipc_gnss_external_utc_time_t *)in);
        return;
    case MIPC_FIELD_GNSS_EXTERNAL_FIX_INFO:
        mipc_gnss_external_fix_info_to_json(w, (const mipc_gnss_external_fix_info_t *)in);
        return;
    case MIPC_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS:
        mipc_gnss_external_satellite_status_to_json(w, (const mipc_gnss_external_satellite_status_t *)in);
        return;
    case MIPC_FIELD_SYSTEM_DATA_BUILT_IN_TEST:
        mipc_system_data_built_in_test_to_json(w, (const mipc_system_data_built_in_test_t *)in);
        return;
    case MIPC_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS:
        mipc_system_data_time_sync_status_to_json(w, (const mipc_system_data_time_sync_status_t *)in);
        return;
    case MIPC_FIELD_SYSTEM_DATA_GPIO_STATE:
        mipc_system_data_gpio_state_to_json(w, (const mipc_system_data_gpio_state_t *)in);
        return;
    case MIPC_FIELD_SHARED_EVENT_SOURCE:
        mipc_shared_event_source_to_json(w, (const mipc_shared_event_source_t *)in);
        return;
    case MIPC_FIELD_SHARED_GPS_TIMESTAMP:
        mipc_shared_gps_timestamp_to_json(w, (const mipc_shared_gps_timestamp_t *)in);
        return;
    case MIPC_FIELD_SHARED_DELTA_TIME:
        mipc_shared_delta_time_to_json(w, (const mipc_shared_delta_time_t *)in);
        return;
    case MIPC_FIELD_SHARED_REFERENCE_TIMESTAMP:
        mipc_shared_reference_timestamp_to_json(w, (const mipc_shared_reference_timestamp_t *)in);
        return;
    case MIPC_FIELD_SHARED_REFERENCE_TIME_DELTA:
        mipc_shared_reference_time_delta_to_json(w, (const mipc_shared_reference_time_delta_t *)in);
        return;
    case MIPC_FIELD_SHARED_EXTERNAL_TIMESTAMP:
        mipc_shared_external_timestamp_to_json(w, (const mipc_shared_external_timestamp_t *)in);
        return;
    case MIPC_FIELD_SHARED_EXTERNAL_TIME_DELTA:
        mipc_shared_external_time_delta_to_json(w, (const mipc_shared_external_time_delta_t *)in);
        return;
    case MIPC_FIELD_NONE:
    case MIPC_FIELD_COUNT:
    default:
        mipc_jw_lit(w, "null");
        return;
    }
}

int mipc_value_from_json(mipc_jr_t *jr, size_t pos, mipc_field_id_t id, mipc_field_value_t *value) {
    value->id = id;
    switch (id) {
    case MIPC_FIELD_ACK_NACK:
        return mipc_ack_nack_from_json(jr, pos, &value->u.ack_nack);
    case MIPC_FIELD_BASE_PING:
        return mipc_base_ping_from_json(jr, pos, &value->u.base_ping);
    case MIPC_FIELD_BASE_SET_TO_IDLE:
        return mipc_base_set_to_idle_from_json(jr, pos, &value->u.base_set_to_idle);
    case MIPC_FIELD_BASE_GET_DEVICE_INFO:
        return mipc_base_get_device_info_from_json(jr, pos, &value->u.base_get_device_info);
    case MIPC_FIELD_BASE_DEVICE_INFO:
        return mipc_base_device_info_from_json(jr, pos, &value->u.base_device_info);
    case MIPC_FIELD_BASE_GET_DEVICE_DESCRIPTORS:
        return mipc_base_get_device_descriptors_from_json(jr, pos, &value->u.base_get_device_descriptors);
    case MIPC_FIELD_BASE_DEVICE_DESCRIPTORS:
        return mipc_base_device_descriptors_from_json(jr, pos, &value->u.base_device_descriptors);
    case MIPC_FIELD_BASE_BUILT_IN_TEST:
        return mipc_base_built_in_test_from_json(jr, pos, &value->u.base_built_in_test);
    case MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45:
        return mipc_base_built_in_test_result_gx5_45_from_json(jr, pos,
                                                               &value->u.base_built_in_test_result_gx5_45);
    case MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS:
        return mipc_base_built_in_test_result_cv7_ins_from_json(jr, pos,
                                                                &value->u.base_built_in_test_result_cv7_ins);
    case MIPC_FIELD_BASE_RESUME:
        return mipc_base_resume_from_json(jr, pos, &value->u.base_resume);
    case MIPC_FIELD_BASE_GET_EXTENDED_DESCRIPTORS:
        return mipc_base_get_extended_descriptors_from_json(jr, pos, &value->u.base_get_extended_descriptors);
    case MIPC_FIELD_BASE_EXTENDED_DESCRIPTORS:
        return mipc_base_extended_descriptors_from_json(jr, pos, &value->u.base_extended_descriptors);
    case MIPC_FIELD_BASE_CONTINUOUS_BIT:
        return mipc_base_continuous_bit_from_json(jr, pos, &value->u.base_continuous_bit);
    case MIPC_FIELD_BASE_CONTINUOUS_BIT_RESULT:
        return mipc_base_continuous_bit_result_from_json(jr, pos, &value->u.base_continuous_bit_result);
    case MIPC_FIELD_BASE_COMM_PORT_SPEED:
        return mipc_base_comm_port_speed_from_json(jr, pos, &value->u.base_comm_port_speed);
    case MIPC_FIELD_BASE_COMM_PORT_SPEED_RESPONSE:
        return mipc_base_comm_port_speed_response_from_json(jr, pos, &value->u.base_comm_port_speed_response);
    case MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45:
        return mipc_base_gps_time_update_gx5_45_from_json(jr, pos, &value->u.base_gps_time_update_gx5_45);
    case MIPC_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS:
        return mipc_base_gps_time_update_cv7_ins_from_json(jr, pos, &value->u.base_gps_time_update_cv7_ins);
    case MIPC_FIELD_BASE_GPS_WEEK:
        return mipc_base_gps_week_from_json(jr, pos, &value->u.base_gps_week);
    case MIPC_FIELD_BASE_GPS_SECONDS:
        return mipc_base_gps_seconds_from_json(jr, pos, &value->u.base_gps_seconds);
    case MIPC_FIELD_BASE_DEVICE_RESET:
        return mipc_base_device_reset_from_json(jr, pos, &value->u.base_device_reset);
    case MIPC_FIELD_THREEDM_EVENT_CONTROL:
        return mipc_threedm_event_control_from_json(jr, pos, &value->u.threedm_event_control);
    case MIPC_FIELD_THREEDM_EVENT_CONTROL_RESPONSE:
        return mipc_threedm_event_control_response_from_json(jr, pos,
                                                             &value->u.threedm_event_control_response);
    case MIPC_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS:
        return mipc_threedm_get_event_trigger_status_from_json(jr, pos,
                                                               &value->u.threedm_get_event_trigger_status);
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_STATUS:
        return mipc_threedm_event_trigger_status_from_json(jr, pos, &value->u.threedm_event_trigger_status);
    case MIPC_FIELD_THREEDM_GET_EVENT_ACTION_STATUS:
        return mipc_threedm_get_event_action_status_from_json(jr, pos,
                                                              &value->u.threedm_get_event_action_status);
    case MIPC_FIELD_THREEDM_EVENT_ACTION_STATUS:
        return mipc_threedm_event_action_status_from_json(jr, pos, &value->u.threedm_event_action_status);
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG:
        return mipc_threedm_event_trigger_config_from_json(jr, pos, &value->u.threedm_event_trigger_config);
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE:
        return mipc_threedm_event_trigger_config_response_from_json(
            jr, pos, &value->u.threedm_event_trigger_config_response);
    case MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG:
        return mipc_threedm_event_action_config_from_json(jr, pos, &value->u.threedm_event_action_config);
    case MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE:
        return mipc_threedm_event_action_config_response_from_json(
            jr, pos, &value->u.threedm_event_action_config_response);
    case MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45:
        return mipc_threedm_device_startup_settings_gx5_45_from_json(
            jr, pos, &value->u.threedm_device_startup_settings_gx5_45);
    case MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS:
        return mipc_threedm_device_startup_settings_cv7_ins_from_json(
            jr, pos, &value->u.threedm_device_startup_settings_cv7_ins);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER:
        return mipc_threedm_sensor_to_vehicle_euler_from_json(jr, pos,
                                                              &value->u.threedm_sensor_to_vehicle_euler);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE:
        return mipc_threedm_sensor_to_vehicle_euler_response_from_json(
            jr, pos, &value->u.threedm_sensor_to_vehicle_euler_response);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION:
        return mipc_threedm_sensor_to_vehicle_quaternion_from_json(
            jr, pos, &value->u.threedm_sensor_to_vehicle_quaternion);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE:
        return mipc_threedm_sensor_to_vehicle_quaternion_response_from_json(
            jr, pos, &value->u.threedm_sensor_to_vehicle_quaternion_response);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM:
        return mipc_threedm_sensor_to_vehicle_dcm_from_json(jr, pos, &value->u.threedm_sensor_to_vehicle_dcm);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE:
        return mipc_threedm_sensor_to_vehicle_dcm_response_from_json(
            jr, pos, &value->u.threedm_sensor_to_vehicle_dcm_response);
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45:
        return mipc_threedm_accel_bias_gx5_45_from_json(jr, pos, &value->u.threedm_accel_bias_gx5_45);
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS:
        return mipc_threedm_accel_bias_cv7_ins_from_json(jr, pos, &value->u.threedm_accel_bias_cv7_ins);
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_RESPONSE:
        return mipc_threedm_accel_bias_response_from_json(jr, pos, &value->u.threedm_accel_bias_response);
    case MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45:
        return mipc_threedm_gyro_bias_gx5_45_from_json(jr, pos, &value->u.threedm_gyro_bias_gx5_45);
    case MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS:
        return mipc_threedm_gyro_bias_cv7_ins_from_json(jr, pos, &value->u.threedm_gyro_bias_cv7_ins);
    case MIPC_FIELD_THREEDM_GYRO_BIAS_RESPONSE:
        return mipc_threedm_gyro_bias_response_from_json(jr, pos, &value->u.threedm_gyro_bias_response);
    case MIPC_FIELD_THREEDM_CAPTURE_GYRO_BIAS:
        return mipc_threedm_capture_gyro_bias_from_json(jr, pos, &value->u.threedm_capture_gyro_bias);
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45:
        return mipc_threedm_mag_hard_iron_offset_gx5_45_from_json(
            jr, pos, &value->u.threedm_mag_hard_iron_offset_gx5_45);
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS:
        return mipc_threedm_mag_hard_iron_offset_cv7_ins_from_json(
            jr, pos, &value->u.threedm_mag_hard_iron_offset_cv7_ins);
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE:
        return mipc_threedm_mag_hard_iron_offset_response_from_json(
            jr, pos, &value->u.threedm_mag_hard_iron_offset_response);
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45:
        return mipc_threedm_mag_soft_iron_matrix_gx5_45_from_json(
            jr, pos, &value->u.threedm_mag_soft_iron_matrix_gx5_45);
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS:
        return mipc_threedm_mag_soft_iron_matrix_cv7_ins_from_json(
            jr, pos, &value->u.threedm_mag_soft_iron_matrix_cv7_ins);
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE:
        return mipc_threedm_mag_soft_iron_matrix_response_from_json(
            jr, pos, &value->u.threedm_mag_soft_iron_matrix_response);
    case MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE:
        return mipc_threedm_coning_sculling_enable_from_json(jr, pos,
                                                             &value->u.threedm_coning_sculling_enable);
    case MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE:
        return mipc_threedm_coning_sculling_enable_response_from_json(
            jr, pos, &value->u.threedm_coning_sculling_enable_response);
    case MIPC_FIELD_THREEDM_UART_BAUDRATE:
        return mipc_threedm_uart_baudrate_from_json(jr, pos, &value->u.threedm_uart_baudrate);
    case MIPC_FIELD_THREEDM_UART_BAUDRATE_RESPONSE:
        return mipc_threedm_uart_baudrate_response_from_json(jr, pos,
                                                             &value->u.threedm_uart_baudrate_response);
    case MIPC_FIELD_THREEDM_GPIO_CONFIG:
        return mipc_threedm_gpio_config_from_json(jr, pos, &value->u.threedm_gpio_config);
    case MIPC_FIELD_THREEDM_GPIO_CONFIG_RESPONSE:
        return mipc_threedm_gpio_config_response_from_json(jr, pos, &value->u.threedm_gpio_config_response);
    case MIPC_FIELD_THREEDM_GPIO_STATE:
        return mipc_threedm_gpio_state_from_json(jr, pos, &value->u.threedm_gpio_state);
    case MIPC_FIELD_THREEDM_GPIO_STATE_RESPONSE:
        return mipc_threedm_gpio_state_response_from_json(jr, pos, &value->u.threedm_gpio_state_response);
    case MIPC_FIELD_THREEDM_ODOMETER_CONFIG:
        return mipc_threedm_odometer_config_from_json(jr, pos, &value->u.threedm_odometer_config);
    case MIPC_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE:
        return mipc_threedm_odometer_config_response_from_json(jr, pos,
                                                               &value->u.threedm_odometer_config_response);
    case MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER:
        return mipc_threedm_advanced_lowpass_filter_from_json(jr, pos,
                                                              &value->u.threedm_advanced_lowpass_filter);
    case MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE:
        return mipc_threedm_advanced_lowpass_filter_response_from_json(
            jr, pos, &value->u.threedm_advanced_lowpass_filter_response);
    case MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER:
        return mipc_threedm_complementary_filter_from_json(jr, pos, &value->u.threedm_complementary_filter);
    case MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE:
        return mipc_threedm_complementary_filter_response_from_json(
            jr, pos, &value->u.threedm_complementary_filter_response);
    case MIPC_FIELD_THREEDM_SENSOR_RANGE:
        return mipc_threedm_sensor_range_from_json(jr, pos, &value->u.threedm_sensor_range);
    case MIPC_FIELD_THREEDM_SENSOR_RANGE_RESPONSE:
        return mipc_threedm_sensor_range_response_from_json(jr, pos, &value->u.threedm_sensor_range_response);
    case MIPC_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES:
        return mipc_threedm_get_calibrated_sensor_ranges_from_json(
            jr, pos, &value->u.threedm_get_calibrated_sensor_ranges);
    case MIPC_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES:
        return mipc_threedm_calibrated_sensor_ranges_from_json(jr, pos,
                                                               &value->u.threedm_calibrated_sensor_ranges);
    case MIPC_FIELD_THREEDM_LOWPASS_FILTER:
        return mipc_threedm_lowpass_filter_from_json(jr, pos, &value->u.threedm_lowpass_filter);
    case MIPC_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE:
        return mipc_threedm_lowpass_filter_response_from_json(jr, pos,
                                                              &value->u.threedm_lowpass_filter_response);
    case MIPC_FIELD_THREEDM_POLL_IMU_DATA:
        return mipc_threedm_poll_imu_data_from_json(jr, pos, &value->u.threedm_poll_imu_data);
    case MIPC_FIELD_THREEDM_POLL_GNSS_DATA:
        return mipc_threedm_poll_gnss_data_from_json(jr, pos, &value->u.threedm_poll_gnss_data);
    case MIPC_FIELD_THREEDM_POLL_FILTER_DATA:
        return mipc_threedm_poll_filter_data_from_json(jr, pos, &value->u.threedm_poll_filter_data);
    case MIPC_FIELD_THREEDM_POLL_NMEA_DATA:
        return mipc_threedm_poll_nmea_data_from_json(jr, pos, &value->u.threedm_poll_nmea_data);
    case MIPC_FIELD_THREEDM_POLL_DATA:
        return mipc_threedm_poll_data_from_json(jr, pos, &value->u.threedm_poll_data);
    case MIPC_FIELD_THREEDM_GET_IMU_BASE_RATE:
        return mipc_threedm_get_imu_base_rate_from_json(jr, pos, &value->u.threedm_get_imu_base_rate);
    case MIPC_FIELD_THREEDM_IMU_BASE_RATE:
        return mipc_threedm_imu_base_rate_from_json(jr, pos, &value->u.threedm_imu_base_rate);
    case MIPC_FIELD_THREEDM_GET_GNSS_BASE_RATE:
        return mipc_threedm_get_gnss_base_rate_from_json(jr, pos, &value->u.threedm_get_gnss_base_rate);
    case MIPC_FIELD_THREEDM_GNSS_BASE_RATE:
        return mipc_threedm_gnss_base_rate_from_json(jr, pos, &value->u.threedm_gnss_base_rate);
    case MIPC_FIELD_THREEDM_GET_FILTER_BASE_RATE:
        return mipc_threedm_get_filter_base_rate_from_json(jr, pos, &value->u.threedm_get_filter_base_rate);
    case MIPC_FIELD_THREEDM_FILTER_BASE_RATE:
        return mipc_threedm_filter_base_rate_from_json(jr, pos, &value->u.threedm_filter_base_rate);
    case MIPC_FIELD_THREEDM_GET_BASE_RATE:
        return mipc_threedm_get_base_rate_from_json(jr, pos, &value->u.threedm_get_base_rate);
    case MIPC_FIELD_THREEDM_BASE_RATE:
        return mipc_threedm_base_rate_from_json(jr, pos, &value->u.threedm_base_rate);
    case MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT:
        return mipc_threedm_imu_message_format_from_json(jr, pos, &value->u.threedm_imu_message_format);
    case MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_imu_message_format_response_from_json(
            jr, pos, &value->u.threedm_imu_message_format_response);
    case MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT:
        return mipc_threedm_gnss_message_format_from_json(jr, pos, &value->u.threedm_gnss_message_format);
    case MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_gnss_message_format_response_from_json(
            jr, pos, &value->u.threedm_gnss_message_format_response);
    case MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT:
        return mipc_threedm_filter_message_format_from_json(jr, pos, &value->u.threedm_filter_message_format);
    case MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_filter_message_format_response_from_json(
            jr, pos, &value->u.threedm_filter_message_format_response);
    case MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT:
        return mipc_threedm_nmea_message_format_from_json(jr, pos, &value->u.threedm_nmea_message_format);
    case MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_nmea_message_format_response_from_json(
            jr, pos, &value->u.threedm_nmea_message_format_response);
    case MIPC_FIELD_THREEDM_MESSAGE_FORMAT:
        return mipc_threedm_message_format_from_json(jr, pos, &value->u.threedm_message_format);
    case MIPC_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_message_format_response_from_json(jr, pos,
                                                              &value->u.threedm_message_format_response);
    case MIPC_FIELD_THREEDM_FACTORY_STREAMING:
        return mipc_threedm_factory_streaming_from_json(jr, pos, &value->u.threedm_factory_streaming);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45:
        return mipc_threedm_data_stream_control_gx5_45_from_json(
            jr, pos, &value->u.threedm_data_stream_control_gx5_45);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS:
        return mipc_threedm_data_stream_control_cv7_ins_from_json(
            jr, pos, &value->u.threedm_data_stream_control_cv7_ins);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45:
        return mipc_threedm_data_stream_control_response_gx5_45_from_json(
            jr, pos, &value->u.threedm_data_stream_control_response_gx5_45);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS:
        return mipc_threedm_data_stream_control_response_cv7_ins_from_json(
            jr, pos, &value->u.threedm_data_stream_control_response_cv7_ins);
    case MIPC_FIELD_THREEDM_RAW_RTCM_MESSAGE:
        return mipc_threedm_raw_rtcm_message_from_json(jr, pos, &value->u.threedm_raw_rtcm_message);
    case MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS:
        return mipc_threedm_gnss_constellation_settings_from_json(
            jr, pos, &value->u.threedm_gnss_constellation_settings);
    case MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE:
        return mipc_threedm_gnss_constellation_settings_response_from_json(
            jr, pos, &value->u.threedm_gnss_constellation_settings_response);
    case MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS:
        return mipc_threedm_gnss_sbas_settings_from_json(jr, pos, &value->u.threedm_gnss_sbas_settings);
    case MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE:
        return mipc_threedm_gnss_sbas_settings_response_from_json(
            jr, pos, &value->u.threedm_gnss_sbas_settings_response);
    case MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL:
        return mipc_threedm_gnss_assisted_fix_control_from_json(jr, pos,
                                                                &value->u.threedm_gnss_assisted_fix_control);
    case MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE:
        return mipc_threedm_gnss_assisted_fix_control_response_from_json(
            jr, pos, &value->u.threedm_gnss_assisted_fix_control_response);
    case MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE:
        return mipc_threedm_gnss_assist_time_update_from_json(jr, pos,
                                                              &value->u.threedm_gnss_assist_time_update);
    case MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE:
        return mipc_threedm_gnss_assist_time_update_response_from_json(
            jr, pos, &value->u.threedm_gnss_assist_time_update_response);
    case MIPC_FIELD_THREEDM_PPS_SOURCE:
        return mipc_threedm_pps_source_from_json(jr, pos, &value->u.threedm_pps_source);
    case MIPC_FIELD_THREEDM_PPS_SOURCE_RESPONSE:
        return mipc_threedm_pps_source_response_from_json(jr, pos, &value->u.threedm_pps_source_response);
    case MIPC_FIELD_THREEDM_GET_SUPPORTED_EVENTS:
        return mipc_threedm_get_supported_events_from_json(jr, pos, &value->u.threedm_get_supported_events);
    case MIPC_FIELD_THREEDM_SUPPORTED_EVENTS:
        return mipc_threedm_supported_events_from_json(jr, pos, &value->u.threedm_supported_events);
    case MIPC_FIELD_THREEDM_DEVICE_STATUS:
        return mipc_threedm_device_status_from_json(jr, pos, &value->u.threedm_device_status);
    case MIPC_FIELD_THREEDM_DEVICE_STATUS_RESPONSE:
        return mipc_threedm_device_status_response_from_json(jr, pos,
                                                             &value->u.threedm_device_status_response);
    case MIPC_FIELD_FILTER_RESET_FILTER:
        return mipc_filter_reset_filter_from_json(jr, pos, &value->u.filter_reset_filter);
    case MIPC_FIELD_FILTER_SET_INITIAL_ATTITUDE:
        return mipc_filter_set_initial_attitude_from_json(jr, pos, &value->u.filter_set_initial_attitude);
    case MIPC_FIELD_FILTER_SET_INITIAL_HEADING:
        return mipc_filter_set_initial_heading_from_json(jr, pos, &value->u.filter_set_initial_heading);
    case MIPC_FIELD_FILTER_RUN_FILTER:
        return mipc_filter_run_filter_from_json(jr, pos, &value->u.filter_run_filter);
    case MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE:
        return mipc_filter_vehicle_dynamics_mode_from_json(jr, pos, &value->u.filter_vehicle_dynamics_mode);
    case MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE:
        return mipc_filter_vehicle_dynamics_mode_response_from_json(
            jr, pos, &value->u.filter_vehicle_dynamics_mode_response);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM:
        return mipc_filter_sensor_to_vehicle_transform_from_json(
            jr, pos, &value->u.filter_sensor_to_vehicle_transform);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE:
        return mipc_filter_sensor_to_vehicle_transform_response_from_json(
            jr, pos, &value->u.filter_sensor_to_vehicle_transform_response);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET:
        return mipc_filter_sensor_to_vehicle_offset_from_json(jr, pos,
                                                              &value->u.filter_sensor_to_vehicle_offset);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE:
        return mipc_filter_sensor_to_vehicle_offset_response_from_json(
            jr, pos, &value->u.filter_sensor_to_vehicle_offset_response);
    case MIPC_FIELD_FILTER_ANTENNA_OFFSET:
        return mipc_filter_antenna_offset_from_json(jr, pos, &value->u.filter_antenna_offset);
    case MIPC_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE:
        return mipc_filter_antenna_offset_response_from_json(jr, pos,
                                                             &value->u.filter_antenna_offset_response);
    case MIPC_FIELD_FILTER_ESTIMATION_CONTROL:
        return mipc_filter_estimation_control_from_json(jr, pos, &value->u.filter_estimation_control);
    case MIPC_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE:
        return mipc_filter_estimation_control_response_from_json(
            jr, pos, &value->u.filter_estimation_control_response);
    case MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL:
        return mipc_filter_gnss_source_control_from_json(jr, pos, &value->u.filter_gnss_source_control);
    case MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE:
        return mipc_filter_gnss_source_control_response_from_json(
            jr, pos, &value->u.filter_gnss_source_control_response);
    case MIPC_FIELD_FILTER_EXTERNAL_GNSS_UPDATE:
        return mipc_filter_external_gnss_update_from_json(jr, pos, &value->u.filter_external_gnss_update);
    case MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE:
        return mipc_filter_external_heading_update_from_json(jr, pos,
                                                             &value->u.filter_external_heading_update);
    case MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL:
        return mipc_filter_heading_update_control_from_json(jr, pos, &value->u.filter_heading_update_control);
    case MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE:
        return mipc_filter_heading_update_control_response_from_json(
            jr, pos, &value->u.filter_heading_update_control_response);
    case MIPC_FIELD_FILTER_AUTO_INIT_CONTROL:
        return mipc_filter_auto_init_control_from_json(jr, pos, &value->u.filter_auto_init_control);
    case MIPC_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE:
        return mipc_filter_auto_init_control_response_from_json(jr, pos,
                                                                &value->u.filter_auto_init_control_response);
    case MIPC_FIELD_FILTER_ACCEL_NOISE:
        return mipc_filter_accel_noise_from_json(jr, pos, &value->u.filter_accel_noise);
    case MIPC_FIELD_FILTER_ACCEL_NOISE_RESPONSE:
        return mipc_filter_accel_noise_response_from_json(jr, pos, &value->u.filter_accel_noise_response);
    case MIPC_FIELD_FILTER_GYRO_NOISE:
        return mipc_filter_gyro_noise_from_json(jr, pos, &value->u.filter_gyro_noise);
    case MIPC_FIELD_FILTER_GYRO_NOISE_RESPONSE:
        return mipc_filter_gyro_noise_response_from_json(jr, pos, &value->u.filter_gyro_noise_response);
    case MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL:
        return mipc_filter_accel_bias_model_from_json(jr, pos, &value->u.filter_accel_bias_model);
    case MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE:
        return mipc_filter_accel_bias_model_response_from_json(jr, pos,
                                                               &value->u.filter_accel_bias_model_response);
    case MIPC_FIELD_FILTER_GYRO_BIAS_MODEL:
        return mipc_filter_gyro_bias_model_from_json(jr, pos, &value->u.filter_gyro_bias_model);
    case MIPC_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE:
        return mipc_filter_gyro_bias_model_response_from_json(jr, pos,
                                                              &value->u.filter_gyro_bias_model_response);
    case MIPC_FIELD_FILTER_ZUPT_CONTROL:
        return mipc_filter_zupt_control_from_json(jr, pos, &value->u.filter_zupt_control);
    case MIPC_FIELD_FILTER_ZUPT_CONTROL_RESPONSE:
        return mipc_filter_zupt_control_response_from_json(jr, pos, &value->u.filter_zupt_control_response);
    case MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME:
        return mipc_filter_external_heading_update_with_time_from_json(
            jr, pos, &value->u.filter_external_heading_update_with_time);
    case MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL:
        return mipc_filter_zero_angular_rate_update_control_from_json(
            jr, pos, &value->u.filter_zero_angular_rate_update_control);
    case MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE:
        return mipc_filter_zero_angular_rate_update_control_response_from_json(
            jr, pos, &value->u.filter_zero_angular_rate_update_control_response);
    case MIPC_FIELD_FILTER_TARE_ORIENTATION:
        return mipc_filter_tare_orientation_from_json(jr, pos, &value->u.filter_tare_orientation);
    case MIPC_FIELD_FILTER_COMMANDED_ZUPT:
        return mipc_filter_commanded_zupt_from_json(jr, pos, &value->u.filter_commanded_zupt);
    case MIPC_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE:
        return mipc_filter_commanded_zero_angular_rate_update_from_json(
            jr, pos, &value->u.filter_commanded_zero_angular_rate_update);
    case MIPC_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION:
        return mipc_filter_mag_capture_auto_calibration_from_json(
            jr, pos, &value->u.filter_mag_capture_auto_calibration);
    case MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV:
        return mipc_filter_gravity_noise_std_dev_from_json(jr, pos, &value->u.filter_gravity_noise_std_dev);
    case MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE:
        return mipc_filter_gravity_noise_std_dev_response_from_json(
            jr, pos, &value->u.filter_gravity_noise_std_dev_response);
    case MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV:
        return mipc_filter_pressure_altitude_noise_std_dev_from_json(
            jr, pos, &value->u.filter_pressure_altitude_noise_std_dev);
    case MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE:
        return mipc_filter_pressure_altitude_noise_std_dev_response_from_json(
            jr, pos, &value->u.filter_pressure_altitude_noise_std_dev_response);
    case MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE:
        return mipc_filter_hard_iron_offset_noise_from_json(jr, pos, &value->u.filter_hard_iron_offset_noise);
    case MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE:
        return mipc_filter_hard_iron_offset_noise_response_from_json(
            jr, pos, &value->u.filter_hard_iron_offset_noise_response);
    case MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE:
        return mipc_filter_soft_iron_matrix_noise_from_json(jr, pos, &value->u.filter_soft_iron_matrix_noise);
    case MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE:
        return mipc_filter_soft_iron_matrix_noise_response_from_json(
            jr, pos, &value->u.filter_soft_iron_matrix_noise_response);
    case MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV:
        return mipc_filter_mag_noise_std_dev_from_json(jr, pos, &value->u.filter_mag_noise_std_dev);
    case MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE:
        return mipc_filter_mag_noise_std_dev_response_from_json(jr, pos,
                                                                &value->u.filter_mag_noise_std_dev_response);
    case MIPC_FIELD_FILTER_DECLINATION_SOURCE:
        return mipc_filter_declination_source_from_json(jr, pos, &value->u.filter_declination_source);
    case MIPC_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE:
        return mipc_filter_declination_source_response_from_json(
            jr, pos, &value->u.filter_declination_source_response);
    case MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mipc_filter_gravity_magnitude_adaptive_measurement_from_json(
            jr, pos, &value->u.filter_gravity_magnitude_adaptive_measurement);
    case MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mipc_filter_gravity_magnitude_adaptive_measurement_response_from_json(
            jr, pos, &value->u.filter_gravity_magnitude_adaptive_measurement_response);
    case MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mipc_filter_mag_magnitude_adaptive_measurement_from_json(
            jr, pos, &value->u.filter_mag_magnitude_adaptive_measurement);
    case MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mipc_filter_mag_magnitude_adaptive_measurement_response_from_json(
            jr, pos, &value->u.filter_mag_magnitude_adaptive_measurement_response);
    case MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT:
        return mipc_filter_mag_dip_angle_adaptive_measurement_from_json(
            jr, pos, &value->u.filter_mag_dip_angle_adaptive_measurement);
    case MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mipc_filter_mag_dip_angle_adaptive_measurement_response_from_json(
            jr, pos, &value->u.filter_mag_dip_angle_adaptive_measurement_response);
    case MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL:
        return mipc_filter_altitude_aiding_control_from_json(jr, pos,
                                                             &value->u.filter_altitude_aiding_control);
    case MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE:
        return mipc_filter_altitude_aiding_control_response_from_json(
            jr, pos, &value->u.filter_altitude_aiding_control_response);
    case MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL:
        return mipc_filter_pitch_roll_aiding_control_from_json(jr, pos,
                                                               &value->u.filter_pitch_roll_aiding_control);
    case MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE:
        return mipc_filter_pitch_roll_aiding_control_response_from_json(
            jr, pos, &value->u.filter_pitch_roll_aiding_control_response);
    case MIPC_FIELD_FILTER_INCLINATION_SOURCE:
        return mipc_filter_inclination_source_from_json(jr, pos, &value->u.filter_inclination_source);
    case MIPC_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE:
        return mipc_filter_inclination_source_response_from_json(
            jr, pos, &value->u.filter_inclination_source_response);
    case MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE:
        return mipc_filter_magnetic_field_magnitude_source_from_json(
            jr, pos, &value->u.filter_magnetic_field_magnitude_source);
    case MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE:
        return mipc_filter_magnetic_field_magnitude_source_response_from_json(
            jr, pos, &value->u.filter_magnetic_field_magnitude_source_response);
    case MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL:
        return mipc_filter_aiding_measurement_control_from_json(jr, pos,
                                                                &value->u.filter_aiding_measurement_control);
    case MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE:
        return mipc_filter_aiding_measurement_control_response_from_json(
            jr, pos, &value->u.filter_aiding_measurement_control_response);
    case MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION:
        return mipc_filter_initialization_configuration_from_json(
            jr, pos, &value->u.filter_initialization_configuration);
    case MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE:
        return mipc_filter_initialization_configuration_response_from_json(
            jr, pos, &value->u.filter_initialization_configuration_response);
    case MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL:
        return mipc_filter_adaptive_filter_control_from_json(jr, pos,
                                                             &value->u.filter_adaptive_filter_control);
    case MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE:
        return mipc_filter_adaptive_filter_control_response_from_json(
            jr, pos, &value->u.filter_adaptive_filter_control_response);
    case MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET:
        return mipc_filter_multi_antenna_offset_from_json(jr, pos, &value->u.filter_multi_antenna_offset);
    case MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE:
        return mipc_filter_multi_antenna_offset_response_from_json(
            jr, pos, &value->u.filter_multi_antenna_offset_response);
    case MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION:
        return mipc_filter_relative_position_configuration_from_json(
            jr, pos, &value->u.filter_relative_position_configuration);
    case MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE:
        return mipc_filter_relative_position_configuration_response_from_json(
            jr, pos, &value->u.filter_relative_position_configuration_response);
    case MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM:
        return mipc_filter_reference_point_lever_arm_from_json(jr, pos,
                                                               &value->u.filter_reference_point_lever_arm);
    case MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE:
        return mipc_filter_reference_point_lever_arm_response_from_json(
            jr, pos, &value->u.filter_reference_point_lever_arm_response);
    case MIPC_FIELD_FILTER_SPEED_LEVER_ARM:
        return mipc_filter_speed_lever_arm_from_json(jr, pos, &value->u.filter_speed_lever_arm);
    case MIPC_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE:
        return mipc_filter_speed_lever_arm_response_from_json(jr, pos,
                                                              &value->u.filter_speed_lever_arm_response);
    case MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL:
        return mipc_filter_wheeled_vehicle_constraint_control_from_json(
            jr, pos, &value->u.filter_wheeled_vehicle_constraint_control);
    case MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE:
        return mipc_filter_wheeled_vehicle_constraint_control_response_from_json(
            jr, pos, &value->u.filter_wheeled_vehicle_constraint_control_response);
    case MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL:
        return mipc_filter_gnss_antenna_calibration_control_from_json(
            jr, pos, &value->u.filter_gnss_antenna_calibration_control);
    case MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE:
        return mipc_filter_gnss_antenna_calibration_control_response_from_json(
            jr, pos, &value->u.filter_gnss_antenna_calibration_control_response);
    case MIPC_FIELD_GNSS_RECEIVER_INFO:
        return mipc_gnss_receiver_info_from_json(jr, pos, &value->u.gnss_receiver_info);
    case MIPC_FIELD_GNSS_RECEIVER_INFO_RESPONSE:
        return mipc_gnss_receiver_info_response_from_json(jr, pos, &value->u.gnss_receiver_info_response);
    case MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION:
        return mipc_gnss_signal_configuration_from_json(jr, pos, &value->u.gnss_signal_configuration);
    case MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE:
        return mipc_gnss_signal_configuration_response_from_json(
            jr, pos, &value->u.gnss_signal_configuration_response);
    case MIPC_FIELD_GNSS_SPARTN_CONFIGURATION:
        return mipc_gnss_spartn_configuration_from_json(jr, pos, &value->u.gnss_spartn_configuration);
    case MIPC_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE:
        return mipc_gnss_spartn_configuration_response_from_json(
            jr, pos, &value->u.gnss_spartn_configuration_response);
    case MIPC_FIELD_AIDING_FRAME_CONFIG:
        return mipc_aiding_frame_config_from_json(jr, pos, &value->u.aiding_frame_config);
    case MIPC_FIELD_AIDING_FRAME_CONFIG_RESPONSE:
        return mipc_aiding_frame_config_response_from_json(jr, pos, &value->u.aiding_frame_config_response);
    case MIPC_FIELD_AIDING_ECHO_CONTROL:
        return mipc_aiding_echo_control_from_json(jr, pos, &value->u.aiding_echo_control);
    case MIPC_FIELD_AIDING_ECHO_CONTROL_RESPONSE:
        return mipc_aiding_echo_control_response_from_json(jr, pos, &value->u.aiding_echo_control_response);
    case MIPC_FIELD_AIDING_ECEF_POSITION:
        return mipc_aiding_ecef_position_from_json(jr, pos, &value->u.aiding_ecef_position);
    case MIPC_FIELD_AIDING_LLH_POSITION:
        return mipc_aiding_llh_position_from_json(jr, pos, &value->u.aiding_llh_position);
    case MIPC_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID:
        return mipc_aiding_height_above_ellipsoid_from_json(jr, pos, &value->u.aiding_height_above_ellipsoid);
    case MIPC_FIELD_AIDING_ECEF_VELOCITY:
        return mipc_aiding_ecef_velocity_from_json(jr, pos, &value->u.aiding_ecef_velocity);
    case MIPC_FIELD_AIDING_NED_VELOCITY:
        return mipc_aiding_ned_velocity_from_json(jr, pos, &value->u.aiding_ned_velocity);
    case MIPC_FIELD_AIDING_BODY_FRAME_VELOCITY:
        return mipc_aiding_body_frame_velocity_from_json(jr, pos, &value->u.aiding_body_frame_velocity);
    case MIPC_FIELD_AIDING_TRUE_HEADING:
        return mipc_aiding_true_heading_from_json(jr, pos, &value->u.aiding_true_heading);
    case MIPC_FIELD_AIDING_MAGNETIC_FIELD:
        return mipc_aiding_magnetic_field_from_json(jr, pos, &value->u.aiding_magnetic_field);
    case MIPC_FIELD_AIDING_PRESSURE:
        return mipc_aiding_pressure_from_json(jr, pos, &value->u.aiding_pressure);
    case MIPC_FIELD_SYSTEM_COMMUNICATION_MODE:
        return mipc_system_communication_mode_from_json(jr, pos, &value->u.system_communication_mode);
    case MIPC_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE:
        return mipc_system_communication_mode_response_from_json(
            jr, pos, &value->u.system_communication_mode_response);
    case MIPC_FIELD_SENSOR_SCALED_ACCEL:
        return mipc_sensor_scaled_accel_from_json(jr, pos, &value->u.sensor_scaled_accel);
    case MIPC_FIELD_SENSOR_SCALED_GYRO:
        return mipc_sensor_scaled_gyro_from_json(jr, pos, &value->u.sensor_scaled_gyro);
    case MIPC_FIELD_SENSOR_SCALED_MAG:
        return mipc_sensor_scaled_mag_from_json(jr, pos, &value->u.sensor_scaled_mag);
    case MIPC_FIELD_SENSOR_DELTA_THETA:
        return mipc_sensor_delta_theta_from_json(jr, pos, &value->u.sensor_delta_theta);
    case MIPC_FIELD_SENSOR_DELTA_VELOCITY:
        return mipc_sensor_delta_velocity_from_json(jr, pos, &value->u.sensor_delta_velocity);
    case MIPC_FIELD_SENSOR_CF_ORIENTATION_MATRIX:
        return mipc_sensor_cf_orientation_matrix_from_json(jr, pos, &value->u.sensor_cf_orientation_matrix);
    case MIPC_FIELD_SENSOR_CF_QUATERNION:
        return mipc_sensor_cf_quaternion_from_json(jr, pos, &value->u.sensor_cf_quaternion);
    case MIPC_FIELD_SENSOR_CF_EULER_ANGLES:
        return mipc_sensor_cf_euler_angles_from_json(jr, pos, &value->u.sensor_cf_euler_angles);
    case MIPC_FIELD_SENSOR_CF_STABILIZED_NORTH:
        return mipc_sensor_cf_stabilized_north_from_json(jr, pos, &value->u.sensor_cf_stabilized_north);
    case MIPC_FIELD_SENSOR_CF_STABILIZED_UP:
        return mipc_sensor_cf_stabilized_up_from_json(jr, pos, &value->u.sensor_cf_stabilized_up);
    case MIPC_FIELD_SENSOR_GPS_TIMESTAMP:
        return mipc_sensor_gps_timestamp_from_json(jr, pos, &value->u.sensor_gps_timestamp);
    case MIPC_FIELD_SENSOR_TEMPERATURE_STATISTICS:
        return mipc_sensor_temperature_statistics_from_json(jr, pos, &value->u.sensor_temperature_statistics);
    case MIPC_FIELD_SENSOR_SCALED_PRESSURE:
        return mipc_sensor_scaled_pressure_from_json(jr, pos, &value->u.sensor_scaled_pressure);
    case MIPC_FIELD_SENSOR_OVERRANGE_STATUS:
        return mipc_sensor_overrange_status_from_json(jr, pos, &value->u.sensor_overrange_status);
    case MIPC_FIELD_SENSOR_ODOMETER_DATA:
        return mipc_sensor_odometer_data_from_json(jr, pos, &value->u.sensor_odometer_data);
    case MIPC_FIELD_GNSS_DATA_LLH_POSITION:
        return mipc_gnss_data_llh_position_from_json(jr, pos, &value->u.gnss_data_llh_position);
    case MIPC_FIELD_GNSS_DATA_ECEF_POSITION:
        return mipc_gnss_data_ecef_position_from_json(jr, pos, &value->u.gnss_data_ecef_position);
    case MIPC_FIELD_GNSS_DATA_NED_VELOCITY:
        return mipc_gnss_data_ned_velocity_from_json(jr, pos, &value->u.gnss_data_ned_velocity);
    case MIPC_FIELD_GNSS_DATA_ECEF_VELOCITY:
        return mipc_gnss_data_ecef_velocity_from_json(jr, pos, &value->u.gnss_data_ecef_velocity);
    case MIPC_FIELD_GNSS_DATA_DOP:
        return mipc_gnss_data_dop_from_json(jr, pos, &value->u.gnss_data_dop);
    case MIPC_FIELD_GNSS_DATA_UTC_TIME:
        return mipc_gnss_data_utc_time_from_json(jr, pos, &value->u.gnss_data_utc_time);
    case MIPC_FIELD_GNSS_DATA_GPS_TIME:
        return mipc_gnss_data_gps_time_from_json(jr, pos, &value->u.gnss_data_gps_time);
    case MIPC_FIELD_GNSS_DATA_CLOCK_INFO:
        return mipc_gnss_data_clock_info_from_json(jr, pos, &value->u.gnss_data_clock_info);
    case MIPC_FIELD_GNSS_DATA_FIX_INFO:
        return mipc_gnss_data_fix_info_from_json(jr, pos, &value->u.gnss_data_fix_info);
    case MIPC_FIELD_GNSS_DATA_SV_INFO:
        return mipc_gnss_data_sv_info_from_json(jr, pos, &value->u.gnss_data_sv_info);
    case MIPC_FIELD_GNSS_DATA_HARDWARE_STATUS:
        return mipc_gnss_data_hardware_status_from_json(jr, pos, &value->u.gnss_data_hardware_status);
    case MIPC_FIELD_GNSS_DATA_DGNSS_INFO:
        return mipc_gnss_data_dgnss_info_from_json(jr, pos, &value->u.gnss_data_dgnss_info);
    case MIPC_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS:
        return mipc_gnss_data_dgnss_channel_status_from_json(jr, pos,
                                                             &value->u.gnss_data_dgnss_channel_status);
    case MIPC_FIELD_FILTER_DATA_LLH_POSITION:
        return mipc_filter_data_llh_position_from_json(jr, pos, &value->u.filter_data_llh_position);
    case MIPC_FIELD_FILTER_DATA_NED_VELOCITY:
        return mipc_filter_data_ned_velocity_from_json(jr, pos, &value->u.filter_data_ned_velocity);
    case MIPC_FIELD_FILTER_DATA_ATTITUDE_QUATERNION:
        return mipc_filter_data_attitude_quaternion_from_json(jr, pos,
                                                              &value->u.filter_data_attitude_quaternion);
    case MIPC_FIELD_FILTER_DATA_ATTITUDE_DCM:
        return mipc_filter_data_attitude_dcm_from_json(jr, pos, &value->u.filter_data_attitude_dcm);
    case MIPC_FIELD_FILTER_DATA_EULER_ANGLES:
        return mipc_filter_data_euler_angles_from_json(jr, pos, &value->u.filter_data_euler_angles);
    case MIPC_FIELD_FILTER_DATA_GYRO_BIAS:
        return mipc_filter_data_gyro_bias_from_json(jr, pos, &value->u.filter_data_gyro_bias);
    case MIPC_FIELD_FILTER_DATA_ACCEL_BIAS:
        return mipc_filter_data_accel_bias_from_json(jr, pos, &value->u.filter_data_accel_bias);
    case MIPC_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY:
        return mipc_filter_data_llh_position_uncertainty_from_json(
            jr, pos, &value->u.filter_data_llh_position_uncertainty);
    case MIPC_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY:
        return mipc_filter_data_ned_velocity_uncertainty_from_json(
            jr, pos, &value->u.filter_data_ned_velocity_uncertainty);
    case MIPC_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY:
        return mipc_filter_data_euler_angles_uncertainty_from_json(
            jr, pos, &value->u.filter_data_euler_angles_uncertainty);
    case MIPC_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY:
        return mipc_filter_data_gyro_bias_uncertainty_from_json(jr, pos,
                                                                &value->u.filter_data_gyro_bias_uncertainty);
    case MIPC_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY:
        return mipc_filter_data_accel_bias_uncertainty_from_json(
            jr, pos, &value->u.filter_data_accel_bias_uncertainty);
    case MIPC_FIELD_FILTER_DATA_LINEAR_ACCEL:
        return mipc_filter_data_linear_accel_from_json(jr, pos, &value->u.filter_data_linear_accel);
    case MIPC_FIELD_FILTER_DATA_COMP_ANGULAR_RATE:
        return mipc_filter_data_comp_angular_rate_from_json(jr, pos, &value->u.filter_data_comp_angular_rate);
    case MIPC_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE:
        return mipc_filter_data_wgs84_gravity_magnitude_from_json(
            jr, pos, &value->u.filter_data_wgs84_gravity_magnitude);
    case MIPC_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45:
        return mipc_filter_data_filter_status_gx5_45_from_json(jr, pos,
                                                               &value->u.filter_data_filter_status_gx5_45);
    case MIPC_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS:
        return mipc_filter_data_filter_status_cv7_ins_from_json(jr, pos,
                                                                &value->u.filter_data_filter_status_cv7_ins);
    case MIPC_FIELD_FILTER_DATA_GPS_TIMESTAMP:
        return mipc_filter_data_gps_timestamp_from_json(jr, pos, &value->u.filter_data_gps_timestamp);
    case MIPC_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY:
        return mipc_filter_data_quaternion_attitude_uncertainty_from_json(
            jr, pos, &value->u.filter_data_quaternion_attitude_uncertainty);
    case MIPC_FIELD_FILTER_DATA_GRAVITY_VECTOR:
        return mipc_filter_data_gravity_vector_from_json(jr, pos, &value->u.filter_data_gravity_vector);
    case MIPC_FIELD_FILTER_DATA_HEADING_UPDATE_STATE:
        return mipc_filter_data_heading_update_state_from_json(jr, pos,
                                                               &value->u.filter_data_heading_update_state);
    case MIPC_FIELD_FILTER_DATA_MAGNETIC_MODEL:
        return mipc_filter_data_magnetic_model_from_json(jr, pos, &value->u.filter_data_magnetic_model);
    case MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR:
        return mipc_filter_data_gyro_scale_factor_from_json(jr, pos, &value->u.filter_data_gyro_scale_factor);
    case MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR:
        return mipc_filter_data_accel_scale_factor_from_json(jr, pos,
                                                             &value->u.filter_data_accel_scale_factor);
    case MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY:
        return mipc_filter_data_gyro_scale_factor_uncertainty_from_json(
            jr, pos, &value->u.filter_data_gyro_scale_factor_uncertainty);
    case MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY:
        return mipc_filter_data_accel_scale_factor_uncertainty_from_json(
            jr, pos, &value->u.filter_data_accel_scale_factor_uncertainty);
    case MIPC_FIELD_FILTER_DATA_COMPENSATED_ACCEL:
        return mipc_filter_data_compensated_accel_from_json(jr, pos, &value->u.filter_data_compensated_accel);
    case MIPC_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE:
        return mipc_filter_data_standard_atmosphere_from_json(jr, pos,
                                                              &value->u.filter_data_standard_atmosphere);
    case MIPC_FIELD_FILTER_DATA_PRESSURE_ALTITUDE:
        return mipc_filter_data_pressure_altitude_from_json(jr, pos, &value->u.filter_data_pressure_altitude);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET:
        return mipc_filter_data_mag_auto_hard_iron_offset_from_json(
            jr, pos, &value->u.filter_data_mag_auto_hard_iron_offset);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX:
        return mipc_filter_data_mag_auto_soft_iron_matrix_from_json(
            jr, pos, &value->u.filter_data_mag_auto_soft_iron_matrix);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY:
        return mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_from_json(
            jr, pos, &value->u.filter_data_mag_auto_hard_iron_offset_uncertainty);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY:
        return mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_from_json(
            jr, pos, &value->u.filter_data_mag_auto_soft_iron_matrix_uncertainty);
    case MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION:
        return mipc_filter_data_gnss_antenna_offset_correction_from_json(
            jr, pos, &value->u.filter_data_gnss_antenna_offset_correction);
    case MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mipc_filter_data_gnss_antenna_offset_correction_uncertainty_from_json(
            jr, pos, &value->u.filter_data_gnss_antenna_offset_correction_uncertainty);
    case MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION:
        return mipc_filter_data_multi_antenna_offset_correction_from_json(
            jr, pos, &value->u.filter_data_multi_antenna_offset_correction);
    case MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mipc_filter_data_multi_antenna_offset_correction_uncertainty_from_json(
            jr, pos, &value->u.filter_data_multi_antenna_offset_correction_uncertainty);
    case MIPC_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY:
        return mipc_filter_data_ecef_position_uncertainty_from_json(
            jr, pos, &value->u.filter_data_ecef_position_uncertainty);
    case MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY:
        return mipc_filter_data_ecef_velocity_uncertainty_from_json(
            jr, pos, &value->u.filter_data_ecef_velocity_uncertainty);
    case MIPC_FIELD_FILTER_DATA_ECEF_POSITION:
        return mipc_filter_data_ecef_position_from_json(jr, pos, &value->u.filter_data_ecef_position);
    case MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY:
        return mipc_filter_data_ecef_velocity_from_json(jr, pos, &value->u.filter_data_ecef_velocity);
    case MIPC_FIELD_FILTER_DATA_NED_RELATIVE_POSITION:
        return mipc_filter_data_ned_relative_position_from_json(jr, pos,
                                                                &value->u.filter_data_ned_relative_position);
    case MIPC_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS:
        return mipc_filter_data_gnss_position_aiding_status_from_json(
            jr, pos, &value->u.filter_data_gnss_position_aiding_status);
    case MIPC_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY:
        return mipc_filter_data_aiding_measurement_summary_from_json(
            jr, pos, &value->u.filter_data_aiding_measurement_summary);
    case MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR:
        return mipc_filter_data_odometer_scale_factor_error_from_json(
            jr, pos, &value->u.filter_data_odometer_scale_factor_error);
    case MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY:
        return mipc_filter_data_odometer_scale_factor_error_uncertainty_from_json(
            jr, pos, &value->u.filter_data_odometer_scale_factor_error_uncertainty);
    case MIPC_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS:
        return mipc_filter_data_gnss_dual_antenna_status_from_json(
            jr, pos, &value->u.filter_data_gnss_dual_antenna_status);
    case MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR:
        return mipc_filter_data_aiding_frame_config_error_from_json(
            jr, pos, &value->u.filter_data_aiding_frame_config_error);
    case MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY:
        return mipc_filter_data_aiding_frame_config_error_uncertainty_from_json(
            jr, pos, &value->u.filter_data_aiding_frame_config_error_uncertainty);
    case MIPC_FIELD_GNSS_RECEIVER_1_LLH_POSITION:
        return mipc_gnss_receiver_1_llh_position_from_json(jr, pos, &value->u.gnss_receiver_1_llh_position);
    case MIPC_FIELD_GNSS_RECEIVER_1_ECEF_POSITION:
        return mipc_gnss_receiver_1_ecef_position_from_json(jr, pos, &value->u.gnss_receiver_1_ecef_position);
    case MIPC_FIELD_GNSS_RECEIVER_1_NED_VELOCITY:
        return mipc_gnss_receiver_1_ned_velocity_from_json(jr, pos, &value->u.gnss_receiver_1_ned_velocity);
    case MIPC_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY:
        return mipc_gnss_receiver_1_ecef_velocity_from_json(jr, pos, &value->u.gnss_receiver_1_ecef_velocity);
    case MIPC_FIELD_GNSS_RECEIVER_1_DOP:
        return mipc_gnss_receiver_1_dop_from_json(jr, pos, &value->u.gnss_receiver_1_dop);
    case MIPC_FIELD_GNSS_RECEIVER_1_UTC_TIME:
        return mipc_gnss_receiver_1_utc_time_from_json(jr, pos, &value->u.gnss_receiver_1_utc_time);
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_TIME:
        return mipc_gnss_receiver_1_gps_time_from_json(jr, pos, &value->u.gnss_receiver_1_gps_time);
    case MIPC_FIELD_GNSS_RECEIVER_1_FIX_INFO:
        return mipc_gnss_receiver_1_fix_info_from_json(jr, pos, &value->u.gnss_receiver_1_fix_info);
    case MIPC_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS:
        return mipc_gnss_receiver_1_hardware_status_from_json(jr, pos,
                                                              &value->u.gnss_receiver_1_hardware_status);
    case MIPC_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2:
        return mipc_gnss_receiver_1_clock_info_2_from_json(jr, pos, &value->u.gnss_receiver_1_clock_info_2);
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS:
        return mipc_gnss_receiver_1_gps_leap_seconds_from_json(jr, pos,
                                                               &value->u.gnss_receiver_1_gps_leap_seconds);
    case MIPC_FIELD_GNSS_RECEIVER_1_SBAS_INFO:
        return mipc_gnss_receiver_1_sbas_info_from_json(jr, pos, &value->u.gnss_receiver_1_sbas_info);
    case MIPC_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS:
        return mipc_gnss_receiver_1_satellite_status_from_json(jr, pos,
                                                               &value->u.gnss_receiver_1_satellite_status);
    case MIPC_FIELD_GNSS_RECEIVER_1_RAW:
        return mipc_gnss_receiver_1_raw_from_json(jr, pos, &value->u.gnss_receiver_1_raw);
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS:
        return mipc_gnss_receiver_1_gps_ephemeris_from_json(jr, pos, &value->u.gnss_receiver_1_gps_ephemeris);
    case MIPC_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS:
        return mipc_gnss_receiver_1_glonass_ephemeris_from_json(jr, pos,
                                                                &value->u.gnss_receiver_1_glonass_ephemeris);
    case MIPC_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS:
        return mipc_gnss_receiver_1_galileo_ephemeris_from_json(jr, pos,
                                                                &value->u.gnss_receiver_1_galileo_ephemeris);
    case MIPC_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS:
        return mipc_gnss_receiver_1_beidou_ephemeris_from_json(jr, pos,
                                                               &value->u.gnss_receiver_1_beidou_ephemeris);
    case MIPC_FIELD_GNSS_RECEIVER_2_LLH_POSITION:
        return mipc_gnss_receiver_2_llh_position_from_json(jr, pos, &value->u.gnss_receiver_2_llh_position);
    case MIPC_FIELD_GNSS_RECEIVER_2_ECEF_POSITION:
        return mipc_gnss_receiver_2_ecef_position_from_json(jr, pos, &value->u.gnss_receiver_2_ecef_position);
    case MIPC_FIELD_GNSS_RECEIVER_2_NED_VELOCITY:
        return mipc_gnss_receiver_2_ned_velocity_from_json(jr, pos, &value->u.gnss_receiver_2_ned_velocity);
    case MIPC_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY:
        return mipc_gnss_receiver_2_ecef_velocity_from_json(jr, pos, &value->u.gnss_receiver_2_ecef_velocity);
    case MIPC_FIELD_GNSS_RECEIVER_2_DOP:
        return mipc_gnss_receiver_2_dop_from_json(jr, pos, &value->u.gnss_receiver_2_dop);
    case MIPC_FIELD_GNSS_RECEIVER_2_UTC_TIME:
        return mipc_gnss_receiver_2_utc_time_from_json(jr, pos, &value->u.gnss_receiver_2_utc_time);
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_TIME:
        return mipc_gnss_receiver_2_gps_time_from_json(jr, pos, &value->u.gnss_receiver_2_gps_time);
    case MIPC_FIELD_GNSS_RECEIVER_2_FIX_INFO:
        return mipc_gnss_receiver_2_fix_info_from_json(jr, pos, &value->u.gnss_receiver_2_fix_info);
    case MIPC_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS:
        return mipc_gnss_receiver_2_hardware_status_from_json(jr, pos,
                                                              &value->u.gnss_receiver_2_hardware_status);
    case MIPC_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2:
        return mipc_gnss_receiver_2_clock_info_2_from_json(jr, pos, &value->u.gnss_receiver_2_clock_info_2);
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS:
        return mipc_gnss_receiver_2_gps_leap_seconds_from_json(jr, pos,
                                                               &value->u.gnss_receiver_2_gps_leap_seconds);
    case MIPC_FIELD_GNSS_RECEIVER_2_SBAS_INFO:
        return mipc_gnss_receiver_2_sbas_info_from_json(jr, pos, &value->u.gnss_receiver_2_sbas_info);
    case MIPC_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS:
        return mipc_gnss_receiver_2_satellite_status_from_json(jr, pos,
                                                               &value->u.gnss_receiver_2_satellite_status);
    case MIPC_FIELD_GNSS_RECEIVER_2_RAW:
        return mipc_gnss_receiver_2_raw_from_json(jr, pos, &value->u.gnss_receiver_2_raw);
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS:
        return mipc_gnss_receiver_2_gps_ephemeris_from_json(jr, pos, &value->u.gnss_receiver_2_gps_ephemeris);
    case MIPC_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS:
        return mipc_gnss_receiver_2_glonass_ephemeris_from_json(jr, pos,
                                                                &value->u.gnss_receiver_2_glonass_ephemeris);
    case MIPC_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS:
        return mipc_gnss_receiver_2_galileo_ephemeris_from_json(jr, pos,
                                                                &value->u.gnss_receiver_2_galileo_ephemeris);
    case MIPC_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS:
        return mipc_gnss_receiver_2_beidou_ephemeris_from_json(jr, pos,
                                                               &value->u.gnss_receiver_2_beidou_ephemeris);
    case MIPC_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO:
        return mipc_gnss_corrections_base_station_info_from_json(
            jr, pos, &value->u.gnss_corrections_base_station_info);
    case MIPC_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS:
        return mipc_gnss_corrections_rtk_corrections_status_from_json(
            jr, pos, &value->u.gnss_corrections_rtk_corrections_status);
    case MIPC_FIELD_GNSS_EXTERNAL_LLH_POSITION:
        return mipc_gnss_external_llh_position_from_json(jr, pos, &value->u.gnss_external_llh_position);
    case MIPC_FIELD_GNSS_EXTERNAL_NED_VELOCITY:
        return mipc_gnss_external_ned_velocity_from_json(jr, pos, &value->u.gnss_external_ned_velocity);
    case MIPC_FIELD_GNSS_EXTERNAL_UTC_TIME:
        return mipc_gnss_external_utc_time_from_json(jr, pos, &value->u.gnss_external_utc_time);
    case MIPC_FIELD_GNSS_EXTERNAL_FIX_INFO:
        return mipc_gnss_external_fix_info_from_json(jr, pos, &value->u.gnss_external_fix_info);
    case MIPC_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS:
        return mipc_gnss_external_satellite_status_from_json(jr, pos,
                                                             &value->u.gnss_external_satellite_status);
    case MIPC_FIELD_SYSTEM_DATA_BUILT_IN_TEST:
        return mipc_system_data_built_in_test_from_json(jr, pos, &value->u.system_data_built_in_test);
    case MIPC_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS:
        return mipc_system_data_time_sync_status_from_json(jr, pos, &value->u.system_data_time_sync_status);
    case MIPC_FIELD_SYSTEM_DATA_GPIO_STATE:
        return mipc_system_data_gpio_state_from_json(jr, pos, &value->u.system_data_gpio_state);
    case MIPC_FIELD_SHARED_EVENT_SOURCE:
        return mipc_shared_event_source_from_json(jr, pos, &value->u.shared_event_source);
    case MIPC_FIELD_SHARED_GPS_TIMESTAMP:
        return mipc_shared_gps_timestamp_from_json(jr, pos, &value->u.shared_gps_timestamp);
    case MIPC_FIELD_SHARED_DELTA_TIME:
        return mipc_shared_delta_time_from_json(jr, pos, &value->u.shared_delta_time);
    case MIPC_FIELD_SHARED_REFERENCE_TIMESTAMP:
        return mipc_shared_reference_timestamp_from_json(jr, pos, &value->u.shared_reference_timestamp);
    case MIPC_FIELD_SHARED_REFERENCE_TIME_DELTA:
        return mipc_shared_reference_time_delta_from_json(jr, pos, &value->u.shared_reference_time_delta);
    case MIPC_FIELD_SHARED_EXTERNAL_TIMESTAMP:
        return mipc_shared_external_timestamp_from_json(jr, pos, &value->u.shared_external_timestamp);
    case MIPC_FIELD_SHARED_EXTERNAL_TIME_DELTA:
        return mipc_shared_external_time_delta_from_json(jr, pos, &value->u.shared_external_time_delta);
    case MIPC_FIELD_NONE:
    case MIPC_FIELD_COUNT:
    default:
        (void)pos;
        return mipc_jr_fail(jr, "no such field layout");
    }
}
