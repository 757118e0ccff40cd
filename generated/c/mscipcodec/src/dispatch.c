/* Dispatch tables. Generated from the spec: do not edit. */
#include "mscipcodec/dispatch.h"
#include "layouts_internal.h"

#include <assert.h>
#include <string.h>

const char *mscipc_device_id(mscipc_device_t device) {
    switch (device) {
    case MSCIPC_DEVICE_MS_IMU3020:
        return "ms_imu3020";
    case MSCIPC_DEVICE_ANY:
    default:
        return NULL;
    }
}

bool mscipc_device_from_id(const char *id, mscipc_device_t *out) {
    assert(id != NULL);
    assert(out != NULL);
    if (strcmp(id, "ms_imu3020") == 0) {
        *out = MSCIPC_DEVICE_MS_IMU3020;
        return true;
    }
    (void)id;
    (void)out;
    return false;
}

const char *mscipc_device_title(mscipc_device_t device) {
    switch (device) {
    case MSCIPC_DEVICE_MS_IMU3020:
        return "MS-IMU3020";
    case MSCIPC_DEVICE_ANY:
    default:
        return NULL;
    }
}

const char *mscipc_device_manual(mscipc_device_t device) {
    switch (device) {
    case MSCIPC_DEVICE_MS_IMU3020:
        return "ms-cip-doc00419-revM.txt";
    case MSCIPC_DEVICE_ANY:
    default:
        return NULL;
    }
}

/* The capabilities tables: (set << 8) | descriptor, ascending (a leading 0 keeps an empty one legal). */
static const uint16_t k_ms_imu3020_commands[] = {0,      0x0102, 0x0103, 0x0104, 0x0105, 0x0106, 0x0107,
                                                 0x0108, 0x0109, 0x0201, 0x0203, 0x0204, 0x0205, 0x0206,
                                                 0x0207, 0x0208, 0x0209, 0x020A, 0x020B, 0x020C, 0x020D};
static const uint16_t k_ms_imu3020_data[] = {0,      0xA281, 0xA282, 0xA283, 0xA284,
                                             0xA285, 0xA286, 0xA287, 0xA288, 0xA289};

static const uint16_t *device_table(mscipc_device_t device, bool data, size_t *count) {
    switch (device) {
    case MSCIPC_DEVICE_MS_IMU3020:
        *count = data ? 9u : 20u;
        return (data ? k_ms_imu3020_data : k_ms_imu3020_commands) + 1;
    case MSCIPC_DEVICE_ANY:
    default:
        *count = 0;
        return NULL;
    }
}

const uint16_t *mscipc_device_commands(mscipc_device_t device, size_t *count) {
    assert(count != NULL);
    return device_table(device, false, count);
}

const uint16_t *mscipc_device_data(mscipc_device_t device, size_t *count) {
    assert(count != NULL);
    return device_table(device, true, count);
}

/* The baud rates of each device's main port (the IR's `link`), ascending. */
static const uint32_t k_ms_imu3020_baud_rates[] = {9600u, 19200u, 115200u, 230400u, 460800u, 921600u};

const uint32_t *mscipc_device_baud_rates(mscipc_device_t device, size_t *count) {
    assert(count != NULL);
    switch (device) {
    case MSCIPC_DEVICE_MS_IMU3020:
        *count = 6u;
        return k_ms_imu3020_baud_rates;
    case MSCIPC_DEVICE_ANY:
    default:
        *count = 0;
        return NULL;
    }
}

uint32_t mscipc_device_default_baud(mscipc_device_t device) {
    switch (device) {
    case MSCIPC_DEVICE_MS_IMU3020:
        return 0u;
    case MSCIPC_DEVICE_ANY:
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

bool mscipc_device_supports(mscipc_device_t device, uint8_t set, uint8_t descriptor) {
    size_t n;
    uint16_t key = (uint16_t)(((unsigned)set << 8) | descriptor);
    const uint16_t *t = device_table(device, false, &n);
    if (t != NULL && table_has(t, n, key)) {
        return true;
    }
    t = device_table(device, true, &n);
    return t != NULL && table_has(t, n, key);
}

mscipc_set_kind_t mscipc_set_kind(uint8_t set) {
    if (set >= 0x01 && set <= 0x7F) {
        return MSCIPC_SET_KIND_COMMAND;
    }
    if (set >= 0x80 && 1) {
        return MSCIPC_SET_KIND_DATA;
    }
    (void)set;
    return MSCIPC_SET_KIND_NONE;
}

static const mscipc_layout_info_t k_layouts[MSCIPC_FIELD_COUNT] = {
    {MSCIPC_FIELD_NONE, NULL, NULL, MSCIPC_DEVICE_ANY, 0},
    {MSCIPC_FIELD_ACK, "ack", NULL, MSCIPC_DEVICE_ANY, 0x80},
    {MSCIPC_FIELD_BASE_PING, "ping", NULL, MSCIPC_DEVICE_ANY, 0x02},
    {MSCIPC_FIELD_BASE_GET_DEVICE_MESSAGES, "get_device_messages", NULL, MSCIPC_DEVICE_ANY, 0x03},
    {MSCIPC_FIELD_BASE_DEVICE_MESSAGES, "device_messages", NULL, MSCIPC_DEVICE_ANY, 0x83},
    {MSCIPC_FIELD_BASE_DEVICE_RESET, "device_reset", NULL, MSCIPC_DEVICE_ANY, 0x04},
    {MSCIPC_FIELD_BASE_GET_DEVICE_MODEL, "get_device_model", NULL, MSCIPC_DEVICE_ANY, 0x05},
    {MSCIPC_FIELD_BASE_DEVICE_MODEL, "device_model", NULL, MSCIPC_DEVICE_ANY, 0x85},
    {MSCIPC_FIELD_BASE_GET_DEVICE_SN, "get_device_sn", NULL, MSCIPC_DEVICE_ANY, 0x06},
    {MSCIPC_FIELD_BASE_DEVICE_SN, "device_sn", NULL, MSCIPC_DEVICE_ANY, 0x86},
    {MSCIPC_FIELD_BASE_GET_DEVICE_FW, "get_device_fw", NULL, MSCIPC_DEVICE_ANY, 0x07},
    {MSCIPC_FIELD_BASE_DEVICE_FW, "device_fw", NULL, MSCIPC_DEVICE_ANY, 0x87},
    {MSCIPC_FIELD_BASE_GET_DEVICE_CAL, "get_device_cal", NULL, MSCIPC_DEVICE_ANY, 0x08},
    {MSCIPC_FIELD_BASE_DEVICE_CAL, "device_cal", NULL, MSCIPC_DEVICE_ANY, 0x88},
    {MSCIPC_FIELD_BASE_CORRELATE_GPS_TIME, "correlate_gps_time", NULL, MSCIPC_DEVICE_ANY, 0x09},
    {MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE, "uart_baud_rate", NULL, MSCIPC_DEVICE_ANY, 0x01},
    {MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE_RESPONSE, "uart_baud_rate_response", NULL, MSCIPC_DEVICE_ANY,
     0x81},
    {MSCIPC_FIELD_IMU_CONFIG_FILTER, "filter", NULL, MSCIPC_DEVICE_ANY, 0x03},
    {MSCIPC_FIELD_IMU_CONFIG_FILTER_RESPONSE, "filter_response", NULL, MSCIPC_DEVICE_ANY, 0x83},
    {MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE, "sample_rate", NULL, MSCIPC_DEVICE_ANY, 0x04},
    {MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE_RESPONSE, "sample_rate_response", NULL, MSCIPC_DEVICE_ANY, 0x84},
    {MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS, "select_sensors", NULL, MSCIPC_DEVICE_ANY, 0x05},
    {MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_RESPONSE, "select_sensors_response", NULL, MSCIPC_DEVICE_ANY,
     0x85},
    {MSCIPC_FIELD_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE, "get_internal_sample_rate", NULL, MSCIPC_DEVICE_ANY,
     0x06},
    {MSCIPC_FIELD_IMU_CONFIG_INTERNAL_SAMPLE_RATE, "internal_sample_rate", NULL, MSCIPC_DEVICE_ANY, 0x86},
    {MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE, "accel_range", NULL, MSCIPC_DEVICE_ANY, 0x07},
    {MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE_RESPONSE, "accel_range_response", NULL, MSCIPC_DEVICE_ANY, 0x87},
    {MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE, "gyro_range", NULL, MSCIPC_DEVICE_ANY, 0x08},
    {MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE_RESPONSE, "gyro_range_response", NULL, MSCIPC_DEVICE_ANY, 0x88},
    {MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL, "config_all", NULL, MSCIPC_DEVICE_ANY, 0x09},
    {MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF, "data_on_off", NULL, MSCIPC_DEVICE_ANY, 0x0A},
    {MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF_RESPONSE, "data_on_off_response", NULL, MSCIPC_DEVICE_ANY, 0x8A},
    {MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF, "xtrig_on_off", NULL, MSCIPC_DEVICE_ANY, 0x0B},
    {MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF_RESPONSE, "xtrig_on_off_response", NULL, MSCIPC_DEVICE_ANY, 0x8B},
    {MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B, "select_sensors_rev_b", NULL, MSCIPC_DEVICE_ANY, 0x0C},
    {MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B_RESPONSE, "select_sensors_rev_b_response", NULL,
     MSCIPC_DEVICE_ANY, 0x8C},
    {MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE, "aux_accel_range", NULL, MSCIPC_DEVICE_ANY, 0x0D},
    {MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE_RESPONSE, "aux_accel_range_response", NULL, MSCIPC_DEVICE_ANY,
     0x8D},
    {MSCIPC_FIELD_IMU_DATA_SCALED_ACCEL, "scaled_accel", NULL, MSCIPC_DEVICE_ANY, 0x81},
    {MSCIPC_FIELD_IMU_DATA_SCALED_GYRO, "scaled_gyro", NULL, MSCIPC_DEVICE_ANY, 0x82},
    {MSCIPC_FIELD_IMU_DATA_SCALED_MAG, "scaled_mag", NULL, MSCIPC_DEVICE_ANY, 0x83},
    {MSCIPC_FIELD_IMU_DATA_DELTA_THETA, "delta_theta", NULL, MSCIPC_DEVICE_ANY, 0x84},
    {MSCIPC_FIELD_IMU_DATA_DELTA_VELOCITY, "delta_velocity", NULL, MSCIPC_DEVICE_ANY, 0x85},
    {MSCIPC_FIELD_IMU_DATA_SCALED_PRESSURE, "scaled_pressure", NULL, MSCIPC_DEVICE_ANY, 0x86},
    {MSCIPC_FIELD_IMU_DATA_SCALED_TEMPERATURE, "scaled_temperature", NULL, MSCIPC_DEVICE_ANY, 0x87},
    {MSCIPC_FIELD_IMU_DATA_GPS_CORRELATED_TIME, "gps_correlated_time", NULL, MSCIPC_DEVICE_ANY, 0x88},
    {MSCIPC_FIELD_IMU_DATA_SCALED_AUX_ACCEL, "scaled_aux_accel", NULL, MSCIPC_DEVICE_ANY, 0x89},
};

static const mscipc_field_info_t k_fields[] = {
    {"ack", 0x80, MSCIPC_FIELD_ACK, 1},
    {"ping", 0x02, MSCIPC_FIELD_BASE_PING, 1},
    {"get_device_messages", 0x03, MSCIPC_FIELD_BASE_GET_DEVICE_MESSAGES, 1},
    {"device_messages", 0x83, MSCIPC_FIELD_BASE_DEVICE_MESSAGES, 1},
    {"device_reset", 0x04, MSCIPC_FIELD_BASE_DEVICE_RESET, 1},
    {"get_device_model", 0x05, MSCIPC_FIELD_BASE_GET_DEVICE_MODEL, 1},
    {"device_model", 0x85, MSCIPC_FIELD_BASE_DEVICE_MODEL, 1},
    {"get_device_sn", 0x06, MSCIPC_FIELD_BASE_GET_DEVICE_SN, 1},
    {"device_sn", 0x86, MSCIPC_FIELD_BASE_DEVICE_SN, 1},
    {"get_device_fw", 0x07, MSCIPC_FIELD_BASE_GET_DEVICE_FW, 1},
    {"device_fw", 0x87, MSCIPC_FIELD_BASE_DEVICE_FW, 1},
    {"get_device_cal", 0x08, MSCIPC_FIELD_BASE_GET_DEVICE_CAL, 1},
    {"device_cal", 0x88, MSCIPC_FIELD_BASE_DEVICE_CAL, 1},
    {"correlate_gps_time", 0x09, MSCIPC_FIELD_BASE_CORRELATE_GPS_TIME, 1},
    {"uart_baud_rate", 0x01, MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE, 1},
    {"uart_baud_rate_response", 0x81, MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE_RESPONSE, 1},
    {"filter", 0x03, MSCIPC_FIELD_IMU_CONFIG_FILTER, 1},
    {"filter_response", 0x83, MSCIPC_FIELD_IMU_CONFIG_FILTER_RESPONSE, 1},
    {"sample_rate", 0x04, MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE, 1},
    {"sample_rate_response", 0x84, MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE_RESPONSE, 1},
    {"select_sensors", 0x05, MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS, 1},
    {"select_sensors_response", 0x85, MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_RESPONSE, 1},
    {"get_internal_sample_rate", 0x06, MSCIPC_FIELD_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE, 1},
    {"internal_sample_rate", 0x86, MSCIPC_FIELD_IMU_CONFIG_INTERNAL_SAMPLE_RATE, 1},
    {"accel_range", 0x07, MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE, 1},
    {"accel_range_response", 0x87, MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE_RESPONSE, 1},
    {"gyro_range", 0x08, MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE, 1},
    {"gyro_range_response", 0x88, MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE_RESPONSE, 1},
    {"config_all", 0x09, MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL, 1},
    {"data_on_off", 0x0A, MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF, 1},
    {"data_on_off_response", 0x8A, MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF_RESPONSE, 1},
    {"xtrig_on_off", 0x0B, MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF, 1},
    {"xtrig_on_off_response", 0x8B, MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF_RESPONSE, 1},
    {"select_sensors_rev_b", 0x0C, MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B, 1},
    {"select_sensors_rev_b_response", 0x8C, MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B_RESPONSE, 1},
    {"aux_accel_range", 0x0D, MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE, 1},
    {"aux_accel_range_response", 0x8D, MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE_RESPONSE, 1},
    {"scaled_accel", 0x81, MSCIPC_FIELD_IMU_DATA_SCALED_ACCEL, 1},
    {"scaled_gyro", 0x82, MSCIPC_FIELD_IMU_DATA_SCALED_GYRO, 1},
    {"scaled_mag", 0x83, MSCIPC_FIELD_IMU_DATA_SCALED_MAG, 1},
    {"delta_theta", 0x84, MSCIPC_FIELD_IMU_DATA_DELTA_THETA, 1},
    {"delta_velocity", 0x85, MSCIPC_FIELD_IMU_DATA_DELTA_VELOCITY, 1},
    {"scaled_pressure", 0x86, MSCIPC_FIELD_IMU_DATA_SCALED_PRESSURE, 1},
    {"scaled_temperature", 0x87, MSCIPC_FIELD_IMU_DATA_SCALED_TEMPERATURE, 1},
    {"gps_correlated_time", 0x88, MSCIPC_FIELD_IMU_DATA_GPS_CORRELATED_TIME, 1},
    {"scaled_aux_accel", 0x89, MSCIPC_FIELD_IMU_DATA_SCALED_AUX_ACCEL, 1},
};

const mscipc_layout_info_t *mscipc_layout_info(mscipc_field_id_t id) {
    if ((size_t)id >= MSCIPC_FIELD_COUNT) {
        return NULL;
    }
    return &k_layouts[id];
}

/* Fields of each set: descriptor -> 1 + index into k_fields (0: not defined). Dispatch by
 * (set, descriptor) is two table lookups. A set's table also holds the reserved fields of its
 * kind and, in a data set, the shared data fields that it does not define itself: the answer
 * find_field's search would reach (the generator resolves the search once). */
static const uint16_t k_set_base[256] = {
    [0x02] = 2,  /* ping */
    [0x03] = 3,  /* get_device_messages */
    [0x04] = 5,  /* device_reset */
    [0x05] = 6,  /* get_device_model */
    [0x06] = 8,  /* get_device_sn */
    [0x07] = 10, /* get_device_fw */
    [0x08] = 12, /* get_device_cal */
    [0x09] = 14, /* correlate_gps_time */
    [0x80] = 1,  /* reserved ack */
    [0x83] = 4,  /* device_messages */
    [0x85] = 7,  /* device_model */
    [0x86] = 9,  /* device_sn */
    [0x87] = 11, /* device_fw */
    [0x88] = 13, /* device_cal */
};
static const uint16_t k_set_imu_config[256] = {
    [0x01] = 15, /* uart_baud_rate */
    [0x03] = 17, /* filter */
    [0x04] = 19, /* sample_rate */
    [0x05] = 21, /* select_sensors */
    [0x06] = 23, /* get_internal_sample_rate */
    [0x07] = 25, /* accel_range */
    [0x08] = 27, /* gyro_range */
    [0x09] = 29, /* config_all */
    [0x0A] = 30, /* data_on_off */
    [0x0B] = 32, /* xtrig_on_off */
    [0x0C] = 34, /* select_sensors_rev_b */
    [0x0D] = 36, /* aux_accel_range */
    [0x80] = 1,  /* reserved ack */
    [0x81] = 16, /* uart_baud_rate_response */
    [0x83] = 18, /* filter_response */
    [0x84] = 20, /* sample_rate_response */
    [0x85] = 22, /* select_sensors_response */
    [0x86] = 24, /* internal_sample_rate */
    [0x87] = 26, /* accel_range_response */
    [0x88] = 28, /* gyro_range_response */
    [0x8A] = 31, /* data_on_off_response */
    [0x8B] = 33, /* xtrig_on_off_response */
    [0x8C] = 35, /* select_sensors_rev_b_response */
    [0x8D] = 37, /* aux_accel_range_response */
};
static const uint16_t k_set_imu_data[256] = {
    [0x81] = 38, /* scaled_accel */
    [0x82] = 39, /* scaled_gyro */
    [0x83] = 40, /* scaled_mag */
    [0x84] = 41, /* delta_theta */
    [0x85] = 42, /* delta_velocity */
    [0x86] = 43, /* scaled_pressure */
    [0x87] = 44, /* scaled_temperature */
    [0x88] = 45, /* gps_correlated_time */
    [0x89] = 46, /* scaled_aux_accel */
};

static const uint16_t *const k_sets[256] = {
    [0x01] = k_set_base,
    [0x02] = k_set_imu_config,
    [0xA2] = k_set_imu_data,
};

/* Fields of a set (reserved and shared data fields included, see k_set_*); *set_known tells
 * whether the set is defined at all. */
static const mscipc_field_info_t *defined(uint8_t set, uint8_t descriptor, bool *set_known) {
    const uint16_t *table = k_sets[set];
    *set_known = table != NULL;
    if (!table || table[descriptor] == 0) {
        return NULL;
    }
    return &k_fields[table[descriptor] - 1];
}

/* The body of mscipc_find_field, static so that mscipc_decode_field inlines it. */
static const mscipc_field_info_t *find_field(uint8_t set, uint8_t descriptor, mscipc_status_t *why) {
    bool known = false;
    mscipc_set_kind_t kind;
    const mscipc_field_info_t *f = defined(set, descriptor, &known);
    if (f) {
        return f;
    }
    kind = mscipc_set_kind(set);
    /* reserved fields of the set's kind */
    switch (kind) {
    case MSCIPC_SET_KIND_COMMAND:
        if (descriptor == 0x80) {
            return &k_fields[0]; /* ack */
        }
        break;
    case MSCIPC_SET_KIND_DATA:
        break;
    case MSCIPC_SET_KIND_NONE:
    default:
        break;
    }
    if (why) {
        *why = known ? MSCIPC_ERR_UNKNOWN_DESCRIPTOR : MSCIPC_ERR_UNKNOWN_SET;
    }
    return NULL;
}

const mscipc_field_info_t *mscipc_find_field(uint8_t set, uint8_t descriptor, mscipc_status_t *why) {
    return find_field(set, descriptor, why);
}

static mscipc_status_t decode_layout(mscipc_field_id_t id, const uint8_t *data, size_t len,
                                     mscipc_field_value_t *out, mscipc_decode_error_t *err) {
    out->id = id;
    switch (id) {
    case MSCIPC_FIELD_ACK:
        return mscipc_ack_decode(data, len, &out->u.ack, err);
    case MSCIPC_FIELD_BASE_PING:
        return mscipc_base_ping_decode(data, len, &out->u.base_ping, err);
    case MSCIPC_FIELD_BASE_GET_DEVICE_MESSAGES:
        return mscipc_base_get_device_messages_decode(data, len, &out->u.base_get_device_messages, err);
    case MSCIPC_FIELD_BASE_DEVICE_MESSAGES:
        return mscipc_base_device_messages_decode(data, len, &out->u.base_device_messages, err);
    case MSCIPC_FIELD_BASE_DEVICE_RESET:
        return mscipc_base_device_reset_decode(data, len, &out->u.base_device_reset, err);
    case MSCIPC_FIELD_BASE_GET_DEVICE_MODEL:
        return mscipc_base_get_device_model_decode(data, len, &out->u.base_get_device_model, err);
    case MSCIPC_FIELD_BASE_DEVICE_MODEL:
        return mscipc_base_device_model_decode(data, len, &out->u.base_device_model, err);
    case MSCIPC_FIELD_BASE_GET_DEVICE_SN:
        return mscipc_base_get_device_sn_decode(data, len, &out->u.base_get_device_sn, err);
    case MSCIPC_FIELD_BASE_DEVICE_SN:
        return mscipc_base_device_sn_decode(data, len, &out->u.base_device_sn, err);
    case MSCIPC_FIELD_BASE_GET_DEVICE_FW:
        return mscipc_base_get_device_fw_decode(data, len, &out->u.base_get_device_fw, err);
    case MSCIPC_FIELD_BASE_DEVICE_FW:
        return mscipc_base_device_fw_decode(data, len, &out->u.base_device_fw, err);
    case MSCIPC_FIELD_BASE_GET_DEVICE_CAL:
        return mscipc_base_get_device_cal_decode(data, len, &out->u.base_get_device_cal, err);
    case MSCIPC_FIELD_BASE_DEVICE_CAL:
        return mscipc_base_device_cal_decode(data, len, &out->u.base_device_cal, err);
    case MSCIPC_FIELD_BASE_CORRELATE_GPS_TIME:
        return mscipc_base_correlate_gps_time_decode(data, len, &out->u.base_correlate_gps_time, err);
    case MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE:
        return mscipc_imu_config_uart_baud_rate_decode(data, len, &out->u.imu_config_uart_baud_rate, err);
    case MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE_RESPONSE:
        return mscipc_imu_config_uart_baud_rate_response_decode(
            data, len, &out->u.imu_config_uart_baud_rate_response, err);
    case MSCIPC_FIELD_IMU_CONFIG_FILTER:
        return mscipc_imu_config_filter_decode(data, len, &out->u.imu_config_filter, err);
    case MSCIPC_FIELD_IMU_CONFIG_FILTER_RESPONSE:
        return mscipc_imu_config_filter_response_decode(data, len, &out->u.imu_config_filter_response, err);
    case MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE:
        return mscipc_imu_config_sample_rate_decode(data, len, &out->u.imu_config_sample_rate, err);
    case MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE_RESPONSE:
        return mscipc_imu_config_sample_rate_response_decode(data, len,
                                                             &out->u.imu_config_sample_rate_response, err);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS:
        return mscipc_imu_config_select_sensors_decode(data, len, &out->u.imu_config_select_sensors, err);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_RESPONSE:
        return mscipc_imu_config_select_sensors_response_decode(
            data, len, &out->u.imu_config_select_sensors_response, err);
    case MSCIPC_FIELD_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE:
        return mscipc_imu_config_get_internal_sample_rate_decode(
            data, len, &out->u.imu_config_get_internal_sample_rate, err);
    case MSCIPC_FIELD_IMU_CONFIG_INTERNAL_SAMPLE_RATE:
        return mscipc_imu_config_internal_sample_rate_decode(data, len,
                                                             &out->u.imu_config_internal_sample_rate, err);
    case MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE:
        return mscipc_imu_config_accel_range_decode(data, len, &out->u.imu_config_accel_range, err);
    case MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE_RESPONSE:
        return mscipc_imu_config_accel_range_response_decode(data, len,
                                                             &out->u.imu_config_accel_range_response, err);
    case MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE:
        return mscipc_imu_config_gyro_range_decode(data, len, &out->u.imu_config_gyro_range, err);
    case MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE_RESPONSE:
        return mscipc_imu_config_gyro_range_response_decode(data, len, &out->u.imu_config_gyro_range_response,
                                                            err);
    case MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL:
        return mscipc_imu_config_config_all_decode(data, len, &out->u.imu_config_config_all, err);
    case MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF:
        return mscipc_imu_config_data_on_off_decode(data, len, &out->u.imu_config_data_on_off, err);
    case MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF_RESPONSE:
        return mscipc_imu_config_data_on_off_response_decode(data, len,
                                                             &out->u.imu_config_data_on_off_response, err);
    case MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF:
        return mscipc_imu_config_xtrig_on_off_decode(data, len, &out->u.imu_config_xtrig_on_off, err);
    case MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF_RESPONSE:
        return mscipc_imu_config_xtrig_on_off_response_decode(data, len,
                                                              &out->u.imu_config_xtrig_on_off_response, err);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B:
        return mscipc_imu_config_select_sensors_rev_b_decode(data, len,
                                                             &out->u.imu_config_select_sensors_rev_b, err);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B_RESPONSE:
        return mscipc_imu_config_select_sensors_rev_b_response_decode(
            data, len, &out->u.imu_config_select_sensors_rev_b_response, err);
    case MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE:
        return mscipc_imu_config_aux_accel_range_decode(data, len, &out->u.imu_config_aux_accel_range, err);
    case MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE_RESPONSE:
        return mscipc_imu_config_aux_accel_range_response_decode(
            data, len, &out->u.imu_config_aux_accel_range_response, err);
    case MSCIPC_FIELD_IMU_DATA_SCALED_ACCEL:
        return mscipc_imu_data_scaled_accel_decode(data, len, &out->u.imu_data_scaled_accel, err);
    case MSCIPC_FIELD_IMU_DATA_SCALED_GYRO:
        return mscipc_imu_data_scaled_gyro_decode(data, len, &out->u.imu_data_scaled_gyro, err);
    case MSCIPC_FIELD_IMU_DATA_SCALED_MAG:
        return mscipc_imu_data_scaled_mag_decode(data, len, &out->u.imu_data_scaled_mag, err);
    case MSCIPC_FIELD_IMU_DATA_DELTA_THETA:
        return mscipc_imu_data_delta_theta_decode(data, len, &out->u.imu_data_delta_theta, err);
    case MSCIPC_FIELD_IMU_DATA_DELTA_VELOCITY:
        return mscipc_imu_data_delta_velocity_decode(data, len, &out->u.imu_data_delta_velocity, err);
    case MSCIPC_FIELD_IMU_DATA_SCALED_PRESSURE:
        return mscipc_imu_data_scaled_pressure_decode(data, len, &out->u.imu_data_scaled_pressure, err);
    case MSCIPC_FIELD_IMU_DATA_SCALED_TEMPERATURE:
        return mscipc_imu_data_scaled_temperature_decode(data, len, &out->u.imu_data_scaled_temperature, err);
    case MSCIPC_FIELD_IMU_DATA_GPS_CORRELATED_TIME:
        return mscipc_imu_data_gps_correlated_time_decode(data, len, &out->u.imu_data_gps_correlated_time,
                                                          err);
    case MSCIPC_FIELD_IMU_DATA_SCALED_AUX_ACCEL:
        return mscipc_imu_data_scaled_aux_accel_decode(data, len, &out->u.imu_data_scaled_aux_accel, err);
    case MSCIPC_FIELD_NONE:
    case MSCIPC_FIELD_COUNT:
    default:
        return MSCIPC_ERR_INVALID;
    }
}

/* Every case of mscipc_decode_field: several layouts per field, a device to choose among them, error
 * details. Out of line (MSCIPC_NOINLINE) so that the common case below stays a short function. */
static MSCIPC_NOINLINE mscipc_status_t decode_field_general(uint8_t set, uint8_t descriptor,
                                                            const uint8_t *data, size_t len,
                                                            mscipc_device_t device, mscipc_field_value_t *out,
                                                            mscipc_decode_error_t *err) {
    mscipc_status_t why = MSCIPC_ERR_UNKNOWN_SET;
    const mscipc_field_info_t *f = find_field(set, descriptor, &why);
    size_t first;
    size_t count;
    size_t i;
    out->id = MSCIPC_FIELD_NONE;
    if (!f) {
        return why;
    }
    first = (size_t)f->first_layout;
    count = f->layout_count;
    if (device != MSCIPC_DEVICE_ANY) {
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
        if (decode_layout((mscipc_field_id_t)(first + i), data, len, out, NULL) == MSCIPC_OK) {
            return MSCIPC_OK;
        }
    }
    if (err) {
        memset(err, 0, sizeof *err);
        (void)decode_layout((mscipc_field_id_t)first, data, len, out, err);
    }
    out->id = MSCIPC_FIELD_NONE;
    return MSCIPC_ERR_DECODE;
}

/* The common case first: a field its set defines, with one layout (the device does not choose
 * among one). Its decoder fills *err itself when it fails (as decode_field_general's second run
 * does). Anything else goes to decode_field_general, which starts over. */
mscipc_status_t mscipc_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                    mscipc_device_t device, mscipc_field_value_t *out,
                                    mscipc_decode_error_t *err) {
    const uint16_t *table = k_sets[set];
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (table && table[descriptor] != 0) {
        const mscipc_field_info_t *f = &k_fields[table[descriptor] - 1];
        if (f->layout_count == 1) {
            if (decode_layout(f->first_layout, data, len, out, err) == MSCIPC_OK) {
                return MSCIPC_OK;
            }
            out->id = MSCIPC_FIELD_NONE;
            return MSCIPC_ERR_DECODE;
        }
    }
    return decode_field_general(set, descriptor, data, len, device, out, err);
}

/* Every entry of a payload to fn (out of line: mscipc_decode_packet stays a switch). */
static MSCIPC_NOINLINE void visit_all(uint8_t set, const uint8_t *payload, size_t len,
                                      mscipc_field_entry_fn fn, void *ctx) {
    mscipc_field_iter_t it;
    mscipc_field_entry_t e;
    mscipc_field_iter_init(&it, set, payload, len);
    while (mscipc_field_iter_next(&it, &e)) {
        fn(ctx, &e);
    }
}

const mscipc_packet_index_t *mscipc_decode_packet(const uint8_t *packet, mscipc_packet_t *out,
                                                  mscipc_field_entry_fn other, void *ctx) {
    const uint8_t set = mscipc_packet_set(packet);
    const uint8_t *payload = mscipc_packet_payload(packet);
    const size_t len = mscipc_packet_payload_length(packet);
    assert(packet != NULL);
    assert(out != NULL);
    out->set = set;
    switch (set) {
    case 0xA2:
        (void)mscipc_imu_data_decode_packet(payload, len, &out->u.imu_data, other, ctx);
        return &out->u.imu_data.index;
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
    mscipc_field_entry_fn other;
    void *ctx;
    size_t count;
    int whole; /* every entry a field, at most MSCIPC_LAYOUT_SHAPE_FIELDS */
    size_t pos[MSCIPC_LAYOUT_SHAPE_FIELDS];
} noted_other_t;

static void note_other(void *ctx, const mscipc_field_entry_t *entry) {
    noted_other_t *c = ctx;
    if (entry->kind != MSCIPC_ENTRY_FIELD || c->count == MSCIPC_LAYOUT_SHAPE_FIELDS) {
        c->whole = 0;
    } else {
        c->pos[c->count++] = entry->offset;
    }
    if (c->other) {
        c->other(c->ctx, entry);
    }
}

/* The members of a set's packet struct (mscipc_layout_cache_record_); count 0: none. */
static const mscipc_layout_member_t *shape_members(uint8_t set, size_t *count) {
    switch (set) {
    case 0xA2:
        *count = 9;
        return mscipc_imu_data_layout_members_;
    default:
        *count = 0;
        return NULL;
    }
}

/* A packet whose shape is not the last one hit: the other cached shapes, else the straight-line
 * decoder (and its shape recorded). */
static MSCIPC_NOINLINE const mscipc_packet_index_t *decode_uncached(mscipc_layout_cache_t *cache,
                                                                    const uint8_t *packet,
                                                                    mscipc_packet_t *out,
                                                                    mscipc_field_entry_fn other, void *ctx) {
    const uint8_t set = mscipc_packet_set(packet);
    const uint8_t *payload = mscipc_packet_payload(packet);
    const size_t len = mscipc_packet_payload_length(packet);
    const mscipc_layout_shape_t *shape = mscipc_layout_cache_find_(cache, set, payload, len);
    const mscipc_packet_index_t *index;
    noted_other_t noted;
    if (shape != NULL &&
        mscipc_layout_shape_decode_(shape, payload, (mscipc_packet_index_t *)(void *)&out->u)) {
        out->set = set;
        if (shape->others != 0 && other != NULL) {
            mscipc_layout_shape_others_(shape, payload, other, ctx);
        }
        return (const mscipc_packet_index_t *)(const void *)&out->u;
    }
    noted.other = other;
    noted.ctx = ctx;
    noted.count = 0;
    noted.whole = 1;
    index = mscipc_decode_packet(packet, out, note_other, &noted);
    if (index != NULL && noted.whole && shape == NULL) {
        size_t count;
        const mscipc_layout_member_t *members = shape_members(set, &count);
        if (count != 0) {
            mscipc_layout_cache_record_(cache, set, payload, len, index, noted.pos, noted.count, members,
                                        count);
        }
    }
    return index;
}

/* Every packet struct of out->u starts with its index: a pointer to the union converts to one to
 * each member, and that to one to its first member (C99 6.7.2.1). */
const mscipc_packet_index_t *mscipc_decode_packet_cached(mscipc_layout_cache_t *cache, const uint8_t *packet,
                                                         mscipc_packet_t *out, mscipc_field_entry_fn other,
                                                         void *ctx) {
    const uint8_t set = mscipc_packet_set(packet);
    const uint8_t *payload = mscipc_packet_payload(packet);
    const mscipc_layout_shape_t *shape;
    assert(cache != NULL);
    assert(out != NULL);
    shape = &cache->shapes[cache->last % MSCIPC_LAYOUT_CACHE_SHAPES];
    if (mscipc_layout_shape_matches_(shape, set, payload, mscipc_packet_payload_length(packet)) &&
        mscipc_layout_shape_decode_(shape, payload, (mscipc_packet_index_t *)(void *)&out->u)) {
        out->set = set;
        if (shape->others != 0 && other != NULL) {
            mscipc_layout_shape_others_(shape, payload, other, ctx);
        }
        return (const mscipc_packet_index_t *)(const void *)&out->u;
    }
    return decode_uncached(cache, packet, out, other, ctx);
}

mscipc_status_t mscipc_encode_field(const mscipc_field_value_t *value, uint8_t *buf, size_t cap,
                                    size_t *len_out) {
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    switch (value->id) {
    case MSCIPC_FIELD_ACK:
        return mscipc_ack_encode(&value->u.ack, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_PING:
        return mscipc_base_ping_encode(&value->u.base_ping, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_GET_DEVICE_MESSAGES:
        return mscipc_base_get_device_messages_encode(&value->u.base_get_device_messages, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_DEVICE_MESSAGES:
        return mscipc_base_device_messages_encode(&value->u.base_device_messages, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_DEVICE_RESET:
        return mscipc_base_device_reset_encode(&value->u.base_device_reset, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_GET_DEVICE_MODEL:
        return mscipc_base_get_device_model_encode(&value->u.base_get_device_model, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_DEVICE_MODEL:
        return mscipc_base_device_model_encode(&value->u.base_device_model, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_GET_DEVICE_SN:
        return mscipc_base_get_device_sn_encode(&value->u.base_get_device_sn, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_DEVICE_SN:
        return mscipc_base_device_sn_encode(&value->u.base_device_sn, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_GET_DEVICE_FW:
        return mscipc_base_get_device_fw_encode(&value->u.base_get_device_fw, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_DEVICE_FW:
        return mscipc_base_device_fw_encode(&value->u.base_device_fw, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_GET_DEVICE_CAL:
        return mscipc_base_get_device_cal_encode(&value->u.base_get_device_cal, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_DEVICE_CAL:
        return mscipc_base_device_cal_encode(&value->u.base_device_cal, buf, cap, len_out);
    case MSCIPC_FIELD_BASE_CORRELATE_GPS_TIME:
        return mscipc_base_correlate_gps_time_encode(&value->u.base_correlate_gps_time, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE:
        return mscipc_imu_config_uart_baud_rate_encode(&value->u.imu_config_uart_baud_rate, buf, cap,
                                                       len_out);
    case MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE_RESPONSE:
        return mscipc_imu_config_uart_baud_rate_response_encode(&value->u.imu_config_uart_baud_rate_response,
                                                                buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_FILTER:
        return mscipc_imu_config_filter_encode(&value->u.imu_config_filter, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_FILTER_RESPONSE:
        return mscipc_imu_config_filter_response_encode(&value->u.imu_config_filter_response, buf, cap,
                                                        len_out);
    case MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE:
        return mscipc_imu_config_sample_rate_encode(&value->u.imu_config_sample_rate, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE_RESPONSE:
        return mscipc_imu_config_sample_rate_response_encode(&value->u.imu_config_sample_rate_response, buf,
                                                             cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS:
        return mscipc_imu_config_select_sensors_encode(&value->u.imu_config_select_sensors, buf, cap,
                                                       len_out);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_RESPONSE:
        return mscipc_imu_config_select_sensors_response_encode(&value->u.imu_config_select_sensors_response,
                                                                buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE:
        return mscipc_imu_config_get_internal_sample_rate_encode(
            &value->u.imu_config_get_internal_sample_rate, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_INTERNAL_SAMPLE_RATE:
        return mscipc_imu_config_internal_sample_rate_encode(&value->u.imu_config_internal_sample_rate, buf,
                                                             cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE:
        return mscipc_imu_config_accel_range_encode(&value->u.imu_config_accel_range, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE_RESPONSE:
        return mscipc_imu_config_accel_range_response_encode(&value->u.imu_config_accel_range_response, buf,
                                                             cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE:
        return mscipc_imu_config_gyro_range_encode(&value->u.imu_config_gyro_range, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE_RESPONSE:
        return mscipc_imu_config_gyro_range_response_encode(&value->u.imu_config_gyro_range_response, buf,
                                                            cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL:
        return mscipc_imu_config_config_all_encode(&value->u.imu_config_config_all, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF:
        return mscipc_imu_config_data_on_off_encode(&value->u.imu_config_data_on_off, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF_RESPONSE:
        return mscipc_imu_config_data_on_off_response_encode(&value->u.imu_config_data_on_off_response, buf,
                                                             cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF:
        return mscipc_imu_config_xtrig_on_off_encode(&value->u.imu_config_xtrig_on_off, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF_RESPONSE:
        return mscipc_imu_config_xtrig_on_off_response_encode(&value->u.imu_config_xtrig_on_off_response, buf,
                                                              cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B:
        return mscipc_imu_config_select_sensors_rev_b_encode(&value->u.imu_config_select_sensors_rev_b, buf,
                                                             cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B_RESPONSE:
        return mscipc_imu_config_select_sensors_rev_b_response_encode(
            &value->u.imu_config_select_sensors_rev_b_response, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE:
        return mscipc_imu_config_aux_accel_range_encode(&value->u.imu_config_aux_accel_range, buf, cap,
                                                        len_out);
    case MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE_RESPONSE:
        return mscipc_imu_config_aux_accel_range_response_encode(
            &value->u.imu_config_aux_accel_range_response, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_DATA_SCALED_ACCEL:
        return mscipc_imu_data_scaled_accel_encode(&value->u.imu_data_scaled_accel, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_DATA_SCALED_GYRO:
        return mscipc_imu_data_scaled_gyro_encode(&value->u.imu_data_scaled_gyro, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_DATA_SCALED_MAG:
        return mscipc_imu_data_scaled_mag_encode(&value->u.imu_data_scaled_mag, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_DATA_DELTA_THETA:
        return mscipc_imu_data_delta_theta_encode(&value->u.imu_data_delta_theta, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_DATA_DELTA_VELOCITY:
        return mscipc_imu_data_delta_velocity_encode(&value->u.imu_data_delta_velocity, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_DATA_SCALED_PRESSURE:
        return mscipc_imu_data_scaled_pressure_encode(&value->u.imu_data_scaled_pressure, buf, cap, len_out);
    case MSCIPC_FIELD_IMU_DATA_SCALED_TEMPERATURE:
        return mscipc_imu_data_scaled_temperature_encode(&value->u.imu_data_scaled_temperature, buf, cap,
                                                         len_out);
    case MSCIPC_FIELD_IMU_DATA_GPS_CORRELATED_TIME:
        return mscipc_imu_data_gps_correlated_time_encode(&value->u.imu_data_gps_correlated_time, buf, cap,
                                                          len_out);
    case MSCIPC_FIELD_IMU_DATA_SCALED_AUX_ACCEL:
        return mscipc_imu_data_scaled_aux_accel_encode(&value->u.imu_data_scaled_aux_accel, buf, cap,
                                                       len_out);
    case MSCIPC_FIELD_NONE:
    case MSCIPC_FIELD_COUNT:
    default:
        return MSCIPC_ERR_INVALID;
    }
}
