/* Dispatch tables. Generated from the spec: do not edit. */
#include "mipcodec/dispatch.h"
#include "layouts_internal.h"

#include <assert.h>
#include <string.h>

const char *mipc_device_id(mipc_device_t device) {
    switch (device) {
    case MIPC_DEVICE_GX5_45:
        return "gx5_45";
    case MIPC_DEVICE_CV7_INS:
        return "cv7_ins";
    case MIPC_DEVICE_ANY:
    default:
        return NULL;
    }
}

bool mipc_device_from_id(const char *id, mipc_device_t *out) {
    assert(id != NULL);
    assert(out != NULL);
    if (strcmp(id, "gx5_45") == 0) {
        *out = MIPC_DEVICE_GX5_45;
        return true;
    }
    if (strcmp(id, "cv7_ins") == 0) {
        *out = MIPC_DEVICE_CV7_INS;
        return true;
    }
    (void)id;
    (void)out;
    return false;
}

const char *mipc_device_title(mipc_device_t device) {
    switch (device) {
    case MIPC_DEVICE_GX5_45:
        return "3DM-GX5-45";
    case MIPC_DEVICE_CV7_INS:
        return "3DM-CV7-GNSS/INS";
    case MIPC_DEVICE_ANY:
    default:
        return NULL;
    }
}

const char *mipc_device_manual(mipc_device_t device) {
    switch (device) {
    case MIPC_DEVICE_GX5_45:
        return "3dm-gx5-45-dcp.txt";
    case MIPC_DEVICE_CV7_INS:
        return "3dm-cv7-ins-docs.txt";
    case MIPC_DEVICE_ANY:
    default:
        return NULL;
    }
}

/* The capabilities tables: (set << 8) | descriptor, ascending (a leading 0 keeps an empty one legal). */
static const uint16_t k_gx5_45_commands[] = {
    0,      0x0101, 0x0102, 0x0103, 0x0104, 0x0105, 0x0106, 0x0107, 0x0172, 0x017E, 0x0C01, 0x0C02, 0x0C03,
    0x0C06, 0x0C07, 0x0C08, 0x0C09, 0x0C0A, 0x0C0B, 0x0C11, 0x0C20, 0x0C21, 0x0C22, 0x0C23, 0x0C24, 0x0C30,
    0x0C37, 0x0C38, 0x0C39, 0x0C3A, 0x0C3B, 0x0C3E, 0x0C40, 0x0C50, 0x0C51, 0x0C64, 0x0D01, 0x0D02, 0x0D03,
    0x0D10, 0x0D11, 0x0D12, 0x0D13, 0x0D14, 0x0D15, 0x0D16, 0x0D17, 0x0D18, 0x0D19, 0x0D1A, 0x0D1B, 0x0D1C,
    0x0D1D, 0x0D1E, 0x0D1F, 0x0D20, 0x0D21, 0x0D22, 0x0D23, 0x0D27, 0x0D28, 0x0D29, 0x0D2B, 0x0D2C, 0x0D42,
    0x0D43, 0x0D44, 0x0D45, 0x0D46, 0x0D47, 0x0D4B, 0x0D4C, 0x0D4D, 0x7F10};
static const uint16_t k_gx5_45_data[] = {
    0,      0x8004, 0x8005, 0x8006, 0x8007, 0x8008, 0x8009, 0x800A, 0x800C, 0x8010, 0x8011, 0x8012,
    0x8017, 0x8103, 0x8104, 0x8105, 0x8106, 0x8107, 0x8108, 0x8109, 0x810A, 0x810B, 0x810C, 0x810D,
    0x810E, 0x810F, 0x8201, 0x8202, 0x8203, 0x8204, 0x8205, 0x8206, 0x8207, 0x8208, 0x8209, 0x820A,
    0x820B, 0x820C, 0x820D, 0x820E, 0x820F, 0x8210, 0x8211, 0x8212, 0x8213, 0x8214, 0x8215, 0x8216,
    0x8217, 0x8218, 0x8219, 0x821C, 0x8220, 0x8221, 0x8225, 0x8226, 0x8228, 0x8229, 0x8230, 0x8231};
static const uint16_t k_cv7_ins_commands[] = {
    0,      0x0101, 0x0102, 0x0103, 0x0104, 0x0105, 0x0106, 0x0107, 0x0108, 0x0109, 0x0172, 0x017E,
    0x0C04, 0x0C0C, 0x0C0D, 0x0C0E, 0x0C0F, 0x0C10, 0x0C11, 0x0C22, 0x0C28, 0x0C2A, 0x0C2B, 0x0C2C,
    0x0C2D, 0x0C2E, 0x0C2F, 0x0C30, 0x0C31, 0x0C32, 0x0C33, 0x0C37, 0x0C38, 0x0C39, 0x0C3A, 0x0C3B,
    0x0C40, 0x0C41, 0x0C42, 0x0C43, 0x0C50, 0x0C51, 0x0C52, 0x0C53, 0x0C54, 0x0D01, 0x0D03, 0x0D05,
    0x0D13, 0x0D15, 0x0D17, 0x0D1A, 0x0D1B, 0x0D1C, 0x0D1D, 0x0D1F, 0x0D20, 0x0D28, 0x0D43, 0x0D50,
    0x0D52, 0x0D53, 0x0D54, 0x0D55, 0x0D56, 0x0D61, 0x0D63, 0x0D64, 0x0E01, 0x0E02, 0x0E20, 0x1301,
    0x131F, 0x1321, 0x1322, 0x1323, 0x1328, 0x1329, 0x132A, 0x1331, 0x1332, 0x1333};
static const uint16_t k_cv7_ins_data[] = {
    0,      0x8004, 0x8005, 0x8006, 0x8007, 0x8008, 0x8009, 0x800A, 0x800C, 0x8012, 0x8014, 0x8017,
    0x8018, 0x8040, 0x8201, 0x8202, 0x8203, 0x8204, 0x8205, 0x8206, 0x8207, 0x8208, 0x8209, 0x820A,
    0x820B, 0x820C, 0x820D, 0x820E, 0x8210, 0x8211, 0x8212, 0x8213, 0x8215, 0x821C, 0x8221, 0x8234,
    0x8235, 0x8236, 0x8237, 0x8240, 0x8241, 0x8242, 0x8243, 0x8246, 0x8247, 0x8248, 0x8249, 0x8250,
    0x8251, 0x9103, 0x9104, 0x9105, 0x9106, 0x9107, 0x9108, 0x9109, 0x910B, 0x910D, 0x9110, 0x9111,
    0x9112, 0x9120, 0x9122, 0x9161, 0x9162, 0x9163, 0x9164, 0x9203, 0x9204, 0x9205, 0x9206, 0x9207,
    0x9208, 0x9209, 0x920B, 0x920D, 0x9210, 0x9211, 0x9212, 0x9220, 0x9222, 0x9261, 0x9262, 0x9263,
    0x9264, 0x9330, 0x9331, 0x9403, 0x9405, 0x9408, 0x940B, 0x9420, 0xA001, 0xA002, 0xA003};

static const uint16_t *device_table(mipc_device_t device, bool data, size_t *count) {
    switch (device) {
    case MIPC_DEVICE_GX5_45:
        *count = data ? 59u : 73u;
        return (data ? k_gx5_45_data : k_gx5_45_commands) + 1;
    case MIPC_DEVICE_CV7_INS:
        *count = data ? 94u : 81u;
        return (data ? k_cv7_ins_data : k_cv7_ins_commands) + 1;
    case MIPC_DEVICE_ANY:
    default:
        *count = 0;
        return NULL;
    }
}

const uint16_t *mipc_device_commands(mipc_device_t device, size_t *count) {
    assert(count != NULL);
    return device_table(device, false, count);
}

const uint16_t *mipc_device_data(mipc_device_t device, size_t *count) {
    assert(count != NULL);
    return device_table(device, true, count);
}

/* The baud rates of each device's main port (the IR's `link`), ascending. */
static const uint32_t k_gx5_45_baud_rates[] = {9600u, 19200u, 115200u, 230400u, 460800u, 921600u};
static const uint32_t k_cv7_ins_baud_rates[] = {115200u, 230400u, 460800u, 921600u, 3000000u};

const uint32_t *mipc_device_baud_rates(mipc_device_t device, size_t *count) {
    assert(count != NULL);
    switch (device) {
    case MIPC_DEVICE_GX5_45:
        *count = 6u;
        return k_gx5_45_baud_rates;
    case MIPC_DEVICE_CV7_INS:
        *count = 5u;
        return k_cv7_ins_baud_rates;
    case MIPC_DEVICE_ANY:
    default:
        *count = 0;
        return NULL;
    }
}

uint32_t mipc_device_default_baud(mipc_device_t device) {
    switch (device) {
    case MIPC_DEVICE_GX5_45:
        return 115200u;
    case MIPC_DEVICE_CV7_INS:
        return 0u;
    case MIPC_DEVICE_ANY:
    default:
        return 0u;
    }
}

static bool table_has(const uint16_t *table, size_t n, uint16_t key) {
    size_t lo = 0;
    while (lo < n) {
        size_t mid = lo + (n - lo) / 2u;
        if (table[mid] == key) {
            return true;
        }
        if (table[mid] < key) {
            lo = mid + 1u;
        } else {
            n = mid;
        }
    }
    return false;
}

bool mipc_device_supports(mipc_device_t device, uint8_t set, uint8_t descriptor) {
    size_t n;
    uint16_t key = (uint16_t)(((unsigned)set << 8) | descriptor);
    const uint16_t *t = device_table(device, false, &n);
    if (t != NULL && table_has(t, n, key)) {
        return true;
    }
    t = device_table(device, true, &n);
    return t != NULL && table_has(t, n, key);
}

mipc_set_kind_t mipc_set_kind(uint8_t set) {
    if (set >= 0x01 && set <= 0x7F) {
        return MIPC_SET_KIND_COMMAND;
    }
    if (set >= 0x80 && 1) {
        return MIPC_SET_KIND_DATA;
    }
    (void)set;
    return MIPC_SET_KIND_NONE;
}

static const mipc_layout_info_t k_layouts[MIPC_FIELD_COUNT] = {
    {MIPC_FIELD_NONE, NULL, NULL, MIPC_DEVICE_ANY, 0},
    {MIPC_FIELD_ACK_NACK, "ack_nack", NULL, MIPC_DEVICE_ANY, 0xF1},
    {MIPC_FIELD_BASE_PING, "ping", NULL, MIPC_DEVICE_ANY, 0x01},
    {MIPC_FIELD_BASE_SET_TO_IDLE, "set_to_idle", NULL, MIPC_DEVICE_ANY, 0x02},
    {MIPC_FIELD_BASE_GET_DEVICE_INFO, "get_device_info", NULL, MIPC_DEVICE_ANY, 0x03},
    {MIPC_FIELD_BASE_DEVICE_INFO, "device_info", NULL, MIPC_DEVICE_ANY, 0x81},
    {MIPC_FIELD_BASE_GET_DEVICE_DESCRIPTORS, "get_device_descriptors", NULL, MIPC_DEVICE_ANY, 0x04},
    {MIPC_FIELD_BASE_DEVICE_DESCRIPTORS, "device_descriptors", NULL, MIPC_DEVICE_ANY, 0x82},
    {MIPC_FIELD_BASE_BUILT_IN_TEST, "built_in_test", NULL, MIPC_DEVICE_ANY, 0x05},
    {MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45, "built_in_test_result", "gx5_45", MIPC_DEVICE_GX5_45, 0x83},
    {MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS, "built_in_test_result", "cv7_ins", MIPC_DEVICE_CV7_INS,
     0x83},
    {MIPC_FIELD_BASE_RESUME, "resume", NULL, MIPC_DEVICE_ANY, 0x06},
    {MIPC_FIELD_BASE_GET_EXTENDED_DESCRIPTORS, "get_extended_descriptors", NULL, MIPC_DEVICE_ANY, 0x07},
    {MIPC_FIELD_BASE_EXTENDED_DESCRIPTORS, "extended_descriptors", NULL, MIPC_DEVICE_ANY, 0x86},
    {MIPC_FIELD_BASE_CONTINUOUS_BIT, "continuous_bit", NULL, MIPC_DEVICE_ANY, 0x08},
    {MIPC_FIELD_BASE_CONTINUOUS_BIT_RESULT, "continuous_bit_result", NULL, MIPC_DEVICE_ANY, 0x88},
    {MIPC_FIELD_BASE_COMM_PORT_SPEED, "comm_port_speed", NULL, MIPC_DEVICE_ANY, 0x09},
    {MIPC_FIELD_BASE_COMM_PORT_SPEED_RESPONSE, "comm_port_speed_response", NULL, MIPC_DEVICE_ANY, 0x89},
    {MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45, "gps_time_update", "gx5_45", MIPC_DEVICE_GX5_45, 0x72},
    {MIPC_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS, "gps_time_update", "cv7_ins", MIPC_DEVICE_CV7_INS, 0x72},
    {MIPC_FIELD_BASE_GPS_WEEK, "gps_week", NULL, MIPC_DEVICE_ANY, 0x84},
    {MIPC_FIELD_BASE_GPS_SECONDS, "gps_seconds", NULL, MIPC_DEVICE_ANY, 0x85},
    {MIPC_FIELD_BASE_DEVICE_RESET, "device_reset", NULL, MIPC_DEVICE_ANY, 0x7E},
    {MIPC_FIELD_THREEDM_EVENT_CONTROL, "event_control", NULL, MIPC_DEVICE_ANY, 0x2B},
    {MIPC_FIELD_THREEDM_EVENT_CONTROL_RESPONSE, "event_control_response", NULL, MIPC_DEVICE_ANY, 0xB5},
    {MIPC_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS, "get_event_trigger_status", NULL, MIPC_DEVICE_ANY, 0x2C},
    {MIPC_FIELD_THREEDM_EVENT_TRIGGER_STATUS, "event_trigger_status", NULL, MIPC_DEVICE_ANY, 0xB6},
    {MIPC_FIELD_THREEDM_GET_EVENT_ACTION_STATUS, "get_event_action_status", NULL, MIPC_DEVICE_ANY, 0x2D},
    {MIPC_FIELD_THREEDM_EVENT_ACTION_STATUS, "event_action_status", NULL, MIPC_DEVICE_ANY, 0xB7},
    {MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG, "event_trigger_config", NULL, MIPC_DEVICE_ANY, 0x2E},
    {MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE, "event_trigger_config_response", NULL, MIPC_DEVICE_ANY,
     0xB8},
    {MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG, "event_action_config", NULL, MIPC_DEVICE_ANY, 0x2F},
    {MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE, "event_action_config_response", NULL, MIPC_DEVICE_ANY,
     0xB9},
    {MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45, "device_startup_settings", "gx5_45",
     MIPC_DEVICE_GX5_45, 0x30},
    {MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS, "device_startup_settings", "cv7_ins",
     MIPC_DEVICE_CV7_INS, 0x30},
    {MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER, "sensor_to_vehicle_euler", NULL, MIPC_DEVICE_ANY, 0x31},
    {MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE, "sensor_to_vehicle_euler_response", NULL,
     MIPC_DEVICE_ANY, 0xB1},
    {MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION, "sensor_to_vehicle_quaternion", NULL, MIPC_DEVICE_ANY,
     0x32},
    {MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE, "sensor_to_vehicle_quaternion_response", NULL,
     MIPC_DEVICE_ANY, 0xB2},
    {MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM, "sensor_to_vehicle_dcm", NULL, MIPC_DEVICE_ANY, 0x33},
    {MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE, "sensor_to_vehicle_dcm_response", NULL,
     MIPC_DEVICE_ANY, 0xB3},
    {MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45, "accel_bias", "gx5_45", MIPC_DEVICE_GX5_45, 0x37},
    {MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS, "accel_bias", "cv7_ins", MIPC_DEVICE_CV7_INS, 0x37},
    {MIPC_FIELD_THREEDM_ACCEL_BIAS_RESPONSE, "accel_bias_response", NULL, MIPC_DEVICE_ANY, 0x9A},
    {MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45, "gyro_bias", "gx5_45", MIPC_DEVICE_GX5_45, 0x38},
    {MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS, "gyro_bias", "cv7_ins", MIPC_DEVICE_CV7_INS, 0x38},
    {MIPC_FIELD_THREEDM_GYRO_BIAS_RESPONSE, "gyro_bias_response", NULL, MIPC_DEVICE_ANY, 0x9B},
    {MIPC_FIELD_THREEDM_CAPTURE_GYRO_BIAS, "capture_gyro_bias", NULL, MIPC_DEVICE_ANY, 0x39},
    {MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45, "mag_hard_iron_offset", "gx5_45", MIPC_DEVICE_GX5_45,
     0x3A},
    {MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS, "mag_hard_iron_offset", "cv7_ins", MIPC_DEVICE_CV7_INS,
     0x3A},
    {MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE, "mag_hard_iron_offset_response", NULL, MIPC_DEVICE_ANY,
     0x9C},
    {MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45, "mag_soft_iron_matrix", "gx5_45", MIPC_DEVICE_GX5_45,
     0x3B},
    {MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS, "mag_soft_iron_matrix", "cv7_ins", MIPC_DEVICE_CV7_INS,
     0x3B},
    {MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE, "mag_soft_iron_matrix_response", NULL, MIPC_DEVICE_ANY,
     0x9D},
    {MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE, "coning_sculling_enable", NULL, MIPC_DEVICE_ANY, 0x3E},
    {MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE, "coning_sculling_enable_response", NULL,
     MIPC_DEVICE_ANY, 0x9E},
    {MIPC_FIELD_THREEDM_UART_BAUDRATE, "uart_baudrate", NULL, MIPC_DEVICE_ANY, 0x40},
    {MIPC_FIELD_THREEDM_UART_BAUDRATE_RESPONSE, "uart_baudrate_response", NULL, MIPC_DEVICE_ANY, 0x87},
    {MIPC_FIELD_THREEDM_GPIO_CONFIG, "gpio_config", NULL, MIPC_DEVICE_ANY, 0x41},
    {MIPC_FIELD_THREEDM_GPIO_CONFIG_RESPONSE, "gpio_config_response", NULL, MIPC_DEVICE_ANY, 0xC1},
    {MIPC_FIELD_THREEDM_GPIO_STATE, "gpio_state", NULL, MIPC_DEVICE_ANY, 0x42},
    {MIPC_FIELD_THREEDM_GPIO_STATE_RESPONSE, "gpio_state_response", NULL, MIPC_DEVICE_ANY, 0xC2},
    {MIPC_FIELD_THREEDM_ODOMETER_CONFIG, "odometer_config", NULL, MIPC_DEVICE_ANY, 0x43},
    {MIPC_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE, "odometer_config_response", NULL, MIPC_DEVICE_ANY, 0xC3},
    {MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER, "advanced_lowpass_filter", NULL, MIPC_DEVICE_ANY, 0x50},
    {MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE, "advanced_lowpass_filter_response", NULL,
     MIPC_DEVICE_ANY, 0x8B},
    {MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER, "complementary_filter", NULL, MIPC_DEVICE_ANY, 0x51},
    {MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE, "complementary_filter_response", NULL, MIPC_DEVICE_ANY,
     0x97},
    {MIPC_FIELD_THREEDM_SENSOR_RANGE, "sensor_range", NULL, MIPC_DEVICE_ANY, 0x52},
    {MIPC_FIELD_THREEDM_SENSOR_RANGE_RESPONSE, "sensor_range_response", NULL, MIPC_DEVICE_ANY, 0xD2},
    {MIPC_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES, "get_calibrated_sensor_ranges", NULL, MIPC_DEVICE_ANY,
     0x53},
    {MIPC_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES, "calibrated_sensor_ranges", NULL, MIPC_DEVICE_ANY, 0xD3},
    {MIPC_FIELD_THREEDM_LOWPASS_FILTER, "lowpass_filter", NULL, MIPC_DEVICE_ANY, 0x54},
    {MIPC_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE, "lowpass_filter_response", NULL, MIPC_DEVICE_ANY, 0xD4},
    {MIPC_FIELD_THREEDM_POLL_IMU_DATA, "poll_imu_data", NULL, MIPC_DEVICE_ANY, 0x01},
    {MIPC_FIELD_THREEDM_POLL_GNSS_DATA, "poll_gnss_data", NULL, MIPC_DEVICE_ANY, 0x02},
    {MIPC_FIELD_THREEDM_POLL_FILTER_DATA, "poll_filter_data", NULL, MIPC_DEVICE_ANY, 0x03},
    {MIPC_FIELD_THREEDM_POLL_NMEA_DATA, "poll_nmea_data", NULL, MIPC_DEVICE_ANY, 0x04},
    {MIPC_FIELD_THREEDM_POLL_DATA, "poll_data", NULL, MIPC_DEVICE_ANY, 0x0D},
    {MIPC_FIELD_THREEDM_GET_IMU_BASE_RATE, "get_imu_base_rate", NULL, MIPC_DEVICE_ANY, 0x06},
    {MIPC_FIELD_THREEDM_IMU_BASE_RATE, "imu_base_rate", NULL, MIPC_DEVICE_ANY, 0x83},
    {MIPC_FIELD_THREEDM_GET_GNSS_BASE_RATE, "get_gnss_base_rate", NULL, MIPC_DEVICE_ANY, 0x07},
    {MIPC_FIELD_THREEDM_GNSS_BASE_RATE, "gnss_base_rate", NULL, MIPC_DEVICE_ANY, 0x84},
    {MIPC_FIELD_THREEDM_GET_FILTER_BASE_RATE, "get_filter_base_rate", NULL, MIPC_DEVICE_ANY, 0x0B},
    {MIPC_FIELD_THREEDM_FILTER_BASE_RATE, "filter_base_rate", NULL, MIPC_DEVICE_ANY, 0x8A},
    {MIPC_FIELD_THREEDM_GET_BASE_RATE, "get_base_rate", NULL, MIPC_DEVICE_ANY, 0x0E},
    {MIPC_FIELD_THREEDM_BASE_RATE, "base_rate", NULL, MIPC_DEVICE_ANY, 0x8E},
    {MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT, "imu_message_format", NULL, MIPC_DEVICE_ANY, 0x08},
    {MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE, "imu_message_format_response", NULL, MIPC_DEVICE_ANY,
     0x80},
    {MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT, "gnss_message_format", NULL, MIPC_DEVICE_ANY, 0x09},
    {MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE, "gnss_message_format_response", NULL, MIPC_DEVICE_ANY,
     0x81},
    {MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT, "filter_message_format", NULL, MIPC_DEVICE_ANY, 0x0A},
    {MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE, "filter_message_format_response", NULL,
     MIPC_DEVICE_ANY, 0x82},
    {MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT, "nmea_message_format", NULL, MIPC_DEVICE_ANY, 0x0C},
    {MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE, "nmea_message_format_response", NULL, MIPC_DEVICE_ANY,
     0x8C},
    {MIPC_FIELD_THREEDM_MESSAGE_FORMAT, "message_format", NULL, MIPC_DEVICE_ANY, 0x0F},
    {MIPC_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE, "message_format_response", NULL, MIPC_DEVICE_ANY, 0x8F},
    {MIPC_FIELD_THREEDM_FACTORY_STREAMING, "factory_streaming", NULL, MIPC_DEVICE_ANY, 0x10},
    {MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45, "data_stream_control", "gx5_45", MIPC_DEVICE_GX5_45,
     0x11},
    {MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS, "data_stream_control", "cv7_ins", MIPC_DEVICE_CV7_INS,
     0x11},
    {MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45, "data_stream_control_response", "gx5_45",
     MIPC_DEVICE_GX5_45, 0x85},
    {MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS, "data_stream_control_response", "cv7_ins",
     MIPC_DEVICE_CV7_INS, 0x85},
    {MIPC_FIELD_THREEDM_RAW_RTCM_MESSAGE, "raw_rtcm_message", NULL, MIPC_DEVICE_ANY, 0x20},
    {MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS, "gnss_constellation_settings", NULL, MIPC_DEVICE_ANY,
     0x21},
    {MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE, "gnss_constellation_settings_response", NULL,
     MIPC_DEVICE_ANY, 0xA0},
    {MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS, "gnss_sbas_settings", NULL, MIPC_DEVICE_ANY, 0x22},
    {MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE, "gnss_sbas_settings_response", NULL, MIPC_DEVICE_ANY,
     0xA1},
    {MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL, "gnss_assisted_fix_control", NULL, MIPC_DEVICE_ANY, 0x23},
    {MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE, "gnss_assisted_fix_control_response", NULL,
     MIPC_DEVICE_ANY, 0xA2},
    {MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE, "gnss_assist_time_update", NULL, MIPC_DEVICE_ANY, 0x24},
    {MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE, "gnss_assist_time_update_response", NULL,
     MIPC_DEVICE_ANY, 0xA3},
    {MIPC_FIELD_THREEDM_PPS_SOURCE, "pps_source", NULL, MIPC_DEVICE_ANY, 0x28},
    {MIPC_FIELD_THREEDM_PPS_SOURCE_RESPONSE, "pps_source_response", NULL, MIPC_DEVICE_ANY, 0xA8},
    {MIPC_FIELD_THREEDM_GET_SUPPORTED_EVENTS, "get_supported_events", NULL, MIPC_DEVICE_ANY, 0x2A},
    {MIPC_FIELD_THREEDM_SUPPORTED_EVENTS, "supported_events", NULL, MIPC_DEVICE_ANY, 0xB4},
    {MIPC_FIELD_THREEDM_DEVICE_STATUS, "device_status", NULL, MIPC_DEVICE_ANY, 0x64},
    {MIPC_FIELD_THREEDM_DEVICE_STATUS_RESPONSE, "device_status_response", NULL, MIPC_DEVICE_ANY, 0x90},
    {MIPC_FIELD_FILTER_RESET_FILTER, "reset_filter", NULL, MIPC_DEVICE_ANY, 0x01},
    {MIPC_FIELD_FILTER_SET_INITIAL_ATTITUDE, "set_initial_attitude", NULL, MIPC_DEVICE_ANY, 0x02},
    {MIPC_FIELD_FILTER_SET_INITIAL_HEADING, "set_initial_heading", NULL, MIPC_DEVICE_ANY, 0x03},
    {MIPC_FIELD_FILTER_RUN_FILTER, "run_filter", NULL, MIPC_DEVICE_ANY, 0x05},
    {MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE, "vehicle_dynamics_mode", NULL, MIPC_DEVICE_ANY, 0x10},
    {MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE, "vehicle_dynamics_mode_response", NULL,
     MIPC_DEVICE_ANY, 0x80},
    {MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM, "sensor_to_vehicle_transform", NULL, MIPC_DEVICE_ANY,
     0x11},
    {MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE, "sensor_to_vehicle_transform_response", NULL,
     MIPC_DEVICE_ANY, 0x81},
    {MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET, "sensor_to_vehicle_offset", NULL, MIPC_DEVICE_ANY, 0x12},
    {MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE, "sensor_to_vehicle_offset_response", NULL,
     MIPC_DEVICE_ANY, 0x82},
    {MIPC_FIELD_FILTER_ANTENNA_OFFSET, "antenna_offset", NULL, MIPC_DEVICE_ANY, 0x13},
    {MIPC_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE, "antenna_offset_response", NULL, MIPC_DEVICE_ANY, 0x83},
    {MIPC_FIELD_FILTER_ESTIMATION_CONTROL, "estimation_control", NULL, MIPC_DEVICE_ANY, 0x14},
    {MIPC_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE, "estimation_control_response", NULL, MIPC_DEVICE_ANY,
     0x84},
    {MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL, "gnss_source_control", NULL, MIPC_DEVICE_ANY, 0x15},
    {MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE, "gnss_source_control_response", NULL, MIPC_DEVICE_ANY,
     0x86},
    {MIPC_FIELD_FILTER_EXTERNAL_GNSS_UPDATE, "external_gnss_update", NULL, MIPC_DEVICE_ANY, 0x16},
    {MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE, "external_heading_update", NULL, MIPC_DEVICE_ANY, 0x17},
    {MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL, "heading_update_control", NULL, MIPC_DEVICE_ANY, 0x18},
    {MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE, "heading_update_control_response", NULL,
     MIPC_DEVICE_ANY, 0x87},
    {MIPC_FIELD_FILTER_AUTO_INIT_CONTROL, "auto_init_control", NULL, MIPC_DEVICE_ANY, 0x19},
    {MIPC_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE, "auto_init_control_response", NULL, MIPC_DEVICE_ANY, 0x88},
    {MIPC_FIELD_FILTER_ACCEL_NOISE, "accel_noise", NULL, MIPC_DEVICE_ANY, 0x1A},
    {MIPC_FIELD_FILTER_ACCEL_NOISE_RESPONSE, "accel_noise_response", NULL, MIPC_DEVICE_ANY, 0x89},
    {MIPC_FIELD_FILTER_GYRO_NOISE, "gyro_noise", NULL, MIPC_DEVICE_ANY, 0x1B},
    {MIPC_FIELD_FILTER_GYRO_NOISE_RESPONSE, "gyro_noise_response", NULL, MIPC_DEVICE_ANY, 0x8A},
    {MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL, "accel_bias_model", NULL, MIPC_DEVICE_ANY, 0x1C},
    {MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE, "accel_bias_model_response", NULL, MIPC_DEVICE_ANY, 0x8B},
    {MIPC_FIELD_FILTER_GYRO_BIAS_MODEL, "gyro_bias_model", NULL, MIPC_DEVICE_ANY, 0x1D},
    {MIPC_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE, "gyro_bias_model_response", NULL, MIPC_DEVICE_ANY, 0x8C},
    {MIPC_FIELD_FILTER_ZUPT_CONTROL, "zupt_control", NULL, MIPC_DEVICE_ANY, 0x1E},
    {MIPC_FIELD_FILTER_ZUPT_CONTROL_RESPONSE, "zupt_control_response", NULL, MIPC_DEVICE_ANY, 0x8D},
    {MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME, "external_heading_update_with_time", NULL,
     MIPC_DEVICE_ANY, 0x1F},
    {MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL, "zero_angular_rate_update_control", NULL,
     MIPC_DEVICE_ANY, 0x20},
    {MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE, "zero_angular_rate_update_control_response",
     NULL, MIPC_DEVICE_ANY, 0x8E},
    {MIPC_FIELD_FILTER_TARE_ORIENTATION, "tare_orientation", NULL, MIPC_DEVICE_ANY, 0x21},
    {MIPC_FIELD_FILTER_COMMANDED_ZUPT, "commanded_zupt", NULL, MIPC_DEVICE_ANY, 0x22},
    {MIPC_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE, "commanded_zero_angular_rate_update", NULL,
     MIPC_DEVICE_ANY, 0x23},
    {MIPC_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION, "mag_capture_auto_calibration", NULL, MIPC_DEVICE_ANY,
     0x27},
    {MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV, "gravity_noise_std_dev", NULL, MIPC_DEVICE_ANY, 0x28},
    {MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE, "gravity_noise_std_dev_response", NULL,
     MIPC_DEVICE_ANY, 0x93},
    {MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV, "pressure_altitude_noise_std_dev", NULL,
     MIPC_DEVICE_ANY, 0x29},
    {MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE, "pressure_altitude_noise_std_dev_response",
     NULL, MIPC_DEVICE_ANY, 0x94},
    {MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE, "hard_iron_offset_noise", NULL, MIPC_DEVICE_ANY, 0x2B},
    {MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE, "hard_iron_offset_noise_response", NULL,
     MIPC_DEVICE_ANY, 0x96},
    {MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE, "soft_iron_matrix_noise", NULL, MIPC_DEVICE_ANY, 0x2C},
    {MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE, "soft_iron_matrix_noise_response", NULL,
     MIPC_DEVICE_ANY, 0x97},
    {MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV, "mag_noise_std_dev", NULL, MIPC_DEVICE_ANY, 0x42},
    {MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE, "mag_noise_std_dev_response", NULL, MIPC_DEVICE_ANY, 0xB1},
    {MIPC_FIELD_FILTER_DECLINATION_SOURCE, "declination_source", NULL, MIPC_DEVICE_ANY, 0x43},
    {MIPC_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE, "declination_source_response", NULL, MIPC_DEVICE_ANY,
     0xB2},
    {MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT, "gravity_magnitude_adaptive_measurement", NULL,
     MIPC_DEVICE_ANY, 0x44},
    {MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE,
     "gravity_magnitude_adaptive_measurement_response", NULL, MIPC_DEVICE_ANY, 0xB3},
    {MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT, "mag_magnitude_adaptive_measurement", NULL,
     MIPC_DEVICE_ANY, 0x45},
    {MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE,
     "mag_magnitude_adaptive_measurement_response", NULL, MIPC_DEVICE_ANY, 0xB4},
    {MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT, "mag_dip_angle_adaptive_measurement", NULL,
     MIPC_DEVICE_ANY, 0x46},
    {MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE,
     "mag_dip_angle_adaptive_measurement_response", NULL, MIPC_DEVICE_ANY, 0xB5},
    {MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL, "altitude_aiding_control", NULL, MIPC_DEVICE_ANY, 0x47},
    {MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE, "altitude_aiding_control_response", NULL,
     MIPC_DEVICE_ANY, 0xB7},
    {MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL, "pitch_roll_aiding_control", NULL, MIPC_DEVICE_ANY, 0x4B},
    {MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE, "pitch_roll_aiding_control_response", NULL,
     MIPC_DEVICE_ANY, 0xBB},
    {MIPC_FIELD_FILTER_INCLINATION_SOURCE, "inclination_source", NULL, MIPC_DEVICE_ANY, 0x4C},
    {MIPC_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE, "inclination_source_response", NULL, MIPC_DEVICE_ANY,
     0xBC},
    {MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE, "magnetic_field_magnitude_source", NULL,
     MIPC_DEVICE_ANY, 0x4D},
    {MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE, "magnetic_field_magnitude_source_response",
     NULL, MIPC_DEVICE_ANY, 0xBD},
    {MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL, "aiding_measurement_control", NULL, MIPC_DEVICE_ANY, 0x50},
    {MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE, "aiding_measurement_control_response", NULL,
     MIPC_DEVICE_ANY, 0xD0},
    {MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION, "initialization_configuration", NULL, MIPC_DEVICE_ANY,
     0x52},
    {MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE, "initialization_configuration_response", NULL,
     MIPC_DEVICE_ANY, 0xD2},
    {MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL, "adaptive_filter_control", NULL, MIPC_DEVICE_ANY, 0x53},
    {MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE, "adaptive_filter_control_response", NULL,
     MIPC_DEVICE_ANY, 0xD3},
    {MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET, "multi_antenna_offset", NULL, MIPC_DEVICE_ANY, 0x54},
    {MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE, "multi_antenna_offset_response", NULL, MIPC_DEVICE_ANY,
     0xD4},
    {MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION, "relative_position_configuration", NULL,
     MIPC_DEVICE_ANY, 0x55},
    {MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE, "relative_position_configuration_response",
     NULL, MIPC_DEVICE_ANY, 0xD5},
    {MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM, "reference_point_lever_arm", NULL, MIPC_DEVICE_ANY, 0x56},
    {MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE, "reference_point_lever_arm_response", NULL,
     MIPC_DEVICE_ANY, 0xD6},
    {MIPC_FIELD_FILTER_SPEED_LEVER_ARM, "speed_lever_arm", NULL, MIPC_DEVICE_ANY, 0x61},
    {MIPC_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE, "speed_lever_arm_response", NULL, MIPC_DEVICE_ANY, 0xE1},
    {MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL, "wheeled_vehicle_constraint_control", NULL,
     MIPC_DEVICE_ANY, 0x63},
    {MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE,
     "wheeled_vehicle_constraint_control_response", NULL, MIPC_DEVICE_ANY, 0xE3},
    {MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL, "gnss_antenna_calibration_control", NULL,
     MIPC_DEVICE_ANY, 0x64},
    {MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE, "gnss_antenna_calibration_control_response",
     NULL, MIPC_DEVICE_ANY, 0xE4},
    {MIPC_FIELD_GNSS_RECEIVER_INFO, "receiver_info", NULL, MIPC_DEVICE_ANY, 0x01},
    {MIPC_FIELD_GNSS_RECEIVER_INFO_RESPONSE, "receiver_info_response", NULL, MIPC_DEVICE_ANY, 0x81},
    {MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION, "signal_configuration", NULL, MIPC_DEVICE_ANY, 0x02},
    {MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE, "signal_configuration_response", NULL, MIPC_DEVICE_ANY,
     0x82},
    {MIPC_FIELD_GNSS_SPARTN_CONFIGURATION, "spartn_configuration", NULL, MIPC_DEVICE_ANY, 0x20},
    {MIPC_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE, "spartn_configuration_response", NULL, MIPC_DEVICE_ANY,
     0xA0},
    {MIPC_FIELD_AIDING_FRAME_CONFIG, "frame_config", NULL, MIPC_DEVICE_ANY, 0x01},
    {MIPC_FIELD_AIDING_FRAME_CONFIG_RESPONSE, "frame_config_response", NULL, MIPC_DEVICE_ANY, 0x81},
    {MIPC_FIELD_AIDING_ECHO_CONTROL, "echo_control", NULL, MIPC_DEVICE_ANY, 0x1F},
    {MIPC_FIELD_AIDING_ECHO_CONTROL_RESPONSE, "echo_control_response", NULL, MIPC_DEVICE_ANY, 0x9F},
    {MIPC_FIELD_AIDING_ECEF_POSITION, "ecef_position", NULL, MIPC_DEVICE_ANY, 0x21},
    {MIPC_FIELD_AIDING_LLH_POSITION, "llh_position", NULL, MIPC_DEVICE_ANY, 0x22},
    {MIPC_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID, "height_above_ellipsoid", NULL, MIPC_DEVICE_ANY, 0x23},
    {MIPC_FIELD_AIDING_ECEF_VELOCITY, "ecef_velocity", NULL, MIPC_DEVICE_ANY, 0x28},
    {MIPC_FIELD_AIDING_NED_VELOCITY, "ned_velocity", NULL, MIPC_DEVICE_ANY, 0x29},
    {MIPC_FIELD_AIDING_BODY_FRAME_VELOCITY, "body_frame_velocity", NULL, MIPC_DEVICE_ANY, 0x2A},
    {MIPC_FIELD_AIDING_TRUE_HEADING, "true_heading", NULL, MIPC_DEVICE_ANY, 0x31},
    {MIPC_FIELD_AIDING_MAGNETIC_FIELD, "magnetic_field", NULL, MIPC_DEVICE_ANY, 0x32},
    {MIPC_FIELD_AIDING_PRESSURE, "pressure", NULL, MIPC_DEVICE_ANY, 0x33},
    {MIPC_FIELD_SYSTEM_COMMUNICATION_MODE, "communication_mode", NULL, MIPC_DEVICE_ANY, 0x10},
    {MIPC_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE, "communication_mode_response", NULL, MIPC_DEVICE_ANY,
     0x90},
    {MIPC_FIELD_SENSOR_SCALED_ACCEL, "scaled_accel", NULL, MIPC_DEVICE_ANY, 0x04},
    {MIPC_FIELD_SENSOR_SCALED_GYRO, "scaled_gyro", NULL, MIPC_DEVICE_ANY, 0x05},
    {MIPC_FIELD_SENSOR_SCALED_MAG, "scaled_mag", NULL, MIPC_DEVICE_ANY, 0x06},
    {MIPC_FIELD_SENSOR_DELTA_THETA, "delta_theta", NULL, MIPC_DEVICE_ANY, 0x07},
    {MIPC_FIELD_SENSOR_DELTA_VELOCITY, "delta_velocity", NULL, MIPC_DEVICE_ANY, 0x08},
    {MIPC_FIELD_SENSOR_CF_ORIENTATION_MATRIX, "cf_orientation_matrix", NULL, MIPC_DEVICE_ANY, 0x09},
    {MIPC_FIELD_SENSOR_CF_QUATERNION, "cf_quaternion", NULL, MIPC_DEVICE_ANY, 0x0A},
    {MIPC_FIELD_SENSOR_CF_EULER_ANGLES, "cf_euler_angles", NULL, MIPC_DEVICE_ANY, 0x0C},
    {MIPC_FIELD_SENSOR_CF_STABILIZED_NORTH, "cf_stabilized_north", NULL, MIPC_DEVICE_ANY, 0x10},
    {MIPC_FIELD_SENSOR_CF_STABILIZED_UP, "cf_stabilized_up", NULL, MIPC_DEVICE_ANY, 0x11},
    {MIPC_FIELD_SENSOR_GPS_TIMESTAMP, "gps_timestamp", NULL, MIPC_DEVICE_ANY, 0x12},
    {MIPC_FIELD_SENSOR_TEMPERATURE_STATISTICS, "temperature_statistics", NULL, MIPC_DEVICE_ANY, 0x14},
    {MIPC_FIELD_SENSOR_SCALED_PRESSURE, "scaled_pressure", NULL, MIPC_DEVICE_ANY, 0x17},
    {MIPC_FIELD_SENSOR_OVERRANGE_STATUS, "overrange_status", NULL, MIPC_DEVICE_ANY, 0x18},
    {MIPC_FIELD_SENSOR_ODOMETER_DATA, "odometer_data", NULL, MIPC_DEVICE_ANY, 0x40},
    {MIPC_FIELD_GNSS_DATA_LLH_POSITION, "llh_position", NULL, MIPC_DEVICE_ANY, 0x03},
    {MIPC_FIELD_GNSS_DATA_ECEF_POSITION, "ecef_position", NULL, MIPC_DEVICE_ANY, 0x04},
    {MIPC_FIELD_GNSS_DATA_NED_VELOCITY, "ned_velocity", NULL, MIPC_DEVICE_ANY, 0x05},
    {MIPC_FIELD_GNSS_DATA_ECEF_VELOCITY, "ecef_velocity", NULL, MIPC_DEVICE_ANY, 0x06},
    {MIPC_FIELD_GNSS_DATA_DOP, "dop", NULL, MIPC_DEVICE_ANY, 0x07},
    {MIPC_FIELD_GNSS_DATA_UTC_TIME, "utc_time", NULL, MIPC_DEVICE_ANY, 0x08},
    {MIPC_FIELD_GNSS_DATA_GPS_TIME, "gps_time", NULL, MIPC_DEVICE_ANY, 0x09},
    {MIPC_FIELD_GNSS_DATA_CLOCK_INFO, "clock_info", NULL, MIPC_DEVICE_ANY, 0x0A},
    {MIPC_FIELD_GNSS_DATA_FIX_INFO, "fix_info", NULL, MIPC_DEVICE_ANY, 0x0B},
    {MIPC_FIELD_GNSS_DATA_SV_INFO, "sv_info", NULL, MIPC_DEVICE_ANY, 0x0C},
    {MIPC_FIELD_GNSS_DATA_HARDWARE_STATUS, "hardware_status", NULL, MIPC_DEVICE_ANY, 0x0D},
    {MIPC_FIELD_GNSS_DATA_DGNSS_INFO, "dgnss_info", NULL, MIPC_DEVICE_ANY, 0x0E},
    {MIPC_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS, "dgnss_channel_status", NULL, MIPC_DEVICE_ANY, 0x0F},
    {MIPC_FIELD_FILTER_DATA_LLH_POSITION, "llh_position", NULL, MIPC_DEVICE_ANY, 0x01},
    {MIPC_FIELD_FILTER_DATA_NED_VELOCITY, "ned_velocity", NULL, MIPC_DEVICE_ANY, 0x02},
    {MIPC_FIELD_FILTER_DATA_ATTITUDE_QUATERNION, "attitude_quaternion", NULL, MIPC_DEVICE_ANY, 0x03},
    {MIPC_FIELD_FILTER_DATA_ATTITUDE_DCM, "attitude_dcm", NULL, MIPC_DEVICE_ANY, 0x04},
    {MIPC_FIELD_FILTER_DATA_EULER_ANGLES, "euler_angles", NULL, MIPC_DEVICE_ANY, 0x05},
    {MIPC_FIELD_FILTER_DATA_GYRO_BIAS, "gyro_bias", NULL, MIPC_DEVICE_ANY, 0x06},
    {MIPC_FIELD_FILTER_DATA_ACCEL_BIAS, "accel_bias", NULL, MIPC_DEVICE_ANY, 0x07},
    {MIPC_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY, "llh_position_uncertainty", NULL, MIPC_DEVICE_ANY,
     0x08},
    {MIPC_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY, "ned_velocity_uncertainty", NULL, MIPC_DEVICE_ANY,
     0x09},
    {MIPC_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY, "euler_angles_uncertainty", NULL, MIPC_DEVICE_ANY,
     0x0A},
    {MIPC_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY, "gyro_bias_uncertainty", NULL, MIPC_DEVICE_ANY, 0x0B},
    {MIPC_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY, "accel_bias_uncertainty", NULL, MIPC_DEVICE_ANY, 0x0C},
    {MIPC_FIELD_FILTER_DATA_LINEAR_ACCEL, "linear_accel", NULL, MIPC_DEVICE_ANY, 0x0D},
    {MIPC_FIELD_FILTER_DATA_COMP_ANGULAR_RATE, "comp_angular_rate", NULL, MIPC_DEVICE_ANY, 0x0E},
    {MIPC_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE, "wgs84_gravity_magnitude", NULL, MIPC_DEVICE_ANY, 0x0F},
    {MIPC_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45, "filter_status", "gx5_45", MIPC_DEVICE_GX5_45, 0x10},
    {MIPC_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS, "filter_status", "cv7_ins", MIPC_DEVICE_CV7_INS, 0x10},
    {MIPC_FIELD_FILTER_DATA_GPS_TIMESTAMP, "gps_timestamp", NULL, MIPC_DEVICE_ANY, 0x11},
    {MIPC_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY, "quaternion_attitude_uncertainty", NULL,
     MIPC_DEVICE_ANY, 0x12},
    {MIPC_FIELD_FILTER_DATA_GRAVITY_VECTOR, "gravity_vector", NULL, MIPC_DEVICE_ANY, 0x13},
    {MIPC_FIELD_FILTER_DATA_HEADING_UPDATE_STATE, "heading_update_state", NULL, MIPC_DEVICE_ANY, 0x14},
    {MIPC_FIELD_FILTER_DATA_MAGNETIC_MODEL, "magnetic_model", NULL, MIPC_DEVICE_ANY, 0x15},
    {MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR, "gyro_scale_factor", NULL, MIPC_DEVICE_ANY, 0x16},
    {MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR, "accel_scale_factor", NULL, MIPC_DEVICE_ANY, 0x17},
    {MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY, "gyro_scale_factor_uncertainty", NULL,
     MIPC_DEVICE_ANY, 0x18},
    {MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY, "accel_scale_factor_uncertainty", NULL,
     MIPC_DEVICE_ANY, 0x19},
    {MIPC_FIELD_FILTER_DATA_COMPENSATED_ACCEL, "compensated_accel", NULL, MIPC_DEVICE_ANY, 0x1C},
    {MIPC_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE, "standard_atmosphere", NULL, MIPC_DEVICE_ANY, 0x20},
    {MIPC_FIELD_FILTER_DATA_PRESSURE_ALTITUDE, "pressure_altitude", NULL, MIPC_DEVICE_ANY, 0x21},
    {MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET, "mag_auto_hard_iron_offset", NULL, MIPC_DEVICE_ANY,
     0x25},
    {MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX, "mag_auto_soft_iron_matrix", NULL, MIPC_DEVICE_ANY,
     0x26},
    {MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY, "mag_auto_hard_iron_offset_uncertainty",
     NULL, MIPC_DEVICE_ANY, 0x28},
    {MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY, "mag_auto_soft_iron_matrix_uncertainty",
     NULL, MIPC_DEVICE_ANY, 0x29},
    {MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION, "gnss_antenna_offset_correction", NULL,
     MIPC_DEVICE_ANY, 0x30},
    {MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY,
     "gnss_antenna_offset_correction_uncertainty", NULL, MIPC_DEVICE_ANY, 0x31},
    {MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION, "multi_antenna_offset_correction", NULL,
     MIPC_DEVICE_ANY, 0x34},
    {MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY,
     "multi_antenna_offset_correction_uncertainty", NULL, MIPC_DEVICE_ANY, 0x35},
    {MIPC_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY, "ecef_position_uncertainty", NULL, MIPC_DEVICE_ANY,
     0x36},
    {MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY, "ecef_velocity_uncertainty", NULL, MIPC_DEVICE_ANY,
     0x37},
    {MIPC_FIELD_FILTER_DATA_ECEF_POSITION, "ecef_position", NULL, MIPC_DEVICE_ANY, 0x40},
    {MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY, "ecef_velocity", NULL, MIPC_DEVICE_ANY, 0x41},
    {MIPC_FIELD_FILTER_DATA_NED_RELATIVE_POSITION, "ned_relative_position", NULL, MIPC_DEVICE_ANY, 0x42},
    {MIPC_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS, "gnss_position_aiding_status", NULL, MIPC_DEVICE_ANY,
     0x43},
    {MIPC_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY, "aiding_measurement_summary", NULL, MIPC_DEVICE_ANY,
     0x46},
    {MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR, "odometer_scale_factor_error", NULL, MIPC_DEVICE_ANY,
     0x47},
    {MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY,
     "odometer_scale_factor_error_uncertainty", NULL, MIPC_DEVICE_ANY, 0x48},
    {MIPC_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS, "gnss_dual_antenna_status", NULL, MIPC_DEVICE_ANY,
     0x49},
    {MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR, "aiding_frame_config_error", NULL, MIPC_DEVICE_ANY,
     0x50},
    {MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY, "aiding_frame_config_error_uncertainty",
     NULL, MIPC_DEVICE_ANY, 0x51},
    {MIPC_FIELD_GNSS_RECEIVER_1_LLH_POSITION, "llh_position", NULL, MIPC_DEVICE_ANY, 0x03},
    {MIPC_FIELD_GNSS_RECEIVER_1_ECEF_POSITION, "ecef_position", NULL, MIPC_DEVICE_ANY, 0x04},
    {MIPC_FIELD_GNSS_RECEIVER_1_NED_VELOCITY, "ned_velocity", NULL, MIPC_DEVICE_ANY, 0x05},
    {MIPC_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY, "ecef_velocity", NULL, MIPC_DEVICE_ANY, 0x06},
    {MIPC_FIELD_GNSS_RECEIVER_1_DOP, "dop", NULL, MIPC_DEVICE_ANY, 0x07},
    {MIPC_FIELD_GNSS_RECEIVER_1_UTC_TIME, "utc_time", NULL, MIPC_DEVICE_ANY, 0x08},
    {MIPC_FIELD_GNSS_RECEIVER_1_GPS_TIME, "gps_time", NULL, MIPC_DEVICE_ANY, 0x09},
    {MIPC_FIELD_GNSS_RECEIVER_1_FIX_INFO, "fix_info", NULL, MIPC_DEVICE_ANY, 0x0B},
    {MIPC_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS, "hardware_status", NULL, MIPC_DEVICE_ANY, 0x0D},
    {MIPC_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2, "clock_info_2", NULL, MIPC_DEVICE_ANY, 0x10},
    {MIPC_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS, "gps_leap_seconds", NULL, MIPC_DEVICE_ANY, 0x11},
    {MIPC_FIELD_GNSS_RECEIVER_1_SBAS_INFO, "sbas_info", NULL, MIPC_DEVICE_ANY, 0x12},
    {MIPC_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS, "satellite_status", NULL, MIPC_DEVICE_ANY, 0x20},
    {MIPC_FIELD_GNSS_RECEIVER_1_RAW, "raw", NULL, MIPC_DEVICE_ANY, 0x22},
    {MIPC_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS, "gps_ephemeris", NULL, MIPC_DEVICE_ANY, 0x61},
    {MIPC_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS, "glonass_ephemeris", NULL, MIPC_DEVICE_ANY, 0x62},
    {MIPC_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS, "galileo_ephemeris", NULL, MIPC_DEVICE_ANY, 0x63},
    {MIPC_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS, "beidou_ephemeris", NULL, MIPC_DEVICE_ANY, 0x64},
    {MIPC_FIELD_GNSS_RECEIVER_2_LLH_POSITION, "llh_position", NULL, MIPC_DEVICE_ANY, 0x03},
    {MIPC_FIELD_GNSS_RECEIVER_2_ECEF_POSITION, "ecef_position", NULL, MIPC_DEVICE_ANY, 0x04},
    {MIPC_FIELD_GNSS_RECEIVER_2_NED_VELOCITY, "ned_velocity", NULL, MIPC_DEVICE_ANY, 0x05},
    {MIPC_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY, "ecef_velocity", NULL, MIPC_DEVICE_ANY, 0x06},
    {MIPC_FIELD_GNSS_RECEIVER_2_DOP, "dop", NULL, MIPC_DEVICE_ANY, 0x07},
    {MIPC_FIELD_GNSS_RECEIVER_2_UTC_TIME, "utc_time", NULL, MIPC_DEVICE_ANY, 0x08},
    {MIPC_FIELD_GNSS_RECEIVER_2_GPS_TIME, "gps_time", NULL, MIPC_DEVICE_ANY, 0x09},
    {MIPC_FIELD_GNSS_RECEIVER_2_FIX_INFO, "fix_info", NULL, MIPC_DEVICE_ANY, 0x0B},
    {MIPC_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS, "hardware_status", NULL, MIPC_DEVICE_ANY, 0x0D},
    {MIPC_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2, "clock_info_2", NULL, MIPC_DEVICE_ANY, 0x10},
    {MIPC_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS, "gps_leap_seconds", NULL, MIPC_DEVICE_ANY, 0x11},
    {MIPC_FIELD_GNSS_RECEIVER_2_SBAS_INFO, "sbas_info", NULL, MIPC_DEVICE_ANY, 0x12},
    {MIPC_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS, "satellite_status", NULL, MIPC_DEVICE_ANY, 0x20},
    {MIPC_FIELD_GNSS_RECEIVER_2_RAW, "raw", NULL, MIPC_DEVICE_ANY, 0x22},
    {MIPC_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS, "gps_ephemeris", NULL, MIPC_DEVICE_ANY, 0x61},
    {MIPC_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS, "glonass_ephemeris", NULL, MIPC_DEVICE_ANY, 0x62},
    {MIPC_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS, "galileo_ephemeris", NULL, MIPC_DEVICE_ANY, 0x63},
    {MIPC_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS, "beidou_ephemeris", NULL, MIPC_DEVICE_ANY, 0x64},
    {MIPC_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO, "base_station_info", NULL, MIPC_DEVICE_ANY, 0x30},
    {MIPC_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS, "rtk_corrections_status", NULL, MIPC_DEVICE_ANY,
     0x31},
    {MIPC_FIELD_GNSS_EXTERNAL_LLH_POSITION, "llh_position", NULL, MIPC_DEVICE_ANY, 0x03},
    {MIPC_FIELD_GNSS_EXTERNAL_NED_VELOCITY, "ned_velocity", NULL, MIPC_DEVICE_ANY, 0x05},
    {MIPC_FIELD_GNSS_EXTERNAL_UTC_TIME, "utc_time", NULL, MIPC_DEVICE_ANY, 0x08},
    {MIPC_FIELD_GNSS_EXTERNAL_FIX_INFO, "fix_info", NULL, MIPC_DEVICE_ANY, 0x0B},
    {MIPC_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS, "satellite_status", NULL, MIPC_DEVICE_ANY, 0x20},
    {MIPC_FIELD_SYSTEM_DATA_BUILT_IN_TEST, "built_in_test", NULL, MIPC_DEVICE_ANY, 0x01},
    {MIPC_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS, "time_sync_status", NULL, MIPC_DEVICE_ANY, 0x02},
    {MIPC_FIELD_SYSTEM_DATA_GPIO_STATE, "gpio_state", NULL, MIPC_DEVICE_ANY, 0x03},
    {MIPC_FIELD_SHARED_EVENT_SOURCE, "event_source", NULL, MIPC_DEVICE_ANY, 0xD0},
    {MIPC_FIELD_SHARED_GPS_TIMESTAMP, "gps_timestamp", NULL, MIPC_DEVICE_ANY, 0xD3},
    {MIPC_FIELD_SHARED_DELTA_TIME, "delta_time", NULL, MIPC_DEVICE_ANY, 0xD4},
    {MIPC_FIELD_SHARED_REFERENCE_TIMESTAMP, "reference_timestamp", NULL, MIPC_DEVICE_ANY, 0xD5},
    {MIPC_FIELD_SHARED_REFERENCE_TIME_DELTA, "reference_time_delta", NULL, MIPC_DEVICE_ANY, 0xD6},
    {MIPC_FIELD_SHARED_EXTERNAL_TIMESTAMP, "external_timestamp", NULL, MIPC_DEVICE_ANY, 0xD7},
    {MIPC_FIELD_SHARED_EXTERNAL_TIME_DELTA, "external_time_delta", NULL, MIPC_DEVICE_ANY, 0xD8},
};

static const mipc_field_info_t k_fields[] = {
    {"ack_nack", 0xF1, MIPC_FIELD_ACK_NACK, 1},
    {"ping", 0x01, MIPC_FIELD_BASE_PING, 1},
    {"set_to_idle", 0x02, MIPC_FIELD_BASE_SET_TO_IDLE, 1},
    {"get_device_info", 0x03, MIPC_FIELD_BASE_GET_DEVICE_INFO, 1},
    {"device_info", 0x81, MIPC_FIELD_BASE_DEVICE_INFO, 1},
    {"get_device_descriptors", 0x04, MIPC_FIELD_BASE_GET_DEVICE_DESCRIPTORS, 1},
    {"device_descriptors", 0x82, MIPC_FIELD_BASE_DEVICE_DESCRIPTORS, 1},
    {"built_in_test", 0x05, MIPC_FIELD_BASE_BUILT_IN_TEST, 1},
    {"built_in_test_result", 0x83, MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45, 2},
    {"resume", 0x06, MIPC_FIELD_BASE_RESUME, 1},
    {"get_extended_descriptors", 0x07, MIPC_FIELD_BASE_GET_EXTENDED_DESCRIPTORS, 1},
    {"extended_descriptors", 0x86, MIPC_FIELD_BASE_EXTENDED_DESCRIPTORS, 1},
    {"continuous_bit", 0x08, MIPC_FIELD_BASE_CONTINUOUS_BIT, 1},
    {"continuous_bit_result", 0x88, MIPC_FIELD_BASE_CONTINUOUS_BIT_RESULT, 1},
    {"comm_port_speed", 0x09, MIPC_FIELD_BASE_COMM_PORT_SPEED, 1},
    {"comm_port_speed_response", 0x89, MIPC_FIELD_BASE_COMM_PORT_SPEED_RESPONSE, 1},
    {"gps_time_update", 0x72, MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45, 2},
    {"gps_week", 0x84, MIPC_FIELD_BASE_GPS_WEEK, 1},
    {"gps_seconds", 0x85, MIPC_FIELD_BASE_GPS_SECONDS, 1},
    {"device_reset", 0x7E, MIPC_FIELD_BASE_DEVICE_RESET, 1},
    {"event_control", 0x2B, MIPC_FIELD_THREEDM_EVENT_CONTROL, 1},
    {"event_control_response", 0xB5, MIPC_FIELD_THREEDM_EVENT_CONTROL_RESPONSE, 1},
    {"get_event_trigger_status", 0x2C, MIPC_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS, 1},
    {"event_trigger_status", 0xB6, MIPC_FIELD_THREEDM_EVENT_TRIGGER_STATUS, 1},
    {"get_event_action_status", 0x2D, MIPC_FIELD_THREEDM_GET_EVENT_ACTION_STATUS, 1},
    {"event_action_status", 0xB7, MIPC_FIELD_THREEDM_EVENT_ACTION_STATUS, 1},
    {"event_trigger_config", 0x2E, MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG, 1},
    {"event_trigger_config_response", 0xB8, MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE, 1},
    {"event_action_config", 0x2F, MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG, 1},
    {"event_action_config_response", 0xB9, MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE, 1},
    {"device_startup_settings", 0x30, MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45, 2},
    {"sensor_to_vehicle_euler", 0x31, MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER, 1},
    {"sensor_to_vehicle_euler_response", 0xB1, MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE, 1},
    {"sensor_to_vehicle_quaternion", 0x32, MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION, 1},
    {"sensor_to_vehicle_quaternion_response", 0xB2, MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE,
     1},
    {"sensor_to_vehicle_dcm", 0x33, MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM, 1},
    {"sensor_to_vehicle_dcm_response", 0xB3, MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE, 1},
    {"accel_bias", 0x37, MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45, 2},
    {"accel_bias_response", 0x9A, MIPC_FIELD_THREEDM_ACCEL_BIAS_RESPONSE, 1},
    {"gyro_bias", 0x38, MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45, 2},
    {"gyro_bias_response", 0x9B, MIPC_FIELD_THREEDM_GYRO_BIAS_RESPONSE, 1},
    {"capture_gyro_bias", 0x39, MIPC_FIELD_THREEDM_CAPTURE_GYRO_BIAS, 1},
    {"mag_hard_iron_offset", 0x3A, MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45, 2},
    {"mag_hard_iron_offset_response", 0x9C, MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE, 1},
    {"mag_soft_iron_matrix", 0x3B, MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45, 2},
    {"mag_soft_iron_matrix_response", 0x9D, MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE, 1},
    {"coning_sculling_enable", 0x3E, MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE, 1},
    {"coning_sculling_enable_response", 0x9E, MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE, 1},
    {"uart_baudrate", 0x40, MIPC_FIELD_THREEDM_UART_BAUDRATE, 1},
    {"uart_baudrate_response", 0x87, MIPC_FIELD_THREEDM_UART_BAUDRATE_RESPONSE, 1},
    {"gpio_config", 0x41, MIPC_FIELD_THREEDM_GPIO_CONFIG, 1},
    {"gpio_config_response", 0xC1, MIPC_FIELD_THREEDM_GPIO_CONFIG_RESPONSE, 1},
    {"gpio_state", 0x42, MIPC_FIELD_THREEDM_GPIO_STATE, 1},
    {"gpio_state_response", 0xC2, MIPC_FIELD_THREEDM_GPIO_STATE_RESPONSE, 1},
    {"odometer_config", 0x43, MIPC_FIELD_THREEDM_ODOMETER_CONFIG, 1},
    {"odometer_config_response", 0xC3, MIPC_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE, 1},
    {"advanced_lowpass_filter", 0x50, MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER, 1},
    {"advanced_lowpass_filter_response", 0x8B, MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE, 1},
    {"complementary_filter", 0x51, MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER, 1},
    {"complementary_filter_response", 0x97, MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE, 1},
    {"sensor_range", 0x52, MIPC_FIELD_THREEDM_SENSOR_RANGE, 1},
    {"sensor_range_response", 0xD2, MIPC_FIELD_THREEDM_SENSOR_RANGE_RESPONSE, 1},
    {"get_calibrated_sensor_ranges", 0x53, MIPC_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES, 1},
    {"calibrated_sensor_ranges", 0xD3, MIPC_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES, 1},
    {"lowpass_filter", 0x54, MIPC_FIELD_THREEDM_LOWPASS_FILTER, 1},
    {"lowpass_filter_response", 0xD4, MIPC_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE, 1},
    {"poll_imu_data", 0x01, MIPC_FIELD_THREEDM_POLL_IMU_DATA, 1},
    {"poll_gnss_data", 0x02, MIPC_FIELD_THREEDM_POLL_GNSS_DATA, 1},
    {"poll_filter_data", 0x03, MIPC_FIELD_THREEDM_POLL_FILTER_DATA, 1},
    {"poll_nmea_data", 0x04, MIPC_FIELD_THREEDM_POLL_NMEA_DATA, 1},
    {"poll_data", 0x0D, MIPC_FIELD_THREEDM_POLL_DATA, 1},
    {"get_imu_base_rate", 0x06, MIPC_FIELD_THREEDM_GET_IMU_BASE_RATE, 1},
    {"imu_base_rate", 0x83, MIPC_FIELD_THREEDM_IMU_BASE_RATE, 1},
    {"get_gnss_base_rate", 0x07, MIPC_FIELD_THREEDM_GET_GNSS_BASE_RATE, 1},
    {"gnss_base_rate", 0x84, MIPC_FIELD_THREEDM_GNSS_BASE_RATE, 1},
    {"get_filter_base_rate", 0x0B, MIPC_FIELD_THREEDM_GET_FILTER_BASE_RATE, 1},
    {"filter_base_rate", 0x8A, MIPC_FIELD_THREEDM_FILTER_BASE_RATE, 1},
    {"get_base_rate", 0x0E, MIPC_FIELD_THREEDM_GET_BASE_RATE, 1},
    {"base_rate", 0x8E, MIPC_FIELD_THREEDM_BASE_RATE, 1},
    {"imu_message_format", 0x08, MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT, 1},
    {"imu_message_format_response", 0x80, MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE, 1},
    {"gnss_message_format", 0x09, MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT, 1},
    {"gnss_message_format_response", 0x81, MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE, 1},
    {"filter_message_format", 0x0A, MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT, 1},
    {"filter_message_format_response", 0x82, MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE, 1},
    {"nmea_message_format", 0x0C, MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT, 1},
    {"nmea_message_format_response", 0x8C, MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE, 1},
    {"message_format", 0x0F, MIPC_FIELD_THREEDM_MESSAGE_FORMAT, 1},
    {"message_format_response", 0x8F, MIPC_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE, 1},
    {"factory_streaming", 0x10, MIPC_FIELD_THREEDM_FACTORY_STREAMING, 1},
    {"data_stream_control", 0x11, MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45, 2},
    {"data_stream_control_response", 0x85, MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45, 2},
    {"raw_rtcm_message", 0x20, MIPC_FIELD_THREEDM_RAW_RTCM_MESSAGE, 1},
    {"gnss_constellation_settings", 0x21, MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS, 1},
    {"gnss_constellation_settings_response", 0xA0, MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE,
     1},
    {"gnss_sbas_settings", 0x22, MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS, 1},
    {"gnss_sbas_settings_response", 0xA1, MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE, 1},
    {"gnss_assisted_fix_control", 0x23, MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL, 1},
    {"gnss_assisted_fix_control_response", 0xA2, MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE, 1},
    {"gnss_assist_time_update", 0x24, MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE, 1},
    {"gnss_assist_time_update_response", 0xA3, MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE, 1},
    {"pps_source", 0x28, MIPC_FIELD_THREEDM_PPS_SOURCE, 1},
    {"pps_source_response", 0xA8, MIPC_FIELD_THREEDM_PPS_SOURCE_RESPONSE, 1},
    {"get_supported_events", 0x2A, MIPC_FIELD_THREEDM_GET_SUPPORTED_EVENTS, 1},
    {"supported_events", 0xB4, MIPC_FIELD_THREEDM_SUPPORTED_EVENTS, 1},
    {"device_status", 0x64, MIPC_FIELD_THREEDM_DEVICE_STATUS, 1},
    {"device_status_response", 0x90, MIPC_FIELD_THREEDM_DEVICE_STATUS_RESPONSE, 1},
    {"reset_filter", 0x01, MIPC_FIELD_FILTER_RESET_FILTER, 1},
    {"set_initial_attitude", 0x02, MIPC_FIELD_FILTER_SET_INITIAL_ATTITUDE, 1},
    {"set_initial_heading", 0x03, MIPC_FIELD_FILTER_SET_INITIAL_HEADING, 1},
    {"run_filter", 0x05, MIPC_FIELD_FILTER_RUN_FILTER, 1},
    {"vehicle_dynamics_mode", 0x10, MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE, 1},
    {"vehicle_dynamics_mode_response", 0x80, MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE, 1},
    {"sensor_to_vehicle_transform", 0x11, MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM, 1},
    {"sensor_to_vehicle_transform_response", 0x81, MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE, 1},
    {"sensor_to_vehicle_offset", 0x12, MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET, 1},
    {"sensor_to_vehicle_offset_response", 0x82, MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE, 1},
    {"antenna_offset", 0x13, MIPC_FIELD_FILTER_ANTENNA_OFFSET, 1},
    {"antenna_offset_response", 0x83, MIPC_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE, 1},
    {"estimation_control", 0x14, MIPC_FIELD_FILTER_ESTIMATION_CONTROL, 1},
    {"estimation_control_response", 0x84, MIPC_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE, 1},
    {"gnss_source_control", 0x15, MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL, 1},
    {"gnss_source_control_response", 0x86, MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE, 1},
    {"external_gnss_update", 0x16, MIPC_FIELD_FILTER_EXTERNAL_GNSS_UPDATE, 1},
    {"external_heading_update", 0x17, MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE, 1},
    {"heading_update_control", 0x18, MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL, 1},
    {"heading_update_control_response", 0x87, MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE, 1},
    {"auto_init_control", 0x19, MIPC_FIELD_FILTER_AUTO_INIT_CONTROL, 1},
    {"auto_init_control_response", 0x88, MIPC_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE, 1},
    {"accel_noise", 0x1A, MIPC_FIELD_FILTER_ACCEL_NOISE, 1},
    {"accel_noise_response", 0x89, MIPC_FIELD_FILTER_ACCEL_NOISE_RESPONSE, 1},
    {"gyro_noise", 0x1B, MIPC_FIELD_FILTER_GYRO_NOISE, 1},
    {"gyro_noise_response", 0x8A, MIPC_FIELD_FILTER_GYRO_NOISE_RESPONSE, 1},
    {"accel_bias_model", 0x1C, MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL, 1},
    {"accel_bias_model_response", 0x8B, MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE, 1},
    {"gyro_bias_model", 0x1D, MIPC_FIELD_FILTER_GYRO_BIAS_MODEL, 1},
    {"gyro_bias_model_response", 0x8C, MIPC_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE, 1},
    {"zupt_control", 0x1E, MIPC_FIELD_FILTER_ZUPT_CONTROL, 1},
    {"zupt_control_response", 0x8D, MIPC_FIELD_FILTER_ZUPT_CONTROL_RESPONSE, 1},
    {"external_heading_update_with_time", 0x1F, MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME, 1},
    {"zero_angular_rate_update_control", 0x20, MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL, 1},
    {"zero_angular_rate_update_control_response", 0x8E,
     MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE, 1},
    {"tare_orientation", 0x21, MIPC_FIELD_FILTER_TARE_ORIENTATION, 1},
    {"commanded_zupt", 0x22, MIPC_FIELD_FILTER_COMMANDED_ZUPT, 1},
    {"commanded_zero_angular_rate_update", 0x23, MIPC_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE, 1},
    {"mag_capture_auto_calibration", 0x27, MIPC_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION, 1},
    {"gravity_noise_std_dev", 0x28, MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV, 1},
    {"gravity_noise_std_dev_response", 0x93, MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE, 1},
    {"pressure_altitude_noise_std_dev", 0x29, MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV, 1},
    {"pressure_altitude_noise_std_dev_response", 0x94,
     MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE, 1},
    {"hard_iron_offset_noise", 0x2B, MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE, 1},
    {"hard_iron_offset_noise_response", 0x96, MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE, 1},
    {"soft_iron_matrix_noise", 0x2C, MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE, 1},
    {"soft_iron_matrix_noise_response", 0x97, MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE, 1},
    {"mag_noise_std_dev", 0x42, MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV, 1},
    {"mag_noise_std_dev_response", 0xB1, MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE, 1},
    {"declination_source", 0x43, MIPC_FIELD_FILTER_DECLINATION_SOURCE, 1},
    {"declination_source_response", 0xB2, MIPC_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE, 1},
    {"gravity_magnitude_adaptive_measurement", 0x44, MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT,
     1},
    {"gravity_magnitude_adaptive_measurement_response", 0xB3,
     MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE, 1},
    {"mag_magnitude_adaptive_measurement", 0x45, MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT, 1},
    {"mag_magnitude_adaptive_measurement_response", 0xB4,
     MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE, 1},
    {"mag_dip_angle_adaptive_measurement", 0x46, MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT, 1},
    {"mag_dip_angle_adaptive_measurement_response", 0xB5,
     MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE, 1},
    {"altitude_aiding_control", 0x47, MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL, 1},
    {"altitude_aiding_control_response", 0xB7, MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE, 1},
    {"pitch_roll_aiding_control", 0x4B, MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL, 1},
    {"pitch_roll_aiding_control_response", 0xBB, MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE, 1},
    {"inclination_source", 0x4C, MIPC_FIELD_FILTER_INCLINATION_SOURCE, 1},
    {"inclination_source_response", 0xBC, MIPC_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE, 1},
    {"magnetic_field_magnitude_source", 0x4D, MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE, 1},
    {"magnetic_field_magnitude_source_response", 0xBD,
     MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE, 1},
    {"aiding_measurement_control", 0x50, MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL, 1},
    {"aiding_measurement_control_response", 0xD0, MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE, 1},
    {"initialization_configuration", 0x52, MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION, 1},
    {"initialization_configuration_response", 0xD2, MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE,
     1},
    {"adaptive_filter_control", 0x53, MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL, 1},
    {"adaptive_filter_control_response", 0xD3, MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE, 1},
    {"multi_antenna_offset", 0x54, MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET, 1},
    {"multi_antenna_offset_response", 0xD4, MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE, 1},
    {"relative_position_configuration", 0x55, MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION, 1},
    {"relative_position_configuration_response", 0xD5,
     MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE, 1},
    {"reference_point_lever_arm", 0x56, MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM, 1},
    {"reference_point_lever_arm_response", 0xD6, MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE, 1},
    {"speed_lever_arm", 0x61, MIPC_FIELD_FILTER_SPEED_LEVER_ARM, 1},
    {"speed_lever_arm_response", 0xE1, MIPC_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE, 1},
    {"wheeled_vehicle_constraint_control", 0x63, MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL, 1},
    {"wheeled_vehicle_constraint_control_response", 0xE3,
     MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE, 1},
    {"gnss_antenna_calibration_control", 0x64, MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL, 1},
    {"gnss_antenna_calibration_control_response", 0xE4,
     MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE, 1},
    {"receiver_info", 0x01, MIPC_FIELD_GNSS_RECEIVER_INFO, 1},
    {"receiver_info_response", 0x81, MIPC_FIELD_GNSS_RECEIVER_INFO_RESPONSE, 1},
    {"signal_configuration", 0x02, MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION, 1},
    {"signal_configuration_response", 0x82, MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE, 1},
    {"spartn_configuration", 0x20, MIPC_FIELD_GNSS_SPARTN_CONFIGURATION, 1},
    {"spartn_configuration_response", 0xA0, MIPC_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE, 1},
    {"frame_config", 0x01, MIPC_FIELD_AIDING_FRAME_CONFIG, 1},
    {"frame_config_response", 0x81, MIPC_FIELD_AIDING_FRAME_CONFIG_RESPONSE, 1},
    {"echo_control", 0x1F, MIPC_FIELD_AIDING_ECHO_CONTROL, 1},
    {"echo_control_response", 0x9F, MIPC_FIELD_AIDING_ECHO_CONTROL_RESPONSE, 1},
    {"ecef_position", 0x21, MIPC_FIELD_AIDING_ECEF_POSITION, 1},
    {"llh_position", 0x22, MIPC_FIELD_AIDING_LLH_POSITION, 1},
    {"height_above_ellipsoid", 0x23, MIPC_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID, 1},
    {"ecef_velocity", 0x28, MIPC_FIELD_AIDING_ECEF_VELOCITY, 1},
    {"ned_velocity", 0x29, MIPC_FIELD_AIDING_NED_VELOCITY, 1},
    {"body_frame_velocity", 0x2A, MIPC_FIELD_AIDING_BODY_FRAME_VELOCITY, 1},
    {"true_heading", 0x31, MIPC_FIELD_AIDING_TRUE_HEADING, 1},
    {"magnetic_field", 0x32, MIPC_FIELD_AIDING_MAGNETIC_FIELD, 1},
    {"pressure", 0x33, MIPC_FIELD_AIDING_PRESSURE, 1},
    {"communication_mode", 0x10, MIPC_FIELD_SYSTEM_COMMUNICATION_MODE, 1},
    {"communication_mode_response", 0x90, MIPC_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE, 1},
    {"scaled_accel", 0x04, MIPC_FIELD_SENSOR_SCALED_ACCEL, 1},
    {"scaled_gyro", 0x05, MIPC_FIELD_SENSOR_SCALED_GYRO, 1},
    {"scaled_mag", 0x06, MIPC_FIELD_SENSOR_SCALED_MAG, 1},
    {"delta_theta", 0x07, MIPC_FIELD_SENSOR_DELTA_THETA, 1},
    {"delta_velocity", 0x08, MIPC_FIELD_SENSOR_DELTA_VELOCITY, 1},
    {"cf_orientation_matrix", 0x09, MIPC_FIELD_SENSOR_CF_ORIENTATION_MATRIX, 1},
    {"cf_quaternion", 0x0A, MIPC_FIELD_SENSOR_CF_QUATERNION, 1},
    {"cf_euler_angles", 0x0C, MIPC_FIELD_SENSOR_CF_EULER_ANGLES, 1},
    {"cf_stabilized_north", 0x10, MIPC_FIELD_SENSOR_CF_STABILIZED_NORTH, 1},
    {"cf_stabilized_up", 0x11, MIPC_FIELD_SENSOR_CF_STABILIZED_UP, 1},
    {"gps_timestamp", 0x12, MIPC_FIELD_SENSOR_GPS_TIMESTAMP, 1},
    {"temperature_statistics", 0x14, MIPC_FIELD_SENSOR_TEMPERATURE_STATISTICS, 1},
    {"scaled_pressure", 0x17, MIPC_FIELD_SENSOR_SCALED_PRESSURE, 1},
    {"overrange_status", 0x18, MIPC_FIELD_SENSOR_OVERRANGE_STATUS, 1},
    {"odometer_data", 0x40, MIPC_FIELD_SENSOR_ODOMETER_DATA, 1},
    {"llh_position", 0x03, MIPC_FIELD_GNSS_DATA_LLH_POSITION, 1},
    {"ecef_position", 0x04, MIPC_FIELD_GNSS_DATA_ECEF_POSITION, 1},
    {"ned_velocity", 0x05, MIPC_FIELD_GNSS_DATA_NED_VELOCITY, 1},
    {"ecef_velocity", 0x06, MIPC_FIELD_GNSS_DATA_ECEF_VELOCITY, 1},
    {"dop", 0x07, MIPC_FIELD_GNSS_DATA_DOP, 1},
    {"utc_time", 0x08, MIPC_FIELD_GNSS_DATA_UTC_TIME, 1},
    {"gps_time", 0x09, MIPC_FIELD_GNSS_DATA_GPS_TIME, 1},
    {"clock_info", 0x0A, MIPC_FIELD_GNSS_DATA_CLOCK_INFO, 1},
    {"fix_info", 0x0B, MIPC_FIELD_GNSS_DATA_FIX_INFO, 1},
    {"sv_info", 0x0C, MIPC_FIELD_GNSS_DATA_SV_INFO, 1},
    {"hardware_status", 0x0D, MIPC_FIELD_GNSS_DATA_HARDWARE_STATUS, 1},
    {"dgnss_info", 0x0E, MIPC_FIELD_GNSS_DATA_DGNSS_INFO, 1},
    {"dgnss_channel_status", 0x0F, MIPC_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS, 1},
    {"llh_position", 0x01, MIPC_FIELD_FILTER_DATA_LLH_POSITION, 1},
    {"ned_velocity", 0x02, MIPC_FIELD_FILTER_DATA_NED_VELOCITY, 1},
    {"attitude_quaternion", 0x03, MIPC_FIELD_FILTER_DATA_ATTITUDE_QUATERNION, 1},
    {"attitude_dcm", 0x04, MIPC_FIELD_FILTER_DATA_ATTITUDE_DCM, 1},
    {"euler_angles", 0x05, MIPC_FIELD_FILTER_DATA_EULER_ANGLES, 1},
    {"gyro_bias", 0x06, MIPC_FIELD_FILTER_DATA_GYRO_BIAS, 1},
    {"accel_bias", 0x07, MIPC_FIELD_FILTER_DATA_ACCEL_BIAS, 1},
    {"llh_position_uncertainty", 0x08, MIPC_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY, 1},
    {"ned_velocity_uncertainty", 0x09, MIPC_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY, 1},
    {"euler_angles_uncertainty", 0x0A, MIPC_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY, 1},
    {"gyro_bias_uncertainty", 0x0B, MIPC_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY, 1},
    {"accel_bias_uncertainty", 0x0C, MIPC_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY, 1},
    {"linear_accel", 0x0D, MIPC_FIELD_FILTER_DATA_LINEAR_ACCEL, 1},
    {"comp_angular_rate", 0x0E, MIPC_FIELD_FILTER_DATA_COMP_ANGULAR_RATE, 1},
    {"wgs84_gravity_magnitude", 0x0F, MIPC_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE, 1},
    {"filter_status", 0x10, MIPC_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45, 2},
    {"gps_timestamp", 0x11, MIPC_FIELD_FILTER_DATA_GPS_TIMESTAMP, 1},
    {"quaternion_attitude_uncertainty", 0x12, MIPC_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY, 1},
    {"gravity_vector", 0x13, MIPC_FIELD_FILTER_DATA_GRAVITY_VECTOR, 1},
    {"heading_update_state", 0x14, MIPC_FIELD_FILTER_DATA_HEADING_UPDATE_STATE, 1},
    {"magnetic_model", 0x15, MIPC_FIELD_FILTER_DATA_MAGNETIC_MODEL, 1},
    {"gyro_scale_factor", 0x16, MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR, 1},
    {"accel_scale_factor", 0x17, MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR, 1},
    {"gyro_scale_factor_uncertainty", 0x18, MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY, 1},
    {"accel_scale_factor_uncertainty", 0x19, MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY, 1},
    {"compensated_accel", 0x1C, MIPC_FIELD_FILTER_DATA_COMPENSATED_ACCEL, 1},
    {"standard_atmosphere", 0x20, MIPC_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE, 1},
    {"pressure_altitude", 0x21, MIPC_FIELD_FILTER_DATA_PRESSURE_ALTITUDE, 1},
    {"mag_auto_hard_iron_offset", 0x25, MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET, 1},
    {"mag_auto_soft_iron_matrix", 0x26, MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX, 1},
    {"mag_auto_hard_iron_offset_uncertainty", 0x28,
     MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY, 1},
    {"mag_auto_soft_iron_matrix_uncertainty", 0x29,
     MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY, 1},
    {"gnss_antenna_offset_correction", 0x30, MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION, 1},
    {"gnss_antenna_offset_correction_uncertainty", 0x31,
     MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY, 1},
    {"multi_antenna_offset_correction", 0x34, MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION, 1},
    {"multi_antenna_offset_correction_uncertainty", 0x35,
     MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY, 1},
    {"ecef_position_uncertainty", 0x36, MIPC_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY, 1},
    {"ecef_velocity_uncertainty", 0x37, MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY, 1},
    {"ecef_position", 0x40, MIPC_FIELD_FILTER_DATA_ECEF_POSITION, 1},
    {"ecef_velocity", 0x41, MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY, 1},
    {"ned_relative_position", 0x42, MIPC_FIELD_FILTER_DATA_NED_RELATIVE_POSITION, 1},
    {"gnss_position_aiding_status", 0x43, MIPC_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS, 1},
    {"aiding_measurement_summary", 0x46, MIPC_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY, 1},
    {"odometer_scale_factor_error", 0x47, MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR, 1},
    {"odometer_scale_factor_error_uncertainty", 0x48,
     MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY, 1},
    {"gnss_dual_antenna_status", 0x49, MIPC_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS, 1},
    {"aiding_frame_config_error", 0x50, MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR, 1},
    {"aiding_frame_config_error_uncertainty", 0x51,
     MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY, 1},
    {"llh_position", 0x03, MIPC_FIELD_GNSS_RECEIVER_1_LLH_POSITION, 1},
    {"ecef_position", 0x04, MIPC_FIELD_GNSS_RECEIVER_1_ECEF_POSITION, 1},
    {"ned_velocity", 0x05, MIPC_FIELD_GNSS_RECEIVER_1_NED_VELOCITY, 1},
    {"ecef_velocity", 0x06, MIPC_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY, 1},
    {"dop", 0x07, MIPC_FIELD_GNSS_RECEIVER_1_DOP, 1},
    {"utc_time", 0x08, MIPC_FIELD_GNSS_RECEIVER_1_UTC_TIME, 1},
    {"gps_time", 0x09, MIPC_FIELD_GNSS_RECEIVER_1_GPS_TIME, 1},
    {"fix_info", 0x0B, MIPC_FIELD_GNSS_RECEIVER_1_FIX_INFO, 1},
    {"hardware_status", 0x0D, MIPC_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS, 1},
    {"clock_info_2", 0x10, MIPC_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2, 1},
    {"gps_leap_seconds", 0x11, MIPC_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS, 1},
    {"sbas_info", 0x12, MIPC_FIELD_GNSS_RECEIVER_1_SBAS_INFO, 1},
    {"satellite_status", 0x20, MIPC_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS, 1},
    {"raw", 0x22, MIPC_FIELD_GNSS_RECEIVER_1_RAW, 1},
    {"gps_ephemeris", 0x61, MIPC_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS, 1},
    {"glonass_ephemeris", 0x62, MIPC_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS, 1},
    {"galileo_ephemeris", 0x63, MIPC_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS, 1},
    {"beidou_ephemeris", 0x64, MIPC_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS, 1},
    {"llh_position", 0x03, MIPC_FIELD_GNSS_RECEIVER_2_LLH_POSITION, 1},
    {"ecef_position", 0x04, MIPC_FIELD_GNSS_RECEIVER_2_ECEF_POSITION, 1},
    {"ned_velocity", 0x05, MIPC_FIELD_GNSS_RECEIVER_2_NED_VELOCITY, 1},
    {"ecef_velocity", 0x06, MIPC_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY, 1},
    {"dop", 0x07, MIPC_FIELD_GNSS_RECEIVER_2_DOP, 1},
    {"utc_time", 0x08, MIPC_FIELD_GNSS_RECEIVER_2_UTC_TIME, 1},
    {"gps_time", 0x09, MIPC_FIELD_GNSS_RECEIVER_2_GPS_TIME, 1},
    {"fix_info", 0x0B, MIPC_FIELD_GNSS_RECEIVER_2_FIX_INFO, 1},
    {"hardware_status", 0x0D, MIPC_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS, 1},
    {"clock_info_2", 0x10, MIPC_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2, 1},
    {"gps_leap_seconds", 0x11, MIPC_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS, 1},
    {"sbas_info", 0x12, MIPC_FIELD_GNSS_RECEIVER_2_SBAS_INFO, 1},
    {"satellite_status", 0x20, MIPC_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS, 1},
    {"raw", 0x22, MIPC_FIELD_GNSS_RECEIVER_2_RAW, 1},
    {"gps_ephemeris", 0x61, MIPC_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS, 1},
    {"glonass_ephemeris", 0x62, MIPC_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS, 1},
    {"galileo_ephemeris", 0x63, MIPC_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS, 1},
    {"beidou_ephemeris", 0x64, MIPC_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS, 1},
    {"base_station_info", 0x30, MIPC_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO, 1},
    {"rtk_corrections_status", 0x31, MIPC_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS, 1},
    {"llh_position", 0x03, MIPC_FIELD_GNSS_EXTERNAL_LLH_POSITION, 1},
    {"ned_velocity", 0x05, MIPC_FIELD_GNSS_EXTERNAL_NED_VELOCITY, 1},
    {"utc_time", 0x08, MIPC_FIELD_GNSS_EXTERNAL_UTC_TIME, 1},
    {"fix_info", 0x0B, MIPC_FIELD_GNSS_EXTERNAL_FIX_INFO, 1},
    {"satellite_status", 0x20, MIPC_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS, 1},
    {"built_in_test", 0x01, MIPC_FIELD_SYSTEM_DATA_BUILT_IN_TEST, 1},
    {"time_sync_status", 0x02, MIPC_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS, 1},
    {"gpio_state", 0x03, MIPC_FIELD_SYSTEM_DATA_GPIO_STATE, 1},
    {"event_source", 0xD0, MIPC_FIELD_SHARED_EVENT_SOURCE, 1},
    {"gps_timestamp", 0xD3, MIPC_FIELD_SHARED_GPS_TIMESTAMP, 1},
    {"delta_time", 0xD4, MIPC_FIELD_SHARED_DELTA_TIME, 1},
    {"reference_timestamp", 0xD5, MIPC_FIELD_SHARED_REFERENCE_TIMESTAMP, 1},
    {"reference_time_delta", 0xD6, MIPC_FIELD_SHARED_REFERENCE_TIME_DELTA, 1},
    {"external_timestamp", 0xD7, MIPC_FIELD_SHARED_EXTERNAL_TIMESTAMP, 1},
    {"external_time_delta", 0xD8, MIPC_FIELD_SHARED_EXTERNAL_TIME_DELTA, 1},
};

const mipc_layout_info_t *mipc_layout_info(mipc_field_id_t id) {
    if ((size_t)id >= MIPC_FIELD_COUNT) {
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
static const mipc_field_info_t *defined(uint8_t set, uint8_t descriptor, bool *set_known) {
    const uint16_t *table = k_sets[set];
    *set_known = table != NULL;
    if (!table || table[descriptor] == 0) {
        return NULL;
    }
    return &k_fields[table[descriptor] - 1];
}

/* The body of mipc_find_field, static so that mipc_decode_field inlines it. */
static const mipc_field_info_t *find_field(uint8_t set, uint8_t descriptor, mipc_status_t *why) {
    bool known = false;
    mipc_set_kind_t kind;
    const mipc_field_info_t *f = defined(set, descriptor, &known);
    if (f) {
        return f;
    }
    kind = mipc_set_kind(set);
    /* reserved fields of the set's kind */
    switch (kind) {
    case MIPC_SET_KIND_COMMAND:
        if (descriptor == 0xF1) {
            return &k_fields[0]; /* ack_nack */
        }
        break;
    case MIPC_SET_KIND_DATA:
        break;
    case MIPC_SET_KIND_NONE:
    default:
        break;
    }
    /* shared data fields, valid in every data set */
    if (kind == MIPC_SET_KIND_DATA) {
        bool shared_known;
        f = defined(0xFF, descriptor, &shared_known);
        if (f) {
            return f;
        }
    }
    if (why) {
        *why = known ? MIPC_ERR_UNKNOWN_DESCRIPTOR : MIPC_ERR_UNKNOWN_SET;
    }
    return NULL;
}

const mipc_field_info_t *mipc_find_field(uint8_t set, uint8_t descriptor, mipc_status_t *why) {
    return find_field(set, descriptor, why);
}

static mipc_status_t decode_layout(mipc_field_id_t id, const uint8_t *data, size_t len,
                                   mipc_field_value_t *out, mipc_decode_error_t *err) {
    out->id = id;
    switch (id) {
    case MIPC_FIELD_ACK_NACK:
        return mipc_ack_nack_decode(data, len, &out->u.ack_nack, err);
    case MIPC_FIELD_BASE_PING:
        return mipc_base_ping_decode(data, len, &out->u.base_ping, err);
    case MIPC_FIELD_BASE_SET_TO_IDLE:
        return mipc_base_set_to_idle_decode(data, len, &out->u.base_set_to_idle, err);
    case MIPC_FIELD_BASE_GET_DEVICE_INFO:
        return mipc_base_get_device_info_decode(data, len, &out->u.base_get_device_info, err);
    case MIPC_FIELD_BASE_DEVICE_INFO:
        return mipc_base_device_info_decode(data, len, &out->u.base_device_info, err);
    case MIPC_FIELD_BASE_GET_DEVICE_DESCRIPTORS:
        return mipc_base_get_device_descriptors_decode(data, len, &out->u.base_get_device_descriptors, err);
    case MIPC_FIELD_BASE_DEVICE_DESCRIPTORS:
        return mipc_base_device_descriptors_decode(data, len, &out->u.base_device_descriptors, err);
    case MIPC_FIELD_BASE_BUILT_IN_TEST:
        return mipc_base_built_in_test_decode(data, len, &out->u.base_built_in_test, err);
    case MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45:
        return mipc_base_built_in_test_result_gx5_45_decode(data, len,
                                                            &out->u.base_built_in_test_result_gx5_45, err);
    case MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS:
        return mipc_base_built_in_test_result_cv7_ins_decode(data, len,
                                                             &out->u.base_built_in_test_result_cv7_ins, err);
    case MIPC_FIELD_BASE_RESUME:
        return mipc_base_resume_decode(data, len, &out->u.base_resume, err);
    case MIPC_FIELD_BASE_GET_EXTENDED_DESCRIPTORS:
        return mipc_base_get_extended_descriptors_decode(data, len, &out->u.base_get_extended_descriptors,
                                                         err);
    case MIPC_FIELD_BASE_EXTENDED_DESCRIPTORS:
        return mipc_base_extended_descriptors_decode(data, len, &out->u.base_extended_descriptors, err);
    case MIPC_FIELD_BASE_CONTINUOUS_BIT:
        return mipc_base_continuous_bit_decode(data, len, &out->u.base_continuous_bit, err);
    case MIPC_FIELD_BASE_CONTINUOUS_BIT_RESULT:
        return mipc_base_continuous_bit_result_decode(data, len, &out->u.base_continuous_bit_result, err);
    case MIPC_FIELD_BASE_COMM_PORT_SPEED:
        return mipc_base_comm_port_speed_decode(data, len, &out->u.base_comm_port_speed, err);
    case MIPC_FIELD_BASE_COMM_PORT_SPEED_RESPONSE:
        return mipc_base_comm_port_speed_response_decode(data, len, &out->u.base_comm_port_speed_response,
                                                         err);
    case MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45:
        return mipc_base_gps_time_update_gx5_45_decode(data, len, &out->u.base_gps_time_update_gx5_45, err);
    case MIPC_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS:
        return mipc_base_gps_time_update_cv7_ins_decode(data, len, &out->u.base_gps_time_update_cv7_ins, err);
    case MIPC_FIELD_BASE_GPS_WEEK:
        return mipc_base_gps_week_decode(data, len, &out->u.base_gps_week, err);
    case MIPC_FIELD_BASE_GPS_SECONDS:
        return mipc_base_gps_seconds_decode(data, len, &out->u.base_gps_seconds, err);
    case MIPC_FIELD_BASE_DEVICE_RESET:
        return mipc_base_device_reset_decode(data, len, &out->u.base_device_reset, err);
    case MIPC_FIELD_THREEDM_EVENT_CONTROL:
        return mipc_threedm_event_control_decode(data, len, &out->u.threedm_event_control, err);
    case MIPC_FIELD_THREEDM_EVENT_CONTROL_RESPONSE:
        return mipc_threedm_event_control_response_decode(data, len, &out->u.threedm_event_control_response,
                                                          err);
    case MIPC_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS:
        return mipc_threedm_get_event_trigger_status_decode(data, len,
                                                            &out->u.threedm_get_event_trigger_status, err);
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_STATUS:
        return mipc_threedm_event_trigger_status_decode(data, len, &out->u.threedm_event_trigger_status, err);
    case MIPC_FIELD_THREEDM_GET_EVENT_ACTION_STATUS:
        return mipc_threedm_get_event_action_status_decode(data, len, &out->u.threedm_get_event_action_status,
                                                           err);
    case MIPC_FIELD_THREEDM_EVENT_ACTION_STATUS:
        return mipc_threedm_event_action_status_decode(data, len, &out->u.threedm_event_action_status, err);
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG:
        return mipc_threedm_event_trigger_config_decode(data, len, &out->u.threedm_event_trigger_config, err);
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE:
        return mipc_threedm_event_trigger_config_response_decode(
            data, len, &out->u.threedm_event_trigger_config_response, err);
    case MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG:
        return mipc_threedm_event_action_config_decode(data, len, &out->u.threedm_event_action_config, err);
    case MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE:
        return mipc_threedm_event_action_config_response_decode(
            data, len, &out->u.threedm_event_action_config_response, err);
    case MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45:
        return mipc_threedm_device_startup_settings_gx5_45_decode(
            data, len, &out->u.threedm_device_startup_settings_gx5_45, err);
    case MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS:
        return mipc_threedm_device_startup_settings_cv7_ins_decode(
            data, len, &out->u.threedm_device_startup_settings_cv7_ins, err);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER:
        return mipc_threedm_sensor_to_vehicle_euler_decode(data, len, &out->u.threedm_sensor_to_vehicle_euler,
                                                           err);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE:
        return mipc_threedm_sensor_to_vehicle_euler_response_decode(
            data, len, &out->u.threedm_sensor_to_vehicle_euler_response, err);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION:
        return mipc_threedm_sensor_to_vehicle_quaternion_decode(
            data, len, &out->u.threedm_sensor_to_vehicle_quaternion, err);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE:
        return mipc_threedm_sensor_to_vehicle_quaternion_response_decode(
            data, len, &out->u.threedm_sensor_to_vehicle_quaternion_response, err);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM:
        return mipc_threedm_sensor_to_vehicle_dcm_decode(data, len, &out->u.threedm_sensor_to_vehicle_dcm,
                                                         err);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE:
        return mipc_threedm_sensor_to_vehicle_dcm_response_decode(
            data, len, &out->u.threedm_sensor_to_vehicle_dcm_response, err);
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45:
        return mipc_threedm_accel_bias_gx5_45_decode(data, len, &out->u.threedm_accel_bias_gx5_45, err);
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS:
        return mipc_threedm_accel_bias_cv7_ins_decode(data, len, &out->u.threedm_accel_bias_cv7_ins, err);
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_RESPONSE:
        return mipc_threedm_accel_bias_response_decode(data, len, &out->u.threedm_accel_bias_response, err);
    case MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45:
        return mipc_threedm_gyro_bias_gx5_45_decode(data, len, &out->u.threedm_gyro_bias_gx5_45, err);
    case MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS:
        return mipc_threedm_gyro_bias_cv7_ins_decode(data, len, &out->u.threedm_gyro_bias_cv7_ins, err);
    case MIPC_FIELD_THREEDM_GYRO_BIAS_RESPONSE:
        return mipc_threedm_gyro_bias_response_decode(data, len, &out->u.threedm_gyro_bias_response, err);
    case MIPC_FIELD_THREEDM_CAPTURE_GYRO_BIAS:
        return mipc_threedm_capture_gyro_bias_decode(data, len, &out->u.threedm_capture_gyro_bias, err);
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45:
        return mipc_threedm_mag_hard_iron_offset_gx5_45_decode(
            data, len, &out->u.threedm_mag_hard_iron_offset_gx5_45, err);
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS:
        return mipc_threedm_mag_hard_iron_offset_cv7_ins_decode(
            data, len, &out->u.threedm_mag_hard_iron_offset_cv7_ins, err);
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE:
        return mipc_threedm_mag_hard_iron_offset_response_decode(
            data, len, &out->u.threedm_mag_hard_iron_offset_response, err);
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45:
        return mipc_threedm_mag_soft_iron_matrix_gx5_45_decode(
            data, len, &out->u.threedm_mag_soft_iron_matrix_gx5_45, err);
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS:
        return mipc_threedm_mag_soft_iron_matrix_cv7_ins_decode(
            data, len, &out->u.threedm_mag_soft_iron_matrix_cv7_ins, err);
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE:
        return mipc_threedm_mag_soft_iron_matrix_response_decode(
            data, len, &out->u.threedm_mag_soft_iron_matrix_response, err);
    case MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE:
        return mipc_threedm_coning_sculling_enable_decode(data, len, &out->u.threedm_coning_sculling_enable,
                                                          err);
    case MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE:
        return mipc_threedm_coning_sculling_enable_response_decode(
            data, len, &out->u.threedm_coning_sculling_enable_response, err);
    case MIPC_FIELD_THREEDM_UART_BAUDRATE:
        return mipc_threedm_uart_baudrate_decode(data, len, &out->u.threedm_uart_baudrate, err);
    case MIPC_FIELD_THREEDM_UART_BAUDRATE_RESPONSE:
        return mipc_threedm_uart_baudrate_response_decode(data, len, &out->u.threedm_uart_baudrate_response,
                                                          err);
    case MIPC_FIELD_THREEDM_GPIO_CONFIG:
        return mipc_threedm_gpio_config_decode(data, len, &out->u.threedm_gpio_config, err);
    case MIPC_FIELD_THREEDM_GPIO_CONFIG_RESPONSE:
        return mipc_threedm_gpio_config_response_decode(data, len, &out->u.threedm_gpio_config_response, err);
    case MIPC_FIELD_THREEDM_GPIO_STATE:
        return mipc_threedm_gpio_state_decode(data, len, &out->u.threedm_gpio_state, err);
    case MIPC_FIELD_THREEDM_GPIO_STATE_RESPONSE:
        return mipc_threedm_gpio_state_response_decode(data, len, &out->u.threedm_gpio_state_response, err);
    case MIPC_FIELD_THREEDM_ODOMETER_CONFIG:
        return mipc_threedm_odometer_config_decode(data, len, &out->u.threedm_odometer_config, err);
    case MIPC_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE:
        return mipc_threedm_odometer_config_response_decode(data, len,
                                                            &out->u.threedm_odometer_config_response, err);
    case MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER:
        return mipc_threedm_advanced_lowpass_filter_decode(data, len, &out->u.threedm_advanced_lowpass_filter,
                                                           err);
    case MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE:
        return mipc_threedm_advanced_lowpass_filter_response_decode(
            data, len, &out->u.threedm_advanced_lowpass_filter_response, err);
    case MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER:
        return mipc_threedm_complementary_filter_decode(data, len, &out->u.threedm_complementary_filter, err);
    case MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE:
        return mipc_threedm_complementary_filter_response_decode(
            data, len, &out->u.threedm_complementary_filter_response, err);
    case MIPC_FIELD_THREEDM_SENSOR_RANGE:
        return mipc_threedm_sensor_range_decode(data, len, &out->u.threedm_sensor_range, err);
    case MIPC_FIELD_THREEDM_SENSOR_RANGE_RESPONSE:
        return mipc_threedm_sensor_range_response_decode(data, len, &out->u.threedm_sensor_range_response,
                                                         err);
    case MIPC_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES:
        return mipc_threedm_get_calibrated_sensor_ranges_decode(
            data, len, &out->u.threedm_get_calibrated_sensor_ranges, err);
    case MIPC_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES:
        return mipc_threedm_calibrated_sensor_ranges_decode(data, len,
                                                            &out->u.threedm_calibrated_sensor_ranges, err);
    case MIPC_FIELD_THREEDM_LOWPASS_FILTER:
        return mipc_threedm_lowpass_filter_decode(data, len, &out->u.threedm_lowpass_filter, err);
    case MIPC_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE:
        return mipc_threedm_lowpass_filter_response_decode(data, len, &out->u.threedm_lowpass_filter_response,
                                                           err);
    case MIPC_FIELD_THREEDM_POLL_IMU_DATA:
        return mipc_threedm_poll_imu_data_decode(data, len, &out->u.threedm_poll_imu_data, err);
    case MIPC_FIELD_THREEDM_POLL_GNSS_DATA:
        return mipc_threedm_poll_gnss_data_decode(data, len, &out->u.threedm_poll_gnss_data, err);
    case MIPC_FIELD_THREEDM_POLL_FILTER_DATA:
        return mipc_threedm_poll_filter_data_decode(data, len, &out->u.threedm_poll_filter_data, err);
    case MIPC_FIELD_THREEDM_POLL_NMEA_DATA:
        return mipc_threedm_poll_nmea_data_decode(data, len, &out->u.threedm_poll_nmea_data, err);
    case MIPC_FIELD_THREEDM_POLL_DATA:
        return mipc_threedm_poll_data_decode(data, len, &out->u.threedm_poll_data, err);
    case MIPC_FIELD_THREEDM_GET_IMU_BASE_RATE:
        return mipc_threedm_get_imu_base_rate_decode(data, len, &out->u.threedm_get_imu_base_rate, err);
    case MIPC_FIELD_THREEDM_IMU_BASE_RATE:
        return mipc_threedm_imu_base_rate_decode(data, len, &out->u.threedm_imu_base_rate, err);
    case MIPC_FIELD_THREEDM_GET_GNSS_BASE_RATE:
        return mipc_threedm_get_gnss_base_rate_decode(data, len, &out->u.threedm_get_gnss_base_rate, err);
    case MIPC_FIELD_THREEDM_GNSS_BASE_RATE:
        return mipc_threedm_gnss_base_rate_decode(data, len, &out->u.threedm_gnss_base_rate, err);
    case MIPC_FIELD_THREEDM_GET_FILTER_BASE_RATE:
        return mipc_threedm_get_filter_base_rate_decode(data, len, &out->u.threedm_get_filter_base_rate, err);
    case MIPC_FIELD_THREEDM_FILTER_BASE_RATE:
        return mipc_threedm_filter_base_rate_decode(data, len, &out->u.threedm_filter_base_rate, err);
    case MIPC_FIELD_THREEDM_GET_BASE_RATE:
        return mipc_threedm_get_base_rate_decode(data, len, &out->u.threedm_get_base_rate, err);
    case MIPC_FIELD_THREEDM_BASE_RATE:
        return mipc_threedm_base_rate_decode(data, len, &out->u.threedm_base_rate, err);
    case MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT:
        return mipc_threedm_imu_message_format_decode(data, len, &out->u.threedm_imu_message_format, err);
    case MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_imu_message_format_response_decode(
            data, len, &out->u.threedm_imu_message_format_response, err);
    case MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT:
        return mipc_threedm_gnss_message_format_decode(data, len, &out->u.threedm_gnss_message_format, err);
    case MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_gnss_message_format_response_decode(
            data, len, &out->u.threedm_gnss_message_format_response, err);
    case MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT:
        return mipc_threedm_filter_message_format_decode(data, len, &out->u.threedm_filter_message_format,
                                                         err);
    case MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_filter_message_format_response_decode(
            data, len, &out->u.threedm_filter_message_format_response, err);
    case MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT:
        return mipc_threedm_nmea_message_format_decode(data, len, &out->u.threedm_nmea_message_format, err);
    case MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_nmea_message_format_response_decode(
            data, len, &out->u.threedm_nmea_message_format_response, err);
    case MIPC_FIELD_THREEDM_MESSAGE_FORMAT:
        return mipc_threedm_message_format_decode(data, len, &out->u.threedm_message_format, err);
    case MIPC_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_message_format_response_decode(data, len, &out->u.threedm_message_format_response,
                                                           err);
    case MIPC_FIELD_THREEDM_FACTORY_STREAMING:
        return mipc_threedm_factory_streaming_decode(data, len, &out->u.threedm_factory_streaming, err);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45:
        return mipc_threedm_data_stream_control_gx5_45_decode(
            data, len, &out->u.threedm_data_stream_control_gx5_45, err);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS:
        return mipc_threedm_data_stream_control_cv7_ins_decode(
            data, len, &out->u.threedm_data_stream_control_cv7_ins, err);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45:
        return mipc_threedm_data_stream_control_response_gx5_45_decode(
            data, len, &out->u.threedm_data_stream_control_response_gx5_45, err);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS:
        return mipc_threedm_data_stream_control_response_cv7_ins_decode(
            data, len, &out->u.threedm_data_stream_control_response_cv7_ins, err);
    case MIPC_FIELD_THREEDM_RAW_RTCM_MESSAGE:
        return mipc_threedm_raw_rtcm_message_decode(data, len, &out->u.threedm_raw_rtcm_message, err);
    case MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS:
        return mipc_threedm_gnss_constellation_settings_decode(
            data, len, &out->u.threedm_gnss_constellation_settings, err);
    case MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE:
        return mipc_threedm_gnss_constellation_settings_response_decode(
            data, len, &out->u.threedm_gnss_constellation_settings_response, err);
    case MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS:
        return mipc_threedm_gnss_sbas_settings_decode(data, len, &out->u.threedm_gnss_sbas_settings, err);
    case MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE:
        return mipc_threedm_gnss_sbas_settings_response_decode(
            data, len, &out->u.threedm_gnss_sbas_settings_response, err);
    case MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL:
        return mipc_threedm_gnss_assisted_fix_control_decode(data, len,
                                                             &out->u.threedm_gnss_assisted_fix_control, err);
    case MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE:
        return mipc_threedm_gnss_assisted_fix_control_response_decode(
            data, len, &out->u.threedm_gnss_assisted_fix_control_response, err);
    case MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE:
        return mipc_threedm_gnss_assist_time_update_decode(data, len, &out->u.threedm_gnss_assist_time_update,
                                                           err);
    case MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE:
        return mipc_threedm_gnss_assist_time_update_response_decode(
            data, len, &out->u.threedm_gnss_assist_time_update_response, err);
    case MIPC_FIELD_THREEDM_PPS_SOURCE:
        return mipc_threedm_pps_source_decode(data, len, &out->u.threedm_pps_source, err);
    case MIPC_FIELD_THREEDM_PPS_SOURCE_RESPONSE:
        return mipc_threedm_pps_source_response_decode(data, len, &out->u.threedm_pps_source_response, err);
    case MIPC_FIELD_THREEDM_GET_SUPPORTED_EVENTS:
        return mipc_threedm_get_supported_events_decode(data, len, &out->u.threedm_get_supported_events, err);
    case MIPC_FIELD_THREEDM_SUPPORTED_EVENTS:
        return mipc_threedm_supported_events_decode(data, len, &out->u.threedm_supported_events, err);
    case MIPC_FIELD_THREEDM_DEVICE_STATUS:
        return mipc_threedm_device_status_decode(data, len, &out->u.threedm_device_status, err);
    case MIPC_FIELD_THREEDM_DEVICE_STATUS_RESPONSE:
        return mipc_threedm_device_status_response_decode(data, len, &out->u.threedm_device_status_response,
                                                          err);
    case MIPC_FIELD_FILTER_RESET_FILTER:
        return mipc_filter_reset_filter_decode(data, len, &out->u.filter_reset_filter, err);
    case MIPC_FIELD_FILTER_SET_INITIAL_ATTITUDE:
        return mipc_filter_set_initial_attitude_decode(data, len, &out->u.filter_set_initial_attitude, err);
    case MIPC_FIELD_FILTER_SET_INITIAL_HEADING:
        return mipc_filter_set_initial_heading_decode(data, len, &out->u.filter_set_initial_heading, err);
    case MIPC_FIELD_FILTER_RUN_FILTER:
        return mipc_filter_run_filter_decode(data, len, &out->u.filter_run_filter, err);
    case MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE:
        return mipc_filter_vehicle_dynamics_mode_decode(data, len, &out->u.filter_vehicle_dynamics_mode, err);
    case MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE:
        return mipc_filter_vehicle_dynamics_mode_response_decode(
            data, len, &out->u.filter_vehicle_dynamics_mode_response, err);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM:
        return mipc_filter_sensor_to_vehicle_transform_decode(
            data, len, &out->u.filter_sensor_to_vehicle_transform, err);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE:
        return mipc_filter_sensor_to_vehicle_transform_response_decode(
            data, len, &out->u.filter_sensor_to_vehicle_transform_response, err);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET:
        return mipc_filter_sensor_to_vehicle_offset_decode(data, len, &out->u.filter_sensor_to_vehicle_offset,
                                                           err);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE:
        return mipc_filter_sensor_to_vehicle_offset_response_decode(
            data, len, &out->u.filter_sensor_to_vehicle_offset_response, err);
    case MIPC_FIELD_FILTER_ANTENNA_OFFSET:
        return mipc_filter_antenna_offset_decode(data, len, &out->u.filter_antenna_offset, err);
    case MIPC_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE:
        return mipc_filter_antenna_offset_response_decode(data, len, &out->u.filter_antenna_offset_response,
                                                          err);
    case MIPC_FIELD_FILTER_ESTIMATION_CONTROL:
        return mipc_filter_estimation_control_decode(data, len, &out->u.filter_estimation_control, err);
    case MIPC_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE:
        return mipc_filter_estimation_control_response_decode(
            data, len, &out->u.filter_estimation_control_response, err);
    case MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL:
        return mipc_filter_gnss_source_control_decode(data, len, &out->u.filter_gnss_source_control, err);
    case MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE:
        return mipc_filter_gnss_source_control_response_decode(
            data, len, &out->u.filter_gnss_source_control_response, err);
    case MIPC_FIELD_FILTER_EXTERNAL_GNSS_UPDATE:
        return mipc_filter_external_gnss_update_decode(data, len, &out->u.filter_external_gnss_update, err);
    case MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE:
        return mipc_filter_external_heading_update_decode(data, len, &out->u.filter_external_heading_update,
                                                          err);
    case MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL:
        return mipc_filter_heading_update_control_decode(data, len, &out->u.filter_heading_update_control,
                                                         err);
    case MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE:
        return mipc_filter_heading_update_control_response_decode(
            data, len, &out->u.filter_heading_update_control_response, err);
    case MIPC_FIELD_FILTER_AUTO_INIT_CONTROL:
        return mipc_filter_auto_init_control_decode(data, len, &out->u.filter_auto_init_control, err);
    case MIPC_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE:
        return mipc_filter_auto_init_control_response_decode(data, len,
                                                             &out->u.filter_auto_init_control_response, err);
    case MIPC_FIELD_FILTER_ACCEL_NOISE:
        return mipc_filter_accel_noise_decode(data, len, &out->u.filter_accel_noise, err);
    case MIPC_FIELD_FILTER_ACCEL_NOISE_RESPONSE:
        return mipc_filter_accel_noise_response_decode(data, len, &out->u.filter_accel_noise_response, err);
    case MIPC_FIELD_FILTER_GYRO_NOISE:
        return mipc_filter_gyro_noise_decode(data, len, &out->u.filter_gyro_noise, err);
    case MIPC_FIELD_FILTER_GYRO_NOISE_RESPONSE:
        return mipc_filter_gyro_noise_response_decode(data, len, &out->u.filter_gyro_noise_response, err);
    case MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL:
        return mipc_filter_accel_bias_model_decode(data, len, &out->u.filter_accel_bias_model, err);
    case MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE:
        return mipc_filter_accel_bias_model_response_decode(data, len,
                                                            &out->u.filter_accel_bias_model_response, err);
    case MIPC_FIELD_FILTER_GYRO_BIAS_MODEL:
        return mipc_filter_gyro_bias_model_decode(data, len, &out->u.filter_gyro_bias_model, err);
    case MIPC_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE:
        return mipc_filter_gyro_bias_model_response_decode(data, len, &out->u.filter_gyro_bias_model_response,
                                                           err);
    case MIPC_FIELD_FILTER_ZUPT_CONTROL:
        return mipc_filter_zupt_control_decode(data, len, &out->u.filter_zupt_control, err);
    case MIPC_FIELD_FILTER_ZUPT_CONTROL_RESPONSE:
        return mipc_filter_zupt_control_response_decode(data, len, &out->u.filter_zupt_control_response, err);
    case MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME:
        return mipc_filter_external_heading_update_with_time_decode(
            data, len, &out->u.filter_external_heading_update_with_time, err);
    case MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL:
        return mipc_filter_zero_angular_rate_update_control_decode(
            data, len, &out->u.filter_zero_angular_rate_update_control, err);
    case MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE:
        return mipc_filter_zero_angular_rate_update_control_response_decode(
            data, len, &out->u.filter_zero_angular_rate_update_control_response, err);
    case MIPC_FIELD_FILTER_TARE_ORIENTATION:
        return mipc_filter_tare_orientation_decode(data, len, &out->u.filter_tare_orientation, err);
    case MIPC_FIELD_FILTER_COMMANDED_ZUPT:
        return mipc_filter_commanded_zupt_decode(data, len, &out->u.filter_commanded_zupt, err);
    case MIPC_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE:
        return mipc_filter_commanded_zero_angular_rate_update_decode(
            data, len, &out->u.filter_commanded_zero_angular_rate_update, err);
    case MIPC_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION:
        return mipc_filter_mag_capture_auto_calibration_decode(
            data, len, &out->u.filter_mag_capture_auto_calibration, err);
    case MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV:
        return mipc_filter_gravity_noise_std_dev_decode(data, len, &out->u.filter_gravity_noise_std_dev, err);
    case MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE:
        return mipc_filter_gravity_noise_std_dev_response_decode(
            data, len, &out->u.filter_gravity_noise_std_dev_response, err);
    case MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV:
        return mipc_filter_pressure_altitude_noise_std_dev_decode(
            data, len, &out->u.filter_pressure_altitude_noise_std_dev, err);
    case MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE:
        return mipc_filter_pressure_altitude_noise_std_dev_response_decode(
            data, len, &out->u.filter_pressure_altitude_noise_std_dev_response, err);
    case MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE:
        return mipc_filter_hard_iron_offset_noise_decode(data, len, &out->u.filter_hard_iron_offset_noise,
                                                         err);
    case MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE:
        return mipc_filter_hard_iron_offset_noise_response_decode(
            data, len, &out->u.filter_hard_iron_offset_noise_response, err);
    case MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE:
        return mipc_filter_soft_iron_matrix_noise_decode(data, len, &out->u.filter_soft_iron_matrix_noise,
                                                         err);
    case MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE:
        return mipc_filter_soft_iron_matrix_noise_response_decode(
            data, len, &out->u.filter_soft_iron_matrix_noise_response, err);
    case MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV:
        return mipc_filter_mag_noise_std_dev_decode(data, len, &out->u.filter_mag_noise_std_dev, err);
    case MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE:
        return mipc_filter_mag_noise_std_dev_response_decode(data, len,
                                                             &out->u.filter_mag_noise_std_dev_response, err);
    case MIPC_FIELD_FILTER_DECLINATION_SOURCE:
        return mipc_filter_declination_source_decode(data, len, &out->u.filter_declination_source, err);
    case MIPC_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE:
        return mipc_filter_declination_source_response_decode(
            data, len, &out->u.filter_declination_source_response, err);
    case MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mipc_filter_gravity_magnitude_adaptive_measurement_decode(
            data, len, &out->u.filter_gravity_magnitude_adaptive_measurement, err);
    case MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mipc_filter_gravity_magnitude_adaptive_measurement_response_decode(
            data, len, &out->u.filter_gravity_magnitude_adaptive_measurement_response, err);
    case MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mipc_filter_mag_magnitude_adaptive_measurement_decode(
            data, len, &out->u.filter_mag_magnitude_adaptive_measurement, err);
    case MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mipc_filter_mag_magnitude_adaptive_measurement_response_decode(
            data, len, &out->u.filter_mag_magnitude_adaptive_measurement_response, err);
    case MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT:
        return mipc_filter_mag_dip_angle_adaptive_measurement_decode(
            data, len, &out->u.filter_mag_dip_angle_adaptive_measurement, err);
    case MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mipc_filter_mag_dip_angle_adaptive_measurement_response_decode(
            data, len, &out->u.filter_mag_dip_angle_adaptive_measurement_response, err);
    case MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL:
        return mipc_filter_altitude_aiding_control_decode(data, len, &out->u.filter_altitude_aiding_control,
                                                          err);
    case MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE:
        return mipc_filter_altitude_aiding_control_response_decode(
            data, len, &out->u.filter_altitude_aiding_control_response, err);
    case MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL:
        return mipc_filter_pitch_roll_aiding_control_decode(data, len,
                                                            &out->u.filter_pitch_roll_aiding_control, err);
    case MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE:
        return mipc_filter_pitch_roll_aiding_control_response_decode(
            data, len, &out->u.filter_pitch_roll_aiding_control_response, err);
    case MIPC_FIELD_FILTER_INCLINATION_SOURCE:
        return mipc_filter_inclination_source_decode(data, len, &out->u.filter_inclination_source, err);
    case MIPC_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE:
        return mipc_filter_inclination_source_response_decode(
            data, len, &out->u.filter_inclination_source_response, err);
    case MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE:
        return mipc_filter_magnetic_field_magnitude_source_decode(
            data, len, &out->u.filter_magnetic_field_magnitude_source, err);
    case MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE:
        return mipc_filter_magnetic_field_magnitude_source_response_decode(
            data, len, &out->u.filter_magnetic_field_magnitude_source_response, err);
    case MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL:
        return mipc_filter_aiding_measurement_control_decode(data, len,
                                                             &out->u.filter_aiding_measurement_control, err);
    case MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE:
        return mipc_filter_aiding_measurement_control_response_decode(
            data, len, &out->u.filter_aiding_measurement_control_response, err);
    case MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION:
        return mipc_filter_initialization_configuration_decode(
            data, len, &out->u.filter_initialization_configuration, err);
    case MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE:
        return mipc_filter_initialization_configuration_response_decode(
            data, len, &out->u.filter_initialization_configuration_response, err);
    case MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL:
        return mipc_filter_adaptive_filter_control_decode(data, len, &out->u.filter_adaptive_filter_control,
                                                          err);
    case MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE:
        return mipc_filter_adaptive_filter_control_response_decode(
            data, len, &out->u.filter_adaptive_filter_control_response, err);
    case MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET:
        return mipc_filter_multi_antenna_offset_decode(data, len, &out->u.filter_multi_antenna_offset, err);
    case MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE:
        return mipc_filter_multi_antenna_offset_response_decode(
            data, len, &out->u.filter_multi_antenna_offset_response, err);
    case MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION:
        return mipc_filter_relative_position_configuration_decode(
            data, len, &out->u.filter_relative_position_configuration, err);
    case MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE:
        return mipc_filter_relative_position_configuration_response_decode(
            data, len, &out->u.filter_relative_position_configuration_response, err);
    case MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM:
        return mipc_filter_reference_point_lever_arm_decode(data, len,
                                                            &out->u.filter_reference_point_lever_arm, err);
    case MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE:
        return mipc_filter_reference_point_lever_arm_response_decode(
            data, len, &out->u.filter_reference_point_lever_arm_response, err);
    case MIPC_FIELD_FILTER_SPEED_LEVER_ARM:
        return mipc_filter_speed_lever_arm_decode(data, len, &out->u.filter_speed_lever_arm, err);
    case MIPC_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE:
        return mipc_filter_speed_lever_arm_response_decode(data, len, &out->u.filter_speed_lever_arm_response,
                                                           err);
    case MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL:
        return mipc_filter_wheeled_vehicle_constraint_control_decode(
            data, len, &out->u.filter_wheeled_vehicle_constraint_control, err);
    case MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE:
        return mipc_filter_wheeled_vehicle_constraint_control_response_decode(
            data, len, &out->u.filter_wheeled_vehicle_constraint_control_response, err);
    case MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL:
        return mipc_filter_gnss_antenna_calibration_control_decode(
            data, len, &out->u.filter_gnss_antenna_calibration_control, err);
    case MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE:
        return mipc_filter_gnss_antenna_calibration_control_response_decode(
            data, len, &out->u.filter_gnss_antenna_calibration_control_response, err);
    case MIPC_FIELD_GNSS_RECEIVER_INFO:
        return mipc_gnss_receiver_info_decode(data, len, &out->u.gnss_receiver_info, err);
    case MIPC_FIELD_GNSS_RECEIVER_INFO_RESPONSE:
        return mipc_gnss_receiver_info_response_decode(data, len, &out->u.gnss_receiver_info_response, err);
    case MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION:
        return mipc_gnss_signal_configuration_decode(data, len, &out->u.gnss_signal_configuration, err);
    case MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE:
        return mipc_gnss_signal_configuration_response_decode(
            data, len, &out->u.gnss_signal_configuration_response, err);
    case MIPC_FIELD_GNSS_SPARTN_CONFIGURATION:
        return mipc_gnss_spartn_configuration_decode(data, len, &out->u.gnss_spartn_configuration, err);
    case MIPC_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE:
        return mipc_gnss_spartn_configuration_response_decode(
            data, len, &out->u.gnss_spartn_configuration_response, err);
    case MIPC_FIELD_AIDING_FRAME_CONFIG:
        return mipc_aiding_frame_config_decode(data, len, &out->u.aiding_frame_config, err);
    case MIPC_FIELD_AIDING_FRAME_CONFIG_RESPONSE:
        return mipc_aiding_frame_config_response_decode(data, len, &out->u.aiding_frame_config_response, err);
    case MIPC_FIELD_AIDING_ECHO_CONTROL:
        return mipc_aiding_echo_control_decode(data, len, &out->u.aiding_echo_control, err);
    case MIPC_FIELD_AIDING_ECHO_CONTROL_RESPONSE:
        return mipc_aiding_echo_control_response_decode(data, len, &out->u.aiding_echo_control_response, err);
    case MIPC_FIELD_AIDING_ECEF_POSITION:
        return mipc_aiding_ecef_position_decode(data, len, &out->u.aiding_ecef_position, err);
    case MIPC_FIELD_AIDING_LLH_POSITION:
        return mipc_aiding_llh_position_decode(data, len, &out->u.aiding_llh_position, err);
    case MIPC_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID:
        return mipc_aiding_height_above_ellipsoid_decode(data, len, &out->u.aiding_height_above_ellipsoid,
                                                         err);
    case MIPC_FIELD_AIDING_ECEF_VELOCITY:
        return mipc_aiding_ecef_velocity_decode(data, len, &out->u.aiding_ecef_velocity, err);
    case MIPC_FIELD_AIDING_NED_VELOCITY:
        return mipc_aiding_ned_velocity_decode(data, len, &out->u.aiding_ned_velocity, err);
    case MIPC_FIELD_AIDING_BODY_FRAME_VELOCITY:
        return mipc_aiding_body_frame_velocity_decode(data, len, &out->u.aiding_body_frame_velocity, err);
    case MIPC_FIELD_AIDING_TRUE_HEADING:
        return mipc_aiding_true_heading_decode(data, len, &out->u.aiding_true_heading, err);
    case MIPC_FIELD_AIDING_MAGNETIC_FIELD:
        return mipc_aiding_magnetic_field_decode(data, len, &out->u.aiding_magnetic_field, err);
    case MIPC_FIELD_AIDING_PRESSURE:
        return mipc_aiding_pressure_decode(data, len, &out->u.aiding_pressure, err);
    case MIPC_FIELD_SYSTEM_COMMUNICATION_MODE:
        return mipc_system_communication_mode_decode(data, len, &out->u.system_communication_mode, err);
    case MIPC_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE:
        return mipc_system_communication_mode_response_decode(
            data, len, &out->u.system_communication_mode_response, err);
    case MIPC_FIELD_SENSOR_SCALED_ACCEL:
        return mipc_sensor_scaled_accel_decode(data, len, &out->u.sensor_scaled_accel, err);
    case MIPC_FIELD_SENSOR_SCALED_GYRO:
        return mipc_sensor_scaled_gyro_decode(data, len, &out->u.sensor_scaled_gyro, err);
    case MIPC_FIELD_SENSOR_SCALED_MAG:
        return mipc_sensor_scaled_mag_decode(data, len, &out->u.sensor_scaled_mag, err);
    case MIPC_FIELD_SENSOR_DELTA_THETA:
        return mipc_sensor_delta_theta_decode(data, len, &out->u.sensor_delta_theta, err);
    case MIPC_FIELD_SENSOR_DELTA_VELOCITY:
        return mipc_sensor_delta_velocity_decode(data, len, &out->u.sensor_delta_velocity, err);
    case MIPC_FIELD_SENSOR_CF_ORIENTATION_MATRIX:
        return mipc_sensor_cf_orientation_matrix_decode(data, len, &out->u.sensor_cf_orientation_matrix, err);
    case MIPC_FIELD_SENSOR_CF_QUATERNION:
        return mipc_sensor_cf_quaternion_decode(data, len, &out->u.sensor_cf_quaternion, err);
    case MIPC_FIELD_SENSOR_CF_EULER_ANGLES:
        return mipc_sensor_cf_euler_angles_decode(data, len, &out->u.sensor_cf_euler_angles, err);
    case MIPC_FIELD_SENSOR_CF_STABILIZED_NORTH:
        return mipc_sensor_cf_stabilized_north_decode(data, len, &out->u.sensor_cf_stabilized_north, err);
    case MIPC_FIELD_SENSOR_CF_STABILIZED_UP:
        return mipc_sensor_cf_stabilized_up_decode(data, len, &out->u.sensor_cf_stabilized_up, err);
    case MIPC_FIELD_SENSOR_GPS_TIMESTAMP:
        return mipc_sensor_gps_timestamp_decode(data, len, &out->u.sensor_gps_timestamp, err);
    case MIPC_FIELD_SENSOR_TEMPERATURE_STATISTICS:
        return mipc_sensor_temperature_statistics_decode(data, len, &out->u.sensor_temperature_statistics,
                                                         err);
    case MIPC_FIELD_SENSOR_SCALED_PRESSURE:
        return mipc_sensor_scaled_pressure_decode(data, len, &out->u.sensor_scaled_pressure, err);
    case MIPC_FIELD_SENSOR_OVERRANGE_STATUS:
        return mipc_sensor_overrange_status_decode(data, len, &out->u.sensor_overrange_status, err);
    case MIPC_FIELD_SENSOR_ODOMETER_DATA:
        return mipc_sensor_odometer_data_decode(data, len, &out->u.sensor_odometer_data, err);
    case MIPC_FIELD_GNSS_DATA_LLH_POSITION:
        return mipc_gnss_data_llh_position_decode(data, len, &out->u.gnss_data_llh_position, err);
    case MIPC_FIELD_GNSS_DATA_ECEF_POSITION:
        return mipc_gnss_data_ecef_position_decode(data, len, &out->u.gnss_data_ecef_position, err);
    case MIPC_FIELD_GNSS_DATA_NED_VELOCITY:
        return mipc_gnss_data_ned_velocity_decode(data, len, &out->u.gnss_data_ned_velocity, err);
    case MIPC_FIELD_GNSS_DATA_ECEF_VELOCITY:
        return mipc_gnss_data_ecef_velocity_decode(data, len, &out->u.gnss_data_ecef_velocity, err);
    case MIPC_FIELD_GNSS_DATA_DOP:
        return mipc_gnss_data_dop_decode(data, len, &out->u.gnss_data_dop, err);
    case MIPC_FIELD_GNSS_DATA_UTC_TIME:
        return mipc_gnss_data_utc_time_decode(data, len, &out->u.gnss_data_utc_time, err);
    case MIPC_FIELD_GNSS_DATA_GPS_TIME:
        return mipc_gnss_data_gps_time_decode(data, len, &out->u.gnss_data_gps_time, err);
    case MIPC_FIELD_GNSS_DATA_CLOCK_INFO:
        return mipc_gnss_data_clock_info_decode(data, len, &out->u.gnss_data_clock_info, err);
    case MIPC_FIELD_GNSS_DATA_FIX_INFO:
        return mipc_gnss_data_fix_info_decode(data, len, &out->u.gnss_data_fix_info, err);
    case MIPC_FIELD_GNSS_DATA_SV_INFO:
        return mipc_gnss_data_sv_info_decode(data, len, &out->u.gnss_data_sv_info, err);
    case MIPC_FIELD_GNSS_DATA_HARDWARE_STATUS:
        return mipc_gnss_data_hardware_status_decode(data, len, &out->u.gnss_data_hardware_status, err);
    case MIPC_FIELD_GNSS_DATA_DGNSS_INFO:
        return mipc_gnss_data_dgnss_info_decode(data, len, &out->u.gnss_data_dgnss_info, err);
    case MIPC_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS:
        return mipc_gnss_data_dgnss_channel_status_decode(data, len, &out->u.gnss_data_dgnss_channel_status,
                                                          err);
    case MIPC_FIELD_FILTER_DATA_LLH_POSITION:
        return mipc_filter_data_llh_position_decode(data, len, &out->u.filter_data_llh_position, err);
    case MIPC_FIELD_FILTER_DATA_NED_VELOCITY:
        return mipc_filter_data_ned_velocity_decode(data, len, &out->u.filter_data_ned_velocity, err);
    case MIPC_FIELD_FILTER_DATA_ATTITUDE_QUATERNION:
        return mipc_filter_data_attitude_quaternion_decode(data, len, &out->u.filter_data_attitude_quaternion,
                                                           err);
    case MIPC_FIELD_FILTER_DATA_ATTITUDE_DCM:
        return mipc_filter_data_attitude_dcm_decode(data, len, &out->u.filter_data_attitude_dcm, err);
    case MIPC_FIELD_FILTER_DATA_EULER_ANGLES:
        return mipc_filter_data_euler_angles_decode(data, len, &out->u.filter_data_euler_angles, err);
    case MIPC_FIELD_FILTER_DATA_GYRO_BIAS:
        return mipc_filter_data_gyro_bias_decode(data, len, &out->u.filter_data_gyro_bias, err);
    case MIPC_FIELD_FILTER_DATA_ACCEL_BIAS:
        return mipc_filter_data_accel_bias_decode(data, len, &out->u.filter_data_accel_bias, err);
    case MIPC_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY:
        return mipc_filter_data_llh_position_uncertainty_decode(
            data, len, &out->u.filter_data_llh_position_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY:
        return mipc_filter_data_ned_velocity_uncertainty_decode(
            data, len, &out->u.filter_data_ned_velocity_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY:
        return mipc_filter_data_euler_angles_uncertainty_decode(
            data, len, &out->u.filter_data_euler_angles_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY:
        return mipc_filter_data_gyro_bias_uncertainty_decode(data, len,
                                                             &out->u.filter_data_gyro_bias_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY:
        return mipc_filter_data_accel_bias_uncertainty_decode(
            data, len, &out->u.filter_data_accel_bias_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_LINEAR_ACCEL:
        return mipc_filter_data_linear_accel_decode(data, len, &out->u.filter_data_linear_accel, err);
    case MIPC_FIELD_FILTER_DATA_COMP_ANGULAR_RATE:
        return mipc_filter_data_comp_angular_rate_decode(data, len, &out->u.filter_data_comp_angular_rate,
                                                         err);
    case MIPC_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE:
        return mipc_filter_data_wgs84_gravity_magnitude_decode(
            data, len, &out->u.filter_data_wgs84_gravity_magnitude, err);
    case MIPC_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45:
        return mipc_filter_data_filter_status_gx5_45_decode(data, len,
                                                            &out->u.filter_data_filter_status_gx5_45, err);
    case MIPC_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS:
        return mipc_filter_data_filter_status_cv7_ins_decode(data, len,
                                                             &out->u.filter_data_filter_status_cv7_ins, err);
    case MIPC_FIELD_FILTER_DATA_GPS_TIMESTAMP:
        return mipc_filter_data_gps_timestamp_decode(data, len, &out->u.filter_data_gps_timestamp, err);
    case MIPC_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY:
        return mipc_filter_data_quaternion_attitude_uncertainty_decode(
            data, len, &out->u.filter_data_quaternion_attitude_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_GRAVITY_VECTOR:
        return mipc_filter_data_gravity_vector_decode(data, len, &out->u.filter_data_gravity_vector, err);
    case MIPC_FIELD_FILTER_DATA_HEADING_UPDATE_STATE:
        return mipc_filter_data_heading_update_state_decode(data, len,
                                                            &out->u.filter_data_heading_update_state, err);
    case MIPC_FIELD_FILTER_DATA_MAGNETIC_MODEL:
        return mipc_filter_data_magnetic_model_decode(data, len, &out->u.filter_data_magnetic_model, err);
    case MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR:
        return mipc_filter_data_gyro_scale_factor_decode(data, len, &out->u.filter_data_gyro_scale_factor,
                                                         err);
    case MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR:
        return mipc_filter_data_accel_scale_factor_decode(data, len, &out->u.filter_data_accel_scale_factor,
                                                          err);
    case MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY:
        return mipc_filter_data_gyro_scale_factor_uncertainty_decode(
            data, len, &out->u.filter_data_gyro_scale_factor_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY:
        return mipc_filter_data_accel_scale_factor_uncertainty_decode(
            data, len, &out->u.filter_data_accel_scale_factor_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_COMPENSATED_ACCEL:
        return mipc_filter_data_compensated_accel_decode(data, len, &out->u.filter_data_compensated_accel,
                                                         err);
    case MIPC_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE:
        return mipc_filter_data_standard_atmosphere_decode(data, len, &out->u.filter_data_standard_atmosphere,
                                                           err);
    case MIPC_FIELD_FILTER_DATA_PRESSURE_ALTITUDE:
        return mipc_filter_data_pressure_altitude_decode(data, len, &out->u.filter_data_pressure_altitude,
                                                         err);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET:
        return mipc_filter_data_mag_auto_hard_iron_offset_decode(
            data, len, &out->u.filter_data_mag_auto_hard_iron_offset, err);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX:
        return mipc_filter_data_mag_auto_soft_iron_matrix_decode(
            data, len, &out->u.filter_data_mag_auto_soft_iron_matrix, err);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY:
        return mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_decode(
            data, len, &out->u.filter_data_mag_auto_hard_iron_offset_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY:
        return mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_decode(
            data, len, &out->u.filter_data_mag_auto_soft_iron_matrix_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION:
        return mipc_filter_data_gnss_antenna_offset_correction_decode(
            data, len, &out->u.filter_data_gnss_antenna_offset_correction, err);
    case MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mipc_filter_data_gnss_antenna_offset_correction_uncertainty_decode(
            data, len, &out->u.filter_data_gnss_antenna_offset_correction_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION:
        return mipc_filter_data_multi_antenna_offset_correction_decode(
            data, len, &out->u.filter_data_multi_antenna_offset_correction, err);
    case MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mipc_filter_data_multi_antenna_offset_correction_uncertainty_decode(
            data, len, &out->u.filter_data_multi_antenna_offset_correction_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY:
        return mipc_filter_data_ecef_position_uncertainty_decode(
            data, len, &out->u.filter_data_ecef_position_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY:
        return mipc_filter_data_ecef_velocity_uncertainty_decode(
            data, len, &out->u.filter_data_ecef_velocity_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_ECEF_POSITION:
        return mipc_filter_data_ecef_position_decode(data, len, &out->u.filter_data_ecef_position, err);
    case MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY:
        return mipc_filter_data_ecef_velocity_decode(data, len, &out->u.filter_data_ecef_velocity, err);
    case MIPC_FIELD_FILTER_DATA_NED_RELATIVE_POSITION:
        return mipc_filter_data_ned_relative_position_decode(data, len,
                                                             &out->u.filter_data_ned_relative_position, err);
    case MIPC_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS:
        return mipc_filter_data_gnss_position_aiding_status_decode(
            data, len, &out->u.filter_data_gnss_position_aiding_status, err);
    case MIPC_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY:
        return mipc_filter_data_aiding_measurement_summary_decode(
            data, len, &out->u.filter_data_aiding_measurement_summary, err);
    case MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR:
        return mipc_filter_data_odometer_scale_factor_error_decode(
            data, len, &out->u.filter_data_odometer_scale_factor_error, err);
    case MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY:
        return mipc_filter_data_odometer_scale_factor_error_uncertainty_decode(
            data, len, &out->u.filter_data_odometer_scale_factor_error_uncertainty, err);
    case MIPC_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS:
        return mipc_filter_data_gnss_dual_antenna_status_decode(
            data, len, &out->u.filter_data_gnss_dual_antenna_status, err);
    case MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR:
        return mipc_filter_data_aiding_frame_config_error_decode(
            data, len, &out->u.filter_data_aiding_frame_config_error, err);
    case MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY:
        return mipc_filter_data_aiding_frame_config_error_uncertainty_decode(
            data, len, &out->u.filter_data_aiding_frame_config_error_uncertainty, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_LLH_POSITION:
        return mipc_gnss_receiver_1_llh_position_decode(data, len, &out->u.gnss_receiver_1_llh_position, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_ECEF_POSITION:
        return mipc_gnss_receiver_1_ecef_position_decode(data, len, &out->u.gnss_receiver_1_ecef_position,
                                                         err);
    case MIPC_FIELD_GNSS_RECEIVER_1_NED_VELOCITY:
        return mipc_gnss_receiver_1_ned_velocity_decode(data, len, &out->u.gnss_receiver_1_ned_velocity, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY:
        return mipc_gnss_receiver_1_ecef_velocity_decode(data, len, &out->u.gnss_receiver_1_ecef_velocity,
                                                         err);
    case MIPC_FIELD_GNSS_RECEIVER_1_DOP:
        return mipc_gnss_receiver_1_dop_decode(data, len, &out->u.gnss_receiver_1_dop, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_UTC_TIME:
        return mipc_gnss_receiver_1_utc_time_decode(data, len, &out->u.gnss_receiver_1_utc_time, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_TIME:
        return mipc_gnss_receiver_1_gps_time_decode(data, len, &out->u.gnss_receiver_1_gps_time, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_FIX_INFO:
        return mipc_gnss_receiver_1_fix_info_decode(data, len, &out->u.gnss_receiver_1_fix_info, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS:
        return mipc_gnss_receiver_1_hardware_status_decode(data, len, &out->u.gnss_receiver_1_hardware_status,
                                                           err);
    case MIPC_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2:
        return mipc_gnss_receiver_1_clock_info_2_decode(data, len, &out->u.gnss_receiver_1_clock_info_2, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS:
        return mipc_gnss_receiver_1_gps_leap_seconds_decode(data, len,
                                                            &out->u.gnss_receiver_1_gps_leap_seconds, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_SBAS_INFO:
        return mipc_gnss_receiver_1_sbas_info_decode(data, len, &out->u.gnss_receiver_1_sbas_info, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS:
        return mipc_gnss_receiver_1_satellite_status_decode(data, len,
                                                            &out->u.gnss_receiver_1_satellite_status, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_RAW:
        return mipc_gnss_receiver_1_raw_decode(data, len, &out->u.gnss_receiver_1_raw, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS:
        return mipc_gnss_receiver_1_gps_ephemeris_decode(data, len, &out->u.gnss_receiver_1_gps_ephemeris,
                                                         err);
    case MIPC_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS:
        return mipc_gnss_receiver_1_glonass_ephemeris_decode(data, len,
                                                             &out->u.gnss_receiver_1_glonass_ephemeris, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS:
        return mipc_gnss_receiver_1_galileo_ephemeris_decode(data, len,
                                                             &out->u.gnss_receiver_1_galileo_ephemeris, err);
    case MIPC_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS:
        return mipc_gnss_receiver_1_beidou_ephemeris_decode(data, len,
                                                            &out->u.gnss_receiver_1_beidou_ephemeris, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_LLH_POSITION:
        return mipc_gnss_receiver_2_llh_position_decode(data, len, &out->u.gnss_receiver_2_llh_position, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_ECEF_POSITION:
        return mipc_gnss_receiver_2_ecef_position_decode(data, len, &out->u.gnss_receiver_2_ecef_position,
                                                         err);
    case MIPC_FIELD_GNSS_RECEIVER_2_NED_VELOCITY:
        return mipc_gnss_receiver_2_ned_velocity_decode(data, len, &out->u.gnss_receiver_2_ned_velocity, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY:
        return mipc_gnss_receiver_2_ecef_velocity_decode(data, len, &out->u.gnss_receiver_2_ecef_velocity,
                                                         err);
    case MIPC_FIELD_GNSS_RECEIVER_2_DOP:
        return mipc_gnss_receiver_2_dop_decode(data, len, &out->u.gnss_receiver_2_dop, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_UTC_TIME:
        return mipc_gnss_receiver_2_utc_time_decode(data, len, &out->u.gnss_receiver_2_utc_time, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_TIME:
        return mipc_gnss_receiver_2_gps_time_decode(data, len, &out->u.gnss_receiver_2_gps_time, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_FIX_INFO:
        return mipc_gnss_receiver_2_fix_info_decode(data, len, &out->u.gnss_receiver_2_fix_info, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS:
        return mipc_gnss_receiver_2_hardware_status_decode(data, len, &out->u.gnss_receiver_2_hardware_status,
                                                           err);
    case MIPC_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2:
        return mipc_gnss_receiver_2_clock_info_2_decode(data, len, &out->u.gnss_receiver_2_clock_info_2, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS:
        return mipc_gnss_receiver_2_gps_leap_seconds_decode(data, len,
                                                            &out->u.gnss_receiver_2_gps_leap_seconds, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_SBAS_INFO:
        return mipc_gnss_receiver_2_sbas_info_decode(data, len, &out->u.gnss_receiver_2_sbas_info, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS:
        return mipc_gnss_receiver_2_satellite_status_decode(data, len,
                                                            &out->u.gnss_receiver_2_satellite_status, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_RAW:
        return mipc_gnss_receiver_2_raw_decode(data, len, &out->u.gnss_receiver_2_raw, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS:
        return mipc_gnss_receiver_2_gps_ephemeris_decode(data, len, &out->u.gnss_receiver_2_gps_ephemeris,
                                                         err);
    case MIPC_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS:
        return mipc_gnss_receiver_2_glonass_ephemeris_decode(data, len,
                                                             &out->u.gnss_receiver_2_glonass_ephemeris, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS:
        return mipc_gnss_receiver_2_galileo_ephemeris_decode(data, len,
                                                             &out->u.gnss_receiver_2_galileo_ephemeris, err);
    case MIPC_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS:
        return mipc_gnss_receiver_2_beidou_ephemeris_decode(data, len,
                                                            &out->u.gnss_receiver_2_beidou_ephemeris, err);
    case MIPC_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO:
        return mipc_gnss_corrections_base_station_info_decode(
            data, len, &out->u.gnss_corrections_base_station_info, err);
    case MIPC_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS:
        return mipc_gnss_corrections_rtk_corrections_status_decode(
            data, len, &out->u.gnss_corrections_rtk_corrections_status, err);
    case MIPC_FIELD_GNSS_EXTERNAL_LLH_POSITION:
        return mipc_gnss_external_llh_position_decode(data, len, &out->u.gnss_external_llh_position, err);
    case MIPC_FIELD_GNSS_EXTERNAL_NED_VELOCITY:
        return mipc_gnss_external_ned_velocity_decode(data, len, &out->u.gnss_external_ned_velocity, err);
    case MIPC_FIELD_GNSS_EXTERNAL_UTC_TIME:
        return mipc_gnss_external_utc_time_decode(data, len, &out->u.gnss_external_utc_time, err);
    case MIPC_FIELD_GNSS_EXTERNAL_FIX_INFO:
        return mipc_gnss_external_fix_info_decode(data, len, &out->u.gnss_external_fix_info, err);
    case MIPC_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS:
        return mipc_gnss_external_satellite_status_decode(data, len, &out->u.gnss_external_satellite_status,
                                                          err);
    case MIPC_FIELD_SYSTEM_DATA_BUILT_IN_TEST:
        return mipc_system_data_built_in_test_decode(data, len, &out->u.system_data_built_in_test, err);
    case MIPC_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS:
        return mipc_system_data_time_sync_status_decode(data, len, &out->u.system_data_time_sync_status, err);
    case MIPC_FIELD_SYSTEM_DATA_GPIO_STATE:
        return mipc_system_data_gpio_state_decode(data, len, &out->u.system_data_gpio_state, err);
    case MIPC_FIELD_SHARED_EVENT_SOURCE:
        return mipc_shared_event_source_decode(data, len, &out->u.shared_event_source, err);
    case MIPC_FIELD_SHARED_GPS_TIMESTAMP:
        return mipc_shared_gps_timestamp_decode(data, len, &out->u.shared_gps_timestamp, err);
    case MIPC_FIELD_SHARED_DELTA_TIME:
        return mipc_shared_delta_time_decode(data, len, &out->u.shared_delta_time, err);
    case MIPC_FIELD_SHARED_REFERENCE_TIMESTAMP:
        return mipc_shared_reference_timestamp_decode(data, len, &out->u.shared_reference_timestamp, err);
    case MIPC_FIELD_SHARED_REFERENCE_TIME_DELTA:
        return mipc_shared_reference_time_delta_decode(data, len, &out->u.shared_reference_time_delta, err);
    case MIPC_FIELD_SHARED_EXTERNAL_TIMESTAMP:
        return mipc_shared_external_timestamp_decode(data, len, &out->u.shared_external_timestamp, err);
    case MIPC_FIELD_SHARED_EXTERNAL_TIME_DELTA:
        return mipc_shared_external_time_delta_decode(data, len, &out->u.shared_external_time_delta, err);
    case MIPC_FIELD_NONE:
    case MIPC_FIELD_COUNT:
    default:
        return MIPC_ERR_INVALID;
    }
}

/* Every case of mipc_decode_field: several layouts per field, a device to choose among them, error
 * details. Out of line (MIPC_NOINLINE) so that the common case below stays a short function. */
static MIPC_NOINLINE mipc_status_t decode_field_general(uint8_t set, uint8_t descriptor, const uint8_t *data,
                                                        size_t len, mipc_device_t device,
                                                        mipc_field_value_t *out, mipc_decode_error_t *err) {
    mipc_status_t why = MIPC_ERR_UNKNOWN_SET;
    const mipc_field_info_t *f = find_field(set, descriptor, &why);
    size_t first;
    size_t count;
    size_t i;
    out->id = MIPC_FIELD_NONE;
    if (!f) {
        return why;
    }
    first = (size_t)f->first_layout;
    count = f->layout_count;
    if (device != MIPC_DEVICE_ANY) {
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
        if (decode_layout((mipc_field_id_t)(first + i), data, len, out, NULL) == MIPC_OK) {
            return MIPC_OK;
        }
    }
    if (err) {
        memset(err, 0, sizeof *err);
        (void)decode_layout((mipc_field_id_t)first, data, len, out, err);
    }
    out->id = MIPC_FIELD_NONE;
    return MIPC_ERR_DECODE;
}

/* The common case first: a field its set defines, with one layout (the device does not choose
 * among one). Its decoder fills *err itself when it fails (as decode_field_general's second run
 * does). Anything else goes to decode_field_general, which starts over. */
mipc_status_t mipc_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                mipc_device_t device, mipc_field_value_t *out, mipc_decode_error_t *err) {
    const uint16_t *table = k_sets[set];
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (table && table[descriptor] != 0) {
        const mipc_field_info_t *f = &k_fields[table[descriptor] - 1];
        if (f->layout_count == 1) {
            if (decode_layout(f->first_layout, data, len, out, err) == MIPC_OK) {
                return MIPC_OK;
            }
            out->id = MIPC_FIELD_NONE;
            return MIPC_ERR_DECODE;
        }
    }
    return decode_field_general(set, descriptor, data, len, device, out, err);
}

/* Every entry of a payload to fn (out of line: mipc_decode_packet stays a switch). */
static MIPC_NOINLINE void visit_all(uint8_t set, const uint8_t *payload, size_t len, mipc_field_entry_fn fn,
                                    void *ctx) {
    mipc_field_iter_t it;
    mipc_field_entry_t e;
    mipc_field_iter_init(&it, set, payload, len);
    while (mipc_field_iter_next(&it, &e)) {
        fn(ctx, &e);
    }
}

const mipc_packet_index_t *mipc_decode_packet(const uint8_t *packet, mipc_packet_t *out,
                                              mipc_field_entry_fn other, void *ctx) {
    const uint8_t set = mipc_packet_set(packet);
    const uint8_t *payload = mipc_packet_payload(packet);
    const size_t len = mipc_packet_payload_length(packet);
    assert(packet != NULL);
    assert(out != NULL);
    out->set = set;
    switch (set) {
    case 0x80:
        (void)mipc_sensor_decode_packet(payload, len, &out->u.sensor, other, ctx);
        return &out->u.sensor.index;
    case 0x81:
        (void)mipc_gnss_data_decode_packet(payload, len, &out->u.gnss_data, other, ctx);
        return &out->u.gnss_data.index;
    case 0x82:
        (void)mipc_filter_data_decode_packet(payload, len, &out->u.filter_data, other, ctx);
        return &out->u.filter_data.index;
    case 0x91:
        (void)mipc_gnss_receiver_1_decode_packet(payload, len, &out->u.gnss_receiver_1, other, ctx);
        return &out->u.gnss_receiver_1.index;
    case 0x92:
        (void)mipc_gnss_receiver_2_decode_packet(payload, len, &out->u.gnss_receiver_2, other, ctx);
        return &out->u.gnss_receiver_2.index;
    case 0x93:
        (void)mipc_gnss_corrections_decode_packet(payload, len, &out->u.gnss_corrections, other, ctx);
        return &out->u.gnss_corrections.index;
    case 0x94:
        (void)mipc_gnss_external_decode_packet(payload, len, &out->u.gnss_external, other, ctx);
        return &out->u.gnss_external.index;
    case 0xA0:
        (void)mipc_system_data_decode_packet(payload, len, &out->u.system_data, other, ctx);
        return &out->u.system_data.index;
    case 0xFF:
        (void)mipc_shared_decode_packet(payload, len, &out->u.shared, other, ctx);
        return &out->u.shared.index;
    default:
        break;
    }
    if (other) {
        visit_all(set, payload, len, other, ctx);
    }
    return NULL;
}

/* The other of a cached decode's fallback: passes each entry on and notes the payload offsets of
 * the fields (a trailing entry, or more fields than a shape holds, and the packet is not recorded). */
typedef struct {
    mipc_field_entry_fn other;
    void *ctx;
    size_t count;
    int whole; /* every entry a field, at most MIPC_LAYOUT_SHAPE_FIELDS */
    size_t pos[MIPC_LAYOUT_SHAPE_FIELDS];
} noted_other_t;

static void note_other(void *ctx, const mipc_field_entry_t *entry) {
    noted_other_t *c = ctx;
    if (entry->kind != MIPC_ENTRY_FIELD || c->count == MIPC_LAYOUT_SHAPE_FIELDS) {
        c->whole = 0;
    } else {
        c->pos[c->count++] = entry->offset;
    }
    if (c->other) {
        c->other(c->ctx, entry);
    }
}

/* The members of a set's packet struct (mipc_layout_cache_record_); count 0: none. */
static const mipc_layout_member_t *shape_members(uint8_t set, size_t *count) {
    switch (set) {
    case 0x80:
        *count = 22;
        return mipc_sensor_layout_members_;
    case 0x81:
        *count = 20;
        return mipc_gnss_data_layout_members_;
    case 0x82:
        *count = 54;
        return mipc_filter_data_layout_members_;
    case 0x91:
        *count = 25;
        return mipc_gnss_receiver_1_layout_members_;
    case 0x92:
        *count = 25;
        return mipc_gnss_receiver_2_layout_members_;
    case 0x93:
        *count = 9;
        return mipc_gnss_corrections_layout_members_;
    case 0x94:
        *count = 12;
        return mipc_gnss_external_layout_members_;
    case 0xA0:
        *count = 10;
        return mipc_system_data_layout_members_;
    case 0xFF:
        *count = 7;
        return mipc_shared_layout_members_;
    default:
        *count = 0;
        return NULL;
    }
}

/* A packet whose shape is not the last one hit: the other cached shapes, else the straight-line
 * decoder (and its shape recorded). */
static MIPC_NOINLINE const mipc_packet_index_t *decode_uncached(mipc_layout_cache_t *cache,
                                                                const uint8_t *packet, mipc_packet_t *out,
                                                                mipc_field_entry_fn other, void *ctx) {
    const uint8_t set = mipc_packet_set(packet);
    const uint8_t *payload = mipc_packet_payload(packet);
    const size_t len = mipc_packet_payload_length(packet);
    const mipc_layout_shape_t *shape = mipc_layout_cache_find_(cache, set, payload, len);
    const mipc_packet_index_t *index;
    noted_other_t noted;
    if (shape != NULL && mipc_layout_shape_decode_(shape, payload, (mipc_packet_index_t *)(void *)&out->u)) {
        out->set = set;
        if (shape->others != 0 && other != NULL) {
            mipc_layout_shape_others_(shape, payload, other, ctx);
        }
        return (const mipc_packet_index_t *)(const void *)&out->u;
    }
    noted.other = other;
    noted.ctx = ctx;
    noted.count = 0;
    noted.whole = 1;
    index = mipc_decode_packet(packet, out, note_other, &noted);
    if (index != NULL && noted.whole && shape == NULL) {
        size_t count;
        const mipc_layout_member_t *members = shape_members(set, &count);
        if (count != 0) {
            mipc_layout_cache_record_(cache, set, payload, len, index, noted.pos, noted.count, members,
                                      count);
        }
    }
    return index;
}

/* Every packet struct of out->u starts with its index: a pointer to the union converts to one to
 * each member, and that to one to its first member (C99 6.7.2.1). */
const mipc_packet_index_t *mipc_decode_packet_cached(mipc_layout_cache_t *cache, const uint8_t *packet,
                                                     mipc_packet_t *out, mipc_field_entry_fn other,
                                                     void *ctx) {
    const uint8_t set = mipc_packet_set(packet);
    const uint8_t *payload = mipc_packet_payload(packet);
    const mipc_layout_shape_t *shape;
    assert(cache != NULL);
    assert(out != NULL);
    shape = &cache->shapes[cache->last % MIPC_LAYOUT_CACHE_SHAPES];
    if (mipc_layout_shape_matches_(shape, set, payload, mipc_packet_payload_length(packet)) &&
        mipc_layout_shape_decode_(shape, payload, (mipc_packet_index_t *)(void *)&out->u)) {
        out->set = set;
        if (shape->others != 0 && other != NULL) {
            mipc_layout_shape_others_(shape, payload, other, ctx);
        }
        return (const mipc_packet_index_t *)(const void *)&out->u;
    }
    return decode_uncached(cache, packet, out, other, ctx);
}

mipc_status_t mipc_encode_field(const mipc_field_value_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    switch (value->id) {
    case MIPC_FIELD_ACK_NACK:
        return mipc_ack_nack_encode(&value->u.ack_nack, buf, cap, len_out);
    case MIPC_FIELD_BASE_PING:
        return mipc_base_ping_encode(&value->u.base_ping, buf, cap, len_out);
    case MIPC_FIELD_BASE_SET_TO_IDLE:
        return mipc_base_set_to_idle_encode(&value->u.base_set_to_idle, buf, cap, len_out);
    case MIPC_FIELD_BASE_GET_DEVICE_INFO:
        return mipc_base_get_device_info_encode(&value->u.base_get_device_info, buf, cap, len_out);
    case MIPC_FIELD_BASE_DEVICE_INFO:
        return mipc_base_device_info_encode(&value->u.base_device_info, buf, cap, len_out);
    case MIPC_FIELD_BASE_GET_DEVICE_DESCRIPTORS:
        return mipc_base_get_device_descriptors_encode(&value->u.base_get_device_descriptors, buf, cap,
                                                       len_out);
    case MIPC_FIELD_BASE_DEVICE_DESCRIPTORS:
        return mipc_base_device_descriptors_encode(&value->u.base_device_descriptors, buf, cap, len_out);
    case MIPC_FIELD_BASE_BUILT_IN_TEST:
        return mipc_base_built_in_test_encode(&value->u.base_built_in_test, buf, cap, len_out);
    case MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_GX5_45:
        return mipc_base_built_in_test_result_gx5_45_encode(&value->u.base_built_in_test_result_gx5_45, buf,
                                                            cap, len_out);
    case MIPC_FIELD_BASE_BUILT_IN_TEST_RESULT_CV7_INS:
        return mipc_base_built_in_test_result_cv7_ins_encode(&value->u.base_built_in_test_result_cv7_ins, buf,
                                                             cap, len_out);
    case MIPC_FIELD_BASE_RESUME:
        return mipc_base_resume_encode(&value->u.base_resume, buf, cap, len_out);
    case MIPC_FIELD_BASE_GET_EXTENDED_DESCRIPTORS:
        return mipc_base_get_extended_descriptors_encode(&value->u.base_get_extended_descriptors, buf, cap,
                                                         len_out);
    case MIPC_FIELD_BASE_EXTENDED_DESCRIPTORS:
        return mipc_base_extended_descriptors_encode(&value->u.base_extended_descriptors, buf, cap, len_out);
    case MIPC_FIELD_BASE_CONTINUOUS_BIT:
        return mipc_base_continuous_bit_encode(&value->u.base_continuous_bit, buf, cap, len_out);
    case MIPC_FIELD_BASE_CONTINUOUS_BIT_RESULT:
        return mipc_base_continuous_bit_result_encode(&value->u.base_continuous_bit_result, buf, cap,
                                                      len_out);
    case MIPC_FIELD_BASE_COMM_PORT_SPEED:
        return mipc_base_comm_port_speed_encode(&value->u.base_comm_port_speed, buf, cap, len_out);
    case MIPC_FIELD_BASE_COMM_PORT_SPEED_RESPONSE:
        return mipc_base_comm_port_speed_response_encode(&value->u.base_comm_port_speed_response, buf, cap,
                                                         len_out);
    case MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45:
        return mipc_base_gps_time_update_gx5_45_encode(&value->u.base_gps_time_update_gx5_45, buf, cap,
                                                       len_out);
    case MIPC_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS:
        return mipc_base_gps_time_update_cv7_ins_encode(&value->u.base_gps_time_update_cv7_ins, buf, cap,
                                                        len_out);
    case MIPC_FIELD_BASE_GPS_WEEK:
        return mipc_base_gps_week_encode(&value->u.base_gps_week, buf, cap, len_out);
    case MIPC_FIELD_BASE_GPS_SECONDS:
        return mipc_base_gps_seconds_encode(&value->u.base_gps_seconds, buf, cap, len_out);
    case MIPC_FIELD_BASE_DEVICE_RESET:
        return mipc_base_device_reset_encode(&value->u.base_device_reset, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_EVENT_CONTROL:
        return mipc_threedm_event_control_encode(&value->u.threedm_event_control, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_EVENT_CONTROL_RESPONSE:
        return mipc_threedm_event_control_response_encode(&value->u.threedm_event_control_response, buf, cap,
                                                          len_out);
    case MIPC_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS:
        return mipc_threedm_get_event_trigger_status_encode(&value->u.threedm_get_event_trigger_status, buf,
                                                            cap, len_out);
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_STATUS:
        return mipc_threedm_event_trigger_status_encode(&value->u.threedm_event_trigger_status, buf, cap,
                                                        len_out);
    case MIPC_FIELD_THREEDM_GET_EVENT_ACTION_STATUS:
        return mipc_threedm_get_event_action_status_encode(&value->u.threedm_get_event_action_status, buf,
                                                           cap, len_out);
    case MIPC_FIELD_THREEDM_EVENT_ACTION_STATUS:
        return mipc_threedm_event_action_status_encode(&value->u.threedm_event_action_status, buf, cap,
                                                       len_out);
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG:
        return mipc_threedm_event_trigger_config_encode(&value->u.threedm_event_trigger_config, buf, cap,
                                                        len_out);
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG_RESPONSE:
        return mipc_threedm_event_trigger_config_response_encode(
            &value->u.threedm_event_trigger_config_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG:
        return mipc_threedm_event_action_config_encode(&value->u.threedm_event_action_config, buf, cap,
                                                       len_out);
    case MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG_RESPONSE:
        return mipc_threedm_event_action_config_response_encode(
            &value->u.threedm_event_action_config_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45:
        return mipc_threedm_device_startup_settings_gx5_45_encode(
            &value->u.threedm_device_startup_settings_gx5_45, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS:
        return mipc_threedm_device_startup_settings_cv7_ins_encode(
            &value->u.threedm_device_startup_settings_cv7_ins, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER:
        return mipc_threedm_sensor_to_vehicle_euler_encode(&value->u.threedm_sensor_to_vehicle_euler, buf,
                                                           cap, len_out);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER_RESPONSE:
        return mipc_threedm_sensor_to_vehicle_euler_response_encode(
            &value->u.threedm_sensor_to_vehicle_euler_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION:
        return mipc_threedm_sensor_to_vehicle_quaternion_encode(
            &value->u.threedm_sensor_to_vehicle_quaternion, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION_RESPONSE:
        return mipc_threedm_sensor_to_vehicle_quaternion_response_encode(
            &value->u.threedm_sensor_to_vehicle_quaternion_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM:
        return mipc_threedm_sensor_to_vehicle_dcm_encode(&value->u.threedm_sensor_to_vehicle_dcm, buf, cap,
                                                         len_out);
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM_RESPONSE:
        return mipc_threedm_sensor_to_vehicle_dcm_response_encode(
            &value->u.threedm_sensor_to_vehicle_dcm_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45:
        return mipc_threedm_accel_bias_gx5_45_encode(&value->u.threedm_accel_bias_gx5_45, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS:
        return mipc_threedm_accel_bias_cv7_ins_encode(&value->u.threedm_accel_bias_cv7_ins, buf, cap,
                                                      len_out);
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_RESPONSE:
        return mipc_threedm_accel_bias_response_encode(&value->u.threedm_accel_bias_response, buf, cap,
                                                       len_out);
    case MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45:
        return mipc_threedm_gyro_bias_gx5_45_encode(&value->u.threedm_gyro_bias_gx5_45, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS:
        return mipc_threedm_gyro_bias_cv7_ins_encode(&value->u.threedm_gyro_bias_cv7_ins, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GYRO_BIAS_RESPONSE:
        return mipc_threedm_gyro_bias_response_encode(&value->u.threedm_gyro_bias_response, buf, cap,
                                                      len_out);
    case MIPC_FIELD_THREEDM_CAPTURE_GYRO_BIAS:
        return mipc_threedm_capture_gyro_bias_encode(&value->u.threedm_capture_gyro_bias, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45:
        return mipc_threedm_mag_hard_iron_offset_gx5_45_encode(&value->u.threedm_mag_hard_iron_offset_gx5_45,
                                                               buf, cap, len_out);
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS:
        return mipc_threedm_mag_hard_iron_offset_cv7_ins_encode(
            &value->u.threedm_mag_hard_iron_offset_cv7_ins, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_RESPONSE:
        return mipc_threedm_mag_hard_iron_offset_response_encode(
            &value->u.threedm_mag_hard_iron_offset_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45:
        return mipc_threedm_mag_soft_iron_matrix_gx5_45_encode(&value->u.threedm_mag_soft_iron_matrix_gx5_45,
                                                               buf, cap, len_out);
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS:
        return mipc_threedm_mag_soft_iron_matrix_cv7_ins_encode(
            &value->u.threedm_mag_soft_iron_matrix_cv7_ins, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_RESPONSE:
        return mipc_threedm_mag_soft_iron_matrix_response_encode(
            &value->u.threedm_mag_soft_iron_matrix_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE:
        return mipc_threedm_coning_sculling_enable_encode(&value->u.threedm_coning_sculling_enable, buf, cap,
                                                          len_out);
    case MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE_RESPONSE:
        return mipc_threedm_coning_sculling_enable_response_encode(
            &value->u.threedm_coning_sculling_enable_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_UART_BAUDRATE:
        return mipc_threedm_uart_baudrate_encode(&value->u.threedm_uart_baudrate, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_UART_BAUDRATE_RESPONSE:
        return mipc_threedm_uart_baudrate_response_encode(&value->u.threedm_uart_baudrate_response, buf, cap,
                                                          len_out);
    case MIPC_FIELD_THREEDM_GPIO_CONFIG:
        return mipc_threedm_gpio_config_encode(&value->u.threedm_gpio_config, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GPIO_CONFIG_RESPONSE:
        return mipc_threedm_gpio_config_response_encode(&value->u.threedm_gpio_config_response, buf, cap,
                                                        len_out);
    case MIPC_FIELD_THREEDM_GPIO_STATE:
        return mipc_threedm_gpio_state_encode(&value->u.threedm_gpio_state, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GPIO_STATE_RESPONSE:
        return mipc_threedm_gpio_state_response_encode(&value->u.threedm_gpio_state_response, buf, cap,
                                                       len_out);
    case MIPC_FIELD_THREEDM_ODOMETER_CONFIG:
        return mipc_threedm_odometer_config_encode(&value->u.threedm_odometer_config, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_ODOMETER_CONFIG_RESPONSE:
        return mipc_threedm_odometer_config_response_encode(&value->u.threedm_odometer_config_response, buf,
                                                            cap, len_out);
    case MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER:
        return mipc_threedm_advanced_lowpass_filter_encode(&value->u.threedm_advanced_lowpass_filter, buf,
                                                           cap, len_out);
    case MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER_RESPONSE:
        return mipc_threedm_advanced_lowpass_filter_response_encode(
            &value->u.threedm_advanced_lowpass_filter_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER:
        return mipc_threedm_complementary_filter_encode(&value->u.threedm_complementary_filter, buf, cap,
                                                        len_out);
    case MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER_RESPONSE:
        return mipc_threedm_complementary_filter_response_encode(
            &value->u.threedm_complementary_filter_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_SENSOR_RANGE:
        return mipc_threedm_sensor_range_encode(&value->u.threedm_sensor_range, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_SENSOR_RANGE_RESPONSE:
        return mipc_threedm_sensor_range_response_encode(&value->u.threedm_sensor_range_response, buf, cap,
                                                         len_out);
    case MIPC_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES:
        return mipc_threedm_get_calibrated_sensor_ranges_encode(
            &value->u.threedm_get_calibrated_sensor_ranges, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_CALIBRATED_SENSOR_RANGES:
        return mipc_threedm_calibrated_sensor_ranges_encode(&value->u.threedm_calibrated_sensor_ranges, buf,
                                                            cap, len_out);
    case MIPC_FIELD_THREEDM_LOWPASS_FILTER:
        return mipc_threedm_lowpass_filter_encode(&value->u.threedm_lowpass_filter, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_LOWPASS_FILTER_RESPONSE:
        return mipc_threedm_lowpass_filter_response_encode(&value->u.threedm_lowpass_filter_response, buf,
                                                           cap, len_out);
    case MIPC_FIELD_THREEDM_POLL_IMU_DATA:
        return mipc_threedm_poll_imu_data_encode(&value->u.threedm_poll_imu_data, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_POLL_GNSS_DATA:
        return mipc_threedm_poll_gnss_data_encode(&value->u.threedm_poll_gnss_data, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_POLL_FILTER_DATA:
        return mipc_threedm_poll_filter_data_encode(&value->u.threedm_poll_filter_data, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_POLL_NMEA_DATA:
        return mipc_threedm_poll_nmea_data_encode(&value->u.threedm_poll_nmea_data, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_POLL_DATA:
        return mipc_threedm_poll_data_encode(&value->u.threedm_poll_data, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GET_IMU_BASE_RATE:
        return mipc_threedm_get_imu_base_rate_encode(&value->u.threedm_get_imu_base_rate, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_IMU_BASE_RATE:
        return mipc_threedm_imu_base_rate_encode(&value->u.threedm_imu_base_rate, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GET_GNSS_BASE_RATE:
        return mipc_threedm_get_gnss_base_rate_encode(&value->u.threedm_get_gnss_base_rate, buf, cap,
                                                      len_out);
    case MIPC_FIELD_THREEDM_GNSS_BASE_RATE:
        return mipc_threedm_gnss_base_rate_encode(&value->u.threedm_gnss_base_rate, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GET_FILTER_BASE_RATE:
        return mipc_threedm_get_filter_base_rate_encode(&value->u.threedm_get_filter_base_rate, buf, cap,
                                                        len_out);
    case MIPC_FIELD_THREEDM_FILTER_BASE_RATE:
        return mipc_threedm_filter_base_rate_encode(&value->u.threedm_filter_base_rate, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GET_BASE_RATE:
        return mipc_threedm_get_base_rate_encode(&value->u.threedm_get_base_rate, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_BASE_RATE:
        return mipc_threedm_base_rate_encode(&value->u.threedm_base_rate, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT:
        return mipc_threedm_imu_message_format_encode(&value->u.threedm_imu_message_format, buf, cap,
                                                      len_out);
    case MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_imu_message_format_response_encode(&value->u.threedm_imu_message_format_response,
                                                               buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT:
        return mipc_threedm_gnss_message_format_encode(&value->u.threedm_gnss_message_format, buf, cap,
                                                       len_out);
    case MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_gnss_message_format_response_encode(
            &value->u.threedm_gnss_message_format_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT:
        return mipc_threedm_filter_message_format_encode(&value->u.threedm_filter_message_format, buf, cap,
                                                         len_out);
    case MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_filter_message_format_response_encode(
            &value->u.threedm_filter_message_format_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT:
        return mipc_threedm_nmea_message_format_encode(&value->u.threedm_nmea_message_format, buf, cap,
                                                       len_out);
    case MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_nmea_message_format_response_encode(
            &value->u.threedm_nmea_message_format_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_MESSAGE_FORMAT:
        return mipc_threedm_message_format_encode(&value->u.threedm_message_format, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_MESSAGE_FORMAT_RESPONSE:
        return mipc_threedm_message_format_response_encode(&value->u.threedm_message_format_response, buf,
                                                           cap, len_out);
    case MIPC_FIELD_THREEDM_FACTORY_STREAMING:
        return mipc_threedm_factory_streaming_encode(&value->u.threedm_factory_streaming, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45:
        return mipc_threedm_data_stream_control_gx5_45_encode(&value->u.threedm_data_stream_control_gx5_45,
                                                              buf, cap, len_out);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS:
        return mipc_threedm_data_stream_control_cv7_ins_encode(&value->u.threedm_data_stream_control_cv7_ins,
                                                               buf, cap, len_out);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_GX5_45:
        return mipc_threedm_data_stream_control_response_gx5_45_encode(
            &value->u.threedm_data_stream_control_response_gx5_45, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_RESPONSE_CV7_INS:
        return mipc_threedm_data_stream_control_response_cv7_ins_encode(
            &value->u.threedm_data_stream_control_response_cv7_ins, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_RAW_RTCM_MESSAGE:
        return mipc_threedm_raw_rtcm_message_encode(&value->u.threedm_raw_rtcm_message, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS:
        return mipc_threedm_gnss_constellation_settings_encode(&value->u.threedm_gnss_constellation_settings,
                                                               buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS_RESPONSE:
        return mipc_threedm_gnss_constellation_settings_response_encode(
            &value->u.threedm_gnss_constellation_settings_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS:
        return mipc_threedm_gnss_sbas_settings_encode(&value->u.threedm_gnss_sbas_settings, buf, cap,
                                                      len_out);
    case MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS_RESPONSE:
        return mipc_threedm_gnss_sbas_settings_response_encode(&value->u.threedm_gnss_sbas_settings_response,
                                                               buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL:
        return mipc_threedm_gnss_assisted_fix_control_encode(&value->u.threedm_gnss_assisted_fix_control, buf,
                                                             cap, len_out);
    case MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL_RESPONSE:
        return mipc_threedm_gnss_assisted_fix_control_response_encode(
            &value->u.threedm_gnss_assisted_fix_control_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE:
        return mipc_threedm_gnss_assist_time_update_encode(&value->u.threedm_gnss_assist_time_update, buf,
                                                           cap, len_out);
    case MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE_RESPONSE:
        return mipc_threedm_gnss_assist_time_update_response_encode(
            &value->u.threedm_gnss_assist_time_update_response, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_PPS_SOURCE:
        return mipc_threedm_pps_source_encode(&value->u.threedm_pps_source, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_PPS_SOURCE_RESPONSE:
        return mipc_threedm_pps_source_response_encode(&value->u.threedm_pps_source_response, buf, cap,
                                                       len_out);
    case MIPC_FIELD_THREEDM_GET_SUPPORTED_EVENTS:
        return mipc_threedm_get_supported_events_encode(&value->u.threedm_get_supported_events, buf, cap,
                                                        len_out);
    case MIPC_FIELD_THREEDM_SUPPORTED_EVENTS:
        return mipc_threedm_supported_events_encode(&value->u.threedm_supported_events, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_DEVICE_STATUS:
        return mipc_threedm_device_status_encode(&value->u.threedm_device_status, buf, cap, len_out);
    case MIPC_FIELD_THREEDM_DEVICE_STATUS_RESPONSE:
        return mipc_threedm_device_status_response_encode(&value->u.threedm_device_status_response, buf, cap,
                                                          len_out);
    case MIPC_FIELD_FILTER_RESET_FILTER:
        return mipc_filter_reset_filter_encode(&value->u.filter_reset_filter, buf, cap, len_out);
    case MIPC_FIELD_FILTER_SET_INITIAL_ATTITUDE:
        return mipc_filter_set_initial_attitude_encode(&value->u.filter_set_initial_attitude, buf, cap,
                                                       len_out);
    case MIPC_FIELD_FILTER_SET_INITIAL_HEADING:
        return mipc_filter_set_initial_heading_encode(&value->u.filter_set_initial_heading, buf, cap,
                                                      len_out);
    case MIPC_FIELD_FILTER_RUN_FILTER:
        return mipc_filter_run_filter_encode(&value->u.filter_run_filter, buf, cap, len_out);
    case MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE:
        return mipc_filter_vehicle_dynamics_mode_encode(&value->u.filter_vehicle_dynamics_mode, buf, cap,
                                                        len_out);
    case MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE_RESPONSE:
        return mipc_filter_vehicle_dynamics_mode_response_encode(
            &value->u.filter_vehicle_dynamics_mode_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM:
        return mipc_filter_sensor_to_vehicle_transform_encode(&value->u.filter_sensor_to_vehicle_transform,
                                                              buf, cap, len_out);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM_RESPONSE:
        return mipc_filter_sensor_to_vehicle_transform_response_encode(
            &value->u.filter_sensor_to_vehicle_transform_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET:
        return mipc_filter_sensor_to_vehicle_offset_encode(&value->u.filter_sensor_to_vehicle_offset, buf,
                                                           cap, len_out);
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET_RESPONSE:
        return mipc_filter_sensor_to_vehicle_offset_response_encode(
            &value->u.filter_sensor_to_vehicle_offset_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_ANTENNA_OFFSET:
        return mipc_filter_antenna_offset_encode(&value->u.filter_antenna_offset, buf, cap, len_out);
    case MIPC_FIELD_FILTER_ANTENNA_OFFSET_RESPONSE:
        return mipc_filter_antenna_offset_response_encode(&value->u.filter_antenna_offset_response, buf, cap,
                                                          len_out);
    case MIPC_FIELD_FILTER_ESTIMATION_CONTROL:
        return mipc_filter_estimation_control_encode(&value->u.filter_estimation_control, buf, cap, len_out);
    case MIPC_FIELD_FILTER_ESTIMATION_CONTROL_RESPONSE:
        return mipc_filter_estimation_control_response_encode(&value->u.filter_estimation_control_response,
                                                              buf, cap, len_out);
    case MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL:
        return mipc_filter_gnss_source_control_encode(&value->u.filter_gnss_source_control, buf, cap,
                                                      len_out);
    case MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL_RESPONSE:
        return mipc_filter_gnss_source_control_response_encode(&value->u.filter_gnss_source_control_response,
                                                               buf, cap, len_out);
    case MIPC_FIELD_FILTER_EXTERNAL_GNSS_UPDATE:
        return mipc_filter_external_gnss_update_encode(&value->u.filter_external_gnss_update, buf, cap,
                                                       len_out);
    case MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE:
        return mipc_filter_external_heading_update_encode(&value->u.filter_external_heading_update, buf, cap,
                                                          len_out);
    case MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL:
        return mipc_filter_heading_update_control_encode(&value->u.filter_heading_update_control, buf, cap,
                                                         len_out);
    case MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL_RESPONSE:
        return mipc_filter_heading_update_control_response_encode(
            &value->u.filter_heading_update_control_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_AUTO_INIT_CONTROL:
        return mipc_filter_auto_init_control_encode(&value->u.filter_auto_init_control, buf, cap, len_out);
    case MIPC_FIELD_FILTER_AUTO_INIT_CONTROL_RESPONSE:
        return mipc_filter_auto_init_control_response_encode(&value->u.filter_auto_init_control_response, buf,
                                                             cap, len_out);
    case MIPC_FIELD_FILTER_ACCEL_NOISE:
        return mipc_filter_accel_noise_encode(&value->u.filter_accel_noise, buf, cap, len_out);
    case MIPC_FIELD_FILTER_ACCEL_NOISE_RESPONSE:
        return mipc_filter_accel_noise_response_encode(&value->u.filter_accel_noise_response, buf, cap,
                                                       len_out);
    case MIPC_FIELD_FILTER_GYRO_NOISE:
        return mipc_filter_gyro_noise_encode(&value->u.filter_gyro_noise, buf, cap, len_out);
    case MIPC_FIELD_FILTER_GYRO_NOISE_RESPONSE:
        return mipc_filter_gyro_noise_response_encode(&value->u.filter_gyro_noise_response, buf, cap,
                                                      len_out);
    case MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL:
        return mipc_filter_accel_bias_model_encode(&value->u.filter_accel_bias_model, buf, cap, len_out);
    case MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL_RESPONSE:
        return mipc_filter_accel_bias_model_response_encode(&value->u.filter_accel_bias_model_response, buf,
                                                            cap, len_out);
    case MIPC_FIELD_FILTER_GYRO_BIAS_MODEL:
        return mipc_filter_gyro_bias_model_encode(&value->u.filter_gyro_bias_model, buf, cap, len_out);
    case MIPC_FIELD_FILTER_GYRO_BIAS_MODEL_RESPONSE:
        return mipc_filter_gyro_bias_model_response_encode(&value->u.filter_gyro_bias_model_response, buf,
                                                           cap, len_out);
    case MIPC_FIELD_FILTER_ZUPT_CONTROL:
        return mipc_filter_zupt_control_encode(&value->u.filter_zupt_control, buf, cap, len_out);
    case MIPC_FIELD_FILTER_ZUPT_CONTROL_RESPONSE:
        return mipc_filter_zupt_control_response_encode(&value->u.filter_zupt_control_response, buf, cap,
                                                        len_out);
    case MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME:
        return mipc_filter_external_heading_update_with_time_encode(
            &value->u.filter_external_heading_update_with_time, buf, cap, len_out);
    case MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL:
        return mipc_filter_zero_angular_rate_update_control_encode(
            &value->u.filter_zero_angular_rate_update_control, buf, cap, len_out);
    case MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL_RESPONSE:
        return mipc_filter_zero_angular_rate_update_control_response_encode(
            &value->u.filter_zero_angular_rate_update_control_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_TARE_ORIENTATION:
        return mipc_filter_tare_orientation_encode(&value->u.filter_tare_orientation, buf, cap, len_out);
    case MIPC_FIELD_FILTER_COMMANDED_ZUPT:
        return mipc_filter_commanded_zupt_encode(&value->u.filter_commanded_zupt, buf, cap, len_out);
    case MIPC_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE:
        return mipc_filter_commanded_zero_angular_rate_update_encode(
            &value->u.filter_commanded_zero_angular_rate_update, buf, cap, len_out);
    case MIPC_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION:
        return mipc_filter_mag_capture_auto_calibration_encode(&value->u.filter_mag_capture_auto_calibration,
                                                               buf, cap, len_out);
    case MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV:
        return mipc_filter_gravity_noise_std_dev_encode(&value->u.filter_gravity_noise_std_dev, buf, cap,
                                                        len_out);
    case MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV_RESPONSE:
        return mipc_filter_gravity_noise_std_dev_response_encode(
            &value->u.filter_gravity_noise_std_dev_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV:
        return mipc_filter_pressure_altitude_noise_std_dev_encode(
            &value->u.filter_pressure_altitude_noise_std_dev, buf, cap, len_out);
    case MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV_RESPONSE:
        return mipc_filter_pressure_altitude_noise_std_dev_response_encode(
            &value->u.filter_pressure_altitude_noise_std_dev_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE:
        return mipc_filter_hard_iron_offset_noise_encode(&value->u.filter_hard_iron_offset_noise, buf, cap,
                                                         len_out);
    case MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE_RESPONSE:
        return mipc_filter_hard_iron_offset_noise_response_encode(
            &value->u.filter_hard_iron_offset_noise_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE:
        return mipc_filter_soft_iron_matrix_noise_encode(&value->u.filter_soft_iron_matrix_noise, buf, cap,
                                                         len_out);
    case MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE_RESPONSE:
        return mipc_filter_soft_iron_matrix_noise_response_encode(
            &value->u.filter_soft_iron_matrix_noise_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV:
        return mipc_filter_mag_noise_std_dev_encode(&value->u.filter_mag_noise_std_dev, buf, cap, len_out);
    case MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV_RESPONSE:
        return mipc_filter_mag_noise_std_dev_response_encode(&value->u.filter_mag_noise_std_dev_response, buf,
                                                             cap, len_out);
    case MIPC_FIELD_FILTER_DECLINATION_SOURCE:
        return mipc_filter_declination_source_encode(&value->u.filter_declination_source, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DECLINATION_SOURCE_RESPONSE:
        return mipc_filter_declination_source_response_encode(&value->u.filter_declination_source_response,
                                                              buf, cap, len_out);
    case MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mipc_filter_gravity_magnitude_adaptive_measurement_encode(
            &value->u.filter_gravity_magnitude_adaptive_measurement, buf, cap, len_out);
    case MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mipc_filter_gravity_magnitude_adaptive_measurement_response_encode(
            &value->u.filter_gravity_magnitude_adaptive_measurement_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT:
        return mipc_filter_mag_magnitude_adaptive_measurement_encode(
            &value->u.filter_mag_magnitude_adaptive_measurement, buf, cap, len_out);
    case MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mipc_filter_mag_magnitude_adaptive_measurement_response_encode(
            &value->u.filter_mag_magnitude_adaptive_measurement_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT:
        return mipc_filter_mag_dip_angle_adaptive_measurement_encode(
            &value->u.filter_mag_dip_angle_adaptive_measurement, buf, cap, len_out);
    case MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT_RESPONSE:
        return mipc_filter_mag_dip_angle_adaptive_measurement_response_encode(
            &value->u.filter_mag_dip_angle_adaptive_measurement_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL:
        return mipc_filter_altitude_aiding_control_encode(&value->u.filter_altitude_aiding_control, buf, cap,
                                                          len_out);
    case MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL_RESPONSE:
        return mipc_filter_altitude_aiding_control_response_encode(
            &value->u.filter_altitude_aiding_control_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL:
        return mipc_filter_pitch_roll_aiding_control_encode(&value->u.filter_pitch_roll_aiding_control, buf,
                                                            cap, len_out);
    case MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL_RESPONSE:
        return mipc_filter_pitch_roll_aiding_control_response_encode(
            &value->u.filter_pitch_roll_aiding_control_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_INCLINATION_SOURCE:
        return mipc_filter_inclination_source_encode(&value->u.filter_inclination_source, buf, cap, len_out);
    case MIPC_FIELD_FILTER_INCLINATION_SOURCE_RESPONSE:
        return mipc_filter_inclination_source_response_encode(&value->u.filter_inclination_source_response,
                                                              buf, cap, len_out);
    case MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE:
        return mipc_filter_magnetic_field_magnitude_source_encode(
            &value->u.filter_magnetic_field_magnitude_source, buf, cap, len_out);
    case MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE_RESPONSE:
        return mipc_filter_magnetic_field_magnitude_source_response_encode(
            &value->u.filter_magnetic_field_magnitude_source_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL:
        return mipc_filter_aiding_measurement_control_encode(&value->u.filter_aiding_measurement_control, buf,
                                                             cap, len_out);
    case MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL_RESPONSE:
        return mipc_filter_aiding_measurement_control_response_encode(
            &value->u.filter_aiding_measurement_control_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION:
        return mipc_filter_initialization_configuration_encode(&value->u.filter_initialization_configuration,
                                                               buf, cap, len_out);
    case MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION_RESPONSE:
        return mipc_filter_initialization_configuration_response_encode(
            &value->u.filter_initialization_configuration_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL:
        return mipc_filter_adaptive_filter_control_encode(&value->u.filter_adaptive_filter_control, buf, cap,
                                                          len_out);
    case MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL_RESPONSE:
        return mipc_filter_adaptive_filter_control_response_encode(
            &value->u.filter_adaptive_filter_control_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET:
        return mipc_filter_multi_antenna_offset_encode(&value->u.filter_multi_antenna_offset, buf, cap,
                                                       len_out);
    case MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET_RESPONSE:
        return mipc_filter_multi_antenna_offset_response_encode(
            &value->u.filter_multi_antenna_offset_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION:
        return mipc_filter_relative_position_configuration_encode(
            &value->u.filter_relative_position_configuration, buf, cap, len_out);
    case MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION_RESPONSE:
        return mipc_filter_relative_position_configuration_response_encode(
            &value->u.filter_relative_position_configuration_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM:
        return mipc_filter_reference_point_lever_arm_encode(&value->u.filter_reference_point_lever_arm, buf,
                                                            cap, len_out);
    case MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM_RESPONSE:
        return mipc_filter_reference_point_lever_arm_response_encode(
            &value->u.filter_reference_point_lever_arm_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_SPEED_LEVER_ARM:
        return mipc_filter_speed_lever_arm_encode(&value->u.filter_speed_lever_arm, buf, cap, len_out);
    case MIPC_FIELD_FILTER_SPEED_LEVER_ARM_RESPONSE:
        return mipc_filter_speed_lever_arm_response_encode(&value->u.filter_speed_lever_arm_response, buf,
                                                           cap, len_out);
    case MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL:
        return mipc_filter_wheeled_vehicle_constraint_control_encode(
            &value->u.filter_wheeled_vehicle_constraint_control, buf, cap, len_out);
    case MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL_RESPONSE:
        return mipc_filter_wheeled_vehicle_constraint_control_response_encode(
            &value->u.filter_wheeled_vehicle_constraint_control_response, buf, cap, len_out);
    case MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL:
        return mipc_filter_gnss_antenna_calibration_control_encode(
            &value->u.filter_gnss_antenna_calibration_control, buf, cap, len_out);
    case MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL_RESPONSE:
        return mipc_filter_gnss_antenna_calibration_control_response_encode(
            &value->u.filter_gnss_antenna_calibration_control_response, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_INFO:
        return mipc_gnss_receiver_info_encode(&value->u.gnss_receiver_info, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_INFO_RESPONSE:
        return mipc_gnss_receiver_info_response_encode(&value->u.gnss_receiver_info_response, buf, cap,
                                                       len_out);
    case MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION:
        return mipc_gnss_signal_configuration_encode(&value->u.gnss_signal_configuration, buf, cap, len_out);
    case MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION_RESPONSE:
        return mipc_gnss_signal_configuration_response_encode(&value->u.gnss_signal_configuration_response,
                                                              buf, cap, len_out);
    case MIPC_FIELD_GNSS_SPARTN_CONFIGURATION:
        return mipc_gnss_spartn_configuration_encode(&value->u.gnss_spartn_configuration, buf, cap, len_out);
    case MIPC_FIELD_GNSS_SPARTN_CONFIGURATION_RESPONSE:
        return mipc_gnss_spartn_configuration_response_encode(&value->u.gnss_spartn_configuration_response,
                                                              buf, cap, len_out);
    case MIPC_FIELD_AIDING_FRAME_CONFIG:
        return mipc_aiding_frame_config_encode(&value->u.aiding_frame_config, buf, cap, len_out);
    case MIPC_FIELD_AIDING_FRAME_CONFIG_RESPONSE:
        return mipc_aiding_frame_config_response_encode(&value->u.aiding_frame_config_response, buf, cap,
                                                        len_out);
    case MIPC_FIELD_AIDING_ECHO_CONTROL:
        return mipc_aiding_echo_control_encode(&value->u.aiding_echo_control, buf, cap, len_out);
    case MIPC_FIELD_AIDING_ECHO_CONTROL_RESPONSE:
        return mipc_aiding_echo_control_response_encode(&value->u.aiding_echo_control_response, buf, cap,
                                                        len_out);
    case MIPC_FIELD_AIDING_ECEF_POSITION:
        return mipc_aiding_ecef_position_encode(&value->u.aiding_ecef_position, buf, cap, len_out);
    case MIPC_FIELD_AIDING_LLH_POSITION:
        return mipc_aiding_llh_position_encode(&value->u.aiding_llh_position, buf, cap, len_out);
    case MIPC_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID:
        return mipc_aiding_height_above_ellipsoid_encode(&value->u.aiding_height_above_ellipsoid, buf, cap,
                                                         len_out);
    case MIPC_FIELD_AIDING_ECEF_VELOCITY:
        return mipc_aiding_ecef_velocity_encode(&value->u.aiding_ecef_velocity, buf, cap, len_out);
    case MIPC_FIELD_AIDING_NED_VELOCITY:
        return mipc_aiding_ned_velocity_encode(&value->u.aiding_ned_velocity, buf, cap, len_out);
    case MIPC_FIELD_AIDING_BODY_FRAME_VELOCITY:
        return mipc_aiding_body_frame_velocity_encode(&value->u.aiding_body_frame_velocity, buf, cap,
                                                      len_out);
    case MIPC_FIELD_AIDING_TRUE_HEADING:
        return mipc_aiding_true_heading_encode(&value->u.aiding_true_heading, buf, cap, len_out);
    case MIPC_FIELD_AIDING_MAGNETIC_FIELD:
        return mipc_aiding_magnetic_field_encode(&value->u.aiding_magnetic_field, buf, cap, len_out);
    case MIPC_FIELD_AIDING_PRESSURE:
        return mipc_aiding_pressure_encode(&value->u.aiding_pressure, buf, cap, len_out);
    case MIPC_FIELD_SYSTEM_COMMUNICATION_MODE:
        return mipc_system_communication_mode_encode(&value->u.system_communication_mode, buf, cap, len_out);
    case MIPC_FIELD_SYSTEM_COMMUNICATION_MODE_RESPONSE:
        return mipc_system_communication_mode_response_encode(&value->u.system_communication_mode_response,
                                                              buf, cap, len_out);
    case MIPC_FIELD_SENSOR_SCALED_ACCEL:
        return mipc_sensor_scaled_accel_encode(&value->u.sensor_scaled_accel, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_SCALED_GYRO:
        return mipc_sensor_scaled_gyro_encode(&value->u.sensor_scaled_gyro, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_SCALED_MAG:
        return mipc_sensor_scaled_mag_encode(&value->u.sensor_scaled_mag, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_DELTA_THETA:
        return mipc_sensor_delta_theta_encode(&value->u.sensor_delta_theta, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_DELTA_VELOCITY:
        return mipc_sensor_delta_velocity_encode(&value->u.sensor_delta_velocity, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_CF_ORIENTATION_MATRIX:
        return mipc_sensor_cf_orientation_matrix_encode(&value->u.sensor_cf_orientation_matrix, buf, cap,
                                                        len_out);
    case MIPC_FIELD_SENSOR_CF_QUATERNION:
        return mipc_sensor_cf_quaternion_encode(&value->u.sensor_cf_quaternion, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_CF_EULER_ANGLES:
        return mipc_sensor_cf_euler_angles_encode(&value->u.sensor_cf_euler_angles, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_CF_STABILIZED_NORTH:
        return mipc_sensor_cf_stabilized_north_encode(&value->u.sensor_cf_stabilized_north, buf, cap,
                                                      len_out);
    case MIPC_FIELD_SENSOR_CF_STABILIZED_UP:
        return mipc_sensor_cf_stabilized_up_encode(&value->u.sensor_cf_stabilized_up, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_GPS_TIMESTAMP:
        return mipc_sensor_gps_timestamp_encode(&value->u.sensor_gps_timestamp, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_TEMPERATURE_STATISTICS:
        return mipc_sensor_temperature_statistics_encode(&value->u.sensor_temperature_statistics, buf, cap,
                                                         len_out);
    case MIPC_FIELD_SENSOR_SCALED_PRESSURE:
        return mipc_sensor_scaled_pressure_encode(&value->u.sensor_scaled_pressure, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_OVERRANGE_STATUS:
        return mipc_sensor_overrange_status_encode(&value->u.sensor_overrange_status, buf, cap, len_out);
    case MIPC_FIELD_SENSOR_ODOMETER_DATA:
        return mipc_sensor_odometer_data_encode(&value->u.sensor_odometer_data, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_LLH_POSITION:
        return mipc_gnss_data_llh_position_encode(&value->u.gnss_data_llh_position, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_ECEF_POSITION:
        return mipc_gnss_data_ecef_position_encode(&value->u.gnss_data_ecef_position, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_NED_VELOCITY:
        return mipc_gnss_data_ned_velocity_encode(&value->u.gnss_data_ned_velocity, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_ECEF_VELOCITY:
        return mipc_gnss_data_ecef_velocity_encode(&value->u.gnss_data_ecef_velocity, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_DOP:
        return mipc_gnss_data_dop_encode(&value->u.gnss_data_dop, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_UTC_TIME:
        return mipc_gnss_data_utc_time_encode(&value->u.gnss_data_utc_time, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_GPS_TIME:
        return mipc_gnss_data_gps_time_encode(&value->u.gnss_data_gps_time, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_CLOCK_INFO:
        return mipc_gnss_data_clock_info_encode(&value->u.gnss_data_clock_info, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_FIX_INFO:
        return mipc_gnss_data_fix_info_encode(&value->u.gnss_data_fix_info, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_SV_INFO:
        return mipc_gnss_data_sv_info_encode(&value->u.gnss_data_sv_info, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_HARDWARE_STATUS:
        return mipc_gnss_data_hardware_status_encode(&value->u.gnss_data_hardware_status, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_DGNSS_INFO:
        return mipc_gnss_data_dgnss_info_encode(&value->u.gnss_data_dgnss_info, buf, cap, len_out);
    case MIPC_FIELD_GNSS_DATA_DGNSS_CHANNEL_STATUS:
        return mipc_gnss_data_dgnss_channel_status_encode(&value->u.gnss_data_dgnss_channel_status, buf, cap,
                                                          len_out);
    case MIPC_FIELD_FILTER_DATA_LLH_POSITION:
        return mipc_filter_data_llh_position_encode(&value->u.filter_data_llh_position, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_NED_VELOCITY:
        return mipc_filter_data_ned_velocity_encode(&value->u.filter_data_ned_velocity, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ATTITUDE_QUATERNION:
        return mipc_filter_data_attitude_quaternion_encode(&value->u.filter_data_attitude_quaternion, buf,
                                                           cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ATTITUDE_DCM:
        return mipc_filter_data_attitude_dcm_encode(&value->u.filter_data_attitude_dcm, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_EULER_ANGLES:
        return mipc_filter_data_euler_angles_encode(&value->u.filter_data_euler_angles, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_GYRO_BIAS:
        return mipc_filter_data_gyro_bias_encode(&value->u.filter_data_gyro_bias, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ACCEL_BIAS:
        return mipc_filter_data_accel_bias_encode(&value->u.filter_data_accel_bias, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_LLH_POSITION_UNCERTAINTY:
        return mipc_filter_data_llh_position_uncertainty_encode(
            &value->u.filter_data_llh_position_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_NED_VELOCITY_UNCERTAINTY:
        return mipc_filter_data_ned_velocity_uncertainty_encode(
            &value->u.filter_data_ned_velocity_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_EULER_ANGLES_UNCERTAINTY:
        return mipc_filter_data_euler_angles_uncertainty_encode(
            &value->u.filter_data_euler_angles_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_GYRO_BIAS_UNCERTAINTY:
        return mipc_filter_data_gyro_bias_uncertainty_encode(&value->u.filter_data_gyro_bias_uncertainty, buf,
                                                             cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY:
        return mipc_filter_data_accel_bias_uncertainty_encode(&value->u.filter_data_accel_bias_uncertainty,
                                                              buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_LINEAR_ACCEL:
        return mipc_filter_data_linear_accel_encode(&value->u.filter_data_linear_accel, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_COMP_ANGULAR_RATE:
        return mipc_filter_data_comp_angular_rate_encode(&value->u.filter_data_comp_angular_rate, buf, cap,
                                                         len_out);
    case MIPC_FIELD_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE:
        return mipc_filter_data_wgs84_gravity_magnitude_encode(&value->u.filter_data_wgs84_gravity_magnitude,
                                                               buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_FILTER_STATUS_GX5_45:
        return mipc_filter_data_filter_status_gx5_45_encode(&value->u.filter_data_filter_status_gx5_45, buf,
                                                            cap, len_out);
    case MIPC_FIELD_FILTER_DATA_FILTER_STATUS_CV7_INS:
        return mipc_filter_data_filter_status_cv7_ins_encode(&value->u.filter_data_filter_status_cv7_ins, buf,
                                                             cap, len_out);
    case MIPC_FIELD_FILTER_DATA_GPS_TIMESTAMP:
        return mipc_filter_data_gps_timestamp_encode(&value->u.filter_data_gps_timestamp, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY:
        return mipc_filter_data_quaternion_attitude_uncertainty_encode(
            &value->u.filter_data_quaternion_attitude_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_GRAVITY_VECTOR:
        return mipc_filter_data_gravity_vector_encode(&value->u.filter_data_gravity_vector, buf, cap,
                                                      len_out);
    case MIPC_FIELD_FILTER_DATA_HEADING_UPDATE_STATE:
        return mipc_filter_data_heading_update_state_encode(&value->u.filter_data_heading_update_state, buf,
                                                            cap, len_out);
    case MIPC_FIELD_FILTER_DATA_MAGNETIC_MODEL:
        return mipc_filter_data_magnetic_model_encode(&value->u.filter_data_magnetic_model, buf, cap,
                                                      len_out);
    case MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR:
        return mipc_filter_data_gyro_scale_factor_encode(&value->u.filter_data_gyro_scale_factor, buf, cap,
                                                         len_out);
    case MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR:
        return mipc_filter_data_accel_scale_factor_encode(&value->u.filter_data_accel_scale_factor, buf, cap,
                                                          len_out);
    case MIPC_FIELD_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY:
        return mipc_filter_data_gyro_scale_factor_uncertainty_encode(
            &value->u.filter_data_gyro_scale_factor_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY:
        return mipc_filter_data_accel_scale_factor_uncertainty_encode(
            &value->u.filter_data_accel_scale_factor_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_COMPENSATED_ACCEL:
        return mipc_filter_data_compensated_accel_encode(&value->u.filter_data_compensated_accel, buf, cap,
                                                         len_out);
    case MIPC_FIELD_FILTER_DATA_STANDARD_ATMOSPHERE:
        return mipc_filter_data_standard_atmosphere_encode(&value->u.filter_data_standard_atmosphere, buf,
                                                           cap, len_out);
    case MIPC_FIELD_FILTER_DATA_PRESSURE_ALTITUDE:
        return mipc_filter_data_pressure_altitude_encode(&value->u.filter_data_pressure_altitude, buf, cap,
                                                         len_out);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET:
        return mipc_filter_data_mag_auto_hard_iron_offset_encode(
            &value->u.filter_data_mag_auto_hard_iron_offset, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX:
        return mipc_filter_data_mag_auto_soft_iron_matrix_encode(
            &value->u.filter_data_mag_auto_soft_iron_matrix, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY:
        return mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_encode(
            &value->u.filter_data_mag_auto_hard_iron_offset_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY:
        return mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_encode(
            &value->u.filter_data_mag_auto_soft_iron_matrix_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION:
        return mipc_filter_data_gnss_antenna_offset_correction_encode(
            &value->u.filter_data_gnss_antenna_offset_correction, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mipc_filter_data_gnss_antenna_offset_correction_uncertainty_encode(
            &value->u.filter_data_gnss_antenna_offset_correction_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION:
        return mipc_filter_data_multi_antenna_offset_correction_encode(
            &value->u.filter_data_multi_antenna_offset_correction, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY:
        return mipc_filter_data_multi_antenna_offset_correction_uncertainty_encode(
            &value->u.filter_data_multi_antenna_offset_correction_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ECEF_POSITION_UNCERTAINTY:
        return mipc_filter_data_ecef_position_uncertainty_encode(
            &value->u.filter_data_ecef_position_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY:
        return mipc_filter_data_ecef_velocity_uncertainty_encode(
            &value->u.filter_data_ecef_velocity_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ECEF_POSITION:
        return mipc_filter_data_ecef_position_encode(&value->u.filter_data_ecef_position, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ECEF_VELOCITY:
        return mipc_filter_data_ecef_velocity_encode(&value->u.filter_data_ecef_velocity, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_NED_RELATIVE_POSITION:
        return mipc_filter_data_ned_relative_position_encode(&value->u.filter_data_ned_relative_position, buf,
                                                             cap, len_out);
    case MIPC_FIELD_FILTER_DATA_GNSS_POSITION_AIDING_STATUS:
        return mipc_filter_data_gnss_position_aiding_status_encode(
            &value->u.filter_data_gnss_position_aiding_status, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY:
        return mipc_filter_data_aiding_measurement_summary_encode(
            &value->u.filter_data_aiding_measurement_summary, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR:
        return mipc_filter_data_odometer_scale_factor_error_encode(
            &value->u.filter_data_odometer_scale_factor_error, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY:
        return mipc_filter_data_odometer_scale_factor_error_uncertainty_encode(
            &value->u.filter_data_odometer_scale_factor_error_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS:
        return mipc_filter_data_gnss_dual_antenna_status_encode(
            &value->u.filter_data_gnss_dual_antenna_status, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR:
        return mipc_filter_data_aiding_frame_config_error_encode(
            &value->u.filter_data_aiding_frame_config_error, buf, cap, len_out);
    case MIPC_FIELD_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY:
        return mipc_filter_data_aiding_frame_config_error_uncertainty_encode(
            &value->u.filter_data_aiding_frame_config_error_uncertainty, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_LLH_POSITION:
        return mipc_gnss_receiver_1_llh_position_encode(&value->u.gnss_receiver_1_llh_position, buf, cap,
                                                        len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_ECEF_POSITION:
        return mipc_gnss_receiver_1_ecef_position_encode(&value->u.gnss_receiver_1_ecef_position, buf, cap,
                                                         len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_NED_VELOCITY:
        return mipc_gnss_receiver_1_ned_velocity_encode(&value->u.gnss_receiver_1_ned_velocity, buf, cap,
                                                        len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_ECEF_VELOCITY:
        return mipc_gnss_receiver_1_ecef_velocity_encode(&value->u.gnss_receiver_1_ecef_velocity, buf, cap,
                                                         len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_DOP:
        return mipc_gnss_receiver_1_dop_encode(&value->u.gnss_receiver_1_dop, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_UTC_TIME:
        return mipc_gnss_receiver_1_utc_time_encode(&value->u.gnss_receiver_1_utc_time, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_TIME:
        return mipc_gnss_receiver_1_gps_time_encode(&value->u.gnss_receiver_1_gps_time, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_FIX_INFO:
        return mipc_gnss_receiver_1_fix_info_encode(&value->u.gnss_receiver_1_fix_info, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_HARDWARE_STATUS:
        return mipc_gnss_receiver_1_hardware_status_encode(&value->u.gnss_receiver_1_hardware_status, buf,
                                                           cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_CLOCK_INFO_2:
        return mipc_gnss_receiver_1_clock_info_2_encode(&value->u.gnss_receiver_1_clock_info_2, buf, cap,
                                                        len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_LEAP_SECONDS:
        return mipc_gnss_receiver_1_gps_leap_seconds_encode(&value->u.gnss_receiver_1_gps_leap_seconds, buf,
                                                            cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_SBAS_INFO:
        return mipc_gnss_receiver_1_sbas_info_encode(&value->u.gnss_receiver_1_sbas_info, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_SATELLITE_STATUS:
        return mipc_gnss_receiver_1_satellite_status_encode(&value->u.gnss_receiver_1_satellite_status, buf,
                                                            cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_RAW:
        return mipc_gnss_receiver_1_raw_encode(&value->u.gnss_receiver_1_raw, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_GPS_EPHEMERIS:
        return mipc_gnss_receiver_1_gps_ephemeris_encode(&value->u.gnss_receiver_1_gps_ephemeris, buf, cap,
                                                         len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_GLONASS_EPHEMERIS:
        return mipc_gnss_receiver_1_glonass_ephemeris_encode(&value->u.gnss_receiver_1_glonass_ephemeris, buf,
                                                             cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_GALILEO_EPHEMERIS:
        return mipc_gnss_receiver_1_galileo_ephemeris_encode(&value->u.gnss_receiver_1_galileo_ephemeris, buf,
                                                             cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_1_BEIDOU_EPHEMERIS:
        return mipc_gnss_receiver_1_beidou_ephemeris_encode(&value->u.gnss_receiver_1_beidou_ephemeris, buf,
                                                            cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_LLH_POSITION:
        return mipc_gnss_receiver_2_llh_position_encode(&value->u.gnss_receiver_2_llh_position, buf, cap,
                                                        len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_ECEF_POSITION:
        return mipc_gnss_receiver_2_ecef_position_encode(&value->u.gnss_receiver_2_ecef_position, buf, cap,
                                                         len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_NED_VELOCITY:
        return mipc_gnss_receiver_2_ned_velocity_encode(&value->u.gnss_receiver_2_ned_velocity, buf, cap,
                                                        len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_ECEF_VELOCITY:
        return mipc_gnss_receiver_2_ecef_velocity_encode(&value->u.gnss_receiver_2_ecef_velocity, buf, cap,
                                                         len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_DOP:
        return mipc_gnss_receiver_2_dop_encode(&value->u.gnss_receiver_2_dop, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_UTC_TIME:
        return mipc_gnss_receiver_2_utc_time_encode(&value->u.gnss_receiver_2_utc_time, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_TIME:
        return mipc_gnss_receiver_2_gps_time_encode(&value->u.gnss_receiver_2_gps_time, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_FIX_INFO:
        return mipc_gnss_receiver_2_fix_info_encode(&value->u.gnss_receiver_2_fix_info, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_HARDWARE_STATUS:
        return mipc_gnss_receiver_2_hardware_status_encode(&value->u.gnss_receiver_2_hardware_status, buf,
                                                           cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_CLOCK_INFO_2:
        return mipc_gnss_receiver_2_clock_info_2_encode(&value->u.gnss_receiver_2_clock_info_2, buf, cap,
                                                        len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_LEAP_SECONDS:
        return mipc_gnss_receiver_2_gps_leap_seconds_encode(&value->u.gnss_receiver_2_gps_leap_seconds, buf,
                                                            cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_SBAS_INFO:
        return mipc_gnss_receiver_2_sbas_info_encode(&value->u.gnss_receiver_2_sbas_info, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_SATELLITE_STATUS:
        return mipc_gnss_receiver_2_satellite_status_encode(&value->u.gnss_receiver_2_satellite_status, buf,
                                                            cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_RAW:
        return mipc_gnss_receiver_2_raw_encode(&value->u.gnss_receiver_2_raw, buf, cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_GPS_EPHEMERIS:
        return mipc_gnss_receiver_2_gps_ephemeris_encode(&value->u.gnss_receiver_2_gps_ephemeris, buf, cap,
                                                         len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_GLONASS_EPHEMERIS:
        return mipc_gnss_receiver_2_glonass_ephemeris_encode(&value->u.gnss_receiver_2_glonass_ephemeris, buf,
                                                             cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_GALILEO_EPHEMERIS:
        return mipc_gnss_receiver_2_galileo_ephemeris_encode(&value->u.gnss_receiver_2_galileo_ephemeris, buf,
                                                             cap, len_out);
    case MIPC_FIELD_GNSS_RECEIVER_2_BEIDOU_EPHEMERIS:
        return mipc_gnss_receiver_2_beidou_ephemeris_encode(&value->u.gnss_receiver_2_beidou_ephemeris, buf,
                                                            cap, len_out);
    case MIPC_FIELD_GNSS_CORRECTIONS_BASE_STATION_INFO:
        return mipc_gnss_corrections_base_station_info_encode(&value->u.gnss_corrections_base_station_info,
                                                              buf, cap, len_out);
    case MIPC_FIELD_GNSS_CORRECTIONS_RTK_CORRECTIONS_STATUS:
        return mipc_gnss_corrections_rtk_corrections_status_encode(
            &value->u.gnss_corrections_rtk_corrections_status, buf, cap, len_out);
    case MIPC_FIELD_GNSS_EXTERNAL_LLH_POSITION:
        return mipc_gnss_external_llh_position_encode(&value->u.gnss_external_llh_position, buf, cap,
                                                      len_out);
    case MIPC_FIELD_GNSS_EXTERNAL_NED_VELOCITY:
        return mipc_gnss_external_ned_velocity_encode(&value->u.gnss_external_ned_velocity, buf, cap,
                                                      len_out);
    case MIPC_FIELD_GNSS_EXTERNAL_UTC_TIME:
        return mipc_gnss_external_utc_time_encode(&value->u.gnss_external_utc_time, buf, cap, len_out);
    case MIPC_FIELD_GNSS_EXTERNAL_FIX_INFO:
        return mipc_gnss_external_fix_info_encode(&value->u.gnss_external_fix_info, buf, cap, len_out);
    case MIPC_FIELD_GNSS_EXTERNAL_SATELLITE_STATUS:
        return mipc_gnss_external_satellite_status_encode(&value->u.gnss_external_satellite_status, buf, cap,
                                                          len_out);
    case MIPC_FIELD_SYSTEM_DATA_BUILT_IN_TEST:
        return mipc_system_data_built_in_test_encode(&value->u.system_data_built_in_test, buf, cap, len_out);
    case MIPC_FIELD_SYSTEM_DATA_TIME_SYNC_STATUS:
        return mipc_system_data_time_sync_status_encode(&value->u.system_data_time_sync_status, buf, cap,
                                                        len_out);
    case MIPC_FIELD_SYSTEM_DATA_GPIO_STATE:
        return mipc_system_data_gpio_state_encode(&value->u.system_data_gpio_state, buf, cap, len_out);
    case MIPC_FIELD_SHARED_EVENT_SOURCE:
        return mipc_shared_event_source_encode(&value->u.shared_event_source, buf, cap, len_out);
    case MIPC_FIELD_SHARED_GPS_TIMESTAMP:
        return mipc_shared_gps_timestamp_encode(&value->u.shared_gps_timestamp, buf, cap, len_out);
    case MIPC_FIELD_SHARED_DELTA_TIME:
        return mipc_shared_delta_time_encode(&value->u.shared_delta_time, buf, cap, len_out);
    case MIPC_FIELD_SHARED_REFERENCE_TIMESTAMP:
        return mipc_shared_reference_timestamp_encode(&value->u.shared_reference_timestamp, buf, cap,
                                                      len_out);
    case MIPC_FIELD_SHARED_REFERENCE_TIME_DELTA:
        return mipc_shared_reference_time_delta_encode(&value->u.shared_reference_time_delta, buf, cap,
                                                       len_out);
    case MIPC_FIELD_SHARED_EXTERNAL_TIMESTAMP:
        return mipc_shared_external_timestamp_encode(&value->u.shared_external_timestamp, buf, cap, len_out);
    case MIPC_FIELD_SHARED_EXTERNAL_TIME_DELTA:
        return mipc_shared_external_time_delta_encode(&value->u.shared_external_time_delta, buf, cap,
                                                      len_out);
    case MIPC_FIELD_NONE:
    case MIPC_FIELD_COUNT:
    default:
        return MIPC_ERR_INVALID;
    }
}
