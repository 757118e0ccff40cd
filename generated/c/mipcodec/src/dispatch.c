/* Dispatch tables. Generated from the spec: do not edit. */
#include "mipcodec/dispatch.h"
#include "layouts_internal.h"

#include <assert.h>
#include <string.h>

const char *mip_device_id(mip_device_t device) {
    switch (device) {
    case MIP_DEVICE_GX5_45:
        return "gx5_45";
    case MIP_DEVICE_CV7_INS:
        return "cv7_ins";
    case MIP_DEVICE_ANY:
    default:
        return NULL;
    }
}

bool mip_device_from_id(const char *id, mip_device_t *out) {
    assert(id != NULL);
    assert(out != NULL);
    if (strcmp(id, "gx5_45") == 0) {
        *out = MIP_DEVICE_GX5_45;
        return true;
    }
    if (strcmp(id, "cv7_ins") == 0) {
        *out = MIP_DEVICE_CV7_INS;
        return true;
    }
    (void)id;
    (void)out;
    return false;
}

mip_set_kind_t mip_set_kind(uint8_t set) {
    if (set >= 0x01 && set <= 0x7F) {
        return MIP_SET_KIND_COMMAND;
    }
    if (set >= 0x80 && 1) {
        return MIP_SET_KIND_DATA;
    }
    (void)set;
    return MIP_SET_KIND_NONE;
}

static const mip_layout_info_t k_layouts[MIP_FIELD_COUNT] = {
    {MIP_FIELD_NONE, NULL, NULL, MIP_DEVICE_ANY, 0},
    {MIP_FIELD_ACK_NACK, "ack_nack", NULL, MIP_DEVICE_ANY, 0xF1},
    {MIP_FIELD_BASE_PING, "ping", NULL, MIP_DEVICE_ANY, 0x01},
    {MIP_FIELD_BASE_SET_TO_IDLE, "set_to_idle", NULL, MIP_DEVICE_ANY, 0x02},
    {MIP_FIELD_BASE_GET_DEVICE_INFO, "get_device_info", NULL, MIP_DEVICE_ANY, 0x03},
    {MIP_FIELD_BASE_DEVICE_INFO, "device_info", NULL, MIP_DEVICE_ANY, 0x81},
    {MIP_FIELD_BASE_GET_DEVICE_DESCRIPTORS, "get_device_descriptors", NULL, MIP_DEVICE_ANY, 0x04},
    {MIP_FIELD_BASE_DEVICE_DESCRIPTORS, "device_descriptors", NULL, MIP_DEVICE_ANY, 0x82},
    {MIP_FIELD_BASE_BUILT_IN_TEST, "built_in_test", NULL, MIP_DEVICE_ANY, 0x05},
    {MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45, "built_in_test_result", "gx5_45", MIP_DEVICE_GX5_45, 0x83},
    {MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS, "built_in_test_result", "cv7_ins", MIP_DEVICE_CV7_INS,
     0x83},
    {MIP_FIELD_BASE_RESUME, "resume", NULL, MIP_DEVICE_ANY, 0x06},
    {MIP_FIELD_BASE_GET_EXTENDED_DESCRIPTORS, "get_extended_descriptors", NULL, MIP_DEVICE_ANY, 0x07},
    {MIP_FIELD_BASE_EXTENDED_DESCRIPTORS, "extended_descriptors", NULL, MIP_DEVICE_ANY, 0x86},
    {MIP_FIELD_BASE_CONTINUOUS_BIT, "continuous_bit", NULL, MIP_DEVICE_ANY, 0x08},
    {MIP_FIELD_BASE_CONTINUOUS_BIT_RESULT, "continuous_bit_result", NULL, MIP_DEVICE_ANY, 0x88},
    {MIP_FIELD_BASE_COMM_PORT_SPEED, "comm_port_speed", NULL, MIP_DEVICE_ANY, 0x09},
    {MIP_FIELD_BASE_COMM_PORT_SPEED_RESPONSE, "comm_port_speed_response", NULL, MIP_DEVICE_ANY, 0x89},
    {MIP_FIELD_BASE_GPS_TIME_UPDATE_GX5_45, "gps_time_update", "gx5_45", MIP_DEVICE_GX5_45, 0x72},
    {MIP_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS, "gps_time_update", "cv7_ins", MIP_DEVICE_CV7_INS, 0x72},
    {MIP_FIELD_BASE_GPS_WEEK, "gps_week", NULL, MIP_DEVICE_ANY, 0x84},
    {MIP_FIELD_BASE_GPS_SECONDS, "gps_seconds", NULL, MIP_DEVICE_ANY, 0x85},
    {MIP_FIELD_BASE_DEVICE_RESET, "device_reset", NULL, MIP_DEVICE_ANY, 0x7E},
    {MIP_FIELD_THREEDM_EVENT_CONTROL, "event_control", NULL, MIP_DEVICE_ANY, 0x2B},
    {MIP_FIELD_THREEDM_EVENT_CONTROL_RESPONSE, "event_control_response", NULL, MIP_DEVICE_ANY, 0xB5},
    {MIP_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS, "get_event_trigger_status", NULL, MIP_DEVICE_ANY, 0x2C},
    {MIP_FIELD_THREEDM_EVENT_TRIGGER_STATUS, "event_trigger_status", NULL, MIP_DEVICE_ANY, 0xB6},
    {MIP_FIELD_THREEDM_GET_EVENT_ACTION_STATUS, "get_event_action_status", NULL, MIP_DEVICE_ANY, 0x2D},
    {MIP_FIELD_THREEDM_EVENT_ACTION_STATUS, "event_action_status", NULL, MIP_DEVICE_ANY, 0xB7},
    {MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG, "event_trigger_config", NULL, MIP_DEVICE_ANY, 0x2E},
    {MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE, "event_trigger_config_response", NULL, MIP_DEVICE_ANY,
     0xB8},
    {MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG, "event_action_config", NULL, MIP_DEVICE_ANY, 0x2F},
    {MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE, "event_action_config_response", NULL, MIP_DEVICE_ANY,
     0xB9},
    {MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45, "device_startup_settings", "gx5_45", MIP_DEVICE_GX5_45,
     0x30},
    {MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS, "device_startup_settings", "cv7_ins",
     MIP_DEVICE_CV7_INS, 0x30},
    {MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER, "sensor_to_vehicle_euler", NULL, MIP_DEVICE_ANY, 0x31},
    {MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE, "sensor_to_vehicle_euler_response", NULL,
     MIP_DEVICE_ANY, 0xB1},
    {MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION, "sensor_to_vehicle_quaternion", NULL, MIP_DEVICE_ANY,
     0x32},
    {MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE, "sensor_to_vehicle_quaternion_response", NULL,
     MIP_DEVICE_ANY, 0xB2},
    {MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM, "sensor_to_vehicle_dcm", NULL, MIP_DEVICE_ANY, 0x33},
    {MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE, "sensor_to_vehicle_dcm_response", NULL, MIP_DEVICE_ANY,
     0xB3},
    {MIP_FIELD_THREEDM_ACCEL_BIAS_GX5_45, "accel_bias", "gx5_45", MIP_DEVICE_GX5_45, 0x37},
    {MIP_FIELD_THREEDM_ACCEL_BIAS_CV7_INS, "accel_bias", "cv7_ins", MIP_DEVICE_CV7_INS, 0x37},
    {MIP_FIELD_THREEDM_ACCEL_BIAS_RESPONSE, "accel_bias_response", NULL, MIP_DEVICE_ANY, 0x9A},
    {MIP_FIELD_THREEDM_GYRO_BIAS_GX5_45, "gyro_bias", "gx5_45", MIP_DEVICE_GX5_45, 0x38},
    {MIP_FIELD_THREEDM_GYRO_BIAS_CV7_INS, "gyro_bias", "cv7_ins", MIP_DEVICE_CV7_INS, 0x38},
    {MIP_FIELD_THREEDM_GYRO_BIAS_RESPONSE, "gyro_bias_response", NULL, MIP_DEVICE_ANY, 0x9B},
    {MIP_FIELD_THREEDM_CAPTURE_GYRO_BIAS, "capture_gyro_bias", NULL, MIP_DEVICE_ANY, 0x39},
    {MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45, "mag_hard_iron_offset", "gx5_45", MIP_DEVICE_GX5_45,
     0x3A},
    {MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS, "mag_hard_iron_offset", "cv7_ins", MIP_DEVICE_CV7_INS,
     0x3A},
    {MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE, "mag_hard_iron_offset_response", NULL, MIP_DEVICE_ANY,
     0x9C},
    {MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45, "mag_soft_iron_matrix", "gx5_45", MIP_DEVICE_GX5_45,
     0x3B},
    {MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS, "mag_soft_iron_matrix", "cv7_ins", MIP_DEVICE_CV7_INS,
     0x3B},
    {MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE, "mag_soft_iron_matrix_response", NULL, MIP_DEVICE_ANY,
     0x9D},
    {MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE, "coning_sculling_enable", NULL, MIP_DEVICE_ANY, 0x3E},
    {MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE, "coning_sculling_enable_response", NULL,
     MIP_DEVICE_ANY, 0x9E},
    {MIP_FIELD_THREEDM_UART_BAUDRATE, "uart_baudrate", NULL, MIP_DEVICE_ANY, 0x40},
    {MIP_FIELD_THREEDM_UART_BAUDRATE_RESPONSE, "uart_baudrate_response", NULL, MIP_DEVICE_ANY, 0x87},
    {MIP_FIELD_THREEDM_GPIO_CONFIG, "gpio_config", NULL, MIP_DEVICE_ANY, 0x41},
    {MIP_FIELD_THREEDM_GPIO_CONFIG_RESPONSE, "gpio_config_response", NULL, MIP_DEVICE_ANY, 0xC1},
    {MIP_FIELD_THREEDM_GPIO_STATE, "gpio_state", NULL, MIP_DEVICE_ANY, 0x42},
    {MIP_FIELD_THREEDM_GPIO_STATE_RESPONSE, "gpio_state_response", NULL, MIP_DEVICE_ANY, 0xC2},
    {MIP_FIELD_THREEDM_ODOMETER_CONFIG, "odometer_config", NULL, MIP_DEVICE_ANY, 0x43},
    {MIP_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE, "odometer_config_response", NULL, MIP_DEVICE_ANY, 0xC3},
    {MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER, "advanced_lowpass_filter", NULL, MIP_DEVICE_ANY, 0x50},
    {MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE, "advanced_lowpass_filter_response", NULL,
     MIP_DEVICE_ANY, 0x8B},
    {MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER, "complementary_filter", NULL, MIP_DEVICE_ANY, 0x51},
    {MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE, "complementary_filter_response", NULL, MIP_DEVICE_ANY,
     0x97},
    {MIP_FIELD_THREEDM_SENSOR_RANGE, "sensor_range", NULL, MIP_DEVICE_ANY, 0x52},
    {MIP_FIELD_THREEDM_SENSOR_RANGE_RESPONSE, "sensor_range_response", NULL, MIP_DEVICE_ANY, 0xD2},
    {MIP_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES, "get_calibrated_sensor_ranges", NULL, MIP_DEVICE_ANY,
     0x53},
    {MIP_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES, "calibrated_sensor_ranges", NULL, MIP_DEVICE_ANY, 0xD3},
    {MIP_FIELD_THREEDM_LOWPASS_FILTER, "lowpass_filter", NULL, MIP_DEVICE_ANY, 0x54},
    {MIP_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE, "lowpass_filter_response", NULL, MIP_DEVICE_ANY, 0xD4},
    {MIP_FIELD_THREEDM_POLL_IMU_DATA, "poll_imu_data", NULL, MIP_DEVICE_ANY, 0x01},
    {MIP_FIELD_THREEDM_POLL_GNSS_DATA, "poll_gnss_data", NULL, MIP_DEVICE_ANY, 0x02},
    {MIP_FIELD_THREEDM_POLL_FILTER_DATA, "poll_filter_data", NULL, MIP_DEVICE_ANY, 0x03},
    {MIP_FIELD_THREEDM_POLL_NMEA_DATA, "poll_nmea_data", NULL, MIP_DEVICE_ANY, 0x04},
    {MIP_FIELD_THREEDM_POLL_DATA, "poll_data", NULL, MIP_DEVICE_ANY, 0x0D},
    {MIP_FIELD_THREEDM_GET_IMU_BASE_RATE, "get_imu_base_rate", NULL, MIP_DEVICE_ANY, 0x06},
    {MIP_FIELD_THREEDM_IMU_BASE_RATE, "imu_base_rate", NULL, MIP_DEVICE_ANY, 0x83},
    {MIP_FIELD_THREEDM_GET_GNSS_BASE_RATE, "get_gnss_base_rate", NULL, MIP_DEVICE_ANY, 0x07},
    {MIP_FIELD_THREEDM_GNSS_BASE_RATE, "gnss_base_rate", NULL, MIP_DEVICE_ANY, 0x84},
    {MIP_FIELD_THREEDM_GET_FILTER_BASE_RATE, "get_filter_base_rate", NULL, MIP_DEVICE_ANY, 0x0B},
    {MIP_FIELD_THREEDM_FILTER_BASE_RATE, "filter_base_rate", NULL, MIP_DEVICE_ANY, 0x8A},
    {MIP_FIELD_THREEDM_GET_BASE_RATE, "get_base_rate", NULL, MIP_DEVICE_ANY, 0x0E},
    {MIP_FIELD_THREEDM_BASE_RATE, "base_rate", NULL, MIP_DEVICE_ANY, 0x8E},
    {MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT, "imu_message_format", NULL, MIP_DEVICE_ANY, 0x08},
    {MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE, "imu_message_format_response", NULL, MIP_DEVICE_ANY,
     0x80},
    {MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT, "gnss_message_format", NULL, MIP_DEVICE_ANY, 0x09},
    {MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE, "gnss_message_format_response", NULL, MIP_DEVICE_ANY,
     0x81},
    {MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT, "filter_message_format", NULL, MIP_DEVICE_ANY, 0x0A},
    {MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE, "filter_message_format_response", NULL, MIP_DEVICE_ANY,
     0x82},
    {MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT, "nmea_message_format", NULL, MIP_DEVICE_ANY, 0x0C},
    {MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE, "nmea_message_format_response", NULL, MIP_DEVICE_ANY,
     0x8C},
    {MIP_FIELD_THREEDM_MESSAGE_FORMAT, "message_format", NULL, MIP_DEVICE_ANY, 0x0F},
    {MIP_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE, "message_format_response", NULL, MIP_DEVICE_ANY, 0x8F},
    {MIP_FIELD_THREEDM_FACTORY_STREAMING, "factory_streaming", NULL, MIP_DEVICE_ANY, 0x10},
    {MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45, "data_stream_control", "gx5_45", MIP_DEVICE_GX5_45, 0x11},
    {MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS, "data_stream_control", "cv7_ins", MIP_DEVICE_CV7_INS,
     0x11},
    {MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45, "data_stream_control_response", "gx5_45",
     MIP_DEVICE_GX5_45, 0x85},
    {MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS, "data_stream_control_response", "cv7_ins",
     MIP_DEVICE_CV7_INS, 0x85},
    {MIP_FIELD_THREEDM_RAW_RTCM_MESSAGE, "raw_rtcm_message", NULL, MIP_DEVICE_ANY, 0x20},
    {MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS, "gnss_constellation_settings", NULL, MIP_DEVICE_ANY,
     0x21},
    {MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE, "gnss_constellation_settings_response", NULL,
     MIP_DEVICE_ANY, 0xA0},
    {MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS, "gnss_sbas_settings", NULL, MIP_DEVICE_ANY, 0x22},
    {MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE, "gnss_sbas_settings_response", NULL, MIP_DEVICE_ANY,
     0xA1},
    {MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL, "gnss_assisted_fix_control", NULL, MIP_DEVICE_ANY, 0x23},
    {MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE, "gnss_assisted_fix_control_response", NULL,
     MIP_DEVICE_ANY, 0xA2},
    {MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE, "gnss_assist_time_update", NULL, MIP_DEVICE_ANY, 0x24},
    {MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE, "gnss_assist_time_update_response", NULL,
     MIP_DEVICE_ANY, 0xA3},
    {MIP_FIELD_THREEDM_PPS_SOURCE, "pps_source", NULL, MIP_DEVICE_ANY, 0x28},
    {MIP_FIELD_THREEDM_PPS_SOURCE_RESPONSE, "pps_source_response", NULL, MIP_DEVICE_ANY, 0xA8},
    {MIP_FIELD_THREEDM_GET_SUPPORTED_EVENTS, "get_supported_events", NULL, MIP_DEVICE_ANY, 0x2A},
    {MIP_FIELD_THREEDM_SUPPORTED_EVENTS, "supported_events", NULL, MIP_DEVICE_ANY, 0xB4},
    {MIP_FIELD_THREEDM_DEVICE_STATUS, "device_status", NULL, MIP_DEVICE_ANY, 0x64},
    {MIP_FIELD_THREEDM_DEVICE_STATUS_RESPONSE, "device_status_response", NULL, MIP_DEVICE_ANY, 0x90},
    {MIP_FIELD_FILTER_RESET_FILTER, "reset_filter", NULL, MIP_DEVICE_ANY, 0x01},
    {MIP_FIELD_FILTER_SET_INITIAL_ATTITUDE, "set_initial_attitude", NULL, MIP_DEVICE_ANY, 0x02},
    {MIP_FIELD_FILTER_SET_INITIAL_HEADING, "set_initial_heading", NULL, MIP_DEVICE_ANY, 0x03},
    {MIP_FIELD_FILTER_RUN_FILTER, "run_filter", NULL, MIP_DEVICE_ANY, 0x05},
    {MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE, "vehicle_dynamics_mode", NULL, MIP_DEVICE_ANY, 0x10},
    {MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE, "vehicle_dynamics_mode_response", NULL, MIP_DEVICE_ANY,
     0x80},
    {MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM, "sensor_to_vehicle_transform", NULL, MIP_DEVICE_ANY, 0x11},
    {MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE, "sensor_to_vehicle_transform_response", NULL,
     MIP_DEVICE_ANY, 0x81},
    {MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET, "sensor_to_vehicle_offset", NULL, MIP_DEVICE_ANY, 0x12},
    {MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE, "sensor_to_vehicle_offset_response", NULL,
     MIP_DEVICE_ANY, 0x82},
    {MIP_FIELD_FILTER_ANTENNA_OFFSET, "antenna_offset", NULL, MIP_DEVICE_ANY, 0x13},
    {MIP_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE, "antenna_offset_response", NULL, MIP_DEVICE_ANY, 0x83},
    {MIP_FIELD_FILTER_ESTIMATION_CONTROL, "estimation_control", NULL, MIP_DEVICE_ANY, 0x14},
    {MIP_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE, "estimation_control_response", NULL, MIP_DEVICE_ANY, 0x84},
    {MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL, "gnss_source_control", NULL, MIP_DEVICE_ANY, 0x15},
    {MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE, "gnss_source_control_response", NULL, MIP_DEVICE_ANY,
     0x86},
    {MIP_FIELD_FILTER_EXTERNAL_GNSS_UPDATE, "external_gnss_update", NULL, MIP_DEVICE_ANY, 0x16},
    {MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE, "external_heading_update", NULL, MIP_DEVICE_ANY, 0x17},
    {MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL, "heading_update_control", NULL, MIP_DEVICE_ANY, 0x18},
    {MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE, "heading_update_control_response", NULL,
     MIP_DEVICE_ANY, 0x87},
    {MIP_FIELD_FILTER_AUTO_INIT_CONTROL, "auto_init_control", NULL, MIP_DEVICE_ANY, 0x19},
    {MIP_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE, "auto_init_control_response", NULL, MIP_DEVICE_ANY, 0x88},
    {MIP_FIELD_FILTER_ACCEL_NOISE, "accel_noise", NULL, MIP_DEVICE_ANY, 0x1A},
    {MIP_FIELD_FILTER_ACCEL_NOISE_RESPONSE, "accel_noise_response", NULL, MIP_DEVICE_ANY, 0x89},
    {MIP_FIELD_FILTER_GYRO_NOISE, "gyro_noise", NULL, MIP_DEVICE_ANY, 0x1B},
    {MIP_FIELD_FILTER_GYRO_NOISE_RESPONSE, "gyro_noise_response", NULL, MIP_DEVICE_ANY, 0x8A},
    {MIP_FIELD_FILTER_ACCEL_BIAS_MODEL, "accel_bias_model", NULL, MIP_DEVICE_ANY, 0x1C},
    {MIP_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE, "accel_bias_model_response", NULL, MIP_DEVICE_ANY, 0x8B},
    {MIP_FIELD_FILTER_GYRO_BIAS_MODEL, "gyro_bias_model", NULL, MIP_DEVICE_ANY, 0x1D},
    {MIP_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE, "gyro_bias_model_response", NULL, MIP_DEVICE_ANY, 0x8C},
    {MIP_FIELD_FILTER_ZUPT_CONTROL, "zupt_control", NULL, MIP_DEVICE_ANY, 0x1E},
    {MIP_FIELD_FILTER_ZUPT_CONTROL_RESPONSE, "zupt_control_response", NULL, MIP_DEVICE_ANY, 0x8D},
    {MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME, "external_heading_update_with_time", NULL,
     MIP_DEVICE_ANY, 0x1F},
    {MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL, "zero_angular_rate_update_control", NULL,
     MIP_DEVICE_ANY, 0x20},
    {MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE, "zero_angular_rate_update_control_response",
     NULL, MIP_DEVICE_ANY, 0x8E},
    {MIP_FIELD_FILTER_TARE_ORIENTATION, "tare_orientation", NULL, MIP_DEVICE_ANY, 0x21},
    {MIP_FIELD_FILTER_COMMANDED_ZUPT, "commanded_zupt", NULL, MIP_DEVICE_ANY, 0x22},
    {MIP_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE, "commanded_zero_angular_rate_update", NULL,
     MIP_DEVICE_ANY, 0x23},
    {MIP_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION, "mag_capture_auto_calibration", NULL, MIP_DEVICE_ANY,
     0x27},
    {MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV, "gravity_noise_std_dev", NULL, MIP_DEVICE_ANY, 0x28},
    {MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE, "gravity_noise_std_dev_response", NULL, MIP_DEVICE_ANY,
     0x93},
    {MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV, "pressure_altitude_noise_std_dev", NULL,
     MIP_DEVICE_ANY, 0x29},
    {MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE, "pressure_altitude_noise_std_dev_response",
     NULL, MIP_DEVICE_ANY, 0x94},
    {MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE, "hard_iron_offset_noise", NULL, MIP_DEVICE_ANY, 0x2B},
    {MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE, "hard_iron_offset_noise_response", NULL,
     MIP_DEVICE_ANY, 0x96},
    {MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE, "soft_iron_matrix_noise", NULL, MIP_DEVICE_ANY, 0x2C},
    {MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE, "soft_iron_matrix_noise_response", NULL,
     MIP_DEVICE_ANY, 0x97},
    {MIP_FIELD_FILTER_MAG_NOISE_STD_DEV, "mag_noise_std_dev", NULL, MIP_DEVICE_ANY, 0x42},
    {MIP_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE, "mag_noise_std_dev_response", NULL, MIP_DEVICE_ANY, 0xB1},
    {MIP_FIELD_FILTER_DECLINATION_SOURCE, "declination_source", NULL, MIP_DEVICE_ANY, 0x43},
    {MIP_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE, "declination_source_response", NULL, MIP_DEVICE_ANY, 0xB2},
    {MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT, "gravity_magnitude_adaptive_measurement", NULL,
     MIP_DEVICE_ANY, 0x44},
    {MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE,
     "gravity_magnitude_adaptive_measurement_response", NULL, MIP_DEVICE_ANY, 0xB3},
    {MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT, "mag_magnitude_adaptive_measurement", NULL,
     MIP_DEVICE_ANY, 0x45},
    {MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE,
     "mag_magnitude_adaptive_measurement_response", NULL, MIP_DEVICE_ANY, 0xB4},
    {MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT, "mag_dip_angle_adaptive_measurement", NULL,
     MIP_DEVICE_ANY, 0x46},
    {MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE,
     "mag_dip_angle_adaptive_measurement_response", NULL, MIP_DEVICE_ANY, 0xB5},
    {MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL, "altitude_aiding_control", NULL, MIP_DEVICE_ANY, 0x47},
    {MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE, "altitude_aiding_control_response", NULL,
     MIP_DEVICE_ANY, 0xB7},
    {MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL, "pitch_roll_aiding_control", NULL, MIP_DEVICE_ANY, 0x4B},
    {MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE, "pitch_roll_aiding_control_response", NULL,
     MIP_DEVICE_ANY, 0xBB},
    {MIP_FIELD_FILTER_INCLINATION_SOURCE, "inclination_source", NULL, MIP_DEVICE_ANY, 0x4C},
    {MIP_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE, "inclination_source_response", NULL, MIP_DEVICE_ANY, 0xBC},
    {MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE, "magnetic_field_magnitude_source", NULL,
     MIP_DEVICE_ANY, 0x4D},
    {MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE, "magnetic_field_magnitude_source_response",
     NULL, MIP_DEVICE_ANY, 0xBD},
    {MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL, "aiding_measurement_control", NULL, MIP_DEVICE_ANY, 0x50},
    {MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE, "aiding_measurement_control_response", NULL,
     MIP_DEVICE_ANY, 0xD0},
    {MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION, "initialization_configuration", NULL, MIP_DEVICE_ANY,
     0x52},
    {MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE, "initialization_configuration_response", NULL,
     MIP_DEVICE_ANY, 0xD2},
    {MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL, "adaptive_filter_control", NULL, MIP_DEVICE_ANY, 0x53},
    {MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE, "adaptive_filter_control_response", NULL,
     MIP_DEVICE_ANY, 0xD3},
    {MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET, "multi_antenna_offset", NULL, MIP_DEVICE_ANY, 0x54},
    {MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE, "multi_antenna_offset_response", NULL, MIP_DEVICE_ANY,
     0xD4},
    {MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION, "relative_position_configuration", NULL,
     MIP_DEVICE_ANY, 0x55},
    {MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE, "relative_position_configuration_response",
     NULL, MIP_DEVICE_ANY, 0xD5},
    {MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM, "reference_point_lever_arm", NULL, MIP_DEVICE_ANY, 0x56},
    {MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE, "reference_point_lever_arm_response", NULL,
     MIP_DEVICE_ANY, 0xD6},
    {MIP_FIELD_FILTER_SPEED_LEVER_ARM, "speed_lever_arm", NULL, MIP_DEVICE_ANY, 0x61},
    {MIP_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE, "speed_lever_arm_response", NULL, MIP_DEVICE_ANY, 0xE1},
    {MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL, "wheeled_vehicle_constraint_control", NULL,
     MIP_DEVICE_ANY, 0x63},
    {MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE,
     "wheeled_vehicle_constraint_control_response", NULL, MIP_DEVICE_ANY, 0xE3},
    {MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL, "gnss_antenna_calibration_control", NULL,
     MIP_DEVICE_ANY, 0x64},
    {MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE, "gnss_antenna_calibration_control_response",
     NULL, MIP_DEVICE_ANY, 0xE4},
    {MIP_FIELD_GNSS_RECEIVER_INFO, "receiver_info", NULL, MIP_DEVICE_ANY, 0x01},
    {MIP_FIELD_GNSS_RECEIVER_INFO_RESPONSE, "receiver_info_response", NULL, MIP_DEVICE_ANY, 0x81},
    {MIP_FIELD_GNSS_SIGNAL_CONFIGURATION, "signal_configuration", NULL, MIP_DEVICE_ANY, 0x02},
    {MIP_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE, "signal_configuration_response", NULL, MIP_DEVICE_ANY,
     0x82},
    {MIP_FIELD_GNSS_SPARTN_CONFIGURATION, "spartn_configuration", NULL, MIP_DEVICE_ANY, 0x20},
    {MIP_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE, "spartn_configuration_response", NULL, MIP_DEVICE_ANY,
     0xA0},
    {MIP_FIELD_AIDING_FRAME_CONFIG, "frame_config", NULL, MIP_DEVICE_ANY, 0x01},
    {MIP_FIELD_AIDING_FRAME_CONFIG_RESPONSE, "frame_config_response", NULL, MIP_DEVICE_ANY, 0x81},
    {MIP_FIELD_AIDING_ECHO_CONTROL, "echo_control", NULL, MIP_DEVICE_ANY, 0x1F},
    {MIP_FIELD_AIDING_ECHO_CONTROL_RESPONSE, "echo_control_response", NULL, MIP_DEVICE_ANY, 0x9F},
    {MIP_FIELD_AIDING_ECEF_POSITION, "ecef_position", NULL, MIP_DEVICE_ANY, 0x21},
    {MIP_FIELD_AIDING_LLH_POSITION, "llh_position", NULL, MIP_DEVICE_ANY, 0x22},
    {MIP_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID, "height_above_ellipsoid", NULL, MIP_DEVICE_ANY, 0x23},
    {MIP_FIELD_AIDING_ECEF_VELOCITY, "ecef_velocity", NULL, MIP_DEVICE_ANY, 0x28},
    {MIP_FIELD_AIDING_NED_VELOCITY, "ned_velocity", NULL, MIP_DEVICE_ANY, 0x29},
    {MIP_FIELD_AIDING_BODY_FRAME_VELOCITY, "body_frame_velocity", NULL, MIP_DEVICE_ANY, 0x2A},
    {MIP_FIELD_AIDING_TRUE_HEADING, "true_heading", NULL, MIP_DEVICE_ANY, 0x31},
    {MIP_FIELD_AIDING_MAGNETIC_FIELD, "magnetic_field", NULL, MIP_DEVICE_ANY, 0x32},
    {MIP_FIELD_AIDING_PRESSURE, "pressure", NULL, MIP_DEVICE_ANY, 0x33},
    {MIP_FIELD_SYSTEM_COMMUNICATION_MODE, "communication_mode", NULL, MIP_DEVICE_ANY, 0x10},
    {MIP_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE, "communication_mode_response", NULL, MIP_DEVICE_ANY, 0x90},
    {MIP_FIELD_SENSOR_SCALED_ACCEL, "scaled_accel", NULL, MIP_DEVICE_ANY, 0x04},
    {MIP_FIELD_SENSOR_SCALED_GYRO, "scaled_gyro", NULL, MIP_DEVICE_ANY, 0x05},
    {MIP_FIELD_SENSOR_SCALED_MAG, "scaled_mag", NULL, MIP_DEVICE_ANY, 0x06},
    {MIP_FIELD_SENSOR_DELTA_THETA, "delta_theta", NULL, MIP_DEVICE_ANY, 0x07},
    {MIP_FIELD_SENSOR_DELTA_VELOCITY, "delta_velocity", NULL, MIP_DEVICE_ANY, 0x08},
    {MIP_FIELD_SENSOR_CF_ORIENTATION_MATRIX, "cf_orientation_matrix", NULL, MIP_DEVICE_ANY, 0x09},
    {MIP_FIELD_SENSOR_CF_QUATERNION, "cf_quaternion", NULL, MIP_DEVICE_ANY, 0x0A},
    {MIP_FIELD_SENSOR_CF_EULER_ANGLES, "cf_euler_angles", NULL, MIP_DEVICE_ANY, 0x0C},
    {MIP_FIELD_SENSOR_CF_STABILIZED_NORTH, "cf_stabilized_north", NULL, MIP_DEVICE_ANY, 0x10},
    {MIP_FIELD_SENSOR_CF_STABILIZED_UP, "cf_stabilized_up", NULL, MIP_DEVICE_ANY, 0x11},
    {MIP_FIELD_SENSOR_GPS_TIMESTAMP, "gps_timestamp", NULL, MIP_DEVICE_ANY, 0x12},
    {MIP_FIELD_SENSOR_TEMPERATURE_STATISTICS, "temperature_statistics", NULL, MIP_DEVICE_ANY, 0x14},
    {MIP_FIELD_SENSOR_SCALED_PRESSURE, "scaled_pressure", NULL, MIP_DEVICE_ANY, 0x17},
    {MIP_FIELD_SENSOR_OVERRANGE_STATUS, "overrange_status", NULL, MIP_DEVICE_ANY, 0x18},
    {MIP_FIELD_SENSOR_ODOMETER_DATA, "odometer_data", NULL, MIP_DEVICE_ANY, 0x40},
    {MIP_FIELD_GNSS_DATA_LLH_POSITION, "llh_position", NULL, MIP_DEVICE_ANY, 0x03},
    {MIP_FIELD_GNSS_DATA_ECEF_POSITION, "ecef_position", NULL, MIP_DEVICE_ANY, 0x04},
    {MIP_FIELD_GNSS_DATA_NED_VELOCITY, "ned_velocity", NULL, MIP_DEVICE_ANY, 0x05},
    {MIP_FIELD_GNSS_DATA_ECEF_VELOCITY, "ecef_velocity", NULL, MIP_DEVICE_ANY, 0x06},
    {MIP_FIELD_GNSS_DATA_DOP, "dop", NULL, MIP_DEVICE_ANY, 0x07},
    {MIP_FIELD_GNSS_DATA_UTC_TIME, "utc_time", NULL, MIP_DEVICE_ANY, 0x08},
    {MIP_FIELD_GNSS_DATA_GPS_TIME, "gps_time", NULL, MIP_DEVICE_ANY, 0x09},
    {MIP_FIELD_GNSS_DATA_CLOCK_INFO, "clock_info", NULL, MIP_DEVICE_ANY, 0x0A},
    {MIP_FIELD_GNSS_DATA_FIX_INFO, "fix_info", NULL, MIP_DEVICE_ANY, 0x0B},
    {MIP_FIELD_GNSS_DATA_SV_INFO, "sv_info", NULL, MIP_DEVICE_ANY, 0x0C},
    {MIP_FIELD_GNSS_DATA_HARDWARE_STATUS, "hardware_status", NULL, MIP_DEVICE_ANY, 0x0D},
    {MIP_FIELD_GNSS_DATA_DGNSS_INFO, "dgnss_info", NULL, MIP_DEVICE_ANY, 0x0E},
    {MIP_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS, "dgnss_channel_status", NULL, MIP_DEVICE_ANY, 0x0F},
    {MIP_FIELD_FILTER_DATA_LLH_POSITION, "llh_position", NULL, MIP_DEVICE_ANY, 0x01},
    {MIP_FIELD_FILTER_DATA_NED_VELOCITY, "ned_velocity", NULL, MIP_DEVICE_ANY, 0x02},
    {MIP_FIELD_FILTER_DATA_ATTITUDE_QUATERNION, "attitude_quaternion", NULL, MIP_DEVICE_ANY, 0x03},
    {MIP_FIELD_FILTER_DATA_ATTITUDE_DCM, "attitude_dcm", NULL, MIP_DEVICE_ANY, 0x04},
    {MIP_FIELD_FILTER_DATA_EULER_ANGLES, "euler_angles", NULL, MIP_DEVICE_ANY, 0x05},
    {MIP_FIELD_FILTER_DATA_GYRO_BIAS, "gyro_bias", NULL, MIP_DEVICE_ANY, 0x06},
    {MIP_FIELD_FILTER_DATA_ACCEL_BIAS, "accel_bias", NULL, MIP_DEVICE_ANY, 0x07},
    {MIP_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY, "llh_position_uncertainty", NULL, MIP_DEVICE_ANY, 0x08},
    {MIP_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY, "ned_velocity_uncertainty", NULL, MIP_DEVICE_ANY, 0x09},
    {MIP_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY, "euler_angles_uncertainty", NULL, MIP_DEVICE_ANY, 0x0A},
    {MIP_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY, "gyro_bias_uncertainty", NULL, MIP_DEVICE_ANY, 0x0B},
    {MIP_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY, "accel_bias_uncertainty", NULL, MIP_DEVICE_ANY, 0x0C},
    {MIP_FIELD_FILTER_DATA_LINEAR_ACCEL, "linear_accel", NULL, MIP_DEVICE_ANY, 0x0D},
    {MIP_FIELD_FILTER_DATA_COMP_ANGULAR_RATE, "comp_angular_rate", NULL, MIP_DEVICE_ANY, 0x0E},
    {MIP_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE, "wgs84_gravity_magnitude", NULL, MIP_DEVICE_ANY, 0x0F},
    {MIP_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45, "filter_status", "gx5_45", MIP_DEVICE_GX5_45, 0x10},
    {MIP_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS, "filter_status", "cv7_ins", MIP_DEVICE_CV7_INS, 0x10},
    {MIP_FIELD_FILTER_DATA_GPS_TIMESTAMP, "gps_timestamp", NULL, MIP_DEVICE_ANY, 0x11},
    {MIP_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY, "quaternion_attitude_uncertainty", NULL,
     MIP_DEVICE_ANY, 0x12},
    {MIP_FIELD_FILTER_DATA_GRAVITY_VECTOR, "gravity_vector", NULL, MIP_DEVICE_ANY, 0x13},
    {MIP_FIELD_FILTER_DATA_HEADING_UPDATE_STATE, "heading_update_state", NULL, MIP_DEVICE_ANY, 0x14},
    {MIP_FIELD_FILTER_DATA_MAGNETIC_MODEL, "magnetic_model", NULL, MIP_DEVICE_ANY, 0x15},
    {MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR, "gyro_scale_factor", NULL, MIP_DEVICE_ANY, 0x16},
    {MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR, "accel_scale_factor", NULL, MIP_DEVICE_ANY, 0x17},
    {MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY, "gyro_scale_factor_uncertainty", NULL,
     MIP_DEVICE_ANY, 0x18},
    {MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY, "accel_scale_factor_uncertainty", NULL,
     MIP_DEVICE_ANY, 0x19},
    {MIP_FIELD_FILTER_DATA_COMPENSATED_ACCEL, "compensated_accel", NULL, MIP_DEVICE_ANY, 0x1C},
    {MIP_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE, "standard_atmosphere", NULL, MIP_DEVICE_ANY, 0x20},
    {MIP_FIELD_FILTER_DATA_PRESSURE_ALTITUDE, "pressure_altitude", NULL, MIP_DEVICE_ANY, 0x21},
    {MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET, "mag_auto_hard_iron_offset", NULL, MIP_DEVICE_ANY,
     0x25},
    {MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX, "mag_auto_soft_iron_matrix", NULL, MIP_DEVICE_ANY,
     0x26},
    {MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY, "mag_auto_hard_iron_offset_uncertainty",
     NULL, MIP_DEVICE_ANY, 0x28},
    {MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY, "mag_auto_soft_iron_matrix_uncertainty",
     NULL, MIP_DEVICE_ANY, 0x29},
    {MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION, "gnss_antenna_offset_correction", NULL,
     MIP_DEVICE_ANY, 0x30},
    {MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY,
     "gnss_antenna_offset_correction_uncertainty", NULL, MIP_DEVICE_ANY, 0x31},
    {MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION, "multi_antenna_offset_correction", NULL,
     MIP_DEVICE_ANY, 0x34},
    {MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY,
     "multi_antenna_offset_correction_uncertainty", NULL, MIP_DEVICE_ANY, 0x35},
    {MIP_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY, "ecef_position_uncertainty", NULL, MIP_DEVICE_ANY,
     0x36},
    {MIP_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY, "ecef_velocity_uncertainty", NULL, MIP_DEVICE_ANY,
     0x37},
    {MIP_FIELD_FILTER_DATA_ECEF_POSITION, "ecef_position", NULL, MIP_DEVICE_ANY, 0x40},
    {MIP_FIELD_FILTER_DATA_ECEF_VELOCITY, "ecef_velocity", NULL, MIP_DEVICE_ANY, 0x41},
    {MIP_FIELD_FILTER_DATA_NED_RELATIVE_POSITION, "ned_relative_position", NULL, MIP_DEVICE_ANY, 0x42},
    {MIP_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS, "gnss_position_aiding_status", NULL, MIP_DEVICE_ANY,
     0x43},
    {MIP_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY, "aiding_measurement_summary", NULL, MIP_DEVICE_ANY,
     0x46},
    {MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR, "odometer_scale_factor_error", NULL, MIP_DEVICE_ANY,
     0x47},
    {MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY, "odometer_scale_factor_error_uncertainty",
     NULL, MIP_DEVICE_ANY, 0x48},
    {MIP_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS, "gnss_dual_antenna_status", NULL, MIP_DEVICE_ANY, 0x49},
    {MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR, "aiding_frame_config_error", NULL, MIP_DEVICE_ANY,
     0x50},
    {MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY, "aiding_frame_config_error_uncertainty",
     NULL, MIP_DEVICE_ANY, 0x51},
    {MIP_FIELD_GNSS_RECEIVER_1_LLH_POSITION, "llh_position", NULL, MIP_DEVICE_ANY, 0x03},
    {MIP_FIELD_GNSS_RECEIVER_1_ECEF_POSITION, "ecef_position", NULL, MIP_DEVICE_ANY, 0x04},
    {MIP_FIELD_GNSS_RECEIVER_1_NED_VELOCITY, "ned_velocity", NULL, MIP_DEVICE_ANY, 0x05},
    {MIP_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY, "ecef_velocity", NULL, MIP_DEVICE_ANY, 0x06},
    {MIP_FIELD_GNSS_RECEIVER_1_DOP, "dop", NULL, MIP_DEVICE_ANY, 0x07},
    {MIP_FIELD_GNSS_RECEIVER_1_UTC_TIME, "utc_time", NULL, MIP_DEVICE_ANY, 0x08},
    {MIP_FIELD_GNSS_RECEIVER_1_GPS_TIME, "gps_time", NULL, MIP_DEVICE_ANY, 0x09},
    {MIP_FIELD_GNSS_RECEIVER_1_FIX_INFO, "fix_info", NULL, MIP_DEVICE_ANY, 0x0B},
    {MIP_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS, "hardware_status", NULL, MIP_DEVICE_ANY, 0x0D},
    {MIP_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2, "clock_info_2", NULL, MIP_DEVICE_ANY, 0x10},
    {MIP_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS, "gps_leap_seconds", NULL, MIP_DEVICE_ANY, 0x11},
    {MIP_FIELD_GNSS_RECEIVER_1_SBAS_INFO, "sbas_info", NULL, MIP_DEVICE_ANY, 0x12},
    {MIP_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS, "satellite_status", NULL, MIP_DEVICE_ANY, 0x20},
    {MIP_FIELD_GNSS_RECEIVER_1_RAW, "raw", NULL, MIP_DEVICE_ANY, 0x22},
    {MIP_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS, "gps_ephemeris", NULL, MIP_DEVICE_ANY, 0x61},
    {MIP_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS, "glonass_ephemeris", NULL, MIP_DEVICE_ANY, 0x62},
    {MIP_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS, "galileo_ephemeris", NULL, MIP_DEVICE_ANY, 0x63},
    {MIP_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS, "beidou_ephemeris", NULL, MIP_DEVICE_ANY, 0x64},
    {MIP_FIELD_GNSS_RECEIVER_2_LLH_POSITION, "llh_position", NULL, MIP_DEVICE_ANY, 0x03},
    {MIP_FIELD_GNSS_RECEIVER_2_ECEF_POSITION, "ecef_position", NULL, MIP_DEVICE_ANY, 0x04},
    {MIP_FIELD_GNSS_RECEIVER_2_NED_VELOCITY, "ned_velocity", NULL, MIP_DEVICE_ANY, 0x05},
    {MIP_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY, "ecef_velocity", NULL, MIP_DEVICE_ANY, 0x06},
    {MIP_FIELD_GNSS_RECEIVER_2_DOP, "dop", NULL, MIP_DEVICE_ANY, 0x07},
    {MIP_FIELD_GNSS_RECEIVER_2_UTC_TIME, "utc_time", NULL, MIP_DEVICE_ANY, 0x08},
    {MIP_FIELD_GNSS_RECEIVER_2_GPS_TIME, "gps_time", NULL, MIP_DEVICE_ANY, 0x09},
    {MIP_FIELD_GNSS_RECEIVER_2_FIX_INFO, "fix_info", NULL, MIP_DEVICE_ANY, 0x0B},
    {MIP_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS, "hardware_status", NULL, MIP_DEVICE_ANY, 0x0D},
    {MIP_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2, "clock_info_2", NULL, MIP_DEVICE_ANY, 0x10},
    {MIP_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS, "gps_leap_seconds", NULL, MIP_DEVICE_ANY, 0x11},
    {MIP_FIELD_GNSS_RECEIVER_2_SBAS_INFO, "sbas_info", NULL, MIP_DEVICE_ANY, 0x12},
    {MIP_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS, "satellite_status", NULL, MIP_DEVICE_ANY, 0x20},
    {MIP_FIELD_GNSS_RECEIVER_2_RAW, "raw", NULL, MIP_DEVICE_ANY, 0x22},
    {MIP_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS, "gps_ephemeris", NULL, MIP_DEVICE_ANY, 0x61},
    {MIP_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS, "glonass_ephemeris", NULL, MIP_DEVICE_ANY, 0x62},
    {MIP_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS, "galileo_ephemeris", NULL, MIP_DEVICE_ANY, 0x63},
    {MIP_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS, "beidou_ephemeris", NULL, MIP_DEVICE_ANY, 0x64},
    {MIP_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO, "base_station_info", NULL, MIP_DEVICE_ANY, 0x30},
    {MIP_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS, "rtk_corrections_status", NULL, MIP_DEVICE_ANY, 0x31},
    {MIP_FIELD_GNSS_EXTERNAL_LLH_POSITION, "llh_position", NULL, MIP_DEVICE_ANY, 0x03},
    {MIP_FIELD_GNSS_EXTERNAL_NED_VELOCITY, "ned_velocity", NULL, MIP_DEVICE_ANY, 0x05},
    {MIP_FIELD_GNSS_EXTERNAL_UTC_TIME, "utc_time", NULL, MIP_DEVICE_ANY, 0x08},
    {MIP_FIELD_GNSS_EXTERNAL_FIX_INFO, "fix_info", NULL, MIP_DEVICE_ANY, 0x0B},
    {MIP_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS, "satellite_status", NULL, MIP_DEVICE_ANY, 0x20},
    {MIP_FIELD_SYSTEM_DATA_BUILT_IN_TEST, "built_in_test", NULL, MIP_DEVICE_ANY, 0x01},
    {MIP_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS, "time_sync_status", NULL, MIP_DEVICE_ANY, 0x02},
    {MIP_FIELD_SYSTEM_DATA_GPIO_STATE, "gpio_state", NULL, MIP_DEVICE_ANY, 0x03},
    {MIP_FIELD_SHARED_EVENT_SOURCE, "event_source", NULL, MIP_DEVICE_ANY, 0xD0},
    {MIP_FIELD_SHARED_GPS_TIMESTAMP, "gps_timestamp", NULL, MIP_DEVICE_ANY, 0xD3},
    {MIP_FIELD_SHARED_DELTA_TIME, "delta_time", NULL, MIP_DEVICE_ANY, 0xD4},
    {MIP_FIELD_SHARED_REFERENCE_TIMESTAMP, "reference_timestamp", NULL, MIP_DEVICE_ANY, 0xD5},
    {MIP_FIELD_SHARED_REFERENCE_TIME_DELTA, "reference_time_delta", NULL, MIP_DEVICE_ANY, 0xD6},
    {MIP_FIELD_SHARED_EXTERNAL_TIMESTAMP, "external_timestamp", NULL, MIP_DEVICE_ANY, 0xD7},
    {MIP_FIELD_SHARED_EXTERNAL_TIME_DELTA, "external_time_delta", NULL, MIP_DEVICE_ANY, 0xD8},
};

static const mip_field_info_t k_fields[340] = {
    {"ack_nack", 0xF1, MIP_FIELD_ACK_NACK, 1},                                                   /* 0 */
    {"ping", 0x01, MIP_FIELD_BASE_PING, 1},                                                      /* 1 */
    {"set_to_idle", 0x02, MIP_FIELD_BASE_SET_TO_IDLE, 1},                                        /* 2 */
    {"get_device_info", 0x03, MIP_FIELD_BASE_GET_DEVICE_INFO, 1},                                /* 3 */
    {"device_info", 0x81, MIP_FIELD_BASE_DEVICE_INFO, 1},                                        /* 4 */
    {"get_device_descriptors", 0x04, MIP_FIELD_BASE_GET_DEVICE_DESCRIPTORS, 1},                  /* 5 */
    {"device_descriptors", 0x82, MIP_FIELD_BASE_DEVICE_DESCRIPTORS, 1},                          /* 6 */
    {"built_in_test", 0x05, MIP_FIELD_BASE_BUILT_IN_TEST, 1},                                    /* 7 */
    {"built_in_test_result", 0x83, MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45, 2},               /* 8 */
    {"resume", 0x06, MIP_FIELD_BASE_RESUME, 1},                                                  /* 9 */
    {"get_extended_descriptors", 0x07, MIP_FIELD_BASE_GET_EXTENDED_DESCRIPTORS, 1},              /* 10 */
    {"extended_descriptors", 0x86, MIP_FIELD_BASE_EXTENDED_DESCRIPTORS, 1},                      /* 11 */
    {"continuous_bit", 0x08, MIP_FIELD_BASE_CONTINUOUS_BIT, 1},                                  /* 12 */
    {"continuous_bit_result", 0x88, MIP_FIELD_BASE_CONTINUOUS_BIT_RESULT, 1},                    /* 13 */
    {"comm_port_speed", 0x09, MIP_FIELD_BASE_COMM_PORT_SPEED, 1},                                /* 14 */
    {"comm_port_speed_response", 0x89, MIP_FIELD_BASE_COMM_PORT_SPEED_RESPONSE, 1},              /* 15 */
    {"gps_time_update", 0x72, MIP_FIELD_BASE_GPS_TIME_UPDATE_GX5_45, 2},                         /* 16 */
    {"gps_week", 0x84, MIP_FIELD_BASE_GPS_WEEK, 1},                                              /* 17 */
    {"gps_seconds", 0x85, MIP_FIELD_BASE_GPS_SECONDS, 1},                                        /* 18 */
    {"device_reset", 0x7E, MIP_FIELD_BASE_DEVICE_RESET, 1},                                      /* 19 */
    {"event_control", 0x2B, MIP_FIELD_THREEDM_EVENT_CONTROL, 1},                                 /* 20 */
    {"event_control_response", 0xB5, MIP_FIELD_THREEDM_EVENT_CONTROL_RESPONSE, 1},               /* 21 */
    {"get_event_trigger_status", 0x2C, MIP_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS, 1},           /* 22 */
    {"event_trigger_status", 0xB6, MIP_FIELD_THREEDM_EVENT_TRIGGER_STATUS, 1},                   /* 23 */
    {"get_event_action_status", 0x2D, MIP_FIELD_THREEDM_GET_EVENT_ACTION_STATUS, 1},             /* 24 */
    {"event_action_status", 0xB7, MIP_FIELD_THREEDM_EVENT_ACTION_STATUS, 1},                     /* 25 */
    {"event_trigger_config", 0x2E, MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG, 1},                   /* 26 */
    {"event_trigger_config_response", 0xB8, MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE, 1}, /* 27 */
    {"event_action_config", 0x2F, MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG, 1},                     /* 28 */
    {"event_action_config_response", 0xB9, MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE, 1},   /* 29 */
    {"device_startup_settings", 0x30, MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45, 2},      /* 30 */
    {"sensor_to_vehicle_euler", 0x31, MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER, 1},             /* 31 */
    {"sensor_to_vehicle_euler_response", 0xB1, MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE,
     1},                                                                                       /* 32 */
    {"sensor_to_vehicle_quaternion", 0x32, MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION, 1}, /* 33 */
    {"sensor_to_vehicle_quaternion_response", 0xB2, MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE,
     1},                                                                                             /* 34 */
    {"sensor_to_vehicle_dcm", 0x33, MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM, 1},                     /* 35 */
    {"sensor_to_vehicle_dcm_response", 0xB3, MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE, 1},   /* 36 */
    {"accel_bias", 0x37, MIP_FIELD_THREEDM_ACCEL_BIAS_GX5_45, 2},                                    /* 37 */
    {"accel_bias_response", 0x9A, MIP_FIELD_THREEDM_ACCEL_BIAS_RESPONSE, 1},                         /* 38 */
    {"gyro_bias", 0x38, MIP_FIELD_THREEDM_GYRO_BIAS_GX5_45, 2},                                      /* 39 */
    {"gyro_bias_response", 0x9B, MIP_FIELD_THREEDM_GYRO_BIAS_RESPONSE, 1},                           /* 40 */
    {"capture_gyro_bias", 0x39, MIP_FIELD_THREEDM_CAPTURE_GYRO_BIAS, 1},                             /* 41 */
    {"mag_hard_iron_offset", 0x3A, MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45, 2},                /* 42 */
    {"mag_hard_iron_offset_response", 0x9C, MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE, 1},     /* 43 */
    {"mag_soft_iron_matrix", 0x3B, MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45, 2},                /* 44 */
    {"mag_soft_iron_matrix_response", 0x9D, MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE, 1},     /* 45 */
    {"coning_sculling_enable", 0x3E, MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE, 1},                   /* 46 */
    {"coning_sculling_enable_response", 0x9E, MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE, 1}, /* 47 */
    {"uart_baudrate", 0x40, MIP_FIELD_THREEDM_UART_BAUDRATE, 1},                                     /* 48 */
    {"uart_baudrate_response", 0x87, MIP_FIELD_THREEDM_UART_BAUDRATE_RESPONSE, 1},                   /* 49 */
    {"gpio_config", 0x41, MIP_FIELD_THREEDM_GPIO_CONFIG, 1},                                         /* 50 */
    {"gpio_config_response", 0xC1, MIP_FIELD_THREEDM_GPIO_CONFIG_RESPONSE, 1},                       /* 51 */
    {"gpio_state", 0x42, MIP_FIELD_THREEDM_GPIO_STATE, 1},                                           /* 52 */
    {"gpio_state_response", 0xC2, MIP_FIELD_THREEDM_GPIO_STATE_RESPONSE, 1},                         /* 53 */
    {"odometer_config", 0x43, MIP_FIELD_THREEDM_ODOMETER_CONFIG, 1},                                 /* 54 */
    {"odometer_config_response", 0xC3, MIP_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE, 1},               /* 55 */
    {"advanced_lowpass_filter", 0x50, MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER, 1},                 /* 56 */
    {"advanced_lowpass_filter_response", 0x8B, MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE,
     1},                                                                                              /* 57 */
    {"complementary_filter", 0x51, MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER, 1},                        /* 58 */
    {"complementary_filter_response", 0x97, MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE, 1},      /* 59 */
    {"sensor_range", 0x52, MIP_FIELD_THREEDM_SENSOR_RANGE, 1},                                        /* 60 */
    {"sensor_range_response", 0xD2, MIP_FIELD_THREEDM_SENSOR_RANGE_RESPONSE, 1},                      /* 61 */
    {"get_calibrated_sensor_ranges", 0x53, MIP_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES, 1},        /* 62 */
    {"calibrated_sensor_ranges", 0xD3, MIP_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES, 1},                /* 63 */
    {"lowpass_filter", 0x54, MIP_FIELD_THREEDM_LOWPASS_FILTER, 1},                                    /* 64 */
    {"lowpass_filter_response", 0xD4, MIP_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE, 1},                  /* 65 */
    {"poll_imu_data", 0x01, MIP_FIELD_THREEDM_POLL_IMU_DATA, 1},                                      /* 66 */
    {"poll_gnss_data", 0x02, MIP_FIELD_THREEDM_POLL_GNSS_DATA, 1},                                    /* 67 */
    {"poll_filter_data", 0x03, MIP_FIELD_THREEDM_POLL_FILTER_DATA, 1},                                /* 68 */
    {"poll_nmea_data", 0x04, MIP_FIELD_THREEDM_POLL_NMEA_DATA, 1},                                    /* 69 */
    {"poll_data", 0x0D, MIP_FIELD_THREEDM_POLL_DATA, 1},                                              /* 70 */
    {"get_imu_base_rate", 0x06, MIP_FIELD_THREEDM_GET_IMU_BASE_RATE, 1},                              /* 71 */
    {"imu_base_rate", 0x83, MIP_FIELD_THREEDM_IMU_BASE_RATE, 1},                                      /* 72 */
    {"get_gnss_base_rate", 0x07, MIP_FIELD_THREEDM_GET_GNSS_BASE_RATE, 1},                            /* 73 */
    {"gnss_base_rate", 0x84, MIP_FIELD_THREEDM_GNSS_BASE_RATE, 1},                                    /* 74 */
    {"get_filter_base_rate", 0x0B, MIP_FIELD_THREEDM_GET_FILTER_BASE_RATE, 1},                        /* 75 */
    {"filter_base_rate", 0x8A, MIP_FIELD_THREEDM_FILTER_BASE_RATE, 1},                                /* 76 */
    {"get_base_rate", 0x0E, MIP_FIELD_THREEDM_GET_BASE_RATE, 1},                                      /* 77 */
    {"base_rate", 0x8E, MIP_FIELD_THREEDM_BASE_RATE, 1},                                              /* 78 */
    {"imu_message_format", 0x08, MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT, 1},                            /* 79 */
    {"imu_message_format_response", 0x80, MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE, 1},          /* 80 */
    {"gnss_message_format", 0x09, MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT, 1},                          /* 81 */
    {"gnss_message_format_response", 0x81, MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE, 1},        /* 82 */
    {"filter_message_format", 0x0A, MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT, 1},                      /* 83 */
    {"filter_message_format_response", 0x82, MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE, 1},    /* 84 */
    {"nmea_message_format", 0x0C, MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT, 1},                          /* 85 */
    {"nmea_message_format_response", 0x8C, MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE, 1},        /* 86 */
    {"message_format", 0x0F, MIP_FIELD_THREEDM_MESSAGE_FORMAT, 1},                                    /* 87 */
    {"message_format_response", 0x8F, MIP_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE, 1},                  /* 88 */
    {"factory_streaming", 0x10, MIP_FIELD_THREEDM_FACTORY_STREAMING, 1},                              /* 89 */
    {"data_stream_control", 0x11, MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45, 2},                   /* 90 */
    {"data_stream_control_response", 0x85, MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45, 2}, /* 91 */
    {"raw_rtcm_message", 0x20, MIP_FIELD_THREEDM_RAW_RTCM_MESSAGE, 1},                                /* 92 */
    {"gnss_constellation_settings", 0x21, MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS, 1},          /* 93 */
    {"gnss_constellation_settings_response", 0xA0, MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE,
     1},                                                                                     /* 94 */
    {"gnss_sbas_settings", 0x22, MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS, 1},                   /* 95 */
    {"gnss_sbas_settings_response", 0xA1, MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE, 1}, /* 96 */
    {"gnss_assisted_fix_control", 0x23, MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL, 1},     /* 97 */
    {"gnss_assisted_fix_control_response", 0xA2, MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE,
     1},                                                                             /* 98 */
    {"gnss_assist_time_update", 0x24, MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE, 1}, /* 99 */
    {"gnss_assist_time_update_response", 0xA3, MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE,
     1},                                                                                          /* 100 */
    {"pps_source", 0x28, MIP_FIELD_THREEDM_PPS_SOURCE, 1},                                        /* 101 */
    {"pps_source_response", 0xA8, MIP_FIELD_THREEDM_PPS_SOURCE_RESPONSE, 1},                      /* 102 */
    {"get_supported_events", 0x2A, MIP_FIELD_THREEDM_GET_SUPPORTED_EVENTS, 1},                    /* 103 */
    {"supported_events", 0xB4, MIP_FIELD_THREEDM_SUPPORTED_EVENTS, 1},                            /* 104 */
    {"device_status", 0x64, MIP_FIELD_THREEDM_DEVICE_STATUS, 1},                                  /* 105 */
    {"device_status_response", 0x90, MIP_FIELD_THREEDM_DEVICE_STATUS_RESPONSE, 1},                /* 106 */
    {"reset_filter", 0x01, MIP_FIELD_FILTER_RESET_FILTER, 1},                                     /* 107 */
    {"set_initial_attitude", 0x02, MIP_FIELD_FILTER_SET_INITIAL_ATTITUDE, 1},                     /* 108 */
    {"set_initial_heading", 0x03, MIP_FIELD_FILTER_SET_INITIAL_HEADING, 1},                       /* 109 */
    {"run_filter", 0x05, MIP_FIELD_FILTER_RUN_FILTER, 1},                                         /* 110 */
    {"vehicle_dynamics_mode", 0x10, MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE, 1},                   /* 111 */
    {"vehicle_dynamics_mode_response", 0x80, MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE, 1}, /* 112 */
    {"sensor_to_vehicle_transform", 0x11, MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM, 1},       /* 113 */
    {"sensor_to_vehicle_transform_response", 0x81, MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE,
     1},                                                                              /* 114 */
    {"sensor_to_vehicle_offset", 0x12, MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET, 1}, /* 115 */
    {"sensor_to_vehicle_offset_response", 0x82, MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE,
     1},                                                                                            /* 116 */
    {"antenna_offset", 0x13, MIP_FIELD_FILTER_ANTENNA_OFFSET, 1},                                   /* 117 */
    {"antenna_offset_response", 0x83, MIP_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE, 1},                 /* 118 */
    {"estimation_control", 0x14, MIP_FIELD_FILTER_ESTIMATION_CONTROL, 1},                           /* 119 */
    {"estimation_control_response", 0x84, MIP_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE, 1},         /* 120 */
    {"gnss_source_control", 0x15, MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL, 1},                         /* 121 */
    {"gnss_source_control_response", 0x86, MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE, 1},       /* 122 */
    {"external_gnss_update", 0x16, MIP_FIELD_FILTER_EXTERNAL_GNSS_UPDATE, 1},                       /* 123 */
    {"external_heading_update", 0x17, MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE, 1},                 /* 124 */
    {"heading_update_control", 0x18, MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL, 1},                   /* 125 */
    {"heading_update_control_response", 0x87, MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE, 1}, /* 126 */
    {"auto_init_control", 0x19, MIP_FIELD_FILTER_AUTO_INIT_CONTROL, 1},                             /* 127 */
    {"auto_init_control_response", 0x88, MIP_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE, 1},           /* 128 */
    {"accel_noise", 0x1A, MIP_FIELD_FILTER_ACCEL_NOISE, 1},                                         /* 129 */
    {"accel_noise_response", 0x89, MIP_FIELD_FILTER_ACCEL_NOISE_RESPONSE, 1},                       /* 130 */
    {"gyro_noise", 0x1B, MIP_FIELD_FILTER_GYRO_NOISE, 1},                                           /* 131 */
    {"gyro_noise_response", 0x8A, MIP_FIELD_FILTER_GYRO_NOISE_RESPONSE, 1},                         /* 132 */
    {"accel_bias_model", 0x1C, MIP_FIELD_FILTER_ACCEL_BIAS_MODEL, 1},                               /* 133 */
    {"accel_bias_model_response", 0x8B, MIP_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE, 1},             /* 134 */
    {"gyro_bias_model", 0x1D, MIP_FIELD_FILTER_GYRO_BIAS_MODEL, 1},                                 /* 135 */
    {"gyro_bias_model_response", 0x8C, MIP_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE, 1},               /* 136 */
    {"zupt_control", 0x1E, MIP_FIELD_FILTER_ZUPT_CONTROL, 1},                                       /* 137 */
    {"zupt_control_response", 0x8D, MIP_FIELD_FILTER_ZUPT_CONTROL_RESPONSE, 1},                     /* 138 */
    {"external_heading_update_with_time", 0x1F, MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME,
     1}, /* 139 */
    {"zero_angular_rate_update_control", 0x20, MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL,
     1}, /* 140 */
    {"zero_angular_rate_update_control_response", 0x8E,
     MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE, 1},  /* 141 */
    {"tare_orientation", 0x21, MIP_FIELD_FILTER_TARE_ORIENTATION, 1}, /* 142 */
    {"commanded_zupt", 0x22, MIP_FIELD_FILTER_COMMANDED_ZUPT, 1},     /* 143 */
    {"commanded_zero_angular_rate_update", 0x23, MIP_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE,
     1},                                                                                            /* 144 */
    {"mag_capture_auto_calibration", 0x27, MIP_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION, 1},       /* 145 */
    {"gravity_noise_std_dev", 0x28, MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV, 1},                     /* 146 */
    {"gravity_noise_std_dev_response", 0x93, MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE, 1},   /* 147 */
    {"pressure_altitude_noise_std_dev", 0x29, MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV, 1}, /* 148 */
    {"pressure_altitude_noise_std_dev_response", 0x94,
     MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE, 1},                                 /* 149 */
    {"hard_iron_offset_noise", 0x2B, MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE, 1},                   /* 150 */
    {"hard_iron_offset_noise_response", 0x96, MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE, 1}, /* 151 */
    {"soft_iron_matrix_noise", 0x2C, MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE, 1},                   /* 152 */
    {"soft_iron_matrix_noise_response", 0x97, MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE, 1}, /* 153 */
    {"mag_noise_std_dev", 0x42, MIP_FIELD_FILTER_MAG_NOISE_STD_DEV, 1},                             /* 154 */
    {"mag_noise_std_dev_response", 0xB1, MIP_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE, 1},           /* 155 */
    {"declination_source", 0x43, MIP_FIELD_FILTER_DECLINATION_SOURCE, 1},                           /* 156 */
    {"declination_source_response", 0xB2, MIP_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE, 1},         /* 157 */
    {"gravity_magnitude_adaptive_measurement", 0x44, MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT,
     1}, /* 158 */
    {"gravity_magnitude_adaptive_measurement_response", 0xB3,
     MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE, 1}, /* 159 */
    {"mag_magnitude_adaptive_measurement", 0x45, MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT,
     1}, /* 160 */
    {"mag_magnitude_adaptive_measurement_response", 0xB4,
     MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE, 1}, /* 161 */
    {"mag_dip_angle_adaptive_measurement", 0x46, MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT,
     1}, /* 162 */
    {"mag_dip_angle_adaptive_measurement_response", 0xB5,
     MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE, 1},              /* 163 */
    {"altitude_aiding_control", 0x47, MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL, 1}, /* 164 */
    {"altitude_aiding_control_response", 0xB7, MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE,
     1},                                                                                /* 165 */
    {"pitch_roll_aiding_control", 0x4B, MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL, 1}, /* 166 */
    {"pitch_roll_aiding_control_response", 0xBB, MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE,
     1},                                                                                            /* 167 */
    {"inclination_source", 0x4C, MIP_FIELD_FILTER_INCLINATION_SOURCE, 1},                           /* 168 */
    {"inclination_source_response", 0xBC, MIP_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE, 1},         /* 169 */
    {"magnetic_field_magnitude_source", 0x4D, MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE, 1}, /* 170 */
    {"magnetic_field_magnitude_source_response", 0xBD,
     MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE, 1},                       /* 171 */
    {"aiding_measurement_control", 0x50, MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL, 1}, /* 172 */
    {"aiding_measurement_control_response", 0xD0, MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE,
     1},                                                                                      /* 173 */
    {"initialization_configuration", 0x52, MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION, 1}, /* 174 */
    {"initialization_configuration_response", 0xD2, MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE,
     1},                                                                            /* 175 */
    {"adaptive_filter_control", 0x53, MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL, 1}, /* 176 */
    {"adaptive_filter_control_response", 0xD3, MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE,
     1},                                                                                            /* 177 */
    {"multi_antenna_offset", 0x54, MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET, 1},                       /* 178 */
    {"multi_antenna_offset_response", 0xD4, MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE, 1},     /* 179 */
    {"relative_position_configuration", 0x55, MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION, 1}, /* 180 */
    {"relative_position_configuration_response", 0xD5,
     MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE, 1},                     /* 181 */
    {"reference_point_lever_arm", 0x56, MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM, 1}, /* 182 */
    {"reference_point_lever_arm_response", 0xD6, MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE,
     1},                                                                              /* 183 */
    {"speed_lever_arm", 0x61, MIP_FIELD_FILTER_SPEED_LEVER_ARM, 1},                   /* 184 */
    {"speed_lever_arm_response", 0xE1, MIP_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE, 1}, /* 185 */
    {"wheeled_vehicle_constraint_control", 0x63, MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL,
     1}, /* 186 */
    {"wheeled_vehicle_constraint_control_response", 0xE3,
     MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE, 1}, /* 187 */
    {"gnss_antenna_calibration_control", 0x64, MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL,
     1}, /* 188 */
    {"gnss_antenna_calibration_control_response", 0xE4,
     MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE, 1},                          /* 189 */
    {"receiver_info", 0x01, MIP_FIELD_GNSS_RECEIVER_INFO, 1},                                 /* 190 */
    {"receiver_info_response", 0x81, MIP_FIELD_GNSS_RECEIVER_INFO_RESPONSE, 1},               /* 191 */
    {"signal_configuration", 0x02, MIP_FIELD_GNSS_SIGNAL_CONFIGURATION, 1},                   /* 192 */
    {"signal_configuration_response", 0x82, MIP_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE, 1}, /* 193 */
    {"spartn_configuration", 0x20, MIP_FIELD_GNSS_SPARTN_CONFIGURATION, 1},                   /* 194 */
    {"spartn_configuration_response", 0xA0, MIP_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE, 1}, /* 195 */
    {"frame_config", 0x01, MIP_FIELD_AIDING_FRAME_CONFIG, 1},                                 /* 196 */
    {"frame_config_response", 0x81, MIP_FIELD_AIDING_FRAME_CONFIG_RESPONSE, 1},               /* 197 */
    {"echo_control", 0x1F, MIP_FIELD_AIDING_ECHO_CONTROL, 1},                                 /* 198 */
    {"echo_control_response", 0x9F, MIP_FIELD_AIDING_ECHO_CONTROL_RESPONSE, 1},               /* 199 */
    {"ecef_position", 0x21, MIP_FIELD_AIDING_ECEF_POSITION, 1},                               /* 200 */
    {"llh_position", 0x22, MIP_FIELD_AIDING_LLH_POSITION, 1},                                 /* 201 */
    {"height_above_ellipsoid", 0x23, MIP_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID, 1},             /* 202 */
    {"ecef_velocity", 0x28, MIP_FIELD_AIDING_ECEF_VELOCITY, 1},                               /* 203 */
    {"ned_velocity", 0x29, MIP_FIELD_AIDING_NED_VELOCITY, 1},                                 /* 204 */
    {"body_frame_velocity", 0x2A, MIP_FIELD_AIDING_BODY_FRAME_VELOCITY, 1},                   /* 205 */
    {"true_heading", 0x31, MIP_FIELD_AIDING_TRUE_HEADING, 1},                                 /* 206 */
    {"magnetic_field", 0x32, MIP_FIELD_AIDING_MAGNETIC_FIELD, 1},                             /* 207 */
    {"pressure", 0x33, MIP_FIELD_AIDING_PRESSURE, 1},                                         /* 208 */
    {"communication_mode", 0x10, MIP_FIELD_SYSTEM_COMMUNICATION_MODE, 1},                     /* 209 */
    {"communication_mode_response", 0x90, MIP_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE, 1},   /* 210 */
    {"scaled_accel", 0x04, MIP_FIELD_SENSOR_SCALED_ACCEL, 1},                                 /* 211 */
    {"scaled_gyro", 0x05, MIP_FIELD_SENSOR_SCALED_GYRO, 1},                                   /* 212 */
    {"scaled_mag", 0x06, MIP_FIELD_SENSOR_SCALED_MAG, 1},                                     /* 213 */
    {"delta_theta", 0x07, MIP_FIELD_SENSOR_DELTA_THETA, 1},                                   /* 214 */
    {"delta_velocity", 0x08, MIP_FIELD_SENSOR_DELTA_VELOCITY, 1},                             /* 215 */
    {"cf_orientation_matrix", 0x09, MIP_FIELD_SENSOR_CF_ORIENTATION_MATRIX, 1},               /* 216 */
    {"cf_quaternion", 0x0A, MIP_FIELD_SENSOR_CF_QUATERNION, 1},                               /* 217 */
    {"cf_euler_angles", 0x0C, MIP_FIELD_SENSOR_CF_EULER_ANGLES, 1},                           /* 218 */
    {"cf_stabilized_north", 0x10, MIP_FIELD_SENSOR_CF_STABILIZED_NORTH, 1},                   /* 219 */
    {"cf_stabilized_up", 0x11, MIP_FIELD_SENSOR_CF_STABILIZED_UP, 1},                         /* 220 */
    {"gps_timestamp", 0x12, MIP_FIELD_SENSOR_GPS_TIMESTAMP, 1},                               /* 221 */
    {"temperature_statistics", 0x14, MIP_FIELD_SENSOR_TEMPERATURE_STATISTICS, 1},             /* 222 */
    {"scaled_pressure", 0x17, MIP_FIELD_SENSOR_SCALED_PRESSURE, 1},                           /* 223 */
    {"overrange_status", 0x18, MIP_FIELD_SENSOR_OVERRANGE_STATUS, 1},                         /* 224 */
    {"odometer_data", 0x40, MIP_FIELD_SENSOR_ODOMETER_DATA, 1},                               /* 225 */
    {"llh_position", 0x03, MIP_FIELD_GNSS_DATA_LLH_POSITION, 1},                              /* 226 */
    {"ecef_position", 0x04, MIP_FIELD_GNSS_DATA_ECEF_POSITION, 1},                            /* 227 */
    {"ned_velocity", 0x05, MIP_FIELD_GNSS_DATA_NED_VELOCITY, 1},                              /* 228 */
    {"ecef_velocity", 0x06, MIP_FIELD_GNSS_DATA_ECEF_VELOCITY, 1},                            /* 229 */
    {"dop", 0x07, MIP_FIELD_GNSS_DATA_DOP, 1},                                                /* 230 */
    {"utc_time", 0x08, MIP_FIELD_GNSS_DATA_UTC_TIME, 1},                                      /* 231 */
    {"gps_time", 0x09, MIP_FIELD_GNSS_DATA_GPS_TIME, 1},                                      /* 232 */
    {"clock_info", 0x0A, MIP_FIELD_GNSS_DATA_CLOCK_INFO, 1},                                  /* 233 */
    {"fix_info", 0x0B, MIP_FIELD_GNSS_DATA_FIX_INFO, 1},                                      /* 234 */
    {"sv_info", 0x0C, MIP_FIELD_GNSS_DATA_SV_INFO, 1},                                        /* 235 */
    {"hardware_status", 0x0D, MIP_FIELD_GNSS_DATA_HARDWARE_STATUS, 1},                        /* 236 */
    {"dgnss_info", 0x0E, MIP_FIELD_GNSS_DATA_DGNSS_INFO, 1},                                  /* 237 */
    {"dgnss_channel_status", 0x0F, MIP_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS, 1},              /* 238 */
    {"llh_position", 0x01, MIP_FIELD_FILTER_DATA_LLH_POSITION, 1},                            /* 239 */
    {"ned_velocity", 0x02, MIP_FIELD_FILTER_DATA_NED_VELOCITY, 1},                            /* 240 */
    {"attitude_quaternion", 0x03, MIP_FIELD_FILTER_DATA_ATTITUDE_QUATERNION, 1},              /* 241 */
    {"attitude_dcm", 0x04, MIP_FIELD_FILTER_DATA_ATTITUDE_DCM, 1},                            /* 242 */
    {"euler_angles", 0x05, MIP_FIELD_FILTER_DATA_EULER_ANGLES, 1},                            /* 243 */
    {"gyro_bias", 0x06, MIP_FIELD_FILTER_DATA_GYRO_BIAS, 1},                                  /* 244 */
    {"accel_bias", 0x07, MIP_FIELD_FILTER_DATA_ACCEL_BIAS, 1},                                /* 245 */
    {"llh_position_uncertainty", 0x08, MIP_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY, 1},    /* 246 */
    {"ned_velocity_uncertainty", 0x09, MIP_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY, 1},    /* 247 */
    {"euler_angles_uncertainty", 0x0A, MIP_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY, 1},    /* 248 */
    {"gyro_bias_uncertainty", 0x0B, MIP_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY, 1},          /* 249 */
    {"accel_bias_uncertainty", 0x0C, MIP_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY, 1},        /* 250 */
    {"linear_accel", 0x0D, MIP_FIELD_FILTER_DATA_LINEAR_ACCEL, 1},                            /* 251 */
    {"comp_angular_rate", 0x0E, MIP_FIELD_FILTER_DATA_COMP_ANGULAR_RATE, 1},                  /* 252 */
    {"wgs84_gravity_magnitude", 0x0F, MIP_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE, 1},      /* 253 */
    {"filter_status", 0x10, MIP_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45, 2},                   /* 254 */
    {"gps_timestamp", 0x11, MIP_FIELD_FILTER_DATA_GPS_TIMESTAMP, 1},                          /* 255 */
    {"quaternion_attitude_uncertainty", 0x12, MIP_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY,
     1},                                                                                             /* 256 */
    {"gravity_vector", 0x13, MIP_FIELD_FILTER_DATA_GRAVITY_VECTOR, 1},                               /* 257 */
    {"heading_update_state", 0x14, MIP_FIELD_FILTER_DATA_HEADING_UPDATE_STATE, 1},                   /* 258 */
    {"magnetic_model", 0x15, MIP_FIELD_FILTER_DATA_MAGNETIC_MODEL, 1},                               /* 259 */
    {"gyro_scale_factor", 0x16, MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR, 1},                         /* 260 */
    {"accel_scale_factor", 0x17, MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR, 1},                       /* 261 */
    {"gyro_scale_factor_uncertainty", 0x18, MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY, 1}, /* 262 */
    {"accel_scale_factor_uncertainty", 0x19, MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY,
     1},                                                                                     /* 263 */
    {"compensated_accel", 0x1C, MIP_FIELD_FILTER_DATA_COMPENSATED_ACCEL, 1},                 /* 264 */
    {"standard_atmosphere", 0x20, MIP_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE, 1},             /* 265 */
    {"pressure_altitude", 0x21, MIP_FIELD_FILTER_DATA_PRESSURE_ALTITUDE, 1},                 /* 266 */
    {"mag_auto_hard_iron_offset", 0x25, MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET, 1}, /* 267 */
    {"mag_auto_soft_iron_matrix", 0x26, MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX, 1}, /* 268 */
    {"mag_auto_hard_iron_offset_uncertainty", 0x28,
     MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY, 1}, /* 269 */
    {"mag_auto_soft_iron_matrix_uncertainty", 0x29,
     MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY, 1}, /* 270 */
    {"gnss_antenna_offset_correction", 0x30, MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION,
     1}, /* 271 */
    {"gnss_antenna_offset_correction_uncertainty", 0x31,
     MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY, 1}, /* 272 */
    {"multi_antenna_offset_correction", 0x34, MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION,
     1}, /* 273 */
    {"multi_antenna_offset_correction_uncertainty", 0x35,
     MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY, 1},                      /* 274 */
    {"ecef_position_uncertainty", 0x36, MIP_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY, 1},     /* 275 */
    {"ecef_velocity_uncertainty", 0x37, MIP_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY, 1},     /* 276 */
    {"ecef_position", 0x40, MIP_FIELD_FILTER_DATA_ECEF_POSITION, 1},                             /* 277 */
    {"ecef_velocity", 0x41, MIP_FIELD_FILTER_DATA_ECEF_VELOCITY, 1},                             /* 278 */
    {"ned_relative_position", 0x42, MIP_FIELD_FILTER_DATA_NED_RELATIVE_POSITION, 1},             /* 279 */
    {"gnss_position_aiding_status", 0x43, MIP_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS, 1}, /* 280 */
    {"aiding_measurement_summary", 0x46, MIP_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY, 1},   /* 281 */
    {"odometer_scale_factor_error", 0x47, MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR, 1}, /* 282 */
    {"odometer_scale_factor_error_uncertainty", 0x48,
     MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY, 1},                      /* 283 */
    {"gnss_dual_antenna_status", 0x49, MIP_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS, 1},   /* 284 */
    {"aiding_frame_config_error", 0x50, MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR, 1}, /* 285 */
    {"aiding_frame_config_error_uncertainty", 0x51,
     MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY, 1},                       /* 286 */
    {"llh_position", 0x03, MIP_FIELD_GNSS_RECEIVER_1_LLH_POSITION, 1},                      /* 287 */
    {"ecef_position", 0x04, MIP_FIELD_GNSS_RECEIVER_1_ECEF_POSITION, 1},                    /* 288 */
    {"ned_velocity", 0x05, MIP_FIELD_GNSS_RECEIVER_1_NED_VELOCITY, 1},                      /* 289 */
    {"ecef_velocity", 0x06, MIP_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY, 1},                    /* 290 */
    {"dop", 0x07, MIP_FIELD_GNSS_RECEIVER_1_DOP, 1},                                        /* 291 */
    {"utc_time", 0x08, MIP_FIELD_GNSS_RECEIVER_1_UTC_TIME, 1},                              /* 292 */
    {"gps_time", 0x09, MIP_FIELD_GNSS_RECEIVER_1_GPS_TIME, 1},                              /* 293 */
    {"fix_info", 0x0B, MIP_FIELD_GNSS_RECEIVER_1_FIX_INFO, 1},                              /* 294 */
    {"hardware_status", 0x0D, MIP_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS, 1},                /* 295 */
    {"clock_info_2", 0x10, MIP_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2, 1},                      /* 296 */
    {"gps_leap_seconds", 0x11, MIP_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS, 1},              /* 297 */
    {"sbas_info", 0x12, MIP_FIELD_GNSS_RECEIVER_1_SBAS_INFO, 1},                            /* 298 */
    {"satellite_status", 0x20, MIP_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS, 1},              /* 299 */
    {"raw", 0x22, MIP_FIELD_GNSS_RECEIVER_1_RAW, 1},                                        /* 300 */
    {"gps_ephemeris", 0x61, MIP_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS, 1},                    /* 301 */
    {"glonass_ephemeris", 0x62, MIP_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS, 1},            /* 302 */
    {"galileo_ephemeris", 0x63, MIP_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS, 1},            /* 303 */
    {"beidou_ephemeris", 0x64, MIP_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS, 1},              /* 304 */
    {"llh_position", 0x03, MIP_FIELD_GNSS_RECEIVER_2_LLH_POSITION, 1},                      /* 305 */
    {"ecef_position", 0x04, MIP_FIELD_GNSS_RECEIVER_2_ECEF_POSITION, 1},                    /* 306 */
    {"ned_velocity", 0x05, MIP_FIELD_GNSS_RECEIVER_2_NED_VELOCITY, 1},                      /* 307 */
    {"ecef_velocity", 0x06, MIP_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY, 1},                    /* 308 */
    {"dop", 0x07, MIP_FIELD_GNSS_RECEIVER_2_DOP, 1},                                        /* 309 */
    {"utc_time", 0x08, MIP_FIELD_GNSS_RECEIVER_2_UTC_TIME, 1},                              /* 310 */
    {"gps_time", 0x09, MIP_FIELD_GNSS_RECEIVER_2_GPS_TIME, 1},                              /* 311 */
    {"fix_info", 0x0B, MIP_FIELD_GNSS_RECEIVER_2_FIX_INFO, 1},                              /* 312 */
    {"hardware_status", 0x0D, MIP_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS, 1},                /* 313 */
    {"clock_info_2", 0x10, MIP_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2, 1},                      /* 314 */
    {"gps_leap_seconds", 0x11, MIP_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS, 1},              /* 315 */
    {"sbas_info", 0x12, MIP_FIELD_GNSS_RECEIVER_2_SBAS_INFO, 1},                            /* 316 */
    {"satellite_status", 0x20, MIP_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS, 1},              /* 317 */
    {"raw", 0x22, MIP_FIELD_GNSS_RECEIVER_2_RAW, 1},                                        /* 318 */
    {"gps_ephemeris", 0x61, MIP_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS, 1},                    /* 319 */
    {"glonass_ephemeris", 0x62, MIP_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS, 1},            /* 320 */
    {"galileo_ephemeris", 0x63, MIP_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS, 1},            /* 321 */
    {"beidou_ephemeris", 0x64, MIP_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS, 1},              /* 322 */
    {"base_station_info", 0x30, MIP_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO, 1},           /* 323 */
    {"rtk_corrections_status", 0x31, MIP_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS, 1}, /* 324 */
    {"llh_position", 0x03, MIP_FIELD_GNSS_EXTERNAL_LLH_POSITION, 1},                        /* 325 */
    {"ned_velocity", 0x05, MIP_FIELD_GNSS_EXTERNAL_NED_VELOCITY, 1},                        /* 326 */
    {"utc_time", 0x08, MIP_FIELD_GNSS_EXTERNAL_UTC_TIME, 1},                                /* 327 */
    {"fix_info", 0x0B, MIP_FIELD_GNSS_EXTERNAL_FIX_INFO, 1},                                /* 328 */
    {"satellite_status", 0x20, MIP_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS, 1},                /* 329 */
    {"built_in_test", 0x01, MIP_FIELD_SYSTEM_DATA_BUILT_IN_TEST, 1},                        /* 330 */
    {"time_sync_status", 0x02, MIP_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS, 1},                  /* 331 */
    {"gpio_state", 0x03, MIP_FIELD_SYSTEM_DATA_GPIO_STATE, 1},                              /* 332 */
    {"event_source", 0xD0, MIP_FIELD_SHARED_EVENT_SOURCE, 1},                               /* 333 */
    {"gps_timestamp", 0xD3, MIP_FIELD_SHARED_GPS_TIMESTAMP, 1},                             /* 334 */
    {"delta_time", 0xD4, MIP_FIELD_SHARED_DELTA_TIME, 1},                                   /* 335 */
    {"reference_timestamp", 0xD5, MIP_FIELD_SHARED_REFERENCE_TIMESTAMP, 1},                 /* 336 */
    {"reference_time_delta", 0xD6, MIP_FIELD_SHARED_REFERENCE_TIME_DELTA, 1},               /* 337 */
    {"external_timestamp", 0xD7, MIP_FIELD_SHARED_EXTERNAL_TIMESTAMP, 1},                   /* 338 */
    {"external_time_delta", 0xD8, MIP_FIELD_SHARED_EXTERNAL_TIME_DELTA, 1},                 /* 339 */
};

const mip_layout_info_t *mip_layout_info(mip_field_id_t id) {
    if ((size_t)id >= MIP_FIELD_COUNT) {
        return NULL;
    }
    return &k_layouts[id];
}

/* Fields of each set: descriptor -> 1 + index into k_fields (0: not defined). Dispatch by
 * (set, descriptor) is two table lookups. A set's table also holds the reserved fields of its
 * kind and, in a data set, the shared data fields that it does not define itself: the answer
 * find_field's search would reach (the generator resolves the search once). */
static const uint16_t k_set_base[256] = {
    [0x01] = 2,  /* ping */
    [0x02] = 3,  /* set_to_idle */
    [0x03] = 4,  /* get_device_info */
    [0x04] = 6,  /* get_device_descriptors */
    [0x05] = 8,  /* built_in_test */
    [0x06] = 10, /* resume */
    [0x07] = 11, /* get_extended_descriptors */
    [0x08] = 13, /* continuous_bit */
    [0x09] = 15, /* comm_port_speed */
    [0x72] = 17, /* gps_time_update */
    [0x7E] = 20, /* device_reset */
    [0x81] = 5,  /* device_info */
    [0x82] = 7,  /* device_descriptors */
    [0x83] = 9,  /* built_in_test_result */
    [0x84] = 18, /* gps_week */
    [0x85] = 19, /* gps_seconds */
    [0x86] = 12, /* extended_descriptors */
    [0x88] = 14, /* continuous_bit_result */
    [0x89] = 16, /* comm_port_speed_response */
    [0xF1] = 1,  /* reserved ack_nack */
};
static const uint16_t k_set_threedm[256] = {
    [0x01] = 67,  /* poll_imu_data */
    [0x02] = 68,  /* poll_gnss_data */
    [0x03] = 69,  /* poll_filter_data */
    [0x04] = 70,  /* poll_nmea_data */
    [0x06] = 72,  /* get_imu_base_rate */
    [0x07] = 74,  /* get_gnss_base_rate */
    [0x08] = 80,  /* imu_message_format */
    [0x09] = 82,  /* gnss_message_format */
    [0x0A] = 84,  /* filter_message_format */
    [0x0B] = 76,  /* get_filter_base_rate */
    [0x0C] = 86,  /* nmea_message_format */
    [0x0D] = 71,  /* poll_data */
    [0x0E] = 78,  /* get_base_rate */
    [0x0F] = 88,  /* message_format */
    [0x10] = 90,  /* factory_streaming */
    [0x11] = 91,  /* data_stream_control */
    [0x20] = 93,  /* raw_rtcm_message */
    [0x21] = 94,  /* gnss_constellation_settings */
    [0x22] = 96,  /* gnss_sbas_settings */
    [0x23] = 98,  /* gnss_assisted_fix_control */
    [0x24] = 100, /* gnss_assist_time_update */
    [0x28] = 102, /* pps_source */
    [0x2A] = 104, /* get_supported_events */
    [0x2B] = 21,  /* event_control */
    [0x2C] = 23,  /* get_event_trigger_status */
    [0x2D] = 25,  /* get_event_action_status */
    [0x2E] = 27,  /* event_trigger_config */
    [0x2F] = 29,  /* event_action_config */
    [0x30] = 31,  /* device_startup_settings */
    [0x31] = 32,  /* sensor_to_vehicle_euler */
    [0x32] = 34,  /* sensor_to_vehicle_quaternion */
    [0x33] = 36,  /* sensor_to_vehicle_dcm */
    [0x37] = 38,  /* accel_bias */
    [0x38] = 40,  /* gyro_bias */
    [0x39] = 42,  /* capture_gyro_bias */
    [0x3A] = 43,  /* mag_hard_iron_offset */
    [0x3B] = 45,  /* mag_soft_iron_matrix */
    [0x3E] = 47,  /* coning_sculling_enable */
    [0x40] = 49,  /* uart_baudrate */
    [0x41] = 51,  /* gpio_config */
    [0x42] = 53,  /* gpio_state */
    [0x43] = 55,  /* odometer_config */
    [0x50] = 57,  /* advanced_lowpass_filter */
    [0x51] = 59,  /* complementary_filter */
    [0x52] = 61,  /* sensor_range */
    [0x53] = 63,  /* get_calibrated_sensor_ranges */
    [0x54] = 65,  /* lowpass_filter */
    [0x64] = 106, /* device_status */
    [0x80] = 81,  /* imu_message_format_response */
    [0x81] = 83,  /* gnss_message_format_response */
    [0x82] = 85,  /* filter_message_format_response */
    [0x83] = 73,  /* imu_base_rate */
    [0x84] = 75,  /* gnss_base_rate */
    [0x85] = 92,  /* data_stream_control_response */
    [0x87] = 50,  /* uart_baudrate_response */
    [0x8A] = 77,  /* filter_base_rate */
    [0x8B] = 58,  /* advanced_lowpass_filter_response */
    [0x8C] = 87,  /* nmea_message_format_response */
    [0x8E] = 79,  /* base_rate */
    [0x8F] = 89,  /* message_format_response */
    [0x90] = 107, /* device_status_response */
    [0x97] = 60,  /* complementary_filter_response */
    [0x9A] = 39,  /* accel_bias_response */
    [0x9B] = 41,  /* gyro_bias_response */
    [0x9C] = 44,  /* mag_hard_iron_offset_response */
    [0x9D] = 46,  /* mag_soft_iron_matrix_response */
    [0x9E] = 48,  /* coning_sculling_enable_response */
    [0xA0] = 95,  /* gnss_constellation_settings_response */
    [0xA1] = 97,  /* gnss_sbas_settings_response */
    [0xA2] = 99,  /* gnss_assisted_fix_control_response */
    [0xA3] = 101, /* gnss_assist_time_update_response */
    [0xA8] = 103, /* pps_source_response */
    [0xB1] = 33,  /* sensor_to_vehicle_euler_response */
    [0xB2] = 35,  /* sensor_to_vehicle_quaternion_response */
    [0xB3] = 37,  /* sensor_to_vehicle_dcm_response */
    [0xB4] = 105, /* supported_events */
    [0xB5] = 22,  /* event_control_response */
    [0xB6] = 24,  /* event_trigger_status */
    [0xB7] = 26,  /* event_action_status */
    [0xB8] = 28,  /* event_trigger_config_response */
    [0xB9] = 30,  /* event_action_config_response */
    [0xC1] = 52,  /* gpio_config_response */
    [0xC2] = 54,  /* gpio_state_response */
    [0xC3] = 56,  /* odometer_config_response */
    [0xD2] = 62,  /* sensor_range_response */
    [0xD3] = 64,  /* calibrated_sensor_ranges */
    [0xD4] = 66,  /* lowpass_filter_response */
    [0xF1] = 1,   /* reserved ack_nack */
};
static const uint16_t k_set_filter[256] = {
    [0x01] = 108, /* reset_filter */
    [0x02] = 109, /* set_initial_attitude */
    [0x03] = 110, /* set_initial_heading */
    [0x05] = 111, /* run_filter */
    [0x10] = 112, /* vehicle_dynamics_mode */
    [0x11] = 114, /* sensor_to_vehicle_transform */
    [0x12] = 116, /* sensor_to_vehicle_offset */
    [0x13] = 118, /* antenna_offset */
    [0x14] = 120, /* estimation_control */
    [0x15] = 122, /* gnss_source_control */
    [0x16] = 124, /* external_gnss_update */
    [0x17] = 125, /* external_heading_update */
    [0x18] = 126, /* heading_update_control */
    [0x19] = 128, /* auto_init_control */
    [0x1A] = 130, /* accel_noise */
    [0x1B] = 132, /* gyro_noise */
    [0x1C] = 134, /* accel_bias_model */
    [0x1D] = 136, /* gyro_bias_model */
    [0x1E] = 138, /* zupt_control */
    [0x1F] = 140, /* external_heading_update_with_time */
    [0x20] = 141, /* zero_angular_rate_update_control */
    [0x21] = 143, /* tare_orientation */
    [0x22] = 144, /* commanded_zupt */
    [0x23] = 145, /* commanded_zero_angular_rate_update */
    [0x27] = 146, /* mag_capture_auto_calibration */
    [0x28] = 147, /* gravity_noise_std_dev */
    [0x29] = 149, /* pressure_altitude_noise_std_dev */
    [0x2B] = 151, /* hard_iron_offset_noise */
    [0x2C] = 153, /* soft_iron_matrix_noise */
    [0x42] = 155, /* mag_noise_std_dev */
    [0x43] = 157, /* declination_source */
    [0x44] = 159, /* gravity_magnitude_adaptive_measurement */
    [0x45] = 161, /* mag_magnitude_adaptive_measurement */
    [0x46] = 163, /* mag_dip_angle_adaptive_measurement */
    [0x47] = 165, /* altitude_aiding_control */
    [0x4B] = 167, /* pitch_roll_aiding_control */
    [0x4C] = 169, /* inclination_source */
    [0x4D] = 171, /* magnetic_field_magnitude_source */
    [0x50] = 173, /* aiding_measurement_control */
    [0x52] = 175, /* initialization_configuration */
    [0x53] = 177, /* adaptive_filter_control */
    [0x54] = 179, /* multi_antenna_offset */
    [0x55] = 181, /* relative_position_configuration */
    [0x56] = 183, /* reference_point_lever_arm */
    [0x61] = 185, /* speed_lever_arm */
    [0x63] = 187, /* wheeled_vehicle_constraint_control */
    [0x64] = 189, /* gnss_antenna_calibration_control */
    [0x80] = 113, /* vehicle_dynamics_mode_response */
    [0x81] = 115, /* sensor_to_vehicle_transform_response */
    [0x82] = 117, /* sensor_to_vehicle_offset_response */
    [0x83] = 119, /* antenna_offset_response */
    [0x84] = 121, /* estimation_control_response */
    [0x86] = 123, /* gnss_source_control_response */
    [0x87] = 127, /* heading_update_control_response */
    [0x88] = 129, /* auto_init_control_response */
    [0x89] = 131, /* accel_noise_response */
    [0x8A] = 133, /* gyro_noise_response */
    [0x8B] = 135, /* accel_bias_model_response */
    [0x8C] = 137, /* gyro_bias_model_response */
    [0x8D] = 139, /* zupt_control_response */
    [0x8E] = 142, /* zero_angular_rate_update_control_response */
    [0x93] = 148, /* gravity_noise_std_dev_response */
    [0x94] = 150, /* pressure_altitude_noise_std_dev_response */
    [0x96] = 152, /* hard_iron_offset_noise_response */
    [0x97] = 154, /* soft_iron_matrix_noise_response */
    [0xB1] = 156, /* mag_noise_std_dev_response */
    [0xB2] = 158, /* declination_source_response */
    [0xB3] = 160, /* gravity_magnitude_adaptive_measurement_response */
    [0xB4] = 162, /* mag_magnitude_adaptive_measurement_response */
    [0xB5] = 164, /* mag_dip_angle_adaptive_measurement_response */
    [0xB7] = 166, /* altitude_aiding_control_response */
    [0xBB] = 168, /* pitch_roll_aiding_control_response */
    [0xBC] = 170, /* inclination_source_response */
    [0xBD] = 172, /* magnetic_field_magnitude_source_response */
    [0xD0] = 174, /* aiding_measurement_control_response */
    [0xD2] = 176, /* initialization_configuration_response */
    [0xD3] = 178, /* adaptive_filter_control_response */
    [0xD4] = 180, /* multi_antenna_offset_response */
    [0xD5] = 182, /* relative_position_configuration_response */
    [0xD6] = 184, /* reference_point_lever_arm_response */
    [0xE1] = 186, /* speed_lever_arm_response */
    [0xE3] = 188, /* wheeled_vehicle_constraint_control_response */
    [0xE4] = 190, /* gnss_antenna_calibration_control_response */
    [0xF1] = 1,   /* reserved ack_nack */
};
static const uint16_t k_set_gnss[256] = {
    [0x01] = 191, /* receiver_info */
    [0x02] = 193, /* signal_configuration */
    [0x20] = 195, /* spartn_configuration */
    [0x81] = 192, /* receiver_info_response */
    [0x82] = 194, /* signal_configuration_response */
    [0xA0] = 196, /* spartn_configuration_response */
    [0xF1] = 1,   /* reserved ack_nack */
};
static const uint16_t k_set_aiding[256] = {
    [0x01] = 197, /* frame_config */
    [0x1F] = 199, /* echo_control */
    [0x21] = 201, /* ecef_position */
    [0x22] = 202, /* llh_position */
    [0x23] = 203, /* height_above_ellipsoid */
    [0x28] = 204, /* ecef_velocity */
    [0x29] = 205, /* ned_velocity */
    [0x2A] = 206, /* body_frame_velocity */
    [0x31] = 207, /* true_heading */
    [0x32] = 208, /* magnetic_field */
    [0x33] = 209, /* pressure */
    [0x81] = 198, /* frame_config_response */
    [0x9F] = 200, /* echo_control_response */
    [0xF1] = 1,   /* reserved ack_nack */
};
static const uint16_t k_set_system[256] = {
    [0x10] = 210, /* communication_mode */
    [0x90] = 211, /* communication_mode_response */
    [0xF1] = 1,   /* reserved ack_nack */
};
static const uint16_t k_set_sensor[256] = {
    [0x04] = 212, /* scaled_accel */
    [0x05] = 213, /* scaled_gyro */
    [0x06] = 214, /* scaled_mag */
    [0x07] = 215, /* delta_theta */
    [0x08] = 216, /* delta_velocity */
    [0x09] = 217, /* cf_orientation_matrix */
    [0x0A] = 218, /* cf_quaternion */
    [0x0C] = 219, /* cf_euler_angles */
    [0x10] = 220, /* cf_stabilized_north */
    [0x11] = 221, /* cf_stabilized_up */
    [0x12] = 222, /* gps_timestamp */
    [0x14] = 223, /* temperature_statistics */
    [0x17] = 224, /* scaled_pressure */
    [0x18] = 225, /* overrange_status */
    [0x40] = 226, /* odometer_data */
    [0xD0] = 334, /* shared event_source */
    [0xD3] = 335, /* shared gps_timestamp */
    [0xD4] = 336, /* shared delta_time */
    [0xD5] = 337, /* shared reference_timestamp */
    [0xD6] = 338, /* shared reference_time_delta */
    [0xD7] = 339, /* shared external_timestamp */
    [0xD8] = 340, /* shared external_time_delta */
};
static const uint16_t k_set_gnss_data[256] = {
    [0x03] = 227, /* llh_position */
    [0x04] = 228, /* ecef_position */
    [0x05] = 229, /* ned_velocity */
    [0x06] = 230, /* ecef_velocity */
    [0x07] = 231, /* dop */
    [0x08] = 232, /* utc_time */
    [0x09] = 233, /* gps_time */
    [0x0A] = 234, /* clock_info */
    [0x0B] = 235, /* fix_info */
    [0x0C] = 236, /* sv_info */
    [0x0D] = 237, /* hardware_status */
    [0x0E] = 238, /* dgnss_info */
    [0x0F] = 239, /* dgnss_channel_status */
    [0xD0] = 334, /* shared event_source */
    [0xD3] = 335, /* shared gps_timestamp */
    [0xD4] = 336, /* shared delta_time */
    [0xD5] = 337, /* shared reference_timestamp */
    [0xD6] = 338, /* shared reference_time_delta */
    [0xD7] = 339, /* shared external_timestamp */
    [0xD8] = 340, /* shared external_time_delta */
};
static const uint16_t k_set_filter_data[256] = {
    [0x01] = 240, /* llh_position */
    [0x02] = 241, /* ned_velocity */
    [0x03] = 242, /* attitude_quaternion */
    [0x04] = 243, /* attitude_dcm */
    [0x05] = 244, /* euler_angles */
    [0x06] = 245, /* gyro_bias */
    [0x07] = 246, /* accel_bias */
    [0x08] = 247, /* llh_position_uncertainty */
    [0x09] = 248, /* ned_velocity_uncertainty */
    [0x0A] = 249, /* euler_angles_uncertainty */
    [0x0B] = 250, /* gyro_bias_uncertainty */
    [0x0C] = 251, /* accel_bias_uncertainty */
    [0x0D] = 252, /* linear_accel */
    [0x0E] = 253, /* comp_angular_rate */
    [0x0F] = 254, /* wgs84_gravity_magnitude */
    [0x10] = 255, /* filter_status */
    [0x11] = 256, /* gps_timestamp */
    [0x12] = 257, /* quaternion_attitude_uncertainty */
    [0x13] = 258, /* gravity_vector */
    [0x14] = 259, /* heading_update_state */
    [0x15] = 260, /* magnetic_model */
    [0x16] = 261, /* gyro_scale_factor */
    [0x17] = 262, /* accel_scale_factor */
    [0x18] = 263, /* gyro_scale_factor_uncertainty */
    [0x19] = 264, /* accel_scale_factor_uncertainty */
    [0x1C] = 265, /* compensated_accel */
    [0x20] = 266, /* standard_atmosphere */
    [0x21] = 267, /* pressure_altitude */
    [0x25] = 268, /* mag_auto_hard_iron_offset */
    [0x26] = 269, /* mag_auto_soft_iron_matrix */
    [0x28] = 270, /* mag_auto_hard_iron_offset_uncertainty */
    [0x29] = 271, /* mag_auto_soft_iron_matrix_uncertainty */
    [0x30] = 272, /* gnss_antenna_offset_correction */
    [0x31] = 273, /* gnss_antenna_offset_correction_uncertainty */
    [0x34] = 274, /* multi_antenna_offset_correction */
    [0x35] = 275, /* multi_antenna_offset_correction_uncertainty */
    [0x36] = 276, /* ecef_position_uncertainty */
    [0x37] = 277, /* ecef_velocity_uncertainty */
    [0x40] = 278, /* ecef_position */
    [0x41] = 279, /* ecef_velocity */
    [0x42] = 280, /* ned_relative_position */
    [0x43] = 281, /* gnss_position_aiding_status */
    [0x46] = 282, /* aiding_measurement_summary */
    [0x47] = 283, /* odometer_scale_factor_error */
    [0x48] = 284, /* odometer_scale_factor_error_uncertainty */
    [0x49] = 285, /* gnss_dual_antenna_status */
    [0x50] = 286, /* aiding_frame_config_error */
    [0x51] = 287, /* aiding_frame_config_error_uncertainty */
    [0xD0] = 334, /* shared event_source */
    [0xD3] = 335, /* shared gps_timestamp */
    [0xD4] = 336, /* shared delta_time */
    [0xD5] = 337, /* shared reference_timestamp */
    [0xD6] = 338, /* shared reference_time_delta */
    [0xD7] = 339, /* shared external_timestamp */
    [0xD8] = 340, /* shared external_time_delta */
};
static const uint16_t k_set_gnss_receiver_1[256] = {
    [0x03] = 288, /* llh_position */
    [0x04] = 289, /* ecef_position */
    [0x05] = 290, /* ned_velocity */
    [0x06] = 291, /* ecef_velocity */
    [0x07] = 292, /* dop */
    [0x08] = 293, /* utc_time */
    [0x09] = 294, /* gps_time */
    [0x0B] = 295, /* fix_info */
    [0x0D] = 296, /* hardware_status */
    [0x10] = 297, /* clock_info_2 */
    [0x11] = 298, /* gps_leap_seconds */
    [0x12] = 299, /* sbas_info */
    [0x20] = 300, /* satellite_status */
    [0x22] = 301, /* raw */
    [0x61] = 302, /* gps_ephemeris */
    [0x62] = 303, /* glonass_ephemeris */
    [0x63] = 304, /* galileo_ephemeris */
    [0x64] = 305, /* beidou_ephemeris */
    [0xD0] = 334, /* shared event_source */
    [0xD3] = 335, /* shared gps_timestamp */
    [0xD4] = 336, /* shared delta_time */
    [0xD5] = 337, /* shared reference_timestamp */
    [0xD6] = 338, /* shared reference_time_delta */
    [0xD7] = 339, /* shared external_timestamp */
    [0xD8] = 340, /* shared external_time_delta */
};
static const uint16_t k_set_gnss_receiver_2[256] = {
    [0x03] = 306, /* llh_position */
    [0x04] = 307, /* ecef_position */
    [0x05] = 308, /* ned_velocity */
    [0x06] = 309, /* ecef_velocity */
    [0x07] = 310, /* dop */
    [0x08] = 311, /* utc_time */
    [0x09] = 312, /* gps_time */
    [0x0B] = 313, /* fix_info */
    [0x0D] = 314, /* hardware_status */
    [0x10] = 315, /* clock_info_2 */
    [0x11] = 316, /* gps_leap_seconds */
    [0x12] = 317, /* sbas_info */
    [0x20] = 318, /* satellite_status */
    [0x22] = 319, /* raw */
    [0x61] = 320, /* gps_ephemeris */
    [0x62] = 321, /* glonass_ephemeris */
    [0x63] = 322, /* galileo_ephemeris */
    [0x64] = 323, /* beidou_ephemeris */
    [0xD0] = 334, /* shared event_source */
    [0xD3] = 335, /* shared gps_timestamp */
    [0xD4] = 336, /* shared delta_time */
    [0xD5] = 337, /* shared reference_timestamp */
    [0xD6] = 338, /* shared reference_time_delta */
    [0xD7] = 339, /* shared external_timestamp */
    [0xD8] = 340, /* shared external_time_delta */
};
static const uint16_t k_set_gnss_corrections[256] = {
    [0x30] = 324, /* base_station_info */
    [0x31] = 325, /* rtk_corrections_status */
    [0xD0] = 334, /* shared event_source */
    [0xD3] = 335, /* shared gps_timestamp */
    [0xD4] = 336, /* shared delta_time */
    [0xD5] = 337, /* shared reference_timestamp */
    [0xD6] = 338, /* shared reference_time_delta */
    [0xD7] = 339, /* shared external_timestamp */
    [0xD8] = 340, /* shared external_time_delta */
};
static const uint16_t k_set_gnss_external[256] = {
    [0x03] = 326, /* llh_position */
    [0x05] = 327, /* ned_velocity */
    [0x08] = 328, /* utc_time */
    [0x0B] = 329, /* fix_info */
    [0x20] = 330, /* satellite_status */
    [0xD0] = 334, /* shared event_source */
    [0xD3] = 335, /* shared gps_timestamp */
    [0xD4] = 336, /* shared delta_time */
    [0xD5] = 337, /* shared reference_timestamp */
    [0xD6] = 338, /* shared reference_time_delta */
    [0xD7] = 339, /* shared external_timestamp */
    [0xD8] = 340, /* shared external_time_delta */
};
static const uint16_t k_set_system_data[256] = {
    [0x01] = 331, /* built_in_test */
    [0x02] = 332, /* time_sync_status */
    [0x03] = 333, /* gpio_state */
    [0xD0] = 334, /* shared event_source */
    [0xD3] = 335, /* shared gps_timestamp */
    [0xD4] = 336, /* shared delta_time */
    [0xD5] = 337, /* shared reference_timestamp */
    [0xD6] = 338, /* shared reference_time_delta */
    [0xD7] = 339, /* shared external_timestamp */
    [0xD8] = 340, /* shared external_time_delta */
};
static const uint16_t k_set_shared[256] = {
    [0xD0] = 334, /* event_source */
    [0xD3] = 335, /* gps_timestamp */
    [0xD4] = 336, /* delta_time */
    [0xD5] = 337, /* reference_timestamp */
    [0xD6] = 338, /* reference_time_delta */
    [0xD7] = 339, /* external_timestamp */
    [0xD8] = 340, /* external_time_delta */
};

static const uint16_t *const k_sets[256] = {
    [0x01] = k_set_base,
    [0x0C] = k_set_threedm,
    [0x0D] = k_set_filter,
    [0x0E] = k_set_gnss,
    [0x13] = k_set_aiding,
    [0x7F] = k_set_system,
    [0x80] = k_set_sensor,
    [0x81] = k_set_gnss_data,
    [0x82] = k_set_filter_data,
    [0x91] = k_set_gnss_receiver_1,
    [0x92] = k_set_gnss_receiver_2,
    [0x93] = k_set_gnss_corrections,
    [0x94] = k_set_gnss_external,
    [0xA0] = k_set_system_data,
    [0xFF] = k_set_shared,
};

/* Fields of a set (reserved and shared data fields included, see k_set_*); *set_known tells
 * whether the set is defined at all. */
static const mip_field_info_t *defined(uint8_t set, uint8_t descriptor, bool *set_known) {
    const uint16_t *table = k_sets[set];
    *set_known = table != NULL;
    if (!table || table[descriptor] == 0) {
        return NULL;
    }
    return &k_fields[table[descriptor] - 1];
}

/* The body of mip_find_field, static so that mip_decode_field inlines it. */
static const mip_field_info_t *find_field(uint8_t set, uint8_t descriptor, mip_status_t *why) {
    bool known = false;
    mip_set_kind_t kind;
    const mip_field_info_t *f = defined(set, descriptor, &known);
    if (f) {
        return f;
    }
    kind = mip_set_kind(set);
    /* reserved fields of the set's kind */
    switch (kind) {
    case MIP_SET_KIND_COMMAND:
        if (descriptor == 0xF1) {
            return &k_fields[0]; /* ack_nack */
        }
        break;
    case MIP_SET_KIND_DATA:
        break;
    case MIP_SET_KIND_NONE:
    default:
        break;
    }
    /* shared data fields, valid in every data set */
    if (kind == MIP_SET_KIND_DATA) {
        bool shared_known;
        f = defined(0xFF, descriptor, &shared_known);
        if (f) {
            return f;
        }
    }
    if (why) {
        *why = known ? MIP_ERR_UNKNOWN_DESCRIPTOR : MIP_ERR_UNKNOWN_SET;
    }
    return NULL;
}

const mip_field_info_t *mip_find_field(uint8_t set, uint8_t descriptor, mip_status_t *why) {
    return find_field(set, descriptor, why);
}

static mip_status_t decode_layout(mip_field_id_t id, const uint8_t *data, size_t len, mip_field_value_t *out,
                                  mip_decode_error_t *err) {
    out->id = id;
    switch (id) {
    case MIP_FIELD_ACK_NACK:
        return mip_ack_nack_decode(data, len, &out->u.ack_nack, err);
    case MIP_FIELD_BASE_PING:
        return mip_base_ping_decode(data, len, &out->u.base_ping, err);
    case MIP_FIELD_BASE_SET_TO_IDLE:
        return mip_base_set_to_idle_decode(data, len, &out->u.base_set_to_idle, err);
    case MIP_FIELD_BASE_GET_DEVICE_INFO:
        return mip_base_get_device_info_decode(data, len, &out->u.base_get_device_info, err);
    case MIP_FIELD_BASE_DEVICE_INFO:
        return mip_base_device_info_decode(data, len, &out->u.base_device_info, err);
    case MIP_FIELD_BASE_GET_DEVICE_DESCRIPTORS:
        return mip_base_get_device_descriptors_decode(data, len, &out->u.base_get_device_descriptors, err);
    case MIP_FIELD_BASE_DEVICE_DESCRIPTORS:
        return mip_base_device_descriptors_decode(data, len, &out->u.base_device_descriptors, err);
    case MIP_FIELD_BASE_BUILT_IN_TEST:
        return mip_base_built_in_test_decode(data, len, &out->u.base_built_in_test, err);
    case MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45:
        return mip_base_built_in_test_result_gx5_45_decode(data, len,
                                                           &out->u.base_built_in_test_result_gx5_45, err);
    case MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS:
        return mip_base_built_in_test_result_cv7_ins_decode(data, len,
                                                            &out->u.base_built_in_test_result_cv7_ins, err);
    case MIP_FIELD_BASE_RESUME:
        return mip_base_resume_decode(data, len, &out->u.base_resume, err);
    case MIP_FIELD_BASE_GET_EXTENDED_DESCRIPTORS:
        return mip_base_get_extended_descriptors_decode(data, len, &out->u.base_get_extended_descriptors,
                                                        err);
    case MIP_FIELD_BASE_EXTENDED_DESCRIPTORS:
        return mip_base_extended_descriptors_decode(data, len, &out->u.base_extended_descriptors, err);
    case MIP_FIELD_BASE_CONTINUOUS_BIT:
        return mip_base_continuous_bit_decode(data, len, &out->u.base_continuous_bit, err);
    case MIP_FIELD_BASE_CONTINUOUS_BIT_RESULT:
        return mip_base_continuous_bit_result_decode(data, len, &out->u.base_continuous_bit_result, err);
    case MIP_FIELD_BASE_COMM_PORT_SPEED:
        return mip_base_comm_port_speed_decode(data, len, &out->u.base_comm_port_speed, err);
    case MIP_FIELD_BASE_COMM_PORT_SPEED_RESPONSE:
        return mip_base_comm_port_speed_response_decode(data, len, &out->u.base_comm_port_speed_response,
                                                        err);
    case MIP_FIELD_BASE_GPS_TIME_UPDATE_GX5_45:
        return mip_base_gps_time_update_gx5_45_decode(data, len, &out->u.base_gps_time_update_gx5_45, err);
    case MIP_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS:
        return mip_base_gps_time_update_cv7_ins_decode(data, len, &out->u.base_gps_time_update_cv7_ins, err);
    case MIP_FIELD_BASE_GPS_WEEK:
        return mip_base_gps_week_decode(data, len, &out->u.base_gps_week, err);
    case MIP_FIELD_BASE_GPS_SECONDS:
        return mip_base_gps_seconds_decode(data, len, &out->u.base_gps_seconds, err);
    case MIP_FIELD_BASE_DEVICE_RESET:
        return mip_base_device_reset_decode(data, len, &out->u.base_device_reset, err);
    case MIP_FIELD_THREEDM_EVENT_CONTROL:
        return mip_threedm_event_control_decode(data, len, &out->u.threedm_event_control, err);
    case MIP_FIELD_THREEDM_EVENT_CONTROL_RESPONSE:
        return mip_threedm_event_control_response_decode(data, len, &out->u.threedm_event_control_response,
                                                         err);
    case MIP_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS:
        return mip_threedm_get_event_trigger_status_decode(data, len,
                                                           &out->u.threedm_get_event_trigger_status, err);
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_STATUS:
        return mip_threedm_event_trigger_status_decode(data, len, &out->u.threedm_event_trigger_status, err);
    case MIP_FIELD_THREEDM_GET_EVENT_ACTION_STATUS:
        return mip_threedm_get_event_action_status_decode(data, len, &out->u.threedm_get_event_action_status,
                                                          err);
    case MIP_FIELD_THREEDM_EVENT_ACTION_STATUS:
        return mip_threedm_event_action_status_decode(data, len, &out->u.threedm_event_action_status, err);
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG:
        return mip_threedm_event_trigger_config_decode(data, len, &out->u.threedm_event_trigger_config, err);
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE:
        return mip_threedm_event_trigger_config_response_decode(
            data, len, &out->u.threedm_event_trigger_config_response, err);
    case MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG:
        return mip_threedm_event_action_config_decode(data, len, &out->u.threedm_event_action_config, err);
    case MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE:
        return mip_threedm_event_action_config_response_decode(
            data, len, &out->u.threedm_event_action_config_response, err);
    case MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45:
        return mip_threedm_device_startup_settings_gx5_45_decode(
            data, len, &out->u.threedm_device_startup_settings_gx5_45, err);
    case MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS:
        return mip_threedm_device_startup_settings_cv7_ins_decode(
            data, len, &out->u.threedm_device_startup_settings_cv7_ins, err);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER:
        return mip_threedm_sensor_to_vehicle_euler_decode(data, len, &out->u.threedm_sensor_to_vehicle_euler,
                                                          err);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE:
        return mip_threedm_sensor_to_vehicle_euler_response_decode(
            data, len, &out->u.threedm_sensor_to_vehicle_euler_response, err);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION:
        return mip_threedm_sensor_to_vehicle_quaternion_decode(
            data, len, &out->u.threedm_sensor_to_vehicle_quaternion, err);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE:
        return mip_threedm_sensor_to_vehicle_quaternion_response_decode(
            data, len, &out->u.threedm_sensor_to_vehicle_quaternion_response, err);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM:
        return mip_threedm_sensor_to_vehicle_dcm_decode(data, len, &out->u.threedm_sensor_to_vehicle_dcm,
                                                        err);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE:
        return mip_threedm_sensor_to_vehicle_dcm_response_decode(
            data, len, &out->u.threedm_sensor_to_vehicle_dcm_response, err);
    case MIP_FIELD_THREEDM_ACCEL_BIAS_GX5_45:
        return mip_threedm_accel_bias_gx5_45_decode(data, len, &out->u.threedm_accel_bias_gx5_45, err);
    case MIP_FIELD_THREEDM_ACCEL_BIAS_CV7_INS:
        return mip_threedm_accel_bias_cv7_ins_decode(data, len, &out->u.threedm_accel_bias_cv7_ins, err);
    case MIP_FIELD_THREEDM_ACCEL_BIAS_RESPONSE:
        return mip_threedm_accel_bias_response_decode(data, len, &out->u.threedm_accel_bias_response, err);
    case MIP_FIELD_THREEDM_GYRO_BIAS_GX5_45:
        return mip_threedm_gyro_bias_gx5_45_decode(data, len, &out->u.threedm_gyro_bias_gx5_45, err);
    case MIP_FIELD_THREEDM_GYRO_BIAS_CV7_INS:
        return mip_threedm_gyro_bias_cv7_ins_decode(data, len, &out->u.threedm_gyro_bias_cv7_ins, err);
    case MIP_FIELD_THREEDM_GYRO_BIAS_RESPONSE:
        return mip_threedm_gyro_bias_response_decode(data, len, &out->u.threedm_gyro_bias_response, err);
    case MIP_FIELD_THREEDM_CAPTURE_GYRO_BIAS:
        return mip_threedm_capture_gyro_bias_decode(data, len, &out->u.threedm_capture_gyro_bias, err);
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45:
        return mip_threedm_mag_hard_iron_offset_gx5_45_decode(
            data, len, &out->u.threedm_mag_hard_iron_offset_gx5_45, err);
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS:
        return mip_threedm_mag_hard_iron_offset_cv7_ins_decode(
            data, len, &out->u.threedm_mag_hard_iron_offset_cv7_ins, err);
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE:
        return mip_threedm_mag_hard_iron_offset_response_decode(
            data, len, &out->u.threedm_mag_hard_iron_offset_response, err);
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45:
        return mip_threedm_mag_soft_iron_matrix_gx5_45_decode(
            data, len, &out->u.threedm_mag_soft_iron_matrix_gx5_45, err);
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS:
        return mip_threedm_mag_soft_iron_matrix_cv7_ins_decode(
            data, len, &out->u.threedm_mag_soft_iron_matrix_cv7_ins, err);
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE:
        return mip_threedm_mag_soft_iron_matrix_response_decode(
            data, len, &out->u.threedm_mag_soft_iron_matrix_response, err);
    case MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE:
        return mip_threedm_coning_sculling_enable_decode(data, len, &out->u.threedm_coning_sculling_enable,
                                                         err);
    case MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE:
        return mip_threedm_coning_sculling_enable_response_decode(
            data, len, &out->u.threedm_coning_sculling_enable_response, err);
    case MIP_FIELD_THREEDM_UART_BAUDRATE:
        return mip_threedm_uart_baudrate_decode(data, len, &out->u.threedm_uart_baudrate, err);
    case MIP_FIELD_THREEDM_UART_BAUDRATE_RESPONSE:
        return mip_threedm_uart_baudrate_response_decode(data, len, &out->u.threedm_uart_baudrate_response,
                                                         err);
    case MIP_FIELD_THREEDM_GPIO_CONFIG:
        return mip_threedm_gpio_config_decode(data, len, &out->u.threedm_gpio_config, err);
    case MIP_FIELD_THREEDM_GPIO_CONFIG_RESPONSE:
        return mip_threedm_gpio_config_response_decode(data, len, &out->u.threedm_gpio_config_response, err);
    case MIP_FIELD_THREEDM_GPIO_STATE:
        return mip_threedm_gpio_state_decode(data, len, &out->u.threedm_gpio_state, err);
    case MIP_FIELD_THREEDM_GPIO_STATE_RESPONSE:
        return mip_threedm_gpio_state_response_decode(data, len, &out->u.threedm_gpio_state_response, err);
    case MIP_FIELD_THREEDM_ODOMETER_CONFIG:
        return mip_threedm_odometer_config_decode(data, len, &out->u.threedm_odometer_config, err);
    case MIP_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE:
        return mip_threedm_odometer_config_response_decode(data, len,
                                                           &out->u.threedm_odometer_config_response, err);
    case MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER:
        return mip_threedm_advanced_lowpass_filter_decode(data, len, &out->u.threedm_advanced_lowpass_filter,
                                                          err);
    case MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE:
        return mip_threedm_advanced_lowpass_filter_response_decode(
            data, len, &out->u.threedm_advanced_lowpass_filter_response, err);
    case MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER:
        return mip_threedm_complementary_filter_decode(data, len, &out->u.threedm_complementary_filter, err);
    case MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE:
        return mip_threedm_complementary_filter_response_decode(
            data, len, &out->u.threedm_complementary_filter_response, err);
    case MIP_FIELD_THREEDM_SENSOR_RANGE:
        return mip_threedm_sensor_range_decode(data, len, &out->u.threedm_sensor_range, err);
    case MIP_FIELD_THREEDM_SENSOR_RANGE_RESPONSE:
        return mip_threedm_sensor_range_response_decode(data, len, &out->u.threedm_sensor_range_response,
                                                        err);
    case MIP_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES:
        return mip_threedm_get_calibrated_sensor_ranges_decode(
            data, len, &out->u.threedm_get_calibrated_sensor_ranges, err);
    case MIP_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES:
        return mip_threedm_calibrated_sensor_ranges_decode(data, len,
                                                           &out->u.threedm_calibrated_sensor_ranges, err);
    case MIP_FIELD_THREEDM_LOWPASS_FILTER:
        return mip_threedm_lowpass_filter_decode(data, len, &out->u.threedm_lowpass_filter, err);
    case MIP_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE:
        return mip_threedm_lowpass_filter_response_decode(data, len, &out->u.threedm_lowpass_filter_response,
                                                          err);
    case MIP_FIELD_THREEDM_POLL_IMU_DATA:
        return mip_threedm_poll_imu_data_decode(data, len, &out->u.threedm_poll_imu_data, err);
    case MIP_FIELD_THREEDM_POLL_GNSS_DATA:
        return mip_threedm_poll_gnss_data_decode(data, len, &out->u.threedm_poll_gnss_data, err);
    case MIP_FIELD_THREEDM_POLL_FILTER_DATA:
        return mip_threedm_poll_filter_data_decode(data, len, &out->u.threedm_poll_filter_data, err);
    case MIP_FIELD_THREEDM_POLL_NMEA_DATA:
        return mip_threedm_poll_nmea_data_decode(data, len, &out->u.threedm_poll_nmea_data, err);
    case MIP_FIELD_THREEDM_POLL_DATA:
        return mip_threedm_poll_data_decode(data, len, &out->u.threedm_poll_data, err);
    case MIP_FIELD_THREEDM_GET_IMU_BASE_RATE:
        return mip_threedm_get_imu_base_rate_decode(data, len, &out->u.threedm_get_imu_base_rate, err);
    case MIP_FIELD_THREEDM_IMU_BASE_RATE:
        return mip_threedm_imu_base_rate_decode(data, len, &out->u.threedm_imu_base_rate, err);
    case MIP_FIELD_THREEDM_GET_GNSS_BASE_RATE:
        return mip_threedm_get_gnss_base_rate_decode(data, len, &out->u.threedm_get_gnss_base_rate, err);
    case MIP_FIELD_THREEDM_GNSS_BASE_RATE:
        return mip_threedm_gnss_base_rate_decode(data, len, &out->u.threedm_gnss_base_rate, err);
    case MIP_FIELD_THREEDM_GET_FILTER_BASE_RATE:
        return mip_threedm_get_filter_base_rate_decode(data, len, &out->u.threedm_get_filter_base_rate, err);
    case MIP_FIELD_THREEDM_FILTER_BASE_RATE:
        return mip_threedm_filter_base_rate_decode(data, len, &out->u.threedm_filter_base_rate, err);
    case MIP_FIELD_THREEDM_GET_BASE_RATE:
        return mip_threedm_get_base_rate_decode(data, len, &out->u.threedm_get_base_rate, err);
    case MIP_FIELD_THREEDM_BASE_RATE:
        return mip_threedm_base_rate_decode(data, len, &out->u.threedm_base_rate, err);
    case MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT:
        return mip_threedm_imu_message_format_decode(data, len, &out->u.threedm_imu_message_format, err);
    case MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_imu_message_format_response_decode(
            data, len, &out->u.threedm_imu_message_format_response, err);
    case MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT:
        return mip_threedm_gnss_message_format_decode(data, len, &out->u.threedm_gnss_message_format, err);
    case MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_gnss_message_format_response_decode(
            data, len, &out->u.threedm_gnss_message_format_response, err);
    case MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT:
        return mip_threedm_filter_message_format_decode(data, len, &out->u.threedm_filter_message_format,
                                                        err);
    case MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_filter_message_format_response_decode(
            data, len, &out->u.threedm_filter_message_format_response, err);
    case MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT:
        return mip_threedm_nmea_message_format_decode(data, len, &out->u.threedm_nmea_message_format, err);
    case MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_nmea_message_format_response_decode(
            data, len, &out->u.threedm_nmea_message_format_response, err);
    case MIP_FIELD_THREEDM_MESSAGE_FORMAT:
        return mip_threedm_message_format_decode(data, len, &out->u.threedm_message_format, err);
    case MIP_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_message_format_response_decode(data, len, &out->u.threedm_message_format_response,
                                                          err);
    case MIP_FIELD_THREEDM_FACTORY_STREAMING:
        return mip_threedm_factory_streaming_decode(data, len, &out->u.threedm_factory_streaming, err);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45:
        return mip_threedm_data_stream_control_gx5_45_decode(data, len,
                                                             &out->u.threedm_data_stream_control_gx5_45, err);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS:
        return mip_threedm_data_stream_control_cv7_ins_decode(
            data, len, &out->u.threedm_data_stream_control_cv7_ins, err);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45:
        return mip_threedm_data_stream_control_response_gx5_45_decode(
            data, len, &out->u.threedm_data_stream_control_response_gx5_45, err);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS:
        return mip_threedm_data_stream_control_response_cv7_ins_decode(
            data, len, &out->u.threedm_data_stream_control_response_cv7_ins, err);
    case MIP_FIELD_THREEDM_RAW_RTCM_MESSAGE:
        return mip_threedm_raw_rtcm_message_decode(data, len, &out->u.threedm_raw_rtcm_message, err);
    case MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS:
        return mip_threedm_gnss_constellation_settings_decode(
            data, len, &out->u.threedm_gnss_constellation_settings, err);
    case MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE:
        return mip_threedm_gnss_constellation_settings_response_decode(
            data, len, &out->u.threedm_gnss_constellation_settings_response, err);
    case MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS:
        return mip_threedm_gnss_sbas_settings_decode(data, len, &out->u.threedm_gnss_sbas_settings, err);
    case MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE:
        return mip_threedm_gnss_sbas_settings_response_decode(
            data, len, &out->u.threedm_gnss_sbas_settings_response, err);
    case MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL:
        return mip_threedm_gnss_assisted_fix_control_decode(data, len,
                                                            &out->u.threedm_gnss_assisted_fix_control, err);
    case MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE:
        return mip_threedm_gnss_assisted_fix_control_response_decode(
            data, len, &out->u.threedm_gnss_assisted_fix_control_response, err);
    case MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE:
        return mip_threedm_gnss_assist_time_update_decode(data, len, &out->u.threedm_gnss_assist_time_update,
                                                          err);
    case MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE:
        return mip_threedm_gnss_assist_time_update_response_decode(
            data, len, &out->u.threedm_gnss_assist_time_update_response, err);
    case MIP_FIELD_THREEDM_PPS_SOURCE:
        return mip_threedm_pps_source_decode(data, len, &out->u.threedm_pps_source, err);
    case MIP_FIELD_THREEDM_PPS_SOURCE_RESPONSE:
        return mip_threedm_pps_source_response_decode(data, len, &out->u.threedm_pps_source_response, err);
    case MIP_FIELD_THREEDM_GET_SUPPORTED_EVENTS:
        return mip_threedm_get_supported_events_decode(data, len, &out->u.threedm_get_supported_events, err);
    case MIP_FIELD_THREEDM_SUPPORTED_EVENTS:
        return mip_threedm_supported_events_decode(data, len, &out->u.threedm_supported_events, err);
    case MIP_FIELD_THREEDM_DEVICE_STATUS:
        return mip_threedm_device_status_decode(data, len, &out->u.threedm_device_status, err);
    case MIP_FIELD_THREEDM_DEVICE_STATUS_RESPONSE:
        return mip_threedm_device_status_response_decode(data, len, &out->u.threedm_device_status_response,
                                                         err);
    case MIP_FIELD_FILTER_RESET_FILTER:
        return mip_filter_reset_filter_decode(data, len, &out->u.filter_reset_filter, err);
    case MIP_FIELD_FILTER_SET_INITIAL_ATTITUDE:
        return mip_filter_set_initial_attitude_decode(data, len, &out->u.filter_set_initial_attitude, err);
    case MIP_FIELD_FILTER_SET_INITIAL_HEADING:
        return mip_filter_set_initial_heading_decode(data, len, &out->u.filter_set_initial_heading, err);
    case MIP_FIELD_FILTER_RUN_FILTER:
        return mip_filter_run_filter_decode(data, len, &out->u.filter_run_filter, err);
    case MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE:
        return mip_filter_vehicle_dynamics_mode_decode(data, len, &out->u.filter_vehicle_dynamics_mode, err);
    case MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE:
        return mip_filter_vehicle_dynamics_mode_response_decode(
            data, len, &out->u.filter_vehicle_dynamics_mode_response, err);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM:
        return mip_filter_sensor_to_vehicle_transform_decode(data, len,
                                                             &out->u.filter_sensor_to_vehicle_transform, err);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE:
        return mip_filter_sensor_to_vehicle_transform_response_decode(
            data, len, &out->u.filter_sensor_to_vehicle_transform_response, err);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET:
        return mip_filter_sensor_to_vehicle_offset_decode(data, len, &out->u.filter_sensor_to_vehicle_offset,
                                                          err);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE:
        return mip_filter_sensor_to_vehicle_offset_response_decode(
            data, len, &out->u.filter_sensor_to_vehicle_offset_response, err);
    case MIP_FIELD_FILTER_ANTENNA_OFFSET:
        return mip_filter_antenna_offset_decode(data, len, &out->u.filter_antenna_offset, err);
    case MIP_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE:
        return mip_filter_antenna_offset_response_decode(data, len, &out->u.filter_antenna_offset_response,
                                                         err);
    case MIP_FIELD_FILTER_ESTIMATION_CONTROL:
        return mip_filter_estimation_control_decode(data, len, &out->u.filter_estimation_control, err);
    case MIP_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE:
        return mip_filter_estimation_control_response_decode(data, len,
                                                             &out->u.filter_estimation_control_response, err);
    case MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL:
        return mip_filter_gnss_source_control_decode(data, len, &out->u.filter_gnss_source_control, err);
    case MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE:
        return mip_filter_gnss_source_control_response_decode(
            data, len, &out->u.filter_gnss_source_control_response, err);
    case MIP_FIELD_FILTER_EXTERNAL_GNSS_UPDATE:
        return mip_filter_external_gnss_update_decode(data, len, &out->u.filter_external_gnss_update, err);
    case MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE:
        return mip_filter_external_heading_update_decode(data, len, &out->u.filter_external_heading_update,
                                                         err);
    case MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL:
        return mip_filter_heading_update_control_decode(data, len, &out->u.filter_heading_update_control,
                                                        err);
    case MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE:
        return mip_filter_heading_update_control_response_decode(
            data, len, &out->u.filter_heading_update_control_response, err);
    case MIP_FIELD_FILTER_AUTO_INIT_CONTROL:
        return mip_filter_auto_init_control_decode(data, len, &out->u.filter_auto_init_control, err);
    case MIP_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE:
        return mip_filter_auto_init_control_response_decode(data, len,
                                                            &out->u.filter_auto_init_control_response, err);
    case MIP_FIELD_FILTER_ACCEL_NOISE:
        return mip_filter_accel_noise_decode(data, len, &out->u.filter_accel_noise, err);
    case MIP_FIELD_FILTER_ACCEL_NOISE_RESPONSE:
        return mip_filter_accel_noise_response_decode(data, len, &out->u.filter_accel_noise_response, err);
    case MIP_FIELD_FILTER_GYRO_NOISE:
        return mip_filter_gyro_noise_decode(data, len, &out->u.filter_gyro_noise, err);
    case MIP_FIELD_FILTER_GYRO_NOISE_RESPONSE:
        return mip_filter_gyro_noise_response_decode(data, len, &out->u.filter_gyro_noise_response, err);
    case MIP_FIELD_FILTER_ACCEL_BIAS_MODEL:
        return mip_filter_accel_bias_model_decode(data, len, &out->u.filter_accel_bias_model, err);
    case MIP_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE:
        return mip_filter_accel_bias_model_response_decode(data, len,
                                                           &out->u.filter_accel_bias_model_response, err);
    case MIP_FIELD_FILTER_GYRO_BIAS_MODEL:
        return mip_filter_gyro_bias_model_decode(data, len, &out->u.filter_gyro_bias_model, err);
    case MIP_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE:
        return mip_filter_gyro_bias_model_response_decode(data, len, &out->u.filter_gyro_bias_model_response,
                                                          err);
    case MIP_FIELD_FILTER_ZUPT_CONTROL:
        return mip_filter_zupt_control_decode(data, len, &out->u.filter_zupt_control, err);
    case MIP_FIELD_FILTER_ZUPT_CONTROL_RESPONSE:
        return mip_filter_zupt_control_response_decode(data, len, &out->u.filter_zupt_control_response, err);
    case MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME:
        return mip_filter_external_heading_update_with_time_decode(
            data, len, &out->u.filter_external_heading_update_with_time, err);
    case MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL:
        return mip_filter_zero_angular_rate_update_control_decode(
            data, len, &out->u.filter_zero_angular_rate_update_control, err);
    case MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE:
        return mip_filter_zero_angular_rate_update_control_response_decode(
            data, len, &out->u.filter_zero_angular_rate_update_control_response, err);
    case MIP_FIELD_FILTER_TARE_ORIENTATION:
        return mip_filter_tare_orientation_decode(data, len, &out->u.filter_tare_orientation, err);
    case MIP_FIELD_FILTER_COMMANDED_ZUPT:
        return mip_filter_commanded_zupt_decode(data, len, &out->u.filter_commanded_zupt, err);
    case MIP_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE:
        return mip_filter_commanded_zero_angular_rate_update_decode(
            data, len, &out->u.filter_commanded_zero_angular_rate_update, err);
    case MIP_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION:
        return mip_filter_mag_capture_auto_calibration_decode(
            data, len, &out->u.filter_mag_capture_auto_calibration, err);
    case MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV:
        return mip_filter_gravity_noise_std_dev_decode(data, len, &out->u.filter_gravity_noise_std_dev, err);
    case MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE:
        return mip_filter_gravity_noise_std_dev_response_decode(
            data, len, &out->u.filter_gravity_noise_std_dev_response, err);
    case MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV:
        return mip_filter_pressure_altitude_noise_std_dev_decode(
            data, len, &out->u.filter_pressure_altitude_noise_std_dev, err);
    case MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE:
        return mip_filter_pressure_altitude_noise_std_dev_response_decode(
            data, len, &out->u.filter_pressure_altitude_noise_std_dev_response, err);
    case MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE:
        return mip_filter_hard_iron_offset_noise_decode(data, len, &out->u.filter_hard_iron_offset_noise,
                                                        err);
    case MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE:
        return mip_filter_hard_iron_offset_noise_response_decode(
            data, len, &out->u.filter_hard_iron_offset_noise_response, err);
    case MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE:
        return mip_filter_soft_iron_matrix_noise_decode(data, len, &out->u.filter_soft_iron_matrix_noise,
                                                        err);
    case MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE:
        return mip_filter_soft_iron_matrix_noise_response_decode(
            data, len, &out->u.filter_soft_iron_matrix_noise_response, err);
    case MIP_FIELD_FILTER_MAG_NOISE_STD_DEV:
        return mip_filter_mag_noise_std_dev_decode(data, len, &out->u.filter_mag_noise_std_dev, err);
    case MIP_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE:
        return mip_filter_mag_noise_std_dev_response_decode(data, len,
                                                            &out->u.filter_mag_noise_std_dev_response, err);
    case MIP_FIELD_FILTER_DECLINATION_SOURCE:
        return mip_filter_declination_source_decode(data, len, &out->u.filter_declination_source, err);
    case MIP_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE:
        return mip_filter_declination_source_response_decode(data, len,
                                                             &out->u.filter_declination_source_response, err);
    case MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mip_filter_gravity_magnitude_adaptive_measurement_decode(
            data, len, &out->u.filter_gravity_magnitude_adaptive_measurement, err);
    case MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mip_filter_gravity_magnitude_adaptive_measurement_response_decode(
            data, len, &out->u.filter_gravity_magnitude_adaptive_measurement_response, err);
    case MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mip_filter_mag_magnitude_adaptive_measurement_decode(
            data, len, &out->u.filter_mag_magnitude_adaptive_measurement, err);
    case MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mip_filter_mag_magnitude_adaptive_measurement_response_decode(
            data, len, &out->u.filter_mag_magnitude_adaptive_measurement_response, err);
    case MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT:
        return mip_filter_mag_dip_angle_adaptive_measurement_decode(
            data, len, &out->u.filter_mag_dip_angle_adaptive_measurement, err);
    case MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mip_filter_mag_dip_angle_adaptive_measurement_response_decode(
            data, len, &out->u.filter_mag_dip_angle_adaptive_measurement_response, err);
    case MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL:
        return mip_filter_altitude_aiding_control_decode(data, len, &out->u.filter_altitude_aiding_control,
                                                         err);
    case MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE:
        return mip_filter_altitude_aiding_control_response_decode(
            data, len, &out->u.filter_altitude_aiding_control_response, err);
    case MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL:
        return mip_filter_pitch_roll_aiding_control_decode(data, len,
                                                           &out->u.filter_pitch_roll_aiding_control, err);
    case MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE:
        return mip_filter_pitch_roll_aiding_control_response_decode(
            data, len, &out->u.filter_pitch_roll_aiding_control_response, err);
    case MIP_FIELD_FILTER_INCLINATION_SOURCE:
        return mip_filter_inclination_source_decode(data, len, &out->u.filter_inclination_source, err);
    case MIP_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE:
        return mip_filter_inclination_source_response_decode(data, len,
                                                             &out->u.filter_inclination_source_response, err);
    case MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE:
        return mip_filter_magnetic_field_magnitude_source_decode(
            data, len, &out->u.filter_magnetic_field_magnitude_source, err);
    case MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE:
        return mip_filter_magnetic_field_magnitude_source_response_decode(
            data, len, &out->u.filter_magnetic_field_magnitude_source_response, err);
    case MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL:
        return mip_filter_aiding_measurement_control_decode(data, len,
                                                            &out->u.filter_aiding_measurement_control, err);
    case MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE:
        return mip_filter_aiding_measurement_control_response_decode(
            data, len, &out->u.filter_aiding_measurement_control_response, err);
    case MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION:
        return mip_filter_initialization_configuration_decode(
            data, len, &out->u.filter_initialization_configuration, err);
    case MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE:
        return mip_filter_initialization_configuration_response_decode(
            data, len, &out->u.filter_initialization_configuration_response, err);
    case MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL:
        return mip_filter_adaptive_filter_control_decode(data, len, &out->u.filter_adaptive_filter_control,
                                                         err);
    case MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE:
        return mip_filter_adaptive_filter_control_response_decode(
            data, len, &out->u.filter_adaptive_filter_control_response, err);
    case MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET:
        return mip_filter_multi_antenna_offset_decode(data, len, &out->u.filter_multi_antenna_offset, err);
    case MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE:
        return mip_filter_multi_antenna_offset_response_decode(
            data, len, &out->u.filter_multi_antenna_offset_response, err);
    case MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION:
        return mip_filter_relative_position_configuration_decode(
            data, len, &out->u.filter_relative_position_configuration, err);
    case MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE:
        return mip_filter_relative_position_configuration_response_decode(
            data, len, &out->u.filter_relative_position_configuration_response, err);
    case MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM:
        return mip_filter_reference_point_lever_arm_decode(data, len,
                                                           &out->u.filter_reference_point_lever_arm, err);
    case MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE:
        return mip_filter_reference_point_lever_arm_response_decode(
            data, len, &out->u.filter_reference_point_lever_arm_response, err);
    case MIP_FIELD_FILTER_SPEED_LEVER_ARM:
        return mip_filter_speed_lever_arm_decode(data, len, &out->u.filter_speed_lever_arm, err);
    case MIP_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE:
        return mip_filter_speed_lever_arm_response_decode(data, len, &out->u.filter_speed_lever_arm_response,
                                                          err);
    case MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL:
        return mip_filter_wheeled_vehicle_constraint_control_decode(
            data, len, &out->u.filter_wheeled_vehicle_constraint_control, err);
    case MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE:
        return mip_filter_wheeled_vehicle_constraint_control_response_decode(
            data, len, &out->u.filter_wheeled_vehicle_constraint_control_response, err);
    case MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL:
        return mip_filter_gnss_antenna_calibration_control_decode(
            data, len, &out->u.filter_gnss_antenna_calibration_control, err);
    case MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE:
        return mip_filter_gnss_antenna_calibration_control_response_decode(
            data, len, &out->u.filter_gnss_antenna_calibration_control_response, err);
    case MIP_FIELD_GNSS_RECEIVER_INFO:
        return mip_gnss_receiver_info_decode(data, len, &out->u.gnss_receiver_info, err);
    case MIP_FIELD_GNSS_RECEIVER_INFO_RESPONSE:
        return mip_gnss_receiver_info_response_decode(data, len, &out->u.gnss_receiver_info_response, err);
    case MIP_FIELD_GNSS_SIGNAL_CONFIGURATION:
        return mip_gnss_signal_configuration_decode(data, len, &out->u.gnss_signal_configuration, err);
    case MIP_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE:
        return mip_gnss_signal_configuration_response_decode(data, len,
                                                             &out->u.gnss_signal_configuration_response, err);
    case MIP_FIELD_GNSS_SPARTN_CONFIGURATION:
        return mip_gnss_spartn_configuration_decode(data, len, &out->u.gnss_spartn_configuration, err);
    case MIP_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE:
        return mip_gnss_spartn_configuration_response_decode(data, len,
                                                             &out->u.gnss_spartn_configuration_response, err);
    case MIP_FIELD_AIDING_FRAME_CONFIG:
        return mip_aiding_frame_config_decode(data, len, &out->u.aiding_frame_config, err);
    case MIP_FIELD_AIDING_FRAME_CONFIG_RESPONSE:
        return mip_aiding_frame_config_response_decode(data, len, &out->u.aiding_frame_config_response, err);
    case MIP_FIELD_AIDING_ECHO_CONTROL:
        return mip_aiding_echo_control_decode(data, len, &out->u.aiding_echo_control, err);
    case MIP_FIELD_AIDING_ECHO_CONTROL_RESPONSE:
        return mip_aiding_echo_control_response_decode(data, len, &out->u.aiding_echo_control_response, err);
    case MIP_FIELD_AIDING_ECEF_POSITION:
        return mip_aiding_ecef_position_decode(data, len, &out->u.aiding_ecef_position, err);
    case MIP_FIELD_AIDING_LLH_POSITION:
        return mip_aiding_llh_position_decode(data, len, &out->u.aiding_llh_position, err);
    case MIP_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID:
        return mip_aiding_height_above_ellipsoid_decode(data, len, &out->u.aiding_height_above_ellipsoid,
                                                        err);
    case MIP_FIELD_AIDING_ECEF_VELOCITY:
        return mip_aiding_ecef_velocity_decode(data, len, &out->u.aiding_ecef_velocity, err);
    case MIP_FIELD_AIDING_NED_VELOCITY:
        return mip_aiding_ned_velocity_decode(data, len, &out->u.aiding_ned_velocity, err);
    case MIP_FIELD_AIDING_BODY_FRAME_VELOCITY:
        return mip_aiding_body_frame_velocity_decode(data, len, &out->u.aiding_body_frame_velocity, err);
    case MIP_FIELD_AIDING_TRUE_HEADING:
        return mip_aiding_true_heading_decode(data, len, &out->u.aiding_true_heading, err);
    case MIP_FIELD_AIDING_MAGNETIC_FIELD:
        return mip_aiding_magnetic_field_decode(data, len, &out->u.aiding_magnetic_field, err);
    case MIP_FIELD_AIDING_PRESSURE:
        return mip_aiding_pressure_decode(data, len, &out->u.aiding_pressure, err);
    case MIP_FIELD_SYSTEM_COMMUNICATION_MODE:
        return mip_system_communication_mode_decode(data, len, &out->u.system_communication_mode, err);
    case MIP_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE:
        return mip_system_communication_mode_response_decode(data, len,
                                                             &out->u.system_communication_mode_response, err);
    case MIP_FIELD_SENSOR_SCALED_ACCEL:
        return mip_sensor_scaled_accel_decode(data, len, &out->u.sensor_scaled_accel, err);
    case MIP_FIELD_SENSOR_SCALED_GYRO:
        return mip_sensor_scaled_gyro_decode(data, len, &out->u.sensor_scaled_gyro, err);
    case MIP_FIELD_SENSOR_SCALED_MAG:
        return mip_sensor_scaled_mag_decode(data, len, &out->u.sensor_scaled_mag, err);
    case MIP_FIELD_SENSOR_DELTA_THETA:
        return mip_sensor_delta_theta_decode(data, len, &out->u.sensor_delta_theta, err);
    case MIP_FIELD_SENSOR_DELTA_VELOCITY:
        return mip_sensor_delta_velocity_decode(data, len, &out->u.sensor_delta_velocity, err);
    case MIP_FIELD_SENSOR_CF_ORIENTATION_MATRIX:
        return mip_sensor_cf_orientation_matrix_decode(data, len, &out->u.sensor_cf_orientation_matrix, err);
    case MIP_FIELD_SENSOR_CF_QUATERNION:
        return mip_sensor_cf_quaternion_decode(data, len, &out->u.sensor_cf_quaternion, err);
    case MIP_FIELD_SENSOR_CF_EULER_ANGLES:
        return mip_sensor_cf_euler_angles_decode(data, len, &out->u.sensor_cf_euler_angles, err);
    case MIP_FIELD_SENSOR_CF_STABILIZED_NORTH:
        return mip_sensor_cf_stabilized_north_decode(data, len, &out->u.sensor_cf_stabilized_north, err);
    case MIP_FIELD_SENSOR_CF_STABILIZED_UP:
        return mip_sensor_cf_stabilized_up_decode(data, len, &out->u.sensor_cf_stabilized_up, err);
    case MIP_FIELD_SENSOR_GPS_TIMESTAMP:
        return mip_sensor_gps_timestamp_decode(data, len, &out->u.sensor_gps_timestamp, err);
    case MIP_FIELD_SENSOR_TEMPERATURE_STATISTICS:
        return mip_sensor_temperature_statistics_decode(data, len, &out->u.sensor_temperature_statistics,
                                                        err);
    case MIP_FIELD_SENSOR_SCALED_PRESSURE:
        return mip_sensor_scaled_pressure_decode(data, len, &out->u.sensor_scaled_pressure, err);
    case MIP_FIELD_SENSOR_OVERRANGE_STATUS:
        return mip_sensor_overrange_status_decode(data, len, &out->u.sensor_overrange_status, err);
    case MIP_FIELD_SENSOR_ODOMETER_DATA:
        return mip_sensor_odometer_data_decode(data, len, &out->u.sensor_odometer_data, err);
    case MIP_FIELD_GNSS_DATA_LLH_POSITION:
        return mip_gnss_data_llh_position_decode(data, len, &out->u.gnss_data_llh_position, err);
    case MIP_FIELD_GNSS_DATA_ECEF_POSITION:
        return mip_gnss_data_ecef_position_decode(data, len, &out->u.gnss_data_ecef_position, err);
    case MIP_FIELD_GNSS_DATA_NED_VELOCITY:
        return mip_gnss_data_ned_velocity_decode(data, len, &out->u.gnss_data_ned_velocity, err);
    case MIP_FIELD_GNSS_DATA_ECEF_VELOCITY:
        return mip_gnss_data_ecef_velocity_decode(data, len, &out->u.gnss_data_ecef_velocity, err);
    case MIP_FIELD_GNSS_DATA_DOP:
        return mip_gnss_data_dop_decode(data, len, &out->u.gnss_data_dop, err);
    case MIP_FIELD_GNSS_DATA_UTC_TIME:
        return mip_gnss_data_utc_time_decode(data, len, &out->u.gnss_data_utc_time, err);
    case MIP_FIELD_GNSS_DATA_GPS_TIME:
        return mip_gnss_data_gps_time_decode(data, len, &out->u.gnss_data_gps_time, err);
    case MIP_FIELD_GNSS_DATA_CLOCK_INFO:
        return mip_gnss_data_clock_info_decode(data, len, &out->u.gnss_data_clock_info, err);
    case MIP_FIELD_GNSS_DATA_FIX_INFO:
        return mip_gnss_data_fix_info_decode(data, len, &out->u.gnss_data_fix_info, err);
    case MIP_FIELD_GNSS_DATA_SV_INFO:
        return mip_gnss_data_sv_info_decode(data, len, &out->u.gnss_data_sv_info, err);
    case MIP_FIELD_GNSS_DATA_HARDWARE_STATUS:
        return mip_gnss_data_hardware_status_decode(data, len, &out->u.gnss_data_hardware_status, err);
    case MIP_FIELD_GNSS_DATA_DGNSS_INFO:
        return mip_gnss_data_dgnss_info_decode(data, len, &out->u.gnss_data_dgnss_info, err);
    case MIP_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS:
        return mip_gnss_data_dgnss_channel_status_decode(data, len, &out->u.gnss_data_dgnss_channel_status,
                                                         err);
    case MIP_FIELD_FILTER_DATA_LLH_POSITION:
        return mip_filter_data_llh_position_decode(data, len, &out->u.filter_data_llh_position, err);
    case MIP_FIELD_FILTER_DATA_NED_VELOCITY:
        return mip_filter_data_ned_velocity_decode(data, len, &out->u.filter_data_ned_velocity, err);
    case MIP_FIELD_FILTER_DATA_ATTITUDE_QUATERNION:
        return mip_filter_data_attitude_quaternion_decode(data, len, &out->u.filter_data_attitude_quaternion,
                                                          err);
    case MIP_FIELD_FILTER_DATA_ATTITUDE_DCM:
        return mip_filter_data_attitude_dcm_decode(data, len, &out->u.filter_data_attitude_dcm, err);
    case MIP_FIELD_FILTER_DATA_EULER_ANGLES:
        return mip_filter_data_euler_angles_decode(data, len, &out->u.filter_data_euler_angles, err);
    case MIP_FIELD_FILTER_DATA_GYRO_BIAS:
        return mip_filter_data_gyro_bias_decode(data, len, &out->u.filter_data_gyro_bias, err);
    case MIP_FIELD_FILTER_DATA_ACCEL_BIAS:
        return mip_filter_data_accel_bias_decode(data, len, &out->u.filter_data_accel_bias, err);
    case MIP_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY:
        return mip_filter_data_llh_position_uncertainty_decode(
            data, len, &out->u.filter_data_llh_position_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY:
        return mip_filter_data_ned_velocity_uncertainty_decode(
            data, len, &out->u.filter_data_ned_velocity_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY:
        return mip_filter_data_euler_angles_uncertainty_decode(
            data, len, &out->u.filter_data_euler_angles_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY:
        return mip_filter_data_gyro_bias_uncertainty_decode(data, len,
                                                            &out->u.filter_data_gyro_bias_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY:
        return mip_filter_data_accel_bias_uncertainty_decode(data, len,
                                                             &out->u.filter_data_accel_bias_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_LINEAR_ACCEL:
        return mip_filter_data_linear_accel_decode(data, len, &out->u.filter_data_linear_accel, err);
    case MIP_FIELD_FILTER_DATA_COMP_ANGULAR_RATE:
        return mip_filter_data_comp_angular_rate_decode(data, len, &out->u.filter_data_comp_angular_rate,
                                                        err);
    case MIP_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE:
        return mip_filter_data_wgs84_gravity_magnitude_decode(
            data, len, &out->u.filter_data_wgs84_gravity_magnitude, err);
    case MIP_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45:
        return mip_filter_data_filter_status_gx5_45_decode(data, len,
                                                           &out->u.filter_data_filter_status_gx5_45, err);
    case MIP_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS:
        return mip_filter_data_filter_status_cv7_ins_decode(data, len,
                                                            &out->u.filter_data_filter_status_cv7_ins, err);
    case MIP_FIELD_FILTER_DATA_GPS_TIMESTAMP:
        return mip_filter_data_gps_timestamp_decode(data, len, &out->u.filter_data_gps_timestamp, err);
    case MIP_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY:
        return mip_filter_data_quaternion_attitude_uncertainty_decode(
            data, len, &out->u.filter_data_quaternion_attitude_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_GRAVITY_VECTOR:
        return mip_filter_data_gravity_vector_decode(data, len, &out->u.filter_data_gravity_vector, err);
    case MIP_FIELD_FILTER_DATA_HEADING_UPDATE_STATE:
        return mip_filter_data_heading_update_state_decode(data, len,
                                                           &out->u.filter_data_heading_update_state, err);
    case MIP_FIELD_FILTER_DATA_MAGNETIC_MODEL:
        return mip_filter_data_magnetic_model_decode(data, len, &out->u.filter_data_magnetic_model, err);
    case MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR:
        return mip_filter_data_gyro_scale_factor_decode(data, len, &out->u.filter_data_gyro_scale_factor,
                                                        err);
    case MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR:
        return mip_filter_data_accel_scale_factor_decode(data, len, &out->u.filter_data_accel_scale_factor,
                                                         err);
    case MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY:
        return mip_filter_data_gyro_scale_factor_uncertainty_decode(
            data, len, &out->u.filter_data_gyro_scale_factor_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY:
        return mip_filter_data_accel_scale_factor_uncertainty_decode(
            data, len, &out->u.filter_data_accel_scale_factor_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_COMPENSATED_ACCEL:
        return mip_filter_data_compensated_accel_decode(data, len, &out->u.filter_data_compensated_accel,
                                                        err);
    case MIP_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE:
        return mip_filter_data_standard_atmosphere_decode(data, len, &out->u.filter_data_standard_atmosphere,
                                                          err);
    case MIP_FIELD_FILTER_DATA_PRESSURE_ALTITUDE:
        return mip_filter_data_pressure_altitude_decode(data, len, &out->u.filter_data_pressure_altitude,
                                                        err);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET:
        return mip_filter_data_mag_auto_hard_iron_offset_decode(
            data, len, &out->u.filter_data_mag_auto_hard_iron_offset, err);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX:
        return mip_filter_data_mag_auto_soft_iron_matrix_decode(
            data, len, &out->u.filter_data_mag_auto_soft_iron_matrix, err);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY:
        return mip_filter_data_mag_auto_hard_iron_offset_uncertainty_decode(
            data, len, &out->u.filter_data_mag_auto_hard_iron_offset_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY:
        return mip_filter_data_mag_auto_soft_iron_matrix_uncertainty_decode(
            data, len, &out->u.filter_data_mag_auto_soft_iron_matrix_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION:
        return mip_filter_data_gnss_antenna_offset_correction_decode(
            data, len, &out->u.filter_data_gnss_antenna_offset_correction, err);
    case MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mip_filter_data_gnss_antenna_offset_correction_uncertainty_decode(
            data, len, &out->u.filter_data_gnss_antenna_offset_correction_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION:
        return mip_filter_data_multi_antenna_offset_correction_decode(
            data, len, &out->u.filter_data_multi_antenna_offset_correction, err);
    case MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mip_filter_data_multi_antenna_offset_correction_uncertainty_decode(
            data, len, &out->u.filter_data_multi_antenna_offset_correction_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY:
        return mip_filter_data_ecef_position_uncertainty_decode(
            data, len, &out->u.filter_data_ecef_position_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY:
        return mip_filter_data_ecef_velocity_uncertainty_decode(
            data, len, &out->u.filter_data_ecef_velocity_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_ECEF_POSITION:
        return mip_filter_data_ecef_position_decode(data, len, &out->u.filter_data_ecef_position, err);
    case MIP_FIELD_FILTER_DATA_ECEF_VELOCITY:
        return mip_filter_data_ecef_velocity_decode(data, len, &out->u.filter_data_ecef_velocity, err);
    case MIP_FIELD_FILTER_DATA_NED_RELATIVE_POSITION:
        return mip_filter_data_ned_relative_position_decode(data, len,
                                                            &out->u.filter_data_ned_relative_position, err);
    case MIP_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS:
        return mip_filter_data_gnss_position_aiding_status_decode(
            data, len, &out->u.filter_data_gnss_position_aiding_status, err);
    case MIP_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY:
        return mip_filter_data_aiding_measurement_summary_decode(
            data, len, &out->u.filter_data_aiding_measurement_summary, err);
    case MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR:
        return mip_filter_data_odometer_scale_factor_error_decode(
            data, len, &out->u.filter_data_odometer_scale_factor_error, err);
    case MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY:
        return mip_filter_data_odometer_scale_factor_error_uncertainty_decode(
            data, len, &out->u.filter_data_odometer_scale_factor_error_uncertainty, err);
    case MIP_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS:
        return mip_filter_data_gnss_dual_antenna_status_decode(
            data, len, &out->u.filter_data_gnss_dual_antenna_status, err);
    case MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR:
        return mip_filter_data_aiding_frame_config_error_decode(
            data, len, &out->u.filter_data_aiding_frame_config_error, err);
    case MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY:
        return mip_filter_data_aiding_frame_config_error_uncertainty_decode(
            data, len, &out->u.filter_data_aiding_frame_config_error_uncertainty, err);
    case MIP_FIELD_GNSS_RECEIVER_1_LLH_POSITION:
        return mip_gnss_receiver_1_llh_position_decode(data, len, &out->u.gnss_receiver_1_llh_position, err);
    case MIP_FIELD_GNSS_RECEIVER_1_ECEF_POSITION:
        return mip_gnss_receiver_1_ecef_position_decode(data, len, &out->u.gnss_receiver_1_ecef_position,
                                                        err);
    case MIP_FIELD_GNSS_RECEIVER_1_NED_VELOCITY:
        return mip_gnss_receiver_1_ned_velocity_decode(data, len, &out->u.gnss_receiver_1_ned_velocity, err);
    case MIP_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY:
        return mip_gnss_receiver_1_ecef_velocity_decode(data, len, &out->u.gnss_receiver_1_ecef_velocity,
                                                        err);
    case MIP_FIELD_GNSS_RECEIVER_1_DOP:
        return mip_gnss_receiver_1_dop_decode(data, len, &out->u.gnss_receiver_1_dop, err);
    case MIP_FIELD_GNSS_RECEIVER_1_UTC_TIME:
        return mip_gnss_receiver_1_utc_time_decode(data, len, &out->u.gnss_receiver_1_utc_time, err);
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_TIME:
        return mip_gnss_receiver_1_gps_time_decode(data, len, &out->u.gnss_receiver_1_gps_time, err);
    case MIP_FIELD_GNSS_RECEIVER_1_FIX_INFO:
        return mip_gnss_receiver_1_fix_info_decode(data, len, &out->u.gnss_receiver_1_fix_info, err);
    case MIP_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS:
        return mip_gnss_receiver_1_hardware_status_decode(data, len, &out->u.gnss_receiver_1_hardware_status,
                                                          err);
    case MIP_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2:
        return mip_gnss_receiver_1_clock_info_2_decode(data, len, &out->u.gnss_receiver_1_clock_info_2, err);
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS:
        return mip_gnss_receiver_1_gps_leap_seconds_decode(data, len,
                                                           &out->u.gnss_receiver_1_gps_leap_seconds, err);
    case MIP_FIELD_GNSS_RECEIVER_1_SBAS_INFO:
        return mip_gnss_receiver_1_sbas_info_decode(data, len, &out->u.gnss_receiver_1_sbas_info, err);
    case MIP_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS:
        return mip_gnss_receiver_1_satellite_status_decode(data, len,
                                                           &out->u.gnss_receiver_1_satellite_status, err);
    case MIP_FIELD_GNSS_RECEIVER_1_RAW:
        return mip_gnss_receiver_1_raw_decode(data, len, &out->u.gnss_receiver_1_raw, err);
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS:
        return mip_gnss_receiver_1_gps_ephemeris_decode(data, len, &out->u.gnss_receiver_1_gps_ephemeris,
                                                        err);
    case MIP_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS:
        return mip_gnss_receiver_1_glonass_ephemeris_decode(data, len,
                                                            &out->u.gnss_receiver_1_glonass_ephemeris, err);
    case MIP_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS:
        return mip_gnss_receiver_1_galileo_ephemeris_decode(data, len,
                                                            &out->u.gnss_receiver_1_galileo_ephemeris, err);
    case MIP_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS:
        return mip_gnss_receiver_1_beidou_ephemeris_decode(data, len,
                                                           &out->u.gnss_receiver_1_beidou_ephemeris, err);
    case MIP_FIELD_GNSS_RECEIVER_2_LLH_POSITION:
        return mip_gnss_receiver_2_llh_position_decode(data, len, &out->u.gnss_receiver_2_llh_position, err);
    case MIP_FIELD_GNSS_RECEIVER_2_ECEF_POSITION:
        return mip_gnss_receiver_2_ecef_position_decode(data, len, &out->u.gnss_receiver_2_ecef_position,
                                                        err);
    case MIP_FIELD_GNSS_RECEIVER_2_NED_VELOCITY:
        return mip_gnss_receiver_2_ned_velocity_decode(data, len, &out->u.gnss_receiver_2_ned_velocity, err);
    case MIP_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY:
        return mip_gnss_receiver_2_ecef_velocity_decode(data, len, &out->u.gnss_receiver_2_ecef_velocity,
                                                        err);
    case MIP_FIELD_GNSS_RECEIVER_2_DOP:
        return mip_gnss_receiver_2_dop_decode(data, len, &out->u.gnss_receiver_2_dop, err);
    case MIP_FIELD_GNSS_RECEIVER_2_UTC_TIME:
        return mip_gnss_receiver_2_utc_time_decode(data, len, &out->u.gnss_receiver_2_utc_time, err);
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_TIME:
        return mip_gnss_receiver_2_gps_time_decode(data, len, &out->u.gnss_receiver_2_gps_time, err);
    case MIP_FIELD_GNSS_RECEIVER_2_FIX_INFO:
        return mip_gnss_receiver_2_fix_info_decode(data, len, &out->u.gnss_receiver_2_fix_info, err);
    case MIP_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS:
        return mip_gnss_receiver_2_hardware_status_decode(data, len, &out->u.gnss_receiver_2_hardware_status,
                                                          err);
    case MIP_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2:
        return mip_gnss_receiver_2_clock_info_2_decode(data, len, &out->u.gnss_receiver_2_clock_info_2, err);
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS:
        return mip_gnss_receiver_2_gps_leap_seconds_decode(data, len,
                                                           &out->u.gnss_receiver_2_gps_leap_seconds, err);
    case MIP_FIELD_GNSS_RECEIVER_2_SBAS_INFO:
        return mip_gnss_receiver_2_sbas_info_decode(data, len, &out->u.gnss_receiver_2_sbas_info, err);
    case MIP_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS:
        return mip_gnss_receiver_2_satellite_status_decode(data, len,
                                                           &out->u.gnss_receiver_2_satellite_status, err);
    case MIP_FIELD_GNSS_RECEIVER_2_RAW:
        return mip_gnss_receiver_2_raw_decode(data, len, &out->u.gnss_receiver_2_raw, err);
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS:
        return mip_gnss_receiver_2_gps_ephemeris_decode(data, len, &out->u.gnss_receiver_2_gps_ephemeris,
                                                        err);
    case MIP_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS:
        return mip_gnss_receiver_2_glonass_ephemeris_decode(data, len,
                                                            &out->u.gnss_receiver_2_glonass_ephemeris, err);
    case MIP_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS:
        return mip_gnss_receiver_2_galileo_ephemeris_decode(data, len,
                                                            &out->u.gnss_receiver_2_galileo_ephemeris, err);
    case MIP_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS:
        return mip_gnss_receiver_2_beidou_ephemeris_decode(data, len,
                                                           &out->u.gnss_receiver_2_beidou_ephemeris, err);
    case MIP_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO:
        return mip_gnss_corrections_base_station_info_decode(data, len,
                                                             &out->u.gnss_corrections_base_station_info, err);
    case MIP_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS:
        return mip_gnss_corrections_rtk_corrections_status_decode(
            data, len, &out->u.gnss_corrections_rtk_corrections_status, err);
    case MIP_FIELD_GNSS_EXTERNAL_LLH_POSITION:
        return mip_gnss_external_llh_position_decode(data, len, &out->u.gnss_external_llh_position, err);
    case MIP_FIELD_GNSS_EXTERNAL_NED_VELOCITY:
        return mip_gnss_external_ned_velocity_decode(data, len, &out->u.gnss_external_ned_velocity, err);
    case MIP_FIELD_GNSS_EXTERNAL_UTC_TIME:
        return mip_gnss_external_utc_time_decode(data, len, &out->u.gnss_external_utc_time, err);
    case MIP_FIELD_GNSS_EXTERNAL_FIX_INFO:
        return mip_gnss_external_fix_info_decode(data, len, &out->u.gnss_external_fix_info, err);
    case MIP_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS:
        return mip_gnss_external_satellite_status_decode(data, len, &out->u.gnss_external_satellite_status,
                                                         err);
    case MIP_FIELD_SYSTEM_DATA_BUILT_IN_TEST:
        return mip_system_data_built_in_test_decode(data, len, &out->u.system_data_built_in_test, err);
    case MIP_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS:
        return mip_system_data_time_sync_status_decode(data, len, &out->u.system_data_time_sync_status, err);
    case MIP_FIELD_SYSTEM_DATA_GPIO_STATE:
        return mip_system_data_gpio_state_decode(data, len, &out->u.system_data_gpio_state, err);
    case MIP_FIELD_SHARED_EVENT_SOURCE:
        return mip_shared_event_source_decode(data, len, &out->u.shared_event_source, err);
    case MIP_FIELD_SHARED_GPS_TIMESTAMP:
        return mip_shared_gps_timestamp_decode(data, len, &out->u.shared_gps_timestamp, err);
    case MIP_FIELD_SHARED_DELTA_TIME:
        return mip_shared_delta_time_decode(data, len, &out->u.shared_delta_time, err);
    case MIP_FIELD_SHARED_REFERENCE_TIMESTAMP:
        return mip_shared_reference_timestamp_decode(data, len, &out->u.shared_reference_timestamp, err);
    case MIP_FIELD_SHARED_REFERENCE_TIME_DELTA:
        return mip_shared_reference_time_delta_decode(data, len, &out->u.shared_reference_time_delta, err);
    case MIP_FIELD_SHARED_EXTERNAL_TIMESTAMP:
        return mip_shared_external_timestamp_decode(data, len, &out->u.shared_external_timestamp, err);
    case MIP_FIELD_SHARED_EXTERNAL_TIME_DELTA:
        return mip_shared_external_time_delta_decode(data, len, &out->u.shared_external_time_delta, err);
    case MIP_FIELD_NONE:
    case MIP_FIELD_COUNT:
    default:
        return MIP_ERR_INVALID;
    }
}

/* Every case of mip_decode_field: several layouts per field, a device to choose among them, error
 * details. Out of line (MIP_NOINLINE) so that the common case below stays a short function. */
static MIP_NOINLINE mip_status_t decode_field_general(uint8_t set, uint8_t descriptor, const uint8_t *data,
                                                      size_t len, mip_device_t device, mip_field_value_t *out,
                                                      mip_decode_error_t *err) {
    mip_status_t why = MIP_ERR_UNKNOWN_SET;
    const mip_field_info_t *f = find_field(set, descriptor, &why);
    size_t first;
    size_t count;
    size_t i;
    out->id = MIP_FIELD_NONE;
    if (!f) {
        return why;
    }
    first = (size_t)f->first_layout;
    count = f->layout_count;
    if (device != MIP_DEVICE_ANY) {
        for (i = 0; i < count; i++) {
            if (k_layouts[first + i].device_id == device) {
                first += i;
                count = 1;
                break;
            }
        }
    }
    /* No error details on the way (the common case is a field that decodes); when no layout
     * decodes, the first one runs again to report its error. */
    for (i = 0; i < count; i++) {
        if (decode_layout((mip_field_id_t)(first + i), data, len, out, NULL) == MIP_OK) {
            return MIP_OK;
        }
    }
    if (err) {
        memset(err, 0, sizeof *err);
        (void)decode_layout((mip_field_id_t)first, data, len, out, err);
    }
    out->id = MIP_FIELD_NONE;
    return MIP_ERR_DECODE;
}

/* The common case first: a field its set defines, with one layout (the device does not choose
 * among one). Its decoder fills *err itself when it fails (as decode_field_general's second run
 * does). Anything else goes to decode_field_general, which starts over. */
mip_status_t mip_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                              mip_device_t device, mip_field_value_t *out, mip_decode_error_t *err) {
    const uint16_t *table = k_sets[set];
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (table && table[descriptor] != 0) {
        const mip_field_info_t *f = &k_fields[table[descriptor] - 1];
        if (f->layout_count == 1) {
            if (decode_layout(f->first_layout, data, len, out, err) == MIP_OK) {
                return MIP_OK;
            }
            out->id = MIP_FIELD_NONE;
            return MIP_ERR_DECODE;
        }
    }
    return decode_field_general(set, descriptor, data, len, device, out, err);
}

mip_status_t mip_encode_field(const mip_field_value_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    switch (value->id) {
    case MIP_FIELD_ACK_NACK:
        return mip_ack_nack_encode(&value->u.ack_nack, buf, cap, len_out);
    case MIP_FIELD_BASE_PING:
        return mip_base_ping_encode(&value->u.base_ping, buf, cap, len_out);
    case MIP_FIELD_BASE_SET_TO_IDLE:
        return mip_base_set_to_idle_encode(&value->u.base_set_to_idle, buf, cap, len_out);
    case MIP_FIELD_BASE_GET_DEVICE_INFO:
        return mip_base_get_device_info_encode(&value->u.base_get_device_info, buf, cap, len_out);
    case MIP_FIELD_BASE_DEVICE_INFO:
        return mip_base_device_info_encode(&value->u.base_device_info, buf, cap, len_out);
    case MIP_FIELD_BASE_GET_DEVICE_DESCRIPTORS:
        return mip_base_get_device_descriptors_encode(&value->u.base_get_device_descriptors, buf, cap,
                                                      len_out);
    case MIP_FIELD_BASE_DEVICE_DESCRIPTORS:
        return mip_base_device_descriptors_encode(&value->u.base_device_descriptors, buf, cap, len_out);
    case MIP_FIELD_BASE_BUILT_IN_TEST:
        return mip_base_built_in_test_encode(&value->u.base_built_in_test, buf, cap, len_out);
    case MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45:
        return mip_base_built_in_test_result_gx5_45_encode(&value->u.base_built_in_test_result_gx5_45, buf,
                                                           cap, len_out);
    case MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS:
        return mip_base_built_in_test_result_cv7_ins_encode(&value->u.base_built_in_test_result_cv7_ins, buf,
                                                            cap, len_out);
    case MIP_FIELD_BASE_RESUME:
        return mip_base_resume_encode(&value->u.base_resume, buf, cap, len_out);
    case MIP_FIELD_BASE_GET_EXTENDED_DESCRIPTORS:
        return mip_base_get_extended_descriptors_encode(&value->u.base_get_extended_descriptors, buf, cap,
                                                        len_out);
    case MIP_FIELD_BASE_EXTENDED_DESCRIPTORS:
        return mip_base_extended_descriptors_encode(&value->u.base_extended_descriptors, buf, cap, len_out);
    case MIP_FIELD_BASE_CONTINUOUS_BIT:
        return mip_base_continuous_bit_encode(&value->u.base_continuous_bit, buf, cap, len_out);
    case MIP_FIELD_BASE_CONTINUOUS_BIT_RESULT:
        return mip_base_continuous_bit_result_encode(&value->u.base_continuous_bit_result, buf, cap, len_out);
    case MIP_FIELD_BASE_COMM_PORT_SPEED:
        return mip_base_comm_port_speed_encode(&value->u.base_comm_port_speed, buf, cap, len_out);
    case MIP_FIELD_BASE_COMM_PORT_SPEED_RESPONSE:
        return mip_base_comm_port_speed_response_encode(&value->u.base_comm_port_speed_response, buf, cap,
                                                        len_out);
    case MIP_FIELD_BASE_GPS_TIME_UPDATE_GX5_45:
        return mip_base_gps_time_update_gx5_45_encode(&value->u.base_gps_time_update_gx5_45, buf, cap,
                                                      len_out);
    case MIP_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS:
        return mip_base_gps_time_update_cv7_ins_encode(&value->u.base_gps_time_update_cv7_ins, buf, cap,
                                                       len_out);
    case MIP_FIELD_BASE_GPS_WEEK:
        return mip_base_gps_week_encode(&value->u.base_gps_week, buf, cap, len_out);
    case MIP_FIELD_BASE_GPS_SECONDS:
        return mip_base_gps_seconds_encode(&value->u.base_gps_seconds, buf, cap, len_out);
    case MIP_FIELD_BASE_DEVICE_RESET:
        return mip_base_device_reset_encode(&value->u.base_device_reset, buf, cap, len_out);
    case MIP_FIELD_THREEDM_EVENT_CONTROL:
        return mip_threedm_event_control_encode(&value->u.threedm_event_control, buf, cap, len_out);
    case MIP_FIELD_THREEDM_EVENT_CONTROL_RESPONSE:
        return mip_threedm_event_control_response_encode(&value->u.threedm_event_control_response, buf, cap,
                                                         len_out);
    case MIP_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS:
        return mip_threedm_get_event_trigger_status_encode(&value->u.threedm_get_event_trigger_status, buf,
                                                           cap, len_out);
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_STATUS:
        return mip_threedm_event_trigger_status_encode(&value->u.threedm_event_trigger_status, buf, cap,
                                                       len_out);
    case MIP_FIELD_THREEDM_GET_EVENT_ACTION_STATUS:
        return mip_threedm_get_event_action_status_encode(&value->u.threedm_get_event_action_status, buf, cap,
                                                          len_out);
    case MIP_FIELD_THREEDM_EVENT_ACTION_STATUS:
        return mip_threedm_event_action_status_encode(&value->u.threedm_event_action_status, buf, cap,
                                                      len_out);
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG:
        return mip_threedm_event_trigger_config_encode(&value->u.threedm_event_trigger_config, buf, cap,
                                                       len_out);
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE:
        return mip_threedm_event_trigger_config_response_encode(
            &value->u.threedm_event_trigger_config_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG:
        return mip_threedm_event_action_config_encode(&value->u.threedm_event_action_config, buf, cap,
                                                      len_out);
    case MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE:
        return mip_threedm_event_action_config_response_encode(&value->u.threedm_event_action_config_response,
                                                               buf, cap, len_out);
    case MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45:
        return mip_threedm_device_startup_settings_gx5_45_encode(
            &value->u.threedm_device_startup_settings_gx5_45, buf, cap, len_out);
    case MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS:
        return mip_threedm_device_startup_settings_cv7_ins_encode(
            &value->u.threedm_device_startup_settings_cv7_ins, buf, cap, len_out);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER:
        return mip_threedm_sensor_to_vehicle_euler_encode(&value->u.threedm_sensor_to_vehicle_euler, buf, cap,
                                                          len_out);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE:
        return mip_threedm_sensor_to_vehicle_euler_response_encode(
            &value->u.threedm_sensor_to_vehicle_euler_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION:
        return mip_threedm_sensor_to_vehicle_quaternion_encode(&value->u.threedm_sensor_to_vehicle_quaternion,
                                                               buf, cap, len_out);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE:
        return mip_threedm_sensor_to_vehicle_quaternion_response_encode(
            &value->u.threedm_sensor_to_vehicle_quaternion_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM:
        return mip_threedm_sensor_to_vehicle_dcm_encode(&value->u.threedm_sensor_to_vehicle_dcm, buf, cap,
                                                        len_out);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE:
        return mip_threedm_sensor_to_vehicle_dcm_response_encode(
            &value->u.threedm_sensor_to_vehicle_dcm_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_ACCEL_BIAS_GX5_45:
        return mip_threedm_accel_bias_gx5_45_encode(&value->u.threedm_accel_bias_gx5_45, buf, cap, len_out);
    case MIP_FIELD_THREEDM_ACCEL_BIAS_CV7_INS:
        return mip_threedm_accel_bias_cv7_ins_encode(&value->u.threedm_accel_bias_cv7_ins, buf, cap, len_out);
    case MIP_FIELD_THREEDM_ACCEL_BIAS_RESPONSE:
        return mip_threedm_accel_bias_response_encode(&value->u.threedm_accel_bias_response, buf, cap,
                                                      len_out);
    case MIP_FIELD_THREEDM_GYRO_BIAS_GX5_45:
        return mip_threedm_gyro_bias_gx5_45_encode(&value->u.threedm_gyro_bias_gx5_45, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GYRO_BIAS_CV7_INS:
        return mip_threedm_gyro_bias_cv7_ins_encode(&value->u.threedm_gyro_bias_cv7_ins, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GYRO_BIAS_RESPONSE:
        return mip_threedm_gyro_bias_response_encode(&value->u.threedm_gyro_bias_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_CAPTURE_GYRO_BIAS:
        return mip_threedm_capture_gyro_bias_encode(&value->u.threedm_capture_gyro_bias, buf, cap, len_out);
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45:
        return mip_threedm_mag_hard_iron_offset_gx5_45_encode(&value->u.threedm_mag_hard_iron_offset_gx5_45,
                                                              buf, cap, len_out);
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS:
        return mip_threedm_mag_hard_iron_offset_cv7_ins_encode(&value->u.threedm_mag_hard_iron_offset_cv7_ins,
                                                               buf, cap, len_out);
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE:
        return mip_threedm_mag_hard_iron_offset_response_encode(
            &value->u.threedm_mag_hard_iron_offset_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45:
        return mip_threedm_mag_soft_iron_matrix_gx5_45_encode(&value->u.threedm_mag_soft_iron_matrix_gx5_45,
                                                              buf, cap, len_out);
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS:
        return mip_threedm_mag_soft_iron_matrix_cv7_ins_encode(&value->u.threedm_mag_soft_iron_matrix_cv7_ins,
                                                               buf, cap, len_out);
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE:
        return mip_threedm_mag_soft_iron_matrix_response_encode(
            &value->u.threedm_mag_soft_iron_matrix_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE:
        return mip_threedm_coning_sculling_enable_encode(&value->u.threedm_coning_sculling_enable, buf, cap,
                                                         len_out);
    case MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE:
        return mip_threedm_coning_sculling_enable_response_encode(
            &value->u.threedm_coning_sculling_enable_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_UART_BAUDRATE:
        return mip_threedm_uart_baudrate_encode(&value->u.threedm_uart_baudrate, buf, cap, len_out);
    case MIP_FIELD_THREEDM_UART_BAUDRATE_RESPONSE:
        return mip_threedm_uart_baudrate_response_encode(&value->u.threedm_uart_baudrate_response, buf, cap,
                                                         len_out);
    case MIP_FIELD_THREEDM_GPIO_CONFIG:
        return mip_threedm_gpio_config_encode(&value->u.threedm_gpio_config, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GPIO_CONFIG_RESPONSE:
        return mip_threedm_gpio_config_response_encode(&value->u.threedm_gpio_config_response, buf, cap,
                                                       len_out);
    case MIP_FIELD_THREEDM_GPIO_STATE:
        return mip_threedm_gpio_state_encode(&value->u.threedm_gpio_state, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GPIO_STATE_RESPONSE:
        return mip_threedm_gpio_state_response_encode(&value->u.threedm_gpio_state_response, buf, cap,
                                                      len_out);
    case MIP_FIELD_THREEDM_ODOMETER_CONFIG:
        return mip_threedm_odometer_config_encode(&value->u.threedm_odometer_config, buf, cap, len_out);
    case MIP_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE:
        return mip_threedm_odometer_config_response_encode(&value->u.threedm_odometer_config_response, buf,
                                                           cap, len_out);
    case MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER:
        return mip_threedm_advanced_lowpass_filter_encode(&value->u.threedm_advanced_lowpass_filter, buf, cap,
                                                          len_out);
    case MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE:
        return mip_threedm_advanced_lowpass_filter_response_encode(
            &value->u.threedm_advanced_lowpass_filter_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER:
        return mip_threedm_complementary_filter_encode(&value->u.threedm_complementary_filter, buf, cap,
                                                       len_out);
    case MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE:
        return mip_threedm_complementary_filter_response_encode(
            &value->u.threedm_complementary_filter_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_SENSOR_RANGE:
        return mip_threedm_sensor_range_encode(&value->u.threedm_sensor_range, buf, cap, len_out);
    case MIP_FIELD_THREEDM_SENSOR_RANGE_RESPONSE:
        return mip_threedm_sensor_range_response_encode(&value->u.threedm_sensor_range_response, buf, cap,
                                                        len_out);
    case MIP_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES:
        return mip_threedm_get_calibrated_sensor_ranges_encode(&value->u.threedm_get_calibrated_sensor_ranges,
                                                               buf, cap, len_out);
    case MIP_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES:
        return mip_threedm_calibrated_sensor_ranges_encode(&value->u.threedm_calibrated_sensor_ranges, buf,
                                                           cap, len_out);
    case MIP_FIELD_THREEDM_LOWPASS_FILTER:
        return mip_threedm_lowpass_filter_encode(&value->u.threedm_lowpass_filter, buf, cap, len_out);
    case MIP_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE:
        return mip_threedm_lowpass_filter_response_encode(&value->u.threedm_lowpass_filter_response, buf, cap,
                                                          len_out);
    case MIP_FIELD_THREEDM_POLL_IMU_DATA:
        return mip_threedm_poll_imu_data_encode(&value->u.threedm_poll_imu_data, buf, cap, len_out);
    case MIP_FIELD_THREEDM_POLL_GNSS_DATA:
        return mip_threedm_poll_gnss_data_encode(&value->u.threedm_poll_gnss_data, buf, cap, len_out);
    case MIP_FIELD_THREEDM_POLL_FILTER_DATA:
        return mip_threedm_poll_filter_data_encode(&value->u.threedm_poll_filter_data, buf, cap, len_out);
    case MIP_FIELD_THREEDM_POLL_NMEA_DATA:
        return mip_threedm_poll_nmea_data_encode(&value->u.threedm_poll_nmea_data, buf, cap, len_out);
    case MIP_FIELD_THREEDM_POLL_DATA:
        return mip_threedm_poll_data_encode(&value->u.threedm_poll_data, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GET_IMU_BASE_RATE:
        return mip_threedm_get_imu_base_rate_encode(&value->u.threedm_get_imu_base_rate, buf, cap, len_out);
    case MIP_FIELD_THREEDM_IMU_BASE_RATE:
        return mip_threedm_imu_base_rate_encode(&value->u.threedm_imu_base_rate, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GET_GNSS_BASE_RATE:
        return mip_threedm_get_gnss_base_rate_encode(&value->u.threedm_get_gnss_base_rate, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GNSS_BASE_RATE:
        return mip_threedm_gnss_base_rate_encode(&value->u.threedm_gnss_base_rate, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GET_FILTER_BASE_RATE:
        return mip_threedm_get_filter_base_rate_encode(&value->u.threedm_get_filter_base_rate, buf, cap,
                                                       len_out);
    case MIP_FIELD_THREEDM_FILTER_BASE_RATE:
        return mip_threedm_filter_base_rate_encode(&value->u.threedm_filter_base_rate, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GET_BASE_RATE:
        return mip_threedm_get_base_rate_encode(&value->u.threedm_get_base_rate, buf, cap, len_out);
    case MIP_FIELD_THREEDM_BASE_RATE:
        return mip_threedm_base_rate_encode(&value->u.threedm_base_rate, buf, cap, len_out);
    case MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT:
        return mip_threedm_imu_message_format_encode(&value->u.threedm_imu_message_format, buf, cap, len_out);
    case MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_imu_message_format_response_encode(&value->u.threedm_imu_message_format_response,
                                                              buf, cap, len_out);
    case MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT:
        return mip_threedm_gnss_message_format_encode(&value->u.threedm_gnss_message_format, buf, cap,
                                                      len_out);
    case MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_gnss_message_format_response_encode(&value->u.threedm_gnss_message_format_response,
                                                               buf, cap, len_out);
    case MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT:
        return mip_threedm_filter_message_format_encode(&value->u.threedm_filter_message_format, buf, cap,
                                                        len_out);
    case MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_filter_message_format_response_encode(
            &value->u.threedm_filter_message_format_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT:
        return mip_threedm_nmea_message_format_encode(&value->u.threedm_nmea_message_format, buf, cap,
                                                      len_out);
    case MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_nmea_message_format_response_encode(&value->u.threedm_nmea_message_format_response,
                                                               buf, cap, len_out);
    case MIP_FIELD_THREEDM_MESSAGE_FORMAT:
        return mip_threedm_message_format_encode(&value->u.threedm_message_format, buf, cap, len_out);
    case MIP_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_message_format_response_encode(&value->u.threedm_message_format_response, buf, cap,
                                                          len_out);
    case MIP_FIELD_THREEDM_FACTORY_STREAMING:
        return mip_threedm_factory_streaming_encode(&value->u.threedm_factory_streaming, buf, cap, len_out);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45:
        return mip_threedm_data_stream_control_gx5_45_encode(&value->u.threedm_data_stream_control_gx5_45,
                                                             buf, cap, len_out);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS:
        return mip_threedm_data_stream_control_cv7_ins_encode(&value->u.threedm_data_stream_control_cv7_ins,
                                                              buf, cap, len_out);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45:
        return mip_threedm_data_stream_control_response_gx5_45_encode(
            &value->u.threedm_data_stream_control_response_gx5_45, buf, cap, len_out);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS:
        return mip_threedm_data_stream_control_response_cv7_ins_encode(
            &value->u.threedm_data_stream_control_response_cv7_ins, buf, cap, len_out);
    case MIP_FIELD_THREEDM_RAW_RTCM_MESSAGE:
        return mip_threedm_raw_rtcm_message_encode(&value->u.threedm_raw_rtcm_message, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS:
        return mip_threedm_gnss_constellation_settings_encode(&value->u.threedm_gnss_constellation_settings,
                                                              buf, cap, len_out);
    case MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE:
        return mip_threedm_gnss_constellation_settings_response_encode(
            &value->u.threedm_gnss_constellation_settings_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS:
        return mip_threedm_gnss_sbas_settings_encode(&value->u.threedm_gnss_sbas_settings, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE:
        return mip_threedm_gnss_sbas_settings_response_encode(&value->u.threedm_gnss_sbas_settings_response,
                                                              buf, cap, len_out);
    case MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL:
        return mip_threedm_gnss_assisted_fix_control_encode(&value->u.threedm_gnss_assisted_fix_control, buf,
                                                            cap, len_out);
    case MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE:
        return mip_threedm_gnss_assisted_fix_control_response_encode(
            &value->u.threedm_gnss_assisted_fix_control_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE:
        return mip_threedm_gnss_assist_time_update_encode(&value->u.threedm_gnss_assist_time_update, buf, cap,
                                                          len_out);
    case MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE:
        return mip_threedm_gnss_assist_time_update_response_encode(
            &value->u.threedm_gnss_assist_time_update_response, buf, cap, len_out);
    case MIP_FIELD_THREEDM_PPS_SOURCE:
        return mip_threedm_pps_source_encode(&value->u.threedm_pps_source, buf, cap, len_out);
    case MIP_FIELD_THREEDM_PPS_SOURCE_RESPONSE:
        return mip_threedm_pps_source_response_encode(&value->u.threedm_pps_source_response, buf, cap,
                                                      len_out);
    case MIP_FIELD_THREEDM_GET_SUPPORTED_EVENTS:
        return mip_threedm_get_supported_events_encode(&value->u.threedm_get_supported_events, buf, cap,
                                                       len_out);
    case MIP_FIELD_THREEDM_SUPPORTED_EVENTS:
        return mip_threedm_supported_events_encode(&value->u.threedm_supported_events, buf, cap, len_out);
    case MIP_FIELD_THREEDM_DEVICE_STATUS:
        return mip_threedm_device_status_encode(&value->u.threedm_device_status, buf, cap, len_out);
    case MIP_FIELD_THREEDM_DEVICE_STATUS_RESPONSE:
        return mip_threedm_device_status_response_encode(&value->u.threedm_device_status_response, buf, cap,
                                                         len_out);
    case MIP_FIELD_FILTER_RESET_FILTER:
        return mip_filter_reset_filter_encode(&value->u.filter_reset_filter, buf, cap, len_out);
    case MIP_FIELD_FILTER_SET_INITIAL_ATTITUDE:
        return mip_filter_set_initial_attitude_encode(&value->u.filter_set_initial_attitude, buf, cap,
                                                      len_out);
    case MIP_FIELD_FILTER_SET_INITIAL_HEADING:
        return mip_filter_set_initial_heading_encode(&value->u.filter_set_initial_heading, buf, cap, len_out);
    case MIP_FIELD_FILTER_RUN_FILTER:
        return mip_filter_run_filter_encode(&value->u.filter_run_filter, buf, cap, len_out);
    case MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE:
        return mip_filter_vehicle_dynamics_mode_encode(&value->u.filter_vehicle_dynamics_mode, buf, cap,
                                                       len_out);
    case MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE:
        return mip_filter_vehicle_dynamics_mode_response_encode(
            &value->u.filter_vehicle_dynamics_mode_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM:
        return mip_filter_sensor_to_vehicle_transform_encode(&value->u.filter_sensor_to_vehicle_transform,
                                                             buf, cap, len_out);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE:
        return mip_filter_sensor_to_vehicle_transform_response_encode(
            &value->u.filter_sensor_to_vehicle_transform_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET:
        return mip_filter_sensor_to_vehicle_offset_encode(&value->u.filter_sensor_to_vehicle_offset, buf, cap,
                                                          len_out);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE:
        return mip_filter_sensor_to_vehicle_offset_response_encode(
            &value->u.filter_sensor_to_vehicle_offset_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_ANTENNA_OFFSET:
        return mip_filter_antenna_offset_encode(&value->u.filter_antenna_offset, buf, cap, len_out);
    case MIP_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE:
        return mip_filter_antenna_offset_response_encode(&value->u.filter_antenna_offset_response, buf, cap,
                                                         len_out);
    case MIP_FIELD_FILTER_ESTIMATION_CONTROL:
        return mip_filter_estimation_control_encode(&value->u.filter_estimation_control, buf, cap, len_out);
    case MIP_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE:
        return mip_filter_estimation_control_response_encode(&value->u.filter_estimation_control_response,
                                                             buf, cap, len_out);
    case MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL:
        return mip_filter_gnss_source_control_encode(&value->u.filter_gnss_source_control, buf, cap, len_out);
    case MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE:
        return mip_filter_gnss_source_control_response_encode(&value->u.filter_gnss_source_control_response,
                                                              buf, cap, len_out);
    case MIP_FIELD_FILTER_EXTERNAL_GNSS_UPDATE:
        return mip_filter_external_gnss_update_encode(&value->u.filter_external_gnss_update, buf, cap,
                                                      len_out);
    case MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE:
        return mip_filter_external_heading_update_encode(&value->u.filter_external_heading_update, buf, cap,
                                                         len_out);
    case MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL:
        return mip_filter_heading_update_control_encode(&value->u.filter_heading_update_control, buf, cap,
                                                        len_out);
    case MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE:
        return mip_filter_heading_update_control_response_encode(
            &value->u.filter_heading_update_control_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_AUTO_INIT_CONTROL:
        return mip_filter_auto_init_control_encode(&value->u.filter_auto_init_control, buf, cap, len_out);
    case MIP_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE:
        return mip_filter_auto_init_control_response_encode(&value->u.filter_auto_init_control_response, buf,
                                                            cap, len_out);
    case MIP_FIELD_FILTER_ACCEL_NOISE:
        return mip_filter_accel_noise_encode(&value->u.filter_accel_noise, buf, cap, len_out);
    case MIP_FIELD_FILTER_ACCEL_NOISE_RESPONSE:
        return mip_filter_accel_noise_response_encode(&value->u.filter_accel_noise_response, buf, cap,
                                                      len_out);
    case MIP_FIELD_FILTER_GYRO_NOISE:
        return mip_filter_gyro_noise_encode(&value->u.filter_gyro_noise, buf, cap, len_out);
    case MIP_FIELD_FILTER_GYRO_NOISE_RESPONSE:
        return mip_filter_gyro_noise_response_encode(&value->u.filter_gyro_noise_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_ACCEL_BIAS_MODEL:
        return mip_filter_accel_bias_model_encode(&value->u.filter_accel_bias_model, buf, cap, len_out);
    case MIP_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE:
        return mip_filter_accel_bias_model_response_encode(&value->u.filter_accel_bias_model_response, buf,
                                                           cap, len_out);
    case MIP_FIELD_FILTER_GYRO_BIAS_MODEL:
        return mip_filter_gyro_bias_model_encode(&value->u.filter_gyro_bias_model, buf, cap, len_out);
    case MIP_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE:
        return mip_filter_gyro_bias_model_response_encode(&value->u.filter_gyro_bias_model_response, buf, cap,
                                                          len_out);
    case MIP_FIELD_FILTER_ZUPT_CONTROL:
        return mip_filter_zupt_control_encode(&value->u.filter_zupt_control, buf, cap, len_out);
    case MIP_FIELD_FILTER_ZUPT_CONTROL_RESPONSE:
        return mip_filter_zupt_control_response_encode(&value->u.filter_zupt_control_response, buf, cap,
                                                       len_out);
    case MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME:
        return mip_filter_external_heading_update_with_time_encode(
            &value->u.filter_external_heading_update_with_time, buf, cap, len_out);
    case MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL:
        return mip_filter_zero_angular_rate_update_control_encode(
            &value->u.filter_zero_angular_rate_update_control, buf, cap, len_out);
    case MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE:
        return mip_filter_zero_angular_rate_update_control_response_encode(
            &value->u.filter_zero_angular_rate_update_control_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_TARE_ORIENTATION:
        return mip_filter_tare_orientation_encode(&value->u.filter_tare_orientation, buf, cap, len_out);
    case MIP_FIELD_FILTER_COMMANDED_ZUPT:
        return mip_filter_commanded_zupt_encode(&value->u.filter_commanded_zupt, buf, cap, len_out);
    case MIP_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE:
        return mip_filter_commanded_zero_angular_rate_update_encode(
            &value->u.filter_commanded_zero_angular_rate_update, buf, cap, len_out);
    case MIP_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION:
        return mip_filter_mag_capture_auto_calibration_encode(&value->u.filter_mag_capture_auto_calibration,
                                                              buf, cap, len_out);
    case MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV:
        return mip_filter_gravity_noise_std_dev_encode(&value->u.filter_gravity_noise_std_dev, buf, cap,
                                                       len_out);
    case MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE:
        return mip_filter_gravity_noise_std_dev_response_encode(
            &value->u.filter_gravity_noise_std_dev_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV:
        return mip_filter_pressure_altitude_noise_std_dev_encode(
            &value->u.filter_pressure_altitude_noise_std_dev, buf, cap, len_out);
    case MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE:
        return mip_filter_pressure_altitude_noise_std_dev_response_encode(
            &value->u.filter_pressure_altitude_noise_std_dev_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE:
        return mip_filter_hard_iron_offset_noise_encode(&value->u.filter_hard_iron_offset_noise, buf, cap,
                                                        len_out);
    case MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE:
        return mip_filter_hard_iron_offset_noise_response_encode(
            &value->u.filter_hard_iron_offset_noise_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE:
        return mip_filter_soft_iron_matrix_noise_encode(&value->u.filter_soft_iron_matrix_noise, buf, cap,
                                                        len_out);
    case MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE:
        return mip_filter_soft_iron_matrix_noise_response_encode(
            &value->u.filter_soft_iron_matrix_noise_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_MAG_NOISE_STD_DEV:
        return mip_filter_mag_noise_std_dev_encode(&value->u.filter_mag_noise_std_dev, buf, cap, len_out);
    case MIP_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE:
        return mip_filter_mag_noise_std_dev_response_encode(&value->u.filter_mag_noise_std_dev_response, buf,
                                                            cap, len_out);
    case MIP_FIELD_FILTER_DECLINATION_SOURCE:
        return mip_filter_declination_source_encode(&value->u.filter_declination_source, buf, cap, len_out);
    case MIP_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE:
        return mip_filter_declination_source_response_encode(&value->u.filter_declination_source_response,
                                                             buf, cap, len_out);
    case MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mip_filter_gravity_magnitude_adaptive_measurement_encode(
            &value->u.filter_gravity_magnitude_adaptive_measurement, buf, cap, len_out);
    case MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mip_filter_gravity_magnitude_adaptive_measurement_response_encode(
            &value->u.filter_gravity_magnitude_adaptive_measurement_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mip_filter_mag_magnitude_adaptive_measurement_encode(
            &value->u.filter_mag_magnitude_adaptive_measurement, buf, cap, len_out);
    case MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mip_filter_mag_magnitude_adaptive_measurement_response_encode(
            &value->u.filter_mag_magnitude_adaptive_measurement_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT:
        return mip_filter_mag_dip_angle_adaptive_measurement_encode(
            &value->u.filter_mag_dip_angle_adaptive_measurement, buf, cap, len_out);
    case MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mip_filter_mag_dip_angle_adaptive_measurement_response_encode(
            &value->u.filter_mag_dip_angle_adaptive_measurement_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL:
        return mip_filter_altitude_aiding_control_encode(&value->u.filter_altitude_aiding_control, buf, cap,
                                                         len_out);
    case MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE:
        return mip_filter_altitude_aiding_control_response_encode(
            &value->u.filter_altitude_aiding_control_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL:
        return mip_filter_pitch_roll_aiding_control_encode(&value->u.filter_pitch_roll_aiding_control, buf,
                                                           cap, len_out);
    case MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE:
        return mip_filter_pitch_roll_aiding_control_response_encode(
            &value->u.filter_pitch_roll_aiding_control_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_INCLINATION_SOURCE:
        return mip_filter_inclination_source_encode(&value->u.filter_inclination_source, buf, cap, len_out);
    case MIP_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE:
        return mip_filter_inclination_source_response_encode(&value->u.filter_inclination_source_response,
                                                             buf, cap, len_out);
    case MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE:
        return mip_filter_magnetic_field_magnitude_source_encode(
            &value->u.filter_magnetic_field_magnitude_source, buf, cap, len_out);
    case MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE:
        return mip_filter_magnetic_field_magnitude_source_response_encode(
            &value->u.filter_magnetic_field_magnitude_source_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL:
        return mip_filter_aiding_measurement_control_encode(&value->u.filter_aiding_measurement_control, buf,
                                                            cap, len_out);
    case MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE:
        return mip_filter_aiding_measurement_control_response_encode(
            &value->u.filter_aiding_measurement_control_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION:
        return mip_filter_initialization_configuration_encode(&value->u.filter_initialization_configuration,
                                                              buf, cap, len_out);
    case MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE:
        return mip_filter_initialization_configuration_response_encode(
            &value->u.filter_initialization_configuration_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL:
        return mip_filter_adaptive_filter_control_encode(&value->u.filter_adaptive_filter_control, buf, cap,
                                                         len_out);
    case MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE:
        return mip_filter_adaptive_filter_control_response_encode(
            &value->u.filter_adaptive_filter_control_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET:
        return mip_filter_multi_antenna_offset_encode(&value->u.filter_multi_antenna_offset, buf, cap,
                                                      len_out);
    case MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE:
        return mip_filter_multi_antenna_offset_response_encode(&value->u.filter_multi_antenna_offset_response,
                                                               buf, cap, len_out);
    case MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION:
        return mip_filter_relative_position_configuration_encode(
            &value->u.filter_relative_position_configuration, buf, cap, len_out);
    case MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE:
        return mip_filter_relative_position_configuration_response_encode(
            &value->u.filter_relative_position_configuration_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM:
        return mip_filter_reference_point_lever_arm_encode(&value->u.filter_reference_point_lever_arm, buf,
                                                           cap, len_out);
    case MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE:
        return mip_filter_reference_point_lever_arm_response_encode(
            &value->u.filter_reference_point_lever_arm_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_SPEED_LEVER_ARM:
        return mip_filter_speed_lever_arm_encode(&value->u.filter_speed_lever_arm, buf, cap, len_out);
    case MIP_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE:
        return mip_filter_speed_lever_arm_response_encode(&value->u.filter_speed_lever_arm_response, buf, cap,
                                                          len_out);
    case MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL:
        return mip_filter_wheeled_vehicle_constraint_control_encode(
            &value->u.filter_wheeled_vehicle_constraint_control, buf, cap, len_out);
    case MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE:
        return mip_filter_wheeled_vehicle_constraint_control_response_encode(
            &value->u.filter_wheeled_vehicle_constraint_control_response, buf, cap, len_out);
    case MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL:
        return mip_filter_gnss_antenna_calibration_control_encode(
            &value->u.filter_gnss_antenna_calibration_control, buf, cap, len_out);
    case MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE:
        return mip_filter_gnss_antenna_calibration_control_response_encode(
            &value->u.filter_gnss_antenna_calibration_control_response, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_INFO:
        return mip_gnss_receiver_info_encode(&value->u.gnss_receiver_info, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_INFO_RESPONSE:
        return mip_gnss_receiver_info_response_encode(&value->u.gnss_receiver_info_response, buf, cap,
                                                      len_out);
    case MIP_FIELD_GNSS_SIGNAL_CONFIGURATION:
        return mip_gnss_signal_configuration_encode(&value->u.gnss_signal_configuration, buf, cap, len_out);
    case MIP_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE:
        return mip_gnss_signal_configuration_response_encode(&value->u.gnss_signal_configuration_response,
                                                             buf, cap, len_out);
    case MIP_FIELD_GNSS_SPARTN_CONFIGURATION:
        return mip_gnss_spartn_configuration_encode(&value->u.gnss_spartn_configuration, buf, cap, len_out);
    case MIP_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE:
        return mip_gnss_spartn_configuration_response_encode(&value->u.gnss_spartn_configuration_response,
                                                             buf, cap, len_out);
    case MIP_FIELD_AIDING_FRAME_CONFIG:
        return mip_aiding_frame_config_encode(&value->u.aiding_frame_config, buf, cap, len_out);
    case MIP_FIELD_AIDING_FRAME_CONFIG_RESPONSE:
        return mip_aiding_frame_config_response_encode(&value->u.aiding_frame_config_response, buf, cap,
                                                       len_out);
    case MIP_FIELD_AIDING_ECHO_CONTROL:
        return mip_aiding_echo_control_encode(&value->u.aiding_echo_control, buf, cap, len_out);
    case MIP_FIELD_AIDING_ECHO_CONTROL_RESPONSE:
        return mip_aiding_echo_control_response_encode(&value->u.aiding_echo_control_response, buf, cap,
                                                       len_out);
    case MIP_FIELD_AIDING_ECEF_POSITION:
        return mip_aiding_ecef_position_encode(&value->u.aiding_ecef_position, buf, cap, len_out);
    case MIP_FIELD_AIDING_LLH_POSITION:
        return mip_aiding_llh_position_encode(&value->u.aiding_llh_position, buf, cap, len_out);
    case MIP_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID:
        return mip_aiding_height_above_ellipsoid_encode(&value->u.aiding_height_above_ellipsoid, buf, cap,
                                                        len_out);
    case MIP_FIELD_AIDING_ECEF_VELOCITY:
        return mip_aiding_ecef_velocity_encode(&value->u.aiding_ecef_velocity, buf, cap, len_out);
    case MIP_FIELD_AIDING_NED_VELOCITY:
        return mip_aiding_ned_velocity_encode(&value->u.aiding_ned_velocity, buf, cap, len_out);
    case MIP_FIELD_AIDING_BODY_FRAME_VELOCITY:
        return mip_aiding_body_frame_velocity_encode(&value->u.aiding_body_frame_velocity, buf, cap, len_out);
    case MIP_FIELD_AIDING_TRUE_HEADING:
        return mip_aiding_true_heading_encode(&value->u.aiding_true_heading, buf, cap, len_out);
    case MIP_FIELD_AIDING_MAGNETIC_FIELD:
        return mip_aiding_magnetic_field_encode(&value->u.aiding_magnetic_field, buf, cap, len_out);
    case MIP_FIELD_AIDING_PRESSURE:
        return mip_aiding_pressure_encode(&value->u.aiding_pressure, buf, cap, len_out);
    case MIP_FIELD_SYSTEM_COMMUNICATION_MODE:
        return mip_system_communication_mode_encode(&value->u.system_communication_mode, buf, cap, len_out);
    case MIP_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE:
        return mip_system_communication_mode_response_encode(&value->u.system_communication_mode_response,
                                                             buf, cap, len_out);
    case MIP_FIELD_SENSOR_SCALED_ACCEL:
        return mip_sensor_scaled_accel_encode(&value->u.sensor_scaled_accel, buf, cap, len_out);
    case MIP_FIELD_SENSOR_SCALED_GYRO:
        return mip_sensor_scaled_gyro_encode(&value->u.sensor_scaled_gyro, buf, cap, len_out);
    case MIP_FIELD_SENSOR_SCALED_MAG:
        return mip_sensor_scaled_mag_encode(&value->u.sensor_scaled_mag, buf, cap, len_out);
    case MIP_FIELD_SENSOR_DELTA_THETA:
        return mip_sensor_delta_theta_encode(&value->u.sensor_delta_theta, buf, cap, len_out);
    case MIP_FIELD_SENSOR_DELTA_VELOCITY:
        return mip_sensor_delta_velocity_encode(&value->u.sensor_delta_velocity, buf, cap, len_out);
    case MIP_FIELD_SENSOR_CF_ORIENTATION_MATRIX:
        return mip_sensor_cf_orientation_matrix_encode(&value->u.sensor_cf_orientation_matrix, buf, cap,
                                                       len_out);
    case MIP_FIELD_SENSOR_CF_QUATERNION:
        return mip_sensor_cf_quaternion_encode(&value->u.sensor_cf_quaternion, buf, cap, len_out);
    case MIP_FIELD_SENSOR_CF_EULER_ANGLES:
        return mip_sensor_cf_euler_angles_encode(&value->u.sensor_cf_euler_angles, buf, cap, len_out);
    case MIP_FIELD_SENSOR_CF_STABILIZED_NORTH:
        return mip_sensor_cf_stabilized_north_encode(&value->u.sensor_cf_stabilized_north, buf, cap, len_out);
    case MIP_FIELD_SENSOR_CF_STABILIZED_UP:
        return mip_sensor_cf_stabilized_up_encode(&value->u.sensor_cf_stabilized_up, buf, cap, len_out);
    case MIP_FIELD_SENSOR_GPS_TIMESTAMP:
        return mip_sensor_gps_timestamp_encode(&value->u.sensor_gps_timestamp, buf, cap, len_out);
    case MIP_FIELD_SENSOR_TEMPERATURE_STATISTICS:
        return mip_sensor_temperature_statistics_encode(&value->u.sensor_temperature_statistics, buf, cap,
                                                        len_out);
    case MIP_FIELD_SENSOR_SCALED_PRESSURE:
        return mip_sensor_scaled_pressure_encode(&value->u.sensor_scaled_pressure, buf, cap, len_out);
    case MIP_FIELD_SENSOR_OVERRANGE_STATUS:
        return mip_sensor_overrange_status_encode(&value->u.sensor_overrange_status, buf, cap, len_out);
    case MIP_FIELD_SENSOR_ODOMETER_DATA:
        return mip_sensor_odometer_data_encode(&value->u.sensor_odometer_data, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_LLH_POSITION:
        return mip_gnss_data_llh_position_encode(&value->u.gnss_data_llh_position, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_ECEF_POSITION:
        return mip_gnss_data_ecef_position_encode(&value->u.gnss_data_ecef_position, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_NED_VELOCITY:
        return mip_gnss_data_ned_velocity_encode(&value->u.gnss_data_ned_velocity, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_ECEF_VELOCITY:
        return mip_gnss_data_ecef_velocity_encode(&value->u.gnss_data_ecef_velocity, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_DOP:
        return mip_gnss_data_dop_encode(&value->u.gnss_data_dop, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_UTC_TIME:
        return mip_gnss_data_utc_time_encode(&value->u.gnss_data_utc_time, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_GPS_TIME:
        return mip_gnss_data_gps_time_encode(&value->u.gnss_data_gps_time, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_CLOCK_INFO:
        return mip_gnss_data_clock_info_encode(&value->u.gnss_data_clock_info, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_FIX_INFO:
        return mip_gnss_data_fix_info_encode(&value->u.gnss_data_fix_info, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_SV_INFO:
        return mip_gnss_data_sv_info_encode(&value->u.gnss_data_sv_info, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_HARDWARE_STATUS:
        return mip_gnss_data_hardware_status_encode(&value->u.gnss_data_hardware_status, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_DGNSS_INFO:
        return mip_gnss_data_dgnss_info_encode(&value->u.gnss_data_dgnss_info, buf, cap, len_out);
    case MIP_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS:
        return mip_gnss_data_dgnss_channel_status_encode(&value->u.gnss_data_dgnss_channel_status, buf, cap,
                                                         len_out);
    case MIP_FIELD_FILTER_DATA_LLH_POSITION:
        return mip_filter_data_llh_position_encode(&value->u.filter_data_llh_position, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_NED_VELOCITY:
        return mip_filter_data_ned_velocity_encode(&value->u.filter_data_ned_velocity, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_ATTITUDE_QUATERNION:
        return mip_filter_data_attitude_quaternion_encode(&value->u.filter_data_attitude_quaternion, buf, cap,
                                                          len_out);
    case MIP_FIELD_FILTER_DATA_ATTITUDE_DCM:
        return mip_filter_data_attitude_dcm_encode(&value->u.filter_data_attitude_dcm, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_EULER_ANGLES:
        return mip_filter_data_euler_angles_encode(&value->u.filter_data_euler_angles, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_GYRO_BIAS:
        return mip_filter_data_gyro_bias_encode(&value->u.filter_data_gyro_bias, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_ACCEL_BIAS:
        return mip_filter_data_accel_bias_encode(&value->u.filter_data_accel_bias, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY:
        return mip_filter_data_llh_position_uncertainty_encode(&value->u.filter_data_llh_position_uncertainty,
                                                               buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY:
        return mip_filter_data_ned_velocity_uncertainty_encode(&value->u.filter_data_ned_velocity_uncertainty,
                                                               buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY:
        return mip_filter_data_euler_angles_uncertainty_encode(&value->u.filter_data_euler_angles_uncertainty,
                                                               buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY:
        return mip_filter_data_gyro_bias_uncertainty_encode(&value->u.filter_data_gyro_bias_uncertainty, buf,
                                                            cap, len_out);
    case MIP_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY:
        return mip_filter_data_accel_bias_uncertainty_encode(&value->u.filter_data_accel_bias_uncertainty,
                                                             buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_LINEAR_ACCEL:
        return mip_filter_data_linear_accel_encode(&value->u.filter_data_linear_accel, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_COMP_ANGULAR_RATE:
        return mip_filter_data_comp_angular_rate_encode(&value->u.filter_data_comp_angular_rate, buf, cap,
                                                        len_out);
    case MIP_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE:
        return mip_filter_data_wgs84_gravity_magnitude_encode(&value->u.filter_data_wgs84_gravity_magnitude,
                                                              buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45:
        return mip_filter_data_filter_status_gx5_45_encode(&value->u.filter_data_filter_status_gx5_45, buf,
                                                           cap, len_out);
    case MIP_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS:
        return mip_filter_data_filter_status_cv7_ins_encode(&value->u.filter_data_filter_status_cv7_ins, buf,
                                                            cap, len_out);
    case MIP_FIELD_FILTER_DATA_GPS_TIMESTAMP:
        return mip_filter_data_gps_timestamp_encode(&value->u.filter_data_gps_timestamp, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY:
        return mip_filter_data_quaternion_attitude_uncertainty_encode(
            &value->u.filter_data_quaternion_attitude_uncertainty, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_GRAVITY_VECTOR:
        return mip_filter_data_gravity_vector_encode(&value->u.filter_data_gravity_vector, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_HEADING_UPDATE_STATE:
        return mip_filter_data_heading_update_state_encode(&value->u.filter_data_heading_update_state, buf,
                                                           cap, len_out);
    case MIP_FIELD_FILTER_DATA_MAGNETIC_MODEL:
        return mip_filter_data_magnetic_model_encode(&value->u.filter_data_magnetic_model, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR:
        return mip_filter_data_gyro_scale_factor_encode(&value->u.filter_data_gyro_scale_factor, buf, cap,
                                                        len_out);
    case MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR:
        return mip_filter_data_accel_scale_factor_encode(&value->u.filter_data_accel_scale_factor, buf, cap,
                                                         len_out);
    case MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY:
        return mip_filter_data_gyro_scale_factor_uncertainty_encode(
            &value->u.filter_data_gyro_scale_factor_uncertainty, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY:
        return mip_filter_data_accel_scale_factor_uncertainty_encode(
            &value->u.filter_data_accel_scale_factor_uncertainty, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_COMPENSATED_ACCEL:
        return mip_filter_data_compensated_accel_encode(&value->u.filter_data_compensated_accel, buf, cap,
                                                        len_out);
    case MIP_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE:
        return mip_filter_data_standard_atmosphere_encode(&value->u.filter_data_standard_atmosphere, buf, cap,
                                                          len_out);
    case MIP_FIELD_FILTER_DATA_PRESSURE_ALTITUDE:
        return mip_filter_data_pressure_altitude_encode(&value->u.filter_data_pressure_altitude, buf, cap,
                                                        len_out);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET:
        return mip_filter_data_mag_auto_hard_iron_offset_encode(
            &value->u.filter_data_mag_auto_hard_iron_offset, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX:
        return mip_filter_data_mag_auto_soft_iron_matrix_encode(
            &value->u.filter_data_mag_auto_soft_iron_matrix, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY:
        return mip_filter_data_mag_auto_hard_iron_offset_uncertainty_encode(
            &value->u.filter_data_mag_auto_hard_iron_offset_uncertainty, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY:
        return mip_filter_data_mag_auto_soft_iron_matrix_uncertainty_encode(
            &value->u.filter_data_mag_auto_soft_iron_matrix_uncertainty, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION:
        return mip_filter_data_gnss_antenna_offset_correction_encode(
            &value->u.filter_data_gnss_antenna_offset_correction, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mip_filter_data_gnss_antenna_offset_correction_uncertainty_encode(
            &value->u.filter_data_gnss_antenna_offset_correction_uncertainty, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION:
        return mip_filter_data_multi_antenna_offset_correction_encode(
            &value->u.filter_data_multi_antenna_offset_correction, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mip_filter_data_multi_antenna_offset_correction_uncertainty_encode(
            &value->u.filter_data_multi_antenna_offset_correction_uncertainty, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY:
        return mip_filter_data_ecef_position_uncertainty_encode(
            &value->u.filter_data_ecef_position_uncertainty, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY:
        return mip_filter_data_ecef_velocity_uncertainty_encode(
            &value->u.filter_data_ecef_velocity_uncertainty, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_ECEF_POSITION:
        return mip_filter_data_ecef_position_encode(&value->u.filter_data_ecef_position, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_ECEF_VELOCITY:
        return mip_filter_data_ecef_velocity_encode(&value->u.filter_data_ecef_velocity, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_NED_RELATIVE_POSITION:
        return mip_filter_data_ned_relative_position_encode(&value->u.filter_data_ned_relative_position, buf,
                                                            cap, len_out);
    case MIP_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS:
        return mip_filter_data_gnss_position_aiding_status_encode(
            &value->u.filter_data_gnss_position_aiding_status, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY:
        return mip_filter_data_aiding_measurement_summary_encode(
            &value->u.filter_data_aiding_measurement_summary, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR:
        return mip_filter_data_odometer_scale_factor_error_encode(
            &value->u.filter_data_odometer_scale_factor_error, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY:
        return mip_filter_data_odometer_scale_factor_error_uncertainty_encode(
            &value->u.filter_data_odometer_scale_factor_error_uncertainty, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS:
        return mip_filter_data_gnss_dual_antenna_status_encode(&value->u.filter_data_gnss_dual_antenna_status,
                                                               buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR:
        return mip_filter_data_aiding_frame_config_error_encode(
            &value->u.filter_data_aiding_frame_config_error, buf, cap, len_out);
    case MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY:
        return mip_filter_data_aiding_frame_config_error_uncertainty_encode(
            &value->u.filter_data_aiding_frame_config_error_uncertainty, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_LLH_POSITION:
        return mip_gnss_receiver_1_llh_position_encode(&value->u.gnss_receiver_1_llh_position, buf, cap,
                                                       len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_ECEF_POSITION:
        return mip_gnss_receiver_1_ecef_position_encode(&value->u.gnss_receiver_1_ecef_position, buf, cap,
                                                        len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_NED_VELOCITY:
        return mip_gnss_receiver_1_ned_velocity_encode(&value->u.gnss_receiver_1_ned_velocity, buf, cap,
                                                       len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY:
        return mip_gnss_receiver_1_ecef_velocity_encode(&value->u.gnss_receiver_1_ecef_velocity, buf, cap,
                                                        len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_DOP:
        return mip_gnss_receiver_1_dop_encode(&value->u.gnss_receiver_1_dop, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_UTC_TIME:
        return mip_gnss_receiver_1_utc_time_encode(&value->u.gnss_receiver_1_utc_time, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_TIME:
        return mip_gnss_receiver_1_gps_time_encode(&value->u.gnss_receiver_1_gps_time, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_FIX_INFO:
        return mip_gnss_receiver_1_fix_info_encode(&value->u.gnss_receiver_1_fix_info, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS:
        return mip_gnss_receiver_1_hardware_status_encode(&value->u.gnss_receiver_1_hardware_status, buf, cap,
                                                          len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2:
        return mip_gnss_receiver_1_clock_info_2_encode(&value->u.gnss_receiver_1_clock_info_2, buf, cap,
                                                       len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS:
        return mip_gnss_receiver_1_gps_leap_seconds_encode(&value->u.gnss_receiver_1_gps_leap_seconds, buf,
                                                           cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_SBAS_INFO:
        return mip_gnss_receiver_1_sbas_info_encode(&value->u.gnss_receiver_1_sbas_info, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS:
        return mip_gnss_receiver_1_satellite_status_encode(&value->u.gnss_receiver_1_satellite_status, buf,
                                                           cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_RAW:
        return mip_gnss_receiver_1_raw_encode(&value->u.gnss_receiver_1_raw, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS:
        return mip_gnss_receiver_1_gps_ephemeris_encode(&value->u.gnss_receiver_1_gps_ephemeris, buf, cap,
                                                        len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS:
        return mip_gnss_receiver_1_glonass_ephemeris_encode(&value->u.gnss_receiver_1_glonass_ephemeris, buf,
                                                            cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS:
        return mip_gnss_receiver_1_galileo_ephemeris_encode(&value->u.gnss_receiver_1_galileo_ephemeris, buf,
                                                            cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS:
        return mip_gnss_receiver_1_beidou_ephemeris_encode(&value->u.gnss_receiver_1_beidou_ephemeris, buf,
                                                           cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_LLH_POSITION:
        return mip_gnss_receiver_2_llh_position_encode(&value->u.gnss_receiver_2_llh_position, buf, cap,
                                                       len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_ECEF_POSITION:
        return mip_gnss_receiver_2_ecef_position_encode(&value->u.gnss_receiver_2_ecef_position, buf, cap,
                                                        len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_NED_VELOCITY:
        return mip_gnss_receiver_2_ned_velocity_encode(&value->u.gnss_receiver_2_ned_velocity, buf, cap,
                                                       len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY:
        return mip_gnss_receiver_2_ecef_velocity_encode(&value->u.gnss_receiver_2_ecef_velocity, buf, cap,
                                                        len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_DOP:
        return mip_gnss_receiver_2_dop_encode(&value->u.gnss_receiver_2_dop, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_UTC_TIME:
        return mip_gnss_receiver_2_utc_time_encode(&value->u.gnss_receiver_2_utc_time, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_TIME:
        return mip_gnss_receiver_2_gps_time_encode(&value->u.gnss_receiver_2_gps_time, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_FIX_INFO:
        return mip_gnss_receiver_2_fix_info_encode(&value->u.gnss_receiver_2_fix_info, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS:
        return mip_gnss_receiver_2_hardware_status_encode(&value->u.gnss_receiver_2_hardware_status, buf, cap,
                                                          len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2:
        return mip_gnss_receiver_2_clock_info_2_encode(&value->u.gnss_receiver_2_clock_info_2, buf, cap,
                                                       len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS:
        return mip_gnss_receiver_2_gps_leap_seconds_encode(&value->u.gnss_receiver_2_gps_leap_seconds, buf,
                                                           cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_SBAS_INFO:
        return mip_gnss_receiver_2_sbas_info_encode(&value->u.gnss_receiver_2_sbas_info, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS:
        return mip_gnss_receiver_2_satellite_status_encode(&value->u.gnss_receiver_2_satellite_status, buf,
                                                           cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_RAW:
        return mip_gnss_receiver_2_raw_encode(&value->u.gnss_receiver_2_raw, buf, cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS:
        return mip_gnss_receiver_2_gps_ephemeris_encode(&value->u.gnss_receiver_2_gps_ephemeris, buf, cap,
                                                        len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS:
        return mip_gnss_receiver_2_glonass_ephemeris_encode(&value->u.gnss_receiver_2_glonass_ephemeris, buf,
                                                            cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS:
        return mip_gnss_receiver_2_galileo_ephemeris_encode(&value->u.gnss_receiver_2_galileo_ephemeris, buf,
                                                            cap, len_out);
    case MIP_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS:
        return mip_gnss_receiver_2_beidou_ephemeris_encode(&value->u.gnss_receiver_2_beidou_ephemeris, buf,
                                                           cap, len_out);
    case MIP_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO:
        return mip_gnss_corrections_base_station_info_encode(&value->u.gnss_corrections_base_station_info,
                                                             buf, cap, len_out);
    case MIP_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS:
        return mip_gnss_corrections_rtk_corrections_status_encode(
            &value->u.gnss_corrections_rtk_corrections_status, buf, cap, len_out);
    case MIP_FIELD_GNSS_EXTERNAL_LLH_POSITION:
        return mip_gnss_external_llh_position_encode(&value->u.gnss_external_llh_position, buf, cap, len_out);
    case MIP_FIELD_GNSS_EXTERNAL_NED_VELOCITY:
        return mip_gnss_external_ned_velocity_encode(&value->u.gnss_external_ned_velocity, buf, cap, len_out);
    case MIP_FIELD_GNSS_EXTERNAL_UTC_TIME:
        return mip_gnss_external_utc_time_encode(&value->u.gnss_external_utc_time, buf, cap, len_out);
    case MIP_FIELD_GNSS_EXTERNAL_FIX_INFO:
        return mip_gnss_external_fix_info_encode(&value->u.gnss_external_fix_info, buf, cap, len_out);
    case MIP_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS:
        return mip_gnss_external_satellite_status_encode(&value->u.gnss_external_satellite_status, buf, cap,
                                                         len_out);
    case MIP_FIELD_SYSTEM_DATA_BUILT_IN_TEST:
        return mip_system_data_built_in_test_encode(&value->u.system_data_built_in_test, buf, cap, len_out);
    case MIP_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS:
        return mip_system_data_time_sync_status_encode(&value->u.system_data_time_sync_status, buf, cap,
                                                       len_out);
    case MIP_FIELD_SYSTEM_DATA_GPIO_STATE:
        return mip_system_data_gpio_state_encode(&value->u.system_data_gpio_state, buf, cap, len_out);
    case MIP_FIELD_SHARED_EVENT_SOURCE:
        return mip_shared_event_source_encode(&value->u.shared_event_source, buf, cap, len_out);
    case MIP_FIELD_SHARED_GPS_TIMESTAMP:
        return mip_shared_gps_timestamp_encode(&value->u.shared_gps_timestamp, buf, cap, len_out);
    case MIP_FIELD_SHARED_DELTA_TIME:
        return mip_shared_delta_time_encode(&value->u.shared_delta_time, buf, cap, len_out);
    case MIP_FIELD_SHARED_REFERENCE_TIMESTAMP:
        return mip_shared_reference_timestamp_encode(&value->u.shared_reference_timestamp, buf, cap, len_out);
    case MIP_FIELD_SHARED_REFERENCE_TIME_DELTA:
        return mip_shared_reference_time_delta_encode(&value->u.shared_reference_time_delta, buf, cap,
                                                      len_out);
    case MIP_FIELD_SHARED_EXTERNAL_TIMESTAMP:
        return mip_shared_external_timestamp_encode(&value->u.shared_external_timestamp, buf, cap, len_out);
    case MIP_FIELD_SHARED_EXTERNAL_TIME_DELTA:
        return mip_shared_external_time_delta_encode(&value->u.shared_external_time_delta, buf, cap, len_out);
    case MIP_FIELD_NONE:
    case MIP_FIELD_COUNT:
    default:
        return MIP_ERR_INVALID;
    }
}

void mip_value_to_json(mip_jw_t *w, const mip_field_value_t *value) {
    switch (value->id) {
    case MIP_FIELD_ACK_NACK:
        mip_ack_nack_to_json(w, &value->u.ack_nack);
        return;
    case MIP_FIELD_BASE_PING:
        mip_base_ping_to_json(w, &value->u.base_ping);
        return;
    case MIP_FIELD_BASE_SET_TO_IDLE:
        mip_base_set_to_idle_to_json(w, &value->u.base_set_to_idle);
        return;
    case MIP_FIELD_BASE_GET_DEVICE_INFO:
        mip_base_get_device_info_to_json(w, &value->u.base_get_device_info);
        return;
    case MIP_FIELD_BASE_DEVICE_INFO:
        mip_base_device_info_to_json(w, &value->u.base_device_info);
        return;
    case MIP_FIELD_BASE_GET_DEVICE_DESCRIPTORS:
        mip_base_get_device_descriptors_to_json(w, &value->u.base_get_device_descriptors);
        return;
    case MIP_FIELD_BASE_DEVICE_DESCRIPTORS:
        mip_base_device_descriptors_to_json(w, &value->u.base_device_descriptors);
        return;
    case MIP_FIELD_BASE_BUILT_IN_TEST:
        mip_base_built_in_test_to_json(w, &value->u.base_built_in_test);
        return;
    case MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45:
        mip_base_built_in_test_result_gx5_45_to_json(w, &value->u.base_built_in_test_result_gx5_45);
        return;
    case MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS:
        mip_base_built_in_test_result_cv7_ins_to_json(w, &value->u.base_built_in_test_result_cv7_ins);
        return;
    case MIP_FIELD_BASE_RESUME:
        mip_base_resume_to_json(w, &value->u.base_resume);
        return;
    case MIP_FIELD_BASE_GET_EXTENDED_DESCRIPTORS:
        mip_base_get_extended_descriptors_to_json(w, &value->u.base_get_extended_descriptors);
        return;
    case MIP_FIELD_BASE_EXTENDED_DESCRIPTORS:
        mip_base_extended_descriptors_to_json(w, &value->u.base_extended_descriptors);
        return;
    case MIP_FIELD_BASE_CONTINUOUS_BIT:
        mip_base_continuous_bit_to_json(w, &value->u.base_continuous_bit);
        return;
    case MIP_FIELD_BASE_CONTINUOUS_BIT_RESULT:
        mip_base_continuous_bit_result_to_json(w, &value->u.base_continuous_bit_result);
        return;
    case MIP_FIELD_BASE_COMM_PORT_SPEED:
        mip_base_comm_port_speed_to_json(w, &value->u.base_comm_port_speed);
        return;
    case MIP_FIELD_BASE_COMM_PORT_SPEED_RESPONSE:
        mip_base_comm_port_speed_response_to_json(w, &value->u.base_comm_port_speed_response);
        return;
    case MIP_FIELD_BASE_GPS_TIME_UPDATE_GX5_45:
        mip_base_gps_time_update_gx5_45_to_json(w, &value->u.base_gps_time_update_gx5_45);
        return;
    case MIP_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS:
        mip_base_gps_time_update_cv7_ins_to_json(w, &value->u.base_gps_time_update_cv7_ins);
        return;
    case MIP_FIELD_BASE_GPS_WEEK:
        mip_base_gps_week_to_json(w, &value->u.base_gps_week);
        return;
    case MIP_FIELD_BASE_GPS_SECONDS:
        mip_base_gps_seconds_to_json(w, &value->u.base_gps_seconds);
        return;
    case MIP_FIELD_BASE_DEVICE_RESET:
        mip_base_device_reset_to_json(w, &value->u.base_device_reset);
        return;
    case MIP_FIELD_THREEDM_EVENT_CONTROL:
        mip_threedm_event_control_to_json(w, &value->u.threedm_event_control);
        return;
    case MIP_FIELD_THREEDM_EVENT_CONTROL_RESPONSE:
        mip_threedm_event_control_response_to_json(w, &value->u.threedm_event_control_response);
        return;
    case MIP_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS:
        mip_threedm_get_event_trigger_status_to_json(w, &value->u.threedm_get_event_trigger_status);
        return;
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_STATUS:
        mip_threedm_event_trigger_status_to_json(w, &value->u.threedm_event_trigger_status);
        return;
    case MIP_FIELD_THREEDM_GET_EVENT_ACTION_STATUS:
        mip_threedm_get_event_action_status_to_json(w, &value->u.threedm_get_event_action_status);
        return;
    case MIP_FIELD_THREEDM_EVENT_ACTION_STATUS:
        mip_threedm_event_action_status_to_json(w, &value->u.threedm_event_action_status);
        return;
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG:
        mip_threedm_event_trigger_config_to_json(w, &value->u.threedm_event_trigger_config);
        return;
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE:
        mip_threedm_event_trigger_config_response_to_json(w, &value->u.threedm_event_trigger_config_response);
        return;
    case MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG:
        mip_threedm_event_action_config_to_json(w, &value->u.threedm_event_action_config);
        return;
    case MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE:
        mip_threedm_event_action_config_response_to_json(w, &value->u.threedm_event_action_config_response);
        return;
    case MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45:
        mip_threedm_device_startup_settings_gx5_45_to_json(w,
                                                           &value->u.threedm_device_startup_settings_gx5_45);
        return;
    case MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS:
        mip_threedm_device_startup_settings_cv7_ins_to_json(
            w, &value->u.threedm_device_startup_settings_cv7_ins);
        return;
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER:
        mip_threedm_sensor_to_vehicle_euler_to_json(w, &value->u.threedm_sensor_to_vehicle_euler);
        return;
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE:
        mip_threedm_sensor_to_vehicle_euler_response_to_json(
            w, &value->u.threedm_sensor_to_vehicle_euler_response);
        return;
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION:
        mip_threedm_sensor_to_vehicle_quaternion_to_json(w, &value->u.threedm_sensor_to_vehicle_quaternion);
        return;
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE:
        mip_threedm_sensor_to_vehicle_quaternion_response_to_json(
            w, &value->u.threedm_sensor_to_vehicle_quaternion_response);
        return;
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM:
        mip_threedm_sensor_to_vehicle_dcm_to_json(w, &value->u.threedm_sensor_to_vehicle_dcm);
        return;
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE:
        mip_threedm_sensor_to_vehicle_dcm_response_to_json(w,
                                                           &value->u.threedm_sensor_to_vehicle_dcm_response);
        return;
    case MIP_FIELD_THREEDM_ACCEL_BIAS_GX5_45:
        mip_threedm_accel_bias_gx5_45_to_json(w, &value->u.threedm_accel_bias_gx5_45);
        return;
    case MIP_FIELD_THREEDM_ACCEL_BIAS_CV7_INS:
        mip_threedm_accel_bias_cv7_ins_to_json(w, &value->u.threedm_accel_bias_cv7_ins);
        return;
    case MIP_FIELD_THREEDM_ACCEL_BIAS_RESPONSE:
        mip_threedm_accel_bias_response_to_json(w, &value->u.threedm_accel_bias_response);
        return;
    case MIP_FIELD_THREEDM_GYRO_BIAS_GX5_45:
        mip_threedm_gyro_bias_gx5_45_to_json(w, &value->u.threedm_gyro_bias_gx5_45);
        return;
    case MIP_FIELD_THREEDM_GYRO_BIAS_CV7_INS:
        mip_threedm_gyro_bias_cv7_ins_to_json(w, &value->u.threedm_gyro_bias_cv7_ins);
        return;
    case MIP_FIELD_THREEDM_GYRO_BIAS_RESPONSE:
        mip_threedm_gyro_bias_response_to_json(w, &value->u.threedm_gyro_bias_response);
        return;
    case MIP_FIELD_THREEDM_CAPTURE_GYRO_BIAS:
        mip_threedm_capture_gyro_bias_to_json(w, &value->u.threedm_capture_gyro_bias);
        return;
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45:
        mip_threedm_mag_hard_iron_offset_gx5_45_to_json(w, &value->u.threedm_mag_hard_iron_offset_gx5_45);
        return;
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS:
        mip_threedm_mag_hard_iron_offset_cv7_ins_to_json(w, &value->u.threedm_mag_hard_iron_offset_cv7_ins);
        return;
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE:
        mip_threedm_mag_hard_iron_offset_response_to_json(w, &value->u.threedm_mag_hard_iron_offset_response);
        return;
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45:
        mip_threedm_mag_soft_iron_matrix_gx5_45_to_json(w, &value->u.threedm_mag_soft_iron_matrix_gx5_45);
        return;
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS:
        mip_threedm_mag_soft_iron_matrix_cv7_ins_to_json(w, &value->u.threedm_mag_soft_iron_matrix_cv7_ins);
        return;
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE:
        mip_threedm_mag_soft_iron_matrix_response_to_json(w, &value->u.threedm_mag_soft_iron_matrix_response);
        return;
    case MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE:
        mip_threedm_coning_sculling_enable_to_json(w, &value->u.threedm_coning_sculling_enable);
        return;
    case MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE:
        mip_threedm_coning_sculling_enable_response_to_json(
            w, &value->u.threedm_coning_sculling_enable_response);
        return;
    case MIP_FIELD_THREEDM_UART_BAUDRATE:
        mip_threedm_uart_baudrate_to_json(w, &value->u.threedm_uart_baudrate);
        return;
    case MIP_FIELD_THREEDM_UART_BAUDRATE_RESPONSE:
        mip_threedm_uart_baudrate_response_to_json(w, &value->u.threedm_uart_baudrate_response);
        return;
    case MIP_FIELD_THREEDM_GPIO_CONFIG:
        mip_threedm_gpio_config_to_json(w, &value->u.threedm_gpio_config);
        return;
    case MIP_FIELD_THREEDM_GPIO_CONFIG_RESPONSE:
        mip_threedm_gpio_config_response_to_json(w, &value->u.threedm_gpio_config_response);
        return;
    case MIP_FIELD_THREEDM_GPIO_STATE:
        mip_threedm_gpio_state_to_json(w, &value->u.threedm_gpio_state);
        return;
    case MIP_FIELD_THREEDM_GPIO_STATE_RESPONSE:
        mip_threedm_gpio_state_response_to_json(w, &value->u.threedm_gpio_state_response);
        return;
    case MIP_FIELD_THREEDM_ODOMETER_CONFIG:
        mip_threedm_odometer_config_to_json(w, &value->u.threedm_odometer_config);
        return;
    case MIP_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE:
        mip_threedm_odometer_config_response_to_json(w, &value->u.threedm_odometer_config_response);
        return;
    case MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER:
        mip_threedm_advanced_lowpass_filter_to_json(w, &value->u.threedm_advanced_lowpass_filter);
        return;
    case MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE:
        mip_threedm_advanced_lowpass_filter_response_to_json(
            w, &value->u.threedm_advanced_lowpass_filter_response);
        return;
    case MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER:
        mip_threedm_complementary_filter_to_json(w, &value->u.threedm_complementary_filter);
        return;
    case MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE:
        mip_threedm_complementary_filter_response_to_json(w, &value->u.threedm_complementary_filter_response);
        return;
    case MIP_FIELD_THREEDM_SENSOR_RANGE:
        mip_threedm_sensor_range_to_json(w, &value->u.threedm_sensor_range);
        return;
    case MIP_FIELD_THREEDM_SENSOR_RANGE_RESPONSE:
        mip_threedm_sensor_range_response_to_json(w, &value->u.threedm_sensor_range_response);
        return;
    case MIP_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES:
        mip_threedm_get_calibrated_sensor_ranges_to_json(w, &value->u.threedm_get_calibrated_sensor_ranges);
        return;
    case MIP_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES:
        mip_threedm_calibrated_sensor_ranges_to_json(w, &value->u.threedm_calibrated_sensor_ranges);
        return;
    case MIP_FIELD_THREEDM_LOWPASS_FILTER:
        mip_threedm_lowpass_filter_to_json(w, &value->u.threedm_lowpass_filter);
        return;
    case MIP_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE:
        mip_threedm_lowpass_filter_response_to_json(w, &value->u.threedm_lowpass_filter_response);
        return;
    case MIP_FIELD_THREEDM_POLL_IMU_DATA:
        mip_threedm_poll_imu_data_to_json(w, &value->u.threedm_poll_imu_data);
        return;
    case MIP_FIELD_THREEDM_POLL_GNSS_DATA:
        mip_threedm_poll_gnss_data_to_json(w, &value->u.threedm_poll_gnss_data);
        return;
    case MIP_FIELD_THREEDM_POLL_FILTER_DATA:
        mip_threedm_poll_filter_data_to_json(w, &value->u.threedm_poll_filter_data);
        return;
    case MIP_FIELD_THREEDM_POLL_NMEA_DATA:
        mip_threedm_poll_nmea_data_to_json(w, &value->u.threedm_poll_nmea_data);
        return;
    case MIP_FIELD_THREEDM_POLL_DATA:
        mip_threedm_poll_data_to_json(w, &value->u.threedm_poll_data);
        return;
    case MIP_FIELD_THREEDM_GET_IMU_BASE_RATE:
        mip_threedm_get_imu_base_rate_to_json(w, &value->u.threedm_get_imu_base_rate);
        return;
    case MIP_FIELD_THREEDM_IMU_BASE_RATE:
        mip_threedm_imu_base_rate_to_json(w, &value->u.threedm_imu_base_rate);
        return;
    case MIP_FIELD_THREEDM_GET_GNSS_BASE_RATE:
        mip_threedm_get_gnss_base_rate_to_json(w, &value->u.threedm_get_gnss_base_rate);
        return;
    case MIP_FIELD_THREEDM_GNSS_BASE_RATE:
        mip_threedm_gnss_base_rate_to_json(w, &value->u.threedm_gnss_base_rate);
        return;
    case MIP_FIELD_THREEDM_GET_FILTER_BASE_RATE:
        mip_threedm_get_filter_base_rate_to_json(w, &value->u.threedm_get_filter_base_rate);
        return;
    case MIP_FIELD_THREEDM_FILTER_BASE_RATE:
        mip_threedm_filter_base_rate_to_json(w, &value->u.threedm_filter_base_rate);
        return;
    case MIP_FIELD_THREEDM_GET_BASE_RATE:
        mip_threedm_get_base_rate_to_json(w, &value->u.threedm_get_base_rate);
        return;
    case MIP_FIELD_THREEDM_BASE_RATE:
        mip_threedm_base_rate_to_json(w, &value->u.threedm_base_rate);
        return;
    case MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT:
        mip_threedm_imu_message_format_to_json(w, &value->u.threedm_imu_message_format);
        return;
    case MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE:
        mip_threedm_imu_message_format_response_to_json(w, &value->u.threedm_imu_message_format_response);
        return;
    case MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT:
        mip_threedm_gnss_message_format_to_json(w, &value->u.threedm_gnss_message_format);
        return;
    case MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE:
        mip_threedm_gnss_message_format_response_to_json(w, &value->u.threedm_gnss_message_format_response);
        return;
    case MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT:
        mip_threedm_filter_message_format_to_json(w, &value->u.threedm_filter_message_format);
        return;
    case MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE:
        mip_threedm_filter_message_format_response_to_json(w,
                                                           &value->u.threedm_filter_message_format_response);
        return;
    case MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT:
        mip_threedm_nmea_message_format_to_json(w, &value->u.threedm_nmea_message_format);
        return;
    case MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE:
        mip_threedm_nmea_message_format_response_to_json(w, &value->u.threedm_nmea_message_format_response);
        return;
    case MIP_FIELD_THREEDM_MESSAGE_FORMAT:
        mip_threedm_message_format_to_json(w, &value->u.threedm_message_format);
        return;
    case MIP_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE:
        mip_threedm_message_format_response_to_json(w, &value->u.threedm_message_format_response);
        return;
    case MIP_FIELD_THREEDM_FACTORY_STREAMING:
        mip_threedm_factory_streaming_to_json(w, &value->u.threedm_factory_streaming);
        return;
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45:
        mip_threedm_data_stream_control_gx5_45_to_json(w, &value->u.threedm_data_stream_control_gx5_45);
        return;
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS:
        mip_threedm_data_stream_control_cv7_ins_to_json(w, &value->u.threedm_data_stream_control_cv7_ins);
        return;
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45:
        mip_threedm_data_stream_control_response_gx5_45_to_json(
            w, &value->u.threedm_data_stream_control_response_gx5_45);
        return;
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS:
        mip_threedm_data_stream_control_response_cv7_ins_to_json(
            w, &value->u.threedm_data_stream_control_response_cv7_ins);
        return;
    case MIP_FIELD_THREEDM_RAW_RTCM_MESSAGE:
        mip_threedm_raw_rtcm_message_to_json(w, &value->u.threedm_raw_rtcm_message);
        return;
    case MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS:
        mip_threedm_gnss_constellation_settings_to_json(w, &value->u.threedm_gnss_constellation_settings);
        return;
    case MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE:
        mip_threedm_gnss_constellation_settings_response_to_json(
            w, &value->u.threedm_gnss_constellation_settings_response);
        return;
    case MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS:
        mip_threedm_gnss_sbas_settings_to_json(w, &value->u.threedm_gnss_sbas_settings);
        return;
    case MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE:
        mip_threedm_gnss_sbas_settings_response_to_json(w, &value->u.threedm_gnss_sbas_settings_response);
        return;
    case MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL:
        mip_threedm_gnss_assisted_fix_control_to_json(w, &value->u.threedm_gnss_assisted_fix_control);
        return;
    case MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE:
        mip_threedm_gnss_assisted_fix_control_response_to_json(
            w, &value->u.threedm_gnss_assisted_fix_control_response);
        return;
    case MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE:
        mip_threedm_gnss_assist_time_update_to_json(w, &value->u.threedm_gnss_assist_time_update);
        return;
    case MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE:
        mip_threedm_gnss_assist_time_update_response_to_json(
            w, &value->u.threedm_gnss_assist_time_update_response);
        return;
    case MIP_FIELD_THREEDM_PPS_SOURCE:
        mip_threedm_pps_source_to_json(w, &value->u.threedm_pps_source);
        return;
    case MIP_FIELD_THREEDM_PPS_SOURCE_RESPONSE:
        mip_threedm_pps_source_response_to_json(w, &value->u.threedm_pps_source_response);
        return;
    case MIP_FIELD_THREEDM_GET_SUPPORTED_EVENTS:
        mip_threedm_get_supported_events_to_json(w, &value->u.threedm_get_supported_events);
        return;
    case MIP_FIELD_THREEDM_SUPPORTED_EVENTS:
        mip_threedm_supported_events_to_json(w, &value->u.threedm_supported_events);
        return;
    case MIP_FIELD_THREEDM_DEVICE_STATUS:
        mip_threedm_device_status_to_json(w, &value->u.threedm_device_status);
        return;
    case MIP_FIELD_THREEDM_DEVICE_STATUS_RESPONSE:
        mip_threedm_device_status_response_to_json(w, &value->u.threedm_device_status_response);
        return;
    case MIP_FIELD_FILTER_RESET_FILTER:
        mip_filter_reset_filter_to_json(w, &value->u.filter_reset_filter);
        return;
    case MIP_FIELD_FILTER_SET_INITIAL_ATTITUDE:
        mip_filter_set_initial_attitude_to_json(w, &value->u.filter_set_initial_attitude);
        return;
    case MIP_FIELD_FILTER_SET_INITIAL_HEADING:
        mip_filter_set_initial_heading_to_json(w, &value->u.filter_set_initial_heading);
        return;
    case MIP_FIELD_FILTER_RUN_FILTER:
        mip_filter_run_filter_to_json(w, &value->u.filter_run_filter);
        return;
    case MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE:
        mip_filter_vehicle_dynamics_mode_to_json(w, &value->u.filter_vehicle_dynamics_mode);
        return;
    case MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE:
        mip_filter_vehicle_dynamics_mode_response_to_json(w, &value->u.filter_vehicle_dynamics_mode_response);
        return;
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM:
        mip_filter_sensor_to_vehicle_transform_to_json(w, &value->u.filter_sensor_to_vehicle_transform);
        return;
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE:
        mip_filter_sensor_to_vehicle_transform_response_to_json(
            w, &value->u.filter_sensor_to_vehicle_transform_response);
        return;
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET:
        mip_filter_sensor_to_vehicle_offset_to_json(w, &value->u.filter_sensor_to_vehicle_offset);
        return;
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE:
        mip_filter_sensor_to_vehicle_offset_response_to_json(
            w, &value->u.filter_sensor_to_vehicle_offset_response);
        return;
    case MIP_FIELD_FILTER_ANTENNA_OFFSET:
        mip_filter_antenna_offset_to_json(w, &value->u.filter_antenna_offset);
        return;
    case MIP_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE:
        mip_filter_antenna_offset_response_to_json(w, &value->u.filter_antenna_offset_response);
        return;
    case MIP_FIELD_FILTER_ESTIMATION_CONTROL:
        mip_filter_estimation_control_to_json(w, &value->u.filter_estimation_control);
        return;
    case MIP_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE:
        mip_filter_estimation_control_response_to_json(w, &value->u.filter_estimation_control_response);
        return;
    case MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL:
        mip_filter_gnss_source_control_to_json(w, &value->u.filter_gnss_source_control);
        return;
    case MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE:
        mip_filter_gnss_source_control_response_to_json(w, &value->u.filter_gnss_source_control_response);
        return;
    case MIP_FIELD_FILTER_EXTERNAL_GNSS_UPDATE:
        mip_filter_external_gnss_update_to_json(w, &value->u.filter_external_gnss_update);
        return;
    case MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE:
        mip_filter_external_heading_update_to_json(w, &value->u.filter_external_heading_update);
        return;
    case MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL:
        mip_filter_heading_update_control_to_json(w, &value->u.filter_heading_update_control);
        return;
    case MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE:
        mip_filter_heading_update_control_response_to_json(w,
                                                           &value->u.filter_heading_update_control_response);
        return;
    case MIP_FIELD_FILTER_AUTO_INIT_CONTROL:
        mip_filter_auto_init_control_to_json(w, &value->u.filter_auto_init_control);
        return;
    case MIP_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE:
        mip_filter_auto_init_control_response_to_json(w, &value->u.filter_auto_init_control_response);
        return;
    case MIP_FIELD_FILTER_ACCEL_NOISE:
        mip_filter_accel_noise_to_json(w, &value->u.filter_accel_noise);
        return;
    case MIP_FIELD_FILTER_ACCEL_NOISE_RESPONSE:
        mip_filter_accel_noise_response_to_json(w, &value->u.filter_accel_noise_response);
        return;
    case MIP_FIELD_FILTER_GYRO_NOISE:
        mip_filter_gyro_noise_to_json(w, &value->u.filter_gyro_noise);
        return;
    case MIP_FIELD_FILTER_GYRO_NOISE_RESPONSE:
        mip_filter_gyro_noise_response_to_json(w, &value->u.filter_gyro_noise_response);
        return;
    case MIP_FIELD_FILTER_ACCEL_BIAS_MODEL:
        mip_filter_accel_bias_model_to_json(w, &value->u.filter_accel_bias_model);
        return;
    case MIP_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE:
        mip_filter_accel_bias_model_response_to_json(w, &value->u.filter_accel_bias_model_response);
        return;
    case MIP_FIELD_FILTER_GYRO_BIAS_MODEL:
        mip_filter_gyro_bias_model_to_json(w, &value->u.filter_gyro_bias_model);
        return;
    case MIP_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE:
        mip_filter_gyro_bias_model_response_to_json(w, &value->u.filter_gyro_bias_model_response);
        return;
    case MIP_FIELD_FILTER_ZUPT_CONTROL:
        mip_filter_zupt_control_to_json(w, &value->u.filter_zupt_control);
        return;
    case MIP_FIELD_FILTER_ZUPT_CONTROL_RESPONSE:
        mip_filter_zupt_control_response_to_json(w, &value->u.filter_zupt_control_response);
        return;
    case MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME:
        mip_filter_external_heading_update_with_time_to_json(
            w, &value->u.filter_external_heading_update_with_time);
        return;
    case MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL:
        mip_filter_zero_angular_rate_update_control_to_json(
            w, &value->u.filter_zero_angular_rate_update_control);
        return;
    case MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE:
        mip_filter_zero_angular_rate_update_control_response_to_json(
            w, &value->u.filter_zero_angular_rate_update_control_response);
        return;
    case MIP_FIELD_FILTER_TARE_ORIENTATION:
        mip_filter_tare_orientation_to_json(w, &value->u.filter_tare_orientation);
        return;
    case MIP_FIELD_FILTER_COMMANDED_ZUPT:
        mip_filter_commanded_zupt_to_json(w, &value->u.filter_commanded_zupt);
        return;
    case MIP_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE:
        mip_filter_commanded_zero_angular_rate_update_to_json(
            w, &value->u.filter_commanded_zero_angular_rate_update);
        return;
    case MIP_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION:
        mip_filter_mag_capture_auto_calibration_to_json(w, &value->u.filter_mag_capture_auto_calibration);
        return;
    case MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV:
        mip_filter_gravity_noise_std_dev_to_json(w, &value->u.filter_gravity_noise_std_dev);
        return;
    case MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE:
        mip_filter_gravity_noise_std_dev_response_to_json(w, &value->u.filter_gravity_noise_std_dev_response);
        return;
    case MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV:
        mip_filter_pressure_altitude_noise_std_dev_to_json(w,
                                                           &value->u.filter_pressure_altitude_noise_std_dev);
        return;
    case MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE:
        mip_filter_pressure_altitude_noise_std_dev_response_to_json(
            w, &value->u.filter_pressure_altitude_noise_std_dev_response);
        return;
    case MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE:
        mip_filter_hard_iron_offset_noise_to_json(w, &value->u.filter_hard_iron_offset_noise);
        return;
    case MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE:
        mip_filter_hard_iron_offset_noise_response_to_json(w,
                                                           &value->u.filter_hard_iron_offset_noise_response);
        return;
    case MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE:
        mip_filter_soft_iron_matrix_noise_to_json(w, &value->u.filter_soft_iron_matrix_noise);
        return;
    case MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE:
        mip_filter_soft_iron_matrix_noise_response_to_json(w,
                                                           &value->u.filter_soft_iron_matrix_noise_response);
        return;
    case MIP_FIELD_FILTER_MAG_NOISE_STD_DEV:
        mip_filter_mag_noise_std_dev_to_json(w, &value->u.filter_mag_noise_std_dev);
        return;
    case MIP_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE:
        mip_filter_mag_noise_std_dev_response_to_json(w, &value->u.filter_mag_noise_std_dev_response);
        return;
    case MIP_FIELD_FILTER_DECLINATION_SOURCE:
        mip_filter_declination_source_to_json(w, &value->u.filter_declination_source);
        return;
    case MIP_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE:
        mip_filter_declination_source_response_to_json(w, &value->u.filter_declination_source_response);
        return;
    case MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        mip_filter_gravity_magnitude_adaptive_measurement_to_json(
            w, &value->u.filter_gravity_magnitude_adaptive_measurement);
        return;
    case MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        mip_filter_gravity_magnitude_adaptive_measurement_response_to_json(
            w, &value->u.filter_gravity_magnitude_adaptive_measurement_response);
        return;
    case MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        mip_filter_mag_magnitude_adaptive_measurement_to_json(
            w, &value->u.filter_mag_magnitude_adaptive_measurement);
        return;
    case MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        mip_filter_mag_magnitude_adaptive_measurement_response_to_json(
            w, &value->u.filter_mag_magnitude_adaptive_measurement_response);
        return;
    case MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT:
        mip_filter_mag_dip_angle_adaptive_measurement_to_json(
            w, &value->u.filter_mag_dip_angle_adaptive_measurement);
        return;
    case MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE:
        mip_filter_mag_dip_angle_adaptive_measurement_response_to_json(
            w, &value->u.filter_mag_dip_angle_adaptive_measurement_response);
        return;
    case MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL:
        mip_filter_altitude_aiding_control_to_json(w, &value->u.filter_altitude_aiding_control);
        return;
    case MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE:
        mip_filter_altitude_aiding_control_response_to_json(
            w, &value->u.filter_altitude_aiding_control_response);
        return;
    case MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL:
        mip_filter_pitch_roll_aiding_control_to_json(w, &value->u.filter_pitch_roll_aiding_control);
        return;
    case MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE:
        mip_filter_pitch_roll_aiding_control_response_to_json(
            w, &value->u.filter_pitch_roll_aiding_control_response);
        return;
    case MIP_FIELD_FILTER_INCLINATION_SOURCE:
        mip_filter_inclination_source_to_json(w, &value->u.filter_inclination_source);
        return;
    case MIP_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE:
        mip_filter_inclination_source_response_to_json(w, &value->u.filter_inclination_source_response);
        return;
    case MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE:
        mip_filter_magnetic_field_magnitude_source_to_json(w,
                                                           &value->u.filter_magnetic_field_magnitude_source);
        return;
    case MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE:
        mip_filter_magnetic_field_magnitude_source_response_to_json(
            w, &value->u.filter_magnetic_field_magnitude_source_response);
        return;
    case MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL:
        mip_filter_aiding_measurement_control_to_json(w, &value->u.filter_aiding_measurement_control);
        return;
    case MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE:
        mip_filter_aiding_measurement_control_response_to_json(
            w, &value->u.filter_aiding_measurement_control_response);
        return;
    case MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION:
        mip_filter_initialization_configuration_to_json(w, &value->u.filter_initialization_configuration);
        return;
    case MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE:
        mip_filter_initialization_configuration_response_to_json(
            w, &value->u.filter_initialization_configuration_response);
        return;
    case MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL:
        mip_filter_adaptive_filter_control_to_json(w, &value->u.filter_adaptive_filter_control);
        return;
    case MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE:
        mip_filter_adaptive_filter_control_response_to_json(
            w, &value->u.filter_adaptive_filter_control_response);
        return;
    case MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET:
        mip_filter_multi_antenna_offset_to_json(w, &value->u.filter_multi_antenna_offset);
        return;
    case MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE:
        mip_filter_multi_antenna_offset_response_to_json(w, &value->u.filter_multi_antenna_offset_response);
        return;
    case MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION:
        mip_filter_relative_position_configuration_to_json(w,
                                                           &value->u.filter_relative_position_configuration);
        return;
    case MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE:
        mip_filter_relative_position_configuration_response_to_json(
            w, &value->u.filter_relative_position_configuration_response);
        return;
    case MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM:
        mip_filter_reference_point_lever_arm_to_json(w, &value->u.filter_reference_point_lever_arm);
        return;
    case MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE:
        mip_filter_reference_point_lever_arm_response_to_json(
            w, &value->u.filter_reference_point_lever_arm_response);
        return;
    case MIP_FIELD_FILTER_SPEED_LEVER_ARM:
        mip_filter_speed_lever_arm_to_json(w, &value->u.filter_speed_lever_arm);
        return;
    case MIP_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE:
        mip_filter_speed_lever_arm_response_to_json(w, &value->u.filter_speed_lever_arm_response);
        return;
    case MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL:
        mip_filter_wheeled_vehicle_constraint_control_to_json(
            w, &value->u.filter_wheeled_vehicle_constraint_control);
        return;
    case MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE:
        mip_filter_wheeled_vehicle_constraint_control_response_to_json(
            w, &value->u.filter_wheeled_vehicle_constraint_control_response);
        return;
    case MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL:
        mip_filter_gnss_antenna_calibration_control_to_json(
            w, &value->u.filter_gnss_antenna_calibration_control);
        return;
    case MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE:
        mip_filter_gnss_antenna_calibration_control_response_to_json(
            w, &value->u.filter_gnss_antenna_calibration_control_response);
        return;
    case MIP_FIELD_GNSS_RECEIVER_INFO:
        mip_gnss_receiver_info_to_json(w, &value->u.gnss_receiver_info);
        return;
    case MIP_FIELD_GNSS_RECEIVER_INFO_RESPONSE:
        mip_gnss_receiver_info_response_to_json(w, &value->u.gnss_receiver_info_response);
        return;
    case MIP_FIELD_GNSS_SIGNAL_CONFIGURATION:
        mip_gnss_signal_configuration_to_json(w, &value->u.gnss_signal_configuration);
        return;
    case MIP_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE:
        mip_gnss_signal_configuration_response_to_json(w, &value->u.gnss_signal_configuration_response);
        return;
    case MIP_FIELD_GNSS_SPARTN_CONFIGURATION:
        mip_gnss_spartn_configuration_to_json(w, &value->u.gnss_spartn_configuration);
        return;
    case MIP_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE:
        mip_gnss_spartn_configuration_response_to_json(w, &value->u.gnss_spartn_configuration_response);
        return;
    case MIP_FIELD_AIDING_FRAME_CONFIG:
        mip_aiding_frame_config_to_json(w, &value->u.aiding_frame_config);
        return;
    case MIP_FIELD_AIDING_FRAME_CONFIG_RESPONSE:
        mip_aiding_frame_config_response_to_json(w, &value->u.aiding_frame_config_response);
        return;
    case MIP_FIELD_AIDING_ECHO_CONTROL:
        mip_aiding_echo_control_to_json(w, &value->u.aiding_echo_control);
        return;
    case MIP_FIELD_AIDING_ECHO_CONTROL_RESPONSE:
        mip_aiding_echo_control_response_to_json(w, &value->u.aiding_echo_control_response);
        return;
    case MIP_FIELD_AIDING_ECEF_POSITION:
        mip_aiding_ecef_position_to_json(w, &value->u.aiding_ecef_position);
        return;
    case MIP_FIELD_AIDING_LLH_POSITION:
        mip_aiding_llh_position_to_json(w, &value->u.aiding_llh_position);
        return;
    case MIP_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID:
        mip_aiding_height_above_ellipsoid_to_json(w, &value->u.aiding_height_above_ellipsoid);
        return;
    case MIP_FIELD_AIDING_ECEF_VELOCITY:
        mip_aiding_ecef_velocity_to_json(w, &value->u.aiding_ecef_velocity);
        return;
    case MIP_FIELD_AIDING_NED_VELOCITY:
        mip_aiding_ned_velocity_to_json(w, &value->u.aiding_ned_velocity);
        return;
    case MIP_FIELD_AIDING_BODY_FRAME_VELOCITY:
        mip_aiding_body_frame_velocity_to_json(w, &value->u.aiding_body_frame_velocity);
        return;
    case MIP_FIELD_AIDING_TRUE_HEADING:
        mip_aiding_true_heading_to_json(w, &value->u.aiding_true_heading);
        return;
    case MIP_FIELD_AIDING_MAGNETIC_FIELD:
        mip_aiding_magnetic_field_to_json(w, &value->u.aiding_magnetic_field);
        return;
    case MIP_FIELD_AIDING_PRESSURE:
        mip_aiding_pressure_to_json(w, &value->u.aiding_pressure);
        return;
    case MIP_FIELD_SYSTEM_COMMUNICATION_MODE:
        mip_system_communication_mode_to_json(w, &value->u.system_communication_mode);
        return;
    case MIP_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE:
        mip_system_communication_mode_response_to_json(w, &value->u.system_communication_mode_response);
        return;
    case MIP_FIELD_SENSOR_SCALED_ACCEL:
        mip_sensor_scaled_accel_to_json(w, &value->u.sensor_scaled_accel);
        return;
    case MIP_FIELD_SENSOR_SCALED_GYRO:
        mip_sensor_scaled_gyro_to_json(w, &value->u.sensor_scaled_gyro);
        return;
    case MIP_FIELD_SENSOR_SCALED_MAG:
        mip_sensor_scaled_mag_to_json(w, &value->u.sensor_scaled_mag);
        return;
    case MIP_FIELD_SENSOR_DELTA_THETA:
        mip_sensor_delta_theta_to_json(w, &value->u.sensor_delta_theta);
        return;
    case MIP_FIELD_SENSOR_DELTA_VELOCITY:
        mip_sensor_delta_velocity_to_json(w, &value->u.sensor_delta_velocity);
        return;
    case MIP_FIELD_SENSOR_CF_ORIENTATION_MATRIX:
        mip_sensor_cf_orientation_matrix_to_json(w, &value->u.sensor_cf_orientation_matrix);
        return;
    case MIP_FIELD_SENSOR_CF_QUATERNION:
        mip_sensor_cf_quaternion_to_json(w, &value->u.sensor_cf_quaternion);
        return;
    case MIP_FIELD_SENSOR_CF_EULER_ANGLES:
        mip_sensor_cf_euler_angles_to_json(w, &value->u.sensor_cf_euler_angles);
        return;
    case MIP_FIELD_SENSOR_CF_STABILIZED_NORTH:
        mip_sensor_cf_stabilized_north_to_json(w, &value->u.sensor_cf_stabilized_north);
        return;
    case MIP_FIELD_SENSOR_CF_STABILIZED_UP:
        mip_sensor_cf_stabilized_up_to_json(w, &value->u.sensor_cf_stabilized_up);
        return;
    case MIP_FIELD_SENSOR_GPS_TIMESTAMP:
        mip_sensor_gps_timestamp_to_json(w, &value->u.sensor_gps_timestamp);
        return;
    case MIP_FIELD_SENSOR_TEMPERATURE_STATISTICS:
        mip_sensor_temperature_statistics_to_json(w, &value->u.sensor_temperature_statistics);
        return;
    case MIP_FIELD_SENSOR_SCALED_PRESSURE:
        mip_sensor_scaled_pressure_to_json(w, &value->u.sensor_scaled_pressure);
        return;
    case MIP_FIELD_SENSOR_OVERRANGE_STATUS:
        mip_sensor_overrange_status_to_json(w, &value->u.sensor_overrange_status);
        return;
    case MIP_FIELD_SENSOR_ODOMETER_DATA:
        mip_sensor_odometer_data_to_json(w, &value->u.sensor_odometer_data);
        return;
    case MIP_FIELD_GNSS_DATA_LLH_POSITION:
        mip_gnss_data_llh_position_to_json(w, &value->u.gnss_data_llh_position);
        return;
    case MIP_FIELD_GNSS_DATA_ECEF_POSITION:
        mip_gnss_data_ecef_position_to_json(w, &value->u.gnss_data_ecef_position);
        return;
    case MIP_FIELD_GNSS_DATA_NED_VELOCITY:
        mip_gnss_data_ned_velocity_to_json(w, &value->u.gnss_data_ned_velocity);
        return;
    case MIP_FIELD_GNSS_DATA_ECEF_VELOCITY:
        mip_gnss_data_ecef_velocity_to_json(w, &value->u.gnss_data_ecef_velocity);
        return;
    case MIP_FIELD_GNSS_DATA_DOP:
        mip_gnss_data_dop_to_json(w, &value->u.gnss_data_dop);
        return;
    case MIP_FIELD_GNSS_DATA_UTC_TIME:
        mip_gnss_data_utc_time_to_json(w, &value->u.gnss_data_utc_time);
        return;
    case MIP_FIELD_GNSS_DATA_GPS_TIME:
        mip_gnss_data_gps_time_to_json(w, &value->u.gnss_data_gps_time);
        return;
    case MIP_FIELD_GNSS_DATA_CLOCK_INFO:
        mip_gnss_data_clock_info_to_json(w, &value->u.gnss_data_clock_info);
        return;
    case MIP_FIELD_GNSS_DATA_FIX_INFO:
        mip_gnss_data_fix_info_to_json(w, &value->u.gnss_data_fix_info);
        return;
    case MIP_FIELD_GNSS_DATA_SV_INFO:
        mip_gnss_data_sv_info_to_json(w, &value->u.gnss_data_sv_info);
        return;
    case MIP_FIELD_GNSS_DATA_HARDWARE_STATUS:
        mip_gnss_data_hardware_status_to_json(w, &value->u.gnss_data_hardware_status);
        return;
    case MIP_FIELD_GNSS_DATA_DGNSS_INFO:
        mip_gnss_data_dgnss_info_to_json(w, &value->u.gnss_data_dgnss_info);
        return;
    case MIP_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS:
        mip_gnss_data_dgnss_channel_status_to_json(w, &value->u.gnss_data_dgnss_channel_status);
        return;
    case MIP_FIELD_FILTER_DATA_LLH_POSITION:
        mip_filter_data_llh_position_to_json(w, &value->u.filter_data_llh_position);
        return;
    case MIP_FIELD_FILTER_DATA_NED_VELOCITY:
        mip_filter_data_ned_velocity_to_json(w, &value->u.filter_data_ned_velocity);
        return;
    case MIP_FIELD_FILTER_DATA_ATTITUDE_QUATERNION:
        mip_filter_data_attitude_quaternion_to_json(w, &value->u.filter_data_attitude_quaternion);
        return;
    case MIP_FIELD_FILTER_DATA_ATTITUDE_DCM:
        mip_filter_data_attitude_dcm_to_json(w, &value->u.filter_data_attitude_dcm);
        return;
    case MIP_FIELD_FILTER_DATA_EULER_ANGLES:
        mip_filter_data_euler_angles_to_json(w, &value->u.filter_data_euler_angles);
        return;
    case MIP_FIELD_FILTER_DATA_GYRO_BIAS:
        mip_filter_data_gyro_bias_to_json(w, &value->u.filter_data_gyro_bias);
        return;
    case MIP_FIELD_FILTER_DATA_ACCEL_BIAS:
        mip_filter_data_accel_bias_to_json(w, &value->u.filter_data_accel_bias);
        return;
    case MIP_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY:
        mip_filter_data_llh_position_uncertainty_to_json(w, &value->u.filter_data_llh_position_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY:
        mip_filter_data_ned_velocity_uncertainty_to_json(w, &value->u.filter_data_ned_velocity_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY:
        mip_filter_data_euler_angles_uncertainty_to_json(w, &value->u.filter_data_euler_angles_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY:
        mip_filter_data_gyro_bias_uncertainty_to_json(w, &value->u.filter_data_gyro_bias_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY:
        mip_filter_data_accel_bias_uncertainty_to_json(w, &value->u.filter_data_accel_bias_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_LINEAR_ACCEL:
        mip_filter_data_linear_accel_to_json(w, &value->u.filter_data_linear_accel);
        return;
    case MIP_FIELD_FILTER_DATA_COMP_ANGULAR_RATE:
        mip_filter_data_comp_angular_rate_to_json(w, &value->u.filter_data_comp_angular_rate);
        return;
    case MIP_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE:
        mip_filter_data_wgs84_gravity_magnitude_to_json(w, &value->u.filter_data_wgs84_gravity_magnitude);
        return;
    case MIP_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45:
        mip_filter_data_filter_status_gx5_45_to_json(w, &value->u.filter_data_filter_status_gx5_45);
        return;
    case MIP_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS:
        mip_filter_data_filter_status_cv7_ins_to_json(w, &value->u.filter_data_filter_status_cv7_ins);
        return;
    case MIP_FIELD_FILTER_DATA_GPS_TIMESTAMP:
        mip_filter_data_gps_timestamp_to_json(w, &value->u.filter_data_gps_timestamp);
        return;
    case MIP_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY:
        mip_filter_data_quaternion_attitude_uncertainty_to_json(
            w, &value->u.filter_data_quaternion_attitude_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_GRAVITY_VECTOR:
        mip_filter_data_gravity_vector_to_json(w, &value->u.filter_data_gravity_vector);
        return;
    case MIP_FIELD_FILTER_DATA_HEADING_UPDATE_STATE:
        mip_filter_data_heading_update_state_to_json(w, &value->u.filter_data_heading_update_state);
        return;
    case MIP_FIELD_FILTER_DATA_MAGNETIC_MODEL:
        mip_filter_data_magnetic_model_to_json(w, &value->u.filter_data_magnetic_model);
        return;
    case MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR:
        mip_filter_data_gyro_scale_factor_to_json(w, &value->u.filter_data_gyro_scale_factor);
        return;
    case MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR:
        mip_filter_data_accel_scale_factor_to_json(w, &value->u.filter_data_accel_scale_factor);
        return;
    case MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY:
        mip_filter_data_gyro_scale_factor_uncertainty_to_json(
            w, &value->u.filter_data_gyro_scale_factor_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY:
        mip_filter_data_accel_scale_factor_uncertainty_to_json(
            w, &value->u.filter_data_accel_scale_factor_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_COMPENSATED_ACCEL:
        mip_filter_data_compensated_accel_to_json(w, &value->u.filter_data_compensated_accel);
        return;
    case MIP_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE:
        mip_filter_data_standard_atmosphere_to_json(w, &value->u.filter_data_standard_atmosphere);
        return;
    case MIP_FIELD_FILTER_DATA_PRESSURE_ALTITUDE:
        mip_filter_data_pressure_altitude_to_json(w, &value->u.filter_data_pressure_altitude);
        return;
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET:
        mip_filter_data_mag_auto_hard_iron_offset_to_json(w, &value->u.filter_data_mag_auto_hard_iron_offset);
        return;
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX:
        mip_filter_data_mag_auto_soft_iron_matrix_to_json(w, &value->u.filter_data_mag_auto_soft_iron_matrix);
        return;
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY:
        mip_filter_data_mag_auto_hard_iron_offset_uncertainty_to_json(
            w, &value->u.filter_data_mag_auto_hard_iron_offset_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY:
        mip_filter_data_mag_auto_soft_iron_matrix_uncertainty_to_json(
            w, &value->u.filter_data_mag_auto_soft_iron_matrix_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION:
        mip_filter_data_gnss_antenna_offset_correction_to_json(
            w, &value->u.filter_data_gnss_antenna_offset_correction);
        return;
    case MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        mip_filter_data_gnss_antenna_offset_correction_uncertainty_to_json(
            w, &value->u.filter_data_gnss_antenna_offset_correction_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION:
        mip_filter_data_multi_antenna_offset_correction_to_json(
            w, &value->u.filter_data_multi_antenna_offset_correction);
        return;
    case MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        mip_filter_data_multi_antenna_offset_correction_uncertainty_to_json(
            w, &value->u.filter_data_multi_antenna_offset_correction_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY:
        mip_filter_data_ecef_position_uncertainty_to_json(w, &value->u.filter_data_ecef_position_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY:
        mip_filter_data_ecef_velocity_uncertainty_to_json(w, &value->u.filter_data_ecef_velocity_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_ECEF_POSITION:
        mip_filter_data_ecef_position_to_json(w, &value->u.filter_data_ecef_position);
        return;
    case MIP_FIELD_FILTER_DATA_ECEF_VELOCITY:
        mip_filter_data_ecef_velocity_to_json(w, &value->u.filter_data_ecef_velocity);
        return;
    case MIP_FIELD_FILTER_DATA_NED_RELATIVE_POSITION:
        mip_filter_data_ned_relative_position_to_json(w, &value->u.filter_data_ned_relative_position);
        return;
    case MIP_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS:
        mip_filter_data_gnss_position_aiding_status_to_json(
            w, &value->u.filter_data_gnss_position_aiding_status);
        return;
    case MIP_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY:
        mip_filter_data_aiding_measurement_summary_to_json(w,
                                                           &value->u.filter_data_aiding_measurement_summary);
        return;
    case MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR:
        mip_filter_data_odometer_scale_factor_error_to_json(
            w, &value->u.filter_data_odometer_scale_factor_error);
        return;
    case MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY:
        mip_filter_data_odometer_scale_factor_error_uncertainty_to_json(
            w, &value->u.filter_data_odometer_scale_factor_error_uncertainty);
        return;
    case MIP_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS:
        mip_filter_data_gnss_dual_antenna_status_to_json(w, &value->u.filter_data_gnss_dual_antenna_status);
        return;
    case MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR:
        mip_filter_data_aiding_frame_config_error_to_json(w, &value->u.filter_data_aiding_frame_config_error);
        return;
    case MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY:
        mip_filter_data_aiding_frame_config_error_uncertainty_to_json(
            w, &value->u.filter_data_aiding_frame_config_error_uncertainty);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_LLH_POSITION:
        mip_gnss_receiver_1_llh_position_to_json(w, &value->u.gnss_receiver_1_llh_position);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_ECEF_POSITION:
        mip_gnss_receiver_1_ecef_position_to_json(w, &value->u.gnss_receiver_1_ecef_position);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_NED_VELOCITY:
        mip_gnss_receiver_1_ned_velocity_to_json(w, &value->u.gnss_receiver_1_ned_velocity);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY:
        mip_gnss_receiver_1_ecef_velocity_to_json(w, &value->u.gnss_receiver_1_ecef_velocity);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_DOP:
        mip_gnss_receiver_1_dop_to_json(w, &value->u.gnss_receiver_1_dop);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_UTC_TIME:
        mip_gnss_receiver_1_utc_time_to_json(w, &value->u.gnss_receiver_1_utc_time);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_TIME:
        mip_gnss_receiver_1_gps_time_to_json(w, &value->u.gnss_receiver_1_gps_time);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_FIX_INFO:
        mip_gnss_receiver_1_fix_info_to_json(w, &value->u.gnss_receiver_1_fix_info);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS:
        mip_gnss_receiver_1_hardware_status_to_json(w, &value->u.gnss_receiver_1_hardware_status);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2:
        mip_gnss_receiver_1_clock_info_2_to_json(w, &value->u.gnss_receiver_1_clock_info_2);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS:
        mip_gnss_receiver_1_gps_leap_seconds_to_json(w, &value->u.gnss_receiver_1_gps_leap_seconds);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_SBAS_INFO:
        mip_gnss_receiver_1_sbas_info_to_json(w, &value->u.gnss_receiver_1_sbas_info);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS:
        mip_gnss_receiver_1_satellite_status_to_json(w, &value->u.gnss_receiver_1_satellite_status);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_RAW:
        mip_gnss_receiver_1_raw_to_json(w, &value->u.gnss_receiver_1_raw);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS:
        mip_gnss_receiver_1_gps_ephemeris_to_json(w, &value->u.gnss_receiver_1_gps_ephemeris);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS:
        mip_gnss_receiver_1_glonass_ephemeris_to_json(w, &value->u.gnss_receiver_1_glonass_ephemeris);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS:
        mip_gnss_receiver_1_galileo_ephemeris_to_json(w, &value->u.gnss_receiver_1_galileo_ephemeris);
        return;
    case MIP_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS:
        mip_gnss_receiver_1_beidou_ephemeris_to_json(w, &value->u.gnss_receiver_1_beidou_ephemeris);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_LLH_POSITION:
        mip_gnss_receiver_2_llh_position_to_json(w, &value->u.gnss_receiver_2_llh_position);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_ECEF_POSITION:
        mip_gnss_receiver_2_ecef_position_to_json(w, &value->u.gnss_receiver_2_ecef_position);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_NED_VELOCITY:
        mip_gnss_receiver_2_ned_velocity_to_json(w, &value->u.gnss_receiver_2_ned_velocity);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY:
        mip_gnss_receiver_2_ecef_velocity_to_json(w, &value->u.gnss_receiver_2_ecef_velocity);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_DOP:
        mip_gnss_receiver_2_dop_to_json(w, &value->u.gnss_receiver_2_dop);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_UTC_TIME:
        mip_gnss_receiver_2_utc_time_to_json(w, &value->u.gnss_receiver_2_utc_time);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_TIME:
        mip_gnss_receiver_2_gps_time_to_json(w, &value->u.gnss_receiver_2_gps_time);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_FIX_INFO:
        mip_gnss_receiver_2_fix_info_to_json(w, &value->u.gnss_receiver_2_fix_info);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS:
        mip_gnss_receiver_2_hardware_status_to_json(w, &value->u.gnss_receiver_2_hardware_status);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2:
        mip_gnss_receiver_2_clock_info_2_to_json(w, &value->u.gnss_receiver_2_clock_info_2);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS:
        mip_gnss_receiver_2_gps_leap_seconds_to_json(w, &value->u.gnss_receiver_2_gps_leap_seconds);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_SBAS_INFO:
        mip_gnss_receiver_2_sbas_info_to_json(w, &value->u.gnss_receiver_2_sbas_info);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS:
        mip_gnss_receiver_2_satellite_status_to_json(w, &value->u.gnss_receiver_2_satellite_status);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_RAW:
        mip_gnss_receiver_2_raw_to_json(w, &value->u.gnss_receiver_2_raw);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS:
        mip_gnss_receiver_2_gps_ephemeris_to_json(w, &value->u.gnss_receiver_2_gps_ephemeris);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS:
        mip_gnss_receiver_2_glonass_ephemeris_to_json(w, &value->u.gnss_receiver_2_glonass_ephemeris);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS:
        mip_gnss_receiver_2_galileo_ephemeris_to_json(w, &value->u.gnss_receiver_2_galileo_ephemeris);
        return;
    case MIP_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS:
        mip_gnss_receiver_2_beidou_ephemeris_to_json(w, &value->u.gnss_receiver_2_beidou_ephemeris);
        return;
    case MIP_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO:
        mip_gnss_corrections_base_station_info_to_json(w, &value->u.gnss_corrections_base_station_info);
        return;
    case MIP_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS:
        mip_gnss_corrections_rtk_corrections_status_to_json(
            w, &value->u.gnss_corrections_rtk_corrections_status);
        return;
    case MIP_FIELD_GNSS_EXTERNAL_LLH_POSITION:
        mip_gnss_external_llh_position_to_json(w, &value->u.gnss_external_llh_position);
        return;
    case MIP_FIELD_GNSS_EXTERNAL_NED_VELOCITY:
        mip_gnss_external_ned_velocity_to_json(w, &value->u.gnss_external_ned_velocity);
        return;
    case MIP_FIELD_GNSS_EXTERNAL_UTC_TIME:
        mip_gnss_external_utc_time_to_json(w, &value->u.gnss_external_utc_time);
        return;
    case MIP_FIELD_GNSS_EXTERNAL_FIX_INFO:
        mip_gnss_external_fix_info_to_json(w, &value->u.gnss_external_fix_info);
        return;
    case MIP_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS:
        mip_gnss_external_satellite_status_to_json(w, &value->u.gnss_external_satellite_status);
        return;
    case MIP_FIELD_SYSTEM_DATA_BUILT_IN_TEST:
        mip_system_data_built_in_test_to_json(w, &value->u.system_data_built_in_test);
        return;
    case MIP_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS:
        mip_system_data_time_sync_status_to_json(w, &value->u.system_data_time_sync_status);
        return;
    case MIP_FIELD_SYSTEM_DATA_GPIO_STATE:
        mip_system_data_gpio_state_to_json(w, &value->u.system_data_gpio_state);
        return;
    case MIP_FIELD_SHARED_EVENT_SOURCE:
        mip_shared_event_source_to_json(w, &value->u.shared_event_source);
        return;
    case MIP_FIELD_SHARED_GPS_TIMESTAMP:
        mip_shared_gps_timestamp_to_json(w, &value->u.shared_gps_timestamp);
        return;
    case MIP_FIELD_SHARED_DELTA_TIME:
        mip_shared_delta_time_to_json(w, &value->u.shared_delta_time);
        return;
    case MIP_FIELD_SHARED_REFERENCE_TIMESTAMP:
        mip_shared_reference_timestamp_to_json(w, &value->u.shared_reference_timestamp);
        return;
    case MIP_FIELD_SHARED_REFERENCE_TIME_DELTA:
        mip_shared_reference_time_delta_to_json(w, &value->u.shared_reference_time_delta);
        return;
    case MIP_FIELD_SHARED_EXTERNAL_TIMESTAMP:
        mip_shared_external_timestamp_to_json(w, &value->u.shared_external_timestamp);
        return;
    case MIP_FIELD_SHARED_EXTERNAL_TIME_DELTA:
        mip_shared_external_time_delta_to_json(w, &value->u.shared_external_time_delta);
        return;
    case MIP_FIELD_NONE:
    case MIP_FIELD_COUNT:
    default:
        mip_jw_lit(w, "null");
        return;
    }
}

int mip_value_from_json(mip_jr_t *jr, size_t pos, mip_field_id_t id, mip_field_value_t *value) {
    value->id = id;
    switch (id) {
    case MIP_FIELD_ACK_NACK:
        return mip_ack_nack_from_json(jr, pos, &value->u.ack_nack);
    case MIP_FIELD_BASE_PING:
        return mip_base_ping_from_json(jr, pos, &value->u.base_ping);
    case MIP_FIELD_BASE_SET_TO_IDLE:
        return mip_base_set_to_idle_from_json(jr, pos, &value->u.base_set_to_idle);
    case MIP_FIELD_BASE_GET_DEVICE_INFO:
        return mip_base_get_device_info_from_json(jr, pos, &value->u.base_get_device_info);
    case MIP_FIELD_BASE_DEVICE_INFO:
        return mip_base_device_info_from_json(jr, pos, &value->u.base_device_info);
    case MIP_FIELD_BASE_GET_DEVICE_DESCRIPTORS:
        return mip_base_get_device_descriptors_from_json(jr, pos, &value->u.base_get_device_descriptors);
    case MIP_FIELD_BASE_DEVICE_DESCRIPTORS:
        return mip_base_device_descriptors_from_json(jr, pos, &value->u.base_device_descriptors);
    case MIP_FIELD_BASE_BUILT_IN_TEST:
        return mip_base_built_in_test_from_json(jr, pos, &value->u.base_built_in_test);
    case MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45:
        return mip_base_built_in_test_result_gx5_45_from_json(jr, pos,
                                                              &value->u.base_built_in_test_result_gx5_45);
    case MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS:
        return mip_base_built_in_test_result_cv7_ins_from_json(jr, pos,
                                                               &value->u.base_built_in_test_result_cv7_ins);
    case MIP_FIELD_BASE_RESUME:
        return mip_base_resume_from_json(jr, pos, &value->u.base_resume);
    case MIP_FIELD_BASE_GET_EXTENDED_DESCRIPTORS:
        return mip_base_get_extended_descriptors_from_json(jr, pos, &value->u.base_get_extended_descriptors);
    case MIP_FIELD_BASE_EXTENDED_DESCRIPTORS:
        return mip_base_extended_descriptors_from_json(jr, pos, &value->u.base_extended_descriptors);
    case MIP_FIELD_BASE_CONTINUOUS_BIT:
        return mip_base_continuous_bit_from_json(jr, pos, &value->u.base_continuous_bit);
    case MIP_FIELD_BASE_CONTINUOUS_BIT_RESULT:
        return mip_base_continuous_bit_result_from_json(jr, pos, &value->u.base_continuous_bit_result);
    case MIP_FIELD_BASE_COMM_PORT_SPEED:
        return mip_base_comm_port_speed_from_json(jr, pos, &value->u.base_comm_port_speed);
    case MIP_FIELD_BASE_COMM_PORT_SPEED_RESPONSE:
        return mip_base_comm_port_speed_response_from_json(jr, pos, &value->u.base_comm_port_speed_response);
    case MIP_FIELD_BASE_GPS_TIME_UPDATE_GX5_45:
        return mip_base_gps_time_update_gx5_45_from_json(jr, pos, &value->u.base_gps_time_update_gx5_45);
    case MIP_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS:
        return mip_base_gps_time_update_cv7_ins_from_json(jr, pos, &value->u.base_gps_time_update_cv7_ins);
    case MIP_FIELD_BASE_GPS_WEEK:
        return mip_base_gps_week_from_json(jr, pos, &value->u.base_gps_week);
    case MIP_FIELD_BASE_GPS_SECONDS:
        return mip_base_gps_seconds_from_json(jr, pos, &value->u.base_gps_seconds);
    case MIP_FIELD_BASE_DEVICE_RESET:
        return mip_base_device_reset_from_json(jr, pos, &value->u.base_device_reset);
    case MIP_FIELD_THREEDM_EVENT_CONTROL:
        return mip_threedm_event_control_from_json(jr, pos, &value->u.threedm_event_control);
    case MIP_FIELD_THREEDM_EVENT_CONTROL_RESPONSE:
        return mip_threedm_event_control_response_from_json(jr, pos,
                                                            &value->u.threedm_event_control_response);
    case MIP_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS:
        return mip_threedm_get_event_trigger_status_from_json(jr, pos,
                                                              &value->u.threedm_get_event_trigger_status);
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_STATUS:
        return mip_threedm_event_trigger_status_from_json(jr, pos, &value->u.threedm_event_trigger_status);
    case MIP_FIELD_THREEDM_GET_EVENT_ACTION_STATUS:
        return mip_threedm_get_event_action_status_from_json(jr, pos,
                                                             &value->u.threedm_get_event_action_status);
    case MIP_FIELD_THREEDM_EVENT_ACTION_STATUS:
        return mip_threedm_event_action_status_from_json(jr, pos, &value->u.threedm_event_action_status);
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG:
        return mip_threedm_event_trigger_config_from_json(jr, pos, &value->u.threedm_event_trigger_config);
    case MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE:
        return mip_threedm_event_trigger_config_response_from_json(
            jr, pos, &value->u.threedm_event_trigger_config_response);
    case MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG:
        return mip_threedm_event_action_config_from_json(jr, pos, &value->u.threedm_event_action_config);
    case MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE:
        return mip_threedm_event_action_config_response_from_json(
            jr, pos, &value->u.threedm_event_action_config_response);
    case MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45:
        return mip_threedm_device_startup_settings_gx5_45_from_json(
            jr, pos, &value->u.threedm_device_startup_settings_gx5_45);
    case MIP_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS:
        return mip_threedm_device_startup_settings_cv7_ins_from_json(
            jr, pos, &value->u.threedm_device_startup_settings_cv7_ins);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER:
        return mip_threedm_sensor_to_vehicle_euler_from_json(jr, pos,
                                                             &value->u.threedm_sensor_to_vehicle_euler);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE:
        return mip_threedm_sensor_to_vehicle_euler_response_from_json(
            jr, pos, &value->u.threedm_sensor_to_vehicle_euler_response);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION:
        return mip_threedm_sensor_to_vehicle_quaternion_from_json(
            jr, pos, &value->u.threedm_sensor_to_vehicle_quaternion);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE:
        return mip_threedm_sensor_to_vehicle_quaternion_response_from_json(
            jr, pos, &value->u.threedm_sensor_to_vehicle_quaternion_response);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM:
        return mip_threedm_sensor_to_vehicle_dcm_from_json(jr, pos, &value->u.threedm_sensor_to_vehicle_dcm);
    case MIP_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE:
        return mip_threedm_sensor_to_vehicle_dcm_response_from_json(
            jr, pos, &value->u.threedm_sensor_to_vehicle_dcm_response);
    case MIP_FIELD_THREEDM_ACCEL_BIAS_GX5_45:
        return mip_threedm_accel_bias_gx5_45_from_json(jr, pos, &value->u.threedm_accel_bias_gx5_45);
    case MIP_FIELD_THREEDM_ACCEL_BIAS_CV7_INS:
        return mip_threedm_accel_bias_cv7_ins_from_json(jr, pos, &value->u.threedm_accel_bias_cv7_ins);
    case MIP_FIELD_THREEDM_ACCEL_BIAS_RESPONSE:
        return mip_threedm_accel_bias_response_from_json(jr, pos, &value->u.threedm_accel_bias_response);
    case MIP_FIELD_THREEDM_GYRO_BIAS_GX5_45:
        return mip_threedm_gyro_bias_gx5_45_from_json(jr, pos, &value->u.threedm_gyro_bias_gx5_45);
    case MIP_FIELD_THREEDM_GYRO_BIAS_CV7_INS:
        return mip_threedm_gyro_bias_cv7_ins_from_json(jr, pos, &value->u.threedm_gyro_bias_cv7_ins);
    case MIP_FIELD_THREEDM_GYRO_BIAS_RESPONSE:
        return mip_threedm_gyro_bias_response_from_json(jr, pos, &value->u.threedm_gyro_bias_response);
    case MIP_FIELD_THREEDM_CAPTURE_GYRO_BIAS:
        return mip_threedm_capture_gyro_bias_from_json(jr, pos, &value->u.threedm_capture_gyro_bias);
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45:
        return mip_threedm_mag_hard_iron_offset_gx5_45_from_json(
            jr, pos, &value->u.threedm_mag_hard_iron_offset_gx5_45);
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS:
        return mip_threedm_mag_hard_iron_offset_cv7_ins_from_json(
            jr, pos, &value->u.threedm_mag_hard_iron_offset_cv7_ins);
    case MIP_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE:
        return mip_threedm_mag_hard_iron_offset_response_from_json(
            jr, pos, &value->u.threedm_mag_hard_iron_offset_response);
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45:
        return mip_threedm_mag_soft_iron_matrix_gx5_45_from_json(
            jr, pos, &value->u.threedm_mag_soft_iron_matrix_gx5_45);
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS:
        return mip_threedm_mag_soft_iron_matrix_cv7_ins_from_json(
            jr, pos, &value->u.threedm_mag_soft_iron_matrix_cv7_ins);
    case MIP_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE:
        return mip_threedm_mag_soft_iron_matrix_response_from_json(
            jr, pos, &value->u.threedm_mag_soft_iron_matrix_response);
    case MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE:
        return mip_threedm_coning_sculling_enable_from_json(jr, pos,
                                                            &value->u.threedm_coning_sculling_enable);
    case MIP_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE:
        return mip_threedm_coning_sculling_enable_response_from_json(
            jr, pos, &value->u.threedm_coning_sculling_enable_response);
    case MIP_FIELD_THREEDM_UART_BAUDRATE:
        return mip_threedm_uart_baudrate_from_json(jr, pos, &value->u.threedm_uart_baudrate);
    case MIP_FIELD_THREEDM_UART_BAUDRATE_RESPONSE:
        return mip_threedm_uart_baudrate_response_from_json(jr, pos,
                                                            &value->u.threedm_uart_baudrate_response);
    case MIP_FIELD_THREEDM_GPIO_CONFIG:
        return mip_threedm_gpio_config_from_json(jr, pos, &value->u.threedm_gpio_config);
    case MIP_FIELD_THREEDM_GPIO_CONFIG_RESPONSE:
        return mip_threedm_gpio_config_response_from_json(jr, pos, &value->u.threedm_gpio_config_response);
    case MIP_FIELD_THREEDM_GPIO_STATE:
        return mip_threedm_gpio_state_from_json(jr, pos, &value->u.threedm_gpio_state);
    case MIP_FIELD_THREEDM_GPIO_STATE_RESPONSE:
        return mip_threedm_gpio_state_response_from_json(jr, pos, &value->u.threedm_gpio_state_response);
    case MIP_FIELD_THREEDM_ODOMETER_CONFIG:
        return mip_threedm_odometer_config_from_json(jr, pos, &value->u.threedm_odometer_config);
    case MIP_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE:
        return mip_threedm_odometer_config_response_from_json(jr, pos,
                                                              &value->u.threedm_odometer_config_response);
    case MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER:
        return mip_threedm_advanced_lowpass_filter_from_json(jr, pos,
                                                             &value->u.threedm_advanced_lowpass_filter);
    case MIP_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE:
        return mip_threedm_advanced_lowpass_filter_response_from_json(
            jr, pos, &value->u.threedm_advanced_lowpass_filter_response);
    case MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER:
        return mip_threedm_complementary_filter_from_json(jr, pos, &value->u.threedm_complementary_filter);
    case MIP_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE:
        return mip_threedm_complementary_filter_response_from_json(
            jr, pos, &value->u.threedm_complementary_filter_response);
    case MIP_FIELD_THREEDM_SENSOR_RANGE:
        return mip_threedm_sensor_range_from_json(jr, pos, &value->u.threedm_sensor_range);
    case MIP_FIELD_THREEDM_SENSOR_RANGE_RESPONSE:
        return mip_threedm_sensor_range_response_from_json(jr, pos, &value->u.threedm_sensor_range_response);
    case MIP_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES:
        return mip_threedm_get_calibrated_sensor_ranges_from_json(
            jr, pos, &value->u.threedm_get_calibrated_sensor_ranges);
    case MIP_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES:
        return mip_threedm_calibrated_sensor_ranges_from_json(jr, pos,
                                                              &value->u.threedm_calibrated_sensor_ranges);
    case MIP_FIELD_THREEDM_LOWPASS_FILTER:
        return mip_threedm_lowpass_filter_from_json(jr, pos, &value->u.threedm_lowpass_filter);
    case MIP_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE:
        return mip_threedm_lowpass_filter_response_from_json(jr, pos,
                                                             &value->u.threedm_lowpass_filter_response);
    case MIP_FIELD_THREEDM_POLL_IMU_DATA:
        return mip_threedm_poll_imu_data_from_json(jr, pos, &value->u.threedm_poll_imu_data);
    case MIP_FIELD_THREEDM_POLL_GNSS_DATA:
        return mip_threedm_poll_gnss_data_from_json(jr, pos, &value->u.threedm_poll_gnss_data);
    case MIP_FIELD_THREEDM_POLL_FILTER_DATA:
        return mip_threedm_poll_filter_data_from_json(jr, pos, &value->u.threedm_poll_filter_data);
    case MIP_FIELD_THREEDM_POLL_NMEA_DATA:
        return mip_threedm_poll_nmea_data_from_json(jr, pos, &value->u.threedm_poll_nmea_data);
    case MIP_FIELD_THREEDM_POLL_DATA:
        return mip_threedm_poll_data_from_json(jr, pos, &value->u.threedm_poll_data);
    case MIP_FIELD_THREEDM_GET_IMU_BASE_RATE:
        return mip_threedm_get_imu_base_rate_from_json(jr, pos, &value->u.threedm_get_imu_base_rate);
    case MIP_FIELD_THREEDM_IMU_BASE_RATE:
        return mip_threedm_imu_base_rate_from_json(jr, pos, &value->u.threedm_imu_base_rate);
    case MIP_FIELD_THREEDM_GET_GNSS_BASE_RATE:
        return mip_threedm_get_gnss_base_rate_from_json(jr, pos, &value->u.threedm_get_gnss_base_rate);
    case MIP_FIELD_THREEDM_GNSS_BASE_RATE:
        return mip_threedm_gnss_base_rate_from_json(jr, pos, &value->u.threedm_gnss_base_rate);
    case MIP_FIELD_THREEDM_GET_FILTER_BASE_RATE:
        return mip_threedm_get_filter_base_rate_from_json(jr, pos, &value->u.threedm_get_filter_base_rate);
    case MIP_FIELD_THREEDM_FILTER_BASE_RATE:
        return mip_threedm_filter_base_rate_from_json(jr, pos, &value->u.threedm_filter_base_rate);
    case MIP_FIELD_THREEDM_GET_BASE_RATE:
        return mip_threedm_get_base_rate_from_json(jr, pos, &value->u.threedm_get_base_rate);
    case MIP_FIELD_THREEDM_BASE_RATE:
        return mip_threedm_base_rate_from_json(jr, pos, &value->u.threedm_base_rate);
    case MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT:
        return mip_threedm_imu_message_format_from_json(jr, pos, &value->u.threedm_imu_message_format);
    case MIP_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_imu_message_format_response_from_json(
            jr, pos, &value->u.threedm_imu_message_format_response);
    case MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT:
        return mip_threedm_gnss_message_format_from_json(jr, pos, &value->u.threedm_gnss_message_format);
    case MIP_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_gnss_message_format_response_from_json(
            jr, pos, &value->u.threedm_gnss_message_format_response);
    case MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT:
        return mip_threedm_filter_message_format_from_json(jr, pos, &value->u.threedm_filter_message_format);
    case MIP_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_filter_message_format_response_from_json(
            jr, pos, &value->u.threedm_filter_message_format_response);
    case MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT:
        return mip_threedm_nmea_message_format_from_json(jr, pos, &value->u.threedm_nmea_message_format);
    case MIP_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_nmea_message_format_response_from_json(
            jr, pos, &value->u.threedm_nmea_message_format_response);
    case MIP_FIELD_THREEDM_MESSAGE_FORMAT:
        return mip_threedm_message_format_from_json(jr, pos, &value->u.threedm_message_format);
    case MIP_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE:
        return mip_threedm_message_format_response_from_json(jr, pos,
                                                             &value->u.threedm_message_format_response);
    case MIP_FIELD_THREEDM_FACTORY_STREAMING:
        return mip_threedm_factory_streaming_from_json(jr, pos, &value->u.threedm_factory_streaming);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45:
        return mip_threedm_data_stream_control_gx5_45_from_json(jr, pos,
                                                                &value->u.threedm_data_stream_control_gx5_45);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS:
        return mip_threedm_data_stream_control_cv7_ins_from_json(
            jr, pos, &value->u.threedm_data_stream_control_cv7_ins);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45:
        return mip_threedm_data_stream_control_response_gx5_45_from_json(
            jr, pos, &value->u.threedm_data_stream_control_response_gx5_45);
    case MIP_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS:
        return mip_threedm_data_stream_control_response_cv7_ins_from_json(
            jr, pos, &value->u.threedm_data_stream_control_response_cv7_ins);
    case MIP_FIELD_THREEDM_RAW_RTCM_MESSAGE:
        return mip_threedm_raw_rtcm_message_from_json(jr, pos, &value->u.threedm_raw_rtcm_message);
    case MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS:
        return mip_threedm_gnss_constellation_settings_from_json(
            jr, pos, &value->u.threedm_gnss_constellation_settings);
    case MIP_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE:
        return mip_threedm_gnss_constellation_settings_response_from_json(
            jr, pos, &value->u.threedm_gnss_constellation_settings_response);
    case MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS:
        return mip_threedm_gnss_sbas_settings_from_json(jr, pos, &value->u.threedm_gnss_sbas_settings);
    case MIP_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE:
        return mip_threedm_gnss_sbas_settings_response_from_json(
            jr, pos, &value->u.threedm_gnss_sbas_settings_response);
    case MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL:
        return mip_threedm_gnss_assisted_fix_control_from_json(jr, pos,
                                                               &value->u.threedm_gnss_assisted_fix_control);
    case MIP_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE:
        return mip_threedm_gnss_assisted_fix_control_response_from_json(
            jr, pos, &value->u.threedm_gnss_assisted_fix_control_response);
    case MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE:
        return mip_threedm_gnss_assist_time_update_from_json(jr, pos,
                                                             &value->u.threedm_gnss_assist_time_update);
    case MIP_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE:
        return mip_threedm_gnss_assist_time_update_response_from_json(
            jr, pos, &value->u.threedm_gnss_assist_time_update_response);
    case MIP_FIELD_THREEDM_PPS_SOURCE:
        return mip_threedm_pps_source_from_json(jr, pos, &value->u.threedm_pps_source);
    case MIP_FIELD_THREEDM_PPS_SOURCE_RESPONSE:
        return mip_threedm_pps_source_response_from_json(jr, pos, &value->u.threedm_pps_source_response);
    case MIP_FIELD_THREEDM_GET_SUPPORTED_EVENTS:
        return mip_threedm_get_supported_events_from_json(jr, pos, &value->u.threedm_get_supported_events);
    case MIP_FIELD_THREEDM_SUPPORTED_EVENTS:
        return mip_threedm_supported_events_from_json(jr, pos, &value->u.threedm_supported_events);
    case MIP_FIELD_THREEDM_DEVICE_STATUS:
        return mip_threedm_device_status_from_json(jr, pos, &value->u.threedm_device_status);
    case MIP_FIELD_THREEDM_DEVICE_STATUS_RESPONSE:
        return mip_threedm_device_status_response_from_json(jr, pos,
                                                            &value->u.threedm_device_status_response);
    case MIP_FIELD_FILTER_RESET_FILTER:
        return mip_filter_reset_filter_from_json(jr, pos, &value->u.filter_reset_filter);
    case MIP_FIELD_FILTER_SET_INITIAL_ATTITUDE:
        return mip_filter_set_initial_attitude_from_json(jr, pos, &value->u.filter_set_initial_attitude);
    case MIP_FIELD_FILTER_SET_INITIAL_HEADING:
        return mip_filter_set_initial_heading_from_json(jr, pos, &value->u.filter_set_initial_heading);
    case MIP_FIELD_FILTER_RUN_FILTER:
        return mip_filter_run_filter_from_json(jr, pos, &value->u.filter_run_filter);
    case MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE:
        return mip_filter_vehicle_dynamics_mode_from_json(jr, pos, &value->u.filter_vehicle_dynamics_mode);
    case MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE:
        return mip_filter_vehicle_dynamics_mode_response_from_json(
            jr, pos, &value->u.filter_vehicle_dynamics_mode_response);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM:
        return mip_filter_sensor_to_vehicle_transform_from_json(jr, pos,
                                                                &value->u.filter_sensor_to_vehicle_transform);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE:
        return mip_filter_sensor_to_vehicle_transform_response_from_json(
            jr, pos, &value->u.filter_sensor_to_vehicle_transform_response);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET:
        return mip_filter_sensor_to_vehicle_offset_from_json(jr, pos,
                                                             &value->u.filter_sensor_to_vehicle_offset);
    case MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE:
        return mip_filter_sensor_to_vehicle_offset_response_from_json(
            jr, pos, &value->u.filter_sensor_to_vehicle_offset_response);
    case MIP_FIELD_FILTER_ANTENNA_OFFSET:
        return mip_filter_antenna_offset_from_json(jr, pos, &value->u.filter_antenna_offset);
    case MIP_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE:
        return mip_filter_antenna_offset_response_from_json(jr, pos,
                                                            &value->u.filter_antenna_offset_response);
    case MIP_FIELD_FILTER_ESTIMATION_CONTROL:
        return mip_filter_estimation_control_from_json(jr, pos, &value->u.filter_estimation_control);
    case MIP_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE:
        return mip_filter_estimation_control_response_from_json(jr, pos,
                                                                &value->u.filter_estimation_control_response);
    case MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL:
        return mip_filter_gnss_source_control_from_json(jr, pos, &value->u.filter_gnss_source_control);
    case MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE:
        return mip_filter_gnss_source_control_response_from_json(
            jr, pos, &value->u.filter_gnss_source_control_response);
    case MIP_FIELD_FILTER_EXTERNAL_GNSS_UPDATE:
        return mip_filter_external_gnss_update_from_json(jr, pos, &value->u.filter_external_gnss_update);
    case MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE:
        return mip_filter_external_heading_update_from_json(jr, pos,
                                                            &value->u.filter_external_heading_update);
    case MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL:
        return mip_filter_heading_update_control_from_json(jr, pos, &value->u.filter_heading_update_control);
    case MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE:
        return mip_filter_heading_update_control_response_from_json(
            jr, pos, &value->u.filter_heading_update_control_response);
    case MIP_FIELD_FILTER_AUTO_INIT_CONTROL:
        return mip_filter_auto_init_control_from_json(jr, pos, &value->u.filter_auto_init_control);
    case MIP_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE:
        return mip_filter_auto_init_control_response_from_json(jr, pos,
                                                               &value->u.filter_auto_init_control_response);
    case MIP_FIELD_FILTER_ACCEL_NOISE:
        return mip_filter_accel_noise_from_json(jr, pos, &value->u.filter_accel_noise);
    case MIP_FIELD_FILTER_ACCEL_NOISE_RESPONSE:
        return mip_filter_accel_noise_response_from_json(jr, pos, &value->u.filter_accel_noise_response);
    case MIP_FIELD_FILTER_GYRO_NOISE:
        return mip_filter_gyro_noise_from_json(jr, pos, &value->u.filter_gyro_noise);
    case MIP_FIELD_FILTER_GYRO_NOISE_RESPONSE:
        return mip_filter_gyro_noise_response_from_json(jr, pos, &value->u.filter_gyro_noise_response);
    case MIP_FIELD_FILTER_ACCEL_BIAS_MODEL:
        return mip_filter_accel_bias_model_from_json(jr, pos, &value->u.filter_accel_bias_model);
    case MIP_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE:
        return mip_filter_accel_bias_model_response_from_json(jr, pos,
                                                              &value->u.filter_accel_bias_model_response);
    case MIP_FIELD_FILTER_GYRO_BIAS_MODEL:
        return mip_filter_gyro_bias_model_from_json(jr, pos, &value->u.filter_gyro_bias_model);
    case MIP_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE:
        return mip_filter_gyro_bias_model_response_from_json(jr, pos,
                                                             &value->u.filter_gyro_bias_model_response);
    case MIP_FIELD_FILTER_ZUPT_CONTROL:
        return mip_filter_zupt_control_from_json(jr, pos, &value->u.filter_zupt_control);
    case MIP_FIELD_FILTER_ZUPT_CONTROL_RESPONSE:
        return mip_filter_zupt_control_response_from_json(jr, pos, &value->u.filter_zupt_control_response);
    case MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME:
        return mip_filter_external_heading_update_with_time_from_json(
            jr, pos, &value->u.filter_external_heading_update_with_time);
    case MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL:
        return mip_filter_zero_angular_rate_update_control_from_json(
            jr, pos, &value->u.filter_zero_angular_rate_update_control);
    case MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE:
        return mip_filter_zero_angular_rate_update_control_response_from_json(
            jr, pos, &value->u.filter_zero_angular_rate_update_control_response);
    case MIP_FIELD_FILTER_TARE_ORIENTATION:
        return mip_filter_tare_orientation_from_json(jr, pos, &value->u.filter_tare_orientation);
    case MIP_FIELD_FILTER_COMMANDED_ZUPT:
        return mip_filter_commanded_zupt_from_json(jr, pos, &value->u.filter_commanded_zupt);
    case MIP_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE:
        return mip_filter_commanded_zero_angular_rate_update_from_json(
            jr, pos, &value->u.filter_commanded_zero_angular_rate_update);
    case MIP_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION:
        return mip_filter_mag_capture_auto_calibration_from_json(
            jr, pos, &value->u.filter_mag_capture_auto_calibration);
    case MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV:
        return mip_filter_gravity_noise_std_dev_from_json(jr, pos, &value->u.filter_gravity_noise_std_dev);
    case MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE:
        return mip_filter_gravity_noise_std_dev_response_from_json(
            jr, pos, &value->u.filter_gravity_noise_std_dev_response);
    case MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV:
        return mip_filter_pressure_altitude_noise_std_dev_from_json(
            jr, pos, &value->u.filter_pressure_altitude_noise_std_dev);
    case MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE:
        return mip_filter_pressure_altitude_noise_std_dev_response_from_json(
            jr, pos, &value->u.filter_pressure_altitude_noise_std_dev_response);
    case MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE:
        return mip_filter_hard_iron_offset_noise_from_json(jr, pos, &value->u.filter_hard_iron_offset_noise);
    case MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE:
        return mip_filter_hard_iron_offset_noise_response_from_json(
            jr, pos, &value->u.filter_hard_iron_offset_noise_response);
    case MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE:
        return mip_filter_soft_iron_matrix_noise_from_json(jr, pos, &value->u.filter_soft_iron_matrix_noise);
    case MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE:
        return mip_filter_soft_iron_matrix_noise_response_from_json(
            jr, pos, &value->u.filter_soft_iron_matrix_noise_response);
    case MIP_FIELD_FILTER_MAG_NOISE_STD_DEV:
        return mip_filter_mag_noise_std_dev_from_json(jr, pos, &value->u.filter_mag_noise_std_dev);
    case MIP_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE:
        return mip_filter_mag_noise_std_dev_response_from_json(jr, pos,
                                                               &value->u.filter_mag_noise_std_dev_response);
    case MIP_FIELD_FILTER_DECLINATION_SOURCE:
        return mip_filter_declination_source_from_json(jr, pos, &value->u.filter_declination_source);
    case MIP_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE:
        return mip_filter_declination_source_response_from_json(jr, pos,
                                                                &value->u.filter_declination_source_response);
    case MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mip_filter_gravity_magnitude_adaptive_measurement_from_json(
            jr, pos, &value->u.filter_gravity_magnitude_adaptive_measurement);
    case MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mip_filter_gravity_magnitude_adaptive_measurement_response_from_json(
            jr, pos, &value->u.filter_gravity_magnitude_adaptive_measurement_response);
    case MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mip_filter_mag_magnitude_adaptive_measurement_from_json(
            jr, pos, &value->u.filter_mag_magnitude_adaptive_measurement);
    case MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mip_filter_mag_magnitude_adaptive_measurement_response_from_json(
            jr, pos, &value->u.filter_mag_magnitude_adaptive_measurement_response);
    case MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT:
        return mip_filter_mag_dip_angle_adaptive_measurement_from_json(
            jr, pos, &value->u.filter_mag_dip_angle_adaptive_measurement);
    case MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mip_filter_mag_dip_angle_adaptive_measurement_response_from_json(
            jr, pos, &value->u.filter_mag_dip_angle_adaptive_measurement_response);
    case MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL:
        return mip_filter_altitude_aiding_control_from_json(jr, pos,
                                                            &value->u.filter_altitude_aiding_control);
    case MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE:
        return mip_filter_altitude_aiding_control_response_from_json(
            jr, pos, &value->u.filter_altitude_aiding_control_response);
    case MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL:
        return mip_filter_pitch_roll_aiding_control_from_json(jr, pos,
                                                              &value->u.filter_pitch_roll_aiding_control);
    case MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE:
        return mip_filter_pitch_roll_aiding_control_response_from_json(
            jr, pos, &value->u.filter_pitch_roll_aiding_control_response);
    case MIP_FIELD_FILTER_INCLINATION_SOURCE:
        return mip_filter_inclination_source_from_json(jr, pos, &value->u.filter_inclination_source);
    case MIP_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE:
        return mip_filter_inclination_source_response_from_json(jr, pos,
                                                                &value->u.filter_inclination_source_response);
    case MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE:
        return mip_filter_magnetic_field_magnitude_source_from_json(
            jr, pos, &value->u.filter_magnetic_field_magnitude_source);
    case MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE:
        return mip_filter_magnetic_field_magnitude_source_response_from_json(
            jr, pos, &value->u.filter_magnetic_field_magnitude_source_response);
    case MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL:
        return mip_filter_aiding_measurement_control_from_json(jr, pos,
                                                               &value->u.filter_aiding_measurement_control);
    case MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE:
        return mip_filter_aiding_measurement_control_response_from_json(
            jr, pos, &value->u.filter_aiding_measurement_control_response);
    case MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION:
        return mip_filter_initialization_configuration_from_json(
            jr, pos, &value->u.filter_initialization_configuration);
    case MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE:
        return mip_filter_initialization_configuration_response_from_json(
            jr, pos, &value->u.filter_initialization_configuration_response);
    case MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL:
        return mip_filter_adaptive_filter_control_from_json(jr, pos,
                                                            &value->u.filter_adaptive_filter_control);
    case MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE:
        return mip_filter_adaptive_filter_control_response_from_json(
            jr, pos, &value->u.filter_adaptive_filter_control_response);
    case MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET:
        return mip_filter_multi_antenna_offset_from_json(jr, pos, &value->u.filter_multi_antenna_offset);
    case MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE:
        return mip_filter_multi_antenna_offset_response_from_json(
            jr, pos, &value->u.filter_multi_antenna_offset_response);
    case MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION:
        return mip_filter_relative_position_configuration_from_json(
            jr, pos, &value->u.filter_relative_position_configuration);
    case MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE:
        return mip_filter_relative_position_configuration_response_from_json(
            jr, pos, &value->u.filter_relative_position_configuration_response);
    case MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM:
        return mip_filter_reference_point_lever_arm_from_json(jr, pos,
                                                              &value->u.filter_reference_point_lever_arm);
    case MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE:
        return mip_filter_reference_point_lever_arm_response_from_json(
            jr, pos, &value->u.filter_reference_point_lever_arm_response);
    case MIP_FIELD_FILTER_SPEED_LEVER_ARM:
        return mip_filter_speed_lever_arm_from_json(jr, pos, &value->u.filter_speed_lever_arm);
    case MIP_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE:
        return mip_filter_speed_lever_arm_response_from_json(jr, pos,
                                                             &value->u.filter_speed_lever_arm_response);
    case MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL:
        return mip_filter_wheeled_vehicle_constraint_control_from_json(
            jr, pos, &value->u.filter_wheeled_vehicle_constraint_control);
    case MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE:
        return mip_filter_wheeled_vehicle_constraint_control_response_from_json(
            jr, pos, &value->u.filter_wheeled_vehicle_constraint_control_response);
    case MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL:
        return mip_filter_gnss_antenna_calibration_control_from_json(
            jr, pos, &value->u.filter_gnss_antenna_calibration_control);
    case MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE:
        return mip_filter_gnss_antenna_calibration_control_response_from_json(
            jr, pos, &value->u.filter_gnss_antenna_calibration_control_response);
    case MIP_FIELD_GNSS_RECEIVER_INFO:
        return mip_gnss_receiver_info_from_json(jr, pos, &value->u.gnss_receiver_info);
    case MIP_FIELD_GNSS_RECEIVER_INFO_RESPONSE:
        return mip_gnss_receiver_info_response_from_json(jr, pos, &value->u.gnss_receiver_info_response);
    case MIP_FIELD_GNSS_SIGNAL_CONFIGURATION:
        return mip_gnss_signal_configuration_from_json(jr, pos, &value->u.gnss_signal_configuration);
    case MIP_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE:
        return mip_gnss_signal_configuration_response_from_json(jr, pos,
                                                                &value->u.gnss_signal_configuration_response);
    case MIP_FIELD_GNSS_SPARTN_CONFIGURATION:
        return mip_gnss_spartn_configuration_from_json(jr, pos, &value->u.gnss_spartn_configuration);
    case MIP_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE:
        return mip_gnss_spartn_configuration_response_from_json(jr, pos,
                                                                &value->u.gnss_spartn_configuration_response);
    case MIP_FIELD_AIDING_FRAME_CONFIG:
        return mip_aiding_frame_config_from_json(jr, pos, &value->u.aiding_frame_config);
    case MIP_FIELD_AIDING_FRAME_CONFIG_RESPONSE:
        return mip_aiding_frame_config_response_from_json(jr, pos, &value->u.aiding_frame_config_response);
    case MIP_FIELD_AIDING_ECHO_CONTROL:
        return mip_aiding_echo_control_from_json(jr, pos, &value->u.aiding_echo_control);
    case MIP_FIELD_AIDING_ECHO_CONTROL_RESPONSE:
        return mip_aiding_echo_control_response_from_json(jr, pos, &value->u.aiding_echo_control_response);
    case MIP_FIELD_AIDING_ECEF_POSITION:
        return mip_aiding_ecef_position_from_json(jr, pos, &value->u.aiding_ecef_position);
    case MIP_FIELD_AIDING_LLH_POSITION:
        return mip_aiding_llh_position_from_json(jr, pos, &value->u.aiding_llh_position);
    case MIP_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID:
        return mip_aiding_height_above_ellipsoid_from_json(jr, pos, &value->u.aiding_height_above_ellipsoid);
    case MIP_FIELD_AIDING_ECEF_VELOCITY:
        return mip_aiding_ecef_velocity_from_json(jr, pos, &value->u.aiding_ecef_velocity);
    case MIP_FIELD_AIDING_NED_VELOCITY:
        return mip_aiding_ned_velocity_from_json(jr, pos, &value->u.aiding_ned_velocity);
    case MIP_FIELD_AIDING_BODY_FRAME_VELOCITY:
        return mip_aiding_body_frame_velocity_from_json(jr, pos, &value->u.aiding_body_frame_velocity);
    case MIP_FIELD_AIDING_TRUE_HEADING:
        return mip_aiding_true_heading_from_json(jr, pos, &value->u.aiding_true_heading);
    case MIP_FIELD_AIDING_MAGNETIC_FIELD:
        return mip_aiding_magnetic_field_from_json(jr, pos, &value->u.aiding_magnetic_field);
    case MIP_FIELD_AIDING_PRESSURE:
        return mip_aiding_pressure_from_json(jr, pos, &value->u.aiding_pressure);
    case MIP_FIELD_SYSTEM_COMMUNICATION_MODE:
        return mip_system_communication_mode_from_json(jr, pos, &value->u.system_communication_mode);
    case MIP_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE:
        return mip_system_communication_mode_response_from_json(jr, pos,
                                                                &value->u.system_communication_mode_response);
    case MIP_FIELD_SENSOR_SCALED_ACCEL:
        return mip_sensor_scaled_accel_from_json(jr, pos, &value->u.sensor_scaled_accel);
    case MIP_FIELD_SENSOR_SCALED_GYRO:
        return mip_sensor_scaled_gyro_from_json(jr, pos, &value->u.sensor_scaled_gyro);
    case MIP_FIELD_SENSOR_SCALED_MAG:
        return mip_sensor_scaled_mag_from_json(jr, pos, &value->u.sensor_scaled_mag);
    case MIP_FIELD_SENSOR_DELTA_THETA:
        return mip_sensor_delta_theta_from_json(jr, pos, &value->u.sensor_delta_theta);
    case MIP_FIELD_SENSOR_DELTA_VELOCITY:
        return mip_sensor_delta_velocity_from_json(jr, pos, &value->u.sensor_delta_velocity);
    case MIP_FIELD_SENSOR_CF_ORIENTATION_MATRIX:
        return mip_sensor_cf_orientation_matrix_from_json(jr, pos, &value->u.sensor_cf_orientation_matrix);
    case MIP_FIELD_SENSOR_CF_QUATERNION:
        return mip_sensor_cf_quaternion_from_json(jr, pos, &value->u.sensor_cf_quaternion);
    case MIP_FIELD_SENSOR_CF_EULER_ANGLES:
        return mip_sensor_cf_euler_angles_from_json(jr, pos, &value->u.sensor_cf_euler_angles);
    case MIP_FIELD_SENSOR_CF_STABILIZED_NORTH:
        return mip_sensor_cf_stabilized_north_from_json(jr, pos, &value->u.sensor_cf_stabilized_north);
    case MIP_FIELD_SENSOR_CF_STABILIZED_UP:
        return mip_sensor_cf_stabilized_up_from_json(jr, pos, &value->u.sensor_cf_stabilized_up);
    case MIP_FIELD_SENSOR_GPS_TIMESTAMP:
        return mip_sensor_gps_timestamp_from_json(jr, pos, &value->u.sensor_gps_timestamp);
    case MIP_FIELD_SENSOR_TEMPERATURE_STATISTICS:
        return mip_sensor_temperature_statistics_from_json(jr, pos, &value->u.sensor_temperature_statistics);
    case MIP_FIELD_SENSOR_SCALED_PRESSURE:
        return mip_sensor_scaled_pressure_from_json(jr, pos, &value->u.sensor_scaled_pressure);
    case MIP_FIELD_SENSOR_OVERRANGE_STATUS:
        return mip_sensor_overrange_status_from_json(jr, pos, &value->u.sensor_overrange_status);
    case MIP_FIELD_SENSOR_ODOMETER_DATA:
        return mip_sensor_odometer_data_from_json(jr, pos, &value->u.sensor_odometer_data);
    case MIP_FIELD_GNSS_DATA_LLH_POSITION:
        return mip_gnss_data_llh_position_from_json(jr, pos, &value->u.gnss_data_llh_position);
    case MIP_FIELD_GNSS_DATA_ECEF_POSITION:
        return mip_gnss_data_ecef_position_from_json(jr, pos, &value->u.gnss_data_ecef_position);
    case MIP_FIELD_GNSS_DATA_NED_VELOCITY:
        return mip_gnss_data_ned_velocity_from_json(jr, pos, &value->u.gnss_data_ned_velocity);
    case MIP_FIELD_GNSS_DATA_ECEF_VELOCITY:
        return mip_gnss_data_ecef_velocity_from_json(jr, pos, &value->u.gnss_data_ecef_velocity);
    case MIP_FIELD_GNSS_DATA_DOP:
        return mip_gnss_data_dop_from_json(jr, pos, &value->u.gnss_data_dop);
    case MIP_FIELD_GNSS_DATA_UTC_TIME:
        return mip_gnss_data_utc_time_from_json(jr, pos, &value->u.gnss_data_utc_time);
    case MIP_FIELD_GNSS_DATA_GPS_TIME:
        return mip_gnss_data_gps_time_from_json(jr, pos, &value->u.gnss_data_gps_time);
    case MIP_FIELD_GNSS_DATA_CLOCK_INFO:
        return mip_gnss_data_clock_info_from_json(jr, pos, &value->u.gnss_data_clock_info);
    case MIP_FIELD_GNSS_DATA_FIX_INFO:
        return mip_gnss_data_fix_info_from_json(jr, pos, &value->u.gnss_data_fix_info);
    case MIP_FIELD_GNSS_DATA_SV_INFO:
        return mip_gnss_data_sv_info_from_json(jr, pos, &value->u.gnss_data_sv_info);
    case MIP_FIELD_GNSS_DATA_HARDWARE_STATUS:
        return mip_gnss_data_hardware_status_from_json(jr, pos, &value->u.gnss_data_hardware_status);
    case MIP_FIELD_GNSS_DATA_DGNSS_INFO:
        return mip_gnss_data_dgnss_info_from_json(jr, pos, &value->u.gnss_data_dgnss_info);
    case MIP_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS:
        return mip_gnss_data_dgnss_channel_status_from_json(jr, pos,
                                                            &value->u.gnss_data_dgnss_channel_status);
    case MIP_FIELD_FILTER_DATA_LLH_POSITION:
        return mip_filter_data_llh_position_from_json(jr, pos, &value->u.filter_data_llh_position);
    case MIP_FIELD_FILTER_DATA_NED_VELOCITY:
        return mip_filter_data_ned_velocity_from_json(jr, pos, &value->u.filter_data_ned_velocity);
    case MIP_FIELD_FILTER_DATA_ATTITUDE_QUATERNION:
        return mip_filter_data_attitude_quaternion_from_json(jr, pos,
                                                             &value->u.filter_data_attitude_quaternion);
    case MIP_FIELD_FILTER_DATA_ATTITUDE_DCM:
        return mip_filter_data_attitude_dcm_from_json(jr, pos, &value->u.filter_data_attitude_dcm);
    case MIP_FIELD_FILTER_DATA_EULER_ANGLES:
        return mip_filter_data_euler_angles_from_json(jr, pos, &value->u.filter_data_euler_angles);
    case MIP_FIELD_FILTER_DATA_GYRO_BIAS:
        return mip_filter_data_gyro_bias_from_json(jr, pos, &value->u.filter_data_gyro_bias);
    case MIP_FIELD_FILTER_DATA_ACCEL_BIAS:
        return mip_filter_data_accel_bias_from_json(jr, pos, &value->u.filter_data_accel_bias);
    case MIP_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY:
        return mip_filter_data_llh_position_uncertainty_from_json(
            jr, pos, &value->u.filter_data_llh_position_uncertainty);
    case MIP_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY:
        return mip_filter_data_ned_velocity_uncertainty_from_json(
            jr, pos, &value->u.filter_data_ned_velocity_uncertainty);
    case MIP_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY:
        return mip_filter_data_euler_angles_uncertainty_from_json(
            jr, pos, &value->u.filter_data_euler_angles_uncertainty);
    case MIP_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY:
        return mip_filter_data_gyro_bias_uncertainty_from_json(jr, pos,
                                                               &value->u.filter_data_gyro_bias_uncertainty);
    case MIP_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY:
        return mip_filter_data_accel_bias_uncertainty_from_json(jr, pos,
                                                                &value->u.filter_data_accel_bias_uncertainty);
    case MIP_FIELD_FILTER_DATA_LINEAR_ACCEL:
        return mip_filter_data_linear_accel_from_json(jr, pos, &value->u.filter_data_linear_accel);
    case MIP_FIELD_FILTER_DATA_COMP_ANGULAR_RATE:
        return mip_filter_data_comp_angular_rate_from_json(jr, pos, &value->u.filter_data_comp_angular_rate);
    case MIP_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE:
        return mip_filter_data_wgs84_gravity_magnitude_from_json(
            jr, pos, &value->u.filter_data_wgs84_gravity_magnitude);
    case MIP_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45:
        return mip_filter_data_filter_status_gx5_45_from_json(jr, pos,
                                                              &value->u.filter_data_filter_status_gx5_45);
    case MIP_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS:
        return mip_filter_data_filter_status_cv7_ins_from_json(jr, pos,
                                                               &value->u.filter_data_filter_status_cv7_ins);
    case MIP_FIELD_FILTER_DATA_GPS_TIMESTAMP:
        return mip_filter_data_gps_timestamp_from_json(jr, pos, &value->u.filter_data_gps_timestamp);
    case MIP_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY:
        return mip_filter_data_quaternion_attitude_uncertainty_from_json(
            jr, pos, &value->u.filter_data_quaternion_attitude_uncertainty);
    case MIP_FIELD_FILTER_DATA_GRAVITY_VECTOR:
        return mip_filter_data_gravity_vector_from_json(jr, pos, &value->u.filter_data_gravity_vector);
    case MIP_FIELD_FILTER_DATA_HEADING_UPDATE_STATE:
        return mip_filter_data_heading_update_state_from_json(jr, pos,
                                                              &value->u.filter_data_heading_update_state);
    case MIP_FIELD_FILTER_DATA_MAGNETIC_MODEL:
        return mip_filter_data_magnetic_model_from_json(jr, pos, &value->u.filter_data_magnetic_model);
    case MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR:
        return mip_filter_data_gyro_scale_factor_from_json(jr, pos, &value->u.filter_data_gyro_scale_factor);
    case MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR:
        return mip_filter_data_accel_scale_factor_from_json(jr, pos,
                                                            &value->u.filter_data_accel_scale_factor);
    case MIP_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY:
        return mip_filter_data_gyro_scale_factor_uncertainty_from_json(
            jr, pos, &value->u.filter_data_gyro_scale_factor_uncertainty);
    case MIP_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY:
        return mip_filter_data_accel_scale_factor_uncertainty_from_json(
            jr, pos, &value->u.filter_data_accel_scale_factor_uncertainty);
    case MIP_FIELD_FILTER_DATA_COMPENSATED_ACCEL:
        return mip_filter_data_compensated_accel_from_json(jr, pos, &value->u.filter_data_compensated_accel);
    case MIP_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE:
        return mip_filter_data_standard_atmosphere_from_json(jr, pos,
                                                             &value->u.filter_data_standard_atmosphere);
    case MIP_FIELD_FILTER_DATA_PRESSURE_ALTITUDE:
        return mip_filter_data_pressure_altitude_from_json(jr, pos, &value->u.filter_data_pressure_altitude);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET:
        return mip_filter_data_mag_auto_hard_iron_offset_from_json(
            jr, pos, &value->u.filter_data_mag_auto_hard_iron_offset);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX:
        return mip_filter_data_mag_auto_soft_iron_matrix_from_json(
            jr, pos, &value->u.filter_data_mag_auto_soft_iron_matrix);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY:
        return mip_filter_data_mag_auto_hard_iron_offset_uncertainty_from_json(
            jr, pos, &value->u.filter_data_mag_auto_hard_iron_offset_uncertainty);
    case MIP_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY:
        return mip_filter_data_mag_auto_soft_iron_matrix_uncertainty_from_json(
            jr, pos, &value->u.filter_data_mag_auto_soft_iron_matrix_uncertainty);
    case MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION:
        return mip_filter_data_gnss_antenna_offset_correction_from_json(
            jr, pos, &value->u.filter_data_gnss_antenna_offset_correction);
    case MIP_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mip_filter_data_gnss_antenna_offset_correction_uncertainty_from_json(
            jr, pos, &value->u.filter_data_gnss_antenna_offset_correction_uncertainty);
    case MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION:
        return mip_filter_data_multi_antenna_offset_correction_from_json(
            jr, pos, &value->u.filter_data_multi_antenna_offset_correction);
    case MIP_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mip_filter_data_multi_antenna_offset_correction_uncertainty_from_json(
            jr, pos, &value->u.filter_data_multi_antenna_offset_correction_uncertainty);
    case MIP_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY:
        return mip_filter_data_ecef_position_uncertainty_from_json(
            jr, pos, &value->u.filter_data_ecef_position_uncertainty);
    case MIP_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY:
        return mip_filter_data_ecef_velocity_uncertainty_from_json(
            jr, pos, &value->u.filter_data_ecef_velocity_uncertainty);
    case MIP_FIELD_FILTER_DATA_ECEF_POSITION:
        return mip_filter_data_ecef_position_from_json(jr, pos, &value->u.filter_data_ecef_position);
    case MIP_FIELD_FILTER_DATA_ECEF_VELOCITY:
        return mip_filter_data_ecef_velocity_from_json(jr, pos, &value->u.filter_data_ecef_velocity);
    case MIP_FIELD_FILTER_DATA_NED_RELATIVE_POSITION:
        return mip_filter_data_ned_relative_position_from_json(jr, pos,
                                                               &value->u.filter_data_ned_relative_position);
    case MIP_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS:
        return mip_filter_data_gnss_position_aiding_status_from_json(
            jr, pos, &value->u.filter_data_gnss_position_aiding_status);
    case MIP_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY:
        return mip_filter_data_aiding_measurement_summary_from_json(
            jr, pos, &value->u.filter_data_aiding_measurement_summary);
    case MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR:
        return mip_filter_data_odometer_scale_factor_error_from_json(
            jr, pos, &value->u.filter_data_odometer_scale_factor_error);
    case MIP_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY:
        return mip_filter_data_odometer_scale_factor_error_uncertainty_from_json(
            jr, pos, &value->u.filter_data_odometer_scale_factor_error_uncertainty);
    case MIP_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS:
        return mip_filter_data_gnss_dual_antenna_status_from_json(
            jr, pos, &value->u.filter_data_gnss_dual_antenna_status);
    case MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR:
        return mip_filter_data_aiding_frame_config_error_from_json(
            jr, pos, &value->u.filter_data_aiding_frame_config_error);
    case MIP_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY:
        return mip_filter_data_aiding_frame_config_error_uncertainty_from_json(
            jr, pos, &value->u.filter_data_aiding_frame_config_error_uncertainty);
    case MIP_FIELD_GNSS_RECEIVER_1_LLH_POSITION:
        return mip_gnss_receiver_1_llh_position_from_json(jr, pos, &value->u.gnss_receiver_1_llh_position);
    case MIP_FIELD_GNSS_RECEIVER_1_ECEF_POSITION:
        return mip_gnss_receiver_1_ecef_position_from_json(jr, pos, &value->u.gnss_receiver_1_ecef_position);
    case MIP_FIELD_GNSS_RECEIVER_1_NED_VELOCITY:
        return mip_gnss_receiver_1_ned_velocity_from_json(jr, pos, &value->u.gnss_receiver_1_ned_velocity);
    case MIP_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY:
        return mip_gnss_receiver_1_ecef_velocity_from_json(jr, pos, &value->u.gnss_receiver_1_ecef_velocity);
    case MIP_FIELD_GNSS_RECEIVER_1_DOP:
        return mip_gnss_receiver_1_dop_from_json(jr, pos, &value->u.gnss_receiver_1_dop);
    case MIP_FIELD_GNSS_RECEIVER_1_UTC_TIME:
        return mip_gnss_receiver_1_utc_time_from_json(jr, pos, &value->u.gnss_receiver_1_utc_time);
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_TIME:
        return mip_gnss_receiver_1_gps_time_from_json(jr, pos, &value->u.gnss_receiver_1_gps_time);
    case MIP_FIELD_GNSS_RECEIVER_1_FIX_INFO:
        return mip_gnss_receiver_1_fix_info_from_json(jr, pos, &value->u.gnss_receiver_1_fix_info);
    case MIP_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS:
        return mip_gnss_receiver_1_hardware_status_from_json(jr, pos,
                                                             &value->u.gnss_receiver_1_hardware_status);
    case MIP_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2:
        return mip_gnss_receiver_1_clock_info_2_from_json(jr, pos, &value->u.gnss_receiver_1_clock_info_2);
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS:
        return mip_gnss_receiver_1_gps_leap_seconds_from_json(jr, pos,
                                                              &value->u.gnss_receiver_1_gps_leap_seconds);
    case MIP_FIELD_GNSS_RECEIVER_1_SBAS_INFO:
        return mip_gnss_receiver_1_sbas_info_from_json(jr, pos, &value->u.gnss_receiver_1_sbas_info);
    case MIP_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS:
        return mip_gnss_receiver_1_satellite_status_from_json(jr, pos,
                                                              &value->u.gnss_receiver_1_satellite_status);
    case MIP_FIELD_GNSS_RECEIVER_1_RAW:
        return mip_gnss_receiver_1_raw_from_json(jr, pos, &value->u.gnss_receiver_1_raw);
    case MIP_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS:
        return mip_gnss_receiver_1_gps_ephemeris_from_json(jr, pos, &value->u.gnss_receiver_1_gps_ephemeris);
    case MIP_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS:
        return mip_gnss_receiver_1_glonass_ephemeris_from_json(jr, pos,
                                                               &value->u.gnss_receiver_1_glonass_ephemeris);
    case MIP_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS:
        return mip_gnss_receiver_1_galileo_ephemeris_from_json(jr, pos,
                                                               &value->u.gnss_receiver_1_galileo_ephemeris);
    case MIP_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS:
        return mip_gnss_receiver_1_beidou_ephemeris_from_json(jr, pos,
                                                              &value->u.gnss_receiver_1_beidou_ephemeris);
    case MIP_FIELD_GNSS_RECEIVER_2_LLH_POSITION:
        return mip_gnss_receiver_2_llh_position_from_json(jr, pos, &value->u.gnss_receiver_2_llh_position);
    case MIP_FIELD_GNSS_RECEIVER_2_ECEF_POSITION:
        return mip_gnss_receiver_2_ecef_position_from_json(jr, pos, &value->u.gnss_receiver_2_ecef_position);
    case MIP_FIELD_GNSS_RECEIVER_2_NED_VELOCITY:
        return mip_gnss_receiver_2_ned_velocity_from_json(jr, pos, &value->u.gnss_receiver_2_ned_velocity);
    case MIP_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY:
        return mip_gnss_receiver_2_ecef_velocity_from_json(jr, pos, &value->u.gnss_receiver_2_ecef_velocity);
    case MIP_FIELD_GNSS_RECEIVER_2_DOP:
        return mip_gnss_receiver_2_dop_from_json(jr, pos, &value->u.gnss_receiver_2_dop);
    case MIP_FIELD_GNSS_RECEIVER_2_UTC_TIME:
        return mip_gnss_receiver_2_utc_time_from_json(jr, pos, &value->u.gnss_receiver_2_utc_time);
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_TIME:
        return mip_gnss_receiver_2_gps_time_from_json(jr, pos, &value->u.gnss_receiver_2_gps_time);
    case MIP_FIELD_GNSS_RECEIVER_2_FIX_INFO:
        return mip_gnss_receiver_2_fix_info_from_json(jr, pos, &value->u.gnss_receiver_2_fix_info);
    case MIP_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS:
        return mip_gnss_receiver_2_hardware_status_from_json(jr, pos,
                                                             &value->u.gnss_receiver_2_hardware_status);
    case MIP_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2:
        return mip_gnss_receiver_2_clock_info_2_from_json(jr, pos, &value->u.gnss_receiver_2_clock_info_2);
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS:
        return mip_gnss_receiver_2_gps_leap_seconds_from_json(jr, pos,
                                                              &value->u.gnss_receiver_2_gps_leap_seconds);
    case MIP_FIELD_GNSS_RECEIVER_2_SBAS_INFO:
        return mip_gnss_receiver_2_sbas_info_from_json(jr, pos, &value->u.gnss_receiver_2_sbas_info);
    case MIP_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS:
        return mip_gnss_receiver_2_satellite_status_from_json(jr, pos,
                                                              &value->u.gnss_receiver_2_satellite_status);
    case MIP_FIELD_GNSS_RECEIVER_2_RAW:
        return mip_gnss_receiver_2_raw_from_json(jr, pos, &value->u.gnss_receiver_2_raw);
    case MIP_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS:
        return mip_gnss_receiver_2_gps_ephemeris_from_json(jr, pos, &value->u.gnss_receiver_2_gps_ephemeris);
    case MIP_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS:
        return mip_gnss_receiver_2_glonass_ephemeris_from_json(jr, pos,
                                                               &value->u.gnss_receiver_2_glonass_ephemeris);
    case MIP_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS:
        return mip_gnss_receiver_2_galileo_ephemeris_from_json(jr, pos,
                                                               &value->u.gnss_receiver_2_galileo_ephemeris);
    case MIP_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS:
        return mip_gnss_receiver_2_beidou_ephemeris_from_json(jr, pos,
                                                              &value->u.gnss_receiver_2_beidou_ephemeris);
    case MIP_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO:
        return mip_gnss_corrections_base_station_info_from_json(jr, pos,
                                                                &value->u.gnss_corrections_base_station_info);
    case MIP_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS:
        return mip_gnss_corrections_rtk_corrections_status_from_json(
            jr, pos, &value->u.gnss_corrections_rtk_corrections_status);
    case MIP_FIELD_GNSS_EXTERNAL_LLH_POSITION:
        return mip_gnss_external_llh_position_from_json(jr, pos, &value->u.gnss_external_llh_position);
    case MIP_FIELD_GNSS_EXTERNAL_NED_VELOCITY:
        return mip_gnss_external_ned_velocity_from_json(jr, pos, &value->u.gnss_external_ned_velocity);
    case MIP_FIELD_GNSS_EXTERNAL_UTC_TIME:
        return mip_gnss_external_utc_time_from_json(jr, pos, &value->u.gnss_external_utc_time);
    case MIP_FIELD_GNSS_EXTERNAL_FIX_INFO:
        return mip_gnss_external_fix_info_from_json(jr, pos, &value->u.gnss_external_fix_info);
    case MIP_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS:
        return mip_gnss_external_satellite_status_from_json(jr, pos,
                                                            &value->u.gnss_external_satellite_status);
    case MIP_FIELD_SYSTEM_DATA_BUILT_IN_TEST:
        return mip_system_data_built_in_test_from_json(jr, pos, &value->u.system_data_built_in_test);
    case MIP_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS:
        return mip_system_data_time_sync_status_from_json(jr, pos, &value->u.system_data_time_sync_status);
    case MIP_FIELD_SYSTEM_DATA_GPIO_STATE:
        return mip_system_data_gpio_state_from_json(jr, pos, &value->u.system_data_gpio_state);
    case MIP_FIELD_SHARED_EVENT_SOURCE:
        return mip_shared_event_source_from_json(jr, pos, &value->u.shared_event_source);
    case MIP_FIELD_SHARED_GPS_TIMESTAMP:
        return mip_shared_gps_timestamp_from_json(jr, pos, &value->u.shared_gps_timestamp);
    case MIP_FIELD_SHARED_DELTA_TIME:
        return mip_shared_delta_time_from_json(jr, pos, &value->u.shared_delta_time);
    case MIP_FIELD_SHARED_REFERENCE_TIMESTAMP:
        return mip_shared_reference_timestamp_from_json(jr, pos, &value->u.shared_reference_timestamp);
    case MIP_FIELD_SHARED_REFERENCE_TIME_DELTA:
        return mip_shared_reference_time_delta_from_json(jr, pos, &value->u.shared_reference_time_delta);
    case MIP_FIELD_SHARED_EXTERNAL_TIMESTAMP:
        return mip_shared_external_timestamp_from_json(jr, pos, &value->u.shared_external_timestamp);
    case MIP_FIELD_SHARED_EXTERNAL_TIME_DELTA:
        return mip_shared_external_time_delta_from_json(jr, pos, &value->u.shared_external_time_delta);
    case MIP_FIELD_NONE:
    case MIP_FIELD_COUNT:
    default:
        (void)pos;
        return mip_jr_fail(jr, "no such field layout");
    }
}
