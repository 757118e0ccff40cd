/* Dispatch tables. Generated from the spec: do not edit. */
#include "mipcodec/dispatch.h"
#include "layouts_internal.h"

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
};

static const mip_field_info_t k_fields[137] = {
    {"ack_nack", 0xF1, MIP_FIELD_ACK_NACK, 1},                                                    /* 0 */
    {"ping", 0x01, MIP_FIELD_BASE_PING, 1},                                                       /* 1 */
    {"set_to_idle", 0x02, MIP_FIELD_BASE_SET_TO_IDLE, 1},                                         /* 2 */
    {"get_device_info", 0x03, MIP_FIELD_BASE_GET_DEVICE_INFO, 1},                                 /* 3 */
    {"device_info", 0x81, MIP_FIELD_BASE_DEVICE_INFO, 1},                                         /* 4 */
    {"get_device_descriptors", 0x04, MIP_FIELD_BASE_GET_DEVICE_DESCRIPTORS, 1},                   /* 5 */
    {"device_descriptors", 0x82, MIP_FIELD_BASE_DEVICE_DESCRIPTORS, 1},                           /* 6 */
    {"built_in_test", 0x05, MIP_FIELD_BASE_BUILT_IN_TEST, 1},                                     /* 7 */
    {"built_in_test_result", 0x83, MIP_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45, 2},                /* 8 */
    {"resume", 0x06, MIP_FIELD_BASE_RESUME, 1},                                                   /* 9 */
    {"get_extended_descriptors", 0x07, MIP_FIELD_BASE_GET_EXTENDED_DESCRIPTORS, 1},               /* 10 */
    {"extended_descriptors", 0x86, MIP_FIELD_BASE_EXTENDED_DESCRIPTORS, 1},                       /* 11 */
    {"continuous_bit", 0x08, MIP_FIELD_BASE_CONTINUOUS_BIT, 1},                                   /* 12 */
    {"continuous_bit_result", 0x88, MIP_FIELD_BASE_CONTINUOUS_BIT_RESULT, 1},                     /* 13 */
    {"comm_port_speed", 0x09, MIP_FIELD_BASE_COMM_PORT_SPEED, 1},                                 /* 14 */
    {"comm_port_speed_response", 0x89, MIP_FIELD_BASE_COMM_PORT_SPEED_RESPONSE, 1},               /* 15 */
    {"gps_time_update", 0x72, MIP_FIELD_BASE_GPS_TIME_UPDATE_GX5_45, 2},                          /* 16 */
    {"gps_week", 0x84, MIP_FIELD_BASE_GPS_WEEK, 1},                                               /* 17 */
    {"gps_seconds", 0x85, MIP_FIELD_BASE_GPS_SECONDS, 1},                                         /* 18 */
    {"device_reset", 0x7E, MIP_FIELD_BASE_DEVICE_RESET, 1},                                       /* 19 */
    {"event_control", 0x2B, MIP_FIELD_THREEDM_EVENT_CONTROL, 1},                                  /* 20 */
    {"event_control_response", 0xB5, MIP_FIELD_THREEDM_EVENT_CONTROL_RESPONSE, 1},                /* 21 */
    {"get_event_trigger_status", 0x2C, MIP_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS, 1},            /* 22 */
    {"event_trigger_status", 0xB6, MIP_FIELD_THREEDM_EVENT_TRIGGER_STATUS, 1},                    /* 23 */
    {"get_event_action_status", 0x2D, MIP_FIELD_THREEDM_GET_EVENT_ACTION_STATUS, 1},              /* 24 */
    {"event_action_status", 0xB7, MIP_FIELD_THREEDM_EVENT_ACTION_STATUS, 1},                      /* 25 */
    {"event_trigger_config", 0x2E, MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG, 1},                    /* 26 */
    {"event_trigger_config_response", 0xB8, MIP_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE, 1},  /* 27 */
    {"event_action_config", 0x2F, MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG, 1},                      /* 28 */
    {"event_action_config_response", 0xB9, MIP_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE, 1},    /* 29 */
    {"reset_filter", 0x01, MIP_FIELD_FILTER_RESET_FILTER, 1},                                     /* 30 */
    {"set_initial_attitude", 0x02, MIP_FIELD_FILTER_SET_INITIAL_ATTITUDE, 1},                     /* 31 */
    {"set_initial_heading", 0x03, MIP_FIELD_FILTER_SET_INITIAL_HEADING, 1},                       /* 32 */
    {"run_filter", 0x05, MIP_FIELD_FILTER_RUN_FILTER, 1},                                         /* 33 */
    {"vehicle_dynamics_mode", 0x10, MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE, 1},                   /* 34 */
    {"vehicle_dynamics_mode_response", 0x80, MIP_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE, 1}, /* 35 */
    {"sensor_to_vehicle_transform", 0x11, MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM, 1},       /* 36 */
    {"sensor_to_vehicle_transform_response", 0x81, MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE,
     1},                                                                              /* 37 */
    {"sensor_to_vehicle_offset", 0x12, MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET, 1}, /* 38 */
    {"sensor_to_vehicle_offset_response", 0x82, MIP_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE,
     1},                                                                                            /* 39 */
    {"antenna_offset", 0x13, MIP_FIELD_FILTER_ANTENNA_OFFSET, 1},                                   /* 40 */
    {"antenna_offset_response", 0x83, MIP_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE, 1},                 /* 41 */
    {"estimation_control", 0x14, MIP_FIELD_FILTER_ESTIMATION_CONTROL, 1},                           /* 42 */
    {"estimation_control_response", 0x84, MIP_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE, 1},         /* 43 */
    {"gnss_source_control", 0x15, MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL, 1},                         /* 44 */
    {"gnss_source_control_response", 0x86, MIP_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE, 1},       /* 45 */
    {"external_gnss_update", 0x16, MIP_FIELD_FILTER_EXTERNAL_GNSS_UPDATE, 1},                       /* 46 */
    {"external_heading_update", 0x17, MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE, 1},                 /* 47 */
    {"heading_update_control", 0x18, MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL, 1},                   /* 48 */
    {"heading_update_control_response", 0x87, MIP_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE, 1}, /* 49 */
    {"auto_init_control", 0x19, MIP_FIELD_FILTER_AUTO_INIT_CONTROL, 1},                             /* 50 */
    {"auto_init_control_response", 0x88, MIP_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE, 1},           /* 51 */
    {"accel_noise", 0x1A, MIP_FIELD_FILTER_ACCEL_NOISE, 1},                                         /* 52 */
    {"accel_noise_response", 0x89, MIP_FIELD_FILTER_ACCEL_NOISE_RESPONSE, 1},                       /* 53 */
    {"gyro_noise", 0x1B, MIP_FIELD_FILTER_GYRO_NOISE, 1},                                           /* 54 */
    {"gyro_noise_response", 0x8A, MIP_FIELD_FILTER_GYRO_NOISE_RESPONSE, 1},                         /* 55 */
    {"accel_bias_model", 0x1C, MIP_FIELD_FILTER_ACCEL_BIAS_MODEL, 1},                               /* 56 */
    {"accel_bias_model_response", 0x8B, MIP_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE, 1},             /* 57 */
    {"gyro_bias_model", 0x1D, MIP_FIELD_FILTER_GYRO_BIAS_MODEL, 1},                                 /* 58 */
    {"gyro_bias_model_response", 0x8C, MIP_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE, 1},               /* 59 */
    {"zupt_control", 0x1E, MIP_FIELD_FILTER_ZUPT_CONTROL, 1},                                       /* 60 */
    {"zupt_control_response", 0x8D, MIP_FIELD_FILTER_ZUPT_CONTROL_RESPONSE, 1},                     /* 61 */
    {"external_heading_update_with_time", 0x1F, MIP_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME,
     1},                                                                                              /* 62 */
    {"zero_angular_rate_update_control", 0x20, MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL, 1}, /* 63 */
    {"zero_angular_rate_update_control_response", 0x8E,
     MIP_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE, 1},  /* 64 */
    {"tare_orientation", 0x21, MIP_FIELD_FILTER_TARE_ORIENTATION, 1}, /* 65 */
    {"commanded_zupt", 0x22, MIP_FIELD_FILTER_COMMANDED_ZUPT, 1},     /* 66 */
    {"commanded_zero_angular_rate_update", 0x23, MIP_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE,
     1},                                                                                            /* 67 */
    {"mag_capture_auto_calibration", 0x27, MIP_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION, 1},       /* 68 */
    {"gravity_noise_std_dev", 0x28, MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV, 1},                     /* 69 */
    {"gravity_noise_std_dev_response", 0x93, MIP_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE, 1},   /* 70 */
    {"pressure_altitude_noise_std_dev", 0x29, MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV, 1}, /* 71 */
    {"pressure_altitude_noise_std_dev_response", 0x94,
     MIP_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE, 1},                                 /* 72 */
    {"hard_iron_offset_noise", 0x2B, MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE, 1},                   /* 73 */
    {"hard_iron_offset_noise_response", 0x96, MIP_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE, 1}, /* 74 */
    {"soft_iron_matrix_noise", 0x2C, MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE, 1},                   /* 75 */
    {"soft_iron_matrix_noise_response", 0x97, MIP_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE, 1}, /* 76 */
    {"mag_noise_std_dev", 0x42, MIP_FIELD_FILTER_MAG_NOISE_STD_DEV, 1},                             /* 77 */
    {"mag_noise_std_dev_response", 0xB1, MIP_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE, 1},           /* 78 */
    {"declination_source", 0x43, MIP_FIELD_FILTER_DECLINATION_SOURCE, 1},                           /* 79 */
    {"declination_source_response", 0xB2, MIP_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE, 1},         /* 80 */
    {"gravity_magnitude_adaptive_measurement", 0x44, MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT,
     1}, /* 81 */
    {"gravity_magnitude_adaptive_measurement_response", 0xB3,
     MIP_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE, 1}, /* 82 */
    {"mag_magnitude_adaptive_measurement", 0x45, MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT,
     1}, /* 83 */
    {"mag_magnitude_adaptive_measurement_response", 0xB4,
     MIP_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE, 1}, /* 84 */
    {"mag_dip_angle_adaptive_measurement", 0x46, MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT,
     1}, /* 85 */
    {"mag_dip_angle_adaptive_measurement_response", 0xB5,
     MIP_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE, 1},                                /* 86 */
    {"altitude_aiding_control", 0x47, MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL, 1},                   /* 87 */
    {"altitude_aiding_control_response", 0xB7, MIP_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE, 1}, /* 88 */
    {"pitch_roll_aiding_control", 0x4B, MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL, 1},               /* 89 */
    {"pitch_roll_aiding_control_response", 0xBB, MIP_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE,
     1},                                                                                            /* 90 */
    {"inclination_source", 0x4C, MIP_FIELD_FILTER_INCLINATION_SOURCE, 1},                           /* 91 */
    {"inclination_source_response", 0xBC, MIP_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE, 1},         /* 92 */
    {"magnetic_field_magnitude_source", 0x4D, MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE, 1}, /* 93 */
    {"magnetic_field_magnitude_source_response", 0xBD,
     MIP_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE, 1},                       /* 94 */
    {"aiding_measurement_control", 0x50, MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL, 1}, /* 95 */
    {"aiding_measurement_control_response", 0xD0, MIP_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE,
     1},                                                                                      /* 96 */
    {"initialization_configuration", 0x52, MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION, 1}, /* 97 */
    {"initialization_configuration_response", 0xD2, MIP_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE,
     1},                                                                            /* 98 */
    {"adaptive_filter_control", 0x53, MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL, 1}, /* 99 */
    {"adaptive_filter_control_response", 0xD3, MIP_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE,
     1},                                                                                            /* 100 */
    {"multi_antenna_offset", 0x54, MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET, 1},                       /* 101 */
    {"multi_antenna_offset_response", 0xD4, MIP_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE, 1},     /* 102 */
    {"relative_position_configuration", 0x55, MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION, 1}, /* 103 */
    {"relative_position_configuration_response", 0xD5,
     MIP_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE, 1},                     /* 104 */
    {"reference_point_lever_arm", 0x56, MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM, 1}, /* 105 */
    {"reference_point_lever_arm_response", 0xD6, MIP_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE,
     1},                                                                              /* 106 */
    {"speed_lever_arm", 0x61, MIP_FIELD_FILTER_SPEED_LEVER_ARM, 1},                   /* 107 */
    {"speed_lever_arm_response", 0xE1, MIP_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE, 1}, /* 108 */
    {"wheeled_vehicle_constraint_control", 0x63, MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL,
     1}, /* 109 */
    {"wheeled_vehicle_constraint_control_response", 0xE3,
     MIP_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE, 1}, /* 110 */
    {"gnss_antenna_calibration_control", 0x64, MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL,
     1}, /* 111 */
    {"gnss_antenna_calibration_control_response", 0xE4,
     MIP_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE, 1},                          /* 112 */
    {"receiver_info", 0x01, MIP_FIELD_GNSS_RECEIVER_INFO, 1},                                 /* 113 */
    {"receiver_info_response", 0x81, MIP_FIELD_GNSS_RECEIVER_INFO_RESPONSE, 1},               /* 114 */
    {"signal_configuration", 0x02, MIP_FIELD_GNSS_SIGNAL_CONFIGURATION, 1},                   /* 115 */
    {"signal_configuration_response", 0x82, MIP_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE, 1}, /* 116 */
    {"spartn_configuration", 0x20, MIP_FIELD_GNSS_SPARTN_CONFIGURATION, 1},                   /* 117 */
    {"spartn_configuration_response", 0xA0, MIP_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE, 1}, /* 118 */
    {"frame_config", 0x01, MIP_FIELD_AIDING_FRAME_CONFIG, 1},                                 /* 119 */
    {"frame_config_response", 0x81, MIP_FIELD_AIDING_FRAME_CONFIG_RESPONSE, 1},               /* 120 */
    {"echo_control", 0x1F, MIP_FIELD_AIDING_ECHO_CONTROL, 1},                                 /* 121 */
    {"echo_control_response", 0x9F, MIP_FIELD_AIDING_ECHO_CONTROL_RESPONSE, 1},               /* 122 */
    {"ecef_position", 0x21, MIP_FIELD_AIDING_ECEF_POSITION, 1},                               /* 123 */
    {"llh_position", 0x22, MIP_FIELD_AIDING_LLH_POSITION, 1},                                 /* 124 */
    {"height_above_ellipsoid", 0x23, MIP_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID, 1},             /* 125 */
    {"ecef_velocity", 0x28, MIP_FIELD_AIDING_ECEF_VELOCITY, 1},                               /* 126 */
    {"ned_velocity", 0x29, MIP_FIELD_AIDING_NED_VELOCITY, 1},                                 /* 127 */
    {"body_frame_velocity", 0x2A, MIP_FIELD_AIDING_BODY_FRAME_VELOCITY, 1},                   /* 128 */
    {"true_heading", 0x31, MIP_FIELD_AIDING_TRUE_HEADING, 1},                                 /* 129 */
    {"magnetic_field", 0x32, MIP_FIELD_AIDING_MAGNETIC_FIELD, 1},                             /* 130 */
    {"pressure", 0x33, MIP_FIELD_AIDING_PRESSURE, 1},                                         /* 131 */
    {"communication_mode", 0x10, MIP_FIELD_SYSTEM_COMMUNICATION_MODE, 1},                     /* 132 */
    {"communication_mode_response", 0x90, MIP_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE, 1},   /* 133 */
    {"scaled_accel", 0x04, MIP_FIELD_SENSOR_SCALED_ACCEL, 1},                                 /* 134 */
    {"scaled_gyro", 0x05, MIP_FIELD_SENSOR_SCALED_GYRO, 1},                                   /* 135 */
    {"scaled_mag", 0x06, MIP_FIELD_SENSOR_SCALED_MAG, 1},                                     /* 136 */
};

const mip_layout_info_t *mip_layout_info(mip_field_id_t id) {
    if ((size_t)id >= MIP_FIELD_COUNT) {
        return NULL;
    }
    return &k_layouts[id];
}

/* Fields defined in a set; *set_known tells whether the set is defined at all. */
static const mip_field_info_t *defined(uint8_t set, uint8_t descriptor, bool *set_known) {
    *set_known = true;
    switch (set) {
    case 0x01: /* base */
        switch (descriptor) {
        case 0x01:
            return &k_fields[1]; /* ping */
        case 0x02:
            return &k_fields[2]; /* set_to_idle */
        case 0x03:
            return &k_fields[3]; /* get_device_info */
        case 0x81:
            return &k_fields[4]; /* device_info */
        case 0x04:
            return &k_fields[5]; /* get_device_descriptors */
        case 0x82:
            return &k_fields[6]; /* device_descriptors */
        case 0x05:
            return &k_fields[7]; /* built_in_test */
        case 0x83:
            return &k_fields[8]; /* built_in_test_result */
        case 0x06:
            return &k_fields[9]; /* resume */
        case 0x07:
            return &k_fields[10]; /* get_extended_descriptors */
        case 0x86:
            return &k_fields[11]; /* extended_descriptors */
        case 0x08:
            return &k_fields[12]; /* continuous_bit */
        case 0x88:
            return &k_fields[13]; /* continuous_bit_result */
        case 0x09:
            return &k_fields[14]; /* comm_port_speed */
        case 0x89:
            return &k_fields[15]; /* comm_port_speed_response */
        case 0x72:
            return &k_fields[16]; /* gps_time_update */
        case 0x84:
            return &k_fields[17]; /* gps_week */
        case 0x85:
            return &k_fields[18]; /* gps_seconds */
        case 0x7E:
            return &k_fields[19]; /* device_reset */
        default:
            return NULL;
        }
    case 0x0C: /* threedm */
        switch (descriptor) {
        case 0x2B:
            return &k_fields[20]; /* event_control */
        case 0xB5:
            return &k_fields[21]; /* event_control_response */
        case 0x2C:
            return &k_fields[22]; /* get_event_trigger_status */
        case 0xB6:
            return &k_fields[23]; /* event_trigger_status */
        case 0x2D:
            return &k_fields[24]; /* get_event_action_status */
        case 0xB7:
            return &k_fields[25]; /* event_action_status */
        case 0x2E:
            return &k_fields[26]; /* event_trigger_config */
        case 0xB8:
            return &k_fields[27]; /* event_trigger_config_response */
        case 0x2F:
            return &k_fields[28]; /* event_action_config */
        case 0xB9:
            return &k_fields[29]; /* event_action_config_response */
        default:
            return NULL;
        }
    case 0x0D: /* filter */
        switch (descriptor) {
        case 0x01:
            return &k_fields[30]; /* reset_filter */
        case 0x02:
            return &k_fields[31]; /* set_initial_attitude */
        case 0x03:
            return &k_fields[32]; /* set_initial_heading */
        case 0x05:
            return &k_fields[33]; /* run_filter */
        case 0x10:
            return &k_fields[34]; /* vehicle_dynamics_mode */
        case 0x80:
            return &k_fields[35]; /* vehicle_dynamics_mode_response */
        case 0x11:
            return &k_fields[36]; /* sensor_to_vehicle_transform */
        case 0x81:
            return &k_fields[37]; /* sensor_to_vehicle_transform_response */
        case 0x12:
            return &k_fields[38]; /* sensor_to_vehicle_offset */
        case 0x82:
            return &k_fields[39]; /* sensor_to_vehicle_offset_response */
        case 0x13:
            return &k_fields[40]; /* antenna_offset */
        case 0x83:
            return &k_fields[41]; /* antenna_offset_response */
        case 0x14:
            return &k_fields[42]; /* estimation_control */
        case 0x84:
            return &k_fields[43]; /* estimation_control_response */
        case 0x15:
            return &k_fields[44]; /* gnss_source_control */
        case 0x86:
            return &k_fields[45]; /* gnss_source_control_response */
        case 0x16:
            return &k_fields[46]; /* external_gnss_update */
        case 0x17:
            return &k_fields[47]; /* external_heading_update */
        case 0x18:
            return &k_fields[48]; /* heading_update_control */
        case 0x87:
            return &k_fields[49]; /* heading_update_control_response */
        case 0x19:
            return &k_fields[50]; /* auto_init_control */
        case 0x88:
            return &k_fields[51]; /* auto_init_control_response */
        case 0x1A:
            return &k_fields[52]; /* accel_noise */
        case 0x89:
            return &k_fields[53]; /* accel_noise_response */
        case 0x1B:
            return &k_fields[54]; /* gyro_noise */
        case 0x8A:
            return &k_fields[55]; /* gyro_noise_response */
        case 0x1C:
            return &k_fields[56]; /* accel_bias_model */
        case 0x8B:
            return &k_fields[57]; /* accel_bias_model_response */
        case 0x1D:
            return &k_fields[58]; /* gyro_bias_model */
        case 0x8C:
            return &k_fields[59]; /* gyro_bias_model_response */
        case 0x1E:
            return &k_fields[60]; /* zupt_control */
        case 0x8D:
            return &k_fields[61]; /* zupt_control_response */
        case 0x1F:
            return &k_fields[62]; /* external_heading_update_with_time */
        case 0x20:
            return &k_fields[63]; /* zero_angular_rate_update_control */
        case 0x8E:
            return &k_fields[64]; /* zero_angular_rate_update_control_response */
        case 0x21:
            return &k_fields[65]; /* tare_orientation */
        case 0x22:
            return &k_fields[66]; /* commanded_zupt */
        case 0x23:
            return &k_fields[67]; /* commanded_zero_angular_rate_update */
        case 0x27:
            return &k_fields[68]; /* mag_capture_auto_calibration */
        case 0x28:
            return &k_fields[69]; /* gravity_noise_std_dev */
        case 0x93:
            return &k_fields[70]; /* gravity_noise_std_dev_response */
        case 0x29:
            return &k_fields[71]; /* pressure_altitude_noise_std_dev */
        case 0x94:
            return &k_fields[72]; /* pressure_altitude_noise_std_dev_response */
        case 0x2B:
            return &k_fields[73]; /* hard_iron_offset_noise */
        case 0x96:
            return &k_fields[74]; /* hard_iron_offset_noise_response */
        case 0x2C:
            return &k_fields[75]; /* soft_iron_matrix_noise */
        case 0x97:
            return &k_fields[76]; /* soft_iron_matrix_noise_response */
        case 0x42:
            return &k_fields[77]; /* mag_noise_std_dev */
        case 0xB1:
            return &k_fields[78]; /* mag_noise_std_dev_response */
        case 0x43:
            return &k_fields[79]; /* declination_source */
        case 0xB2:
            return &k_fields[80]; /* declination_source_response */
        case 0x44:
            return &k_fields[81]; /* gravity_magnitude_adaptive_measurement */
        case 0xB3:
            return &k_fields[82]; /* gravity_magnitude_adaptive_measurement_response */
        case 0x45:
            return &k_fields[83]; /* mag_magnitude_adaptive_measurement */
        case 0xB4:
            return &k_fields[84]; /* mag_magnitude_adaptive_measurement_response */
        case 0x46:
            return &k_fields[85]; /* mag_dip_angle_adaptive_measurement */
        case 0xB5:
            return &k_fields[86]; /* mag_dip_angle_adaptive_measurement_response */
        case 0x47:
            return &k_fields[87]; /* altitude_aiding_control */
        case 0xB7:
            return &k_fields[88]; /* altitude_aiding_control_response */
        case 0x4B:
            return &k_fields[89]; /* pitch_roll_aiding_control */
        case 0xBB:
            return &k_fields[90]; /* pitch_roll_aiding_control_response */
        case 0x4C:
            return &k_fields[91]; /* inclination_source */
        case 0xBC:
            return &k_fields[92]; /* inclination_source_response */
        case 0x4D:
            return &k_fields[93]; /* magnetic_field_magnitude_source */
        case 0xBD:
            return &k_fields[94]; /* magnetic_field_magnitude_source_response */
        case 0x50:
            return &k_fields[95]; /* aiding_measurement_control */
        case 0xD0:
            return &k_fields[96]; /* aiding_measurement_control_response */
        case 0x52:
            return &k_fields[97]; /* initialization_configuration */
        case 0xD2:
            return &k_fields[98]; /* initialization_configuration_response */
        case 0x53:
            return &k_fields[99]; /* adaptive_filter_control */
        case 0xD3:
            return &k_fields[100]; /* adaptive_filter_control_response */
        case 0x54:
            return &k_fields[101]; /* multi_antenna_offset */
        case 0xD4:
            return &k_fields[102]; /* multi_antenna_offset_response */
        case 0x55:
            return &k_fields[103]; /* relative_position_configuration */
        case 0xD5:
            return &k_fields[104]; /* relative_position_configuration_response */
        case 0x56:
            return &k_fields[105]; /* reference_point_lever_arm */
        case 0xD6:
            return &k_fields[106]; /* reference_point_lever_arm_response */
        case 0x61:
            return &k_fields[107]; /* speed_lever_arm */
        case 0xE1:
            return &k_fields[108]; /* speed_lever_arm_response */
        case 0x63:
            return &k_fields[109]; /* wheeled_vehicle_constraint_control */
        case 0xE3:
            return &k_fields[110]; /* wheeled_vehicle_constraint_control_response */
        case 0x64:
            return &k_fields[111]; /* gnss_antenna_calibration_control */
        case 0xE4:
            return &k_fields[112]; /* gnss_antenna_calibration_control_response */
        default:
            return NULL;
        }
    case 0x0E: /* gnss */
        switch (descriptor) {
        case 0x01:
            return &k_fields[113]; /* receiver_info */
        case 0x81:
            return &k_fields[114]; /* receiver_info_response */
        case 0x02:
            return &k_fields[115]; /* signal_configuration */
        case 0x82:
            return &k_fields[116]; /* signal_configuration_response */
        case 0x20:
            return &k_fields[117]; /* spartn_configuration */
        case 0xA0:
            return &k_fields[118]; /* spartn_configuration_response */
        default:
            return NULL;
        }
    case 0x13: /* aiding */
        switch (descriptor) {
        case 0x01:
            return &k_fields[119]; /* frame_config */
        case 0x81:
            return &k_fields[120]; /* frame_config_response */
        case 0x1F:
            return &k_fields[121]; /* echo_control */
        case 0x9F:
            return &k_fields[122]; /* echo_control_response */
        case 0x21:
            return &k_fields[123]; /* ecef_position */
        case 0x22:
            return &k_fields[124]; /* llh_position */
        case 0x23:
            return &k_fields[125]; /* height_above_ellipsoid */
        case 0x28:
            return &k_fields[126]; /* ecef_velocity */
        case 0x29:
            return &k_fields[127]; /* ned_velocity */
        case 0x2A:
            return &k_fields[128]; /* body_frame_velocity */
        case 0x31:
            return &k_fields[129]; /* true_heading */
        case 0x32:
            return &k_fields[130]; /* magnetic_field */
        case 0x33:
            return &k_fields[131]; /* pressure */
        default:
            return NULL;
        }
    case 0x7F: /* system */
        switch (descriptor) {
        case 0x10:
            return &k_fields[132]; /* communication_mode */
        case 0x90:
            return &k_fields[133]; /* communication_mode_response */
        default:
            return NULL;
        }
    case 0x80: /* sensor */
        switch (descriptor) {
        case 0x04:
            return &k_fields[134]; /* scaled_accel */
        case 0x05:
            return &k_fields[135]; /* scaled_gyro */
        case 0x06:
            return &k_fields[136]; /* scaled_mag */
        default:
            return NULL;
        }
    default:
        (void)descriptor;
        *set_known = false;
        return NULL;
    }
}

const mip_field_info_t *mip_find_field(uint8_t set, uint8_t descriptor, mip_status_t *why) {
    bool known = false;
    mip_set_kind_t kind = mip_set_kind(set);
    const mip_field_info_t *f = defined(set, descriptor, &known);
    if (f) {
        return f;
    }
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
    if (why) {
        *why = known ? MIP_ERR_UNKNOWN_DESCRIPTOR : MIP_ERR_UNKNOWN_SET;
    }
    return NULL;
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
    case MIP_FIELD_NONE:
    case MIP_FIELD_COUNT:
    default:
        return MIP_ERR_INVALID;
    }
}

mip_status_t mip_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                              mip_device_t device, mip_field_value_t *out, mip_decode_error_t *err) {
    mip_status_t why = MIP_ERR_UNKNOWN_SET;
    const mip_field_info_t *f = mip_find_field(set, descriptor, &why);
    size_t first;
    size_t count;
    size_t i;
    mip_decode_error_t first_err;
    mip_decode_error_t other_err;
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
    memset(&first_err, 0, sizeof first_err);
    for (i = 0; i < count; i++) {
        if (decode_layout((mip_field_id_t)(first + i), data, len, out, i == 0 ? &first_err : &other_err) ==
            MIP_OK) {
            return MIP_OK;
        }
    }
    out->id = MIP_FIELD_NONE;
    if (err) {
        *err = first_err;
    }
    return MIP_ERR_DECODE;
}

mip_status_t mip_encode_field(const mip_field_value_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
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
    case MIP_FIELD_NONE:
    case MIP_FIELD_COUNT:
    default:
        (void)pos;
        return mip_jr_fail(jr, "no such field layout");
    }
}
