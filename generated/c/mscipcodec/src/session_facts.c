/* What the Memsense MS-CIP spec says about every command, for the session core (session.c,
 * docs/conformance.md section 8): the ack rule and, per command layout, its devices, function
 * values, expected reply descriptors with their conditions, ack suppression and timeout
 * allowance. Generated: do not edit. */
#include "mscipcodec/session.h"

#include <string.h>

/* Per device, where a data packet carries the device's reference time (the spec's
 * time.reference_time; the host clock model, docs/time.md). */
const mscipc_reference_time_t mscipc_reference_times[] = {
    {MSCIPC_DEVICE_ANY, 0, false, 0, false, 0, 0, 0, 0, 0}}; /* none (C has no empty arrays) */
const size_t mscipc_reference_time_count = 0;

const char *mscipc_function_name(int value) {
    switch (value) {
    case 1:
        return "write";
    case 2:
        return "read";
    case 3:
        return "save";
    case 4:
        return "load";
    case 5:
        return "default";
    default:
        return NULL;
    }
}

/* Devices a function selector value is limited to (every device when it is not). */
static uint32_t function_devices(int value) {
    switch (value) {
    default:
        return 0x2u;
    }
}

static bool listed(int value, const int *values, size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (values[i] == value) {
            return true;
        }
    }
    return false;
}

static void expect(mscipc_command_facts_t *out, uint8_t descriptor) {
    if (out->expect_count < MSCIPC_SESSION_MAX_EXPECT) {
        out->expect[out->expect_count++] = descriptor;
    }
}

bool mscipc_command_facts(const mscipc_field_value_t *command, mscipc_command_facts_t *out) {
    memset(out, 0, sizeof *out);
    out->id = command->id;
    out->function = -1;
    out->function_listed = true;
    out->function_devices = 0x2u;
    out->layout_device = MSCIPC_DEVICE_ANY;
    switch (command->id) {
    case MSCIPC_FIELD_BASE_PING: {
        out->set = 0x01;
        out->descriptor = 0x02;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        return true;
    }
    case MSCIPC_FIELD_BASE_GET_DEVICE_MESSAGES: {
        out->set = 0x01;
        out->descriptor = 0x03;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        expect(out, 0x83);
        return true;
    }
    case MSCIPC_FIELD_BASE_DEVICE_RESET: {
        out->set = 0x01;
        out->descriptor = 0x04;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        return true;
    }
    case MSCIPC_FIELD_BASE_GET_DEVICE_MODEL: {
        out->set = 0x01;
        out->descriptor = 0x05;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        expect(out, 0x85);
        return true;
    }
    case MSCIPC_FIELD_BASE_GET_DEVICE_SN: {
        out->set = 0x01;
        out->descriptor = 0x06;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        expect(out, 0x86);
        return true;
    }
    case MSCIPC_FIELD_BASE_GET_DEVICE_FW: {
        out->set = 0x01;
        out->descriptor = 0x07;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        expect(out, 0x87);
        return true;
    }
    case MSCIPC_FIELD_BASE_GET_DEVICE_CAL: {
        out->set = 0x01;
        out->descriptor = 0x08;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        expect(out, 0x88);
        return true;
    }
    case MSCIPC_FIELD_BASE_CORRELATE_GPS_TIME: {
        out->set = 0x01;
        out->descriptor = 0x09;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE: {
        const mscipc_imu_config_uart_baud_rate_t *c = &command->u.imu_config_uart_baud_rate;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x01;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x81);
        }
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_FILTER: {
        const mscipc_imu_config_filter_t *c = &command->u.imu_config_filter;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x03;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x83);
        }
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE: {
        const mscipc_imu_config_sample_rate_t *c = &command->u.imu_config_sample_rate;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x04;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x84);
        }
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS: {
        const mscipc_imu_config_select_sensors_t *c = &command->u.imu_config_select_sensors;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x05;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x85);
        }
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE: {
        out->set = 0x02;
        out->descriptor = 0x06;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        expect(out, 0x86);
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE: {
        const mscipc_imu_config_accel_range_t *c = &command->u.imu_config_accel_range;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x07;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x87);
        }
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE: {
        const mscipc_imu_config_gyro_range_t *c = &command->u.imu_config_gyro_range;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x08;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x88);
        }
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL: {
        const mscipc_imu_config_config_all_t *c = &command->u.imu_config_config_all;
        static const int functions[] = {3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x09;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF: {
        const mscipc_imu_config_data_on_off_t *c = &command->u.imu_config_data_on_off;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x0A;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8A);
        }
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF: {
        const mscipc_imu_config_xtrig_on_off_t *c = &command->u.imu_config_xtrig_on_off;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x0B;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8B);
        }
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B: {
        const mscipc_imu_config_select_sensors_rev_b_t *c = &command->u.imu_config_select_sensors_rev_b;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x0C;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8C);
        }
        return true;
    }
    case MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE: {
        const mscipc_imu_config_aux_accel_range_t *c = &command->u.imu_config_aux_accel_range;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x02;
        out->descriptor = 0x0D;
        out->field_devices = 0x2u;
        out->layout_device = MSCIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8D);
        }
        return true;
    }
    default:
        return false;
    }
}

int mscipc_session_ack_decode(uint8_t set, const uint8_t *data, size_t len, mscipc_device_t device,
                              uint8_t *echo, uint32_t *code) {
    mscipc_status_t why;
    const mscipc_field_info_t *f = mscipc_find_field(set, MSCIPC_SESSION_ACK_DESCRIPTOR, &why);
    mscipc_ack_t ack;
    if (f == NULL) {
        return 0;
    }
    if (f->first_layout != MSCIPC_FIELD_ACK) {
        mscipc_field_value_t value;
        return mscipc_decode_field(set, MSCIPC_SESSION_ACK_DESCRIPTOR, data, len, device, &value, NULL) ==
                       MSCIPC_OK
                   ? -1
                   : 0;
    }
    if (mscipc_ack_decode(data, len, &ack, NULL) != MSCIPC_OK) {
        return 0;
    }
    *echo = (uint8_t)ack.command_code;
    *code = (uint32_t)ack.error_code;
    return 1;
}

/* The names a device answers to in the wrong-model check: its title and its identity model name
 * (the spec's simulation.identity), upper case without spaces and punctuation; NULL-terminated. */
const char *const *mscipc_device_model_names(mscipc_device_t device) {
    static const char *const names_0[] = {"MSIMU3020", NULL}; /* MS-IMU3020, MS_IMU3020 */
    static const char *const none[] = {NULL};
    switch (device) {
    case MSCIPC_DEVICE_MS_IMU3020:
        return names_0;
    default:
        return none;
    }
}
