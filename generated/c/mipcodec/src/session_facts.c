/* What the MicroStrain MIP spec says about every command, for the session core (session.c,
 * docs/conformance.md section 8): the ack rule and, per command layout, its devices, function
 * values, expected reply descriptors with their conditions, ack suppression and timeout
 * allowance. Generated: do not edit. */
#include "mipcodec/session.h"

#include <string.h>

/* Per device, where a data packet carries the device's reference time (the spec's
 * time.reference_time; the host clock model, docs/time.md). */
const mipc_reference_time_t mipc_reference_times[] = {
    {MIPC_DEVICE_CV7_INS, 0xFF, true, 0xD5, false, 0, 8, 0, 0, 1}, /* shared.reference_timestamp */
    {MIPC_DEVICE_GX5_45, 0x80, false, 0x12, true, 0, 8, 8, 2, 1},  /* sensor.gps_timestamp */
};
const size_t mipc_reference_time_count = 2;

const char *mipc_function_name(int value) {
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
    case 6:
        return "write_no_ack";
    default:
        return NULL;
    }
}

/* Devices a function selector value is limited to (every device when it is not). */
static uint32_t function_devices(int value) {
    switch (value) {
    case 6:
        return 0x2u;
    default:
        return 0x6u;
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

static void expect(mipc_command_facts_t *out, uint8_t descriptor) {
    if (out->expect_count < MIPC_SESSION_MAX_EXPECT) {
        out->expect[out->expect_count++] = descriptor;
    }
}

bool mipc_command_facts(const mipc_field_value_t *command, mipc_command_facts_t *out) {
    memset(out, 0, sizeof *out);
    out->id = command->id;
    out->function = -1;
    out->function_listed = true;
    out->function_devices = 0x6u;
    out->layout_device = MIPC_DEVICE_ANY;
    switch (command->id) {
    case MIPC_FIELD_BASE_PING: {
        out->set = 0x01;
        out->descriptor = 0x01;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_BASE_SET_TO_IDLE: {
        out->set = 0x01;
        out->descriptor = 0x02;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_BASE_GET_DEVICE_INFO: {
        out->set = 0x01;
        out->descriptor = 0x03;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0x81);
        return true;
    }
    case MIPC_FIELD_BASE_GET_DEVICE_DESCRIPTORS: {
        out->set = 0x01;
        out->descriptor = 0x04;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0x82);
        return true;
    }
    case MIPC_FIELD_BASE_BUILT_IN_TEST: {
        out->set = 0x01;
        out->descriptor = 0x05;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        {
            {
                out->allowance_ms = 5000u;
            }
        }
        expect(out, 0x83);
        return true;
    }
    case MIPC_FIELD_BASE_RESUME: {
        out->set = 0x01;
        out->descriptor = 0x06;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_BASE_GET_EXTENDED_DESCRIPTORS: {
        out->set = 0x01;
        out->descriptor = 0x07;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0x86);
        return true;
    }
    case MIPC_FIELD_BASE_CONTINUOUS_BIT: {
        out->set = 0x01;
        out->descriptor = 0x08;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0x88);
        return true;
    }
    case MIPC_FIELD_BASE_COMM_PORT_SPEED: {
        const mipc_base_comm_port_speed_t *c = &command->u.base_comm_port_speed;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x01;
        out->descriptor = 0x09;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x89);
        }
        return true;
    }
    case MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45: {
        const mipc_base_gps_time_update_gx5_45_t *c = &command->u.base_gps_time_update_gx5_45;
        static const int functions[] = {1, 2, 6};
        out->set = 0x01;
        out->descriptor = 0x72;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_GX5_45;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        out->suppressed = out->function == 6;
        if (out->function == 2 && (int64_t)c->field_id == 1) {
            expect(out, 0x84);
        }
        if (out->function == 2 && (int64_t)c->field_id == 2) {
            expect(out, 0x85);
        }
        return true;
    }
    case MIPC_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS: {
        const mipc_base_gps_time_update_cv7_ins_t *c = &command->u.base_gps_time_update_cv7_ins;
        static const int functions[] = {1};
        out->set = 0x01;
        out->descriptor = 0x72;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_CV7_INS;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        return true;
    }
    case MIPC_FIELD_BASE_DEVICE_RESET: {
        out->set = 0x01;
        out->descriptor = 0x7E;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_THREEDM_EVENT_CONTROL: {
        const mipc_threedm_event_control_t *c = &command->u.threedm_event_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x2B;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB5);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS: {
        out->set = 0x0C;
        out->descriptor = 0x2C;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0xB6);
        return true;
    }
    case MIPC_FIELD_THREEDM_GET_EVENT_ACTION_STATUS: {
        out->set = 0x0C;
        out->descriptor = 0x2D;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0xB7);
        return true;
    }
    case MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG: {
        const mipc_threedm_event_trigger_config_t *c = &command->u.threedm_event_trigger_config;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x2E;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB8);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG: {
        const mipc_threedm_event_action_config_t *c = &command->u.threedm_event_action_config;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x2F;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB9);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45: {
        const mipc_threedm_device_startup_settings_gx5_45_t *c =
            &command->u.threedm_device_startup_settings_gx5_45;
        static const int functions[] = {2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x30;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_GX5_45;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        return true;
    }
    case MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS: {
        const mipc_threedm_device_startup_settings_cv7_ins_t *c =
            &command->u.threedm_device_startup_settings_cv7_ins;
        static const int functions[] = {3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x30;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_CV7_INS;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        {
            {
                out->allowance_ms = 1000u;
            }
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER: {
        const mipc_threedm_sensor_to_vehicle_euler_t *c = &command->u.threedm_sensor_to_vehicle_euler;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x31;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB1);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION: {
        const mipc_threedm_sensor_to_vehicle_quaternion_t *c =
            &command->u.threedm_sensor_to_vehicle_quaternion;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x32;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB2);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM: {
        const mipc_threedm_sensor_to_vehicle_dcm_t *c = &command->u.threedm_sensor_to_vehicle_dcm;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x33;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB3);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45: {
        const mipc_threedm_accel_bias_gx5_45_t *c = &command->u.threedm_accel_bias_gx5_45;
        static const int functions[] = {1, 2, 3, 4, 5, 6};
        out->set = 0x0C;
        out->descriptor = 0x37;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_GX5_45;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        out->suppressed = out->function == 6;
        if (out->function == 2) {
            expect(out, 0x9A);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS: {
        const mipc_threedm_accel_bias_cv7_ins_t *c = &command->u.threedm_accel_bias_cv7_ins;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x37;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_CV7_INS;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x9A);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45: {
        const mipc_threedm_gyro_bias_gx5_45_t *c = &command->u.threedm_gyro_bias_gx5_45;
        static const int functions[] = {1, 2, 3, 4, 5, 6};
        out->set = 0x0C;
        out->descriptor = 0x38;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_GX5_45;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        out->suppressed = out->function == 6;
        if (out->function == 2) {
            expect(out, 0x9B);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS: {
        const mipc_threedm_gyro_bias_cv7_ins_t *c = &command->u.threedm_gyro_bias_cv7_ins;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x38;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_CV7_INS;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x9B);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_CAPTURE_GYRO_BIAS: {
        const mipc_threedm_capture_gyro_bias_t *c = &command->u.threedm_capture_gyro_bias;
        out->set = 0x0C;
        out->descriptor = 0x39;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        {
            {
                out->allowance_ms = 0u;
                out->allowance_ms += (uint32_t)c->averaging_time_ms;
            }
        }
        expect(out, 0x9B);
        return true;
    }
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45: {
        const mipc_threedm_mag_hard_iron_offset_gx5_45_t *c = &command->u.threedm_mag_hard_iron_offset_gx5_45;
        static const int functions[] = {1, 2, 3, 4, 5, 6};
        out->set = 0x0C;
        out->descriptor = 0x3A;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_GX5_45;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        out->suppressed = out->function == 6;
        if (out->function == 2) {
            expect(out, 0x9C);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS: {
        const mipc_threedm_mag_hard_iron_offset_cv7_ins_t *c =
            &command->u.threedm_mag_hard_iron_offset_cv7_ins;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x3A;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_CV7_INS;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x9C);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45: {
        const mipc_threedm_mag_soft_iron_matrix_gx5_45_t *c = &command->u.threedm_mag_soft_iron_matrix_gx5_45;
        static const int functions[] = {1, 2, 3, 4, 5, 6};
        out->set = 0x0C;
        out->descriptor = 0x3B;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_GX5_45;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        out->suppressed = out->function == 6;
        if (out->function == 2) {
            expect(out, 0x9D);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS: {
        const mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *c =
            &command->u.threedm_mag_soft_iron_matrix_cv7_ins;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x3B;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_CV7_INS;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x9D);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE: {
        const mipc_threedm_coning_sculling_enable_t *c = &command->u.threedm_coning_sculling_enable;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x3E;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x9E);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_UART_BAUDRATE: {
        const mipc_threedm_uart_baudrate_t *c = &command->u.threedm_uart_baudrate;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x40;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x87);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GPIO_CONFIG: {
        const mipc_threedm_gpio_config_t *c = &command->u.threedm_gpio_config;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x41;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xC1);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GPIO_STATE: {
        const mipc_threedm_gpio_state_t *c = &command->u.threedm_gpio_state;
        static const int functions[] = {1, 2};
        out->set = 0x0C;
        out->descriptor = 0x42;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xC2);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_ODOMETER_CONFIG: {
        const mipc_threedm_odometer_config_t *c = &command->u.threedm_odometer_config;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x43;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xC3);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER: {
        const mipc_threedm_advanced_lowpass_filter_t *c = &command->u.threedm_advanced_lowpass_filter;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x50;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8B);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER: {
        const mipc_threedm_complementary_filter_t *c = &command->u.threedm_complementary_filter;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x51;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x97);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_SENSOR_RANGE: {
        const mipc_threedm_sensor_range_t *c = &command->u.threedm_sensor_range;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x52;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xD2);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES: {
        out->set = 0x0C;
        out->descriptor = 0x53;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0xD3);
        return true;
    }
    case MIPC_FIELD_THREEDM_LOWPASS_FILTER: {
        const mipc_threedm_lowpass_filter_t *c = &command->u.threedm_lowpass_filter;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x54;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xD4);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_POLL_IMU_DATA: {
        const mipc_threedm_poll_imu_data_t *c = &command->u.threedm_poll_imu_data;
        out->set = 0x0C;
        out->descriptor = 0x01;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->suppressed = (int64_t)c->option == 1;
        return true;
    }
    case MIPC_FIELD_THREEDM_POLL_GNSS_DATA: {
        const mipc_threedm_poll_gnss_data_t *c = &command->u.threedm_poll_gnss_data;
        out->set = 0x0C;
        out->descriptor = 0x02;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->suppressed = (int64_t)c->option == 1;
        return true;
    }
    case MIPC_FIELD_THREEDM_POLL_FILTER_DATA: {
        const mipc_threedm_poll_filter_data_t *c = &command->u.threedm_poll_filter_data;
        out->set = 0x0C;
        out->descriptor = 0x03;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->suppressed = (int64_t)c->option == 1;
        return true;
    }
    case MIPC_FIELD_THREEDM_POLL_NMEA_DATA: {
        const mipc_threedm_poll_nmea_data_t *c = &command->u.threedm_poll_nmea_data;
        out->set = 0x0C;
        out->descriptor = 0x04;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->suppressed = c->suppress_ack != 0;
        return true;
    }
    case MIPC_FIELD_THREEDM_POLL_DATA: {
        const mipc_threedm_poll_data_t *c = &command->u.threedm_poll_data;
        out->set = 0x0C;
        out->descriptor = 0x0D;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->suppressed = c->suppress_ack != 0;
        return true;
    }
    case MIPC_FIELD_THREEDM_GET_IMU_BASE_RATE: {
        out->set = 0x0C;
        out->descriptor = 0x06;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0x83);
        return true;
    }
    case MIPC_FIELD_THREEDM_GET_GNSS_BASE_RATE: {
        out->set = 0x0C;
        out->descriptor = 0x07;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0x84);
        return true;
    }
    case MIPC_FIELD_THREEDM_GET_FILTER_BASE_RATE: {
        out->set = 0x0C;
        out->descriptor = 0x0B;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0x8A);
        return true;
    }
    case MIPC_FIELD_THREEDM_GET_BASE_RATE: {
        out->set = 0x0C;
        out->descriptor = 0x0E;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0x8E);
        return true;
    }
    case MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT: {
        const mipc_threedm_imu_message_format_t *c = &command->u.threedm_imu_message_format;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x08;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x80);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT: {
        const mipc_threedm_gnss_message_format_t *c = &command->u.threedm_gnss_message_format;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x09;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x81);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT: {
        const mipc_threedm_filter_message_format_t *c = &command->u.threedm_filter_message_format;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x0A;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x82);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT: {
        const mipc_threedm_nmea_message_format_t *c = &command->u.threedm_nmea_message_format;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x0C;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8C);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_MESSAGE_FORMAT: {
        const mipc_threedm_message_format_t *c = &command->u.threedm_message_format;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x0F;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8F);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_FACTORY_STREAMING: {
        out->set = 0x0C;
        out->descriptor = 0x10;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45: {
        const mipc_threedm_data_stream_control_gx5_45_t *c = &command->u.threedm_data_stream_control_gx5_45;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x11;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_GX5_45;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x85);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS: {
        const mipc_threedm_data_stream_control_cv7_ins_t *c = &command->u.threedm_data_stream_control_cv7_ins;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x11;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_CV7_INS;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x85);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_RAW_RTCM_MESSAGE: {
        out->set = 0x0C;
        out->descriptor = 0x20;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS: {
        const mipc_threedm_gnss_constellation_settings_t *c = &command->u.threedm_gnss_constellation_settings;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x21;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xA0);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS: {
        const mipc_threedm_gnss_sbas_settings_t *c = &command->u.threedm_gnss_sbas_settings;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x22;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xA1);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL: {
        const mipc_threedm_gnss_assisted_fix_control_t *c = &command->u.threedm_gnss_assisted_fix_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x23;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xA2);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE: {
        const mipc_threedm_gnss_assist_time_update_t *c = &command->u.threedm_gnss_assist_time_update;
        static const int functions[] = {1, 2};
        out->set = 0x0C;
        out->descriptor = 0x24;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xA3);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_PPS_SOURCE: {
        const mipc_threedm_pps_source_t *c = &command->u.threedm_pps_source;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0C;
        out->descriptor = 0x28;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xA8);
        }
        return true;
    }
    case MIPC_FIELD_THREEDM_GET_SUPPORTED_EVENTS: {
        out->set = 0x0C;
        out->descriptor = 0x2A;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0xB4);
        return true;
    }
    case MIPC_FIELD_THREEDM_DEVICE_STATUS: {
        out->set = 0x0C;
        out->descriptor = 0x64;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0x90);
        return true;
    }
    case MIPC_FIELD_FILTER_RESET_FILTER: {
        out->set = 0x0D;
        out->descriptor = 0x01;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_FILTER_SET_INITIAL_ATTITUDE: {
        out->set = 0x0D;
        out->descriptor = 0x02;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_FILTER_SET_INITIAL_HEADING: {
        out->set = 0x0D;
        out->descriptor = 0x03;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_FILTER_RUN_FILTER: {
        out->set = 0x0D;
        out->descriptor = 0x05;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE: {
        const mipc_filter_vehicle_dynamics_mode_t *c = &command->u.filter_vehicle_dynamics_mode;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x10;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x80);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM: {
        const mipc_filter_sensor_to_vehicle_transform_t *c = &command->u.filter_sensor_to_vehicle_transform;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x11;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x81);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET: {
        const mipc_filter_sensor_to_vehicle_offset_t *c = &command->u.filter_sensor_to_vehicle_offset;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x12;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x82);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_ANTENNA_OFFSET: {
        const mipc_filter_antenna_offset_t *c = &command->u.filter_antenna_offset;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x13;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x83);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_ESTIMATION_CONTROL: {
        const mipc_filter_estimation_control_t *c = &command->u.filter_estimation_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x14;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x84);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL: {
        const mipc_filter_gnss_source_control_t *c = &command->u.filter_gnss_source_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x15;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x86);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_EXTERNAL_GNSS_UPDATE: {
        out->set = 0x0D;
        out->descriptor = 0x16;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE: {
        out->set = 0x0D;
        out->descriptor = 0x17;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL: {
        const mipc_filter_heading_update_control_t *c = &command->u.filter_heading_update_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x18;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x87);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_AUTO_INIT_CONTROL: {
        const mipc_filter_auto_init_control_t *c = &command->u.filter_auto_init_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x19;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x88);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_ACCEL_NOISE: {
        const mipc_filter_accel_noise_t *c = &command->u.filter_accel_noise;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x1A;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x89);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_GYRO_NOISE: {
        const mipc_filter_gyro_noise_t *c = &command->u.filter_gyro_noise;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x1B;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8A);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL: {
        const mipc_filter_accel_bias_model_t *c = &command->u.filter_accel_bias_model;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x1C;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8B);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_GYRO_BIAS_MODEL: {
        const mipc_filter_gyro_bias_model_t *c = &command->u.filter_gyro_bias_model;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x1D;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8C);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_ZUPT_CONTROL: {
        const mipc_filter_zupt_control_t *c = &command->u.filter_zupt_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x1E;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8D);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME: {
        out->set = 0x0D;
        out->descriptor = 0x1F;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL: {
        const mipc_filter_zero_angular_rate_update_control_t *c =
            &command->u.filter_zero_angular_rate_update_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x20;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x8E);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_TARE_ORIENTATION: {
        const mipc_filter_tare_orientation_t *c = &command->u.filter_tare_orientation;
        static const int functions[] = {1, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x21;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        return true;
    }
    case MIPC_FIELD_FILTER_COMMANDED_ZUPT: {
        out->set = 0x0D;
        out->descriptor = 0x22;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE: {
        out->set = 0x0D;
        out->descriptor = 0x23;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION: {
        const mipc_filter_mag_capture_auto_calibration_t *c = &command->u.filter_mag_capture_auto_calibration;
        static const int functions[] = {1, 3};
        out->set = 0x0D;
        out->descriptor = 0x27;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        return true;
    }
    case MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV: {
        const mipc_filter_gravity_noise_std_dev_t *c = &command->u.filter_gravity_noise_std_dev;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x28;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x93);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV: {
        const mipc_filter_pressure_altitude_noise_std_dev_t *c =
            &command->u.filter_pressure_altitude_noise_std_dev;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x29;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x94);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE: {
        const mipc_filter_hard_iron_offset_noise_t *c = &command->u.filter_hard_iron_offset_noise;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x2B;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x96);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE: {
        const mipc_filter_soft_iron_matrix_noise_t *c = &command->u.filter_soft_iron_matrix_noise;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x2C;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x97);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV: {
        const mipc_filter_mag_noise_std_dev_t *c = &command->u.filter_mag_noise_std_dev;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x42;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB1);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_DECLINATION_SOURCE: {
        const mipc_filter_declination_source_t *c = &command->u.filter_declination_source;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x43;
        out->field_devices = 0x6u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB2);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT: {
        const mipc_filter_gravity_magnitude_adaptive_measurement_t *c =
            &command->u.filter_gravity_magnitude_adaptive_measurement;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x44;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB3);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT: {
        const mipc_filter_mag_magnitude_adaptive_measurement_t *c =
            &command->u.filter_mag_magnitude_adaptive_measurement;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x45;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB4);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT: {
        const mipc_filter_mag_dip_angle_adaptive_measurement_t *c =
            &command->u.filter_mag_dip_angle_adaptive_measurement;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x46;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB5);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL: {
        const mipc_filter_altitude_aiding_control_t *c = &command->u.filter_altitude_aiding_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x47;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xB7);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL: {
        const mipc_filter_pitch_roll_aiding_control_t *c = &command->u.filter_pitch_roll_aiding_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x4B;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xBB);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_INCLINATION_SOURCE: {
        const mipc_filter_inclination_source_t *c = &command->u.filter_inclination_source;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x4C;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xBC);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE: {
        const mipc_filter_magnetic_field_magnitude_source_t *c =
            &command->u.filter_magnetic_field_magnitude_source;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x4D;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xBD);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL: {
        const mipc_filter_aiding_measurement_control_t *c = &command->u.filter_aiding_measurement_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x50;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xD0);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION: {
        const mipc_filter_initialization_configuration_t *c = &command->u.filter_initialization_configuration;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x52;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xD2);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL: {
        const mipc_filter_adaptive_filter_control_t *c = &command->u.filter_adaptive_filter_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x53;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xD3);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET: {
        const mipc_filter_multi_antenna_offset_t *c = &command->u.filter_multi_antenna_offset;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x54;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xD4);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION: {
        const mipc_filter_relative_position_configuration_t *c =
            &command->u.filter_relative_position_configuration;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x55;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xD5);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM: {
        const mipc_filter_reference_point_lever_arm_t *c = &command->u.filter_reference_point_lever_arm;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x56;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xD6);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_SPEED_LEVER_ARM: {
        const mipc_filter_speed_lever_arm_t *c = &command->u.filter_speed_lever_arm;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x61;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xE1);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL: {
        const mipc_filter_wheeled_vehicle_constraint_control_t *c =
            &command->u.filter_wheeled_vehicle_constraint_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x63;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xE3);
        }
        return true;
    }
    case MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL: {
        const mipc_filter_gnss_antenna_calibration_control_t *c =
            &command->u.filter_gnss_antenna_calibration_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0D;
        out->descriptor = 0x64;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xE4);
        }
        return true;
    }
    case MIPC_FIELD_GNSS_RECEIVER_INFO: {
        out->set = 0x0E;
        out->descriptor = 0x01;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        expect(out, 0x81);
        return true;
    }
    case MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION: {
        const mipc_gnss_signal_configuration_t *c = &command->u.gnss_signal_configuration;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0E;
        out->descriptor = 0x02;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x82);
        }
        return true;
    }
    case MIPC_FIELD_GNSS_SPARTN_CONFIGURATION: {
        const mipc_gnss_spartn_configuration_t *c = &command->u.gnss_spartn_configuration;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x0E;
        out->descriptor = 0x20;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0xA0);
        }
        return true;
    }
    case MIPC_FIELD_AIDING_FRAME_CONFIG: {
        const mipc_aiding_frame_config_t *c = &command->u.aiding_frame_config;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x13;
        out->descriptor = 0x01;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x81);
        }
        return true;
    }
    case MIPC_FIELD_AIDING_ECHO_CONTROL: {
        const mipc_aiding_echo_control_t *c = &command->u.aiding_echo_control;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x13;
        out->descriptor = 0x1F;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x9F);
        }
        return true;
    }
    case MIPC_FIELD_AIDING_ECEF_POSITION: {
        out->set = 0x13;
        out->descriptor = 0x21;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_AIDING_LLH_POSITION: {
        out->set = 0x13;
        out->descriptor = 0x22;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID: {
        out->set = 0x13;
        out->descriptor = 0x23;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_AIDING_ECEF_VELOCITY: {
        out->set = 0x13;
        out->descriptor = 0x28;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_AIDING_NED_VELOCITY: {
        out->set = 0x13;
        out->descriptor = 0x29;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_AIDING_BODY_FRAME_VELOCITY: {
        out->set = 0x13;
        out->descriptor = 0x2A;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_AIDING_TRUE_HEADING: {
        out->set = 0x13;
        out->descriptor = 0x31;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_AIDING_MAGNETIC_FIELD: {
        out->set = 0x13;
        out->descriptor = 0x32;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_AIDING_PRESSURE: {
        out->set = 0x13;
        out->descriptor = 0x33;
        out->field_devices = 0x4u;
        out->layout_device = MIPC_DEVICE_ANY;
        return true;
    }
    case MIPC_FIELD_SYSTEM_COMMUNICATION_MODE: {
        const mipc_system_communication_mode_t *c = &command->u.system_communication_mode;
        static const int functions[] = {1, 2, 3, 4, 5};
        out->set = 0x7F;
        out->descriptor = 0x10;
        out->field_devices = 0x2u;
        out->layout_device = MIPC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        if (out->function == 2) {
            expect(out, 0x90);
        }
        return true;
    }
    default:
        return false;
    }
}

int mipc_session_ack_decode(uint8_t set, const uint8_t *data, size_t len, mipc_device_t device, uint8_t *echo,
                            uint32_t *code) {
    mipc_status_t why;
    const mipc_field_info_t *f = mipc_find_field(set, MIPC_SESSION_ACK_DESCRIPTOR, &why);
    mipc_ack_nack_t ack;
    if (f == NULL) {
        return 0;
    }
    if (f->first_layout != MIPC_FIELD_ACK_NACK) {
        mipc_field_value_t value;
        return mipc_decode_field(set, MIPC_SESSION_ACK_DESCRIPTOR, data, len, device, &value, NULL) == MIPC_OK
                   ? -1
                   : 0;
    }
    if (mipc_ack_nack_decode(data, len, &ack, NULL) != MIPC_OK) {
        return 0;
    }
    *echo = (uint8_t)ack.command_descriptor;
    *code = (uint32_t)ack.ack_code;
    return 1;
}

/* The names a device answers to in the wrong-model check: its title and its identity model name
 * (the spec's simulation.identity), upper case without spaces and punctuation; NULL-terminated. */
const char *const *mipc_device_model_names(mipc_device_t device) {
    static const char *const names_0[] = {"3DMGX545", NULL};      /* 3DM-GX5-45, 3DM-GX5-45 */
    static const char *const names_1[] = {"3DMCV7GNSSINS", NULL}; /* 3DM-CV7-GNSS/INS, 3DM-CV7-GNSS/INS */
    static const char *const none[] = {NULL};
    switch (device) {
    case MIPC_DEVICE_GX5_45:
        return names_0;
    case MIPC_DEVICE_CV7_INS:
        return names_1;
    default:
        return none;
    }
}
