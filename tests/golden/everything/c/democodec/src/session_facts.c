/* What the Demo protocol with every spec feature spec says about every command, for the session core
 * (session.c, docs/conformance.md section 8): the ack rule and, per command layout, its devices, function
 * values, expected reply descriptors with their conditions, ack suppression and timeout
 * allowance. Generated: do not edit. */
#include "democodec/session.h"

#include <string.h>

/* Per device, where a data packet carries the device's reference time (the spec's
 * time.reference_time; the host clock model, docs/time.md). */
const democ_reference_time_t democ_reference_times[] = {
    {DEMOC_DEVICE_ANY, 0, false, 0, false, 0, 0, 0, 0, 0}}; /* none (C has no empty arrays) */
const size_t democ_reference_time_count = 0;

const char *democ_function_name(int value) {
    switch (value) {
    case 1:
        return "write";
    case 2:
        return "read";
    case 3:
        return "save";
    default:
        return NULL;
    }
}

/* Devices a function selector value is limited to (every device when it is not). */
static uint32_t function_devices(int value) {
    switch (value) {
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

static void expect(democ_command_facts_t *out, uint8_t descriptor) {
    if (out->expect_count < DEMOC_SESSION_MAX_EXPECT) {
        out->expect[out->expect_count++] = descriptor;
    }
}

bool democ_command_facts(const democ_field_value_t *command, democ_command_facts_t *out) {
    memset(out, 0, sizeof *out);
    out->id = command->id;
    out->function = -1;
    out->function_listed = true;
    out->function_devices = 0x6u;
    out->layout_device = DEMOC_DEVICE_ANY;
    switch (command->id) {
    case DEMOC_FIELD_COMMANDS_PING: {
        out->set = 0x01;
        out->descriptor = 0x01;
        out->field_devices = 0x2u;
        out->layout_device = DEMOC_DEVICE_ANY;
        return true;
    }
    case DEMOC_FIELD_COMMANDS_CONFIGURE: {
        const democ_commands_configure_t *c = &command->u.commands_configure;
        static const int functions[] = {1, 2, 3};
        out->set = 0x01;
        out->descriptor = 0x02;
        out->field_devices = 0x2u;
        out->layout_device = DEMOC_DEVICE_ANY;
        out->function = (int)c->function;
        out->function_listed = listed(out->function, functions, sizeof functions / sizeof functions[0]);
        out->function_devices = function_devices(out->function);
        out->suppressed = c->has_suppress_ack && c->suppress_ack != 0;
        if (out->function == 2) {
            expect(out, 0x82);
        }
        return true;
    }
    case DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_A: {
        out->set = 0x01;
        out->descriptor = 0x03;
        out->field_devices = 0x6u;
        out->layout_device = DEMOC_DEVICE_DEV_A;
        return true;
    }
    case DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_B: {
        out->set = 0x01;
        out->descriptor = 0x03;
        out->field_devices = 0x6u;
        out->layout_device = DEMOC_DEVICE_DEV_B;
        return true;
    }
    default:
        return false;
    }
}

int democ_session_ack_decode(uint8_t set, const uint8_t *data, size_t len, democ_device_t device,
                             uint8_t *echo, uint32_t *code) {
    democ_status_t why;
    const democ_field_info_t *f = democ_find_field(set, DEMOC_SESSION_ACK_DESCRIPTOR, &why);
    democ_ack_t ack;
    if (f == NULL) {
        return 0;
    }
    if (f->first_layout != DEMOC_FIELD_ACK) {
        democ_field_value_t value;
        return democ_decode_field(set, DEMOC_SESSION_ACK_DESCRIPTOR, data, len, device, &value, NULL) ==
                       DEMOC_OK
                   ? -1
                   : 0;
    }
    if (democ_ack_decode(data, len, &ack, NULL) != DEMOC_OK) {
        return 0;
    }
    *echo = (uint8_t)ack.echo;
    *code = (uint32_t)ack.code;
    return 1;
}

/* The names a device answers to in the wrong-model check: its title and its identity model name
 * (the spec's simulation.identity), upper case without spaces and punctuation; NULL-terminated. */
const char *const *democ_device_model_names(democ_device_t device) {
    static const char *const none[] = {NULL};
    switch (device) {
    default:
        return none;
    }
}
